//! Routes read back for `eval` and `plan --init`: tidepath's plan JSON and its exports
//! (GeoJSON, GPX, KML, CSV), as written and as edited in QGIS or a chart plotter.
//!
//! Each file gives one route per mission, in mission order: a GeoJSON `LineString` feature
//! (a `MultiLineString` is joined), a GPX track (its segments joined) or route, a KML
//! `LineString` or `gx:Track` placemark (points, such as the start and goal marks, are
//! skipped), CSV rows grouped by their `mission` column in order of first appearance.
//!
//! The curve a vehicle with a turning radius flies, which exports write beside its waypoints,
//! is not a route and is skipped: a GeoJSON feature with `kind` "flown", a GPX track or route
//! whose `<type>` is "flown", a KML placemark whose `ExtendedData` says `kind` "flown", CSV
//! rows whose `kind` column says "flown". The waypoints are the route; the scenario flies
//! them again.
//!
//! Frames: GeoJSON, GPX and KML are longitude/latitude with an elevation (z = -depth); a CSV
//! is longitude/latitude when it has `lat` and `lon` columns (with `depth_m`), metres when it
//! has `x_m`, `y_m`, `z_m`; a plan JSON is metres unless it says `"frame": "lonlat"` (then its
//! waypoints are [longitude, latitude, depth_m], depth positive down). A point without an
//! elevation or depth has none: the scenario then takes its 2-D plane's depth, and a 3-D
//! scenario refuses it, naming the point.
//!
//! Times in the files are ignored: a route is flown on the scenario's own clock from the
//! mission's departure, so a re-read route is judged as the scenario would fly it now.

use std::path::Path;

use quick_xml::events::Event;
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;

use crate::export::KIND_FLOWN;
use crate::plan_json::{PlanFile, RouteFrame, MAX_PLAN_POINTS};

/// Whether a line's `kind` label marks a flown curve (not a route).
fn is_flown(kind: &str) -> bool {
    kind.trim().eq_ignore_ascii_case(KIND_FLOWN)
}

/// The route file formats, by extension.
pub const ROUTE_EXTENSIONS: &str = ".json, .geojson, .gpx, .kml, .csv";

/// Reads the routes in `path`, its format chosen by the extension.
pub fn read(path: &Path) -> Result<PlanFile> {
    let shown = path.display().to_string();
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    if ext == "json" || ext.is_empty() {
        return PlanFile::read(path);
    }
    let parse: fn(&str, &str) -> Result<Vec<Route>> = match ext.as_str() {
        "geojson" => geojson_routes,
        "gpx" => gpx_routes,
        "kml" => kml_routes,
        "csv" => return csv_routes(&crate::input::read_text(path, &shown, crate::input::MAX_PLAN_BYTES)?, &shown),
        _ => {
            return Err(Error::input(
                shown,
                format!("unknown route file extension '.{ext}' (known: {ROUTE_EXTENSIONS})"),
            ))
        }
    };
    let text = crate::input::read_text(path, &shown, crate::input::MAX_PLAN_BYTES)?;
    let routes = parse(&text, &shown)?;
    finish(routes, RouteFrame::LonLat, format_name(&ext), &shown)
}

fn format_name(ext: &str) -> &'static str {
    match ext {
        "geojson" => "GeoJSON",
        "gpx" => "GPX",
        "kml" => "KML",
        _ => "CSV",
    }
}

/// One route as read: a name, and points as (longitude or x, latitude or y, elevation or z),
/// the elevation NaN where the file gives none.
struct Route {
    name: Option<String>,
    points: Vec<Vec3>,
}

fn finish(routes: Vec<Route>, frame: RouteFrame, format: &'static str, source: &str) -> Result<PlanFile> {
    if routes.is_empty() {
        return Err(Error::input(
            source,
            format!("no route in this {format} file (expected a track or line per mission)"),
        ));
    }
    let mut paths = Vec::with_capacity(routes.len());
    for (i, r) in routes.into_iter().enumerate() {
        let what = r.name.clone().map_or(format!("route {}", i + 1), |n| format!("route {} ('{}')", i + 1, n));
        if r.points.len() < 2 {
            return Err(Error::input(
                source,
                format!("{what}: a route needs at least 2 points, got {}", r.points.len()),
            ));
        }
        if r.points.len() > MAX_PLAN_POINTS {
            return Err(Error::input(
                source,
                format!("{what}: at most {MAX_PLAN_POINTS} points, got {}", r.points.len()),
            ));
        }
        for (k, p) in r.points.iter().enumerate() {
            if !(p.x.is_finite() && p.y.is_finite()) || p.z.is_infinite() {
                return Err(Error::input(
                    source,
                    format!("{what}, point {}: coordinates must be finite numbers", k + 1),
                ));
            }
        }
        paths.push((r.name, r.points));
    }
    Ok(PlanFile {
        paths,
        speeds: Vec::new(),
        cost: None,
        planner: None,
        scenario: None,
        version: 1,
        frame: Some(frame),
        format,
    })
}

fn geojson_routes(text: &str, source: &str) -> Result<Vec<Route>> {
    use geojson::{GeoJson, GeometryValue};
    let gj: GeoJson = text.parse().map_err(|e| Error::input(source, format!("not GeoJSON: {e}")))?;
    let features = match gj {
        GeoJson::FeatureCollection(fc) => fc.features,
        GeoJson::Feature(f) => vec![f],
        GeoJson::Geometry(g) => vec![geojson::Feature::from(g)],
    };
    let mut routes = Vec::new();
    for f in features {
        if f.property("kind").and_then(|v| v.as_str()).is_some_and(is_flown) {
            continue;
        }
        let name = f.property("name").and_then(|v| v.as_str()).map(str::to_string);
        // The export's per-point depths, when present, say the depth exactly.
        let depths: Option<Vec<f64>> = f
            .property("depth_m")
            .and_then(|v| v.as_array())
            .map(|a| a.iter().map(|d| d.as_f64().unwrap_or(f64::NAN)).collect());
        let Some(g) = f.geometry else { continue };
        let lines = match g.value {
            GeometryValue::LineString { coordinates } => vec![coordinates],
            GeometryValue::MultiLineString { coordinates } => coordinates,
            _ => continue,
        };
        let mut points = Vec::new();
        for c in lines.iter().flatten() {
            let s = c.as_slice();
            points.push(Vec3::new(s[0], s.get(1).copied().unwrap_or(f64::NAN), s.get(2).copied().unwrap_or(f64::NAN)));
        }
        if let Some(d) = depths.filter(|d| d.len() == points.len()) {
            for (p, d) in points.iter_mut().zip(d) {
                if d.is_finite() {
                    p.z = -d;
                }
            }
        }
        routes.push(Route { name, points });
    }
    Ok(routes)
}

/// The XML events of `text`, with one-line errors naming the file and the byte offset.
fn xml_walk(text: &str, source: &str, mut on: impl FnMut(XmlEvent<'_>) -> Result<()>) -> Result<()> {
    let mut reader = quick_xml::Reader::from_str(text);
    let mut path: Vec<String> = Vec::new();
    loop {
        let at = reader.buffer_position();
        let ev = reader.read_event().map_err(|e| {
            Error::input(source, format!("malformed XML at byte {at}: {}", tidepath::text::one_line(&e.to_string())))
        })?;
        match ev {
            Event::Start(e) => {
                let (name, attrs) = tag_of(&e);
                path.push(name.clone());
                on(XmlEvent::Open { name: &name, attrs: &attrs, at })?;
            }
            Event::Empty(e) => {
                let (name, attrs) = tag_of(&e);
                on(XmlEvent::Open { name: &name, attrs: &attrs, at })?;
                on(XmlEvent::Close { name: &name })?;
            }
            Event::Text(t) => {
                let s =
                    t.decode().map_err(|e| Error::input(source, format!("malformed XML text at byte {at}: {e}")))?;
                let s = quick_xml::escape::unescape(&s)
                    .map_err(|e| Error::input(source, format!("malformed XML text at byte {at}: {e}")))?;
                on(XmlEvent::Text { text: &s, at })?;
            }
            Event::CData(t) => on(XmlEvent::Text { text: &String::from_utf8_lossy(&t), at })?,
            Event::End(_) => {
                let name = path.pop().unwrap_or_default();
                on(XmlEvent::Close { name: &name })?;
            }
            Event::Eof => break,
            _ => {}
        }
    }
    Ok(())
}

/// An element's local name (without its namespace prefix, so `gx:coord` is `coord`) and its
/// attributes, unescaped; an attribute that cannot be read is left out.
fn tag_of(e: &quick_xml::events::BytesStart<'_>) -> (String, Vec<(String, String)>) {
    let name = String::from_utf8_lossy(e.local_name().as_ref()).into_owned();
    let attrs = e
        .attributes()
        .flatten()
        .map(|a| {
            let k = String::from_utf8_lossy(a.key.local_name().as_ref()).into_owned();
            let v = a.unescape_value().map(|v| v.into_owned()).unwrap_or_default();
            (k, v)
        })
        .collect();
    (name, attrs)
}

enum XmlEvent<'a> {
    Open { name: &'a str, attrs: &'a [(String, String)], at: u64 },
    Text { text: &'a str, at: u64 },
    Close { name: &'a str },
}

fn number(text: &str, what: &str, source: &str, at: u64) -> Result<f64> {
    text.trim().parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| {
        Error::input(
            source,
            format!("{what} '{}' at byte {at} is not a finite number", tidepath::text::one_line(text.trim())),
        )
    })
}

/// GPX 1.1: each `trk` (its `trkseg`s joined) or `rte` is a route of `trkpt`/`rtept` points
/// with `lat` and `lon` attributes and an optional `ele`; one whose `<type>` is "flown" is
/// skipped.
fn gpx_routes(text: &str, source: &str) -> Result<Vec<Route>> {
    let mut routes: Vec<Route> = Vec::new();
    let mut current: Option<Route> = None;
    let mut flown = false;
    let mut in_point = false;
    let mut field = String::new();
    xml_walk(text, source, |ev| {
        match ev {
            XmlEvent::Open { name, attrs, at } => match name {
                "trk" | "rte" => {
                    current = Some(Route { name: None, points: Vec::new() });
                    flown = false;
                }
                "trkpt" | "rtept" => {
                    let get = |k: &str| attrs.iter().find(|(a, _)| a == k).map(|(_, v)| v.as_str());
                    let (Some(lat), Some(lon)) = (get("lat"), get("lon")) else {
                        return Err(Error::input(
                            source,
                            format!("<{name}> at byte {at} needs lat and lon attributes"),
                        ));
                    };
                    let p = Vec3::new(number(lon, "lon", source, at)?, number(lat, "lat", source, at)?, f64::NAN);
                    if let Some(r) = current.as_mut() {
                        r.points.push(p);
                    }
                    in_point = true;
                }
                _ => field = name.to_string(),
            },
            XmlEvent::Text { text, at } => {
                if let Some(r) = current.as_mut() {
                    if in_point && field == "ele" {
                        if let Some(p) = r.points.last_mut() {
                            p.z = number(text, "ele", source, at)?;
                        }
                    } else if !in_point && field == "name" && r.name.is_none() {
                        r.name = Some(text.trim().to_string());
                    } else if !in_point && field == "type" && is_flown(text) {
                        flown = true;
                    }
                }
            }
            XmlEvent::Close { name } => match name {
                "trkpt" | "rtept" => in_point = false,
                "trk" | "rte" => routes.extend(current.take().filter(|_| !flown)),
                _ => field.clear(),
            },
        }
        Ok(())
    })?;
    Ok(routes)
}

/// KML 2.2: each placemark with a `LineString` (its `coordinates`, "lon,lat[,alt]" tuples) or
/// a `gx:Track` (its `gx:coord`s, "lon lat alt") is a route; a placemark with both gives its
/// track once. Point placemarks are skipped, and so are placemarks whose `ExtendedData` has
/// `<Data name="kind">` "flown".
fn kml_routes(text: &str, source: &str) -> Result<Vec<Route>> {
    let mut routes: Vec<Route> = Vec::new();
    let mut current: Option<(Option<String>, Vec<Vec3>, Vec<Vec3>)> = None;
    let mut field = String::new();
    // Inside `<Data name="kind">`, and whether this placemark's kind is "flown".
    let (mut in_kind, mut flown) = (false, false);
    xml_walk(text, source, |ev| {
        match ev {
            XmlEvent::Open { name, attrs, .. } => {
                if name == "Placemark" {
                    current = Some((None, Vec::new(), Vec::new()));
                    flown = false;
                }
                if name == "Data" {
                    in_kind = attrs.iter().any(|(k, v)| k == "name" && v == "kind");
                }
                field = name.to_string();
            }
            XmlEvent::Text { text, at } => {
                let Some((pname, line, track)) = current.as_mut() else { return Ok(()) };
                match field.as_str() {
                    "value" if in_kind => flown = is_flown(text),
                    "name" if pname.is_none() => *pname = Some(text.trim().to_string()),
                    "coordinates" => {
                        for tuple in text.split_whitespace() {
                            let v: Vec<&str> = tuple.split(',').collect();
                            if v.len() < 2 {
                                return Err(Error::input(
                                    source,
                                    format!(
                                        "coordinates '{}' at byte {at}: expected lon,lat[,alt]",
                                        tidepath::text::one_line(tuple)
                                    ),
                                ));
                            }
                            let z = v.get(2).map(|z| number(z, "altitude", source, at)).transpose()?;
                            line.push(Vec3::new(
                                number(v[0], "longitude", source, at)?,
                                number(v[1], "latitude", source, at)?,
                                z.unwrap_or(f64::NAN),
                            ));
                        }
                    }
                    "coord" => {
                        let v: Vec<&str> = text.split_whitespace().collect();
                        if v.len() < 2 {
                            return Err(Error::input(
                                source,
                                format!(
                                    "gx:coord '{}' at byte {at}: expected lon lat [alt]",
                                    tidepath::text::one_line(text.trim())
                                ),
                            ));
                        }
                        let z = v.get(2).map(|z| number(z, "altitude", source, at)).transpose()?;
                        track.push(Vec3::new(
                            number(v[0], "longitude", source, at)?,
                            number(v[1], "latitude", source, at)?,
                            z.unwrap_or(f64::NAN),
                        ));
                    }
                    _ => {}
                }
            }
            XmlEvent::Close { name } => {
                if name == "Data" {
                    in_kind = false;
                }
                if name == "Placemark" {
                    if let Some((pname, line, track)) = current.take().filter(|_| !flown) {
                        // A Point placemark (the start and goal marks) holds one coordinate.
                        let points = if track.len() >= 2 { track } else { line };
                        if points.len() >= 2 {
                            routes.push(Route { name: pname, points });
                        }
                    }
                }
                field.clear();
            }
        }
        Ok(())
    })?;
    Ok(routes)
}

/// CSV with a header: `mission`, optional `point` (the order within a mission), optional
/// `kind` (rows of kind "flown" are skipped), and either `lat`, `lon` (with optional
/// `depth_m`) or `x_m`, `y_m`, `z_m`.
fn csv_routes(text: &str, source: &str) -> Result<PlanFile> {
    let mut reader = csv::ReaderBuilder::new().has_headers(true).flexible(false).from_reader(text.as_bytes());
    let headers = reader.headers().map_err(|e| Error::input(source, format!("unreadable CSV header: {e}")))?.clone();
    let col = |name: &str| headers.iter().position(|h| h.trim().eq_ignore_ascii_case(name));
    let (frame, a, b, c) = match (col("lon"), col("lat"), col("x_m"), col("y_m")) {
        (Some(lon), Some(lat), _, _) => (RouteFrame::LonLat, lon, lat, col("depth_m")),
        (_, _, Some(x), Some(y)) => (RouteFrame::Metres, x, y, col("z_m")),
        _ => {
            return Err(Error::input(
                source,
                "the CSV header needs `lat` and `lon` (with `depth_m`) or `x_m`, `y_m` and `z_m` columns",
            ))
        }
    };
    let (mission, point, kind) = (col("mission"), col("point"), col("kind"));
    // Missions in order of first appearance; points ordered by `point` when given.
    let mut routes: Vec<(String, Vec<(f64, Vec3)>)> = Vec::new();
    for (row, record) in reader.records().enumerate() {
        let line = row + 2;
        let record = record.map_err(|e| Error::input(source, format!("line {line}: {e}")))?;
        if kind.and_then(|k| record.get(k)).is_some_and(is_flown) {
            continue;
        }
        let field = |k: usize, what: &str| -> Result<f64> {
            let t = record.get(k).unwrap_or("").trim();
            t.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| {
                Error::input(
                    source,
                    format!("line {line}, column {what}: '{}' is not a finite number", tidepath::text::one_line(t)),
                )
            })
        };
        let name = mission.and_then(|k| record.get(k)).unwrap_or("").to_string();
        let order = match point {
            Some(k) => field(k, "point")?,
            None => row as f64,
        };
        let third = match c {
            Some(k) if !record.get(k).unwrap_or("").trim().is_empty() => {
                let v = field(k, &headers[k])?;
                if frame == RouteFrame::LonLat {
                    -v
                } else {
                    v
                }
            }
            _ => f64::NAN,
        };
        let p = Vec3::new(field(a, &headers[a])?, field(b, &headers[b])?, third);
        match routes.iter_mut().find(|(n, _)| *n == name) {
            Some((_, pts)) => pts.push((order, p)),
            None => routes.push((name, vec![(order, p)])),
        }
    }
    let routes = routes
        .into_iter()
        .map(|(name, mut pts)| {
            pts.sort_by(|x, y| x.0.total_cmp(&y.0));
            Route { name: (!name.is_empty()).then_some(name), points: pts.into_iter().map(|(_, p)| p).collect() }
        })
        .collect();
    finish(routes, frame, "CSV", source)
}
