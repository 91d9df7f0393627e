//! The original wolf pack algorithm (WPA; Wu, Zhang & Wu 2013, Wu & Zhang 2014), the baseline
//! of wpa2017 (Zhang et al., "Three-Dimensional Underwater Path Planning Based on Modified
//! Wolf Pack Algorithm", IEEE Access 2017, section III and Table 5).
//!
//! ```text
//! scouting   x' = x + sin(2 pi p/h) step_a,  p = 1..h   (best of h, kept if better;
//!            up to T_max rounds; a scout beating the lead becomes the lead and scouting ends)
//! calling    x_d <- x_d + step_b sign(g_d - x_d)        (until dist <= d_near, the wolf beats
//!            the lead, or T_max raids);  d_near = sum_d |max_d - min_d| / (D omega)
//! besieging  x_d' = x_d + lambda step_c |G_d - x_d|,  lambda ~ U[-1, 1] per wolf, greedy
//! renewal    R ~ U{N/(2 beta) .. N/beta} worst wolves replaced by uniform random wolves
//! ```
//!
//! Steps are fractions of each dimension's range (step_a = 0.004 of the range is the paper's
//! 0.2 km on its 50 km box). The distance compared with d_near is the mean absolute
//! per-dimension difference, and a wolf raids at most T_max times per calling phase
//! (docs/papers/wpa2017.md, A9). The engine is shared with `mwpa` (`wolf.rs`).

use super::wolf::{Pack, Settings, Variant};
use super::MAX_POPULATION;
use crate::params::{Bound, Checked, Range};

crate::params! {
    /// WPA parameters. Defaults: wpa2017's path experiment (section IV), steps as fractions
    /// of each dimension's range.
    pub struct WpaParams {
        /// Wolves N.
        population: usize = 300, Range::integer(4, MAX_POPULATION as u64), "wpa2017 section IV";
        /// Most scouting rounds, and most raids of a wolf per calling phase, T_max.
        t_max: usize = 30, Range::integer(1, 100_000), "wpa2017 section IV";
        /// Distance factor omega of d_near = mean range / omega.
        omega: f64 = 50.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Unbounded }, "wpa2017 section IV";
        /// Scouting step step_a, as a fraction of each dimension's range (0.2 km of 50 km).
        step_a: f64 = 0.004, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "wpa2017 section IV";
        /// Raid step step_b, as a fraction of each dimension's range (0.4 km of 50 km).
        step_b: f64 = 0.008, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "wpa2017 section IV";
        /// Siege step step_c, as a fraction of each dimension's range (0.1 km of 50 km).
        step_c: f64 = 0.002, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1.0) }, "wpa2017 section IV";
        /// Scout ratio alpha: T scouts with T in [N/(alpha+1), N/alpha].
        alpha: f64 = 4.0, Range::Number { lo: Bound::Closed(1.0), hi: Bound::Unbounded }, "wpa2017 section IV";
        /// Renewal factor beta: R wolves renewed with R in [N/(2 beta), N/beta].
        beta: f64 = 5.0, Range::Number { lo: Bound::Closed(1.0), hi: Bound::Unbounded }, "wpa2017 section IV";
        /// Scouting directions h.
        h: usize = 4, Range::integer(1, 1000), "tidepath (not given in wpa2017)";
    }
}

impl WpaParams {
    /// wpa2017's path experiment (section IV): the defaults.
    pub fn wpa2017_path() -> Self {
        Self::default()
    }

    /// wpa2017's benchmark setting (Table 3, with docs/papers/wpa2017.md A12): N = 100,
    /// T_max = 20, omega = 500, alpha = 4 (printed 0.8), beta = 6, step_a = range/1000,
    /// step_b = range/500, step_c = range/2000.
    pub fn wpa2017() -> Self {
        Self {
            population: 100,
            t_max: 20,
            omega: 500.0,
            step_a: 0.001,
            step_b: 0.002,
            step_c: 0.0005,
            alpha: 4.0,
            beta: 6.0,
            h: 4,
        }
    }

    pub(crate) fn settings(&self) -> Settings {
        Settings {
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
    /// The original wolf pack algorithm, built from checked parameters.
    Wpa,
    WpaParams,
    "wpa"
);

impl Wpa {
    pub fn new(params: Checked<WpaParams>) -> Self {
        let params = params.into_inner();
        let variant = Variant { interactive: false, adaptive: None, decay: None, replace_infeasible: false };
        let pack = Pack::new(params.settings(), variant);
        Self { params, pack }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_presets_and_checks() {
        let p = WpaParams::default();
        assert_eq!((p.population, p.t_max, p.omega, p.alpha, p.beta, p.h), (300, 30, 50.0, 4.0, 5.0, 4));
        // The paper's 0.2, 0.4, 0.1 km on its 50 km box.
        assert_eq!((p.step_a * 50.0, p.step_b * 50.0, p.step_c * 50.0), (0.2, 0.4, 0.1));
        assert_eq!(p, WpaParams::wpa2017_path());
        assert!(WpaParams::wpa2017().checked("t").is_ok());
        for bad in [
            WpaParams { population: 3, ..p.clone() },
            WpaParams { alpha: 0.8, ..p.clone() },
            WpaParams { beta: 0.5, ..p.clone() },
            WpaParams { omega: 0.0, ..p.clone() },
            WpaParams { step_a: 0.0, ..p.clone() },
            WpaParams { t_max: 0, ..p.clone() },
            WpaParams { h: 0, ..p.clone() },
        ] {
            let e = bad.checked("planner.params.wpa").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.wpa."), "{e}");
        }
        let q = WpaParams::from_table(&toml::from_str("h = 6").unwrap(), "p").unwrap();
        assert_eq!(*q.get(), WpaParams { h: 6, ..WpaParams::default() });
    }
}
