//! amfa2015's printed numbers: Tables 2 and 4 (best, mean, standard deviation and the "0"
//! times column of AMFA, FA, PSO and GA over 30 runs), as printed. "00E + 00" is read as 0.
//! Table 2's AMFA Rosenbrock standard deviation (4.34e-7, below its mean although 21 of 30 runs
//! end at 0) cannot belong to those runs (docs/papers/amfa2015.md A15); it is kept as printed.

use tidepath::optim::functions::Function;

/// The six functions of Tables 1-4, in the tables' order.
pub const FUNCTIONS: [Function; 6] = [
    Function::Sphere,
    Function::Rosenbrock,
    Function::Rastrigin,
    Function::Griewank,
    Function::Ackley,
    Function::Zakharov,
];

/// The multimodal ones among them, where the paper claims AMFA beats PSO and GA on the small
/// ranges too.
pub const MULTIMODAL: [Function; 3] = [Function::Rastrigin, Function::Griewank, Function::Ackley];

/// The paper's planners, in its column order.
pub const PAPER_PLANNERS: [&str; 4] = ["amfa", "fa", "pso", "ga"];

/// (best, mean, std, "0" times) per function, in [`FUNCTIONS`] order.
pub type Rows = [(f64, f64, f64, u32); 6];

pub const TABLE2_AMFA: Rows = [
    (0.0, 5.58e-13, 1.73e-12, 22),
    (0.0, 2.38e-6, 4.34e-7, 21),
    (0.0, 0.0, 0.0, 30),
    (0.0, 3.20e-11, 1.12e-10, 26),
    (0.0, 1.75e-7, 7.23e-7, 21),
    (0.0, 1.6e-6, 9.0e-6, 4),
];
pub const TABLE2_FA: Rows = [
    (5.20e-9, 2.76e-6, 3.58e-6, 0),
    (3.66e-7, 6.70e-5, 1.07e-4, 0),
    (1.98e-7, 9.81e-6, 1.70e-4, 0),
    (1.35e-10, 5.36e-7, 8.51e-7, 0),
    (3.16e-5, 3.12e-4, 2.69e-4, 0),
    (1.7e-7, 2.4e-3, 3.8e-3, 0),
];
pub const TABLE2_PSO: Rows = [
    (5.05e-41, 1.75e-36, 9.19e-36, 0),
    (1.27e-2, 2.17e-1, 0.75, 0),
    (1.00, 4.88, 2.24, 0),
    (0.0, 5.6e-3, 8.3e-3, 7),
    (1.42e-14, 3.02e-1, 5.68e-1, 0),
    (4.6e-6, 6.7e-5, 6.8e-5, 0),
];
pub const TABLE2_GA: Rows = [
    (9.64e-7, 4.91e-6, 4.56e-6, 0),
    (7.8507, 51.3280, 29.7729, 0),
    (43.78, 58.04, 8.28, 0),
    (1.14e-7, 2.30e-2, 4.40e-2, 0),
    (1.34, 2.34, 3.71e-1, 0),
    (9.8e1, 1.8e2, 4.6e1, 0),
];

pub const TABLE4_AMFA: Rows = [
    (0.0, 0.0, 0.0, 30),
    (0.0, 0.0, 0.0, 30),
    (0.0, 0.0, 0.0, 30),
    (0.0, 0.0, 0.0, 30),
    (0.0, 0.0, 0.0, 30),
    (0.0, 1.5e-322, 0.0, 5),
];
pub const TABLE4_FA: Rows = [
    (5.87e-9, 4.00e-3, 2.15e-2, 0),
    (5.95e-7, 6.00e4, 3.28e5, 0),
    (6.11e-5, 8.13e1, 2.54e2, 0),
    (4.05e2, 5.72e2, 5.52e1, 0),
    (3.57e-5, 2.30e-3, 4.40e-3, 0),
    (2.0e-6, 1.5e-1, 7.6e-1, 0),
];
pub const TABLE4_PSO: Rows = [
    (5.23e-39, 8.73e-35, 2.16e-34, 0),
    (2.58e-2, 8.61e-1, 1.46, 0),
    (2.98, 6.40, 2.38, 0),
    (0.0, 2.30e-2, 2.85e-2, 2),
    (2.13e-14, 1.63, 1.12, 0),
    (4.8e1, 3.3e2, 2.8e2, 0),
];
pub const TABLE4_GA: Rows = [
    (3.42e-4, 1.71e-3, 1.52e-3, 0),
    (2.88, 7.67e1, 4.98e1, 0),
    (1.99e1, 6.08e1, 3.15e1, 0),
    (4.85e-4, 5.45e-2, 5.30e-2, 0),
    (4.10e-3, 7.7e-3, 3.1e-3, 0),
    (1.5e4, 3.0e4, 6.2e3, 0),
];

/// One of the paper's two benchmark tables.
pub struct Table {
    /// File-name-safe experiment id.
    pub id: &'static str,
    pub title: &'static str,
    /// "small" (Table 1's ranges) or "wide" (Table 3's).
    pub range: &'static str,
    pub source: &'static str,
    /// The paper's rows per planner, in [`PAPER_PLANNERS`] order.
    pub rows: [&'static Rows; 4],
}

pub const TABLES: [Table; 2] = [
    Table {
        id: "table2-small",
        title: "Table 2: small ranges",
        range: "small",
        source: "amfa2015, Table 2",
        rows: [&TABLE2_AMFA, &TABLE2_FA, &TABLE2_PSO, &TABLE2_GA],
    },
    Table {
        id: "table4-wide",
        title: "Table 4: wide ranges",
        range: "wide",
        source: "amfa2015, Table 4",
        rows: [&TABLE4_AMFA, &TABLE4_FA, &TABLE4_PSO, &TABLE4_GA],
    },
];

impl Table {
    /// The paper's row of `planner` (one of [`PAPER_PLANNERS`]).
    pub fn rows_of(&self, planner: &str) -> Option<&'static Rows> {
        PAPER_PLANNERS.iter().position(|p| *p == planner).map(|i| self.rows[i])
    }
}
