//! The cheap, sound check every planner gets before it runs: is the goal reachable at all for
//! this vehicle? On an optimistic rasterisation (a cell counts as blocked only if it is blocked
//! everywhere, see [`crate::raster`]) the maximin path between start and goal gives the deepest
//! water any route must cross; if even that is too shallow for the vehicle, or fixed obstacles
//! cut start from goal, no path exists and the plan's status is `unreachable`, with the
//! bottleneck named. The check never calls a reachable goal unreachable: its bounds only err
//! towards "passable".

use tidepath_search::{maximin, Grid2, SearchGrid};

use super::Problem;
use crate::geom::Vec3;
use crate::termination::Termination;
use crate::world::Dims;

/// Cells on the longer side of the domain.
const CELLS_LONG_SIDE: f64 = 256.0;

/// What the check found for one mission.
#[derive(Clone, Debug, PartialEq)]
pub enum Reachability {
    /// No path exists: `reason` says why; `at` is the bottleneck, when one place decides it.
    Unreachable { reason: String, at: Option<Vec3> },
    /// The optimistic raster connects start and goal. `bottleneck` is the deepest connection's
    /// shallowest place from [`check`]; from [`explain`], where a planner that finds no route
    /// should look first: on the connection with the most water *surely* there
    /// (each cell's shallowest point, none where an obstacle may reach in), the cell where that
    /// runs short of what the vehicle needs (a passage narrower than a cell may exist there);
    /// if none runs short, the shallowest place of the deepest connection (`None` when no
    /// seabed or obstacle limits it).
    Connected { bottleneck: Option<Bottleneck> },
    /// The clock fired before anything was decided.
    Undecided,
}

/// The shallowest place of the optimistic check's deepest connection between start and goal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bottleneck {
    /// The centre of the cell, at the seabed's deepest point in it.
    pub at: Vec3,
    /// Water depth there (m), at the deepest point of the cell (infinite without a seabed).
    pub water_m: f64,
    /// Water the vehicle needs: its safety distance below its highest allowed depth (m).
    pub needed_m: f64,
    /// The check's cell size (m): passages narrower than this are not resolved.
    pub cell_m: f64,
    /// Whether this is where the water surely there runs short (a passage narrower than a
    /// cell may exist here), rather than the deepest connection's shallowest place.
    pub pinch: bool,
}

/// Whether mission `i` of `problem` provably has no path, and if not, where its deepest
/// connection pinches. Polls `termination` (the run's clock): when it fires, nothing is
/// proved and the answer is [`Reachability::Undecided`].
pub fn check(problem: &Problem<'_>, i: usize, termination: &Termination) -> Reachability {
    check_inner(problem, i, termination, false).unwrap_or(Reachability::Undecided)
}

/// For a mission whose planner found no route: where to look, the [`Reachability::Connected`]
/// bottleneck with its pinch (a second raster pass, made only on failure). `None` when the
/// goal is not connected, no seabed or obstacle limits the connection, or `termination`
/// stops it.
pub fn explain(problem: &Problem<'_>, i: usize, termination: &Termination) -> Option<Bottleneck> {
    match check_inner(problem, i, termination, true)? {
        Reachability::Connected { bottleneck } => bottleneck,
        _ => None,
    }
}

/// `Some(reason)` when mission `i` of `problem` provably has no path.
pub fn unreachable(problem: &Problem<'_>, i: usize, termination: &Termination) -> Option<String> {
    match check(problem, i, termination) {
        Reachability::Unreachable { reason, .. } => Some(reason),
        _ => None,
    }
}

/// The check; with `pinch`, a connected goal's bottleneck is where the water surely there
/// runs short (see [`Reachability::Connected`]), else the deepest connection's shallowest place.
fn check_inner(problem: &Problem<'_>, i: usize, termination: &Termination, pinch: bool) -> Option<Reachability> {
    let world = problem.world;
    let m = &problem.missions[i];
    let v = &m.vehicle;
    let b = &world.bounds;
    let (w, h) = (b.max.x - b.min.x, b.max.y - b.min.y);
    // Fine cells: a ridge narrower than a cell cannot be proved to block (a cell is blocked
    // only if it is blocked everywhere).
    let cell = w.max(h) / CELLS_LONG_SIDE;
    let nx = ((w / cell).ceil() as usize).clamp(1, 4096);
    let ny = ((h / cell).ceil() as usize).clamp(1, 4096);
    let (dx, dy) = (w / nx as f64, h / ny as f64);
    // The highest z the vehicle may use, and the lowest.
    let (z_top, z_bottom) = match world.dims {
        Dims::Two => (m.start.z, m.start.z),
        Dims::Three => (b.max.z.min(v.z_max()), b.min.z.max(v.z_min())),
    };
    let safety = v.safety_distance;
    let needed = safety - z_top;
    let mut depth = vec![0.0; nx * ny];
    let mut blocked = vec![false; nx * ny];
    // Cells a fixed obstacle (with the safety distance) may reach into in the usable water
    // column: a conservative raster may block them even where the check finds water.
    let mut touched = vec![false; nx * ny];
    if !matches!(world.terrain, crate::world::Terrain::None) {
        for j in 0..ny {
            termination.interrupted().is_none().then_some(())?;
            for ii in 0..nx {
                let (xa, ya) = (b.min.x + ii as f64 * dx, b.min.y + j as f64 * dy);
                // Water depth at the deepest point of the cell.
                depth[ii + nx * j] = -world.terrain.min_elevation_in(xa, ya, xa + dx, ya + dy);
            }
        }
    } else {
        depth.fill(f64::INFINITY);
    }
    // Fixed obstacles block the cells they fill over the whole usable water column; only the
    // cells under an obstacle's box are tested.
    for o in world.obstacles.iter().filter(|o| o.is_fixed()) {
        let bb = o.shape.aabb();
        let cells = |lo: f64, hi: f64, o: f64, d: f64, n: usize| {
            let a = ((lo - o) / d).floor().max(0.0) as usize;
            let z = ((hi - o) / d).floor().max(0.0) as usize;
            (a.min(n - 1), z.min(n - 1))
        };
        let (i0, i1) = cells(bb.min.x - safety, bb.max.x + safety, b.min.x, dx, nx);
        let (j0, j1) = cells(bb.min.y - safety, bb.max.y + safety, b.min.y, dy, ny);
        let in_column = bb.max.z + safety >= z_bottom && bb.min.z - safety <= z_top;
        for j in j0..=j1 {
            termination.interrupted().is_none().then_some(())?;
            for ii in i0..=i1 {
                touched[ii + nx * j] |= in_column;
                let (xa, ya) = (b.min.x + ii as f64 * dx, b.min.y + j as f64 * dy);
                let (xb, yb) = (xa + dx, ya + dy);
                let corners = [
                    Vec3::new(xa, ya, z_bottom),
                    Vec3::new(xb, ya, z_bottom),
                    Vec3::new(xa, yb, z_bottom),
                    Vec3::new(xb, yb, z_bottom),
                    Vec3::new(xa, ya, z_top),
                    Vec3::new(xb, ya, z_top),
                    Vec3::new(xa, yb, z_top),
                    Vec3::new(xb, yb, z_top),
                ];
                if corners.iter().all(|&p| o.contains(p, 0.0, safety)) {
                    blocked[ii + nx * j] = true;
                }
            }
        }
    }
    let at = |p: Vec3| {
        let i = (((p.x - b.min.x) / dx).floor().max(0.0) as usize).min(nx - 1);
        let j = (((p.y - b.min.y) / dy).floor().max(0.0) as usize).min(ny - 1);
        i + nx * j
    };
    let (s, g) = (at(m.start), at(m.goal));
    // Start and goal were checked valid, so their cells are not blocked everywhere; the
    // obstacle test is on whole cells, which may still contain a valid point: free them.
    blocked[s] = false;
    blocked[g] = false;
    let depth: Vec<f64> = depth.iter().map(|d| if d.is_nan() { f64::INFINITY } else { *d }).collect();
    let grid = Grid2::from_blocked(nx, ny, blocked).ok()?;
    let who = if problem.missions.len() > 1 { format!("{}: ", m.name) } else { String::new() };
    let found = maximin(&grid, &depth, s, g).ok()?;
    let centre = |cell: usize| {
        let (ci, cj) = (cell % nx, cell / nx);
        (b.min.x + (ci as f64 + 0.5) * dx, b.min.y + (cj as f64 + 0.5) * dy)
    };
    let Some(bn) = found else {
        // Where the water the start reaches comes nearest the goal: the side of the cut.
        let edge = nearest_reached(&grid, s, |c| {
            let (x, y) = centre(c);
            (x - m.goal.x).hypot(y - m.goal.y)
        });
        let (x, y) = centre(edge);
        let reason = format!(
            "{who}goal unreachable: fixed obstacles and the domain's edges separate start and goal; the water the start reaches ends nearest the goal at ({}), {:.0} m from it",
            world.place(x, y),
            (x - m.goal.x).hypot(y - m.goal.y)
        );
        return Some(Reachability::Unreachable { reason, at: Some(Vec3::new(x, y, m.start.z)) });
    };
    let bottleneck_at = |cell: usize, pinch: bool| {
        let (x, y) = centre(cell);
        let water = depth[cell].max(0.0);
        Bottleneck { at: Vec3::new(x, y, -water), water_m: water, needed_m: needed, cell_m: dx.max(dy), pinch }
    };
    if bn.value < needed {
        let (x, y) = centre(bn.cell);
        return Some(Reachability::Unreachable {
            reason: format!(
                "{who}goal unreachable: the deepest water connecting start and goal is {:.1} m at ({}); this vehicle needs {needed:.1} m",
                bn.value.max(0.0),
                world.place(x, y)
            ),
            at: Some(bottleneck_at(bn.cell, false).at),
        });
    }
    if !pinch {
        let bottleneck = bn.value.is_finite().then(|| bottleneck_at(bn.cell, false));
        return Some(Reachability::Connected { bottleneck });
    }
    // Connected. Where would a conservative search get stuck? Rank the same connections by
    // the water they surely have (a cell's shallowest point, none where an obstacle may reach
    // in): the best of them pinches where a passage is narrower than a cell, if anywhere.
    let mut sure = vec![f64::INFINITY; nx * ny];
    if !matches!(world.terrain, crate::world::Terrain::None) {
        for (k, v) in sure.iter_mut().enumerate() {
            if k % nx == 0 {
                termination.interrupted().is_none().then_some(())?;
            }
            let (xa, ya) = (b.min.x + (k % nx) as f64 * dx, b.min.y + (k / nx) as f64 * dy);
            let w = -world.terrain.max_elevation_in(xa, ya, xa + dx, ya + dy);
            *v = if w.is_nan() { f64::INFINITY } else { w };
        }
    }
    for (v, &t) in sure.iter_mut().zip(&touched) {
        if t {
            *v = v.min(0.0);
        }
    }
    let tight = maximin(&grid, &sure, s, g).ok().flatten().filter(|t| t.value < needed);
    let bottleneck = match tight {
        Some(t) => Some(bottleneck_at(t.cell, true)),
        None => bn.value.is_finite().then(|| bottleneck_at(bn.cell, false)),
    };
    Some(Reachability::Connected { bottleneck })
}

/// The cell of the start's connected region (the moves of [`SearchGrid`]) that minimises
/// `distance` (the first found on a tie, in flood order, which is fixed).
fn nearest_reached(grid: &Grid2, start: usize, distance: impl Fn(usize) -> f64) -> usize {
    let mut seen = vec![false; grid.len()];
    let mut stack = vec![start];
    seen[start] = true;
    let (mut best, mut best_d) = (start, distance(start));
    while let Some(u) = stack.pop() {
        grid.for_each_neighbour(u, |v| {
            if !seen[v] {
                seen[v] = true;
                stack.push(v);
            }
        });
        let d = distance(u);
        if d < best_d {
            (best, best_d) = (u, d);
        }
    }
    best
}
