//! `aco` and `acopf`: ant colonies on the world's raster. `acopf` is acopf2016's improved ant
//! colony with a potential field (Gao, Zhao, Guan, Wang & Zhang 2016): heuristic eqs. 7-10,
//! elite pheromone update eqs. 11-13, loop steps 1-9, section 4's defaults. `aco` is the basic
//! ant system it improves (Dorigo 1991) in the grid form of acopf2016 eqs. 4-6, with the
//! classic heuristic 1/L(s_j, goal).
//!
//! * **Graph** ([`colony`]): the raster search's free cells, 8-connected without corner
//!   cutting, the mission's start and goal points in their cells; every move priced by the
//!   scenario's cost model at the ant's clock ([`RasterSearch::price`]) and refused where the
//!   shared validator refuses it.
//! * **Tours** ([`colony::Walker`]): K ants per iteration, each from the start with a tabu list,
//!   roulette over the allowed neighbours with p ∝ τ^α η^β, until the goal or a dead end.
//! * **Heuristic** ([`heuristic`]) and **pheromone** ([`pheromone`]).
//! * **Result**: the cheapest tour found over all iterations (start, cell centres, goal, points
//!   where it runs straight dropped); `feasible` at best, never `exact`. The history holds the
//!   best cost after each iteration; the iteration that first found the final best is
//!   [`iterations_to_converge`] of it.
//! * **Budget**: T iterations (the run's iteration limit, when set, replaces T and is shared
//!   among a fleet's missions as the sampling planners share samples). Every ant step is
//!   reported as an expansion (a termination's expansion limit, where a caller sets one,
//!   bounds them; the registry declares iterations only) and polls the run's termination
//!   (wall time, stop flag); the rasterisation and the per-cell precomputations poll it once
//!   per row.
//!
//! # Readings (what acopf2016 leaves open, and what tidepath chose)
//!
//! * L_k (eqs. 6, 12, 13) is the tour's summed price (the scenario's cost for `objective =
//!   "cost"`, its length or travel time otherwise) in *cell units*: divided by the least price
//!   of one cell's length (the cost model's lower bound at the best ground speed). The paper's
//!   grid has cells of edge 1 and L in cells; without the division Q = 6 against a cost of
//!   thousands would leave every τ at the clamp.
//! * Distances in the heuristic (L, L_g, L_n, L_0) are in cells of the mean raster edge; L at
//!   the goal cell is half a cell (A13), and the attraction there points along the move into
//!   it (the goal has no direction from itself).
//! * The force is taken at the candidate s_j (A5). Repulsion comes from the raster's blocked
//!   cells within L_0 (centre to centre); the domain's edge does not repel (the paper names
//!   obstacles only, and its start and goal sit in corners). θ_art uses the actual move vector
//!   (start and goal are points, not centres). cos θ is 0 where F or the current vanishes.
//! * X_wht is the wave height at the candidate divided by the world's largest
//!   ([`crate::world::Waves::height_bound`]), X_hfr the current's speed divided by the largest
//!   (exact bound, else the sampled peak at departure), both clamped to [0, 1] (A6). In a
//!   world that does not change in time they are sampled once per cell at the departure time;
//!   otherwise at the ant's clock on every step.
//! * `aco`'s heuristic is 1/L alone (the potential field is what acopf adds); its update is
//!   eqs. 4-6 with ρ on the deposit, as printed.
//! * Pheromone: directed edges, τ_0 = 1, clamp [1e-3, 1e3] after every update, also for eqs.
//!   4-6 (A8). Best and worst are over the ants that reached the goal; stuck ants are
//!   discarded (A9); a lone completed ant is both, and its two extra terms cancel.
//! * Moves: an ant also keeps the vehicle's turn limit at every joint (every vehicle has one;
//!   60 degrees by default, so a path of 90-degree grid corners would be infeasible), as the
//!   sampling planners do; a move the validator refuses at the ant's clock is dropped from
//!   the roulette and the draw repeated. With `lookahead` (default) an ant never enters a
//!   cell it could not leave ([`colony`]); `lookahead = false` gives the paper's ants.
//! * Warm start (`--init`): the cells the given path passes through get τ = τ_max on the
//!   edges between them (where the move is in the graph) before the first iteration.
//! * Worlds that do not change in time: a move's price is kept per directed edge after its
//!   first pricing (the same answer; most of a run's time otherwise).
//! * Unstated constants (A7): α = 1, β = 5, ξ = 1, μ = 10, L_0 = 2 cells, ς = σ = ω = 1.

pub mod colony;
pub mod heuristic;
pub mod pheromone;
#[cfg(test)]
mod tests;

pub use heuristic::{Attraction, Field};

use self::colony::Graph;
use self::pheromone::{TAU_MAX, TAU_MIN};
use super::grid_search::simplify;
use super::raster_search::{current_speed_bound, time_invariant, Objective, RasterSearch};
use super::sampling::{mission_budget, Kinematics};
use super::{Claim, Planner, PlannerOutput, Problem, RunOptions};
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::params::{Bound, Checked, Range};
use crate::raster::Raster;
use crate::rng::Rng;
use crate::termination::{StopReason, Termination, Usage};
use crate::world::{Dims, Terrain, World};

mod run;

/// Most raster cells an ant colony takes: its pheromone, heuristic and price tables hold
/// about 300 bytes per cell (some 300 MB here).
pub const MAX_CELLS: usize = 1 << 20;

crate::params! {
    /// The basic ant colony's parameters (`aco`).
    pub struct AcoParams {
        /// Iterations T when the run sets no iteration limit (`--iterations` or `[planner]
        /// iterations` win).
        iterations: usize = 60, Range::integer(1, 1_000_000), "acopf2016";
        /// Ants K per iteration.
        ants: usize = 30, Range::integer(1, 100_000), "acopf2016";
        /// Evaporation ρ (it also scales the deposit, eq. 4).
        rho: f64 = 0.85, Range::closed(0.0, 1.0), "acopf2016";
        /// Pheromone intensity Q.
        q: f64 = 6.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e6) }, "acopf2016";
        /// Pheromone exponent α.
        alpha: f64 = 1.0, Range::closed(0.0, 10.0), "tidepath (chosen)";
        /// Heuristic exponent β.
        beta: f64 = 5.0, Range::closed(0.0, 20.0), "tidepath (chosen)";
        /// Initial pheromone τ_0.
        tau0: f64 = 1.0, Range::closed(TAU_MIN, TAU_MAX), "tidepath (chosen)";
        /// Ants never enter a cell they could not leave (one step of lookahead; tidepath's,
        /// see the module's readings); false: the paper's ants.
        lookahead: bool = true, Range::Flag, "tidepath (chosen)";
        /// What a move costs: the scenario's cost model, or length or time alone.
        objective: Objective = Objective::Cost, Range::Choice(&["cost", "length", "time"]), "tidepath";
        /// Cell size (m); absent: from `cells`.
        cell: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e7) }, "tidepath";
        /// Cells along the domain's longer side when `cell` is absent; absent: a cell map's own
        /// cells, else 200.
        cells: Option<usize> = None, Range::integer(4, 4096), "tidepath";
    }
}

crate::params! {
    /// acopf2016's improved ant colony's parameters (`acopf`).
    pub struct AcopfParams {
        /// Iterations T when the run sets no iteration limit (`--iterations` or `[planner]
        /// iterations` win).
        iterations: usize = 60, Range::integer(1, 1_000_000), "acopf2016";
        /// Ants K per iteration.
        ants: usize = 30, Range::integer(1, 100_000), "acopf2016";
        /// Evaporation ρ (it also scales the deposit, eq. 11).
        rho: f64 = 0.85, Range::closed(0.0, 1.0), "acopf2016";
        /// Pheromone intensity Q.
        q: f64 = 6.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e6) }, "acopf2016";
        /// Pheromone exponent α.
        alpha: f64 = 1.0, Range::closed(0.0, 10.0), "tidepath (chosen)";
        /// Heuristic exponent β.
        beta: f64 = 5.0, Range::closed(0.0, 20.0), "tidepath (chosen)";
        /// Initial pheromone τ_0.
        tau0: f64 = 1.0, Range::closed(TAU_MIN, TAU_MAX), "tidepath (chosen)";
        /// Attraction gain ξ (eq. 8).
        xi: f64 = 1.0, Range::closed(0.0, 1e3), "tidepath (chosen)";
        /// Repulsion gain μ (eq. 8).
        mu: f64 = 10.0, Range::closed(0.0, 1e6), "tidepath (chosen)";
        /// Range of the repulsion L_0 (cells, eq. 8).
        l0: f64 = 2.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(50.0) }, "tidepath (chosen)";
        /// Weight ς of the potential-field factor (eq. 10; the paper's range).
        varsigma: f64 = 1.0, Range::closed(0.5, 1.5), "tidepath (chosen)";
        /// Weight σ of the distance factor (eq. 10; the paper's range).
        sigma: f64 = 1.0, Range::closed(0.5, 1.5), "tidepath (chosen)";
        /// Weight ω of the environment factor (eq. 10; the paper's range).
        omega: f64 = 1.0, Range::closed(0.5, 1.5), "tidepath (chosen)";
        /// Wave coefficient a (eq. 10).
        a: f64 = 0.3, Range::closed(-10.0, 10.0), "acopf2016";
        /// Current coefficient b (eq. 10).
        b: f64 = 0.7, Range::closed(-10.0, 10.0), "acopf2016";
        /// Attraction magnitude: "printed" ξ (L_g + 1/L_g) or "khatib" ξ L_g (eq. 8).
        attraction: Attraction = Attraction::Printed, Range::Choice(&["printed", "khatib"]), "acopf2016 (printed); Khatib 1986";
        /// Ants never enter a cell they could not leave (one step of lookahead; tidepath's,
        /// see the module's readings); false: the paper's ants.
        lookahead: bool = true, Range::Flag, "tidepath (chosen)";
        /// What a move costs: the scenario's cost model, or length or time alone.
        objective: Objective = Objective::Cost, Range::Choice(&["cost", "length", "time"]), "tidepath";
        /// Cell size (m); absent: from `cells`.
        cell: Option<f64> = None, Range::Number { lo: Bound::Open(0.0), hi: Bound::Closed(1e7) }, "tidepath";
        /// Cells along the domain's longer side when `cell` is absent; absent: a cell map's own
        /// cells, else 200.
        cells: Option<usize> = None, Range::integer(4, 4096), "tidepath";
    }
}

/// The settings both colonies run on; `field` is `Some` for acopf.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    pub iterations: usize,
    pub ants: usize,
    pub rho: f64,
    pub q: f64,
    pub alpha: f64,
    pub beta: f64,
    pub tau0: f64,
    pub lookahead: bool,
    pub objective: Objective,
    pub cell: Option<f64>,
    pub cells: Option<usize>,
    pub field: Option<Field>,
}

/// An ant colony: `aco` or, with a potential field, `acopf`.
pub struct AntColony {
    id: &'static str,
    s: Settings,
}

impl AntColony {
    pub fn aco(p: Checked<AcoParams>) -> Self {
        let p = p.into_inner();
        let s = Settings {
            iterations: p.iterations,
            ants: p.ants,
            rho: p.rho,
            q: p.q,
            alpha: p.alpha,
            beta: p.beta,
            tau0: p.tau0,
            lookahead: p.lookahead,
            objective: p.objective,
            cell: p.cell,
            cells: p.cells,
            field: None,
        };
        Self { id: "aco", s }
    }

    pub fn acopf(p: Checked<AcopfParams>) -> Self {
        let p = p.into_inner();
        let field = Field {
            xi: p.xi,
            mu: p.mu,
            l0: p.l0,
            varsigma: p.varsigma,
            sigma: p.sigma,
            omega: p.omega,
            a: p.a,
            b: p.b,
            attraction: p.attraction,
        };
        let s = Settings {
            iterations: p.iterations,
            ants: p.ants,
            rho: p.rho,
            q: p.q,
            alpha: p.alpha,
            beta: p.beta,
            tau0: p.tau0,
            lookahead: p.lookahead,
            objective: p.objective,
            cell: p.cell,
            cells: p.cells,
            field: Some(field),
        };
        Self { id: "acopf", s }
    }

    /// Whether this is acopf2016's improved colony.
    pub fn improved(&self) -> bool {
        self.s.field.is_some()
    }

    /// The raster's cell size in `world`: the parameter, a cell map's own cells, or the longer
    /// side over `cells` (as the grid planners).
    fn cell_size(&self, world: &World) -> f64 {
        let b = &world.bounds;
        let size = b.size();
        let map_cell = match &world.terrain {
            Terrain::Cells(c)
                if self.s.cells.is_none()
                    && c.dx == c.dy
                    && size.x.max(size.y) / c.dx <= 1000.0
                    && c.x0 == b.min.x
                    && c.y0 == b.min.y =>
            {
                Some(c.dx)
            }
            _ => None,
        };
        let cells = self.s.cells.unwrap_or(200);
        self.s.cell.unwrap_or_else(|| map_cell.unwrap_or(size.x.max(size.y) / cells as f64))
    }
}

/// The iteration (from 1) at which a history of best costs first reached its final value;
/// `None` when it never held a finite cost.
pub fn iterations_to_converge(history: &[f64]) -> Option<usize> {
    let last = *history.last()?;
    if !last.is_finite() {
        return None;
    }
    history.iter().position(|&h| h == last).map(|k| k + 1)
}

impl Planner for AntColony {
    fn id(&self) -> &'static str {
        self.id
    }

    fn check(&self, problem: &Problem<'_>) -> Result<()> {
        if problem.world.dims != Dims::Two {
            return Err(Error::input("planner", format!("{} plans 2-D worlds only (world.dimensions = 2)", self.id)));
        }
        let field = format!("planner.params.{}", self.id);
        for m in problem.missions {
            let (nx, ny, _) =
                Raster::shape(problem.world, &m.vehicle, self.cell_size(problem.world), 1.0).map_err(|e| match e {
                    Error::Input { message, .. } => Error::input(field.clone(), message),
                    other => other,
                })?;
            if nx * ny > MAX_CELLS {
                return Err(Error::input(
                    field,
                    format!("{nx} x {ny} cells exceed the ant colony's limit of {MAX_CELLS}; use coarser cells"),
                ));
            }
        }
        Ok(())
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
        let n = problem.missions.len();
        let total = termination.max_iterations.unwrap_or(self.s.iterations as u64);
        let mut out = PlannerOutput::default();
        let mut no_route = vec![None; n];
        let mut earlier = 0.0;
        for (i, no_route) in no_route.iter_mut().enumerate() {
            let (iterations, share) = mission_budget(termination, total, out.stats.iterations, i, n);
            let steps = termination.max_expansions.map(|m| m.saturating_sub(out.stats.expansions));
            let init = options.init.and_then(|p| p.get(i)).map(Vec::as_slice);
            let budget = run::Budget { termination: &share, iterations, steps, target: termination.target_cost };
            let mut report = |o: &PlannerOutput, best: f64| {
                let used = Usage { iterations: o.stats.iterations, expansions: o.stats.expansions, ..Usage::default() };
                observer(&Progress {
                    iteration: o.stats.iterations,
                    evaluations: 0,
                    best_cost: earlier + best,
                    elapsed: watch.elapsed(),
                    fraction: watch.fraction(used),
                });
            };
            let r = run::mission(self, problem, i, &budget, init, rng, &mut out, earlier, &mut report);
            earlier += r.best;
            out.stats.stop_reason = r.stopped.unwrap_or(StopReason::MaxIterations);
            *no_route = r.no_route;
            out.paths.push(r.path);
        }
        out.stats.elapsed = watch.elapsed();
        out.claim = no_route.iter().any(Option::is_some).then_some(Claim::NoRoute(no_route));
        out
    }
}

/// Seeds τ = τ_max on the graph's edges between the cells `path` passes through (sampled at a
/// quarter cell, at most a few samples per cell of the domain per segment); returns the
/// number of edges seeded.
fn seed_pheromone(g: &Graph, tau: &mut [f64], path: &[Vec3]) -> usize {
    let step = 0.25 * g.dx.min(g.dy);
    let cap = 8 * (g.nx + g.ny);
    let mut prev: Option<usize> = None;
    let mut seeded = 0;
    for w in path.windows(2) {
        let len = w[0].truncate().distance(w[1].truncate());
        let n = ((len / step).ceil() as usize).clamp(1, cap);
        for k in 0..=n {
            let c = g.cell_of(w[0].lerp(w[1], k as f64 / n as f64));
            if let Some(a) = prev.filter(|&a| a != c) {
                if let Some(d) = g.direction(a, c) {
                    tau[8 * a + d] = TAU_MAX;
                    seeded += 1;
                }
            }
            prev = Some(c);
        }
    }
    seeded
}
