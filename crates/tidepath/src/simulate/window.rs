//! Re-planning a window of the route ahead (lfhh2019 sections IV-E and IV-F): from the
//! vehicle's position and time to the route point W waypoints ahead, growing W while no
//! feasible piece is found, up to the goal; the piece is spliced into the route.

use std::time::Instant;

use super::{Acceptance, Replan, Setup};
use crate::error::Result;
use crate::geom::Vec3;
use crate::mission::Mission;
use crate::path::PathModel;
use crate::planner::{registry, solve, Problem, RunOptions, SolveOptions, Status};
use crate::rng::Rng;
use crate::termination::Termination;
use crate::world::World;

/// How the window grows after a window with no feasible piece.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Growth {
    /// W <- 2 W: reaches the goal in log2 steps (few planner calls).
    Double,
    /// W <- W + n: lfhh2019's rule with n = 1.
    Add(usize),
}

/// The next window after one of `w` waypoints failed, with `remaining` waypoints left to the
/// goal: `None` once the window already reached the goal (nothing larger to try), else the
/// grown window, never past the goal.
pub fn next_window(w: usize, growth: Growth, remaining: usize) -> Option<usize> {
    if w >= remaining {
        return None;
    }
    let grown = match growth {
        Growth::Double => w.saturating_mul(2),
        Growth::Add(n) => w.saturating_add(n.max(1)),
    };
    Some(grown.min(remaining))
}

/// The route with its first `end` segments replaced by `piece`, whose ends are set exactly to
/// the route's (the vehicle's position and the window's target), so the vehicle never jumps.
pub fn splice(piece: &[Vec3], route: &[Vec3], end: usize) -> Vec<Vec3> {
    let mut out: Vec<Vec3> = piece.to_vec();
    out[0] = route[0];
    *out.last_mut().expect("a piece has two points") = route[end];
    out.extend_from_slice(&route[end + 1..]);
    out
}

/// Whether the built-in table says planner `id` takes warm starts; a planner it does not list
/// (a user's own) runs cold.
pub fn takes_warm_start(id: &str) -> bool {
    registry().find(id).is_some_and(|e| e.build.caps.warm_start)
}

/// The termination of one replan: the per-replan limits, cut to what the total budget has
/// left on its clock, with the total's stop flag when the per-replan one has none.
pub fn replan_budget(per_replan: &Termination, total: &Termination) -> Termination {
    let mut t = per_replan.clone();
    t.started = None;
    if t.stop.is_none() {
        t.stop = total.stop.clone();
    }
    if let Some(deadline) = total.deadline() {
        let left = deadline.saturating_duration_since(Instant::now()).max(std::time::Duration::from_micros(1));
        t.wall_time = Some(t.wall_time.map_or(left, |w| w.min(left)));
    }
    t
}

/// Re-plans a window of `route` (its first point the vehicle's position at `t`) on `known`,
/// growing the window until the spliced route is feasible to the goal (or, with
/// [`Acceptance::Window`], until the window's piece is). Returns the replan
/// record and, when it succeeded, the new route. `warm_allowed` is false for the departure
/// plan (there is no old route to start from).
pub(super) fn replan(
    s: &Setup<'_>,
    known: &World,
    route: &[Vec3],
    t: f64,
    rng: &mut Rng,
    warm_allowed: bool,
) -> Result<(Replan, Option<Vec<Vec3>>)> {
    let remaining = route.len() - 1;
    let mut w = s.params.window.clamp(1, remaining);
    let mut tried = Vec::new();
    loop {
        let budget = replan_budget(s.per_replan, s.total);
        let sub = Mission { start: route[0], goal: route[w], departure_time: t, ..s.mission.clone() };
        let missions = [sub];
        let problem = Problem {
            world: known,
            settings: s.settings,
            cost: s.cost,
            missions: &missions,
            fleet: &crate::fleet::NO_FLEET,
        };
        let mut planner = (s.planner)()?;
        let warm = warm_allowed && s.params.warm_start && takes_warm_start(planner.id());
        let init = [route[..=w].to_vec()];
        let run = RunOptions { init: warm.then_some(&init[..]), ..RunOptions::default() };
        let clock = Instant::now();
        let plan =
            solve(&mut *planner, &problem, &budget, rng, SolveOptions { run, ..SolveOptions::default() }, &mut |_| {})?;
        let planning_s = clock.elapsed().as_secs_f64();
        let m = &plan.missions[0];
        tried.push(w);
        let mut record = Replan {
            windows: tried.clone(),
            target: route[w],
            piece: m.path().to_vec(),
            status: m.status,
            reason: m.reason.clone(),
            cost: m.cost,
            planning_s,
            warm,
            focus: m.focus.clone(),
        };
        let cancelled = m.status == Status::Cancelled;
        if m.status.is_success() {
            let spliced = splice(m.path(), route, w);
            let whole = Mission { start: route[0], goal: s.mission.goal, departure_time: t, ..s.mission.clone() };
            let violations = PathModel::new(known, &whole, s.settings).violations(&spliced);
            match (violations.first(), s.params.accept) {
                (None, _) => return Ok((record, Some(spliced))),
                (Some(v), Acceptance::Window) => {
                    record.reason = format!(
                        "the window's piece is feasible (accepted: the window is judged alone); the route after it is not: {}",
                        v.message
                    );
                    return Ok((record, Some(spliced)));
                }
                (Some(v), Acceptance::Route) => {
                    record.reason =
                        format!("the window's piece is feasible, but the route after it is not: {}", v.message)
                }
            }
        }
        match next_window(w, s.params.growth, remaining) {
            Some(grown) if !cancelled && s.total.interrupted().is_none() => w = grown,
            _ => return Ok((record, None)),
        }
    }
}
