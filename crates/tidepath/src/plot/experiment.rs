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
//! drawn on the bottom edge of the axis (one decade below the smallest positive cost) and the
//! axis label says so.

use std::ops::Range;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::convergence::{build, draw_curves, wants_log_scale, ConvergenceSeries, Y_LABELS};
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
/// panels keep readable tick labels (twelve problems give 4 x 3).
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

/// How a cost axis maps values: linear, or log10 with zeros drawn at `zero_at`.
#[derive(Clone, Copy, Debug, PartialEq)]
enum CostAxis {
    Linear { lo: f64, hi: f64 },
    Log { lo: f64, hi: f64, zero_at: Option<f64> },
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
            let mut a = 10f64.powf(min_pos.log10().floor());
            // A zero needs its own place below every positive cost, or it would look like one.
            if has_zero {
                a /= 10.0;
            }
            let b = 10f64.powf(hi.log10().ceil());
            return Some(CostAxis::Log { lo: a, hi: b, zero_at: has_zero.then_some(a) });
        }
        let pad = if hi > lo { (hi - lo) * 0.05 } else { lo.abs().max(1.0) * 0.1 };
        Some(CostAxis::Linear { lo: lo - pad, hi: hi + pad })
    }

    /// The value to draw for cost `v`: zeros move to the floor of a log axis.
    fn map(&self, v: f64) -> f64 {
        match *self {
            CostAxis::Log { zero_at: Some(z), .. } if v == 0.0 => z,
            _ => v,
        }
    }

    fn desc(&self, what: &str) -> String {
        match *self {
            CostAxis::Linear { .. } => what.to_string(),
            CostAxis::Log { zero_at: None, .. } => format!("{what} (log scale)"),
            CostAxis::Log { zero_at: Some(z), .. } => {
                format!("{what} (log scale; 0 drawn at {})", style::fmt_sig(z))
            }
        }
    }
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
            let s = Summary::of(&column).expect("filled histories hold no NaN");
            out.q1.push(s.q1);
            out.median.push(s.median);
            out.q3.push(s.q3);
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

/// Title, shared legend and an explanatory note; returns the height they take at `width`.
fn header_height(legend: &[LegendEntry], width: u32) -> u32 {
    TITLE_H + style::legend_height(legend, legend_width(width)) + 22
}

fn legend_width(width: u32) -> u32 {
    width.saturating_sub(2 * MARGIN + LEGEND_INDENT)
}

fn draw_header<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    legend: &[LegendEntry],
    note: &str,
) -> Result<()> {
    let (w, _) = root.dim_in_pixel();
    let title_style = style::bold(style::TITLE_PX).pos(Pos::new(HPos::Center, VPos::Center));
    root.draw(&Text::new(title.to_string(), (w as i32 / 2, TITLE_H as i32 / 2 + 2), title_style)).map_err(plot_err)?;
    let legend_h = style::legend_height(legend, legend_width(w));
    let x0 = (MARGIN + LEGEND_INDENT) as i32;
    let legend_area = root.clone().shrink((x0, TITLE_H as i32), (legend_width(w), legend_h.max(1)));
    style::draw_legend(&legend_area, legend)?;
    let note_style = style::font(style::LEGEND_PX).color(&style::MUTED).pos(Pos::new(HPos::Left, VPos::Center));
    root.draw(&Text::new(note.to_string(), (x0, (TITLE_H + legend_h) as i32 + 10), note_style)).map_err(plot_err)?;
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

/// convergence.svg: one panel per problem with, per planner, the median best cost per iteration
/// over runs and its interquartile band.
pub fn render_convergence_figure(title: &str, problems: &[ProblemRuns]) -> Result<String> {
    let order = planner_order(problems);
    let mut legend: Vec<LegendEntry> = order
        .iter()
        .enumerate()
        .map(|(i, p)| LegendEntry::new(*p, Swatch::Line { color: style::path_color(i).to_rgba(), width: 2 }))
        .collect();
    legend.push(LegendEntry::new(
        "interquartile range (25–75 % of runs)",
        Swatch::Fill { color: style::MUTED.mix(0.25), edge: None },
    ));
    let (w, _, _) = figure_size(problems.len(), 0);
    let header_h = header_height(&legend, w);
    let (w, h, panel) = figure_size(problems.len(), header_h);
    render_svg((w, h), |root| {
        draw_header(
            root,
            title,
            &legend,
            "Lines: median over runs of the best cost so far; gaps: fewer than half (band: a quarter) \
             of the runs have a finite cost yet.",
        )?;
        let areas = panels(root, problems.len(), header_h, panel);
        if problems.is_empty() {
            return draw_message(&areas[0], "no runs");
        }
        for (area, problem) in areas.iter().zip(problems) {
            draw_convergence_panel(area, problem, &order)?;
        }
        Ok(())
    })
}

fn draw_convergence_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    problem: &ProblemRuns,
    order: &[&str],
) -> Result<()> {
    let body = style::caption(area, problem.problem)?;
    let bands: Vec<(usize, Bands)> =
        problem.planners.iter().map(|p| (color_index(order, p.planner), Bands::of(&p.histories))).collect();
    let axis = CostAxis::for_values(bands.iter().flat_map(|(_, b)| b.q1.iter().chain(&b.median).chain(&b.q3)).copied());
    let Some(axis) = axis else {
        let msg =
            if bands.iter().all(|(_, b)| b.runs == 0) { "no convergence history" } else { "no finite cost recorded" };
        return draw_message(&body, msg);
    };
    let mapped: Vec<(usize, Vec<f64>, Vec<f64>, Vec<f64>, usize)> = bands
        .iter()
        .map(|(c, b)| {
            let m = |v: &Vec<f64>| v.iter().map(|&x| axis.map(x)).collect::<Vec<f64>>();
            (*c, m(&b.q1), m(&b.median), m(&b.q3), b.runs)
        })
        .collect();
    // All bands first, then all medians, so no band veils another planner's line.
    let mut series: Vec<ConvergenceSeries> = mapped
        .iter()
        .filter(|(.., runs)| *runs > 1)
        .map(|(c, q1, _, q3, _)| ConvergenceSeries {
            label: String::new(),
            median: &[],
            band: Some((q1.as_slice(), q3.as_slice())),
            color: Some(*c),
        })
        .collect();
    series.extend(mapped.iter().map(|(c, _, median, ..)| ConvergenceSeries {
        label: String::new(),
        median,
        band: None,
        color: Some(*c),
    }));
    let n = mapped.iter().map(|m| m.2.len()).max().unwrap_or(0);
    let x = 0.0..(n.saturating_sub(1) as f64).max(1.0);
    let desc = axis.desc("best cost");
    match axis {
        CostAxis::Log { lo, hi, .. } => {
            let chart = build(&body, x, (lo..hi).log_scale(), &desc, |v: &f64| style::fmt_sig(*v))?;
            draw_curves(chart, &series)
        }
        CostAxis::Linear { lo, hi } => {
            let chart = build(&body, x, lo..hi, &desc, style::tick_formatter(lo..hi, Y_LABELS))?;
            draw_curves(chart, &series)
        }
    }
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
    let (w, _, _) = figure_size(problems.len(), 0);
    let header_h = header_height(&legend, w);
    let (w, h, panel) = figure_size(problems.len(), header_h);
    render_svg((w, h), |root| {
        draw_header(
            root,
            title,
            &legend,
            "Final cost of every run. Box: 25–75 %, bar: median, whiskers: furthest run within 1.5 box \
             heights, circles: runs beyond.",
        )?;
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

fn draw_box_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    problem: &ProblemRuns,
    order: &[&str],
) -> Result<()> {
    let body = style::caption(area, problem.problem)?;
    let boxes: Vec<Option<BoxStats>> = problem.planners.iter().map(|p| BoxStats::of(&p.costs)).collect();
    let axis = CostAxis::for_values(problem.planners.iter().flat_map(|p| p.costs.iter().copied()));
    let Some(axis) = axis else {
        let msg =
            if problem.planners.iter().all(|p| p.costs.is_empty()) { "no runs" } else { "no finite cost recorded" };
        return draw_message(&body, msg);
    };
    let n = problem.planners.len().max(1);
    let x = -0.5..n as f64 - 0.5;
    let desc = axis.desc("final cost");
    match axis {
        CostAxis::Log { lo, hi, .. } => {
            let chart = build_box_chart(&body, x, (lo..hi).log_scale(), &desc, |v: &f64| style::fmt_sig(*v))?;
            draw_boxes(&body, chart, problem, &boxes, order, axis)
        }
        CostAxis::Linear { lo, hi } => {
            let chart = build_box_chart(&body, x, lo..hi, &desc, style::tick_formatter(lo..hi, Y_LABELS))?;
            draw_boxes(&body, chart, problem, &boxes, order, axis)
        }
    }
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

fn draw_boxes<DB, Y>(
    body: &DrawingArea<DB, Shift>,
    chart: ChartContext<DB, Cartesian2d<plotters::coord::types::RangedCoordf64, Y>>,
    problem: &ProblemRuns,
    boxes: &[Option<BoxStats>],
    order: &[&str],
    axis: CostAxis,
) -> Result<()>
where
    DB: DrawingBackend,
    Y: plotters::coord::ranged1d::Ranged<ValueType = f64>,
{
    let plot = chart.plotting_area();
    let y = |v: f64| axis.map(v);
    let (half, cap) = (0.3, 0.15);
    for (i, (p, b)) in problem.planners.iter().zip(boxes).enumerate() {
        let c = style::path_color(color_index(order, p.planner));
        let xi = i as f64;
        let Some(b) = b else { continue };
        let whisker = style::line(c, 2);
        for (from, to) in [(b.q1, b.whisker_lo), (b.q3, b.whisker_hi)] {
            plot.draw(&PathElement::new(vec![(xi, y(from)), (xi, y(to))], whisker)).map_err(plot_err)?;
            plot.draw(&PathElement::new(vec![(xi - cap, y(to)), (xi + cap, y(to))], whisker)).map_err(plot_err)?;
        }
        let corners = [(xi - half, y(b.q1)), (xi + half, y(b.q3))];
        plot.draw(&Rectangle::new(corners, style::fill(WHITE))).map_err(plot_err)?;
        plot.draw(&Rectangle::new(corners, style::fill(c.mix(0.3)))).map_err(plot_err)?;
        plot.draw(&Rectangle::new(corners, style::line(c, 2))).map_err(plot_err)?;
        plot.draw(&PathElement::new(
            vec![(xi - half, y(b.median)), (xi + half, y(b.median))],
            style::line(style::TEXT, 3),
        ))
        .map_err(plot_err)?;
        for &o in &b.outliers {
            plot.draw(&Circle::new((xi, y(o)), 3, style::line(c, 2))).map_err(plot_err)?;
        }
    }

    // Planner names under their boxes, on two staggered rows when they would collide.
    let base = body.get_base_pixel();
    let y_axis = chart.y_range().start;
    let n = problem.planners.len();
    let slot = if n > 1 {
        (chart.backend_coord(&(1.0, y_axis)).0 - chart.backend_coord(&(0.0, y_axis)).0) as f64
    } else {
        chart.plotting_area().dim_in_pixel().0 as f64
    };
    let widest = problem.planners.iter().map(|p| style::text_width(p.planner, style::TICK_PX)).fold(0.0, f64::max);
    let stagger = n > 1 && widest > slot - 6.0;
    let room = if stagger { 2.0 * slot - 8.0 } else { slot - 6.0 };
    let text = style::font(style::TICK_PX).pos(Pos::new(HPos::Center, VPos::Top));
    let note = style::font(style::TICK_PX).color(&style::MUTED).pos(Pos::new(HPos::Center, VPos::Top));
    let top = chart.backend_coord(&(0.0, chart.y_range().end)).1;
    for (i, (p, b)) in problem.planners.iter().zip(boxes).enumerate() {
        let (px, py) = chart.backend_coord(&(i as f64, y_axis));
        let row = if stagger { (i % 2) as i32 } else { 0 };
        let at = (px - base.0, py - base.1 + 8 + row * 17);
        body.draw(&Text::new(fit_label(p.planner, room), at, text.clone())).map_err(plot_err)?;
        let missing = b.as_ref().map_or(p.costs.len(), |b| b.non_finite);
        if missing > 0 {
            let label = if b.is_none() {
                "no finite cost".to_string()
            } else {
                format!("{missing} run{} = ∞", if missing == 1 { "" } else { "s" })
            };
            body.draw(&Text::new(label, (px - base.0, top - base.1 + 4), note.clone())).map_err(plot_err)?;
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
        let title_style = style::bold(style::TITLE_PX).pos(Pos::new(HPos::Center, VPos::Center));
        root.draw(&Text::new(title.to_string(), (w as i32 / 2, TITLE_H as i32 / 2 + 2), title_style))
            .map_err(plot_err)?;
        let body = root.split_vertically(TITLE_H).1.margin(0, 8, 8, 8);
        // A wide domain gets a wider plan view, as in the plan figure; the profile keeps
        // enough width to read the climbs.
        let b = world.bounds;
        let aspect = ((b.max.x - b.min.x) / (b.max.y - b.min.y)).clamp(0.3, 3.0);
        let avail_h = (h - TITLE_H) as f64 - 200.0;
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
        assert_eq!(axis, CostAxis::Log { lo: 1e-9, hi: 1e3, zero_at: Some(1e-9) });
        assert_eq!(axis.map(0.0), 1e-9);
        assert!(axis.desc("best cost").contains("0 drawn at 1e-9"));
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
