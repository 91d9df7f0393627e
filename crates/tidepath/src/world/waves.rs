//! Significant wave height on a regular grid (the wave glider's propulsion, seed 004).

use super::grid::RegularGrid2;

#[derive(Clone, Debug, PartialEq)]
pub struct WaveField {
    pub grid: RegularGrid2,
    /// Significant wave height (m) at the nodes, row-major.
    pub heights: Vec<f64>,
}

impl WaveField {
    /// Significant wave height at (x, y) and time t (s).
    pub fn height(&self, x: f64, y: f64, t: f64) -> f64 {
        let _ = (x, y, t);
        todo!("currents helper")
    }
}
