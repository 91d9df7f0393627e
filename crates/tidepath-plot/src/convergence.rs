//! Convergence curves: best cost against iteration (or sample), one median line per series
//! with an optional band (the interquartile range over repeated runs).
//!
//! The y axis switches to log10 when the costs span more than two decades, since early costs
//! (often penalty-dominated) would otherwise flatten everything that happens later; it is then
//! labelled at whole decades from end to end (see [`super::log_axis`]). Non-finite
//! values (no feasible solution yet, failed runs) break the line instead of being invented.
//! Long histories (a sampling planner's, one entry per sample) are thinned to at most
//! [`MAX_DRAWN_POINTS`] per line for drawing, keeping every end of a finite stretch.

use std::ops::Range;

use plotters::coord::ranged1d::{AsRangedCoord, BoldPoints, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::log_axis::{self, DecadeAxis, Decades};
use super::style::{self, plot_err, LegendEntry, Swatch};
use tidepath::error::Result;

pub(crate) const Y_LABELS: usize = 7;

/// Most points of one drawn line or band edge: more are invisible at any figure width and
/// only slow the drawing and bloat the SVG (20 runs of 20,000 samples each).
pub const MAX_DRAWN_POINTS: usize = 2000;

/// One curve of a convergence plot: `median[i]` is the value at x = `first_x + i` (an
/// iteration or a sample count); `band`, when given, is (lower, upper) per entry and is shaded
/// behind the line.
#[derive(Clone, Debug)]
pub struct ConvergenceSeries<'a> {
    pub label: String,
    pub median: &'a [f64],
    /// The x of entry 0: 0 for iterations (entry 0 is the state after initialisation), 1 for
    /// samples (entry 0 is the best cost after the first sample).
    pub first_x: f64,
    pub band: Option<(&'a [f64], &'a [f64])>,
    /// Palette index ([`style::path_color`]); `None` takes the series' position in the list.
    /// Set it when a series belongs to a path drawn elsewhere, so both share a colour.
    pub color: Option<usize>,
    /// Mark the first finite point with a hollow diamond: something ran before the iterations
    /// (a composite planner's reference search) and the curve starts from its result.
    pub mark_first: bool,
}

impl<'a> ConvergenceSeries<'a> {
    /// A single run's history: a line without a band.
    pub fn line(label: impl Into<String>, values: &'a [f64]) -> Self {
        Self { label: label.into(), median: values, first_x: 0.0, band: None, color: None, mark_first: false }
    }

    /// The x of the last entry of the line or band.
    fn last_x(&self) -> f64 {
        let n = self.median.len().max(self.band.map_or(0, |(l, u)| l.len().min(u.len())));
        self.first_x + n.saturating_sub(1) as f64
    }
}

/// Whether a log10 axis reads better for `values`: all positive and spanning over two decades.
pub fn wants_log_scale(values: impl IntoIterator<Item = f64>) -> bool {
    let (mut lo, mut hi, mut any) = (f64::INFINITY, 0.0f64, false);
    for v in values.into_iter().filter(|v| v.is_finite()) {
        if v <= 0.0 {
            return false;
        }
        lo = lo.min(v);
        hi = hi.max(v);
        any = true;
    }
    any && hi / lo > 100.0
}

fn series_color(i: usize, s: &ConvergenceSeries) -> RGBColor {
    style::path_color(s.color.unwrap_or(i))
}

/// Whether two values draw the same: equal, or both not finite (a gap either way).
fn same(a: f64, b: f64) -> bool {
    a == b || (!a.is_finite() && !b.is_finite())
}

/// The indices of `lines` (equally long) to draw, at most about `max` of them: all when they
/// fit; else both ends of every finite stretch (where a curve becomes finite, and where it
/// stops) and both ends of every flat stretch, which draw a step curve exactly; and when even
/// those are too many, the ends of the finite stretches and an even stride over the rest.
pub(crate) fn thin(lines: &[&[f64]], max: usize) -> Vec<usize> {
    let n = lines.iter().map(|l| l.len()).min().unwrap_or(0);
    if n <= max.max(2) {
        return (0..n).collect();
    }
    let finite = |i: usize| lines.iter().all(|l| l[i].is_finite());
    let edge = |i: usize| i == 0 || i + 1 == n || finite(i) != finite(i - 1) || finite(i) != finite(i + 1);
    let step = |i: usize| lines.iter().any(|l| !same(l[i], l[i - 1]) || !same(l[i], l[i + 1]));
    let corners: Vec<usize> = (0..n).filter(|&i| edge(i) || step(i)).collect();
    if corners.len() <= max {
        return corners;
    }
    let edges = corners.iter().filter(|&&i| edge(i)).count();
    let stride = n.div_ceil(max.saturating_sub(edges).max(1));
    (0..n).filter(|&i| i % stride == 0 || edge(i)).collect()
}

/// Maximal runs of consecutive indices where `ok` holds.
fn runs(n: usize, ok: impl Fn(usize) -> bool) -> Vec<Range<usize>> {
    let mut out = Vec::new();
    let mut start = None;
    for i in 0..=n {
        match (start, i < n && ok(i)) {
            (None, true) => start = Some(i),
            (Some(s), false) => {
                out.push(s..i);
                start = None;
            }
            _ => {}
        }
    }
    out
}

fn all_values<'a>(series: &'a [ConvergenceSeries]) -> impl Iterator<Item = f64> + 'a {
    series.iter().flat_map(|s| {
        let band = s.band.map(|(l, u)| l.iter().chain(u.iter())).into_iter().flatten();
        s.median.iter().chain(band).copied()
    })
}

/// Draws the convergence panel: one median line per series over its band, on a log10 axis
/// when [`wants_log_scale`] says so. `start_note` says what iteration 0 is when something ran
/// before the iterations; the first point of each series with `mark_first` is then marked and
/// the note is its legend entry.
pub fn draw_convergence<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    series: &[ConvergenceSeries],
    start_note: Option<&str>,
) -> Result<()> {
    let body = style::caption(area, "Convergence")?;
    let finite: Vec<f64> = all_values(series).filter(|v| v.is_finite()).collect();
    if finite.is_empty() {
        let (w, h) = body.dim_in_pixel();
        let empty = series.iter().all(|s| s.median.is_empty() && s.band.is_none());
        let msg = if empty { "no convergence history" } else { "no finite cost recorded" };
        let style = style::font(style::AXIS_DESC_PX).color(&style::MUTED).pos(Pos::new(HPos::Center, VPos::Center));
        body.draw(&Text::new(msg, (w as i32 / 2, h as i32 / 3), style)).map_err(plot_err)?;
        return Ok(());
    }
    let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let x_range = x_range(series);
    // Sample histories start at x = 1 (entry k is after sample k + 1).
    let x_desc = if series.iter().all(|s| s.first_x == 1.0) { "samples" } else { "iteration" };

    // Each swatch is drawn as its curve is: a line, over its own band when it has one.
    let mut legend: Vec<LegendEntry> = series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let c = series_color(i, s);
            let swatch =
                if s.band.is_some() { Swatch::LineOverBand(c) } else { Swatch::Line { color: c.to_rgba(), width: 2 } };
            let label =
                if s.band.is_some() { format!("{} (median, interquartile range)", s.label) } else { s.label.clone() };
            LegendEntry::new(label, swatch)
        })
        .collect();
    if let (Some(note), Some((i, s))) = (start_note, series.iter().enumerate().find(|(_, s)| s.mark_first)) {
        legend.push(LegendEntry::new(note, Swatch::Diamond(series_color(i, s))));
    }
    let (w, _) = body.dim_in_pixel();
    let legend_h = style::legend_height(&legend, w.saturating_sub(70));
    let (legend_area, chart_area) = body.split_vertically(legend_h);
    style::draw_legend(&legend_area.margin(0, 0, 70, 0), &legend)?;

    if let Some(decades) = Decades::for_values(lo, hi).filter(|_| wants_log_scale(finite.iter().copied())) {
        let y = DecadeAxis::new(decades);
        let mut chart =
            build(&chart_area, Frame::new(x_range, x_desc), y, "best cost (log scale)", |v: &f64| log_axis::label(*v))?;
        draw_curves(&mut chart, series)
    } else {
        let pad = if hi > lo { (hi - lo) * 0.05 } else { lo.abs().max(1.0) * 0.1 };
        let y = (lo - pad)..(hi + pad);
        let frame = Frame::new(x_range, x_desc);
        let mut chart = build(&chart_area, frame, y.clone(), "best cost", style::tick_formatter(y, Y_LABELS))?;
        draw_curves(&mut chart, series)
    }
}

/// From 0 to the last entry of the longest series (at least 1), with a little room left of 0
/// when a first point is marked so its diamond is not cut in half by the axis.
pub(crate) fn x_range(series: &[ConvergenceSeries]) -> Range<f64> {
    let end = series.iter().map(ConvergenceSeries::last_x).fold(1.0, f64::max);
    let start = if series.iter().any(|s| s.mark_first) { -0.025 * end } else { 0.0 };
    start..end
}

/// The x axis of a convergence chart and the room right of the plot.
pub(crate) struct Frame<'s> {
    pub x: Range<f64>,
    /// "iteration", "samples", ...
    pub x_desc: &'s str,
    /// Pixels right of the plot (labels at the curves' ends go there).
    pub margin_right: u32,
}

impl<'s> Frame<'s> {
    pub fn new(x: Range<f64>, x_desc: &'s str) -> Self {
        Self { x, x_desc, margin_right: 18 }
    }
}

pub(crate) fn build<'a, DB, Y>(
    area: &'a DrawingArea<DB, Shift>,
    frame: Frame<'_>,
    y: Y,
    y_desc: &str,
    y_fmt: impl Fn(&f64) -> String,
) -> Result<ChartContext<'a, DB, Cartesian2d<RangedCoordf64, Y::CoordDescType>>>
where
    DB: DrawingBackend,
    Y: AsRangedCoord<Value = f64>,
    Y::CoordDescType: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let x = frame.x;
    // Iterations and samples are whole numbers: at most one label per whole number.
    let x_labels = ((x.end - x.start).round() as usize + 1).min(8);
    // Room for the widest tick label and the axis description beside it, never on it.
    let y: Y::CoordDescType = y.into();
    let y_label_w = style::label_area_for(y.key_points(BoldPoints(Y_LABELS)).iter().map(&y_fmt));
    let mut chart = ChartBuilder::on(area)
        .margin_right(frame.margin_right)
        .margin_top(6)
        .x_label_area_size(46)
        .y_label_area_size(y_label_w)
        .build_cartesian_2d(x, y)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(style::GRID)
        .x_labels(x_labels)
        .y_labels(Y_LABELS)
        .x_desc(frame.x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v: &f64| if v.fract().abs() < 1e-9 { format!("{v:.0}") } else { String::new() })
        .y_label_formatter(&y_fmt)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;
    Ok(chart)
}

/// Draws every series' band and median line (thinned to [`MAX_DRAWN_POINTS`]), values
/// clamped to the y range, and the marked first points on top.
pub(crate) fn draw_curves<DB, Y>(
    chart: &mut ChartContext<DB, Cartesian2d<RangedCoordf64, Y>>,
    series: &[ConvergenceSeries],
) -> Result<()>
where
    DB: DrawingBackend,
    Y: Ranged<ValueType = f64>,
{
    let (y_lo, y_hi) = {
        let r = chart.y_range();
        (r.start.min(r.end), r.start.max(r.end))
    };
    let y = |v: f64| v.clamp(y_lo, y_hi);
    for (i, s) in series.iter().enumerate() {
        let color = series_color(i, s);
        let x = |k: usize| s.first_x + k as f64;
        if let Some((lower, upper)) = s.band {
            let m = lower.len().min(upper.len());
            let keep = thin(&[&lower[..m], &upper[..m]], MAX_DRAWN_POINTS);
            let ok = |j: usize| lower[keep[j]].is_finite() && upper[keep[j]].is_finite();
            for r in runs(keep.len(), ok) {
                let mut poly: Vec<(f64, f64)> = keep[r.clone()].iter().map(|&k| (x(k), y(upper[k]))).collect();
                poly.extend(keep[r].iter().rev().map(|&k| (x(k), y(lower[k]))));
                chart
                    .draw_series(std::iter::once(Polygon::new(poly, style::fill(color.mix(0.2)))))
                    .map_err(plot_err)?;
            }
        }
        let keep = thin(&[s.median], MAX_DRAWN_POINTS);
        for r in runs(keep.len(), |j| s.median[keep[j]].is_finite()) {
            let pts: Vec<(f64, f64)> = keep[r].iter().map(|&k| (x(k), y(s.median[k]))).collect();
            if pts.len() == 1 {
                chart.draw_series(std::iter::once(Circle::new(pts[0], 3, style::fill(color)))).map_err(plot_err)?;
            } else {
                chart.draw_series(LineSeries::new(pts, style::line(color, 2))).map_err(plot_err)?;
            }
        }
    }
    // Diamonds last, on top of every line.
    let area = chart.plotting_area().strip_coord_spec();
    let base = chart.plotting_area().get_base_pixel();
    for (i, s) in series.iter().enumerate().filter(|(_, s)| s.mark_first) {
        if let Some(k) = s.median.iter().position(|v| v.is_finite()) {
            let (px, py) = chart.backend_coord(&(s.first_x + k as f64, y(s.median[k])));
            style::draw_diamond(&area, (px - base.0, py - base.1), series_color(i, s))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_scale_only_for_positive_values_over_two_decades() {
        assert!(wants_log_scale([1000.0, 50.0, 0.9, f64::INFINITY]));
        assert!(!wants_log_scale([1000.0, 50.0, 20.0]));
        assert!(!wants_log_scale([1000.0, 0.0, 0.001]));
        assert!(!wants_log_scale([f64::NAN]));
    }

    #[test]
    fn bands_render_behind_medians() {
        let median: Vec<f64> = (0..60).map(|i| 5.0 + 300.0 * (-(i as f64) / 8.0).exp()).collect();
        let lower: Vec<f64> = median.iter().map(|m| m * 0.7).collect();
        let mut upper: Vec<f64> = median.iter().map(|m| m * 1.5).collect();
        upper[10] = f64::INFINITY;
        let other: Vec<f64> = median.iter().map(|m| m * 1.2 + 2.0).collect();
        let series = [
            ConvergenceSeries {
                label: "pso".into(),
                median: &median,
                first_x: 0.0,
                band: Some((&lower, &upper)),
                color: None,
                mark_first: false,
            },
            ConvergenceSeries {
                label: "de".into(),
                median: &other,
                first_x: 0.0,
                band: Some((&lower, &other)),
                color: Some(3),
                mark_first: true,
            },
        ];
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (700, 420)).into_drawing_area();
            root.fill(&WHITE).unwrap();
            draw_convergence(&root, &series, Some("iteration 0: refinement starts from the reference")).unwrap();
            root.present().unwrap();
        }
        // The infinite upper value splits the first band in two: three band pieces, and the
        // diamond's white fill on the curve and in the legend.
        assert_eq!(svg.matches("<polygon").count(), 5);
        assert!(svg.contains("pso (median, interquartile range)") && svg.contains("best cost (log scale)"));
        // The marked series' first point: a hollow diamond in its colour (palette 3, violet).
        assert!(svg.contains("iteration 0: refinement starts from the reference"));
        assert!(svg.contains(r##"stroke="#8C50C8" stroke-width="2" points="##), "no diamond in violet");
        assert!(!svg.contains("NaN"));
        if let Some(dir) = std::env::var_os("TIDEPATH_PLOT_DIR") {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(std::path::Path::new(&dir).join("convergence_bands.svg"), &svg).unwrap();
        }
    }

    #[test]
    fn runs_split_at_gaps() {
        let v = [f64::INFINITY, 3.0, 2.0, f64::NAN, 1.0];
        assert_eq!(runs(v.len(), |k| v[k].is_finite()), vec![1..3, 4..5]);
    }
}
