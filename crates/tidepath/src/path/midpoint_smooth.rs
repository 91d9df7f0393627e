//! lfhh2019's smooth method (eq. 15): every interior waypoint moves to the midpoint of its
//! longer leg, evening out the zig-zags a histogram sampler leaves.
//!
//! For interior waypoint j with left leg l_{j-1} = |p_j - p_{j-1}| and right leg
//! l_j = |p_{j+1} - p_j|:
//!
//! ```text
//! p'_j = (p_{j-1} + p_j) / 2   if l_{j-1} > l_j
//! p'_j = (p_j + p_{j+1}) / 2   otherwise
//! ```
//!
//! Reading (docs/papers/lfhh2019.md A10): every new point is computed from the old path
//! (Jacobi form), not in place, so the result does not depend on the order of the loop; the
//! endpoints stay; equal legs take the right one, as the printed "otherwise" does. Encodings
//! then keep only each point's free coordinates ([`crate::encoding::Encoding::set_waypoint`]).

use crate::geom::Vec3;

/// Writes eq. 15 applied to `points` into `out` (cleared first); paths of fewer than three
/// points are copied.
pub fn midpoint_smooth(points: &[Vec3], out: &mut Vec<Vec3>) {
    out.clear();
    out.extend_from_slice(points);
    for j in 1..points.len().saturating_sub(1) {
        let (a, p, b) = (points[j - 1], points[j], points[j + 1]);
        out[j] = if p.distance(a) > b.distance(p) { (a + p) * 0.5 } else { (p + b) * 0.5 };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// By hand: (0,0) (1,3) (2,0) (6,1) (7,0). Legs: sqrt 10, sqrt 10, sqrt 17, sqrt 2.
    /// j = 1: left sqrt 10 is not longer than right sqrt 10 -> towards p2: (1.5, 1.5).
    /// j = 2: left sqrt 10 < right sqrt 17 -> towards p3: (4, 0.5).
    /// j = 3: left sqrt 17 > right sqrt 2 -> towards p2 (old): (4, 0.5).
    #[test]
    fn jacobi_form_by_hand_with_ends_fixed() {
        let v = |x: f64, y: f64| Vec3::new(x, y, -1.0);
        let p = [v(0.0, 0.0), v(1.0, 3.0), v(2.0, 0.0), v(6.0, 1.0), v(7.0, 0.0)];
        let mut out = Vec::new();
        midpoint_smooth(&p, &mut out);
        assert_eq!(out, vec![v(0.0, 0.0), v(1.5, 1.5), v(4.0, 0.5), v(4.0, 0.5), v(7.0, 0.0)]);
        midpoint_smooth(&p[..2], &mut out);
        assert_eq!(out, p[..2].to_vec());
    }
}
