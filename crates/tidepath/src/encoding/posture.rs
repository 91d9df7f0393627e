//! Posture limits of the sliced encoding: ijs2023 (Guo, Chen & Pang 2023), section II.B, eq. 14
//! (its "visualization constraint").
//!
//! Between consecutive planes a waypoint may move at most UB sideways and UR vertically:
//! |y_{j+1} − y_j| ≤ UB, |z_{j+1} − z_j| ≤ UR, the start counting as plane 0. The paper uses
//! them as a stand-in for the AUV's heading and pitch limits, so a scenario may give them as
//! angles: with planes Δs apart, UB = Δs tan(heading limit) and UR = Δs tan(pitch limit).
//!
//! **Enforced by the encoding** (`Sliced::repair`, and again by `Sliced::decode_into`, so every
//! decoded path of every planner satisfies them, repaired or not). The paper clamps each point
//! into the box and then, from the start onward, into the window its predecessor allows. On a
//! box that is the same on every plane (planes across x, as in the paper) that is what this
//! does. Where the box differs from plane to plane (planes across a diagonal start-goal axis
//! cut the domain rectangle in different places), a point clamped into its predecessor's
//! window can land where no later plane is reachable. So each plane's window is also cut to
//! the values from which every later plane stays reachable: an interval computed once by a
//! forward pass (reachable from the start) and a backward pass (able to continue to the last
//! plane). Clamping into "predecessor's window ∩ that interval" is then never empty, and the
//! chain holds on every plane.
//!
//! **Not enforced:** the last move, from the last plane to the goal. ijs2023 prices it instead
//! (its target penalty F_p3, in the `ijs2023` cost model), and so does tidepath.

use crate::error::{Error, Result};

/// One limit of eq. 14, as a distance between planes or as an angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepLimit {
    /// Metres between consecutive planes (UB or UR).
    Metres(f64),
    /// An angle (radians, in (0, π/2)): the step is the plane spacing times its tangent.
    Angle(f64),
}

impl StepLimit {
    /// The step in metres for planes `spacing` metres apart.
    pub fn metres(&self, spacing: f64) -> f64 {
        match *self {
            StepLimit::Metres(m) => m,
            StepLimit::Angle(a) => spacing * a.tan(),
        }
    }
}

/// The sliced encoding's posture limits: lateral (UB) and vertical (UR), each optional.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Posture {
    pub lateral: Option<StepLimit>,
    pub vertical: Option<StepLimit>,
}

impl Posture {
    pub fn is_none(&self) -> bool {
        self.lateral.is_none() && self.vertical.is_none()
    }

    /// The limits of `[encoding]`: `lateral_step` (m) or `heading_limit_deg`, and
    /// `vertical_step` (m) or `pitch_limit_deg`; each pair is one-or-neither.
    pub fn from_spec(
        lateral_step: Option<f64>,
        heading_limit_deg: Option<f64>,
        vertical_step: Option<f64>,
        pitch_limit_deg: Option<f64>,
    ) -> Result<Self> {
        fn one(
            metres: Option<f64>,
            degrees: Option<f64>,
            metres_field: &str,
            degrees_field: &str,
        ) -> Result<Option<StepLimit>> {
            match (metres, degrees) {
                (Some(_), Some(_)) => Err(Error::input(
                    format!("encoding.{metres_field}"),
                    format!("give {metres_field} (m) or {degrees_field}, not both"),
                )),
                (Some(m), None) => {
                    if !(m.is_finite() && m > 0.0) {
                        return Err(Error::input(
                            format!("encoding.{metres_field}"),
                            format!("must be a positive number of metres, got {m}"),
                        ));
                    }
                    Ok(Some(StepLimit::Metres(m)))
                }
                (None, Some(d)) => {
                    if !(d.is_finite() && d > 0.0 && d < 90.0) {
                        return Err(Error::input(
                            format!("encoding.{degrees_field}"),
                            format!("must be an angle in (0, 90) degrees, got {d}"),
                        ));
                    }
                    Ok(Some(StepLimit::Angle(d.to_radians())))
                }
                (None, None) => Ok(None),
            }
        }
        Ok(Self {
            lateral: one(lateral_step, heading_limit_deg, "lateral_step", "heading_limit_deg")?,
            vertical: one(vertical_step, pitch_limit_deg, "vertical_step", "pitch_limit_deg")?,
        })
    }
}

/// One variable's eq. 14 chain over the planes: its value at the start, the largest step
/// between planes, and for each plane the interval of values reachable from the start from
/// which every later plane stays reachable (within that plane's box).
#[derive(Clone, Debug)]
pub(crate) struct StepChain {
    step: f64,
    start: f64,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl StepChain {
    /// The chain for a variable worth `start` at the start, `step` per plane at most, plane k
    /// boxed to `[box_lo[k], box_hi[k]]`. Fails (naming `field`) when no chain fits.
    pub fn new(start: f64, step: f64, box_lo: &[f64], box_hi: &[f64], field: &str) -> Result<Self> {
        let n = box_lo.len();
        let (mut lo, mut hi) = (vec![0.0; n], vec![0.0; n]);
        // Forward: reachable from the start.
        let (mut a, mut b) = (start, start);
        for k in 0..n {
            a = (a - step).max(box_lo[k]);
            b = (b + step).min(box_hi[k]);
            (lo[k], hi[k]) = (a, b);
            if a > b {
                return Err(Self::empty(field, k, step));
            }
        }
        // Backward: able to reach every later plane.
        for k in (0..n.saturating_sub(1)).rev() {
            lo[k] = lo[k].max(lo[k + 1] - step);
            hi[k] = hi[k].min(hi[k + 1] + step);
            if lo[k] > hi[k] {
                return Err(Self::empty(field, k, step));
            }
        }
        Ok(Self { step, start, lo, hi })
    }

    fn empty(field: &str, k: usize, step: f64) -> Error {
        Error::input(
            format!("encoding.{field}"),
            format!("a step of {step} m between planes cannot reach plane {} from the start inside the domain and depth band", k + 1),
        )
    }

    /// The value at the start (plane 0).
    pub fn start(&self) -> f64 {
        self.start
    }

    /// `v` on plane `k` moved into the window the value `prev` on plane k − 1 allows.
    #[inline]
    pub fn clamp(&self, k: usize, prev: f64, v: f64) -> f64 {
        // Into plane k's interval first (off the chain from plane to plane), then into the
        // window prev allows: the same as clamping into the two's intersection, which is never
        // empty when prev came from this chain (module doc), because then each end of the
        // window that binds lies inside the interval. Written as selects, which compile to
        // min/max without branches (the values are random: branches would mispredict).
        let v = if v < self.lo[k] { self.lo[k] } else { v };
        let v = if v > self.hi[k] { self.hi[k] } else { v };
        let (a, b) = (prev - self.step, prev + self.step);
        let v = if v < a { a } else { v };
        if v > b {
            b
        } else {
            v
        }
    }

    pub fn step(&self) -> f64 {
        self.step
    }

    /// Whether the values `v(0), v(1), ..` of the planes already satisfy the chain, so
    /// [`StepChain::clamp`] would leave each unchanged. No value depends on the one before,
    /// so unlike clamping this runs without a serial chain (repaired vectors, the common
    /// case, are decoded without clamping them again).
    #[inline]
    pub fn holds(&self, v: impl Fn(usize) -> f64) -> bool {
        let mut prev = self.start;
        let mut ok = true;
        for k in 0..self.lo.len() {
            let x = v(k);
            ok &= x >= self.lo[k] && x <= self.hi[k] && (x - prev).abs() <= self.step;
            prev = x;
        }
        ok
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_become_steps_by_the_spacing() {
        let p = Posture::from_spec(None, Some(45.0), Some(10.0), None).unwrap();
        assert!((p.lateral.unwrap().metres(200.0) - 200.0).abs() < 1e-9);
        assert_eq!(p.vertical.unwrap().metres(200.0), 10.0);
        for (args, field) in [
            ((Some(1.0), Some(10.0), None, None), "encoding.lateral_step"),
            ((Some(-1.0), None, None, None), "encoding.lateral_step"),
            ((None, None, None, Some(90.0)), "encoding.pitch_limit_deg"),
            ((None, None, Some(f64::NAN), None), "encoding.vertical_step"),
        ] {
            let e = Posture::from_spec(args.0, args.1, args.2, args.3).unwrap_err().to_string();
            assert!(e.starts_with(field), "{e}");
        }
    }

    #[test]
    fn chain_clamps_forward_from_the_start() {
        // Same box on every plane (the paper's case): the predecessor's window only.
        let c = StepChain::new(0.0, 5.0, &[-100.0; 4], &[100.0; 4], "lateral_step").unwrap();
        let raw = [20.0, -20.0, 3.0, 50.0];
        let mut prev = c.start();
        let mut out = vec![];
        for (k, &v) in raw.iter().enumerate() {
            prev = c.clamp(k, prev, v);
            out.push(prev);
        }
        assert_eq!(out, vec![5.0, 0.0, 3.0, 8.0]);
    }

    #[test]
    fn chain_keeps_later_planes_reachable() {
        // Plane 2's box is [40, 50]: from the start at 0 with steps of 20, plane 0 must be at
        // least 0 and plane 1 at least 20, whatever the raw values say.
        let c = StepChain::new(0.0, 20.0, &[-100.0, -100.0, 40.0], &[100.0, 100.0, 50.0], "lateral_step").unwrap();
        let mut prev = c.start();
        let mut out = vec![];
        for (k, v) in [-50.0, -50.0, -50.0].into_iter().enumerate() {
            prev = c.clamp(k, prev, v);
            out.push(prev);
        }
        assert_eq!(out, vec![0.0, 20.0, 40.0]);
        // Unreachable: plane 1's box starts 30 away with steps of 10.
        let e = StepChain::new(0.0, 10.0, &[-1.0, 30.0], &[1.0, 40.0], "lateral_step").unwrap_err();
        assert!(e.to_string().contains("plane"), "{e}");
    }
}
