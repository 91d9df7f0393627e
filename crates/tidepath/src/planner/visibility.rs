//! `visibility`: the exact shortest path in a 2-D world of discs and polygons, through the
//! tangent visibility graph (bitangents between discs, tangents from start, goal and convex
//! polygon corners, arcs along each disc), solved by the `tidepath-search` crate.
//!
//! The world at the mission's plane: circles and full-depth cylinders are discs, spheres cut by
//! the plane are discs, boxes are rectangles; every obstacle is grown by the safety distance.
//! A disc grows exactly; a rectangle grown by a distance has rounded corners, which this
//! planner replaces by the circumscribed polygon (corners cut at 16 segments per quarter), so
//! its path is then valid but up to about 0.05% longer than the true optimum on those corners
//! and the status is `feasible`, not `exact`. The arcs of the path are drawn as chords outside
//! the grown disc (radius divided by cos(step/2)), so the polyline keeps the safety distance.
//!
//! It applies to 2-D worlds without a seabed that could block the plane and without moving
//! obstacles; elsewhere it is an input error naming why (use `theta-star` or `hybrid`).

use tidepath_search::visibility::{shortest_path, shortest_path_within, Circle, Polygon, Rect, Scene, VisError};

use super::{Claim, Planner, PlannerOutput, Problem, RunOptions, SearchStats};
use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::optim::Progress;
use crate::rng::Rng;
use crate::termination::{from_search_stop, StopReason, Termination};
use crate::world::{Dims, Shape};

/// Chord step along arcs (rad): 2 degrees.
const ARC_STEP: f64 = std::f64::consts::PI / 90.0;
/// Segments per quarter circle where a grown rectangle's rounded corner is approximated.
const CORNER_SEGMENTS: usize = 16;

pub struct Visibility;

crate::params! {
    /// The visibility graph has no parameters.
    pub struct VisibilityParams {}
}

/// The scene of mission `i` at its plane, and whether it is exact (only discs and exact
/// polygons). `inflate` divides disc radii by cos(ARC_STEP / 2) so chords stay outside.
pub fn scene(problem: &Problem<'_>, i: usize, inflate: bool) -> Result<(Scene, bool)> {
    let w = problem.world;
    let m = &problem.missions[i];
    let field = "planner";
    if w.dims != Dims::Two {
        return Err(Error::input(
            field,
            "visibility needs a 2-D world (world.dimensions = 2); use theta-star or hybrid",
        ));
    }
    let z = m.start.z;
    // A hair more than the safety distance, so a path touching a grown obstacle still keeps it
    // under the validator's strict test; lengths change by about a micrometre.
    let s = m.vehicle.safety_distance * (1.0 + 1e-9) + 1e-6;
    let b = &w.bounds;
    if w.terrain.max_elevation_in(b.min.x, b.min.y, b.max.x, b.max.y) + s > z {
        return Err(Error::input(
            field,
            "visibility needs a world without a seabed that reaches the plane; use theta-star or hybrid",
        ));
    }
    if w.obstacles.iter().any(|o| !o.is_fixed()) {
        return Err(Error::input(field, "visibility needs fixed obstacles only; use theta-star or hybrid"));
    }
    let grow = if inflate { 1.0 / (ARC_STEP / 2.0).cos() } else { 1.0 };
    let mut scene =
        Scene { domain: Some(Rect { min: [b.min.x, b.min.y], max: [b.max.x, b.max.y] }), ..Scene::default() };
    let mut exact = true;
    for o in &w.obstacles {
        match o.shape {
            Shape::Circle { center, radius } => {
                scene.circles.push(Circle { centre: [center.x, center.y], radius: (radius + s) * grow });
            }
            Shape::Cylinder { center, radius, z_min, z_max } => {
                if z >= z_min - s && z <= z_max + s {
                    scene.circles.push(Circle { centre: [center.x, center.y], radius: (radius + s) * grow });
                }
            }
            Shape::Sphere { center, radius } => {
                let r = radius + s;
                let dz = z - center.z;
                if dz.abs() < r {
                    scene
                        .circles
                        .push(Circle { centre: [center.x, center.y], radius: (r * r - dz * dz).sqrt() * grow });
                }
            }
            Shape::Box { min, max } => {
                if z < min.z - s || z > max.z + s {
                    continue;
                }
                if m.vehicle.safety_distance == 0.0 {
                    scene.polygons.push(Polygon {
                        vertices: vec![
                            [min.x - s, min.y - s],
                            [max.x + s, min.y - s],
                            [max.x + s, max.y + s],
                            [min.x - s, max.y + s],
                        ],
                    });
                } else {
                    exact = false;
                    scene.polygons.push(Polygon { vertices: rounded_box(min, max, s) });
                }
            }
        }
    }
    Ok((scene, exact))
}

/// The polygon circumscribing a rectangle grown by `s` (rounded corners cut into segments
/// whose sides touch the true rounded corner from outside).
fn rounded_box(min: Vec3, max: Vec3, s: f64) -> Vec<[f64; 2]> {
    let step = std::f64::consts::FRAC_PI_2 / CORNER_SEGMENTS as f64;
    // Vertices at this radius make every side tangent to the quarter circle of radius s.
    let r = s / (0.5 * step).cos();
    let corners = [([max.x, min.y], -90.0f64), ([max.x, max.y], 0.0), ([min.x, max.y], 90.0), ([min.x, min.y], 180.0)];
    let mut out = Vec::new();
    for (c, a0) in corners {
        let a0 = a0.to_radians();
        let at = |radius: f64, a: f64| [c[0] + radius * a.cos(), c[1] + radius * a.sin()];
        out.push(at(s, a0));
        for k in 0..CORNER_SEGMENTS {
            out.push(at(r, a0 + (k as f64 + 0.5) * step));
        }
        out.push(at(s, a0 + std::f64::consts::FRAC_PI_2));
    }
    out
}

/// The exact shortest length for mission `i` (grown discs exactly), when the scene is exact.
pub fn shortest_length(problem: &Problem<'_>, i: usize) -> Result<Option<f64>> {
    let (scene, exact) = scene(problem, i, false)?;
    let m = &problem.missions[i];
    let p = shortest_path(&scene, [m.start.x, m.start.y], [m.goal.x, m.goal.y], ARC_STEP)
        .map_err(|e| Error::input("planner", format!("visibility: {e}")))?;
    Ok(p.filter(|_| exact).map(|p| p.length))
}

impl Planner for Visibility {
    fn id(&self) -> &'static str {
        "visibility"
    }

    fn check(&self, problem: &Problem<'_>) -> Result<()> {
        for i in 0..problem.missions.len() {
            scene(problem, i, true)?;
        }
        Ok(())
    }

    fn plan(
        &mut self,
        problem: &Problem<'_>,
        termination: &Termination,
        _rng: &mut Rng,
        _options: RunOptions<'_>,
        _observer: &mut dyn FnMut(&Progress),
    ) -> PlannerOutput {
        let watch = termination.start();
        let mut paths = Vec::new();
        let mut all_exact = true;
        let mut stop_reason = StopReason::Completed;
        let mut graph = (0u64, 0u64);
        for i in 0..problem.missions.len() {
            let m = &problem.missions[i];
            let limits = termination.search_limits(None);
            let found = match scene(problem, i, true) {
                Ok((scene, exact)) => {
                    all_exact &= exact;
                    match shortest_path_within(&scene, [m.start.x, m.start.y], [m.goal.x, m.goal.y], ARC_STEP, &limits)
                    {
                        Ok((p, size)) => {
                            graph.0 += size.nodes as u64;
                            graph.1 += size.edges as u64;
                            p
                        }
                        Err(VisError::Stopped(r)) => {
                            stop_reason = from_search_stop(r);
                            None
                        }
                        Err(_) => None,
                    }
                }
                Err(_) => None,
            };
            match found {
                Some(p) => {
                    let mut pts: Vec<Vec3> = p.polyline.iter().map(|q| Vec3::new(q[0], q[1], m.start.z)).collect();
                    pts[0] = m.start;
                    let n = pts.len();
                    pts[n - 1] = m.goal;
                    paths.push(pts);
                }
                None => {
                    all_exact = false;
                    paths.push(Vec::new());
                }
            }
        }
        let stats = SearchStats {
            stop_reason,
            graph_nodes: graph.0,
            graph_edges: graph.1,
            elapsed: watch.elapsed(),
            ..SearchStats::default()
        };
        // Shortest is cheapest when the cost model charges the same per metre everywhere.
        let per_metre =
            (0..problem.missions.len()).all(|i| problem.cost.cost_per_metre(&problem.path_model(i)).is_some());
        let claim = all_exact.then(|| Claim::Optimal {
            space: "over all paths in the plane (tangent visibility graph among the discs and boxes)".into(),
            objective: if per_metre { "the scenario's cost model".into() } else { "length".into() },
            scenario_cost: per_metre,
        });
        PlannerOutput { paths, speeds: Vec::new(), claim, stats, graphs: Vec::new() }
    }
}
