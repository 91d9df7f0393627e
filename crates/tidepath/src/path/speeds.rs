//! Segment speeds carried from one path onto another that follows it (a smoothed path, a
//! path cut or re-sampled): how a plan's chosen speeds survive a smoother.

use crate::geom::Vec3;

/// The speed of each segment of `to`, read from `from` flown at `speeds` (one per segment of
/// `from`): a segment of `to` takes the speed of the segment of `from` at the same fraction of
/// the length as its own midpoint. Exact when `to` is `from`; a smoother that moves points
/// sideways keeps the speed profile along the route.
pub fn resample_speeds(from: &[Vec3], speeds: &[f64], to: &[Vec3]) -> Vec<f64> {
    let n = to.len().saturating_sub(1);
    let Some(&last) = speeds.last() else { return Vec::new() };
    let lengths = |p: &[Vec3]| -> Vec<f64> {
        let mut acc = vec![0.0];
        for w in p.windows(2) {
            acc.push(acc[acc.len() - 1] + w[0].distance(w[1]));
        }
        acc
    };
    let (cum_from, cum_to) = (lengths(from), lengths(to));
    let (total_from, total_to) = (cum_from[cum_from.len() - 1], cum_to[cum_to.len() - 1]);
    if from.len() == to.len() && from == to {
        return (0..n).map(|i| speeds[i.min(speeds.len() - 1)]).collect();
    }
    (0..n)
        .map(|i| {
            let mid = if total_to > 0.0 { 0.5 * (cum_to[i] + cum_to[i + 1]) / total_to } else { 0.0 };
            let at = mid * total_from;
            // The first segment of `from` whose end lies at or beyond `at`.
            let k = cum_from[1..].partition_point(|&c| c < at);
            speeds.get(k).copied().unwrap_or(last)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_path_keeps_its_own_speeds_and_a_split_segment_keeps_its_speed() {
        let from = [Vec3::ZERO, Vec3::new(100.0, 0.0, 0.0), Vec3::new(100.0, 300.0, 0.0)];
        let speeds = [1.0, 2.0];
        assert_eq!(resample_speeds(&from, &speeds, &from), vec![1.0, 2.0]);
        // Cut each segment in two: 4 segments at 50, 50, 150, 150 m; midpoints at 25, 75,
        // 175, 325 m of 400 m, so the first two fall in the first segment (0..100 m).
        let to = [
            Vec3::ZERO,
            Vec3::new(50.0, 0.0, 0.0),
            Vec3::new(100.0, 0.0, 0.0),
            Vec3::new(100.0, 150.0, 0.0),
            Vec3::new(100.0, 300.0, 0.0),
        ];
        assert_eq!(resample_speeds(&from, &speeds, &to), vec![1.0, 1.0, 2.0, 2.0]);
        // A shortcut of one segment takes the speed at the middle of the route (200 m: the
        // second segment).
        let straight = [Vec3::ZERO, Vec3::new(100.0, 300.0, 0.0)];
        assert_eq!(resample_speeds(&from, &speeds, &straight), vec![2.0]);
        assert!(resample_speeds(&from, &[], &to).is_empty());
    }
}
