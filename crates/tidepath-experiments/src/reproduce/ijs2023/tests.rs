use super::paper::{PLANNERS, SETTINGS};
use super::tables::outcome_from;

/// The paper's rows are complete where it prints them: every planner has a row, success
/// rates are fractions, and the 1.2 x setting has no time for HHO and MPA (0 % success).
#[test]
fn the_papers_tables_are_transcribed_whole() {
    for s in &SETTINGS {
        for p in PLANNERS {
            let r = s.row_of(p).unwrap();
            assert!((0.0..=1.0).contains(&r.success), "{} {p}", s.id);
            assert_eq!(r.t_best.is_some(), r.success > 0.0, "{} {p}", s.id);
            if let (Some(b), Some(m)) = (r.t_best, r.t_mean) {
                assert!(b <= m, "{} {p}: best {b} above mean {m}", s.id);
            }
        }
        assert_eq!(s.row_of("ijs").unwrap().success, 1.0, "{}", s.id);
    }
    assert!(SETTINGS[3].row_of("hho").unwrap().t_best.is_none());
}

/// A run succeeds only when the ijs2023 cost's safety and target terms are both 0, on every
/// mission; its time is the latest arrival; F_p2 is the `current` term over its weight, summed
/// over the missions.
#[test]
fn the_success_test_reads_the_cost_terms() {
    let terms = |safety: f64, target: f64, current: f64| {
        let mut m = serde_json::Map::new();
        for (k, v) in [("time", 0.1), ("current", current), ("target", target), ("safety", safety)] {
            m.insert(k.into(), v.into());
        }
        m
    };
    let (a, b) = (terms(0.0, 0.0, 0.03), terms(0.0, 0.0, 0.06));
    let o = outcome_from(&[(&a, 100.0), (&b, 120.0)], 0.3);
    assert!(o.success && o.time_s == 120.0, "{o:?}");
    assert!((o.current_penalty.unwrap() - 0.3).abs() < 1e-12, "{o:?}");
    let missed = terms(0.0, 5.0, 0.06);
    assert!(!outcome_from(&[(&a, 100.0), (&missed, 120.0)], 0.3).success);
    let unsafe_ = terms(1.2, 0.0, 0.06);
    assert!(!outcome_from(&[(&a, 100.0), (&unsafe_, 120.0)], 0.3).success);
    assert_eq!(outcome_from(&[(&a, 100.0)], 0.0).current_penalty, None);
    assert!(!outcome_from(&[], 0.3).success);
}

fn opts(runs: u64) -> crate::reproduce::ReproduceOptions {
    crate::reproduce::ReproduceOptions {
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

/// Table 2 at two runs and the quick budget: every planner runs 50 iterations of 45, the
/// travel-time and current-penalty tables sit beside the paper's, and every claim (IJS against
/// each baseline, IJS's current penalty against MPA's) gets a verdict.
#[test]
fn table2_runs_every_planner_and_judges_every_claim() {
    let o = super::tables::experiment(&SETTINGS[1], &opts(2), &|_| {}).unwrap();
    let c = &o.comparison;
    assert!(c.complete);
    assert_eq!(c.rows.len(), PLANNERS.len());
    for r in &c.records {
        assert_eq!(r.iterations, super::tables::QUICK_ITERATIONS, "{}", r.planner);
        assert_eq!(r.waypoints.len(), 40, "{}", r.planner);
    }
    assert_eq!(o.tables.len(), 2, "travel times and the current penalty");
    for p in PLANNERS {
        assert!(o.tables[0].1.contains(&format!("| {p} |")), "{p}");
    }
    assert_eq!(o.claims.len(), PLANNERS.len());
    // Every run takes part in the travel-time claims (failures ranked last); the current
    // penalty's needs successful runs, which 50 iterations may not give.
    let timed = &o.claims[..PLANNERS.len() - 1];
    assert!(timed.iter().all(|(_, v)| !matches!(v, crate::reproduce::ClaimVerdict::NotRun)), "{timed:?}");
    assert!(o.notes.iter().any(|n| n.starts_with("The paper: IJS succeeds in every run")), "{:?}", o.notes);
}

/// The fleet at two runs: IJS plans the three vehicles as one, and the table states success,
/// the common arrival and the total current penalty beside the paper's.
#[test]
fn the_fleet_plans_three_vehicles_together() {
    let o = super::fleet::experiment(&opts(2), &|_| {}).unwrap();
    assert_eq!(o.comparison.records.len(), 2 * super::fleet::PLANNERS.len());
    assert!(o.comparison.records.iter().all(|r| r.missions.len() == 3));
    let t = &o.tables[0].1;
    for row in ["| success |", "| common arrival (s)", "| total current penalty"] {
        assert!(t.contains(row), "{row}: {t}");
    }
}
