//! Simulations on a scenario (`tidepath simulate`): the mission loop of
//! [`tidepath::simulate`] run with the scenario's world, changes (`[[changes]]`), loop
//! settings (`[simulate]`), planner and limits, and the simulation file it writes.
//!
//! The limits of a plan apply to each re-plan (counts, `--time-limit`); the whole loop has
//! its own wall-time limit and the stop flag (Ctrl-C), which it polls between phases and
//! hands to every planner call.

mod json;
#[cfg(test)]
mod tests;

pub use json::{accept_id, policy_id, simulation_json, SIMULATION_FORMAT_VERSION};

use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Duration;

use crate::scenario::{default_time_limit_s, PlanRequest, Scenario};
use tidepath::error::{Error, Result};
use tidepath::planner;
use tidepath::rng::run_rng;
use tidepath::simulate::{simulate, Acceptance, Growth, ReplanPolicy, Setup, SimParams, Simulation};
use tidepath::termination::check_wall_time;

/// How to run one simulation; `None` fields fall back to the scenario (`[planner]`,
/// `[simulate]`).
#[derive(Clone, Debug, Default)]
pub struct SimRequest {
    pub planner: Option<String>,
    pub seed: u64,
    /// Limits of each re-plan (as `plan` takes them).
    pub iterations: Option<u64>,
    pub evaluations: Option<u64>,
    pub expansions: Option<u64>,
    pub samples: Option<u64>,
    pub population: Option<usize>,
    /// Wall time of each re-plan (s).
    pub time_limit_s: Option<f64>,
    /// Wall time of the whole simulation (s); the default cap when `None`.
    pub total_time_limit_s: Option<f64>,
    pub window: Option<usize>,
    pub growth: Option<Growth>,
    pub policy: Option<ReplanPolicy>,
    pub sensor_range: Option<f64>,
    pub warm_start: Option<bool>,
    /// What makes a window good enough (default: the scenario's `[simulate] accept`).
    pub accept: Option<Acceptance>,
    /// Evaluate populations on the rayon pool (results are identical either way).
    pub parallel: bool,
    pub stop: Option<Arc<AtomicBool>>,
}

/// A simulation with what it ran on.
#[derive(Clone, Debug)]
pub struct SimReport {
    pub planner: String,
    pub seed: u64,
    pub params: SimParams,
    /// Wall-time limits (s) of each re-plan and of the whole loop.
    pub replan_time_limit_s: Option<f64>,
    pub total_time_limit_s: f64,
    pub sim: Simulation,
    /// Wall time of the whole loop (s).
    pub elapsed_s: f64,
}

impl SimReport {
    /// Whether Ctrl-C (or the total time limit) ended the loop before its outcome.
    pub fn interrupted(&self) -> bool {
        !self.sim.complete
    }
}

/// Most waypoints a window may reach ahead: far more than any route has.
pub const MAX_WINDOW: usize = 1 << 20;

impl Scenario {
    /// The loop settings: the scenario's `[simulate]` with the request's overrides, checked.
    pub fn sim_params(&self, req: &SimRequest) -> Result<SimParams> {
        let mut p = self.simulate;
        if let Some(w) = req.window {
            p.window = w;
        }
        if let Some(g) = req.growth {
            p.growth = g;
        }
        if let Some(policy) = req.policy {
            p.policy = policy;
        }
        if let Some(r) = req.sensor_range {
            p.sensor_range = Some(r);
        }
        if let Some(w) = req.warm_start {
            p.warm_start = w;
        }
        if let Some(a) = req.accept {
            p.accept = a;
        }
        if !(1..=MAX_WINDOW).contains(&p.window) {
            return Err(Error::input(
                "--window",
                format!("must be from 1 to {MAX_WINDOW} waypoints, got {}", p.window),
            ));
        }
        if let Growth::Add(n) = p.growth {
            if !(1..=MAX_WINDOW).contains(&n) {
                return Err(Error::input("--growth", format!("must add 1 to {MAX_WINDOW} waypoints, got {n}")));
            }
        }
        if let Some(r) = p.sensor_range {
            if !(r.is_finite() && r > 0.0) {
                return Err(Error::input("--sensor-range", format!("must be finite and > 0 m, got {r}")));
            }
        }
        Ok(p)
    }

    /// The request as a plan request: what each re-plan is.
    fn replan_request(&self, req: &SimRequest) -> PlanRequest {
        PlanRequest {
            planner: req.planner.clone(),
            seed: req.seed,
            iterations: req.iterations,
            evaluations: req.evaluations,
            expansions: req.expansions,
            samples: req.samples,
            population: req.population,
            time_limit_s: req.time_limit_s,
            parallel: req.parallel,
            stop: req.stop.clone(),
            ..PlanRequest::default()
        }
    }

    /// Checks a request without running it: the planner and its limits, the loop settings,
    /// the scenario (one mission).
    pub fn check_sim_request(&self, req: &SimRequest) -> Result<()> {
        if self.missions.len() != 1 {
            return Err(Error::input(
                "SCENARIO",
                format!(
                    "simulate flies one mission; this scenario has {} (fleets are planned with `plan`)",
                    self.missions.len()
                ),
            ));
        }
        if let Some((lo, hi)) = self.missions[0].vehicle.speed_range {
            return Err(Error::input(
                "vehicle.speed_min",
                format!(
                    "simulate flies every segment at the cruise speed; a speed range ([{lo}, {hi}] m/s) is for `plan` and `eval` (remove speed_min and speed_max to simulate)"
                ),
            ));
        }
        self.sim_params(req)?;
        if let Some(t) = req.total_time_limit_s {
            check_wall_time("--total-time-limit", t)?;
        }
        self.check_request(&self.replan_request(req))
    }

    /// Runs the mission loop.
    pub fn simulate(&self, req: &SimRequest) -> Result<SimReport> {
        self.check_sim_request(req)?;
        let params = self.sim_params(req)?;
        let plan_req = self.replan_request(req);
        let id = plan_req.planner.clone().unwrap_or_else(|| self.planner.id.clone());
        let registry = planner::registry();
        let entry = *registry.get(&id)?;
        let (per_replan, _) = self.termination_for_planner(&plan_req, &entry)?;
        let total_s = match req.total_time_limit_s {
            Some(t) => check_wall_time("--total-time-limit", t)?.as_secs_f64(),
            None => default_time_limit_s()?,
        };
        let mut total = tidepath::termination::Termination::default().with_wall_time(Duration::from_secs_f64(total_s));
        total.stop = req.stop.clone();
        let population = req.population.or(self.planner.population.filter(|_| entry.has_param("population")));
        let params_table = self.planner.params.get(&id);
        let make = || registry.build(&id, params_table, population, &self.encoding);
        let cost = self.cost_model()?;
        let setup = Setup {
            world: &self.world,
            mission: &self.missions[0],
            changes: &self.changes,
            planner: &make,
            cost: cost.as_ref(),
            settings: &self.settings,
            params,
            per_replan: &per_replan,
            total: &total,
        };
        let clock = std::time::Instant::now();
        let sim = simulate(&setup, &mut run_rng(req.seed, 0))?;
        Ok(SimReport {
            planner: id,
            seed: req.seed,
            params,
            replan_time_limit_s: per_replan.wall_time.map(|d| d.as_secs_f64()),
            total_time_limit_s: total_s,
            sim,
            elapsed_s: clock.elapsed().as_secs_f64(),
        })
    }
}
