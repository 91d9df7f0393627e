//! The search's two lower bounds on the horizontal length still to fly, and the turn-then-
//! straight curves the first one is made of.
//!
//! * **Free-heading Dubins length** ([`free_heading_length`]): the shortest curve of curvature
//!   at most 1/r from a pose to the goal *point*, the final heading being free (the goal of a
//!   mission has none). When the goal lies outside both turning circles of the pose it is a turn
//!   on one of them followed by the tangent straight to the goal, the shorter of the two (Bui,
//!   Boissonnat, Souères & Laumond 1994 on Dubins' problem with a free end heading); when it
//!   lies inside one, the straight distance stands in (a lower bound; such goals are within 2r).
//!   Every path this planner returns is a curve of curvature at most 1/r (arcs of radius r and
//!   straights) ending at the goal, so its horizontal length is at least this.
//! * **Hop distance** ([`Hops`]): a breadth-first count of 8-connected moves (diagonals allowed
//!   between any two free cells) from each column of the optimistic raster to the goal's, where
//!   a column is free when any of its voxels in the depth band is (a blocked cell is blocked
//!   everywhere in it, [`crate::raster`]). Sample a valid curve of horizontal length L every
//!   s = min(dx, dy) metres: consecutive samples differ by at most one column index along each
//!   axis, and every sampled column holds a valid point, so is free; the curve is therefore
//!   followed by at most ceil(L / s) moves and L > s (H - 1) for the column's hop count H.
//!   8-connected *distances* (1 and sqrt 2 per move) divided by their free-space overestimate
//!   (1.0824) are not a bound: along a one-cell-wide diagonal staircase of free cells a curve
//!   needs sqrt 2 per cell where the grid without corner cutting needs 2.
//!
//! The heuristic is the larger of the two and of |dz| / tan(pitch limit) (every piece keeps
//! within the pitch limit, so the horizontal length is at least that for a height change dz),
//! combined with dz (sqrt(h^2 + dz^2), by Minkowski's inequality a bound on the 3-D length),
//! and turned into a cost by the cost model's own lower bound at the best ground speed the
//! current allows.

use std::collections::VecDeque;
use std::f64::consts::{FRAC_PI_2, TAU};

use crate::geom::{Vec2, Vec3};
use crate::kinematics::Pose;
use crate::raster::Raster;

/// A turn of `sweep` rad (>= 0) on the circle of side `side` (+1 left, -1 right), then a
/// straight of `straight` metres: a Dubins curve to a point with a free end heading.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurnStraight {
    pub side: i8,
    pub sweep: f64,
    pub straight: f64,
}

impl TurnStraight {
    /// Horizontal length with radius `r`.
    pub fn length(&self, r: f64) -> f64 {
        r * self.sweep + self.straight
    }
}

/// The goal in the frame of the pose: `x` ahead, `y` to the left.
#[inline]
fn local(from: Pose, goal: Vec2) -> (f64, f64) {
    let d = goal - from.p.truncate();
    let (s, c) = from.heading.sin_cos();
    (d.x * c + d.y * s, -d.x * s + d.y * c)
}

/// The turn on side `side` then the tangent straight to `goal`, or `None` when the goal lies
/// strictly inside that turning circle (no such curve).
pub fn turn_then_straight(from: Pose, goal: Vec2, r: f64, side: i8) -> Option<TurnStraight> {
    let (x, y) = local(from, goal);
    // Mirrored so the turn is to the left, round the centre (0, r).
    let y = f64::from(side) * y;
    let (cx, cy) = (x, y - r);
    let dc2 = cx * cx + cy * cy;
    if dc2 < r * r {
        return None;
    }
    let t = (dc2 - r * r).max(0.0).sqrt();
    // The tangent point's angle about the centre: the goal's minus the angle the straight adds.
    let beta = cy.atan2(cx) - t.atan2(r);
    // The vehicle starts at angle -pi/2 about the centre and turns counter-clockwise.
    let mut sweep = (beta + FRAC_PI_2).rem_euclid(TAU);
    // A sweep within rounding of a full turn is no turn.
    if TAU - sweep < 1e-12 {
        sweep = 0.0;
    }
    Some(TurnStraight { side, sweep, straight: t })
}

/// A lower bound on the horizontal length of any curve of curvature at most 1/r from `from` to
/// `goal` (any final heading); exact when the goal lies outside both turning circles.
pub fn free_heading_length(from: Pose, goal: Vec2, r: f64) -> f64 {
    match (turn_then_straight(from, goal, r, 1), turn_then_straight(from, goal, r, -1)) {
        (Some(a), Some(b)) => a.length(r).min(b.length(r)),
        _ => from.p.truncate().distance(goal),
    }
}

/// Hop counts to the goal's column over the optimistic raster's free columns.
pub struct Hops {
    nx: usize,
    ny: usize,
    x0: f64,
    y0: f64,
    dx: f64,
    dy: f64,
    hops: Vec<u32>,
    /// The sampling step s = min(dx, dy) of the bound.
    step: f64,
}

/// Not connected to the goal's column.
pub const UNREACHED: u32 = u32::MAX;

impl Hops {
    /// Counts hops from every column of `raster` to the column holding `goal`; `None` when
    /// `interrupted` says so (polled every few thousand columns).
    pub fn new(raster: &Raster, goal: Vec3, interrupted: &dyn Fn() -> bool) -> Option<Self> {
        let (nx, ny) = (raster.nx, raster.ny);
        let layer = nx * ny;
        // A column is free when any of its voxels is.
        let mut free = vec![false; layer];
        for k in 0..raster.nz {
            for (c, f) in free.iter_mut().enumerate() {
                *f |= !raster.optimistic[c + layer * k];
            }
        }
        let mut hops = vec![UNREACHED; layer];
        let g = raster.cell_of(goal) % layer;
        // The goal is a valid point, so its column is free; set it regardless.
        hops[g] = 0;
        let mut queue = VecDeque::from([g]);
        let mut popped = 0u64;
        while let Some(c) = queue.pop_front() {
            popped += 1;
            if popped % 4096 == 0 && interrupted() {
                return None;
            }
            let (i, j) = ((c % nx) as isize, (c / nx) as isize);
            let next = hops[c] + 1;
            for dj in -1..=1isize {
                for di in -1..=1isize {
                    let (a, b) = (i + di, j + dj);
                    if (di, dj) == (0, 0) || a < 0 || b < 0 || a >= nx as isize || b >= ny as isize {
                        continue;
                    }
                    let n = a as usize + nx * b as usize;
                    if free[n] && hops[n] == UNREACHED {
                        hops[n] = next;
                        queue.push_back(n);
                    }
                }
            }
        }
        Some(Self {
            nx,
            ny,
            x0: raster.x0,
            y0: raster.y0,
            dx: raster.dx,
            dy: raster.dy,
            hops,
            step: raster.dx.min(raster.dy),
        })
    }

    /// The column holding `p` (clamped to the grid, as [`Raster::cell_of`]).
    fn column(&self, p: Vec3) -> usize {
        let f = |v: f64, o: f64, d: f64, n: usize| (((v - o) / d).floor().max(0.0) as usize).min(n - 1);
        f(p.x, self.x0, self.dx, self.nx) + self.nx * f(p.y, self.y0, self.dy, self.ny)
    }

    /// A lower bound on the horizontal length of any valid curve from `p` to the goal, or
    /// `None` when `p`'s column is not connected to the goal's (no curve exists).
    pub fn bound(&self, p: Vec3) -> Option<f64> {
        let h = self.hops[self.column(p)];
        (h != UNREACHED).then(|| self.step * (f64::from(h) - 1.0).max(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Aabb;
    use crate::vehicle::Vehicle;
    use crate::world::{Current, Dims, Obstacle, Shape, Terrain, World};

    #[test]
    fn the_hop_bound_sees_the_detour_round_a_wall_and_stays_below_it() {
        // A wall from the bottom edge to y = 900 between start and goal: every path goes round
        // its top, at least 2 sqrt(380^2 + 800^2) + 40 = 1811 m; the straight line is 800 m.
        let w = World {
            waves: Default::default(),
            bounds: Aabb::new(Vec3::ZERO, Vec3::new(1000.0, 1000.0, 0.0)),
            dims: Dims::Two,
            terrain: Terrain::None,
            obstacles: vec![Obstacle::fixed(Shape::Box {
                min: Vec3::new(480.0, -10.0, -10.0),
                max: Vec3::new(520.0, 900.0, 10.0),
            })],
            current: Current::None,
            frame: None,
        };
        let v = Vehicle { safety_distance: 0.0, ..Vehicle::default() };
        let (start, goal) = (Vec3::new(100.0, 100.0, 0.0), Vec3::new(900.0, 100.0, 0.0));
        let shortest = 2.0 * (380f64.powi(2) + 800f64.powi(2)).sqrt() + 40.0;
        // (A cell is blocked only when all of it is: cells of 20 m or less see the 40 m wall.)
        for cell in [5.0, 10.0, 20.0] {
            let raster = Raster::new(&w, &v, cell, 1.0, 0.0).unwrap();
            let hops = Hops::new(&raster, goal, &|| false).unwrap();
            let b = hops.bound(start).unwrap();
            // Below the shortest path, and well above the straight line (the Chebyshev count
            // loses up to 1 - 1 / sqrt 2 on diagonal legs, 10 % on these).
            assert!(b <= shortest && b > 0.85 * shortest, "{cell} m cells: {b} vs {shortest}");
            // Where start and goal share a column, nothing is claimed.
            assert_eq!(hops.bound(goal), Some(0.0));
        }
        // A wall across the whole domain leaves the start's column unreached.
        let mut closed = w.clone();
        closed.obstacles[0] =
            Obstacle::fixed(Shape::Box { min: Vec3::new(480.0, -10.0, -10.0), max: Vec3::new(520.0, 1010.0, 10.0) });
        let raster = Raster::new(&closed, &v, 10.0, 1.0, 0.0).unwrap();
        assert_eq!(Hops::new(&raster, goal, &|| false).unwrap().bound(start), None);
    }
}
