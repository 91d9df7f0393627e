//! The Lamb-Oseen vortex: one analytic vortex of the `Current::Vortices` superposition.

use crate::geom::Vec2;
use std::f64::consts::TAU;

/// One Lamb-Oseen vortex (lfhh2019 eqs. 3-5, docs/papers/shared.md#lamb-oseen).
#[derive(Clone, Debug, PartialEq)]
pub struct LambOseen {
    pub x: f64,
    pub y: f64,
    /// eta: circulation strength (m^2/s); positive is counter-clockwise.
    pub strength: f64,
    /// zeta: core radius (m).
    pub core_radius: f64,
}

/// Beyond this r^2/zeta^2, exp(-r^2/zeta^2) < 2e-22 and 1 - exp(..) rounds to exactly 1.
const VORTEX_FAR_FIELD: f64 = 50.0;

/// Radius of peak speed of a Lamb-Oseen vortex in core radii (root of 2 r^2 = e^{r^2} - 1);
/// used so that speed hints do not miss a small core between sample points.
pub(super) const VORTEX_PEAK_RADIUS: f64 = 1.120_906_423_2;

impl LambOseen {
    /// Horizontal velocity of this vortex alone at (x, y).
    ///
    /// The paper's "(R - R0)^2" is the squared distance. The centre returns zero because the
    /// limit there is zero and the formula would divide 0 by 0.
    #[inline]
    pub fn velocity(&self, x: f64, y: f64) -> Vec2 {
        let (dx, dy) = (x - self.x, y - self.y);
        let r2 = dx * dx + dy * dy;
        if r2 < 1e-12 {
            return Vec2::ZERO;
        }
        let q = r2 / (self.core_radius * self.core_radius);
        // -expm1(-q) rather than 1 - exp(-q): near the core the subtraction would cancel.
        let shape = if q > VORTEX_FAR_FIELD { 1.0 } else { -(-q).exp_m1() };
        let k = self.strength * shape / (TAU * r2);
        Vec2::new(-k * dy, k * dx)
    }
}
