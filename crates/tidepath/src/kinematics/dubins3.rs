//! Dubins curves in 3-D: the Dubins-airplane construction (Chitsaz & LaValle 2007; Owen,
//! Beard & McLain 2014) between poses (x, y, z, heading) for a horizontal turning radius r
//! and a pitch limit gamma, as OMPL's `OwenStateSpace` builds it, except that the radius
//! stays r in every case (see *High altitude*).
//!
//! Let L be the horizontal Dubins length from the start to the goal ([`Dubins`]) and dz the
//! height change. The climb is always spread evenly over the whole horizontal curve, so the
//! curve has one constant pitch, atan(|dz| / H) for a horizontal length H.
//!
//! * **Low altitude**, |dz| <= L tan(gamma): the horizontal Dubins curve itself (H = L).
//! * **Medium altitude**, L tan(gamma) < |dz| < (L + 2 pi r) tan(gamma): the curve first turns
//!   by an angle phi (0 < |phi| < 2 pi, left or right) on the circle of radius r tangent at the
//!   start, then follows the shortest horizontal Dubins curve from there to the goal; phi is
//!   chosen so that H = r |phi| + L(phi) = |dz| / tan(gamma), so the pitch is exactly gamma and
//!   the 3-D length |dz| / sin(gamma) is the least any curve within the pitch limit can have.
//!   (This is Owen et al.'s intermediate-arc case as OMPL implements it.) phi is found by
//!   scanning |phi| outwards in 5-degree steps on both sides, alternately, and bisecting the
//!   first bracket to machine precision; a bracket whose end values straddle a jump of the
//!   Dubins length (Dubins lengths are discontinuous in the start pose) is refused and the scan
//!   goes on.
//! * **High altitude**, |dz| >= (L + 2 pi r) tan(gamma): k = floor((|dz| / tan(gamma) - L) /
//!   (2 pi r)) whole turns of radius r (a helix) are added to the pre-turn, and the remainder
//!   is taken up by the medium-altitude phi, so again H = |dz| / tan(gamma) exactly. Owen et
//!   al. and OMPL instead widen the radius of the k-turn helix and the Dubins curve until the
//!   pitch is exactly gamma; both give the same 3-D length |dz| / sin(gamma), but a wider radius
//!   is not what the fillet model flies at the vehicle's radius ([`super::fillet`]), so
//!   tidepath keeps r and adds the partial turn phi instead.
//! * When no phi bracket is found (which the scan makes rare), k + 1 whole turns are flown on
//!   the side of the Dubins curve's first turn, with the climb spread over them: the pitch is
//!   then below gamma and the curve longer than |dz| / sin(gamma). [`Altitude::Helix`] marks
//!   that case.
//!
//! Written into a [`TangentPolygon`], the pre-turn is one arc (whole turns and phi together),
//! then the Dubins curve's three elements; every element ends at a waypoint and its climb is
//! spread over it in proportion to its horizontal length, so the fillet model flies the pitch
//! planned here exactly. Callers that must stay within a pitch limit plan with
//! [`planning_pitch`], a hair below it, so rounding never makes the flown pitch a violation.

use super::dubins::{advance, Dubins, Word};
use super::{Pose, TangentPolygon};
use std::f64::consts::TAU;

/// Which case of the construction a curve is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Altitude {
    /// The horizontal Dubins curve; the climb fits along it.
    Low,
    /// A partial pre-turn phi (|phi| < 2 pi), then a Dubins curve; pitch exactly the limit.
    Medium,
    /// Whole helical turns and a partial one, then a Dubins curve; pitch exactly the limit.
    High,
    /// The fallback: whole turns on the first arc's side only; pitch below the limit.
    Helix,
}

/// A 3-D Dubins-airplane curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dubins3 {
    pub from: Pose,
    pub to: Pose,
    pub radius: f64,
    /// The signed angle turned on the start's circle before the horizontal curve (rad;
    /// positive: left), whole helical turns included; 0 for low altitude.
    pub pre_turn: f64,
    /// The horizontal Dubins curve from the end of the pre-turn to the goal.
    pub horizontal: Dubins,
    /// Height change (m).
    pub dz: f64,
    pub altitude: Altitude,
}

/// Relative margin below the pitch limit that planned curves keep.
pub const PITCH_MARGIN: f64 = 1e-9;

/// The pitch to plan with for a vehicle whose limit is `max_pitch`: its tangent is
/// `PITCH_MARGIN` (relative) below the limit's.
pub fn planning_pitch(max_pitch: f64) -> f64 {
    (max_pitch.tan() * (1.0 - PITCH_MARGIN)).atan()
}

/// Scan step for the pre-turn angle (rad).
const PHI_STEP: f64 = TAU / 72.0;

impl Dubins3 {
    /// The curve from `from` to `to` (3-D poses) with radius `radius` whose constant pitch is
    /// at most `max_pitch` (rad, in [0, pi/2)), using the shortest horizontal Dubins words;
    /// `None` for a radius that is not positive, non-finite input, or a height change with a
    /// pitch limit of 0.
    pub fn shortest(from: Pose, to: Pose, radius: f64, max_pitch: f64) -> Option<Self> {
        Self::shortest_in(from, to, radius, max_pitch, &Word::ALL)
    }

    /// The same, with the horizontal curve (after the pre-turn) restricted to `words`.
    pub fn shortest_in(from: Pose, to: Pose, radius: f64, max_pitch: f64, words: &[Word]) -> Option<Self> {
        let dz = to.p.z - from.p.z;
        if !(dz.is_finite() && max_pitch.is_finite() && max_pitch >= 0.0) {
            return None;
        }
        let direct = Dubins::shortest_in(from, to, radius, words)?;
        let slope = max_pitch.tan();
        let len = direct.length();
        let low = |h: Dubins, pre: f64, altitude| Self { from, to, radius, pre_turn: pre, horizontal: h, dz, altitude };
        if dz.abs() <= len * slope || dz == 0.0 {
            return Some(low(direct, 0.0, Altitude::Low));
        }
        if slope <= 0.0 || slope.is_infinite() {
            // A height change with no pitch allowed, or a vertical move (len 0, any pitch).
            return (slope.is_infinite()).then(|| low(direct, 0.0, Altitude::Low));
        }
        let target = dz.abs() / slope;
        let circle = TAU * radius;
        let k = ((target - len) / circle).floor().max(0.0);
        let rest = target - k * circle;
        let side = f64::from(direct.word.turns()[0]);
        if rest - len <= 1e-12 * target {
            // Whole turns take up the climb exactly.
            return Some(low(direct, side * k * TAU, Altitude::High));
        }
        if let Some((phi, h)) = pre_turn(from, to, radius, words, rest) {
            let pre = phi + phi.signum() * k * TAU;
            let altitude = if k > 0.0 { Altitude::High } else { Altitude::Medium };
            return Some(low(h, pre, altitude));
        }
        // Fallback: whole turns on the first arc's side, enough for the climb.
        Some(low(direct, side * (k + 1.0) * TAU, Altitude::Helix))
    }

    /// Horizontal length (m).
    pub fn horizontal_length(&self) -> f64 {
        self.radius * self.pre_turn.abs() + self.horizontal.length()
    }

    /// 3-D length (m): the helix length sqrt(H^2 + dz^2) of a curve with constant pitch.
    pub fn length(&self) -> f64 {
        self.horizontal_length().hypot(self.dz)
    }

    /// |dz| / horizontal length: the tangent of the pitch flown (+inf for a vertical move).
    pub fn slope(&self) -> f64 {
        if self.dz == 0.0 {
            0.0
        } else {
            self.dz.abs() / self.horizontal_length()
        }
    }

    /// The pose `s` metres along the horizontal curve (clamped), with the height the curve
    /// has there.
    pub fn pose_at(&self, s: f64) -> Pose {
        let h = self.horizontal_length();
        let s = s.clamp(0.0, h);
        let pre = self.radius * self.pre_turn.abs();
        let side = if self.pre_turn >= 0.0 { 1 } else { -1 };
        let mut pose = if s <= pre {
            advance(self.from, side, s, self.radius)
        } else {
            let mut p = self.horizontal.pose_at(s - pre);
            p.p.z = self.from.p.z;
            p
        };
        pose.p.z = self.from.p.z + if h > 0.0 { self.dz * s / h } else { self.dz };
        pose
    }

    /// Writes the curve into `tp`, whose pen must be at `from`.
    pub fn write(&self, tp: &mut TangentPolygon) {
        let h = self.horizontal_length();
        let pre = self.radius * self.pre_turn.abs();
        let dz_pre = if h > 0.0 { self.dz * pre / h } else { 0.0 };
        if self.pre_turn != 0.0 {
            tp.arc(self.pre_turn, dz_pre);
        }
        self.horizontal.write(tp, self.dz - dz_pre);
    }
}

/// The pre-turn phi (signed, 0 < |phi| < 2 pi) after which the shortest horizontal curve in
/// `words` to `to` makes the horizontal length r |phi| + L(phi) equal `target`, with that
/// curve; the smallest |phi| the scan finds.
fn pre_turn(from: Pose, to: Pose, radius: f64, words: &[Word], target: f64) -> Option<(f64, Dubins)> {
    let eval = |phi: f64| -> Option<(f64, Dubins)> {
        let side = if phi >= 0.0 { 1 } else { -1 };
        let mid = advance(from, side, phi.abs() * radius, radius);
        let d = Dubins::shortest_in(mid, to, radius, words)?;
        Some((radius * phi.abs() + d.length() - target, d))
    };
    let steps = (TAU / PHI_STEP).round() as usize;
    let mut prev = [eval(0.0).map(|e| e.0), eval(-0.0).map(|e| e.0)];
    for m in 1..=steps {
        for (j, side) in [1.0, -1.0].into_iter().enumerate() {
            let (lo, hi) = (side * (m - 1) as f64 * PHI_STEP, side * m as f64 * PHI_STEP);
            let g_hi = eval(hi).map(|e| e.0);
            if let (Some(a), Some(b)) = (prev[j], g_hi) {
                if a <= 0.0 && b >= 0.0 {
                    if let Some(found) = bisect(&eval, lo, hi, target) {
                        return Some(found);
                    }
                }
            }
            prev[j] = g_hi;
        }
    }
    None
}

/// Bisects g (negative at `lo`, non-negative at `hi`) to machine precision; the root when g is
/// continuous there (|g| within 1e-9 of the target), `None` at a jump.
fn bisect(eval: &dyn Fn(f64) -> Option<(f64, Dubins)>, mut lo: f64, mut hi: f64, target: f64) -> Option<(f64, Dubins)> {
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            break;
        }
        match eval(mid) {
            Some((g, _)) if g < 0.0 => lo = mid,
            Some(_) => hi = mid,
            None => return None,
        }
    }
    // The end whose residual is smaller; refuse a jump.
    let (a, b) = (eval(lo)?, eval(hi)?);
    let (phi, best) = if a.0.abs() <= b.0.abs() { (lo, a) } else { (hi, b) };
    (best.0.abs() <= 1e-9 * target.max(1.0) && phi != 0.0).then_some((phi, best.1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Vec3;
    use crate::kinematics::fillet::{for_each_piece, FlownPiece};
    use std::f64::consts::{FRAC_PI_2, PI};

    /// The 3-D length of the curve the fillet model flies along `points` at radius `r`.
    fn flown_length(points: &[Vec3], r: f64) -> f64 {
        let mut len = 0.0;
        for_each_piece(points, r, |p| match p {
            FlownPiece::Line { a, b, .. } => len += (b - a).length(),
            FlownPiece::Arc(arc) => len += arc.horizontal_length().hypot(arc.b.z - arc.a.z),
        });
        len
    }

    /// The polygon of `d` from its start pose, pieces of at most `piece` rad.
    fn polygon(d: &Dubins3, piece: f64) -> Vec<Vec3> {
        let mut tp = TangentPolygon::new(d.from, d.radius, piece);
        d.write(&mut tp);
        tp.finish()
    }

    /// Largest pitch (tangent) flown on any piece.
    fn max_flown_slope(points: &[Vec3], r: f64) -> f64 {
        let mut s: f64 = 0.0;
        for_each_piece(points, r, |p| match p {
            // A straight part lies on its leg: the leg's slope (its own ends may be a rounding
            // apart, where a tangent point is a waypoint).
            FlownPiece::Line { a, b, segment } => {
                let leg = points[segment + 1] - points[segment];
                let h = leg.truncate().length();
                if a != b && h > 0.0 {
                    s = s.max(leg.z.abs() / h);
                }
            }
            FlownPiece::Arc(arc) => s = s.max(arc.slope()),
        });
        s
    }

    fn pose(x: f64, y: f64, z: f64, h: f64) -> Pose {
        Pose::new(Vec3::new(x, y, z), h)
    }

    #[test]
    fn pure_climb_in_a_straight_line_is_the_hypotenuse() {
        let (l, dz) = (200.0, 30.0);
        let d = Dubins3::shortest(
            pose(0.0, 0.0, -100.0, 0.3),
            pose(l * 0.3f64.cos(), l * 0.3f64.sin(), -70.0, 0.3),
            20.0,
            0.5,
        )
        .unwrap();
        assert_eq!(d.altitude, Altitude::Low);
        assert!((d.length() - (l * l + dz * dz).sqrt()).abs() < 1e-9 * l, "{d:?}");
        let pts = polygon(&d, 0.5);
        assert!((flown_length(&pts, 20.0) - d.length()).abs() < 1e-9 * d.length());
    }

    #[test]
    fn low_altitude_is_the_planar_curve_with_the_climb_spread() {
        let (a, b) = (pose(0.0, 0.0, 0.0, 0.0), pose(0.0, 2.0 * 10.0, -5.0, PI));
        let d = Dubins3::shortest(a, b, 10.0, 0.3).unwrap();
        // A half circle of radius 10 (31.4 m) allows 31.4 tan(0.3) = 9.7 m: 5 fits.
        assert_eq!(d.altitude, Altitude::Low);
        assert!((d.length() - (PI * 10.0).hypot(5.0)).abs() < 1e-12);
        assert!((d.slope() - 5.0 / (PI * 10.0)).abs() < 1e-15);
    }

    #[test]
    fn helix_by_hand() {
        // Start and goal at one place, same heading, 100 m apart in height; r = 10, pitch
        // limit 20 degrees. The planar curve is empty (L = 0) and the climb needs a horizontal
        // length of 100 / tan(20 deg) = 274.75 m. A closed curve of radius 10 through one pose
        // is at least a circle long, and turning phi round the start's circle and flying the
        // Dubins curve home is always exactly one circle (62.83 m), so no partial turn helps:
        // the curve is ceil(274.75 / 62.83) = 5 whole turns, a helix of horizontal length
        // 314.16 m at pitch atan(100 / 314.16) = 17.656787 deg, 3-D length 329.690831 m.
        let (r, g, dz) = (10.0, 20f64.to_radians(), -100.0);
        let a = pose(5.0, 5.0, -10.0, FRAC_PI_2);
        let b = pose(5.0, 5.0, -10.0 + dz, FRAC_PI_2);
        let d = Dubins3::shortest(a, b, r, g).unwrap();
        assert_eq!(d.altitude, Altitude::Helix);
        assert!((d.pre_turn.abs() - 5.0 * TAU).abs() < 1e-12, "{d:?}");
        let h = 5.0 * TAU * r;
        assert!((d.horizontal_length() - h).abs() < 1e-9, "{d:?}");
        assert!((d.length() - 329.690831).abs() < 1e-6, "{}", d.length());
        assert!((d.slope().atan().to_degrees() - 17.656787).abs() < 1e-6, "{}", d.slope().atan().to_degrees());
        // The polygon ends at the goal and flies the curve's length at the curve's pitch.
        let pts = polygon(&d, 30f64.to_radians());
        assert!((*pts.last().unwrap() - b.p).length() < 1e-9, "{:?}", pts.last());
        assert!((flown_length(&pts, r) - d.length()).abs() < 1e-9 * d.length());
        // Halfway along the helix: two and a half turns from the start, half the dive.
        let mid = d.pose_at(0.5 * h);
        let side = d.pre_turn.signum();
        assert!((mid.p - Vec3::new(5.0 - side * 2.0 * r, 5.0, -60.0)).length() < 1e-9, "{mid:?}");
    }

    #[test]
    fn high_altitude_adds_whole_turns_and_a_partial_one() {
        // A goal 120 m ahead at the same heading, 200 m deeper; r = 10, limit 30 degrees.
        // L = 120; the dive needs 200 / tan(30 deg) = 346.41 m: k = floor(226.41 / 62.83) = 3
        // whole turns and a partial turn phi taking up the remaining 37.92 m, so the pitch is
        // exactly 30 degrees and the length 200 / sin(30 deg) = 400 m.
        let (r, g) = (10.0, 30f64.to_radians());
        let a = pose(0.0, 0.0, -10.0, 0.0);
        let b = pose(120.0, 0.0, -210.0, 0.0);
        let d = Dubins3::shortest(a, b, r, g).unwrap();
        assert_eq!(d.altitude, Altitude::High);
        assert!((d.length() - 400.0).abs() < 1e-9 * 400.0, "{d:?}");
        let turns = (d.pre_turn.abs() / TAU).floor();
        assert_eq!(turns, 3.0, "{d:?}");
        let phi = d.pre_turn.abs() - 3.0 * TAU;
        assert!((r * phi + d.horizontal.length() - (346.4101615 - 3.0 * TAU * r)).abs() < 1e-6, "{d:?}");
        let pts = polygon(&d, 0.4);
        assert!((*pts.last().unwrap() - b.p).length() < 1e-9);
        assert!((flown_length(&pts, r) - 400.0).abs() < 1e-9 * 400.0);
        assert!(max_flown_slope(&pts, r) <= g.tan() * (1.0 + 1e-12));
    }

    #[test]
    fn a_climb_of_whole_turns_exactly_is_those_turns() {
        // A goal 80 m straight ahead whose climb needs exactly L + 2 circles: k = 2, no
        // partial turn, the turns on the side of the (empty) first arc.
        let (r, g) = (10.0, 0.4f64);
        let dz = (80.0 + 2.0 * TAU * r) * g.tan();
        let d = Dubins3::shortest(pose(0.0, 0.0, 0.0, 0.0), pose(80.0, 0.0, dz, 0.0), r, g).unwrap();
        assert_eq!(d.altitude, Altitude::High);
        assert!((d.pre_turn.abs() - 2.0 * TAU).abs() < 1e-12, "{d:?}");
        assert!((d.length() - dz / g.sin()).abs() < 1e-9 * d.length());
    }

    #[test]
    fn medium_altitude_flies_exactly_the_pitch_limit() {
        let (r, g) = (15.0, 25f64.to_radians());
        let a = pose(0.0, 0.0, -50.0, 0.0);
        let b = pose(60.0, 40.0, 0.0, 2.0);
        let flat = Dubins::shortest(a, b, r).unwrap();
        assert!(50.0 > flat.length() * g.tan() && 50.0 < (flat.length() + TAU * r) * g.tan());
        let d = Dubins3::shortest(a, b, r, g).unwrap();
        assert_eq!(d.altitude, Altitude::Medium);
        assert!((d.length() - 50.0 / g.sin()).abs() < 1e-9 * d.length());
        assert!(d.pre_turn.abs() < TAU);
        let pts = polygon(&d, 0.3);
        assert!((*pts.last().unwrap() - b.p).length() < 1e-9);
        assert!((flown_length(&pts, r) - d.length()).abs() < 1e-9 * d.length());
        // The end pose: the goal, heading included.
        let end = d.pose_at(d.horizontal_length());
        assert!((end.p - b.p).length() < 1e-9 && (crate::kinematics::wrap_angle(end.heading - b.heading)).abs() < 1e-9);
    }

    #[test]
    fn random_pairs_fly_their_length_and_pitch() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(27);
        let mut seen = [0usize; 4];
        for _ in 0..300 {
            let r = rng.random_range(5.0..40.0);
            let g = rng.random_range(0.1..0.7f64);
            let a = pose(
                rng.random_range(-100.0..100.0),
                rng.random_range(-100.0..100.0),
                rng.random_range(-300.0..0.0),
                rng.random_range(-PI..PI),
            );
            let b = pose(
                rng.random_range(-100.0..100.0),
                rng.random_range(-100.0..100.0),
                rng.random_range(-300.0..0.0),
                rng.random_range(-PI..PI),
            );
            let d = Dubins3::shortest(a, b, r, planning_pitch(g)).unwrap();
            seen[d.altitude as usize] += 1;
            let pts = polygon(&d, 0.4);
            let len = d.length();
            assert!((flown_length(&pts, r) - len).abs() < 1e-9 * len, "{d:?}");
            assert!((*pts.last().unwrap() - b.p).length() < 1e-8 * len.max(1.0));
            assert!(max_flown_slope(&pts, r) <= g.tan(), "{d:?}");
            // Never shorter than the planar curve or the pitch-limited climb.
            let flat = Dubins::shortest(a, b, r).unwrap().length();
            assert!(len >= flat.hypot(d.dz) * (1.0 - 1e-12));
            assert!(len >= d.dz.abs() / planning_pitch(g).sin() * (1.0 - 1e-12));
        }
        assert!(seen[0] > 0 && seen[1] > 0 && seen[2] > 0, "{seen:?}");
        eprintln!("low, medium, high, helix: {seen:?}");
    }
}
