//! Obstacles on the plan view: each kind its own look, the safety distance as a dashed halo,
//! and moving obstacles with their velocity and, when the paths are timed, their track with
//! time marks matching marks on the path, so a reader sees where both are at the same time.

use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::flown::Drawn;
use super::super::obstacle_look::{draw_circle_decor, ObstacleLook};
use super::super::style::{self, plot_err};
use super::super::{time_label, PlanFigure};
use super::overlays::{to_px, LabelBox};
use super::Chart;
use tidepath::error::Result;
use tidepath::geom::{Vec2, Vec3};
use tidepath::world::{Obstacle, Shape};

/// Most time marks along a track.
const MOST_MARKS: usize = 5;

/// Points of a circle as a polygon, so it is round in data units whatever the pixel scale.
pub(super) fn circle_points(c: Vec2, r: f64, u: f64) -> Vec<(f64, f64)> {
    (0..=64)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 64.0;
            ((c.x + r * a.cos()) / u, (c.y + r * a.sin()) / u)
        })
        .collect()
}

/// A rectangle grown by `s` with rounded corners (data units), the safety halo of a box.
fn rounded_rect(min: Vec2, max: Vec2, s: f64, u: f64) -> Vec<(f64, f64)> {
    let corners = [(max.x, max.y, 0.0), (min.x, max.y, 0.25), (min.x, min.y, 0.5), (max.x, min.y, 0.75)];
    let mut out = Vec::new();
    for (cx, cy, turn) in corners {
        for k in 0..=8 {
            let a = std::f64::consts::TAU * (turn + 0.25 * k as f64 / 8.0);
            out.push(((cx + s * a.cos()) / u, (cy + s * a.sin()) / u));
        }
    }
    out.push(out[0]);
    out
}

/// An obstacle's outline polygon (data units), horizontal centre and radius (metres; `None`
/// for boxes).
type Outline = (Vec<(f64, f64)>, Vec2, Option<f64>);

/// The [`Outline`] of an obstacle's shape, `None` where it has no finite place.
pub(super) fn outline(shape: &Shape, u: f64) -> Option<Outline> {
    let (outline, centre, radius) = match *shape {
        Shape::Sphere { center, radius } => {
            (circle_points(center.truncate(), radius, u), center.truncate(), Some(radius))
        }
        Shape::Cylinder { center, radius, .. } | Shape::Circle { center, radius } => {
            (circle_points(center, radius, u), center, Some(radius))
        }
        Shape::Box { min, max } => {
            let (a, b) = (min / u, max / u);
            let pts = vec![(a.x, a.y), (b.x, a.y), (b.x, b.y), (a.x, b.y), (a.x, a.y)];
            (pts, (min.truncate() + max.truncate()) * 0.5, None)
        }
    };
    outline.iter().all(|p| p.0.is_finite() && p.1.is_finite()).then_some((outline, centre, radius))
}

/// Pixels per data unit along x.
pub(super) fn px_per_unit<DB: DrawingBackend>(chart: &Chart<DB>) -> f64 {
    let r = chart.x_range();
    let (a, b) = (to_px(chart, r.start, 0.0).0, to_px(chart, r.end, 0.0).0);
    (b - a) as f64 / (r.end - r.start)
}

/// Every obstacle at `fig.time`, in the look of its kind; `warn` lists obstacles to outline
/// in the warning colour (those a failure's place is in).
pub(crate) fn draw_obstacles<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &PlanFigure,
    u: f64,
    warn: &[usize],
) -> Result<()> {
    let plot = chart.plotting_area();
    let px = plot.strip_coord_spec();
    let scale = px_per_unit(chart);
    for (k, o) in fig.world.obstacles.iter().enumerate() {
        let shape = o.shape_at(fig.time);
        let Some((pts, centre, radius)) = outline(&shape, u) else { continue };
        let look = ObstacleLook::of(&shape);
        plot.draw(&Polygon::new(pts.clone(), style::fill(look.fill()))).map_err(plot_err)?;
        if let Some(r) = radius {
            draw_circle_decor(&px, to_px(chart, centre.x / u, centre.y / u), r / u * scale, look)?;
        }
        let edge = if warn.contains(&k) { style::line(style::WARN, 3) } else { style::line(style::OBSTACLE_EDGE, 1) };
        plot.draw(&PathElement::new(pts, edge)).map_err(plot_err)?;
    }
    Ok(())
}

/// The halo at the vehicle's safety distance around every obstacle (the caller decides whether
/// it is wide enough to see).
pub(crate) fn draw_safety_halos<DB: DrawingBackend>(chart: &Chart<DB>, fig: &PlanFigure, u: f64) -> Result<()> {
    let s = fig.safety_distance;
    let plot = chart.plotting_area();
    for o in &fig.world.obstacles {
        let halo = match o.shape_at(fig.time) {
            Shape::Sphere { center, radius } => circle_points(center.truncate(), radius + s, u),
            Shape::Cylinder { center, radius, .. } | Shape::Circle { center, radius } => {
                circle_points(center, radius + s, u)
            }
            Shape::Box { min, max } => rounded_rect(min.truncate(), max.truncate(), s, u),
        };
        if halo.iter().all(|p| p.0.is_finite() && p.1.is_finite()) {
            plot.draw(&DashedPathElement::new(halo, 5, 4, style::line(style::OBSTACLE_EDGE.mix(0.7), 1)))
                .map_err(plot_err)?;
        }
    }
    Ok(())
}

/// The latest arrival time of any timed path, the end of the moving obstacles' tracks.
pub(super) fn horizon(fig: &PlanFigure) -> Option<f64> {
    let end =
        fig.paths.iter().filter_map(|p| p.times.last().copied()).filter(|t| t.is_finite()).fold(f64::NAN, f64::max);
    (end > fig.time).then_some(end)
}

/// Times of the marks between `fig.time` and the horizon, on round steps of the clock.
pub(super) fn mark_times(fig: &PlanFigure) -> Vec<f64> {
    let Some(end) = horizon(fig) else { return Vec::new() };
    if !fig.world.obstacles.iter().any(is_moving) {
        return Vec::new();
    }
    let step = time_label::mark_step(end - fig.time, MOST_MARKS);
    let first = (fig.time / step).floor() * step + step;
    (0..MOST_MARKS).map(|k| first + step * k as f64).filter(|&t| t <= end).collect()
}

pub(super) fn is_moving(o: &Obstacle) -> bool {
    let v = o.velocity.truncate().length();
    v > 0.0 && v.is_finite()
}

/// A time mark's text, relative to departure: "+1 h".
pub(super) fn mark_text(fig: &PlanFigure, t: f64) -> String {
    format!("+{}", time_label::span(t - fig.time))
}

/// Obstacles that exist but are not known yet (not yet sighted), where they are at `time`:
/// a faint dashed outline on a pale fill, so they read as there-but-unseen beside the known
/// obstacles' solid outlines.
pub(crate) fn draw_unseen<DB: DrawingBackend>(chart: &Chart<DB>, unseen: &[Obstacle], time: f64, u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    for o in unseen {
        let Some((pts, _, _)) = outline(&o.shape_at(time), u) else { continue };
        plot.draw(&Polygon::new(pts.clone(), style::fill(style::OBSTACLE_FILL.mix(0.35)))).map_err(plot_err)?;
        plot.draw(&DashedPathElement::new(pts, 4, 4, style::line(UNSEEN_EDGE, 1))).map_err(plot_err)?;
    }
    Ok(())
}

/// The outline of an obstacle not yet seen.
pub(crate) const UNSEEN_EDGE: RGBAColor = RGBAColor(30, 30, 30, 0.7);

/// Tracks of moving obstacles to the horizon, dashed outlines where they are at each mark.
pub(super) fn draw_tracks<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &PlanFigure,
    u: f64,
    marks: &[f64],
) -> Result<()> {
    let Some(end) = horizon(fig) else { return Ok(()) };
    let plot = chart.plotting_area();
    let track_style = style::line(style::OBSTACLE_EDGE.mix(0.6), 1);
    for o in fig.world.obstacles.iter().filter(|o| is_moving(o)) {
        let centre = |t: f64| outline(&o.shape_at(t), u).map(|(_, c, _)| (c.x / u, c.y / u));
        let (Some(a), Some(b)) = (centre(fig.time), centre(end)) else { continue };
        plot.draw(&DashedPathElement::new(vec![a, b], 2, 3, track_style)).map_err(plot_err)?;
        for &t in marks {
            if let Some((pts, _, _)) = outline(&o.shape_at(t), u) {
                plot.draw(&DashedPathElement::new(pts, 4, 3, style::line(style::OBSTACLE_EDGE.mix(0.75), 1)))
                    .map_err(plot_err)?;
            }
        }
    }
    Ok(())
}

/// Labels of the time marks: at each moving obstacle's centre and on the first timed path.
pub(super) fn draw_mark_labels<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &PlanFigure,
    u: f64,
    marks: &[f64],
) -> Result<()> {
    let px = chart.plotting_area().strip_coord_spec();
    let label = |at: (i32, i32), text: String, dy: i32| -> Result<()> {
        let (tw, th) = (style::text_width(&text, 11.0).round() as i32 + 6, 14);
        let (bx, by) = (at.0 - tw / 2, at.1 + dy - th / 2);
        px.draw(&Rectangle::new([(bx, by), (bx + tw, by + th)], style::fill(WHITE.mix(0.8)))).map_err(plot_err)?;
        let centre = Pos::new(HPos::Center, VPos::Center);
        px.draw(&Text::new(text, (at.0, at.1 + dy), style::font(11.0).pos(centre))).map_err(plot_err)
    };
    // A slow obstacle's marks crowd together: label only those clear of the last label and
    // of the speed label at departure (placed beyond the 34-pixel velocity arrow).
    const CLEAR_PX: f64 = 30.0;
    const CLEAR_OF_SPEED_PX: f64 = 64.0;
    for o in fig.world.obstacles.iter().filter(|o| is_moving(o)) {
        let at = |t: f64| outline(&o.shape_at(t), u).map(|(_, c, _)| to_px(chart, c.x / u, c.y / u));
        let Some(departure) = at(fig.time) else { continue };
        let dist = |a: (i32, i32), b: (i32, i32)| f64::from(a.0 - b.0).hypot(f64::from(a.1 - b.1));
        let far = |a: (i32, i32), b: (i32, i32)| dist(a, b) >= CLEAR_PX;
        let mut last = departure;
        for (k, &t) in marks.iter().enumerate() {
            let Some(c) = at(t) else { continue };
            let next_clear = marks.get(k + 1).and_then(|&n| at(n)).is_none_or(|n| far(n, c));
            let clear_of_speed = dist(c, departure) >= CLEAR_OF_SPEED_PX;
            if far(c, last) && clear_of_speed && (next_clear || k + 1 == marks.len()) {
                label(c, mark_text(fig, t), 0)?;
                last = c;
            }
        }
    }
    // Where the vehicle is: on the flown curve when the path has one.
    let drawn: Vec<Drawn> = fig.paths.iter().map(Drawn::of).collect();
    let Some(path) = drawn.iter().find(|d| d.times.len() == d.line.len() && d.line.len() >= 2) else {
        return Ok(());
    };
    for &t in marks {
        let Some(p) = position_at(path.line, path.times, t) else { continue };
        let c = to_px(chart, p.x / u, p.y / u);
        style::draw_diamond(&px, c, style::OBSTACLE_EDGE)?;
        label(c, mark_text(fig, t), -16)?;
    }
    Ok(())
}

/// Where a timed path is at time `t` (linear between its points); `None` outside its times.
pub(crate) fn position_at(points: &[Vec3], times: &[f64], t: f64) -> Option<Vec3> {
    let k = times.windows(2).position(|w| w[0] <= t && t <= w[1])?;
    let (t0, t1) = (times[k], times[k + 1]);
    let f = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
    Some(points[k].lerp(points[k + 1], f))
}

/// Which speed labels [`draw_obstacle_motion`] writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SpeedLabels {
    /// Every moving obstacle's.
    All,
    /// Those inside the map and clear of the labels before them (the boxes given, and the
    /// speed labels drawn); obstacles whose centre is off the map get no arrow either.
    Clear,
    /// None: the arrows alone (a small map), and only of obstacles whose centre is on it.
    Off,
}

/// Velocity arrows of moving obstacles with their speed, drawn above paths and currents so the
/// labels stay legible. `boxes` holds labels already on the map; the speed labels drawn are
/// added to it.
pub(crate) fn draw_obstacle_motion<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &PlanFigure,
    u: f64,
    labels: SpeedLabels,
    boxes: &mut Vec<LabelBox>,
) -> Result<()> {
    let px = chart.plotting_area().strip_coord_spec();
    for o in fig.world.obstacles.iter().filter(|o| is_moving(o)) {
        let v = o.velocity.truncate();
        let speed = v.length();
        let Some((_, centre, _)) = outline(&o.shape_at(fig.time), u) else { continue };
        // A fixed on-screen length: the arrow says where it is heading, the label how fast.
        let from = to_px(chart, centre.x / u, centre.y / u);
        let (pw, ph) = px.dim_in_pixel();
        let on_map = (0..=pw as i32).contains(&from.0) && (0..=ph as i32).contains(&from.1);
        if labels != SpeedLabels::All && !on_map {
            continue;
        }
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
        let overlaps = |b: &LabelBox| bx < b[1].0 && b[0].0 < bx + tw && by < b[1].1 && b[0].1 < by + th;
        let inside = bx >= 0 && by >= 0 && bx + tw <= pw as i32 && by + th <= ph as i32;
        let clear = inside && !boxes.iter().any(overlaps);
        if labels == SpeedLabels::Off || labels == SpeedLabels::Clear && !clear {
            continue;
        }
        px.draw(&Rectangle::new([(bx, by), (bx + tw, by + th)], style::fill(WHITE.mix(0.85)))).map_err(plot_err)?;
        boxes.push([(bx, by), (bx + tw, by + th)]);
        let centre = Pos::new(HPos::Center, VPos::Center);
        px.draw(&Text::new(text, (bx + tw / 2, by + th / 2), style::font(11.0).pos(centre))).map_err(plot_err)?;
    }
    Ok(())
}
