//! Colour bars beside or under the map: the seabed's shading and, for a plan in a current, the
//! path's speed over ground. One drawing for both, so they read alike.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::style::{self, plot_err};
use tidepath::error::Result;

/// A colour bar from `lo` to `hi`, labelled at `ticks`.
pub(crate) struct ColourBar {
    pub(crate) title: String,
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    /// The spacing of the ticks: labels' decimals, and how many labels fit.
    pub(crate) step: f64,
    pub(crate) ticks: Vec<f64>,
    /// A tick whose label is always drawn, even where labels are thinned (the coastline).
    pub(crate) always: Option<f64>,
    /// A value marked across the bar with a heavy line (a vehicle's speed through still
    /// water, where the current neither helps nor hinders).
    pub(crate) mark: Option<f64>,
    pub(crate) colour: Box<dyn Fn(f64) -> RGBColor>,
}

impl ColourBar {
    /// How many ticks to skip between labels so labels stay `min_gap` pixels apart on a bar
    /// of `len` pixels.
    fn label_every(&self, len: f64, min_gap: f64) -> usize {
        let span = self.hi - self.lo;
        let px_per_step = if span > 0.0 { len * self.step / span } else { len };
        (min_gap / px_per_step).ceil().max(1.0) as usize
    }

    fn labelled(&self, k: usize, every: usize, v: f64) -> bool {
        k % every == 0 || self.always == Some(v)
    }

    /// Pixel runs [k0, k1) of one colour along the bar `len` pixels long, where pixel k
    /// shows the value `v_at((k + 0.5) / len)`; runs keep the bar to a few dozen SVG elements.
    fn gradient_runs(&self, len: u32, v_at: impl Fn(f64) -> f64) -> Vec<(i32, i32, RGBColor)> {
        let n = len.max(2) as i32;
        let mut runs: Vec<(i32, i32, RGBColor)> = Vec::new();
        for k in 0..n {
            let c = (self.colour)(v_at((k as f64 + 0.5) / n as f64));
            match runs.last_mut() {
                Some(last) if last.2 == c => last.1 = k + 1,
                _ => runs.push((k, k + 1, c)),
            }
        }
        runs
    }

    /// The mark, when it is on the bar.
    fn mark_on_bar(&self) -> Option<f64> {
        self.mark.filter(|m| m.is_finite() && *m >= self.lo && *m <= self.hi)
    }
}

/// Vertical colour bar filling the height of `area`, labelled at its ticks, its title rotated
/// beside it.
pub(crate) fn draw_vertical<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, b: &ColourBar) -> Result<()> {
    let (_, h) = area.dim_in_pixel();
    let (bar_x0, bar_x1) = (0i32, 16i32);
    let span = b.hi - b.lo;
    let y_of = |v: f64| -> i32 {
        if span > 0.0 {
            ((b.hi - v) / span * (h as f64 - 1.0)).round() as i32
        } else {
            h as i32 / 2
        }
    };
    for (k0, k1, c) in b.gradient_runs(h, |t| b.hi - span * t) {
        area.draw(&Rectangle::new([(bar_x0, k0), (bar_x1, k1)], style::fill(c))).map_err(plot_err)?;
    }
    area.draw(&Rectangle::new([(bar_x0, 0), (bar_x1, h as i32 - 1)], style::line(BLACK, 1))).map_err(plot_err)?;
    let every = b.label_every(h as f64, 16.0);
    let label = style::font(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (k, &v) in b.ticks.iter().enumerate() {
        let y = y_of(v);
        area.draw(&PathElement::new(vec![(bar_x0, y), (bar_x1 + 3, y)], style::line(BLACK.mix(0.7), 1)))
            .map_err(plot_err)?;
        if b.labelled(k, every, v) {
            area.draw(&Text::new(style::fmt_num(v, b.step), (bar_x1 + 6, y), label.clone())).map_err(plot_err)?;
        }
    }
    if let Some(m) = b.mark_on_bar() {
        let y = y_of(m);
        area.draw(&PathElement::new(vec![(bar_x0 - 4, y), (bar_x1 + 4, y)], style::line(WHITE, 5)))
            .map_err(plot_err)?;
        area.draw(&PathElement::new(vec![(bar_x0 - 4, y), (bar_x1 + 4, y)], style::line(BLACK, 2)))
            .map_err(plot_err)?;
    }
    let title =
        style::font(style::AXIS_DESC_PX).pos(Pos::new(HPos::Center, VPos::Center)).transform(FontTransform::Rotate270);
    area.draw(&Text::new(b.title.clone(), (bar_x1 + 70, h as i32 / 2), title)).map_err(plot_err)?;
    Ok(())
}

/// Horizontal colour bar `bar_w` pixels long with labels under it and its title to the right.
pub(crate) fn draw_horizontal<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    b: &ColourBar,
    bar_w: u32,
) -> Result<()> {
    let (bar_y0, bar_y1) = (10i32, 24i32);
    let span = b.hi - b.lo;
    let x_of = |v: f64| -> i32 {
        if span > 0.0 {
            ((v - b.lo) / span * (bar_w as f64 - 1.0)).round() as i32
        } else {
            bar_w as i32 / 2
        }
    };
    for (k0, k1, c) in b.gradient_runs(bar_w, |t| b.lo + span * t) {
        area.draw(&Rectangle::new([(k0, bar_y0), (k1, bar_y1)], style::fill(c))).map_err(plot_err)?;
    }
    area.draw(&Rectangle::new([(0, bar_y0), (bar_w as i32 - 1, bar_y1)], style::line(BLACK, 1))).map_err(plot_err)?;
    let widest = b.ticks.iter().map(|&v| style::fmt_num(v, b.step).len()).max().unwrap_or(1);
    let every = b.label_every(bar_w as f64, style::text_width(&"0".repeat(widest), style::TICK_PX) + 10.0);
    let label = style::font(style::TICK_PX).pos(Pos::new(HPos::Center, VPos::Top));
    for (k, &v) in b.ticks.iter().enumerate() {
        let x = x_of(v);
        area.draw(&PathElement::new(vec![(x, bar_y0), (x, bar_y1 + 3)], style::line(BLACK.mix(0.7), 1)))
            .map_err(plot_err)?;
        if b.labelled(k, every, v) {
            area.draw(&Text::new(style::fmt_num(v, b.step), (x, bar_y1 + 5), label.clone())).map_err(plot_err)?;
        }
    }
    if let Some(m) = b.mark_on_bar() {
        let x = x_of(m);
        area.draw(&PathElement::new(vec![(x, bar_y0 - 4), (x, bar_y1 + 4)], style::line(WHITE, 5)))
            .map_err(plot_err)?;
        area.draw(&PathElement::new(vec![(x, bar_y0 - 4), (x, bar_y1 + 4)], style::line(BLACK, 2)))
            .map_err(plot_err)?;
    }
    let title = style::font(style::AXIS_DESC_PX).pos(Pos::new(HPos::Left, VPos::Center));
    area.draw(&Text::new(b.title.clone(), (bar_w as i32 + 14, (bar_y0 + bar_y1) / 2), title)).map_err(plot_err)?;
    Ok(())
}
