//! Shared look of every figure: fonts, colours, units, number formatting and a hand-laid legend.
//!
//! The legend is drawn by hand rather than with plotters' series labels because plotters puts
//! its legend box inside the plot, where it hides data; ours sits in a strip outside the plot
//! and wraps onto as many rows as the labels need.

use std::ops::Range;

use plotters::coord::ranged1d::Ranged;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use tidepath::error::{Error, Result};

mod colormaps;

pub use colormaps::{elevation_color, speed_color, wave_color, SPEED_OUTLINE};

/// Font family used everywhere; SVG viewers substitute their default sans-serif font.
pub const FONT: &str = "sans-serif";
/// Pixel sizes of the rendered text (see [`font`] for the plotters conversion).
pub const TITLE_PX: f64 = 20.0;
pub const CAPTION_PX: f64 = 16.0;
pub const AXIS_DESC_PX: f64 = 14.0;
pub const TICK_PX: f64 = 13.0;
pub const LEGEND_PX: f64 = 13.0;
/// Height reserved for a panel caption.
pub const CAPTION_H: u32 = 28;

pub const TEXT: RGBColor = RGBColor(30, 30, 30);
pub const MUTED: RGBColor = RGBColor(90, 90, 90);
pub const GRID: RGBAColor = RGBAColor(0, 0, 0, 0.08);
pub const START: RGBColor = RGBColor(20, 150, 60);
pub const GOAL: RGBColor = RGBColor(215, 25, 28);
pub const SEABED: RGBColor = RGBColor(176, 148, 108);
pub const SEABED_LINE: RGBColor = RGBColor(110, 84, 50);
pub const OBSTACLE_FILL: RGBAColor = RGBAColor(225, 225, 225, 0.6);
pub const OBSTACLE_EDGE: RGBColor = RGBColor(30, 30, 30);
pub const CURRENT: RGBColor = RGBColor(20, 30, 45);
pub const CONTOUR: RGBAColor = RGBAColor(10, 25, 45, 0.45);
pub const COAST: RGBColor = RGBColor(70, 50, 25);
pub const NO_TERRAIN_BG: RGBColor = RGBColor(236, 244, 250);
pub const SURFACE: RGBColor = RGBColor(90, 160, 220);
/// What went wrong: violated segments and waypoints, the place a failure is about. Apart from
/// every path colour and from the goal's darker red.
pub const WARN: RGBColor = RGBColor(255, 0, 40);
/// The reference path a comparison's gaps are measured against.
pub const REFERENCE: RGBColor = RGBColor(0, 90, 50);

/// Colours that stay visible on both the dark and the light end of the blue seabed map and
/// stay apart from the start (green) and goal (red) markers.
const PATH_COLORS: [RGBColor; 8] = [
    RGBColor(255, 127, 14),  // orange
    RGBColor(200, 30, 130),  // magenta
    RGBColor(0, 0, 0),       // black
    RGBColor(140, 80, 200),  // violet
    RGBColor(150, 90, 40),   // brown
    RGBColor(240, 200, 0),   // gold
    RGBColor(0, 170, 170),   // teal
    RGBColor(120, 120, 120), // grey
];

/// The colour of the i-th path or series; figures that show the same planners in several
/// panels pass the same index so a planner keeps its colour across panels.
pub fn path_color(i: usize) -> RGBColor {
    PATH_COLORS[i % PATH_COLORS.len()]
}

/// A plotters text style whose rendered SVG font-size is `px`: the SVG backend writes
/// `size / 1.24`, so the size is scaled up to compensate.
pub fn font(px: f64) -> TextStyle<'static> {
    TextStyle::from((FONT, px * 1.24).into_font()).color(&TEXT)
}

pub fn bold(px: f64) -> TextStyle<'static> {
    TextStyle::from((FONT, px * 1.24, FontStyle::Bold).into_font()).color(&TEXT)
}

/// Rough width of `text` in pixels at `px`, for layout only (DejaVu Sans averages about
/// 0.55 em per character).
pub fn text_width(text: &str, px: f64) -> f64 {
    text.chars().count() as f64 * px * 0.55
}

pub fn line(color: impl Color, width: u32) -> ShapeStyle {
    ShapeStyle { color: color.to_rgba(), filled: false, stroke_width: width }
}

pub fn fill(color: impl Color) -> ShapeStyle {
    ShapeStyle { color: color.to_rgba(), filled: true, stroke_width: 0 }
}

/// Turns a plotters error into the crate error; drawing to a string only fails on a bug or on
/// a figure plotters cannot lay out, so it is reported as a problem with the figure input.
pub fn plot_err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> Error {
    Error::input("plot", format!("could not draw the figure: {e}"))
}

/// Length unit of an axis: metres for small domains, kilometres once numbers would get long.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LengthUnit {
    /// Metres per unit.
    pub metres: f64,
    pub name: &'static str,
}

impl LengthUnit {
    pub fn for_extent(extent_m: f64) -> Self {
        if extent_m >= 5000.0 {
            Self { metres: 1000.0, name: "km" }
        } else {
            Self { metres: 1.0, name: "m" }
        }
    }
}

/// A "nice" step (1, 2, 2.5 or 5 times a power of ten) giving about `target` steps over `span`.
pub fn nice_step(span: f64, target: usize) -> f64 {
    if !(span.is_finite() && span > 0.0) {
        return 1.0;
    }
    let raw = span / target.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    for m in [1.0, 2.0, 2.5, 5.0, 10.0] {
        if m * mag >= raw {
            return m * mag;
        }
    }
    10.0 * mag
}

/// Multiples of a nice step strictly inside (lo, hi).
pub fn nice_levels(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let step = nice_step(hi - lo, target);
    let mut levels = Vec::new();
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return (levels, step);
    }
    let mut k = (lo / step).floor() as i64 + 1;
    loop {
        let v = k as f64 * step;
        if v >= hi {
            break;
        }
        if v > lo {
            levels.push(v);
        }
        k += 1;
    }
    (levels, step)
}

/// Formats `v` with just enough decimals for values `step` apart; never prints "-0".
pub fn fmt_num(v: f64, step: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    // The nudge keeps a step of 0.1 computed as 0.0999.. from asking for two decimals.
    let decimals =
        if step > 0.0 && step.is_finite() { (-(step.log10() + 1e-9).floor()).clamp(0.0, 6.0) as usize } else { 0 };
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// Formatter for the ticks plotters puts on a linear axis over `range` when asked for
/// `labels` labels: every label gets the decimals of the actual tick step, so an axis reads
/// "3.8, 4.0, 4.2" rather than "3.80, 4.00" or "3.8, 4, 4.2".
pub fn tick_formatter(range: Range<f64>, labels: usize) -> impl Fn(&f64) -> String {
    let ticks = RangedCoordf64::from(range.clone()).key_points(labels);
    let step = match ticks.as_slice() {
        [a, b, ..] => b - a,
        _ => (range.end - range.start).abs(),
    };
    move |v: &f64| fmt_num(*v, step)
}

/// Width (pixels) of a y label area holding `labels` right-aligned at the axis and the
/// rotated axis description beyond them, so the description never overlaps a tick label.
/// Digits are wider than average text (about 0.64 em in DejaVu Sans), so they are measured as
/// such.
pub fn label_area_for(labels: impl IntoIterator<Item = String>) -> u32 {
    let widest = labels.into_iter().map(|l| l.chars().count() as f64 * TICK_PX * 0.64).fold(0.0, f64::max);
    // Tick mark and gap, then the description's line and a margin.
    (widest + 12.0 + AXIS_DESC_PX * 1.4 + 8.0).ceil().max(48.0) as u32
}

/// [`label_area_for`] the ticks plotters puts on a linear axis over `range` (`labels` of
/// them) formatted by `fmt`.
pub fn y_label_area(range: Range<f64>, labels: usize, fmt: &dyn Fn(&f64) -> String) -> u32 {
    label_area_for(RangedCoordf64::from(range).key_points(labels).iter().map(fmt))
}

/// Compact number for a cost or speed: 3 significant digits, scientific when very large/small.
pub fn fmt_sig(v: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if !(1e-3..1e5).contains(&a) {
        let s = format!("{v:.1e}");
        s.replace(".0e", "e")
    } else {
        let decimals = (2.0 - a.log10().floor()).clamp(0.0, 5.0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    }
}

/// What a legend entry shows next to its label.
#[derive(Clone, Debug)]
pub enum Swatch {
    Line {
        color: RGBAColor,
        width: u32,
    },
    Dashed(RGBAColor),
    /// A path: line with a waypoint dot.
    Path(RGBColor),
    Fill {
        color: RGBAColor,
        edge: Option<RGBColor>,
    },
    Marker(Marker, RGBColor),
    Arrow(RGBColor),
    /// An arrow `len_px` long: the scale of the current arrows (wider than other swatches).
    ScaledArrow {
        color: RGBColor,
        len_px: i32,
    },
    /// A kind of obstacle.
    Obstacle(super::obstacle_look::ObstacleLook),
    /// A hollow ring: a marked waypoint or place.
    Ring(RGBColor),
    /// A wide translucent band: a highlighted segment.
    Band(RGBAColor),
    /// A dashed path line (the reference path).
    DashedPath(RGBColor),
    /// A line over a band of its own colour: a median with its interquartile range.
    LineOverBand(RGBColor),
    /// A hollow diamond: a marked point of a curve.
    Diamond(RGBColor),
    /// Waypoints a vehicle with a turning radius does not pass through: small hollow markers
    /// on a thin dashed line.
    Waypoints(RGBColor),
    /// A time tick: a short bar across a line.
    Tick(RGBColor),
    /// A path coloured along its length (by speed over ground): these colours in turn, with
    /// a dark outline.
    Ramp(Vec<RGBColor>),
}

impl Swatch {
    /// Pixels the swatch takes in a legend row.
    fn width(&self) -> f64 {
        match self {
            Swatch::ScaledArrow { len_px, .. } => (*len_px as f64 + 4.0).max(SWATCH_W),
            _ => SWATCH_W,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    Triangle,
    Star,
}

#[derive(Clone, Debug)]
pub struct LegendEntry {
    pub label: String,
    pub swatch: Swatch,
}

impl LegendEntry {
    pub fn new(label: impl Into<String>, swatch: Swatch) -> Self {
        Self { label: label.into(), swatch }
    }
}

const SWATCH_W: f64 = 26.0;
const ROW_H: f64 = 20.0;
const GAP: f64 = 18.0;

/// Places entries left to right, wrapping at `width`; returns (x, row) per entry and rows used.
fn legend_layout(entries: &[LegendEntry], width: f64) -> (Vec<(f64, usize)>, usize) {
    let mut out = Vec::with_capacity(entries.len());
    let (mut x, mut row) = (0.0, 0usize);
    for e in entries {
        let w = e.swatch.width() + 6.0 + text_width(&e.label, LEGEND_PX);
        if x > 0.0 && x + w > width {
            x = 0.0;
            row += 1;
        }
        out.push((x, row));
        x += w + GAP;
    }
    let rows = if entries.is_empty() { 0 } else { row + 1 };
    (out, rows)
}

/// Height a legend of `entries` needs when wrapped at `width` pixels.
pub fn legend_height(entries: &[LegendEntry], width: u32) -> u32 {
    let (_, rows) = legend_layout(entries, width as f64);
    (rows as f64 * ROW_H).ceil() as u32 + if rows > 0 { 6 } else { 0 }
}

/// Draws the legend at the top-left of `area`, wrapped at its width.
pub fn draw_legend<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, entries: &[LegendEntry]) -> Result<()> {
    let (w, _) = area.dim_in_pixel();
    let (pos, _) = legend_layout(entries, w as f64);
    let text = font(LEGEND_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (e, (x, row)) in entries.iter().zip(pos) {
        let cy = (row as f64 * ROW_H + ROW_H / 2.0 + 3.0).round() as i32;
        let x0 = x.round() as i32;
        let x1 = x0 + e.swatch.width() as i32;
        let xm = (x0 + x1) / 2;
        match &e.swatch {
            Swatch::Line { color, width } => {
                area.draw(&PathElement::new(vec![(x0, cy), (x1, cy)], line(*color, *width))).map_err(plot_err)?;
            }
            Swatch::Dashed(c) => {
                for k in 0..3 {
                    let xa = x0 + k * 10;
                    area.draw(&PathElement::new(vec![(xa, cy), (xa + 6, cy)], line(*c, 1))).map_err(plot_err)?;
                }
            }
            Swatch::Path(c) => {
                area.draw(&PathElement::new(vec![(x0, cy), (x1, cy)], line(*c, 3))).map_err(plot_err)?;
                area.draw(&Circle::new((xm, cy), 3, fill(*c))).map_err(plot_err)?;
            }
            Swatch::Fill { color, edge } => {
                area.draw(&Rectangle::new([(x0 + 2, cy - 6), (x1 - 2, cy + 6)], fill(*color))).map_err(plot_err)?;
                if let Some(edge) = edge {
                    area.draw(&Rectangle::new([(x0 + 2, cy - 6), (x1 - 2, cy + 6)], line(*edge, 1)))
                        .map_err(plot_err)?;
                }
            }
            Swatch::Marker(m, c) => draw_marker(area, (xm, cy), *m, *c)?,
            Swatch::Arrow(c) => draw_arrow_px(area, (x0 + 2, cy), (x1 - 2, cy), *c, 1)?,
            Swatch::ScaledArrow { color, len_px } => {
                draw_arrow_px(area, (x0 + 2, cy), (x0 + 2 + len_px, cy), color.mix(0.8), 1)?
            }
            Swatch::Obstacle(look) => super::obstacle_look::draw_swatch(area, (xm, cy), *look)?,
            Swatch::Ring(c) => {
                area.draw(&Circle::new((xm, cy), 7, line(*c, 2))).map_err(plot_err)?;
            }
            Swatch::Band(c) => {
                area.draw(&PathElement::new(vec![(x0, cy), (x1, cy)], line(*c, 10))).map_err(plot_err)?;
            }
            Swatch::DashedPath(c) => {
                for k in 0..3 {
                    let xa = x0 + k * 10;
                    area.draw(&PathElement::new(vec![(xa, cy), (xa + 6, cy)], line(*c, 3))).map_err(plot_err)?;
                }
            }
            Swatch::LineOverBand(c) => {
                area.draw(&Rectangle::new([(x0, cy - 6), (x1, cy + 6)], fill(c.mix(0.2)))).map_err(plot_err)?;
                area.draw(&PathElement::new(vec![(x0, cy), (x1, cy)], line(*c, 2))).map_err(plot_err)?;
            }
            Swatch::Diamond(c) => draw_diamond(area, (xm, cy), *c)?,
            Swatch::Tick(c) => {
                area.draw(&PathElement::new(vec![(x0, cy), (x1, cy)], line(c.mix(0.6), 2))).map_err(plot_err)?;
                area.draw(&PathElement::new(vec![(xm, cy - 6), (xm, cy + 6)], line(*c, 2))).map_err(plot_err)?;
            }
            Swatch::Ramp(colors) => {
                area.draw(&PathElement::new(vec![(x0, cy), (x1, cy)], line(SPEED_OUTLINE, 6))).map_err(plot_err)?;
                let n = colors.len().max(1) as i32;
                for (k, c) in colors.iter().enumerate() {
                    let (a, b) = (x0 + (x1 - x0) * k as i32 / n, x0 + (x1 - x0) * (k as i32 + 1) / n);
                    area.draw(&PathElement::new(vec![(a, cy), (b, cy)], line(*c, 4))).map_err(plot_err)?;
                }
            }
            Swatch::Waypoints(c) => {
                for k in 0..3 {
                    let xa = x0 + k * 9;
                    area.draw(&PathElement::new(vec![(xa, cy), (xa + 5, cy)], line(*c, 1))).map_err(plot_err)?;
                }
                for x in [x0 + 3, x1 - 3] {
                    area.draw(&Circle::new((x, cy), 3, fill(WHITE))).map_err(plot_err)?;
                    area.draw(&Circle::new((x, cy), 3, line(*c, 1))).map_err(plot_err)?;
                }
            }
        }
        area.draw(&Text::new(e.label.clone(), (x1 + 6, cy), text.clone())).map_err(plot_err)?;
    }
    Ok(())
}

/// A start/goal marker centred on a pixel position of `area`.
pub fn draw_marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x, y): (i32, i32),
    marker: Marker,
    color: RGBColor,
) -> Result<()> {
    let pts: Vec<(i32, i32)> = match marker {
        Marker::Triangle => vec![(x, y - 8), (x + 8, y + 6), (x - 8, y + 6)],
        Marker::Star => (0..10)
            .map(|k| {
                let r = if k % 2 == 0 { 10.0 } else { 4.2 };
                let a = std::f64::consts::PI * (k as f64 / 5.0 - 0.5);
                (x + (r * a.cos()).round() as i32, y + (r * a.sin()).round() as i32)
            })
            .collect(),
    };
    area.draw(&Polygon::new(pts.clone(), fill(color))).map_err(plot_err)?;
    let mut outline = pts;
    outline.push(outline[0]);
    area.draw(&PathElement::new(outline, line(BLACK, 1))).map_err(plot_err)?;
    Ok(())
}

/// A hollow diamond 7 pixels from centre to corner, on white so it stands out on a line.
pub fn draw_diamond<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x, y): (i32, i32),
    color: RGBColor,
) -> Result<()> {
    let pts = vec![(x, y - 7), (x + 7, y), (x, y + 7), (x - 7, y), (x, y - 7)];
    area.draw(&Polygon::new(pts.clone(), fill(WHITE))).map_err(plot_err)?;
    area.draw(&PathElement::new(pts, line(color, 2))).map_err(plot_err)?;
    Ok(())
}

/// An arrow between two pixel positions, with a head scaled to its length.
pub fn draw_arrow_px<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    from: (i32, i32),
    to: (i32, i32),
    color: impl Color,
    width: u32,
) -> Result<()> {
    let style = line(color.to_rgba(), width);
    let Some(head) = arrow_head(from, to) else { return Ok(()) };
    area.draw(&PathElement::new(vec![from, to], style)).map_err(plot_err)?;
    area.draw(&Polygon::new(head.to_vec(), ShapeStyle { filled: true, ..style })).map_err(plot_err)?;
    Ok(())
}

/// The corners of the head of an arrow from `from` to `to` (its tip first), scaled to its
/// length; `None` for an arrow shorter than a pixel.
fn arrow_head(from: (i32, i32), to: (i32, i32)) -> Option<[(i32, i32); 3]> {
    let (dx, dy) = ((to.0 - from.0) as f64, (to.1 - from.1) as f64);
    let len = (dx * dx + dy * dy).sqrt();
    if len < 1.0 {
        return None;
    }
    let head = (len * 0.35).clamp(3.0, 7.0);
    let (ux, uy) = (dx / len, dy / len);
    let side = |s: f64| {
        let (hx, hy) = (-ux * head + s * -uy * head * 0.55, -uy * head + s * ux * head * 0.55);
        (to.0 + hx.round() as i32, to.1 + hy.round() as i32)
    };
    Some([to, side(1.0), side(-1.0)])
}

/// A pale outline `width` pixels wide around the arrow [`draw_arrow_px`] draws from `from`
/// to `to`, drawn first so a dark arrow stays readable over dark colours.
pub fn draw_arrow_halo_px<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    from: (i32, i32),
    to: (i32, i32),
    color: impl Color,
    width: u32,
) -> Result<()> {
    let Some([tip, a, b]) = arrow_head(from, to) else { return Ok(()) };
    let style = line(color.to_rgba(), width);
    area.draw(&PathElement::new(vec![from, to], style)).map_err(plot_err)?;
    area.draw(&PathElement::new(vec![tip, a, b, tip, a], style)).map_err(plot_err)?;
    Ok(())
}

/// Draws a panel caption centred in the top `CAPTION_H` pixels and returns the area below it.
pub fn caption<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, text: &str) -> Result<DrawingArea<DB, Shift>> {
    let (w, _) = area.dim_in_pixel();
    let style = bold(CAPTION_PX).pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(text.to_string(), (w as i32 / 2, CAPTION_H as i32 / 2), style)).map_err(plot_err)?;
    Ok(area.split_vertically(CAPTION_H).1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_levels_are_round_and_inside() {
        let (levels, step) = nice_levels(-900.0, -150.0, 8);
        assert_eq!(step, 100.0);
        assert_eq!(levels, vec![-800.0, -700.0, -600.0, -500.0, -400.0, -300.0, -200.0]);
    }

    #[test]
    fn numbers_format_without_noise() {
        assert_eq!(fmt_num(-0.0001, 1.0), "0");
        assert_eq!(fmt_num(2.5, 0.5), "2.5");
        assert_eq!(fmt_num(1200.0, 100.0), "1200");
        assert_eq!(fmt_sig(1.2345), "1.23");
        assert_eq!(fmt_sig(123456.0), "1.2e5");
        assert_eq!(fmt_sig(0.5), "0.5");
        assert_eq!(fmt_num(0.30000000000000004, 0.1), "0.3");
        let f = tick_formatter(3.6..4.4, 7);
        assert_eq!((f(&3.8), f(&4.0)), ("3.8".to_string(), "4.0".to_string()));
    }

    #[test]
    fn legend_wraps_long_lists() {
        let entries: Vec<_> =
            (0..10).map(|i| LegendEntry::new(format!("planner number {i}"), Swatch::Path(path_color(i)))).collect();
        assert!(legend_height(&entries, 400) > legend_height(&entries[..1], 400));
    }
}

/// Which of a sequence of screen points to mark so that marks stay at least `min_px` pixels
/// apart (the first and the last are always marked): dense waypoints, such as a Dubins curve's
/// tangent polygon, would otherwise pile into a solid band of rings.
pub fn spaced_marks(px: &[(i32, i32)], min_px: i32) -> Vec<bool> {
    let mut keep = vec![false; px.len()];
    let mut last: Option<(i32, i32)> = None;
    for (i, &q) in px.iter().enumerate() {
        let far = last.is_none_or(|l| {
            let (dx, dy) = (i64::from(q.0 - l.0), i64::from(q.1 - l.1));
            dx * dx + dy * dy >= i64::from(min_px) * i64::from(min_px)
        });
        if far || i + 1 == px.len() {
            keep[i] = true;
            last = Some(q);
        }
    }
    keep
}

/// Least distance (px) between two waypoint marks on a flown curve.
pub const MARK_SPACING_PX: i32 = 9;

#[cfg(test)]
mod spacing_tests {
    use super::spaced_marks;

    #[test]
    fn marks_keep_their_distance_and_the_ends() {
        let px = [(0, 0), (3, 0), (6, 0), (9, 0), (10, 0), (30, 0), (31, 1)];
        assert_eq!(spaced_marks(&px, 9), [true, false, false, true, false, true, true]);
        assert_eq!(spaced_marks(&[], 9), Vec::<bool>::new());
        assert_eq!(spaced_marks(&[(5, 5)], 9), [true]);
    }
}
