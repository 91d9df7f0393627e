//! Gridded wave forecasts from NetCDF: the significant wave height of Copernicus Marine's wave
//! products (`VHM0`), ERA5 (`swh`), WAVEWATCH III (`hs`) or any CF file whose variable carries
//! the standard name `sea_surface_wave_significant_height`. The file is read like a current
//! forecast ([`super::currents`]): time decoded with its CF units and calendar, only the
//! requested box, fill values and land as `NaN`.

use chrono::{DateTime, Utc};
use netcdf_reader::{NcFile, NcVariable};

use super::currents::{read_steps, Axes};
use super::netcdf::{open, Layout};
use super::{DataFile, GeoBox, GeoGrid};
use tidepath::error::{Error, Result};

/// The CF standard name of a significant wave height.
pub const STANDARD_NAME: &str = "sea_surface_wave_significant_height";
/// Names taken for a significant wave height when no variable carries the standard name
/// (compared without case: `Hs`, `SWH` too).
pub const NAMES: &[&str] = &["VHM0", "swh", "hs"];

/// The significant wave height (m) at each time step, on longitude/latitude.
#[derive(Clone, Debug)]
pub struct WaveSeries {
    pub times: Vec<DateTime<Utc>>,
    pub height: Vec<GeoGrid>,
    /// The variable read.
    pub variable: String,
}

/// Finds the height variable: `name` (exactly, else without case), else the first variable of
/// two or more dimensions with the standard name, else one named as in [`NAMES`].
fn find<'a>(file: &'a NcFile, name: Option<&str>, what: &str) -> Result<&'a NcVariable> {
    let vars = file.variables().map_err(|e| Error::input(what, e.to_string()))?;
    let listing = || vars.iter().map(|v| v.name()).collect::<Vec<_>>().join(", ");
    if let Some(n) = name {
        return vars
            .iter()
            .find(|v| v.name() == n)
            .or_else(|| vars.iter().find(|v| v.name().eq_ignore_ascii_case(n)))
            .ok_or_else(|| {
                Error::input("world.waves.variable", format!("`{n}` not found in {what}; variables: {}", listing()))
            });
    }
    let std_name = |v: &NcVariable| v.attribute("standard_name").and_then(|a| a.value.as_string()).unwrap_or_default();
    let fields = || vars.iter().filter(|v| v.ndim() >= 2);
    fields()
        .find(|v| std_name(v).trim() == STANDARD_NAME)
        .or_else(|| NAMES.iter().find_map(|n| fields().find(|v| v.name().eq_ignore_ascii_case(n))))
        .ok_or_else(|| {
            Error::input(
                what,
                format!(
                    "no significant wave height found (standard name {STANDARD_NAME}, or a variable named {}; name it with world.waves.variable); variables: {}",
                    NAMES.join(", "),
                    listing()
                ),
            )
        })
}

/// Reads the significant wave height from `file` inside `subset`, every `decimate`-th node;
/// a depth axis, if any, at its level nearest the surface. Every error after the variable is
/// found names the file and the variable in one line.
pub fn read_waves(file: &DataFile, name: Option<&str>, subset: Option<&GeoBox>, decimate: usize) -> Result<WaveSeries> {
    let what = file.display();
    let nc = open(file)?;
    let var = find(&nc, name, &what)?;
    let vname = var.name().to_string();
    let read = || -> Result<WaveSeries> {
        let layout = Layout::of(&nc, var, &what)?;
        let axes = Axes::of(&nc, var, 0.0, &what)?;
        let (times, steps) = read_steps(&nc, &layout, [var], axes, subset, decimate, &what)?;
        let height = steps.into_iter().map(|[h]| h).collect();
        Ok(WaveSeries { times, height, variable: vname.clone() })
    };
    read().map_err(|e| match e {
        Error::Input { field, message } if !message.contains(&format!("`{vname}`")) => {
            Error::input(field, format!("wave height `{vname}`: {message}"))
        }
        e => e,
    })
}
