//! The lfhh2019 cost model (eqs. 6-10): path length ratio, joints the vehicle cannot turn,
//! blocked segments and the angle to the current. See `docs/papers/lfhh2019.md`, section
//! "cost" and A2-A3.
//!
//! F = C_length + C_curvature + C_block + C_current
//!
//! - C_length = 1 - L_straight / L_path, L_straight the 3-D start-goal distance of the mission,
//!   L_path the path's 3-D length; 0 for a path of zero length.
//! - C_curvature = N_unable / N_all + 2 when N_unable > 0, else 0. N_all is the number of
//!   segments (points - 1). A joint is unable when the interior angle between its two segments
//!   (pi = straight on, measured in 3-D, A2) is below T_theta (`min_interior_angle_deg`, pi/6 in
//!   the paper). Our reading: a joint that breaks the vehicle's own limits is unable too, so
//!   that F < 2 implies tidepath's feasibility. N_unable counts *segments*: segment i is unable
//!   when the joint at its start is (interior angle below T_theta, or a heading change over the
//!   vehicle's `max_turn` measured as [`PathModel::assess`] does it, from the last segment with
//!   horizontal extent), or when it is steeper than the vehicle's `max_pitch` (3-D). With a
//!   turning radius, a turn whose fillet does not fit (as `assess` judges it) or that climbs
//!   too steeply makes the segment after it unable. So N_unable <= N_all and the term stays in
//!   (2, 3] when any joint is unable. With a radius the straight legs' pitch is judged on the
//!   whole leg, a little stricter than `assess` (which judges the part flown straight).
//! - C_block = N_block / N_all + 2 when N_block > 0, else 0. Segment i is blocked when its
//!   motion is invalid under tidepath's validator on the vehicle's clock (seabed or obstacle
//!   within the safety distance, moving obstacles at the vehicle's time, a current the vehicle
//!   cannot stem, no current data), when one of its ends is outside the domain or (3-D) the
//!   depth band (the domain is a box: a segment leaves it exactly when an end does), or, for
//!   the first and last segments, when the path does not start at the mission's start or end
//!   at its goal. With a turning radius the motions judged are the flown curve's, as in
//!   `assess`; a turn belongs to the segment entering it. The paper samples the seabed every
//!   0.1 km; tidepath's exact seabed and obstacle tests replace it.
//! - C_current = (1 / N_all) sum_n alpha_n / pi (A3: alpha_min = 0, alpha_max = pi), alpha_n the
//!   angle between the horizontal projection of segment n and the horizontal current at its
//!   midpoint, at the mid time of the segment on the vehicle's clock. Where the current is
//!   slower than `still_current` m/s, or the segment has no horizontal extent, alpha_n = pi/2
//!   (neutral). So still water adds 0.5 whatever the path.
//! - Zero-length segments (a repeated waypoint) count in N_all like any other segment (they are
//!   checked for blocks like any other motion and add pi/2 to the current term); they have no
//!   direction, so the joint across them is measured between the segments on either side and
//!   charged to the one after.
//! - A path of fewer than two points has no segment: every term is 0, except C_block = 3 when
//!   it misses the mission's start or goal or lies outside the domain.
//!
//! The paper's own rule is that a path is feasible exactly when F < 2
//! ([`CostModel::feasible_below`]). With the vehicle-limit reading above, F < 2 implies
//! [`crate::path::Assessment::feasible`]; the converse fails only for a path whose joints are
//! sharper than T_theta while the vehicle allows them.
//!
//! Graph and sampling planners (A*, RRT*, PRM*) build paths edge by edge: a valid motion costs
//! its length over L_straight, so they minimise the path's length as the paper's RRT* and PRM*
//! do. Those motion costs add up to L_path / L_straight = 1 / (1 - C_length), which orders
//! paths as C_length does: `length` is the model's additive term. Curvature, block and
//! current depend on joints, on the clock along the whole path or on normalisation by N_all:
//! they are path-level, and these planners do not see them (they are checked on the
//! finished path, where the evaluation counts them).

use super::CostModel;
use crate::error::Result;
use crate::geom::Vec3;
use crate::kinematics::fillet::{self, FlownPiece};
use crate::params::{Bound, Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;
use crate::world::Dims;
use std::f64::consts::{FRAC_PI_2, PI};

crate::params! {
    /// The lfhh2019 model's parameters (`[cost] weights`); the paper's terms are unweighted.
    pub struct Lfhh2019Params {
        /// T_theta (degrees): a joint whose interior angle (180 = straight on) is below this
        /// is unable.
        min_interior_angle_deg: f64 = 30.0, ANGLE, "lfhh2019";
        /// Current speed (m/s) below which the flow counts as zero: the angle to it is then
        /// neutral (pi/2).
        still_current: f64 = 1e-9, NON_NEGATIVE, "lfhh2019 (chosen, A3)";
    }
}

const ANGLE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Closed(180.0) };
const NON_NEGATIVE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded };

/// The paper's feasibility threshold: any unable joint or blocked segment adds at least 2.
pub const FEASIBLE_BELOW: f64 = 2.0;

/// Per-segment flags in `Scratch::values`: blocked at `i`, unable at `n + i`.
const SET: f64 = 1.0;

#[derive(Clone, Debug)]
pub struct Lfhh2019Cost {
    pub params: Lfhh2019Params,
}

const TERMS: [&str; 4] = ["length", "curvature", "block", "current"];

impl Lfhh2019Cost {
    pub fn new(params: Checked<Lfhh2019Params>) -> Self {
        Self { params: params.into_inner() }
    }

    /// N / N_all + 2 when N > 0, else 0 (eqs. 8 and 9).
    pub fn count_term(n: usize, n_all: usize) -> f64 {
        if n == 0 {
            0.0
        } else {
            n as f64 / n_all.max(1) as f64 + 2.0
        }
    }

    /// alpha / pi for a segment of horizontal direction `h` in a horizontal current `c`: the
    /// angle between them over pi, 1/2 where either is (practically) zero.
    pub fn current_angle_ratio(&self, h: crate::geom::Vec2, c: crate::geom::Vec2) -> f64 {
        let (h_len, c_len) = (h.length(), c.length());
        // A NaN length fails both tests: neutral too.
        if h_len > 0.0 && c_len > self.params.still_current {
            (h.dot(c) / (h_len * c_len)).clamp(-1.0, 1.0).acos() / PI
        } else {
            FRAC_PI_2 / PI
        }
    }

    /// Marks the unable segments (joints and pitch of the polyline) and the segments with an
    /// end outside the domain or depth band, in `flags` (`n` segments).
    fn geometry_flags(&self, model: &PathModel<'_>, points: &[Vec3], flags: &mut [f64]) {
        let n = points.len() - 1;
        let veh = model.vehicle;
        let three_d = model.world.dims == Dims::Three;
        let validator = &model.validator;
        // Interior angle theta < T  <=>  the angle between the directions > pi - T
        //                           <=>  cos(direction change) < -cos(T).
        let cos_limit = -self.params.min_interior_angle_deg.to_radians().cos();
        // The same comparisons as `PathModel::assess`, so the verdicts agree at the limits.
        let cos_turn_limit = veh.max_turn.cos();
        let tan_pitch_limit = veh.max_pitch.tan();
        let mut prev_dir: Option<(Vec3, f64)> = None;
        let mut prev_h: Option<(crate::geom::Vec2, f64)> = None;
        let mut a_in = validator.in_bounds(points[0]).is_ok();
        for (i, w) in points.windows(2).enumerate() {
            let dir = w[1] - w[0];
            let b_in = validator.in_bounds(w[1]).is_ok();
            if !a_in || !b_in {
                flags[i] = SET;
            }
            a_in = b_in;
            let len = dir.length();
            let mut unable = false;
            if len > 0.0 {
                if let Some((pd, pl)) = prev_dir {
                    unable |= (pd.dot(dir) / (pl * len)).clamp(-1.0, 1.0) < cos_limit;
                }
                prev_dir = Some((dir, len));
            }
            let h = dir.truncate();
            let h_len = h.length();
            if h_len > 0.0 {
                if let Some((ph, ph_len)) = prev_h {
                    unable |= (ph.dot(h) / (ph_len * h_len)).clamp(-1.0, 1.0) < cos_turn_limit;
                }
                prev_h = Some((h, h_len));
            }
            if three_d && dir.z != 0.0 {
                let slope = if h_len > 0.0 { dir.z.abs() / h_len } else { f64::INFINITY };
                unable |= slope > tan_pitch_limit;
            }
            if unable {
                flags[n + i] = SET;
            }
        }
        let tol = model.endpoint_tolerance();
        let off = |p: Vec3, q: Vec3| {
            let d = p.distance(q);
            d.is_nan() || d > tol
        };
        if off(points[0], model.start) {
            flags[0] = SET;
        }
        if off(points[n], model.goal) {
            flags[n - 1] = SET;
        }
    }

    /// Flies the path on the evaluation's clock: marks the segments whose motions are
    /// invalid, and (with a turning radius) the segments after a turn that does not fit or
    /// climbs too steeply, and fills `times` with the arrival time at each point.
    fn clock_flags(model: &PathModel<'_>, points: &[Vec3], flags: &mut [f64], times: &mut Vec<f64>) {
        let n = points.len() - 1;
        let validator = &model.validator;
        times.clear();
        let Some(r) = model.vehicle.turn_radius else {
            let mut t = model.departure_time;
            times.push(t);
            for (i, w) in points.windows(2).enumerate() {
                let m = validator.motion_at(w[0], w[1], t, model.segment_speed(i));
                if !m.valid() {
                    flags[i] = SET;
                }
                t = m.arrival;
                times.push(t);
            }
            return;
        };
        // As `PathModel::assess` on the flown curve: the times at interior waypoints are
        // halfway round their turns.
        times.resize(n + 1, model.departure_time);
        let arrival = model.walk_flown(
            points,
            r,
            |m, check, _, t1| {
                if !check.valid() {
                    flags[m.segment] = SET;
                }
                match m.turn {
                    None => times[m.segment + 1] = t1,
                    Some((arc, c, k)) => {
                        if 2 * (c + 1) == k {
                            times[arc.waypoint] = t1;
                        }
                    }
                }
            },
            |_, _, _| {},
        );
        times[n] = arrival;
        let tol = model.settings.arc_tolerance;
        let three_d = model.world.dims == Dims::Three;
        let tan_pitch_limit = model.vehicle.max_pitch.tan();
        fillet::for_each_piece(points, r, |piece| {
            if let FlownPiece::Arc(arc) = piece {
                // The same test as the flown assessment's "too tight".
                let tight = !arc.corner.fits && arc.corner.deviation(r) > tol;
                let steep = three_d && arc.a != arc.b && arc.slope() > tan_pitch_limit;
                if tight || steep {
                    flags[n + arc.waypoint] = SET;
                }
            }
        });
    }
}

impl CostModel for Lfhh2019Cost {
    fn id(&self) -> &'static str {
        "lfhh2019"
    }

    fn term_names(&self) -> &'static [&'static str] {
        &TERMS
    }

    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch, terms: &mut [f64]) -> f64 {
        terms[..4].fill(0.0);
        if points.len() < 2 {
            let tol = model.endpoint_tolerance();
            let missed = match points.first() {
                None => true,
                Some(p) => {
                    !(p.distance(model.start) <= tol && p.distance(model.goal) <= tol)
                        || model.validator.in_bounds(*p).is_err()
                }
            };
            terms[2] = Self::count_term(usize::from(missed), 1);
            return terms[2];
        }
        let n = points.len() - 1;
        let flags = &mut scratch.values;
        flags.clear();
        flags.resize(2 * n, 0.0);
        self.geometry_flags(model, points, flags);
        Self::clock_flags(model, points, flags, &mut scratch.times);
        let times = &scratch.times;
        let n_block = flags[..n].iter().filter(|&&f| f == SET).count();
        let n_unable = flags[n..].iter().filter(|&&f| f == SET).count();

        let straight = model.start.distance(model.goal);
        let length = PathModel::length(points);
        let mut current = 0.0;
        for (i, w) in points.windows(2).enumerate() {
            let mid = (w[0] + w[1]) * 0.5;
            let t_mid = 0.5 * (times[i] + times[i + 1]);
            let c = model.world.current.velocity(mid, t_mid).truncate();
            current += self.current_angle_ratio((w[1] - w[0]).truncate(), c);
        }
        terms[0] = if length > 0.0 { 1.0 - straight / length } else { 0.0 };
        terms[1] = Self::count_term(n_unable, n);
        terms[2] = Self::count_term(n_block, n);
        terms[3] = current / n as f64;
        terms[..4].iter().sum()
    }

    /// The motion costs add up to L_path / L_straight, which orders paths as C_length does.
    fn additive_terms(&self) -> &'static [&'static str] {
        &TERMS[..1]
    }

    /// A motion costs its length over L_straight, whatever the current.
    fn motion_lower_bound(&self, model: &PathModel<'_>, distance: f64, _max_ground_speed: f64) -> f64 {
        distance / reference_length(model)
    }

    /// 1 / L_straight per metre, in any current: the motion cost is the length's share.
    fn cost_per_metre(&self, model: &PathModel<'_>) -> Option<f64> {
        Some(1.0 / reference_length(model))
    }

    /// A valid motion costs l / L_straight (a shortest path minimises C_length); curvature,
    /// block and current are path-level.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)> {
        let m = model.validator.motion_at(a, b, t0, v);
        if !m.valid() {
            return None;
        }
        Some((a.distance(b) / reference_length(model), m.arrival))
    }

    fn feasible_below(&self) -> Option<f64> {
        Some(FEASIBLE_BELOW)
    }
}

/// L_straight for the motion costs, kept away from 0 (a mission whose start is its goal).
fn reference_length(model: &PathModel<'_>) -> f64 {
    model.start.distance(model.goal).max(1e-9)
}

/// Builds the model from `[cost.weights]`.
pub fn build(table: &toml::Table) -> Result<Box<dyn CostModel>> {
    Ok(Box::new(Lfhh2019Cost::new(Lfhh2019Params::from_table(table, "cost.weights")?)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{Aabb, Vec2};
    use crate::mission::Mission;
    use crate::path::ModelSettings;
    use crate::vehicle::Vehicle;
    use crate::world::terrain::{GaussianPeaks, Peak, Terrain};
    use crate::world::{Current, Obstacle, Shape, World};
    use rand::Rng as _;

    /// A 3000 x 3000 m box, 1000 m deep, still water.
    fn world_3d() -> World {
        World::open(Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(3000.0, 3000.0, 0.0)))
    }

    /// The same box as a 2-D (sea surface) world.
    fn world_2d() -> World {
        let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(3000.0, 3000.0, 0.0)));
        w.dims = Dims::Two;
        w
    }

    /// A vehicle whose own limits never bind: any turn, any pitch.
    fn free_vehicle() -> Vehicle {
        Vehicle {
            speed: 2.0,
            max_turn: PI,
            max_pitch: FRAC_PI_2,
            depth_max: 1000.0,
            safety_distance: 5.0,
            ..Vehicle::default()
        }
    }

    fn cost() -> Lfhh2019Cost {
        Lfhh2019Cost::new(Lfhh2019Params::default().checked("cost.weights").unwrap())
    }

    fn term(terms: &[(&str, f64)], name: &str) -> f64 {
        terms.iter().find(|t| t.0 == name).unwrap().1
    }

    fn close(a: f64, b: f64) {
        assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{a} != {b}");
    }

    /// Evaluates `p` for a mission from its first to its last point.
    fn breakdown(w: &World, v: Vehicle, p: &[Vec3]) -> (f64, Vec<(&'static str, f64)>, bool) {
        let mission = Mission::new("m", v, p[0], *p.last().unwrap(), 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(w, &mission, &settings);
        let (total, terms) = cost().breakdown(&model, p);
        let feasible = model.assess(p, &mut Vec::new()).feasible();
        (total, terms, feasible)
    }

    /// Collinear waypoints in still water: no length excess, no joint, no block; the current
    /// term is neutral (1/2).
    #[test]
    fn a_straight_path_in_still_water_costs_one_half() {
        for (w, z) in [(world_2d(), 0.0), (world_3d(), -50.0)] {
            let p = [Vec3::new(100.0, 100.0, z), Vec3::new(1100.0, 600.0, z), Vec3::new(2100.0, 1100.0, z)];
            let (total, terms, feasible) = breakdown(&w, free_vehicle(), &p);
            for name in ["length", "curvature", "block"] {
                close(term(&terms, name), 0.0);
            }
            close(term(&terms, "current"), 0.5);
            close(total, 0.5);
            assert!(feasible);
        }
    }

    /// S = (0, 0), W = (300, 400), G = (600, 0): L_straight = 600, L_path = 1000.
    #[test]
    fn the_length_term_by_hand() {
        let p = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(300.0, 400.0, 0.0), Vec3::new(600.0, 0.0, 0.0)];
        let (_, terms, _) = breakdown(&world_2d(), free_vehicle(), &p);
        close(term(&terms, "length"), 1.0 - 600.0 / 1000.0);
        // The same in 3-D, with a dive: L_straight = |(600, 0, -100)|, L_path = 2 |(300, 400, -50)|.
        let p = [Vec3::new(0.0, 0.0, -100.0), Vec3::new(300.0, 400.0, -150.0), Vec3::new(600.0, 0.0, -200.0)];
        let (_, terms, _) = breakdown(&world_3d(), free_vehicle(), &p);
        let straight = (600.0f64 * 600.0 + 100.0 * 100.0).sqrt();
        let path = 2.0 * (300.0f64 * 300.0 + 400.0 * 400.0 + 50.0 * 50.0).sqrt();
        close(term(&terms, "length"), 1.0 - straight / path);
        // A path of zero length (a mission whose start is its goal) has no length excess.
        let q = [Vec3::new(500.0, 500.0, -100.0), Vec3::new(500.0, 500.0, -100.0)];
        let (total, terms, _) = breakdown(&world_3d(), free_vehicle(), &q);
        close(term(&terms, "length"), 0.0);
        close(total, 0.5);
    }

    /// A joint whose interior angle is 20 degrees is unable: 1 of 2 segments, so 1/2 + 2.
    /// The vehicle allows any turn, so tidepath calls the path feasible: the paper's rule is
    /// stricter there.
    #[test]
    fn a_sharp_joint_costs_one_over_n_all_plus_two() {
        let wp = Vec3::new(1500.0, 1000.0, -50.0);
        let back = 160f64.to_radians();
        let g = wp + Vec3::new(back.cos(), back.sin(), 0.0) * 1000.0;
        let p = [Vec3::new(500.0, 1000.0, -50.0), wp, g];
        let (total, terms, feasible) = breakdown(&world_3d(), free_vehicle(), &p);
        close(term(&terms, "curvature"), 0.5 + 2.0);
        assert!(total >= FEASIBLE_BELOW && feasible);
        // At 40 degrees the joint is able.
        let back = 140f64.to_radians();
        let p = [p[0], wp, wp + Vec3::new(back.cos(), back.sin(), 0.0) * 1000.0];
        let (_, terms, _) = breakdown(&world_3d(), free_vehicle(), &p);
        close(term(&terms, "curvature"), 0.0);
        // T_theta is a parameter: at 150 degrees this joint is unable; with a 2-D path of
        // three unable joints out of four segments the term is 3/4 + 2.
        let c = Lfhh2019Cost::new(
            Lfhh2019Params { min_interior_angle_deg: 150.0, ..Default::default() }.checked("w").unwrap(),
        );
        let mission = Mission::new("m", free_vehicle(), p[0], p[2], 0.0);
        let settings = ModelSettings::default();
        let w = world_3d();
        let model = PathModel::new(&w, &mission, &settings);
        close(term(&c.breakdown(&model, &p).1, "curvature"), 0.5 + 2.0);
        let zig = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1000.0, 0.0, 0.0),
            Vec3::new(1000.0, 1000.0, 0.0),
            Vec3::new(2000.0, 1000.0, 0.0),
            Vec3::new(2000.0, 2000.0, 0.0),
        ];
        let w = world_2d();
        let mission = Mission::new("m", free_vehicle(), zig[0], zig[4], 0.0);
        let model = PathModel::new(&w, &mission, &settings);
        close(term(&c.breakdown(&model, &zig).1, "curvature"), 0.75 + 2.0);
        close(term(&cost().breakdown(&model, &zig).1, "curvature"), 0.0);
    }

    /// The interior angle is measured in 3-D: two steep dives whose horizontal directions
    /// are opposite turn by about 11 degrees in 3-D (interior angle about 169): able.
    #[test]
    fn the_interior_angle_is_measured_in_3d() {
        let p =
            [Vec3::new(1000.0, 1000.0, -10.0), Vec3::new(1100.0, 1000.0, -510.0), Vec3::new(1000.0, 1000.0, -1000.0)];
        let (_, terms, feasible) = breakdown(&world_3d(), free_vehicle(), &p);
        close(term(&terms, "curvature"), 0.0);
        assert!(feasible);
        // Flattened to the plane it would be a 0 degree interior angle.
        let flat: Vec<Vec3> = p.iter().map(|q| Vec3::new(q.x, q.y, -10.0)).collect();
        let (_, terms, _) = breakdown(&world_3d(), free_vehicle(), &flat);
        close(term(&terms, "curvature"), 0.5 + 2.0);
    }

    /// The middle one of three segments crosses a circle: 1/3 + 2; its motion has no cost.
    #[test]
    fn a_segment_through_a_circle_is_blocked() {
        let mut w = world_2d();
        w.obstacles.push(Obstacle::fixed(Shape::Circle { center: Vec2::new(1500.0, 1000.0), radius: 100.0 }));
        let p = [
            Vec3::new(100.0, 1000.0, 0.0),
            Vec3::new(1000.0, 1000.0, 0.0),
            Vec3::new(2000.0, 1000.0, 0.0),
            Vec3::new(2900.0, 1000.0, 0.0),
        ];
        let (total, terms, feasible) = breakdown(&w, free_vehicle(), &p);
        close(term(&terms, "block"), 1.0 / 3.0 + 2.0);
        close(total, 1.0 / 3.0 + 2.0 + 0.5);
        assert!(!feasible);
        let mission = Mission::new("m", free_vehicle(), p[0], p[3], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        assert!(cost().motion_cost(&model, p[1], p[2], 0.0).is_none());
        assert!(cost().motion_cost(&model, p[0], p[1], 0.0).is_some());
        // Passing within the safety distance (5 m) blocks too: 3 m from the circle.
        let q = [Vec3::new(100.0, 1103.0, 0.0), Vec3::new(2900.0, 1103.0, 0.0)];
        let (_, terms, _) = breakdown(&w, free_vehicle(), &q);
        close(term(&terms, "block"), 1.0 + 2.0);
    }

    /// A sphere in 3-D, the seabed and a waypoint out of the domain block their segments.
    #[test]
    fn spheres_the_seabed_and_the_domain_block() {
        let mut w = world_3d();
        w.terrain = Terrain::Peaks(GaussianPeaks { base: -500.0, peaks: vec![], ceiling: None });
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(1500.0, 1000.0, -200.0), radius: 100.0 }));
        let p = [
            Vec3::new(100.0, 1000.0, -200.0),
            Vec3::new(1000.0, 1000.0, -200.0),
            Vec3::new(2000.0, 1000.0, -200.0), // through the sphere
            Vec3::new(2200.0, 1000.0, -497.0), // within 5 m of the seabed
            Vec3::new(2400.0, 1000.0, -200.0),
            Vec3::new(2600.0, 3200.0, -200.0), // outside the box
            Vec3::new(2800.0, 1000.0, -200.0),
        ];
        let (_, terms, feasible) = breakdown(&w, free_vehicle(), &p);
        // Segments 1, 2, 3, 4 and 5 of 6.
        close(term(&terms, "block"), 5.0 / 6.0 + 2.0);
        assert!(!feasible);
    }

    /// A uniform current at 60 degrees from east: an eastward segment is 60 degrees from it
    /// (1/3), a northward one 30 (1/6), a westward one 120 (2/3), a vertical one neutral.
    #[test]
    fn the_current_term_by_hand() {
        let mut w = world_3d();
        let a = 60f64.to_radians();
        w.current = Current::Uniform(Vec3::new(0.5 * a.cos(), 0.5 * a.sin(), 0.0));
        let p = [
            Vec3::new(1000.0, 1000.0, -100.0),
            Vec3::new(2000.0, 1000.0, -100.0),
            Vec3::new(2000.0, 2000.0, -100.0),
            Vec3::new(1500.0, 2000.0, -100.0),
            Vec3::new(1500.0, 2000.0, -300.0),
        ];
        let (_, terms, feasible) = breakdown(&w, free_vehicle(), &p);
        close(term(&terms, "current"), (1.0 / 3.0 + 1.0 / 6.0 + 2.0 / 3.0 + 0.5) / 4.0);
        // A vertical segment is steeper than any pitch limit, for tidepath and for the model.
        close(term(&terms, "curvature"), 0.25 + 2.0);
        assert!(!feasible);
        // Straight with the current: 0; straight against it: 1.
        let along =
            [Vec3::new(1000.0, 1000.0, -100.0), Vec3::new(1000.0 + 500.0 * a.cos(), 1000.0 + 500.0 * a.sin(), -100.0)];
        close(term(&breakdown(&w, free_vehicle(), &along).1, "current"), 0.0);
        let against = [along[1], along[0]];
        close(term(&breakdown(&w, free_vehicle(), &against).1, "current"), 1.0);
    }

    /// The current is read at the segment's midpoint: below a counter-clockwise vortex's
    /// centre the flow runs east, along an eastward segment (alpha = 0), though at the
    /// segment's ends it turns north and south. Through the centre, where the flow is zero,
    /// the angle is neutral.
    #[test]
    fn the_current_is_read_at_the_midpoint() {
        let mut w = world_2d();
        let vortex = crate::world::current::LambOseen { x: 1500.0, y: 1000.0, strength: 50.0, core_radius: 50.0 };
        w.current = Current::Vortices(vec![vortex]);
        let p = [Vec3::new(1000.0, 900.0, 0.0), Vec3::new(2000.0, 900.0, 0.0)];
        let ends = w.current.velocity(p[0], 0.0).truncate();
        assert!(ends.y.abs() > 0.1 * ends.length(), "the flow at the ends is not along the segment");
        let (_, terms, _) = breakdown(&w, free_vehicle(), &p);
        close(term(&terms, "current"), 0.0);
        let through = [Vec3::new(1000.0, 1000.0, 0.0), Vec3::new(2000.0, 1000.0, 0.0)];
        let (_, terms, _) = breakdown(&w, free_vehicle(), &through);
        close(term(&terms, "current"), 0.5);
    }

    /// Flow below the threshold counts as none: the angle is neutral whatever the direction.
    /// With a threshold of 0 the same weak flow is measured.
    #[test]
    fn practically_zero_flow_is_neutral() {
        let mut w = world_2d();
        w.current = Current::Uniform(Vec3::new(-1e-12, 0.0, 0.0));
        let p = [Vec3::new(100.0, 100.0, 0.0), Vec3::new(1100.0, 100.0, 0.0)];
        let (_, terms, _) = breakdown(&w, free_vehicle(), &p);
        close(term(&terms, "current"), 0.5);
        let c = Lfhh2019Cost::new(Lfhh2019Params { still_current: 0.0, ..Default::default() }.checked("w").unwrap());
        let mission = Mission::new("m", free_vehicle(), p[0], p[1], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        close(term(&c.breakdown(&model, &p).1, "current"), 1.0);
        close(c.current_angle_ratio(Vec2::new(1.0, 0.0), Vec2::ZERO), 0.5);
    }

    /// The vehicle's own limits make joints unable: a 90 degree turn (interior angle 90, fine
    /// for the paper) against a 60 degree limit, a 45 degree dive against a 30 degree limit,
    /// and with a turning radius a turn whose fillet does not fit.
    #[test]
    fn a_joint_over_the_vehicles_limits_is_unable() {
        let w = world_3d();
        let limited = Vehicle { max_turn: 60f64.to_radians(), max_pitch: 30f64.to_radians(), ..free_vehicle() };
        let turn =
            [Vec3::new(500.0, 500.0, -100.0), Vec3::new(1500.0, 500.0, -100.0), Vec3::new(1500.0, 1500.0, -100.0)];
        let (_, terms, _) = breakdown(&w, free_vehicle(), &turn);
        close(term(&terms, "curvature"), 0.0);
        let (total, terms, feasible) = breakdown(&w, limited.clone(), &turn);
        close(term(&terms, "curvature"), 0.5 + 2.0);
        assert!(total >= FEASIBLE_BELOW && !feasible);
        // Level, then a 45 degree dive, then level: one steep segment of three.
        let dive = [
            Vec3::new(500.0, 500.0, -100.0),
            Vec3::new(1000.0, 500.0, -100.0),
            Vec3::new(1200.0, 500.0, -300.0),
            Vec3::new(2000.0, 500.0, -300.0),
        ];
        let (_, terms, _) = breakdown(&w, free_vehicle(), &dive);
        close(term(&terms, "curvature"), 0.0);
        let (_, terms, feasible) = breakdown(&w, limited.clone(), &dive);
        close(term(&terms, "curvature"), 1.0 / 3.0 + 2.0);
        assert!(!feasible);
        // 2-D has no pitch.
        let (_, terms, _) = breakdown(&world_2d(), limited, &[Vec3::new(0.0, 0.0, 0.0), Vec3::new(10.0, 0.0, 0.0)]);
        close(term(&terms, "curvature"), 0.0);
        // A 90 degree turn needs r of each leg: 100 m legs allow r = 100, not 200.
        let short = [Vec3::new(500.0, 500.0, -100.0), Vec3::new(600.0, 500.0, -100.0), Vec3::new(600.0, 600.0, -100.0)];
        let fits = Vehicle { turn_radius: Some(100.0), ..free_vehicle() };
        let (_, terms, feasible) = breakdown(&w, fits, &short);
        close(term(&terms, "curvature"), 0.0);
        assert!(feasible);
        let wide = Vehicle { turn_radius: Some(200.0), ..free_vehicle() };
        let (_, terms, feasible) = breakdown(&w, wide, &short);
        close(term(&terms, "curvature"), 0.5 + 2.0);
        assert!(!feasible);
    }

    /// A path that stops short of the goal blocks its last segment.
    #[test]
    fn a_path_off_its_mission_is_blocked() {
        let w = world_2d();
        let (s, g) = (Vec3::new(100.0, 100.0, 0.0), Vec3::new(2000.0, 100.0, 0.0));
        let mission = Mission::new("m", free_vehicle(), s, g, 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let p = [s, Vec3::new(1000.0, 100.0, 0.0), Vec3::new(1500.0, 100.0, 0.0)];
        close(term(&cost().breakdown(&model, &p).1, "block"), 0.5 + 2.0);
        assert!(!model.assess(&p, &mut Vec::new()).feasible());
        // No segment at all: 3.
        close(cost().breakdown(&model, &[s]).0, 3.0);
        close(cost().breakdown(&model, &[]).0, 3.0);
    }

    /// The motion costs of a path add up to L_path / L_straight = 1 / (1 - C_length), and
    /// the lower bound is below each.
    #[test]
    fn motion_costs_add_up_to_the_length_ratio() {
        let mut w = world_3d();
        w.current = Current::Uniform(Vec3::new(0.3, -0.2, 0.0));
        let p = [
            Vec3::new(100.0, 100.0, -50.0),
            Vec3::new(900.0, 700.0, -250.0),
            Vec3::new(1500.0, 800.0, -300.0),
            Vec3::new(2500.0, 2000.0, -100.0),
        ];
        let mission = Mission::new("m", free_vehicle(), p[0], p[3], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let c = cost();
        let (_, terms) = c.breakdown(&model, &p);
        let (mut t, mut sum) = (model.departure_time, 0.0);
        for s in p.windows(2) {
            let (cost, arrival) = c.motion_cost(&model, s[0], s[1], t).unwrap();
            assert!(cost >= c.motion_lower_bound(&model, s[0].distance(s[1]), 10.0) - 1e-15);
            close(cost, s[0].distance(s[1]) * c.cost_per_metre(&model).unwrap());
            sum += cost;
            t = arrival;
        }
        close(1.0 - 1.0 / sum, term(&terms, "length"));
        assert_eq!(c.additive_terms(), ["length"]);
        assert_eq!(c.feasible_below(), Some(2.0));
    }

    /// The paper's rule implies tidepath's: on random paths in a small world with a seabed,
    /// spheres, a current and (sometimes) a turning radius, F < 2 never comes with a
    /// violation. Both verdicts occur, so the check is not empty.
    #[test]
    fn f_below_two_implies_feasible_on_random_paths() {
        let mut rng = crate::rng::run_rng(7, 0);
        let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -400.0), Vec3::new(2000.0, 2000.0, 0.0)));
        w.terrain = Terrain::Peaks(GaussianPeaks {
            base: -380.0,
            peaks: vec![Peak { x: 1000.0, y: 1000.0, height: 200.0, sigma_x: 300.0, sigma_y: 300.0 }],
            ceiling: None,
        });
        for (x, y) in [(500.0, 1500.0), (1500.0, 500.0), (1400.0, 1500.0)] {
            w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(x, y, -150.0), radius: 150.0 }));
        }
        let c = cost();
        let settings = ModelSettings::default();
        let (mut below, mut above) = (0, 0);
        for k in 0..600 {
            w.current = match k % 3 {
                0 => Current::None,
                1 => Current::Uniform(Vec3::new(0.4, 0.1, 0.0)),
                _ => Current::Uniform(Vec3::new(-2.0, 1.5, 0.0)),
            };
            let v = Vehicle {
                max_turn: rng.random_range(30.0f64..180.0).to_radians(),
                max_pitch: rng.random_range(10.0f64..60.0).to_radians(),
                depth_max: 390.0,
                turn_radius: (k % 4 == 0).then_some(40.0),
                ..free_vehicle()
            };
            let point = |rng: &mut crate::rng::Rng| {
                Vec3::new(rng.random_range(0.0..2000.0), rng.random_range(0.0..2000.0), rng.random_range(-300.0..-20.0))
            };
            let (s, g) = (point(&mut rng), point(&mut rng));
            let n = rng.random_range(0..4usize);
            let mut p = vec![s];
            for _ in 0..n {
                // Mostly near the straight line, so some paths are feasible.
                let u = rng.random_range(0.0..1.0);
                let q = s.lerp(g, u) + (point(&mut rng) - Vec3::new(1000.0, 1000.0, -160.0)) * 0.1;
                p.push(q);
            }
            p.sort_by(|a, b| a.distance(s).total_cmp(&b.distance(s)));
            p.push(g);
            let mission = Mission::new("m", v, s, g, 0.0);
            let model = PathModel::new(&w, &mission, &settings);
            let f = c.cost(&model, &p, &mut Scratch::default());
            let feasible = model.assess(&p, &mut Vec::new()).feasible();
            if f < FEASIBLE_BELOW {
                assert!(feasible, "F = {f} < 2 but infeasible: {:?}", model.violations(&p));
                below += 1;
            } else {
                above += 1;
            }
        }
        assert!(below > 30 && above > 30, "F < 2 on {below} paths, F >= 2 on {above}");
    }

    /// Once the scratch has grown, evaluating again reuses it and gives the same terms.
    #[test]
    fn evaluation_reuses_the_scratch() {
        let w = world_3d();
        let p = [Vec3::new(100.0, 100.0, -50.0), Vec3::new(900.0, 700.0, -250.0), Vec3::new(2500.0, 2000.0, -100.0)];
        let mission = Mission::new("m", Vehicle { turn_radius: Some(50.0), ..free_vehicle() }, p[0], p[2], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let mut scratch = Scratch::default();
        let first = cost().cost(&model, &p, &mut scratch);
        let (cap_v, cap_t) = (scratch.values.capacity(), scratch.times.capacity());
        assert_eq!(cost().cost(&model, &p, &mut scratch), first);
        assert_eq!((scratch.values.capacity(), scratch.times.capacity()), (cap_v, cap_t));
    }

    #[test]
    fn the_registry_builds_it_and_refuses_unknown_weights() {
        let reg = crate::cost::registry();
        let build = reg.get("lfhh2019").unwrap().build;
        let m = build(&toml::Table::new()).unwrap();
        assert_eq!((m.id(), m.feasible_below()), ("lfhh2019", Some(2.0)));
        assert_eq!(m.term_names(), ["length", "curvature", "block", "current"]);
        let t: toml::Table = toml::from_str("min_interior_angle_deg = 45.0\nstill_current = 1e-6").unwrap();
        build(&t).unwrap();
        let t: toml::Table = toml::from_str("length = 2.0").unwrap();
        let e = build(&t).err().unwrap().to_string();
        assert!(e.starts_with("cost.weights.length"), "{e}");
        let t: toml::Table = toml::from_str("min_interior_angle_deg = 200.0").unwrap();
        let e = build(&t).err().unwrap().to_string();
        assert!(e.starts_with("cost.weights.min_interior_angle_deg"), "{e}");
        // The other models keep no rule of their own.
        assert_eq!((reg.get("general").unwrap().build)(&toml::Table::new()).unwrap().feasible_below(), None);
    }
}
