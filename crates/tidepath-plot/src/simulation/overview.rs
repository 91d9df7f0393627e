//! The overview: the last phase's known world with the whole flown track coloured by phase,
//! a numbered badge where each phase began, the start, goal, failures and focus places, and a
//! legend naming each phase.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::experiment::layout::render_svg;
use super::super::plan_view::{
    draw_endpoints, draw_focus, draw_map, draw_obstacle_motion, draw_obstacles, draw_safety_halos, draw_unseen,
    halos_wide, map_frame, map_legend, time_varying, Chart, LabelBox, MapSpec, SpeedLabels, UNSEEN_EDGE,
};
use super::super::style::{self, plot_err, LegendEntry, Swatch};
use super::super::{failure, time_label, PlanFigure, PlotPath};
use super::parts::{self, draw_badge, draw_failure, draw_line, phase_color, phase_end, px, track_between, BADGE_R};
use super::SimulationFigure;
use tidepath::error::Result;

/// Tallest the overview's map gets (pixels).
const MAX_MAP_H: u32 = 540;
/// Longest phase name in the legend (characters).
const SHORT_LABEL: usize = 60;

/// The overview as an SVG document `width` wide, and its height.
pub(super) fn render(fig: &SimulationFigure, view: (f64, f64, f64, f64), z: f64, width: u32) -> Result<(String, u32)> {
    let n = fig.phases.len();
    let last = &fig.phases[n - 1];
    let mut plan = PlanFigure::new("", last.known, fig.start, fig.goal, last.time);
    plan.epoch = fig.epoch;
    plan.safety_distance = fig.safety_distance;
    plan.focus = fig.focus.clone();
    // The track as the path the start's and goal's labels keep clear of.
    plan.paths = vec![PlotPath::new("track", fig.track)];
    let halos = halos_wide(last.known, fig.safety_distance, view, width);
    let at = time_label::instant(last.time, fig.epoch);

    let mut spec = MapSpec::new(last.known, view, last.time, z);
    spec.caption = Some(format!(
        "Overview: the flown track coloured by phase, numbered where each phase began, \
         over the world as known at phase {} ({at})",
        n - 1
    ));
    let mut legend: Vec<LegendEntry> = fig
        .phases
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let name = parts::short_label(&p.label, SHORT_LABEL);
            let name = if name.starts_with("phase") { name } else { format!("phase {k}: {name}") };
            LegendEntry::new(name, Swatch::Line { color: phase_color(k).to_rgba(), width: 3 })
        })
        .collect();
    legend.extend(super::endpoint_entries());
    if fig.phases.iter().any(|p| p.failed) {
        legend.push(LegendEntry::new("mission ended: no feasible route", Swatch::Ring(style::WARN)));
    }
    for f in &fig.focus {
        legend.push(LegendEntry::new(parts::clean(&f.label), Swatch::Ring(style::WARN)));
    }
    if !last.unseen.is_empty() {
        legend.push(LegendEntry::new("obstacle not yet seen (at the end)", Swatch::Dashed(UNSEEN_EDGE)));
    }
    let when = time_varying(last.known).then(|| format!("{at} (phase {})", n - 1));
    legend.extend(map_legend(&plan, &spec, halos, None, when));
    spec.legend = legend;

    // As tall as a map filling the width needs, up to MAX_MAP_H, plus what goes around it.
    let (extra_w, extra_h) = map_frame(&spec, width);
    let (x0, y0, x1, y1) = view;
    let map_h = (f64::from(width.saturating_sub(extra_w)) * (y1 - y0) / (x1 - x0)).min(f64::from(MAX_MAP_H));
    let height = map_h.max(120.0).round() as u32 + extra_h + 8;

    let svg = render_svg((width, height), |root| {
        draw_map(root, spec, |chart, u| {
            let warn: Vec<usize> = plan.focus.iter().flat_map(|f| failure::obstacles_at(&plan, f)).collect();
            draw_obstacles(chart, &plan, u, &warn)?;
            if halos {
                draw_safety_halos(chart, &plan, u)?;
            }
            draw_unseen(chart, &last.unseen, last.time, u)?;
            draw_track_by_phase(chart, fig, u)?;
            // Labels first, then the badges and failure labels placed clear of them.
            let mut boxes = Vec::new();
            draw_obstacle_motion(chart, &plan, u, SpeedLabels::Clear, &mut boxes)?;
            boxes.extend(draw_endpoints(chart, &plan.paths, fig.start, fig.goal, u)?);
            boxes.extend(draw_focus(chart, &plan, u)?);
            draw_failures(chart, fig, u, &mut boxes)?;
            draw_badges(chart, fig, u, &boxes)
        })
    })?;
    Ok((svg, height))
}

/// The flown track, phase k's part (from its time to the next phase's) in its colour.
fn draw_track_by_phase<DB: DrawingBackend>(chart: &Chart<DB>, fig: &SimulationFigure, u: f64) -> Result<()> {
    let starts: Vec<f64> = fig.phases.iter().map(|p| p.time).collect();
    for k in 0..starts.len() {
        // Phase 0's part also takes whatever the track flew before it.
        let t0 = if k == 0 { f64::NEG_INFINITY } else { starts[k] };
        let part = track_between(fig.track, fig.track_times, t0, phase_end(&starts, k, fig.track_times));
        draw_line(chart, &part, u, phase_color(k), 3)?;
    }
    Ok(())
}

/// Whether a disc of radius `r` at `c` comes within a pixel of box `b`.
fn hits(c: (i32, i32), r: i32, b: &LabelBox) -> bool {
    let dx = (b[0].0 - c.0).max(c.0 - b[1].0).max(0);
    let dy = (b[0].1 - c.1).max(c.1 - b[1].1).max(0);
    dx * dx + dy * dy < (r + 1) * (r + 1)
}

/// Numbered badges where the phases began. A badge that would cover another, the start or
/// goal marker or a label moves to the nearest clear place around its point, with a leader
/// line.
fn draw_badges<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &SimulationFigure,
    u: f64,
    boxes: &[LabelBox],
) -> Result<()> {
    let area = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = area.dim_in_pixel();
    let r = BADGE_R + 1;
    let inside = |c: (i32, i32)| c.0 >= r && c.1 >= r && c.0 <= pw as i32 - r && c.1 <= ph as i32 - r;
    let mut taken: Vec<(i32, i32)> = [fig.start, fig.goal].into_iter().filter_map(|p| px(chart, p, u)).collect();
    let clear = |c: (i32, i32), taken: &[(i32, i32)]| {
        taken.iter().all(|t| f64::from(t.0 - c.0).hypot(f64::from(t.1 - c.1)) >= f64::from(2 * r))
            && !boxes.iter().any(|b| hits(c, r, b))
    };
    for (k, p) in fig.phases.iter().enumerate() {
        let Some(c) = px(chart, p.position, u) else { continue };
        // The place itself, else rings of candidate places around it, nearest first.
        let mut candidates = std::iter::once(c).chain([24.0, 44.0, 64.0, 84.0].into_iter().flat_map(|d: f64| {
            (0..16).map(move |j| {
                let a = std::f64::consts::TAU * (f64::from(j) / 16.0 + 0.125);
                (c.0 + (d * a.cos()).round() as i32, c.1 - (d * a.sin()).round() as i32)
            })
        }));
        let spot = candidates.find(|&q| inside(q) && clear(q, &taken)).unwrap_or(c);
        if spot != c {
            area.draw(&PathElement::new(vec![c, spot], style::line(style::OBSTACLE_EDGE, 1))).map_err(plot_err)?;
            area.draw(&Circle::new(c, 3, style::fill(phase_color(k)))).map_err(plot_err)?;
            area.draw(&Circle::new(c, 3, style::line(style::OBSTACLE_EDGE, 1))).map_err(plot_err)?;
        }
        draw_badge(&area, spot, k, phase_color(k))?;
        taken.push(spot);
    }
    Ok(())
}

/// A failure mark where a phase ended the mission, labelled beside it clear of `boxes` (when
/// it can be), and its label's box added to them.
fn draw_failures<DB: DrawingBackend>(
    chart: &Chart<DB>,
    fig: &SimulationFigure,
    u: f64,
    boxes: &mut Vec<LabelBox>,
) -> Result<()> {
    let area = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = area.dim_in_pixel();
    for (k, p) in fig.phases.iter().enumerate().filter(|(_, p)| p.failed) {
        let Some(c) = px(chart, p.position, u) else { continue };
        draw_failure(&area, c)?;
        let text = format!("phase {k}: no feasible route");
        let (tw, th) = ((style::text_width(&text, style::LEGEND_PX) * 1.12).round() as i32 + 12, 20);
        // Below right, below left, above right, above left of the mark, kept in the plot.
        let place = |(x, y): (i32, i32)| -> LabelBox {
            let x = x.clamp(2, (pw as i32 - tw - 2).max(2));
            let y = y.clamp(2, (ph as i32 - th - 2).max(2));
            [(x, y), (x + tw, y + th)]
        };
        let candidates = [
            (c.0 + 18, c.1 + 16),
            (c.0 - 18 - tw, c.1 + 16),
            (c.0 + 18, c.1 - 16 - th),
            (c.0 - 18 - tw, c.1 - 16 - th),
        ]
        .map(place);
        let overlaps = |b: &LabelBox| {
            boxes.iter().any(|o| b[0].0 < o[1].0 && o[0].0 < b[1].0 && b[0].1 < o[1].1 && o[0].1 < b[1].1)
        };
        let b = candidates.iter().find(|b| !overlaps(b)).copied().unwrap_or(candidates[0]);
        area.draw(&Rectangle::new(b, style::fill(WHITE.mix(0.9)))).map_err(plot_err)?;
        area.draw(&Rectangle::new(b, style::line(style::WARN, 2))).map_err(plot_err)?;
        let font = style::bold(style::LEGEND_PX).pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(text, (b[0].0 + 6, b[0].1 + th / 2), font)).map_err(plot_err)?;
        boxes.push(b);
    }
    Ok(())
}
