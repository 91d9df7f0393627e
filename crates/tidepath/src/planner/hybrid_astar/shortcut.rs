//! Shortcuts along the found path (Dolgov et al. 2010 smooth the search's path before use;
//! here the smoothing is by the same analytic curves as the shots). From the start, the path
//! is rebuilt greedily: from the current pose, a shot to the goal if one is valid, else the
//! turn-then-straight curve to the farthest state of the found path it can reach (found by
//! doubling, then bisection), the heading at that state being the curve's own. A curve counts
//! only when the rebuilt path up to its end costs no more than the found path up to the same
//! state, and turns by at most half a turn (no loop round a state just beside the vehicle).
//! Every curve is flown on the rebuilt path's own
//! clock, so moving obstacles and changing currents are judged where the vehicle now is. The
//! rebuilt path replaces the found one only when it is cheaper; when no curve reaches the next
//! state, or the clock or the stop flag ends the pass, the found path stands.

use std::f64::consts::PI;

use super::flight::{Check, Curve};
use super::search::Search;
use crate::geom::Vec3;
use crate::kinematics::Pose;
use crate::termination::Termination;

/// A curve flown from a pose: its polygon, cost, arrival time and end pose.
struct Leg {
    points: Vec<Vec3>,
    cost: f64,
    t: f64,
    end: Pose,
}

impl Search<'_> {
    /// The found path rebuilt by shortcuts from the states' poses `poses` (the start's first)
    /// and their costs `g`, and the path's cost `cost`; `None` when it is not cheaper or could
    /// not be rebuilt.
    pub(super) fn shortcut(
        &self,
        poses: &[Pose],
        g: &[f64],
        cost: f64,
        checks: &mut u64,
        termination: &Termination,
    ) -> Option<Vec<Vec3>> {
        let r = self.lattice.radius;
        let n = poses.len();
        let mut path = vec![self.start];
        let (mut pose, mut t, mut total, mut i) = (poses[0], self.departure, 0.0, 0);
        // Rounding: the same curve as the found path's costs the same within this.
        let slack = 1e-9 * cost;
        // Flies `points` from time `t` where it may cost `budget`: `Err` when the pass must end.
        let mut fly = |points: Vec<Vec3>, t: f64, end: Pose, budget: f64| -> Result<Option<Leg>, ()> {
            match self.price(&points, t, checks, Some(termination)) {
                Ok((c, t)) if c <= budget + slack => Ok(Some(Leg { points, cost: c, t, end })),
                Ok(_) => Ok(None),
                Err(Check::Invalid) => Ok(None),
                Err(Check::Interrupted(_)) => Err(()),
            }
        };
        loop {
            for points in self.shots(pose) {
                if let Some(leg) = fly(points, t, pose, cost - total).ok()? {
                    path.extend(leg.points.into_iter().skip(1));
                    total += leg.cost;
                    return (total < cost).then_some(path);
                }
            }
            if i + 1 >= n {
                return None;
            }
            let mut to = |j: usize, t: f64| -> Result<Option<Leg>, ()> {
                let target = poses[j].p;
                // To the last state with its own heading, so its shot to the goal stays open.
                let (curve, end) = if j + 1 == n {
                    match self.connect(pose, poses[j]) {
                        Some(c) => (c, poses[j]),
                        None => return Ok(None),
                    }
                } else {
                    match Curve::to_point(pose, target, r).filter(|c| c.lengths[0] <= PI * r) {
                        Some(c) => (c, Pose::new(target, c.end_heading(pose, r))),
                        None => return Ok(None),
                    }
                };
                let Some(points) = self.polygon(&curve, pose, target) else { return Ok(None) };
                fly(points, t, end, g[j] - total)
            };
            // The farthest state reachable: the states 1, 2, 4, ... ahead and the last, then
            // bisection between the farthest reached and the next one tried.
            let mut probes: Vec<usize> = std::iter::successors(Some(1usize), |k| k.checked_mul(2))
                .map(|k| i + k)
                .take_while(|&j| j < n)
                .collect();
            if probes.last() != Some(&(n - 1)) {
                probes.push(n - 1);
            }
            let mut best = None;
            let mut hi = None;
            for &j in probes.iter().rev() {
                match to(j, t).ok()? {
                    Some(leg) => {
                        best = Some((j, leg));
                        break;
                    }
                    None => hi = Some(j),
                }
            }
            if let (Some((lo, _)), Some(hi)) = (&best, hi) {
                let (mut lo, mut hi) = (*lo, hi);
                while hi > lo + 1 {
                    let mid = (lo + hi) / 2;
                    match to(mid, t).ok()? {
                        Some(leg) => {
                            best = Some((mid, leg));
                            lo = mid;
                        }
                        None => hi = mid,
                    }
                }
            }
            let (j, leg) = match best {
                Some(b) => b,
                // Not even the next state: the curve to its pose, else give up.
                None => {
                    let curve = self.connect(pose, poses[i + 1])?;
                    let points = self.polygon(&curve, pose, poses[i + 1].p)?;
                    (i + 1, fly(points, t, poses[i + 1], g[i + 1] - total).ok()??)
                }
            };
            path.extend(leg.points.into_iter().skip(1));
            total += leg.cost;
            (pose, t, i) = (leg.end, leg.t, j);
        }
    }
}
