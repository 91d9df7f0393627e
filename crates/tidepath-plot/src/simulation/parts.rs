//! What the overview and the panels both draw: phase colours, the track between two times,
//! route lines, the numbered phase badge, the vehicle, the failure mark, and wrapped labels.

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::experiment::layout::wrap;
use super::super::plan_view::{position_at, to_px, Chart};
use super::super::style::{self, plot_err};
use tidepath::error::Result;
use tidepath::geom::Vec3;

/// The route ahead before a change: the path palette's grey, which no phase takes.
pub(super) const OLD_ROUTE: RGBColor = RGBColor(120, 120, 120);
/// Phase colours: the path palette without its grey.
const PHASE_COLORS: usize = 7;

/// The colour of phase `k`; colours repeat after seven phases (the numbers tell them apart).
pub(super) fn phase_color(k: usize) -> RGBColor {
    style::path_color(k % PHASE_COLORS)
}

/// Text safe in an SVG document: control characters (which XML forbids) become spaces.
pub(super) fn clean(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { ' ' } else { c }).collect()
}

/// The track's part between times `t0` and `t1` (clipped to its times), its ends interpolated.
pub(super) fn track_between(track: &[Vec3], times: &[f64], t0: f64, t1: f64) -> Vec<Vec3> {
    let (Some(&first), Some(&last)) = (times.first(), times.last()) else { return Vec::new() };
    let (t0, t1) = (t0.max(first), t1.min(last));
    // Also refuses a NaN time.
    if t1.partial_cmp(&t0).is_none_or(|o| o.is_lt()) {
        return Vec::new();
    }
    let mut out: Vec<Vec3> = position_at(track, times, t0).into_iter().collect();
    out.extend(track.iter().zip(times).filter(|(_, &t)| t > t0 && t < t1).map(|(p, _)| *p));
    out.extend(position_at(track, times, t1));
    out
}

/// The end of phase `k` of `times` (the next phase's start; the track's end for the last).
pub(super) fn phase_end(starts: &[f64], k: usize, track_times: &[f64]) -> f64 {
    starts.get(k + 1).copied().or(track_times.last().copied()).unwrap_or(starts[k])
}

fn xy(pts: &[Vec3], u: f64) -> Vec<(f64, f64)> {
    pts.iter().filter(|q| q.x.is_finite() && q.y.is_finite()).map(|q| (q.x / u, q.y / u)).collect()
}

/// A line `width` pixels wide on a pale casing, which keeps it readable over dark water.
pub(super) fn draw_line<DB: DrawingBackend>(
    chart: &Chart<DB>,
    pts: &[Vec3],
    u: f64,
    color: RGBColor,
    width: u32,
) -> Result<()> {
    let pts = xy(pts, u);
    if pts.len() >= 2 {
        let plot = chart.plotting_area();
        plot.draw(&PathElement::new(pts.clone(), style::line(WHITE.mix(0.75), width + 2))).map_err(plot_err)?;
        plot.draw(&PathElement::new(pts, style::line(color, width))).map_err(plot_err)?;
    }
    Ok(())
}

/// A dashed line (the route ahead before a change).
pub(super) fn draw_dashed<DB: DrawingBackend>(chart: &Chart<DB>, pts: &[Vec3], u: f64, color: RGBColor) -> Result<()> {
    let pts = xy(pts, u);
    if pts.len() >= 2 {
        let plot = chart.plotting_area();
        plot.draw(&DashedPathElement::new(pts, 7, 5, style::line(color, 2))).map_err(plot_err)?;
    }
    Ok(())
}

/// The replanned piece's highlight: a wide translucent band of the phase's colour, drawn
/// under the route so the route stays sharp on top.
pub(super) const BAND_WIDTH: u32 = 11;
pub(super) fn band(color: RGBColor) -> RGBAColor {
    color.mix(0.4)
}

pub(super) fn draw_band<DB: DrawingBackend>(chart: &Chart<DB>, pts: &[Vec3], u: f64, color: RGBColor) -> Result<()> {
    let pts = xy(pts, u);
    if pts.len() >= 2 {
        chart.plotting_area().draw(&PathElement::new(pts, style::line(band(color), BAND_WIDTH))).map_err(plot_err)?;
    }
    Ok(())
}

/// Pixel position of a point on the chart's plotting area, `None` when not finite.
pub(super) fn px<DB: DrawingBackend>(chart: &Chart<DB>, p: Vec3, u: f64) -> Option<(i32, i32)> {
    (p.x.is_finite() && p.y.is_finite()).then(|| to_px(chart, p.x / u, p.y / u))
}

/// Radius of a phase badge (pixels).
pub(super) const BADGE_R: i32 = 9;

/// A phase's number in a disc of its colour, with a dark rim; the number is white or black,
/// whichever reads on the colour.
pub(super) fn draw_badge<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: (i32, i32),
    k: usize,
    color: RGBColor,
) -> Result<()> {
    let r = if k >= 100 { BADGE_R + 3 } else { BADGE_R } as u32;
    area.draw(&Circle::new(c, r + 1, style::fill(WHITE))).map_err(plot_err)?;
    area.draw(&Circle::new(c, r, style::fill(color))).map_err(plot_err)?;
    area.draw(&Circle::new(c, r, style::line(style::OBSTACLE_EDGE, 1))).map_err(plot_err)?;
    let light = 0.299 * f64::from(color.0) + 0.587 * f64::from(color.1) + 0.114 * f64::from(color.2) > 150.0;
    let ink = if light { BLACK } else { WHITE };
    let font = style::bold(if k >= 10 { 10.0 } else { 12.0 }).color(&ink).pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(k.to_string(), c, font)).map_err(plot_err)
}

/// The vehicle: a dark ring with a white core and a dark centre.
pub(super) fn draw_vehicle<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, c: (i32, i32)) -> Result<()> {
    area.draw(&Circle::new(c, 8, style::fill(WHITE))).map_err(plot_err)?;
    area.draw(&Circle::new(c, 7, style::line(style::OBSTACLE_EDGE, 2))).map_err(plot_err)?;
    area.draw(&Circle::new(c, 2, style::fill(style::OBSTACLE_EDGE))).map_err(plot_err)
}

/// Where a mission ended without a feasible route: a ring crossed in the warning colour.
pub(super) fn draw_failure<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, c: (i32, i32)) -> Result<()> {
    area.draw(&Circle::new(c, 13, style::line(WHITE.mix(0.8), 6))).map_err(plot_err)?;
    area.draw(&Circle::new(c, 13, style::line(style::WARN, 3))).map_err(plot_err)?;
    for (dx, dy) in [(1, 1), (1, -1)] {
        let line = vec![(c.0 - 9 * dx, c.1 - 9 * dy), (c.0 + 9 * dx, c.1 + 9 * dy)];
        area.draw(&PathElement::new(line, style::line(style::WARN, 3))).map_err(plot_err)?;
    }
    Ok(())
}

/// How much wider than [`style::text_width`]'s estimate a line may really be (digits, capitals):
/// labels are wrapped to the width divided by this, so they stay inside their panel.
const WIDTH_MARGIN: f64 = 1.12;

/// `text` wrapped at spaces into lines no wider than `width` pixels at `px` (a word too long
/// for a line is cut), at most `max_lines` of them, the last ending in "…" when text is left
/// out.
pub(super) fn wrap_label(text: &str, width: f64, px: f64, max_lines: usize) -> Vec<String> {
    let width = width / WIDTH_MARGIN;
    let per_line = ((width / style::text_width("0", px)).floor() as usize).max(4);
    let mut lines: Vec<String> = Vec::new();
    for line in wrap(text, width, px) {
        let chars: Vec<char> = line.chars().collect();
        if style::text_width(&line, px) <= width {
            lines.push(line);
        } else {
            lines.extend(chars.chunks(per_line).map(|c| c.iter().collect::<String>()));
        }
    }
    if lines.len() > max_lines {
        lines.truncate(max_lines);
        let last = lines.last_mut().expect("max_lines > 0");
        let keep = last.chars().count().min(per_line.saturating_sub(2));
        *last = format!("{}…", last.chars().take(keep).collect::<String>().trim_end());
    }
    lines
}

/// A phase's short name for the legend: its label up to the first ';', at most `most` chars.
pub(super) fn short_label(label: &str, most: usize) -> String {
    let head = clean(label.split(';').next().unwrap_or(label).trim());
    if head.chars().count() <= most {
        head
    } else {
        format!("{}…", head.chars().take(most - 1).collect::<String>().trim_end())
    }
}
