//! World changes as data: what changes (an obstacle moves, changes course, appears or
//! disappears; a vortex moves or changes strength; a newer current forecast replaces the old
//! one) and when it is revealed (a clock time, or a distance travelled along the route).
//!
//! A mission loop applies each change to the world the planner knows when its trigger fires,
//! so the planner only ever sees what has been revealed. A change may be drawn at random (a
//! Gaussian or uniform displacement of a centre, clipped to the domain), always from the
//! run's own `&mut Rng` so the same seed gives the same changes; a draw that would cover the
//! vehicle or its goal is redrawn, and after too many draws the change is skipped and said so
//! (lfhh2019 redraws "safe rectangles" at most 100 times, see docs/papers/lfhh2019.md A9).

mod random;
#[cfg(test)]
mod tests;

pub use random::{Law, RandomShift};

use super::{Current, Obstacle, Shape, World};
use crate::error::{Error, Result};
use crate::geom::{Vec2, Vec3};
use crate::rng::Rng;

/// When a change is revealed to the vehicle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Trigger {
    /// At this time on the scenario clock (s).
    AtTime(f64),
    /// Once the vehicle has travelled this far along its route since departure (m).
    AfterDistance(f64),
}

/// What changes. Obstacle and vortex indices are positions in the world's lists as they are
/// when the change applies: removing an obstacle shifts the indices of those after it.
#[derive(Clone, Debug, PartialEq)]
pub enum ChangeKind {
    /// Obstacle `index` is at `center` at the change's time (keeping its velocity). For a
    /// circle or a full-depth cylinder only x and y matter.
    MoveObstacle {
        index: usize,
        center: Vec3,
    },
    /// Obstacle `index` keeps its place at the change's time and moves on at `velocity`.
    ObstacleVelocity {
        index: usize,
        velocity: Vec3,
    },
    /// A new obstacle; like every obstacle it is given by its place at time 0.
    AddObstacle(Obstacle),
    RemoveObstacle {
        index: usize,
    },
    /// Vortex `index` of a `Current::Vortices` has a new centre.
    MoveVortex {
        index: usize,
        center: Vec2,
    },
    /// Vortex `index` has a new circulation strength (m^2/s).
    VortexStrength {
        index: usize,
        strength: f64,
    },
    /// A newer forecast replaces the current.
    ReplaceCurrent(Current),
}

/// One change: its trigger, what it does and, optionally, a random displacement of the
/// centre it sets (only for `MoveObstacle`, `AddObstacle` and `MoveVortex`).
#[derive(Clone, Debug, PartialEq)]
pub struct Change {
    pub trigger: Trigger,
    pub kind: ChangeKind,
    pub random: Option<RandomShift>,
}

/// What applying a change did.
#[derive(Clone, Debug, PartialEq)]
pub struct AppliedChange {
    /// One line for reports: "obstacle 2 moved to [300.0, 120.0, 0.0] at t = 200.0 s".
    pub description: String,
    /// The change as applied, random displacement resolved (so a caller can replay it).
    pub resolved: ChangeKind,
    /// Random draws taken (0 for a fixed change).
    pub draws: u32,
    /// Why the change was not applied (every draw covered the vehicle or the goal); the
    /// world is then unchanged.
    pub skipped: Option<String>,
}

impl Change {
    /// Applies the change to `world` at time `at_time`, with the vehicle at `vehicle_pos`
    /// heading for `goal`; random draws keep `safety` metres from both and come from `rng`.
    /// Errors name what is wrong with the change (an index out of range, a vortex change on a
    /// current without vortices, a random shift on a change without a centre).
    pub fn apply(
        &self,
        world: &mut World,
        at_time: f64,
        vehicle_pos: Vec3,
        goal: Vec3,
        safety: f64,
        rng: &mut Rng,
    ) -> Result<AppliedChange> {
        if !at_time.is_finite() {
            return Err(Error::input("changes", format!("the change time must be finite, got {at_time}")));
        }
        let Some(shift) = &self.random else {
            let resolved = self.kind.clone();
            let description = resolved.apply_to(world, at_time)?;
            return Ok(AppliedChange { description, resolved, draws: 0, skipped: None });
        };
        shift.check()?;
        let dims3 = world.dims == super::Dims::Three;
        for draw in 1..=shift.max_draws {
            let d = shift.draw(rng, dims3);
            let resolved = self.kind.displaced(d, world, at_time, shift.from_current)?;
            let mut trial = world.clone();
            let description = resolved.apply_to(&mut trial, at_time)?;
            if resolved.covers(&trial, at_time, [vehicle_pos, goal], safety) {
                continue;
            }
            *world = trial;
            return Ok(AppliedChange { description, resolved, draws: draw, skipped: None });
        }
        let why = format!(
            "skipped: all {} random draws put the obstacle within {safety} m of the vehicle or its goal",
            shift.max_draws
        );
        Ok(AppliedChange {
            description: why.clone(),
            resolved: self.kind.clone(),
            draws: shift.max_draws,
            skipped: Some(why),
        })
    }
}

impl ChangeKind {
    /// Applies this (resolved) change to `world` at `t` and describes it.
    pub fn apply_to(&self, world: &mut World, t: f64) -> Result<String> {
        let n = world.obstacles.len();
        Ok(match self {
            ChangeKind::MoveObstacle { index, center } => {
                move_to(obstacle(world, *index)?, *center, t);
                format!("obstacle {index} moved to {} at t = {t:.1} s", world.point(*center))
            }
            ChangeKind::ObstacleVelocity { index, velocity } => {
                let o = obstacle(world, *index)?;
                // Its place at t stays; the time-0 reference is where the new course puts it.
                o.shape = o.shape_at(t).translated(-at_time(*velocity, t));
                o.velocity = *velocity;
                format!(
                    "obstacle {index} now moves at [{:.2}, {:.2}, {:.2}] m/s from t = {t:.1} s",
                    velocity.x, velocity.y, velocity.z
                )
            }
            ChangeKind::AddObstacle(o) => {
                world.obstacles.push(o.clone());
                let c = center(&o.shape_at(t));
                format!("obstacle {n} appeared at {} at t = {t:.1} s", world.point(c))
            }
            ChangeKind::RemoveObstacle { index } => {
                obstacle(world, *index)?;
                world.obstacles.remove(*index);
                format!("obstacle {index} disappeared at t = {t:.1} s")
            }
            ChangeKind::MoveVortex { index, center } => {
                let v = vortex(world, *index)?;
                (v.x, v.y) = (center.x, center.y);
                format!("vortex {index} moved to {} at t = {t:.1} s", world.place(center.x, center.y))
            }
            ChangeKind::VortexStrength { index, strength } => {
                if !strength.is_finite() {
                    return Err(Error::input("changes", format!("vortex strength must be finite, got {strength}")));
                }
                vortex(world, *index)?.strength = *strength;
                format!("vortex {index} strength now {strength} m^2/s at t = {t:.1} s")
            }
            ChangeKind::ReplaceCurrent(c) => {
                world.current = c.clone();
                format!("a new current forecast arrived at t = {t:.1} s")
            }
        })
    }

    /// This change with its centre displaced by `d` and clipped to the domain (the centre an
    /// obstacle has at `t`, for moves and appearances). With `from_current`, a move displaces
    /// the centre the obstacle or vortex has at `t` instead of the written one.
    fn displaced(&self, d: Vec3, world: &World, t: f64, from_current: bool) -> Result<ChangeKind> {
        let (lo, hi) = (world.bounds.min, world.bounds.max);
        Ok(match self {
            ChangeKind::MoveObstacle { index, center } => {
                let base = if from_current {
                    let n = world.obstacles.len();
                    let o = world.obstacles.get(*index).ok_or_else(|| out_of_range("obstacle", *index, n))?;
                    self::center(&o.shape_at(t))
                } else {
                    *center
                };
                ChangeKind::MoveObstacle { index: *index, center: (base + d).clamp(lo, hi) }
            }
            ChangeKind::AddObstacle(o) => {
                let mut o = o.clone();
                let c = center(&o.shape_at(t));
                move_to(&mut o, (c + d).clamp(lo, hi), t);
                ChangeKind::AddObstacle(o)
            }
            ChangeKind::MoveVortex { index, center } => {
                let base = match (&world.current, from_current) {
                    (Current::Vortices(v), true) => {
                        let n = v.len();
                        let v = v.get(*index).ok_or_else(|| out_of_range("vortex", *index, n))?;
                        Vec2::new(v.x, v.y)
                    }
                    _ => *center,
                };
                let c = (base + d.truncate()).clamp(lo.truncate(), hi.truncate());
                ChangeKind::MoveVortex { index: *index, center: c }
            }
            _ => {
                return Err(Error::input(
                    "changes",
                    "a random shift needs a change that sets a centre (an obstacle move or appearance, a vortex move)",
                ))
            }
        })
    }

    /// Whether the obstacle this change placed comes within `safety` of any of `points` at `t`
    /// (a vortex covers nothing).
    fn covers(&self, world: &World, t: f64, points: [Vec3; 2], safety: f64) -> bool {
        let o = match self {
            ChangeKind::MoveObstacle { index, .. } => &world.obstacles[*index],
            ChangeKind::AddObstacle(_) => world.obstacles.last().expect("just added"),
            _ => return false,
        };
        points.iter().any(|&p| o.contains(p, t, safety))
    }
}

/// `velocity * t`, with axes it does not move along left at exactly 0 (as `shape_at` does).
fn at_time(velocity: Vec3, t: f64) -> Vec3 {
    Vec3::select(velocity.cmpeq(Vec3::ZERO), Vec3::ZERO, velocity * t)
}

/// Sets the obstacle's time-0 reference so that at time `t` its centre is `c`: the shape
/// with its centre at `c`, moved back by velocity * t (a fixed obstacle's centre becomes
/// exactly `c`).
fn move_to(o: &mut Obstacle, c: Vec3, t: f64) {
    let placed = match o.shape {
        Shape::Sphere { radius, .. } => Shape::Sphere { center: c, radius },
        Shape::Circle { radius, .. } => Shape::Circle { center: c.truncate(), radius },
        Shape::Cylinder { radius, z_min, z_max, .. } => {
            let dz = if (z_min + z_max).is_finite() { c.z - 0.5 * (z_min + z_max) } else { 0.0 };
            Shape::Cylinder { center: c.truncate(), radius, z_min: z_min + dz, z_max: z_max + dz }
        }
        Shape::Box { min, max } => {
            let half = 0.5 * (max - min);
            Shape::Box { min: c - half, max: c + half }
        }
    };
    o.shape = placed.translated(-at_time(o.velocity, t));
}

/// A shape's centre; z is 0 for circles and for cylinders without a finite height (a move
/// ignores their z).
pub fn center(s: &Shape) -> Vec3 {
    match *s {
        Shape::Sphere { center, .. } => center,
        Shape::Cylinder { center, z_min, z_max, .. } => {
            let z = 0.5 * (z_min + z_max);
            center.extend(if z.is_finite() { z } else { 0.0 })
        }
        Shape::Box { min, max } => 0.5 * (min + max),
        Shape::Circle { center, .. } => center.extend(0.0),
    }
}

/// Obstacle `index` of the world, or an error naming it.
fn obstacle(world: &mut World, index: usize) -> Result<&mut Obstacle> {
    let n = world.obstacles.len();
    world.obstacles.get_mut(index).ok_or_else(|| out_of_range("obstacle", index, n))
}

fn vortex(world: &mut World, index: usize) -> Result<&mut super::current::LambOseen> {
    match &mut world.current {
        Current::Vortices(v) => {
            let n = v.len();
            v.get_mut(index).ok_or_else(|| out_of_range("vortex", index, n))
        }
        _ => Err(Error::input("changes", "a vortex change needs a current made of vortices")),
    }
}

fn out_of_range(what: &str, index: usize, n: usize) -> Error {
    Error::input("changes", format!("{what} {index} does not exist (the world has {n} {what}s at this change)"))
}
