//! The plan view: seabed shading and contours, obstacles and currents at one time, and paths.
//!
//! The map keeps the domain's aspect ratio (a distorted map misleads about turning and about
//! distances to obstacles), so the plot size is computed here from the available area rather
//! than left to plotters.

mod graph;
mod graticule;
mod obstacles;
mod overlays;
mod seabed;
#[cfg(test)]
mod tests;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor;

use super::obstacle_look::ObstacleLook;
use super::style::{self, plot_err, LegendEntry, LengthUnit, Marker, Swatch};
use super::{failure, time_label, PlanFigure, PlotPath};
use graticule::Graticule;
use obstacles::{draw_mark_labels, draw_obstacle_motion, draw_obstacles, draw_safety_halos, draw_tracks, mark_times};
use overlays::{
    draw_endpoints, draw_focus, draw_paths, draw_quiver, draw_reference, draw_violated_segments,
    draw_violated_waypoints, quiver_px_per_speed, scale_speed, Quiver,
};
use seabed::{draw_colorbar_horizontal, draw_colorbar_vertical, draw_seabed, Seabed};
use tidepath::error::{Error, Result};
use tidepath::world::{Current, World};

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

const Y_LABEL_W: u32 = 74;
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

/// The region shown: the domain, grown to hold every path point, start, goal and focus so
/// nothing is squashed against the frame.
fn view_rect(fig: &PlanFigure) -> Result<(f64, f64, f64, f64)> {
    let b = fig.world.bounds;
    let (mut x0, mut y0, mut x1, mut y1) = (b.min.x, b.min.y, b.max.x, b.max.y);
    if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite() && x1 > x0 && y1 > y0) {
        return Err(Error::input(
            "world.bounds",
            format!("cannot plot a domain without horizontal extent: {:?} .. {:?}", b.min, b.max),
        ));
    }
    let paths = fig.paths.iter().chain(&fig.reference).flat_map(|p| p.points.iter());
    let extra = paths.chain([&fig.start, &fig.goal]).chain(fig.focus.iter().map(|f| &f.at));
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

/// Whether the picture depends on the time it is drawn at: a current that changes with time
/// or an obstacle that moves. Its caption then says which time it shows.
fn time_varying(world: &World) -> bool {
    let current = match &world.current {
        Current::Jet(_) => true,
        Current::Grid(g) => !g.is_steady(),
        Current::None | Current::Uniform(_) | Current::Vortices(_) => false,
    };
    current || world.obstacles.iter().any(obstacles::is_moving)
}

/// The instant the map shows, for captions and legends: "t = 0 s (departure)".
fn shown_at(fig: &PlanFigure) -> String {
    format!("{} (departure)", time_label::instant(fig.time, fig.epoch))
}

/// Draws the plan view (x east, y north) of `fig` with its legend and, when there is a
/// seabed, a colour bar. Paths take colours [`style::path_color`] in order.
pub fn draw_plan_view<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, fig: &PlanFigure) -> Result<()> {
    let (world, time, paths) = (fig.world, fig.time, fig.paths.as_slice());
    let view = view_rect(fig)?;
    let (x0, y0, x1, y1) = view;
    let unit = LengthUnit::for_extent((x1 - x0).max(y1 - y0));
    let seabed = Seabed::sample(&world.terrain, x0, y0, x1, y1);
    let quiver = Quiver::sample(world, time, current_depth(world, paths), view);
    let marks = mark_times(fig);

    // The scale arrow's length is known once the map is laid out; its legend entry keeps a
    // place as wide as the longest arrow can be and gets its length below.
    let (w, h) = area.dim_in_pixel();
    // The safety halo is drawn when it is at least two pixels wide (thinner, it would only
    // thicken the outline); the map is at most the area's width, which decides it before the
    // layout, since the legend says whether it is there.
    let halos = !world.obstacles.is_empty() && fig.safety_distance / (x1 - x0) * f64::from(w) >= 2.0;
    let mut legend = legend_entries(fig, seabed.as_ref(), quiver.as_ref(), !marks.is_empty(), halos);
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

    let caption = if time_varying(world) { format!("Plan view at {}", shown_at(fig)) } else { "Plan view".to_string() };
    let body = style::caption(area, &caption)?;
    let chart_area = body.clone().shrink((left, 0), (chart_w, chart_h));
    let (nx_labels, ny_labels) = ((plot_w / 70).clamp(2, 10) as usize, (plot_h / 45).clamp(2, 10) as usize);
    let u = unit.metres;
    let (rx, ry) = (x0 / u..x1 / u, y0 / u..y1 / u);
    // Geographic worlds: ticks where meridians and parallels meet the edges, in degrees.
    let graticule = world.frame.as_ref().map(|f| Graticule::new(f, view, nx_labels.min(7), ny_labels.min(6)));
    let mut chart = ChartBuilder::on(&chart_area)
        .margin_top(TOP_PAD)
        .margin_right(RIGHT_PAD)
        .x_label_area_size(X_LABEL_H)
        .y_label_area_size(Y_LABEL_W)
        .build_cartesian_2d(rx.clone(), ry.clone())
        .map_err(plot_err)?;
    let ticks_x = style::tick_formatter(rx, nx_labels);
    let ticks_y = style::tick_formatter(ry, ny_labels);
    // Geographic worlds label their own ticks (where meridians and parallels meet the edges).
    let geographic = graticule.is_some();
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(if geographic { 0 } else { nx_labels })
        .y_labels(if geographic { 0 } else { ny_labels })
        .x_desc(if geographic { "longitude".to_string() } else { format!("x east ({})", unit.name) })
        .y_desc(if geographic { "latitude".to_string() } else { format!("y north ({})", unit.name) })
        .x_label_formatter(&ticks_x)
        .y_label_formatter(&ticks_y)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;
    if let Some(g) = &graticule {
        draw_degree_ticks(&chart_area, &chart, g, view, u)?;
    }

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
    if let Some(g) = &graticule {
        for line in &g.lines {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    line.iter().map(|&(x, y)| (x / u, y / u)).collect::<Vec<_>>(),
                    style::line(style::MUTED.mix(0.45), 1),
                )))
                .map_err(plot_err)?;
        }
    }
    if let Some(q) = &quiver {
        draw_quiver(&chart, q, u)?;
        let len_px = (scale_speed(q.max_speed) * quiver_px_per_speed(&chart, q, u)).round() as i32;
        for e in legend.iter_mut() {
            if let Swatch::ScaledArrow { len_px: l, .. } = &mut e.swatch {
                *l = len_px.clamp(4, MAX_SCALE_ARROW_PX);
            }
        }
    }
    // The search graph under the obstacles' outlines and the paths, which stay readable.
    graph::draw_graphs(&chart, fig, u)?;
    let warn: Vec<usize> = fig.focus.iter().flat_map(|f| failure::obstacles_at(fig, f)).collect();
    draw_obstacles(&chart, fig, u, &warn)?;
    if halos {
        draw_safety_halos(&chart, fig, u)?;
    }
    draw_tracks(&chart, fig, u, &marks)?;
    draw_violated_segments(&chart, paths, u)?;
    draw_paths(&chart, paths, u)?;
    // Over the paths, dashed: a path that is the reference (an exact planner's) shows through.
    if let Some(r) = &fig.reference {
        draw_reference(&chart, r, u)?;
    }
    draw_violated_waypoints(&chart, paths, u)?;
    draw_obstacle_motion(&chart, fig, u)?;
    draw_mark_labels(&chart, fig, u, &marks)?;
    draw_endpoints(&chart, paths, fig.start, fig.goal, u)?;
    draw_focus(&chart, fig, u)?;
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

/// Tick marks and degree labels on the bottom and left edges, in pixels of `area`.
fn draw_degree_ticks<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    chart: &Chart<DB>,
    g: &Graticule,
    (x0, y0, _, _): (f64, f64, f64, f64),
    u: f64,
) -> Result<()> {
    let base = area.get_base_pixel();
    let font = style::font(style::TICK_PX);
    for (x, label) in &g.x_ticks {
        let (px, py) = chart.backend_coord(&(x / u, y0 / u));
        let (px, py) = (px - base.0, py - base.1);
        area.draw(&PathElement::new(vec![(px, py), (px, py + 5)], style::line(BLACK, 1))).map_err(plot_err)?;
        let t = font.clone().pos(text_anchor::Pos::new(text_anchor::HPos::Center, text_anchor::VPos::Top));
        area.draw(&Text::new(label.clone(), (px, py + 8), t)).map_err(plot_err)?;
    }
    for (y, label) in &g.y_ticks {
        let (px, py) = chart.backend_coord(&(x0 / u, y / u));
        let (px, py) = (px - base.0, py - base.1);
        area.draw(&PathElement::new(vec![(px - 5, py), (px, py)], style::line(BLACK, 1))).map_err(plot_err)?;
        let t = font.clone().pos(text_anchor::Pos::new(text_anchor::HPos::Right, text_anchor::VPos::Center));
        area.draw(&Text::new(label.clone(), (px - 8, py), t)).map_err(plot_err)?;
    }
    Ok(())
}

/// A path's legend entries: its line with a waypoint dot; or, flown with a turning radius,
/// the flown curve and the waypoints apart.
pub(crate) fn path_entries(i: usize, p: &PlotPath) -> Vec<LegendEntry> {
    let color = style::path_color(i);
    if p.points.is_empty() {
        return vec![LegendEntry::new(format!("{} (no path)", p.label), Swatch::Path(color))];
    }
    match p.flown.filter(|f| f.points.len() >= 2) {
        None => vec![LegendEntry::new(&p.label, Swatch::Path(color))],
        Some(f) => vec![
            LegendEntry::new(
                format!("{}: flown, turns of radius {} m", p.label, style::fmt_sig(f.radius)),
                Swatch::Line { color: color.to_rgba(), width: 3 },
            ),
            LegendEntry::new(format!("{}: waypoints (corners cut)", p.label), Swatch::Waypoints(color)),
        ],
    }
}

/// Longest scale arrow in the legend (pixels): the longest current arrow is 0.8 of the arrow
/// spacing, about 45 pixels on the widest map.
const MAX_SCALE_ARROW_PX: i32 = 48;

fn legend_entries(
    fig: &PlanFigure,
    seabed: Option<&Seabed>,
    quiver: Option<&Quiver>,
    marks: bool,
    halos: bool,
) -> Vec<LegendEntry> {
    let (world, paths) = (fig.world, fig.paths.as_slice());
    let mut out: Vec<LegendEntry> = paths.iter().enumerate().flat_map(|(i, p)| path_entries(i, p)).collect();
    if let Some(r) = &fig.reference {
        out.push(LegendEntry::new(&r.label, Swatch::DashedPath(style::REFERENCE)));
    }
    out.push(LegendEntry::new("start", Swatch::Marker(Marker::Triangle, style::START)));
    out.push(LegendEntry::new("goal", Swatch::Marker(Marker::Star, style::GOAL)));
    out.extend(graph::legend_entries(fig));
    let (seg, way) = failure::kinds(paths);
    if !seg.is_empty() {
        out.push(LegendEntry::new(failure::legend_text("violated segment", &seg), Swatch::Band(style::WARN.mix(0.65))));
    }
    if !way.is_empty() {
        out.push(LegendEntry::new(failure::legend_text("violated waypoint", &way), Swatch::Ring(style::WARN)));
    }
    for f in &fig.focus {
        out.push(LegendEntry::new(&f.label, Swatch::Ring(style::WARN)));
    }
    let mut looks: Vec<ObstacleLook> = world
        .obstacles
        .iter()
        .map(|o| ObstacleLook::of(&o.shape))
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    looks.sort();
    for look in looks {
        out.push(LegendEntry::new(look.label(), Swatch::Obstacle(look)));
    }
    if !world.obstacles.is_empty() && halos {
        out.push(LegendEntry::new(
            format!("safety distance ({} m)", style::fmt_sig(fig.safety_distance)),
            Swatch::Dashed(style::OBSTACLE_EDGE.mix(0.7)),
        ));
    }
    if world.obstacles.iter().any(obstacles::is_moving) {
        out.push(LegendEntry::new("obstacle velocity", Swatch::Arrow(style::OBSTACLE_EDGE)));
        if marks {
            out.push(LegendEntry::new(
                "obstacle (dashed) and vehicle (◇) at the same time after departure",
                Swatch::Diamond(style::OBSTACLE_EDGE),
            ));
        }
    }
    if let Some(q) = quiver {
        let at = if world.dims == tidepath::world::Dims::Two {
            "current".to_string()
        } else {
            format!("current at z = {} m", style::fmt_num(q.z, 1.0))
        };
        let when = if time_varying(world) { format!(", {}", shown_at(fig)) } else { String::new() };
        out.push(LegendEntry::new(
            format!(
                "{at}{when}: arrow = {} m/s (fastest {} m/s)",
                style::fmt_sig(scale_speed(q.max_speed)),
                style::fmt_sig(q.max_speed)
            ),
            Swatch::ScaledArrow { color: style::CURRENT, len_px: MAX_SCALE_ARROW_PX },
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
