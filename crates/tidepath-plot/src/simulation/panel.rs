//! One phase's panel: its label, then the plan view of the world as known at its time with
//! the obstacles not yet seen, the track flown so far, the route ahead before (dashed grey)
//! and after (the phase's colour) and the replanned piece, and the vehicle.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::experiment::layout::render_svg;
use super::super::plan_view::{
    draw_map, draw_obstacle_motion, draw_obstacles, draw_safety_halos, draw_unseen, halos_wide, map_frame, Chart,
    MapSpec, SpeedLabels, UNSEEN_EDGE,
};
use super::super::style::{self, plot_err, LegendEntry, Marker, Swatch};
use super::super::PlanFigure;
use super::parts::{
    self, band, draw_badge, draw_band, draw_dashed, draw_failure, draw_line, draw_vehicle, phase_color, phase_end, px,
    track_between, OLD_ROUTE,
};
use super::SimulationFigure;
use tidepath::error::Result;
use tidepath::world::Current;

/// The label's font size and line height (pixels).
const LABEL_PX: f64 = 13.0;
const LINE_H: u32 = 17;
/// Most lines of a label; a longer one ends in "…".
const MAX_LINES: usize = 6;
/// Room left of the label for the phase's badge, and the panel's inner margin.
const BADGE_W: u32 = 26;
const PAD: u32 = 6;
/// Current arrows each way on a panel's map (the plan view's fifteen crowd a small map).
const ARROW_CELLS: usize = 8;
const FAILED_LINE: &str = "the mission ended here: no feasible route";

/// The legend of what the panels draw, shown once above them.
pub(super) fn legend(fig: &SimulationFigure) -> Vec<LegendEntry> {
    let mut out = vec![
        LegendEntry::new("track flown so far (by phase)", Swatch::Line { color: phase_color(0).to_rgba(), width: 2 }),
        LegendEntry::new("route ahead before the change", Swatch::Dashed(OLD_ROUTE.to_rgba())),
        LegendEntry::new(
            "route ahead after the phase (its colour)",
            Swatch::Line { color: phase_color(1).to_rgba(), width: 2 },
        ),
        LegendEntry::new("replanned piece", Swatch::Band(band(phase_color(1)))),
        LegendEntry::new("vehicle at the phase's time", Swatch::Ring(style::OBSTACLE_EDGE)),
    ];
    if fig.phases.iter().any(|p| !p.unseen.is_empty()) {
        out.push(LegendEntry::new("obstacle not yet seen", Swatch::Dashed(UNSEEN_EDGE)));
    }
    if fig.phases.iter().any(|p| p.failed) {
        out.push(LegendEntry::new(FAILED_LINE, Swatch::Ring(style::WARN)));
    }
    if fig.phases.iter().any(|p| !matches!(p.known.current, Current::None)) {
        out.push(LegendEntry::new("current (arrows scaled to each panel's fastest)", Swatch::Arrow(style::CURRENT)));
    }
    out.extend(super::endpoint_entries());
    out
}

/// Width left for a label's lines in a panel `w` wide.
fn label_width(w: u32) -> f64 {
    f64::from(w.saturating_sub(BADGE_W + 3 * PAD))
}

/// A phase's label as drawn: wrapped, and a failed phase's extra line.
fn label_lines(fig: &SimulationFigure, k: usize, w: u32) -> Vec<String> {
    let p = &fig.phases[k];
    let mut lines = parts::wrap_label(&parts::clean(&p.label), label_width(w), LABEL_PX, MAX_LINES);
    if p.failed {
        lines.extend(parts::wrap_label(FAILED_LINE, label_width(w) / 1.12, LABEL_PX, 2));
    }
    lines
}

/// The map of phase `k`, without caption, legend or colour bar (the overview has them).
fn spec<'w>(fig: &SimulationFigure<'w>, k: usize, view: (f64, f64, f64, f64), z: f64) -> MapSpec<'w> {
    let p = &fig.phases[k];
    let mut spec = MapSpec::with_arrows(p.known, view, p.time, z, ARROW_CELLS);
    spec.colorbar = false;
    spec
}

/// The layout every panel shares, so the grid's maps line up: the label's height (that of the
/// longest label among the panels drawn) and the panel's, with a map as tall as the view's
/// aspect asks, within limits.
#[derive(Clone, Copy, Debug)]
pub(super) struct Layout {
    pub(super) size: (u32, u32),
    label_h: u32,
}

pub(super) fn layout(fig: &SimulationFigure, shown: &[usize], view: (f64, f64, f64, f64), w: u32) -> Layout {
    let lines = shown.iter().map(|&k| label_lines(fig, k, w).len()).max().unwrap_or(1) as u32;
    let label_h = PAD + lines * LINE_H + PAD;
    let (extra_w, extra_h) = map_frame(&spec(fig, 0, view, 0.0), w - 2 * PAD);
    let plot_w = f64::from(w.saturating_sub(2 * PAD + extra_w).max(60));
    let (x0, y0, x1, y1) = view;
    let plot_h = (plot_w * (y1 - y0) / (x1 - x0)).clamp(100.0, 1.3 * plot_w);
    Layout { size: (w, label_h + plot_h.round() as u32 + extra_h + PAD), label_h }
}

/// Phase `k`'s panel as an SVG document laid out by `layout`.
pub(super) fn render(
    fig: &SimulationFigure,
    k: usize,
    view: (f64, f64, f64, f64),
    z: f64,
    layout: Layout,
) -> Result<String> {
    let ((w, h), label_h) = (layout.size, layout.label_h);
    let p = &fig.phases[k];
    let color = phase_color(k);
    let lines = label_lines(fig, k, w);
    let mut plan = PlanFigure::new("", p.known, fig.start, fig.goal, p.time);
    plan.safety_distance = fig.safety_distance;
    let halos = halos_wide(p.known, fig.safety_distance, view, w);
    render_svg((w, h), |root| {
        // A thin frame around each panel; a failed phase's in the warning colour.
        let frame = if p.failed { style::line(style::WARN, 3) } else { style::line(style::GRID.mix(2.0), 1) };
        root.draw(&Rectangle::new([(1, 1), (w as i32 - 2, h as i32 - 2)], frame)).map_err(plot_err)?;
        let top = PAD as i32 + LINE_H as i32 / 2;
        draw_badge(root, (PAD as i32 + parts::BADGE_R + 1, top), k, color)?;
        let x = (PAD + BADGE_W + PAD) as i32;
        let n_label = lines.len() - usize::from(p.failed);
        for (j, line) in lines.iter().enumerate() {
            let ink = if j >= n_label { style::WARN } else { style::TEXT };
            // Regular weight: bold runs wider than the width the label was wrapped to.
            let font = if j >= n_label { style::bold(LABEL_PX) } else { style::font(LABEL_PX) };
            let font = font.color(&ink).pos(Pos::new(HPos::Left, VPos::Center));
            root.draw(&Text::new(line.clone(), (x, top + (j as u32 * LINE_H) as i32), font)).map_err(plot_err)?;
        }
        let map = root.clone().shrink((PAD as i32, label_h as i32), (w - 2 * PAD, h.saturating_sub(label_h + PAD)));
        draw_map(&map, spec(fig, k, view, z), |chart, u| {
            draw_obstacles(chart, &plan, u, &[])?;
            if halos {
                draw_safety_halos(chart, &plan, u)?;
            }
            draw_unseen(chart, &p.unseen, p.time, u)?;
            draw_routes(chart, fig, k, u)?;
            // Arrows without speeds (the overview states them), which would crowd a small map.
            draw_obstacle_motion(chart, &plan, u, SpeedLabels::Off, &mut Vec::new())?;
            let area = chart.plotting_area().strip_coord_spec();
            for (q, marker, c) in [(fig.start, Marker::Triangle, style::START), (fig.goal, Marker::Star, style::GOAL)] {
                if let Some(at) = px(chart, q, u) {
                    style::draw_marker(&area, at, marker, c)?;
                }
            }
            if let Some(at) = px(chart, p.position, u) {
                draw_vehicle(&area, at)?;
                if p.failed {
                    draw_failure(&area, at)?;
                }
            }
            Ok(())
        })
    })
}

/// The track flown up to the phase's time (each earlier phase's part in its colour), the old
/// route ahead dashed grey, the replanned piece's band and the new route in the phase's colour.
fn draw_routes<DB: DrawingBackend>(chart: &Chart<DB>, fig: &SimulationFigure, k: usize, u: f64) -> Result<()> {
    let p = &fig.phases[k];
    let starts: Vec<f64> = fig.phases.iter().map(|q| q.time).collect();
    for j in 0..k {
        let t0 = if j == 0 { f64::NEG_INFINITY } else { starts[j] };
        let t1 = phase_end(&starts, j, fig.track_times).min(p.time);
        draw_line(chart, &track_between(fig.track, fig.track_times, t0, t1), u, phase_color(j), 2)?;
    }
    draw_dashed(chart, p.old_route, u, OLD_ROUTE)?;
    if let Some(piece) = p.piece {
        draw_band(chart, piece, u, phase_color(k))?;
    }
    draw_line(chart, p.new_route, u, phase_color(k), 2)
}
