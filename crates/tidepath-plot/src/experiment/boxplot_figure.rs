//! boxplot.svg: Tukey boxes of every planner's final costs over runs.

use std::ops::Range;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::convergence::Y_LABELS;
use super::super::log_axis::DecadeAxis;
use super::super::style::{self, plot_err, LegendEntry, Swatch};
use super::cost_axis::{draw_zero_tick, CostAxis};
use super::layout::{draw_message, render_panel_grid, NOTE_H, ZERO_NOTE};
use super::{color_index, planner_order, ProblemRuns};
use tidepath::error::Result;
use tidepath_experiments::stats::Summary;

/// Room under a box plot for planner names on two staggered rows.
const BOX_LABEL_H: u32 = 44;
/// Tukey's box of one planner's final costs.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct BoxStats {
    pub(super) q1: f64,
    pub(super) median: f64,
    pub(super) q3: f64,
    /// Most extreme costs within 1.5 IQR of the box.
    pub(super) whisker_lo: f64,
    pub(super) whisker_hi: f64,
    pub(super) outliers: Vec<f64>,
    /// Runs without a finite cost, which no box can show.
    pub(super) non_finite: usize,
}

impl BoxStats {
    pub(super) fn of(costs: &[f64]) -> Option<Self> {
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
    render_panel_grid(title, &legend, &note, problems.len(), |area, i| draw_box_panel(area, &problems[i], &order))
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
