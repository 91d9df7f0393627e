//! wpa2017's printed numbers: Table 4 (benchmark functions, 10 runs) and Table 5 (the path
//! experiment), transcribed as printed.

use super::super::{PaperCell, PaperTable};
use tidepath::optim::functions::Function;

/// Runs per cell of Table 4 ("optimize the function of 10 times", section IV.A).
pub const TABLE4_RUNS: u64 = 10;

/// Table 4's functions, in its order.
pub const FUNCTIONS: [Function; 5] =
    [Function::Easom, Function::Trid, Function::Sphere, Function::Rastrigin, Function::Quadric];

/// (optimal, worst, average, average time (s)) per function in [`FUNCTIONS`] order, as printed.
pub type Rows = [(f64, f64, f64, f64); 5];

pub const TABLE4_MWPA: Rows = [
    (-1.0, -0.9963, -0.9998, 2.8624),
    (-49.9999, -49.9961, -49.9995, 2.0192),
    (0.0, 0.0, 0.0, 0.7224),
    (0.0, 0.0, 0.0, 1.3567),
    (0.0, 0.0, 0.0, 2.0326),
];
pub const TABLE4_PSO: Rows = [
    (-1.0, -1.0, -1.0, 1.6213),
    (-50.0, -50.0, -50.0, 1.6011),
    (0.1674, 0.2843, 0.1835, 2.5340),
    (22.3114, 73.4401, 40.8835, 2.9841),
    (11.0788, 59.2433, 22.0566, 29.5144),
];
pub const TABLE4_GA: Rows = [
    (-1.0, -1.0, -1.0, 3.6351),
    (-50.0, -49.9986, -49.9996, 7.3417),
    (0.2011, 0.4269, 0.3378, 26.6625),
    (35.3936, 42.6349, 39.1620, 56.1134),
    (18.1023, 77.9319, 24.6056, 140.7281),
];

/// The paper's rows of `planner` (`mwpa`, `pso`, `ga`; WPA is not in Table 4).
pub fn table4_rows(planner: &str) -> Option<&'static Rows> {
    match planner {
        "mwpa" => Some(&TABLE4_MWPA),
        "pso" => Some(&TABLE4_PSO),
        "ga" => Some(&TABLE4_GA),
        _ => None,
    }
}

/// Table 4 keyed by our problem labels (in [`FUNCTIONS`] order).
pub fn table4(source: &str, labels: &[String]) -> PaperTable {
    let mut cells = Vec::new();
    for (i, label) in labels.iter().enumerate() {
        for planner in ["mwpa", "pso", "ga"] {
            let (best, worst, mean, time) = table4_rows(planner).expect("Table 4 planner")[i];
            cells.push(PaperCell {
                problem: label.clone(),
                planner: planner.into(),
                best: Some(best),
                worst: Some(worst),
                mean: Some(mean),
                time_s: Some(time),
                ..PaperCell::default()
            });
        }
    }
    PaperTable { source: source.into(), runs: Some(TABLE4_RUNS), cells }
}

/// Table 5: (path length, printed "m" but kilometres (docs/papers/wpa2017.md, A16); simulation
/// time (s)) of MWPA and WPA, one run each as far as the paper says.
pub const TABLE5_MWPA: (f64, f64) = (72.2521, 4.3712);
pub const TABLE5_WPA: (f64, f64) = (77.0736, 10.2408);

pub fn table5_row(planner: &str) -> Option<(f64, f64)> {
    match planner {
        "mwpa" => Some(TABLE5_MWPA),
        "wpa" => Some(TABLE5_WPA),
        _ => None,
    }
}
