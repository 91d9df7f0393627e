//! Log10 axes labelled at whole decades over their whole range.
//!
//! plotters' own log axis drops every key point below about 2.2e-16 (it mistakes them for its
//! zero point), so a cost axis reaching 1e-28 was labelled only down to 1e-12, and it picks
//! its decades without regard to the ends of the axis, which then often go unlabelled.
//! [`Decades`] chooses a decade step giving at most eight labels, with a label at both ends of
//! the axis, and [`DecadeAxis`] is the plotters coordinate that puts the ticks, their labels
//! and the grid lines there.

use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;

/// Decade steps tried; a span is labelled with the step that needs the least padding, the
/// smallest of those on a tie.
const STEPS: [i32; 24] =
    [1, 2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 25, 30, 40, 50, 60, 80, 100, 120, 150, 200, 250, 300, 400];
/// Fewest and most labels on one axis (fewer only when the axis has fewer decades): panels
/// are about 250 pixels high.
const MIN_LABELS: i32 = 4;
const MAX_LABELS: i32 = 8;
/// Decades of the values an axis is laid out for; costs beyond are drawn at its edge.
const MIN_EXP: i32 = -300;
const MAX_EXP: i32 = 300;
/// Decades an axis may reach when rounded out to its step: still positive and finite f64s.
const MIN_AXIS_EXP: i32 = -320;
const MAX_AXIS_EXP: i32 = 308;

/// The decades of a log axis: it runs from 10^`bottom` to 10^`top`, labelled every `step`
/// decades, so both ends carry a label.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Decades {
    pub bottom: i32,
    pub top: i32,
    pub step: i32,
}

impl Decades {
    /// The axis over the decades from 10^`lo` to 10^`hi`: labels on the multiples of a step
    /// (so 1 = 10^0 is labelled whenever it is shown), four to eight of them, with both ends
    /// rounded out to a label, choosing the step that adds the fewest decades.
    pub fn covering(lo: i32, hi: i32) -> Self {
        let lo = lo.clamp(MIN_EXP, MAX_EXP - 1);
        let hi = hi.clamp(lo + 1, MAX_EXP);
        let aligned =
            |step: i32| Decades { bottom: lo.div_euclid(step) * step, top: -(-hi).div_euclid(step) * step, step };
        STEPS
            .iter()
            .map(|&step| aligned(step))
            .filter(|d| {
                let enough = d.labels() >= MIN_LABELS.min(hi - lo + 1);
                enough && d.labels() <= MAX_LABELS && d.bottom >= MIN_AXIS_EXP && d.top <= MAX_AXIS_EXP
            })
            .min_by_key(|d| (d.top - d.bottom, d.step))
            .unwrap_or_else(|| {
                // Unreachable for spans within [MIN_EXP, MAX_EXP]; kept total regardless.
                let step = (hi - lo + MAX_LABELS - 2) / (MAX_LABELS - 1);
                Decades { bottom: lo, top: lo + step * (MAX_LABELS - 1), step }
            })
    }

    fn labels(&self) -> i32 {
        (self.top - self.bottom) / self.step + 1
    }

    /// The axis for positive values from `min` to `max`: from the decade at or below `min` to
    /// the one at or above `max`. `None` unless both are finite and positive.
    pub fn for_values(min: f64, max: f64) -> Option<Self> {
        if !(min.is_finite() && max.is_finite() && min > 0.0 && max > 0.0) {
            return None;
        }
        let (min, max) = (min.min(max), min.max(max));
        // The nudge keeps 1e-28, computed as 10^-28.000000000000004, in its own decade.
        let lo = (min.log10() + 1e-9).floor() as i32;
        let hi = (max.log10() - 1e-9).ceil() as i32;
        Some(Self::covering(lo, hi))
    }

    /// Exponents of the labelled decades, from the bottom up.
    pub fn exponents(&self) -> Vec<i32> {
        (self.bottom..=self.top).step_by(self.step.max(1) as usize).collect()
    }

    pub fn lo(&self) -> f64 {
        pow10(self.bottom)
    }

    pub fn hi(&self) -> f64 {
        pow10(self.top)
    }
}

/// 10^`e`, exactly as the literal "1e`e`" reads.
pub fn pow10(e: i32) -> f64 {
    format!("1e{e}").parse().unwrap_or_else(|_| 10f64.powi(e))
}

/// Label of a tick at `v`: plain numbers from 0.001 to 1000, "1e4" and "1e-4" beyond, so the
/// labels of a many-decade axis have similar widths.
pub fn label(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || !a.is_finite() || (1e-3..9_999.5).contains(&a) {
        return super::style::fmt_sig(v);
    }
    let e = a.log10().round();
    if (a / 10f64.powf(e) - 1.0).abs() < 1e-6 {
        format!("{}1e{e}", if v < 0.0 { "-" } else { "" })
    } else {
        super::style::fmt_sig(v)
    }
}

/// A log10 coordinate whose key points are the labelled decades of [`Decades`], so plotters
/// draws ticks, labels and grid lines there and nowhere else.
#[derive(Clone)]
pub struct DecadeAxis {
    range: Range<f64>,
    log: RangedCoordf64,
    ticks: Vec<f64>,
}

impl DecadeAxis {
    /// The axis labelled at `decades` over their range.
    pub fn new(decades: Decades) -> Self {
        Self::with_range(decades.lo(), decades.hi(), decades)
    }

    /// The axis from `lo` to `hi` (both positive), labelled at those of `decades` within it;
    /// `lo` may lie below the labelled decades, to leave room for a zero line.
    pub fn with_range(lo: f64, hi: f64, decades: Decades) -> Self {
        let (lo_log, hi_log) = (lo.log10(), hi.log10());
        let ticks = decades
            .exponents()
            .into_iter()
            .map(pow10)
            .filter(|v| (lo_log - 1e-9..=hi_log + 1e-9).contains(&v.log10()))
            .collect();
        DecadeAxis { range: lo..hi, log: (lo_log..hi_log).into(), ticks }
    }
}

impl Ranged for DecadeAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let v = if *value > 0.0 { value.log10() } else { f64::NEG_INFINITY };
        self.log.map(&v, limit)
    }

    /// The labelled decades as bold points; no light points, so no unlabelled grid lines.
    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.range.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::coord::ranged1d::BoldPoints;

    /// The decade exponents labelled on a log axis showing positive values from `min` to `max`.
    fn decade_labels(min: f64, max: f64) -> Vec<i32> {
        Decades::for_values(min, max).map(|d| d.exponents()).unwrap_or_default()
    }

    fn exps(bottom: i32, top: i32, step: i32) -> Vec<i32> {
        (bottom..=top).step_by(step as usize).collect()
    }

    #[test]
    fn every_span_is_labelled_end_to_end() {
        // 1 decade: both ends.
        assert_eq!(decade_labels(1.5, 9.0), vec![0, 1]);
        // 3 decades: every decade.
        assert_eq!(decade_labels(2e-3, 0.7), vec![-3, -2, -1, 0]);
        // 12 decades: every second one.
        assert_eq!(decade_labels(1e-8, 1e4), exps(-8, 4, 2));
        // 30 decades: every fifth; 28 decades (the sphere benchmark): every fourth.
        assert_eq!(decade_labels(3e-30, 1.0), exps(-30, 0, 5));
        assert_eq!(decade_labels(1e-28, 1.0), exps(-28, 0, 4));
        // Labels sit on multiples of the step, the ends rounded out to the next one.
        assert_eq!(decade_labels(1e-28, 2.0), exps(-30, 5, 5));
        assert_eq!(decade_labels(1e-5, 1e5), exps(-6, 6, 2));
        // 300 decades: every fiftieth.
        assert_eq!(decade_labels(1e-300, 1.0), exps(-300, 0, 50));
        assert_eq!(Decades::covering(-8, 3), Decades { bottom: -8, top: 4, step: 2 });
        // An empty span still gets an axis; values an f64 cannot hold do not.
        assert_eq!(Decades::covering(2, 2), Decades { bottom: 2, top: 3, step: 1 });
        assert!(decade_labels(0.0, 1.0).is_empty() && decade_labels(1.0, f64::INFINITY).is_empty());
    }

    #[test]
    fn spans_get_four_to_eight_labels_and_stay_within_f64() {
        for lo in -320..300 {
            for span in [1, 2, 3, 5, 7, 8, 9, 11, 13, 17, 29, 31, 47, 99, 101, 250, 333, 600] {
                let d = Decades::covering(lo, lo + span);
                let n = d.exponents().len();
                assert!(n <= MAX_LABELS as usize && (n >= 4 || d.step == 1), "{d:?}");
                assert_eq!(d.exponents().last(), Some(&d.top), "{d:?}");
                assert!(d.bottom <= lo.max(MIN_EXP) && d.top >= (lo + span).min(MAX_EXP), "{d:?}");
                assert!(d.bottom >= MIN_AXIS_EXP && d.top <= MAX_AXIS_EXP, "{d:?}");
                assert!(d.bottom % d.step == 0 && d.top % d.step == 0, "{d:?}");
                assert!(d.lo() > 0.0 && d.hi().is_finite());
            }
        }
    }

    #[test]
    fn ticks_and_labels_are_exact_decades() {
        let axis = DecadeAxis::with_range(pow10(-30) * 0.3, 1.0, Decades::covering(-28, 0));
        let ticks = axis.key_points(BoldPoints(7));
        assert_eq!(ticks.len(), 8);
        assert_eq!((ticks[0], ticks[1], ticks[7]), (1e-28, 1e-24, 1.0));
        // No light points: no unlabelled grid lines.
        assert_eq!(axis.key_points(7usize), Vec::<f64>::new());
        let labels: Vec<String> = [1e-28, 1e-4, 1e-3, 1.0, 1000.0, 1e4, 1e12].map(label).into();
        assert_eq!(labels, ["1e-28", "1e-4", "0.001", "1", "1000", "1e4", "1e12"]);
        assert_eq!(label(2.5e-7), "2.5e-7");
    }
}
