//! The wave glider's speed model (acopf2016 eqs. 1-2, after Ngo et al.'s regression).
//!
//! A wave glider has no throttle: the waves drive it, so its speed over ground is a function of
//! the sea state and the current, not a decision. acopf2016 keeps the regression's two main
//! terms (eq. 2): y_sog = 0.1623 x_wht - k x_hfr, with x_wht the significant wave height (m)
//! and x_hfr the subsurface current projected on the heading (m/s).
//!
//! * **Coefficient.** Eq. 1 prints k = 0.2660 and eq. 2, which only drops terms, reprints it as
//!   0.2260. We take eq. 1's 0.2660 as the source and read eq. 2's as a misprint; both are a
//!   parameter (`current_gain`).
//! * **Sign.** A negative coefficient on a current projected on the heading would make a
//!   following current slow the glider. We read x_hfr as the current *against* the heading
//!   (Ngo et al. project it onto the reverse course), so a following current speeds the glider
//!   up: v = 0.1623 H + 0.2660 (c . d), d the unit heading. acopf2016's own heuristic (eq. 10,
//!   b X_hfr cos theta with b > 0) rewards a current along the move, which agrees.
//! * **Floor.** The regression has no intercept, so in calm water it predicts 0 m/s; the glider
//!   is given a floor (`min_speed`, default 0.05 m/s) so every clock stays finite.
//! * **Track.** The glider holds its track; the regression has no cross-current term, so a
//!   cross-current only enters through c . d. Where the current along the heading drives the
//!   glider backwards (the regression is not positive with a head current), it cannot hold
//!   the track: the piece is flagged like a current the thrusters cannot stem.

use crate::params::{Bound, ParamSpec, Range};

/// Coefficients of the regression and the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GliderSpeed {
    /// m/s of speed per metre of significant wave height (eq. 1: 0.1623).
    pub wave_gain: f64,
    /// m/s of speed per m/s of current along the heading (eq. 1: 0.2660).
    pub current_gain: f64,
    /// The slowest speed over ground (m/s), in calm water or a head current.
    pub min_speed: f64,
}

impl Default for GliderSpeed {
    fn default() -> Self {
        Self { wave_gain: 0.1623, current_gain: 0.2660, min_speed: 0.05 }
    }
}

impl GliderSpeed {
    /// The scenario keys of the model (`[vehicle]` of a `kind = "wave-glider"`), declared
    /// once for listings (`tidepath vehicles`) and the scenario reader's checks: name, range,
    /// default and source. The gains' cap of 10 is already a vehicle faster than the waves
    /// (acopf2016's are 0.1623 and 0.2660); no wave glider keeps 5 m/s in calm water.
    pub const PARAMS: &'static [ParamSpec] = &[
        ParamSpec {
            name: "wave_gain",
            range: Range::Number { lo: Bound::Closed(0.0), hi: Bound::Closed(10.0) },
            optional: false,
            default: || Some(toml::Value::Float(GliderSpeed::default().wave_gain)),
            doc: "m/s of speed over ground per metre of significant wave height",
            source: "acopf2016 eq. 1 (Ngo et al.'s regression)",
        },
        ParamSpec {
            name: "current_gain",
            range: Range::Number { lo: Bound::Closed(0.0), hi: Bound::Closed(10.0) },
            optional: false,
            default: || Some(toml::Value::Float(GliderSpeed::default().current_gain)),
            doc: "m/s of speed over ground per m/s of current along the heading (following > 0)",
            source: "acopf2016 eq. 1 (eq. 2's 0.2260 read as a misprint)",
        },
        ParamSpec {
            name: "min_speed",
            range: Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(5.0) },
            optional: false,
            default: || Some(toml::Value::Float(GliderSpeed::default().min_speed)),
            doc: "the slowest speed over ground (m/s), in calm water or a head current",
            source: "tidepath (the regression has no intercept)",
        },
    ];

    /// Speed over ground (m/s) in waves of significant height `wave_height` (m) with the
    /// current's component along the heading `current_along` (m/s, positive following);
    /// `None` when a head current drives the glider backwards (it cannot hold the track).
    #[inline]
    pub fn ground_speed(&self, wave_height: f64, current_along: f64) -> Option<f64> {
        let v = self.wave_gain * wave_height + self.current_gain * current_along;
        if current_along < 0.0 && v <= 0.0 {
            return None;
        }
        Some(v.max(self.min_speed))
    }

    /// The fastest the glider can go where waves are at most `wave_bound` (m) and the current
    /// at most `current_bound` (m/s): an upper bound on [`GliderSpeed::ground_speed`] for
    /// admissible search heuristics.
    pub fn best_speed(&self, wave_bound: f64, current_bound: f64) -> f64 {
        (self.wave_gain * wave_bound + self.current_gain * current_bound).max(self.min_speed)
    }

    /// The model as one line, for listings and reports.
    pub fn formula(&self) -> String {
        format!(
            "speed over ground = max({}, {} H + {} c_along) m/s (H significant wave height in m, c_along the current along the heading in m/s)",
            self.min_speed, self.wave_gain, self.current_gain
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regression_at_hand_computed_points() {
        let g = GliderSpeed::default();
        // 2 m waves, still water: 0.1623 * 2 = 0.3246 m/s.
        assert!((g.ground_speed(2.0, 0.0).unwrap() - 0.3246).abs() < 1e-12);
        // 1.5 m waves and 0.5 m/s following: 0.24345 + 0.133 = 0.37645 m/s.
        assert!((g.ground_speed(1.5, 0.5).unwrap() - 0.37645).abs() < 1e-12);
        // 1.5 m waves and 0.5 m/s against: 0.24345 - 0.133 = 0.11045 m/s.
        assert!((g.ground_speed(1.5, -0.5).unwrap() - 0.11045).abs() < 1e-12);
        // Calm water: the floor.
        assert_eq!(g.ground_speed(0.0, 0.0), Some(0.05));
        // 0.2 m waves, 0.1 m/s against: 0.03246 - 0.0266 = 0.00586, below the floor.
        assert_eq!(g.ground_speed(0.2, -0.1), Some(0.05));
        // 0.5 m waves and 0.4 m/s against: 0.08115 - 0.1064 < 0, driven back.
        assert_eq!(g.ground_speed(0.5, -0.4), None);
        // The bound: 3 m and 1 m/s: 0.4869 + 0.266 = 0.7529.
        assert!((g.best_speed(3.0, 1.0) - 0.7529).abs() < 1e-12);
        assert!(g.formula().contains("0.1623 H"));
    }

    #[test]
    fn declared_keys_give_the_defaults_and_refuse_what_stalls_the_clock() {
        let d = GliderSpeed::default();
        let default = |k: usize| (GliderSpeed::PARAMS[k].default)().and_then(|v| v.as_float());
        let names: Vec<&str> = GliderSpeed::PARAMS.iter().map(|p| p.name).collect();
        assert_eq!(names, ["wave_gain", "current_gain", "min_speed"]);
        assert_eq!([default(0), default(1), default(2)], [Some(d.wave_gain), Some(d.current_gain), Some(d.min_speed)]);
        // A zero floor would let a calm sea stop the clock; a zero current gain is a glider
        // the current does not push, which is allowed.
        assert!(GliderSpeed::PARAMS[2].range.check_number(0.0).is_err());
        assert!(GliderSpeed::PARAMS[1].range.check_number(0.0).is_ok());
        assert_eq!(GliderSpeed::PARAMS[0].range.to_string(), "in [0, 10]");
    }
}
