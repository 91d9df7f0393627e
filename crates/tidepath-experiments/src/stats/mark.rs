//! The '+', '≈', '-' marks against the reference planner.

use std::fmt;

use serde::{Deserialize, Serialize};

use super::rank_sum::{test_without_nan, RankSumResult};

/// The '+', '≈', '-' marks of the papers' tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Mark {
    /// The reference planner is significantly better (lower costs).
    Better,
    /// No significant difference.
    Similar,
    /// The reference planner is significantly worse (higher costs).
    Worse,
}

impl Mark {
    pub fn symbol(self) -> &'static str {
        match self {
            Mark::Better => "+",
            Mark::Similar => "≈",
            Mark::Worse => "-",
        }
    }
}

impl fmt::Display for Mark {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

/// Marks `other` against the reference planner (the first planner listed) as lfhh2019 does:
/// '+' means the reference is significantly better. Costs are minimised, so with `p < alpha`
/// the mark is [`Mark::Better`] when the reference's U is below its null mean `n_r n_o / 2`
/// (its mean rank is lower: its costs tend to be smaller) and [`Mark::Worse`] when above;
/// otherwise [`Mark::Similar`]. The returned result is the test of `reference` against `other`,
/// so `u_x` is the reference's U.
pub fn compare_to_reference(reference: &[f64], other: &[f64], alpha: f64) -> (Mark, RankSumResult) {
    let (result, nr, no) = test_without_nan(reference, other);
    let null_mean = nr as f64 * no as f64 / 2.0;
    let mark = if result.p_value < alpha {
        if result.u_x < null_mean {
            Mark::Better
        } else if result.u_x > null_mean {
            Mark::Worse
        } else {
            Mark::Similar
        }
    } else {
        Mark::Similar
    };
    (mark, result)
}
