//! Forecast files of geographic scenarios (currents and waves, NetCDF): read inside the
//! domain's longitude/latitude cover, resampled onto a metric grid, put on the scenario clock,
//! with the water nodes that lack data turned into gaps. The two differ only in which
//! variables they read and how a node's values turn into the frame (a current's east/north
//! vector is rotated, a wave height is a scalar); everything else is written once here.

use chrono::{DateTime, Utc};

use super::geographic::{cover, data_file};
use super::resample::{water_test, MetricGrid};
use super::spec::*;
use crate::geodata::currents::{read_currents, MAX_FORECAST_VALUES};
use crate::geodata::waves::read_waves;
use crate::geodata::{DataFile, Format, GeoBox, GeoGrid};
use tidepath::error::{Error, Result};
use tidepath::geo::GeoFrame;

/// A forecast resampled onto a metric grid: N values per node and time step.
struct Resampled<const N: usize> {
    origin: P2,
    spacing: P2,
    shape: [usize; 2],
    /// Seconds after the epoch.
    times: Vec<f64>,
    /// Per time step, one row-major layer per value.
    layers: Vec<[Vec<f64>; N]>,
    /// Water nodes without data at some time step, sorted.
    gaps: Vec<usize>,
}

/// What a forecast reads, for messages: "current" or "wave".
#[derive(Clone, Copy)]
struct Kind {
    name: &'static str,
    /// What its layers hold: "velocity", "wave height".
    layer: &'static str,
}

/// The data file at `path` (named `field.path`), which must be NetCDF.
fn open_forecast(path: &str, field: &str, kind: Kind, source: &str, warnings: &mut Vec<String>) -> Result<DataFile> {
    let path_field = format!("{field}.path");
    let file = data_file(path, source, &path_field, warnings)?;
    if Format::of(&file, &path_field)? != Format::NetCdf {
        return Err(Error::input(path_field, format!("`{path}`: {} forecasts are read from NetCDF (.nc)", kind.name)));
    }
    Ok(file)
}

/// Resamples the time steps `steps` (at `instants`) onto a metric grid over `world`'s domain:
/// times become seconds after `epoch` (the file's first time when the scenario gives none),
/// `convert` turns a node's values (at its (lon, lat) and (x, y)) into the frame, and water
/// nodes where any value is missing at any step (land or fill in the forecast) become gaps,
/// counted in a warning naming the first; their values are 0. Land nodes without data are NaN
/// for the caller to fill ([`fill_land`]).
#[allow(clippy::too_many_arguments)]
fn resample_steps<const N: usize>(
    field: &str,
    kind: Kind,
    instants: &[DateTime<Utc>],
    steps: &[[GeoGrid; N]],
    resolution: Option<f64>,
    (frame, world): (&GeoFrame, &WorldSpec),
    epoch: Option<DateTime<Utc>>,
    warnings: &mut Vec<String>,
    convert: impl Fn((f64, f64), (f64, f64), [f64; N]) -> [f64; N],
) -> Result<(Resampled<N>, DateTime<Utc>)> {
    let epoch = match (epoch, instants.first()) {
        (Some(e), _) => e,
        (None, Some(t)) => *t,
        (None, None) => {
            return Err(Error::input(
                "world.epoch",
                format!("the {} file has no time axis: give world.epoch", kind.name),
            ))
        }
    };
    let times: Vec<f64> = if instants.is_empty() {
        vec![0.0]
    } else {
        instants.iter().map(|t| (*t - epoch).num_milliseconds() as f64 / 1e3).collect()
    };
    let Some(first) = steps.first() else {
        return Err(Error::input(format!("{field}.path"), format!("no {} layer inside the box", kind.layer)));
    };
    let (lo, hi) = ([world.bounds.min[0], world.bounds.min[1]], [world.bounds.max[0], world.bounds.max[1]]);
    // All time steps share the grid: their product stays within the forecast limit too.
    let max_nodes = (MAX_FORECAST_VALUES / steps.len().max(1) as u64) as usize;
    let m =
        MetricGrid::new(&first[0], frame, (lo, hi), resolution, max_nodes, &format!("{field}.resolution"), warnings)?;
    let water = water_test(&world.terrain);
    let mut gaps: Vec<usize> = Vec::new();
    let mut layers = Vec::with_capacity(steps.len());
    for step in steps {
        let sampled: Vec<Vec<f64>> = step.iter().map(|g| m.sample(g, true)).collect();
        let mut out: [Vec<f64>; N] = std::array::from_fn(|_| Vec::with_capacity(m.lonlat.len()));
        for (k, &lonlat) in m.lonlat.iter().enumerate() {
            let values: [f64; N] = std::array::from_fn(|c| sampled[c][k]);
            let xy = m.xy(k);
            let node = if values.iter().all(|v| v.is_finite()) {
                convert(lonlat, xy, values)
            } else if water(xy.0, xy.1) {
                gaps.push(k);
                [0.0; N]
            } else {
                // Land: the caller decides what stands in (`fill_land`).
                [f64::NAN; N]
            };
            for (layer, v) in out.iter_mut().zip(node) {
                layer.push(v);
            }
        }
        layers.push(out);
    }
    gaps.sort_unstable();
    gaps.dedup();
    if let Some(&k) = gaps.first() {
        let (x, y) = m.xy(k);
        warnings.push(format!(
            "{field}: {} water nodes have no {} data at some time step (land or fill in the forecast); routes through them are refused; the first at {}",
            gaps.len(),
            kind.name,
            frame.place(x, y)
        ));
    }
    Ok((Resampled { origin: m.origin, spacing: m.spacing, shape: m.shape, times, layers, gaps }, epoch))
}

/// Reads the current forecast file of `current` (a `CurrentSpec::File`, named `field` in
/// errors) over the metric domain of `world` (already in metres, its terrain resampled) and
/// returns it as a metric `CurrentSpec::Grid` on the scenario clock, with the epoch used:
/// times are seconds after `epoch` (the file's first time when the scenario gives none),
/// vectors are turned from east/north into the frame's x/y (which differ by the meridian
/// convergence away from the origin), and water nodes without data (land or fill in the
/// forecast, at any time step) become gaps: a motion through their cells is invalid and
/// names where, since a current made up there could carry a plan onto the rocks. Counted in a
/// warning.
pub(super) fn forecast_grid(
    current: &CurrentSpec,
    field: &str,
    frame: &GeoFrame,
    world: &WorldSpec,
    source: &str,
    epoch: Option<DateTime<Utc>>,
    warnings: &mut Vec<String>,
) -> Result<(CurrentSpec, DateTime<Utc>)> {
    let CurrentSpec::File { path, u, v, depth, resolution } = current.clone() else {
        return Err(Error::input(format!("{field}.kind"), "a forecast file needs kind = \"file\""));
    };
    let kind = Kind { name: "current", layer: "velocity" };
    let file = open_forecast(&path, field, kind, source, warnings)?;
    let depth = depth.unwrap_or(0.0);
    if !depth.is_finite() || !(0.0..=12_000.0).contains(&depth) {
        return Err(Error::input(format!("{field}.depth"), format!("must be from 0 to 12000 m, got {depth}")));
    }
    let subset = domain_cover(frame, world)?;
    let series = read_currents(&file, u.as_deref(), v.as_deref(), depth, Some(&subset), 1)?;
    let steps: Vec<[GeoGrid; 2]> = series.u.into_iter().zip(series.v).map(|(u, v)| [u, v]).collect();
    let (r, epoch) = resample_steps(
        field,
        kind,
        &series.times,
        &steps,
        resolution,
        (frame, world),
        epoch,
        warnings,
        |ll, xy, [e, n]| {
            let (u, v) = frame.east_north_to_xy(ll, xy, e, n);
            [u, v]
        },
    )?;
    // No current runs into land: 0 at land nodes.
    let (u, v) = r
        .layers
        .into_iter()
        .map(|[mut u, mut v]| {
            fill_land(&mut u, r.shape, false);
            fill_land(&mut v, r.shape, false);
            (u, v)
        })
        .unzip();
    let grid = CurrentSpec::Grid {
        origin: r.origin,
        spacing: r.spacing,
        shape: r.shape,
        times: r.times,
        u,
        v,
        no_data: r.gaps,
    };
    Ok((grid, epoch))
}

/// Reads the wave forecast file of `[world.waves] kind = "file"` over the metric domain and
/// rewrites `world.waves` as a metric `WavesSpec::Grid` on the scenario clock, like a current
/// forecast ([`forecast_grid`]): water nodes without a height (land or fill) become gaps,
/// where a wave glider's motion is invalid. Returns the epoch used.
pub(super) fn load_waves(
    spec: &mut ScenarioSpec,
    frame: &GeoFrame,
    source: &str,
    epoch: Option<DateTime<Utc>>,
    warnings: &mut Vec<String>,
) -> Result<DateTime<Utc>> {
    const F: &str = "world.waves";
    let Some(WavesSpec::File { path, variable, resolution }) = spec.world.waves.clone() else {
        return Err(Error::input(format!("{F}.kind"), "a forecast file needs kind = \"file\""));
    };
    let kind = Kind { name: "wave", layer: "wave height" };
    let file = open_forecast(&path, F, kind, source, warnings)?;
    let subset = domain_cover(frame, &spec.world)?;
    let series = read_waves(&file, variable.as_deref(), Some(&subset), 1)?;
    let steps: Vec<[GeoGrid; 1]> = series.height.into_iter().map(|h| [h]).collect();
    let (r, epoch) =
        resample_steps(F, kind, &series.times, &steps, resolution, (frame, &spec.world), epoch, warnings, |_, _, h| h)?;
    // Near the coast the sea state is the nearest sea node's, not a calm invented by the land
    // mask (which would slow a glider in the last cells before land).
    let height = r
        .layers
        .into_iter()
        .map(|[mut h]| {
            fill_land(&mut h, r.shape, true);
            h
        })
        .collect();
    spec.world.waves = Some(WavesSpec::Grid {
        origin: r.origin,
        spacing: r.spacing,
        shape: r.shape,
        times: r.times,
        height,
        no_data: r.gaps,
    });
    Ok(epoch)
}

/// The longitude/latitude box holding `world`'s metric domain.
fn domain_cover(frame: &GeoFrame, world: &WorldSpec) -> Result<GeoBox> {
    cover(frame, [world.bounds.min[0], world.bounds.min[1]], [world.bounds.max[0], world.bounds.max[1]])
}

/// Replaces the NaN (land) nodes of a row-major `[nx, ny]` layer: with 0, or with the value of
/// the nearest node that has one (breadth-first over the 4-neighbours, so ties go to the node
/// reached first in a fixed order: deterministic). A layer with no value at all becomes 0.
fn fill_land(layer: &mut [f64], [nx, ny]: [usize; 2], nearest: bool) {
    if !nearest {
        for v in layer.iter_mut().filter(|v| v.is_nan()) {
            *v = 0.0;
        }
        return;
    }
    let mut queue: std::collections::VecDeque<usize> = (0..layer.len()).filter(|&k| !layer[k].is_nan()).collect();
    while let Some(k) = queue.pop_front() {
        let (i, j) = (k % nx, k / nx);
        let around = [
            (i > 0).then(|| k - 1),
            (i + 1 < nx).then(|| k + 1),
            (j > 0).then(|| k - nx),
            (j + 1 < ny).then(|| k + nx),
        ];
        for n in around.into_iter().flatten() {
            if layer[n].is_nan() {
                layer[n] = layer[k];
                queue.push_back(n);
            }
        }
    }
    for v in layer.iter_mut().filter(|v| v.is_nan()) {
        *v = 0.0;
    }
}

#[cfg(test)]
mod tests {
    use super::fill_land;

    #[test]
    fn land_takes_zero_or_the_nearest_sea_value() {
        let nan = f64::NAN;
        // 4 x 2 nodes: sea at the west and east ends, land between.
        let mut layer = [1.0, nan, nan, 3.0, 1.5, nan, nan, nan];
        let mut zero = layer;
        fill_land(&mut zero, [4, 2], false);
        assert_eq!(zero, [1.0, 0.0, 0.0, 3.0, 1.5, 0.0, 0.0, 0.0]);
        fill_land(&mut layer, [4, 2], true);
        // Node 1 is next to 1.0, node 2 and node 7 next to 3.0, node 5 next to 1.5; node 6 is
        // two steps from 3.0 (via 2 or 7) and from 1.5 (via 5): the queue, in node order,
        // reaches it first from node 2.
        assert_eq!(layer, [1.0, 1.0, 3.0, 3.0, 1.5, 1.5, 3.0, 3.0]);
        let mut empty = [nan; 3];
        fill_land(&mut empty, [3, 1], true);
        assert_eq!(empty, [0.0; 3]);
    }
}
