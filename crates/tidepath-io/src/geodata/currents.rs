//! Gridded current forecasts from NetCDF, in the layouts of Copernicus Marine (`uo`, `vo`;
//! time, depth, latitude, longitude; often int16 packed) and HYCOM (`water_u`, `water_v`),
//! or any CF file whose eastward/northward velocity variables are named or carry the standard
//! names. The time axis is decoded with its CF units and calendar (`hours since 1950-01-01`
//! and the like) into UTC instants; one depth level is read (the one nearest the requested
//! depth), only inside the requested box.

use chrono::{DateTime, Utc};
use netcdf_reader::{NcFile, NcVariable};

use super::netcdf::{check_axis, open, Layout, MAX_AXIS};
use super::{DataFile, GeoBox, GeoGrid};
use tidepath::error::{Error, Result};

/// Most time steps read from one file: a year of hourly fields.
pub const MAX_TIMES: usize = 9000;

/// Most values of one velocity component a forecast may hold inside the box, over all its
/// time steps: 2^26 (512 MiB per component as f64). Each of the other limits holds alone, but
/// their product does not: 9,000 steps on 201 x 201 nodes would be 7.9 GB. Checked from the
/// header before any field is read.
pub const MAX_FORECAST_VALUES: u64 = 1 << 26;

const U_NAMES: &[&str] = &["uo", "water_u", "u", "uvel", "eastward_sea_water_velocity"];
const V_NAMES: &[&str] = &["vo", "water_v", "v", "vvel", "northward_sea_water_velocity"];

/// The eastward and northward velocity (m/s) at each time step, on longitude/latitude.
#[derive(Clone, Debug)]
pub struct CurrentSeries {
    pub times: Vec<DateTime<Utc>>,
    pub u: Vec<GeoGrid>,
    pub v: Vec<GeoGrid>,
    /// The depth (m, positive down) of the level read, when the file has a depth axis.
    pub depth: Option<f64>,
}

/// Finds a velocity variable: by `name`, else by the usual names and standard names.
fn find<'a>(file: &'a NcFile, name: Option<&str>, usual: &[&str], field: &str, what: &str) -> Result<&'a NcVariable> {
    let vars = file.variables().map_err(|e| Error::input(what, e.to_string()))?;
    let listing = || vars.iter().map(|v| v.name()).collect::<Vec<_>>().join(", ");
    if let Some(n) = name {
        return vars
            .iter()
            .find(|v| v.name() == n)
            .ok_or_else(|| Error::input(field, format!("`{n}` not found in {what}; variables: {}", listing())));
    }
    let std_name = |v: &NcVariable| v.attribute("standard_name").and_then(|a| a.value.as_string()).unwrap_or_default();
    usual.iter().find_map(|n| vars.iter().find(|v| v.name() == *n || std_name(v) == *n)).ok_or_else(|| {
        Error::input(field, format!("no velocity variable found in {what} (name it); variables: {}", listing()))
    })
}

/// Reads the current components from `file` inside `subset`, at the depth level nearest
/// `depth` (m, positive down).
pub fn read_currents(
    file: &DataFile,
    u_name: Option<&str>,
    v_name: Option<&str>,
    depth: f64,
    subset: Option<&GeoBox>,
    decimate: usize,
) -> Result<CurrentSeries> {
    let what = file.display();
    let nc = open(file)?;
    let u = find(&nc, u_name, U_NAMES, "world.current.u", &what)?;
    let v = find(&nc, v_name, V_NAMES, "world.current.v", &what)?;
    if u.dimensions().iter().map(|d| &d.name).ne(v.dimensions().iter().map(|d| &d.name)) {
        return Err(Error::input(what, format!("`{}` and `{}` do not share their dimensions", u.name(), v.name())));
    }
    let layout = Layout::of(&nc, u, &what)?;
    let axes = Axes::of(&nc, u, depth, &what)?;
    let depth = axes.level.map(|l| l.2);
    let (times, steps) = read_steps(&nc, &layout, [u, v], axes, subset, decimate, &what)?;
    let (u, v) = steps.into_iter().map(|[a, b]| (a, b)).unzip();
    Ok(CurrentSeries { times, u, v, depth })
}

/// The time and depth dimensions of a forecast variable, found by their coordinate variables'
/// CF axes: the time axis decoded with its units and calendar into UTC instants, the depth
/// level nearest the one asked for.
pub(crate) struct Axes {
    /// The time dimension's index in the variable and its instants.
    pub time: Option<(usize, Vec<DateTime<Utc>>)>,
    /// The depth dimension's index, the level's index on it and its depth (m, positive down).
    pub level: Option<(usize, u64, f64)>,
}

impl Axes {
    /// The axes of `var` in `nc` (named `what` in errors), the level nearest `depth` (m,
    /// positive down).
    pub(crate) fn of(nc: &NcFile, var: &NcVariable, depth: f64, what: &str) -> Result<Self> {
        use netcdf_reader::cf::CfAxisType;
        let what = what.to_string();
        let mut time: Option<(usize, Vec<DateTime<Utc>>)> = None;
        let mut level: Option<(usize, u64, f64)> = None;
        for (k, d) in var.dimensions().iter().enumerate() {
            let Ok(c) = nc.variable(&d.name) else { continue };
            match netcdf_reader::cf::identify_axis(c) {
                CfAxisType::T => time = Some((k, time_axis(nc, c, &what)?)),
                CfAxisType::Z => {
                    check_axis(c, MAX_AXIS, &what)?;
                    let values =
                        nc.read_variable_as_f64(c.name()).map_err(|e| Error::input(what.clone(), e.to_string()))?;
                    let up =
                        c.attribute("positive").and_then(|a| a.value.as_string()).is_some_and(|p| p.trim() == "up");
                    let depths: Vec<f64> = values.iter().map(|&z| if up { -z } else { z }).collect();
                    let (best, &d) = depths
                        .iter()
                        .enumerate()
                        .min_by(|a, b| (a.1 - depth).abs().total_cmp(&(b.1 - depth).abs()))
                        .ok_or_else(|| Error::input(what.clone(), format!("depth axis `{}` is empty", c.name())))?;
                    level = Some((k, best as u64, d));
                }
                _ => {}
            }
        }
        Ok(Self { time, level })
    }
}

/// The instants of the time coordinate `c`, checked increasing and at most [`MAX_TIMES`].
fn time_axis(nc: &NcFile, c: &NcVariable, what: &str) -> Result<Vec<DateTime<Utc>>> {
    let r = netcdf_reader::cf::time::time_ref_from_variable(c)
        .map_err(|e| Error::input(what, format!("time axis `{}`: {e}", c.name())))?
        .ok_or_else(|| Error::input(what, format!("time axis `{}` has no `units ... since ...`", c.name())))?;
    let steps = c.num_elements().unwrap_or(u64::MAX);
    if steps > MAX_TIMES as u64 {
        return Err(Error::input(what, format!("{steps} time steps, more than the limit of {MAX_TIMES}")));
    }
    let values = nc.read_variable_as_f64(c.name()).map_err(|e| Error::input(what, e.to_string()))?;
    let values: Vec<f64> = values.iter().copied().collect();
    if values.len() > MAX_TIMES {
        return Err(Error::input(what, format!("{} time steps, more than the limit of {MAX_TIMES}", values.len())));
    }
    let times = netcdf_reader::cf::time::decode_times(&values, &r)
        .map_err(|e| Error::input(what, format!("time axis `{}`: {e}", c.name())))?;
    if times.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Error::input(what, format!("time axis `{}` is not increasing", c.name())));
    }
    Ok(times)
}

/// A forecast's instants and, per time step, one grid per variable read.
pub(crate) type Steps<const N: usize> = (Vec<DateTime<Utc>>, Vec<[GeoGrid; N]>);

/// Reads the `N` variables `vars` (sharing `layout`'s dimensions) inside `subset` at every time
/// step of `axes`, at its depth level: the instants and, per step, one grid per variable.
/// The values held are checked against [`MAX_FORECAST_VALUES`] before any is read.
pub(crate) fn read_steps<const N: usize>(
    nc: &NcFile,
    layout: &Layout,
    vars: [&NcVariable; N],
    axes: Axes,
    subset: Option<&GeoBox>,
    decimate: usize,
    what: &str,
) -> Result<Steps<N>> {
    let (t_dim, times) = match axes.time {
        Some(t) => (Some(t.0), t.1),
        None => (None, Vec::new()),
    };
    let steps = times.len().max(1);
    let b = layout.box_runs(subset, decimate, what)?;
    let held = steps as u64 * b.nx as u64 * b.ny as u64;
    if held > MAX_FORECAST_VALUES {
        return Err(Error::input(
            what,
            format!(
                "the box holds {steps} time steps x {} x {} nodes = {held} values per component, more than the limit of {MAX_FORECAST_VALUES}: use a shorter forecast or a smaller box",
                b.nx, b.ny
            ),
        ));
    }
    let mut out = Vec::with_capacity(steps);
    for k in 0..steps {
        let mut fixed = Vec::new();
        if let Some(t) = t_dim {
            fixed.push((t, k as u64));
        }
        if let Some((d, i, _)) = axes.level {
            fixed.push((d, i));
        }
        let mut grids = Vec::with_capacity(N);
        for var in vars {
            grids.push(layout.read(nc, var, &fixed, subset, decimate, what)?);
        }
        out.push(grids.try_into().map_err(|_| Error::input(what, "internal: wrong number of grids"))?);
    }
    Ok((times, out))
}
