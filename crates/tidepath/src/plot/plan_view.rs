//! The plan view: seabed shading and contours, obstacles and currents at one time, and paths.
//!
//! The map keeps the domain's aspect ratio (a distorted map misleads about turning and about
//! distances to obstacles), so the plot size is computed here from the available area rather
//! than left to plotters.

use std::collections::HashMap;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::contour::{contour_lines, Raster};
use super::style::{self, plot_err, LegendEntry, LengthUnit, Marker, Swatch};
use super::PlotPath;
use crate::error::{Error, Result};
use crate::geom::{Aabb, Vec2, Vec3};
use crate::world::{Current, Obstacle, Shape, Terrain, World};

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Raster cells across the view for shading and contours.
const RASTER_CELLS: usize = 120;
/// Current arrows across the view.
const ARROW_CELLS: usize = 15;
const Y_LABEL_W: u32 = 64;
const X_LABEL_H: u32 = 46;
const TOP_PAD: u32 = 8;
const RIGHT_PAD: u32 = 16;
const COLORBAR_W: u32 = 104;
const COLORBAR_H: u32 = 48;

/// Where the colour bar goes: beside suits tall maps, below suits wide ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum BarPlace {
    Beside,
    Below,
}

/// Seabed sampled over the view, with the derived contour levels.
struct Seabed {
    raster: Raster,
    z_min: f64,
    z_max: f64,
    levels: Vec<f64>,
    step: f64,
}

impl Seabed {
    fn sample(terrain: &Terrain, x0: f64, y0: f64, x1: f64, y1: f64) -> Option<Self> {
        if matches!(terrain, Terrain::None) {
            return None;
        }
        let raster = Raster::sample(x0, y0, x1, y1, RASTER_CELLS + 1, RASTER_CELLS + 1, |x, y| terrain.elevation(x, y));
        let (z_min, z_max) = raster.finite_range()?;
        let (mut levels, step) = style::nice_levels(z_min, z_max, 8);
        // The zero level is drawn separately as the coastline.
        levels.retain(|v| v.abs() > step * 1e-9);
        Some(Self { raster, z_min, z_max, levels, step })
    }

    fn has_land(&self) -> bool {
        self.z_max > 0.0 && self.z_min < 0.0
    }
}

/// Current arrows sampled on a coarse grid: (x, y, u, v) in metres and m/s, with the speed
/// that maps to the longest arrow.
struct Quiver {
    arrows: Vec<(f64, f64, f64, f64)>,
    max_speed: f64,
    z: f64,
    spacing: f64,
}

impl Quiver {
    fn sample(world: &World, time: f64, z: f64, (x0, y0, x1, y1): (f64, f64, f64, f64)) -> Option<Self> {
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

/// The region shown: the domain, grown to hold every path point, start and goal so nothing is
/// squashed against the frame.
fn view_rect(world: &World, paths: &[PlotPath], start: Vec3, goal: Vec3) -> Result<(f64, f64, f64, f64)> {
    let b = world.bounds;
    let (mut x0, mut y0, mut x1, mut y1) = (b.min.x, b.min.y, b.max.x, b.max.y);
    if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite() && x1 > x0 && y1 > y0) {
        return Err(Error::input(
            "world.bounds",
            format!("cannot plot a domain without horizontal extent: {:?} .. {:?}", b.min, b.max),
        ));
    }
    let extra = paths.iter().flat_map(|p| p.points.iter()).chain([&start, &goal]);
    for p in extra.filter(|p| p.x.is_finite() && p.y.is_finite()) {
        x0 = x0.min(p.x);
        x1 = x1.max(p.x);
        y0 = y0.min(p.y);
        y1 = y1.max(p.y);
    }
    Ok((x0, y0, x1, y1))
}

/// Depth at which currents are drawn: where the first path travels, else mid-depth.
fn current_depth(world: &World, paths: &[PlotPath]) -> f64 {
    let zs: Vec<f64> =
        paths.iter().find(|p| !p.points.is_empty()).map(|p| p.points.iter().map(|q| q.z).collect()).unwrap_or_default();
    let zs: Vec<f64> = zs.into_iter().filter(|z| z.is_finite()).collect();
    if zs.is_empty() {
        0.5 * (world.bounds.min.z + world.bounds.max.z)
    } else {
        zs.iter().sum::<f64>() / zs.len() as f64
    }
}

/// Draws the plan view (x east, y north) with its legend and, when there is a seabed, a colour
/// bar. Paths take colours [`style::path_color`] in order.
pub fn draw_plan_view<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    world: &World,
    time: f64,
    paths: &[PlotPath],
    start: Vec3,
    goal: Vec3,
) -> Result<()> {
    let view = view_rect(world, paths, start, goal)?;
    let (x0, y0, x1, y1) = view;
    let unit = LengthUnit::for_extent((x1 - x0).max(y1 - y0));
    let seabed = Seabed::sample(&world.terrain, x0, y0, x1, y1);
    let quiver = Quiver::sample(world, time, current_depth(world, paths), view);

    let legend = legend_entries(world, time, paths, seabed.as_ref(), quiver.as_ref());
    let (w, h) = area.dim_in_pixel();
    let legend_w = w.saturating_sub(20).max(100);
    let legend_h = style::legend_height(&legend, legend_w);

    // Largest plot that keeps the aspect ratio and leaves room for labels and legend, with the
    // colour bar beside the map or under it, whichever leaves the bigger map.
    let (lx, ly) = ((x1 - x0) / unit.metres, (y1 - y0) / unit.metres);
    let base_w = w.saturating_sub(Y_LABEL_W + RIGHT_PAD + 4);
    let base_h = h.saturating_sub(style::CAPTION_H + TOP_PAD + X_LABEL_H + 8 + legend_h);
    let fit = |aw: u32, ah: u32| (aw.max(40) as f64 / lx).min(ah.max(40) as f64 / ly);
    let (bar, scale) = match seabed {
        None => (None, fit(base_w, base_h)),
        Some(_) => {
            let beside = fit(base_w.saturating_sub(COLORBAR_W), base_h);
            let below = fit(base_w, base_h.saturating_sub(COLORBAR_H));
            if beside >= below {
                (Some(BarPlace::Beside), beside)
            } else {
                (Some(BarPlace::Below), below)
            }
        }
    };
    let (plot_w, plot_h) = ((lx * scale).floor() as u32, (ly * scale).floor() as u32);
    let chart_w = Y_LABEL_W + plot_w + RIGHT_PAD;
    let chart_h = TOP_PAD + plot_h + X_LABEL_H;
    let block_w = chart_w + if bar == Some(BarPlace::Beside) { COLORBAR_W } else { 0 };
    let left = (w.saturating_sub(block_w) / 2) as i32;
    let legend_top = chart_h + 6 + if bar == Some(BarPlace::Below) { COLORBAR_H } else { 0 };

    let caption =
        if time == 0.0 { "Plan view".to_string() } else { format!("Plan view at t = {} s", style::fmt_sig(time)) };
    let body = style::caption(area, &caption)?;
    let chart_area = body.clone().shrink((left, 0), (chart_w, chart_h));
    let mut chart = ChartBuilder::on(&chart_area)
        .margin_top(TOP_PAD)
        .margin_right(RIGHT_PAD)
        .x_label_area_size(X_LABEL_H)
        .y_label_area_size(Y_LABEL_W)
        .build_cartesian_2d(x0 / unit.metres..x1 / unit.metres, y0 / unit.metres..y1 / unit.metres)
        .map_err(plot_err)?;
    let (nx_labels, ny_labels) = ((plot_w / 70).clamp(2, 10) as usize, (plot_h / 45).clamp(2, 10) as usize);
    let ticks_x = style::tick_formatter(x0 / unit.metres..x1 / unit.metres, nx_labels);
    let ticks_y = style::tick_formatter(y0 / unit.metres..y1 / unit.metres, ny_labels);
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(nx_labels)
        .y_labels(ny_labels)
        .x_desc(format!("x east ({})", unit.name))
        .y_desc(format!("y north ({})", unit.name))
        .x_label_formatter(&ticks_x)
        .y_label_formatter(&ticks_y)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;

    let u = unit.metres;
    match &seabed {
        Some(s) => draw_seabed(&chart, s, u)?,
        None => {
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(x0 / u, y0 / u), (x1 / u, y1 / u)],
                    style::fill(style::NO_TERRAIN_BG),
                )))
                .map_err(plot_err)?;
        }
    }
    if let Some(q) = &quiver {
        draw_quiver(&chart, q, u)?;
    }
    draw_obstacles(&chart, world, time, u)?;
    draw_paths(&chart, paths, u)?;
    draw_obstacle_motion(&chart, world, time, u)?;
    draw_endpoints(&chart, paths, start, goal, u)?;
    // Frame on top of the shading, which otherwise covers the axis line's inner half.
    chart
        .draw_series(std::iter::once(Rectangle::new([(x0 / u, y0 / u), (x1 / u, y1 / u)], style::line(BLACK, 1))))
        .map_err(plot_err)?;

    if let (Some(s), Some(place)) = (&seabed, bar) {
        match place {
            BarPlace::Beside => {
                let area = body.clone().shrink((left + chart_w as i32 + 6, TOP_PAD as i32), (COLORBAR_W - 6, plot_h));
                draw_colorbar_vertical(&area, s)?;
            }
            BarPlace::Below => {
                let bar_w = plot_w.saturating_sub(190).clamp(120, 480);
                let area = body.clone().shrink((left + Y_LABEL_W as i32, chart_h as i32), (bar_w + 200, COLORBAR_H));
                draw_colorbar_horizontal(&area, s, bar_w)?;
            }
        }
    }
    let legend_area = body.shrink((10, legend_top as i32), (legend_w, legend_h.max(1)));
    style::draw_legend(&legend_area, &legend)
}

fn legend_entries(
    world: &World,
    time: f64,
    paths: &[PlotPath],
    seabed: Option<&Seabed>,
    quiver: Option<&Quiver>,
) -> Vec<LegendEntry> {
    let mut out: Vec<LegendEntry> =
        paths.iter().enumerate().map(|(i, p)| LegendEntry::new(&p.label, Swatch::Path(style::path_color(i)))).collect();
    out.push(LegendEntry::new("start", Swatch::Marker(Marker::Triangle, style::START)));
    out.push(LegendEntry::new("goal", Swatch::Marker(Marker::Star, style::GOAL)));
    if !world.obstacles.is_empty() {
        let label =
            if time == 0.0 { "obstacle".to_string() } else { format!("obstacle at t = {} s", style::fmt_sig(time)) };
        out.push(LegendEntry::new(
            label,
            Swatch::Fill { color: style::OBSTACLE_FILL, edge: Some(style::OBSTACLE_EDGE) },
        ));
        if world.obstacles.iter().any(|o| o.velocity.truncate().length() > 0.0) {
            out.push(LegendEntry::new("obstacle velocity", Swatch::Arrow(style::OBSTACLE_EDGE)));
        }
    }
    if let Some(q) = quiver {
        out.push(LegendEntry::new(
            format!("current at z = {} m (max {} m/s)", style::fmt_num(q.z, 1.0), style::fmt_sig(q.max_speed)),
            Swatch::Arrow(style::CURRENT),
        ));
    }
    if let Some(s) = seabed {
        if !s.levels.is_empty() {
            out.push(LegendEntry::new(
                format!("elevation contours every {} m", style::fmt_sig(s.step)),
                Swatch::Line { color: style::CONTOUR.mix(1.6), width: 1 },
            ));
        }
        if s.has_land() {
            out.push(LegendEntry::new("coastline", Swatch::Line { color: style::COAST.to_rgba(), width: 2 }));
        }
    }
    out
}

/// A block of raster cells [i0, i1) x [j0, j1) of one colour.
type Block = (usize, usize, usize, usize, RGBColor);
/// A colour as a hashable key.
type Rgb = (u8, u8, u8);
/// A run of cells [i0, i1) of one colour within a row.
type Run = (usize, usize, Rgb);

/// Covers the raster with few rectangles: the most common colour becomes one background block
/// and the remaining cells merge into runs along rows, then into stacks of identical runs. This
/// keeps the SVG several times smaller than one `<rect>` per cell.
fn seabed_blocks(s: &Seabed) -> Vec<Block> {
    let r = &s.raster;
    let (cx, cy) = (r.nx - 1, r.ny - 1);
    // Each cell takes the mean of its corners, which is what the contours see.
    let colors: Vec<RGBColor> = (0..cy)
        .flat_map(|j| (0..cx).map(move |i| (i, j)))
        .map(|(i, j)| {
            let z = 0.25 * (r.at(i, j) + r.at(i + 1, j) + r.at(i, j + 1) + r.at(i + 1, j + 1));
            if z.is_finite() {
                style::elevation_color(z, s.z_min, s.z_max)
            } else {
                style::NO_TERRAIN_BG
            }
        })
        .collect();
    let key = |c: RGBColor| -> Rgb { (c.0, c.1, c.2) };
    let mut counts: HashMap<Rgb, usize> = HashMap::new();
    for &c in &colors {
        *counts.entry(key(c)).or_default() += 1;
    }
    let background = colors.iter().copied().max_by_key(|&c| (counts[&key(c)], key(c))).unwrap_or(style::NO_TERRAIN_BG);
    let mut blocks: Vec<Block> = vec![(0, cx, 0, cy, background)];
    // Open stacks: run (i0, i1, colour) -> first row.
    let mut open: HashMap<Run, usize> = HashMap::new();
    for j in 0..=cy {
        let mut next = HashMap::new();
        if j < cy {
            let row = &colors[j * cx..(j + 1) * cx];
            let mut i0 = 0;
            for i in 1..=cx {
                if i == cx || row[i] != row[i0] {
                    if row[i0] != background {
                        let k = (i0, i, key(row[i0]));
                        next.insert(k, open.remove(&k).unwrap_or(j));
                    }
                    i0 = i;
                }
            }
        }
        let mut closed: Vec<_> = open.drain().collect();
        closed.sort_unstable();
        blocks.extend(closed.into_iter().map(|((i0, i1, (cr, cg, cb)), j0)| (i0, i1, j0, j, RGBColor(cr, cg, cb))));
        open = next;
    }
    blocks
}

fn draw_seabed<DB: DrawingBackend>(chart: &Chart<DB>, s: &Seabed, u: f64) -> Result<()> {
    let r = &s.raster;
    let plot = chart.plotting_area();
    for (i0, i1, j0, j1, c) in seabed_blocks(s) {
        let a = ((r.x0 + r.dx * i0 as f64) / u, (r.y0 + r.dy * j0 as f64) / u);
        let b = ((r.x0 + r.dx * i1 as f64) / u, (r.y0 + r.dy * j1 as f64) / u);
        plot.draw(&Rectangle::new([a, b], style::fill(c))).map_err(plot_err)?;
    }

    let scaled = |line: Vec<(f64, f64)>| line.into_iter().map(|(x, y)| (x / u, y / u)).collect::<Vec<_>>();
    for &level in &s.levels {
        let lines = contour_lines(r, level);
        for l in lines {
            plot.draw(&PathElement::new(scaled(l), style::line(style::CONTOUR, 1))).map_err(plot_err)?;
        }
    }
    if s.has_land() {
        let lines = contour_lines(r, 0.0);
        for l in lines {
            plot.draw(&PathElement::new(scaled(l), style::line(style::COAST, 2))).map_err(plot_err)?;
        }
    }
    Ok(())
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

fn draw_obstacles<DB: DrawingBackend>(chart: &Chart<DB>, world: &World, time: f64, u: f64) -> Result<()> {
    let plot = chart.plotting_area();
    for (outline, _) in world.obstacles.iter().filter_map(|o| obstacle_outline(o, time, u)) {
        plot.draw(&Polygon::new(outline.clone(), style::fill(style::OBSTACLE_FILL))).map_err(plot_err)?;
        plot.draw(&PathElement::new(outline, style::line(style::OBSTACLE_EDGE, 1))).map_err(plot_err)?;
    }
    Ok(())
}

/// Velocity arrows of moving obstacles with their speed, drawn above paths and currents so the
/// labels stay legible.
fn draw_obstacle_motion<DB: DrawingBackend>(chart: &Chart<DB>, world: &World, time: f64, u: f64) -> Result<()> {
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

fn draw_quiver<DB: DrawingBackend>(chart: &Chart<DB>, q: &Quiver, u: f64) -> Result<()> {
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

fn draw_paths<DB: DrawingBackend>(chart: &Chart<DB>, paths: &[PlotPath], u: f64) -> Result<()> {
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

fn draw_endpoints<DB: DrawingBackend>(
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

/// Labelled ticks of the colour bar: the contour levels, and the coastline level.
fn colorbar_ticks(s: &Seabed) -> Vec<f64> {
    if s.levels.is_empty() {
        // A (nearly) flat seabed has no contours; its extremes are all there is to say.
        let mut ends = vec![s.z_min, s.z_max];
        ends.dedup();
        return ends;
    }
    let mut ticks: Vec<f64> = s.levels.clone();
    if s.has_land() {
        ticks.push(0.0);
        ticks.sort_by(f64::total_cmp);
    }
    ticks
}

/// How many ticks to skip between labels so labels stay `min_gap` pixels apart on a bar of
/// `len` pixels.
fn label_every(s: &Seabed, len: f64, min_gap: f64) -> usize {
    let span = s.z_max - s.z_min;
    let px_per_step = if span > 0.0 { len * s.step / span } else { len };
    (min_gap / px_per_step).ceil().max(1.0) as usize
}

/// Pixel runs [k0, k1) of one colour along a colour bar `len` pixels long, where pixel k shows
/// the elevation `z_at((k + 0.5) / len)`; runs keep the bar to a few dozen SVG elements.
fn gradient_runs(len: u32, z_at: impl Fn(f64) -> f64, s: &Seabed) -> Vec<(i32, i32, RGBColor)> {
    let n = len.max(2) as i32;
    let mut runs: Vec<(i32, i32, RGBColor)> = Vec::new();
    for k in 0..n {
        let c = style::elevation_color(z_at((k as f64 + 0.5) / n as f64), s.z_min, s.z_max);
        match runs.last_mut() {
            Some(last) if last.2 == c => last.1 = k + 1,
            _ => runs.push((k, k + 1, c)),
        }
    }
    runs
}

/// Vertical colour bar of the seabed shading, labelled at the contour levels.
fn draw_colorbar_vertical<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, s: &Seabed) -> Result<()> {
    let (_, h) = area.dim_in_pixel();
    let (bar_x0, bar_x1) = (0i32, 16i32);
    let span = s.z_max - s.z_min;
    let y_of = |z: f64| -> i32 {
        if span > 0.0 {
            ((s.z_max - z) / span * (h as f64 - 1.0)).round() as i32
        } else {
            h as i32 / 2
        }
    };
    for (k0, k1, c) in gradient_runs(h, |t| s.z_max - span * t, s) {
        area.draw(&Rectangle::new([(bar_x0, k0), (bar_x1, k1)], style::fill(c))).map_err(plot_err)?;
    }
    area.draw(&Rectangle::new([(bar_x0, 0), (bar_x1, h as i32 - 1)], style::line(BLACK, 1))).map_err(plot_err)?;
    let every = label_every(s, h as f64, 16.0);
    let label = style::font(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (k, &z) in colorbar_ticks(s).iter().enumerate() {
        let y = y_of(z);
        area.draw(&PathElement::new(vec![(bar_x0, y), (bar_x1 + 3, y)], style::line(BLACK.mix(0.7), 1)))
            .map_err(plot_err)?;
        if k % every == 0 || z == 0.0 {
            area.draw(&Text::new(style::fmt_num(z, s.step), (bar_x1 + 6, y), label.clone())).map_err(plot_err)?;
        }
    }
    let title =
        style::font(style::AXIS_DESC_PX).pos(Pos::new(HPos::Center, VPos::Center)).transform(FontTransform::Rotate270);
    area.draw(&Text::new("seabed elevation (m)", (bar_x1 + 70, h as i32 / 2), title)).map_err(plot_err)?;
    Ok(())
}

/// Horizontal colour bar `bar_w` pixels long with labels under it and its title to the right.
fn draw_colorbar_horizontal<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, s: &Seabed, bar_w: u32) -> Result<()> {
    let (bar_y0, bar_y1) = (10i32, 24i32);
    let span = s.z_max - s.z_min;
    let x_of = |z: f64| -> i32 {
        if span > 0.0 {
            ((z - s.z_min) / span * (bar_w as f64 - 1.0)).round() as i32
        } else {
            bar_w as i32 / 2
        }
    };
    for (k0, k1, c) in gradient_runs(bar_w, |t| s.z_min + span * t, s) {
        area.draw(&Rectangle::new([(k0, bar_y0), (k1, bar_y1)], style::fill(c))).map_err(plot_err)?;
    }
    area.draw(&Rectangle::new([(0, bar_y0), (bar_w as i32 - 1, bar_y1)], style::line(BLACK, 1))).map_err(plot_err)?;
    let ticks = colorbar_ticks(s);
    let widest = ticks.iter().map(|&z| style::fmt_num(z, s.step).len()).max().unwrap_or(1);
    let every = label_every(s, bar_w as f64, style::text_width(&"0".repeat(widest), style::TICK_PX) + 10.0);
    let label = style::font(style::TICK_PX).pos(Pos::new(HPos::Center, VPos::Top));
    for (k, &z) in ticks.iter().enumerate() {
        let x = x_of(z);
        area.draw(&PathElement::new(vec![(x, bar_y0), (x, bar_y1 + 3)], style::line(BLACK.mix(0.7), 1)))
            .map_err(plot_err)?;
        if k % every == 0 || z == 0.0 {
            area.draw(&Text::new(style::fmt_num(z, s.step), (x, bar_y1 + 5), label.clone())).map_err(plot_err)?;
        }
    }
    let title = style::font(style::AXIS_DESC_PX).pos(Pos::new(HPos::Left, VPos::Center));
    area.draw(&Text::new("seabed elevation (m)", (bar_w as i32 + 14, (bar_y0 + bar_y1) / 2), title))
        .map_err(plot_err)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seabed_blocks_paint_every_cell_its_own_colour() {
        let raster = Raster::sample(0.0, 0.0, 10.0, 8.0, 21, 17, |x, y| {
            -500.0 + 300.0 * (-((x - 5.0).powi(2) + (y - 4.0).powi(2)) / 2.0).exp()
        });
        let (z_min, z_max) = raster.finite_range().unwrap();
        let s = Seabed { raster, z_min, z_max, levels: vec![], step: 100.0 };
        let (cx, cy) = (20, 16);
        // Paint the blocks in order (background first) and compare with each cell's colour.
        let mut painted = vec![None; cx * cy];
        let blocks = seabed_blocks(&s);
        for &(i0, i1, j0, j1, c) in &blocks {
            for j in j0..j1 {
                for i in i0..i1 {
                    painted[j * cx + i] = Some(c);
                }
            }
        }
        let r = &s.raster;
        for j in 0..cy {
            for i in 0..cx {
                let z = 0.25 * (r.at(i, j) + r.at(i + 1, j) + r.at(i, j + 1) + r.at(i + 1, j + 1));
                assert_eq!(painted[j * cx + i], Some(style::elevation_color(z, z_min, z_max)), "cell ({i}, {j})");
            }
        }
        assert!(blocks.len() < cx * cy / 2, "{} blocks for {} cells", blocks.len(), cx * cy);
    }
}
