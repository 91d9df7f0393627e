//! Planning and evaluating on a scenario: the entry points the CLI and the experiment runner
//! share, so `plan`, `eval` and `compare` report the same numbers.

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use super::Scenario;
use crate::{PlanAbout, PlanReport};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::optim::Progress;
use tidepath::planner::{self, registry::BuildPlanner, MissionPlan, RunOptions, SolveOptions};
use tidepath::registry::Registry;
use tidepath::rng::run_rng;
use tidepath::smoothing::build_smoother;
use tidepath::termination::{check_count, check_wall_time, Termination};

/// The wall-time cap (s) every run gets when neither the command line nor the scenario sets a
/// limit, so no command runs forever. `TIDEPATH_DEFAULT_TIME_LIMIT` (seconds) changes it.
pub const DEFAULT_TIME_LIMIT_S: f64 = 600.0;

/// The default cap in force: [`DEFAULT_TIME_LIMIT_S`] or the environment's override.
pub fn default_time_limit_s() -> Result<f64> {
    match std::env::var("TIDEPATH_DEFAULT_TIME_LIMIT") {
        Ok(v) => {
            let s: f64 = v.trim().parse().map_err(|_| {
                Error::input("TIDEPATH_DEFAULT_TIME_LIMIT", format!("'{v}' is not a number of seconds"))
            })?;
            check_wall_time("TIDEPATH_DEFAULT_TIME_LIMIT", s)?;
            Ok(s)
        }
        Err(_) => Ok(DEFAULT_TIME_LIMIT_S),
    }
}

/// Most pieces of current integration one `eval` may fly (each a current lookup): about a
/// second of work. A plan from any planner needs far fewer; only a hostile plan file of
/// long segments in a world with a tiny `model.current_step` comes near.
pub const MAX_EVAL_PIECES: u64 = 20_000_000;

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
    /// A path per mission to start from (`plan --init`).
    pub init: Option<Vec<Vec<Vec3>>>,
    /// Raised by the caller to stop the run (Ctrl-C).
    pub stop: Option<Arc<AtomicBool>>,
}

/// A run's pieces, built from a request.
struct Prepared {
    planner: Box<dyn tidepath::planner::Planner>,
    termination: Termination,
    limit_source: LimitSource,
    cost: Box<dyn tidepath::cost::CostModel>,
    smoother: Option<Box<dyn tidepath::smoothing::Smoother>>,
}

/// Where the wall-time limit of a run came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LimitSource {
    CommandLine,
    Scenario,
    DefaultCap,
}

impl Scenario {
    /// The termination for a request: explicit limits win; with none given, the scenario's;
    /// with no wall time anywhere, the default cap. Every value is checked and an error names
    /// the flag or field it came from.
    pub fn termination(&self, req: &PlanRequest) -> Result<(Termination, LimitSource)> {
        let explicit = req.iterations.is_some() || req.evaluations.is_some();
        let (iters, evals) = if explicit {
            (req.iterations, req.evaluations)
        } else {
            (self.planner.iterations, self.planner.evaluations)
        };
        let source = if explicit { "--" } else { "planner." };
        let count = |name: &str, v: Option<u64>| v.map(|v| check_count(&format!("{source}{name}"), v)).transpose();
        let (time, limit_source) = match (req.time_limit_s, self.planner.time_limit_s) {
            (Some(t), _) => (check_wall_time("--time-limit", t)?, LimitSource::CommandLine),
            (None, Some(t)) => (check_wall_time("planner.time_limit_s", t)?, LimitSource::Scenario),
            (None, None) => (check_wall_time("default time limit", default_time_limit_s()?)?, LimitSource::DefaultCap),
        };
        let mut t = Termination {
            max_iterations: count("iterations", iters)?,
            max_evaluations: count("evaluations", evals)?,
            wall_time: Some(time),
            ..Termination::default()
        };
        t.stop = req.stop.clone();
        Ok((t, limit_source))
    }

    /// Runs one plan with the built-in planners and judges the result.
    pub fn plan(&self, req: &PlanRequest, observer: &mut dyn FnMut(&Progress)) -> Result<PlanReport> {
        self.plan_with(&planner::registry(), req, observer)
    }

    /// Checks a request without planning: the planner id and parameters, the limits, the
    /// smoother, the warm start's size, and whether the planner can take this scenario at all
    /// (e.g. `visibility` needs a 2-D world). Commands call it for every planner they will run
    /// before they start, so a bad flag never costs a run or leaves an output behind.
    pub fn check_request(&self, req: &PlanRequest) -> Result<()> {
        self.check_request_with(&planner::registry(), req)
    }

    /// [`Scenario::check_request`] against `planners`.
    pub fn check_request_with(&self, planners: &Registry<BuildPlanner>, req: &PlanRequest) -> Result<()> {
        let prepared = self.prepare(planners, req)?;
        let problem = self.problem(prepared.cost.as_ref());
        prepared.planner.check(&problem)
    }

    /// Everything a run needs, built and checked.
    fn prepare(&self, planners: &Registry<BuildPlanner>, req: &PlanRequest) -> Result<Prepared> {
        let id = req.planner.clone().unwrap_or_else(|| self.planner.id.clone());
        let population = req.population.or(self.planner.population);
        let planner = planners.build(&id, self.planner.params.get(&id), population, &self.encoding)?;
        let (termination, limit_source) = self.termination(req)?;
        let cost = self.cost_model()?;
        let smoother = match req.smoother.as_deref().or(self.planner.smoother.as_deref()) {
            None | Some("none") => None,
            Some(id) => Some(build_smoother(id)?),
        };
        if let Some(init) = &req.init {
            if init.len() != self.missions.len() {
                return Err(Error::input(
                    "--init",
                    format!(
                        "the plan has {} path(s); this scenario has {} mission(s)",
                        init.len(),
                        self.missions.len()
                    ),
                ));
            }
        }
        Ok(Prepared { planner, termination, limit_source, cost, smoother })
    }

    /// Runs one plan with a planner from `planners` (the built-in table, possibly extended).
    pub fn plan_with(
        &self,
        planners: &Registry<BuildPlanner>,
        req: &PlanRequest,
        observer: &mut dyn FnMut(&Progress),
    ) -> Result<PlanReport> {
        let Prepared { mut planner, termination, limit_source, cost, smoother } = self.prepare(planners, req)?;
        let problem = self.problem(cost.as_ref());
        let options = SolveOptions {
            run: RunOptions { init: req.init.as_deref(), parallel: req.parallel },
            smoother: smoother.as_deref(),
        };
        let mut rng = run_rng(req.seed, req.run);
        let plan = planner::solve(planner.as_mut(), &problem, &termination, &mut rng, options, observer)?;
        let about = PlanAbout {
            seed: req.seed,
            scenario: self.name.clone(),
            scenario_source: self.source.clone(),
            cost_model: cost.id().to_string(),
            travel_time_model: self.settings.travel.id().to_string(),
            time_limit_s: termination.wall_time.map(|d| d.as_secs_f64()),
            default_time_cap: limit_source == LimitSource::DefaultCap,
            warm_start: req.init.is_some(),
        };
        Ok(PlanReport::new(&plan, about).with_frame(self.frame.as_ref(), self.epoch))
    }

    /// Judges one path per mission (start and goal included).
    pub fn evaluate_paths(&self, paths: &[Vec<Vec3>]) -> Result<Vec<MissionPlan>> {
        if paths.len() != self.missions.len() {
            return Err(Error::input(
                "plan",
                format!("the plan has {} path(s); this scenario has {} mission(s)", paths.len(), self.missions.len()),
            ));
        }
        let cost = self.cost_model()?;
        // The work of judging a hostile plan is bounded before it starts.
        let mut pieces = 0u64;
        for (i, p) in paths.iter().enumerate() {
            let model = self.mission_model(i);
            pieces += p.windows(2).map(|w| u64::from(model.validator.pieces_of(w[0].distance(w[1])))).sum::<u64>();
        }
        if pieces > MAX_EVAL_PIECES {
            return Err(Error::input(
                "plan",
                format!(
                    "judging these paths means flying {pieces} pieces of model.current_step = {} m, more than the limit of {MAX_EVAL_PIECES}: use fewer or shorter segments",
                    self.settings.current_step
                ),
            ));
        }
        Ok(paths
            .iter()
            .enumerate()
            .map(|(i, p)| planner::solve::judge(&self.mission_model(i), cost.as_ref(), p, &self.missions[i].name))
            .collect())
    }

    /// Judges a path of the first mission.
    pub fn evaluate(&self, points: &[Vec3]) -> Result<MissionPlan> {
        let cost = self.cost_model()?;
        Ok(planner::solve::judge(&self.path_model(), cost.as_ref(), points, &self.missions[0].name))
    }
}
