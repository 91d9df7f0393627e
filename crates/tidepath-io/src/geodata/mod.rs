//! Gridded geographic data from the files users have: bathymetry (NetCDF, GeoTIFF, ESRI ASCII
//! grid) and current forecasts (NetCDF). Every reader returns the same shape, a [`GeoGrid`] on
//! longitude/latitude axes, read only inside the requested [`GeoBox`] where the format allows.
//! Projection into the local metric frame is [`tidepath::geo`]'s job, not the readers'.

pub mod currents;
pub mod esri_ascii;
pub mod geotiff;
pub mod netcdf;

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
];

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
