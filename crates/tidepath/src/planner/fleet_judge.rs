//! The fleet's verdict on a plan: every pair of vehicles checked for separation on their
//! own clocks ([`crate::fleet`]); a pair that comes too close makes both missions infeasible,
//! each with a violation naming both vehicles, the time, the places and the distance.

use super::solve::MissionPlan;
use crate::fleet::{self, FleetCheck, FleetRules};
use crate::geom::Vec3;
use crate::path::{PathModel, Violation, ViolationKind};

/// Checks the missions' final paths against `rules` and records each conflict on both
/// missions; `None` when the rules check nothing for this many missions.
pub fn judge_fleet(models: &[PathModel<'_>], missions: &mut [MissionPlan], rules: &FleetRules) -> Option<FleetCheck> {
    if !rules.active(missions.len()) {
        return None;
    }
    let paths: Vec<&[Vec3]> = missions.iter().map(|m| m.path()).collect();
    let check = fleet::check(models, &paths, rules, &mut Vec::new());
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
    Some(check)
}

/// A position for messages: [x, y, z] in a local world, (longitude, latitude, depth) in a
/// geographic one.
fn place(model: &PathModel<'_>, p: Vec3) -> String {
    match model.world.frame {
        Some(_) => format!("({})", model.world.point(p)),
        None => model.world.point(p),
    }
}
