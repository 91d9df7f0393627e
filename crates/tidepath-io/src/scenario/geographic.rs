//! Geographic scenarios: a spec written in longitude/latitude is rewritten into the local
//! metric frame before the world is built, so everything after loading works in metres.
//!
//! * The frame is the azimuthal equidistant projection about the centre of the `bounds` box
//!   (`tidepath::geo`); the metric domain is the smallest rectangle holding the projected box
//!   (its edges sampled densely), so it reaches slightly beyond the box's curved edges.
//! * Mission starts and goals and obstacle centres are projected; an obstacle box's corners
//!   are projected and the box holding them is used (a conservative approximation).
//! * A bathymetry file is read inside the longitude/latitude box that covers the metric
//!   domain, then resampled onto a metric grid at the file's own resolution unless
//!   `resolution` says otherwise, as an envelope nowhere below the file's own surface
//!   (`resample.rs` says why it holds). Nodes without data (fill values, outside the file)
//!   are taken as land, [`NO_DATA_ELEVATION`], and counted in a warning.
//! * Current and wave forecast files are read and resampled the same way (`forecast.rs`).
//! * Other positions (peaks, vortices, current and wave grids, jet regions, cell grids) stay
//!   metres in the local frame, whose origin is the box centre.

use std::path::{Path, PathBuf};

use chrono::{DateTime, Utc};

pub(super) use super::forecast::forecast_grid;
use super::resample::resample;
use super::spec::*;
use crate::geodata::netcdf::{read_bathymetry, Positive};
use crate::geodata::{esri_ascii, name_decimate, DataFile, Format, GeoBox, EMBEDDED};
use tidepath::error::{Error, Result};
use tidepath::geo::GeoFrame;

pub use super::resample::{MAX_GRID_NODES, MAX_RESOLUTION_M, MIN_RESOLUTION_M, NO_DATA_ELEVATION};

/// A spec in metres, with the frame and clock it came from.
pub(crate) struct Localised {
    pub spec: ScenarioSpec,
    pub frame: Option<GeoFrame>,
    pub epoch: Option<DateTime<Utc>>,
    pub warnings: Vec<String>,
}

/// Rewrites `spec` into metres when its frame is geographic, resolves ISO departures against
/// the epoch; `source` is the scenario's file path or `builtin:NAME` (for data file paths).
pub(crate) fn localise(spec: &ScenarioSpec, source: &str) -> Result<Localised> {
    let mut out = spec.clone();
    let mut warnings = Vec::new();
    let epoch = resolve_clock(&mut out)?;
    let frame = match spec.world.frame {
        FrameKind::Local => {
            if matches!(spec.world.terrain, TerrainSpec::File { .. }) {
                return Err(Error::input(
                    "world.terrain.kind",
                    "\"file\" reads longitude/latitude data: set world.frame = \"geographic\"",
                ));
            }
            if matches!(spec.world.current, CurrentSpec::File { .. }) {
                return Err(Error::input(
                    "world.current.kind",
                    "\"file\" reads longitude/latitude data: set world.frame = \"geographic\"",
                ));
            }
            if matches!(spec.world.waves, Some(WavesSpec::File { .. })) {
                return Err(Error::input(
                    "world.waves.kind",
                    "\"file\" reads longitude/latitude data: set world.frame = \"geographic\"",
                ));
            }
            None
        }
        FrameKind::Geographic => Some(project(&mut out, source, &mut warnings)?),
    };
    let mut epoch = epoch;
    if let (Some(f), CurrentSpec::File { .. }) = (&frame, &spec.world.current) {
        epoch = Some(load_currents(&mut out, f, source, epoch, &mut warnings)?);
    }
    // Waves after the current: without world.epoch, the current forecast's clock is kept.
    if let (Some(f), Some(WavesSpec::File { .. })) = (&frame, &spec.world.waves) {
        epoch = Some(super::forecast::load_waves(&mut out, f, source, epoch, &mut warnings)?);
    }
    Ok(Localised { spec: out, frame, epoch, warnings })
}

pub(super) fn parse_instant(field: &str, text: &str) -> Result<DateTime<Utc>> {
    let t = text.trim();
    DateTime::parse_from_rfc3339(t)
        .map(|d| d.with_timezone(&Utc))
        .or_else(|_| {
            // Also a date alone, or a time without a zone, taken as UTC.
            chrono::NaiveDateTime::parse_from_str(t, "%Y-%m-%dT%H:%M:%S")
                .or_else(|_| chrono::NaiveDate::parse_from_str(t, "%Y-%m-%d").map(|d| d.and_hms_opt(0, 0, 0).unwrap()))
                .map(|n| n.and_utc())
        })
        .map_err(|_| {
            Error::input(field, format!("`{text}` is not an ISO 8601 UTC instant (e.g. 2025-11-12T06:00:00Z)"))
        })
        .and_then(|t| {
            use chrono::Datelike;
            if (MIN_YEAR..=MAX_YEAR).contains(&t.year()) {
                Ok(t)
            } else {
                Err(Error::input(field, format!("`{text}` is outside the years {MIN_YEAR} to {MAX_YEAR}")))
            }
        })
}

/// The years an epoch or departure may fall in: wide enough for any hindcast or forecast, and
/// far enough inside the calendar's range that every arrival time can still be written.
pub const MIN_YEAR: i32 = 1800;
pub const MAX_YEAR: i32 = 2300;

/// The scenario clock: `world.epoch`, or the earliest ISO departure; ISO departures become
/// seconds after it.
fn resolve_clock(spec: &mut ScenarioSpec) -> Result<Option<DateTime<Utc>>> {
    let mut isos: Vec<(String, DateTime<Utc>)> = Vec::new();
    if let Some(m) = &spec.mission {
        if let Some(d) = &m.departure {
            isos.push(("mission.departure".into(), parse_instant("mission.departure", d)?));
        }
    }
    for (i, m) in spec.missions.iter().enumerate() {
        if let Some(d) = &m.departure {
            let f = format!("missions[{i}].departure");
            isos.push((f.clone(), parse_instant(&f, d)?));
        }
    }
    let epoch = match &spec.world.epoch {
        Some(e) => Some(parse_instant("world.epoch", e)?),
        None => isos.iter().map(|(_, t)| *t).min(),
    };
    let seconds = |t: &DateTime<Utc>| (*t - epoch.unwrap()).num_milliseconds() as f64 / 1e3;
    if let Some(m) = &mut spec.mission {
        if m.departure.is_some() {
            if m.departure_time != 0.0 {
                return Err(Error::input("mission.departure", "give departure or departure_time, not both"));
            }
            m.departure_time = seconds(&isos.remove(0).1);
        }
    }
    for (i, m) in spec.missions.iter_mut().enumerate() {
        if m.departure.is_some() {
            if m.departure_time != 0.0 {
                return Err(Error::input(
                    format!("missions[{i}].departure"),
                    "give departure or departure_time, not both",
                ));
            }
            m.departure_time = seconds(&isos.remove(0).1);
        }
    }
    Ok(epoch)
}

/// Projects every geographic position of `spec` and loads its bathymetry file.
/// A box obstacle's cover this much larger than its lon/lat box gets a note (1 %).
const EXCESS_NOTE: f64 = 0.01;

fn project(spec: &mut ScenarioSpec, source: &str, warnings: &mut Vec<String>) -> Result<GeoFrame> {
    let [w, s, z0] = spec.world.bounds.min;
    let [e, n, z1] = spec.world.bounds.max;
    let geo_box = GeoBox::new(w, s, e, n, "world.bounds")?;
    let lon0 = tidepath::geo::normalise_lon(w + geo_box.width() / 2.0);
    let frame = GeoFrame::new(lon0, (s + n) / 2.0, "world.bounds")?;
    // The metric rectangle holding the projected box.
    let domain = super::geo_cover::cover(&frame, &geo_box, "world.bounds")?;
    let (lo, hi) = (domain.lo, domain.hi);
    spec.world.bounds.min = [lo[0], lo[1], z0];
    spec.world.bounds.max = [hi[0], hi[1], z1];
    let point = |p: &mut P3, field: &str| -> Result<()> {
        let (x, y) = frame.forward(p[0], p[1], field)?;
        *p = [x, y, p[2]];
        Ok(())
    };
    if let Some(m) = &mut spec.mission {
        // Cells (`start_cell`, `goal_cell`) are numbered on the metric terrain grid.
        if let Some(p) = &mut m.start {
            point(p, "mission.start")?;
        }
        if let Some(p) = &mut m.goal {
            point(p, "mission.goal")?;
        }
    }
    for (i, m) in spec.missions.iter_mut().enumerate() {
        point(&mut m.start, &format!("missions[{i}].start"))?;
        point(&mut m.goal, &format!("missions[{i}].goal"))?;
    }
    for (i, o) in spec.world.obstacles.iter_mut().enumerate() {
        project_obstacle(&frame, o, &format!("world.obstacles[{i}]"), warnings)?;
    }
    if let TerrainSpec::File { path, variable, positive, decimate, resolution } = &spec.world.terrain {
        let file = data_file(path, source, "world.terrain.path", warnings)?;
        let positive = match positive.as_deref() {
            None => None,
            Some("up") => Some(Positive::Up),
            Some("down") => Some(Positive::Down),
            Some(other) => {
                return Err(Error::input(
                    "world.terrain.positive",
                    format!("must be \"up\" or \"down\", got \"{other}\""),
                ))
            }
        };
        let decimate = decimate.unwrap_or(1);
        if !(1..=10_000).contains(&decimate) {
            return Err(Error::input("world.terrain.decimate", format!("must be from 1 to 10000, got {decimate}")));
        }
        let subset = cover(&frame, lo, hi)?;
        let grid = match Format::of(&file, "world.terrain.path")? {
            Format::NetCdf => read_bathymetry(&file, variable.as_deref(), positive, Some(&subset), decimate),
            Format::EsriAscii => esri_ascii::read(&file, Some(&subset), decimate),
            Format::GeoTiff => crate::geodata::geotiff::read(&file, Some(&subset), decimate),
        }
        .map_err(|e| name_decimate(e, decimate, "world.terrain.decimate", &file.display()))?;
        spec.world.terrain = resample(&grid, &frame, lo, hi, *resolution, warnings)?;
    }
    Ok(frame)
}

/// Projects one obstacle given in longitude/latitude (a `[[world.obstacles]]` entry, or a
/// change's `add`, named `field` in errors) into the frame: its centre is projected, a
/// lon/lat box is covered by the frame-aligned box holding it, and a velocity given east and
/// north is turned into the frame's x and y at the obstacle's centre.
pub(super) fn project_obstacle(
    frame: &GeoFrame,
    o: &mut ObstacleSpec,
    field: &str,
    warnings: &mut Vec<String>,
) -> Result<()> {
    if let Some(c) = &mut o.center {
        if c.len() >= 2 {
            let (x, y) = frame.forward(c[0], c[1], &format!("{field}.center"))?;
            c[0] = x;
            c[1] = y;
            // A velocity is given east and north (m/s).
            if let Some(v) = &mut o.velocity {
                let (vx, vy) = east_north_to_frame(frame, x, y, v[0], v[1]);
                *v = [vx, vy, v[2]];
            }
        }
    }
    if let (Some(a), Some(b)) = (&mut o.min, &mut o.max) {
        // A lon/lat rectangle: covered whole, edges included (see geo_cover).
        let lonlat = GeoBox::new(a[0], a[1], b[0], b[1], field)?;
        let c = super::geo_cover::cover(frame, &lonlat, field)?;
        if c.excess() > EXCESS_NOTE {
            warnings.push(format!(
                "{field}: the lon/lat box is covered by a frame-aligned box {:.1} % larger (meridians converge, parallels curve); split it into smaller boxes for a tighter zone",
                100.0 * c.excess()
            ));
        }
        [a[0], a[1], b[0], b[1]] = [c.lo[0], c.lo[1], c.hi[0], c.hi[1]];
        if let (None, Some(v)) = (&o.center, &mut o.velocity) {
            let (vx, vy) = east_north_to_frame(frame, (a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, v[0], v[1]);
            *v = [vx, vy, v[2]];
        }
    }
    Ok(())
}

/// The longitude/latitude box holding the metric rectangle `lo`..`hi`, with a margin of 1%.
/// A rectangle around a pole has no such box (its longitudes go all the way round and its
/// edges never reach the pole's latitude): refused in one line.
pub(super) fn cover(frame: &GeoFrame, lo: [f64; 2], hi: [f64; 2]) -> Result<GeoBox> {
    for (pole, lat) in [("North", 90.0), ("South", -90.0)] {
        if let Ok((x, y)) = frame.forward(frame.lon0, lat, "world.bounds") {
            if (lo[0]..=hi[0]).contains(&x) && (lo[1]..=hi[1]).contains(&y) {
                return Err(Error::input(
                    "world.bounds",
                    format!("the metric domain (the rectangle holding the projected box) contains the {pole} Pole, which data files cannot be read around by longitude/latitude: keep the box clear of the pole"),
                ));
            }
        }
    }
    let (mut west, mut east, mut south, mut north) =
        (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    const SAMPLES: usize = 64;
    for k in 0..=SAMPLES {
        let f = k as f64 / SAMPLES as f64;
        let x = lo[0] + f * (hi[0] - lo[0]);
        let y = lo[1] + f * (hi[1] - lo[1]);
        for (px, py) in [(x, lo[1]), (x, hi[1]), (lo[0], y), (hi[0], y)] {
            let (lon, lat) = frame.inverse(px, py);
            // Longitudes relative to the origin, so a box across the antimeridian stays whole.
            let lon = frame.lon0 + tidepath::geo::normalise_lon(lon - frame.lon0);
            west = west.min(lon);
            east = east.max(lon);
            south = south.min(lat);
            north = north.max(lat);
        }
    }
    let (mx, my) = (0.01 * (east - west) + 1e-6, 0.01 * (north - south) + 1e-6);
    GeoBox::new(
        tidepath::geo::normalise_lon(west - mx),
        (south - my).max(-90.0),
        tidepath::geo::normalise_lon(east + mx),
        (north + my).min(90.0),
        "world.bounds",
    )
}

/// `path` relative to the scenario's folder, or a built-in data file for built-in scenarios.
pub(super) fn data_file(path: &str, source: &str, field: &str, warnings: &mut Vec<String>) -> Result<DataFile> {
    if let Some(_name) = source.strip_prefix("builtin:") {
        return EMBEDDED
            .iter()
            .find(|(n, _)| *n == path)
            .map(|(name, bytes)| DataFile::Embedded { name, bytes })
            .ok_or_else(|| Error::input(field, format!("no built-in data file `{path}`")));
    }
    let p = Path::new(path);
    let full: PathBuf = if p.is_absolute() {
        p.to_path_buf()
    } else {
        Path::new(source).parent().map(|d| d.join(p)).unwrap_or_else(|| p.to_path_buf())
    };
    // A copy of a built-in scenario (`tidepath scenario salish > mine.toml`) keeps working
    // where its data file is not next to it: the built-in copy is used.
    if !full.exists() {
        if let Some((name, bytes)) = EMBEDDED.iter().find(|(n, _)| *n == path) {
            warnings.push(format!(
                "{field}: '{}' does not exist; using tidepath's built-in copy of {name} (put your own file there to use it)",
                full.display()
            ));
            return Ok(DataFile::Embedded { name, bytes });
        }
    }
    Ok(DataFile::Path(full))
}

/// Reads the world's current forecast file and rewrites `world.current` as a metric grid on
/// the scenario clock (see [`forecast_grid`]). Returns the epoch used.
fn load_currents(
    spec: &mut ScenarioSpec,
    frame: &GeoFrame,
    source: &str,
    epoch: Option<DateTime<Utc>>,
    warnings: &mut Vec<String>,
) -> Result<DateTime<Utc>> {
    let (grid, epoch) =
        forecast_grid(&spec.world.current, "world.current", frame, &spec.world, source, epoch, warnings)?;
    spec.world.current = grid;
    Ok(epoch)
}

/// A horizontal vector given east and north at the frame point (x, y), in the frame's x and y.
pub(super) fn east_north_to_frame(frame: &GeoFrame, x: f64, y: f64, east: f64, north: f64) -> (f64, f64) {
    frame.east_north_to_xy(frame.inverse(x, y), (x, y), east, north)
}
