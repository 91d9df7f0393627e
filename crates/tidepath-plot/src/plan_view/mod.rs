//! The plan view: seabed shading and contours, obstacles and currents at one time, and paths.
//!
//! The map keeps the domain's aspect ratio (a distorted map misleads about turning and about
//! distances to obstacles), so the plot size is computed here from the available area rather
//! than left to plotters.

mod graticule;
mod overlays;
mod seabed;
#[cfg(test)]
mod tests;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor;

use super::style::{self, plot_err, LegendEntry, LengthUnit, Marker, Swatch};
use super::PlotPath;
use graticule::Graticule;
use overlays::{draw_endpoints, draw_obstacle_motion, draw_obstacles, draw_paths, draw_quiver, Quiver};
use seabed::{draw_colorbar_horizontal, draw_colorbar_vertical, draw_seabed, Seabed};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::world::World;

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
