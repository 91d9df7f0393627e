//! `astar` and `theta-star`: search on a rasterised world, through the reusable raster search
//! ([`super::raster_search`]): every move priced by the scenario's cost model (or by length or
//! time alone, `objective`), checked by the shared motion validator at the vehicle's clock.
//! A* with an admissible heuristic finds the cheapest path on its graph (status `exact`, the
//! reason naming the raster) when the world does not change in time; Theta* (Nash et al. 2007)
//! relaxes a node through its parent when the two see each other, giving any-angle paths never
//! costlier than A*'s, but not guaranteed optimal.

use super::raster_search::{Objective, RasterSearch};
use super::{Claim, Planner, PlannerOutput, Problem, RunOptions, SearchStats};
use crate::error::Result;
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::params::{Bound, Checked, Range, Word};
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};
use crate::world::{Dims, Terrain, World};

/// Most cells along the domain's longer side for which a map given cell by cell is searched
/// on its own cells by default (beyond, the default raster applies).
const MAX_MAP_CELLS: f64 = 1000.0;

impl Word for Objective {
    const WORDS: &'static [(&'static str, Self)] =
        &[("cost", Objective::Cost), ("length", Objective::Length), ("time", Objective::Time)];
}

crate::params::word_param!(Objective);

crate::params! {
    /// The parameters of the grid planners.
    pub struct GridParams {
        /// What a move costs: the scenario's cost model, or length or time alone.
        objective: Objective = Objective::Cost, Range::Choice(&["cost", "length", "time"]), "tidepath";
        /// Horizontal cell size (m); absent: from `cells`.
        cell: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e7) }, "tidepath";
        /// Cells along the domain's longer side when `cell` is absent; absent: a cell map's
        /// own cells, else 200 in 2-D and 80 in 3-D (where the voxels also span the depth band
        /// and every edge is a motion check).
        cells: Option<usize> = None, Range::integer(4, 4096), "tidepath";
        /// Voxel layers across the depth band (3-D).
        layers: usize = 16, Range::integer(1, 256), "tidepath";
    }
}

pub use super::raster_search::current_speed_bound;

/// A search over one mission's raster.
pub struct GridSearch {
    id: &'static str,
    params: GridParams,
    any_angle: bool,
}

impl GridSearch {
    /// A grid planner from checked parameters.
    pub fn new(id: &'static str, params: Checked<GridParams>, any_angle: bool) -> Self {
        Self { id, params: params.into_inner(), any_angle }
    }
}

/// What one mission's search found.
pub struct MissionSearch {
    pub path: Vec<Vec3>,
    pub optimal: bool,
    pub expansions: u64,
    pub motion_checks: u64,
    /// Raster cells judged, and the free ones (the graph's nodes).
    pub state_checks: u64,
    pub graph_nodes: u64,
    pub stopped: Option<StopReason>,
    /// The graph searched, for the reason of an `exact` plan.
    pub space: String,
    /// The search ran to completion and found no path: nothing on this raster connects start
    /// and goal (a passage narrower than its cells may still exist).
    pub exhausted: bool,
}

impl GridSearch {
    /// The raster's cell size, layer thickness and 2-D plane for mission `i`.
    fn raster_settings(&self, problem: &Problem<'_>, i: usize) -> (f64, f64, f64) {
        let w = problem.world;
        let m = &problem.missions[i];
        let size = w.bounds.size();
        let cells = match self.params.cells {
            None if w.dims == Dims::Three => 80,
            None => 200,
            Some(n) => n,
        };
        // A seabed given cell by cell is searched on its own cells (when they are not too many
        // and nothing else was asked): the raster then sees exactly the map.
        let map_cell = match &w.terrain {
            Terrain::Cells(c)
                if self.params.cells.is_none()
                    && c.dx == c.dy
                    && size.x.max(size.y) / c.dx <= MAX_MAP_CELLS
                    && c.x0 == w.bounds.min.x
                    && c.y0 == w.bounds.min.y =>
            {
                Some(c.dx)
            }
            _ => None,
        };
        let cell = self.params.cell.unwrap_or_else(|| map_cell.unwrap_or(size.x.max(size.y) / cells as f64));
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
        let (cell, cell_z, _) = self.raster_settings(problem, i);
        let Some(rs) = RasterSearch::new(problem, i, cell, cell_z, self.params.objective, termination)? else {
            let stopped = termination.interrupted().or(Some(StopReason::WallTime));
            return Ok(MissionSearch {
                path: Vec::new(),
                optimal: false,
                expansions: 0,
                motion_checks: 0,
                state_checks: 0,
                graph_nodes: 0,
                stopped,
                space: String::new(),
                exhausted: false,
            });
        };
        let out = rs.search(self.any_angle, termination, max_expansions)?;
        let r = &rs.raster;
        let space = if r.three_d {
            format!("the 26-connected {} x {} x {} raster", r.nx, r.ny, r.nz)
        } else {
            format!("the 8-connected {} x {} raster", r.nx, r.ny)
        };
        Ok(MissionSearch {
            exhausted: !out.found && out.stopped.is_none(),
            optimal: out.found && !self.any_angle && rs.exact(problem.world),
            path: simplify(out.path),
            expansions: out.expansions,
            motion_checks: out.motion_checks,
            state_checks: out.cells,
            graph_nodes: out.free_cells,
            stopped: out.stopped,
            space,
        })
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
        super::raster_search::check_raster_sizes(problem, self.id, |i| {
            let (cell, cell_z, _) = self.raster_settings(problem, i);
            (cell, cell_z)
        })
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
        let mut space = String::new();
        let mut no_route = vec![None; problem.missions.len()];
        for (i, no_route) in no_route.iter_mut().enumerate() {
            let left = termination.max_expansions.map(|m| m.saturating_sub(stats.expansions));
            match self.search(problem, i, termination, left) {
                Ok(r) => {
                    stats.expansions += r.expansions;
                    stats.motion_checks += r.motion_checks;
                    stats.state_checks += r.state_checks;
                    stats.graph_nodes += r.graph_nodes;
                    optimal &= r.optimal;
                    if r.exhausted {
                        *no_route = Some(format!("no route on {} (searched completely)", r.space));
                    }
                    space = r.space;
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
        let what = match self.params.objective {
            Objective::Cost => "the scenario's cost model",
            Objective::Length => "length",
            Objective::Time => "travel time",
        };
        let claim = if optimal {
            Some(Claim::Optimal {
                space: format!("on {space}"),
                scenario_cost: self.params.objective == Objective::Cost,
                objective: what.to_string(),
            })
        } else {
            no_route.iter().any(Option::is_some).then_some(Claim::NoRoute(no_route))
        };
        PlannerOutput { paths, speeds: Vec::new(), claim, stats, graphs: Vec::new() }
    }
}

/// True when every mission's world is one the grid planners cover (always: 2-D planes and
/// 3-D voxels); kept for symmetry with the visibility planner's check.
pub fn applies(world: &World) -> bool {
    matches!(world.dims, Dims::Two | Dims::Three)
}
