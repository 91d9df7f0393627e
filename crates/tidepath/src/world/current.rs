//! Ocean currents behind one interface: velocity (m/s, ENU) at a point and time.

use super::grid::RegularGrid2;
use crate::geom::Vec3;

/// One Lamb-Oseen vortex (seed 001 eqs. 3-5, ALGORITHMS.md section 0.2).
#[derive(Clone, Debug, PartialEq)]
pub struct LambOseen {
    pub x: f64,
    pub y: f64,
    /// eta: circulation strength (m^2/s); positive is counter-clockwise.
    pub strength: f64,
    /// zeta: core radius (m).
    pub core_radius: f64,
}

/// The time-varying meandering jet of seed 003 (eqs. 27-28, ALGORITHMS.md section 0.3),
/// mapped from jet units onto a rectangle of the world.
#[derive(Clone, Debug, PartialEq)]
pub struct MeanderingJet {
    // Field list to be completed by the currents helper.
}

/// u, v components on a regular grid at a list of times; bilinear in space, linear in time.
#[derive(Clone, Debug, PartialEq)]
pub struct CurrentGrid {
    pub grid: RegularGrid2,
    /// Strictly increasing times (s) of the layers.
    pub times: Vec<f64>,
    /// One row-major layer per time.
    pub u: Vec<Vec<f64>>,
    pub v: Vec<Vec<f64>>,
}

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
    pub fn velocity(&self, p: Vec3, t: f64) -> Vec3 {
        let _ = (p, t);
        todo!("currents helper")
    }
}
