//! One run's score as the paper reports it (docs/papers/lfhh2019.md, A6 and A8): the mean F
//! of the paths re-planned at the five changes, a sampling planner's path first resampled at
//! the paper's lines x = 0, 1, ..., 39 km.

use tidepath::cost::CostModel;
use tidepath::geom::Vec3;
use tidepath::mission::Mission;
use tidepath::path::{ModelSettings, PathModel};
use tidepath::scratch::Scratch;
use tidepath::simulate::{Replan, Simulation};
use tidepath::world::World;

use super::paper::NO_PATH_F;

/// The paper's lines (tidepath x, the direction of travel) are this far apart (m).
pub const LINE_SPACING_M: f64 = 1000.0;

/// `points` resampled at the lines x = k * `spacing` strictly between its first and last
/// point's x: the start, one point per line in the direction of travel, the end. Each line's
/// point is where the path, walked from the previous line's point on, first reaches that x
/// (linear along the segment that crosses it); every coordinate is interpolated, so in 3-D
/// the depth follows the path too. `None` for fewer than two points. A path that turns back
/// across a line is read at its first crossing after the previous line's point, which always
/// exists for a continuous path from the first x to the last.
pub fn resample_to_lines(points: &[Vec3], spacing: f64) -> Option<Vec<Vec3>> {
    let (first, last) = (*points.first()?, *points.last()?);
    if points.len() < 2 {
        return None;
    }
    let (x0, x1) = (first.x, last.x);
    let forward = x1 >= x0;
    let (lo, hi) = if forward { (x0, x1) } else { (x1, x0) };
    // Lines strictly inside (lo, hi): a line within a micrometre of an end would give a
    // zero-length segment.
    let tiny = 1e-6;
    let mut lines: Vec<f64> = ((lo / spacing).floor() as i64..=(hi / spacing).ceil() as i64)
        .map(|k| k as f64 * spacing)
        .filter(|&x| x > lo + tiny && x < hi - tiny)
        .collect();
    if !forward {
        lines.reverse();
    }
    let mut out = Vec::with_capacity(lines.len() + 2);
    out.push(first);
    let (mut seg, mut t0) = (0usize, 0.0f64);
    for &x in &lines {
        // The first crossing of x at or after (seg, t0).
        let mut j = seg;
        let found = loop {
            if j + 1 >= points.len() {
                break None;
            }
            let (a, b) = (points[j], points[j + 1]);
            let from = if j == seg { t0 } else { 0.0 };
            let t = if (b.x - a.x).abs() < 1e-12 {
                ((a.x - x).abs() < 1e-12).then_some(from)
            } else {
                Some((x - a.x) / (b.x - a.x))
            };
            match t {
                Some(t) if (from..=1.0).contains(&t) => break Some((j, t)),
                _ => j += 1,
            }
        };
        // None is unreachable for a path from x0 to x1 (it crosses every line in between).
        let (j, t) = found?;
        let (a, b) = (points[j], points[j + 1]);
        let mut p = a + (b - a) * t;
        p.x = x;
        out.push(p);
        (seg, t0) = (j, t);
    }
    out.push(last);
    Some(out)
}

/// The paper's F of `points` flown from `points[0]` at time `t` to its last point on `world`.
pub fn f_of(
    cost: &dyn CostModel,
    world: &World,
    mission: &Mission,
    settings: &ModelSettings,
    points: &[Vec3],
    t: f64,
) -> f64 {
    let (Some(&start), Some(&goal)) = (points.first(), points.last()) else {
        return NO_PATH_F;
    };
    let m = Mission { start, goal, departure_time: t, ..mission.clone() };
    let model = PathModel::new(world, &m, settings);
    cost.cost(&model, points, &mut Scratch::default())
}

/// How the F of a (re-)planned piece is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scoring {
    /// The planner's own cost of its piece (the evolutionary planners, whose waypoints already
    /// lie on planes across x and whose cost is the scenario's F).
    Own,
    /// Resampled at the lines, then F (RRT*, PRM*; A8); F = 5 when no path was found.
    Resampled,
}

/// The F of one (re-)plan made in phase `k` of `sim`.
pub fn replan_f(
    replan: &Replan,
    scoring: Scoring,
    sim: &Simulation,
    k: usize,
    ctx: (&dyn CostModel, &World, &Mission, &ModelSettings),
) -> f64 {
    let found = replan.piece.len() >= 2 && replan.cost.is_finite();
    match scoring {
        Scoring::Own if found => replan.cost,
        Scoring::Own => NO_PATH_F,
        // A sampling planner's piece counts only when it reached the window's target.
        Scoring::Resampled if !(found && replan.status.is_success()) => NO_PATH_F,
        Scoring::Resampled => {
            let (cost, world, mission, settings) = ctx;
            let Some(points) = resample_to_lines(&replan.piece, LINE_SPACING_M) else { return NO_PATH_F };
            let (known, _) = sim.known(world, k);
            f_of(cost, &known, mission, settings, &points, sim.phases[k].time)
        }
    }
}

/// What one simulation scored: the F of the departure plan and of each re-plan at a change.
#[derive(Clone, Debug, PartialEq)]
pub struct RunScore {
    pub departure: f64,
    /// One per change phase that re-planned, in order (5 when the loop ran to the goal).
    pub changes: Vec<f64>,
}

impl RunScore {
    /// A6: the run's F is the mean F of its re-planned paths. A run whose loop stopped early
    /// (no feasible window up to the goal) is averaged over the re-plans it made, the failed
    /// one included; one that stopped at departure scores its departure plan.
    pub fn run_f(&self) -> f64 {
        if self.changes.is_empty() {
            self.departure
        } else {
            self.changes.iter().sum::<f64>() / self.changes.len() as f64
        }
    }

    pub fn of(sim: &Simulation, scoring: Scoring, ctx: (&dyn CostModel, &World, &Mission, &ModelSettings)) -> Self {
        let mut departure = NO_PATH_F;
        let mut changes = Vec::new();
        for (k, phase) in sim.phases.iter().enumerate() {
            let Some(r) = &phase.replan else { continue };
            let f = replan_f(r, scoring, sim, k, ctx);
            if k == 0 {
                departure = f;
            } else {
                changes.push(f);
            }
        }
        RunScore { departure, changes }
    }
}
