//! The fleet's verdict on a plan: every pair of vehicles checked for separation on their
//! own clocks ([`crate::fleet`]); a pair that comes too close makes both missions infeasible,
//! each with a violation naming both vehicles, the time, the places and the distance.

use super::solve::MissionPlan;
use crate::fleet::{self, Arrival, ArrivalCheck, Broken, FleetCheck, FleetRules};
use crate::geom::Vec3;
use crate::path::{PathModel, Violation, ViolationKind};

/// Checks the missions' final paths against `rules` and records each conflict on both
/// missions; `None` when the rules check nothing for this many missions.
pub fn judge_fleet(models: &[PathModel<'_>], missions: &mut [MissionPlan], rules: &FleetRules) -> Option<FleetCheck> {
    if !rules.active(missions.len()) {
        return None;
    }
    let paths: Vec<&[Vec3]> = missions.iter().map(|m| m.path()).collect();
    // Each vehicle flies its plan's own segment speeds.
    let sped: Vec<PathModel<'_>> =
        models.iter().zip(missions.iter()).map(|(m, p)| m.with_speeds(p.speeds.as_deref())).collect();
    let check = fleet::check(&sped, &paths, rules, &mut Vec::new());
    for c in &check.conflicts {
        let x = &c.approach;
        let message = format!(
            "vehicles {} and {} come within {:.1} m of each other at t = {:.1} s, at {} and {}; the fleet's separation is {} m",
            missions[c.a].name,
            missions[c.b].name,
            x.distance,
            x.time,
            place(&models[c.a], x.at_a),
            place(&models[c.b], x.at_b),
            c.required
        );
        for k in [c.a, c.b] {
            let m = &mut missions[k];
            let index = m.times.iter().rposition(|&t| t <= x.time).unwrap_or(0).min(m.times.len().saturating_sub(2));
            m.violations.push(Violation { kind: ViolationKind::Separation, index, message: message.clone() });
            if m.feasible {
                m.feasible = false;
                m.reason = message.clone();
            }
        }
    }
    if let Some(a) = &check.arrival {
        if let Some(why) = arrival_message(a, rules, missions) {
            for m in missions.iter_mut().filter(|m| m.path().len() >= 2) {
                let index = m.path().len() - 1;
                m.violations.push(Violation { kind: ViolationKind::Arrival, index, message: why.clone() });
                if m.feasible {
                    m.feasible = false;
                    m.reason = why.clone();
                }
            }
        }
    }
    Some(check)
}

/// Why the arrivals break the fleet's rule, naming the vehicles; `None` when they keep it.
fn arrival_message(a: &ArrivalCheck, rules: &FleetRules, missions: &[MissionPlan]) -> Option<String> {
    let name = |i: usize| missions[i].name.as_str();
    Some(match a.broken.as_ref()? {
        Broken::Spread { tolerance_s } => format!(
            "the fleet arrives over {:.1} s ({} first at t = {:.1} s, {} last at t = {:.1} s); together within {tolerance_s} s is asked",
            a.spread_s,
            name(a.first.0),
            a.first.1,
            name(a.last.0),
            a.last.1
        ),
        Broken::Order { earlier, later, by_s } => {
            let order = match &rules.arrival {
                Arrival::Order(o) => o.iter().map(|&i| name(i)).collect::<Vec<_>>().join(", "),
                _ => String::new(),
            };
            format!("{} arrives {by_s:.1} s before {}; the order asked is {order}", name(*later), name(*earlier))
        }
    })
}

/// A position for messages: [x, y, z] in a local world, (longitude, latitude, depth) in a
/// geographic one.
fn place(model: &PathModel<'_>, p: Vec3) -> String {
    match model.world.frame {
        Some(_) => format!("({})", model.world.point(p)),
        None => model.world.point(p),
    }
}
