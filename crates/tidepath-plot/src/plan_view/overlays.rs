//! What the plan view draws over the seabed: currents, paths (with their violations and the
//! reference), the start and goal markers, and the place a failure is about.

use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::failure;
use super::super::flown::Drawn;
use super::super::style::{self, plot_err, Marker};
use super::super::{PlanFigure, PlotPath};
use super::Chart;
use tidepath::error::Result;
use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::world::{Current, World};

/// Current arrows across the view (each way) of a full-size plan view.
pub(super) const ARROW_CELLS: usize = 15;

/// Current arrows sampled on a coarse grid: (x, y, u, v) in metres and m/s, with the speed
/// that maps to the longest arrow.
pub(super) struct Quiver {
    pub(super) arrows: Vec<(f64, f64, f64, f64)>,
    pub(super) max_speed: f64,
    pub(super) z: f64,
    pub(super) spacing: f64,
}

/// The round speed the legend's scale arrow stands for: 1, 2 or 5 times a power of ten, at
/// most the fastest current, so the scale arrow is never longer than the longest arrow.
pub(super) fn scale_speed(max_speed: f64) -> f64 {
    if !(max_speed > 0.0 && max_speed.is_finite()) {
        return 1.0;
    }
    let mag = 10f64.powf(max_speed.log10().floor());
    [5.0, 2.0, 1.0].into_iter().map(|m| m * mag).find(|&v| v <= max_speed * (1.0 + 1e-9)).unwrap_or(mag)
}

impl Quiver {
    /// The arrows on a grid of `cells` x `cells` over the view.
    pub(super) fn sample(
        world: &World,
        time: f64,
        z: f64,
        (x0, y0, x1, y1): (f64, f64, f64, f64),
        cells: usize,
    ) -> Option<Self> {
        if matches!(world.current, Current::None) {
            return None;
        }
        let (sx, sy) = ((x1 - x0) / cells as f64, (y1 - y0) / cells as f64);
        let mut arrows = Vec::with_capacity(cells * cells);
        let mut max_speed: f64 = 0.0;
        for j in 0..cells {
            for i in 0..cells {
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

/// Pixel position of a data point relative to the plotting area's top-left corner.
pub(crate) fn to_px<DB: DrawingBackend>(chart: &Chart<DB>, x: f64, y: f64) -> (i32, i32) {
    let (bx, by) = chart.plotting_area().get_base_pixel();
    let (px, py) = chart.backend_coord(&(x, y));
    (px - bx, py - by)
}

/// Pixels per m/s of the current arrows: the fastest current gets 0.8 of the arrow spacing.
pub(super) fn quiver_px_per_speed<DB: DrawingBackend>(chart: &Chart<DB>, q: &Quiver, u: f64) -> f64 {
    let (ox, _) = to_px(chart, 0.0, 0.0);
    let (sx, _) = to_px(chart, q.spacing / u, 0.0);
    let spacing_px = (sx - ox).abs() as f64;
    if q.max_speed > 0.0 && q.max_speed.is_finite() {
        0.8 * spacing_px / q.max_speed
    } else {
        0.0
    }
}

/// The current arrows, each on a pale `halo` when asked (over a colour map with dark shades).
pub(super) fn draw_quiver<DB: DrawingBackend>(chart: &Chart<DB>, q: &Quiver, u: f64, halo: bool) -> Result<()> {
    let per_speed = quiver_px_per_speed(chart, q, u);
    if per_speed <= 0.0 {
        return Ok(());
    }
    let px = chart.plotting_area().strip_coord_spec();
    for &(x, y, vx, vy) in &q.arrows {
        let len = (vx * vx + vy * vy).sqrt() * per_speed;
        if len < 2.0 {
            continue;
        }
        let (cx, cy) = to_px(chart, x / u, y / u);
        let s = (vx * vx + vy * vy).sqrt();
        let (dx, dy) = (vx / s * len / 2.0, -vy / s * len / 2.0);
        let from = (cx - dx.round() as i32, cy - dy.round() as i32);
        let to = (cx + dx.round() as i32, cy + dy.round() as i32);
        if halo {
            style::draw_arrow_halo_px(&px, from, to, WHITE.mix(0.7), 3)?;
        }
        style::draw_arrow_px(&px, from, to, style::CURRENT.mix(0.8), 1)?;
    }
    Ok(())
}

fn finite_points(p: &PlotPath, u: f64) -> Vec<(f64, f64)> {
    p.points.iter().filter(|q| q.x.is_finite() && q.y.is_finite()).map(|q| (q.x / u, q.y / u)).collect()
}

/// The reference path: dashed over the paths, with its points left out so it reads as a
/// guide rather than as one more planner's path, and a path equal to it shows between dashes.
pub(super) fn draw_reference<DB: DrawingBackend>(chart: &Chart<DB>, r: &PlotPath, u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    let pts = finite_points(r, u);
    if pts.len() >= 2 {
        plot.draw(&DashedPathElement::new(pts, 9, 7, style::line(style::REFERENCE, 2))).map_err(plot_err)?;
    }
    Ok(())
}

/// Bands under the violated segments, drawn before the paths so the path stays on top. On a
/// flown curve a segment's band covers the part the vehicle flies for it (its leg's straight
/// part and the turn at its end).
pub(super) fn draw_violated_segments<DB: DrawingBackend>(chart: &Chart<DB>, paths: &[PlotPath], u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    for p in paths {
        let drawn = Drawn::of(p);
        for v in p.violations.iter().filter(|v| failure::on_segment(v.kind)) {
            let part: Vec<Vec3> = match drawn.segment(v.index) {
                Some(r) => drawn.line[r].to_vec(),
                None => match (p.points.get(v.index), p.points.get(v.index + 1)) {
                    (Some(a), Some(b)) => vec![*a, *b],
                    _ => continue,
                },
            };
            if part.len() >= 2 && part.iter().all(|q| q.is_finite()) {
                let seg: Vec<(f64, f64)> = part.iter().map(|q| (q.x / u, q.y / u)).collect();
                plot.draw(&PathElement::new(seg, style::line(style::WARN.mix(0.65), 12))).map_err(plot_err)?;
            }
        }
    }
    Ok(())
}

/// Rings around the violated waypoints (a sharp turn, a point outside the depth band).
pub(super) fn draw_violated_waypoints<DB: DrawingBackend>(chart: &Chart<DB>, paths: &[PlotPath], u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    for p in paths {
        for v in p.violations.iter().filter(|v| !failure::on_segment(v.kind)) {
            if let Some(q) = p.points.get(v.index).filter(|q| q.is_finite()) {
                plot.draw(&Circle::new((q.x / u, q.y / u), 9, style::line(style::WARN, 2))).map_err(plot_err)?;
            }
        }
    }
    Ok(())
}

/// A label's box on the plotting area (pixels): top-left and bottom-right corners.
pub(crate) type LabelBox = [(i32, i32); 2];

/// The places failures are about: a ring with cross hairs, labelled with the focus's label and
/// what is there (the seabed's depth, the obstacle it is in). Returns the labels' boxes.
pub(crate) fn draw_focus<DB: DrawingBackend>(chart: &Chart<DB>, fig: &PlanFigure, u: f64) -> Result<Vec<LabelBox>> {
    let px = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = px.dim_in_pixel();
    let mut boxes = Vec::new();
    for f in fig.focus.iter().filter(|f| f.at.x.is_finite() && f.at.y.is_finite()) {
        let c = to_px(chart, f.at.x / u, f.at.y / u);
        px.draw(&Circle::new(c, 15, style::line(WHITE.mix(0.8), 6))).map_err(plot_err)?;
        px.draw(&Circle::new(c, 15, style::line(style::WARN, 3))).map_err(plot_err)?;
        for (dx, dy) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
            let line = vec![(c.0 + 9 * dx, c.1 + 9 * dy), (c.0 + 22 * dx, c.1 + 22 * dy)];
            px.draw(&PathElement::new(line, style::line(style::WARN, 2))).map_err(plot_err)?;
        }
        let mut lines = vec![f.label.clone()];
        lines.extend(failure::what_is_there(fig, f));
        let tw = lines.iter().map(|l| style::text_width(l, style::LEGEND_PX)).fold(0.0, f64::max).round() as i32 + 12;
        let th = 18 * lines.len() as i32 + 4;
        // Right of the mark when it fits, else left; above the centre, clear of the start and
        // goal labels, which go beside their markers.
        let bx = if c.0 + 26 + tw <= pw as i32 - 2 { c.0 + 26 } else { (c.0 - 26 - tw).max(2) };
        let by = (c.1 - 26 - th).clamp(2, (ph as i32 - th - 2).max(2));
        px.draw(&Rectangle::new([(bx, by), (bx + tw, by + th)], style::fill(WHITE.mix(0.9)))).map_err(plot_err)?;
        px.draw(&Rectangle::new([(bx, by), (bx + tw, by + th)], style::line(style::WARN, 2))).map_err(plot_err)?;
        for (k, l) in lines.into_iter().enumerate() {
            let font = if k == 0 { style::bold(style::LEGEND_PX) } else { style::font(style::LEGEND_PX) };
            let at = (bx + 6, by + 11 + 18 * k as i32);
            px.draw(&Text::new(l, at, font.pos(Pos::new(HPos::Left, VPos::Center)))).map_err(plot_err)?;
        }
        boxes.push([(bx, by), (bx + tw, by + th)]);
    }
    Ok(boxes)
}

/// Each path's line with a pale casing. A path without a flown curve has a dot at every
/// waypoint; with one, the flown curve is the line and the waypoints are small hollow markers
/// on a thin dashed line beneath it, so the corners the vehicle cuts show. Flown curves are
/// drawn over the other paths (a smoothed plan's raw path), which would otherwise hide them.
/// The path `by_speed` (coloured by its speed over ground, drawn apart after the others) gets
/// only its flown curve's dashed waypoint line here (its rings go over the coloured line), and the others (a smoothed plan's raw path) are
/// drawn thin beneath it, so its colours stay clear.
pub(super) fn draw_paths<DB: DrawingBackend>(
    chart: &Chart<DB>,
    paths: &[PlotPath],
    u: f64,
    by_speed: Option<usize>,
) -> Result<()> {
    let plot = chart.plotting_area();
    let finite = |pts: &[Vec3]| -> Vec<(f64, f64)> {
        pts.iter().filter(|q| q.x.is_finite() && q.y.is_finite()).map(|q| (q.x / u, q.y / u)).collect()
    };
    for (i, p, drawn) in flown_last(paths) {
        let color = style::path_color(i);
        let waypoints = finite(p.points);
        if drawn.flown && waypoints.len() >= 2 {
            plot.draw(&PathElement::new(waypoints.clone(), style::line(WHITE.mix(0.6), 3))).map_err(plot_err)?;
            plot.draw(&DashedPathElement::new(waypoints.clone(), 5, 4, style::line(color, 1))).map_err(plot_err)?;
        }
        let speed_coloured = by_speed == Some(i);
        let thin = by_speed.is_some() && !speed_coloured;
        let pts = finite(drawn.line);
        if pts.len() >= 2 && !speed_coloured {
            // A pale casing keeps the line readable over dark water and dark contours.
            let (casing, width) = if thin { (3, 1) } else { (5, 3) };
            plot.draw(&PathElement::new(pts.clone(), style::line(WHITE.mix(0.75), casing))).map_err(plot_err)?;
            plot.draw(&PathElement::new(pts.clone(), style::line(color, width))).map_err(plot_err)?;
        }
        let px: Vec<(i32, i32)> = waypoints.iter().map(|&(x, y)| to_px(chart, x, y)).collect();
        let marked = style::spaced_marks(&px, style::MARK_SPACING_PX);
        for (&q, &mark) in waypoints.iter().zip(&marked) {
            if drawn.flown {
                // Rings at least a few pixels apart: a tangent polygon's waypoints are dense.
                if mark && !speed_coloured {
                    plot.draw(&Circle::new(q, 3, style::fill(WHITE))).map_err(plot_err)?;
                    plot.draw(&Circle::new(q, 3, style::line(color, 1))).map_err(plot_err)?;
                }
            } else if thin {
                plot.draw(&Circle::new(q, 3, style::fill(WHITE))).map_err(plot_err)?;
                plot.draw(&Circle::new(q, 2, style::fill(color))).map_err(plot_err)?;
            } else if !speed_coloured {
                plot.draw(&Circle::new(q, 4, style::fill(WHITE))).map_err(plot_err)?;
                plot.draw(&Circle::new(q, 3, style::fill(color))).map_err(plot_err)?;
            }
        }
    }
    Ok(())
}

/// The paths with their index (their colour) and drawn line, flown curves last so they are
/// drawn on top; otherwise in order.
pub(super) fn flown_last<'p, 'a>(paths: &'p [PlotPath<'a>]) -> Vec<(usize, &'p PlotPath<'a>, Drawn<'a>)> {
    let mut out: Vec<_> = paths.iter().enumerate().map(|(i, p)| (i, p, Drawn::of(p))).collect();
    out.sort_by_key(|(_, _, d)| d.flown);
    out
}

/// The box of the start's or goal's label, the marker at pixel `c` in a plot of `pw` x `ph`:
/// right, left, above or below it, the fitting side most away from the path (`away`, the
/// direction from the path's neighbouring point); the right side when none fits. Shared with
/// the time ticks, whose labels keep clear of it.
pub(crate) fn endpoint_box(c: (i32, i32), away: Option<Vec2>, label: &str, (pw, ph): (i32, i32)) -> LabelBox {
    let (tw, th) = (style::text_width(label, style::LEGEND_PX).round() as i32 + 8, 18);
    let candidates = [
        ((c.0 + 12, c.1 - th / 2), Vec2::new(1.0, 0.0)),
        ((c.0 - 12 - tw, c.1 - th / 2), Vec2::new(-1.0, 0.0)),
        ((c.0 - tw / 2, c.1 - 14 - th), Vec2::new(0.0, 1.0)),
        ((c.0 - tw / 2, c.1 + 14), Vec2::new(0.0, -1.0)),
    ];
    let fits = |((x, y), _): &&((i32, i32), Vec2)| *x >= 2 && *y >= 2 && x + tw <= pw - 2 && y + th <= ph - 2;
    let score = |d: Vec2| away.map(|a| a.normalize_or_zero().dot(d)).unwrap_or(d.x);
    let best = candidates.iter().filter(fits).max_by(|a, b| score(a.1).total_cmp(&score(b.1)));
    let (x, y) = best.unwrap_or(&candidates[0]).0;
    [(x, y), (x + tw, y + th)]
}

/// The start and goal markers, each labelled on the side away from the first path; returns
/// the labels' boxes.
pub(crate) fn draw_endpoints<DB: DrawingBackend>(
    chart: &Chart<DB>,
    paths: &[PlotPath],
    start: Vec3,
    goal: Vec3,
    u: f64,
) -> Result<Vec<LabelBox>> {
    let mut boxes = Vec::new();
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
        let [best, corner] = endpoint_box(c, away, label, (pw as i32, ph as i32));
        let (tw, th) = (corner.0 - best.0, corner.1 - best.1);
        px.draw(&Rectangle::new([best, corner], style::fill(WHITE.mix(0.85)))).map_err(plot_err)?;
        boxes.push([best, corner]);
        px.draw(&Text::new(
            label,
            (best.0 + tw / 2, best.1 + th / 2),
            style::bold(style::LEGEND_PX).pos(Pos::new(HPos::Center, VPos::Center)),
        ))
        .map_err(plot_err)?;
    }
    Ok(boxes)
}
