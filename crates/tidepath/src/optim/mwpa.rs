//! The modified wolf pack algorithm (MWPA) of wpa2017: Zhang et al., "Three-Dimensional
//! Underwater Path Planning Based on Modified Wolf Pack Algorithm", IEEE Access 2017,
//! section III. The skeleton is the original WPA (`wpa.rs`); MWPA changes:
//!
//! ```text
//! scouting (eqs. 22-23)  the h directions x + sin(2 pi p/h) step_a (eq. 22, printed
//!                        sin(2 pi + p/h)) plus the interactive candidate
//!                        x + phi (lead - x) + varphi (x_a - x_b), phi ~ U[0,1]^D,
//!                        varphi ~ U[-1,1]^D, a != b two other scouts (eq. 23);
//!                        best of the h + 1, kept if better
//! raiding (eqs. 25-26)   s_i = w_i step_b for the calling phase (eq. 25's one update per
//!                        iteration k, from the step reset to step_b; `compound_raid_step`:
//!                        s_i <- w_i s_i before every raid instead),
//!                        x_id += s_id sign(g_d - x_id); w_i from the wolf's own cost:
//!                        w_min + (w_max - w_min)(F_i - F_min)/(F_avg - F_min) if F_i <= F_avg,
//!                        else w_max (eq. 26 as printed is degenerate)
//! d_near (eq. 27)        sum_d |max_d - min_d| / (D omega), compared with the mean absolute
//!                        per-dimension distance to the lead
//! siege (eqs. 28-29)     x_d' = x_d + xi lambda step_c |G_d - x_d|, xi <- c xi from xi = M = 1,
//!                        lambda ~ U[-1, 1] per wolf, greedy
//! renewal                R ~ U{N/(2 beta) .. N/beta} worst wolves replaced (printed N/2xbeta)
//! ```
//!
//! F_min is the lead's cost and F_avg the pack's mean (finite) cost at the start of the
//! calling phase. Step 7 (section III.B): after renewal, every wolf whose path is infeasible
//! (the objective's [`feasible`](super::Objective::feasible)) becomes a copy of the best
//! feasible wolf; objectives without constraints skip it (docs/papers/wpa2017.md, A17). The
//! engine is shared with `wpa` (`wolf.rs`).

use super::wolf::{Adaptive, Pack, Variant};
use super::wpa::WpaParams;
use super::MAX_POPULATION;
use crate::error::Result;
use crate::params::{field_error, Bound, Checked, Range};

crate::params! {
    /// MWPA parameters. Defaults: wpa2017's path experiment (section IV), steps as fractions
    /// of each dimension's range.
    pub struct MwpaParams {
        /// Wolves N.
        population: usize = 300, Range::integer(4, MAX_POPULATION as u64), "wpa2017 section IV";
        /// Most scouting rounds, and most raids of a wolf per calling phase, T_max.
        t_max: usize = 30, Range::integer(1, 100_000), "wpa2017 section IV";
        /// Distance factor omega of d_near (eq. 27).
        omega: f64 = 50.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Unbounded }, "wpa2017 section IV";
        /// Scouting step step_a, as a fraction of each dimension's range (0.2 km of 50 km).
        step_a: f64 = 0.004, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "wpa2017 section IV";
        /// Initial raid step step_b, as a fraction of each dimension's range (0.4 km of 50 km).
        step_b: f64 = 0.008, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "wpa2017 section IV";
        /// Siege step step_c, as a fraction of each dimension's range (0.1 km of 50 km).
        step_c: f64 = 0.002, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "wpa2017 section IV";
        /// Scout ratio alpha: T scouts with T in [N/(alpha+1), N/alpha].
        alpha: f64 = 4.0, Range::Number { lo: Bound::Closed(1.0), hi: Bound::Unbounded }, "wpa2017 section IV";
        /// Renewal factor beta: R wolves renewed with R in [N/(2 beta), N/beta].
        beta: f64 = 5.0, Range::Number { lo: Bound::Closed(1.0), hi: Bound::Unbounded }, "wpa2017 section IV";
        /// Scouting directions h (h + 1 candidates with the interactive one).
        h: usize = 4, Range::integer(1, 1000), "tidepath (not given in wpa2017)";
        /// Smallest raid weight w_min (eq. 26), for the wolves closest in cost to the lead.
        w_min: f64 = 0.4, Range::closed(0.0, 1.0), "tidepath (wpa2017 says w in [0, 1])";
        /// Largest raid weight w_max (eq. 26), for wolves worse than the pack's mean.
        w_max: f64 = 1.0, Range::closed(0.0, 1.0), "tidepath (wpa2017 says w in [0, 1])";
        /// Siege decay c (eq. 29): xi <- c xi each iteration, from xi = 1.
        c: f64 = 0.99, Range::closed(0.9, 0.999), "wpa2017 eq. 29 (range), 0.99 chosen";
        /// Raid step update (eq. 25): false, s = w step_b for all raids of a calling phase
        /// (one update per iteration k); true, s <- w s before every raid from s = step_b.
        compound_raid_step: bool = false, Range::Flag, "tidepath (docs/papers/wpa2017.md)";
        /// Step 7: after each iteration, wolves whose path is infeasible become copies of the
        /// best feasible wolf (each moved wolf's check counts as an evaluation).
        replace_infeasible: bool = true, Range::Flag, "wpa2017 section III.B, Step 7";
    }
    check = check_weights;
}

fn check_weights(p: &MwpaParams, prefix: &str) -> Result<()> {
    if p.w_min > p.w_max {
        return Err(field_error(prefix, "w_min", format!("must be at most w_max ({}), got {}", p.w_max, p.w_min)));
    }
    Ok(())
}

impl MwpaParams {
    /// wpa2017's path experiment (section IV): the defaults.
    pub fn wpa2017_path() -> Self {
        Self::default()
    }

    /// wpa2017's benchmark setting (Table 3, with docs/papers/wpa2017.md A12): N = 100,
    /// T_max = 20, omega = 500, alpha = 4 (printed 0.8), beta = 6, step_a = range/1000,
    /// step_b = range/500, step_c = range/2000; w and c as in the defaults.
    pub fn wpa2017() -> Self {
        let w = WpaParams::wpa2017();
        Self {
            population: w.population,
            t_max: w.t_max,
            omega: w.omega,
            step_a: w.step_a,
            step_b: w.step_b,
            step_c: w.step_c,
            alpha: w.alpha,
            beta: w.beta,
            h: w.h,
            ..Self::default()
        }
    }

    fn common(&self) -> WpaParams {
        WpaParams {
            population: self.population,
            t_max: self.t_max,
            omega: self.omega,
            step_a: self.step_a,
            step_b: self.step_b,
            step_c: self.step_c,
            alpha: self.alpha,
            beta: self.beta,
            h: self.h,
        }
    }
}

super::wolf::wolf_optimizer!(
    /// The modified wolf pack algorithm, built from checked parameters.
    Mwpa,
    MwpaParams,
    "mwpa"
);

impl Mwpa {
    pub fn new(params: Checked<MwpaParams>) -> Self {
        let params = params.into_inner();
        let adaptive = Adaptive { w_min: params.w_min, w_max: params.w_max, compound: params.compound_raid_step };
        let variant = Variant {
            interactive: true,
            adaptive: Some(adaptive),
            decay: Some(params.c),
            replace_infeasible: params.replace_infeasible,
        };
        let pack = Pack::new(params.common().settings(), variant);
        Self { params, pack }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_presets_and_checks() {
        let p = MwpaParams::default();
        assert_eq!((p.population, p.t_max, p.omega, p.w_min, p.w_max, p.c), (300, 30, 50.0, 0.4, 1.0, 0.99));
        assert_eq!(p, MwpaParams::wpa2017_path());
        let b = MwpaParams::wpa2017();
        assert_eq!((b.population, b.t_max, b.omega, b.alpha, b.beta, b.step_a), (100, 20, 500.0, 4.0, 6.0, 0.001));
        assert!(b.checked("t").is_ok());
        for bad in [
            MwpaParams { w_min: 0.9, w_max: 0.5, ..p.clone() },
            MwpaParams { c: 1.0, ..p.clone() },
            MwpaParams { w_max: 1.5, ..p.clone() },
        ] {
            let e = bad.checked("planner.params.mwpa").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.mwpa."), "{e}");
        }
    }
}
