//! `hybrid-astar`: Hybrid-A* (Dolgov, Thrun, Montemerlo & Diebel 2010; Nav2 Smac's
//! production version is the model) over motion primitives of the vehicle's turning radius,
//! priced by the scenario's cost model on the vehicle's clock.
//!
//! * **Lattice** (`lattice.rs`): the cells of the world's raster (`cells` along the longer side,
//!   or `cell` metres), `headings` heading bins and, in 3-D, `layers` depth layers across the
//!   band. Each (cell, layer, bin) keeps one continuous state: the cheapest pose that reached it
//!   while it was open (`search.rs`).
//! * **Primitives**: arcs of radius r by whole heading bins (left and right) then straight to a
//!   step of sqrt 2 cells; in 3-D each with a straight part also climbs or dives one layer on
//!   it, within the pitch limit. Each is a tangent polygon, so the vehicle flies exactly the arcs
//!   planned.
//! * **Edges**: every primitive is flown the way the evaluation flies it (`flight.rs`:
//!   straights, and arcs as chords within `model.arc_tolerance`; for a vehicle without a radius,
//!   the polygon itself), each motion priced by
//!   [`crate::cost::CostModel::motion_cost`] leaving at the vehicle's arrival time: the shared
//!   validator checks the seabed, obstacles (moving ones at the vehicle's time), the current and
//!   the domain; its waypoints must be in the domain and depth band.
//! * **Analytic expansion**: from an expanded state, once the expansions since the last try
//!   reach the remaining steps over `shot_ratio` (Nav2's schedule: every expansion near the
//!   goal), the shortest curves to the goal are tried (the two turn-then-straight curves with a
//!   free final heading, and the Dubins curves to `goal_headings` fixed headings, shortest
//!   first, three at most), in 3-D changing height evenly along their straight parts within the
//!   pitch limit. A valid one offers
//!   the goal at its cost; the search ends when the goal is the cheapest open entry, so a later
//!   shot that is cheaper replaces it.
//! * **Heuristic** (`heuristic.rs`): the larger of the free-heading Dubins length and a hop
//!   bound on the optimistic raster, both lower bounds on the length left (the module says
//!   why), made a cost by the model's lower bound at the best ground speed. Admissible when the
//!   current's speed bound is known exactly (still water, uniform, gridded currents); for
//!   sampled fields (vortices, jets) it uses 1.5 times the sampled maximum, as the raster
//!   planners do, and is then only a guide.
//! * **Weight**: the open list orders states by g + w h (weighted A*, Pohl 1970), w = `weight`
//!   (1.5 by default). With w = 1 the search expands every state that could lead to a cheaper
//!   path on the lattice: on a lattice a hundred kilometres across, where a turn of radius 40 m
//!   costs next to nothing at the cell's scale and every heading and depth layer of a cell is
//!   almost as good as the next, that is millions of states (a minute on `salish-strait-turns`);
//!   w = 1.5 finds a path there in some 1,300 expansions.
//! * **Shortcuts** (`shortcut.rs`): the path found is rebuilt from the start with the same
//!   analytic curves as the shots, to the farthest of its states each can reach, and kept when
//!   cheaper (Dolgov et al. smooth the search's path too; this keeps it a tangent polygon).
//! * **Radius**: the vehicle's `turn_radius`; for a vehicle without one, the parameter
//!   `radius`, else two cells (any radius gives a path that respects `max_turn`: each vertex of
//!   a tangent polygon turns by at most 22.5 degrees, less when `max_turn` is smaller).
//! * **Result**: the tangent polygon from the mission's start to its goal, status `feasible`
//!   at best (the lattice is a discretisation and the search weighted; the planner claims no
//!   optimality). When the lattice is exhausted, no route on it; when a budget stops the
//!   search, the path to the expanded state nearest the goal; at a cap of about two million
//!   states, the same, saying so.
//!
//! Budgets: expansions (counted) and the run's wall time and stop flag, polled every 16
//! expansions, in the long checks of the shots, in the rasterisation and in the hop count.

mod flight;
mod heuristic;
mod lattice;
mod search;
mod shortcut;
#[cfg(test)]
mod tests;

pub use heuristic::{free_heading_length, turn_then_straight, TurnStraight};

use super::raster_search::current_speed_bound;
use super::{Claim, Planner, PlannerOutput, Problem, RunOptions, SearchStats};
use crate::error::Result;
use crate::optim::Progress;
use crate::params::{Bound, Checked, Range};
use crate::raster::Raster;
use crate::rng::Rng;
use crate::termination::{StopReason, Termination};
use crate::world::Dims;
use lattice::{Lattice, MAX_PIECE};
use search::{Search, MAX_STATES};

crate::params! {
    /// Hybrid-A*'s parameters.
    pub struct HybridAstarParams {
        /// Heading bins of the lattice (72: 5 degrees each).
        headings: usize = 72, Range::integer(8, 720), "Dolgov et al. 2010";
        /// Horizontal cell size (m); absent: from `cells`.
        cell: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e7) }, "tidepath";
        /// Cells along the domain's longer side when `cell` is absent (a primitive flies about
        /// sqrt 2 cells: on a domain of a hundred kilometres, several turning radii).
        cells: usize = 200, Range::integer(4, 4096), "tidepath";
        /// Layers across the depth band (3-D): a climbing or diving primitive changes depth by
        /// one layer.
        layers: usize = 16, Range::integer(1, 256), "tidepath";
        /// Turning radius of the primitives for a vehicle without `turn_radius` (m); absent:
        /// two cells. A vehicle's own radius is always used.
        radius: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e7) }, "tidepath";
        /// Analytic expansion ratio: a shot to the goal is tried once the expansions since the
        /// last try exceed the steps left divided by this.
        shot_ratio: f64 = 3.5, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e6) }, "Nav2 Smac Hybrid-A* (analytic_expansion_ratio)";
        /// Weight on the heuristic (weighted A*, Pohl 1970): 1 expands every state that could
        /// lead to a cheaper path on the lattice; above 1, far fewer, for paths that may cost
        /// more (at most w times the best on an exact graph with a consistent heuristic).
        weight: f64 = 1.5, Range::closed(1.0, 10.0), "Pohl 1970";
        /// Fixed goal headings the shots try besides the free-heading curves (0: none).
        goal_headings: usize = 8, Range::integer(0, 360), "tidepath";
    }
}

/// The planner.
pub struct HybridAstar {
    params: HybridAstarParams,
}

impl HybridAstar {
    pub fn new(params: Checked<HybridAstarParams>) -> Self {
        Self { params: params.into_inner() }
    }

    /// The requested cell size, layer thickness and the turning radius for mission `i`, and
    /// whether the radius is the vehicle's.
    fn settings(&self, problem: &Problem<'_>, i: usize) -> (f64, f64, f64, bool) {
        let w = problem.world;
        let v = &problem.missions[i].vehicle;
        let size = w.bounds.size();
        let cell = self.params.cell.unwrap_or(size.x.max(size.y) / self.params.cells as f64);
        let band = (w.bounds.max.z.min(v.z_max()) - w.bounds.min.z.max(v.z_min())).max(1e-9);
        let (radius, own) = match v.turn_radius {
            Some(r) => (r, true),
            None => (self.params.radius.unwrap_or(2.0 * cell), false),
        };
        (cell, band / self.params.layers as f64, radius, own)
    }
}

/// What one mission's search found, for the claim.
struct MissionResult {
    space: String,
    exhausted: bool,
    full: bool,
    stopped: bool,
}

impl Planner for HybridAstar {
    fn id(&self) -> &'static str {
        "hybrid-astar"
    }

    fn check(&self, problem: &Problem<'_>) -> Result<()> {
        super::raster_search::check_raster_sizes(problem, "hybrid-astar", |i| {
            let (cell, cell_z, _, _) = self.settings(problem, i);
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
        let mut results = Vec::new();
        for i in 0..problem.missions.len() {
            let left = termination.max_expansions.map(|m| m.saturating_sub(stats.expansions));
            match self.search(problem, i, termination, left, &mut stats) {
                Some((path, r)) => {
                    paths.push(path);
                    results.push(Some(r));
                }
                None => {
                    paths.push(Vec::new());
                    results.push(None);
                }
            }
        }
        stats.elapsed = watch.elapsed();
        let no_route: Vec<Option<String>> = results
            .iter()
            .map(|r| {
                r.as_ref().filter(|r| r.exhausted).map(|r| format!("no route on {} (searched completely)", r.space))
            })
            .collect();
        let claim = if no_route.iter().any(Option::is_some) {
            Claim::NoRoute(no_route)
        } else {
            // The hint is read when a path is not feasible: say why the search gave that path.
            let all: Vec<&MissionResult> = results.iter().flatten().collect();
            let hint = if let Some(r) = all.iter().find(|r| r.full) {
                format!(
                    "the search stopped at its cap of {MAX_STATES} states on {}: use coarser cells, fewer headings or layers, or a larger weight",
                    r.space
                )
            } else if let Some(r) = all.iter().find(|r| r.stopped) {
                format!("the path leads to the expanded state nearest the goal on {}", r.space)
            } else if let Some(r) = all.first() {
                format!("found on {} (a discretisation: flyable paths, not optimal ones)", r.space)
            } else {
                "the search was stopped before it began".to_string()
            };
            Claim::Hint(hint)
        };
        PlannerOutput { paths, speeds: Vec::new(), claim: Some(claim), stats, graphs: Vec::new() }
    }
}

impl HybridAstar {
    /// Searches mission `i`; `None` when the clock or the stop flag ended the preparation.
    fn search(
        &self,
        problem: &Problem<'_>,
        i: usize,
        termination: &Termination,
        max_expansions: Option<u64>,
        stats: &mut SearchStats,
    ) -> Option<(Vec<crate::geom::Vec3>, MissionResult)> {
        let m = &problem.missions[i];
        let (cell, cell_z, radius, own) = self.settings(problem, i);
        let interrupted = || termination.interrupted().is_some();
        let stopped = |stats: &mut SearchStats| {
            stats.stop_reason = termination.interrupted().unwrap_or(StopReason::WallTime);
        };
        let Ok(Some(raster)) = Raster::new_within(problem.world, &m.vehicle, cell, cell_z, m.start.z, &interrupted)
        else {
            stopped(stats);
            return None;
        };
        stats.state_checks += raster.len() as u64;
        let bound = current_speed_bound(problem.world);
        let current = match bound {
            Some(b) => b,
            None => {
                match problem.world.current.max_speed_hint_within(&problem.world.bounds, m.departure_time, &interrupted)
                {
                    Some(h) => 1.5 * h,
                    None => {
                        stopped(stats);
                        return None;
                    }
                }
            }
        };
        let Some(hops) = heuristic::Hops::new(&raster, m.goal, &interrupted) else {
            stopped(stats);
            return None;
        };
        let three_d = problem.world.dims == Dims::Three;
        let max_piece = MAX_PIECE.min(0.99 * m.vehicle.max_turn);
        let lattice = Lattice::new(
            raster.dx.max(raster.dy),
            self.params.headings,
            radius,
            three_d.then_some(raster.dz),
            m.vehicle.max_pitch,
            max_piece,
        );
        let whose = if own { "the vehicle's" } else { "the planner's" };
        let space = if three_d {
            format!(
                "the {}-heading lattice of {} x {} cells x {} layers for {whose} {radius:.1} m turning radius",
                lattice.bins, raster.nx, raster.ny, raster.nz
            )
        } else {
            format!(
                "the {}-heading lattice of {} x {} cells for {whose} {radius:.1} m turning radius",
                lattice.bins, raster.nx, raster.ny
            )
        };
        let search = Search {
            model: problem.path_model(i),
            cost: problem.cost,
            raster,
            hops,
            lattice,
            goal: m.goal,
            start: m.start,
            departure: m.departure_time,
            best_speed: m.vehicle.best_ground_speed(problem.world.waves.height_bound(), current),
            shot_ratio: self.params.shot_ratio,
            weight: self.params.weight,
            goal_headings: self.params.goal_headings,
            max_piece,
            tan_pitch: m.vehicle.max_pitch.tan(),
            three_d,
        };
        let out = search.run(termination, max_expansions);
        stats.expansions += out.expansions;
        stats.motion_checks += out.motion_checks;
        stats.graph_nodes += out.states;
        stats.graph_edges += out.edges;
        if let Some(r) = out.stopped {
            stats.stop_reason = r;
        }
        let exhausted = !out.found && out.stopped.is_none() && !out.full;
        Some((out.path, MissionResult { space, exhausted, full: out.full, stopped: out.stopped.is_some() }))
    }
}
