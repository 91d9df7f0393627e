//! ESRI ASCII grid (`.asc`): a six-line header (`ncols`, `nrows`, `xllcorner` or `xllcenter`,
//! `yllcorner` or `yllcenter`, `cellsize`, optional `NODATA_value`), then `nrows` rows of
//! values from north to south. Coordinates are taken as longitude/latitude degrees.
//!
//! Only the rows and columns inside the requested box are kept, so memory follows the box,
//! not the file (the text is still read once, line by line).

use std::io::BufRead;

use super::{DataFile, GeoBox, GeoGrid};
use crate::error::{Error, Result};

/// Most values a grid may have (rows x columns): 2^31, far beyond any ASCII grid one would
/// write, and checked before anything is allocated.
pub const MAX_VALUES: u64 = 1 << 31;

/// Reads `path`, keeping the nodes inside `subset` (all when `None`) and every `decimate`-th
/// row and column.
pub fn read(file: &DataFile, subset: Option<&GeoBox>, decimate: usize) -> Result<GeoGrid> {
    match file {
        DataFile::Path(path) => {
            let f = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
            read_from(std::io::BufReader::new(f), &file.display(), subset, decimate)
        }
        DataFile::Embedded { bytes, .. } => read_from(*bytes, &file.display(), subset, decimate),
    }
}

/// [`read`] from any reader; `what` names the source in errors.
pub fn read_from(mut input: impl BufRead, what: &str, subset: Option<&GeoBox>, decimate: usize) -> Result<GeoGrid> {
    let err = |m: String| Error::input(what, m);
    let decimate = decimate.max(1);
    let mut header = Header::default();
    let mut line = String::new();
    let mut first_data: Option<String> = None;
    // Header lines: a keyword then a number. The first line starting with a number ends it.
    for _ in 0..16 {
        line.clear();
        if input.read_line(&mut line).map_err(|e| err(e.to_string()))? == 0 {
            break;
        }
        let mut parts = line.split_whitespace();
        let Some(key) = parts.next() else { continue };
        if key.parse::<f64>().is_ok() {
            first_data = Some(line.clone());
            break;
        }
        let value = parts.next().ok_or_else(|| err(format!("header line `{}` has no value", line.trim())))?;
        let number: f64 = value.parse().map_err(|_| err(format!("header `{key}`: `{value}` is not a number")))?;
        header.set(&key.to_ascii_lowercase(), number).map_err(err)?;
    }
    let h = header.finish().map_err(err)?;
    let (nx, ny) = (h.ncols, h.nrows);
    // Node centres: column i at x0 + i cell, row r (from the north) at the top centre - r cell.
    let lon_of = |i: usize| h.x_centre + i as f64 * h.cell;
    let lat_of = |r: usize| h.y_centre + (ny - 1 - r) as f64 * h.cell;
    let keep_col: Vec<usize> = (0..nx).filter(|&i| inside_lon(subset, lon_of(i))).collect();
    let keep_col: Vec<usize> = keep_col.into_iter().step_by(decimate).collect();
    let rows: Vec<usize> =
        (0..ny).filter(|&r| subset.is_none_or(|b| (b.south..=b.north).contains(&lat_of(r)))).collect();
    // Keep every decimate-th row counted from the south, so the kept lattice is regular.
    let keep_row: Vec<bool> = {
        let mut keep = vec![false; ny];
        for r in rows.iter().rev().step_by(decimate) {
            keep[*r] = true;
        }
        keep
    };
    let kept_rows = keep_row.iter().filter(|&&k| k).count();
    if keep_col.len() < 2 || kept_rows < 2 {
        return Err(err(format!(
            "fewer than 2 x 2 nodes inside the requested box ({} x {} kept of {nx} x {ny})",
            keep_col.len(),
            kept_rows
        )));
    }
    let mut values = vec![f64::NAN; keep_col.len() * kept_rows];
    let mut row_values = Vec::with_capacity(nx);
    let mut out_row = kept_rows;
    for (r, &keep) in keep_row.iter().enumerate() {
        let text = match (r, first_data.take()) {
            (0, Some(t)) => t,
            _ => {
                line.clear();
                if input.read_line(&mut line).map_err(|e| err(e.to_string()))? == 0 {
                    return Err(err(format!("ends after {r} of {ny} rows")));
                }
                line.clone()
            }
        };
        if !keep {
            continue;
        }
        row_values.clear();
        for tok in text.split_whitespace() {
            let v: f64 = tok.parse().map_err(|_| err(format!("row {r}: `{tok}` is not a number")))?;
            row_values.push(v);
        }
        if row_values.len() != nx {
            return Err(err(format!("row {r} has {} values, the header says ncols = {nx}", row_values.len())));
        }
        out_row -= 1;
        for (k, &i) in keep_col.iter().enumerate() {
            let v = row_values[i];
            values[out_row * keep_col.len() + k] =
                if h.nodata.is_some_and(|nd| v == nd) || !v.is_finite() { f64::NAN } else { v };
        }
    }
    let mut lon: Vec<f64> = keep_col.iter().map(|&i| lon_of(i)).collect();
    unwrap_lon(&mut lon, subset);
    let lat: Vec<f64> = (0..ny).rev().filter(|&r| keep_row[r]).map(lat_of).collect();
    // Columns may need reordering after unwrapping across the antimeridian.
    reorder_by_lon(lon, lat, values, what)
}

#[derive(Default)]
struct Header {
    ncols: Option<f64>,
    nrows: Option<f64>,
    x: Option<(f64, bool)>,
    y: Option<(f64, bool)>,
    cell: Option<f64>,
    nodata: Option<f64>,
}

struct Checked {
    ncols: usize,
    nrows: usize,
    x_centre: f64,
    y_centre: f64,
    cell: f64,
    nodata: Option<f64>,
}

impl Header {
    fn set(&mut self, key: &str, v: f64) -> std::result::Result<(), String> {
        match key {
            "ncols" => self.ncols = Some(v),
            "nrows" => self.nrows = Some(v),
            "xllcorner" => self.x = Some((v, true)),
            "xllcenter" => self.x = Some((v, false)),
            "yllcorner" => self.y = Some((v, true)),
            "yllcenter" => self.y = Some((v, false)),
            "cellsize" => self.cell = Some(v),
            "nodata_value" => self.nodata = Some(v),
            _ => return Err(format!("unknown header keyword `{key}`")),
        }
        Ok(())
    }

    fn finish(self) -> std::result::Result<Checked, String> {
        let count = |v: Option<f64>, name: &str| -> std::result::Result<usize, String> {
            let v = v.ok_or_else(|| format!("header has no `{name}`"))?;
            if v.fract() != 0.0 || !(2.0..=1e9).contains(&v) {
                return Err(format!("`{name}` must be an integer from 2 to 1e9, got {v}"));
            }
            Ok(v as usize)
        };
        let (ncols, nrows) = (count(self.ncols, "ncols")?, count(self.nrows, "nrows")?);
        if ncols as u64 * nrows as u64 > MAX_VALUES {
            return Err(format!("{ncols} x {nrows} values exceed the limit of {MAX_VALUES}"));
        }
        let cell = self.cell.ok_or("header has no `cellsize`")?;
        if !(cell > 0.0 && cell.is_finite()) {
            return Err(format!("`cellsize` must be positive, got {cell}"));
        }
        let (x, x_corner) = self.x.ok_or("header has no `xllcorner` or `xllcenter`")?;
        let (y, y_corner) = self.y.ok_or("header has no `yllcorner` or `yllcenter`")?;
        if !x.is_finite() || !y.is_finite() {
            return Err(format!("lower-left corner must be finite, got ({x}, {y})"));
        }
        let half = |corner: bool| if corner { 0.5 * cell } else { 0.0 };
        Ok(Checked {
            ncols,
            nrows,
            x_centre: x + half(x_corner),
            y_centre: y + half(y_corner),
            cell,
            nodata: self.nodata,
        })
    }
}

/// Whether longitude `lon` lies inside the box (any multiple of 360 away counts).
pub(crate) fn inside_lon(subset: Option<&GeoBox>, lon: f64) -> bool {
    let Some(b) = subset else { return true };
    let d = (lon - b.west).rem_euclid(360.0);
    d <= b.width() + 1e-9
}

/// Shifts longitudes by multiples of 360 so they lie within 180 degrees of the box's centre
/// (or leaves them as they are without a box): continuous across the antimeridian, and nodes
/// just beyond the box's edges stay next to it.
pub(crate) fn unwrap_lon(lon: &mut [f64], subset: Option<&GeoBox>) {
    if let Some(b) = subset {
        let c = b.west + b.width() / 2.0;
        for x in lon.iter_mut() {
            *x = c - 180.0 + (*x - (c - 180.0)).rem_euclid(360.0);
        }
    }
}

/// Sorts columns by longitude (a stable permutation) and builds the grid.
pub(crate) fn reorder_by_lon(lon: Vec<f64>, lat: Vec<f64>, values: Vec<f64>, what: &str) -> Result<GeoGrid> {
    let nx = lon.len();
    let mut order: Vec<usize> = (0..nx).collect();
    order.sort_by(|&a, &b| lon[a].total_cmp(&lon[b]));
    if order.iter().enumerate().all(|(k, &i)| k == i) {
        return GeoGrid::new(lon, lat, values, what);
    }
    let lon2: Vec<f64> = order.iter().map(|&i| lon[i]).collect();
    let mut v2 = Vec::with_capacity(values.len());
    for j in 0..lat.len() {
        v2.extend(order.iter().map(|&i| values[j * nx + i]));
    }
    GeoGrid::new(lon2, lat, v2, what)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SAMPLE: &str = "ncols 4\nnrows 3\nxllcorner -124.0\nyllcorner 48.0\ncellsize 0.5\nNODATA_value -9999\n\
        1 2 3 4\n5 -9999 7 8\n9 10 11 12\n";

    #[test]
    fn reads_rows_from_north_to_south() {
        let g = read_from(SAMPLE.as_bytes(), "t.asc", None, 1).unwrap();
        assert_eq!(g.lon, vec![-123.75, -123.25, -122.75, -122.25]);
        assert_eq!(g.lat, vec![48.25, 48.75, 49.25]);
        // The southern row is the file's last one.
        assert_eq!(&g.values[0..4], &[9.0, 10.0, 11.0, 12.0]);
        assert!(g.value(1, 1).is_nan());
        assert_eq!(g.value(3, 2), 4.0);
    }

    #[test]
    fn subset_and_decimation_keep_only_the_box() {
        let b = GeoBox::new(-123.5, 48.5, -122.0, 49.5, "box").unwrap();
        let g = read_from(SAMPLE.as_bytes(), "t.asc", Some(&b), 1).unwrap();
        assert_eq!(g.lon, vec![-123.25, -122.75, -122.25]);
        assert_eq!(g.lat, vec![48.75, 49.25]);
        let g = read_from(SAMPLE.as_bytes(), "t.asc", None, 2).unwrap();
        assert_eq!(g.lon, vec![-123.75, -122.75]);
        assert_eq!(g.lat, vec![48.25, 49.25]);
    }

    #[test]
    fn centre_registration() {
        let text = SAMPLE.replace("xllcorner", "xllcenter").replace("yllcorner", "yllcenter");
        let g = read_from(text.as_bytes(), "t.asc", None, 1).unwrap();
        assert_eq!(g.lon[0], -124.0);
        assert_eq!(g.lat[0], 48.0);
    }

    #[test]
    fn bad_files_name_what_is_wrong() {
        let e = |t: &str| read_from(t.as_bytes(), "t.asc", None, 1).unwrap_err().to_string();
        assert!(e(&SAMPLE.replace("ncols 4", "ncols 4.5")).contains("ncols"));
        assert!(e(&SAMPLE.replace("cellsize 0.5", "cellsize -1")).contains("cellsize"));
        assert!(e(&SAMPLE.replace("9 10 11 12\n", "")).contains("ends after 2 of 3 rows"));
        assert!(e(&SAMPLE.replace("1 2 3 4", "1 2 x 4")).contains("`x` is not a number"));
        assert!(e(&SAMPLE.replace("1 2 3 4", "1 2 3")).contains("row 0 has 3 values"));
        assert!(e("ncols 100000\nnrows 100000\nxllcorner 0\nyllcorner 0\ncellsize 1\n").contains("exceed"));
        assert!(e("").contains("no `ncols`"));
    }

    #[test]
    fn across_the_antimeridian() {
        let text = "ncols 4\nnrows 2\nxllcorner 178\nyllcorner 0\ncellsize 1\n1 2 3 4\n5 6 7 8\n";
        // Columns at 178.5 .. 181.5; a box from 179 to -179 keeps 179.5 and 180.5.
        let b = GeoBox::new(179.0, -1.0, -179.0, 3.0, "box").unwrap();
        let g = read_from(text.as_bytes(), "t.asc", Some(&b), 1).unwrap();
        assert_eq!(g.lon, vec![179.5, 180.5]);
        assert_eq!(g.values, vec![6.0, 7.0, 2.0, 3.0]);
    }
}
