use std::sync::Mutex;

use super::paper::*;
use super::score::{resample_to_lines, RunScore, LINE_SPACING_M};
use super::*;
use crate::output::NoFigures;
use crate::reproduce::{paper as find_paper, report, ClaimVerdict, Metric, PAPERS};
use crate::table::num;
use tidepath_io::Outputs;

/// A budget small enough for a debug-build test: one case per table, ten generations of 20.
const TINY: Scale = Scale {
    name: "a test's tiny",
    generations_2d: 10,
    generations_3d: 10,
    population: 20,
    samples: 20,
    cases_2d: 1,
    cases_3d: 1,
    lambdas: &[0.5, 0.08],
    periods: &[5, 2],
    populations: &[16, 20],
};

fn opts(jobs: usize) -> ReproduceOptions {
    ReproduceOptions {
        runs: 2,
        master_seed: 5,
        jobs,
        reference: None,
        stop: None,
        time_limit_s: None,
        quick: false,
        only: Vec::new(),
    }
}

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

#[test]
fn lfhh2019_is_a_registry_entry_with_the_paper_s_budgets() {
    assert_eq!(find_paper("lfhh2019").unwrap().id, "lfhh2019");
    assert_eq!(PAPERS.iter().filter(|p| p.id == "lfhh2019").count(), 1);
    assert_eq!((Scale::PAPER.generations_2d, Scale::PAPER.generations_3d, Scale::PAPER.population), (100, 300, 200));
    assert_eq!((Scale::PAPER.lambdas.len(), Scale::PAPER.periods.len(), Scale::PAPER.populations.len()), (20, 4, 10));
    assert_eq!(TABLE2[0][0], (0.660, Some(0.171), Some(1.91)));
    assert_eq!(TABLE2[1][6].0, 0.899);
    assert_eq!(TABLE3_LFHH[2], (0.627, 2.57));
    // Paper (X, Y) = (13, 0) km is tidepath (x, y) = (0, 13000) m; Z = 7 km is z = -13000 m.
    assert_eq!(CASES_2D[0].world_point(CASES_2D[0].pair.start, 0.0), [0.0, 13000.0, 0.0]);
    assert_eq!(CASES_3D[0].world_point(CASES_3D[0].pair.target, 0.0), [39000.0, 3000.0, -5000.0]);
    assert_eq!(CASES_3D[2].label(), "3d-2 (13,0,7)->(7,39,5)");
    assert_eq!(CASES_2D[2].label(), "2d (5,0)->(12,39)");
}

/// A straight piece from x = 0.5 to 3.5 km: the start, the lines 1, 2, 3 km, the end, every
/// coordinate interpolated.
#[test]
fn resampling_puts_one_point_on_each_line_in_between() {
    let p = resample_to_lines(&[v(500.0, 0.0, -100.0), v(3500.0, 3000.0, -400.0)], LINE_SPACING_M).unwrap();
    let want = [
        v(500.0, 0.0, -100.0),
        v(1000.0, 500.0, -150.0),
        v(2000.0, 1500.0, -250.0),
        v(3000.0, 2500.0, -350.0),
        v(3500.0, 3000.0, -400.0),
    ];
    assert_eq!(p.len(), want.len());
    for (a, b) in p.iter().zip(want) {
        assert!((*a - b).length() < 1e-9, "{p:?}");
    }
    // Ends on lines are kept once: 0 and 3 km give the lines 1 and 2 only in between.
    let p = resample_to_lines(&[v(0.0, 0.0, 0.0), v(3000.0, 0.0, 0.0)], LINE_SPACING_M).unwrap();
    assert_eq!(p.iter().map(|q| q.x).collect::<Vec<_>>(), [0.0, 1000.0, 2000.0, 3000.0]);
    // Travel toward -x: lines in that order.
    let p = resample_to_lines(&[v(2500.0, 0.0, 0.0), v(500.0, 2000.0, 0.0)], LINE_SPACING_M).unwrap();
    assert_eq!(p.iter().map(|q| q.x).collect::<Vec<_>>(), [2500.0, 2000.0, 1000.0, 500.0]);
    assert!((p[1].y - 500.0).abs() < 1e-9 && (p[2].y - 1500.0).abs() < 1e-9);
    assert!(resample_to_lines(&[v(0.0, 0.0, 0.0)], LINE_SPACING_M).is_none());
}

/// A path that doubles back: each line is read where the path first reaches it after the
/// previous line's point, and the detour's own vertices are dropped.
#[test]
fn resampling_reads_a_path_that_turns_back_at_its_first_crossings() {
    // 0 -> 2.5 km (y = 0), back to 0.5 km (y = 1000), then on to 3 km (y = 2000).
    let path = [v(0.0, 0.0, 0.0), v(2500.0, 0.0, 0.0), v(500.0, 1000.0, 0.0), v(3000.0, 2000.0, 0.0)];
    let p = resample_to_lines(&path, LINE_SPACING_M).unwrap();
    assert_eq!(p.iter().map(|q| q.x).collect::<Vec<_>>(), [0.0, 1000.0, 2000.0, 3000.0]);
    // Lines 1 and 2 km on the first leg (y = 0), not on the later crossings.
    assert_eq!((p[1].y, p[2].y), (0.0, 0.0));
    // Walking on from the 2 km point: the path turns back, crosses 2 km twice more and
    // never reaches 3 km before its end, which is the last point.
    assert_eq!(p[3], v(3000.0, 2000.0, 0.0));
    // A vertical segment exactly on a line: its first point.
    let p = resample_to_lines(
        &[v(0.0, 0.0, 0.0), v(1000.0, 0.0, 0.0), v(1000.0, 500.0, 0.0), v(2000.0, 500.0, 0.0)],
        LINE_SPACING_M,
    )
    .unwrap();
    assert_eq!(p, vec![v(0.0, 0.0, 0.0), v(1000.0, 0.0, 0.0), v(2000.0, 500.0, 0.0)]);
}

/// A6: a run's F is the mean of its re-plans at the changes; without any, its departure plan's.
#[test]
fn a_run_scores_the_mean_of_its_five_replans() {
    let s = RunScore { departure: 3.5, changes: vec![0.5, 0.7, 0.9, 2.5, 0.4] };
    assert!((s.run_f() - 1.0).abs() < 1e-12);
    let early = RunScore { departure: 0.6, changes: vec![0.8, 3.0] };
    assert!((early.run_f() - 1.9).abs() < 1e-12);
    assert_eq!(RunScore { departure: 4.2, changes: vec![] }.run_f(), 4.2);
}

/// Each run's F is the mean of its re-plans at the changes (A6), its departure plan's without
/// any; the details kept beside each record agree with it.
#[test]
fn each_record_scores_its_simulation() {
    let runs = run_cases(&opts(2), &TINY, &CASES_2D[..1], &algorithms(), &|_| {}).unwrap();
    assert_eq!(runs.details.len(), runs.comparison.records.len());
    // The loop is exercised: LFHH (scored on its own F) and PRM* (resampled) re-plan at all
    // five changes at this budget with this seed.
    for planner in ["lfhh", "prm-star"] {
        assert!(runs.details.iter().any(|d| d.planner == planner && d.score.changes.len() == 5), "{planner}");
    }
    for r in &runs.comparison.records {
        let d = runs.detail(&r.problem, &r.planner, r.run).unwrap();
        assert_eq!(r.cost, d.score.run_f(), "{}", r.planner);
        assert!(d.score.changes.len() <= 5);
        // A run that re-planned at all five changes flew on to the goal.
        if d.score.changes.len() == 5 {
            assert!(r.travel_time_s.is_some() || !d.reached);
        }
    }
}

/// The whole reproduction at a tiny budget: every experiment, planner and claim, each run's F
/// the mean of its re-plans, the report's tables and verdicts formed from the runs, and the
/// same numbers with another number of jobs.
#[test]
fn a_tiny_run_has_every_table_claim_and_sweep() {
    let progress = Mutex::new(Vec::new());
    let outcomes = run_scaled(&opts(2), &|d, t| progress.lock().unwrap().push((d, t)), &TINY).unwrap();
    let ids: Vec<&str> = outcomes.iter().map(|o| o.id.as_str()).collect();
    assert_eq!(
        ids,
        [
            "table2-2d",
            "table3-3d",
            "table4-ablation-2d",
            "table5-ablation-3d",
            "sweep-lambda",
            "sweep-period",
            "sweep-population"
        ]
    );
    let total = 7 * 2 + 7 * 2 + 3 * 2 + 3 * 2 + 6 * 2;
    let progress = progress.into_inner().unwrap();
    assert!(progress.iter().all(|p| p.1 == total));
    assert_eq!(progress.iter().map(|p| p.0).max(), Some(total));

    let algorithms: Vec<&str> = ALGORITHMS.iter().map(|a| a.0).collect();
    for o in &outcomes[..2] {
        assert_eq!(o.comparison.planners, algorithms);
        assert_eq!(o.comparison.records.len(), 7 * 2);
        assert!(o.comparison.complete);
        // LFHH and the six baselines on the one case: 7 feasibility claims, each with counts
        // taken from the runs.
        assert_eq!(o.claims.len(), 7);
        for (claim, verdict) in &o.claims {
            let planner = if claim.a == "F = 2" { &claim.b } else { &claim.a };
            let costs: Vec<f64> = o.comparison.records_of(&claim.problem, planner).map(|r| r.cost).collect();
            let below = costs.iter().filter(|&&f| f < 2.0).count();
            assert!(claim.text.contains(&format!("ours: {below} of 2 runs below 2")), "{}", claim.text);
            assert!(matches!(verdict, ClaimVerdict::Undecidable { runs: (2, 2), .. }), "{verdict:?}");
        }
    }
    let three_d = &outcomes[1];
    let prm = three_d.claims.iter().find(|(c, _)| c.b == "prm-star").expect("PRM* infeasible in 3-D");
    assert!(prm.0.text.starts_with("PRM* is infeasible (F > 2) on 3d-1 (12,0,7)->(3,39,15)"), "{}", prm.0.text);
    let t2 = &outcomes[0];
    assert!(t2.claims.iter().any(|(c, _)| c.a == "prm-star" && c.text.starts_with("PRM* is feasible (F < 2)")));

    // F lies in [0, 8) (length < 1, curvature and block at most 3 each, current at most 1) and
    // feasible means F < 2.
    for o in &outcomes {
        for r in &o.comparison.records {
            assert!(r.cost.is_finite() && (0.0..8.0).contains(&r.cost), "{r:?}");
            assert_eq!(r.feasible, r.cost < 2.0);
            assert!(r.elapsed_s > 0.0 && !r.waypoints.is_empty());
        }
    }
    // The ablation: LFHH's rows are Table 2's runs, the three variants run anew; claims on F
    // and on wall time, and the no-smoothing feasibility claim.
    let ab = &outcomes[2];
    assert_eq!(ab.comparison.planners, ["lfhh", NO_LTS, NO_SMOOTH, NO_WINDOW]);
    let lfhh_t2: Vec<&RunRecord> = t2.comparison.records.iter().filter(|r| r.planner == "lfhh").collect();
    let lfhh_ab: Vec<&RunRecord> = ab.comparison.records.iter().filter(|r| r.planner == "lfhh").collect();
    assert_eq!(lfhh_t2, lfhh_ab);
    let metrics: Vec<Metric> = ab.claims.iter().map(|(c, _)| c.metric).collect();
    assert_eq!(metrics, [Metric::Cost, Metric::Time, Metric::Cost, Metric::Time, Metric::Cost]);
    assert!(ab.claims[4].0.text.starts_with("LFHH without the smooth method is infeasible (F > 2)"));
    // The sweeps, in increasing order of the parameter; the paper's value is the one the
    // others are compared with (the first when the sweep lacks it).
    let lambda = &outcomes[4];
    assert_eq!(lambda.comparison.planners, ["λ = 0.08", "λ = 0.5"]);
    assert_eq!(outcomes[5].comparison.planners, ["T = 2", "T = 5"]);
    assert_eq!(outcomes[6].comparison.planners, ["NP = 16", "NP = 20"]);
    let row = |o: &ExperimentOutcome, value: &str| -> String {
        o.tables[0].1.lines().find(|l| l.starts_with(&format!("| {value} |"))).unwrap().to_string()
    };
    assert!(row(lambda, "0.08").ends_with("| ref |") && !row(lambda, "0.5").ends_with("| ref |"));
    assert!(row(&outcomes[5], "5").ends_with("| ref |"));
    // NP = 200 is not in this sweep: the first value is the reference.
    assert!(row(&outcomes[6], "16").ends_with("| ref |"));

    // The report: every table beside the paper's, the claims, the sweep tables, formed from the
    // runs (LFHH's mean F and the paper's 0.66 on one line).
    let dir = tempfile::tempdir().unwrap();
    let mut out = Outputs::new();
    report::stage(&mut out, &find_paper("lfhh2019").unwrap(), &opts(2), &outcomes, dir.path(), &NoFigures).unwrap();
    out.commit().unwrap();
    let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
    for needle in [
        "## Table 2: the 2-D world, three start/target pairs",
        "### Table 2 beside ours (per pair and algorithm)",
        "| case | algorithm | F paper | F ours: mean (std) | time paper (s) | time ours (s) | mark paper | vs LFHH ours |",
        "## Table 3: the 3-D worlds, three scenarios x two pairs",
        "3.9–5 (over the 6 cases)",
        "## Tables 4-5: ablation in 2-D",
        "## Tables 4-5: ablation in 3-D",
        "| case | variant | paper | F ours: mean (std) | time ours (s) | F vs LFHH | time vs LFHH |",
        "## Figs. 15-16: parameter study of λ",
        "### F and time against NP",
        "![final costs](sweep-lambda/boxplot.svg)",
        "LFHH is feasible (F < 2) on 2d (13,0)->(6,39)",
        "The window saves time: LFHH runs faster than LFHH re-planning to the goal each time",
        "Paper values from lfhh2019, Table 2 (30 runs per cell). Ours: 2 runs per cell, fewer than the paper's 30.",
    ] {
        assert!(md.contains(needle), "{needle} missing from\n{md}");
    }
    assert!(!md.contains("convergence.svg"), "a simulation has no convergence curve");
    let label = CASES_2D[0].label();
    let lfhh_costs: Vec<f64> = t2.comparison.records_of(&label, "lfhh").map(|r| r.cost).collect();
    let mean = lfhh_costs.iter().sum::<f64>() / lfhh_costs.len() as f64;
    let line =
        md.lines().find(|l| l.starts_with(&format!("| {label} | LFHH | 0.6600 (0.1710) |"))).expect("LFHH's row");
    assert!(line.contains(&format!("| {} (", num(mean))) && line.contains("| 1.910 |"), "{line}");

    // Another number of jobs: the same runs, timing apart (Table 2's, run again on one thread).
    let again = run_cases(&opts(1), &TINY, &CASES_2D[..1], &super::algorithms(), &|_| {}).unwrap();
    let strip = |c: &Comparison| -> Vec<RunRecord> {
        c.records.iter().map(|r| RunRecord { elapsed_s: 0.0, ..r.clone() }).collect()
    };
    assert_eq!(strip(&t2.comparison), strip(&again.comparison));
}

/// Ctrl-C: runs not started when the flag is raised are left out, the runs that finished are
/// kept in an incomplete table, and no later experiment starts.
#[test]
fn a_stopped_reproduction_keeps_the_runs_that_finished() {
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;
    let flag = Arc::new(AtomicBool::new(false));
    let o = ReproduceOptions { stop: Some(flag.clone()), ..opts(1) };
    let raise = |done: usize, _| {
        if done >= 3 {
            flag.store(true, Ordering::Relaxed);
        }
    };
    let outcomes = run_scaled(&o, &raise, &TINY).unwrap();
    assert_eq!(outcomes.len(), 1, "no experiment after the stop");
    let c = &outcomes[0].comparison;
    assert!(!c.complete);
    assert!((3..7 * 2).contains(&c.records.len()), "{}", c.records.len());
    assert!(c.records.iter().all(|r| r.stop_reason != tidepath::optim::StopReason::Cancelled));
    let dir = tempfile::tempdir().unwrap();
    let mut out = Outputs::new();
    report::stage(&mut out, &find_paper("lfhh2019").unwrap(), &o, &outcomes, dir.path(), &NoFigures).unwrap();
    out.commit().unwrap();
    let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
    assert!(md.contains("> **Incomplete**: the run was interrupted (Ctrl-C)."), "{md}");
}

/// `--only` runs the parts asked for: the ablation alone runs LFHH's own rows and the three
/// ablated ones, but prints no Table 2 or 3; an unknown part, or `--only` for a paper without
/// parts, is refused naming the flag.
#[test]
fn only_runs_the_parts_asked_for() {
    let o = ReproduceOptions { only: vec!["ablation".into()], ..opts(1) };
    let finished = Mutex::new(0usize);
    let outcomes = run_scaled(&o, &|n, _| *finished.lock().unwrap() = n, &TINY).unwrap();
    let ids: Vec<&str> = outcomes.iter().map(|e| e.id.as_str()).collect();
    assert!(ids.iter().all(|id| id.starts_with("table4") || id.contains("ablation")), "{ids:?}");
    assert_eq!(ids.len(), 2, "{ids:?}");
    // LFHH and three ablated rows, one 2-D and one 3-D case, two runs each.
    assert_eq!(*finished.lock().unwrap(), 2 * 4 * 2);
    let e = crate::reproduce::check_only("lfhh2019", &["table9".into()]).unwrap_err().to_string();
    assert!(e.starts_with("--only") && e.contains("table2, table3, ablation, sweeps"), "{e}");
    let e = crate::reproduce::check_only("wpa2017", &["table2".into()]).unwrap_err().to_string();
    assert!(e.starts_with("--only"), "{e}");
    crate::reproduce::check_only("lfhh2019", &["sweeps".into(), "table3".into()]).unwrap();
}
