//! A path flown with a turning radius: the curve the vehicle flies is the path's line, and the
//! waypoints, which it does not pass through (it cuts each corner on a turn), are markers on
//! a thin dashed line.
//!
//! Violations keep the indices the evaluation gives them: a waypoint's, or a segment's, where
//! segment k of the flown curve is leg k's straight part followed by the turn at waypoint
//! k + 1 (`tidepath::path::flown`: a turn's issues are reported on the segment that ends at
//! its waypoint). [`Drawn`] says which points of the drawn line each segment and each
//! waypoint is, so the plan view and the profile mark the part of the curve that failed.

use tidepath::geom::Vec3;
use tidepath::kinematics::fillet::{self, FlownPiece};

use super::PlotPath;

/// The line drawn for a path, and where its segments and waypoints are on it.
pub(crate) struct Drawn<'a> {
    /// The flown curve when there is one, else the waypoints.
    pub line: &'a [Vec3],
    /// Arrival time at each point of `line` (may be empty).
    pub times: &'a [f64],
    /// Whether `line` is a flown curve (and the waypoints are drawn apart).
    pub flown: bool,
    /// Per segment of the waypoints, the first and last index of its part of `line`.
    segments: Vec<(usize, usize)>,
    /// Per waypoint, the index of the point of `line` nearest it.
    places: Vec<usize>,
}

impl<'a> Drawn<'a> {
    pub fn of(p: &PlotPath<'a>) -> Self {
        let n = p.points.len();
        let plain = Self {
            line: p.points,
            times: p.times,
            flown: false,
            segments: (0..n.saturating_sub(1)).map(|k| (k, k + 1)).collect(),
            places: (0..n).collect(),
        };
        let Some(f) = p.flown.filter(|f| f.points.len() >= 2 && n >= 2) else { return plain };
        let Some(segments) = segment_ranges(p.points, f.points, f.radius) else {
            // A curve that is not the fillets of these waypoints at this radius is drawn,
            // and the violations stay on the waypoints' straight segments.
            return Self { line: f.points, times: f.times, flown: true, segments: Vec::new(), places: Vec::new() };
        };
        let places = (0..n)
            .map(|i| match i {
                0 => 0,
                i if i + 1 == n => f.points.len() - 1,
                // An interior waypoint is nearest the middle of its turn, the end of segment
                // i - 1's part.
                i => {
                    let (a, b) = segments[i - 1];
                    let d = |j: usize| (f.points[j].truncate() - p.points[i].truncate()).length();
                    (a..=b).min_by(|&x, &y| d(x).total_cmp(&d(y))).unwrap_or(b)
                }
            })
            .collect();
        Self { line: f.points, times: f.times, flown: true, segments, places }
    }

    /// The indices into `line` of segment `k`'s part, both ends included; `None` when the
    /// path has no such segment or the flown curve could not be placed on the waypoints.
    pub fn segment(&self, k: usize) -> Option<std::ops::RangeInclusive<usize>> {
        self.segments.get(k).map(|&(a, b)| a..=b)
    }

    /// The index into `line` of the point nearest waypoint `i`.
    pub fn waypoint(&self, i: usize) -> Option<usize> {
        self.places.get(i).copied()
    }
}

/// Per segment of `waypoints`, the first and last index of its part of `flown`, the curve
/// flown along them with radius `r`: each segment ends where the turn at its end waypoint
/// ends, a point of the curve (the evaluation samples every turn's end). `None` when a turn's
/// end is not on `flown` (a curve of another radius).
fn segment_ranges(waypoints: &[Vec3], flown: &[Vec3], r: f64) -> Option<Vec<(usize, usize)>> {
    let mut ends = Vec::with_capacity(waypoints.len().saturating_sub(2));
    fillet::for_each_piece(waypoints, r, |piece| {
        if let FlownPiece::Arc(arc) = piece {
            ends.push(arc.b);
        }
    });
    let mut out = Vec::with_capacity(ends.len() + 1);
    let mut start = 0;
    for e in ends {
        let close = |q: &Vec3| q.distance(e) <= 1e-9 * (1.0 + e.length());
        let end = start + flown[start..].iter().position(close)?;
        out.push((start, end));
        start = end;
    }
    out.push((start, flown.len() - 1));
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A right-angle corner flown with radius 10: the turn's end closes segment 0, the
    /// waypoint's place is the middle of the turn, a segment's part is what it flies.
    #[test]
    fn segments_and_waypoints_are_placed_on_the_flown_curve() {
        let w = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(100.0, 0.0, 0.0), Vec3::new(100.0, 100.0, 0.0)];
        // Straight to (90, 0), the quarter circle about (90, 10) in 4 chords, on to the goal.
        let mut f = vec![w[0], Vec3::new(90.0, 0.0, 0.0)];
        for k in 1..=4 {
            let a = -std::f64::consts::FRAC_PI_2 + std::f64::consts::FRAC_PI_2 * k as f64 / 4.0;
            f.push(Vec3::new(90.0 + 10.0 * a.cos(), 10.0 + 10.0 * a.sin(), 0.0));
        }
        f.push(w[2]);
        let mut p = PlotPath::new("p", &w).with_flown(&f, &[], 10.0);
        let d = Drawn::of(&p);
        assert!(d.flown);
        assert_eq!(d.segment(0), Some(0..=5));
        assert_eq!(d.segment(1), Some(5..=6));
        assert_eq!(d.segment(2), None);
        assert_eq!((d.waypoint(0), d.waypoint(1), d.waypoint(2)), (Some(0), Some(3), Some(6)));
        // Another radius's curve is drawn, its segments unplaced.
        p = p.with_flown(&f, &[], 20.0);
        let d = Drawn::of(&p);
        assert!(d.flown && d.segment(0).is_none() && d.waypoint(1).is_none());
        // Without a flown curve the line is the waypoints.
        let d = Drawn::of(&PlotPath::new("p", &w));
        assert!(!d.flown);
        assert_eq!((d.segment(1), d.waypoint(2)), (Some(1..=2), Some(2)));
    }
}
