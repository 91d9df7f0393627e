//! A toy planner and a toy smoother, each registered the way a new component is: one type, one
//! parameter declaration, one table entry in a registry extended here. Every generic check
//! runs them beside the built-in components, so the promise "a component is a file plus a
//! table entry, and the generic tests then cover it" is itself tested.

use tidepath::geom::Vec3;
use tidepath::optim::Progress;
use tidepath::params::Range;
use tidepath::path::PathModel;
use tidepath::planner::{
    self, BuildPlanner, Capabilities, Dimensions, Fleets, Planner, PlannerOutput, Problem, RunOptions, SearchStats,
};
use tidepath::registry::{Entry, Registry};
use tidepath::rng::Rng;
use tidepath::smoothing::{self, BuildSmoother, Smoother};
use tidepath::termination::{StopReason, Termination, Usage};

tidepath::params! {
    /// The toy planner's parameters.
    pub struct StraightParams {
        /// How far the path's midpoint bends aside, as a fraction of the start-goal distance.
        bend: f64 = 0.0, Range::closed(0.0, 0.5), "test";
    }
}

/// A planner that is not an optimizer: the straight line from start to goal (bent aside by
/// `bend`), each motion judged by the shared validator.
pub struct StraightLine {
    params: StraightParams,
}

impl Planner for StraightLine {
    fn id(&self) -> &'static str {
        "straight"
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
        for i in 0..problem.missions.len() {
            let m = &problem.missions[i];
            let d = m.goal - m.start;
            let side = Vec3::new(-d.y, d.x, 0.0) * self.params.bend;
            let path = if side == Vec3::ZERO {
                vec![m.start, m.goal]
            } else {
                vec![m.start, m.start + d * 0.5 + side, m.goal]
            };
            let model = problem.path_model(i);
            for w in path.windows(2) {
                let _ = model.validator.motion(w[0], w[1], m.departure_time);
                stats.motion_checks += 1;
            }
            paths.push(path);
        }
        stats.stop_reason = watch.stop_reason(Usage::default(), 0.0).unwrap_or(StopReason::Completed);
        stats.elapsed = watch.elapsed();
        PlannerOutput { paths, speeds: Vec::new(), claim: None, stats, graphs: Vec::new() }
    }
}

pub const STRAIGHT: Entry<BuildPlanner> = Entry {
    id: "straight",
    description: "the straight line (bent aside by `bend`), if the validator accepts it",
    citation: "test",
    params: StraightParams::SPECS,
    build: BuildPlanner::direct(
        Capabilities {
            dimensions: Dimensions::Both,
            fleets: Fleets::OneAfterAnother,
            warm_start: false,
            counts: &[],
            optimal: None,
            randomised: false,
            graph: false,
        },
        |s| Ok(Box::new(StraightLine { params: StraightParams::from_table(&s.params, &s.prefix)?.into_inner() })),
    ),
};

tidepath::params! {
    /// The toy smoother's parameters.
    pub struct ThinParams {
        /// Most interior points it may drop.
        max_dropped: usize = 1000, Range::integer(0, 100_000), "test";
    }
}

/// A smoother that drops interior points, one at a time from the end, while that is no costlier
/// and no less feasible: never worse, by construction.
pub struct Thin {
    params: ThinParams,
}

impl Smoother for Thin {
    fn id(&self) -> &'static str {
        "thin"
    }

    fn smooth(
        &self,
        model: &PathModel<'_>,
        cost: &dyn tidepath::cost::CostModel,
        points: &[Vec3],
        termination: &Termination,
    ) -> Vec<Vec3> {
        let mut path = points.to_vec();
        let judge = |p: &[Vec3]| (model.assess(p, &mut Vec::new()).feasible(), cost.breakdown(model, p).0);
        let (mut feasible, mut best) = judge(&path);
        let mut dropped = 0;
        let mut k = path.len().saturating_sub(2);
        while k >= 1 && dropped < self.params.max_dropped && termination.interrupted().is_none() {
            let mut candidate = path.clone();
            candidate.remove(k);
            let (f, c) = judge(&candidate);
            if (f || !feasible) && c <= best {
                (path, feasible, best) = (candidate, f, c);
                dropped += 1;
            }
            k -= 1;
        }
        path
    }
}

pub const THIN: Entry<BuildSmoother> = Entry {
    id: "thin",
    description: "drop interior points from the end while no costlier and no less feasible",
    citation: "test",
    params: ThinParams::SPECS,
    build: |t, prefix| Ok(Box::new(Thin { params: ThinParams::from_table(t, prefix)?.into_inner() })),
};

/// The built-in planners and the toy.
pub fn planners() -> Registry<BuildPlanner> {
    planner::registry().with(STRAIGHT)
}

/// The built-in smoothers and the toy.
pub fn smoothers() -> Registry<BuildSmoother> {
    smoothing::registry().with(THIN)
}
