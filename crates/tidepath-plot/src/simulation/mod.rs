//! The figure of a replanning simulation (`tidepath simulate --plot sim.svg`): an overview plan
//! view of the whole flown track coloured by phase, then one small plan view per phase showing
//! the world as the vehicle knew it then, what it had not seen yet, the route ahead before and
//! after the phase and the replanned piece.
//!
//! Every map is the plan figure's (same layout, seabed, currents, obstacles, graticule), drawn
//! with `plan_view`'s functions. The overview and each panel are drawn as SVG documents of
//! their own and nested in the figure as `<svg class="sim-overview">` and
//! `<svg class="sim-panel" data-phase="k">` (`sim-panel sim-failed` for a failed phase), so a
//! panel's text is clipped at its edge rather than running into its neighbour's, and a test or
//! a reader's script can find each panel.

mod overview;
mod panel;
mod parts;
#[cfg(test)]
mod tests;

use std::path::Path;

use chrono::{DateTime, Utc};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::experiment::layout::{draw_title, render_svg, title_height};
use super::style::{self, plot_err, LegendEntry};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::planner::Focus;
use tidepath::world::{Obstacle, World};

/// Width of the simulation figure in pixels; its height follows from the phases.
pub(crate) const SIMULATION_FIGURE_WIDTH: u32 = 1500;
/// Most phases given a panel: with more, the first `MOST_PANELS - 1` and the last are drawn.
pub(crate) const MOST_PANELS: usize = 12;
const MARGIN: u32 = 12;
const OUTCOME_PX: f64 = 15.0;
const OUTCOME_LINE_H: u32 = 22;
const NOTE_LINE_H: u32 = 18;

/// One phase of a simulation, as drawn.
#[derive(Clone, Debug)]
pub struct SimPanel<'a> {
    /// e.g. "phase 2, t = 812 s: obstacle 1 sighted at 1500 m; route blocked; replanned window
    /// 20 → feasible". Wrapped to the panel's width (at most six lines). The overview's legend
    /// names the phase by the part before the first ';' (shortened when long).
    pub label: String,
    /// The world as the vehicle knew it after this phase's change (obstacles drawn where they
    /// are at `time`).
    pub known: &'a World,
    /// Obstacles that exist but the vehicle had not seen yet at `time` (drawn faint/dashed,
    /// "not yet seen").
    pub unseen: Vec<Obstacle>,
    pub time: f64,
    /// The vehicle's position at `time`.
    pub position: Vec3,
    /// The route ahead before the change (empty for phase 0), drawn dashed grey.
    pub old_route: &'a [Vec3],
    /// The route ahead after the phase (the replanned route, or the old one if kept).
    pub new_route: &'a [Vec3],
    /// The replanned window's piece, if the phase replanned (highlighted).
    pub piece: Option<&'a [Vec3]>,
    /// The phase ended the mission without a feasible route.
    pub failed: bool,
}

/// Everything shown in the figure of one simulation.
#[derive(Clone, Debug)]
pub struct SimulationFigure<'a> {
    pub title: String,
    /// The UTC instant of the scenario clock's zero, when the scenario has one: the overview
    /// states the time it shows as a date.
    pub epoch: Option<DateTime<Utc>>,
    /// The vehicle's safety distance (m), drawn as a dashed halo around obstacles.
    pub safety_distance: f64,
    pub start: Vec3,
    pub goal: Vec3,
    /// The executed track with its times (continuous; one point at every phase's time).
    pub track: &'a [Vec3],
    /// Arrival time (s, scenario clock) at each point of `track`; as long as `track`.
    pub track_times: &'a [f64],
    /// The phases in order of time; at least one (phase 0, the departure plan).
    pub phases: Vec<SimPanel<'a>>,
    /// One line: "reached the goal at t = 5012 s" or "phase 3: no feasible window up to the
    /// goal: ...".
    pub outcome: String,
    /// Places a failure is about (a bottleneck), as in [`PlanFigure`](crate::PlanFigure);
    /// marked on the overview.
    pub focus: Vec<Focus>,
}

/// The phases given a panel: all of them, or with more than [`MOST_PANELS`] the first
/// `MOST_PANELS - 1` and the last.
pub(crate) fn panel_phases(n: usize) -> Vec<usize> {
    if n <= MOST_PANELS {
        (0..n).collect()
    } else {
        (0..MOST_PANELS - 1).chain([n - 1]).collect()
    }
}

/// Columns of the panel grid: three, or four once three would make more than two rows
/// (except nine, a square).
fn columns(panels: usize) -> usize {
    if panels <= 6 || panels == 9 {
        3
    } else {
        4
    }
}

/// The region every map of the figure shows: the union of the phases' domains, grown to hold
/// the track, every route, position, start, goal and focus, so the maps line up.
fn view_rect(fig: &SimulationFigure) -> Result<(f64, f64, f64, f64)> {
    let (mut x0, mut y0, mut x1, mut y1) = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut grow = |p: &Vec3| {
        if p.x.is_finite() && p.y.is_finite() {
            (x0, y0, x1, y1) = (x0.min(p.x), y0.min(p.y), x1.max(p.x), y1.max(p.y));
        }
    };
    for ph in &fig.phases {
        grow(&ph.known.bounds.min);
        grow(&ph.known.bounds.max);
        let routes = ph.old_route.iter().chain(ph.new_route).chain(ph.piece.unwrap_or_default());
        routes.chain([&ph.position]).for_each(&mut grow);
    }
    fig.track.iter().chain([&fig.start, &fig.goal]).chain(fig.focus.iter().map(|f| &f.at)).for_each(&mut grow);
    if !(x1 > x0 && y1 > y0) {
        return Err(Error::input("simulation figure", "cannot plot a domain without horizontal extent"));
    }
    Ok((x0, y0, x1, y1))
}

/// Depth at which currents are drawn: the track's mean depth, else the first domain's middle.
fn current_depth(fig: &SimulationFigure) -> f64 {
    let zs: Vec<f64> = fig.track.iter().map(|p| p.z).filter(|z| z.is_finite()).collect();
    if zs.is_empty() {
        let b = fig.phases[0].known.bounds;
        0.5 * (b.min.z + b.max.z)
    } else {
        zs.iter().sum::<f64>() / zs.len() as f64
    }
}

/// `svg` (a whole document from plotters) as a nested `<svg>` placed at (x, y), with extra
/// attributes.
fn nest(svg: &str, (x, y): (u32, u32), attrs: &str) -> String {
    let body = svg.strip_prefix("<svg ").unwrap_or(svg);
    format!("<svg x=\"{x}\" y=\"{y}\" {attrs} {body}")
}

/// The outcome line, wrapped to the figure's width (bold text runs wider than the estimate).
fn outcome_lines(outcome: &str) -> Vec<String> {
    let width = (SIMULATION_FIGURE_WIDTH - 2 * MARGIN) as f64;
    parts::wrap_label(&format!("Outcome: {}", parts::clean(outcome)), width / 1.12, OUTCOME_PX, 4)
}

/// What is left out of the panels, or nothing.
fn left_out_note(n: usize) -> Option<String> {
    (n > MOST_PANELS).then(|| {
        let (a, b) = (MOST_PANELS - 1, n - 2);
        let which = if a == b { format!("phase {a}") } else { format!("phases {a} to {b}") };
        format!(
            "{} of {n} phases ({which}) have no panel here: the panels show phases 0 to {} and the last, \
             phase {}; the overview shows every phase.",
            n - MOST_PANELS,
            MOST_PANELS - 2,
            n - 1
        )
    })
}

/// Renders the figure to SVG text. Fails when there is no phase, when `track_times` is not as
/// long as `track`, or when the domain has no horizontal extent.
pub fn render_simulation_figure(fig: &SimulationFigure) -> Result<String> {
    if fig.phases.is_empty() {
        return Err(Error::input("simulation figure", "no phase to draw (phase 0 is the departure plan)"));
    }
    if fig.track.len() != fig.track_times.len() {
        return Err(Error::input(
            "simulation figure",
            format!("the track has {} points but {} times", fig.track.len(), fig.track_times.len()),
        ));
    }
    let view = view_rect(fig)?;
    let z = current_depth(fig);
    let w = SIMULATION_FIGURE_WIDTH;
    let inner_w = w - 2 * MARGIN;
    let title = parts::clean(&fig.title);
    let title_h = title_height(&title, w);
    let outcome = outcome_lines(&fig.outcome);
    let outcome_h = outcome.len() as u32 * OUTCOME_LINE_H + 6;

    let overview = overview::render(fig, view, z, inner_w)?;
    let overview_top = title_h + outcome_h;

    let shown = panel_phases(fig.phases.len());
    let legend = panel::legend(fig);
    let legend_w = inner_w - 20;
    let legend_h = style::legend_height(&legend, legend_w);
    let note = left_out_note(fig.phases.len());
    let note_lines = note.as_deref().map(|n| parts::wrap_label(n, legend_w as f64, style::LEGEND_PX, 3));
    let strip_top = overview_top + overview.1 + 8;
    let note_top = strip_top + 24 + legend_h;
    let grid_top = note_top + note_lines.as_ref().map_or(0, |l| l.len() as u32 * NOTE_LINE_H) + 6;

    let cols = columns(shown.len());
    let panel_w = inner_w / cols as u32;
    let layout = panel::layout(fig, &shown, view, panel_w);
    let panel_h = layout.size.1;
    let rows = shown.len().div_ceil(cols) as u32;
    let h = grid_top + rows * panel_h + MARGIN;

    let svg = render_svg((w, h), |root| {
        draw_title(root, &title)?;
        let color = if fig.phases.iter().any(|p| p.failed) { style::GOAL } else { style::TEXT };
        let font = style::bold(OUTCOME_PX).color(&color).pos(Pos::new(HPos::Center, VPos::Center));
        for (k, line) in outcome.iter().enumerate() {
            let y = (title_h + k as u32 * OUTCOME_LINE_H + OUTCOME_LINE_H / 2) as i32;
            root.draw(&Text::new(line.clone(), (w as i32 / 2, y), font.clone())).map_err(plot_err)?;
        }
        let heading = style::bold(style::CAPTION_PX).pos(Pos::new(HPos::Left, VPos::Center));
        let x0 = (MARGIN + 10) as i32;
        let text = format!("Phases, one panel each ({} of {})", shown.len(), fig.phases.len());
        root.draw(&Text::new(text, (x0, strip_top as i32 + 11), heading)).map_err(plot_err)?;
        let area = root.clone().shrink((x0, strip_top as i32 + 24), (legend_w, legend_h.max(1)));
        style::draw_legend(&area, &legend)?;
        let muted = style::bold(style::LEGEND_PX).color(&style::MUTED).pos(Pos::new(HPos::Left, VPos::Center));
        for (k, line) in note_lines.iter().flatten().enumerate() {
            let y = (note_top + k as u32 * NOTE_LINE_H + NOTE_LINE_H / 2) as i32;
            root.draw(&Text::new(line.clone(), (x0, y), muted.clone())).map_err(plot_err)?;
        }
        Ok(())
    })?;

    let mut nested = nest(&overview.0, (MARGIN, overview_top), "class=\"sim-overview\"");
    for (slot, &k) in shown.iter().enumerate() {
        let (c, r) = ((slot % cols) as u32, (slot / cols) as u32);
        let at = (MARGIN + c * panel_w, grid_top + r * panel_h);
        let class = if fig.phases[k].failed { "sim-panel sim-failed" } else { "sim-panel" };
        let doc = panel::render(fig, k, view, z, layout)?;
        nested.push_str(&nest(&doc, at, &format!("class=\"{class}\" id=\"sim-phase-{k}\" data-phase=\"{k}\"")));
    }
    let end = svg.rfind("</svg>").unwrap_or(svg.len());
    Ok(format!("{}{nested}{}", &svg[..end], &svg[end..]))
}

/// Renders the figure and writes it to `out` (an `.svg` file).
pub fn write_simulation_figure(fig: &SimulationFigure, out: &Path) -> Result<()> {
    let svg = render_simulation_figure(fig)?;
    std::fs::write(out, svg).map_err(|e| Error::io(out, e))
}

/// The legend entries every part of the figure shares: start and goal.
fn endpoint_entries() -> Vec<LegendEntry> {
    use super::style::{Marker, Swatch};
    vec![
        LegendEntry::new("start", Swatch::Marker(Marker::Triangle, style::START)),
        LegendEntry::new("goal", Swatch::Marker(Marker::Star, style::GOAL)),
    ]
}
