//! Ocean currents behind one interface: velocity (m/s, ENU) at a point and time.
//!
//! `Current::velocity` sits in the innermost loop of every cost evaluation (tens of calls per
//! path, about 5 microseconds per path), so no variant allocates and each avoids work it can
//! prove is wasted: vortices skip `exp` where it cannot change the result, the grid locates
//! the cell once for all four interpolations.

mod grid;
mod jet;
mod lamb_oseen;

pub use grid::CurrentGrid;
pub use jet::{JetConfig, Magnitude, MeanderingJet};
pub use lamb_oseen::LambOseen;

use crate::geom::{Aabb, Vec2, Vec3};
use lamb_oseen::VORTEX_PEAK_RADIUS;
use std::f64::consts::TAU;

#[derive(Clone, Debug, PartialEq)]
pub enum Current {
    None,
    Uniform(Vec3),
    Vortices(Vec<LambOseen>),
    Jet(MeanderingJet),
    Grid(CurrentGrid),
}

impl Current {
    /// Current velocity at `p` and time `t` (s).
    #[inline]
    pub fn velocity(&self, p: Vec3, t: f64) -> Vec3 {
        match self {
            Current::None => Vec3::ZERO,
            Current::Uniform(v) => *v,
            Current::Vortices(vortices) => {
                let mut sum = Vec2::ZERO;
                for vortex in vortices {
                    sum += vortex.velocity(p.x, p.y);
                }
                sum.extend(0.0)
            }
            Current::Jet(jet) => jet.velocity(p, t),
            Current::Grid(grid) => grid.velocity(p.x, p.y, t),
        }
    }

    /// Whether the current at `p` comes from data: false only inside the cells of a gridded
    /// forecast next to a node without data (land or fill in its file).
    #[inline]
    pub fn has_data(&self, p: Vec3) -> bool {
        match self {
            Current::Grid(grid) => grid.has_data(p.x, p.y),
            _ => true,
        }
    }

    /// The first point of the horizontal projection of a -> b where the current has no data
    /// (see [`CurrentGrid::first_gap_on`]); `None` for currents without gaps.
    #[inline]
    pub fn first_gap_on(&self, a: Vec3, b: Vec3) -> Option<Vec2> {
        match self {
            Current::Grid(grid) => grid.first_gap_on(a.x, a.y, b.x, b.y).map(|(x, y)| Vec2::new(x, y)),
            _ => None,
        }
    }

    /// An estimate of the largest horizontal current speed (m/s) over the horizontal extent of
    /// `bounds` at time `t`, for scaling arrows and speed bounds in plots.
    ///
    /// Exact for `None`, `Uniform` and `Grid`. Vortices and the jet are sampled on a 64 x 64
    /// grid; for vortices the ring of peak speed around each centre inside `bounds` is sampled
    /// too, since a core smaller than the grid spacing would otherwise be missed.
    pub fn max_speed_hint(&self, bounds: &Aabb, t: f64) -> f64 {
        self.max_speed_hint_within(bounds, t, &|| false).expect("never stopped")
    }

    /// [`Current::max_speed_hint`], polling `stop` once per row of samples and per vortex:
    /// `None` when it asked to stop (thousands of vortices make every sample slow).
    pub fn max_speed_hint_within(&self, bounds: &Aabb, t: f64, stop: &dyn Fn() -> bool) -> Option<f64> {
        Some(match self {
            Current::None => 0.0,
            Current::Uniform(v) => v.x.hypot(v.y),
            Current::Grid(grid) => grid.max_speed(bounds, t),
            Current::Jet(_) => sample_max_speed(self, bounds, t, stop)?,
            Current::Vortices(vortices) => {
                let mut peak = sample_max_speed(self, bounds, t, stop)?;
                for vortex in vortices {
                    if stop() {
                        return None;
                    }
                    let r = VORTEX_PEAK_RADIUS * vortex.core_radius.abs();
                    for k in 0..16 {
                        let (s, c) = (TAU * k as f64 / 16.0).sin_cos();
                        let p = Vec3::new(vortex.x + r * c, vortex.y + r * s, bounds.min.z);
                        if p.x >= bounds.min.x && p.x <= bounds.max.x && p.y >= bounds.min.y && p.y <= bounds.max.y {
                            peak = peak.max(self.velocity(p, t).truncate().length());
                        }
                    }
                }
                peak
            }
        })
    }
}

/// Largest horizontal speed on a 64 x 64 grid of points spanning `bounds` (edges included);
/// `None` if `stop` (polled per row) asks to stop.
fn sample_max_speed(current: &Current, bounds: &Aabb, t: f64, stop: &dyn Fn() -> bool) -> Option<f64> {
    const N: usize = 64;
    let mut peak: f64 = 0.0;
    for j in 0..N {
        if stop() {
            return None;
        }
        let y = bounds.min.y + (bounds.max.y - bounds.min.y) * j as f64 / (N - 1) as f64;
        for i in 0..N {
            let x = bounds.min.x + (bounds.max.x - bounds.min.x) * i as f64 / (N - 1) as f64;
            let v = current.velocity(Vec3::new(x, y, bounds.min.z), t);
            peak = peak.max(v.truncate().length());
        }
    }
    Some(peak)
}

#[cfg(test)]
mod tests;
