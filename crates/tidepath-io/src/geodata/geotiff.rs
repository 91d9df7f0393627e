//! GeoTIFF bathymetry (GEBCO and ETOPO ship it) through the `tiff` crate and the GeoTIFF
//! tags: `ModelPixelScale` and `ModelTiepoint` place the raster, the GeoKey directory says
//! the CRS and whether pixels are areas or points, GDAL's `GDAL_NODATA` tag marks no data.
//!
//! * Only longitude/latitude rasters on WGS84 (EPSG:4326) are read; a projected CRS or
//!   another datum is refused with its EPSG code named.
//! * Pixel-is-area (the default): the tie point is a pixel's outer corner, values belong to
//!   pixel centres. Pixel-is-point: the tie point is the first pixel's centre.
//! * Only the strips or tiles overlapping the requested box are decoded, so memory follows
//!   the box; a box across the raster's edge meridian (the antimeridian of a global raster)
//!   reads the columns at both ends.

use std::io::{Cursor, Read, Seek};

use tiff::decoder::{Decoder, DecodingResult};
use tiff::tags::Tag;

use super::esri_ascii::{reorder_by_lon, unwrap_lon};
use super::{DataFile, GeoBox, GeoGrid};
use tidepath::error::{Error, Result};

/// Most values one read may return (as in the NetCDF reader).
pub const MAX_VALUES: u64 = 1 << 28;

const MODEL_TYPE: u16 = 1024;
const RASTER_TYPE: u16 = 1025;
const GEOGRAPHIC_TYPE: u16 = 2048;
const PROJECTED_TYPE: u16 = 3072;
const WGS84: u16 = 4326;

/// Reads `file` inside `subset`, every `decimate`-th pixel.
pub fn read(file: &DataFile, subset: Option<&GeoBox>, decimate: usize) -> Result<GeoGrid> {
    let what = file.display();
    match file {
        DataFile::Path(p) => {
            crate::input::regular_file(p, &what)?;
            super::check_not_empty(file)?;
            let f = std::fs::File::open(p).map_err(|e| Error::io(p, e))?;
            read_from(std::io::BufReader::new(f), &what, subset, decimate)
        }
        DataFile::Embedded { bytes, .. } => {
            super::check_not_empty(file)?;
            read_from(Cursor::new(*bytes), &what, subset, decimate)
        }
    }
}

fn tiff_err(what: &str) -> impl Fn(tiff::TiffError) -> Error + '_ {
    move |e| Error::input(what, format!("not a readable GeoTIFF: {e}"))
}

/// Refuses a text (ASCII) tag read here (the no-data value) declaring more bytes than the file
/// holds, before the `tiff`
/// crate reads it: tiff 0.11.3 reports that case through a stray `dbg!`, an extra line on
/// stderr, where tidepath promises one.
fn refuse_oversized_text_tags<R: Read + Seek>(dec: &mut Decoder<R>, len: u64, what: &str) -> Result<()> {
    let Some(ptr) = dec.ifd_pointer() else { return Ok(()) };
    let dir = dec.read_directory(ptr).map_err(tiff_err(what))?;
    for (tag, e) in dir.iter() {
        // Only the text tags this reader asks for: an unused damaged tag does not stop a read.
        if tag == Tag::GdalNodata && e.field_type() == tiff::tags::Type::ASCII && e.count() > len {
            return Err(Error::input(
                what,
                format!(
                    "not a readable GeoTIFF: text tag {} declares {} bytes, more than the file's {len}",
                    tag.to_u16(),
                    e.count()
                ),
            ));
        }
    }
    Ok(())
}

/// [`read`] from any seekable reader; `what` names the source in errors.
pub fn read_from<R: Read + Seek>(mut r: R, what: &str, subset: Option<&GeoBox>, decimate: usize) -> Result<GeoGrid> {
    let err = tiff_err(what);
    let decimate = decimate.max(1);
    let io = |e: std::io::Error| Error::input(what, format!("not a readable GeoTIFF: {e}"));
    let len = r.seek(std::io::SeekFrom::End(0)).map_err(io)?;
    r.seek(std::io::SeekFrom::Start(0)).map_err(io)?;
    let mut dec = Decoder::new(r).map_err(&err)?;
    refuse_oversized_text_tags(&mut dec, len, what)?;
    let (w, h) = dec.dimensions().map_err(&err)?;
    let (w, h) = (w as usize, h as usize);
    if w < 2 || h < 2 {
        return Err(Error::input(what, format!("{w} x {h} pixels: needs at least 2 x 2")));
    }
    match dec.colortype().map_err(&err)? {
        tiff::ColorType::Gray(_) => {}
        other => return Err(Error::input(what, format!("{other:?} raster: a bathymetry GeoTIFF has one band"))),
    }
    let scale = dec
        .find_tag(Tag::ModelPixelScaleTag)
        .map_err(&err)?
        .ok_or_else(|| {
            Error::input(what, "no ModelPixelScale tag: not georeferenced (or rotated, which is not supported)")
        })?
        .into_f64_vec()
        .map_err(&err)?;
    let tie = dec
        .find_tag(Tag::ModelTiepointTag)
        .map_err(&err)?
        .ok_or_else(|| Error::input(what, "no ModelTiepoint tag: not georeferenced"))?
        .into_f64_vec()
        .map_err(&err)?;
    if scale.len() < 2
        || tie.len() < 6
        || !(scale[0] > 0.0 && scale[1] > 0.0)
        || tie.iter().take(6).any(|v| !v.is_finite())
    {
        return Err(Error::input(what, format!("bad georeferencing: pixel scale {scale:?}, tie point {tie:?}")));
    }
    let keys = match dec.find_tag(Tag::GeoKeyDirectoryTag).map_err(&err)? {
        Some(v) => v.into_u16_vec().map_err(&err)?,
        None => Vec::new(),
    };
    let key =
        |id: u16| -> Option<u16> { keys.get(4..)?.chunks_exact(4).find(|k| k[0] == id && k[1] == 0).map(|k| k[3]) };
    if let Some(code) = key(PROJECTED_TYPE) {
        return Err(Error::input(
            what,
            format!("EPSG:{code} is a projected CRS; tidepath reads GeoTIFF bathymetry in longitude/latitude (EPSG:4326): reproject it, e.g. gdalwarp -t_srs EPSG:4326"),
        ));
    }
    if key(MODEL_TYPE) == Some(1) {
        return Err(Error::input(
            what,
            "a projected raster (GTModelType 1); tidepath reads longitude/latitude (EPSG:4326)",
        ));
    }
    match key(GEOGRAPHIC_TYPE) {
        Some(WGS84) | None => {}
        Some(code) => {
            return Err(Error::input(
                what,
                format!("EPSG:{code} is not WGS84; tidepath reads EPSG:4326 (reproject it)"),
            ))
        }
    }
    let point = key(RASTER_TYPE) == Some(2);
    let nodata = match dec.find_tag(Tag::GdalNodata).map_err(&err)? {
        Some(v) => v.into_string().ok().and_then(|s| s.trim().trim_end_matches('\0').parse::<f64>().ok()),
        None => None,
    };
    // Pixel (i, j) centre; j counts rows from the top (north).
    let half = if point { 0.0 } else { 0.5 };
    let (i0, j0, x0, y0) = (tie[0], tie[1], tie[3], tie[4]);
    let lon_of = |i: usize| x0 + (i as f64 + half - i0) * scale[0];
    let lat_of = |j: usize| y0 - (j as f64 + half - j0) * scale[1];
    // The pixels inside the box and one beyond each edge, or the two bracketing a box smaller
    // than a pixel; a box across the raster's edge meridian (a global raster and a box across
    // the antimeridian) takes its columns from both ends.
    let distinct = super::distinct_lons(w, lon_of);
    let runs = super::lon_runs(distinct, lon_of, subset);
    let rows = match subset {
        None => Some((0, h - 1)),
        // Rows count from the north: latitude falls with the row index.
        Some(b) => super::axis_span(h, lat_of, b.south, b.north),
    };
    let (Some((r0, r1)), false) = (rows, runs.is_empty()) else {
        return Err(Error::input(what, "no pixel of the file lies inside or around the requested box"));
    };
    let keep_c: Vec<usize> = runs
        .iter()
        .flat_map(|&(a, b)| (a..=super::decimated_last(a, b, decimate, distinct)).step_by(decimate))
        .collect();
    let keep_r: Vec<usize> = (r0..=super::decimated_last(r0, r1, decimate, h)).step_by(decimate).collect();
    let total = keep_c.len() as u64 * keep_r.len() as u64;
    if total > MAX_VALUES {
        return Err(Error::input(
            what,
            format!("the box holds {total} values, more than the limit of {MAX_VALUES}: use a smaller box or decimate"),
        ));
    }
    let (nx, ny) = (keep_c.len(), keep_r.len());
    let mut values = vec![f64::NAN; nx * ny];
    // Decode only the chunks (strips or tiles) overlapping the kept rows and columns.
    let (cw, ch) = dec.chunk_dimensions();
    let (cw, ch) = (cw as usize, ch as usize);
    if cw == 0 || ch == 0 {
        return Err(Error::input(what, "zero-sized strips or tiles"));
    }
    let across = w.div_ceil(cw);
    let mut tile_cols: Vec<usize> = keep_c.iter().map(|&i| i / cw).collect();
    tile_cols.dedup();
    let mut tile_rows: Vec<usize> = keep_r.iter().map(|&j| j / ch).collect();
    tile_rows.dedup();
    for &ty in &tile_rows {
        for &tx in &tile_cols {
            let index = (ty * across + tx) as u32;
            let data = dec.read_chunk(index).map_err(&err)?;
            let data_w = dec.chunk_data_dimensions(index).0 as usize;
            let sample = |k: usize| -> f64 {
                match &data {
                    DecodingResult::U8(v) => v[k] as f64,
                    DecodingResult::U16(v) => v[k] as f64,
                    DecodingResult::U32(v) => v[k] as f64,
                    DecodingResult::U64(v) => v[k] as f64,
                    DecodingResult::I8(v) => v[k] as f64,
                    DecodingResult::I16(v) => v[k] as f64,
                    DecodingResult::I32(v) => v[k] as f64,
                    DecodingResult::I64(v) => v[k] as f64,
                    DecodingResult::F32(v) => v[k] as f64,
                    DecodingResult::F64(v) => v[k],
                    _ => f64::NAN,
                }
            };
            let len = match &data {
                DecodingResult::U8(v) => v.len(),
                DecodingResult::U16(v) => v.len(),
                DecodingResult::U32(v) => v.len(),
                DecodingResult::U64(v) => v.len(),
                DecodingResult::I8(v) => v.len(),
                DecodingResult::I16(v) => v.len(),
                DecodingResult::I32(v) => v.len(),
                DecodingResult::I64(v) => v.len(),
                DecodingResult::F32(v) => v.len(),
                DecodingResult::F64(v) => v.len(),
                _ => return Err(Error::input(what, "unsupported sample format")),
            };
            for (out_j, &j) in keep_r.iter().enumerate().filter(|(_, &j)| j / ch == ty) {
                for (out_i, &i) in keep_c.iter().enumerate().filter(|(_, &i)| i / cw == tx) {
                    let k = (j - ty * ch) * data_w + (i - tx * cw);
                    if k >= len {
                        return Err(Error::input(what, format!("chunk {index} is shorter than its tile")));
                    }
                    let v = sample(k);
                    // Rows come north first: flip to south first.
                    values[(ny - 1 - out_j) * nx + out_i] =
                        if nodata.is_some_and(|nd| v == nd) || !v.is_finite() { f64::NAN } else { v };
                }
            }
        }
    }
    let mut lon: Vec<f64> = keep_c.iter().map(|&i| lon_of(i)).collect();
    unwrap_lon(&mut lon, subset);
    let lat: Vec<f64> = keep_r.iter().rev().map(|&j| lat_of(j)).collect();
    reorder_by_lon(lon, lat, values, what)
}
