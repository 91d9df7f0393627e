//! Planning and evaluating on a scenario: the entry points the CLI and the experiment runner
//! share, so `plan`, `eval` and `compare` report the same numbers.

use std::time::Duration;

use super::Scenario;
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::io::PlanReport;
use crate::optim::{Budget, Progress};
use crate::path::{Metrics, Violation};
use crate::planner::{build_planner, Problem};
use crate::rng::run_rng;
use crate::smoothing::build_smoother;

/// How to run one plan; `None` fields fall back to the scenario's `[planner]` section.
#[derive(Clone, Debug, Default)]
pub struct PlanRequest {
    pub planner: Option<String>,
    pub seed: u64,
    /// Run index: run i of a seed uses its own random stream.
    pub run: u64,
    pub iterations: Option<u64>,
    pub evaluations: Option<u64>,
    pub population: Option<usize>,
    pub time_limit_s: Option<f64>,
    /// Evaluate populations on the rayon pool (results are identical either way).
    pub parallel: bool,
    /// Smoother id; `None` uses the scenario's `[planner] smoother`, `Some("none")` disables it.
    pub smoother: Option<String>,
}

/// A path judged against the scenario.
#[derive(Clone, Debug)]
pub struct Evaluation {
    pub cost: f64,
    pub terms: Vec<(&'static str, f64)>,
    pub feasible: bool,
    pub violations: Vec<Violation>,
    pub metrics: Metrics,
}

impl Scenario {
    /// The budget for a request: explicit limits win; with none given, the scenario's.
    pub fn budget(&self, req: &PlanRequest) -> Result<Budget> {
        let explicit = req.iterations.is_some() || req.evaluations.is_some();
        let (iters, evals) = if explicit {
            (req.iterations, req.evaluations)
        } else {
            (self.planner.iterations, self.planner.evaluations)
        };
        let (time, time_field) = match req.time_limit_s {
            Some(t) => (Some(t), "--time-limit"),
            None => (self.planner.time_limit_s, "planner.time_limit_s"),
        };
        let time = match time {
            None => None,
            Some(t) if t > 0.0 && t.is_finite() => Some(Duration::from_secs_f64(t)),
            Some(t) => return Err(Error::input(time_field, format!("must be positive and finite, got {t}"))),
        };
        let source = if explicit { "--" } else { "planner." };
        if iters == Some(0) {
            return Err(Error::input(format!("{source}iterations"), "must be at least 1, got 0"));
        }
        if evals == Some(0) {
            return Err(Error::input(format!("{source}evaluations"), "must be at least 1, got 0"));
        }
        Ok(Budget { max_iterations: iters, max_evaluations: evals, max_time: time })
    }

    /// Runs one plan and judges the result.
    pub fn plan(&self, req: &PlanRequest, observer: &mut dyn FnMut(&Progress)) -> Result<PlanReport> {
        let id = req.planner.clone().unwrap_or_else(|| self.planner.id.clone());
        let population = req.population.or(self.planner.population);
        let mut planner = build_planner(&id, self.planner.params.get(&id), population)?;
        let budget = self.budget(req)?;
        let cost = self.cost_model()?;
        let encoding = self.build_encoding()?;
        let problem = Problem {
            model: self.path_model(),
            cost: cost.as_ref(),
            encoding: encoding.as_ref(),
            start: self.start,
            goal: self.goal,
        };
        let smoother = match req.smoother.as_deref().or(self.planner.smoother.as_deref()) {
            None | Some("none") => None,
            Some(id) => Some(build_smoother(id)?),
        };
        let outcome = planner.plan(&problem, &budget, run_rng(req.seed, req.run), req.parallel, observer);
        let smoothed = smoother.map(|s| s.smooth(&problem.model, cost.as_ref(), &outcome.waypoints));
        let raw_cost = smoothed.as_ref().map(|_| outcome.cost);
        let eval = self.evaluate(smoothed.as_deref().unwrap_or(&outcome.waypoints))?;
        Ok(PlanReport {
            tidepath_version: env!("CARGO_PKG_VERSION").to_string(),
            planner: id,
            seed: req.seed,
            scenario: self.name.clone(),
            scenario_source: self.source.clone(),
            cost_model: cost.id().to_string(),
            travel_time_model: self.settings.travel.id().to_string(),
            waypoints: outcome.waypoints.iter().map(|p| p.to_array()).collect(),
            smoothed: smoothed.map(|p| p.iter().map(|q| q.to_array()).collect()),
            raw_cost,
            cost: eval.cost,
            cost_terms: eval.terms.iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect(),
            feasible: eval.feasible,
            violations: eval.violations,
            metrics: eval.metrics,
            evaluations: outcome.evaluations,
            iterations: outcome.iterations,
            stop_reason: outcome.stop_reason,
            elapsed_s: outcome.elapsed.as_secs_f64(),
            history: outcome.history.iter().map(|h| h.is_finite().then_some(*h)).collect(),
        })
    }

    /// Cost, terms, feasibility and metrics of a path (start and goal included).
    pub fn evaluate(&self, points: &[Vec3]) -> Result<Evaluation> {
        let cost = self.cost_model()?;
        let model = self.path_model();
        let (total, terms) = cost.breakdown(&model, points);
        let violations = model.violations(points);
        Ok(Evaluation {
            cost: total,
            terms,
            feasible: violations.is_empty(),
            violations,
            metrics: model.metrics(points),
        })
    }
}
