//! The mission loop: fly a planned route while the world changes, and re-plan a window of the
//! route ahead when a change makes it infeasible (or at every change), with any planner.
//!
//! The planner only ever sees the world as known: the scenario's world at departure, with
//! each change applied when its trigger fires. The vehicle moves along its route on the
//! travel clock of that known world (the forecasts as they arrived), never jumps (every new
//! piece starts at its position and time) and its flown track is checked after the fact
//! against the true world the caller gives. Everything random comes from the one `&mut Rng`,
//! so the same seed gives the same simulation.

mod walk;
mod window;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_loop;

pub use walk::{advance, due, track_violations, Track};
pub use window::{next_window, replan_budget, splice, takes_warm_start, Growth};

use crate::cost::CostModel;
use crate::error::Result;
use crate::geom::Vec3;
use crate::mission::Mission;
use crate::path::{ModelSettings, PathModel};
use crate::planner::{Planner, Status};
use crate::rng::Rng;
use crate::termination::Termination;
use crate::validity::Validator;
use crate::world::changes::{AppliedChange, Change, Trigger};
use crate::world::World;

/// When a change leads to a re-plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReplanPolicy {
    /// Only when the route ahead is no longer feasible on the known world.
    WhenInfeasible,
    /// At every change (lfhh2019 re-plans at each environment change).
    Always,
}

/// The loop's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimParams {
    /// Waypoints ahead of the vehicle the first window reaches (W).
    pub window: usize,
    pub growth: Growth,
    pub policy: ReplanPolicy,
    /// Warm-start planners that take one from the old route's piece in the window.
    pub warm_start: bool,
}

impl SimParams {
    /// lfhh2019's window rule (docs/papers/lfhh2019.md, sections IV-E and IV-F): W = 20,
    /// W <- W + 1 while no feasible piece is found, a re-plan at every change.
    pub const LFHH2019: SimParams =
        SimParams { window: 20, growth: Growth::Add(1), policy: ReplanPolicy::Always, warm_start: true };
}

impl Default for SimParams {
    /// lfhh2019's first window, doubled on failure (fewer planner calls than W + 1), re-planning
    /// only routes a change made infeasible.
    fn default() -> Self {
        SimParams { window: 20, growth: Growth::Double, policy: ReplanPolicy::WhenInfeasible, warm_start: true }
    }
}

/// Everything one simulation runs on.
#[derive(Clone, Copy)]
pub struct Setup<'a> {
    /// The world as it really is, for the after-the-fact check of the flown track.
    pub truth: &'a World,
    /// The world as known at departure: the truth minus the changes not yet revealed.
    pub known: &'a World,
    pub mission: &'a Mission,
    pub changes: &'a [Change],
    /// Builds a fresh planner for each (re-)plan.
    pub planner: &'a dyn Fn() -> Result<Box<dyn Planner>>,
    pub cost: &'a dyn CostModel,
    pub settings: &'a ModelSettings,
    pub params: SimParams,
    /// Limits of each planner call, cut to what `total` leaves.
    pub per_replan: &'a Termination,
    /// Limits of the whole simulation (wall time, stop flag), polled in every loop.
    pub total: &'a Termination,
}

/// One (re-)plan: the windows tried (waypoints ahead), the last one's target, piece and verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Replan {
    pub windows: Vec<usize>,
    pub target: Vec3,
    pub piece: Vec<Vec3>,
    pub status: Status,
    pub reason: String,
    pub cost: f64,
    /// Wall time of the last planner call (s); the only field that differs between runs.
    pub planning_s: f64,
    /// Whether the planner was warm-started from the old route.
    pub warm: bool,
}

/// One phase: the departure plan (phase 0) or one change and what the loop did about it.
#[derive(Clone, Debug, PartialEq)]
pub struct Phase {
    pub trigger: Option<Trigger>,
    /// The vehicle's position and time when the phase began.
    pub position: Vec3,
    pub time: f64,
    pub change: Option<AppliedChange>,
    /// The first violation of the route ahead on the known world after the change.
    pub route_problem: Option<String>,
    pub replan: Option<Replan>,
}

/// A whole simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct Simulation {
    pub phases: Vec<Phase>,
    /// Where the vehicle flew, with times.
    pub track: Track,
    /// The route still ahead when the loop stopped (empty at the goal).
    pub route: Vec<Vec3>,
    /// At the goal along a track the true world allows at every moment.
    pub reached: bool,
    /// False when the stop flag or the total time limit ended the loop early.
    pub complete: bool,
    /// One line: "reached the goal at t = 812.3 s" or "phase 3: no feasible window up to the
    /// goal: ...".
    pub reason: String,
    /// The flown track against the true world (empty when it never broke a rule).
    pub track_violations: Vec<String>,
}

/// Runs the mission loop; errors are bad input (a termination, a change, a planner setting).
pub fn simulate(s: &Setup<'_>, rng: &mut Rng) -> Result<Simulation> {
    s.per_replan.check()?;
    s.total.check()?;
    let total = s.total.started_now();
    let s = &Setup { total: &total, ..*s };
    let m = s.mission;
    let mut known = s.known.clone();
    let mut track = Track::new(m.start, m.departure_time);
    let mut phases = Vec::new();
    let (first, route) = window::replan(s, &known, &[m.start, m.goal], m.departure_time, rng, false)?;
    phases.push(Phase {
        trigger: None,
        position: m.start,
        time: m.departure_time,
        change: None,
        route_problem: None,
        replan: Some(first.clone()),
    });
    let Some(mut route) = route else {
        return Ok(finish(
            s,
            phases,
            track,
            vec![m.start, m.goal],
            Err(format!("phase 0: no feasible route at departure: {}", first.reason)),
            true,
        ));
    };
    let mut pending: Vec<usize> = (0..s.changes.len()).collect();
    loop {
        if let Some(r) = total.interrupted() {
            let why = format!("stopped ({}) after phase {}", r.id(), phases.len() - 1);
            return Ok(finish(s, phases, track, route, Err(why), false));
        }
        let (pos, t) = track.now();
        let now = pending.iter().position(|&k| due(s.changes[k].trigger, t, track.travelled));
        let k = match now {
            Some(i) => pending.remove(i),
            None => {
                let triggers: Vec<Trigger> = pending.iter().map(|&k| s.changes[k].trigger).collect();
                let v = Validator::new(&known, &m.vehicle, s.settings);
                match advance(&v, &route, &triggers, &mut track) {
                    None => return Ok(finish(s, phases, track, Vec::new(), Ok(()), true)),
                    Some((i, ahead)) => {
                        route = ahead;
                        pending.remove(i)
                    }
                }
            }
        };
        let (pos, t) = if now.is_some() { (pos, t) } else { track.now() };
        let change = &s.changes[k];
        let applied = change.apply(&mut known, t, pos, m.goal, m.vehicle.safety_distance, rng)?;
        let whole = Mission { start: pos, departure_time: t, ..m.clone() };
        let problem = PathModel::new(&known, &whole, s.settings).violations(&route).first().map(|v| v.message.clone());
        let mut phase = Phase {
            trigger: Some(change.trigger),
            position: pos,
            time: t,
            change: Some(applied),
            route_problem: problem.clone(),
            replan: None,
        };
        if problem.is_none() && s.params.policy == ReplanPolicy::WhenInfeasible {
            phases.push(phase);
            continue;
        }
        let (record, new) = window::replan(s, &known, &route, t, rng, true)?;
        let (status, reason) = (record.status, record.reason.clone());
        phase.replan = Some(record);
        phases.push(phase);
        let n = phases.len() - 1;
        match new {
            Some(r) => route = r,
            // Re-planned at every change, the old route is kept when it is still feasible.
            None if problem.is_none() => {}
            None if status == Status::Cancelled || total.interrupted().is_some() => {
                let why = format!("stopped during phase {n}: {reason}");
                return Ok(finish(s, phases, track, route, Err(why), false));
            }
            None => {
                let why = format!("phase {n}: no feasible window up to the goal: {reason}");
                return Ok(finish(s, phases, track, route, Err(why), true));
            }
        }
    }
}

/// The simulation's verdict: `outcome` is `Ok` when the vehicle reached the goal; the flown
/// track is then checked against the true world.
fn finish(
    s: &Setup<'_>,
    phases: Vec<Phase>,
    track: Track,
    route: Vec<Vec3>,
    outcome: std::result::Result<(), String>,
    complete: bool,
) -> Simulation {
    let v = Validator::new(s.truth, &s.mission.vehicle, s.settings);
    let track_violations = track_violations(&v, &track.points, &track.times);
    let (reached, reason) = match (outcome, track_violations.first()) {
        (Ok(()), None) => (true, format!("reached the goal at t = {:.1} s", track.now().1)),
        (Ok(()), Some(first)) => (false, format!("reached the goal, but the true world forbids the track: {first}")),
        (Err(why), _) => (false, why),
    };
    Simulation { phases, track, route, reached, complete, reason, track_violations }
}
