//! Rows and the Markdown table, checked against hand-computed numbers.

use super::*;
use crate::compare::{from_records, gap_percent, Comparison, Reference};

#[test]
fn numbers_keep_four_significant_digits() {
    assert_eq!(num(1.23456), "1.235");
    assert_eq!(num(123.456), "123.5");
    assert_eq!(num(0.0), "0");
    assert_eq!(num(1.5e-7), "1.500e-7");
    assert_eq!(num(2.5e6), "2.500e6");
}

/// A scenario run of `planner` with `cost`, feasible or not, and a path of `length` m
/// (travel time: twice the length).
fn run(planner: &str, i: u64, cost: f64, feasible: bool, length: f64) -> RunRecord {
    RunRecord {
        problem: "bay".into(),
        planner: planner.into(),
        run: i,
        cost,
        feasible,
        length_m: Some(length),
        travel_time_s: Some(2.0 * length),
        status: Some(if feasible { Status::Feasible } else { Status::Infeasible }),
        ..RunRecord::default()
    }
}

/// `a` feasible in all 4 runs (costs 1..4, lengths 10..40); `b` feasible once (cost 5, 50 m)
/// and three times infeasible with penalised costs 11..13 and short paths through obstacles
/// (1..3 m); `c` never feasible (costs 20..23). Reference cost 2.
fn bay() -> Comparison {
    let mut records = Vec::new();
    for i in 0..4 {
        records.push(run("a", i, 1.0 + i as f64, true, 10.0 * (i + 1) as f64));
    }
    records.push(run("b", 0, 5.0, true, 50.0));
    for i in 1..4 {
        records.push(run("b", i, 10.0 + i as f64, false, i as f64));
    }
    for i in 0..4 {
        records.push(run("c", i, 20.0 + i as f64, false, 1.0 + i as f64));
    }
    let mut c = from_records("scenario", &["bay"], &["a", "b", "c"], 4, records);
    c.reference = Some(Reference {
        planner: "exact-one".into(),
        status: "exact".into(),
        cost: 2.0,
        length_m: None,
        travel_time_s: None,
        waypoints: Vec::new(),
    });
    for row in &mut c.rows {
        row.gap_percent = row.feasible_mean.map(|m| gap_percent(m, 2.0));
        row.best_gap_percent = row.feasible_best.map(|b| gap_percent(b, 2.0));
    }
    c
}

#[test]
fn length_time_and_gap_count_feasible_runs_only() {
    let c = bay();
    let [a, b, cc] = [&c.rows[0], &c.rows[1], &c.rows[2]];
    // Costs over all runs, penalties included: b's mean is (5 + 11 + 12 + 13) / 4 = 10.25.
    assert_eq!((b.runs, b.feasible_runs, b.mean, b.best, b.worst), (4, 1, 10.25, 5.0, 13.0));
    // Feasible only: b's one feasible run, 50 m and 100 s, not (50 + 1 + 2 + 3) / 4 = 14 m.
    assert_eq!(
        (b.feasible_best, b.feasible_mean, b.mean_length_m, b.mean_travel_time_s),
        (Some(5.0), Some(5.0), Some(50.0), Some(100.0))
    );
    assert_eq!((a.mean_length_m, a.feasible_mean), (Some(25.0), Some(2.5)));
    // Gaps to the reference cost 2: a's best 1 is -50 %, its mean 2.5 is +25 %; b's 5 is +150 %.
    assert_eq!((a.best_gap_percent, a.gap_percent), (Some(-50.0), Some(25.0)));
    assert_eq!((b.best_gap_percent, b.gap_percent), (Some(150.0), Some(150.0)));
    // c has no feasible run: no feasible-only statistic at all.
    assert_eq!((cc.feasible_runs, cc.feasible_mean, cc.mean_length_m, cc.gap_percent), (0, None, None, None));
    // a's four costs all lie below b's and c's: exact p = 2 / C(8, 4) = 2/70; the rows of b and c
    // say they are worse than a.
    for r in [b, cc] {
        assert_eq!(r.mark, Some(RowMark::Worse), "{}", r.planner);
        assert!((r.p_value.unwrap() - 2.0 / 70.0).abs() < 1e-15);
        assert!((r.smallest_p.unwrap() - 2.0 / 70.0).abs() < 1e-15);
    }
    assert_eq!(a.mark, None);
}

#[test]
fn the_table_says_which_runs_each_column_counts() {
    let c = bay();
    let md = markdown(&c);
    let line = |p: &str| md.lines().find(|l| l.starts_with(&format!("| {p} |"))).unwrap().to_string();
    assert!(
        md.starts_with("| planner | feasible runs | best (pen.) | mean (pen.) | std (pen.) | worst (pen.) |"),
        "{md}"
    );
    // One format per column: costs 1 .. 23 with 4 significant digits of the smallest.
    assert!(line("b").starts_with("| b | 1/4 | 5.000 | 10.250 | "), "{}", line("b"));
    assert!(line("b").contains("| 5.000 / 5.000 | +150.00 / +150.00 | 50.00 | 100.00 |"), "{}", line("b"));
    assert!(line("b").ends_with("| worse (p=0.029) |"), "{}", line("b"));
    assert_eq!(line("c").matches(NO_FEASIBLE_RUN).count(), 4, "{}", line("c"));
    assert!(line("a").ends_with("| ref |"));
    let legend = legend(&c);
    for needle in ["penalties for violations included", "over the feasible runs only", "better / worse", "vs a:"] {
        assert!(legend.contains(needle), "{needle} missing from {legend}");
    }
    assert!(reference_line(&c).unwrap().contains("exact-one (exact), cost 2.000, "));
}

#[test]
fn two_runs_cannot_decide_and_say_so() {
    let records = vec![
        run("a", 0, 1.0, true, 1.0),
        run("a", 1, 2.0, true, 1.0),
        run("b", 0, 8.0, true, 1.0),
        run("b", 1, 9.0, true, 1.0),
    ];
    let c = from_records("scenario", &["bay"], &["a", "b"], 2, records);
    let b = &c.rows[1];
    // Fully separated, untied: the exact p is 2 / C(4, 2) = 1/3, also the smallest possible.
    assert_eq!(b.mark, Some(RowMark::Undecidable));
    assert!((b.smallest_p.unwrap() - 1.0 / 3.0).abs() < 1e-15);
    assert!(markdown(&c).contains("| undecidable (p ≥ 0.33) |"), "{}", markdown(&c));
}

#[test]
fn function_tables_give_zero_counts_with_their_denominator() {
    let f = |planner: &str, i: u64, cost: f64| RunRecord {
        problem: "sphere-d2-standard".into(),
        planner: planner.into(),
        run: i,
        cost,
        feasible: true,
        ..RunRecord::default()
    };
    let records = vec![
        f("pso", 0, 0.0),
        f("pso", 1, 1e-310),
        f("pso", 2, 3.0),
        f("de", 0, 1.5e-7),
        f("de", 1, 2.0),
        f("de", 2, 5.0),
    ];
    let c = from_records("functions", &["sphere-d2-standard"], &["pso", "de"], 3, records);
    let md = markdown(&c);
    // Bests 0 and 1.5e-7: scientific for the column, 0 exact; means 1 and 2.3333: fixed.
    assert!(md.contains("| sphere-d2-standard | pso | 0 | 1.000 | "), "{md}");
    assert!(md.contains("| sphere-d2-standard | de | 1.500e-7 | 2.333 | "), "{md}");
    // pso: one run exactly 0, two below 1e-300 (0 and 1e-310), of 3; de none.
    assert!(md.contains("| 1/3 | 2/3 |") && md.contains("| 0/3 | 0/3 |"), "{md}");
    assert!(legend(&c).contains("of all runs"));
}

#[test]
fn sampling_planners_are_marked_by_their_final_costs_like_any_planner() {
    // Samples, no iterations, a history per sample; two rrt-star runs found no path (infinite
    // cost, which ranks last).
    let sampled = |planner: &str, i: u64, cost: f64| RunRecord {
        samples: 3000,
        iterations: 0,
        history: vec![None, Some(cost)],
        ..run(planner, i, cost, cost.is_finite(), 100.0)
    };
    let mut records: Vec<RunRecord> =
        (0..8).map(|i| sampled("rrt-star", i, if i < 6 { 20.0 + i as f64 } else { f64::INFINITY })).collect();
    records.extend((0..8).map(|i| sampled("informed-rrt-star", i, 10.0 + i as f64)));
    records.extend((0..8).map(|i| RunRecord { iterations: 50, ..run("pso", i, 24.5 + i as f64, true, 100.0) }));
    let c = from_records("scenario", &["bay"], &["rrt-star", "informed-rrt-star", "pso"], 8, records);
    assert_eq!(c.rows[1].mark, Some(RowMark::Better), "{:?}", c.rows[1]);
    assert_eq!(c.rows[2].mark, Some(RowMark::Similar), "{:?}", c.rows[2]);
    assert!(c.rows[1].p_value.unwrap() < ALPHA);
    assert_eq!(c.rows[0].feasible_runs, 6);
}
