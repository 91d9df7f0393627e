//! Exact shortest paths in the plane among circles and simple polygons.
//!
//! A shortest path among such obstacles consists of straight segments that are
//! tangent to circles (or end at convex polygon vertices, start or goal) and
//! circular arcs along obstacle circles. So the **tangent visibility graph** on
//! these nodes contains a shortest path:
//!
//! * point nodes: start, goal, and every convex vertex of every polygon
//!   (a shortest path never bends at a reflex vertex);
//! * segment edges: point–point, point–circle tangents (two per pair),
//!   circle–circle bitangents (two outer, plus two inner when disjoint), each
//!   kept only if it does not enter the interior of any obstacle (touching a
//!   boundary is allowed) and stays inside the domain;
//! * arc edges: along each circle between angularly consecutive tangent points,
//!   kept only if the arc does not enter another obstacle (or leave the domain).
//!
//! Every edge is a feasible piece of path, so Dijkstra on the graph returns a
//! feasible path, and since the graph contains an optimal one, its length is
//! the exact shortest length (up to floating point).
//!
//! # Domain
//!
//! An optional rectangle the path must stay inside. A rectangle is convex, so a
//! segment is inside iff its ends are; arcs are checked at their ends and axis
//! extremes. Its walls are never bending points of a shortest path (they are
//! convex from the inside), so nothing else is needed.
//!
//! # Cost and limits
//!
//! With `c` circles and `p` point nodes there are `O(c² + p·c)` nodes and
//! `O(c² + p·c + p²)` candidate segments, each tested against every obstacle;
//! scenes are refused above [`MAX_NODES`] candidate nodes.
//!
//! # Output
//!
//! The exact length, the pieces (segments and arcs), and a polyline in which
//! each arc is discretised with an angular step no larger than the requested
//! one (its chords cut slightly inside the circle: the polyline is a drawing,
//! the pieces are the path).

mod geometry;
mod route;
use crate::outcome::{Limits, StopReason};

use geometry::{
    bitangent_angles, dist, in_rect, on_circle, point_tangent_angles, segment_enters_circle, segment_enters_polygon,
    strictly_inside_polygon, Arc,
};

/// A point `[x, y]`.
pub type Point = [f64; 2];

/// A disc obstacle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre.
    pub centre: Point,
    /// Radius (> 0).
    pub radius: f64,
}

/// A simple polygon obstacle (either orientation, no repeated closing vertex).
#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    /// At least three vertices.
    pub vertices: Vec<Point>,
}

/// An axis-aligned rectangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Lower-left corner.
    pub min: Point,
    /// Upper-right corner.
    pub max: Point,
}

/// Obstacles and an optional domain.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Scene {
    /// Disc obstacles.
    pub circles: Vec<Circle>,
    /// Polygon obstacles.
    pub polygons: Vec<Polygon>,
    /// If set, the path must stay inside this rectangle.
    pub domain: Option<Rect>,
}

/// Largest number of candidate graph nodes accepted (about 2·10⁵): beyond that
/// the quadratic construction would take minutes.
pub const MAX_NODES: usize = 200_000;

/// Why a scene could not be solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VisError {
    /// A coordinate, radius or step is NaN or infinite.
    #[error("non-finite input: {0}")]
    NonFinite(&'static str),
    /// Circle with a non-positive radius.
    #[error("circle {0} has a non-positive radius")]
    BadCircle(usize),
    /// Polygon with fewer than three vertices or zero area.
    #[error("polygon {0} needs at least three vertices and a non-zero area")]
    BadPolygon(usize),
    /// The arc step must be in (0, π].
    #[error("arc step {0} must be in (0, pi]")]
    BadArcStep(f64),
    /// Start or goal strictly inside an obstacle or outside the domain.
    #[error("{which} {point:?} is inside an obstacle or outside the domain")]
    EndpointNotFree {
        /// "start" or "goal".
        which: &'static str,
        /// The point.
        point: Point,
    },
    /// Too many obstacles for the quadratic construction.
    #[error("scene would need {0} graph nodes (limit {max})", max = MAX_NODES)]
    TooLarge(usize),
    /// The stop flag or the deadline of the [`Limits`] ended the construction or the search.
    #[error("stopped before the graph was searched ({0:?})")]
    Stopped(StopReason),
}

/// How many segment or arc tests the graph construction makes between two polls of its
/// limits: each test scans every obstacle, so this keeps a poll within milliseconds.
const POLL_TESTS: u32 = 64;

/// Polls `limits` every [`POLL_TESTS`] calls.
struct Poll<'a, 'b> {
    limits: &'a Limits<'b>,
    count: u32,
}

impl Poll<'_, '_> {
    fn tick(&mut self) -> Result<(), VisError> {
        self.count += 1;
        if self.count % POLL_TESTS == 0 {
            if let Some(r) = self.limits.interrupted() {
                return Err(VisError::Stopped(r));
            }
        }
        Ok(())
    }
}

/// One piece of a path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    /// A straight segment.
    Segment {
        /// Start point.
        from: Point,
        /// End point.
        to: Point,
    },
    /// A circular arc: from `start_angle`, through `sweep` radians
    /// (positive counter-clockwise).
    Arc {
        /// Circle centre.
        centre: Point,
        /// Radius.
        radius: f64,
        /// Angle of the first point.
        start_angle: f64,
        /// Signed angle travelled.
        sweep: f64,
    },
}

/// A shortest path.
#[derive(Debug, Clone, PartialEq)]
pub struct VisPath {
    /// Exact length (sum of segment lengths and `radius · |sweep|`).
    pub length: f64,
    /// Segments and arcs from start to goal (zero-length pieces omitted).
    pub pieces: Vec<Piece>,
    /// Start, every bend and arc sample, goal.
    pub polyline: Vec<Point>,
}

#[derive(Debug, Clone, Copy)]
enum EdgeKind {
    Segment,
    /// Arc on circle `circle` starting at the edge source's angle.
    Arc {
        circle: usize,
        sweep: f64,
    },
}

#[derive(Debug, Clone, Copy)]
struct Edge {
    to: usize,
    len: f64,
    kind: EdgeKind,
}

#[derive(Debug, Clone, Copy)]
struct Node {
    pos: Point,
    /// `(circle, angle)` for tangent points.
    on: Option<(usize, f64)>,
}

struct Graph<'a> {
    scene: &'a Scene,
    polys: Vec<Vec<Point>>,
    eps: f64,
    nodes: Vec<Node>,
    adj: Vec<Vec<Edge>>,
    /// Per circle: (angle, node) of its tangent points.
    on_circle: Vec<Vec<(f64, usize)>>,
}

impl Graph<'_> {
    fn add_node(&mut self, pos: Point, on: Option<(usize, f64)>) -> usize {
        self.nodes.push(Node { pos, on });
        self.adj.push(Vec::new());
        if let Some((c, a)) = on {
            self.on_circle[c].push((a, self.nodes.len() - 1));
        }
        self.nodes.len() - 1
    }

    fn add_edge(&mut self, a: usize, b: usize, len: f64, kind: EdgeKind) {
        self.adj[a].push(Edge { to: b, len, kind });
        let back = match kind {
            EdgeKind::Segment => EdgeKind::Segment,
            EdgeKind::Arc { circle, sweep } => EdgeKind::Arc { circle, sweep: -sweep },
        };
        self.adj[b].push(Edge { to: a, len, kind: back });
    }

    fn point_free(&self, p: Point) -> bool {
        let e = self.eps;
        self.scene.domain.is_none_or(|r| in_rect(p, &r, e))
            && self.scene.circles.iter().all(|c| dist(p, c.centre) >= c.radius - e)
            && self.polys.iter().all(|poly| !strictly_inside_polygon(p, poly, e))
    }

    fn segment_free(&self, a: Point, b: Point) -> bool {
        let e = self.eps;
        self.scene.domain.is_none_or(|r| in_rect(a, &r, e) && in_rect(b, &r, e))
            && self.scene.circles.iter().all(|c| !segment_enters_circle(a, b, c, e))
            && self.polys.iter().all(|poly| !segment_enters_polygon(a, b, poly, e))
    }

    fn arc_free(&self, arc: &Arc, own: usize) -> bool {
        let e = self.eps;
        self.scene.domain.is_none_or(|r| arc.inside_rect(&r, e))
            && self.scene.circles.iter().enumerate().all(|(k, c)| k == own || !arc.enters_circle(c, e))
            && self.polys.iter().all(|poly| !arc.enters_polygon(poly, e))
    }

    /// Adds the segment between two (existing or new tangent) nodes if free.
    fn try_segment(
        &mut self,
        a: (Point, Option<usize>, Option<(usize, f64)>),
        b: (Point, Option<usize>, Option<(usize, f64)>),
    ) {
        if !self.segment_free(a.0, b.0) {
            return;
        }
        let ia = a.1.unwrap_or_else(|| self.add_node(a.0, a.2));
        let ib = b.1.unwrap_or_else(|| self.add_node(b.0, b.2));
        self.add_edge(ia, ib, dist(a.0, b.0), EdgeKind::Segment);
    }
}

/// The shortest path from `start` to `goal` avoiding the interiors of the
/// scene's obstacles (and staying in its domain), with arcs discretised at
/// most `arc_step` radians apart in the polyline.
///
/// `Ok(None)`: proved that no path exists (the graph is complete, so the
/// search cannot give up early).
pub fn shortest_path(scene: &Scene, start: Point, goal: Point, arc_step: f64) -> Result<Option<VisPath>, VisError> {
    shortest_path_within(scene, start, goal, arc_step, &Limits::none()).map(|(p, _)| p)
}

/// The size of the visibility graph a search built.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct GraphSize {
    pub nodes: usize,
    pub edges: usize,
}

/// [`shortest_path`] within `limits`, with the size of the graph it built: the stop flag and
/// the deadline are polled during the graph's construction (quadratic in the obstacles) and
/// its search; when either fires the answer is [`VisError::Stopped`] (nothing was proved).
pub fn shortest_path_within(
    scene: &Scene,
    start: Point,
    goal: Point,
    arc_step: f64,
    limits: &Limits<'_>,
) -> Result<(Option<VisPath>, GraphSize), VisError> {
    validate(scene, start, goal, arc_step)?;
    let mut poll = Poll { limits, count: 0 };
    let polys: Vec<Vec<Point>> = scene.polygons.iter().map(|p| ccw(&p.vertices)).collect();
    let scale = scene
        .circles
        .iter()
        .flat_map(|c| [c.centre[0].abs(), c.centre[1].abs(), c.radius])
        .chain(polys.iter().flatten().flat_map(|p| [p[0].abs(), p[1].abs()]))
        .chain(start.iter().chain(goal.iter()).map(|x| x.abs()))
        .fold(1.0f64, f64::max);
    let eps = 1e-9 * scale;
    let mut g = Graph {
        scene,
        polys,
        eps,
        nodes: Vec::new(),
        adj: Vec::new(),
        on_circle: vec![Vec::new(); scene.circles.len()],
    };
    for (which, p) in [("start", start), ("goal", goal)] {
        if !g.point_free(p) {
            return Err(VisError::EndpointNotFree { which, point: p });
        }
    }
    // Point nodes: start (0), goal (1), convex polygon vertices that are free.
    g.add_node(start, None);
    g.add_node(goal, None);
    for k in 0..g.polys.len() {
        let poly = g.polys[k].clone();
        let n = poly.len();
        for v in 0..n {
            poll.tick()?;
            let (a, b, c) = (poly[(v + n - 1) % n], poly[v], poly[(v + 1) % n]);
            let turn = geometry::cross(geometry::sub(b, a), geometry::sub(c, b));
            if turn > 0.0 && g.point_free(b) {
                g.add_node(b, None);
            }
        }
    }
    let points = g.nodes.len();
    let circles = &scene.circles;
    let estimate = points + 2 * points * circles.len() + 4 * circles.len() * circles.len();
    if estimate > MAX_NODES {
        return Err(VisError::TooLarge(estimate));
    }
    // Point–point segments.
    for a in 0..points {
        for b in a + 1..points {
            poll.tick()?;
            let (pa, pb) = (g.nodes[a].pos, g.nodes[b].pos);
            g.try_segment((pa, Some(a), None), (pb, Some(b), None));
        }
    }
    // Point–circle tangents.
    for p in 0..points {
        let pos = g.nodes[p].pos;
        for (ci, c) in circles.iter().enumerate() {
            poll.tick()?;
            let d = dist(pos, c.centre);
            if d < c.radius - eps {
                continue; // cannot happen for free points; defensive
            }
            if d <= c.radius + eps {
                // The point is on the circle: it is its own tangent point.
                let angle = geometry::norm_angle((pos[1] - c.centre[1]).atan2(pos[0] - c.centre[0]));
                let t = g.add_node(pos, Some((ci, angle)));
                g.add_edge(p, t, 0.0, EdgeKind::Segment);
                continue;
            }
            for angle in point_tangent_angles(pos, c) {
                g.try_segment((pos, Some(p), None), (on_circle(c, angle), None, Some((ci, angle))));
            }
        }
    }
    // Circle–circle bitangents.
    for i in 0..circles.len() {
        for j in i + 1..circles.len() {
            poll.tick()?;
            for (ai, aj) in bitangent_angles(&circles[i], &circles[j], eps) {
                g.try_segment(
                    (on_circle(&circles[i], ai), None, Some((i, ai))),
                    (on_circle(&circles[j], aj), None, Some((j, aj))),
                );
            }
        }
    }
    // Arcs between angularly consecutive tangent points.
    for (ci, circle) in circles.iter().enumerate() {
        let mut pts = std::mem::take(&mut g.on_circle[ci]);
        pts.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        let m = pts.len();
        if m >= 2 {
            for k in 0..m {
                poll.tick()?;
                let (a0, n0) = pts[k];
                let (a1, n1) = pts[(k + 1) % m];
                let sweep = if k + 1 < m { a1 - a0 } else { a1 + std::f64::consts::TAU - a0 };
                let arc = Arc { circle: *circle, start: a0, sweep };
                if g.arc_free(&arc, ci) {
                    g.add_edge(n0, n1, circle.radius * sweep, EdgeKind::Arc { circle: ci, sweep });
                }
            }
        }
        g.on_circle[ci] = pts;
    }
    if let Some(r) = limits.interrupted() {
        return Err(VisError::Stopped(r));
    }
    let size = GraphSize { nodes: g.nodes.len(), edges: g.adj.iter().map(Vec::len).sum::<usize>() / 2 };
    Ok((route::dijkstra(&g, 0, 1).map(|(length, r)| route::build_path(&g, length, &r, arc_step)), size))
}

fn validate(scene: &Scene, start: Point, goal: Point, arc_step: f64) -> Result<(), VisError> {
    let finite = |p: Point| p[0].is_finite() && p[1].is_finite();
    if !finite(start) || !finite(goal) {
        return Err(VisError::NonFinite("start or goal"));
    }
    if !(arc_step.is_finite() && arc_step > 0.0 && arc_step <= std::f64::consts::PI) {
        return Err(VisError::BadArcStep(arc_step));
    }
    for (k, c) in scene.circles.iter().enumerate() {
        if !finite(c.centre) || !c.radius.is_finite() {
            return Err(VisError::NonFinite("circle"));
        }
        if c.radius <= 0.0 {
            return Err(VisError::BadCircle(k));
        }
    }
    for (k, p) in scene.polygons.iter().enumerate() {
        if !p.vertices.iter().all(|&v| finite(v)) {
            return Err(VisError::NonFinite("polygon vertex"));
        }
        if p.vertices.len() < 3 || signed_area(&p.vertices) == 0.0 {
            return Err(VisError::BadPolygon(k));
        }
    }
    if let Some(r) = scene.domain {
        if !finite(r.min) || !finite(r.max) {
            return Err(VisError::NonFinite("domain"));
        }
    }
    Ok(())
}

fn signed_area(v: &[Point]) -> f64 {
    let n = v.len();
    0.5 * (0..n).map(|k| geometry::cross(v[k], v[(k + 1) % n])).sum::<f64>()
}

/// The vertices in counter-clockwise order.
fn ccw(v: &[Point]) -> Vec<Point> {
    let mut out = v.to_vec();
    if signed_area(v) < 0.0 {
        out.reverse();
    }
    out
}

#[cfg(test)]
mod tests;
