//! Planning and evaluating on a scenario: the entry points the CLI and the experiment runner
//! share, so `plan`, `eval` and `compare` report the same numbers.

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use super::Scenario;
use crate::{PlanAbout, PlanReport};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::optim::Progress;
use tidepath::planner::Unit;
use tidepath::planner::{self, registry::BuildPlanner, MissionPlan, RunOptions, SolveOptions};
use tidepath::registry::Entry;
use tidepath::registry::Registry;
use tidepath::rng::run_rng;
use tidepath::smoothing::{build_smoother_with, BuildSmoother};
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
    pub expansions: Option<u64>,
    pub samples: Option<u64>,
    /// Stop once the best cost is at most this.
    pub target_cost: Option<f64>,
    pub population: Option<usize>,
    pub time_limit_s: Option<f64>,
    /// Evaluate populations on the rayon pool (results are identical either way).
    pub parallel: bool,
    /// Smoother id; `None` uses the scenario's `[planner] smoother`, `Some("none")` disables it.
    pub smoother: Option<String>,
    /// The smoother's parameters (`--smooth ID:KEY=VALUE,...`); `None`: the scenario's
    /// `[planner.smoother_params.ID]`, else its defaults.
    pub smoother_params: Option<toml::Table>,
    /// A path per mission to start from (`plan --init`).
    pub init: Option<Vec<Vec<Vec3>>>,
    /// Raised by the caller to stop the run (Ctrl-C).
    pub stop: Option<Arc<AtomicBool>>,
    /// Keep the planner's search graph (tree or roadmap) in the report (`plan --graph`).
    pub record_graph: bool,
    /// How a fleet is planned (`plan --fleet sequential`).
    pub fleet: tidepath::planner::FleetMode,
}

/// The component tables a plan draws on: the built-in planners and smoothers by default; a
/// program or a test extends them with its own.
#[derive(Clone, Debug)]
pub struct Components {
    pub planners: Registry<BuildPlanner>,
    pub smoothers: Registry<BuildSmoother>,
}

impl Default for Components {
    fn default() -> Self {
        Self { planners: planner::registry(), smoothers: tidepath::smoothing::registry() }
    }
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
    /// The termination for a request: limits given on the command line win; with none given,
    /// the scenario's; with no wall time anywhere, the default cap. Every value is checked and
    /// an error names the flag or field it came from. `counts` keeps only the count limits of
    /// the units a planner counts (all when `None`): a scenario's `iterations` is a default
    /// for whichever planner runs, and means nothing to one that counts expansions.
    pub fn termination(&self, req: &PlanRequest) -> Result<(Termination, LimitSource)> {
        self.termination_for(req, None)
    }

    /// The termination of one run of the planner of table entry `entry`: only the counts it
    /// counts (as a plan of it gets).
    pub(crate) fn termination_for_planner(
        &self,
        req: &PlanRequest,
        entry: &Entry<BuildPlanner>,
    ) -> Result<(Termination, LimitSource)> {
        self.termination_for(req, Some(entry.build.caps.counts))
    }

    fn termination_for(&self, req: &PlanRequest, counts: Option<&[Unit]>) -> Result<(Termination, LimitSource)> {
        let explicit = req.iterations.is_some()
            || req.evaluations.is_some()
            || req.expansions.is_some()
            || req.samples.is_some()
            || req.target_cost.is_some();
        let p = &self.planner;
        let (limits, target, source) = if explicit {
            ([req.iterations, req.evaluations, req.expansions, req.samples], req.target_cost, "--")
        } else {
            ([p.iterations, p.evaluations, p.expansions, p.samples], p.target_cost, "planner.")
        };
        let mut checked = [None; 4];
        for (k, unit) in Unit::ALL.iter().enumerate() {
            if let Some(v) = limits[k] {
                let v = check_count(&format!("{source}{}", unit.name()), v)?;
                if counts.is_none_or(|c| c.contains(unit)) {
                    checked[k] = Some(v);
                }
            }
        }
        if let Some(t) = target {
            if !t.is_finite() {
                let field = if explicit { "--target-cost" } else { "planner.target_cost" };
                return Err(Error::input(field, format!("must be finite, got {t}")));
            }
        }
        let (time, limit_source) = match (req.time_limit_s, p.time_limit_s) {
            (Some(t), _) => (check_wall_time("--time-limit", t)?, LimitSource::CommandLine),
            (None, Some(t)) => (check_wall_time("planner.time_limit_s", t)?, LimitSource::Scenario),
            (None, None) => (check_wall_time("default time limit", default_time_limit_s()?)?, LimitSource::DefaultCap),
        };
        let t = Termination {
            max_iterations: checked[0],
            max_evaluations: checked[1],
            max_expansions: checked[2],
            max_samples: checked[3],
            target_cost: target,
            wall_time: Some(time),
            stop: req.stop.clone(),
            ..Termination::default()
        };
        Ok((t, limit_source))
    }

    /// Refuses, naming the flag, what planner `id` cannot honour: a count in a unit it does not
    /// count, a population it does not have, a warm start it does not use, a world it does not
    /// plan in, a search graph it does not build (the planners of `planners` that do are
    /// named).
    fn check_capabilities(
        &self,
        planners: &Registry<BuildPlanner>,
        entry: &Entry<BuildPlanner>,
        req: &PlanRequest,
    ) -> Result<()> {
        let caps = &entry.build.caps;
        let id = entry.id;
        let flags = [req.iterations, req.evaluations, req.expansions, req.samples];
        for (unit, v) in Unit::ALL.iter().zip(flags) {
            if v.is_some() && !caps.counts_unit(*unit) {
                let hint = match caps.counts.first() {
                    Some(u) => format!("; use --{}", u.name()),
                    None => "; it runs to completion (use --time-limit to bound it)".into(),
                };
                return Err(Error::input(
                    format!("--{}", unit.name()),
                    format!("{id} counts {}{hint}", caps.counts_text()),
                ));
            }
        }
        if req.target_cost.is_some() && caps.counts.is_empty() {
            return Err(Error::input(
                "--target-cost",
                format!("{id} runs to completion; a target cost cannot stop it"),
            ));
        }
        if req.population.is_some() && !entry.has_param("population") {
            return Err(Error::input("--population", format!("{id} has no population")));
        }
        if req.init.is_some() && !caps.warm_start {
            return Err(Error::input("--init", format!("{id} takes no warm start")));
        }
        if req.record_graph && !caps.graph {
            let builders: Vec<&str> = planners.entries().iter().filter(|e| e.build.caps.graph).map(|e| e.id).collect();
            let which = if builders.is_empty() {
                "and no planner of this build does".to_string()
            } else {
                format!("planners that do: {}", builders.join(", "))
            };
            return Err(Error::input("--graph", format!("{id} builds no search graph; {which}")));
        }
        if !caps.dimensions.covers(self.world.dims) {
            return Err(Error::input("planner", format!("{id} plans 2-D worlds only; use theta-star or hybrid")));
        }
        Ok(())
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
        self.check_request_in(&Components { planners: planners.clone(), ..Components::default() }, req)
    }

    /// [`Scenario::check_request`] against the component tables `c`.
    pub fn check_request_in(&self, c: &Components, req: &PlanRequest) -> Result<()> {
        let prepared = self.prepare(c, req)?;
        let problem = self.problem(prepared.cost.as_ref());
        prepared.planner.check(&problem)?;
        if req.fleet == tidepath::planner::FleetMode::Sequential && self.missions.len() > 1 {
            // Planned one after another, each vehicle meets the earlier ones as obstacles that
            // move (and exist only while they fly a leg): the planner must take such a world.
            let mut world = self.world.clone();
            let shape = tidepath::world::Shape::Sphere { center: world.bounds.min, radius: 1e-3 };
            world.obstacles.push(tidepath::world::Obstacle { shape, velocity: Vec3::ZERO, window: Some((0.0, 0.0)) });
            let probe = tidepath::planner::Problem { world: &world, ..problem };
            prepared.planner.check(&probe).map_err(|e| {
                Error::input(
                    "--fleet",
                    format!("sequential: the vehicles planned first are moving obstacles for the next, and {e}"),
                )
            })?;
        }
        Ok(())
    }

    /// Everything a run needs, built and checked.
    fn prepare(&self, c: &Components, req: &PlanRequest) -> Result<Prepared> {
        let planners = &c.planners;
        let id = req.planner.clone().unwrap_or_else(|| self.planner.id.clone());
        let entry = *planners.get(&id)?;
        self.check_capabilities(planners, &entry, req)?;
        // The scenario's population is a default for planners that have one.
        let population = req.population.or(self.planner.population.filter(|_| entry.has_param("population")));
        let planner = planners.build(&id, self.planner.params.get(&id), population, &self.encoding)?;
        let (termination, limit_source) = self.termination_for(req, Some(entry.build.caps.counts))?;
        let cost = self.cost_model()?;
        let smoother = match req.smoother.as_deref().or(self.planner.smoother.as_deref()) {
            None | Some("none") => None,
            Some(sid) => {
                let params = req.smoother_params.as_ref().or(self.planner.smoother_params.get(sid));
                Some(build_smoother_with(&c.smoothers, sid, params)?)
            }
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
        self.plan_in(&Components { planners: planners.clone(), ..Components::default() }, req, observer)
    }

    /// Runs one plan with the planner and smoother tables `c` (the built-in ones, possibly
    /// extended).
    pub fn plan_in(
        &self,
        c: &Components,
        req: &PlanRequest,
        observer: &mut dyn FnMut(&Progress),
    ) -> Result<PlanReport> {
        let Prepared { mut planner, termination, limit_source, cost, smoother } = self.prepare(c, req)?;
        let problem = self.problem(cost.as_ref());
        let options = SolveOptions {
            run: RunOptions { init: req.init.as_deref(), parallel: req.parallel, record_graph: req.record_graph },
            smoother: smoother.as_deref(),
            fleet: req.fleet,
        };
        let mut rng = run_rng(req.seed, req.run);
        let plan = planner::solve(planner.as_mut(), &problem, &termination, &mut rng, options, observer)?;
        let about = PlanAbout {
            seed: req.seed,
            scenario: self.name.clone(),
            scenario_source: self.source.clone(),
            cost_model: cost.id().to_string(),
            // A wave glider's clock is its speed regression, whatever `[model] travel` says.
            travel_time_model: if self.missions.iter().all(|m| m.vehicle.glider().is_some()) {
                "wave-glider".to_string()
            } else {
                self.settings.travel.id().to_string()
            },
            time_limit_s: termination.wall_time.map(|d| d.as_secs_f64()),
            default_time_cap: limit_source == LimitSource::DefaultCap,
            warm_start: req.init.is_some(),
            model_rule_below: cost.feasible_below(),
        };
        let mut report = PlanReport::new(&plan, about).with_frame(self.frame.as_ref(), self.epoch);
        let names: Vec<String> = plan.missions.iter().map(|m| m.name.clone()).collect();
        report.fleet = plan.fleet.as_ref().map(|c| crate::FleetReport::new(c, &self.fleet, &names));
        Ok(report)
    }

    /// Judges one path per mission (start and goal included).
    pub fn evaluate_paths(&self, paths: &[Vec<Vec3>]) -> Result<Vec<MissionPlan>> {
        self.evaluate_routes(paths, &[])
    }

    /// [`Scenario::evaluate_paths`] with each path's segment speeds where given (`speeds[i]`
    /// for path i; missing or `None`: the cruise speed). A speed outside the vehicle's speed
    /// range, or any speed for a vehicle without one other than its cruise speed, is bad
    /// input naming the mission and segment.
    pub fn evaluate_routes(&self, paths: &[Vec<Vec3>], speeds: &[Option<Vec<f64>>]) -> Result<Vec<MissionPlan>> {
        for (i, s) in speeds.iter().enumerate() {
            let (Some(s), Some(m)) = (s, self.missions.get(i)) else { continue };
            let veh = &m.vehicle;
            let (lo, hi) = veh.speed_range.unwrap_or((veh.speed, veh.speed));
            if let Some((k, v)) = s.iter().enumerate().find(|(_, v)| !(lo..=hi).contains(*v)) {
                let field = if self.missions.len() == 1 {
                    format!("speeds[{k}]")
                } else {
                    format!("missions[{i}].speeds[{k}]")
                };
                let range = match veh.speed_range {
                    Some(_) => format!("the vehicle's speed range [{lo}, {hi}] m/s"),
                    None => format!("the vehicle's speed {lo} m/s (it has no speed_min/speed_max)"),
                };
                return Err(Error::input(field, format!("{v} m/s is outside {range}")));
            }
        }
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
            pieces += model.pieces_to_judge(p);
        }
        if pieces > MAX_EVAL_PIECES {
            return Err(Error::input(
                "plan",
                format!(
                    "judging these paths means flying {pieces} pieces of model.current_step = {} m, more than the limit of {MAX_EVAL_PIECES}: use fewer or shorter segments (or, with a turning radius, a larger model.arc_tolerance)",
                    self.settings.current_step
                ),
            ));
        }
        let models: Vec<_> = (0..paths.len()).map(|i| self.mission_model(i)).collect();
        let mut missions: Vec<MissionPlan> = paths
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let given = speeds.get(i).and_then(|s| s.as_deref());
                // A vehicle with a range flies a route without speeds at its cruise speed.
                let cruise = self.missions[i]
                    .vehicle
                    .speed_range
                    .map(|_| vec![self.missions[i].vehicle.speed; p.len().saturating_sub(1)]);
                let model = models[i].with_speeds(given.or(cruise.as_deref()));
                planner::solve::judge(&model, cost.as_ref(), p, &self.missions[i].name)
            })
            .collect();
        planner::judge_fleet(&models, &mut missions, &self.fleet);
        Ok(missions)
    }

    /// The fleet's verdict on `missions` (their final paths): the closest pair and every
    /// separation conflict, `None` when the scenario keeps no separation.
    pub fn fleet_check(&self, missions: &[MissionPlan]) -> Option<tidepath::fleet::FleetCheck> {
        if !self.fleet.active(missions.len()) {
            return None;
        }
        let models: Vec<_> = (0..missions.len()).map(|i| self.mission_model(i)).collect();
        // Each vehicle at its plan's own segment speeds.
        let flown: Vec<_> = models.iter().zip(missions).map(|(m, p)| m.with_speeds(p.speeds.as_deref())).collect();
        let paths: Vec<&[Vec3]> = missions.iter().map(|m| m.path()).collect();
        Some(tidepath::fleet::check(&flown, &paths, &self.fleet, &mut Vec::new()))
    }

    /// Judges a path of the first mission.
    pub fn evaluate(&self, points: &[Vec3]) -> Result<MissionPlan> {
        let cost = self.cost_model()?;
        Ok(planner::solve::judge(&self.path_model(), cost.as_ref(), points, &self.missions[0].name))
    }
}
