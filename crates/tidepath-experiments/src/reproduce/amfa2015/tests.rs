use super::functions::{self, GA_PER_CHROMOSOME, GA_PM_SMALL, PSO_VMAX_RANGE};
use super::paper::{self, TABLES};
use super::paths;
use crate::reproduce::{ClaimVerdict, ReproduceOptions};

fn opts(runs: u64) -> ReproduceOptions {
    ReproduceOptions {
        runs,
        master_seed: 1,
        jobs: 2,
        reference: Some("none".into()),
        stop: None,
        time_limit_s: None,
        quick: true,
        only: Vec::new(),
    }
}

#[test]
fn every_reading_builds_with_the_papers_population() {
    for id in functions::PLANNERS {
        let o = functions::factory(id).unwrap_or_else(|e| panic!("{id}: {e}"));
        assert_eq!(o.population(), functions::POPULATION, "{id}");
    }
    assert!(functions::factory("nope").is_err());
    // The readings differ where they should, and only there.
    let pso = tidepath::optim::pso::PsoParams::amfa2015();
    let full = tidepath::optim::pso::PsoParams::amfa2015_vmax_range();
    assert_eq!((pso.vmax_fraction, full.vmax_fraction), (0.5, 1.0));
    assert_eq!((pso.w_start, pso.c1, pso.c2), (0.729, 1.494, 1.494));
    let ga = tidepath::optim::ga::GaParams::amfa2015_per_bit_small(30);
    assert_eq!(ga.mutation_rate, Some(1.0 / 600.0));
    for (variant, base) in [(PSO_VMAX_RANGE, "pso"), (GA_PM_SMALL, "ga"), (GA_PER_CHROMOSOME, "ga")] {
        assert_eq!(functions::factory(variant).unwrap().id(), base);
    }
    assert_eq!(functions::factory(functions::AMFA_EUCLIDEAN).unwrap().id(), "amfa");
    assert_eq!(functions::factory(functions::FA_LITERAL).unwrap().id(), "fa");
}

#[test]
fn the_papers_tables_and_claims() {
    for t in &TABLES {
        let labels: Vec<String> = functions::problems(t.range).iter().map(|p| p.label.clone()).collect();
        assert_eq!(labels.len(), 6);
        let claims = functions::claims(t, &labels);
        // AMFA against FA everywhere; against PSO and GA on the three multimodal functions
        // (small ranges) or on all six (wide ranges).
        let expected = if t.range == "small" { 6 + 3 * 2 } else { 6 + 6 * 2 };
        assert_eq!(claims.len(), expected, "{}", t.id);
        assert!(claims.iter().all(|c| c.a == "amfa"));
        for p in paper::PAPER_PLANNERS {
            assert!(t.rows_of(p).is_some());
        }
    }
    // Spot checks against the printed tables.
    assert_eq!(paper::TABLE2_PSO[2].1, 4.88);
    assert_eq!(paper::TABLE2_AMFA[0].3, 22);
    assert_eq!(paper::TABLE4_FA[3].1, 572.0);
    assert_eq!(paper::TABLE4_AMFA[5], (0.0, 1.5e-322, 0.0, 5));
}

/// Table 2 at two runs: every planner runs its full budget on every function, the paper's
/// columns sit beside ours, and every claim gets a verdict.
#[test]
fn table2_runs_every_reading_on_every_function() {
    let o = functions::experiment(&TABLES[0], &opts(2), &|_| {}).unwrap();
    let c = &o.comparison;
    assert!(c.complete);
    assert_eq!(c.rows.len(), 6 * functions::PLANNERS.len());
    assert!(c.records.iter().all(|r| r.evaluations == functions::EVALUATIONS), "every run spends 60,000 evaluations");
    assert_eq!(o.paper.cells.len(), 6 * 4);
    assert!(o.claims.iter().all(|(_, v)| !matches!(v, ClaimVerdict::NotRun)));
    assert!(o.notes.iter().any(|n| n.contains("Are the paper's baseline numbers reachable?")), "{:?}", o.notes);
    // Every cell is a real minimum of a non-negative function.
    assert!(c.rows.iter().all(|r| r.mean.is_finite() && r.best >= 0.0), "{:?}", c.rows);
}

#[test]
fn path_rows_set_the_operators() {
    let s = tidepath_io::scenario::load(paths::EXPERIMENTS[0].1).unwrap();
    assert_eq!(paths::PLANNERS.len(), 8);
    for row in paths::PLANNERS {
        let (planner, repair) = paths::setup_of(row);
        assert!(["amfa", "fa", "pso", "de"].contains(&planner), "{row}");
        assert_eq!(repair.is_some(), row.ends_with("ops"), "{row}");
        let (sc, id) = paths::scenario_for(&s, row);
        assert_eq!(id, planner);
        sc.check_request(&crate::compare::request(&crate::compare::RunBudget::default(), &id, 0)).unwrap();
    }
}

/// One path experiment at two runs and the quick budget: every row runs, AMFA's paths are
/// judged, and the notes say what the operators do for AMFA, PSO and DE.
#[test]
fn path_experiment_runs_every_row() {
    let o = paths::experiment(0, &opts(2), &|_| {}).unwrap();
    assert!(o.comparison.complete);
    assert_eq!(o.comparison.rows.len(), paths::PLANNERS.len());
    assert!(o.comparison.records.iter().all(|r| r.evaluations <= paths::QUICK_EVALUATIONS));
    assert_eq!(o.claims.len(), 2);
    for who in ["AMFA with", "PSO with", "DE with"] {
        assert!(o.notes.iter().any(|n| n.starts_with(who)), "{who}: {:?}", o.notes);
    }
    assert!(o.scenario.is_some());
}
