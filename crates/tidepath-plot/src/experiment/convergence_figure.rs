//! convergence.svg: the median best cost per iteration over runs, with its interquartile band.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::convergence::{build, draw_curves, x_range, ConvergenceSeries, Y_LABELS};
use super::super::log_axis::DecadeAxis;
use super::super::style::{self, plot_err, LegendEntry, Swatch};
use super::cost_axis::{draw_zero_tick, CostAxis};
use super::layout::{draw_message, render_panel_grid, NOTE_H, ZERO_NOTE};
use super::{color_index, planner_order, ProblemRuns};
use tidepath::error::Result;
use tidepath_experiments::stats::Summary;

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
struct Curve {
    color: usize,
    q1: Vec<f64>,
    median: Vec<f64>,
    q3: Vec<f64>,
    runs: usize,
    /// Iteration 0 follows a search (a composite planner's reference): marked.
    seeded: bool,
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
                    seeded: p.search_before_iterations,
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
    // Each planner's swatch is its line over its own band, as the panels draw them.
    let mut legend: Vec<LegendEntry> = order
        .iter()
        .enumerate()
        .map(|(i, p)| LegendEntry::new(*p, Swatch::LineOverBand(style::path_color(i))))
        .collect();
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
    if !seeded.is_empty() {
        note.push_str(" A reference search's own time and cost are not on the iteration axis.");
    }
    if panels_data.iter().any(|p| p.axis.and_then(|a| a.zero_at()).is_some()) {
        note.push_str(ZERO_NOTE);
    }
    render_panel_grid(title, &legend, &note, problems.len(), |area, i| draw_convergence_panel(area, &panels_data[i]))
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
            mark_first: false,
        })
        .collect();
    series.extend(data.curves.iter().map(|c| ConvergenceSeries {
        label: String::new(),
        median: &c.median,
        band: None,
        color: Some(c.color),
        mark_first: c.seeded,
    }));
    let n = data.curves.iter().map(|c| c.median.len()).max().unwrap_or(0);
    let x = x_range(n, &series);
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
