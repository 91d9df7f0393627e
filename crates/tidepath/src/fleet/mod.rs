//! Vehicles of a fleet keeping their distance in time (issue "fleets").
//!
//! Each vehicle flies its path on its own travel clock: the evaluation flies each segment (or
//! each chord of a turn, with a turning radius) in pieces of constant ground speed
//! ([`crate::validity::Validator::for_each_piece`]). Within a piece a vehicle's position is
//! linear in time, so two vehicles' distance on any time interval where both are inside one
//! piece is the norm of a linear function of time, and its minimum has a closed form
//! ([`approach`]). Sweeping both vehicles' pieces in time order gives the exact closest
//! approach of two timed paths: no sampling, no missed crossing.
//!
//! Outside its mission a vehicle either waits at its start before departing and stays at its
//! goal after arriving ([`Presence::Stays`], the default: it is in the water) or is not there
//! at all ([`Presence::Leaves`]: launched at departure, recovered on arrival).

mod approach;
mod arrival;
mod legs;
#[cfg(test)]
mod tests;

pub use approach::{closest_approach, Approach};
pub use arrival::{arrival_penalty, check_arrivals, Arrival, ArrivalCheck, Broken};
pub use legs::{timed_legs, Leg};

use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::path::PathModel;

/// Where a vehicle is outside its mission's time.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Presence {
    /// At its start before departure, at its goal after arrival.
    #[default]
    Stays,
    /// Nowhere: launched at departure, recovered on arrival.
    Leaves,
}

/// The separation a fleet keeps: one distance for every pair, overridden per pair.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FleetRules {
    /// Least distance (m) between any two vehicles at the same time; 0 checks nothing.
    pub separation_m: f64,
    /// (vehicle a, vehicle b, separation) overrides, by mission index.
    pub pairs: Vec<(usize, usize, f64)>,
    pub presence: Presence,
    /// When the vehicles must reach their goals.
    pub arrival: Arrival,
}

/// Rules that check nothing: the default for a problem without a `[fleet]`.
pub static NO_FLEET: FleetRules =
    FleetRules { separation_m: 0.0, pairs: Vec::new(), presence: Presence::Stays, arrival: Arrival::Free };

/// Most vehicles whose arrivals are checked (a scenario holds at most 64 missions).
const MAX_ARRIVALS: usize = 64;

/// Penalty added to a joint objective per pair of vehicles that come too close, plus the
/// same again times the shortfall as a fraction of the separation (so optimizers are led
/// apart); the general cost model's default collision weight.
pub const SEPARATION_PENALTY: f64 = 10.0;

impl FleetRules {
    /// The separation required between vehicles `i` and `j`.
    pub fn separation(&self, i: usize, j: usize) -> f64 {
        let (a, b) = (i.min(j), i.max(j));
        self.pairs.iter().rev().find(|p| (p.0.min(p.1), p.0.max(p.1)) == (a, b)).map_or(self.separation_m, |p| p.2)
    }

    /// Whether `n` vehicles have a separation to keep or an arrival rule to meet.
    pub fn active(&self, n: usize) -> bool {
        n >= 2 && (self.separation_m > 0.0 || self.pairs.iter().any(|p| p.2 > 0.0) || self.arrival != Arrival::Free)
    }

    /// These rules for the missions `kept` (indices into the full list), renumbered in that
    /// order: the problem a planner sees when some missions could not be planned.
    pub fn subset(&self, kept: &[usize]) -> FleetRules {
        let at = |i: usize| kept.iter().position(|&k| k == i);
        let pairs = self.pairs.iter().filter_map(|&(a, b, m)| Some((at(a)?, at(b)?, m))).collect();
        let arrival = match &self.arrival {
            Arrival::Order(order) => Arrival::Order(order.iter().filter_map(|&i| at(i)).collect()),
            other => other.clone(),
        };
        FleetRules { pairs, arrival, ..self.clone() }
    }

    /// Checks the values, naming the field.
    pub fn check(&self, vehicles: usize) -> Result<()> {
        let ok = |v: f64| v.is_finite() && v >= 0.0;
        if !ok(self.separation_m) {
            return Err(Error::input(
                "fleet.separation_m",
                format!("must be finite and >= 0, got {}", self.separation_m),
            ));
        }
        for (k, &(a, b, m)) in self.pairs.iter().enumerate() {
            if a >= vehicles || b >= vehicles || a == b {
                return Err(Error::input(
                    format!("fleet.pairs[{k}]"),
                    format!("must name two different vehicles of the {vehicles}, got {a} and {b}"),
                ));
            }
            if !ok(m) {
                return Err(Error::input(
                    format!("fleet.pairs[{k}].separation_m"),
                    format!("must be finite and >= 0, got {m}"),
                ));
            }
        }
        match &self.arrival {
            Arrival::Together { tolerance_s } if !ok(*tolerance_s) => {
                return Err(Error::input(
                    "fleet.arrival_tolerance_s",
                    format!("must be finite and >= 0, got {tolerance_s}"),
                ));
            }
            Arrival::Order(order) => {
                let mut seen = vec![false; vehicles];
                for &i in order {
                    if i >= vehicles || std::mem::replace(&mut seen[i], true) {
                        return Err(Error::input(
                            "fleet.arrival_order",
                            format!("must list each of the {vehicles} vehicles at most once"),
                        ));
                    }
                }
            }
            _ => {}
        }
        Ok(())
    }
}

/// Two vehicles closer than their separation: mission indices, the approach and the
/// separation they had to keep.
#[derive(Clone, Debug, PartialEq)]
pub struct Conflict {
    pub a: usize,
    pub b: usize,
    pub approach: Approach,
    pub required: f64,
}

/// The fleet's closest pair and every pair that broke its separation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FleetCheck {
    /// The closest approach of any two vehicles (mission indices and the approach).
    pub closest: Option<(usize, usize, Approach)>,
    pub conflicts: Vec<Conflict>,
    /// The arrivals (with two or more vehicles planned).
    pub arrival: Option<ArrivalCheck>,
}

impl FleetCheck {
    /// The joint objective's penalty: [`SEPARATION_PENALTY`] per conflict, plus as much again
    /// times its shortfall over the separation.
    pub fn penalty(&self) -> f64 {
        self.terms().iter().map(|(_, v)| v).sum()
    }

    /// The penalty's two terms, named as plans report them: `separation` (every pair too
    /// close) and `arrival` (the broken arrival rule). Both 0 for a fleet that keeps its rules.
    pub fn terms(&self) -> [(&'static str, f64); 2] {
        let separation = self
            .conflicts
            .iter()
            .map(|c| SEPARATION_PENALTY * (1.0 + ((c.required - c.approach.distance) / c.required).clamp(0.0, 1.0)))
            .sum::<f64>();
        [("separation", separation), ("arrival", self.arrival.as_ref().map_or(0.0, arrival_penalty))]
    }
}

/// Checks the timed paths of every pair of vehicles (`paths[i]` flown by `models[i]`;
/// missions without a path, fewer than two points, are left out). `legs` is a reusable
/// buffer per mission.
pub fn check<P: AsRef<[Vec3]>>(
    models: &[PathModel<'_>],
    paths: &[P],
    rules: &FleetRules,
    legs: &mut Vec<Vec<Leg>>,
) -> FleetCheck {
    let n = models.len().min(paths.len());
    legs.resize_with(n, Vec::new);
    for i in 0..n {
        legs[i].clear();
        let path = paths[i].as_ref();
        if path.len() >= 2 {
            timed_legs(&models[i], path, &mut legs[i]);
        }
    }
    check_legs(&legs[..n], rules)
}

/// [`check`] on legs already flown: `legs[i]` is vehicle i's timed path
/// ([`timed_legs`]; empty when it has none).
pub fn check_legs(legs: &[Vec<Leg>], rules: &FleetRules) -> FleetCheck {
    let n = legs.len();
    let mut out = FleetCheck::default();
    // Arrivals, without allocating: at most a handful of missions, checked in place.
    if rules.arrival != Arrival::Free {
        let mut arrivals = [(0usize, 0.0f64); MAX_ARRIVALS];
        let mut m = 0;
        for (i, l) in legs.iter().enumerate().take(n) {
            if let (Some(last), true) = (l.last(), m < MAX_ARRIVALS) {
                arrivals[m] = (i, last.3);
                m += 1;
            }
        }
        out.arrival = check_arrivals(&rules.arrival, &arrivals[..m]);
    }
    for i in 0..n {
        for j in i + 1..n {
            if legs[i].is_empty() || legs[j].is_empty() {
                continue;
            }
            let Some(a) = closest_approach(&legs[i], &legs[j], rules.presence) else { continue };
            if out.closest.as_ref().is_none_or(|c| a.distance < c.2.distance) {
                out.closest = Some((i, j, a));
            }
            let required = rules.separation(i, j);
            if a.distance < required {
                out.conflicts.push(Conflict { a: i, b: j, approach: a, required });
            }
        }
    }
    out
}
