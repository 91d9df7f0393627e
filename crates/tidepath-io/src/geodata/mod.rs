//! Gridded geographic data from the files users have: bathymetry (NetCDF, GeoTIFF, ESRI ASCII
//! grid) and current forecasts (NetCDF). Every reader returns the same shape, a [`GeoGrid`] on
//! longitude/latitude axes, read only inside the requested [`GeoBox`] where the format allows.
//! Projection into the local metric frame is [`tidepath::geo`]'s job, not the readers'.

pub mod currents;
pub mod esri_ascii;
pub mod geotiff;
pub mod netcdf;
pub mod waves;

use std::path::{Path, PathBuf};

use tidepath::error::{Error, Result};

/// Where a data file's bytes come from: a path, or data built into the binary (the built-in
/// scenarios' seabeds, so they work from any directory).
#[derive(Clone, Debug)]
pub enum DataFile {
    Path(PathBuf),
    Embedded { name: &'static str, bytes: &'static [u8] },
}

impl DataFile {
    /// The name shown in messages.
    pub fn display(&self) -> String {
        match self {
            DataFile::Path(p) => p.display().to_string(),
            DataFile::Embedded { name, .. } => format!("builtin:{name}"),
        }
    }

    /// The file name's extension, lower case.
    pub fn extension(&self) -> String {
        let name = match self {
            DataFile::Path(p) => p.as_path(),
            DataFile::Embedded { name, .. } => Path::new(name),
        };
        name.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase()
    }
}

/// Data files built into the binary, by the name scenarios use for them.
pub const EMBEDDED: &[(&str, &[u8])] = &[
    ("salish_topobathy.nc", include_bytes!("../../data/salish_topobathy.nc")),
    ("salish_forecast.nc", include_bytes!("../../data/salish_forecast.nc")),
    ("salish_forecast_update.nc", include_bytes!("../../data/salish_forecast_update.nc")),
    ("glider_ocean.nc", include_bytes!("../../data/glider_ocean.nc")),
    ("glider_ocean_topo.nc", include_bytes!("../../data/glider_ocean_topo.nc")),
];

/// Refuses a file of no bytes in one line that says so (rather than a format's complaint
/// about its first bytes).
pub(crate) fn check_not_empty(file: &DataFile) -> Result<()> {
    let len = match file {
        DataFile::Path(p) => std::fs::metadata(p).map(|m| m.len()).unwrap_or(1),
        DataFile::Embedded { bytes, .. } => bytes.len() as u64,
    };
    if len == 0 {
        return Err(Error::input(file.display(), "the file is empty (0 bytes)"));
    }
    Ok(())
}

/// The file formats bathymetry can come in, by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    NetCdf,
    EsriAscii,
    GeoTiff,
}

impl Format {
    /// The format of `file` by its extension; `field` names the input in errors.
    pub fn of(file: &DataFile, field: &str) -> Result<Self> {
        match file.extension().as_str() {
            "nc" | "nc4" | "cdf" | "netcdf" | "grd" => Ok(Format::NetCdf),
            "asc" => Ok(Format::EsriAscii),
            "tif" | "tiff" => Ok(Format::GeoTiff),
            other => Err(Error::input(
                field,
                format!("`{}`: unknown data format `.{other}` (known: .nc .nc4 .cdf .grd for NetCDF, .tif .tiff for GeoTIFF, .asc for ESRI ASCII grid)", file.display()),
            )),
        }
    }
}

/// A longitude/latitude box in degrees. `west > east` means the box crosses the antimeridian
/// (e.g. west 179, east -179 is a 2-degree box).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GeoBox {
    pub west: f64,
    pub south: f64,
    pub east: f64,
    pub north: f64,
}

impl GeoBox {
    /// Checks the values; `field` names the scenario field for error messages.
    pub fn new(west: f64, south: f64, east: f64, north: f64, field: &str) -> Result<Self> {
        for (name, v, lim) in
            [("west", west, 180.0), ("east", east, 180.0), ("south", south, 90.0), ("north", north, 90.0)]
        {
            if !v.is_finite() || v.abs() > lim {
                return Err(Error::input(
                    format!("{field}.{name}"),
                    format!("must be within [-{lim}, {lim}] degrees, got {v}"),
                ));
            }
        }
        if south >= north {
            return Err(Error::input(field, format!("south ({south}) must be below north ({north})")));
        }
        if west == east {
            return Err(Error::input(field, format!("west and east are both {west}: the box has no width")));
        }
        Ok(Self { west, south, east, north })
    }

    /// Width in degrees of longitude (through the antimeridian when `west > east`).
    pub fn width(&self) -> f64 {
        if self.west < self.east {
            self.east - self.west
        } else {
            self.east + 360.0 - self.west
        }
    }

    /// The box's east edge as a longitude at or above `west` (adds 360 across the antimeridian).
    pub fn east_unwrapped(&self) -> f64 {
        self.west + self.width()
    }
}

/// How every reader's "too few nodes" error begins, so that a scenario can name its
/// `decimate` setting when decimation is what left too few.
pub const TOO_FEW_NODES: &str = "needs at least 2 x 2 nodes";

/// `e`, renamed to the `decimate` setting `field` when decimation by `decimate` left fewer than
/// 2 x 2 nodes of `file`: the setting, not the file, is what to change.
pub fn name_decimate(e: Error, decimate: usize, field: &str, file: &str) -> Error {
    match e {
        Error::Input { message, .. } if decimate > 1 && message.starts_with(TOO_FEW_NODES) => Error::input(
            field,
            format!("{decimate} leaves too few nodes of `{file}` inside the box ({message}); use a smaller value"),
        ),
        other => other,
    }
}

/// The index range `(first, last)` of a monotonic axis (either direction) that the interval
/// `lo..=hi` needs: the nodes inside it and one more beyond each end, or, when no node lies
/// inside (an interval smaller than one cell), the two nodes bracketing it; so every point of
/// the interval can be interpolated. `None` when the interval lies outside the axis.
pub(crate) fn axis_span(n: usize, value: impl Fn(usize) -> f64, lo: f64, hi: f64) -> Option<(usize, usize)> {
    let inside = |k: usize| (lo..=hi).contains(&value(k));
    match ((0..n).find(|&k| inside(k)), (0..n).rev().find(|&k| inside(k))) {
        (Some(a), Some(b)) => {
            let (a, b) = (a.min(b), a.max(b));
            Some((a.saturating_sub(1), (b + 1).min(n - 1)))
        }
        _ => (0..n.saturating_sub(1))
            .find(|&k| {
                let (p, q) = (value(k), value(k + 1));
                p.min(q) < lo && p.max(q) > hi
            })
            .map(|k| (k, k + 1)),
    }
}

/// The longitude index runs `(first, last)` a box needs on an increasing or decreasing axis of
/// `n` longitudes (`value(k)`, any multiple of 360 apart from the box): the nodes inside it
/// plus one beyond each run's ends, or the two bracketing a box narrower than one cell. On a
/// global axis (its nodes going all the way round) the node beyond an end is taken across the
/// axis's seam. Empty when no node is inside or brackets the box.
pub(crate) fn lon_runs(n: usize, value: impl Fn(usize) -> f64, b: Option<&GeoBox>) -> Vec<(usize, usize)> {
    use esri_ascii::inside_lon;
    if n == 0 {
        return Vec::new();
    }
    let Some(bx) = b else { return vec![(0, n - 1)] };
    let step = if n > 1 { (value(n - 1) - value(0)) / (n - 1) as f64 } else { 0.0 };
    let global = n > 2 && ((value(n - 1) - value(0)).abs() + step.abs() - 360.0).abs() < 1e-6 * step.abs().max(1e-9);
    let mut keep: Vec<bool> = (0..n).map(|k| inside_lon(b, value(k))).collect();
    if keep.iter().any(|&x| x) {
        let mut grown = keep.clone();
        for k in 0..n {
            if keep[k] {
                match (k.checked_sub(1), global) {
                    (Some(p), _) => grown[p] = true,
                    (None, true) => grown[n - 1] = true,
                    _ => {}
                }
                match (k + 1 < n, global) {
                    (true, _) => grown[k + 1] = true,
                    (false, true) => grown[0] = true,
                    _ => {}
                }
            }
        }
        keep = grown;
    } else {
        // A box between two nodes: the pair whose interval (modulo 360) holds it.
        let pairs = (0..n - 1).map(|k| (k, k + 1)).chain(global.then_some((n - 1, 0)));
        for (p, q) in pairs {
            let (a, c) = if step > 0.0 { (p, q) } else { (q, p) };
            let span = (value(c) - value(a)).rem_euclid(360.0);
            if (bx.west - value(a)).rem_euclid(360.0) + bx.width() <= span {
                keep[p] = true;
                keep[q] = true;
                break;
            }
        }
    }
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for (k, _) in keep.iter().enumerate().filter(|(_, &x)| x) {
        match runs.last_mut() {
            Some((_, last)) if *last + 1 == k => *last = k,
            _ => runs.push((k, k)),
        }
    }
    runs
}

/// How many of an axis's `n` longitudes to use: all but the last when it repeats the first a
/// full turn later (global files holding both -180 and 180, or 0 and 360), which would
/// otherwise give two columns at one place.
pub(crate) fn distinct_lons(n: usize, value: impl Fn(usize) -> f64) -> usize {
    if n > 2 && ((value(n - 1) - value(0)).abs() - 360.0).abs() < 1e-9 * 360.0 {
        n - 1
    } else {
        n
    }
}

/// The last index to read from `first` towards `last` every `decimate` nodes so that the
/// kept nodes still reach `last` (the bracketing node), within an axis of `n` nodes.
pub(crate) fn decimated_last(first: usize, last: usize, decimate: usize, n: usize) -> usize {
    let d = decimate.max(1);
    let end = first + (last - first).div_ceil(d) * d;
    if end < n {
        end
    } else {
        first + (n - 1 - first) / d * d
    }
}

/// Values on a longitude/latitude lattice: node `(i, j)` is at `(lon[i], lat[j])` and holds
/// `values[j * lon.len() + i]`; `NaN` where the file has no data (fill, missing or masked).
///
/// Both axes are strictly increasing. Longitudes are continuous across the antimeridian (a
/// box from 179 to -179 comes back as 179 ... 181), so interpolation never sees a jump.
#[derive(Clone, Debug, PartialEq)]
pub struct GeoGrid {
    pub lon: Vec<f64>,
    pub lat: Vec<f64>,
    pub values: Vec<f64>,
}

impl GeoGrid {
    /// Checks the axes and sizes; `what` names the file or variable for error messages.
    pub fn new(lon: Vec<f64>, lat: Vec<f64>, values: Vec<f64>, what: &str) -> Result<Self> {
        if lon.len() < 2 || lat.len() < 2 {
            return Err(Error::input(what, format!("{TOO_FEW_NODES}, got {} x {}", lon.len(), lat.len())));
        }
        for (name, axis) in [("longitude", &lon), ("latitude", &lat)] {
            if let Some(k) = axis.windows(2).position(|w| w[1] <= w[0] || !w[0].is_finite() || !w[1].is_finite()) {
                return Err(Error::input(
                    what,
                    format!(
                        "{name} axis is not strictly increasing and finite at index {k}: {} then {}",
                        axis[k],
                        axis[k + 1]
                    ),
                ));
            }
        }
        if values.len() != lon.len() * lat.len() {
            return Err(Error::input(what, format!("{} values for {} x {} nodes", values.len(), lon.len(), lat.len())));
        }
        Ok(Self { lon, lat, values })
    }

    pub fn nx(&self) -> usize {
        self.lon.len()
    }

    pub fn ny(&self) -> usize {
        self.lat.len()
    }

    pub fn value(&self, i: usize, j: usize) -> f64 {
        self.values[j * self.lon.len() + i]
    }

    /// Bilinear interpolation at (`lon`, `lat`); `None` outside the grid. A `NaN` corner with
    /// non-zero weight gives `NaN` (no data is never blended with data).
    pub fn sample(&self, lon: f64, lat: f64) -> Option<f64> {
        let (i, fx) = bracket(&self.lon, lon)?;
        let (j, fy) = bracket(&self.lat, lat)?;
        let mut acc = 0.0;
        for (di, wx) in [(0, 1.0 - fx), (1, fx)] {
            for (dj, wy) in [(0, 1.0 - fy), (1, fy)] {
                let w = wx * wy;
                if w > 0.0 {
                    acc += w * self.value(i + di, j + dj);
                }
            }
        }
        Some(acc)
    }
}

impl GeoGrid {
    /// Like [`GeoGrid::sample`], but corners without data are left out and the others'
    /// weights renormalised: a point between a sea node and a land node takes the sea value
    /// (how currents are extended to a coastline finer than their grid). `NaN` only when no
    /// corner with weight has data.
    pub fn sample_valid(&self, lon: f64, lat: f64) -> Option<f64> {
        let (i, fx) = bracket(&self.lon, lon)?;
        let (j, fy) = bracket(&self.lat, lat)?;
        let (mut acc, mut wsum) = (0.0, 0.0);
        for (di, wx) in [(0, 1.0 - fx), (1, fx)] {
            for (dj, wy) in [(0, 1.0 - fy), (1, fy)] {
                let (w, v) = (wx * wy, self.value(i + di, j + dj));
                if w > 0.0 && v.is_finite() {
                    acc += w * v;
                    wsum += w;
                }
            }
        }
        Some(if wsum > 0.0 { acc / wsum } else { f64::NAN })
    }
}

/// The interval of the increasing `axis` holding `x` and the fraction along it; `None`
/// outside. Axes may be irregular (binary search).
fn bracket(axis: &[f64], x: f64) -> Option<(usize, f64)> {
    let (first, last) = (axis[0], axis[axis.len() - 1]);
    if x.is_nan() || x < first || x > last {
        return None;
    }
    let k = axis.partition_point(|&a| a <= x).clamp(1, axis.len() - 1) - 1;
    let f = ((x - axis[k]) / (axis[k + 1] - axis[k])).clamp(0.0, 1.0);
    Some((k, f))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> GeoGrid {
        GeoGrid::new(vec![0.0, 1.0, 3.0], vec![10.0, 11.0], vec![0.0, 1.0, 3.0, 10.0, 11.0, 13.0], "t").unwrap()
    }

    #[test]
    fn bilinear_on_an_irregular_axis() {
        let g = grid();
        assert_eq!(g.sample(0.5, 10.0), Some(0.5));
        assert_eq!(g.sample(2.0, 10.5), Some(7.0));
        assert_eq!(g.sample(3.0, 11.0), Some(13.0));
        assert_eq!(g.sample(3.1, 11.0), None);
        assert_eq!(g.sample(f64::NAN, 11.0), None);
    }

    #[test]
    fn sample_valid_leaves_out_corners_without_data() {
        let mut g = grid();
        g.values[0] = f64::NAN;
        // Corners (0,0)=NaN, (1,0)=1, (0,1)=10, (1,1)=11 with equal weights: mean of the rest.
        assert!((g.sample_valid(0.5, 10.5).unwrap() - 22.0 / 3.0).abs() < 1e-12);
        g.values = vec![f64::NAN; 6];
        assert!(g.sample_valid(0.5, 10.5).unwrap().is_nan());
    }

    #[test]
    fn no_data_is_not_blended() {
        let mut g = grid();
        g.values[0] = f64::NAN;
        assert!(g.sample(0.5, 10.5).unwrap().is_nan());
        assert_eq!(g.sample(1.0, 11.0), Some(11.0));
    }

    #[test]
    fn axes_and_sizes_are_checked() {
        assert!(GeoGrid::new(vec![0.0, 0.0], vec![0.0, 1.0], vec![0.0; 4], "f")
            .unwrap_err()
            .to_string()
            .contains("longitude"));
        assert!(GeoGrid::new(vec![0.0, 1.0], vec![0.0, 1.0], vec![0.0; 3], "f").is_err());
    }

    #[test]
    fn boxes_across_the_antimeridian() {
        let b = GeoBox::new(179.0, -1.0, -179.0, 1.0, "box").unwrap();
        assert_eq!(b.width(), 2.0);
        assert_eq!(b.east_unwrapped(), 181.0);
        assert!(GeoBox::new(0.0, 1.0, 1.0, 0.0, "box").is_err());
        assert!(GeoBox::new(0.0, 0.0, 181.0, 1.0, "box").unwrap_err().to_string().contains("box.east"));
    }
}
