//! One mission's lattice search: the states, the best-first loop, the analytic shots to the
//! goal, and the path back.
//!
//! States are numbered as they are first reached and found again by their key (cell, layer,
//! heading bin) in a hash map that is only ever looked up, never iterated, so the search is
//! deterministic; a lattice over a long strait has tens of millions of keys and reaches a few.
//! Each key keeps one continuous state (pose, arrival time, cost), replaced while the key is
//! open when a cheaper one arrives (the hybrid part of Hybrid-A*). The open list pops the
//! smallest f = g + h, ties to the larger g, then the earlier state.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};
use std::hash::{BuildHasherDefault, Hasher};

use super::flight::Check;
use super::heuristic::{free_heading_length, Hops};
use super::lattice::Lattice;
use crate::cost::CostModel;
use crate::geom::Vec3;
use crate::kinematics::Pose;
use crate::path::PathModel;
use crate::raster::Raster;
use crate::termination::{StopReason, Termination};

/// Most states one search stores (about 100 bytes each with the map and the open list, so some
/// 200 MB): a run that reaches it stops and says so.
pub const MAX_STATES: usize = 1 << 21;

/// How often (in expansions, and in motions within one long check) the clock and the stop
/// flag are polled.
pub const POLL_EVERY: u64 = 16;

/// A multiplicative hash for the integer keys (the map is never iterated).
#[derive(Default)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x100_0000_01b3);
        }
    }
    fn write_u64(&mut self, k: u64) {
        self.0 = (k ^ (k >> 29)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    }
}

const NONE: u32 = u32::MAX;

#[derive(Clone, Copy, Debug)]
struct State {
    pose: Pose,
    /// Arrival time (s).
    t: f64,
    g: f64,
    parent: u32,
    /// The primitive that reached it from its parent.
    primitive: u16,
    closed: bool,
}

#[derive(Clone, Copy, Debug)]
struct Open {
    f: f64,
    g: f64,
    id: u32,
}

impl PartialEq for Open {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Open {}
impl PartialOrd for Open {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Open {
    /// A max-heap: the smallest f first, then the largest g, then the smallest id.
    fn cmp(&self, o: &Self) -> Ordering {
        o.f.total_cmp(&self.f).then_with(|| self.g.total_cmp(&o.g)).then_with(|| o.id.cmp(&self.id))
    }
}

/// The goal, reached by a shot from state `from`.
#[derive(Clone, Debug)]
struct Shot {
    from: u32,
    points: Vec<Vec3>,
    g: f64,
}

/// What one search found.
pub struct Outcome {
    /// Start to goal when found; start to the expanded state nearest the goal when stopped;
    /// empty when the lattice was exhausted.
    pub path: Vec<Vec3>,
    pub found: bool,
    pub expansions: u64,
    pub motion_checks: u64,
    pub states: u64,
    pub edges: u64,
    /// Why it stopped early, if it did.
    pub stopped: Option<StopReason>,
    /// It stopped at [`MAX_STATES`].
    pub full: bool,
}

/// Everything one mission's search reads.
pub struct Search<'a> {
    pub model: PathModel<'a>,
    pub cost: &'a dyn CostModel,
    pub raster: Raster,
    pub hops: Hops,
    pub lattice: Lattice,
    pub goal: Vec3,
    pub start: Vec3,
    pub departure: f64,
    /// The best ground speed the current allows (m/s).
    pub best_speed: f64,
    /// Analytic expansion ratio.
    pub shot_ratio: f64,
    /// Weight on the heuristic.
    pub weight: f64,
    /// Fixed goal headings the shots also try.
    pub goal_headings: usize,
    pub max_piece: f64,
    /// Tangent of the pitch limit.
    pub tan_pitch: f64,
    pub three_d: bool,
}

impl Search<'_> {
    /// The key of a pose: cell, layer and heading bin.
    fn key(&self, pose: Pose) -> u64 {
        (self.raster.cell_of(pose.p) as u64) * self.lattice.bins as u64 + self.lattice.bin_of(pose.heading) as u64
    }

    /// A lower bound on the length still to fly from `pose`, or `None` when the goal cannot be
    /// reached from its column (or its height with no pitch allowed): the horizontal length is
    /// at least both horizontal bounds and the height left over the pitch limit's slope.
    fn length_bound(&self, pose: Pose) -> Option<f64> {
        let grid = self.hops.bound(pose.p)?;
        let free = free_heading_length(pose, self.goal.truncate(), self.lattice.radius);
        let dz = self.goal.z - pose.p.z;
        let climb = if dz == 0.0 { 0.0 } else { dz.abs() / self.tan_pitch };
        Some(free.max(grid).max(climb).hypot(dz)).filter(|l| l.is_finite())
    }

    fn cost_bound(&self, length: f64) -> f64 {
        self.cost.motion_lower_bound(&self.model, length, self.best_speed)
    }

    /// The open list's estimate of the cost to the goal from a state `length` metres away.
    fn h(&self, length: f64) -> f64 {
        self.weight * self.cost_bound(length)
    }

    /// The start states: the start in every heading bin, the bin holding the bearing to the
    /// goal at that bearing exactly (the straight line, when it is free, is then one shot).
    fn start_poses(&self) -> Vec<Pose> {
        let l = &self.lattice;
        let d = (self.goal - self.start).truncate();
        let bearing = (d.length() > 0.0).then(|| d.y.atan2(d.x));
        (0..l.bins)
            .map(|b| {
                let h = match bearing {
                    Some(a) if l.bin_of(a) == b => a,
                    _ => b as f64 * l.bin,
                };
                Pose::new(self.start, h)
            })
            .collect()
    }

    /// Searches from the start to the goal within `termination` and `max_expansions`.
    pub fn run(&self, termination: &Termination, max_expansions: Option<u64>) -> Outcome {
        let mut out = Outcome {
            path: Vec::new(),
            found: false,
            expansions: 0,
            motion_checks: 0,
            states: 0,
            edges: 0,
            stopped: None,
            full: false,
        };
        if self.start.distance(self.goal) == 0.0 {
            out.path = vec![self.start, self.goal];
            out.found = true;
            return out;
        }
        let mut states: Vec<State> = Vec::new();
        let mut index: HashMap<u64, u32, BuildHasherDefault<KeyHasher>> = HashMap::default();
        let mut open = BinaryHeap::new();
        for pose in self.start_poses() {
            let Some(h) = self.length_bound(pose) else { continue };
            let id = states.len() as u32;
            index.insert(self.key(pose), id);
            states.push(State { pose, t: self.departure, g: 0.0, parent: NONE, primitive: 0, closed: false });
            open.push(Open { f: self.h(h), g: 0.0, id });
        }
        let mut goal: Option<Shot> = None;
        // The expanded state nearest the goal, for a run that stops early.
        let mut nearest: Option<(f64, u32)> = None;
        let mut since_shot = u64::MAX;
        let mut scratch = Vec::new();
        let prim_bounds: Vec<f64> = self.lattice.primitives.iter().map(|p| self.cost_bound(p.length_3d)).collect();
        let stop = loop {
            let Some(e) = open.pop() else { break None };
            if e.id == NONE {
                if goal.as_ref().is_some_and(|s| s.g == e.g) {
                    out.found = true;
                    break None;
                }
                continue;
            }
            let u = e.id as usize;
            if states[u].closed || states[u].g != e.g {
                continue; // replaced by a cheaper state, or already expanded
            }
            if max_expansions.is_some_and(|m| out.expansions >= m) {
                break Some(StopReason::MaxExpansions);
            }
            if out.expansions % POLL_EVERY == 0 {
                if let Some(r) = termination.interrupted() {
                    break Some(r);
                }
            }
            if states.len() >= MAX_STATES {
                out.full = true;
                break None;
            }
            states[u].closed = true;
            out.expansions += 1;
            let s = states[u];
            let near = s.pose.p.distance(self.goal);
            if nearest.is_none_or(|(d, _)| near < d) {
                nearest = Some((near, u as u32));
            }
            // The analytic expansion (Nav2's schedule): more often as the goal nears.
            let free = free_heading_length(s.pose, self.goal.truncate(), self.lattice.radius);
            let due = (free / self.lattice.step / self.shot_ratio).floor() as u64;
            since_shot = since_shot.saturating_add(1);
            if since_shot > due {
                since_shot = 0;
                for pts in self.shots(s.pose) {
                    match self.price(&pts, s.t, &mut out.motion_checks, Some(termination)) {
                        Ok((c, _)) => {
                            let g = s.g + c;
                            if goal.as_ref().is_none_or(|best| g < best.g) {
                                goal = Some(Shot { from: u as u32, points: pts, g });
                                open.push(Open { f: g, g, id: NONE });
                            }
                            break;
                        }
                        Err(Check::Invalid) => {}
                        Err(Check::Interrupted(r)) => {
                            out.stopped = Some(r);
                            break;
                        }
                    }
                }
                if out.stopped.is_some() {
                    break out.stopped;
                }
            }
            let key_u = self.key(s.pose);
            for (j, prim) in self.lattice.primitives.iter().enumerate() {
                prim.place(s.pose, &mut scratch);
                let end = Pose::new(*scratch.last().expect("a primitive has points"), s.pose.heading + prim.sweep);
                let key = self.key(end);
                if key == key_u {
                    continue;
                }
                let existing = index.get(&key).copied();
                if let Some(v) = existing {
                    let v = &states[v as usize];
                    if v.closed || v.g <= s.g + prim_bounds[j] {
                        continue;
                    }
                }
                let Some(h) = self.length_bound(end) else { continue };
                let (c, t) = match self.price(&scratch, s.t, &mut out.motion_checks, None) {
                    Ok(ct) => ct,
                    Err(_) => continue,
                };
                out.edges += 1;
                let g = s.g + c;
                let state = State { pose: end, t, g, parent: u as u32, primitive: j as u16, closed: false };
                let id = match existing {
                    Some(v) if g < states[v as usize].g => {
                        states[v as usize] = state;
                        v
                    }
                    Some(_) => continue,
                    None => {
                        let id = states.len() as u32;
                        index.insert(key, id);
                        states.push(state);
                        id
                    }
                };
                open.push(Open { f: g + self.h(h), g, id });
            }
        };
        out.stopped = out.stopped.or(stop);
        out.states = states.len() as u64;
        if out.found {
            let shot = goal.expect("found through a shot");
            let chain = self.chain(&states, shot.from);
            let poses: Vec<Pose> = chain.iter().map(|&c| states[c as usize].pose).collect();
            let g: Vec<f64> = chain.iter().map(|&c| states[c as usize].g).collect();
            out.path = match self.shortcut(&poses, &g, shot.g, &mut out.motion_checks, termination) {
                Some(p) => p,
                None => {
                    let mut p = self.path_to(&states, shot.from);
                    p.extend(shot.points.into_iter().skip(1));
                    p
                }
            };
        } else if out.stopped.is_some() || out.full {
            if let Some((_, u)) = nearest {
                out.path = self.path_to(&states, u);
            }
        }
        out
    }

    /// The states from the start to `u`.
    fn chain(&self, states: &[State], u: u32) -> Vec<u32> {
        let mut chain = Vec::new();
        let mut c = u;
        while c != NONE {
            chain.push(c);
            c = states[c as usize].parent;
        }
        chain.reverse();
        chain
    }

    /// The tangent polygon from the start to state `u`, primitive by primitive.
    fn path_to(&self, states: &[State], u: u32) -> Vec<Vec3> {
        let chain = self.chain(states, u);
        let mut out = vec![self.start];
        let mut scratch = Vec::new();
        for w in chain.windows(2) {
            let (from, to) = (&states[w[0] as usize], &states[w[1] as usize]);
            self.lattice.primitives[to.primitive as usize].place(from.pose, &mut scratch);
            out.extend(scratch.iter().skip(1));
        }
        out
    }
}
