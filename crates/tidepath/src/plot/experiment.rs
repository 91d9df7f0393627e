//! Figures of an experiment: how planners converge, how their final costs spread over seeded
//! runs, and the best path each one found.
//!
//! A comparison is only honest if it shows the spread over runs, not one lucky seed, so the
//! convergence figure draws the median with the interquartile band and the box plot shows
//! every quartile and outlier. Several problems go into one figure as a grid of panels with
//! one shared legend, so a planner keeps its colour (and the reader their bearings) across
//! panels and across the three figures: colours follow the order in which planners first
//! appear in `problems`, and the paths figure colours paths in the order given, so pass the
//! paths in that same planner order.
//!
//! Cost axes switch to log10 when the costs span more than two decades, as in the plan figure.
//! Function benchmarks often reach a cost of exactly 0, which a log axis cannot show; rather
//! than fall back to a linear axis that flattens every other value into the floor, zeros are
//! drawn on their own line labelled "0", a decade below the smallest positive cost and below a
//! break in the axis, and the axis label and the figure note say so.

use std::ops::Range;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::convergence::{build, draw_curves, wants_log_scale, ConvergenceSeries, Y_LABELS};
use super::log_axis::{self, DecadeAxis, Decades};
use super::style::{self, plot_err, LegendEntry, Swatch};
use super::{draw_plan_view, draw_profile, PlotPath};
use crate::error::Result;
use crate::experiments::stats::Summary;
use crate::experiments::RunRecord;
use crate::geom::Vec3;
use crate::world::World;

/// One planner's runs on one problem.
#[derive(Clone, Debug, Default)]
pub struct PlannerRuns<'a> {
    pub planner: &'a str,
    /// Final cost of every run; non-finite costs (no solution) are counted, not plotted.
    pub costs: Vec<f64>,
    /// Best cost per iteration per run; NaN or infinite entries mean "no finite cost yet".
    pub histories: Vec<Vec<f64>>,
}

/// All planners' runs on one problem (one panel of the convergence and box plot figures).
#[derive(Clone, Debug, Default)]
pub struct ProblemRuns<'a> {
    pub problem: &'a str,
    pub planners: Vec<PlannerRuns<'a>>,
}

/// Groups run records by problem and planner, both in order of first appearance, so that the
/// figures show problems and colour planners in the order the experiment ran them.
pub fn group_runs(records: &[RunRecord]) -> Vec<ProblemRuns<'_>> {
    let mut out: Vec<ProblemRuns> = Vec::new();
    for r in records {
        let p = match out.iter().position(|p| p.problem == r.problem) {
            Some(k) => k,
            None => {
                out.push(ProblemRuns { problem: &r.problem, planners: Vec::new() });
                out.len() - 1
            }
        };
        let planners = &mut out[p].planners;
        let k = match planners.iter().position(|q| q.planner == r.planner) {
            Some(k) => k,
            None => {
                planners.push(PlannerRuns { planner: &r.planner, ..Default::default() });
                planners.len() - 1
            }
        };
        planners[k].costs.push(r.cost);
        planners[k].histories.push(r.history.iter().map(|v| v.unwrap_or(f64::INFINITY)).collect());
    }
    out
}

/// Label of a planner's best path in the paths figure, so the legend reads the same in every
/// report: "pso (best 1.23)".
pub fn best_path_label(planner: &str, cost: f64) -> String {
    if cost.is_finite() {
        format!("{planner} (best {})", style::fmt_sig(cost))
    } else {
        format!("{planner} (no finite cost)")
    }
}

const TITLE_H: u32 = 40;
const MARGIN: u32 = 12;
/// Left indent of the shared legend, matching the y label area so it lines up with the plots.
const LEGEND_INDENT: u32 = 64;
/// Size of the one panel of a single-problem figure, and of each panel of a grid.
const SINGLE_PANEL: (u32, u32) = (1000, 560);
const GRID_PANEL: (u32, u32) = (440, 330);
/// Room under a box plot for planner names on two staggered rows.
const BOX_LABEL_H: u32 = 44;

/// Columns and rows of the panel grid: as square as possible, at most four columns so that
/// panels keep readable tick labels. Twelve problems (six functions, small and wide) give 4 x 3,
/// which keeps each function's two variants side by side.
fn grid_shape(n: usize) -> (usize, usize) {
    let cols = match n {
        0 | 1 => 1,
        2 | 4 => 2,
        3 | 5 | 6 | 9 => 3,
        _ => 4,
    };
    (cols, n.max(1).div_ceil(cols))
}

/// Every planner of the experiment in order of first appearance; its position is its colour.
fn planner_order<'a>(problems: &[ProblemRuns<'a>]) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for p in problems.iter().flat_map(|p| &p.planners) {
        if !out.contains(&p.planner) {
            out.push(p.planner);
        }
    }
    out
}

fn color_index(order: &[&str], planner: &str) -> usize {
    order.iter().position(|p| *p == planner).unwrap_or(0)
}

/// How a cost axis maps values: linear, or log10 labelled at `decades`, with zeros drawn on
/// their own line at `zero_at`, a decade or more below the lowest labelled one and separated
/// from it by an axis break.
#[derive(Clone, Copy, Debug, PartialEq)]
enum CostAxis {
    Linear { lo: f64, hi: f64 },
    Log { lo: f64, hi: f64, zero_at: Option<f64>, decades: Decades },
}

impl CostAxis {
    /// The axis for `values` (non-finite ones ignored); `None` when no value is finite.
    fn for_values(values: impl IntoIterator<Item = f64>) -> Option<Self> {
        let finite: Vec<f64> = values.into_iter().filter(|v| v.is_finite()).collect();
        let lo = finite.iter().copied().reduce(f64::min)?;
        let hi = finite.iter().copied().fold(lo, f64::max);
        let has_zero = finite.contains(&0.0);
        if lo >= 0.0 && wants_log_scale(finite.iter().copied().filter(|v| *v > 0.0)) {
            let min_pos = finite.iter().copied().filter(|v| *v > 0.0).fold(f64::INFINITY, f64::min);
            let decades = Decades::for_values(min_pos, hi)?;
            let (lo, hi) = (decades.lo(), decades.hi());
            if has_zero {
                // The zero line sits a decade, or a tenth of the axis on one spanning many
                // decades, below the lowest label, so "0" and that label never touch; and a
                // third of that gap above the bottom so it is not hidden by the x axis.
                let gap = (f64::from(decades.top - decades.bottom) * 0.1).max(1.0);
                let z = lo / 10f64.powf(gap);
                return Some(CostAxis::Log { lo: lo / 10f64.powf(1.35 * gap), hi, zero_at: Some(z), decades });
            }
            return Some(CostAxis::Log { lo, hi, zero_at: None, decades });
        }
        let pad = if hi > lo { (hi - lo) * 0.05 } else { lo.abs().max(1.0) * 0.1 };
        Some(CostAxis::Linear { lo: lo - pad, hi: hi + pad })
    }

    /// The value to draw for cost `v`: zeros move to their line on a log axis.
    fn map(&self, v: f64) -> f64 {
        match *self {
            CostAxis::Log { zero_at: Some(z), .. } if v == 0.0 => z,
            _ => v,
        }
    }

    fn zero_at(&self) -> Option<f64> {
        match *self {
            CostAxis::Log { zero_at, .. } => zero_at,
            CostAxis::Linear { .. } => None,
        }
    }

    /// The zero line and the lowest labelled decade above it, between which the axis breaks.
    fn zero_gap(&self) -> Option<(f64, f64)> {
        match *self {
            CostAxis::Log { zero_at: Some(z), decades, .. } => Some((z, decades.lo())),
            _ => None,
        }
    }

    fn desc(&self, what: &str) -> String {
        match *self {
            CostAxis::Linear { .. } => what.to_string(),
            CostAxis::Log { zero_at: None, .. } => format!("{what} (log scale)"),
            CostAxis::Log { zero_at: Some(_), .. } => format!("{what} (log scale, 0 below break)"),
        }
    }

    /// Tick labels: powers of ten from 1e4 up as "1e4" rather than "10000", so labels of a
    /// many-decade axis have similar widths ([`log_axis::label`]); the zero line's tick is
    /// labelled by [`draw_zero_tick`] instead.
    fn tick_label(&self, v: f64) -> String {
        if self.zero_at().is_some_and(|z| v < z * 3.0) {
            return String::new();
        }
        log_axis::label(v)
    }
}

/// Labels the zero line of a log axis "0" and breaks the y axis above it, since the distance
/// from 0 to the smallest positive cost is not to scale. `axis_x` and `zero_y` are pixels of
/// `area`: the plot's left edge and the zero line.
fn draw_zero_tick<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, axis_x: i32, zero_y: i32, gap: i32) -> Result<()> {
    let text = style::font(style::TICK_PX).pos(Pos::new(HPos::Right, VPos::Center));
    area.draw(&Text::new("0", (axis_x - 10, zero_y), text)).map_err(plot_err)?;
    area.draw(&PathElement::new(vec![(axis_x - 6, zero_y), (axis_x - 1, zero_y)], style::line(BLACK, 1)))
        .map_err(plot_err)?;
    // The break: a gap in the axis line between two slashes, halfway to the lowest label.
    let y = zero_y - (gap / 2).clamp(5, 14);
    area.draw(&Rectangle::new([(axis_x - 4, y - 3), (axis_x + 2, y + 3)], style::fill(WHITE))).map_err(plot_err)?;
    for dy in [-3, 3] {
        area.draw(&PathElement::new(vec![(axis_x - 6, y + dy + 2), (axis_x + 4, y + dy - 2)], style::line(BLACK, 1)))
            .map_err(plot_err)?;
    }
    Ok(())
}

/// A history with its gaps filled the way a best-so-far curve means them: before the first
/// finite value there is no solution yet (+inf, worse than any cost, so it counts against the
/// planner in the quartiles), afterwards a missing entry repeats the last finite one.
fn fill_history(h: &[f64]) -> Vec<f64> {
    let mut last = f64::INFINITY;
    h.iter()
        .map(|&v| {
            if v.is_finite() {
                last = v;
            }
            last
        })
        .collect()
}

/// Per-iteration first quartile, median and third quartile over runs, each run padded to the
/// longest with its last value (a stopped run keeps its best cost). Infinite where too few
/// runs have a finite cost yet, which leaves a gap in the curve rather than a survivor-biased
/// value.
struct Bands {
    q1: Vec<f64>,
    median: Vec<f64>,
    q3: Vec<f64>,
    runs: usize,
}

impl Bands {
    fn of(histories: &[Vec<f64>]) -> Self {
        let filled: Vec<Vec<f64>> = histories.iter().filter(|h| !h.is_empty()).map(|h| fill_history(h)).collect();
        let len = filled.iter().map(Vec::len).max().unwrap_or(0);
        let mut out = Bands { q1: vec![], median: vec![], q3: vec![], runs: filled.len() };
        let mut column = Vec::with_capacity(filled.len());
        for i in 0..len {
            column.clear();
            column.extend(filled.iter().map(|h| h.get(i).or(h.last()).copied().unwrap_or(f64::INFINITY)));
            // Filled histories hold no NaN, so a summary always exists.
            let (q1, median, q3) =
                Summary::of(&column).map_or((f64::INFINITY, f64::INFINITY, f64::INFINITY), |s| (s.q1, s.median, s.q3));
            out.q1.push(q1);
            out.median.push(median);
            out.q3.push(q3);
        }
        out
    }
}

/// Figure size for `n` panels of `panel` pixels under a header `header_h` high.
fn figure_size(n: usize, header_h: u32) -> (u32, u32, (u32, u32)) {
    let (cols, rows) = grid_shape(n);
    let panel = if n <= 1 { SINGLE_PANEL } else { GRID_PANEL };
    (cols as u32 * panel.0 + 2 * MARGIN, header_h + rows as u32 * panel.1 + MARGIN, panel)
}

const NOTE_LINE_H: u32 = 18;
const TITLE_LINE_H: u32 = 26;
/// Bold text runs wider than the regular-weight estimate of [`style::text_width`].
const BOLD_WIDTH: f64 = 1.12;

/// The title wrapped to the figure width: a long title (many problems joined) would otherwise
/// run off a one-panel figure.
fn title_lines(title: &str, width: u32) -> Vec<String> {
    wrap(title, width.saturating_sub(2 * MARGIN) as f64 / BOLD_WIDTH, style::TITLE_PX)
}

fn title_height(title: &str, width: u32) -> u32 {
    TITLE_H + title_lines(title, width).len().saturating_sub(1) as u32 * TITLE_LINE_H
}

fn draw_title<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, title: &str) -> Result<()> {
    let (w, _) = root.dim_in_pixel();
    let style = style::bold(style::TITLE_PX).pos(Pos::new(HPos::Center, VPos::Center));
    for (k, line) in title_lines(title, w).into_iter().enumerate() {
        let y = (TITLE_H / 2 + 2 + k as u32 * TITLE_LINE_H) as i32;
        root.draw(&Text::new(line, (w as i32 / 2, y), style.clone())).map_err(plot_err)?;
    }
    Ok(())
}

/// Height of the title, shared legend and explanatory note at figure width `width`.
fn header_height(title: &str, legend: &[LegendEntry], note: &str, width: u32) -> u32 {
    let lines = wrap(note, legend_width(width) as f64, style::LEGEND_PX).len() as u32;
    title_height(title, width) + style::legend_height(legend, legend_width(width)) + lines * NOTE_LINE_H + 6
}

fn legend_width(width: u32) -> u32 {
    width.saturating_sub(2 * MARGIN + LEGEND_INDENT)
}

/// Splits `text` into lines no wider than `width` pixels at `px`, at spaces.
fn wrap(text: &str, width: f64, px: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if style::text_width(&format!("{line} {word}"), px) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

fn draw_header<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    legend: &[LegendEntry],
    note: &str,
) -> Result<()> {
    let (w, _) = root.dim_in_pixel();
    draw_title(root, title)?;
    let top = title_height(title, w);
    let legend_h = style::legend_height(legend, legend_width(w));
    let x0 = (MARGIN + LEGEND_INDENT) as i32;
    let legend_area = root.clone().shrink((x0, top as i32), (legend_width(w), legend_h.max(1)));
    style::draw_legend(&legend_area, legend)?;
    let note_style = style::font(style::LEGEND_PX).color(&style::MUTED).pos(Pos::new(HPos::Left, VPos::Center));
    for (k, line) in wrap(note, legend_width(w) as f64, style::LEGEND_PX).into_iter().enumerate() {
        let y = (top + legend_h + k as u32 * NOTE_LINE_H + NOTE_LINE_H / 2) as i32;
        root.draw(&Text::new(line, (x0, y), note_style.clone())).map_err(plot_err)?;
    }
    Ok(())
}

/// The panel areas of the grid below the header, in reading order.
fn panels<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    n: usize,
    header_h: u32,
    panel: (u32, u32),
) -> Vec<DrawingArea<DB, Shift>> {
    let (cols, _) = grid_shape(n);
    (0..n.max(1))
        .map(|k| {
            let (c, r) = ((k % cols) as u32, (k / cols) as u32);
            let x = MARGIN + c * panel.0;
            let y = header_h + r * panel.1;
            root.clone().shrink((x as i32, y as i32), panel).margin(4, 8, 4, 8)
        })
        .collect()
}

/// A muted message in an empty panel, so a missing result is visible rather than a blank.
fn draw_message<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, msg: &str) -> Result<()> {
    let (w, h) = area.dim_in_pixel();
    let style = style::font(style::AXIS_DESC_PX).color(&style::MUTED).pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(msg.to_string(), (w as i32 / 2, h as i32 / 3), style)).map_err(plot_err)?;
    Ok(())
}

fn render_svg(size: (u32, u32), draw: impl FnOnce(&DrawingArea<SVGBackend, Shift>) -> Result<()>) -> Result<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        draw(&root)?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// Explains a zero line in the header, once, when any panel has one.
const ZERO_NOTE: &str = " On log axes, runs that reached exactly 0 are drawn on the line labelled 0.";
/// Height of the strip above a plot for per-planner notes ("never feasible", "2 runs = ∞").
const NOTE_H: u32 = 18;

/// One planner's curve in a convergence panel, already mapped to the panel's axis.
struct Curve {
    color: usize,
    q1: Vec<f64>,
    median: Vec<f64>,
    q3: Vec<f64>,
    runs: usize,
}

/// Everything a convergence panel shows, computed before drawing so the header knows whether
/// any panel needs the zero-line note.
struct ConvergencePanel<'p> {
    problem: &'p str,
    curves: Vec<Curve>,
    axis: Option<CostAxis>,
    /// Planners with runs but no finite median at any iteration, which draw nothing.
    missing: Vec<&'p str>,
}

impl<'p> ConvergencePanel<'p> {
    fn of(problem: &ProblemRuns<'p>, order: &[&str]) -> Self {
        let bands: Vec<Bands> = problem.planners.iter().map(|p| Bands::of(&p.histories)).collect();
        let axis = CostAxis::for_values(bands.iter().flat_map(|b| b.q1.iter().chain(&b.median).chain(&b.q3)).copied());
        let missing = problem
            .planners
            .iter()
            .zip(&bands)
            .filter(|(_, b)| b.runs > 0 && !b.median.iter().any(|v| v.is_finite()))
            .map(|(p, _)| p.planner)
            .collect();
        let curves = problem
            .planners
            .iter()
            .zip(bands)
            .map(|(p, b)| {
                let m = |v: Vec<f64>| v.into_iter().map(|x| axis.map_or(x, |a| a.map(x))).collect();
                Curve {
                    color: color_index(order, p.planner),
                    q1: m(b.q1),
                    median: m(b.median),
                    q3: m(b.q3),
                    runs: b.runs,
                }
            })
            .collect();
        ConvergencePanel { problem: problem.problem, curves, axis, missing }
    }
}

/// convergence.svg: one panel per problem with, per planner, the median best cost per iteration
/// over runs and its interquartile band.
pub fn render_convergence_figure(title: &str, problems: &[ProblemRuns]) -> Result<String> {
    let order = planner_order(problems);
    let panels_data: Vec<ConvergencePanel> = problems.iter().map(|p| ConvergencePanel::of(p, &order)).collect();
    let mut legend: Vec<LegendEntry> = order
        .iter()
        .enumerate()
        .map(|(i, p)| LegendEntry::new(*p, Swatch::Line { color: style::path_color(i).to_rgba(), width: 2 }))
        .collect();
    legend.push(LegendEntry::new(
        "interquartile range (25–75 % of runs)",
        Swatch::Fill { color: style::MUTED.mix(0.25), edge: None },
    ));
    let mut note = "Lines: median over runs of the best cost so far, drawn once half of the runs (bands: three \
                    quarters) have a finite cost."
        .to_string();
    if panels_data.iter().any(|p| p.axis.and_then(|a| a.zero_at()).is_some()) {
        note.push_str(ZERO_NOTE);
    }
    let (w, _, _) = figure_size(problems.len(), 0);
    let header_h = header_height(title, &legend, &note, w);
    let (w, h, panel) = figure_size(problems.len(), header_h);
    render_svg((w, h), |root| {
        draw_header(root, title, &legend, &note)?;
        let areas = panels(root, problems.len(), header_h, panel);
        if problems.is_empty() {
            return draw_message(&areas[0], "no runs");
        }
        for (area, data) in areas.iter().zip(&panels_data) {
            draw_convergence_panel(area, data)?;
        }
        Ok(())
    })
}

fn draw_convergence_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, data: &ConvergencePanel) -> Result<()> {
    let body = style::caption(area, data.problem)?;
    let Some(axis) = data.axis else {
        let msg = if data.curves.is_empty() {
            "no runs"
        } else if data.curves.iter().all(|c| c.runs == 0) {
            "no convergence history"
        } else {
            "no finite cost recorded"
        };
        return draw_message(&body, msg);
    };
    let (strip, plot_area) = body.split_vertically(if data.missing.is_empty() { 0 } else { NOTE_H });
    if !data.missing.is_empty() {
        let (w, _) = strip.dim_in_pixel();
        let msg = format!("no finite median: {}", data.missing.join(", "));
        let style = style::font(style::TICK_PX).color(&style::MUTED).pos(Pos::new(HPos::Center, VPos::Center));
        strip.draw(&Text::new(msg, (w as i32 / 2, NOTE_H as i32 / 2), style)).map_err(plot_err)?;
    }
    // All bands first, then all medians, so no band veils another planner's line.
    let mut series: Vec<ConvergenceSeries> = data
        .curves
        .iter()
        .filter(|c| c.runs > 1)
        .map(|c| ConvergenceSeries {
            label: String::new(),
            median: &[],
            band: Some((c.q1.as_slice(), c.q3.as_slice())),
            color: Some(c.color),
        })
        .collect();
    series.extend(data.curves.iter().map(|c| ConvergenceSeries {
        label: String::new(),
        median: &c.median,
        band: None,
        color: Some(c.color),
    }));
    let n = data.curves.iter().map(|c| c.median.len()).max().unwrap_or(0);
    let x = 0.0..(n.saturating_sub(1) as f64).max(1.0);
    let desc = axis.desc("best cost");
    let zero = match axis {
        CostAxis::Log { lo, hi, decades, .. } => {
            let y = DecadeAxis::with_range(lo, hi, decades);
            let chart = build(&plot_area, x, y, &desc, |v: &f64| axis.tick_label(*v))?;
            let zero = axis.zero_gap().map(|(z, a)| (chart.backend_coord(&(0.0, z)), chart.backend_coord(&(0.0, a))));
            draw_curves(chart, &series)?;
            zero
        }
        CostAxis::Linear { lo, hi } => {
            let chart = build(&plot_area, x, lo..hi, &desc, style::tick_formatter(lo..hi, Y_LABELS))?;
            draw_curves(chart, &series)?;
            None
        }
    };
    if let Some(((x0, y0), (_, y1))) = zero {
        let base = plot_area.get_base_pixel();
        draw_zero_tick(&plot_area, x0 - base.0, y0 - base.1, y0 - y1)?;
    }
    Ok(())
}

/// Tukey's box of one planner's final costs.
#[derive(Clone, Debug, PartialEq)]
struct BoxStats {
    q1: f64,
    median: f64,
    q3: f64,
    /// Most extreme costs within 1.5 IQR of the box.
    whisker_lo: f64,
    whisker_hi: f64,
    outliers: Vec<f64>,
    /// Runs without a finite cost, which no box can show.
    non_finite: usize,
}

impl BoxStats {
    fn of(costs: &[f64]) -> Option<Self> {
        let finite: Vec<f64> = costs.iter().copied().filter(|v| v.is_finite()).collect();
        let non_finite = costs.len() - finite.len();
        let s = Summary::of(&finite)?;
        let iqr = s.q3 - s.q1;
        let (fence_lo, fence_hi) = (s.q1 - 1.5 * iqr, s.q3 + 1.5 * iqr);
        let inside = || finite.iter().copied().filter(|v| (fence_lo..=fence_hi).contains(v));
        // The box always lies within the fences, so `inside` is never empty; the fallback is
        // for rounding at the fences.
        let whisker_lo = inside().reduce(f64::min).unwrap_or(s.q1).min(s.q1);
        let whisker_hi = inside().reduce(f64::max).unwrap_or(s.q3).max(s.q3);
        let outliers = finite.iter().copied().filter(|v| !(fence_lo..=fence_hi).contains(v)).collect();
        Some(BoxStats { q1: s.q1, median: s.median, q3: s.q3, whisker_lo, whisker_hi, outliers, non_finite })
    }

    /// The note above a box for runs it cannot show.
    fn note(stats: Option<&BoxStats>, runs: usize) -> Option<String> {
        match stats {
            None if runs > 0 => Some("no finite cost".into()),
            Some(b) if b.non_finite > 0 => {
                Some(format!("{} run{} = ∞", b.non_finite, if b.non_finite == 1 { "" } else { "s" }))
            }
            _ => None,
        }
    }
}

/// boxplot.svg: one panel per problem with one box per planner of the final costs of all runs.
pub fn render_boxplot_figure(title: &str, problems: &[ProblemRuns]) -> Result<String> {
    let order = planner_order(problems);
    let legend: Vec<LegendEntry> = order
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let c = style::path_color(i);
            LegendEntry::new(*p, Swatch::Fill { color: c.mix(0.3), edge: Some(c) })
        })
        .collect();
    let mut note = "Final cost of every run. Box: 25–75 %, bar: median, whiskers: furthest run within 1.5 box \
                    heights, circles: runs beyond."
        .to_string();
    let zero = |p: &ProblemRuns| {
        let axis = CostAxis::for_values(p.planners.iter().flat_map(|q| q.costs.iter().copied()));
        axis.and_then(|a| a.zero_at()).is_some()
    };
    if problems.iter().any(zero) {
        note.push_str(ZERO_NOTE);
    }
    let (w, _, _) = figure_size(problems.len(), 0);
    let header_h = header_height(title, &legend, &note, w);
    let (w, h, panel) = figure_size(problems.len(), header_h);
    render_svg((w, h), |root| {
        draw_header(root, title, &legend, &note)?;
        let areas = panels(root, problems.len(), header_h, panel);
        if problems.is_empty() {
            return draw_message(&areas[0], "no runs");
        }
        for (area, problem) in areas.iter().zip(problems) {
            draw_box_panel(area, problem, &order)?;
        }
        Ok(())
    })
}

/// A box in pixels of the panel: x of its centre, y of its statistics.
struct BoxPx {
    x: i32,
    q1: i32,
    median: i32,
    q3: i32,
    lo: i32,
    hi: i32,
    outliers: Vec<i32>,
}

/// The pixel layout of a box panel, taken from the chart so the boxes can be sized in pixels
/// (a capped width, a visible height for identical costs).
struct BoxPanelPx {
    boxes: Vec<Option<BoxPx>>,
    /// Pixel distance between neighbouring boxes.
    slot: i32,
    /// Left edge and bottom of the plot.
    axis_x: i32,
    axis_y: i32,
    /// The zero line and the lowest labelled decade above it, on a log axis with zeros.
    zero: Option<(i32, i32)>,
}

fn box_pixels<DB, Y>(
    chart: &ChartContext<DB, Cartesian2d<plotters::coord::types::RangedCoordf64, Y>>,
    boxes: &[Option<BoxStats>],
    axis: CostAxis,
    base: (i32, i32),
) -> BoxPanelPx
where
    DB: DrawingBackend,
    Y: plotters::coord::ranged1d::Ranged<ValueType = f64>,
{
    let px = |x: f64, v: f64| {
        let (a, b) = chart.backend_coord(&(x, axis.map(v)));
        (a - base.0, b - base.1)
    };
    let y_lo = chart.y_range().start;
    let (axis_x, axis_y) = {
        let (a, b) = chart.backend_coord(&(-0.5, y_lo));
        (a - base.0, b - base.1)
    };
    let slot = px(1.0, 1.0).0 - px(0.0, 1.0).0;
    let boxes = boxes
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let b = b.as_ref()?;
            let x = i as f64;
            Some(BoxPx {
                x: px(x, b.median).0,
                q1: px(x, b.q1).1,
                median: px(x, b.median).1,
                q3: px(x, b.q3).1,
                lo: px(x, b.whisker_lo).1,
                hi: px(x, b.whisker_hi).1,
                outliers: b.outliers.iter().map(|&o| px(x, o).1).collect(),
            })
        })
        .collect();
    let zero = axis.zero_gap().map(|(z, a)| (px(0.0, z).1, px(0.0, a).1));
    BoxPanelPx { boxes, slot, axis_x, axis_y, zero }
}

fn draw_box_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    problem: &ProblemRuns,
    order: &[&str],
) -> Result<()> {
    let body = style::caption(area, problem.problem)?;
    let stats: Vec<Option<BoxStats>> = problem.planners.iter().map(|p| BoxStats::of(&p.costs)).collect();
    let axis = CostAxis::for_values(problem.planners.iter().flat_map(|p| p.costs.iter().copied()));
    let Some(axis) = axis else {
        let msg =
            if problem.planners.iter().all(|p| p.costs.is_empty()) { "no runs" } else { "no finite cost recorded" };
        return draw_message(&body, msg);
    };
    let notes: Vec<Option<String>> =
        problem.planners.iter().zip(&stats).map(|(p, b)| BoxStats::note(b.as_ref(), p.costs.len())).collect();
    let has_notes = notes.iter().any(Option::is_some);
    let (_, plot_area) = body.split_vertically(if has_notes { NOTE_H } else { 0 });
    let n = problem.planners.len().max(1);
    let x = -0.5..n as f64 - 0.5;
    let desc = axis.desc("final cost");
    let base = body.get_base_pixel();
    let layout = match axis {
        CostAxis::Log { lo, hi, decades, .. } => {
            let y = DecadeAxis::with_range(lo, hi, decades);
            let chart = build_box_chart(&plot_area, x, y, &desc, |v: &f64| axis.tick_label(*v))?;
            box_pixels(&chart, &stats, axis, base)
        }
        CostAxis::Linear { lo, hi } => {
            let chart = build_box_chart(&plot_area, x, lo..hi, &desc, style::tick_formatter(lo..hi, Y_LABELS))?;
            box_pixels(&chart, &stats, axis, base)
        }
    };
    draw_box_glyphs(&body, problem, order, &layout)?;
    draw_box_labels(&body, problem, &notes, &layout)?;
    if let Some((y0, y1)) = layout.zero {
        draw_zero_tick(&body, layout.axis_x, y0, y0 - y1)?;
    }
    Ok(())
}

fn build_box_chart<'a, DB, Y>(
    area: &'a DrawingArea<DB, Shift>,
    x: Range<f64>,
    y: Y,
    y_desc: &str,
    y_fmt: impl Fn(&f64) -> String,
) -> Result<ChartContext<'a, DB, Cartesian2d<plotters::coord::types::RangedCoordf64, Y::CoordDescType>>>
where
    DB: DrawingBackend,
    Y: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
    Y::CoordDescType:
        plotters::coord::ranged1d::Ranged<ValueType = f64> + plotters::coord::ranged1d::ValueFormatter<f64>,
{
    let mut chart = ChartBuilder::on(area)
        .margin_right(18)
        .margin_top(6)
        .x_label_area_size(BOX_LABEL_H)
        .y_label_area_size(64)
        .build_cartesian_2d(x, y)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(style::GRID)
        .disable_x_mesh()
        .x_labels(0)
        .y_labels(Y_LABELS)
        .y_desc(y_desc)
        .y_label_formatter(&y_fmt)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;
    Ok(chart)
}

/// Widest box in pixels: wider boxes in a single-problem figure only look heavier.
const MAX_BOX_HALF_W: i32 = 40;
/// Boxes of identical costs get this half height, so their colour still shows.
const MIN_BOX_HALF_H: i32 = 4;

fn draw_box_glyphs<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    problem: &ProblemRuns,
    order: &[&str],
    layout: &BoxPanelPx,
) -> Result<()> {
    let half = ((layout.slot as f64 * 0.3) as i32).clamp(4, MAX_BOX_HALF_W);
    let cap = (half / 2).max(3);
    for (p, b) in problem.planners.iter().zip(&layout.boxes) {
        let Some(b) = b else { continue };
        let c = style::path_color(color_index(order, p.planner));
        let whisker = style::line(c, 2);
        for (from, to) in [(b.q1, b.lo), (b.q3, b.hi)] {
            if from != to {
                area.draw(&PathElement::new(vec![(b.x, from), (b.x, to)], whisker)).map_err(plot_err)?;
                area.draw(&PathElement::new(vec![(b.x - cap, to), (b.x + cap, to)], whisker)).map_err(plot_err)?;
            }
        }
        // Pixel y grows downwards: q3 is above q1.
        let (mut top, mut bottom) = (b.q3, b.q1);
        if bottom - top < 2 * MIN_BOX_HALF_H {
            (top, bottom) = (b.median - MIN_BOX_HALF_H, b.median + MIN_BOX_HALF_H);
        }
        let corners = [(b.x - half, top), (b.x + half, bottom)];
        area.draw(&Rectangle::new(corners, style::fill(WHITE))).map_err(plot_err)?;
        area.draw(&Rectangle::new(corners, style::fill(c.mix(0.3)))).map_err(plot_err)?;
        area.draw(&Rectangle::new(corners, style::line(c, 2))).map_err(plot_err)?;
        area.draw(&PathElement::new(vec![(b.x - half, b.median), (b.x + half, b.median)], style::line(style::TEXT, 3)))
            .map_err(plot_err)?;
        for &o in &b.outliers {
            area.draw(&Circle::new((b.x, o), 3, style::line(c, 2))).map_err(plot_err)?;
        }
    }
    Ok(())
}

/// Shortens `name` with an ellipsis to fit `width` pixels at the tick font size.
fn fit_label(name: &str, width: f64) -> String {
    if style::text_width(name, style::TICK_PX) <= width {
        return name.to_string();
    }
    let keep = (width / (style::TICK_PX * 0.55)).floor() as usize;
    let mut s: String = name.chars().take(keep.saturating_sub(1).max(1)).collect();
    s.push('…');
    s
}

/// Planner names under their boxes (on two staggered rows when they would collide) and the
/// notes above them.
fn draw_box_labels<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    problem: &ProblemRuns,
    notes: &[Option<String>],
    layout: &BoxPanelPx,
) -> Result<()> {
    let slot = layout.slot as f64;
    let widest = problem.planners.iter().map(|p| style::text_width(p.planner, style::TICK_PX)).fold(0.0, f64::max);
    let stagger = problem.planners.len() > 1 && widest > slot - 6.0;
    let room = if stagger { 2.0 * slot - 8.0 } else { slot - 6.0 };
    let text = style::font(style::TICK_PX).pos(Pos::new(HPos::Center, VPos::Top));
    let muted = style::font(style::TICK_PX).color(&style::MUTED).pos(Pos::new(HPos::Center, VPos::Center));
    for (i, (p, note)) in problem.planners.iter().zip(notes).enumerate() {
        let x = layout.axis_x + ((i as f64 + 0.5) * slot).round() as i32;
        let row = if stagger { (i % 2) as i32 } else { 0 };
        let at = (x, layout.axis_y + 8 + row * 17);
        area.draw(&Text::new(fit_label(p.planner, room), at, text.clone())).map_err(plot_err)?;
        if let Some(note) = note {
            area.draw(&Text::new(note.clone(), (x, NOTE_H as i32 / 2), muted.clone())).map_err(plot_err)?;
        }
    }
    Ok(())
}

/// paths.svg: the plan view with each planner's best path beside their vertical profile. Give
/// each path a [`best_path_label`] so the legend carries the cost.
pub fn render_paths_figure(
    title: &str,
    world: &World,
    start: Vec3,
    goal: Vec3,
    time: f64,
    paths: &[PlotPath],
) -> Result<String> {
    const SIZE: (u32, u32) = (1400, 760);
    render_svg(SIZE, |root| {
        let (w, h) = SIZE;
        draw_title(root, title)?;
        let title_h = title_height(title, w);
        let body = root.split_vertically(title_h).1.margin(0, 8, 8, 8);
        // A wide domain gets a wider plan view, as in the plan figure; the profile keeps
        // enough width to read the climbs.
        let b = world.bounds;
        let aspect = ((b.max.x - b.min.x) / (b.max.y - b.min.y)).clamp(0.3, 3.0);
        let avail_h = h.saturating_sub(title_h) as f64 - 200.0;
        let left_w = (aspect * avail_h + 200.0).clamp(560.0, 880.0) as u32;
        let (left, right) = body.split_horizontally(left_w);
        draw_plan_view(&left, world, time, paths, start, goal)?;
        draw_profile(&right.margin(0, 0, 16, 0), world, paths)
    })
}

/// Writes [`render_convergence_figure`] to `out` atomically.
pub fn write_convergence_figure(title: &str, problems: &[ProblemRuns], out: &Path) -> Result<()> {
    crate::io::write_atomic(out, render_convergence_figure(title, problems)?.as_bytes())
}

/// Writes [`render_boxplot_figure`] to `out` atomically.
pub fn write_boxplot_figure(title: &str, problems: &[ProblemRuns], out: &Path) -> Result<()> {
    crate::io::write_atomic(out, render_boxplot_figure(title, problems)?.as_bytes())
}

/// Writes [`render_paths_figure`] to `out` atomically.
pub fn write_paths_figure(
    title: &str,
    world: &World,
    start: Vec3,
    goal: Vec3,
    time: f64,
    paths: &[PlotPath],
    out: &Path,
) -> Result<()> {
    crate::io::write_atomic(out, render_paths_figure(title, world, start, goal, time, paths)?.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_stays_within_four_columns() {
        assert_eq!(grid_shape(1), (1, 1));
        assert_eq!(grid_shape(2), (2, 1));
        assert_eq!(grid_shape(6), (3, 2));
        assert_eq!(grid_shape(12), (4, 3));
        assert_eq!(grid_shape(13), (4, 4));
    }

    #[test]
    fn histories_fill_gaps_as_best_so_far() {
        let h = [f64::INFINITY, f64::NAN, 5.0, f64::NAN, 3.0];
        assert_eq!(fill_history(&h), vec![f64::INFINITY, f64::INFINITY, 5.0, 5.0, 3.0]);
        let b = Bands::of(&[vec![4.0, 2.0, 1.0], vec![8.0], vec![]]);
        assert_eq!(b.runs, 2);
        assert_eq!(b.median, vec![6.0, 5.0, 4.5]);
        assert_eq!(b.q1, vec![5.0, 3.5, 2.75]);
    }

    #[test]
    fn quartile_gaps_while_most_runs_lack_a_cost() {
        let inf = f64::INFINITY;
        let b = Bands::of(&[vec![inf, 1.0], vec![inf, 2.0], vec![3.0, 3.0]]);
        assert!(b.median[0].is_infinite() && b.median[1] == 2.0);
    }

    #[test]
    fn boxes_follow_tukey() {
        let mut costs: Vec<f64> = (1..=9).map(f64::from).collect();
        costs.extend([100.0, f64::INFINITY]);
        let b = BoxStats::of(&costs).unwrap();
        assert_eq!((b.q1, b.median, b.q3), (3.25, 5.5, 7.75));
        assert_eq!((b.whisker_lo, b.whisker_hi), (1.0, 9.0));
        assert_eq!(b.outliers, vec![100.0]);
        assert_eq!(b.non_finite, 1);
        let flat = BoxStats::of(&[2.0; 5]).unwrap();
        assert_eq!((flat.whisker_lo, flat.whisker_hi, flat.outliers.len()), (2.0, 2.0, 0));
        assert!(BoxStats::of(&[f64::INFINITY]).is_none());
    }

    #[test]
    fn zeros_sit_below_the_smallest_positive_cost_on_a_log_axis() {
        let axis = CostAxis::for_values([0.0, 3e-8, 5.0, 200.0]).unwrap();
        let CostAxis::Log { lo, hi, zero_at: Some(z), decades } = axis else { panic!("{axis:?}") };
        // 3e-8 to 200 is labelled every other decade, from 1e-8 up to 1e4; the zero line sits
        // a tenth of those 12 decades below 1e-8.
        assert!((z.log10() + 9.2).abs() < 1e-9 && lo < z && hi == 1e4);
        assert_eq!(decades.exponents(), [-8, -6, -4, -2, 0, 2, 4]);
        assert_eq!(axis.map(0.0), z);
        assert_eq!(axis.map(5.0), 5.0);
        assert_eq!(axis.desc("best cost"), "best cost (log scale, 0 below break)");
        assert_eq!(
            (axis.tick_label(z), axis.tick_label(1e4), axis.tick_label(1e-8)),
            (String::new(), "1e4".into(), "1e-8".into())
        );
        assert!(matches!(CostAxis::for_values([-1.0, 0.0, 500.0]), Some(CostAxis::Linear { .. })));
        assert!(matches!(CostAxis::for_values([4.0, 4.0]), Some(CostAxis::Linear { lo, hi }) if lo < 4.0 && hi > 4.0));
        assert!(CostAxis::for_values([f64::NAN, f64::INFINITY]).is_none());
    }

    #[test]
    fn records_group_by_first_appearance() {
        let rec = |problem: &str, planner: &str, cost: f64| RunRecord {
            problem: problem.into(),
            planner: planner.into(),
            run: 0,
            seed: 0,
            cost,
            feasible: true,
            length_m: None,
            travel_time_s: None,
            evaluations: 0,
            iterations: 1,
            elapsed_s: 0.0,
            stop_reason: crate::optim::StopReason::MaxIterations,
            history: vec![None, Some(cost)],
            waypoints: vec![],
        };
        let records = [rec("b", "pso", 1.0), rec("a", "de", 2.0), rec("b", "de", 3.0), rec("b", "pso", 4.0)];
        let g = group_runs(&records);
        assert_eq!(g.iter().map(|p| p.problem).collect::<Vec<_>>(), ["b", "a"]);
        assert_eq!(g[0].planners[0].costs, vec![1.0, 4.0]);
        assert_eq!(g[0].planners[0].histories[1], vec![f64::INFINITY, 4.0]);
        assert_eq!(planner_order(&g), ["pso", "de"]);
    }
}
