//! A plan's path coloured by its speed over ground: in a current the vehicle's speed over
//! the seabed is its speed through the water plus the current, so the colours show where the
//! current helps (fast) and where it hinders (slow). The speed of each segment of the drawn
//! line (the flown curve when there is one) is its length (horizontal and vertical) over the
//! time between its ends on the path's own clock.
//!
//! The clock is the validator's (the plan's arrival times), not the through-water speed plus
//! the current, so the colouring holds for any propulsion: a wave glider's speed over ground
//! follows the waves and the current (acopf2016 eqs. 1-2) and shows the same way. A glider has
//! no speed through still water, so its bar has no mark.

use plotters::prelude::*;

use super::super::flown::Drawn;
use super::super::style::{self, plot_err, LegendEntry, Swatch};
use super::super::PlanFigure;
use super::colorbar::ColourBar;
use super::overlays::to_px;
use super::Chart;
use tidepath::error::Result;
use tidepath::geom::Vec3;
use tidepath::world::Current;

/// Multiples of a step of 1, 2 or 5 times a power of ten strictly inside (lo, hi), about five
/// of them, and the step (not 2.5, whose labels would need one more decimal than the step).
pub(super) fn round_ticks(lo: f64, hi: f64) -> (Vec<f64>, f64) {
    let step = style::nice_step(hi - lo, 5);
    let mag = 10f64.powf(step.log10().floor());
    let step = if (step / mag - 2.5).abs() < 1e-9 { 2.0 * mag } else { step };
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return (Vec::new(), step);
    }
    let ticks = ((lo / step).floor() as i64 + 1..).map(|k| k as f64 * step).take_while(|&v| v < hi).filter(|&v| v > lo);
    (ticks.collect(), step)
}

/// Ticks of a colour bar from `lo` to `hi` and the step their labels are written at: round
/// values ([`round_ticks`]), or the ends when the range holds fewer than two.
pub(super) fn bar_ticks(lo: f64, hi: f64) -> (Vec<f64>, f64) {
    let (ticks, step) = round_ticks(lo, hi);
    if ticks.len() >= 2 {
        return (ticks, step);
    }
    // Three significant digits: "1.54", not a step's worth of decimals of a range too narrow
    // for round values.
    let ends = if hi > lo { vec![lo, hi] } else { vec![lo] };
    (ends, 10f64.powf(hi.abs().max(1e-9).log10().floor() - 2.0))
}

/// The path coloured by speed: its drawn line and each segment's speed over ground.
pub(crate) struct SpeedPath<'a> {
    /// Which of the figure's paths it is.
    pub(crate) index: usize,
    pub(crate) line: &'a [Vec3],
    /// Whether `line` is a flown curve rather than the waypoints.
    pub(crate) flown: bool,
    /// The path's waypoints (`line` unless flown).
    pub(crate) waypoints: &'a [Vec3],
    /// Speed over ground (m/s) of segment k (`line[k]` to `line[k + 1]`); NaN where the times
    /// do not give one (a segment of no duration).
    pub(crate) speeds: Vec<f64>,
    /// The slowest and fastest segment.
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    /// The vehicle's speed through still water, when it has one.
    pub(crate) still_water: Option<f64>,
}

/// Speed over ground of each segment of `line`, from the arrival `times` at its points.
pub(crate) fn segment_speeds(line: &[Vec3], times: &[f64]) -> Vec<f64> {
    line.windows(2)
        .zip(times.windows(2))
        .map(|(q, t)| {
            let (d, dt) = (q[0].distance(q[1]), t[1] - t[0]);
            let v = d / dt;
            if dt > 0.0 && v.is_finite() {
                v
            } else {
                f64::NAN
            }
        })
        .collect()
}

impl<'a> SpeedPath<'a> {
    /// The path `fig.speed_path` names, when the world has a current or waves (which set a
    /// wave glider's speed) and the path's drawn line is finite and has a time at every point
    /// giving at least one speed.
    pub(crate) fn of(fig: &PlanFigure<'a>) -> Option<Self> {
        let index = fig.speed_path?;
        if matches!(fig.world.current, Current::None) && fig.world.waves.is_none() {
            return None;
        }
        let path = fig.paths.get(index)?;
        let drawn = Drawn::of(path);
        let (line, times) = (drawn.line, drawn.times);
        if line.len() < 2 || times.len() != line.len() || !line.iter().all(|q| q.x.is_finite() && q.y.is_finite()) {
            return None;
        }
        let speeds = segment_speeds(line, times);
        let finite = speeds.iter().copied().filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
        if lo > hi {
            return None;
        }
        Some(Self {
            index,
            line,
            flown: drawn.flown,
            waypoints: path.points,
            speeds,
            lo,
            hi,
            still_water: fig.still_water_speed.filter(|v| v.is_finite()),
        })
    }

    pub(crate) fn color(&self, v: f64) -> RGBColor {
        if v.is_finite() {
            style::speed_color(v, self.lo, self.hi)
        } else {
            style::MUTED
        }
    }

    /// The colour bar: the path's range of speeds, labelled at round values (its ends when
    /// the range holds fewer than two), the still-water speed marked.
    pub(crate) fn colour_bar(&self) -> ColourBar {
        let (lo, hi) = (self.lo, self.hi);
        let (ticks, step) = bar_ticks(lo, hi);
        ColourBar {
            title: "speed over ground (m/s)".to_string(),
            lo,
            hi,
            step,
            ticks,
            always: None,
            mark: self.still_water,
            colour: Box::new(move |v| style::speed_color(v, lo, hi)),
        }
    }

    /// The legend entry of the path, in place of its plain one.
    pub(crate) fn legend_label(&self, label: &str) -> LegendEntry {
        let mut text = format!("{label}, coloured by speed over ground");
        if let Some(v) = self.still_water {
            let v_text = style::fmt_sig(v);
            text.push_str(&if v < self.lo {
                format!(" (faster throughout than its {v_text} m/s through still water)")
            } else if v > self.hi {
                format!(" (slower throughout than its {v_text} m/s through still water)")
            } else {
                format!(" (mark on the bar: {v_text} m/s, through still water)")
            });
        }
        let (lo, hi) = (self.lo, self.hi);
        let ramp = (0..4).map(|k| style::speed_color(lo + (hi - lo) * (k as f64 + 0.5) / 4.0, lo, hi)).collect();
        LegendEntry::new(text, Swatch::Ramp(ramp))
    }
}

/// The path's line with a dark outline and a pale halo, each run of segments of one colour one SVG element.
/// Drawn in pixels, with points closer than two pixels to the last one kept left out: a dense
/// line (a smoothed path's samples) rounded to whole pixels would otherwise zigzag, and its
/// outline's joins spike.
pub(crate) fn draw_speed_path<DB: DrawingBackend>(chart: &Chart<DB>, sp: &SpeedPath, u: f64) -> Result<()> {
    let px = chart.plotting_area().strip_coord_spec();
    // (pixel, colour of the segment ending there) of the kept points.
    let mut kept: Vec<((i32, i32), RGBColor)> = Vec::with_capacity(sp.line.len());
    for (k, q) in sp.line.iter().enumerate() {
        let p = to_px(chart, q.x / u, q.y / u);
        let c = if k == 0 { sp.color(sp.speeds[0]) } else { sp.color(sp.speeds[k - 1]) };
        match kept.last() {
            Some(&(last, _)) if k + 1 < sp.line.len() && (p.0 - last.0).pow(2) + (p.1 - last.1).pow(2) < 4 => {}
            // The last point always ends the line, in place of a close one before it.
            Some(&(last, _)) if k + 1 == sp.line.len() && kept.len() > 1 && last == p => {}
            _ => kept.push((p, c)),
        }
    }
    if kept.len() < 2 {
        return Ok(());
    }
    let pts: Vec<(i32, i32)> = kept.iter().map(|&(p, _)| p).collect();
    // A pale halo outside the dark outline: dark red on deep water still stands out.
    px.draw(&PathElement::new(pts.clone(), style::line(WHITE.mix(0.7), 8))).map_err(plot_err)?;
    px.draw(&PathElement::new(pts.clone(), style::line(style::SPEED_OUTLINE, 6))).map_err(plot_err)?;
    // Segment j runs from point j to j + 1 and takes the colour of point j + 1.
    let mut j = 0;
    while j + 1 < kept.len() {
        let c = kept[j + 1].1;
        let mut end = j + 1;
        while end + 1 < kept.len() && kept[end + 1].1 == c {
            end += 1;
        }
        px.draw(&PathElement::new(pts[j..=end].to_vec(), style::line(c, 4))).map_err(plot_err)?;
        j = end;
    }
    if sp.flown {
        // The waypoints of a flown curve, as on any flown path: rings a few pixels apart.
        let color = style::path_color(sp.index);
        let way: Vec<(i32, i32)> = sp
            .waypoints
            .iter()
            .filter(|q| q.x.is_finite() && q.y.is_finite())
            .map(|q| to_px(chart, q.x / u, q.y / u))
            .collect();
        for (&c, mark) in way.iter().zip(style::spaced_marks(&way, style::MARK_SPACING_PX)) {
            if mark {
                px.draw(&Circle::new(c, 3, style::fill(WHITE))).map_err(plot_err)?;
                px.draw(&Circle::new(c, 3, style::line(color, 1))).map_err(plot_err)?;
            }
        }
        return Ok(());
    }
    // Waypoints a reader can tell apart (on average at least 15 pixels apart) are marked; a
    // smoothed path's dense samples are not.
    let length: f64 = pts.windows(2).map(|w| f64::from(w[1].0 - w[0].0).hypot(f64::from(w[1].1 - w[0].1))).sum();
    if length >= 15.0 * (sp.line.len() - 1) as f64 {
        for q in sp.line {
            let c = to_px(chart, q.x / u, q.y / u);
            px.draw(&Circle::new(c, 3, style::fill(WHITE))).map_err(plot_err)?;
            px.draw(&Circle::new(c, 3, style::line(style::SPEED_OUTLINE, 1))).map_err(plot_err)?;
        }
    }
    Ok(())
}
