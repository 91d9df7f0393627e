//! The lattice: cells of a raster, heading bins, depth layers, and the motion primitives that
//! join its states.
//!
//! A primitive turns on the vehicle's radius r by a whole number of heading bins (left or
//! right), then flies straight until its horizontal length reaches the step length
//! l = max(sqrt 2 x cell, r x bin), enough to leave the cell (Nav2 Smac's choice). The turns are
//! the pure arc of length l rounded to whole bins (at least one, at most a quarter turn), then
//! halved down to one bin: with r much smaller than the cell (a lattice over a strait a hundred
//! kilometres long for a 40 m radius), a step can turn by a quarter turn, an eighth, ... one
//! bin; with r of the cell size or larger, a step is one arc of one or a few bins, as in Dolgov
//! et al. (2010).
//!
//! In 3-D each primitive also comes climbing and diving by one layer (`dz`, less where the
//! pitch limit needs it), spread evenly over its whole length, arc and straight.
//!
//! Each primitive is built once from the origin as a tangent polygon
//! ([`crate::kinematics::TangentPolygon`]): its fillets at radius r are exactly its arcs, so the
//! vehicle flies it as planned. The search places it at a state by rotating and translating
//! its points.

use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};

use crate::geom::Vec3;
use crate::kinematics::{Pose, TangentPolygon};

/// Largest piece (rad) an arc is cut into for its tangent polygon: each vertex then lies at
/// most r (sec(pi/16) - 1) = 0.02 r outside the arc.
pub const MAX_PIECE: f64 = PI / 8.0;

/// Relative margin kept below the pitch limit, so rounding never makes a climb too steep.
pub const PITCH_MARGIN: f64 = 1e-6;

/// One motion primitive, from the origin heading east at height 0.
#[derive(Clone, Debug)]
pub struct Primitive {
    /// Its tangent polygon (the origin first).
    pub points: Vec<Vec3>,
    /// The heading change (rad, positive left): a whole number of bins.
    pub sweep: f64,
    /// 3-D length of the flown curve (m).
    pub length_3d: f64,
}

impl Primitive {
    /// A turn of `sweep` rad, then straight to a horizontal length of `step`, climbing `dz`
    /// evenly over the whole.
    fn new(radius: f64, sweep: f64, step: f64, dz: f64, max_piece: f64) -> Self {
        let arc = radius * sweep.abs();
        let straight = (step - arc).max(0.0);
        let length = arc + straight;
        let mut tp = TangentPolygon::new(Pose::new(Vec3::ZERO, 0.0), radius, max_piece);
        tp.arc(sweep, dz * arc / length);
        tp.straight(straight, dz * straight / length);
        Self { points: tp.finish(), sweep, length_3d: length.hypot(dz) }
    }

    /// Its points placed at `at`, into `out` (cleared first).
    pub fn place(&self, at: Pose, out: &mut Vec<Vec3>) {
        out.clear();
        let (s, c) = at.heading.sin_cos();
        out.extend(self.points.iter().map(|q| at.p + Vec3::new(q.x * c - q.y * s, q.x * s + q.y * c, q.z)));
    }
}

/// The lattice's geometry and its primitives.
#[derive(Clone, Debug)]
pub struct Lattice {
    pub bins: usize,
    /// Bin width (rad).
    pub bin: f64,
    pub radius: f64,
    /// Step length (m).
    pub step: f64,
    pub primitives: Vec<Primitive>,
}

impl Lattice {
    /// The lattice for cells of `cell` metres (the smaller side), `bins` heading bins, radius
    /// `radius`, and in 3-D layers of `layer` metres with pitch limit `max_pitch` (rad); tangent
    /// polygons cut arcs into pieces of at most `max_piece` rad.
    pub fn new(cell: f64, bins: usize, radius: f64, layer: Option<f64>, max_pitch: f64, max_piece: f64) -> Self {
        let bin = std::f64::consts::TAU / bins as f64;
        let step = (SQRT_2 * cell).max(radius * bin);
        // The pure arc of one step, in whole bins: at least one, at most a quarter turn.
        let quarter = ((FRAC_PI_2 / bin).floor() as usize).max(1);
        let arc_bins = ((step / (radius * bin)).round() as usize).clamp(1, quarter);
        let mut turns = vec![arc_bins];
        while let Some(&m) = turns.last() {
            if m <= 1 {
                break;
            }
            turns.push(m / 2);
        }
        let tan_pitch = max_pitch.tan() * (1.0 - PITCH_MARGIN);
        // One layer per step, less where the pitch limit needs it.
        let dz = layer.map(|l| l.min(step * tan_pitch));
        let mut sweeps = vec![0.0];
        for &m in &turns {
            sweeps.extend([m as f64 * bin, -(m as f64) * bin]);
        }
        let mut primitives: Vec<Primitive> =
            sweeps.iter().map(|&a| Primitive::new(radius, a, step, 0.0, max_piece)).collect();
        // Every primitive is at least a step long, so none is steeper than dz over a step.
        if let Some(dz) = dz.filter(|&d| d > 0.0) {
            for k in [1.0, -1.0] {
                primitives.extend(sweeps.iter().map(|&a| Primitive::new(radius, a, step, k * dz, max_piece)));
            }
        }
        Self { bins, bin, radius, step, primitives }
    }

    /// The bin of heading `h`.
    pub fn bin_of(&self, h: f64) -> usize {
        ((h / self.bin).round() as i64).rem_euclid(self.bins as i64) as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The turns of the level primitives, in bins, left ones only.
    fn turns(l: &Lattice) -> Vec<usize> {
        l.primitives
            .iter()
            .filter(|p| p.sweep > 0.0 && p.points.last().unwrap().z == 0.0)
            .map(|p| (p.sweep / l.bin).round() as usize)
            .collect()
    }

    #[test]
    fn a_radius_of_cells_gives_arcs_of_a_step_and_a_small_radius_gives_turns_then_straights() {
        // r = 30 m, 5 m cells, 72 bins: a step of 7.07 m is an arc of 2.7 bins: turns of 3 bins
        // (a pure arc, a little longer than the step) and 1 bin (then straight), 5 primitives.
        let l = Lattice::new(5.0, 72, 30.0, None, 0.3, MAX_PIECE);
        assert_eq!((turns(&l), l.primitives.len()), (vec![3, 1], 5));
        let left = &l.primitives[1];
        assert!((left.sweep - 3.0 * l.bin).abs() < 1e-15 && (left.length_3d - 90.0 * l.bin).abs() < 1e-12);
        assert_eq!(left.points.len(), 3, "one piece: start, vertex, end");
        let small = &l.primitives[3];
        assert!((small.length_3d - l.step).abs() < 1e-12);
        // r = 40 m, 800 m cells: turns of 18, 9, 4, 2 and 1 bins, each then straight to 1131 m,
        // level, climbing or diving one 8.75 m layer.
        let l = Lattice::new(800.0, 72, 40.0, Some(8.75), 20f64.to_radians(), MAX_PIECE);
        assert_eq!(turns(&l), vec![18, 9, 4, 2, 1]);
        assert_eq!(l.primitives.len(), 33);
        // r = 30 m, 5 m cells, 1 m layers: the pure arcs climb too.
        let l3 = Lattice::new(5.0, 72, 30.0, Some(1.0), 20f64.to_radians(), MAX_PIECE);
        assert_eq!(l3.primitives.len(), 15);
        for p in &l.primitives {
            let end = *p.points.last().unwrap();
            assert!(end.z == 0.0 || (end.z.abs() - 8.75).abs() < 1e-12);
            let (r, a, length) = (40.0, p.sweep, 800.0 * SQRT_2);
            let rest = length - r * a.abs();
            assert!((p.length_3d - length.hypot(end.z)).abs() < 1e-9);
            // The end lies where a turn then a straight of the rest leaves it.
            let turned = Vec3::new(r * a.abs().sin(), a.signum() * r * (1.0 - a.cos()), 0.0);
            let expect = turned + Vec3::new(a.cos(), a.sin(), 0.0) * rest;
            assert!((end.truncate() - expect.truncate()).length() < 1e-9, "{end:?} {expect:?}");
        }
    }

    #[test]
    fn placing_rotates_and_translates() {
        let l = Lattice::new(10.0, 16, 10.0, None, 0.3, MAX_PIECE);
        let mut out = Vec::new();
        l.primitives[0].place(Pose::new(Vec3::new(1.0, 2.0, -3.0), FRAC_PI_2), &mut out);
        let end = *out.last().unwrap();
        assert!((end - Vec3::new(1.0, 2.0 + l.step, -3.0)).length() < 1e-12);
        assert_eq!(l.bin_of(-l.bin * 0.4), 0);
        assert_eq!(l.bin_of(-l.bin), 15);
    }
}
