//! `hybrid`: a reference path from exact search, refined by a continuous optimizer over free
//! waypoints under the scenario's own cost model. Routes that must turn back along the
//! start-goal axis (around a headland, into a bay) are found by the search; the optimizer then
//! straightens the grid's corners, rides or avoids the currents, and honours every term of the
//! cost model.
//!
//! 1. Reference: `visibility` where it applies (2-D discs and boxes), else `theta-star` on the
//!    world's raster in 2-D and `astar` in 3-D (time-optimal objective in currents). A straight line if neither finds
//!    one (the optimizer then starts from it).
//! 2. Waypoints: the reference, shortcut (points whose bypass is feasible and no costlier are
//!    dropped), keeps k turns; n = clamp(2 k + 4, 6, 24) waypoints (at least k, at most 40),
//!    placed so every turn is a waypoint and the longest legs are split.
//! 3. Refinement: DE/rand/1/bin over the free-waypoint encoding, its population seeded with
//!    the reference and copies jittered by up to one raster cell (a local search around the
//!    reference), for the run's iterations and evaluations. Its result is never worse than the
//!    reference under the cost model, since the reference is in the first population.
//! 4. The shortcut smoother (never worse, never less feasible).

use rand::Rng as _;

use super::grid_search::{GridParams, GridSearch};
use super::{visibility, Claim, PathObjective, Planner, PlannerOutput, Problem, RunOptions, SearchStats};
use crate::encoding::{Encoding, FreeWaypoints};
use crate::error::Result;
use crate::geom::Vec3;
use crate::optim::de::{De, DeParams};
use crate::optim::MAX_POPULATION;
use crate::optim::{self, Objective as _, Progress};
use crate::params::{Checked, Range};
use crate::rng::Rng;
use crate::smoothing::Smoother;
use crate::termination::Termination;
use crate::termination::MAX_COUNT;

crate::params! {
    /// The composite planner's parameters.
    pub struct HybridParams {
        /// DE population of the refinement.
        population: usize = 30, Range::integer(4, MAX_POPULATION as u64), "tidepath";
        /// Raster cells along the domain's longer side for the reference search; absent: the
        /// grid planners' default (200 in 2-D, 80 in 3-D).
        cells: Option<usize> = None, Range::integer(4, 4096), "tidepath";
        /// Refinement iterations when the run limits neither iterations nor evaluations.
        iterations: u64 = 300, Range::integer(1, MAX_COUNT), "tidepath";
        /// The smoother the reference and the result go through (a smoother id).
        smoother: String = "shortcut".to_string(), Range::Id("smoother"), "tidepath";
    }
}

/// Most free waypoints per mission.
const MAX_WAYPOINTS: usize = 40;

pub struct Hybrid {
    params: HybridParams,
    smoother: Box<dyn Smoother>,
}

impl Hybrid {
    pub fn new(params: Checked<HybridParams>) -> Result<Self> {
        let params = params.into_inner();
        let smoother = crate::smoothing::build_smoother(&params.smoother, None)
            .map_err(|e| e.for_field("planner.params.hybrid.smoother"))?;
        Ok(Self { params, smoother })
    }

    /// The reference path of mission `i` within `termination` (a share of the run's time on
    /// the run's clock), the expansions it took, and why there is none when the search found
    /// none (the straight line then stands in for it).
    fn reference(
        &self,
        problem: &Problem<'_>,
        i: usize,
        termination: &Termination,
    ) -> (Vec<Vec3>, u64, Option<String>) {
        let m = &problem.missions[i];
        if let Ok((scene, _)) = visibility::scene(problem, i, true) {
            let p = tidepath_search::visibility::shortest_path_within(
                &scene,
                [m.start.x, m.start.y],
                [m.goal.x, m.goal.y],
                0.1,
                &termination.search_limits(None),
            );
            if let Ok((Some(p), _)) = p {
                let mut pts: Vec<Vec3> = p.polyline.iter().map(|q| Vec3::new(q[0], q[1], m.start.z)).collect();
                let n = pts.len();
                pts[0] = m.start;
                pts[n - 1] = m.goal;
                return (pts, 0, None);
            }
        }
        // Any-angle Theta* in 2-D; in 3-D plain A* (Theta*'s line-of-sight relaxations make
        // every voxel try long motions, ten times slower, and the refinement straightens the
        // grid's corners anyway).
        let any_angle = problem.world.dims == crate::world::Dims::Two;
        let id = if any_angle { "theta-star" } else { "astar" };
        let grid = GridParams { cells: self.params.cells, ..GridParams::default() };
        let grid = grid.checked("planner.params.hybrid").expect("hybrid's cells are the grid planners' range");
        let search = GridSearch::new(id, grid, any_angle);
        let straight = vec![m.start, m.goal];
        match search.search(problem, i, termination, None) {
            Ok(r) if r.path.len() >= 2 => (r.path, r.expansions, None),
            Ok(r) if r.exhausted => {
                let why = format!("its reference search ({id}) found no route on {} (searched completely)", r.space);
                (straight, r.expansions, Some(why))
            }
            Ok(r) => {
                let why = format!("its reference search ({id}) stopped before finding a route");
                (straight, r.expansions, Some(why))
            }
            Err(e) => (straight, 0, Some(format!("its reference search ({id}) failed: {e}"))),
        }
    }
}

/// `n` interior points along `path` that include all its turns: the turns, then the longest
/// pieces split in half until there are `n`.
fn waypoints_through(path: &[Vec3], n: usize) -> Vec<Vec3> {
    let mut pts: Vec<Vec3> = path.to_vec();
    while pts.len() < n + 2 {
        let k = (0..pts.len() - 1)
            .max_by(|&a, &b| pts[a].distance(pts[a + 1]).total_cmp(&pts[b].distance(pts[b + 1])))
            .unwrap();
        let mid = (pts[k] + pts[k + 1]) * 0.5;
        pts.insert(k + 1, mid);
    }
    while pts.len() > n + 2 {
        // Too many turns: drop the interior point whose removal shortens the path least.
        let k = (1..pts.len() - 1)
            .min_by(|&a, &b| {
                let d = |k: usize| {
                    pts[k - 1].distance(pts[k]) + pts[k].distance(pts[k + 1]) - pts[k - 1].distance(pts[k + 1])
                };
                d(a).total_cmp(&d(b))
            })
            .unwrap();
        pts.remove(k);
    }
    pts[1..pts.len() - 1].to_vec()
}

impl Planner for Hybrid {
    fn id(&self) -> &'static str {
        "hybrid"
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        rng: &mut Rng,
        options: RunOptions<'_>,
        observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        let watch = termination.start();
        let mut expansions = 0;
        let mut refs = Vec::new();
        let mut no_route = Vec::new();
        let missions = problem.missions.len();
        for i in 0..missions {
            // The references share half of the time left, mission by mission; the refinement
            // then has what remains, on the same clock.
            let share = 0.5 / (missions - i) as f64;
            let (path, e, why) = match options.init.and_then(|p| p.get(i)).filter(|p| p.len() >= 2) {
                Some(p) => (p.clone(), 0, None),
                None => self.reference(problem, i, &termination.share_of_remaining(share)),
            };
            expansions += e;
            refs.push(path);
            no_route.push(why);
        }
        // One free encoding per mission, with enough waypoints for the reference's turns.
        let mut encodings: Vec<Box<dyn Encoding>> = Vec::new();
        let mut seeds_pts = Vec::new();
        for (i, r) in refs.iter().enumerate() {
            let m = &problem.missions[i];
            // The reference's essential turns: drop every point whose bypass is feasible and
            // no costlier (so the arcs of a visibility path shrink to the bends that matter).
            let r = &self.smoother.smooth(&problem.path_model(i), problem.cost, r, termination);
            let turns = r.len().saturating_sub(2);
            let n = (2 * turns + 4).clamp(6, 24).max(turns.min(MAX_WAYPOINTS));
            let enc = FreeWaypoints::new(m.start, m.goal, n, &problem.world.bounds, problem.z_range(i))
                .expect("free encodings accept any mission inside the domain");
            let mut pts = vec![m.start];
            pts.extend(waypoints_through(r, n));
            pts.push(m.goal);
            seeds_pts.push(pts);
            encodings.push(Box::new(enc));
        }
        let objective = PathObjective::new(problem, encodings);
        let claim = no_route.iter().any(Option::is_some).then_some(Claim::NoRoute(no_route));
        let Some(base) = objective.encode(&seeds_pts) else {
            return PlannerOutput {
                paths: refs,
                speeds: Vec::new(),
                claim,
                stats: SearchStats { expansions, ..SearchStats::default() },
                graphs: Vec::new(),
            };
        };
        // The reference and jittered copies (up to about one raster cell, in the encoding's
        // normalised units).
        let size = problem.world.bounds.size();
        let cells = self.params.cells.unwrap_or(200) as f64;
        let jitter = 1.0 / cells * size.x.max(size.y) / size.x.min(size.y).max(1e-9);
        let mut seeds = vec![base.clone()];
        for _ in 1..self.params.population {
            let x: Vec<f64> = base.iter().map(|v| v + jitter * (2.0 * rng.random::<f64>() - 1.0)).collect();
            seeds.push(x);
        }
        let de_params = DeParams { population: self.params.population, ..DeParams::default() };
        let mut de = De::new(de_params.checked("planner.params.hybrid").expect("DE accepts every hybrid population"));
        let t = if termination.max_iterations.is_some() || termination.max_evaluations.is_some() {
            termination.clone()
        } else {
            Termination { max_iterations: Some(self.params.iterations), ..termination.clone() }
        };
        // Every seed is a starting point: the population is the reference's neighbourhood.
        let r = optim::run(&mut de, &objective, &t, rng, options.parallel, &seeds, observer);
        let (raw, speeds) = if r.best_x.len() == objective.dim() {
            (objective.decode(&r.best_x), objective.decode_speeds(&r.best_x))
        } else {
            (seeds_pts, Vec::new())
        };
        let mut paths = Vec::with_capacity(raw.len());
        let mut smoothed_speeds = Vec::with_capacity(raw.len());
        for (i, p) in raw.iter().enumerate() {
            let given = speeds.get(i).cloned().flatten();
            let base = problem.path_model(i);
            let model = base.with_speeds(given.as_deref());
            let s = self.smoother.smooth(&model, problem.cost, p, termination);
            smoothed_speeds.push(given.map(|v| crate::path::resample_speeds(p, &v, &s)));
            paths.push(s);
        }
        PlannerOutput {
            paths,
            speeds: smoothed_speeds,
            claim,
            stats: SearchStats {
                iterations: r.iterations,
                evaluations: r.evaluations,
                expansions,
                history: r.history,
                stop_reason: r.stop_reason,
                elapsed: watch.elapsed(),
                ..SearchStats::default()
            },
            graphs: Vec::new(),
        }
    }
}
