//! Plan files read back (`eval`, `plan --init`): any format version, and hand-written files
//! that give only waypoints.

use serde::Deserialize;

use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;

use super::{MAX_PLAN_POINTS, PLAN_FORMAT_VERSION};

/// One mission's path in a plan file, in either format version.
#[derive(Clone, Debug, Deserialize)]
struct PathEntry {
    #[serde(default)]
    name: Option<String>,
    waypoints: Vec<[f64; 3]>,
    #[serde(default)]
    smoothed: Option<Vec<[f64; 3]>>,
    #[serde(default)]
    speeds: Option<Vec<f64>>,
    #[serde(default)]
    cost: Option<f64>,
}

/// The part of a plan file `eval` and `plan --init` need; other fields are optional so
/// hand-written files work. Version 2 files list `missions`; version 1 files (and hand-written
/// ones) may give `waypoints` (and `smoothed`, `cost`) at the top level instead.
#[derive(Clone, Debug, Deserialize)]
struct RawPlanFile {
    #[serde(default)]
    version: Option<u32>,
    #[serde(default)]
    missions: Option<Vec<PathEntry>>,
    #[serde(default)]
    waypoints: Option<Vec<[f64; 3]>>,
    #[serde(default)]
    smoothed: Option<Vec<[f64; 3]>>,
    #[serde(default)]
    cost: Option<f64>,
    #[serde(default)]
    planner: Option<String>,
    #[serde(default)]
    scenario: Option<String>,
    #[serde(default)]
    format: Option<String>,
    #[serde(default)]
    frame: Option<String>,
}

/// The frame of a route file's points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RouteFrame {
    /// The scenario's frame: x east, y north, z up (m).
    Metres,
    /// Longitude and latitude (degrees); points hold (longitude, latitude, elevation = -depth).
    LonLat,
}

/// A plan file as read: one final path per mission.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanFile {
    /// (mission name if given, final path).
    pub paths: Vec<(Option<String>, Vec<Vec3>)>,
    /// Per path, its segments' through-water speeds when the file gives them (plan JSON
    /// `speeds`); empty for formats without speeds.
    pub speeds: Vec<Option<Vec<f64>>>,
    /// The recorded total cost, if any.
    pub cost: Option<f64>,
    pub planner: Option<String>,
    pub scenario: Option<String>,
    /// 1 for files without a version field.
    pub version: u32,
    /// The frame the file's points are in; `None` when a hand-written plan JSON does not say
    /// (metres for a local scenario; a geographic one asks).
    pub frame: Option<RouteFrame>,
    /// "plan JSON", "GeoJSON", "GPX", "KML" or "CSV".
    pub format: &'static str,
}

impl PlanFile {
    pub fn read(path: &std::path::Path) -> Result<Self> {
        let shown = path.display().to_string();
        let text = crate::input::read_text(path, &shown, crate::input::MAX_PLAN_BYTES)?;
        Self::parse(&text, &shown)
    }

    pub fn parse(text: &str, source: &str) -> Result<Self> {
        let de = &mut serde_json::Deserializer::from_str(text);
        let raw: RawPlanFile = serde_path_to_error::deserialize(&mut *de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            let field = if path == "." { source.to_string() } else { format!("{source}: {path}") };
            Error::input(
                field,
                format!("{} (line {}, column {})", strip_position(&inner.to_string()), inner.line(), inner.column()),
            )
        })?;
        // Anything after the JSON object is a damaged or concatenated file, not a plan.
        de.end().map_err(|e| {
            Error::input(
                source,
                format!("unexpected text after the plan's JSON object (line {}, column {})", e.line(), e.column()),
            )
        })?;
        let version = raw.version.unwrap_or(1);
        if version == 0 {
            return Err(Error::input(format!("{source}: version"), "must be 1 or more, got 0"));
        }
        if version > PLAN_FORMAT_VERSION {
            return Err(Error::input(
                format!("{source}: version"),
                format!("{version} is newer than this tidepath reads ({PLAN_FORMAT_VERSION})"),
            ));
        }
        let frame = match raw.frame.as_deref() {
            Some("lonlat") => Some(RouteFrame::LonLat),
            Some("metres" | "meters") => Some(RouteFrame::Metres),
            Some(other) => {
                return Err(Error::input(
                    format!("{source}: frame"),
                    format!("must be \"metres\" or \"lonlat\", got \"{}\"", tidepath::text::one_line(other)),
                ))
            }
            // Files tidepath writes are in metres.
            None => (raw.format.as_deref() == Some("tidepath-plan")).then_some(RouteFrame::Metres),
        };
        let entries: Vec<(String, PathEntry)> = match (raw.missions, raw.waypoints) {
            (Some(_), Some(_)) => {
                return Err(Error::input(source, "give either `missions` or top-level `waypoints`, not both"));
            }
            (Some(m), None) => m.into_iter().enumerate().map(|(i, e)| (format!("missions[{i}]."), e)).collect(),
            (None, Some(w)) => {
                vec![(
                    String::new(),
                    PathEntry { name: None, waypoints: w, smoothed: raw.smoothed, speeds: None, cost: raw.cost },
                )]
            }
            (None, None) => return Err(Error::input(source, "no path: expected `missions` or `waypoints`")),
        };
        if entries.is_empty() {
            return Err(Error::input(format!("{source}: missions"), "is empty"));
        }
        let mut paths = Vec::with_capacity(entries.len());
        let mut speeds = Vec::with_capacity(entries.len());
        for (prefix, e) in entries {
            let lists = [("waypoints", Some(&e.waypoints)), ("smoothed", e.smoothed.as_ref())];
            for (name, list) in lists.into_iter().filter_map(|(n, l)| l.map(|l| (n, l))) {
                if list.len() < 2 {
                    return Err(Error::input(
                        format!("{source}: {prefix}{name}"),
                        format!("a path needs at least 2 points, got {}", list.len()),
                    ));
                }
                if list.len() > MAX_PLAN_POINTS {
                    return Err(Error::input(
                        format!("{source}: {prefix}{name}"),
                        format!("at most {MAX_PLAN_POINTS} points, got {}", list.len()),
                    ));
                }
                for (i, p) in list.iter().enumerate() {
                    if p.iter().any(|v| !v.is_finite()) {
                        return Err(Error::input(
                            format!("{source}: {prefix}{name}[{i}]"),
                            format!("{p:?}: numbers must be finite"),
                        ));
                    }
                }
            }
            let _ = e.cost;
            if let Some(v) = &e.speeds {
                let segments = e.smoothed.as_ref().unwrap_or(&e.waypoints).len() - 1;
                if v.len() != segments {
                    return Err(Error::input(
                        format!("{source}: {prefix}speeds"),
                        format!("one speed per segment of the final path: expected {segments}, got {}", v.len()),
                    ));
                }
                if let Some((i, s)) = v.iter().enumerate().find(|(_, s)| !(s.is_finite() && **s > 0.0)) {
                    return Err(Error::input(
                        format!("{source}: {prefix}speeds[{i}]"),
                        format!("must be a positive number of m/s, got {s}"),
                    ));
                }
            }
            speeds.push(e.speeds.clone());
            // Longitude/latitude files give depth positive down; points hold the elevation.
            let sign = if frame == Some(RouteFrame::LonLat) { -1.0 } else { 1.0 };
            let pts = e
                .smoothed
                .as_ref()
                .unwrap_or(&e.waypoints)
                .iter()
                .map(|p| Vec3::new(p[0], p[1], sign * p[2]))
                .collect();
            paths.push((e.name, pts));
        }
        Ok(Self {
            paths,
            speeds,
            cost: raw.cost,
            planner: raw.planner,
            scenario: raw.scenario,
            version,
            frame,
            format: "plan JSON",
        })
    }

    /// The final path of each mission.
    pub fn mission_paths(&self) -> Vec<Vec<Vec3>> {
        self.paths.iter().map(|(_, p)| p.clone()).collect()
    }
}

/// serde_json appends " at line L column C"; we print the position once, our way.
fn strip_position(msg: &str) -> &str {
    msg.rfind(" at line ").map_or(msg, |i| &msg[..i])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_file_errors_name_the_field() {
        let e = PlanFile::parse(r#"{"waypoints": [[0,0,0],[1,"a",0]]}"#, "p.json").unwrap_err().to_string();
        assert!(e.starts_with("p.json: waypoints[1][1]: invalid type"), "{e}");
        let e = PlanFile::parse(r#"{"waypoints": [[0,0,0]]}"#, "p.json").unwrap_err().to_string();
        assert!(e.contains("at least 2 points"), "{e}");
        let e = PlanFile::parse("{not json", "p.json").unwrap_err().to_string();
        assert!(e.starts_with("p.json"), "{e}");
        let e = PlanFile::parse(r#"{"version": 2, "missions": [{"waypoints": [[0,0,0],[1,0,NaN]]}]}"#, "p.json");
        assert!(e.is_err());
        let e = PlanFile::parse(r#"{"waypoints": [[0,0,0],[1,0,0]]} {"x": 1}"#, "p.json").unwrap_err().to_string();
        assert!(e.starts_with("p.json: unexpected text after the plan's JSON object"), "{e}");
        assert!(PlanFile::parse("{\"waypoints\": [[0,0,0],[1,0,0]]}\n  \n", "p.json").is_ok());
        let e = PlanFile::parse(r#"{"version": 0, "waypoints": [[0,0,0],[1,0,0]]}"#, "p.json").unwrap_err().to_string();
        assert_eq!(e, "p.json: version: must be 1 or more, got 0");
        let e = PlanFile::parse(r#"{"version": 9, "missions": []}"#, "p.json").unwrap_err().to_string();
        assert!(e.contains("newer"), "{e}");
    }

    #[test]
    fn version_one_and_two_files_both_load() {
        let v1 =
            PlanFile::parse(r#"{"waypoints": [[0,0,0],[1,0,0]], "smoothed": [[0,0,0],[2,0,0]], "cost": 1.5}"#, "a")
                .unwrap();
        assert_eq!(v1.version, 1);
        assert_eq!(v1.mission_paths(), vec![vec![Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0)]]);
        let v2 = PlanFile::parse(
            r#"{"version": 2, "missions": [{"name": "a", "waypoints": [[0,0,0],[1,0,0]]},
                {"name": "b", "waypoints": [[0,1,0],[1,1,0]]}]}"#,
            "b",
        )
        .unwrap();
        assert_eq!(v2.paths.len(), 2);
        assert_eq!(v2.paths[1].0.as_deref(), Some("b"));
    }
}
