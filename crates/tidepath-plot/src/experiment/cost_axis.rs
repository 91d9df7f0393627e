//! The cost axis of the convergence and box plot figures: linear, or log10 with zeros on their
//! own line below a break in the axis.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::convergence::wants_log_scale;
use super::super::log_axis::{self, Decades};
use super::super::style::{self, plot_err};
use tidepath::error::Result;

/// How a cost axis maps values: linear, or log10 labelled at `decades`, with zeros drawn on
/// their own line at `zero_at`, a decade or more below the lowest labelled one and separated
/// from it by an axis break.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum CostAxis {
    Linear { lo: f64, hi: f64 },
    Log { lo: f64, hi: f64, zero_at: Option<f64>, decades: Decades },
}

impl CostAxis {
    /// The axis for `values` (non-finite ones ignored); `None` when no value is finite.
    pub(super) fn for_values(values: impl IntoIterator<Item = f64>) -> Option<Self> {
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
    pub(super) fn map(&self, v: f64) -> f64 {
        match *self {
            CostAxis::Log { zero_at: Some(z), .. } if v == 0.0 => z,
            _ => v,
        }
    }

    pub(super) fn zero_at(&self) -> Option<f64> {
        match *self {
            CostAxis::Log { zero_at, .. } => zero_at,
            CostAxis::Linear { .. } => None,
        }
    }

    /// The zero line and the lowest labelled decade above it, between which the axis breaks.
    pub(super) fn zero_gap(&self) -> Option<(f64, f64)> {
        match *self {
            CostAxis::Log { zero_at: Some(z), decades, .. } => Some((z, decades.lo())),
            _ => None,
        }
    }

    pub(super) fn desc(&self, what: &str) -> String {
        match *self {
            CostAxis::Linear { .. } => what.to_string(),
            CostAxis::Log { zero_at: None, .. } => format!("{what} (log scale)"),
            CostAxis::Log { zero_at: Some(_), .. } => format!("{what} (log scale, 0 below break)"),
        }
    }

    /// Tick labels: powers of ten from 1e4 up as "1e4" rather than "10000", so labels of a
    /// many-decade axis have similar widths ([`log_axis::label`]); the zero line's tick is
    /// labelled by [`draw_zero_tick`] instead.
    pub(super) fn tick_label(&self, v: f64) -> String {
        if self.zero_at().is_some_and(|z| v < z * 3.0) {
            return String::new();
        }
        log_axis::label(v)
    }
}

/// Labels the zero line of a log axis "0" and breaks the y axis above it, since the distance
/// from 0 to the smallest positive cost is not to scale. `axis_x` and `zero_y` are pixels of
/// `area`: the plot's left edge and the zero line.
pub(super) fn draw_zero_tick<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    axis_x: i32,
    zero_y: i32,
    gap: i32,
) -> Result<()> {
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
