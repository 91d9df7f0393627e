//! State validity and motion validation, shared by every planner and by the path evaluation
//! (OMPL's `StateValidityChecker` and `MotionValidator` are the model).
//!
//! * [`Validator::state`]: is a point valid at time t (in the domain and depth band, clear of
//!   the seabed and of every obstacle by the safety distance)?
//! * [`Validator::motion`]: is the straight motion a -> b valid when leaving at t0? It returns
//!   the arrival time through the currents, every object the motion comes too close to, and the
//!   pieces where the current stops the vehicle.
//!
//! The motion check runs on the same clock as the travel time: a segment is flown in pieces
//! ([`Validator::for_each_piece`]), each at the ground speed the travel model gives there, and
//! each moving obstacle is tested against each piece over the times the vehicle is on it. Within
//! a piece the ground speed is constant, so the test is exact there (an obstacle moving at
//! constant velocity sees a straight relative segment). A plan judged feasible is therefore
//! feasible under the timing it reports. Fixed obstacles and the seabed do not depend on time
//! and are tested once per segment.

// `!(d >= margin)` is deliberate: a NaN must fail every "valid" test.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod obstacle_index;
mod travel;

pub use travel::{crab_ground_speed, TravelModel, MIN_SPEED_FRACTION};

use crate::geom::Vec3;
use crate::vehicle::Vehicle;
use crate::world::{Current, Dims, World};
use obstacle_index::ObstacleIndex;

/// Numerical settings of the evaluation, set per scenario under `[model]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelSettings {
    pub travel: TravelModel,
    /// Longest sub-step (m) over which the current is taken as constant when integrating
    /// travel time along a segment (crab model). Smaller is more accurate and slower.
    pub current_step: f64,
    /// How far (m) the chords a flown turn is checked on may stray from the arc (their
    /// sagitta), for vehicles with a turning radius: smaller is more accurate and slower.
    pub arc_tolerance: f64,
}

/// Default [`ModelSettings::arc_tolerance`] (m): 5 cm, well inside any safety distance; a
/// quarter turn at 30 m radius is then checked on 14 chords.
pub const ARC_TOLERANCE: f64 = 0.05;

impl Default for ModelSettings {
    fn default() -> Self {
        Self { travel: TravelModel::Crab, current_step: 500.0, arc_tolerance: ARC_TOLERANCE }
    }
}

/// Relative slack on the domain box, so waypoints placed exactly on a face by an encoding are
/// not rejected by rounding.
pub const BOUNDS_SLACK: f64 = 1e-9;

/// Most pieces one segment is flown in. A segment longer than `MAX_PIECES` current steps (only
/// a waypoint far outside the domain makes one) uses longer pieces, so a hostile plan file
/// cannot make one evaluation run for hours.
pub const MAX_PIECES: f64 = 100_000.0;

/// Moving obstacles whose hits are counted once per motion; beyond this many (a world built in
/// code, scenario files are capped lower), a hit may be counted once per piece.
const MAX_TRACKED_MOVING: usize = 1024;

/// Why a state is invalid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StateIssue {
    OutsideDomain,
    OutsideDepthBand,
    /// Clearance above the seabed (m, negative below it), less than the safety distance.
    Seabed {
        clearance: f64,
    },
    /// Obstacle `index`, with `inside` true when the point is inside the shape itself.
    Obstacle {
        index: usize,
        inside: bool,
    },
    /// The current forecast has no data here (land or fill in its file).
    NoCurrentData,
    /// The wave forecast has no data here, and the vehicle is a wave glider.
    NoWaveData,
}

/// One reason a motion is invalid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionIssue {
    /// The segment comes closer to the seabed than the safety distance.
    Terrain,
    /// The segment comes closer to obstacle `k` than the safety distance, at the vehicle's clock.
    Obstacle(usize),
    /// The current stops the vehicle from holding the track on `pieces` pieces.
    Current { pieces: u32 },
    /// The motion passes where the current forecast has no data.
    NoCurrentData,
    /// A wave glider's motion passes where the wave forecast has no data.
    NoWaveData,
}

/// The verdict on one motion.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MotionCheck {
    /// Time of arrival at the end point (s).
    pub arrival: f64,
    /// Objects (the seabed counts as one) closer than the safety distance.
    pub collisions: u32,
    /// Pieces where the current stops the vehicle.
    pub blocked: u32,
    /// 1 for each forecast (current; waves for a glider) with no data where the motion passes.
    pub gaps: u32,
    /// The first issue found (seabed, then fixed obstacles, then moving ones, then current).
    pub first: Option<MotionIssue>,
}

impl MotionCheck {
    pub fn valid(&self) -> bool {
        self.first.is_none()
    }
}

/// A piece of a segment flown at constant ground speed: from `p0` at `t0` to `p1` at `t1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    pub p0: Vec3,
    pub p1: Vec3,
    pub t0: f64,
    pub t1: f64,
}

/// A world, a vehicle and the model settings: everything needed to judge states and motions.
#[derive(Clone, Debug)]
pub struct Validator<'a> {
    pub world: &'a World,
    pub vehicle: &'a Vehicle,
    pub settings: &'a ModelSettings,
    /// Which fixed obstacles each segment needs testing against; built once and shared, so a
    /// copy of the validator (a path model given per-segment speeds) costs no allocation.
    obstacles: std::sync::Arc<ObstacleIndex>,
}

impl<'a> Validator<'a> {
    pub fn new(world: &'a World, vehicle: &'a Vehicle, settings: &'a ModelSettings) -> Self {
        let obstacles = std::sync::Arc::new(ObstacleIndex::new(world, vehicle.safety_distance));
        Self { world, vehicle, settings, obstacles }
    }

    /// Is `p` inside the domain (and, in 3-D, the depth band), with the slack encodings need?
    pub fn in_bounds(&self, p: Vec3) -> Result<(), StateIssue> {
        let slack = self.world.bounds.size().max_element() * BOUNDS_SLACK;
        if !self.world.bounds.inflate(slack).contains(p) {
            return Err(StateIssue::OutsideDomain);
        }
        let veh = self.vehicle;
        if self.world.dims == Dims::Three && (p.z > veh.z_max() + slack || p.z < veh.z_min() - slack) {
            return Err(StateIssue::OutsideDepthBand);
        }
        Ok(())
    }

    /// Is `p` a valid state at time `t`? The first issue found, if any.
    pub fn state(&self, p: Vec3, t: f64) -> Result<(), StateIssue> {
        self.in_bounds(p)?;
        let safety = self.vehicle.safety_distance;
        let clearance = p.z - self.world.terrain.elevation(p.x, p.y);
        if !(clearance >= safety) {
            return Err(StateIssue::Seabed { clearance });
        }
        for (index, o) in self.world.obstacles.iter().enumerate() {
            if o.contains(p, t, safety) {
                return Err(StateIssue::Obstacle { index, inside: o.contains(p, t, 0.0) });
            }
        }
        self.forecast_data(p)
    }

    /// Is `p` valid whatever the time: the checks of [`Validator::state`] without the moving
    /// obstacles. Used for a goal, whose arrival time is not known before planning.
    pub fn fixed_state(&self, p: Vec3) -> Result<(), StateIssue> {
        self.in_bounds(p)?;
        let safety = self.vehicle.safety_distance;
        let clearance = p.z - self.world.terrain.elevation(p.x, p.y);
        if !(clearance >= safety) {
            return Err(StateIssue::Seabed { clearance });
        }
        for (index, o) in self.world.obstacles.iter().enumerate().filter(|(_, o)| o.is_fixed()) {
            if o.contains(p, 0.0, safety) {
                return Err(StateIssue::Obstacle { index, inside: o.contains(p, 0.0, 0.0) });
            }
        }
        self.forecast_data(p)
    }

    /// Whether the forecasts the vehicle's speed depends on have data at `p`: the current's
    /// always, the waves' for a wave glider.
    fn forecast_data(&self, p: Vec3) -> Result<(), StateIssue> {
        if !self.world.current.has_data(p) {
            return Err(StateIssue::NoCurrentData);
        }
        if self.vehicle.glider().is_some() && !self.world.waves.has_data(p) {
            return Err(StateIssue::NoWaveData);
        }
        Ok(())
    }

    /// One line saying why state `p` is invalid, for messages.
    pub fn describe(&self, p: Vec3, issue: StateIssue) -> String {
        let shown = match self.world.frame {
            Some(_) => format!("({})", self.world.point(p)),
            None => self.world.point(p),
        };
        let veh = self.vehicle;
        match issue {
            StateIssue::OutsideDomain => {
                format!("{shown} is outside the domain {}", self.world.domain_text())
            }
            StateIssue::OutsideDepthBand => {
                format!("{shown} is outside the vehicle's depth band [{}, {}] m", veh.depth_min, veh.depth_max)
            }
            StateIssue::Seabed { clearance } => {
                let seabed = p.z - clearance;
                if seabed > 0.0 {
                    return format!("{shown} is on land (ground at {seabed:.1} m above the sea surface)");
                }
                let what =
                    if clearance < 0.0 { "below the seabed" } else { "within the safety distance of the seabed" };
                format!("{shown} is {what} (seabed at {seabed:.1} m, safety distance {} m)", veh.safety_distance)
            }
            StateIssue::Obstacle { index, inside } => {
                let what = if inside { "inside" } else { "within the safety distance of" };
                format!("{shown} is {what} obstacle {index} (world.obstacles[{index}])")
            }
            StateIssue::NoCurrentData => {
                format!("{shown} has no current data in the forecast (land or fill in world.current.path)")
            }
            StateIssue::NoWaveData => {
                format!("{shown} has no wave data in the forecast (land or fill in world.waves)")
            }
        }
    }

    /// [`Validator::for_each_piece_at`] at the vehicle's cruise speed.
    #[inline]
    pub fn for_each_piece(&self, a: Vec3, b: Vec3, t0: f64, f: impl FnMut(Piece)) -> (f64, u32) {
        self.for_each_piece_at(a, b, t0, self.vehicle.speed, f)
    }

    /// Flies a -> b leaving at `t0` at through-water speed `v` in pieces of constant ground
    /// speed, calling `f` for each, and returns the arrival time and the number of pieces the
    /// current makes impossible (flown at [`MIN_SPEED_FRACTION`] of `v` so the clock stays
    /// finite).
    ///
    /// Crab model: one piece in still water or a uniform current, else pieces of at most
    /// `current_step` metres, each at the ground speed for the current at its midpoint when the
    /// vehicle enters it. Vector-sum model: one piece at the model's mean speed. A wave glider
    /// ignores `v` and the travel model: its pieces are cut the same way (also where the waves
    /// vary) and each is flown at [`crate::vehicle::GliderSpeed::ground_speed`] for the waves
    /// and current at its midpoint.
    #[inline]
    pub fn for_each_piece_at(&self, a: Vec3, b: Vec3, t0: f64, v: f64, mut f: impl FnMut(Piece)) -> (f64, u32) {
        let len = a.distance(b);
        if len == 0.0 {
            f(Piece { p0: a, p1: b, t0, t1: t0 });
            return (t0, 0);
        }
        let d = (b - a) / len;
        let current = &self.world.current;
        if let Some(glider) = self.vehicle.glider() {
            let n = self.pieces_of(len);
            let step = len / n as f64;
            let (mut t, mut blocked) = (t0, 0);
            let mut p0 = a;
            for k in 0..n {
                let mid = a + d * (step * (k as f64 + 0.5));
                let h = self.world.waves.height(mid, t);
                let g = match glider.ground_speed(h, current.velocity(mid, t).dot(d)) {
                    Some(g) => g,
                    None => {
                        blocked += 1;
                        glider.min_speed
                    }
                };
                let t1 = t + step / g;
                let p1 = if k + 1 == n { b } else { a + d * (step * (k + 1) as f64) };
                f(Piece { p0, p1, t0: t, t1 });
                p0 = p1;
                t = t1;
            }
            return (t, blocked);
        }
        match self.settings.travel {
            TravelModel::Crab => {
                if let Current::None = current {
                    let t1 = t0 + len / v;
                    f(Piece { p0: a, p1: b, t0, t1 });
                    return (t1, 0);
                }
                let n = self.pieces_of(len);
                let step = len / n as f64;
                let (mut t, mut blocked) = (t0, 0);
                let mut p0 = a;
                for k in 0..n {
                    let mid = a + d * (step * (k as f64 + 0.5));
                    let g = match crab_ground_speed(d, v, current.velocity(mid, t)) {
                        Some(g) => g,
                        None => {
                            blocked += 1;
                            MIN_SPEED_FRACTION * v
                        }
                    };
                    let t1 = t + step / g;
                    let p1 = if k + 1 == n { b } else { a + d * (step * (k + 1) as f64) };
                    f(Piece { p0, p1, t0: t, t1 });
                    p0 = p1;
                    t = t1;
                }
                (t, blocked)
            }
            TravelModel::VectorSum => {
                let dt = travel::vector_sum_time(d, len, v, current, a, b, t0);
                f(Piece { p0: a, p1: b, t0, t1: t0 + dt });
                (t0 + dt, 0)
            }
        }
    }

    /// How many pieces a segment of length `len` is flown in (crab model): one in still water
    /// or a uniform current, else one per `current_step`, at most [`MAX_PIECES`]. A segment
    /// longer than the domain's diagonal must leave the domain (a violation whatever its clock)
    /// and is flown as one piece, so a hostile plan of far-away waypoints costs no more to
    /// judge than a short one.
    #[inline]
    pub fn pieces_of(&self, len: f64) -> u32 {
        let waves_vary = self.vehicle.glider().is_some() && self.world.waves.varies();
        match self.world.current {
            Current::None | Current::Uniform(_) if !waves_vary => 1,
            _ if len > self.world.bounds.size().length() => 1,
            _ => (len / self.settings.current_step).ceil().clamp(1.0, MAX_PIECES) as u32,
        }
    }

    /// Time to fly a -> b leaving at `t0`, and the number of impossible pieces.
    #[inline]
    pub fn travel_time(&self, a: Vec3, b: Vec3, t0: f64) -> (f64, u32) {
        let (t1, blocked) = self.for_each_piece(a, b, t0, |_| {});
        (t1 - t0, blocked)
    }

    /// Judges the motion a -> b leaving at `t0` at cruise speed; see [`Validator::motion_with_at`].
    #[inline]
    pub fn motion(&self, a: Vec3, b: Vec3, t0: f64) -> MotionCheck {
        self.motion_with_at(a, b, t0, self.vehicle.speed, |_| {})
    }

    /// Judges the motion a -> b leaving at `t0` at through-water speed `v`.
    #[inline]
    pub fn motion_at(&self, a: Vec3, b: Vec3, t0: f64, v: f64) -> MotionCheck {
        self.motion_with_at(a, b, t0, v, |_| {})
    }

    /// [`Validator::motion_with_at`] at cruise speed.
    #[inline]
    pub fn motion_with(&self, a: Vec3, b: Vec3, t0: f64, on_issue: impl FnMut(MotionIssue)) -> MotionCheck {
        self.motion_with_at(a, b, t0, self.vehicle.speed, on_issue)
    }

    /// Judges the motion a -> b leaving at `t0` at through-water speed `v` and calls
    /// `on_issue` for every issue: the seabed once, each obstacle once, the current once.
    /// Allocation-free.
    pub fn motion_with_at(
        &self,
        a: Vec3,
        b: Vec3,
        t0: f64,
        v: f64,
        mut on_issue: impl FnMut(MotionIssue),
    ) -> MotionCheck {
        let world = self.world;
        let safety = self.vehicle.safety_distance;
        let mut out = MotionCheck { arrival: t0, ..MotionCheck::default() };
        let mut report = |out: &mut MotionCheck, issue| {
            out.first.get_or_insert(issue);
            on_issue(issue);
        };
        if world.segment_hits_terrain(a, b, safety) {
            out.collisions += 1;
            report(&mut out, MotionIssue::Terrain);
        }
        // Fixed obstacles ignore the times.
        self.obstacles.for_each_candidate(a, b, |k| {
            if world.obstacles[k].segment_hits(a, b, t0, t0, safety) {
                out.collisions += 1;
                report(&mut out, MotionIssue::Obstacle(k));
            }
        });
        let moving = self.obstacles.moving();
        let (arrival, blocked) = if moving.is_empty() {
            self.for_each_piece_at(a, b, t0, v, |_| {})
        } else {
            // The clock first; then a box test over the whole motion clears most moving
            // obstacles at once, and only if one remains are the pieces walked again (the
            // same pieces, at the same times) to test those piece by piece.
            let (arrival, blocked) = self.for_each_piece_at(a, b, t0, v, |_| {});
            let (lo, hi) = (a.min(b) - Vec3::splat(safety), a.max(b) + Vec3::splat(safety));
            // Bit j set: moving obstacle j cannot come near (tracked ones only).
            let mut clear = [0u64; MAX_TRACKED_MOVING / 64];
            let mut near = false;
            for j in 0..moving.len() {
                if self.obstacles.moving_may_come_within(j, lo, hi, t0, arrival) {
                    near = true;
                } else if j < MAX_TRACKED_MOVING {
                    clear[j / 64] |= 1 << (j % 64);
                }
            }
            if near {
                self.for_each_piece_at(a, b, t0, v, |pc| {
                    for (j, &k) in moving.iter().enumerate() {
                        let tracked = j < MAX_TRACKED_MOVING;
                        if tracked && clear[j / 64] & (1 << (j % 64)) != 0 {
                            continue;
                        }
                        if world.obstacles[k as usize].segment_hits(pc.p0, pc.p1, pc.t0, pc.t1, safety) {
                            // Counted once: a hit obstacle joins the cleared ones.
                            if tracked {
                                clear[j / 64] |= 1 << (j % 64);
                            }
                            out.collisions += 1;
                            report(&mut out, MotionIssue::Obstacle(k as usize));
                        }
                    }
                });
            }
            (arrival, blocked)
        };
        out.arrival = arrival;
        out.blocked = blocked;
        if blocked > 0 {
            report(&mut out, MotionIssue::Current { pieces: blocked });
        }
        if world.current.first_gap_on(a, b).is_some() {
            out.gaps += 1;
            report(&mut out, MotionIssue::NoCurrentData);
        }
        if self.vehicle.glider().is_some() && world.waves.first_gap_on(a, b).is_some() {
            out.gaps += 1;
            report(&mut out, MotionIssue::NoWaveData);
        }
        out
    }

    /// The farthest point p of a -> b such that the motion a -> p leaving at `t0` is valid,
    /// to within `resolution` metres, and the motion checks it took (OMPL's
    /// `checkMotion(s1, s2, lastValid)` is the model). Sampling planners extend a blocked edge
    /// this far. `None` when a -> b is valid (nothing to cut) or when no prefix longer than
    /// `resolution` was found valid.
    ///
    /// Bisection on the fraction of the segment: every point returned is the end of a motion
    /// [`Validator::motion`] judged valid, so the cut edge is valid however the blocked part
    /// looks (several obstacles, a gap in the current). About log2(|ab| / resolution) checks.
    pub fn last_valid(&self, a: Vec3, b: Vec3, t0: f64, resolution: f64) -> (Option<Vec3>, u32) {
        let len = a.distance(b);
        let mut checks = 1;
        if self.motion(a, b, t0).valid() || !(len > resolution) {
            return (None, checks);
        }
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        while (hi - lo) * len > resolution {
            let mid = 0.5 * (lo + hi);
            checks += 1;
            if self.motion(a, a.lerp(b, mid), t0).valid() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        ((lo * len >= resolution).then(|| a.lerp(b, lo)), checks)
    }

    /// Smallest clearance of the motion a -> b leaving at `t0` at cruise speed; see
    /// [`Validator::motion_clearance_at`].
    pub fn motion_clearance(&self, a: Vec3, b: Vec3, t0: f64) -> f64 {
        self.motion_clearance_at(a, b, t0, self.vehicle.speed)
    }

    /// Smallest clearance of the motion a -> b leaving at `t0` at through-water speed `v`:
    /// vertical to the seabed (negative below it) and Euclidean to obstacle surfaces, moving
    /// ones at the vehicle's clock. +inf in an empty world.
    pub fn motion_clearance_at(&self, a: Vec3, b: Vec3, t0: f64, v: f64) -> f64 {
        let world = self.world;
        let mut best = world.segment_terrain_clearance(a, b);
        for o in world.obstacles.iter().filter(|o| o.is_fixed()) {
            best = best.min(o.segment_clearance(a, b, t0, t0));
        }
        if self.obstacles.moving().is_empty() {
            return best;
        }
        self.for_each_piece_at(a, b, t0, v, |pc| {
            for &k in self.obstacles.moving() {
                best = best.min(world.obstacles[k as usize].segment_clearance(pc.p0, pc.p1, pc.t0, pc.t1));
            }
        });
        best
    }
}

#[cfg(test)]
mod tests;
