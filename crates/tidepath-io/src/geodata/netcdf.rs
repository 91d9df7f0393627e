//! NetCDF bathymetry and currents (classic CDF-1, 64-bit offset CDF-2, CDF-5 and NetCDF-4/HDF5)
//! through the pure-Rust `netcdf-reader` crate, with the CF conventions users' files follow:
//!
//! * latitude and longitude are found by `axis`, `standard_name` or `units` on the variable's
//!   coordinate variables (the crate's CF axis rules), so `lat`/`lon`, `latitude`/`longitude`,
//!   `y`/`x` with degree units all work;
//! * `scale_factor`, `add_offset`, `_FillValue`, `missing_value` and `valid_range` are applied
//!   (no data becomes `NaN`), and so are values beyond 1e30 (NetCDF's default fill values,
//!   which files written without `_FillValue` contain where nothing was written);
//! * longitudes in 0..360 or -180..180, latitudes ascending or descending, and a requested box
//!   crossing the antimeridian: only the needed index runs are read (one hyperslab per run),
//!   with one node beyond each edge of the box so every point inside can be interpolated.

use netcdf_reader::{NcFile, NcSliceInfo, NcSliceInfoElem, NcVariable};

use super::esri_ascii::{reorder_by_lon, unwrap_lon};
use super::{DataFile, GeoBox, GeoGrid};
use tidepath::error::{Error, Result};

/// Values beyond this magnitude are no data (NetCDF's default fills are about 9.97e36).
const FILL_MAGNITUDE: f64 = 1e30;

/// Most values one read may return: 2^28 (2 GiB as f64). A box larger than this needs
/// `decimate`; the error says so.
pub const MAX_VALUES: u64 = 1 << 28;

/// Most nodes a coordinate axis (longitude, latitude, depth) may have: 2^24, far beyond the
/// finest global grid (GEBCO's 86,400 longitudes); checked from the header before reading, so a
/// crafted file cannot make a coordinate read allocate gigabytes.
pub const MAX_AXIS: u64 = 1 << 24;

/// Refuses a one-dimensional coordinate variable longer than `limit` before it is read.
pub(crate) fn check_axis(c: &NcVariable, limit: u64, what: &str) -> Result<()> {
    let n = c.num_elements().unwrap_or(u64::MAX);
    if n > limit {
        return Err(Error::input(
            what,
            format!("coordinate `{}` has {n} values, more than the limit of {limit}", c.name()),
        ));
    }
    Ok(())
}

/// Standard names and variable names taken for elevation (up positive) when the user names no
/// variable, and those taken for depth (down positive).
const ELEVATION_NAMES: &[&str] = &[
    "height_above_reference_ellipsoid",
    "height_above_mean_sea_level",
    "altitude",
    "height",
    "surface_altitude",
    "elevation",
    "z",
    "Band1",
    "topo",
    "bathymetry",
];
const DEPTH_NAMES: &[&str] = &["sea_floor_depth_below_sea_surface", "sea_floor_depth_below_geoid", "depth", "deptho"];

/// Which way a bathymetry variable's values point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Positive {
    /// Elevation: up positive, the seabed negative (GEBCO, ETOPO).
    Up,
    /// Depth: down positive (many model bathymetries).
    Down,
}

/// Opens a NetCDF file; errors name the path.
pub fn open(file: &DataFile) -> Result<NcFile> {
    let opened = match file {
        DataFile::Path(path) => {
            crate::input::regular_file(path, &file.display())?;
            super::check_not_empty(file)?;
            NcFile::open(path)
        }
        DataFile::Embedded { bytes, .. } => {
            super::check_not_empty(file)?;
            NcFile::from_bytes(bytes)
        }
    };
    opened.map_err(|e| Error::input(file.display(), format!("not a readable NetCDF file: {e}")))
}

/// Reads a bathymetry grid as elevation (up positive): the variable named `variable` or the
/// one found by name and standard name, inside `subset`, every `decimate`-th node. `positive`
/// overrides the sign convention found from the variable's attributes.
pub fn read_bathymetry(
    file: &DataFile,
    variable: Option<&str>,
    positive: Option<Positive>,
    subset: Option<&GeoBox>,
    decimate: usize,
) -> Result<GeoGrid> {
    let what = file.display();
    let file = open(file)?;
    let var = match variable {
        Some(name) => file.variable(name).map_err(|_| {
            Error::input(format!("{what}: variable"), format!("`{name}` not found; variables: {}", names(&file)))
        })?,
        None => find_bathymetry(&file).ok_or_else(|| {
            Error::input(
                what.clone(),
                format!("no elevation or depth variable found (name one with `variable`); variables: {}", names(&file)),
            )
        })?,
    };
    let sign = match positive.unwrap_or_else(|| convention(var)) {
        Positive::Up => 1.0,
        Positive::Down => -1.0,
    };
    let layout = Layout::of(&file, var, &what)?;
    let mut grid = layout.read(&file, var, &[], subset, decimate, &what)?;
    for v in &mut grid.values {
        *v *= sign;
    }
    Ok(grid)
}

fn names(file: &NcFile) -> String {
    file.variables()
        .map(|vs| vs.iter().map(|v| v.name().to_string()).collect::<Vec<_>>().join(", "))
        .unwrap_or_default()
}

fn attr(var: &NcVariable, name: &str) -> Option<String> {
    var.attribute(name).and_then(|a| a.value.as_string()).map(|s| s.trim().to_string())
}

/// The first variable with two or more dimensions whose standard name or name says elevation
/// or depth (standard names first).
fn find_bathymetry(file: &NcFile) -> Option<&NcVariable> {
    let vars = file.variables().ok()?;
    let candidates = || vars.iter().filter(|v| v.ndim() >= 2);
    let all: Vec<&str> = ELEVATION_NAMES.iter().chain(DEPTH_NAMES).copied().collect();
    candidates()
        .find(|v| attr(v, "standard_name").is_some_and(|s| all.contains(&s.as_str())))
        .or_else(|| candidates().find(|v| all.iter().any(|n| n.eq_ignore_ascii_case(v.name()))))
}

/// Up or down, from `positive`, then the standard name, then the variable name.
fn convention(var: &NcVariable) -> Positive {
    if let Some(p) = attr(var, "positive") {
        return if p.eq_ignore_ascii_case("down") { Positive::Down } else { Positive::Up };
    }
    let depth = |s: &str| DEPTH_NAMES.iter().any(|n| n.eq_ignore_ascii_case(s));
    if attr(var, "standard_name").is_some_and(|s| depth(&s)) || depth(var.name()) {
        Positive::Down
    } else {
        Positive::Up
    }
}

/// Where longitude and latitude are among a variable's dimensions, and their values.
pub(crate) struct Layout {
    /// Dimension indices of longitude and latitude in the variable.
    x_dim: usize,
    y_dim: usize,
    lon: Vec<f64>,
    lat: Vec<f64>,
}

impl Layout {
    pub(crate) fn of(file: &NcFile, var: &NcVariable, what: &str) -> Result<Self> {
        use netcdf_reader::cf::CfAxisType;
        let mut x = None;
        let mut y = None;
        for (k, d) in var.dimensions().iter().enumerate() {
            let Ok(c) = file.variable(&d.name) else { continue };
            if c.ndim() != 1 {
                continue;
            }
            match netcdf_reader::cf::identify_axis(c) {
                CfAxisType::X => x = Some((k, c)),
                CfAxisType::Y => y = Some((k, c)),
                _ => {
                    // GMT-style `x`/`y` without units: take the names.
                    match d.name.as_str() {
                        "lon" | "longitude" | "x" if x.is_none() => x = Some((k, c)),
                        "lat" | "latitude" | "y" if y.is_none() => y = Some((k, c)),
                        _ => {}
                    }
                }
            }
        }
        let ((x_dim, xv), (y_dim, yv)) = match (x, y) {
            (Some(x), Some(y)) => (x, y),
            _ => {
                return Err(Error::input(
                    what,
                    format!(
                        "variable `{}`: no longitude and latitude coordinate variables among its dimensions ({})",
                        var.name(),
                        var.dimensions().iter().map(|d| d.name.as_str()).collect::<Vec<_>>().join(", ")
                    ),
                ))
            }
        };
        let read = |c: &NcVariable| -> Result<Vec<f64>> {
            check_axis(c, MAX_AXIS, what)?;
            let a = file
                .read_variable_unpacked(c.name())
                .map_err(|e| Error::input(what, format!("coordinate `{}`: {e}", c.name())))?;
            Ok(a.iter().copied().collect())
        };
        let (lon, lat) = (read(xv)?, read(yv)?);
        for (name, axis) in [(xv.name(), &lon), (yv.name(), &lat)] {
            let up = axis.windows(2).all(|w| w[1] > w[0]);
            let down = axis.windows(2).all(|w| w[1] < w[0]);
            if axis.len() < 2 || !(up || down) || axis.iter().any(|v| !v.is_finite()) {
                return Err(Error::input(what, format!("coordinate `{name}` is not monotonic and finite")));
            }
        }
        // A global axis holding both -180 and 180 (or 0 and 360): the last column repeats
        // the first, so it is left out.
        let mut lon = lon;
        lon.truncate(super::distinct_lons(lon.len(), |k| lon[k]));
        if lat.iter().any(|v| v.abs() > 90.0) {
            return Err(Error::input(what, format!("latitude `{}` has values beyond 90 degrees", yv.name())));
        }
        Ok(Self { x_dim, y_dim, lon, lat })
    }

    /// Reads `var` inside `subset`; `fixed` gives the index of every other dimension (in the
    /// variable's order, skipping longitude and latitude); a missing one must have size 1.
    pub(crate) fn read(
        &self,
        file: &NcFile,
        var: &NcVariable,
        fixed: &[(usize, u64)],
        subset: Option<&GeoBox>,
        decimate: usize,
        what: &str,
    ) -> Result<GeoGrid> {
        let decimate = decimate.max(1);
        let BoxRuns { runs, y0, y1, nx, ny } = self.box_runs(subset, decimate, what)?;
        let mut values = vec![f64::NAN; nx * ny];
        let mut lon = Vec::with_capacity(nx);
        let mut col = 0;
        for &(a, b) in &runs {
            let run_nx = (b - a) / decimate + 1;
            let mut sel = Vec::with_capacity(var.ndim());
            for (k, d) in var.dimensions().iter().enumerate() {
                let elem = if k == self.x_dim {
                    NcSliceInfoElem::Slice { start: a as u64, end: b as u64 + 1, step: decimate as u64 }
                } else if k == self.y_dim {
                    NcSliceInfoElem::Slice { start: y0 as u64, end: y1 as u64 + 1, step: decimate as u64 }
                } else if let Some(&(_, i)) = fixed.iter().find(|(dim, _)| *dim == k) {
                    NcSliceInfoElem::Index(i)
                } else if d.size == 1 {
                    NcSliceInfoElem::Index(0)
                } else {
                    return Err(Error::input(
                        what,
                        format!(
                            "variable `{}` has a dimension `{}` of size {}: say which index to use",
                            var.name(),
                            d.name,
                            d.size
                        ),
                    ));
                };
                sel.push(elem);
            }
            let data = file
                .read_variable_slice_unpacked_masked(var.name(), &NcSliceInfo { selections: sel })
                .map_err(|e| Error::input(what, format!("reading `{}`: {e}", var.name())))?;
            let x_first = self.x_dim < self.y_dim;
            let flat: Vec<f64> = data.iter().copied().collect();
            if flat.len() != run_nx * ny {
                return Err(Error::input(
                    what,
                    format!("reading `{}`: got {} values for {run_nx} x {ny}", var.name(), flat.len()),
                ));
            }
            for jj in 0..ny {
                for ii in 0..run_nx {
                    let v = if x_first { flat[ii * ny + jj] } else { flat[jj * run_nx + ii] };
                    values[jj * nx + col + ii] = if v.is_finite() && v.abs() < FILL_MAGNITUDE { v } else { f64::NAN };
                }
            }
            lon.extend((0..run_nx).map(|ii| self.lon[a + ii * decimate]));
            col += run_nx;
        }
        let mut lat: Vec<f64> = (0..ny).map(|jj| self.lat[y0 + jj * decimate]).collect();
        // Latitude descending in the file: flip rows.
        if lat.len() > 1 && lat[1] < lat[0] {
            lat.reverse();
            let mut flipped = Vec::with_capacity(values.len());
            for jj in (0..ny).rev() {
                flipped.extend_from_slice(&values[jj * nx..(jj + 1) * nx]);
            }
            values = flipped;
        }
        // Longitudes into one continuous range (0..360 files, boxes across the antimeridian),
        // then columns in increasing order.
        match subset {
            Some(_) => unwrap_lon(&mut lon, subset),
            None => {
                for x in lon.iter_mut() {
                    if *x > 180.0 {
                        *x -= 360.0;
                    }
                }
            }
        }
        reorder_by_lon(lon, lat, values, what)
    }

    /// The index runs of the box (with one node beyond each edge) and the size of the grid
    /// they make, checked against [`MAX_VALUES`] before anything is read.
    pub(crate) fn box_runs(&self, subset: Option<&GeoBox>, decimate: usize, what: &str) -> Result<BoxRuns> {
        let decimate = decimate.max(1);
        let (nlon, nlat) = (self.lon.len(), self.lat.len());
        // The nodes inside the box and one beyond each edge, or the two bracketing a box
        // smaller than one cell: every point of the box lies between nodes that are read.
        let runs: Vec<(usize, usize)> = super::lon_runs(nlon, |k| self.lon[k], subset)
            .into_iter()
            .map(|(a, b)| (a, super::decimated_last(a, b, decimate, nlon)))
            .collect();
        let (y0, y1) = match subset {
            None => (0, nlat - 1),
            Some(b) => super::axis_span(nlat, |k| self.lat[k], b.south, b.north)
                .ok_or_else(|| Error::input(what, "no latitude of the file lies inside or around the requested box"))?,
        };
        let y1 = super::decimated_last(y0, y1, decimate, nlat);
        if runs.is_empty() {
            return Err(Error::input(what, "no longitude of the file lies inside or around the requested box"));
        }
        let ny = (y1 - y0) / decimate + 1;
        let nx: usize = runs.iter().map(|&(a, b)| (b - a) / decimate + 1).sum();
        let total = nx as u64 * ny as u64;
        if total > MAX_VALUES {
            return Err(Error::input(
                what,
                format!("the box holds {nx} x {ny} values, more than the limit of {MAX_VALUES}: use a smaller box or decimate"),
            ));
        }
        Ok(BoxRuns { runs, y0, y1, nx, ny })
    }
}

/// Index runs of a box: longitude runs (first, last), the latitude range, and the grid size.
pub(crate) struct BoxRuns {
    runs: Vec<(usize, usize)>,
    y0: usize,
    y1: usize,
    pub(crate) nx: usize,
    pub(crate) ny: usize,
}
