//! convergence.svg: the median best cost per iteration (or per sample, for sampling planners)
//! over runs, with its interquartile band; with a reference, its cost as a dashed line and
//! each median's final gap to it.

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::convergence::{build, draw_curves, x_range, ConvergenceSeries, Frame, Y_LABELS};
use super::super::log_axis::DecadeAxis;
use super::super::style::{self, plot_err, LegendEntry, Swatch};
use super::cost_axis::{draw_zero_tick, CostAxis};
use super::layout::{draw_message, render_panel_grid, NOTE_H, ZERO_NOTE};
use super::{color_index, planner_order, ProblemRuns};
use tidepath::error::Result;
use tidepath_experiments::compare::{gap_percent, Comparison};
use tidepath_experiments::stats::Summary;
use tidepath_experiments::table::num;
use tidepath_experiments::RunRecord;

/// What one entry of a run's history stands for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum HistoryUnit {
    /// One entry per iteration, entry 0 after initialisation (optimizers).
    #[default]
    Iterations,
    /// One entry per sample drawn, entry k after sample k + 1 (sampling planners).
    Samples,
}

impl HistoryUnit {
    /// A run that drew samples and counted no iterations recorded its history per sample.
    pub fn of(r: &RunRecord) -> Self {
        if r.samples > 0 && r.iterations == 0 {
            HistoryUnit::Samples
        } else {
            HistoryUnit::Iterations
        }
    }

    /// The x of a history's entry 0.
    fn first_x(self) -> f64 {
        match self {
            HistoryUnit::Iterations => 0.0,
            HistoryUnit::Samples => 1.0,
        }
    }
}

/// The reference a problem's gaps are measured against: drawn across its convergence panel as
/// a dashed line.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceCost<'a> {
    pub problem: &'a str,
    pub planner: &'a str,
    /// Its plan's status ("exact", "feasible", ...).
    pub status: &'a str,
    pub cost: f64,
}

/// What the convergence figure knows beyond the runs: the unit of each planner's history,
/// each problem's reference, and how many runs ended feasible.
#[derive(Clone, Debug, Default)]
pub struct ConvergenceContext<'a> {
    /// Planners whose histories count samples; every other planner's counts iterations.
    pub sample_planners: Vec<&'a str>,
    pub references: Vec<ReferenceCost<'a>>,
    /// (problem, planner, runs whose path is feasible); a pair not listed had only feasible
    /// runs. A gap to the reference is given only when more than half of the runs are
    /// feasible: otherwise the final median is mostly penalty, not the cost of a route.
    pub feasible_runs: Vec<(&'a str, &'a str, usize)>,
}

impl<'a> ConvergenceContext<'a> {
    /// The units of `records`' planners (a planner counts samples when any of its runs did)
    /// and their feasible runs; no reference.
    pub fn of_records(records: &'a [RunRecord]) -> Self {
        let mut out = ConvergenceContext::default();
        for r in records {
            if HistoryUnit::of(r) == HistoryUnit::Samples && !out.sample_planners.contains(&r.planner.as_str()) {
                out.sample_planners.push(&r.planner);
            }
            let key = (r.problem.as_str(), r.planner.as_str());
            let k = match out.feasible_runs.iter().position(|(p, q, _)| (*p, *q) == key) {
                Some(k) => k,
                None => {
                    out.feasible_runs.push((key.0, key.1, 0));
                    out.feasible_runs.len() - 1
                }
            };
            out.feasible_runs[k].2 += usize::from(r.feasible);
        }
        out
    }

    /// A comparison's units and, for a scenario with a reference, the reference on its panel.
    pub fn of(c: &'a Comparison) -> Self {
        let mut out = Self::of_records(&c.records);
        if let Some(r) = c.reference.as_ref().filter(|r| r.cost.is_finite()) {
            out.references = c
                .problems
                .iter()
                .map(|p| ReferenceCost { problem: p, planner: &r.planner, status: &r.status, cost: r.cost })
                .collect();
        }
        out
    }

    pub fn unit(&self, planner: &str) -> HistoryUnit {
        if self.sample_planners.contains(&planner) {
            HistoryUnit::Samples
        } else {
            HistoryUnit::Iterations
        }
    }

    fn reference(&self, problem: &str) -> Option<&ReferenceCost<'a>> {
        self.references.iter().find(|r| r.problem == problem)
    }

    /// Runs of `planner` on `problem` whose path is feasible, of `runs`.
    fn feasible(&self, problem: &str, planner: &str, runs: usize) -> usize {
        self.feasible_runs.iter().find(|(p, q, _)| *p == problem && *q == planner).map_or(runs, |f| f.2)
    }
}

/// What the end of a curve says when there is a reference.
#[derive(Clone, Copy, Debug, PartialEq)]
enum CurveEnd {
    /// The final median's gap to the reference, in percent.
    Gap(f64),
    /// Too few runs ended feasible for the final median to be a route's cost.
    MostlyInfeasible { feasible: usize, runs: usize },
}

impl CurveEnd {
    /// At the curve's end: "+3.1 %", "1/5 feasible".
    fn text(self) -> String {
        match self {
            CurveEnd::Gap(g) => gap_text(g),
            CurveEnd::MostlyInfeasible { feasible, runs } => format!("{feasible}/{runs} feasible"),
        }
    }

    /// In the legend: "final gap +3.1 %", "1/5 runs feasible".
    fn legend(self) -> String {
        match self {
            CurveEnd::Gap(g) => format!("final gap {}", gap_text(g)),
            CurveEnd::MostlyInfeasible { feasible, runs } => format!("{feasible}/{runs} runs feasible"),
        }
    }
}

/// The x axis' description for a panel whose planners count in `units`: "iteration",
/// "samples", or "iteration (samples for rrt-star, prm-star)" when they differ.
pub(super) fn x_axis_desc(units: &[(&str, HistoryUnit)]) -> String {
    let samplers: Vec<&str> = units.iter().filter(|(_, u)| *u == HistoryUnit::Samples).map(|(p, _)| *p).collect();
    if samplers.is_empty() {
        "iteration".into()
    } else if samplers.len() == units.len() {
        "samples".into()
    } else {
        format!("iteration (samples for {})", samplers.join(", "))
    }
}

/// A gap in percent as a label: "+3.1 %", "+154 %", "-0.4 %".
pub(super) fn gap_text(gap: f64) -> String {
    let g = if gap.abs() < 0.05 { 0.0 } else { gap };
    if g.abs() >= 99.95 {
        format!("{g:+.0} %")
    } else {
        format!("{g:+.1} %")
    }
}

/// The legend label of a reference: "reference visibility (exact): 12.3".
pub(super) fn reference_label(r: &ReferenceCost, with_cost: bool) -> String {
    let what = format!("reference {} ({})", r.planner, r.status);
    if with_cost {
        format!("{what}: {}", num(r.cost))
    } else {
        format!("{what}, its cost at the line")
    }
}

/// A history with its gaps filled the way a best-so-far curve means them: before the first
/// finite value there is no solution yet (+inf, worse than any cost, so it counts against the
/// planner in the quartiles), afterwards a missing entry repeats the last finite one.
pub(super) fn fill_history(h: &[f64]) -> Vec<f64> {
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
pub(super) struct Bands {
    pub(super) q1: Vec<f64>,
    pub(super) median: Vec<f64>,
    pub(super) q3: Vec<f64>,
    pub(super) runs: usize,
}

impl Bands {
    pub(super) fn of(histories: &[Vec<f64>]) -> Self {
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

/// One planner's curve in a convergence panel, already mapped to the panel's axis.
struct Curve<'p> {
    planner: &'p str,
    color: usize,
    unit: HistoryUnit,
    q1: Vec<f64>,
    median: Vec<f64>,
    q3: Vec<f64>,
    runs: usize,
    /// Iteration 0 follows a search (a composite planner's reference): marked.
    seeded: bool,
    /// With a reference: the last median's gap to it, or why there is none.
    end: Option<CurveEnd>,
}

/// Everything a convergence panel shows, computed before drawing so the header knows whether
/// any panel needs the zero-line note.
struct ConvergencePanel<'p> {
    problem: &'p str,
    curves: Vec<Curve<'p>>,
    axis: Option<CostAxis>,
    /// Planners with runs but no finite median at any iteration, which draw nothing.
    missing: Vec<&'p str>,
    reference: Option<ReferenceCost<'p>>,
    x_desc: String,
}

impl<'p> ConvergencePanel<'p> {
    fn of(problem: &ProblemRuns<'p>, order: &[&str], ctx: &ConvergenceContext<'p>) -> Self {
        let bands: Vec<Bands> = problem.planners.iter().map(|p| Bands::of(&p.histories)).collect();
        let reference = ctx.reference(problem.problem).cloned();
        // The reference's cost is on the axis, but alone it makes no chart: a panel without a
        // finite cost still says so.
        let values = || bands.iter().flat_map(|b| b.q1.iter().chain(&b.median).chain(&b.q3)).copied();
        let axis = CostAxis::for_values(values())
            .and_then(|_| CostAxis::for_values(values().chain(reference.as_ref().map(|r| r.cost))));
        let missing = problem
            .planners
            .iter()
            .zip(&bands)
            .filter(|(_, b)| b.runs > 0 && !b.median.iter().any(|v| v.is_finite()))
            .map(|(p, _)| p.planner)
            .collect();
        let curves: Vec<Curve> = problem
            .planners
            .iter()
            .zip(bands)
            .map(|(p, b)| {
                // Of all runs, as the table counts them (a run may have no history).
                let runs = p.costs.len();
                let feasible = ctx.feasible(problem.problem, p.planner, runs);
                let end = match (&reference, b.median.last()) {
                    (Some(_), Some(_)) if 2 * feasible <= runs => Some(CurveEnd::MostlyInfeasible { feasible, runs }),
                    (Some(r), Some(&m)) if m.is_finite() => Some(CurveEnd::Gap(gap_percent(m, r.cost))),
                    _ => None,
                };
                let m = |v: Vec<f64>| v.into_iter().map(|x| axis.map_or(x, |a| a.map(x))).collect();
                Curve {
                    planner: p.planner,
                    color: color_index(order, p.planner),
                    unit: ctx.unit(p.planner),
                    q1: m(b.q1),
                    median: m(b.median),
                    q3: m(b.q3),
                    runs: b.runs,
                    seeded: p.search_before_iterations,
                    end,
                }
            })
            .collect();
        // The axis speaks for the planners that drew something, or for all when none did.
        let drawn: Vec<(&str, HistoryUnit)> =
            curves.iter().filter(|c| !c.median.is_empty()).map(|c| (c.planner, c.unit)).collect();
        let units = if drawn.is_empty() { curves.iter().map(|c| (c.planner, c.unit)).collect() } else { drawn };
        ConvergencePanel { problem: problem.problem, x_desc: x_axis_desc(&units), curves, axis, missing, reference }
    }
}

/// convergence.svg without references, every planner counting iterations: see
/// [`render_convergence_figure_with`].
pub fn render_convergence_figure(title: &str, problems: &[ProblemRuns]) -> Result<String> {
    render_convergence_figure_with(title, problems, &ConvergenceContext::default())
}

/// convergence.svg: one panel per problem with, per planner, the median best cost per iteration
/// (or per sample) over runs and its interquartile band; where `ctx` has a reference for the
/// problem, its cost as a dashed line and each median's final gap to it at the curve's end
/// (and in the legend, when there is one problem).
pub fn render_convergence_figure_with<'p>(
    title: &str,
    problems: &[ProblemRuns<'p>],
    ctx: &ConvergenceContext<'p>,
) -> Result<String> {
    let order = planner_order(problems);
    let panels_data: Vec<ConvergencePanel> = problems.iter().map(|p| ConvergencePanel::of(p, &order, ctx)).collect();
    let single = match panels_data.as_slice() {
        [p] => Some(p),
        _ => None,
    };
    // Each planner's swatch is its line over its own band, as the panels draw them; with one
    // problem, its entry also gives the final gap.
    let mut legend: Vec<LegendEntry> = order
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let end = single.and_then(|s| s.curves.iter().find(|c| c.planner == *p)).and_then(|c| c.end);
            let label = match end {
                Some(e) => format!("{p} ({})", e.legend()),
                None => p.to_string(),
            };
            LegendEntry::new(label, Swatch::LineOverBand(style::path_color(i)))
        })
        .collect();
    let references: Vec<&ReferenceCost> = panels_data.iter().filter_map(|p| p.reference.as_ref()).collect();
    if let Some(first) = references.first() {
        // One reference cost goes in the legend; several are written on their lines.
        let label = reference_label(first, references.len() == 1);
        legend.push(LegendEntry::new(label, Swatch::DashedPath(style::REFERENCE)));
    }
    let seeded: Vec<&str> =
        problems.iter().flat_map(|p| &p.planners).filter(|p| p.search_before_iterations).map(|p| p.planner).fold(
            Vec::new(),
            |mut v, p| {
                if !v.contains(&p) {
                    v.push(p);
                }
                v
            },
        );
    if !seeded.is_empty() {
        legend.push(LegendEntry::new(
            format!("iteration 0 of {}: refinement starts from the reference search", seeded.join(", ")),
            Swatch::Diamond(style::MUTED),
        ));
    }
    let mut note = "Lines: median over runs of the best cost so far, drawn once half of the runs have a finite \
                    cost; shaded: the interquartile range (25–75 % of runs), drawn once three quarters have one."
        .to_string();
    if !references.is_empty() {
        note.push_str(
            " Dashed: the reference's cost; at each line's end: the final median's gap to it, where more than half \
             of the runs ended feasible.",
        );
    }
    if panels_data.iter().any(|p| p.curves.iter().any(|c| c.unit == HistoryUnit::Samples && c.runs > 0)) {
        note.push_str(" Sampling planners are drawn per sample: the best cost of a path to the goal after each.");
    }
    if !seeded.is_empty() {
        note.push_str(" A reference search's own time and cost are not on the iteration axis.");
    }
    if panels_data.iter().any(|p| p.axis.and_then(|a| a.zero_at()).is_some()) {
        note.push_str(ZERO_NOTE);
    }
    let several_references = references.len() > 1;
    render_panel_grid(title, &legend, &note, problems.len(), |area, i| {
        draw_convergence_panel(area, &panels_data[i], several_references)
    })
}

/// Pixels between the centres of two stacked gap labels.
const GAP_LABEL_SPACING: i32 = 16;

/// A gap label at the end of a curve: the curve's last point and the label's text and colour.
struct GapLabel {
    point: (i32, i32),
    text: String,
    color: RGBColor,
}

/// Label centres as near `wanted` (pixel rows) as they can be while at least `spacing` apart
/// and inside `lo..=hi`, in the order given.
pub(super) fn stagger(wanted: &[i32], spacing: i32, lo: i32, hi: i32) -> Vec<i32> {
    let mut order: Vec<usize> = (0..wanted.len()).collect();
    order.sort_by_key(|&k| (wanted[k], k));
    let hi = hi.max(lo);
    let mut y: Vec<i32> = order.iter().map(|&k| wanted[k].clamp(lo, hi)).collect();
    for j in 1..y.len() {
        y[j] = y[j].max(y[j - 1] + spacing);
    }
    // Pushed past the bottom: shift back up from the bottom, then keep the top inside.
    if let Some(&last) = y.last() {
        if last > hi {
            let n = y.len();
            y[n - 1] = hi;
            for j in (0..n - 1).rev() {
                y[j] = y[j].min(y[j + 1] - spacing);
            }
        }
    }
    let mut out = vec![0; wanted.len()];
    for (j, &k) in order.iter().enumerate() {
        out[k] = y[j].max(lo);
    }
    out
}

/// A planner's colour for text: light ones (gold) darkened so they read on white.
fn text_color(c: RGBColor) -> RGBColor {
    let lum = 0.2126 * f64::from(c.0) + 0.7152 * f64::from(c.1) + 0.0722 * f64::from(c.2);
    if lum > 150.0 {
        let k = 150.0 / lum;
        RGBColor((f64::from(c.0) * k) as u8, (f64::from(c.1) * k) as u8, (f64::from(c.2) * k) as u8)
    } else {
        c
    }
}

/// Room right of the plot for the widest gap label (with its leader), or the usual margin.
fn gap_margin(data: &ConvergencePanel) -> u32 {
    let widest = data.curves.iter().filter_map(|c| c.end).map(|e| style::text_width(&e.text(), style::TICK_PX));
    widest.fold(None, |m: Option<f64>, w| Some(m.map_or(w, |m| m.max(w)))).map_or(18, |w| w.ceil() as u32 + 16)
}

fn draw_convergence_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    data: &ConvergencePanel,
    reference_cost_on_line: bool,
) -> Result<()> {
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
            first_x: c.unit.first_x(),
            band: Some((c.q1.as_slice(), c.q3.as_slice())),
            color: Some(c.color),
            mark_first: false,
        })
        .collect();
    series.extend(data.curves.iter().map(|c| ConvergenceSeries {
        label: String::new(),
        median: &c.median,
        first_x: c.unit.first_x(),
        band: None,
        color: Some(c.color),
        mark_first: c.seeded,
    }));
    let frame = Frame { x: x_range(&series), x_desc: &data.x_desc, margin_right: gap_margin(data) };
    let desc = axis.desc("best cost");
    let reference = data.reference.as_ref().map(|r| (axis.map(r.cost), r));
    let (zero, labels) = match axis {
        CostAxis::Log { lo, hi, decades, .. } => {
            let y = DecadeAxis::with_range(lo, hi, decades);
            let mut chart = build(&plot_area, frame, y, &desc, |v: &f64| axis.tick_label(*v))?;
            let zero = axis.zero_gap().map(|(z, a)| (chart.backend_coord(&(0.0, z)), chart.backend_coord(&(0.0, a))));
            let labels = draw_with_reference(&mut chart, &series, data, reference, reference_cost_on_line)?;
            (zero, labels)
        }
        CostAxis::Linear { lo, hi } => {
            let mut chart = build(&plot_area, frame, lo..hi, &desc, style::tick_formatter(lo..hi, Y_LABELS))?;
            let labels = draw_with_reference(&mut chart, &series, data, reference, reference_cost_on_line)?;
            (None, labels)
        }
    };
    let base = plot_area.get_base_pixel();
    if let Some(((x0, y0), (_, y1))) = zero {
        draw_zero_tick(&plot_area, x0 - base.0, y0 - base.1, y0 - y1)?;
    }
    if let Some((labels, (top, bottom))) = labels {
        draw_gap_labels(&plot_area, base, &labels, top, bottom)?;
    }
    Ok(())
}

/// Where the gap labels go: the curves' end points and the plot's top and bottom pixel rows
/// (backend pixels).
type GapLabels = Option<(Vec<GapLabel>, (i32, i32))>;

/// The curves, the reference line over them (a curve that reaches it would hide it), and
/// where each curve's gap label belongs.
fn draw_with_reference<DB, Y>(
    chart: &mut ChartContext<DB, Cartesian2d<RangedCoordf64, Y>>,
    series: &[ConvergenceSeries],
    data: &ConvergencePanel,
    reference: Option<(f64, &ReferenceCost)>,
    cost_on_line: bool,
) -> Result<GapLabels>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64>,
{
    draw_curves(chart, series)?;
    let x = chart.x_range();
    if let Some((y, r)) = reference {
        let line = vec![(x.start, y), (x.end, y)];
        chart.draw_series(DashedLineSeries::new(line, 9, 6, style::line(style::REFERENCE, 2))).map_err(plot_err)?;
        if cost_on_line {
            let (px, py) = chart.backend_coord(&(x.start, y));
            let base = chart.plotting_area().get_base_pixel();
            let text = style::font(style::TICK_PX).color(&style::REFERENCE).pos(Pos::new(HPos::Left, VPos::Bottom));
            chart
                .plotting_area()
                .strip_coord_spec()
                .draw(&Text::new(num(r.cost), (px - base.0 + 6, py - base.1 - 3), text))
                .map_err(plot_err)?;
        }
    }
    if reference.is_none() {
        return Ok(None);
    }
    let labels = data
        .curves
        .iter()
        .filter_map(|c| {
            let end = c.end?;
            let k = c.median.iter().rposition(|v| v.is_finite())?;
            let point = chart.backend_coord(&(c.unit.first_x() + k as f64, c.median[k]));
            Some(GapLabel { point, text: end.text(), color: text_color(style::path_color(c.color)) })
        })
        .collect();
    let (_, rows) = chart.plotting_area().get_pixel_range();
    Ok(Some((labels, (rows.start, rows.end))))
}

/// Each gap label right of its curve's end, in the planner's colour, joined to it by a short
/// leader and staggered so that no two overlap.
fn draw_gap_labels<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    base: (i32, i32),
    labels: &[GapLabel],
    top: i32,
    bottom: i32,
) -> Result<()> {
    let (w, _) = area.dim_in_pixel();
    let wanted: Vec<i32> = labels.iter().map(|l| l.point.1).collect();
    let half = GAP_LABEL_SPACING / 2;
    let rows = stagger(&wanted, GAP_LABEL_SPACING, top + half, bottom - half);
    for (l, y) in labels.iter().zip(rows) {
        let (px, py) = (l.point.0 - base.0, l.point.1 - base.1);
        let width = style::text_width(&l.text, style::TICK_PX).ceil() as i32;
        let x = (px + 10).min(w as i32 - width - 2);
        let y = y - base.1;
        area.draw(&PathElement::new(vec![(px + 2, py), (x - 2, y)], style::line(l.color, 1))).map_err(plot_err)?;
        let text = style::font(style::TICK_PX).color(&l.color).pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(l.text.clone(), (x, y), text)).map_err(plot_err)?;
    }
    Ok(())
}
