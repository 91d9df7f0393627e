//! lfhh2019's printed numbers (docs/papers/lfhh2019.md, experiments): Table 2 (2-D), Table 3
//! (3-D, LFHH's cells and the other methods' ranges), the ablation's ranges (Tables 4-5) and
//! the start/target pairs, in the paper's kilometres.

use super::super::{PaperCell, PaperTable};

/// Runs per cell ("every algorithm runs 30 times").
pub const RUNS: u64 = 30;

/// Table 2's and Table 3's algorithms, in the paper's column order, as (planner id, name).
pub const ALGORITHMS: [(&str, &str); 7] = [
    ("lfhh", "LFHH"),
    ("fhh", "FHH"),
    ("fhh-lts", "FHH+LTS"),
    ("eda-g", "EDA-G"),
    ("ade", "aDE"),
    ("rrt-star", "RRT*"),
    ("prm-star", "PRM*"),
];

/// A start -> target pair as printed: (X, Y) in 2-D, (X, Y, Z) in 3-D, km.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair {
    pub start: [f64; 3],
    pub target: [f64; 3],
}

/// One test case: the built-in scenario and the pair flown on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Case {
    pub scenario: &'static str,
    /// 0 for 2-D, else the 3-D scenario's number (Table 5's grouping, A11).
    pub group: u8,
    pub pair: Pair,
    pub three_d: bool,
}

const fn p2(s: [f64; 2], t: [f64; 2]) -> Pair {
    Pair { start: [s[0], s[1], 0.0], target: [t[0], t[1], 0.0] }
}

const fn p3(start: [f64; 3], target: [f64; 3]) -> Pair {
    Pair { start, target }
}

/// Table 2's pairs on `lfhh-2d`.
pub const CASES_2D: [Case; 3] = [
    Case { scenario: "lfhh-2d", group: 0, pair: p2([13.0, 0.0], [6.0, 39.0]), three_d: false },
    Case { scenario: "lfhh-2d", group: 0, pair: p2([6.0, 0.0], [8.0, 39.0]), three_d: false },
    Case { scenario: "lfhh-2d", group: 0, pair: p2([5.0, 0.0], [12.0, 39.0]), three_d: false },
];

/// Table 3's pairs, grouped into scenarios as Table 5 groups them (A11).
pub const CASES_3D: [Case; 6] = [
    Case { scenario: "lfhh-3d-1", group: 1, pair: p3([12.0, 0.0, 7.0], [3.0, 39.0, 15.0]), three_d: true },
    Case { scenario: "lfhh-3d-1", group: 1, pair: p3([14.0, 0.0, 8.0], [5.0, 39.0, 13.0]), three_d: true },
    Case { scenario: "lfhh-3d-2", group: 2, pair: p3([13.0, 0.0, 7.0], [7.0, 39.0, 5.0]), three_d: true },
    Case { scenario: "lfhh-3d-2", group: 2, pair: p3([12.0, 0.0, 7.0], [13.0, 39.0, 5.0]), three_d: true },
    Case { scenario: "lfhh-3d-3", group: 3, pair: p3([9.0, 0.0, 6.0], [15.0, 39.0, 4.0]), three_d: true },
    Case { scenario: "lfhh-3d-3", group: 3, pair: p3([12.0, 0.0, 5.0], [5.0, 39.0, 8.0]), three_d: true },
];

impl Case {
    /// The case's label in tables: `2d (13,0)->(6,39)`, `3d-1 (12,0,7)->(3,39,15)`.
    pub fn label(&self) -> String {
        let f = |v: &[f64; 3]| {
            let n = if self.three_d { 3 } else { 2 };
            let parts: Vec<String> = v[..n].iter().map(|x| format!("{x}")).collect();
            format!("({})", parts.join(","))
        };
        let head = if self.three_d { format!("3d-{}", self.group) } else { "2d".to_string() };
        format!("{head} {}->{}", f(&self.pair.start), f(&self.pair.target))
    }

    /// A paper point (km) in tidepath's frame (m): paper X is tidepath y, paper Y (the
    /// direction of travel) is tidepath x, paper Z is z = Z - 20 km; in 2-D, z is `z2d`.
    pub fn world_point(self, p: [f64; 3], z2d: f64) -> [f64; 3] {
        let z = if self.three_d { (p[2] - 20.0) * 1000.0 } else { z2d };
        [p[1] * 1000.0, p[0] * 1000.0, z]
    }
}

/// Table 2: (mean F, std F, mean time per run (s)) per algorithm in [`ALGORITHMS`] order and
/// pair in [`CASES_2D`] order, `None` where the paper prints nothing.
pub type Cell = (f64, Option<f64>, Option<f64>);
pub const TABLE2: [[Cell; 7]; 3] = [
    [
        (0.660, Some(0.171), Some(1.91)),
        (4.56, None, Some(11.0)),
        (3.69, None, Some(10.2)),
        (2.07, None, Some(25.1)),
        (5.66, None, Some(20.2)),
        (2.04, None, Some(2.75)),
        (1.04, None, Some(1.48)),
    ],
    [
        (0.692, Some(0.144), Some(2.47)),
        (4.12, None, None),
        (3.71, None, None),
        (1.77, None, None),
        (5.56, None, None),
        (2.43, None, None),
        (0.899, None, None),
    ],
    [
        (0.734, Some(0.175), Some(2.94)),
        (4.12, None, None),
        (3.80, None, None),
        (1.99, None, None),
        (5.52, None, None),
        (2.57, None, None),
        (1.12, None, None),
    ],
];

/// The rank-sum marks the transcription prints in Table 2 (pair index, planner, mark): only
/// PRM* on the second pair, "≈".
pub const TABLE2_MARKS: [(usize, &str, &str); 1] = [(1, "prm-star", "≈")];

/// Table 3: LFHH's (mean F, mean time per run (s)) per case in [`CASES_3D`] order.
pub const TABLE3_LFHH: [(f64, f64); 6] =
    [(0.662, 0.59), (0.656, 0.56), (0.627, 2.57), (0.653, 1.09), (0.710, 1.66), (0.734, 1.36)];

/// Table 3: every other method's range of mean F over the six cases, (low, high).
pub const TABLE3_RANGES: [(&str, f64, f64); 6] = [
    ("fhh", 3.9, 5.0),
    ("fhh-lts", 3.2, 4.5),
    ("eda-g", 2.8, 3.1),
    ("ade", 6.2, 6.4),
    ("rrt-star", 3.1, 3.6),
    ("prm-star", 2.6, 2.8),
];

/// The ablation (Tables 4-5) as the transcription gives it: without smoothing F is about
/// 2.9-3.1 and a run takes 10-14 s; without LTS or the window F is similar and runs longer.
pub const NO_SMOOTH_F: (f64, f64) = (2.9, 3.1);
pub const NO_SMOOTH_TIME_S: (f64, f64) = (10.0, 14.0);

/// The sweeps of Figs. 15-16 and the pair the paper found best.
pub const LAMBDAS: [f64; 20] =
    [0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0];
pub const PERIODS: [u64; 4] = [5, 10, 15, 20];
pub const POPULATIONS: [usize; 10] = [100, 200, 300, 400, 500, 600, 700, 800, 900, 1000];
pub const BEST_LAMBDA: f64 = 0.08;
pub const BEST_PERIOD: u64 = 5;
/// The paper's LFHH: λ = 0.08, T = 5, NP = 200, 100 (2-D) and 300 (3-D) generations per
/// planning.
pub const POPULATION: usize = 200;
pub const GENERATIONS_2D: u64 = 100;
pub const GENERATIONS_3D: u64 = 300;
/// RRT*'s iterations and PRM*'s nodes.
pub const SAMPLES: u64 = 300;
/// A6/A8: the score of a planning that found no path.
pub const NO_PATH_F: f64 = 5.0;
/// F below this is feasible (any curvature or collision violation adds at least 2).
pub const FEASIBLE_BELOW: f64 = 2.0;

/// Table 2 keyed by case label and planner id.
pub fn table2(labels: &[String]) -> PaperTable {
    let mut cells = Vec::new();
    for (k, label) in labels.iter().enumerate().take(3) {
        for (i, (id, _)) in ALGORITHMS.iter().enumerate() {
            let (mean, std, time) = TABLE2[k][i];
            cells.push(PaperCell {
                problem: label.clone(),
                planner: id.to_string(),
                mean: Some(mean),
                std,
                time_s: time,
                ..PaperCell::default()
            });
        }
    }
    PaperTable { source: "lfhh2019, Table 2".into(), runs: Some(RUNS), cells }
}

/// Table 3's LFHH cells keyed by case label (the others print ranges only).
pub fn table3(labels: &[String]) -> PaperTable {
    let cells = labels
        .iter()
        .zip(TABLE3_LFHH)
        .map(|(label, (mean, time))| PaperCell {
            problem: label.clone(),
            planner: "lfhh".into(),
            mean: Some(mean),
            time_s: Some(time),
            ..PaperCell::default()
        })
        .collect();
    PaperTable { source: "lfhh2019, Table 3".into(), runs: Some(RUNS), cells }
}
