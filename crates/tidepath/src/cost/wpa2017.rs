//! The wpa2017 cost model (eqs. 17-21): length, depth penalty and buoyancy/rudder energy, plus
//! a large penalty per violation. See `docs/papers/wpa2017.md`, section "cost" and A3-A5.
//!
//! F = sum_i [ w1 l_i + w2 f_i + w3 (E_b,i + E_r,i) ] + w_violation N_violations
//!
//! Readings (tidepath worlds are in metres, the paper's in km):
//! - l_i is the 3-D length of segment i in km, so w1 = 1 per km keeps the paper's scale.
//! - f_i = sqrt(|z_i - h_i^ideal|) / 2 with the heights in km, z_i the height of the end point
//!   of segment i. h^ideal is the start and goal heights interpolated linearly along the
//!   start-goal horizontal axis (the paper says along x; we take the projection of the point
//!   on that axis, clamped to the start and goal; a mission whose start and goal share a
//!   vertical uses the start height), raised to at least seabed + the vehicle's safety
//!   distance.
//! - E_b = (2m/(eta_b rho))(rho g D_i + P0) J, charged only when segment i changes depth,
//!   D_i = |dz| in metres.
//! - E_r = a_r^2 gamma_i^4 / (2 eta_r) J, gamma_i the horizontal heading change at the start of
//!   segment i (rad), measured from the last segment with horizontal extent (a vertical
//!   segment keeps the heading). With a_r = 1 it is at most pi^4 J, about 1e-4 MJ: the
//!   printed constants make it negligible next to E_b; we keep them.
//! - Energies in MJ, w3 per MJ.
//! - N_violations counts what `general` counts: collisions (seabed within the safety distance
//!   included), waypoints out of the domain or depth band, endpoints, current stops and gaps,
//!   and the vehicle's turn, turning-radius and pitch violations (the paper has no such limits;
//!   a vehicle's limits are hard constraints in tidepath).
//!
//! Length, depth and buoyancy are additive per segment (`motion_cost_at` accumulates them);
//! the rudder energy depends on the joint between two segments and the violation count on the
//! whole path, so both are path-level.

use super::CostModel;
use crate::error::{Error, Result};
use crate::geom::{heading_change, Vec3};
use crate::params::{Bound, Checked, Range};
use crate::path::PathModel;
use crate::scratch::Scratch;

crate::params! {
    /// The wpa2017 model's weights (`[cost] weights`).
    pub struct Wpa2017Weights {
        /// w1, per km of 3-D length.
        length: f64 = 1.0, NON_NEGATIVE, "wpa2017 (chosen, A5)";
        /// w2, on the depth penalty sqrt(|z - h_ideal| in km) / 2 of each waypoint.
        depth: f64 = 0.1, NON_NEGATIVE, "wpa2017 (chosen, A5)";
        /// w3, per MJ of buoyancy and rudder energy.
        energy: f64 = 0.1, NON_NEGATIVE, "wpa2017 (chosen, A5)";
        /// Per collision, bounds, endpoint, current, turn or pitch violation.
        violation: f64 = 1e6, NON_NEGATIVE, "wpa2017";
    }
    check = something_to_minimise;
}

const NON_NEGATIVE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded };

fn something_to_minimise(w: &Wpa2017Weights, prefix: &str) -> Result<()> {
    if w.length + w.depth + w.energy == 0.0 {
        return Err(Error::input(prefix, "length, depth and energy cannot all be 0"));
    }
    Ok(())
}

/// Vehicle mass (kg), buoyancy efficiency, sea-water density (kg/m^3), gravity (m/s^2),
/// surface pressure (Pa), rudder efficiency and rudder coefficient: chosen (A4).
pub const MASS: f64 = 50.0;
pub const ETA_B: f64 = 0.5;
pub const RHO: f64 = 1025.0;
pub const G: f64 = 9.81;
pub const P0: f64 = 101_325.0;
pub const ETA_R: f64 = 0.5;
pub const A_R: f64 = 1.0;

const KM: f64 = 1000.0;
const MJ: f64 = 1e6;

/// Buoyancy energy of a depth change of `d` metres (eq. 20), MJ; 0 for a level segment.
pub fn buoyancy_energy(d: f64) -> f64 {
    if d == 0.0 {
        return 0.0;
    }
    2.0 * MASS / (ETA_B * RHO) * (RHO * G * d.abs() + P0) / MJ
}

/// Rudder energy of a heading change of `gamma` rad (eq. 21), MJ.
pub fn rudder_energy(gamma: f64) -> f64 {
    A_R * A_R * gamma.powi(4) / (2.0 * ETA_R) / MJ
}

#[derive(Clone, Debug)]
pub struct Wpa2017Cost {
    pub weights: Wpa2017Weights,
}

const TERMS: [&str; 5] = ["length", "depth", "buoyancy", "rudder", "violation"];

impl Wpa2017Cost {
    pub fn new(weights: Checked<Wpa2017Weights>) -> Self {
        Self { weights: weights.into_inner() }
    }

    /// h^ideal at `p` (m): start and goal heights interpolated along the start-goal horizontal
    /// axis, raised to at least seabed + safety distance.
    pub fn ideal_height(model: &PathModel<'_>, p: Vec3) -> f64 {
        let (s, g) = (model.start, model.goal);
        let axis = (g - s).truncate();
        let len2 = axis.length_squared();
        let u = if len2 > 0.0 { ((p - s).truncate().dot(axis) / len2).clamp(0.0, 1.0) } else { 0.0 };
        let h = s.z + (g.z - s.z) * u;
        h.max(model.world.terrain.elevation(p.x, p.y) + model.vehicle.safety_distance)
    }

    /// sqrt(|z - h^ideal| in km) / 2 at the point `p` (eq. 18, A3).
    pub fn depth_penalty(model: &PathModel<'_>, p: Vec3) -> f64 {
        ((p.z - Self::ideal_height(model, p)).abs() / KM).sqrt() / 2.0
    }

    /// The unweighted additive terms of segment a -> b: (length km, depth penalty of b, E_b MJ).
    fn segment(model: &PathModel<'_>, a: Vec3, b: Vec3) -> (f64, f64, f64) {
        (a.distance(b) / KM, Self::depth_penalty(model, b), buoyancy_energy(b.z - a.z))
    }
}

impl CostModel for Wpa2017Cost {
    fn id(&self) -> &'static str {
        "wpa2017"
    }

    fn term_names(&self) -> &'static [&'static str] {
        &TERMS
    }

    fn evaluate(&self, model: &PathModel<'_>, points: &[Vec3], scratch: &mut Scratch, terms: &mut [f64]) -> f64 {
        let a = model.assess(points, &mut scratch.times);
        let w = &self.weights;
        let (mut depth, mut buoy, mut rudder) = (0.0, 0.0, 0.0);
        let mut prev_dir: Option<Vec3> = None;
        for s in points.windows(2) {
            let (_, f, eb) = Self::segment(model, s[0], s[1]);
            depth += f;
            buoy += eb;
            let dir = s[1] - s[0];
            if dir.truncate().length() > 1e-12 {
                if let Some(gamma) = prev_dir.and_then(|p| heading_change(p, dir)) {
                    rudder += rudder_energy(gamma);
                }
                prev_dir = Some(dir);
            }
        }
        terms[0] = w.length * a.length / KM;
        terms[1] = w.depth * depth;
        terms[2] = w.energy * buoy;
        terms[3] = w.energy * rudder;
        terms[4] = w.violation * a.violation_count() as f64;
        terms[..5].iter().sum()
    }

    fn additive_terms(&self) -> &'static [&'static str] {
        &TERMS[..3]
    }

    /// Depth and buoyancy terms are non-negative, so the length alone bounds the cost.
    fn motion_lower_bound(&self, _model: &PathModel<'_>, distance: f64, _max_ground_speed: f64) -> f64 {
        self.weights.length * distance / KM
    }

    /// Depth and buoyancy terms do not scale with length.
    fn cost_per_metre(&self, _model: &PathModel<'_>) -> Option<f64> {
        None
    }

    /// w1 l + w2 f(b) + w3 E_b of a valid motion; rudder energy and violations are path-level.
    fn motion_cost_at(&self, model: &PathModel<'_>, a: Vec3, b: Vec3, t0: f64, v: f64) -> Option<(f64, f64)> {
        let m = model.validator.motion_at(a, b, t0, v);
        if !m.valid() {
            return None;
        }
        let (l, f, eb) = Self::segment(model, a, b);
        let w = &self.weights;
        Some((w.length * l + w.depth * f + w.energy * eb, m.arrival))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Aabb;
    use crate::mission::Mission;
    use crate::path::ModelSettings;
    use crate::vehicle::Vehicle;
    use crate::world::terrain::{GaussianPeaks, Terrain};
    use crate::world::World;
    use std::f64::consts::{FRAC_PI_2, PI};

    fn open_world() -> World {
        World::open(Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(3000.0, 3000.0, 0.0)))
    }

    fn vehicle() -> Vehicle {
        Vehicle { max_turn: PI, max_pitch: FRAC_PI_2, depth_max: 1000.0, ..Vehicle::default() }
    }

    fn flat(z: f64) -> Terrain {
        Terrain::Peaks(GaussianPeaks { base: z, peaks: vec![], ceiling: None })
    }

    fn cost() -> Wpa2017Cost {
        Wpa2017Cost::new(Wpa2017Weights::default().checked("cost.weights").unwrap())
    }

    fn term(terms: &[(&str, f64)], name: &str) -> f64 {
        terms.iter().find(|t| t.0 == name).unwrap().1
    }

    fn close(a: f64, b: f64) {
        assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{a} != {b}");
    }

    #[test]
    fn energies_by_hand() {
        // 2 * 50 / (0.5 * 1025) * (1025 * 9.81 * 100 + 101325) J = 215 970.73... J.
        close(buoyancy_energy(100.0), 100.0 / 512.5 * 1_106_850.0 / 1e6);
        close(buoyancy_energy(-100.0), buoyancy_energy(100.0));
        assert_eq!(buoyancy_energy(0.0), 0.0);
        // (pi/2)^4 / (2 * 0.5) J.
        close(rudder_energy(FRAC_PI_2), 6.088_068_189_625_15e-6);
    }

    /// S = (0, 0, -100), W = (1000, 0, -200), G = (1000, 1000, -100): segment 1 dives 100 m,
    /// segment 2 climbs 100 m after a 90 degree turn.
    #[test]
    fn every_term_by_hand_on_a_three_point_path() {
        let w = open_world();
        let (s, wp, g) =
            (Vec3::new(0.0, 0.0, -100.0), Vec3::new(1000.0, 0.0, -200.0), Vec3::new(1000.0, 1000.0, -100.0));
        let mission = Mission::new("m", vehicle(), s, g, 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let (total, terms) = cost().breakdown(&model, &[s, wp, g]);
        let l = 2.0 * (1000.0f64 * 1000.0 + 100.0 * 100.0).sqrt() / 1000.0;
        close(term(&terms, "length"), l);
        // The axis is the diagonal: W projects half way, h_ideal = -100; |z - h| = 100 m = 0.1
        // km. At G, h_ideal = -100 = z.
        close(Wpa2017Cost::ideal_height(&model, wp), -100.0);
        let f = 0.1f64.sqrt() / 2.0;
        close(term(&terms, "depth"), 0.1 * f);
        let eb = 2.0 * 100.0 / 512.5 * 1_106_850.0 / 1e6;
        close(term(&terms, "buoyancy"), 0.1 * eb);
        let er = FRAC_PI_2.powi(4) / 1.0 / 1e6;
        close(term(&terms, "rudder"), 0.1 * er);
        assert_eq!(term(&terms, "violation"), 0.0);
        close(total, l + 0.1 * f + 0.1 * eb + 0.1 * er);
    }

    /// h_ideal is raised to the seabed plus the safety distance.
    #[test]
    fn ideal_height_is_raised_above_the_seabed() {
        let mut w = open_world();
        w.terrain = flat(-150.0);
        let v = Vehicle { safety_distance: 10.0, ..vehicle() };
        let mission = Mission::new("m", v, Vec3::new(0.0, 0.0, -200.0), Vec3::new(2000.0, 0.0, -200.0), 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        close(Wpa2017Cost::ideal_height(&model, Vec3::new(500.0, 0.0, -100.0)), -140.0);
        close(Wpa2017Cost::depth_penalty(&model, Vec3::new(500.0, 0.0, -100.0)), 0.04f64.sqrt() / 2.0);
    }

    #[test]
    fn a_level_straight_path_costs_its_length_only() {
        let w = open_world();
        let p = [Vec3::new(0.0, 0.0, -50.0), Vec3::new(1000.0, 0.0, -50.0), Vec3::new(2500.0, 0.0, -50.0)];
        let mission = Mission::new("m", vehicle(), p[0], p[2], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let (total, terms) = cost().breakdown(&model, &p);
        for name in ["depth", "buoyancy", "rudder", "violation"] {
            assert_eq!(term(&terms, name), 0.0, "{name}");
        }
        close(total, 2.5);
    }

    /// Along a path without heading changes (a straight line in plan, with depth changes) the
    /// motion costs add up to the additive terms of `evaluate`.
    #[test]
    fn motion_costs_add_up_to_the_additive_terms() {
        let w = open_world();
        let p = [
            Vec3::new(0.0, 0.0, -50.0),
            Vec3::new(400.0, 300.0, -250.0),
            Vec3::new(480.0, 360.0, -300.0),
            Vec3::new(1200.0, 900.0, -100.0),
            Vec3::new(2000.0, 1500.0, -120.0),
        ];
        let mission = Mission::new("m", vehicle(), p[0], p[4], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let c = cost();
        let (_, terms) = c.breakdown(&model, &p);
        assert_eq!(term(&terms, "rudder"), 0.0);
        assert_eq!(term(&terms, "violation"), 0.0);
        assert!(term(&terms, "depth") > 0.0 && term(&terms, "buoyancy") > 0.0);
        let additive: f64 = c.additive_terms().iter().map(|n| term(&terms, n)).sum();
        let mut t = model.departure_time;
        let mut sum = 0.0;
        for s in p.windows(2) {
            let (cost, arrival) = c.motion_cost(&model, s[0], s[1], t).unwrap();
            assert!(cost >= c.motion_lower_bound(&model, s[0].distance(s[1]), model.vehicle.speed));
            sum += cost;
            t = arrival;
        }
        close(sum, additive);
    }

    #[test]
    fn a_path_through_the_seabed_costs_more_than_the_penalty() {
        let mut w = open_world();
        w.terrain = flat(-150.0);
        let p = [Vec3::new(0.0, 0.0, -100.0), Vec3::new(1000.0, 0.0, -400.0), Vec3::new(2000.0, 0.0, -100.0)];
        let mission = Mission::new("m", vehicle(), p[0], p[2], 0.0);
        let settings = ModelSettings::default();
        let model = PathModel::new(&w, &mission, &settings);
        let c = cost();
        let (total, terms) = c.breakdown(&model, &p);
        assert!(term(&terms, "violation") >= c.weights.violation);
        assert!(total > c.weights.violation);
        assert!(c.motion_cost(&model, p[0], p[1], 0.0).is_none());
    }

    #[test]
    fn the_registry_builds_it_and_refuses_unknown_weights() {
        let reg = crate::cost::registry();
        let build = reg.get("wpa2017").unwrap().build;
        let m = build(&toml::Table::new()).unwrap();
        assert_eq!(m.id(), "wpa2017");
        let t: toml::Table = toml::from_str("length = 2.0\nviolation = 1e3").unwrap();
        build(&t).unwrap();
        let t: toml::Table = toml::from_str("lenght = 2.0").unwrap();
        let e = build(&t).err().unwrap().to_string();
        assert!(e.starts_with("cost.weights.lenght"), "{e}");
        let t: toml::Table = toml::from_str("length = 0.0\ndepth = 0.0\nenergy = 0.0").unwrap();
        assert!(build(&t).is_err());
    }
}
