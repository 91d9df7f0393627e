use super::boxplot_figure::BoxStats;
use super::convergence_figure::{fill_history, Bands};
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
