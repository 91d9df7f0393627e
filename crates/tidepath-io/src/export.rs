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
//!   has an epoch (ISO departures or `world.epoch`);
//! * with a turning radius a mission has two lines, labelled: its **waypoints** (the route an
//!   autopilot is given, and what `eval` and `plan --init` read back) and the curve the
//!   vehicle **flies** along them (a fillet at each interior waypoint, sampled as the
//!   evaluation checked it, with its times). GeoJSON: two features, property `kind`
//!   `"waypoints"` and `"flown"`; GPX: a `<rte>` of the waypoints and a `<trk>` of the flown
//!   curve, `<type>` saying which; KML: a second placemark "NAME (flown)" with
//!   `<Data name="kind">` `flown`; CSV: a `kind` column. Without a radius the files are as
//!   they were (one line per mission, no `kind`).

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

/// One timed point of a mission's final path or flown curve.
struct Point {
    lon: f64,
    lat: f64,
    z: f64,
    t: f64,
}

/// The `kind` of a mission's waypoints and of its flown curve, in every format that labels
/// them.
pub const KIND_WAYPOINTS: &str = "waypoints";
pub const KIND_FLOWN: &str = "flown";

/// One mission's lines in longitude/latitude: its waypoints and, with a turning radius, the
/// curve the vehicle flies along them.
struct Track {
    name: String,
    waypoints: Vec<Point>,
    flown: Option<Vec<Point>>,
}

/// Whether any mission of the plan has a flown curve: the exports then label their lines.
fn has_flown(report: &PlanReport) -> bool {
    report.missions.iter().any(|m| m.flown.is_some())
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

/// Timed points in longitude/latitude (a time is NaN where `times` has none).
fn lonlat(points: &[Vec3], times: &[f64], f: &GeoFrame) -> Vec<Point> {
    points
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let (lon, lat) = f.inverse(p.x, p.y);
            Point { lon, lat, z: p.z, t: times.get(k).copied().unwrap_or(f64::NAN) }
        })
        .collect()
}

fn tracks(report: &PlanReport, f: &GeoFrame) -> Vec<Track> {
    report
        .missions
        .iter()
        .map(|m| Track {
            name: m.name.clone(),
            waypoints: lonlat(&m.points(), &m.times, f),
            flown: m.flown.as_ref().map(|c| lonlat(&c.vectors(), &c.times, f)),
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

/// One row per point: of the waypoints, then (with a turning radius, `kind` `flown`) of the
/// flown curve, mission by mission; the `kind` column is there only when a mission has a flown
/// curve.
fn csv(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let mut w = crate::csv_table::writer();
    let row = |w: &mut csv::Writer<Vec<u8>>, fields: Vec<String>| crate::csv_table::row(w, "--out", &fields);
    let labelled = has_flown(report);
    // The mission's name, then its kind when lines are labelled.
    let lead = |name: &str, kind: &str| {
        let mut v = vec![name.to_string()];
        if labelled {
            v.push(kind.to_string());
        }
        v
    };
    match geo.frame {
        Some(f) => {
            row(
                &mut w,
                [
                    lead("mission", "kind"),
                    ["point", "lat", "lon", "depth_m", "time_s", "utc"].map(String::from).to_vec(),
                ]
                .concat(),
            )?;
            for t in tracks(report, f) {
                let lines = [(KIND_WAYPOINTS, Some(&t.waypoints)), (KIND_FLOWN, t.flown.as_ref())];
                for (kind, line) in lines.into_iter().filter_map(|(k, l)| l.map(|l| (k, l))) {
                    for (k, p) in line.iter().enumerate() {
                        let fields = [
                            k.to_string(),
                            format!("{:.7}", p.lat),
                            format!("{:.7}", p.lon),
                            fixed(-p.z + 0.0, 2),
                            fixed(p.t, 3),
                            utc(geo.epoch, p.t).unwrap_or_default(),
                        ];
                        row(&mut w, [lead(&t.name, kind), fields.to_vec()].concat())?;
                    }
                }
            }
        }
        None => {
            row(
                &mut w,
                [lead("mission", "kind"), ["point", "x_m", "y_m", "z_m", "time_s"].map(String::from).to_vec()].concat(),
            )?;
            for m in &report.missions {
                let waypoints = (m.points(), m.times.as_slice());
                let flown = m.flown.as_ref().map(|c| (c.vectors(), c.times.as_slice()));
                let lines = [(KIND_WAYPOINTS, Some(waypoints)), (KIND_FLOWN, flown)];
                for (kind, (points, times)) in lines.into_iter().filter_map(|(k, l)| l.map(|l| (k, l))) {
                    for (k, p) in points.iter().enumerate() {
                        let t = times.get(k).copied().unwrap_or(f64::NAN);
                        let fields = [k.to_string(), fixed(p.x, 3), fixed(p.y, 3), fixed(p.z, 3), fixed(t, 3)];
                        row(&mut w, [lead(&m.name, kind), fields.to_vec()].concat())?;
                    }
                }
            }
        }
    }
    crate::csv_table::text(w, "--out")
}

/// A mission's line as a GeoJSON feature: the line, and per point its depth, time and (with an
/// epoch) UTC instant; `kind` labels it when the plan has flown curves.
fn geojson_feature(
    report: &PlanReport,
    name: &str,
    kind: Option<&str>,
    line: &[Point],
    geo: Georef<'_>,
) -> geojson::Feature {
    use geojson::{Feature, Geometry, GeometryValue, JsonObject, JsonValue};
    let coords: Vec<[f64; 3]> = line.iter().map(|p| [round7(p.lon), round7(p.lat), round_to(p.z, 2)]).collect();
    let mut props = JsonObject::new();
    props.insert("name".into(), JsonValue::from(name));
    if let Some(kind) = kind {
        props.insert("kind".into(), JsonValue::from(kind));
    }
    props.insert("scenario".into(), JsonValue::from(report.scenario.clone()));
    props.insert("planner".into(), JsonValue::from(report.planner.clone()));
    props.insert("status".into(), JsonValue::from(report.status.to_string()));
    props.insert("feasible".into(), JsonValue::from(report.feasible));
    props.insert("depth_m".into(), JsonValue::from(line.iter().map(|p| round_to(-p.z, 2)).collect::<Vec<_>>()));
    props.insert(
        "time_s".into(),
        JsonValue::from(
            line.iter()
                .map(|p| if p.t.is_finite() { JsonValue::from(round_to(p.t, 3)) } else { JsonValue::Null })
                .collect::<Vec<_>>(),
        ),
    );
    if geo.epoch.is_some() {
        let times: Vec<JsonValue> =
            line.iter().map(|p| utc(geo.epoch, p.t).map(JsonValue::from).unwrap_or(JsonValue::Null)).collect();
        props.insert("utc".into(), JsonValue::from(times));
    }
    // A LineString needs two positions; a mission without a path has no geometry.
    let geometry = (coords.len() >= 2).then(|| Geometry::new(GeometryValue::new_line_string(coords)));
    Feature { bbox: None, geometry, id: None, properties: Some(props), foreign_members: None }
}

fn geojson(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    use geojson::FeatureCollection;
    let f = frame(geo, ".geojson")?;
    let labelled = has_flown(report);
    let mut features = Vec::new();
    for t in tracks(report, f) {
        let kind = labelled.then_some(KIND_WAYPOINTS);
        features.push(geojson_feature(report, &t.name, kind, &t.waypoints, geo));
        if let Some(flown) = &t.flown {
            features.push(geojson_feature(report, &t.name, Some(KIND_FLOWN), flown, geo));
        }
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
pub(crate) fn xml_text(s: &str) -> String {
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
/// (docs/data-formats.md says how). With a turning radius the route placemark is the thin line
/// of the waypoints and a second placemark, "NAME (flown)", the thick line of the flown
/// curve; each says its `kind` in its `ExtendedData`.
fn kml(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let f = frame(geo, ".kml")?;
    let labelled = has_flown(report);
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
        // (style id, colour aabbggrr, width): with flown curves the waypoints are a thin, paler
        // line under the flown curve, so the corners the vehicle cuts show.
        let styles: &[(&str, &str, &str)] = if labelled {
            &[(KIND_WAYPOINTS, "b30080ff", "1.5"), (KIND_FLOWN, "ff0080ff", "3")]
        } else {
            &[("route", "ff0080ff", "3")]
        };
        for (id, color, width) in styles {
            start(w, "Style", &[("id", id)])?;
            start(w, "LineStyle", &[])?;
            element(w, "color", color)?;
            element(w, "width", width)?;
            end(w, "LineStyle")?;
            end(w, "Style")?;
        }
        for t in tracks(report, f) {
            if labelled {
                kml_line(w, &t.name, KIND_WAYPOINTS, Some(KIND_WAYPOINTS), &t.waypoints, geo)?;
            } else {
                kml_line(w, &t.name, "route", None, &t.waypoints, geo)?;
            }
            if let Some(flown) = &t.flown {
                kml_line(w, &format!("{} (flown)", t.name), KIND_FLOWN, Some(KIND_FLOWN), flown, geo)?;
            }
            let ends = [("start", t.waypoints.first()), ("goal", t.waypoints.last())];
            for (what, p) in ends.into_iter().filter_map(|(w, p)| p.map(|p| (w, p))) {
                start(w, "Placemark", &[])?;
                element(w, "name", &format!("{} {what}", t.name))?;
                start(w, "Point", &[])?;
                element(w, "altitudeMode", "absolute")?;
                element(w, "coordinates", &kml_coord(p, ","))?;
                end(w, "Point")?;
                end(w, "Placemark")?;
            }
        }
        end(w, "Document")?;
        end(w, "kml")
    })
}

fn kml_coord(p: &Point, sep: &str) -> String {
    format!("{:.7}{sep}{:.7}{sep}{}", p.lon, p.lat, fixed(p.z, 2))
}

/// One line placemark: a `gx:Track` when every point has a UTC time, else a `LineString`;
/// `kind`, when given, goes in its `ExtendedData`.
fn kml_line(w: &mut Xml, name: &str, style: &str, kind: Option<&str>, line: &[Point], geo: Georef<'_>) -> Result<()> {
    start(w, "Placemark", &[])?;
    element(w, "name", name)?;
    element(w, "styleUrl", &format!("#{style}"))?;
    if let Some(kind) = kind {
        start(w, "ExtendedData", &[])?;
        start(w, "Data", &[("name", "kind")])?;
        element(w, "value", kind)?;
        end(w, "Data")?;
        end(w, "ExtendedData")?;
    }
    let times: Option<Vec<String>> = line.iter().map(|p| utc(geo.epoch, p.t)).collect();
    match times {
        Some(times) if !line.is_empty() => {
            start(w, "gx:Track", &[])?;
            element(w, "altitudeMode", "absolute")?;
            for t in &times {
                element(w, "when", t)?;
            }
            for p in line {
                element(w, "gx:coord", &kml_coord(p, " "))?;
            }
            end(w, "gx:Track")?;
        }
        _ => {
            start(w, "LineString", &[])?;
            element(w, "altitudeMode", "absolute")?;
            let coords: Vec<String> = line.iter().map(|p| kml_coord(p, ",")).collect();
            element(w, "coordinates", &coords.join(" "))?;
            end(w, "LineString")?;
        }
    }
    end(w, "Placemark")
}

/// GPX 1.1 for chart plotters: one track per mission. With a turning radius, the waypoints of
/// every mission are a route (`<rte>`, what a plotter or autopilot follows) and the flown
/// curves are tracks (`<trk>`, with times); `<type>` says which, and GPX's order puts every
/// route before the tracks.
fn gpx(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let f = frame(geo, ".gpx")?;
    let labelled = has_flown(report);
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
        let tracks = tracks(report, f);
        if labelled {
            for t in &tracks {
                start(w, "rte", &[])?;
                element(w, "name", &t.name)?;
                element(w, "type", KIND_WAYPOINTS)?;
                gpx_points(w, "rtept", &t.waypoints, geo)?;
                end(w, "rte")?;
            }
            for t in &tracks {
                let Some(flown) = &t.flown else { continue };
                start(w, "trk", &[])?;
                element(w, "name", &format!("{} (flown)", t.name))?;
                element(w, "type", KIND_FLOWN)?;
                start(w, "trkseg", &[])?;
                gpx_points(w, "trkpt", flown, geo)?;
                end(w, "trkseg")?;
                end(w, "trk")?;
            }
        } else {
            for t in &tracks {
                start(w, "trk", &[])?;
                element(w, "name", &t.name)?;
                start(w, "trkseg", &[])?;
                gpx_points(w, "trkpt", &t.waypoints, geo)?;
                end(w, "trkseg")?;
                end(w, "trk")?;
            }
        }
        end(w, "gpx")
    })
}

/// `<tag lat lon>` points with their elevation and, with an epoch, UTC time.
fn gpx_points(w: &mut Xml, tag: &str, line: &[Point], geo: Georef<'_>) -> Result<()> {
    for p in line {
        let (lat, lon) = (format!("{:.7}", p.lat), format!("{:.7}", p.lon));
        start(w, tag, &[("lat", &lat), ("lon", &lon)])?;
        element(w, "ele", &fixed(p.z, 2))?;
        if let Some(t) = utc(geo.epoch, p.t) {
            element(w, "time", &t)?;
        }
        end(w, tag)?;
    }
    Ok(())
}
