//! Scenario support for ijs2023's meandering jet.

use super::spec::JetSpec;
use tidepath::error::{Error, Result};
use tidepath::geom::Aabb;
use tidepath::world::current::{JetConfig, Magnitude, MeanderingJet};

/// The jet of `spec` over `bounds`. ijs2023 states the current's magnitude as a ratio of the
/// AUV's speed (0.5 in its Table 2, 0.8 and 1.2 in Table 3, 0.2 for the fleet): `speed_ratio`
/// and `max_speed_ratio` multiply `vehicle_speed` (the scenario's `[vehicle] speed`) into the
/// `speed` and `max_speed` forms.
pub(super) fn build_jet(spec: &JetSpec, bounds: &Aabb, vehicle_speed: f64) -> Result<MeanderingJet> {
    let ratio = |field: &str, r: f64| -> Result<f64> {
        if !(r.is_finite() && r >= 0.0) {
            return Err(Error::input(
                format!("world.current.{field}"),
                format!("must be a finite non-negative ratio of the vehicle's speed, got {r}"),
            ));
        }
        Ok(r * vehicle_speed)
    };
    let given = [spec.speed, spec.max_speed, spec.speed_ratio, spec.max_speed_ratio];
    let magnitude = match (given.iter().filter(|v| v.is_some()).count(), given) {
        (1, [Some(s), ..]) => Magnitude::Fixed(s),
        (1, [_, Some(s), ..]) => Magnitude::Scaled(s),
        (1, [_, _, Some(r), _]) => Magnitude::Fixed(ratio("speed_ratio", r)?),
        (1, [_, _, _, Some(r)]) => Magnitude::Scaled(ratio("max_speed_ratio", r)?),
        _ => {
            return Err(Error::input(
                "world.current",
                "a jet needs exactly one of `speed` (m/s everywhere), `max_speed` (m/s at its fastest point), `speed_ratio` or `max_speed_ratio` (the same as ratios of [vehicle] speed)",
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
