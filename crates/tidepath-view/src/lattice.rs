//! Sampling lattices and the rounding that keeps the page small.
//!
//! A view samples fields (seabed, currents, waves) on regular lattices over the domain, far
//! coarser than a 3,000 x 3,000 elevation grid: a browser turns a surface of 160 x 160 nodes
//! smoothly, and the file stays a few megabytes. Numbers are written rounded to what a viewer
//! can tell apart (a tenth of a metre, a millimetre per second), which halves the JSON.

/// `n` evenly spaced values from `lo` to `hi`, both included (`[lo]` when `n` is 1).
pub fn axis(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![0.5 * (lo + hi)],
        _ => (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect(),
    }
}

/// Node counts (nx, ny) for a lattice over `width` x `height` with at most `max_side` nodes
/// along the longer side and cells as square as the counts allow (at least 2 a side).
pub fn shape(width: f64, height: f64, max_side: usize) -> (usize, usize) {
    let max_side = max_side.max(2);
    if !(width > 0.0 && height > 0.0) {
        return (max_side, max_side);
    }
    let other = |long: f64, short: f64| ((max_side as f64 - 1.0) * short / long).round() as usize + 1;
    if width >= height {
        (max_side, other(width, height).clamp(2, max_side))
    } else {
        (other(height, width).clamp(2, max_side), max_side)
    }
}

/// `x` rounded to a multiple of `step` (a power of ten: 0.1 for metres, 1e-3 for speeds).
pub fn round(x: f64, step: f64) -> f64 {
    if x.is_finite() {
        let r = (x / step).round() * step;
        // Print 1e-1 multiples as 12.3, not 12.300000000000001.
        let digits = (-step.log10()).round().max(0.0) as i32;
        let scale = 10f64.powi(digits);
        (r * scale).round() / scale
    } else {
        x
    }
}

/// Metres to the tenth.
pub fn m(x: f64) -> f64 {
    round(x, 0.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_includes_both_ends_evenly() {
        assert_eq!(axis(0.0, 10.0, 3), vec![0.0, 5.0, 10.0]);
        assert_eq!(axis(2.0, 4.0, 1), vec![3.0]);
        assert!(axis(0.0, 1.0, 0).is_empty());
    }

    #[test]
    fn shape_keeps_cells_square() {
        assert_eq!(shape(2000.0, 1000.0, 161), (161, 81));
        assert_eq!(shape(1000.0, 4000.0, 41), (11, 41));
        // Never fewer than two nodes a side, even for a thin strip.
        assert_eq!(shape(1e6, 1.0, 10), (10, 2));
    }

    #[test]
    fn rounding_prints_short() {
        assert_eq!(round(12.34999, 0.1), 12.3);
        assert_eq!(round(0.1 + 0.2, 0.1), 0.3);
        assert_eq!(round(1.23456, 1e-3), 1.235);
        assert_eq!(serde_json::to_string(&m(1234.5678)).unwrap(), "1234.6");
        assert!(round(f64::NAN, 0.1).is_nan());
    }
}
