//! ijs2023's printed numbers: Tables 1-3 (T_best, T_mean and STD of the successful runs'
//! travel times in seconds, the success rate over 20 runs and the time per run on the
//! authors' machine) and the fleet experiment of section IV-C, as printed. Table 3 prints
//! neither STD nor run times; "—" (no successful run) is `None`.

/// The paper's planners, in its row order.
pub const PLANNERS: [&str; 6] = ["ijs", "js", "qpso", "pso", "hho", "mpa"];

/// One row of a table: T_best, T_mean, STD (s), success (fraction), run time (s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    pub t_best: Option<f64>,
    pub t_mean: Option<f64>,
    pub std: Option<f64>,
    pub success: f64,
    pub run_time_s: Option<f64>,
}

const fn full(t_best: f64, t_mean: f64, std: f64, success: f64, run_time_s: f64) -> Row {
    Row { t_best: Some(t_best), t_mean: Some(t_mean), std: Some(std), success, run_time_s: Some(run_time_s) }
}

const fn short(t_best: f64, t_mean: f64, success: f64) -> Row {
    Row { t_best: Some(t_best), t_mean: Some(t_mean), std: None, success, run_time_s: None }
}

const NONE: Row = Row { t_best: None, t_mean: None, std: None, success: 0.0, run_time_s: None };

/// One setting of Tables 1-3.
pub struct Setting {
    /// File-name-safe experiment id.
    pub id: &'static str,
    pub scenario: &'static str,
    pub title: &'static str,
    pub source: &'static str,
    /// Rows in [`PLANNERS`] order.
    pub rows: [Row; 6],
    /// Whether the setting has a current (the current-penalty box plots, Figs. 14-16).
    pub current: bool,
}

pub const SETTINGS: [Setting; 4] = [
    Setting {
        id: "table1-static",
        scenario: "ijs-static-1",
        title: "Table 1: static experiment I",
        source: "ijs2023, Table 1",
        rows: [
            full(26741.73, 27243.69, 281.27, 1.00, 51.90),
            full(28236.75, 28763.32, 369.12, 0.75, 52.45),
            full(27107.05, 27278.21, 127.49, 0.65, 51.77),
            full(29537.65, 30127.55, 534.59, 0.60, 52.41),
            full(27369.97, 28413.51, 657.77, 0.50, 87.84),
            full(29622.87, 30891.96, 827.48, 0.55, 51.64),
        ],
        current: false,
    },
    Setting {
        id: "table2-current",
        scenario: "ijs-current",
        title: "Table 2: current at 0.5 x the AUV's speed",
        source: "ijs2023, Table 2 and Fig. 14",
        rows: [
            full(27982.83, 29347.53, 840.24, 1.00, 54.62),
            full(30137.38, 33629.18, 2931.88, 0.70, 54.73),
            full(28190.70, 39278.23, 6394.63, 0.65, 56.93),
            full(30240.62, 37151.21, 5520.58, 0.60, 54.85),
            full(36513.56, 42980.60, 4481.69, 0.27, 100.32),
            full(36817.99, 47163.61, 8205.61, 0.50, 55.91),
        ],
        current: true,
    },
    Setting {
        id: "table3-strong-0.8",
        scenario: "ijs-strong-0.8",
        title: "Table 3: current at 0.8 x the AUV's speed",
        source: "ijs2023, Table 3 and Fig. 15",
        rows: [
            short(26142.71, 29813.04, 1.00),
            short(27271.98, 41802.74, 0.70),
            short(27039.31, 51941.12, 0.60),
            short(27251.74, 32234.78, 0.55),
            short(32225.29, 54922.90, 0.30),
            short(48019.19, 63591.34, 0.35),
        ],
        current: true,
    },
    Setting {
        id: "table3-strong-1.2",
        scenario: "ijs-strong-1.2",
        title: "Table 3: current at 1.2 x the AUV's speed",
        source: "ijs2023, Table 3 and Fig. 16",
        rows: [
            short(24565.41, 28427.09, 1.00),
            short(25569.06, 47805.70, 0.50),
            short(25074.04, 75846.74, 0.40),
            short(26282.91, 38740.45, 0.60),
            NONE,
            NONE,
        ],
        current: true,
    },
];

/// The paper's range of IJS's current penalty F_p2 over its successful paths (Fig. 14).
pub const IJS_CURRENT_PENALTY: (f64, f64) = (0.105, 0.166);

/// Static experiment I's printed shortest distance (m) and time (s): the time is the distance
/// over 1.542 m/s, though the distance cannot be recovered from the coordinates (A14).
pub const PRINTED_SHORTEST: (f64, f64) = (40_789.30, 26_452.21);

/// The fleet (section IV-C): common arrival time (s), success rate, total current penalty.
pub const FLEET: (f64, f64, f64) = (29_071.70, 0.65, 0.41);

impl Setting {
    /// The paper's row of `planner` (one of [`PLANNERS`]).
    pub fn row_of(&self, planner: &str) -> Option<Row> {
        PLANNERS.iter().position(|p| *p == planner).map(|i| self.rows[i])
    }
}
