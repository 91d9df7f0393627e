//! Encodings turn a bounded decision vector into a path (start and goal included). They own
//! their bounds and constraints, so every optimizer gets them for free through `repair`.

pub mod free;
pub mod sliced;

pub use free::FreeWaypoints;
pub use sliced::Sliced;

use crate::geom::Vec3;

pub trait Encoding: Send + Sync {
    /// The name used in scenario files.
    fn id(&self) -> &'static str;
    fn dim(&self) -> usize;
    fn lower(&self) -> &[f64];
    fn upper(&self) -> &[f64];
    /// Writes the path for `x` into `out` (cleared first): start, waypoints, goal.
    fn decode_into(&self, x: &[f64], out: &mut Vec<Vec3>);
    /// Brings `x` back inside the encoding's feasible set. The default clamps to the bounds.
    fn repair(&self, x: &mut [f64]) {
        for ((v, lo), hi) in x.iter_mut().zip(self.lower()).zip(self.upper()) {
            *v = v.clamp(*lo, *hi);
        }
    }

    fn decode(&self, x: &[f64]) -> Vec<Vec3> {
        let mut out = Vec::new();
        self.decode_into(x, &mut out);
        out
    }
}
