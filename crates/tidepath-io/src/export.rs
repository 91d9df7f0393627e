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
        ExportFormat::Csv => Ok(csv(report, geo)),
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

fn utc(epoch: Option<DateTime<Utc>>, t: f64) -> Option<String> {
    let e = epoch?;
    if !t.is_finite() {
        return None;
    }
    // An arrival beyond the calendar (a hostile plan's time) is left blank, never a panic.
    let at = e.checked_add_signed(chrono::TimeDelta::try_milliseconds((t * 1e3).round() as i64)?)?;
    Some(at.to_rfc3339_opts(chrono::SecondsFormat::Millis, true))
}

fn num(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        String::new()
    }
}

fn csv(report: &PlanReport, geo: Georef<'_>) -> String {
    let mut out = String::new();
    match geo.frame {
        Some(f) => {
            out.push_str("mission,point,lat,lon,depth_m,time_s,utc\n");
            for (name, track) in tracks(report, f) {
                for (k, p) in track.iter().enumerate() {
                    out.push_str(&format!(
                        "{},{k},{:.7},{:.7},{},{},{}\n",
                        csv_field(&name),
                        p.lat,
                        p.lon,
                        num(-p.z + 0.0),
                        num(p.t),
                        utc(geo.epoch, p.t).unwrap_or_default()
                    ));
                }
            }
        }
        None => {
            out.push_str("mission,point,x_m,y_m,z_m,time_s\n");
            for m in &report.missions {
                for (k, p) in m.points().iter().enumerate() {
                    let t = m.times.get(k).copied().unwrap_or(f64::NAN);
                    out.push_str(&format!("{},{k},{},{},{},{}\n", csv_field(&m.name), p.x, p.y, p.z, num(t)));
                }
            }
        }
    }
    out
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn geojson(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    use geojson::{Feature, FeatureCollection, Geometry, GeometryValue, JsonObject, JsonValue};
    let f = frame(geo, ".geojson")?;
    let mut features = Vec::new();
    for (name, track) in tracks(report, f) {
        let coords: Vec<[f64; 3]> = track.iter().map(|p| [round7(p.lon), round7(p.lat), p.z]).collect();
        let mut props = JsonObject::new();
        props.insert("name".into(), JsonValue::from(name));
        props.insert("scenario".into(), JsonValue::from(report.scenario.clone()));
        props.insert("planner".into(), JsonValue::from(report.planner.clone()));
        props.insert("status".into(), JsonValue::from(report.status.to_string()));
        props.insert("feasible".into(), JsonValue::from(report.feasible));
        props.insert("depth_m".into(), JsonValue::from(track.iter().map(|p| -p.z + 0.0).collect::<Vec<_>>()));
        props.insert(
            "time_s".into(),
            JsonValue::from(
                track
                    .iter()
                    .map(|p| if p.t.is_finite() { JsonValue::from(p.t) } else { JsonValue::Null })
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

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;").replace('\'', "&apos;")
}

fn kml(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let f = frame(geo, ".kml")?;
    let mut out = String::from(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\">\n<Document>\n",
    );
    out.push_str(&format!(
        "<name>{}</name>\n<description>{} plan by {}: {}</description>\n",
        xml_escape(&report.scenario),
        xml_escape(&report.scenario),
        xml_escape(&report.planner),
        xml_escape(&format!("{}: {}", report.status, report.reason))
    ));
    out.push_str("<Style id=\"route\"><LineStyle><color>ff0080ff</color><width>3</width></LineStyle></Style>\n");
    for (name, track) in tracks(report, f) {
        out.push_str(&format!("<Placemark>\n<name>{}</name>\n<styleUrl>#route</styleUrl>\n", xml_escape(&name)));
        out.push_str("<LineString>\n<altitudeMode>absolute</altitudeMode>\n<coordinates>\n");
        for p in &track {
            out.push_str(&format!("{:.7},{:.7},{}\n", p.lon, p.lat, p.z));
        }
        out.push_str("</coordinates>\n</LineString>\n</Placemark>\n");
    }
    out.push_str("</Document>\n</kml>\n");
    Ok(out)
}

fn gpx(report: &PlanReport, geo: Georef<'_>) -> Result<String> {
    let f = frame(geo, ".gpx")?;
    let mut out = String::from(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<gpx version=\"1.1\" creator=\"tidepath\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n",
    );
    out.push_str(&format!(
        "<metadata><name>{}</name><desc>{}</desc></metadata>\n",
        xml_escape(&report.scenario),
        xml_escape(&format!("{} plan: {}: {}", report.planner, report.status, report.reason))
    ));
    for (name, track) in tracks(report, f) {
        out.push_str(&format!("<trk><name>{}</name><trkseg>\n", xml_escape(&name)));
        for p in &track {
            out.push_str(&format!("<trkpt lat=\"{:.7}\" lon=\"{:.7}\"><ele>{}</ele>", p.lat, p.lon, p.z));
            if let Some(t) = utc(geo.epoch, p.t) {
                out.push_str(&format!("<time>{t}</time>"));
            }
            out.push_str("</trkpt>\n");
        }
        out.push_str("</trkseg></trk>\n");
    }
    out.push_str("</gpx>\n");
    Ok(out)
}
