use super::paper::*;
use super::*;
use crate::output::NoFigures;
use crate::reproduce::{paper as find_paper, report, ClaimVerdict, Metric, PAPERS};
use tidepath_io::Outputs;

/// A budget small enough for a debug-build test: a few iterations of small packs and swarms.
const TINY: Scale = Scale {
    wolf_iterations: 2,
    wolf_population: 8,
    baseline_iterations: 3,
    baseline_population: 6,
    path_iterations: Some(1),
    path_population: Some(6),
};

fn opts(jobs: usize) -> ReproduceOptions {
    ReproduceOptions {
        runs: 2,
        master_seed: 7,
        jobs,
        reference: None,
        stop: None,
        time_limit_s: None,
        quick: false,
        only: Vec::new(),
    }
}

fn labels() -> Vec<String> {
    problems().into_iter().map(|p| p.label).collect()
}

#[test]
fn wpa2017_is_a_registry_entry() {
    let p = find_paper("wpa2017").unwrap();
    assert_eq!(p.id, "wpa2017");
    assert!(p.citation.contains("Tables 2-5"), "{}", p.citation);
    assert_eq!(PAPERS.iter().filter(|p| p.id == "wpa2017").count(), 1);
    assert_eq!(Scale::PAPER.wolf_iterations, 500);
    assert_eq!((Scale::PAPER.baseline_population, Scale::PAPER.baseline_iterations), (50, 1000));
}

/// Spot checks against the paper's Tables 2, 4 and 5 as printed.
#[test]
fn the_paper_numbers_are_transcribed() {
    assert_eq!(labels(), ["easom-d2", "trid-d6", "sphere-d30", "rastrigin-d60", "quadric-d120"]);
    let p = problems();
    assert_eq!((p[1].dim, p[1].lower, p[1].upper), (6, -36.0, 36.0));
    assert_eq!((p[4].dim, p[4].lower, p[4].upper), (120, -30.0, 30.0));
    assert_eq!(TABLE4_MWPA[0], (-1.0, -0.9963, -0.9998, 2.8624));
    assert_eq!(TABLE4_MWPA[1], (-49.9999, -49.9961, -49.9995, 2.0192));
    assert_eq!(TABLE4_PSO[3], (22.3114, 73.4401, 40.8835, 2.9841));
    assert_eq!(TABLE4_PSO[4].3, 29.5144);
    assert_eq!(TABLE4_GA[2], (0.2011, 0.4269, 0.3378, 26.6625));
    assert_eq!(TABLE4_GA[4], (18.1023, 77.9319, 24.6056, 140.7281));
    assert_eq!(TABLE5_MWPA, (72.2521, 4.3712));
    assert_eq!(TABLE5_WPA, (77.0736, 10.2408));
    let t = table4("wpa2017, Table 4", &labels());
    assert_eq!(t.runs, Some(10));
    assert_eq!(t.cells.len(), 15, "MWPA, PSO and GA on five functions; WPA is not in Table 4");
    let ga = t.cell("quadric-d120", "ga").unwrap();
    assert_eq!((ga.best, ga.worst, ga.mean, ga.time_s), (Some(18.1023), Some(77.9319), Some(24.6056), Some(140.7281)));
    let pso = t.cell("trid-d6", "pso").unwrap();
    assert_eq!((pso.mean, pso.std, pso.zeros), (Some(-50.0), None, None));
    assert!(t.cell("sphere-d30", "wpa").is_none());
}

/// MWPA below PSO and GA from D = 30 up; PSO and GA below MWPA at D = 2 and 6, as the paper's
/// means have it. All on cost.
#[test]
fn table4_claims_take_the_paper_s_side() {
    let claims = claims(&labels());
    assert_eq!(claims.len(), 10);
    for c in &claims {
        assert_eq!(c.metric, Metric::Cost);
        let high = ["sphere-d30", "rastrigin-d60", "quadric-d120"].contains(&c.problem.as_str());
        if high {
            assert_eq!(c.a, "mwpa", "{}", c.text);
            assert!(["pso", "ga"].contains(&c.b.as_str()));
        } else {
            assert_eq!(c.b, "mwpa", "{}", c.text);
        }
        assert!(!c.text.contains("wpa ") && c.a != "wpa" && c.b != "wpa");
    }
    assert_eq!(
        claims[3].text,
        "GA reaches lower costs than MWPA on trid (D = 6; the paper's means -49.9996 against -49.9995, the \
         low-dimension converse)"
    );
    assert_eq!(claims[9].text, "MWPA reaches lower costs than GA on quadric (D = 120)");
}

#[test]
fn helpers_measure_what_they_say() {
    assert_eq!(path::polyline_length_m(&[[0.0, 0.0, 0.0], [3.0, 4.0, 0.0], [3.0, 4.0, -12.0]]), 17.0);
    assert_eq!(path::polyline_length_m(&[[1.0, 1.0, 1.0]]), 0.0);
    let mut records = vec![
        RunRecord { history: (0..5000).map(|i| Some(i as f64)).collect(), ..RunRecord::default() },
        RunRecord { history: vec![Some(1.0), None], ..RunRecord::default() },
    ];
    assert!(thin_histories(&mut records));
    assert_eq!(records[0].history.len(), MAX_HISTORY);
    assert_eq!((records[0].history[0], records[0].history[MAX_HISTORY - 1]), (Some(0.0), Some(4999.0)));
    assert_eq!(records[1].history, vec![Some(1.0), None]);
    assert!(!thin_histories(&mut records[1..]));
}

/// The whole reproduction at a tiny budget: the three experiments, their planners, claims on
/// cost, length and time, the equal budget taken from MWPA's own counts, the paths figure's
/// scenario, and the report's columns; results do not depend on the number of jobs.
#[test]
fn a_tiny_run_has_every_experiment_planner_and_claim() {
    let progress = Mutex::new(Vec::new());
    let outcomes = run_scaled(&opts(2), &|d, t| progress.lock().unwrap().push((d, t)), &TINY).unwrap();
    let ids: Vec<&str> = outcomes.iter().map(|o| o.id.as_str()).collect();
    assert_eq!(ids, ["table4-functions", "table4-equal-evaluations", "table5-path"]);
    let progress = progress.into_inner().unwrap();
    assert_eq!(progress.iter().map(|p| p.1).max(), Some(2 * 5 * 4 * 2 + 3 * 2));
    assert_eq!(progress.iter().map(|p| p.0).max(), Some(2 * 5 * 4 * 2 + 3 * 2));

    let (own, equal, path) = (&outcomes[0], &outcomes[1], &outcomes[2]);
    for o in [own, equal] {
        assert_eq!(o.comparison.planners, ["mwpa", "pso", "ga", "wpa"]);
        assert_eq!(o.comparison.records.len(), 5 * 4 * 2);
        assert!(o.comparison.complete);
        assert_eq!(o.claims.len(), 10);
        assert!(o.claims.iter().all(|(_, v)| matches!(v, ClaimVerdict::Undecidable { runs: (2, 2), .. })));
        assert!(o.notes[0].starts_with("Mean evaluations per run: easom-d2: mwpa "), "{}", o.notes[0]);
        assert!(o.notes[1]
            .starts_with("Mean distance to the optimum, f - f*, where f* is not 0: easom-d2 (f* = -1): mwpa "));
        assert!(o.notes[1].contains("; trid-d6 (f* = -50): mwpa ") && !o.notes[1].contains("sphere"), "{}", o.notes[1]);
    }
    // Own budgets: the wolf packs stop after 2 iterations, PSO and GA after 3 generations of 6
    // (the GA's elite is not evaluated again).
    for r in &own.comparison.records {
        match r.planner.as_str() {
            "pso" => assert_eq!((r.iterations, r.evaluations), (3, 6 + 3 * 6)),
            "ga" => assert_eq!((r.iterations, r.evaluations), (3, 6 + 3 * 5)),
            _ => assert_eq!(r.iterations, 2),
        }
    }
    // Equal evaluations: on each function every run stops at MWPA's mean count there.
    let budgets = equal_budgets(&own.comparison);
    assert_eq!(budgets.len(), 5);
    for (label, e) in &budgets {
        let mean = own.comparison.rows.iter().find(|r| &r.problem == label && r.planner == "mwpa").unwrap();
        assert_eq!(*e, mean.mean_evaluations.ceil() as u64);
        for r in equal.comparison.records.iter().filter(|r| &r.problem == label) {
            assert_eq!(r.evaluations, *e, "{} on {label}", r.planner);
        }
    }
    assert!(equal.setup.contains(&format!("easom-d2 {}", budgets[0].1)), "{}", equal.setup);

    assert_eq!(path.comparison.planners, ["mwpa", "wpa", "mwpa-no-step7"]);
    assert!(path.notes.iter().any(|n| n.starts_with("Step 7 (replace every infeasible wolf")), "{:?}", path.notes);
    assert_eq!(path.comparison.problems, [path::SCENARIO]);
    assert_eq!(path.comparison.records.len(), 6);
    assert!(path.comparison.records.iter().all(|r| r.iterations == 1 && r.length_m.is_some()));
    assert_eq!(path.comparison.smoother.as_ref().map(|s| s.id.as_str()), Some("dubins"));
    assert_eq!(path.comparison.reference_planner.as_deref(), Some("theta-star"));
    assert!(path.scenario.is_some());
    let metrics: Vec<Metric> = path.claims.iter().map(|(c, _)| c.metric).collect();
    assert_eq!(metrics, [Metric::Length, Metric::Cost, Metric::Length, Metric::Cost, Metric::Time]);
    assert!(path.claims[0].0.text.contains("polyline") && path.claims[2].0.text.contains("Dubins"));
    assert!(path.claims.iter().all(|(c, v)| c.a == "mwpa" && c.b == "wpa" && v.p().is_some()));
    let (heading, table) = &path.tables[0];
    assert!(heading.starts_with("Table 5 beside ours"));
    assert!(table.starts_with("| planner | length paper (km) | polyline ours (km) | Dubins ours (km) |"), "{table}");
    let mwpa = table.lines().find(|l| l.starts_with("| mwpa |")).unwrap();
    assert!(mwpa.contains("| 72.25 |") && mwpa.contains("| 4.371 |"), "{mwpa}");

    // The report: Table 4's worst and time columns, the evaluations, Table 5, the paths figure.
    let dir = tempfile::tempdir().unwrap();
    let mut out = Outputs::new();
    report::stage(&mut out, &find_paper("wpa2017").unwrap(), &opts(2), &outcomes, dir.path(), &NoFigures).unwrap();
    out.commit().unwrap();
    let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
    for needle in [
        "| worst paper | worst ours |",
        "| time paper (s) | time ours (s) | evaluations ours (mean) |",
        "### Table 5 beside ours",
        "![best path of each planner](table5-path/paths.svg)",
        "MWPA takes less time than WPA (wall time per run; machine-dependent): **undecidable with 2 runs**",
        "Gap to a reference: theta-star",
    ] {
        assert!(md.contains(needle), "{needle} missing from\n{md}");
    }
    let quadric = md.lines().find(|l| l.starts_with("| quadric-d120 | ga |")).unwrap();
    assert!(quadric.contains("| 77.9319 |") && quadric.contains("| 140.7281 |"), "{quadric}");

    // Another number of jobs, the same results (timing apart).
    let again = run_scaled(&opts(1), &|_, _| {}, &TINY).unwrap();
    for (a, b) in outcomes.iter().zip(&again) {
        let strip = |c: &Comparison| -> Vec<RunRecord> {
            c.records.iter().map(|r| RunRecord { elapsed_s: 0.0, ..r.clone() }).collect()
        };
        assert_eq!(strip(&a.comparison), strip(&b.comparison), "{}", a.id);
        let verdicts = |o: &ExperimentOutcome| -> Vec<String> {
            o.claims.iter().filter(|(c, _)| c.metric != Metric::Time).map(|(_, v)| v.label()).collect()
        };
        assert_eq!(verdicts(a), verdicts(b));
    }
}

use std::sync::Mutex;
