//! The reusable piece every raster planner calls: one mission's world rasterised on the run's
//! clock, every move priced by the scenario's own cost model, and the search crate's one
//! best-first loop driven by a relaxation that keeps the vehicle's clock.
//!
//! * **Graph**: the centres of the conservative raster's free cells (see [`crate::raster`]),
//!   8-connected in 2-D and 26-connected in 3-D without corner cutting, with the mission's own
//!   start and goal in place of their cells' centres.
//! * **Edges**: a move is priced by [`CostModel::motion_cost`], the cost the path evaluation
//!   reports for the model's additive terms, leaving at the vehicle's arrival time at its tail
//!   (a time-dependent search). Moves the motion validator rejects, and moves steeper than the
//!   vehicle's pitch limit, are not in the graph. `length` and `time` objectives price a move
//!   by its length or its travel time instead.
//! * **Clock**: the arrival time at each node is kept beside its cost and set exactly when the
//!   search accepts an offer ([`Frontier::offer`] returns whether it did), so an edge always
//!   leaves at the arrival time of the path the search holds for its tail.
//! * **Heuristic**: the cost model's lower bound on covering the straight distance to the goal
//!   at the best ground speed the current allows ([`CostModel::motion_lower_bound`]);
//!   admissible and consistent when a bound on the current's speed is known exactly.
//! * **Stops**: the run's termination bounds the rasterisation, the speed estimate and the
//!   search; the search crate's stop reasons are mapped to the run's.

use tidepath_search::{
    best_first_on_grid, Expanded, Frontier, Grid2, Grid3, LineOfSight, Relax, SearchArena, SearchGrid, SearchOutcome,
};

use super::Problem;
use crate::cost::CostModel;
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::path::PathModel;
use crate::raster::Raster;
use crate::termination::{from_search_stop, StopReason, Termination};
use crate::world::{Current, World};

/// What a raster search minimises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Objective {
    /// The scenario's cost model (its additive terms).
    Cost,
    /// Path length.
    Length,
    /// Travel time through the currents.
    Time,
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

/// Whether an edge's cost and validity do not depend on when the vehicle leaves: no moving
/// obstacle, and a current that does not change in time. Label-setting search on cost is then
/// exact; in a time-varying world a path that arrives later at a node with a lower cost can
/// be worse onwards.
pub fn time_invariant(world: &World) -> bool {
    let steady = match &world.current {
        Current::None | Current::Uniform(_) | Current::Vortices(_) => true,
        Current::Grid(g) => g.is_steady(),
        _ => false,
    };
    steady && world.obstacles.iter().all(|o| o.is_fixed())
}

/// One mission's raster, priced and ready to search.
pub struct RasterSearch<'a> {
    pub raster: Raster,
    model: PathModel<'a>,
    cost: &'a dyn CostModel,
    objective: Objective,
    /// Start and goal cells.
    pub start: usize,
    pub goal: usize,
    start_point: Vec3,
    goal_point: Vec3,
    departure: f64,
    /// The best ground speed the current allows (for the heuristic).
    best_speed: f64,
    /// The heuristic is a true lower bound (the current's speed bound is exact).
    admissible: bool,
    tan_pitch: f64,
}

/// What one raster search found.
pub struct RasterOutcome {
    /// Start, turning points, goal; empty when nothing was found.
    pub path: Vec<Vec3>,
    pub found: bool,
    pub expansions: u64,
    /// Moves priced (each a motion check by the shared validator).
    pub motion_checks: u64,
    /// Cells rasterised (each a state judgement) and the free ones among them (the graph's nodes).
    pub cells: u64,
    pub free_cells: u64,
    pub stopped: Option<StopReason>,
}

impl<'a> RasterSearch<'a> {
    /// Rasterises mission `i` with cells of `cell` m (layers `cell_z` m thick in 3-D) within
    /// `termination`; `Ok(None)` when the clock or the stop flag ended the preparation.
    pub fn new(
        problem: &Problem<'a>,
        i: usize,
        cell: f64,
        cell_z: f64,
        objective: Objective,
        termination: &Termination,
    ) -> Result<Option<Self>> {
        let m = &problem.missions[i];
        let stop = || termination.interrupted().is_some();
        let Some(raster) = Raster::new_within(problem.world, &m.vehicle, cell, cell_z, m.start.z, &stop)? else {
            return Ok(None);
        };
        let bound = current_speed_bound(problem.world);
        let hint = match bound {
            Some(b) => b,
            None => match problem.world.current.max_speed_hint_within(&problem.world.bounds, m.departure_time, &stop) {
                Some(h) => 1.5 * h,
                None => return Ok(None),
            },
        };
        let (start, goal) = (raster.cell_of(m.start), raster.cell_of(m.goal));
        Ok(Some(Self {
            raster,
            model: problem.path_model(i),
            cost: problem.cost,
            objective,
            start,
            goal,
            start_point: m.start,
            goal_point: m.goal,
            departure: m.departure_time,
            best_speed: m.vehicle.best_ground_speed(problem.world.waves.height_bound(), hint),
            admissible: bound.is_some(),
            tan_pitch: m.vehicle.max_pitch.tan(),
        }))
    }

    /// The point a cell stands for: the mission's start and goal in their own cells.
    pub fn point(&self, c: usize) -> Vec3 {
        if c == self.start {
            self.start_point
        } else if c == self.goal {
            self.goal_point
        } else {
            self.raster.centre(c)
        }
    }

    /// The move a -> b leaving at `t0`: its cost under the objective and the arrival time, or
    /// `None` when it is not in the graph (invalid, or steeper than the pitch limit).
    pub fn price(&self, a: usize, b: usize, t0: f64) -> Option<(f64, f64)> {
        let (pa, pb) = (self.point(a), self.point(b));
        let d = pb - pa;
        if self.raster.three_d && d.z != 0.0 && d.z.abs() > self.tan_pitch * d.truncate().length() {
            return None;
        }
        match self.objective {
            // With a speed range, the cheapest of the vehicle's speed levels for this edge.
            Objective::Cost => crate::cost::cheapest_motion(self.cost, &self.model, pa, pb, t0).map(|(c, t, _)| (c, t)),
            Objective::Length | Objective::Time => {
                let check = self.model.validator.motion(pa, pb, t0);
                if !check.valid() {
                    return None;
                }
                let c = if self.objective == Objective::Time { check.arrival - t0 } else { pa.distance(pb) };
                Some((c, check.arrival))
            }
        }
    }

    /// A lower bound on the cost from cell `c` to the goal.
    pub fn heuristic(&self, c: usize) -> f64 {
        let d = self.point(c).distance(self.goal_point);
        match self.objective {
            Objective::Cost => self.cost.motion_lower_bound(&self.model, d, self.best_speed),
            Objective::Length => d,
            Objective::Time => d / self.best_speed,
        }
    }

    /// Whether a found path is optimal on this graph for the objective: the heuristic is a
    /// true bound, and either the world does not change in time or the objective is time alone
    /// (label-setting on arrival time is exact for FIFO moves).
    pub fn exact(&self, world: &World) -> bool {
        self.admissible && (time_invariant(world) || self.objective == Objective::Time)
    }

    /// Searches from start to goal (any-angle Theta* relaxations when `any_angle`) within
    /// `termination` and at most `max_expansions` expansions.
    pub fn search(
        &self,
        any_angle: bool,
        termination: &Termination,
        max_expansions: Option<u64>,
    ) -> Result<RasterOutcome> {
        let mut blocked = self.raster.conservative.clone();
        blocked[self.start] = false;
        blocked[self.goal] = false;
        let limits = termination.search_limits(max_expansions);
        let r = &self.raster;
        let (outcome, checks) = if r.three_d {
            let grid =
                Grid3::from_blocked(r.nx, r.ny, r.nz, blocked).map_err(|e| Error::input("raster", e.to_string()))?;
            self.run(&grid, any_angle, &limits)
        } else {
            let grid = Grid2::from_blocked(r.nx, r.ny, blocked).map_err(|e| Error::input("raster", e.to_string()))?;
            self.run(&grid, any_angle, &limits)
        };
        let outcome = outcome.map_err(|e| Error::input("planner", e.to_string()))?;
        let stopped = match outcome.status {
            tidepath_search::SearchStatus::Stopped(reason) => Some(from_search_stop(reason)),
            _ => None,
        };
        let found = outcome.found() || self.start == self.goal;
        let path = if self.start == self.goal {
            vec![self.start_point, self.goal_point]
        } else if found {
            outcome.path.iter().map(|&c| self.point(c)).collect()
        } else {
            Vec::new()
        };
        let free_cells = self.raster.conservative.iter().filter(|b| !**b).count() as u64;
        Ok(RasterOutcome {
            path,
            found,
            expansions: outcome.expansions,
            motion_checks: checks,
            cells: self.raster.conservative.len() as u64,
            free_cells,
            stopped,
        })
    }

    fn run<G: SearchGrid + LineOfSight>(
        &self,
        grid: &G,
        any_angle: bool,
        limits: &tidepath_search::Limits<'_>,
    ) -> (std::result::Result<SearchOutcome, tidepath_search::SearchError>, u64) {
        let mut arrival = vec![f64::NAN; grid.cell_count()];
        arrival[self.start] = self.departure;
        let mut relax = Priced { search: self, grid, arrival, any_angle, checks: 0 };
        let out = best_first_on_grid(
            &mut SearchArena::new(),
            grid,
            self.start,
            self.goal,
            &mut relax,
            |c| self.heuristic(c),
            limits,
        );
        (out, relax.checks)
    }
}

/// The relaxation: the move from the expanded cell, and (any-angle) the straight move from its
/// parent when the parent sees the neighbour; the cheaper is offered, and the neighbour's
/// arrival time is set when the search takes the offer.
struct Priced<'s, 'a, G> {
    search: &'s RasterSearch<'a>,
    grid: &'s G,
    /// The vehicle's arrival time at each node, for the path the search holds.
    arrival: Vec<f64>,
    any_angle: bool,
    checks: u64,
}

impl<G: LineOfSight> Relax for &mut Priced<'_, '_, G> {
    fn relax<H: FnMut(usize) -> f64>(&mut self, u: Expanded, v: usize, frontier: &mut Frontier<'_, H>) {
        let mut price = |from: usize, g_from: f64| {
            self.checks += 1;
            self.search.price(from, v, self.arrival[from]).map(|(c, t)| (g_from + c, t, from))
        };
        let mut best = price(u.node, u.g);
        if self.any_angle {
            if let Some(p) = u.parent {
                if self.grid.line_of_sight(p, v) {
                    if let Some(through) = price(p, frontier.g(p)) {
                        // Ties go to the parent: fewer turning points.
                        if best.is_none_or(|b| through.0 <= b.0) {
                            best = Some(through);
                        }
                    }
                }
            }
        }
        if let Some((g, t, from)) = best {
            if g >= 0.0 && frontier.offer(v, g, from) {
                self.arrival[v] = t;
            }
        }
    }
}

/// Refuses, before planning, a raster too large for memory for any mission: `cells(i)` gives
/// mission i's horizontal and vertical cell sizes; errors name `planner.params.ID`.
pub fn check_raster_sizes(problem: &Problem<'_>, id: &str, cells: impl Fn(usize) -> (f64, f64)) -> Result<()> {
    for i in 0..problem.missions.len() {
        let (cell, cell_z) = cells(i);
        Raster::shape(problem.world, &problem.missions[i].vehicle, cell, cell_z).map_err(|e| match e {
            Error::Input { message, .. } => Error::input(format!("planner.params.{id}"), message),
            other => other,
        })?;
    }
    Ok(())
}
