//! Plans in the forms GIS and mission tools open, chosen by the output file's extension:
//! `.json` (tidepath's plan), `.geojson` (RFC 7946), `.csv`, `.kml` (Google Earth), `.gpx`
//! (chart plotters).
//!
//! Geographic formats need latitude and longitude, so they need a geographic scenario (its
//! frame turns metres back into degrees); `.csv` of a local scenario gives metres instead.
//! Conventions, the same in every format:
//!
//! * depth is metres below the sea surface, positive down (`depth_m`); where a format's third
//!   coordinate is an altitude (GeoJSON, KML, GPX `ele`) it holds the elevation z = -depth,
//!   as RFC 7946 and KML define it;
//! * times are seconds on the scenario clock (`time_s`), and UTC instants where the scenario
//!   has an epoch (ISO departures or `world.epoch`).

use chrono::{DateTime, Utc};

use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};

use super::PlanReport;
use tidepath::error::{Error, Result};
use tidepath::geo::GeoFrame;
use tidepath::geom::Vec3;

/// The output formats, by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExportFormat {
    Json,
    GeoJson,
    Csv,
    Kml,
    Gpx,
}

pub const EXTENSIONS: &str = ".json, .geojson, .csv, .kml, .gpx";

impl ExportFormat {
    /// The format of an output path by its extension; `flag` names the option in errors.
    pub fn of(path: &std::path::Path, flag: &str) -> Result<Self> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        Ok(match ext.as_str() {
            "json" => ExportFormat::Json,
            "geojson" => ExportFormat::GeoJson,
            "csv" => ExportFormat::Csv,
            "kml" => ExportFormat::Kml,
            "gpx" => ExportFormat::Gpx,
            _ => {
                return Err(Error::input(
                    flag,
                    format!("'{}': unknown extension (known: {EXTENSIONS})", path.display()),
                ))
            }
        })
    }
}

impl ExportFormat {
    /// Whether the format is in latitude/longitude (and so needs a geographic scenario).
    pub fn is_geographic(self) -> bool {
        matches!(self, ExportFormat::GeoJson | ExportFormat::Kml | ExportFormat::Gpx)
    }

    /// Refuses a latitude/longitude format for a scenario without a geographic frame, before
    /// any planning time is spent.
    pub fn check(self, frame: Option<&GeoFrame>, flag: &str) -> Result<()> {
        if self.is_geographic() && frame.is_none() {
            return Err(Error::input(
                flag,
                "this format is in latitude/longitude: use a geographic scenario (world.frame = \"geographic\"), or .json or .csv",
            ));
        }
        Ok(())
    }
}

/// Where the plan's metres and seconds sit on the Earth and the calendar.
#[derive(Clone, Copy)]
pub struct Georef<'a> {
    pub frame: Option<&'a GeoFrame>,
    pub epoch: Option<DateTime<Utc>>,
}

/// One timed point of a mission's final path.
struct Point {
    lon: f64,
    lat: f64,
    z: f64,
    t: f64,
}

/// The plan in `format`.
pub fn export(report: &PlanReport, format: ExportFormat, geo: Georef<'_>) -> Result<String> {
    match format {
        ExportFormat::Json => Ok(report.to_json()),
        ExportFormat::Csv => csv(report, geo),
        ExportFormat::GeoJson => geojson(report, geo),
        ExportFormat::Kml => kml(report, geo),
        ExportFormat::Gpx => gpx(report, geo),
    }
}

fn frame<'a>(geo: Georef<'a>, what: &str) -> Result<&'a GeoFrame> {
    geo.frame.ok_or_else(|| {
        Error::input(
            "--out",
            format!("{what} needs latitude/longitude: use a geographic scenario (world.frame = \"geographic\"), or .json or .csv"),
        )
    })
}

fn tracks(report: &PlanReport, f: &GeoFrame) -> Vec<(String, Vec<Point>)> {
    report
        .missions
        .iter()
        .map(|m| {
            let pts = m.points();
            let times = &m.times;
            let track = pts
                .iter()
                .enumerate()
                .map(|(k, p): (usize, &Vec3)| {
                    let (lon, lat) = f.inverse(p.x, p.y);
                    Point { lon, lat, z: p.z, t: times.get(k).copied().unwrap_or(f64::NAN) }
                })
                .collect();
            (m.name.clone(), track)
        })
        .collect()
}

/// The instant `t` seconds after `epoch` in UTC (RFC 3339, milliseconds), when there is an
/// epoch and the instant is on the calendar.
pub fn utc(epoch: Option<DateTime<Utc>>, t: f64) -> Option<String> {
    let e = epoch?;
    if !t.is_finite() {
        return None;
    }
    // An arrival beyond the calendar (a hostile plan's time) is left blank, never a panic.
    let at = e.checked_add_signed(chrono::TimeDelta::try_milliseconds((t * 1e3).round() as i64)?)?;
    Some(at.to_rfc3339_opts(chrono::SecondsFormat::Millis, true))
}

/// `v` with at most `decimals` decimals and no trailing zeros ("40.63", "12", "-0.5"): depth
/// to the centimetre, times to the millisecond, metres to the millimetre; blank when not a
/// number.
fn fixed(v: f64, decimals: usize) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.') } else { &s };
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Rounds to `decimals` decimals, for numbers written by serializers.
fn round_to(v: f64, decimals: i32) -> f64 {
    let f = 10f64.powi(decimals);
    (v * f).round() / f + 0.0
}

fn csv(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let mut w = crate::csv_table::writer();
    let row = |w: &mut csv::Writer<Vec<u8>>, fields: &[String]| crate::csv_table::row(w, "--out", fields);
    match geo.frame {
        Some(f) => {
            row(&mut w, &["mission", "point", "lat", "lon", "depth_m", "time_s", "utc"].map(String::from))?;
            for (name, track) in tracks(report, f) {
                for (k, p) in track.iter().enumerate() {
                    let fields = [
                        name.clone(),
                        k.to_string(),
                        format!("{:.7}", p.lat),
                        format!("{:.7}", p.lon),
                        fixed(-p.z + 0.0, 2),
                        fixed(p.t, 3),
                        utc(geo.epoch, p.t).unwrap_or_default(),
                    ];
                    row(&mut w, &fields)?;
                }
            }
        }
        None => {
            row(&mut w, &["mission", "point", "x_m", "y_m", "z_m", "time_s"].map(String::from))?;
            for m in &report.missions {
                for (k, p) in m.points().iter().enumerate() {
                    let t = m.times.get(k).copied().unwrap_or(f64::NAN);
                    let fields =
                        [m.name.clone(), k.to_string(), fixed(p.x, 3), fixed(p.y, 3), fixed(p.z, 3), fixed(t, 3)];
                    row(&mut w, &fields)?;
                }
            }
        }
    }
    crate::csv_table::text(w, "--out")
}

fn geojson(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    use geojson::{Feature, FeatureCollection, Geometry, GeometryValue, JsonObject, JsonValue};
    let f = frame(geo, ".geojson")?;
    let mut features = Vec::new();
    for (name, track) in tracks(report, f) {
        let coords: Vec<[f64; 3]> = track.iter().map(|p| [round7(p.lon), round7(p.lat), round_to(p.z, 2)]).collect();
        let mut props = JsonObject::new();
        props.insert("name".into(), JsonValue::from(name));
        props.insert("scenario".into(), JsonValue::from(report.scenario.clone()));
        props.insert("planner".into(), JsonValue::from(report.planner.clone()));
        props.insert("status".into(), JsonValue::from(report.status.to_string()));
        props.insert("feasible".into(), JsonValue::from(report.feasible));
        props.insert("depth_m".into(), JsonValue::from(track.iter().map(|p| round_to(-p.z, 2)).collect::<Vec<_>>()));
        props.insert(
            "time_s".into(),
            JsonValue::from(
                track
                    .iter()
                    .map(|p| if p.t.is_finite() { JsonValue::from(round_to(p.t, 3)) } else { JsonValue::Null })
                    .collect::<Vec<_>>(),
            ),
        );
        if geo.epoch.is_some() {
            let times: Vec<JsonValue> =
                track.iter().map(|p| utc(geo.epoch, p.t).map(JsonValue::from).unwrap_or(JsonValue::Null)).collect();
            props.insert("utc".into(), JsonValue::from(times));
        }
        // A LineString needs two positions; a mission without a path has no geometry.
        let geometry = (coords.len() >= 2).then(|| Geometry::new(GeometryValue::new_line_string(coords)));
        features.push(Feature { bbox: None, geometry, id: None, properties: Some(props), foreign_members: None });
    }
    let fc = FeatureCollection { bbox: None, features, foreign_members: None };
    Ok(fc.to_string())
}

/// Seven decimals of a degree: about 1 cm, as RFC 7946 suggests (no false precision).
fn round7(v: f64) -> f64 {
    (v * 1e7).round() / 1e7
}

/// Text that XML 1.0 can hold: characters it forbids even escaped (control characters other
/// than tab, newline and carriage return) are written as visible escapes, `\u{1b}`; the
/// writer escapes markup (`&`, `<`, ...).
fn xml_text(s: &str) -> String {
    let legal = |c: char| matches!(c, '\t' | '\n' | '\r') || (c >= ' ' && !matches!(c, '\u{FFFE}' | '\u{FFFF}'));
    if s.chars().all(legal) {
        return s.to_string();
    }
    s.chars().map(|c| if legal(c) { c.to_string() } else { format!("\\u{{{:x}}}", c as u32) }).collect()
}

type Xml = quick_xml::Writer<Vec<u8>>;

fn xml_error(e: std::io::Error) -> Error {
    Error::input("--out", format!("writing XML: {e}"))
}

/// `<tag>text</tag>`.
fn element(w: &mut Xml, tag: &str, text: &str) -> Result<()> {
    w.create_element(tag).write_text_content(BytesText::new(&xml_text(text))).map_err(xml_error)?;
    Ok(())
}

fn start(w: &mut Xml, tag: &str, attrs: &[(&str, &str)]) -> Result<()> {
    let mut e = BytesStart::new(tag);
    for (k, v) in attrs {
        e.push_attribute((*k, xml_text(v).as_str()));
    }
    w.write_event(Event::Start(e)).map_err(xml_error)
}

fn end(w: &mut Xml, tag: &str) -> Result<()> {
    w.write_event(Event::End(BytesEnd::new(tag))).map_err(xml_error)
}

fn xml_document(root: impl FnOnce(&mut Xml) -> Result<()>) -> Result<String> {
    let mut w = quick_xml::Writer::new_with_indent(Vec::new(), b' ', 1);
    w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None))).map_err(xml_error)?;
    root(&mut w)?;
    let mut text = String::from_utf8(w.into_inner()).expect("the writer writes the UTF-8 it is given");
    text.push('\n');
    Ok(text)
}

/// KML 2.2 for Google Earth: per mission a route placemark (a `gx:Track` with a time per
/// point when the scenario has an epoch, so the globe's time slider plays it, else a
/// `LineString`) and start and goal placemarks. Altitudes are `absolute`: below the sea
/// surface for an AUV, which Google Earth shows once its view goes under water
/// (docs/data-formats.md says how).
fn kml(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let f = frame(geo, ".kml")?;
    let coord = |p: &Point, sep: &str| format!("{:.7}{sep}{:.7}{sep}{}", p.lon, p.lat, fixed(p.z, 2));
    xml_document(|w| {
        start(
            w,
            "kml",
            &[("xmlns", "http://www.opengis.net/kml/2.2"), ("xmlns:gx", "http://www.google.com/kml/ext/2.2")],
        )?;
        start(w, "Document", &[])?;
        element(w, "name", &report.scenario)?;
        let desc = format!("{} plan by {}: {}: {}", report.scenario, report.planner, report.status, report.reason);
        element(w, "description", &desc)?;
        start(w, "Style", &[("id", "route")])?;
        start(w, "LineStyle", &[])?;
        element(w, "color", "ff0080ff")?;
        element(w, "width", "3")?;
        end(w, "LineStyle")?;
        end(w, "Style")?;
        for (name, track) in tracks(report, f) {
            start(w, "Placemark", &[])?;
            element(w, "name", &name)?;
            element(w, "styleUrl", "#route")?;
            let times: Option<Vec<String>> = track.iter().map(|p| utc(geo.epoch, p.t)).collect();
            match times {
                Some(times) if !track.is_empty() => {
                    start(w, "gx:Track", &[])?;
                    element(w, "altitudeMode", "absolute")?;
                    for t in &times {
                        element(w, "when", t)?;
                    }
                    for p in &track {
                        element(w, "gx:coord", &coord(p, " "))?;
                    }
                    end(w, "gx:Track")?;
                }
                _ => {
                    start(w, "LineString", &[])?;
                    element(w, "altitudeMode", "absolute")?;
                    let coords: Vec<String> = track.iter().map(|p| coord(p, ",")).collect();
                    element(w, "coordinates", &coords.join(" "))?;
                    end(w, "LineString")?;
                }
            }
            end(w, "Placemark")?;
            let ends = [("start", track.first()), ("goal", track.last())];
            for (what, p) in ends.into_iter().filter_map(|(w, p)| p.map(|p| (w, p))) {
                start(w, "Placemark", &[])?;
                element(w, "name", &format!("{name} {what}"))?;
                start(w, "Point", &[])?;
                element(w, "altitudeMode", "absolute")?;
                element(w, "coordinates", &coord(p, ","))?;
                end(w, "Point")?;
                end(w, "Placemark")?;
            }
        }
        end(w, "Document")?;
        end(w, "kml")
    })
}

fn gpx(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let f = frame(geo, ".gpx")?;
    xml_document(|w| {
        start(
            w,
            "gpx",
            &[("version", "1.1"), ("creator", "tidepath"), ("xmlns", "http://www.topografix.com/GPX/1/1")],
        )?;
        start(w, "metadata", &[])?;
        element(w, "name", &report.scenario)?;
        element(w, "desc", &format!("{} plan: {}: {}", report.planner, report.status, report.reason))?;
        end(w, "metadata")?;
        for (name, track) in tracks(report, f) {
            start(w, "trk", &[])?;
            element(w, "name", &name)?;
            start(w, "trkseg", &[])?;
            for p in &track {
                let (lat, lon) = (format!("{:.7}", p.lat), format!("{:.7}", p.lon));
                start(w, "trkpt", &[("lat", &lat), ("lon", &lon)])?;
                element(w, "ele", &fixed(p.z, 2))?;
                if let Some(t) = utc(geo.epoch, p.t) {
                    element(w, "time", &t)?;
                }
                end(w, "trkpt")?;
            }
            end(w, "trkseg")?;
            end(w, "trk")?;
        }
        end(w, "gpx")
    })
}
