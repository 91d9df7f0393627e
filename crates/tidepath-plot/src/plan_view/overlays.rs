//! What the plan view draws over the seabed: currents, obstacles and their motion, paths, and
//! the start and goal markers.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::style::{self, plot_err, Marker};
use super::super::PlotPath;
use super::Chart;
use tidepath::error::Result;
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::world::{Current, Obstacle, Shape, World};

/// Current arrows across the view.
const ARROW_CELLS: usize = 15;

/// Current arrows sampled on a coarse grid: (x, y, u, v) in metres and m/s, with the speed
/// that maps to the longest arrow.
pub(super) struct Quiver {
    pub(super) arrows: Vec<(f64, f64, f64, f64)>,
    pub(super) max_speed: f64,
    pub(super) z: f64,
    pub(super) spacing: f64,
}

impl Quiver {
    pub(super) fn sample(world: &World, time: f64, z: f64, (x0, y0, x1, y1): (f64, f64, f64, f64)) -> Option<Self> {
        if matches!(world.current, Current::None) {
            return None;
        }
        let (sx, sy) = ((x1 - x0) / ARROW_CELLS as f64, (y1 - y0) / ARROW_CELLS as f64);
        let mut arrows = Vec::with_capacity(ARROW_CELLS * ARROW_CELLS);
        let mut max_speed: f64 = 0.0;
        for j in 0..ARROW_CELLS {
            for i in 0..ARROW_CELLS {
                let (x, y) = (x0 + sx * (i as f64 + 0.5), y0 + sy * (j as f64 + 0.5));
                // No arrow inside rock: the current there means nothing to the vehicle.
                if world.terrain.elevation(x, y) > z {
                    continue;
                }
                let v = world.current.velocity(Vec3::new(x, y, z), time);
                let speed = v.truncate().length();
                if speed.is_finite() {
                    max_speed = max_speed.max(speed);
                    arrows.push((x, y, v.x, v.y));
                }
            }
        }
        // The world's bound (if it has one) rather than the samples sets the scale, so a fast
        // core between sample points does not make its neighbours look like the fastest flow.
        let bounds = Aabb::new(Vec3::new(x0, y0, z), Vec3::new(x1, y1, z));
        let hint = world.current.max_speed_hint(&bounds, time);
        if hint.is_finite() && hint > 0.0 {
            max_speed = hint;
        }
        Some(Self { arrows, max_speed, z, spacing: sx.min(sy) })
    }
}

/// Points of a circle as a polygon, so it is round in data units whatever the pixel scale.
fn circle_points(c: Vec2, r: f64, u: f64) -> Vec<(f64, f64)> {
    (0..=64)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 64.0;
            ((c.x + r * a.cos()) / u, (c.y + r * a.sin()) / u)
        })
        .collect()
}

/// Outline polygon (data units) and horizontal centre (metres) of an obstacle at `time`.
fn obstacle_outline(o: &Obstacle, time: f64, u: f64) -> Option<(Vec<(f64, f64)>, Vec2)> {
    let (outline, centre) = match o.shape_at(time) {
        Shape::Sphere { center, radius } => (circle_points(center.truncate(), radius, u), center.truncate()),
        Shape::Cylinder { center, radius, .. } | Shape::Circle { center, radius } => {
            (circle_points(center, radius, u), center)
        }
        Shape::Box { min, max } => {
            let (a, b) = (min / u, max / u);
            (vec![(a.x, a.y), (b.x, a.y), (b.x, b.y), (a.x, b.y), (a.x, a.y)], (min.truncate() + max.truncate()) * 0.5)
        }
    };
    outline.iter().all(|p| p.0.is_finite() && p.1.is_finite()).then_some((outline, centre))
}

pub(super) fn draw_obstacles<DB: DrawingBackend>(chart: &Chart<DB>, world: &World, time: f64, u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    for (outline, _) in world.obstacles.iter().filter_map(|o| obstacle_outline(o, time, u)) {
        plot.draw(&Polygon::new(outline.clone(), style::fill(style::OBSTACLE_FILL))).map_err(plot_err)?;
        plot.draw(&PathElement::new(outline, style::line(style::OBSTACLE_EDGE, 1))).map_err(plot_err)?;
    }
    Ok(())
}

/// Velocity arrows of moving obstacles with their speed, drawn above paths and currents so the
/// labels stay legible.
pub(super) fn draw_obstacle_motion<DB: DrawingBackend>(
    chart: &Chart<DB>,
    world: &World,
    time: f64,
    u: f64,
) -> Result<()> {
    let px = chart.plotting_area().strip_coord_spec();
    for o in &world.obstacles {
        let v = o.velocity.truncate();
        let speed = v.length();
        let Some((_, centre)) = obstacle_outline(o, time, u) else { continue };
        if !(speed > 0.0 && speed.is_finite()) {
            continue;
        }
        // A fixed on-screen length: the arrow says where it is heading, the label how fast.
        let from = to_px(chart, centre.x / u, centre.y / u);
        let dir = v / speed;
        let to = (from.0 + (dir.x * 34.0).round() as i32, from.1 - (dir.y * 34.0).round() as i32);
        style::draw_arrow_px(&px, from, to, style::OBSTACLE_EDGE, 2)?;
        let text = format!("{} m/s", style::fmt_sig(speed));
        let (tw, th) = (style::text_width(&text, 11.0).round() as i32 + 10, 15);
        // Centred just beyond the tip, along the arrow, so it covers neither tip nor shaft.
        let gap = 4.0;
        let reach_x = if dir.x.abs() > 1e-9 { (tw as f64 / 2.0 + gap) / dir.x.abs() } else { f64::INFINITY };
        let reach_y = if dir.y.abs() > 1e-9 { (th as f64 / 2.0 + gap) / dir.y.abs() } else { f64::INFINITY };
        let reach = reach_x.min(reach_y);
        let bx = to.0 + (dir.x * reach).round() as i32 - tw / 2;
        let by = to.1 - (dir.y * reach).round() as i32 - th / 2;
        px.draw(&Rectangle::new([(bx, by), (bx + tw, by + th)], style::fill(WHITE.mix(0.85)))).map_err(plot_err)?;
        let centre = Pos::new(HPos::Center, VPos::Center);
        px.draw(&Text::new(text, (bx + tw / 2, by + th / 2), style::font(11.0).pos(centre))).map_err(plot_err)?;
    }
    Ok(())
}

/// Pixel position of a data point relative to the plotting area's top-left corner.
fn to_px<DB: DrawingBackend>(chart: &Chart<DB>, x: f64, y: f64) -> (i32, i32) {
    let (bx, by) = chart.plotting_area().get_base_pixel();
    let (px, py) = chart.backend_coord(&(x, y));
    (px - bx, py - by)
}

pub(super) fn draw_quiver<DB: DrawingBackend>(chart: &Chart<DB>, q: &Quiver, u: f64) -> Result<()> {
    let max = q.max_speed;
    if !(max > 0.0 && max.is_finite()) {
        return Ok(());
    }
    let px = chart.plotting_area().strip_coord_spec();
    let (ox, _) = to_px(chart, 0.0, 0.0);
    let (sx, _) = to_px(chart, q.spacing / u, 0.0);
    let spacing_px = (sx - ox).abs() as f64;
    for &(x, y, vx, vy) in &q.arrows {
        let len = (vx * vx + vy * vy).sqrt() / max * 0.8 * spacing_px;
        if len < 2.0 {
            continue;
        }
        let (cx, cy) = to_px(chart, x / u, y / u);
        let s = (vx * vx + vy * vy).sqrt();
        let (dx, dy) = (vx / s * len / 2.0, -vy / s * len / 2.0);
        let from = (cx - dx.round() as i32, cy - dy.round() as i32);
        let to = (cx + dx.round() as i32, cy + dy.round() as i32);
        style::draw_arrow_px(&px, from, to, style::CURRENT.mix(0.8), 1)?;
    }
    Ok(())
}

pub(super) fn draw_paths<DB: DrawingBackend>(chart: &Chart<DB>, paths: &[PlotPath], u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    for (i, p) in paths.iter().enumerate() {
        let color = style::path_color(i);
        let pts: Vec<(f64, f64)> =
            p.points.iter().filter(|q| q.x.is_finite() && q.y.is_finite()).map(|q| (q.x / u, q.y / u)).collect();
        if pts.len() >= 2 {
            // A pale casing keeps the line readable over dark water and dark contours.
            plot.draw(&PathElement::new(pts.clone(), style::line(WHITE.mix(0.75), 5))).map_err(plot_err)?;
            plot.draw(&PathElement::new(pts.clone(), style::line(color, 3))).map_err(plot_err)?;
        }
        for &q in &pts {
            plot.draw(&Circle::new(q, 4, style::fill(WHITE))).map_err(plot_err)?;
            plot.draw(&Circle::new(q, 3, style::fill(color))).map_err(plot_err)?;
        }
    }
    Ok(())
}

pub(super) fn draw_endpoints<DB: DrawingBackend>(
    chart: &Chart<DB>,
    paths: &[PlotPath],
    start: Vec3,
    goal: Vec3,
    u: f64,
) -> Result<()> {
    let px = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = px.dim_in_pixel();
    let first = paths.iter().find(|p| p.points.len() >= 2).map(|p| p.points);
    // Labels go where the path is not: behind the start, beyond the goal.
    let away_from_start = first.map(|pts| pts[0].truncate() - pts[1].truncate());
    let away_from_goal = first.map(|pts| pts[pts.len() - 1].truncate() - pts[pts.len() - 2].truncate());
    for (p, away, marker, color, label) in [
        (start, away_from_start, Marker::Triangle, style::START, "start"),
        (goal, away_from_goal, Marker::Star, style::GOAL, "goal"),
    ] {
        if !(p.x.is_finite() && p.y.is_finite()) {
            continue;
        }
        let c = to_px(chart, p.x / u, p.y / u);
        style::draw_marker(&px, c, marker, color)?;
        let (tw, th) = (style::text_width(label, style::LEGEND_PX).round() as i32 + 8, 18);
        // Candidate label boxes (top-left corners) right, left, above, below the marker.
        let candidates = [
            ((c.0 + 12, c.1 - th / 2), Vec2::new(1.0, 0.0)),
            ((c.0 - 12 - tw, c.1 - th / 2), Vec2::new(-1.0, 0.0)),
            ((c.0 - tw / 2, c.1 - 14 - th), Vec2::new(0.0, 1.0)),
            ((c.0 - tw / 2, c.1 + 14), Vec2::new(0.0, -1.0)),
        ];
        let fits =
            |&((x, y), _): &((i32, i32), Vec2)| x >= 2 && y >= 2 && x + tw <= pw as i32 - 2 && y + th <= ph as i32 - 2;
        let score = |d: Vec2| away.map(|a| a.normalize_or_zero().dot(d)).unwrap_or(d.x);
        let best = candidates
            .iter()
            .filter(|c| fits(c))
            .max_by(|a, b| score(a.1).total_cmp(&score(b.1)))
            .or(candidates.first())
            .map(|c| c.0)
            .unwrap_or(c);
        px.draw(&Rectangle::new([best, (best.0 + tw, best.1 + th)], style::fill(WHITE.mix(0.85)))).map_err(plot_err)?;
        px.draw(&Text::new(
            label,
            (best.0 + tw / 2, best.1 + th / 2),
            style::bold(style::LEGEND_PX).pos(Pos::new(HPos::Center, VPos::Center)),
        ))
        .map_err(plot_err)?;
    }
    Ok(())
}
