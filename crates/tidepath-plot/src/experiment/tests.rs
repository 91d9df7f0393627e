use super::boxplot_figure::BoxStats;
use super::convergence_figure::{fill_history, gap_text, Bands};
use super::cost_axis::CostAxis;
use super::layout::grid_shape;
use super::*;

#[test]
fn grid_stays_within_four_columns() {
    assert_eq!(grid_shape(1), (1, 1));
    assert_eq!(grid_shape(2), (2, 1));
    assert_eq!(grid_shape(6), (3, 2));
    assert_eq!(grid_shape(12), (4, 3));
    assert_eq!(grid_shape(13), (4, 4));
}

#[test]
fn histories_fill_gaps_as_best_so_far() {
    let h = [f64::INFINITY, f64::NAN, 5.0, f64::NAN, 3.0];
    assert_eq!(fill_history(&h), vec![f64::INFINITY, f64::INFINITY, 5.0, 5.0, 3.0]);
    let b = Bands::of(&[vec![4.0, 2.0, 1.0], vec![8.0], vec![]]);
    assert_eq!(b.runs, 2);
    assert_eq!(b.median, vec![6.0, 5.0, 4.5]);
    assert_eq!(b.q1, vec![5.0, 3.5, 2.75]);
}

#[test]
fn quartile_gaps_while_most_runs_lack_a_cost() {
    let inf = f64::INFINITY;
    let b = Bands::of(&[vec![inf, 1.0], vec![inf, 2.0], vec![3.0, 3.0]]);
    assert!(b.median[0].is_infinite() && b.median[1] == 2.0);
}

#[test]
fn boxes_follow_tukey() {
    let mut costs: Vec<f64> = (1..=9).map(f64::from).collect();
    costs.extend([100.0, f64::INFINITY]);
    let b = BoxStats::of(&costs).unwrap();
    assert_eq!((b.q1, b.median, b.q3), (3.25, 5.5, 7.75));
    assert_eq!((b.whisker_lo, b.whisker_hi), (1.0, 9.0));
    assert_eq!(b.outliers, vec![100.0]);
    assert_eq!(b.non_finite, 1);
    let flat = BoxStats::of(&[2.0; 5]).unwrap();
    assert_eq!((flat.whisker_lo, flat.whisker_hi, flat.outliers.len()), (2.0, 2.0, 0));
    assert!(BoxStats::of(&[f64::INFINITY]).is_none());
}

#[test]
fn zeros_sit_below_the_smallest_positive_cost_on_a_log_axis() {
    let axis = CostAxis::for_values([0.0, 3e-8, 5.0, 200.0]).unwrap();
    let CostAxis::Log { lo, hi, zero_at: Some(z), decades } = axis else { panic!("{axis:?}") };
    // 3e-8 to 200 is labelled every other decade, from 1e-8 up to 1e4; the zero line sits
    // a tenth of those 12 decades below 1e-8.
    assert!((z.log10() + 9.2).abs() < 1e-9 && lo < z && hi == 1e4);
    assert_eq!(decades.exponents(), [-8, -6, -4, -2, 0, 2, 4]);
    assert_eq!(axis.map(0.0), z);
    assert_eq!(axis.map(5.0), 5.0);
    assert_eq!(axis.desc("best cost"), "best cost (log scale, 0 below break)");
    assert_eq!(
        (axis.tick_label(z), axis.tick_label(1e4), axis.tick_label(1e-8)),
        (String::new(), "1e4".into(), "1e-8".into())
    );
    assert!(matches!(CostAxis::for_values([-1.0, 0.0, 500.0]), Some(CostAxis::Linear { .. })));
    assert!(matches!(CostAxis::for_values([4.0, 4.0]), Some(CostAxis::Linear { lo, hi }) if lo < 4.0 && hi > 4.0));
    assert!(CostAxis::for_values([f64::NAN, f64::INFINITY]).is_none());
}

#[test]
fn records_group_by_first_appearance() {
    let rec = |problem: &str, planner: &str, cost: f64| RunRecord {
        problem: problem.into(),
        planner: planner.into(),
        run: 0,
        seed: 0,
        cost,
        feasible: true,
        length_m: None,
        travel_time_s: None,
        evaluations: 0,
        iterations: 1,
        elapsed_s: 0.0,
        stop_reason: tidepath::optim::StopReason::MaxIterations,
        history: vec![None, Some(cost)],
        waypoints: vec![],
        ..RunRecord::default()
    };
    let records = [rec("b", "pso", 1.0), rec("a", "de", 2.0), rec("b", "de", 3.0), rec("b", "pso", 4.0)];
    let g = group_runs(&records);
    assert_eq!(g.iter().map(|p| p.problem).collect::<Vec<_>>(), ["b", "a"]);
    assert_eq!(g[0].planners[0].costs, vec![1.0, 4.0]);
    assert_eq!(g[0].planners[0].histories[1], vec![f64::INFINITY, 4.0]);
    assert_eq!(planner_order(&g), ["pso", "de"]);
}

/// A sampling planner's runs: no path for the first ~100 samples, then a best cost that falls
/// in steps towards `floor` (one history entry per sample).
fn sampling_runs(planner: &str, runs: u64, samples: usize, floor: f64, seed: u64) -> Vec<RunRecord> {
    let mut state = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    let mut next = move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..runs)
        .map(|run| {
            let first = 60 + (next() * 80.0) as usize;
            let mut best = floor * (1.5 + 0.4 * next());
            let history: Vec<Option<f64>> = (0..samples)
                .map(|k| {
                    if k < first {
                        return None;
                    }
                    if next() < 0.01 {
                        best = floor + (best - floor) * (0.6 + 0.3 * next());
                    }
                    Some(best)
                })
                .collect();
            RunRecord {
                problem: "headland".into(),
                planner: planner.into(),
                run,
                cost: best,
                feasible: true,
                samples: samples as u64,
                history,
                ..RunRecord::default()
            }
        })
        .collect()
}

fn headland_runs(samples: usize, runs: u64) -> Vec<RunRecord> {
    let mut records = sampling_runs("rrt-star", runs, samples, 1300.0, 1);
    records.extend(sampling_runs("informed-rrt-star", runs, samples, 1262.0, 2));
    records
}

fn visibility(cost: f64) -> tidepath_experiments::compare::Reference {
    tidepath_experiments::compare::Reference {
        planner: "visibility".into(),
        status: "exact".into(),
        cost,
        length_m: None,
        travel_time_s: None,
        waypoints: vec![],
    }
}

fn save(name: &str, svg: &str) {
    if let Some(dir) = std::env::var_os("TIDEPATH_PLOT_DIR") {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(std::path::Path::new(&dir).join(name), svg).unwrap();
    }
}

#[test]
fn a_reference_draws_its_line_and_every_final_gap() {
    let records = headland_runs(3000, 5);
    let mut c = tidepath_experiments::compare::Comparison {
        tidepath_version: String::new(),
        kind: "scenario".into(),
        problems: vec!["headland".into()],
        planners: vec!["rrt-star".into(), "informed-rrt-star".into()],
        runs: 5,
        master_seed: 1,
        budget: Default::default(),
        rows: vec![],
        records,
        total_wall_s: 0.0,
        reference: Some(visibility(1250.0)),
        complete: true,
        finished_runs: 10,
        reference_planner: Some("visibility".into()),
        smoother: None,
    };
    let runs = c.records.clone();
    let problems = group_runs(&runs);
    let ctx = ConvergenceContext::of(&c);
    assert_eq!(ctx.sample_planners, ["rrt-star", "informed-rrt-star"]);
    let svg = render_convergence_figure_with("headland", &problems, &ctx).unwrap();
    save("convergence_reference.svg", &svg);
    assert!(svg.contains("reference visibility (exact): 1250"), "no reference label");
    assert!(svg.contains(r##"stroke="#005A32""##), "no reference line");
    assert!(svg.contains("\nsamples\n"), "x axis is not in samples");
    // Each planner's final median gap, at its curve's end and in its legend entry.
    for p in ["rrt-star", "informed-rrt-star"] {
        let bands = Bands::of(&problems[0].planners.iter().find(|r| r.planner == p).unwrap().histories);
        let gap = gap_text(tidepath_experiments::compare::gap_percent(*bands.median.last().unwrap(), 1250.0));
        assert!(gap.starts_with('+'), "{p}: {gap}");
        assert!(svg.contains(&format!("{p} (final gap {gap})")), "{p}: no legend gap {gap}");
        assert!(svg.contains(&format!("\n{gap}\n")), "{p}: no gap label {gap}");
    }
    // A planner with at most half of its runs feasible ends on penalties: no gap, the count.
    for r in c.records.iter_mut().filter(|r| r.planner == "rrt-star" && r.run >= 2) {
        r.feasible = false;
    }
    let svg = render_convergence_figure_with("headland", &problems, &ConvergenceContext::of(&c)).unwrap();
    assert!(svg.contains("rrt-star (2/5 runs feasible)") && svg.contains("\n2/5 feasible\n"));
    assert!(svg.contains("informed-rrt-star (final gap +"));
    // A reference alone makes no chart: a panel without a history still says so.
    let graph =
        [RunRecord { problem: "headland".into(), planner: "astar".into(), expansions: 9, ..RunRecord::default() }];
    let mut only = ConvergenceContext::of_records(&graph);
    only.references = vec![ReferenceCost { problem: "headland", planner: "visibility", status: "exact", cost: 1250.0 }];
    let svg = render_convergence_figure_with("graph", &group_runs(&graph), &only).unwrap();
    assert!(svg.contains("\nno convergence history\n"));
    // Without a reference: no line, no gaps.
    c.reference = None;
    let svg = render_convergence_figure_with("headland", &problems, &ConvergenceContext::of(&c)).unwrap();
    assert!(!svg.contains("reference visibility") && !svg.contains("final gap") && !svg.contains(" %\n"));
}

#[test]
fn the_x_axis_names_what_the_histories_count() {
    use super::convergence_figure::x_axis_desc;
    let sampled = RunRecord { samples: 40, history: vec![None; 40], ..RunRecord::default() };
    let iterated = RunRecord { iterations: 40, evaluations: 800, ..RunRecord::default() };
    let seeded = RunRecord { iterations: 40, expansions: 90, samples: 3, ..RunRecord::default() };
    assert_eq!(HistoryUnit::of(&sampled), HistoryUnit::Samples);
    assert_eq!(HistoryUnit::of(&iterated), HistoryUnit::Iterations);
    assert_eq!(HistoryUnit::of(&seeded), HistoryUnit::Iterations);
    let (s, i) = (HistoryUnit::Samples, HistoryUnit::Iterations);
    assert_eq!(x_axis_desc(&[("rrt-star", s), ("prm-star", s)]), "samples");
    assert_eq!(x_axis_desc(&[("pso", i), ("de", i)]), "iteration");
    assert_eq!(
        x_axis_desc(&[("pso", i), ("rrt-star", s), ("prm-star", s)]),
        "iteration (samples for rrt-star, prm-star)"
    );
    // A mixed panel in the figure says so.
    let mut records = sampling_runs("rrt-star", 3, 200, 10.0, 3);
    records.extend((0..3).map(|run| RunRecord {
        problem: "headland".into(),
        planner: "pso".into(),
        run,
        cost: 12.0,
        iterations: 30,
        history: (0..31).map(|k| Some(20.0 - k as f64 / 4.0)).collect(),
        ..RunRecord::default()
    }));
    let ctx = ConvergenceContext::of_records(&records);
    let svg = render_convergence_figure_with("mixed", &group_runs(&records), &ctx).unwrap();
    save("convergence_mixed_units.svg", &svg);
    assert!(svg.contains("\niteration (samples for rrt-star)\n"), "mixed axis label missing");
    let svg = render_convergence_figure("plain", &group_runs(&records)).unwrap();
    assert!(svg.contains("\niteration\n"));
}

#[test]
fn gaps_read_as_signed_percentages() {
    assert_eq!(gap_text(3.06), "+3.1 %");
    assert_eq!(gap_text(-0.02), "+0.0 %");
    assert_eq!(gap_text(-2.0), "-2.0 %");
    assert_eq!(gap_text(153.6), "+154 %");
}

#[test]
fn staggered_labels_keep_apart_and_inside() {
    use super::convergence_figure::stagger;
    let y = stagger(&[100, 102, 101, 300], 16, 20, 310);
    assert_eq!(y, vec![100, 132, 116, 300]);
    // Crowded at the bottom: pushed up, never below `hi` or above `lo`.
    let y = stagger(&[305, 305, 305], 16, 20, 310);
    assert_eq!(y, vec![278, 294, 310]);
    let y = stagger(&[0, 0, 0], 16, 20, 310);
    assert_eq!(y, vec![20, 36, 52]);
}

#[test]
fn long_histories_draw_thinned_with_their_ends() {
    use crate::convergence::{thin, MAX_DRAWN_POINTS};
    // A noisy median 20,000 samples long that becomes finite at sample 137.
    let v: Vec<f64> =
        (0..20_000).map(|k| if k < 137 { f64::INFINITY } else { 100.0 + ((k * 7919) % 1000) as f64 }).collect();
    let keep = thin(&[&v], MAX_DRAWN_POINTS);
    assert!(keep.len() <= MAX_DRAWN_POINTS + 4, "{} points", keep.len());
    for k in [0, 136, 137, 19_999] {
        assert!(keep.contains(&k), "{k} dropped");
    }
    assert!(keep.windows(2).all(|w| w[0] < w[1]));
    // A step curve keeps both ends of every step, so it draws exactly.
    let steps: Vec<f64> = (0..20_000).map(|k| 50.0 - (k / 1000) as f64).collect();
    let keep = thin(&[&steps], MAX_DRAWN_POINTS);
    assert_eq!(keep.len(), 40);
    assert!(keep.contains(&999) && keep.contains(&1000) && keep.contains(&19_999));
    // Short ones are drawn whole.
    assert_eq!(thin(&[&steps[..50]], MAX_DRAWN_POINTS), (0..50).collect::<Vec<_>>());
}

#[test]
fn twenty_runs_of_twenty_thousand_samples_draw_quickly() {
    let records = headland_runs(20_000, 20);
    let ctx = ConvergenceContext::of_records(&records);
    let start = std::time::Instant::now();
    let svg = render_convergence_figure_with("long", &group_runs(&records), &ctx).unwrap();
    let took = start.elapsed();
    save("convergence_long.svg", &svg);
    // Two planners, each a median line and a band of two edges, at most 2000 points each.
    assert!(svg.len() < 400_000, "{} bytes", svg.len());
    assert!(took.as_secs_f64() < 2.0, "{took:?}");
}
