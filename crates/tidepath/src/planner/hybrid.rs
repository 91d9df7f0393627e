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
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::optim::de::{De, DeParams};
use crate::optim::{self, Objective as _, Progress};
use crate::registry::Param;
use crate::rng::Rng;
use crate::smoothing::{Shortcut, Smoother as _};
use crate::termination::Termination;

#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HybridParams {
    /// DE population.
    pub population: usize,
    /// Cells along the domain's longer side for the reference search; 0: the grid planners'
    /// default (200 in 2-D, 80 in 3-D).
    pub cells: usize,
    /// Iterations of the refinement when the run gives no count limit.
    pub iterations: u64,
}

impl Default for HybridParams {
    fn default() -> Self {
        Self { population: 30, cells: 0, iterations: 300 }
    }
}

pub const PARAMS: &[Param] = &[
    Param { name: "population", range: "integer in [4, 100000]", help: "DE population of the refinement (default 30)" },
    Param {
        name: "cells",
        range: "integer in [4, 4096]",
        help: "raster cells along the longer side for the reference (default 200)",
    },
    Param {
        name: "iterations",
        range: "integer >= 1",
        help: "refinement iterations when the run sets no count limit (default 300)",
    },
];

/// Most free waypoints per mission.
const MAX_WAYPOINTS: usize = 40;

pub struct Hybrid {
    params: HybridParams,
}

impl Hybrid {
    pub fn new(params: HybridParams) -> Result<Self> {
        crate::optim::check_population(params.population, 4).map_err(|e| match e {
            Error::Input { message, .. } => Error::input("planner.params.hybrid.population", message),
            other => other,
        })?;
        if params.cells != 0 && !(4..=4096).contains(&params.cells) {
            return Err(Error::input(
                "planner.params.hybrid.cells",
                format!("must be 0 or in [4, 4096], got {}", params.cells),
            ));
        }
        crate::termination::check_count("planner.params.hybrid.iterations", params.iterations)?;
        Ok(Self { params })
    }

    /// The reference path of mission `i` within `termination` (a share of the run's time on
    /// the run's clock), and the expansions it took.
    fn reference(&self, problem: &Problem<'_>, i: usize, termination: &Termination) -> (Vec<Vec3>, u64) {
        let m = &problem.missions[i];
        if let Ok((scene, _)) = visibility::scene(problem, i, true) {
            let p = tidepath_search::visibility::shortest_path_within(
                &scene,
                [m.start.x, m.start.y],
                [m.goal.x, m.goal.y],
                0.1,
                &termination.search_limits(None),
            );
            if let Ok(Some(p)) = p {
                let mut pts: Vec<Vec3> = p.polyline.iter().map(|q| Vec3::new(q[0], q[1], m.start.z)).collect();
                let n = pts.len();
                pts[0] = m.start;
                pts[n - 1] = m.goal;
                return (pts, 0);
            }
        }
        // Any-angle Theta* in 2-D; in 3-D plain A* (Theta*'s line-of-sight relaxations make
        // every voxel try long motions, ten times slower, and the refinement straightens the
        // grid's corners anyway).
        let any_angle = problem.world.dims == crate::world::Dims::Two;
        let id = if any_angle { "theta-star" } else { "astar" };
        let search = GridSearch::new(id, GridParams { cells: self.params.cells, ..GridParams::default() }, any_angle);
        match search.search(problem, i, termination, None) {
            Ok(r) if r.path.len() >= 2 => (r.path, r.expansions),
            Ok(r) => (vec![m.start, m.goal], r.expansions),
            Err(_) => (vec![m.start, m.goal], 0),
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
        let missions = problem.missions.len();
        for i in 0..missions {
            // The references share half of the time left, mission by mission; the refinement
            // then has what remains, on the same clock.
            let share = 0.5 / (missions - i) as f64;
            let (path, e) = match options.init.and_then(|p| p.get(i)).filter(|p| p.len() >= 2) {
                Some(p) => (p.clone(), 0),
                None => self.reference(problem, i, &termination.share_of_remaining(share)),
            };
            expansions += e;
            refs.push(path);
        }
        // One free encoding per mission, with enough waypoints for the reference's turns.
        let mut encodings: Vec<Box<dyn Encoding>> = Vec::new();
        let mut seeds_pts = Vec::new();
        for (i, r) in refs.iter().enumerate() {
            let m = &problem.missions[i];
            // The reference's essential turns: drop every point whose bypass is feasible and
            // no costlier (so the arcs of a visibility path shrink to the bends that matter).
            let r = &Shortcut.smooth(&problem.path_model(i), problem.cost, r, termination);
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
        let Some(base) = objective.encode(&seeds_pts) else {
            return PlannerOutput {
                paths: refs,
                claim: None,
                stats: SearchStats { expansions, ..SearchStats::default() },
            };
        };
        // The reference and jittered copies (up to about one raster cell, in the encoding's
        // normalised units).
        let size = problem.world.bounds.size();
        let cells = if self.params.cells == 0 { 200.0 } else { self.params.cells as f64 };
        let jitter = 1.0 / cells * size.x.max(size.y) / size.x.min(size.y).max(1e-9);
        let mut seeds = vec![base.clone()];
        for _ in 1..self.params.population {
            let x: Vec<f64> = base.iter().map(|v| v + jitter * (2.0 * rng.random::<f64>() - 1.0)).collect();
            seeds.push(x);
        }
        let mut de = De::new(DeParams { population: self.params.population, ..DeParams::default() });
        let t = if termination.max_iterations.is_some() || termination.max_evaluations.is_some() {
            termination.clone()
        } else {
            Termination { max_iterations: Some(self.params.iterations), ..termination.clone() }
        };
        // Every seed is a starting point: the population is the reference's neighbourhood.
        let r = optim::run(&mut de, &objective, &t, rng, options.parallel, &seeds, observer);
        let paths = if r.best_x.len() == objective.dim() { objective.decode(&r.best_x) } else { seeds_pts };
        let paths = paths
            .iter()
            .enumerate()
            .map(|(i, p)| Shortcut.smooth(&problem.path_model(i), problem.cost, p, termination))
            .collect();
        PlannerOutput {
            paths,
            claim: None::<Claim>,
            stats: SearchStats {
                iterations: r.iterations,
                evaluations: r.evaluations,
                expansions,
                history: r.history,
                stop_reason: r.stop_reason,
                elapsed: watch.elapsed(),
                ..SearchStats::default()
            },
        }
    }
}
