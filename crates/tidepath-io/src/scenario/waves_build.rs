//! From `[world.waves]` to the world's sea state ([`Waves`]), and a `[vehicle] kind =
//! "wave-glider"` to its propulsion (acopf2016 eqs. 1-2): every value checked, errors naming
//! the field and value. A forecast file (`kind = "file"`) has already been read and rewritten
//! as a metric grid by `forecast.rs` when this runs.

use super::spec::{VehicleKind, VehicleSpec, WavesSpec, P2};
use tidepath::error::{Error, Result};
use tidepath::vehicle::{GliderSpeed, Propulsion, Vehicle};
use tidepath::world::waves::WaveGrid;
use tidepath::world::{Dims, RegularGrid2, Waves, World};

/// The highest significant wave height accepted (m): above the highest ever recorded (about
/// 20 m), so a larger value is a typo or a unit error.
pub const MAX_WAVE_HEIGHT_M: f64 = 30.0;

pub(super) fn build_waves(spec: Option<&WavesSpec>) -> Result<Waves> {
    const F: &str = "world.waves";
    let Some(spec) = spec else { return Ok(Waves::None) };
    let waves = match spec {
        WavesSpec::Uniform { height } => {
            check_height(&format!("{F}.height"), *height)?;
            Waves::Uniform(*height)
        }
        WavesSpec::Grid { origin, spacing, shape, times, height, no_data } => {
            let grid = grid2(F, *origin, *spacing, *shape)?;
            let g = WaveGrid::new(grid, times.clone(), height.clone(), F)?.with_gaps(no_data.clone(), F)?;
            check_layers(&format!("{F}.height"), &g)?;
            Waves::Grid(g)
        }
        WavesSpec::Cells { origin, resolution, heights } => {
            let g = super::cells::build_waves(*origin, *resolution, heights)?;
            check_layers(&format!("{F}.heights"), &g)?;
            Waves::Grid(g)
        }
        // Geographic scenarios turn forecast files into grids before the world is built.
        WavesSpec::File { .. } => {
            return Err(Error::input(format!("{F}.kind"), "\"file\" needs world.frame = \"geographic\""))
        }
    };
    Ok(waves)
}

fn grid2(field: &str, origin: P2, spacing: P2, shape: [usize; 2]) -> Result<RegularGrid2> {
    RegularGrid2::new(origin[0], origin[1], spacing[0], spacing[1], shape[0], shape[1], field)
}

/// A height must be finite, not negative and at most [`MAX_WAVE_HEIGHT_M`].
fn check_height(field: &str, h: f64) -> Result<()> {
    if !(h.is_finite() && (0.0..=MAX_WAVE_HEIGHT_M).contains(&h)) {
        return Err(Error::input(
            field,
            format!("must be a significant wave height from 0 to {MAX_WAVE_HEIGHT_M} m, got {h}"),
        ));
    }
    Ok(())
}

/// The grid's checks leave the upper limit: the first node above it is named.
fn check_layers(field: &str, g: &WaveGrid) -> Result<()> {
    for (l, layer) in g.heights.iter().enumerate() {
        if let Some(k) = layer.iter().position(|&h| h > MAX_WAVE_HEIGHT_M) {
            return Err(Error::input(
                field,
                format!(
                    "layer {l}, value {k} (node i = {}, j = {}) is {} m, above the {MAX_WAVE_HEIGHT_M} m a sea state reaches",
                    k % g.grid.nx,
                    k / g.grid.nx,
                    layer[k]
                ),
            ));
        }
    }
    Ok(())
}

/// What drives a `[vehicle]` (named `at`): thrusters, or the waves through acopf2016's
/// regression (eqs. 1-2) with the spec's coefficients over the defaults. The glider's fields
/// are refused for an AUV, and a speed range for a glider (its speed is not a decision).
pub(super) fn propulsion(s: &VehicleSpec, at: &str) -> Result<Propulsion> {
    let fields = [("wave_gain", s.wave_gain), ("current_gain", s.current_gain), ("min_speed", s.min_speed)];
    if s.kind == VehicleKind::Auv {
        if let Some((name, v)) = fields.iter().find_map(|(n, v)| v.map(|v| (n, v))) {
            return Err(Error::input(
                format!("{at}.{name}"),
                format!("= {v} belongs to a wave glider: set {at}.kind = \"wave-glider\" or remove it"),
            ));
        }
        return Ok(Propulsion::Thruster);
    }
    for (name, v) in [("speed_min", s.speed_min), ("speed_max", s.speed_max)] {
        if let Some(v) = v {
            return Err(Error::input(
                format!("{at}.{name}"),
                format!("= {v}: a wave glider's speed is set by the waves and the current, not chosen; remove it"),
            ));
        }
    }
    let mut g = GliderSpeed::default();
    // The ranges are the ones `tidepath vehicles` lists: declared once, with the model.
    for ((name, v), spec) in fields.into_iter().zip(GliderSpeed::PARAMS) {
        let Some(v) = v else { continue };
        debug_assert_eq!(name, spec.name);
        spec.range.check_number(v).map_err(|e| Error::input(format!("{at}.{name}"), e))?;
        match name {
            "wave_gain" => g.wave_gain = v,
            "current_gain" => g.current_gain = v,
            _ => g.min_speed = v,
        }
    }
    Ok(Propulsion::WaveGlider(g))
}

/// Fits a vehicle (named `at`) to the built world: a wave glider needs a 2-D world (it rides
/// the surface) and `[world.waves]` (they drive it), and its nominal speed, which cost models
/// normalise time by, becomes its still-water speed in the world's highest waves.
pub(super) fn fit_to_world(vehicle: &mut Vehicle, at: &str, world: &World) -> Result<()> {
    let Some(g) = vehicle.glider().copied() else { return Ok(()) };
    if world.dims != Dims::Two {
        return Err(Error::input(
            format!("{at}.kind"),
            "\"wave-glider\" rides the sea surface: it needs world.dimensions = 2, got 3",
        ));
    }
    if world.waves.is_none() {
        return Err(Error::input(
            "world.waves",
            format!("missing: {at}.kind = \"wave-glider\" is driven by the waves; give [world.waves]"),
        ));
    }
    vehicle.speed = g.best_speed(world.waves.height_bound(), 0.0);
    Ok(())
}
