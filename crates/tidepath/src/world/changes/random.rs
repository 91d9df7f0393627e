//! Random displacements of a change's centre, drawn from the run's own stream.

use rand::Rng as _;
use rand_distr::StandardNormal;

use crate::error::{Error, Result};
use crate::geom::Vec3;
use crate::rng::Rng;

/// The law of each axis' displacement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Law {
    /// Normal with mean 0 and standard deviation `scale` (lfhh2019's 2-D moves, 1 km).
    Gaussian,
    /// Uniform on [-scale, scale] (lfhh2019's 3-D sphere moves, 1 km).
    Uniform,
}

/// A random displacement of a centre, redrawn while it covers the vehicle or its goal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RandomShift {
    pub law: Law,
    /// Metres.
    pub scale: f64,
    /// Draws before the change is skipped (lfhh2019 A9: 100).
    pub max_draws: u32,
    /// Displace the centre the obstacle or vortex has when the change applies, not the one
    /// written in the change: successive changes then add up to a random walk (lfhh2019's
    /// obstacles move on from where the last change left them).
    pub from_current: bool,
}

impl RandomShift {
    /// lfhh2019's redraw limit.
    pub const LFHH2019_MAX_DRAWS: u32 = 100;

    pub fn check(&self) -> Result<()> {
        if !(self.scale >= 0.0 && self.scale.is_finite()) {
            return Err(Error::input("changes.random.scale", format!("must be finite and >= 0, got {}", self.scale)));
        }
        if self.max_draws == 0 {
            return Err(Error::input("changes.random.max_draws", "must be at least 1, got 0"));
        }
        Ok(())
    }

    /// One displacement: x and y, and z in a 3-D world, each drawn in that order.
    pub fn draw(&self, rng: &mut Rng, three_d: bool) -> Vec3 {
        let mut one = || match self.law {
            Law::Gaussian => self.scale * rng.sample::<f64, _>(StandardNormal),
            Law::Uniform => self.scale * (2.0 * rng.random::<f64>() - 1.0),
        };
        let (x, y) = (one(), one());
        let z = if three_d { one() } else { 0.0 };
        Vec3::new(x, y, z)
    }
}
