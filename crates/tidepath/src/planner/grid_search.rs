//! `astar` and `theta-star`: exact search on a rasterised world (see [`crate::raster`]).
//!
//! The graph: the centres of the conservative raster's free cells (8-connected in 2-D,
//! 26-connected in 3-D, no corner cutting), with the mission's own start and goal in place of
//! their cells' centres. Every edge is checked by the shared motion validator at the time the
//! vehicle reaches it, so a returned path is valid edge by edge. The objective is `length` or
//! `time` (travel time through the currents, a time-dependent search: an edge leaves at the
//! arrival time of its tail); `auto` takes time when the world has a current, else length
//! (in still water the two agree). A* uses the straight-line distance, over the best possible
//! ground speed for time, as its heuristic: admissible when a bound on the current's speed is
//! known (none, uniform, gridded), and then a found path is optimal on this graph (status
//! `exact`). Theta* (Nash et al. 2007) relaxes a node through its parent's parent when the two
//! see each other, giving any-angle paths never longer than A*'s; it is not guaranteed optimal.

use tidepath_search::{astar, theta_star, Grid2, Grid3, Limits, SearchGrid, SearchStatus};

use super::{Claim, Planner, PlannerOutput, PlannerSettings, Problem, RunOptions, SearchStats};
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::raster::Raster;
use crate::registry::Param;
use crate::rng::Rng;
use crate::termination::from_search_stop;
use crate::termination::{StopReason, Termination};
use crate::world::{Current, Dims, Terrain, World};

/// Most cells along the domain's longer side for which a map given cell by cell is searched
/// on its own cells by default (beyond, the default raster applies).
const MAX_MAP_CELLS: f64 = 1000.0;

/// The parameters of the grid planners.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GridParams {
    /// "auto", "length" or "time".
    pub objective: String,
    /// Horizontal cell size (m); 0 picks one so the domain's longer side has `cells` cells.
    pub cell: f64,
    /// Cells along the domain's longer side when `cell` is 0; 0 picks 200 in 2-D and 80 in
    /// 3-D (where the voxels also span the depth band, and every edge is a motion check).
    pub cells: usize,
    /// Layers across the depth band (3-D).
    pub layers: usize,
}

impl Default for GridParams {
    fn default() -> Self {
        Self { objective: "auto".into(), cell: 0.0, cells: 0, layers: 16 }
    }
}

pub const PARAMS: &[Param] = &[
    Param {
        name: "objective",
        range: "\"auto\", \"length\" or \"time\"",
        help: "what the search minimises (default auto)",
    },
    Param { name: "cell", range: "m, >= 0", help: "horizontal cell size; 0: from `cells` (default 0)" },
    Param {
        name: "cells",
        range: "0, or integer in [4, 4096]",
        help: "cells along the domain's longer side; 0: a cell map's own cells, else 200 in 2-D, 80 in 3-D (default 0)",
    },
    Param {
        name: "layers",
        range: "integer in [1, 256]",
        help: "voxel layers across the depth band, 3-D (default 16)",
    },
];

impl GridParams {
    pub fn from_settings(s: &PlannerSettings, id: &str) -> Result<Self> {
        let mut t = s.params.clone();
        t.remove("population");
        let p: GridParams = crate::config::from_value(toml::Value::Table(t), &format!("planner.params.{id}"))?;
        let field = |f: &str| format!("planner.params.{id}.{f}");
        if !["auto", "length", "time"].contains(&p.objective.as_str()) {
            return Err(Error::input(
                field("objective"),
                format!("must be auto, length or time, got '{}'", p.objective),
            ));
        }
        if !(p.cell >= 0.0 && p.cell.is_finite()) {
            return Err(Error::input(field("cell"), format!("must be finite and >= 0, got {}", p.cell)));
        }
        if p.cells != 0 && !(4..=4096).contains(&p.cells) {
            return Err(Error::input(field("cells"), format!("must be 0 or in [4, 4096], got {}", p.cells)));
        }
        if !(1..=256).contains(&p.layers) {
            return Err(Error::input(field("layers"), format!("must be in [1, 256], got {}", p.layers)));
        }
        Ok(p)
    }
}

/// An upper bound on the current's horizontal speed anywhere and any time, when one is known
/// exactly; `None` for fields only sampled (vortices, the jet).
pub fn current_speed_bound(world: &World) -> Option<f64> {
    match &world.current {
        Current::None => Some(0.0),
        Current::Uniform(v) => Some(v.length()),
        Current::Grid(g) => Some(g.speed_bound()),
        _ => None,
    }
}

/// A search over one mission's raster.
pub struct GridSearch {
    id: &'static str,
    params: GridParams,
    any_angle: bool,
}

impl GridSearch {
    pub fn new(id: &'static str, params: GridParams, any_angle: bool) -> Self {
        Self { id, params, any_angle }
    }
}

/// What one mission's search found.
pub struct MissionSearch {
    pub path: Vec<Vec3>,
    pub optimal: bool,
    pub expansions: u64,
    pub stopped: Option<StopReason>,
}

impl GridSearch {
    /// The raster's cell size, layer thickness and 2-D plane for mission `i`.
    fn raster_settings(&self, problem: &Problem<'_>, i: usize) -> (f64, f64, f64) {
        let w = problem.world;
        let m = &problem.missions[i];
        let size = w.bounds.size();
        let cells = match self.params.cells {
            0 if w.dims == Dims::Three => 80,
            0 => 200,
            n => n,
        };
        // A seabed given cell by cell is searched on its own cells (when they are not too many
        // and nothing else was asked): the raster then sees exactly the map.
        let map_cell = match &w.terrain {
            Terrain::Cells(c)
                if self.params.cells == 0
                    && c.dx == c.dy
                    && size.x.max(size.y) / c.dx <= MAX_MAP_CELLS
                    && c.x0 == w.bounds.min.x
                    && c.y0 == w.bounds.min.y =>
            {
                Some(c.dx)
            }
            _ => None,
        };
        let cell = if self.params.cell > 0.0 {
            self.params.cell
        } else {
            map_cell.unwrap_or(size.x.max(size.y) / cells as f64)
        };
        let band = (w.bounds.max.z.min(m.vehicle.z_max()) - w.bounds.min.z.max(m.vehicle.z_min())).max(1e-9);
        (cell, band / self.params.layers as f64, m.start.z)
    }

    /// Searches mission `i` within `termination` (its clock, stop flag and deadline bound the
    /// rasterisation and the search) and at most `max_expansions` expansions.
    pub fn search(
        &self,
        problem: &Problem<'_>,
        i: usize,
        termination: &Termination,
        max_expansions: Option<u64>,
    ) -> Result<MissionSearch> {
        let (cell, cell_z, plane_z) = self.raster_settings(problem, i);
        let stop = || termination.interrupted().is_some();
        let vehicle = &problem.missions[i].vehicle;
        let Some(r) = Raster::new_within(problem.world, vehicle, cell, cell_z, plane_z, &stop)? else {
            let stopped = termination.interrupted().or(Some(StopReason::WallTime));
            return Ok(MissionSearch { path: Vec::new(), optimal: false, expansions: 0, stopped });
        };
        let limits = &termination.search_limits(max_expansions);
        let m = &problem.missions[i];
        let model = problem.path_model(i);
        let validator = &model.validator;
        let (s, g) = (r.cell_of(m.start), r.cell_of(m.goal));
        let time = match self.params.objective.as_str() {
            "time" => true,
            "length" => false,
            _ => !matches!(problem.world.current, Current::None),
        };
        let v = m.vehicle.speed;
        let bound = current_speed_bound(problem.world);
        let hint = match bound {
            Some(b) => b,
            None => match problem.world.current.max_speed_hint_within(&problem.world.bounds, m.departure_time, &stop) {
                Some(h) => 1.5 * h,
                None => {
                    let stopped = termination.interrupted().or(Some(StopReason::WallTime));
                    return Ok(MissionSearch { path: Vec::new(), optimal: false, expansions: 0, stopped });
                }
            },
        };
        let best_speed = v + hint;
        let pos = |c: usize| {
            if c == s {
                m.start
            } else if c == g {
                m.goal
            } else {
                r.centre(c)
            }
        };
        // The pitch limit is a property of each segment, so edges steeper than it are left out
        // of the graph (pure vertical moves among them, in 3-D), rather than found on the path.
        let tan_pitch = m.vehicle.max_pitch.tan();
        let edge = |a: usize, b: usize, g_from: f64| -> Option<f64> {
            let t0 = if time { m.departure_time + g_from } else { m.departure_time + g_from / v };
            let (pa, pb) = (pos(a), pos(b));
            let d = pb - pa;
            if r.three_d && d.z != 0.0 && d.z.abs() > tan_pitch * d.truncate().length() {
                return None;
            }
            let check = validator.motion(pa, pb, t0);
            if !check.valid() {
                return None;
            }
            Some(if time { check.arrival - t0 } else { pa.distance(pb) })
        };
        let goal = m.goal;
        let h = |c: usize| {
            let d = pos(c).distance(goal);
            if time {
                d / best_speed
            } else {
                d
            }
        };
        let mut blocked = r.conservative.clone();
        blocked[s] = false;
        blocked[g] = false;
        let outcome = if r.three_d {
            let grid =
                Grid3::from_blocked(r.nx, r.ny, r.nz, blocked).map_err(|e| Error::input("raster", e.to_string()))?;
            self.run(&grid, s, g, edge, h, limits)
        } else {
            let grid = Grid2::from_blocked(r.nx, r.ny, blocked).map_err(|e| Error::input("raster", e.to_string()))?;
            self.run(&grid, s, g, edge, h, limits)
        }
        .map_err(|e| Error::input("planner", e.to_string()))?;
        let stopped = match outcome.status {
            SearchStatus::Stopped(r) => Some(from_search_stop(r)),
            _ => None,
        };
        let path =
            if s == g { vec![m.start, m.goal] } else { simplify(outcome.path.iter().map(|&c| pos(c)).collect()) };
        // Optimal on the graph: for time with an admissible heuristic (and FIFO edges); for
        // length when the times used to check edges are exact (still water or a uniform
        // current) and nothing moves.
        let fixed = problem.world.obstacles.iter().all(|o| o.velocity == Vec3::ZERO);
        let exact_model = if time {
            bound.is_some()
        } else {
            fixed && matches!(problem.world.current, Current::None | Current::Uniform(_))
        };
        Ok(MissionSearch {
            optimal: outcome.found() && !self.any_angle && exact_model,
            path: if outcome.found() || s == g { path } else { Vec::new() },
            expansions: outcome.expansions,
            stopped,
        })
    }

    fn run<G, C, H>(
        &self,
        grid: &G,
        s: usize,
        g: usize,
        edge: C,
        h: H,
        limits: &Limits<'_>,
    ) -> std::result::Result<tidepath_search::SearchOutcome, tidepath_search::SearchError>
    where
        G: SearchGrid + tidepath_search::LineOfSight,
        C: FnMut(usize, usize, f64) -> Option<f64>,
        H: FnMut(usize) -> f64,
    {
        if self.any_angle {
            theta_star(grid, s, g, edge, h, limits)
        } else {
            astar(grid, s, g, edge, h, limits)
        }
    }
}

/// Drops interior points where the path runs straight on.
pub fn simplify(points: Vec<Vec3>) -> Vec<Vec3> {
    if points.len() < 3 {
        return points;
    }
    let mut out = vec![points[0]];
    for k in 1..points.len() - 1 {
        let (a, b, c) = (*out.last().unwrap(), points[k], points[k + 1]);
        let (u, w) = (b - a, c - b);
        if u.cross(w).length() > 1e-9 * u.length() * w.length() || u.dot(w) < 0.0 {
            out.push(b);
        }
    }
    out.push(*points.last().unwrap());
    out
}

impl Planner for GridSearch {
    fn id(&self) -> &'static str {
        self.id
    }

    fn check(&self, problem: &Problem<'_>) -> Result<()> {
        for i in 0..problem.missions.len() {
            let (cell, cell_z, _) = self.raster_settings(problem, i);
            Raster::shape(problem.world, &problem.missions[i].vehicle, cell, cell_z).map_err(|e| match e {
                Error::Input { message, .. } => Error::input(format!("planner.params.{}", self.id), message),
                other => other,
            })?;
        }
        Ok(())
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        _rng: &mut Rng,
        _options: RunOptions<'_>,
        _observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        let watch = termination.start();
        let mut stats = SearchStats::default();
        let mut paths = Vec::new();
        let mut optimal = true;
        for i in 0..problem.missions.len() {
            let left = termination.max_expansions.map(|m| m.saturating_sub(stats.expansions));
            match self.search(problem, i, termination, left) {
                Ok(r) => {
                    stats.expansions += r.expansions;
                    optimal &= r.optimal;
                    if let Some(reason) = r.stopped {
                        stats.stop_reason = reason;
                    }
                    paths.push(r.path);
                }
                Err(_) => {
                    optimal = false;
                    paths.push(Vec::new());
                }
            }
        }
        stats.elapsed = watch.elapsed();
        PlannerOutput { paths, claim: optimal.then_some(Claim::Optimal), stats }
    }
}

/// True when every mission's world is one the grid planners cover (always: 2-D planes and
/// 3-D voxels); kept for symmetry with the visibility planner's check.
pub fn applies(world: &World) -> bool {
    matches!(world.dims, Dims::Two | Dims::Three)
}
