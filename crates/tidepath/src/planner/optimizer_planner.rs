//! Encoding + cost model + optimizer, run by the shared optimizer runner. The encoding is a
//! setting of this kind of planner, not part of the problem.

use super::{PathObjective, Planner, PlannerOutput, Problem, RunOptions, SearchStats};
use crate::encoding::{self, Encoding, EncodingArgs, EncodingSpec};
use crate::error::Result;
use crate::optim::Objective as _;
use crate::optim::{self, Optimizer, Progress};
use crate::rng::Rng;
use crate::termination::Termination;

pub struct OptimizerPlanner {
    optimizer: Box<dyn Optimizer>,
    encoding: EncodingSpec,
}

impl OptimizerPlanner {
    pub fn new(optimizer: Box<dyn Optimizer>, encoding: EncodingSpec) -> Self {
        Self { optimizer, encoding }
    }

    /// The encoding of every mission of `problem` under this planner's setting.
    pub fn encodings(&self, problem: &Problem<'_>) -> Result<Vec<Box<dyn Encoding>>> {
        let entry = encoding::registry().get(&self.encoding.kind)?.build;
        let posture = self.encoding.posture()?;
        (0..problem.missions.len())
            .map(|i| {
                let m = &problem.missions[i];
                entry(&EncodingArgs {
                    start: m.start,
                    goal: m.goal,
                    waypoints: self.encoding.waypoints,
                    bounds: &problem.world.bounds,
                    z_range: problem.z_range(i),
                    axis: self.encoding.axis,
                    posture,
                })
            })
            .collect()
    }
}

impl OptimizerPlanner {
    /// When a sliced encoding's best path is infeasible and every route here must turn back
    /// along the start-goal axis, say so: no amount of search fixes that encoding.
    /// A hint for a failed sliced encoding: it costs a raster, so it is given only while the
    /// run's clock has time left.
    fn sliced_hint(
        &self,
        problem: &Problem<'_>,
        paths: &[Vec<crate::geom::Vec3>],
        termination: &Termination,
    ) -> Option<super::Claim> {
        if self.encoding.kind != "sliced" || termination.interrupted().is_some() {
            return None;
        }
        for (i, p) in paths.iter().enumerate() {
            let model = problem.path_model(i);
            if p.len() < 2 || model.assess(p, &mut Vec::new()).feasible() {
                continue;
            }
            if super::sliced_hint::must_turn_back(problem, i, self.encoding.axis) {
                let axis = match self.encoding.axis {
                    crate::encoding::SliceAxis::Path => "the start-goal axis",
                    crate::encoding::SliceAxis::X => "x",
                    crate::encoding::SliceAxis::Y => "y",
                };
                return Some(super::Claim::Hint(format!(
                    "the sliced encoding cannot go back along {axis}, and every route here must: use the default planner (hybrid) or [encoding] kind = \"free\""
                )));
            }
        }
        None
    }
}

impl Planner for OptimizerPlanner {
    fn id(&self) -> &'static str {
        self.optimizer.id()
    }

    fn check(&self, problem: &Problem<'_>) -> Result<()> {
        self.encoding.build_repair(self.optimizer.default_repair())?;
        let dim: usize = self.encodings(problem)?.iter().map(|e| e.dim()).sum();
        optim::check_memory(self.optimizer.population(), dim)
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        rng: &mut Rng,
        options: RunOptions<'_>,
        observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        // The encodings were built once when the planner was checked (`solve` does so before
        // planning); a failure here means the problem changed since, and yields no path.
        let Ok(encodings) = self.encodings(problem) else {
            return PlannerOutput {
                paths: vec![Vec::new(); problem.missions.len()],
                speeds: Vec::new(),
                claim: None,
                stats: SearchStats::default(),
                graphs: Vec::new(),
            };
        };
        // Checked with the planner (`check`); a failure here yields no path repair.
        let repair = self.encoding.build_repair(self.optimizer.default_repair()).ok().flatten();
        let objective = PathObjective::new(problem, encodings).with_repair(repair);
        let seeds: Vec<Vec<f64>> = options.init.and_then(|p| objective.encode(p)).into_iter().collect();
        let r = optim::run(self.optimizer.as_mut(), &objective, termination, rng, options.parallel, &seeds, observer);
        let segments = (self.encoding.waypoints as u64 + 1) * problem.missions.len() as u64;
        // No best point when no evaluation gave a number (all NaN): no path, status infeasible.
        let (paths, speeds) = if r.best_x.len() == objective.dim() {
            (objective.decode(&r.best_x), objective.decode_speeds(&r.best_x))
        } else {
            (vec![Vec::new(); problem.missions.len()], Vec::new())
        };
        let claim = self.sliced_hint(problem, &paths, termination);
        PlannerOutput {
            paths,
            speeds,
            claim,
            stats: SearchStats {
                iterations: r.iterations,
                evaluations: r.evaluations,
                // Each evaluation judges every segment of every mission's path.
                motion_checks: r.evaluations * segments,
                history: r.history,
                stop_reason: r.stop_reason,
                elapsed: r.elapsed,
                ..SearchStats::default()
            },
            graphs: Vec::new(),
        }
    }
}
