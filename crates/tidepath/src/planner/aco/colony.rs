//! The ants' graph and tours (acopf2016 steps 3-7): each ant starts on the start cell with a
//! tabu list holding it, chooses each next cell by roulette over its allowed neighbours with
//! p_ij ∝ τ_ij^α η_ij^β (A14), and ends on the goal or in a dead end (no allowed neighbour:
//! the ant is discarded, A9).
//!
//! The graph is the raster search's ([`super::super::raster_search`]): free cells of the
//! conservative raster, 8-connected without corner cutting (a diagonal needs both orthogonal
//! neighbours free, the rule of [`tidepath_search::Grid2`], A12), the mission's start and goal
//! points in place of their cells' centres. A neighbour is allowed when it is not tabu, the turn
//! into it keeps the vehicle's turn limit ([`crate::planner::sampling::Kinematics`]), and the
//! move is priced (the shared validator accepts it at the ant's clock); a move refused by
//! pricing is dropped from the roulette and the draw repeated.
//!
//! With `lookahead` (tidepath's, on by default) an ant also looks one step ahead: it does not
//! enter a cell it could not leave (every neighbour tabu, blocked, or past the turn limit with
//! the heading it would arrive with). On rasters of hundreds of cells the 1/L heuristic barely
//! differs between neighbours near an obstacle, and a walk that is nearly random traps itself
//! in its own trail; under a 45-degree turn limit every coast met head-on is such a trap.
//! Larger traps remain, and their ants are discarded as the paper's (A9).

use rand::Rng as _;

use super::pheromone::Tours;
use crate::geom::Vec3;
use crate::planner::raster_search::RasterSearch;
use crate::planner::sampling::Kinematics;
use crate::termination::StopReason;

/// The eight moves, by direction index: E, N, W, S, NE, NW, SW, SE. Edge `e` of the directed
/// graph is `8 c + d`: the move out of cell `c` in direction `d`.
pub const DIRS: [(isize, isize); 8] = [(1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (-1, 1), (-1, -1), (1, -1)];

/// The ants' graph on one mission's raster.
#[derive(Clone, Debug)]
pub struct Graph {
    pub nx: usize,
    pub ny: usize,
    /// Lower-left corner of the raster (z: the mission's plane) and the cell sizes (m).
    pub origin: Vec3,
    pub dx: f64,
    pub dy: f64,
    /// Cells an ant may not enter (the start's and goal's cells are always free).
    pub blocked: Vec<bool>,
    /// Bit d set: the move in direction d is in the graph.
    pub masks: Vec<u8>,
    pub start: usize,
    pub goal: usize,
    pub start_point: Vec3,
    pub goal_point: Vec3,
}

impl Graph {
    /// The graph of an `nx` x `ny` grid with these blocked cells (start and goal freed).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        nx: usize,
        ny: usize,
        origin: Vec3,
        (dx, dy): (f64, f64),
        mut blocked: Vec<bool>,
        (start, goal): (usize, usize),
        start_point: Vec3,
        goal_point: Vec3,
    ) -> Self {
        blocked[start] = false;
        blocked[goal] = false;
        let mut g = Graph { nx, ny, origin, dx, dy, blocked, masks: Vec::new(), start, goal, start_point, goal_point };
        g.masks = (0..nx * ny).map(|c| g.mask_of(c)).collect();
        g
    }

    /// The graph of a raster search (2-D).
    pub fn of(rs: &RasterSearch<'_>) -> Self {
        let r = &rs.raster;
        Self::new(
            r.nx,
            r.ny,
            Vec3::new(r.x0, r.y0, r.z0),
            (r.dx, r.dy),
            r.conservative.clone(),
            (rs.start, rs.goal),
            rs.point(rs.start),
            rs.point(rs.goal),
        )
    }

    /// The allowed moves out of `c` (none out of a blocked cell), by the box rule.
    fn mask_of(&self, c: usize) -> u8 {
        if self.blocked[c] {
            return 0;
        }
        let (i, j) = ((c % self.nx) as isize, (c / self.nx) as isize);
        let free = |di: isize, dj: isize| {
            let (a, b) = (i + di, j + dj);
            a >= 0 && b >= 0 && (a as usize) < self.nx && (b as usize) < self.ny && !self.blocked[self.cell(a, b)]
        };
        let mut m = 0u8;
        for (d, &(di, dj)) in DIRS.iter().enumerate() {
            let ok = if di != 0 && dj != 0 { free(di, 0) && free(0, dj) && free(di, dj) } else { free(di, dj) };
            if ok {
                m |= 1 << d;
            }
        }
        m
    }

    fn cell(&self, i: isize, j: isize) -> usize {
        i as usize + self.nx * j as usize
    }

    pub fn len(&self) -> usize {
        self.blocked.len()
    }

    pub fn is_empty(&self) -> bool {
        self.blocked.is_empty()
    }

    /// Metres per cell in the heuristic's distances: the mean cell edge.
    pub fn unit(&self) -> f64 {
        0.5 * (self.dx + self.dy)
    }

    pub fn centre(&self, c: usize) -> Vec3 {
        let (i, j) = (c % self.nx, c / self.nx);
        Vec3::new(self.origin.x + (i as f64 + 0.5) * self.dx, self.origin.y + (j as f64 + 0.5) * self.dy, self.origin.z)
    }

    /// The point cell `c` stands for: the mission's start and goal in their own cells.
    #[inline]
    pub fn point(&self, c: usize) -> Vec3 {
        if c == self.start {
            self.start_point
        } else if c == self.goal {
            self.goal_point
        } else {
            self.centre(c)
        }
    }

    /// The cell holding `p` (clamped to the grid).
    pub fn cell_of(&self, p: Vec3) -> usize {
        let f = |v: f64, o: f64, d: f64, n: usize| (((v - o) / d).floor().max(0.0) as usize).min(n - 1);
        f(p.x, self.origin.x, self.dx, self.nx) + self.nx * f(p.y, self.origin.y, self.dy, self.ny)
    }

    /// The cell reached from `c` in direction `d` (the move must be in the graph).
    #[inline]
    pub fn neighbour(&self, c: usize, d: usize) -> usize {
        let (di, dj) = DIRS[d];
        (c as isize + di + dj * self.nx as isize) as usize
    }

    /// The direction taking `a` to its 8-neighbour `b`, if the move is in the graph.
    pub fn direction(&self, a: usize, b: usize) -> Option<usize> {
        (0..8).find(|&d| self.masks[a] & (1 << d) != 0 && self.neighbour(a, d) == b)
    }

    /// Directed edges in the graph.
    pub fn edge_count(&self) -> u64 {
        self.masks.iter().map(|m| u64::from(m.count_ones())).sum()
    }

    /// Whether the goal can be reached from the start on the graph (ignoring tabu, turns and
    /// pricing); `None` when `stop` (polled every 4096 cells) asked to stop.
    pub fn connected(&self, stop: &dyn Fn() -> bool) -> Option<bool> {
        let mut seen = vec![false; self.len()];
        let mut queue = vec![self.start];
        seen[self.start] = true;
        let mut n = 0usize;
        while let Some(c) = queue.pop() {
            n += 1;
            if n % 4096 == 0 && stop() {
                return None;
            }
            if c == self.goal {
                return Some(true);
            }
            for d in 0..8 {
                if self.masks[c] & (1 << d) != 0 {
                    let v = self.neighbour(c, d);
                    if !seen[v] {
                        seen[v] = true;
                        queue.push(v);
                    }
                }
            }
        }
        Some(false)
    }
}

/// The index chosen by a roulette over `weights` (summing to `total`) for a uniform draw
/// `u` in [0, 1): the first k whose running sum exceeds u·total. Weights that are all zero
/// (or a total that is not finite) give every index the same chance.
pub fn roulette(weights: &[f64], total: f64, u: f64) -> usize {
    let n = weights.len();
    if !(total > 0.0 && total.is_finite()) {
        return ((u * n as f64) as usize).min(n - 1);
    }
    let target = u * total;
    let mut sum = 0.0;
    for (k, &w) in weights.iter().enumerate() {
        sum += w;
        if target < sum {
            return k;
        }
    }
    // Rounding left the target at the very end: the last index with weight.
    weights.iter().rposition(|&w| w > 0.0).unwrap_or(n - 1)
}

/// How a tour ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TourEnd {
    /// On the goal, with the summed price of its moves and the arrival time.
    Goal { cost: f64, arrival: f64 },
    /// No allowed neighbour: discarded (A9).
    DeadEnd,
    /// The budget or the stop flag ended the tour.
    Stopped(StopReason),
}

/// One ant's buffers, reused by every ant of a run: the tabu list and the tour (no allocation
/// per step or per ant).
pub struct Walker {
    tabu: Vec<bool>,
    /// Look one step ahead: never enter a cell the ant could not leave.
    pub lookahead: bool,
    /// The cells of the last tour, start first.
    pub cells: Vec<usize>,
    /// Its directed edges (`8 c + d`).
    pub edges: Vec<u32>,
}

impl Walker {
    pub fn new(cells: usize, lookahead: bool) -> Self {
        Self { tabu: vec![false; cells], lookahead, cells: Vec::new(), edges: Vec::new() }
    }

    /// Whether an ant entering `v` from the point `from` could leave it: some neighbour of `v`
    /// not tabu whose move keeps the turn limit.
    fn can_leave(&self, g: &Graph, kinematics: &Kinematics, from: Vec3, v: usize) -> bool {
        let pv = g.point(v);
        (0..8).any(|d| {
            g.masks[v] & (1 << d) != 0 && {
                let w = g.neighbour(v, d);
                !self.tabu[w] && kinematics.joint_ok(Some(from), pv, g.point(w))
            }
        })
    }

    /// One ant's tour. `tau` holds the pheromone per directed edge, `weight(e, t)` gives
    /// η_e^β for edge e entered at time t, `price(u, v, e, t)` the move's cost and arrival
    /// time (`None`: refused), `step()` is polled before every step (the budget: `Some`
    /// stops the tour).
    #[allow(clippy::too_many_arguments)]
    pub fn tour(
        &mut self,
        g: &Graph,
        tau: &[f64],
        alpha: f64,
        kinematics: &Kinematics,
        departure: f64,
        weight: &mut impl FnMut(usize, f64) -> f64,
        price: &mut impl FnMut(usize, usize, usize, f64) -> Option<(f64, f64)>,
        step: &mut impl FnMut() -> Option<StopReason>,
        rng: &mut crate::rng::Rng,
    ) -> TourEnd {
        for &c in &self.cells {
            self.tabu[c] = false;
        }
        self.cells.clear();
        self.edges.clear();
        let (mut u, mut t, mut cost) = (g.start, departure, 0.0);
        self.tabu[u] = true;
        self.cells.push(u);
        let mut prev: Option<Vec3> = None;
        let (mut dirs, mut w) = ([0u8; 8], [0.0f64; 8]);
        loop {
            if u == g.goal {
                return TourEnd::Goal { cost, arrival: t };
            }
            if let Some(r) = step() {
                return TourEnd::Stopped(r);
            }
            let pu = g.point(u);
            let mut n = 0;
            for d in 0..8 {
                if g.masks[u] & (1 << d) == 0 {
                    continue;
                }
                let v = g.neighbour(u, d);
                if self.tabu[v] || !kinematics.joint_ok(prev, pu, g.point(v)) {
                    continue;
                }
                // A cell the ant could not leave (its own trail, a coast met head-on under a
                // turn limit) is a dead end one step ahead.
                if self.lookahead && v != g.goal && !self.can_leave(g, kinematics, pu, v) {
                    continue;
                }
                let e = 8 * u + d;
                let p = if alpha == 1.0 { tau[e] } else { tau[e].powf(alpha) };
                dirs[n] = d as u8;
                w[n] = p * weight(e, t);
                n += 1;
            }
            let moved = loop {
                if n == 0 {
                    return TourEnd::DeadEnd;
                }
                let total: f64 = w[..n].iter().sum();
                let k = roulette(&w[..n], total, rng.random::<f64>());
                let d = usize::from(dirs[k]);
                let v = g.neighbour(u, d);
                match price(u, v, 8 * u + d, t) {
                    Some((c, arrival)) => break (d, v, c, arrival),
                    None => {
                        // Refused at this clock: out of this roulette.
                        n -= 1;
                        dirs[k] = dirs[n];
                        w[k] = w[n];
                    }
                }
            };
            let (d, v, c, arrival) = moved;
            self.edges.push((8 * u + d) as u32);
            self.cells.push(v);
            self.tabu[v] = true;
            cost += c;
            t = arrival;
            prev = Some(pu);
            u = v;
        }
    }
}

/// What the colony's tours share within a mission: the graph, the turn limit, the pheromone
/// exponent, the departure time and the price of one cell (L_k is the tour's cost over it).
pub struct Colony<'g> {
    pub graph: &'g Graph,
    pub kinematics: Kinematics,
    pub alpha: f64,
    pub departure: f64,
    pub unit: f64,
}

impl Colony<'_> {
    /// One iteration's `ants` tours (steps 3-7): each completed tour goes into `tours` with
    /// L = cost / unit, and replaces `best` (cost, cells) when cheaper; a dead end is dropped.
    /// Returns the number of dead ends, or why the budget stopped the iteration.
    #[allow(clippy::too_many_arguments)]
    pub fn iteration(
        &self,
        ants: usize,
        walker: &mut Walker,
        tau: &[f64],
        tours: &mut Tours,
        best: &mut (f64, Vec<usize>),
        weight: &mut impl FnMut(usize, f64) -> f64,
        price: &mut impl FnMut(usize, usize, usize, f64) -> Option<(f64, f64)>,
        step: &mut impl FnMut() -> Option<StopReason>,
        rng: &mut crate::rng::Rng,
    ) -> Result<usize, StopReason> {
        tours.clear();
        let mut dead = 0;
        for _ in 0..ants {
            let g = self.graph;
            match walker.tour(g, tau, self.alpha, &self.kinematics, self.departure, weight, price, step, rng) {
                TourEnd::Goal { cost, .. } => {
                    tours.push(&walker.edges, (cost / self.unit).max(1e-12));
                    if cost < best.0 {
                        best.0 = cost;
                        best.1.clone_from(&walker.cells);
                    }
                }
                TourEnd::DeadEnd => dead += 1,
                TourEnd::Stopped(r) => return Err(r),
            }
        }
        Ok(dead)
    }
}
