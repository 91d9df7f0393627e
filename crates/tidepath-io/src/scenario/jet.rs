//! Scenario support for ijs2023's meandering jet.

use super::spec::JetSpec;
use tidepath::error::{Error, Result};
use tidepath::geom::Aabb;
use tidepath::world::current::{JetConfig, Magnitude, MeanderingJet};

pub(super) fn build_jet(spec: &JetSpec, bounds: &Aabb) -> Result<MeanderingJet> {
    let magnitude = match (spec.speed, spec.max_speed) {
        (Some(s), None) => Magnitude::Fixed(s),
        (None, Some(s)) => Magnitude::Scaled(s),
        _ => {
            return Err(Error::input(
                "world.current",
                "a jet needs exactly one of `speed` (m/s everywhere) or `max_speed` (m/s at its fastest point)",
            ))
        }
    };
    let mut c = match spec.region {
        Some([x0, y0, x1, y1]) => JetConfig::new(x0, x1, y0, y1, magnitude),
        None => JetConfig::over(bounds, magnitude),
    };
    let set = |dst: &mut f64, v: Option<f64>| {
        if let Some(v) = v {
            *dst = v;
        }
    };
    set(&mut c.seconds_per_unit, spec.time_scale);
    set(&mut c.kappa, spec.kappa);
    set(&mut c.eps, spec.eps);
    set(&mut c.eta, spec.eta);
    set(&mut c.alpha0, spec.alpha0);
    set(&mut c.beta, spec.beta);
    set(&mut c.gamma, spec.gamma);
    set(&mut c.omega0, spec.omega0);
    if let Some(j) = spec.jet_x {
        c.jet_x = j;
    }
    if let Some(j) = spec.jet_y {
        c.jet_y = j;
    }
    MeanderingJet::new(c, "world.current")
}
