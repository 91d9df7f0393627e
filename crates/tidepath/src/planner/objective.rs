//! The bridge from a path problem to the optimizer's view: a bounded vector and a cost. With
//! several missions the vector is the concatenation of each mission's variables and the cost is
//! the sum of the missions' costs (plus the fleet's penalties).
//!
//! A mission's variables are its encoding's, then, when its vehicle has a speed range, one
//! through-water speed per segment of the decoded path, in m/s within the range (ijs2023
//! leaves open how speeds enter the decision vector; this is our reading: plain bounded
//! variables, so every optimizer searches them like coordinates and the bounds repair clamps
//! them). A vehicle without a range adds none, so such problems are unchanged.

use super::section_cells::SectionCells;
use super::Problem;
use crate::encoding::Encoding;
use crate::optim::{Objective, Scratch};
use crate::path::PathModel;

pub struct PathObjective<'a> {
    problem: &'a Problem<'a>,
    models: Vec<PathModel<'a>>,
    encodings: Vec<Box<dyn Encoding>>,
    /// Mission i's variables are x[offsets[i]..offsets[i + 1]]: its encoding's, then
    /// `speed_genes[i]` segment speeds.
    offsets: Vec<usize>,
    speed_genes: Vec<usize>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    /// Every interior waypoint of every mission: (mission, waypoint, its variables in x).
    groups: Vec<(usize, usize, std::ops::Range<usize>)>,
    /// Each group's free cells, built on first use ([`super::section_cells`]).
    cells: Vec<std::sync::OnceLock<SectionCells>>,
    /// The repair applied to every mission's path in [`Objective::repair`] (`[encoding]
    /// repair`), after the encoding's own.
    path_repair: Option<Box<dyn crate::repair::Repair>>,
}

impl<'a> PathObjective<'a> {
    /// `encodings[i]` encodes mission i.
    pub fn new(problem: &'a Problem<'a>, encodings: Vec<Box<dyn Encoding>>) -> Self {
        let models = (0..problem.missions.len()).map(|i| problem.path_model(i)).collect();
        let mut offsets = vec![0];
        let mut speed_genes = Vec::with_capacity(encodings.len());
        let (mut lower, mut upper) = (Vec::new(), Vec::new());
        for (e, m) in encodings.iter().zip(problem.missions) {
            lower.extend_from_slice(e.lower());
            upper.extend_from_slice(e.upper());
            let genes = match m.vehicle.speed_range {
                Some((lo, hi)) => {
                    let n = e.decode(e.lower()).len().saturating_sub(1);
                    lower.extend(std::iter::repeat_n(lo, n));
                    upper.extend(std::iter::repeat_n(hi, n));
                    n
                }
                None => 0,
            };
            speed_genes.push(genes);
            offsets.push(lower.len());
        }
        let mut groups = Vec::new();
        for (i, e) in encodings.iter().enumerate() {
            let per = e.waypoint_dim();
            for k in 0..e.dim().checked_div(per).unwrap_or(0) {
                let start = offsets[i] + k * per;
                groups.push((i, k, start..start + per));
            }
        }
        let cells = groups.iter().map(|_| std::sync::OnceLock::new()).collect();
        Self { problem, models, encodings, offsets, speed_genes, lower, upper, groups, cells, path_repair: None }
    }

    /// The objective applying `repair` to every mission's decoded path in
    /// [`Objective::repair`] (`None`: only the encoding's repair and the speed clamp).
    pub fn with_repair(mut self, repair: Option<Box<dyn crate::repair::Repair>>) -> Self {
        self.path_repair = repair;
        self
    }

    /// Mission i's encoding variables and its segment speeds (empty without a range).
    fn split<'x>(&self, x: &'x [f64], i: usize) -> (&'x [f64], &'x [f64]) {
        x[self.offsets[i]..self.offsets[i + 1]].split_at(self.encodings[i].dim())
    }

    /// Mission i's model, flying its segments at `speeds` when it has speed variables.
    fn model<'s>(&'s self, i: usize, speeds: &'s [f64]) -> std::borrow::Cow<'s, PathModel<'s>> {
        if speeds.is_empty() {
            std::borrow::Cow::Borrowed(&self.models[i])
        } else {
            std::borrow::Cow::Owned(self.models[i].with_speeds(Some(speeds)))
        }
    }

    /// One path per mission for the vector `x`.
    pub fn decode(&self, x: &[f64]) -> Vec<Vec<crate::geom::Vec3>> {
        self.encodings.iter().enumerate().map(|(i, e)| e.decode(self.split(x, i).0)).collect()
    }

    /// Each mission's segment speeds in `x`; `None` for a vehicle without a speed range.
    pub fn decode_speeds(&self, x: &[f64]) -> Vec<Option<Vec<f64>>> {
        (0..self.encodings.len())
            .map(|i| {
                let s = self.split(x, i).1;
                (self.speed_genes[i] > 0).then(|| s.to_vec())
            })
            .collect()
    }

    /// The vector whose paths follow `paths` (one per mission), for a warm start; segment
    /// speeds start at the cruise speed.
    pub fn encode(&self, paths: &[Vec<crate::geom::Vec3>]) -> Option<Vec<f64>> {
        if paths.len() != self.encodings.len() || paths.iter().any(|p| p.len() < 2) {
            return None;
        }
        let mut out = Vec::with_capacity(self.lower.len());
        for (i, (e, p)) in self.encodings.iter().zip(paths).enumerate() {
            out.extend(e.encode(p));
            let cruise = self.problem.missions[i].vehicle.speed;
            out.extend(std::iter::repeat_n(cruise, self.speed_genes[i]));
        }
        Some(out)
    }
}

impl PathObjective<'_> {
    /// The missions' costs plus the fleet's separation penalty ([`crate::fleet::FleetCheck::penalty`]),
    /// every path decoded into its own reused buffer so all are at hand for the pairwise check.
    fn evaluate_fleet(&self, x: &[f64], scratch: &mut Scratch) -> f64 {
        let mut paths = std::mem::take(&mut scratch.paths);
        let mut legs = std::mem::take(&mut scratch.legs);
        paths.resize_with(self.encodings.len(), Vec::new);
        let mut total = 0.0;
        legs.resize_with(self.encodings.len(), Vec::new);
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = self.split(x, i);
            e.decode_into(genes, &mut paths[i]);
            let model = self.model(i, speeds);
            total += self.problem.cost.cost(&model, &paths[i], scratch);
            crate::fleet::timed_legs(&model, &paths[i], &mut legs[i]);
        }
        total += crate::fleet::check_legs(&legs, self.problem.fleet).penalty();
        scratch.paths = paths;
        scratch.legs = legs;
        total
    }
}

impl Objective for PathObjective<'_> {
    fn dim(&self) -> usize {
        self.lower.len()
    }

    fn lower(&self) -> &[f64] {
        &self.lower
    }

    fn upper(&self) -> &[f64] {
        &self.upper
    }

    fn evaluate(&self, x: &[f64], scratch: &mut Scratch) -> f64 {
        if self.problem.fleet.active(self.encodings.len()) {
            return self.evaluate_fleet(x, scratch);
        }
        // Move the point buffer out so the cost model can borrow the rest of the scratch;
        // moving a Vec does not allocate.
        let mut points = std::mem::take(&mut scratch.points);
        let mut total = 0.0;
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = self.split(x, i);
            e.decode_into(genes, &mut points);
            total += self.problem.cost.cost(&self.model(i, speeds), &points, scratch);
        }
        scratch.points = points;
        total
    }

    /// Every mission's path judged by the path assessment the cost models use (collisions,
    /// domain and depth band, vehicle limits, current); a fleet's separation and arrival rules
    /// are penalties, not constraints, and are not part of it.
    fn feasible(&self, x: &[f64], scratch: &mut Scratch) -> Option<bool> {
        let mut points = std::mem::take(&mut scratch.points);
        let mut times = std::mem::take(&mut scratch.times);
        let mut all = true;
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = self.split(x, i);
            e.decode_into(genes, &mut points);
            if !self.model(i, speeds).assess(&points, &mut times).feasible() {
                all = false;
                break;
            }
        }
        scratch.points = points;
        scratch.times = times;
        Some(all)
    }

    /// Each mission's path smoothed by eq. 15 and written back through its encoding; segment
    /// speeds stay.
    fn smooth_path(&self, x: &mut [f64], scratch: &mut Scratch) -> bool {
        let mut points = std::mem::take(&mut scratch.points);
        let mut smooth = std::mem::take(&mut scratch.paths);
        smooth.resize_with(1, Vec::new);
        for (i, e) in self.encodings.iter().enumerate() {
            let genes = &mut x[self.offsets[i]..self.offsets[i] + e.dim()];
            e.decode_into(genes, &mut points);
            crate::path::midpoint_smooth(&points, &mut smooth[0]);
            let interior = smooth[0].len().saturating_sub(2);
            for k in 0..interior.min(e.dim().checked_div(e.waypoint_dim()).unwrap_or(0)) {
                e.set_waypoint(genes, k, smooth[0][k + 1]);
            }
            e.repair(genes);
        }
        scratch.points = points;
        scratch.paths = smooth;
        true
    }

    fn waypoint_groups(&self) -> Vec<std::ops::Range<usize>> {
        self.groups.iter().map(|g| g.2.clone()).collect()
    }

    /// Free cells of the waypoint's section, built from its variables' bounds on first use.
    fn region_free(&self, group: usize, lo: &[f64], hi: &[f64]) -> Option<bool> {
        let (i, k, vars) = self.groups.get(group)?;
        if lo.len() != vars.len() || hi.len() != vars.len() || vars.len() > super::section_cells::MAX_VARS {
            return None;
        }
        let cells = self.cells[group].get_or_init(|| {
            SectionCells::new(
                &self.models[*i],
                &*self.encodings[*i],
                *k,
                &self.lower[vars.clone()],
                &self.upper[vars.clone()],
            )
        });
        Some(cells.overlaps_free(lo, hi))
    }

    fn repair(&self, x: &mut [f64]) {
        for (i, e) in self.encodings.iter().enumerate() {
            let (genes, speeds) = x[self.offsets[i]..self.offsets[i + 1]].split_at_mut(e.dim());
            e.repair(genes);
            let lo = &self.lower[self.offsets[i] + e.dim()..self.offsets[i + 1]];
            let hi = &self.upper[self.offsets[i] + e.dim()..self.offsets[i + 1]];
            for ((v, l), h) in speeds.iter_mut().zip(lo).zip(hi) {
                *v = v.clamp(*l, *h);
            }
        }
        let Some(repair) = &self.path_repair else { return };
        // The path repair: each mission's path decoded, repaired (at its segment speeds) and
        // its interior waypoints written back through the encoding, which then repairs again.
        let mut points = Vec::new();
        for (i, e) in self.encodings.iter().enumerate() {
            {
                let (genes, speeds) = self.split(x, i);
                e.decode_into(genes, &mut points);
                repair.apply(&self.model(i, speeds), &mut points);
            }
            let genes = &mut x[self.offsets[i]..self.offsets[i] + e.dim()];
            let interior = points.len().saturating_sub(2);
            for k in 0..interior.min(e.dim().checked_div(e.waypoint_dim()).unwrap_or(0)) {
                e.set_waypoint(genes, k, points[k + 1]);
            }
            e.repair(genes);
        }
    }

    fn parallel_hint(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cost::{GeneralCost, GeneralWeights};
    use crate::encoding::{SliceAxis, Sliced};
    use crate::geom::{Aabb, Vec3};
    use crate::mission::Mission;
    use crate::path::ModelSettings;
    use crate::vehicle::Vehicle;
    use crate::world::obstacle::{Obstacle, Shape};
    use crate::world::terrain::{GaussianPeaks, Terrain};
    use crate::world::World;

    /// A 4 x 2 km box 1 km deep over a flat seabed at -900 m, one sphere of radius 300 m at
    /// (2000, 1000, -500); the mission runs along x with planes x = 1000, 2000, 3000.
    fn world() -> World {
        let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(4000.0, 2000.0, 0.0)));
        w.terrain = Terrain::Peaks(GaussianPeaks { base: -900.0, peaks: vec![], ceiling: None });
        w.obstacles.push(Obstacle::fixed(Shape::Sphere { center: Vec3::new(2000.0, 1000.0, -500.0), radius: 300.0 }));
        w
    }

    /// The start and goal of the test mission.
    const START: Vec3 = Vec3::new(0.0, 1000.0, -500.0);
    const GOAL: Vec3 = Vec3::new(4000.0, 600.0, -500.0);

    /// The test problem in [`world`] for vehicle `v`, from [`START`] to [`GOAL`].
    fn with_problem(v: Vehicle, f: impl FnOnce(&Problem<'_>)) {
        let w = world();
        let missions = [Mission::new("m", v, START, GOAL, 0.0)];
        let settings = ModelSettings::default();
        let cost = GeneralCost::new(GeneralWeights::default().checked("w").unwrap());
        f(&Problem {
            world: &w,
            settings: &settings,
            cost: &cost,
            missions: &missions,
            fleet: &crate::fleet::NO_FLEET,
        });
    }

    fn with_objective(three_d: bool, f: impl FnOnce(&PathObjective<'_>, &Sliced)) {
        let v = Vehicle { depth_max: 1000.0, safety_distance: 0.0, ..Vehicle::default() };
        with_problem(v, |problem| {
            let band = three_d.then_some((-1000.0, 0.0));
            let enc = Sliced::along(START, GOAL, 3, &problem.world.bounds, band, SliceAxis::X).unwrap();
            let objective = PathObjective::new(problem, vec![Box::new(enc.clone())]);
            f(&objective, &enc);
        });
    }

    /// Lateral offsets (from y = 1000) 0, 400, -200 on planes x = 1000, 2000, 3000; the goal's
    /// offset is -400. Legs: 1000, sqrt(1000^2 + 400^2), sqrt(1000^2 + 600^2),
    /// sqrt(1000^2 + 200^2). Waypoint 1: left < right -> (0 + 400) / 2 = 200. Waypoint 2:
    /// left < right -> (400 - 200) / 2 = 100. Waypoint 3: left > right -> (400 - 200) / 2 = 100.
    #[test]
    fn smoothing_moves_only_the_free_coordinates_by_eq_15() {
        with_objective(false, |o, _| {
            let mut x = vec![0.0, 400.0, -200.0];
            assert!(o.smooth_path(&mut x, &mut Scratch::default()));
            assert_eq!(x, vec![200.0, 100.0, 100.0]);
        });
        with_objective(true, |o, enc| {
            let mut x = vec![0.0, -500.0, 400.0, -100.0, -200.0, -500.0];
            assert!(o.smooth_path(&mut x, &mut Scratch::default()));
            assert_eq!(x, vec![200.0, -300.0, 100.0, -300.0, 100.0, -300.0]);
            // Every waypoint stays on its plane.
            let xs: Vec<f64> = enc.decode(&x).iter().map(|p| p.x).collect();
            assert_eq!(xs, vec![0.0, 1000.0, 2000.0, 3000.0, 4000.0]);
        });
    }

    /// With the free encoding and `exclude-contract`, a repaired vector has no route point in
    /// the sphere (nor within the safety distance of it or the seabed), whatever it was.
    #[test]
    fn exclude_contract_repair_leaves_no_point_inside() {
        use crate::encoding::FreeWaypoints;
        use rand::Rng as _;
        let v =
            Vehicle { depth_max: 1000.0, safety_distance: 5.0, max_turn: std::f64::consts::PI, ..Vehicle::default() };
        with_problem(v, |problem| {
            let (w, s, g) = (problem.world, START, GOAL);
            let enc = FreeWaypoints::new(s, g, 12, &w.bounds, problem.z_range(0)).unwrap();
            let repair = crate::repair::build_repair("exclude-contract", None).unwrap();
            let objective = PathObjective::new(problem, vec![Box::new(enc)]).with_repair(Some(repair));
            let model = problem.path_model(0);
            let mut rng = crate::rng::run_rng(3, 0);
            let mut inside_before = 0;
            for _ in 0..100 {
                let mut x: Vec<f64> = (0..objective.dim())
                    .map(|j| objective.lower()[j] + rng.random::<f64>() * (objective.upper()[j] - objective.lower()[j]))
                    .collect();
                let before = objective.decode(&x).remove(0);
                inside_before += before.iter().filter(|p| model.validator.state(**p, 0.0).is_err()).count();
                objective.repair(&mut x);
                let after = objective.decode(&x).remove(0);
                assert_eq!((after[0], *after.last().unwrap()), (s, g));
                for p in &after[1..after.len() - 1] {
                    assert!(model.validator.state(*p, 0.0).is_ok(), "{p} still invalid: {after:?}");
                    assert!(!w.obstacles[0].contains(*p, 0.0, 0.0));
                }
            }
            assert!(inside_before > 0, "no random point started inside: the test tests nothing");
        });
    }

    /// The sphere fills the middle of plane x = 2000: a rectangle inside it has no free cell, one
    /// reaching beyond it has; planes 1000 and 3000 are free except under the seabed.
    #[test]
    fn safe_cells_see_the_sphere_and_the_seabed() {
        with_objective(true, |o, _| {
            assert_eq!(o.waypoint_groups(), vec![0..2, 2..4, 4..6]);
            // Offset 0 is y = 1000; the sphere's section at x = 2000 is a disc of 300 m.
            assert_eq!(o.region_free(1, &[-100.0, -600.0], &[100.0, -400.0]), Some(false));
            assert_eq!(o.region_free(1, &[-100.0, -600.0], &[600.0, -400.0]), Some(true));
            assert_eq!(o.region_free(0, &[-100.0, -600.0], &[100.0, -400.0]), Some(true));
            // Below the seabed (cells 50 m tall: -1000 .. -950 and -950 .. -900).
            assert_eq!(o.region_free(0, &[-900.0, -1000.0], &[900.0, -920.0]), Some(false));
            assert_eq!(o.region_free(3, &[0.0, 0.0], &[1.0, 1.0]), None);
            assert_eq!(o.region_free(0, &[0.0], &[1.0]), None);
        });
    }
}
