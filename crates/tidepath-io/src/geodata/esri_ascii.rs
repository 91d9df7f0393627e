//! ESRI ASCII grid (`.asc`): a six-line header (`ncols`, `nrows`, `xllcorner` or `xllcenter`,
//! `yllcorner` or `yllcenter`, `cellsize`, optional `NODATA_value`), then `nrows` rows of
//! values from north to south. Coordinates are taken as longitude/latitude degrees.
//!
//! Only the rows and columns inside the requested box are kept, so memory follows the box,
//! not the file: the text is read line by line up to the last row inside the box, each line
//! bounded in length, and the header's declared size must fit in the file's bytes.

use std::io::BufRead;

use super::{DataFile, GeoBox, GeoGrid};
use tidepath::error::{Error, Result};

/// Most values a grid may have (rows x columns): 2^28, as for the other readers, checked
/// from the header before anything is allocated.
pub const MAX_VALUES: u64 = 1 << 28;

/// Most rows, and most columns, a grid may have: 2^20 (GEBCO's global grid has 86,400
/// columns).
pub const MAX_SIDE: u64 = 1 << 20;

/// Longest header line accepted, in bytes.
const MAX_HEADER_LINE: usize = 1024;

/// Most bytes one value of a data row may take, its separator included (a 17-digit number in
/// exponent form takes 25): a row longer than `ncols` times this is not a row of this grid.
const MAX_VALUE_BYTES: usize = 64;

/// Reads `path`, keeping the nodes inside `subset` (all when `None`) and every `decimate`-th
/// row and column. Only a regular file is read (a FIFO or `/dev/zero` is refused).
pub fn read(file: &DataFile, subset: Option<&GeoBox>, decimate: usize) -> Result<GeoGrid> {
    match file {
        DataFile::Path(path) => {
            let size = crate::input::regular_file(path, &file.display())?;
            super::check_not_empty(file)?;
            let f = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
            read_from(std::io::BufReader::new(f), &file.display(), Some(size), subset, decimate)
        }
        DataFile::Embedded { bytes, .. } => {
            super::check_not_empty(file)?;
            read_from(*bytes, &file.display(), Some(bytes.len() as u64), subset, decimate)
        }
    }
}

/// Reads one line of at most `max` bytes into `buf` (cleared first), without ever holding
/// more: a file of a billion bytes without a newline is refused after `max`. Returns false at
/// the end of the input.
fn read_line_bounded(input: &mut impl BufRead, buf: &mut Vec<u8>, max: usize) -> std::io::Result<Option<bool>> {
    buf.clear();
    loop {
        let chunk = input.fill_buf()?;
        if chunk.is_empty() {
            return Ok(Some(!buf.is_empty()));
        }
        let (take, done) = match chunk.iter().position(|&b| b == b'\n') {
            Some(k) => (k + 1, true),
            None => (chunk.len(), false),
        };
        if buf.len() + take > max + 1 {
            return Ok(None);
        }
        buf.extend_from_slice(&chunk[..take]);
        input.consume(take);
        if done {
            return Ok(Some(true));
        }
    }
}

/// Whether the next line starts with a number (a data row, not a header line), judged from
/// its first characters without consuming anything.
fn next_line_is_data(input: &mut impl BufRead) -> std::io::Result<bool> {
    let chunk = input.fill_buf()?;
    let token: Vec<u8> = chunk
        .iter()
        .skip_while(|b| matches!(b, b' ' | b'\t' | b'\r' | b'\n'))
        .take(3)
        .map(|b| b.to_ascii_lowercase())
        .collect();
    Ok(match token.first() {
        Some(b) if b.is_ascii_digit() || matches!(b, b'-' | b'+' | b'.') => true,
        _ => token.starts_with(b"nan") || token.starts_with(b"inf"),
    })
}

/// [`read`] from any reader; `what` names the source in errors; `size` (bytes), when known,
/// must be able to hold the values the header declares.
pub fn read_from(
    mut input: impl BufRead,
    what: &str,
    size: Option<u64>,
    subset: Option<&GeoBox>,
    decimate: usize,
) -> Result<GeoGrid> {
    let err = |m: String| Error::input(what, m);
    let decimate = decimate.max(1);
    let mut header = Header::default();
    let mut buf = Vec::new();
    let text_of = |buf: &[u8], what: &str| -> Result<String> {
        String::from_utf8(buf.to_vec()).map_err(|_| err(format!("{what} is not text")))
    };
    // Header lines: a keyword then a number. The first line starting with a number ends it;
    // it is left in the input for the row loop, which reads it with the rows' length limit.
    for k in 0..16 {
        if next_line_is_data(&mut input).map_err(|e| err(e.to_string()))? {
            break;
        }
        match read_line_bounded(&mut input, &mut buf, MAX_HEADER_LINE).map_err(|e| err(e.to_string()))? {
            None => return Err(err(format!("header line {} is longer than {MAX_HEADER_LINE} bytes", k + 1))),
            Some(false) => break,
            Some(true) => {}
        }
        let line = text_of(&buf, &format!("header line {}", k + 1))?;
        let mut parts = line.split_whitespace();
        let Some(key) = parts.next() else { continue };
        let value = parts.next().ok_or_else(|| err(format!("header line `{}` has no value", line.trim())))?;
        let number: f64 = value.parse().map_err(|_| err(format!("header `{key}`: `{value}` is not a number")))?;
        header.set(&key.to_ascii_lowercase(), number).map_err(err)?;
    }
    let h = header.finish().map_err(err)?;
    let (nx, ny) = (h.ncols, h.nrows);
    // Every value takes at least two bytes (a digit and a separator): a header declaring more
    // than the file can hold is refused before anything is allocated.
    if let Some(size) = size {
        let least = 2 * nx as u64 * ny as u64;
        if size < least {
            return Err(err(format!(
                "the header declares {nx} x {ny} values, which need at least {least} bytes; the file has {size}"
            )));
        }
    }
    // Node centres: column i at x0 + i cell, row r (from the north) at the top centre - r cell.
    let lon_of = |i: usize| h.x_centre + i as f64 * h.cell;
    let lat_of = |r: usize| h.y_centre + (ny - 1 - r) as f64 * h.cell;
    // The columns and rows inside the box and one beyond each edge (or the two bracketing a
    // box smaller than a cell), as the NetCDF and GeoTIFF readers keep them, so interpolation
    // up to the box's edges sees real nodes; every `decimate`-th from the south-west one.
    let distinct = super::distinct_lons(nx, lon_of);
    let keep_col: Vec<usize> = super::lon_runs(distinct, lon_of, subset)
        .into_iter()
        .flat_map(|(a, b)| (a..=super::decimated_last(a, b, decimate, distinct)).step_by(decimate))
        .collect();
    // Rows count from the north; in latitude order (from the south) they run backwards.
    let south_first = |k: usize| lat_of(ny - 1 - k);
    let span = match subset {
        None => Some((0, ny - 1)),
        Some(b) => super::axis_span(ny, south_first, b.south, b.north),
    };
    let (first_row, last_row, any_row) = match span {
        Some((s0, s1)) => {
            let s1 = super::decimated_last(s0, s1, decimate, ny);
            (ny - 1 - s1, ny - 1 - s0, true)
        }
        None => (0, 0, false),
    };
    let keep = |r: usize| any_row && (first_row..=last_row).contains(&r) && (last_row - r) % decimate == 0;
    let kept_rows = if any_row { (last_row - first_row) / decimate + 1 } else { 0 };
    if keep_col.len() < 2 || kept_rows < 2 {
        return Err(err(format!(
            "{} inside or around the requested box, got {} x {} (of {nx} x {ny})",
            super::TOO_FEW_NODES,
            keep_col.len(),
            kept_rows
        )));
    }
    // Values grow with the rows actually read (north first), so memory follows the data.
    let mut rows_north_first: Vec<f64> = Vec::new();
    let max_row = nx * MAX_VALUE_BYTES + MAX_HEADER_LINE;
    for r in 0..=last_row {
        match read_line_bounded(&mut input, &mut buf, max_row).map_err(|e| err(e.to_string()))? {
            None => return Err(err(format!("row {r} is longer than {max_row} bytes ({nx} values)"))),
            Some(false) => return Err(err(format!("ends after {r} of {ny} rows"))),
            Some(true) => {}
        }
        if !keep(r) {
            continue;
        }
        let text = text_of(&buf, &format!("row {r}"))?;
        let mut next_kept = keep_col.iter().peekable();
        let mut count = 0usize;
        for (i, tok) in text.split_whitespace().enumerate() {
            let v: f64 = tok.parse().map_err(|_| err(format!("row {r}: `{tok}` is not a number")))?;
            count += 1;
            if next_kept.peek() == Some(&&i) {
                next_kept.next();
                rows_north_first.push(if h.nodata.is_some_and(|nd| v == nd) || !v.is_finite() { f64::NAN } else { v });
            }
        }
        if count != nx {
            return Err(err(format!("row {r} has {count} values, the header says ncols = {nx}")));
        }
    }
    // Rows into south-first order.
    let width = keep_col.len();
    let mut values = Vec::with_capacity(rows_north_first.len());
    for row in rows_north_first.chunks(width).rev() {
        values.extend_from_slice(row);
    }
    let mut lon: Vec<f64> = keep_col.iter().map(|&i| lon_of(i)).collect();
    unwrap_lon(&mut lon, subset);
    let lat: Vec<f64> = (first_row..=last_row).rev().filter(|&r| keep(r)).map(lat_of).collect();
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
            if v.fract() != 0.0 || !(2.0..=MAX_SIDE as f64).contains(&v) {
                return Err(format!("`{name}` must be an integer from 2 to {MAX_SIDE}, got {v}"));
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
    use std::io::Read as _;

    const SAMPLE: &str = "ncols 4\nnrows 3\nxllcorner -124.0\nyllcorner 48.0\ncellsize 0.5\nNODATA_value -9999\n\
        1 2 3 4\n5 -9999 7 8\n9 10 11 12\n";

    #[test]
    fn reads_rows_from_north_to_south() {
        let g = read_from(SAMPLE.as_bytes(), "t.asc", None, None, 1).unwrap();
        assert_eq!(g.lon, vec![-123.75, -123.25, -122.75, -122.25]);
        assert_eq!(g.lat, vec![48.25, 48.75, 49.25]);
        // The southern row is the file's last one.
        assert_eq!(&g.values[0..4], &[9.0, 10.0, 11.0, 12.0]);
        assert!(g.value(1, 1).is_nan());
        assert_eq!(g.value(3, 2), 4.0);
    }

    #[test]
    fn subset_and_decimation_keep_the_box_and_its_bracketing_nodes() {
        // Columns -123.25 .. -122.25 and rows 48.75, 49.25 inside, one more west and south.
        let b = GeoBox::new(-123.5, 48.5, -122.0, 49.5, "box").unwrap();
        let g = read_from(SAMPLE.as_bytes(), "t.asc", None, Some(&b), 1).unwrap();
        assert_eq!(g.lon, vec![-123.75, -123.25, -122.75, -122.25]);
        assert_eq!(g.lat, vec![48.25, 48.75, 49.25]);
        // A box inside one cell reads the four nodes around it.
        let small = GeoBox::new(-123.2, 48.8, -123.1, 48.9, "box").unwrap();
        let g = read_from(SAMPLE.as_bytes(), "t.asc", None, Some(&small), 1).unwrap();
        assert_eq!((g.lon.clone(), g.lat.clone()), (vec![-123.25, -122.75], vec![48.75, 49.25]));
        assert!(g.value(0, 0).is_nan());
        assert_eq!((g.value(1, 0), g.value(0, 1), g.value(1, 1)), (7.0, 2.0, 3.0));
        let g = read_from(SAMPLE.as_bytes(), "t.asc", None, None, 2).unwrap();
        assert_eq!(g.lon, vec![-123.75, -122.75]);
        assert_eq!(g.lat, vec![48.25, 49.25]);
    }

    #[test]
    fn centre_registration() {
        let text = SAMPLE.replace("xllcorner", "xllcenter").replace("yllcorner", "yllcenter");
        let g = read_from(text.as_bytes(), "t.asc", None, None, 1).unwrap();
        assert_eq!(g.lon[0], -124.0);
        assert_eq!(g.lat[0], 48.0);
    }

    #[test]
    fn bad_files_name_what_is_wrong() {
        let e = |t: &str| read_from(t.as_bytes(), "t.asc", None, None, 1).unwrap_err().to_string();
        assert!(e(&SAMPLE.replace("ncols 4", "ncols 4.5")).contains("ncols"));
        assert!(e(&SAMPLE.replace("cellsize 0.5", "cellsize -1")).contains("cellsize"));
        assert!(e(&SAMPLE.replace("9 10 11 12\n", "")).contains("ends after 2 of 3 rows"));
        assert!(e(&SAMPLE.replace("1 2 3 4", "1 2 x 4")).contains("`x` is not a number"));
        assert!(e(&SAMPLE.replace("1 2 3 4", "1 2 3")).contains("row 0 has 3 values"));
        assert!(e("ncols 100000\nnrows 100000\nxllcorner 0\nyllcorner 0\ncellsize 1\n").contains("exceed"));
        assert!(e("ncols 2000000\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n").contains("from 2 to 1048576"));
        assert!(e("").contains("no `ncols`"));
    }

    /// Size bombs: a header declaring more than the file holds, a line without an end, a row
    /// of endless bytes. Each is refused after reading at most a bounded number of bytes.
    #[test]
    fn declared_sizes_and_line_lengths_are_bounded() {
        let header = "ncols 10000\nnrows 10000\nxllcorner 0\nyllcorner 0\ncellsize 0.001\n";
        let e = read_from(header.as_bytes(), "t.asc", Some(header.len() as u64), None, 1).unwrap_err().to_string();
        assert!(e.contains("need at least") && e.contains("the file has"), "{e}");
        // 1 GB of zero bytes and no newline, without holding it: refused at the first line.
        let zeros = std::io::BufReader::new(std::io::repeat(0).take(1 << 30));
        let e = read_from(zeros, "t.asc", None, None, 1).unwrap_err().to_string();
        assert!(e.contains("header line 1 is longer than 1024 bytes"), "{e}");
        let endless =
            "ncols 4\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n".as_bytes().chain(std::io::repeat(b'7'));
        let e = read_from(std::io::BufReader::new(endless), "t.asc", None, None, 1).unwrap_err().to_string();
        assert!(e.contains("row 0 is longer than"), "{e}");
    }

    #[test]
    fn across_the_antimeridian() {
        let text = "ncols 4\nnrows 2\nxllcorner 178\nyllcorner 0\ncellsize 1\n1 2 3 4\n5 6 7 8\n";
        // Columns at 178.5 .. 181.5; a box from 179 to -179 holds 179.5 and 180.5.
        let b = GeoBox::new(179.0, -1.0, -179.0, 3.0, "box").unwrap();
        let g = read_from(text.as_bytes(), "t.asc", None, Some(&b), 1).unwrap();
        // And one column beyond each edge.
        assert_eq!(g.lon, vec![178.5, 179.5, 180.5, 181.5]);
        assert_eq!(g.values, vec![5.0, 6.0, 7.0, 8.0, 1.0, 2.0, 3.0, 4.0]);
    }
}
