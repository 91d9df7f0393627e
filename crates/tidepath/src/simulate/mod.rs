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
#[cfg(test)]
mod tests_sensor;

pub use walk::{advance, bounding_radius, due, track_violations, Event, Track};
pub use window::{next_window, replan_budget, splice, takes_warm_start, Growth};
// `Acceptance` is defined here, beside `SimParams`.

use crate::cost::CostModel;
use crate::error::Result;
use crate::geom::Vec3;
use crate::mission::Mission;
use crate::path::{ModelSettings, PathModel};
use crate::planner::{Planner, Status};
use crate::rng::Rng;
use crate::termination::Termination;
use crate::validity::Validator;
use crate::world::changes::{center, AppliedChange, Change, ChangeKind, Trigger};
use crate::world::{Current, Obstacle, World};

/// When a change leads to a re-plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReplanPolicy {
    /// Only when the route ahead is no longer feasible on the known world.
    WhenInfeasible,
    /// At every change (lfhh2019 re-plans at each environment change).
    Always,
}

/// What makes a re-planned window good enough to stop growing it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Acceptance {
    /// The route spliced from the window's piece is feasible all the way to the goal: the
    /// vehicle never flies a route known to be blocked.
    Route,
    /// The window's piece is feasible (lfhh2019: "if F >= 2, W + 1"); a blockage beyond the
    /// window waits for the next change's re-plan, so a loop with no later change can fly into
    /// it (the after-the-fact check then fails the simulation).
    Window,
}

/// The loop's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimParams {
    /// Waypoints ahead of the vehicle the first window reaches (W).
    pub window: usize,
    pub growth: Growth,
    pub accept: Acceptance,
    pub policy: ReplanPolicy,
    /// Warm-start planners that take one from the old route's piece in the window.
    pub warm_start: bool,
    /// Moving obstacles (ships, other vehicles) are known only once they come within this
    /// range (m) of the vehicle, counted from their surface (a centre within range plus the
    /// obstacle's bounding radius); fixed obstacles are charted and known from departure.
    /// `None`: every obstacle is known from departure.
    pub sensor_range: Option<f64>,
}

impl SimParams {
    /// lfhh2019's window rule (docs/papers/lfhh2019.md, sections IV-E and IV-F): W = 20,
    /// W <- W + 1 while the window's piece is infeasible, a re-plan at every change, each from
    /// a fresh population (no warm start).
    pub const LFHH2019: SimParams = SimParams {
        window: 20,
        growth: Growth::Add(1),
        accept: Acceptance::Window,
        policy: ReplanPolicy::Always,
        warm_start: false,
        sensor_range: None,
    };
}

impl Default for SimParams {
    /// lfhh2019's first window, doubled on failure (fewer planner calls than W + 1), re-planning
    /// only routes a change made infeasible.
    fn default() -> Self {
        SimParams {
            window: 20,
            growth: Growth::Double,
            accept: Acceptance::Route,
            policy: ReplanPolicy::WhenInfeasible,
            warm_start: true,
            sensor_range: None,
        }
    }
}

/// Everything one simulation runs on.
#[derive(Clone, Copy)]
pub struct Setup<'a> {
    /// The world at departure as it really is: every obstacle, moving ones the vehicle has not
    /// seen yet included (with a sensor range). Changes turn it into the later true worlds;
    /// the vehicle knows it minus what it has not seen.
    pub world: &'a World,
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
    /// Where the planner's failure is about (a bottleneck, an invalid end), when it says.
    pub focus: Option<crate::planner::solve::Focus>,
}

/// The true world from a time on: its obstacles (indices as changes name them) and which of
/// [`Simulation::currents`] flows.
#[derive(Clone, Debug, PartialEq)]
pub struct Epoch {
    pub from: f64,
    pub obstacles: Vec<Obstacle>,
    pub current: usize,
}

/// One phase: the departure plan (phase 0), one change event, or one sighting, and what the
/// loop did about it. A change event is every pending change with the same trigger (equal
/// `Trigger` values): they apply together, in the scenario's order, and the route is checked
/// and re-planned once for all of them (lfhh2019 moves every obstacle and vortex at each of
/// its five changes: five events, not one per obstacle).
#[derive(Clone, Debug, PartialEq)]
pub struct Phase {
    /// The changes' trigger (`None` for the departure plan and for sightings).
    pub trigger: Option<Trigger>,
    /// One line: what happened.
    pub event: String,
    /// The vehicle's position and time when the phase began.
    pub position: Vec3,
    pub time: f64,
    /// The changes of a change event, in the scenario's order (empty for the departure plan
    /// and for sightings).
    pub changes: Vec<AppliedChange>,
    /// The obstacle seen in a sighting phase (its index in the true world).
    pub sighted: Option<usize>,
    /// Whether the vehicle learnt anything: false when every change of the event concerns a
    /// ship it has not seen or is a skipped random change (nothing to check or re-plan).
    pub revealed: bool,
    /// The true world after the phase: an index into [`Simulation::epochs`].
    pub epoch: usize,
    /// Which of that epoch's obstacles the vehicle knew after the phase.
    pub seen: Vec<bool>,
    /// The route ahead when the phase began (empty for the departure plan).
    pub route_before: Vec<Vec3>,
    /// The first violation of the route ahead on the known world after the change.
    pub route_problem: Option<String>,
    pub replan: Option<Replan>,
    /// The route ahead after the phase (the old one when it was kept).
    pub route_after: Vec<Vec3>,
}

/// A whole simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct Simulation {
    pub phases: Vec<Phase>,
    /// Where the vehicle flew, with times.
    pub track: Track,
    /// The route still ahead when the loop stopped (empty at the goal).
    pub route: Vec<Vec3>,
    /// The true world over time, the first from departure.
    pub epochs: Vec<Epoch>,
    /// The departure's current and each newer forecast, in order of arrival.
    pub currents: Vec<Current>,
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

impl Simulation {
    /// The true world of epoch `e`, on the base world `world` (the setup's).
    pub fn truth(&self, world: &World, e: usize) -> World {
        let ep = &self.epochs[e];
        World { obstacles: ep.obstacles.clone(), current: self.currents[ep.current].clone(), ..world.clone() }
    }

    /// The world the vehicle knew after phase `k`, and the obstacles it had not seen.
    pub fn known(&self, world: &World, k: usize) -> (World, Vec<Obstacle>) {
        let p = &self.phases[k];
        let mut w = self.truth(world, p.epoch);
        let (seen, unseen) = split_seen(&w.obstacles, &p.seen);
        w.obstacles = seen;
        (w, unseen)
    }

    /// The arrival time at the goal, when the vehicle reached it.
    pub fn arrival(&self) -> Option<f64> {
        self.reached.then(|| self.track.now().1)
    }
}

fn split_seen(obstacles: &[Obstacle], seen: &[bool]) -> (Vec<Obstacle>, Vec<Obstacle>) {
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for (o, &s) in obstacles.iter().zip(seen) {
        if s {
            a.push(o.clone())
        } else {
            b.push(o.clone())
        }
    }
    (a, b)
}

/// The ocean as the loop tracks it: the true world now, what the vehicle has seen of it,
/// and the history of true worlds for the after-the-fact check.
struct Ocean {
    truth: World,
    seen: Vec<bool>,
    epochs: Vec<Epoch>,
    currents: Vec<Current>,
}

impl Ocean {
    fn new(world: &World, sensor_range: Option<f64>, start: Vec3, t: f64) -> Self {
        let seen = world
            .obstacles
            .iter()
            .map(|o| match sensor_range {
                Some(r) if o.velocity != Vec3::ZERO => due(&Event::sighting(o, r), start, t, 0.0),
                _ => true,
            })
            .collect();
        let epochs = vec![Epoch { from: f64::NEG_INFINITY, obstacles: world.obstacles.clone(), current: 0 }];
        Ocean { truth: world.clone(), seen, epochs, currents: vec![world.current.clone()] }
    }

    /// The world the vehicle knows: the truth without what it has not seen.
    fn known(&self) -> World {
        World { obstacles: split_seen(&self.truth.obstacles, &self.seen).0, ..self.truth.clone() }
    }

    /// Records the truth as it is from time `t` on.
    fn push_epoch(&mut self, t: f64, new_current: bool) {
        if new_current {
            self.currents.push(self.truth.current.clone());
        }
        let current = self.currents.len() - 1;
        self.epochs.push(Epoch { from: t, obstacles: self.truth.obstacles.clone(), current });
    }
}

/// Whether a change to the true world concerns an obstacle the vehicle has not seen (so it
/// learns nothing from it), keeping `seen` in step with the obstacle list.
fn update_seen(kind: &ChangeKind, seen: &mut Vec<bool>, added: Option<&Obstacle>, sensor: Option<f64>) -> bool {
    match kind {
        ChangeKind::AddObstacle(_) => {
            let o = added.expect("an added obstacle");
            let visible = sensor.is_none() || o.velocity == Vec3::ZERO;
            seen.push(visible);
            !visible
        }
        ChangeKind::RemoveObstacle { index } => !seen.remove(*index),
        ChangeKind::MoveObstacle { index, .. } | ChangeKind::ObstacleVelocity { index, .. } => !seen[*index],
        _ => false,
    }
}

/// Runs the mission loop; errors are bad input (a termination, a change, a planner setting).
pub fn simulate(s: &Setup<'_>, rng: &mut Rng) -> Result<Simulation> {
    s.per_replan.check()?;
    s.total.check()?;
    if let Some(r) = s.params.sensor_range {
        if !(r.is_finite() && r > 0.0) {
            return Err(crate::error::Error::input(
                "simulate.sensor_range",
                format!("must be finite and > 0, got {r}"),
            ));
        }
    }
    let total = s.total.started_now();
    let s = &Setup { total: &total, ..*s };
    let m = s.mission;
    let mut ocean = Ocean::new(s.world, s.params.sensor_range, m.start, m.departure_time);
    let mut track = Track::new(m.start, m.departure_time);
    let mut phases = Vec::new();
    let known = ocean.known();
    let (first, route) = window::replan(s, &known, &[m.start, m.goal], m.departure_time, rng, false)?;
    phases.push(Phase {
        trigger: None,
        event: "departure".to_string(),
        position: m.start,
        time: m.departure_time,
        changes: Vec::new(),
        sighted: None,
        revealed: true,
        epoch: 0,
        seen: ocean.seen.clone(),
        route_before: Vec::new(),
        route_problem: None,
        replan: Some(first.clone()),
        route_after: route.clone().unwrap_or_default(),
    });
    let Some(mut route) = route else {
        if first.status == Status::Cancelled || total.interrupted().is_some() {
            let why = format!("stopped during phase 0: {}", first.reason);
            return Ok(finish(s, phases, track, vec![m.start, m.goal], ocean, Err(why), false));
        }
        let why = format!("phase 0: no feasible route at departure: {}", first.reason);
        return Ok(finish(s, phases, track, vec![m.start, m.goal], ocean, Err(why), true));
    };
    let mut pending: Vec<usize> = (0..s.changes.len()).collect();
    loop {
        if let Some(r) = total.interrupted() {
            let why = format!("stopped ({}) after phase {}", r.id(), phases.len() - 1);
            return Ok(finish(s, phases, track, route, ocean, Err(why), false));
        }
        // Pending changes first (in the scenario's order), then sightings of unseen obstacles.
        let unseen: Vec<usize> = (0..ocean.seen.len()).filter(|&i| !ocean.seen[i]).collect();
        let mut events: Vec<Event> = pending.iter().map(|&k| Event::Trigger(s.changes[k].trigger)).collect();
        if let Some(r) = s.params.sensor_range {
            events.extend(unseen.iter().map(|&i| Event::sighting(&ocean.truth.obstacles[i], r)));
        }
        let (pos, t) = track.now();
        let fired = match events.iter().position(|e| due(e, pos, t, track.travelled)) {
            Some(i) => i,
            None => {
                let known = ocean.known();
                let v = Validator::new(&known, &m.vehicle, s.settings);
                match advance(&v, &route, &events, &mut track) {
                    None => return Ok(finish(s, phases, track, Vec::new(), ocean, Ok(()), true)),
                    Some((i, ahead)) => {
                        route = ahead;
                        i
                    }
                }
            }
        };
        let (pos, t) = track.now();
        let route_before = route.clone();
        let mut phase = Phase {
            trigger: None,
            event: String::new(),
            position: pos,
            time: t,
            changes: Vec::new(),
            sighted: None,
            revealed: true,
            epoch: ocean.epochs.len() - 1,
            seen: Vec::new(),
            route_before: route_before.clone(),
            route_problem: None,
            replan: None,
            route_after: Vec::new(),
        };
        let mut learned = true;
        if fired < pending.len() {
            // The event: every pending change with this very trigger, in the scenario's order.
            let trigger = s.changes[pending[fired]].trigger;
            let group: Vec<usize> = pending.iter().copied().filter(|&k| s.changes[k].trigger == trigger).collect();
            pending.retain(|k| !group.contains(k));
            let (mut seen_any, mut applied_any, mut new_current) = (false, false, false);
            let mut unseen = Vec::with_capacity(group.len());
            for &k in &group {
                let applied = s.changes[k].apply(&mut ocean.truth, t, pos, m.goal, m.vehicle.safety_distance, rng)?;
                let mut hidden = true;
                if applied.skipped.is_none() {
                    let added = ocean.truth.obstacles.last().cloned();
                    hidden = update_seen(&applied.resolved, &mut ocean.seen, added.as_ref(), s.params.sensor_range);
                    applied_any = true;
                    new_current |= matches!(applied.resolved, ChangeKind::ReplaceCurrent(_));
                }
                seen_any |= !hidden;
                unseen.push(hidden);
                phase.changes.push(applied);
            }
            if applied_any {
                ocean.push_epoch(t, new_current);
            }
            learned = seen_any;
            phase.event = event_line(&phase.changes, &unseen);
            phase.trigger = Some(trigger);
        } else {
            let i = unseen[fired - pending.len()];
            ocean.seen[i] = true;
            let o = &ocean.truth.obstacles[i];
            let c = center(&o.shape_at(t));
            let d = c.distance(pos) - bounding_radius(&o.shape);
            phase.event =
                format!("obstacle {i} sighted {:.0} m away at {} at t = {t:.1} s", d.max(0.0), ocean.truth.point(c));
            phase.sighted = Some(i);
        }
        phase.epoch = ocean.epochs.len() - 1;
        phase.seen = ocean.seen.clone();
        phase.revealed = learned;
        if !learned {
            phase.route_after = route.clone();
            phases.push(phase);
            continue;
        }
        let known = ocean.known();
        let whole = Mission { start: pos, departure_time: t, ..m.clone() };
        let problem = PathModel::new(&known, &whole, s.settings).violations(&route).first().map(|v| v.message.clone());
        phase.route_problem = problem.clone();
        if problem.is_none() && s.params.policy == ReplanPolicy::WhenInfeasible {
            phase.route_after = route.clone();
            phases.push(phase);
            continue;
        }
        let (record, new) = window::replan(s, &known, &route, t, rng, true)?;
        let (status, reason) = (record.status, record.reason.clone());
        phase.replan = Some(record);
        let n = phases.len();
        match new {
            Some(r) => route = r,
            // Re-planned at every change, the old route is kept when it is still feasible.
            None if problem.is_none() => {}
            None if status == Status::Cancelled || total.interrupted().is_some() => {
                phase.route_after = route.clone();
                phases.push(phase);
                let why = format!("stopped during phase {n}: {reason}");
                return Ok(finish(s, phases, track, route, ocean, Err(why), false));
            }
            None => {
                phase.route_after = route.clone();
                phases.push(phase);
                let why = format!("phase {n}: no feasible window up to the goal: {reason}");
                return Ok(finish(s, phases, track, route, ocean, Err(why), true));
            }
        }
        phase.route_after = route.clone();
        phases.push(phase);
    }
}

/// One line for a change event: the change's own description when it is alone; for several,
/// how many of each kind (their descriptions, with the time, are in [`Phase::changes`]).
/// `unseen[k]`: the vehicle learnt nothing from change k (a ship not seen yet, or a skipped
/// draw).
fn event_line(changes: &[AppliedChange], unseen: &[bool]) -> String {
    if let ([c], [hidden]) = (changes, unseen) {
        return match hidden {
            false => c.description.clone(),
            true => format!("{} (unseen by the vehicle: nothing to replan)", c.description),
        };
    }
    // (singular, plural) per kind, in a fixed order.
    const KINDS: [(&str, &str); 7] = [
        ("obstacle moved", "obstacles moved"),
        ("course change", "course changes"),
        ("obstacle appeared", "obstacles appeared"),
        ("obstacle disappeared", "obstacles disappeared"),
        ("vortex moved", "vortices moved"),
        ("vortex strength changed", "vortex strengths changed"),
        ("new current forecast", "new current forecasts"),
    ];
    let mut counts = [0usize; 7];
    let mut skipped = 0;
    for c in changes {
        if c.skipped.is_some() {
            skipped += 1;
            continue;
        }
        counts[match c.resolved {
            ChangeKind::MoveObstacle { .. } => 0,
            ChangeKind::ObstacleVelocity { .. } => 1,
            ChangeKind::AddObstacle(_) => 2,
            ChangeKind::RemoveObstacle { .. } => 3,
            ChangeKind::MoveVortex { .. } => 4,
            ChangeKind::VortexStrength { .. } => 5,
            ChangeKind::ReplaceCurrent(_) => 6,
        }] += 1;
    }
    let mut parts: Vec<String> = KINDS
        .iter()
        .zip(counts)
        .filter(|(_, n)| *n > 0)
        .map(|((one, many), n)| if n == 1 { format!("1 {one}") } else { format!("{n} {many}") })
        .collect();
    if skipped > 0 {
        parts.push(format!("{skipped} skipped (every random draw covered the vehicle or its goal)"));
    }
    let hidden = unseen.iter().filter(|&&h| h).count() - skipped;
    if hidden > 0 {
        parts.push(format!("{hidden} unseen by the vehicle"));
    }
    let line = format!("{} changes: {}", changes.len(), parts.join(", "));
    match unseen.iter().all(|&h| h) {
        true => format!("{line} (nothing to replan)"),
        false => line,
    }
}

/// The simulation's verdict: `outcome` is `Ok` when the vehicle reached the goal; the flown
/// track is checked against the true world of each moment in any case.
fn finish(
    s: &Setup<'_>,
    phases: Vec<Phase>,
    track: Track,
    route: Vec<Vec3>,
    ocean: Ocean,
    outcome: std::result::Result<(), String>,
    complete: bool,
) -> Simulation {
    let Ocean { epochs, currents, .. } = ocean;
    let mut sim = Simulation {
        phases,
        track,
        route,
        epochs,
        currents,
        reached: false,
        complete,
        reason: String::new(),
        track_violations: Vec::new(),
    };
    let worlds: Vec<World> = (0..sim.epochs.len()).map(|e| sim.truth(s.world, e)).collect();
    let validators: Vec<(f64, Validator<'_>)> = worlds
        .iter()
        .zip(&sim.epochs)
        .map(|(w, e)| (e.from, Validator::new(w, &s.mission.vehicle, s.settings)))
        .collect();
    sim.track_violations = track_violations(&validators, &sim.track.points, &sim.track.times);
    let (reached, reason) = match (outcome, sim.track_violations.first()) {
        (Ok(()), None) => (true, format!("reached the goal at t = {:.1} s", sim.track.now().1)),
        (Ok(()), Some(first)) => (false, format!("reached the goal, but the true world forbids the track: {first}")),
        (Err(why), _) => (false, why),
    };
    sim.reached = reached;
    sim.reason = reason;
    sim
}
