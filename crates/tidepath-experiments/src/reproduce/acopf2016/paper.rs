//! What acopf2016 (Gao, Zhao, Guan, Wang & Zhang 2016, section 4) states: its environments
//! (Figs. 3-5, and a fourth it announces but never describes), its run parameters, and its
//! claims. The paper prints no table: every claim is about figures or about the method's
//! design (section 3.2), so each is read here as a measurable statement (docs/papers/acopf2016.md).

/// One environment: the built-in scenario that stands for it and the paper's figure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Environment {
    /// File-name-safe experiment id.
    pub id: &'static str,
    pub scenario: &'static str,
    /// The paper's figure, or why there is none.
    pub figure: &'static str,
    pub title: &'static str,
    /// What the built-in scenario holds, in words.
    pub setup: &'static str,
}

pub const ENVIRONMENTS: [Environment; 4] = [
    Environment {
        id: "fig3-glider-1",
        scenario: "glider-1",
        figure: "acopf2016, Fig. 3 (a figure, no numbers)",
        title: "Fig. 3: environment 1, fixed wave height, no current",
        setup: "the paper's 20 x 20 grid with blocked cells, one wave height everywhere, no current",
    },
    Environment {
        id: "fig4-glider-2",
        scenario: "glider-2",
        figure: "acopf2016, Fig. 4 (a figure, no numbers)",
        title: "Fig. 4: environment 2, wave height falling with x in the right half, no current",
        setup: "as environment 1, with the wave height constant for x <= 10 cells and falling with x beyond",
    },
    Environment {
        id: "fig5-glider-3",
        scenario: "glider-3",
        figure: "acopf2016, Fig. 5 (a figure, no numbers)",
        title: "Fig. 5: environment 3, falling waves and a south-east current band",
        setup: "as environment 2, plus a south-east subsurface current in 10 < x <= 20, 8 <= y <= 16 (cells)",
    },
    Environment {
        id: "env4-glider-4",
        scenario: "glider-4",
        figure: "nowhere: the paper announces a fourth environment but never describes it",
        title: "Environment 4 (ours): the composite of Fig. 2 with a time trade-off",
        setup: "tidepath's design for the paper's undescribed fourth environment (docs/papers/acopf2016.md A11)",
    },
];

/// The paper's iterations T and ants K (section 4), and `--quick`'s.
pub const ITERATIONS: u64 = 60;
pub const ANTS: usize = 30;
pub const QUICK_ITERATIONS: u64 = 15;
pub const QUICK_ANTS: usize = 10;

/// The planners: the paper's improved ACOPF first (the others are marked against it), then
/// the plain ACO (eqs. 4-6 and 9) the paper improves on.
pub const PLANNERS: [&str; 2] = ["acopf", "aco"];

/// The ants' objective at the paper's setting: eqs. 6, 12, 13 deposit Q/L with L the path
/// length. `COST`: the scenario's cost model (the glider's travel time), tidepath's variant.
pub const PAPER_OBJECTIVE: &str = "length";
pub const COST_OBJECTIVE: &str = "cost";

/// The claims, as the report words them.
pub const CLAIM_CONVERGES: &str = "ACOPF converges faster than ACO (fewer iterations to reach its final best; \
     section 3.1: the potential field \"reduces inferior solutions\", section 5: it \"overcomes the deficiency of \
     the traditional ant colony algorithm\")";
pub const CLAIM_SHORTER: &str =
    "ACOPF finds shorter paths than ACO (section 3.2: \"shortening the path length\"; failed runs ranked last)";
pub const CLAIM_QUICKER: &str = "ACOPF finds quicker paths than ACO, in the glider's travel time (section 3.2: \
     \"increasing the WG speed and shortening the time of travel\"; failed runs ranked last)";
pub const CLAIM_TWO_OPTIMA: &str = "In environment 1 there are two optimal paths of equal length (section 4, Fig. 3)";
pub const CLAIM_WAVES: &str = "ACOPF's paths follow the larger waves (section 4, Fig. 4: \"along the locations of \
     larger wave energy\"): a higher mean wave height along the path than ACO's";
pub const CLAIM_CURRENT: &str = "ACOPF's paths use the current (section 4, Fig. 5): a larger share of the path \
     length inside the current band than ACO's";

/// Which environment carries the claims on one environment: 1 for [`CLAIM_TWO_OPTIMA`], 2 for
/// [`CLAIM_WAVES`], 3 for [`CLAIM_CURRENT`] (indices into [`ENVIRONMENTS`]).
pub const TWO_OPTIMA_ENV: usize = 0;
pub const WAVES_ENV: usize = 1;
pub const CURRENT_ENV: usize = 2;
