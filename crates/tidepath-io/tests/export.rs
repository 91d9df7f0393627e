//! Plans exported for GIS and mission tools: GeoJSON parses (RFC 7946, by the `geojson`
//! crate) and round-trips; CSV, KML and GPX give back the plan's points; KML and GPX are
//! well-formed XML; latitude/longitude formats refuse a local scenario.

use tidepath_io::export::{export, ExportFormat, Georef};
use tidepath_io::scenario::{load, PlanRequest, Scenario};
use tidepath_io::PlanReport;

fn planned(name: &str) -> (Scenario, PlanReport) {
    let s = load(name).unwrap();
    let r = s
        .plan(&PlanRequest { planner: Some("hybrid".into()), seed: 1, ..PlanRequest::default() }, &mut |_| {})
        .unwrap();
    assert!(r.status.is_success(), "{}", r.reason);
    (s, r)
}

/// The plan's points in metres from latitude/longitude pairs, through the scenario's frame.
fn back_to_metres(s: &Scenario, lonlat: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let f = s.frame.as_ref().unwrap();
    lonlat.iter().map(|&(lon, lat)| f.forward(lon, lat, "t").unwrap()).collect()
}

fn assert_same_points(s: &Scenario, r: &PlanReport, lonlat: &[(f64, f64)]) {
    let pts = r.missions[0].points();
    let xy = back_to_metres(s, lonlat);
    assert_eq!(xy.len(), pts.len());
    for (p, q) in pts.iter().zip(&xy) {
        // Seven decimals of a degree: about 1 cm.
        assert!((p.x - q.0).abs() < 0.05 && (p.y - q.1).abs() < 0.05, "{p:?} vs {q:?}");
    }
}

fn geo(s: &Scenario) -> Georef<'_> {
    Georef { frame: s.frame.as_ref(), epoch: s.epoch }
}

#[test]
fn geojson_parses_and_round_trips() {
    use geojson::{GeoJson, GeometryValue};
    let (s, r) = planned("salish");
    let text = export(&r, ExportFormat::GeoJson, geo(&s)).unwrap();
    let parsed: GeoJson = text.parse().unwrap();
    let GeoJson::FeatureCollection(fc) = &parsed else { panic!("not a FeatureCollection") };
    assert_eq!(fc.features.len(), 1);
    let f = &fc.features[0];
    let GeometryValue::LineString { coordinates } = &f.geometry.as_ref().unwrap().value else {
        panic!("not a LineString")
    };
    let lonlat: Vec<(f64, f64)> = coordinates.iter().map(|p| (p[0], p[1])).collect();
    assert_same_points(&s, &r, &lonlat);
    assert_eq!(f.property("status").and_then(|v| v.as_str()), Some(r.status.to_string().as_str()));
    assert_eq!(f.property("time_s").and_then(|v| v.as_array()).map(|a| a.len()), Some(coordinates.len()));
    // Round trip: written again, parsed again, the same document.
    let again: GeoJson = parsed.to_string().parse().unwrap();
    assert_eq!(again, parsed);
}

#[test]
fn csv_gives_back_the_points() {
    let (s, r) = planned("salish");
    let text = export(&r, ExportFormat::Csv, geo(&s)).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("mission,point,lat,lon,depth_m,time_s,utc"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let lonlat: Vec<(f64, f64)> = rows.iter().map(|c| (c[3].parse().unwrap(), c[2].parse().unwrap())).collect();
    assert_same_points(&s, &r, &lonlat);
    // Times to the millisecond.
    let times: Vec<f64> = rows.iter().map(|c| c[5].parse().unwrap()).collect();
    assert_eq!(times.len(), r.missions[0].times.len());
    for (t, want) in times.iter().zip(&r.missions[0].times) {
        assert!((t - want).abs() <= 0.0005 + 1e-9, "{t} vs {want}");
    }
    // A local scenario gives metres.
    let (d, rd) = planned("headland");
    let local = export(&rd, ExportFormat::Csv, geo(&d)).unwrap();
    assert!(local.starts_with("mission,point,x_m,y_m,z_m,time_s\n"), "{local}");
}

/// Every `tag` element's attributes or text, from a well-formed XML document.
fn xml_points(text: &str, tag: &[u8]) -> Vec<String> {
    use quick_xml::events::Event;
    let mut reader = quick_xml::Reader::from_str(text);
    let mut out = Vec::new();
    let mut inside = false;
    loop {
        match reader.read_event().expect("well-formed XML") {
            Event::Start(e) if e.name().as_ref() == tag => {
                inside = true;
                let attrs: Vec<String> = e
                    .attributes()
                    .map(|a| {
                        let a = a.unwrap();
                        format!("{}={}", String::from_utf8_lossy(a.key.as_ref()), String::from_utf8_lossy(&a.value))
                    })
                    .collect();
                if !attrs.is_empty() {
                    out.push(attrs.join(" "));
                }
            }
            Event::Text(t) if inside => out.push(String::from_utf8_lossy(&t).trim().to_string()),
            Event::End(e) if e.name().as_ref() == tag => inside = false,
            Event::Eof => break,
            _ => {}
        }
    }
    out
}

#[test]
fn kml_and_gpx_are_well_formed_and_hold_the_points() {
    let (s, r) = planned("salish");
    let kml = export(&r, ExportFormat::Kml, geo(&s)).unwrap();
    // The route's coordinates, then the start and goal placemarks' points.
    let all = xml_points(&kml, b"coordinates");
    assert_eq!(all.len(), 3, "{kml}");
    let coords = &all[0];
    let lonlat: Vec<(f64, f64)> = coords
        .split_whitespace()
        .map(|c| {
            let v: Vec<f64> = c.split(',').map(|x| x.parse().unwrap()).collect();
            (v[0], v[1])
        })
        .collect();
    assert_same_points(&s, &r, &lonlat);
    let gpx = export(&r, ExportFormat::Gpx, geo(&s)).unwrap();
    let pts = xml_points(&gpx, b"trkpt");
    let lonlat: Vec<(f64, f64)> = pts
        .iter()
        .filter(|a| a.contains("lat="))
        .map(|a| {
            let get = |k: &str| a.split(' ').find_map(|kv| kv.strip_prefix(&format!("{k}="))).unwrap().parse().unwrap();
            (get("lon"), get("lat"))
        })
        .collect();
    assert_same_points(&s, &r, &lonlat);
}

#[test]
fn latitude_longitude_formats_refuse_a_local_scenario() {
    let (d, r) = planned("headland");
    for f in [ExportFormat::GeoJson, ExportFormat::Kml, ExportFormat::Gpx] {
        assert!(f.check(None, "--out").is_err());
        let e = export(&r, f, geo(&d)).unwrap_err().to_string();
        assert!(e.contains("geographic scenario"), "{e}");
    }
    assert!(ExportFormat::of(std::path::Path::new("x.shp"), "--out").unwrap_err().to_string().contains(".geojson"));
}

/// With an epoch (an ISO departure), GPX points carry UTC times.
#[test]
fn iso_departures_give_utc_times() {
    let text = tidepath_io::scenario::builtin("salish")
        .unwrap()
        .replace("goal = [-123.28, 48.40, 0.0]", "goal = [-123.28, 48.40, 0.0]\ndeparture = \"2025-11-12T06:00:00Z\"");
    let s = Scenario::from_toml(&text, "builtin:t").unwrap();
    assert_eq!(s.departure_time, 0.0);
    let r = s.plan(&PlanRequest { planner: Some("hybrid".into()), ..PlanRequest::default() }, &mut |_| {}).unwrap();
    let gpx = export(&r, ExportFormat::Gpx, geo(&s)).unwrap();
    let times = xml_points(&gpx, b"time");
    assert_eq!(times.first().map(String::as_str), Some("2025-11-12T06:00:00.000Z"));
    assert_eq!(times.len(), r.missions[0].times.len());
}

/// A scenario or mission name holding control characters and markup still gives well-formed
/// XML: XML 1.0 forbids most control characters even escaped, so they are written as visible
/// escapes, and markup is escaped by the writer.
#[test]
fn control_characters_in_names_give_well_formed_xml() {
    let (s, mut r) = planned("salish");
    r.scenario = "bad\u{1}name <&> \u{1b}[31m".into();
    r.missions[0].name = "m\u{7}\"one\"".into();
    for f in [ExportFormat::Kml, ExportFormat::Gpx] {
        let text = export(&r, f, geo(&s)).unwrap();
        let illegal = text.chars().find(|&c| c.is_control() && !matches!(c, '\n' | '\t' | '\r'));
        assert_eq!(illegal, None, "{f:?}: {text}");
        // Parses from end to end, and holds the names escaped.
        xml_points(&text, b"name");
        assert!(text.contains("<name>bad\\u{1}name &lt;&amp;&gt; \\u{1b}[31m</name>"), "{f:?}: {text}");
        assert!(
            text.contains("<name>m\\u{7}&quot;one&quot;</name>") || text.contains("<name>m\\u{7}\"one\"</name>"),
            "{f:?}: {text}"
        );
    }
    let csv = export(&r, ExportFormat::Csv, geo(&s)).unwrap();
    assert!(csv.lines().nth(1).unwrap().starts_with("\"m\u{7}\"\"one\"\"\",0,"), "{csv}");
}

/// Plan `r` written in every export format and read back as routes (the way `eval` and
/// `plan --init` read them): (extension, paths) per format.
fn read_back_every_format(s: &Scenario, r: &PlanReport) -> Vec<(&'static str, Vec<Vec<tidepath::geom::Vec3>>)> {
    let dir = tempfile::tempdir().unwrap();
    [
        ("json", ExportFormat::Json),
        ("geojson", ExportFormat::GeoJson),
        ("gpx", ExportFormat::Gpx),
        ("kml", ExportFormat::Kml),
        ("csv", ExportFormat::Csv),
    ]
    .into_iter()
    .map(|(ext, f)| {
        let path = dir.path().join(format!("route.{ext}"));
        std::fs::write(&path, export(r, f, geo(s)).unwrap()).unwrap();
        let file = tidepath_io::routes::read(&path).unwrap();
        (ext, s.route_paths(&file, "route").unwrap())
    })
    .collect()
}

/// Every export is read back as a route (the way `eval` and `plan --init` read it) and gives
/// the plan's points again, depth included: to a centimetre in latitude/longitude and depth.
#[test]
fn every_export_reads_back_as_the_same_route() {
    for name in ["salish", "salish-strait"] {
        let s = load(name).unwrap();
        let r = s.plan(&PlanRequest { seed: 1, ..PlanRequest::default() }, &mut |_| {}).unwrap();
        let want = r.missions[0].points();
        assert!(want.len() >= 2, "{name}: {}", r.reason);
        for (ext, got) in read_back_every_format(&s, &r) {
            assert_eq!(got.len(), 1);
            assert_eq!(got[0].len(), want.len(), "{name} {ext}");
            for (p, q) in got[0].iter().zip(&want) {
                assert!(p.distance(*q) < 0.03, "{name} {ext}: {p:?} vs {q:?}");
            }
        }
    }
}

/// A built-in with a turning radius (m) for its vehicle, and an `astar` plan on it: its
/// corners are sharper than the radius allows, so it is infeasible, but the flown curve
/// exists all the same.
fn planned_with_radius(name: &str, radius: f64, departure: Option<&str>) -> (Scenario, PlanReport) {
    let mut text = tidepath_io::scenario::builtin(name)
        .unwrap()
        .replace("[vehicle]\n", &format!("[vehicle]\nturn_radius = {radius}\n"));
    if let Some(d) = departure {
        text = text.replace("[mission]\n", &format!("[mission]\ndeparture = \"{d}\"\n"));
    }
    let s = Scenario::from_toml(&text, &format!("builtin:{name}")).unwrap();
    assert_eq!(s.vehicle.turn_radius, Some(radius));
    let r =
        s.plan(&PlanRequest { planner: Some("astar".into()), seed: 1, ..PlanRequest::default() }, &mut |_| {}).unwrap();
    assert!(r.missions[0].points().len() >= 3, "{name}: {}", r.reason);
    (s, r)
}

/// The plan JSON carries each mission's flown curve (metres, with times; in degrees under
/// `geographic`) with a radius and nothing without one; both load again as the same report,
/// and a plan file read back as a route gives the waypoints, not the flown curve.
#[test]
fn plan_json_round_trips_with_and_without_the_flown_curve() {
    let (s, r) = planned_with_radius("salish", 500.0, None);
    let flown = r.missions[0].flown.as_ref().expect("a radius gives a flown curve");
    let waypoints = r.missions[0].points();
    assert!(flown.points.len() > waypoints.len(), "{} flown points", flown.points.len());
    assert_eq!(flown.points.len(), flown.times.len());
    let text = r.to_json();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["version"], 3);
    let m = &v["missions"][0];
    assert_eq!(m["flown"]["points"].as_array().unwrap().len(), flown.points.len());
    assert_eq!(m["flown"]["times"].as_array().unwrap().len(), flown.points.len());
    assert!(m["metrics"]["min_turn_radius_m"].is_number(), "{}", m["metrics"]);
    let geo_flown = v["geographic"]["flown"][0].as_array().unwrap();
    assert_eq!(geo_flown.len(), flown.points.len());
    // The degrees are the metres through the frame (to 1 cm), depth positive down.
    let f = s.frame.as_ref().unwrap();
    for (p, q) in flown.points.iter().zip(geo_flown) {
        let (lon, lat) = (q[0].as_f64().unwrap(), q[1].as_f64().unwrap());
        let (x, y) = f.forward(lon, lat, "t").unwrap();
        assert!((x - p[0]).abs() < 0.05 && (y - p[1]).abs() < 0.05, "{p:?} vs {q}");
        assert_eq!(q[2].as_f64().unwrap(), -p[2] + 0.0);
    }
    // Loads again as the same report (numbers to a last-digit rounding of the JSON reader).
    let back: PlanReport = serde_json::from_str(&text).unwrap();
    let fb = back.missions[0].flown.as_ref().unwrap();
    assert_eq!(fb.points.len(), flown.points.len());
    for (a, b) in fb.points.iter().flatten().chain(&fb.times).zip(flown.points.iter().flatten().chain(&flown.times)) {
        assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} vs {b}");
    }
    // Read back as a route: the waypoints.
    let file = tidepath_io::PlanFile::parse(&text, "p.json").unwrap();
    let read = file.mission_paths();
    assert_eq!(read.len(), 1);
    assert_eq!(read[0].len(), waypoints.len());
    for (p, q) in read[0].iter().zip(&waypoints) {
        assert!(p.distance(*q) < 1e-6, "{p:?} vs {q:?}");
    }

    // Without a radius: no flown curve anywhere in the file, and it loads as before.
    let (_, plain) = planned("salish");
    assert!(plain.missions[0].flown.is_none());
    let text = plain.to_json();
    assert!(!text.contains("flown") && !text.contains("min_turn_radius_m"), "{text}");
    let back: PlanReport = serde_json::from_str(&text).unwrap();
    assert!(back.missions[0].flown.is_none() && back.geographic.as_ref().unwrap().flown.is_none());
}

/// The flown curve's points in metres, from latitude/longitude pairs.
fn assert_same_flown(s: &Scenario, r: &PlanReport, lonlat: &[(f64, f64)]) {
    let flown = &r.missions[0].flown.as_ref().unwrap().points;
    let xy = back_to_metres(s, lonlat);
    assert_eq!(xy.len(), flown.len());
    for (p, q) in flown.iter().zip(&xy) {
        assert!((p[0] - q.0).abs() < 0.05 && (p[1] - q.1).abs() < 0.05, "{p:?} vs {q:?}");
    }
}

/// With a radius every format holds the flown curve as its own line, labelled, beside the
/// waypoints: GeoJSON a second feature of kind "flown", GPX a track of type "flown" after the
/// waypoints' route, KML a "(flown)" placemark, CSV rows of kind "flown".
#[test]
fn every_export_carries_the_flown_curve_labelled() {
    use geojson::{GeoJson, GeometryValue};
    let (s, r) = planned_with_radius("salish", 500.0, Some("2025-11-12T06:00:00Z"));
    let flown = r.missions[0].flown.clone().unwrap();

    let text = export(&r, ExportFormat::GeoJson, geo(&s)).unwrap();
    let GeoJson::FeatureCollection(fc) = text.parse().unwrap() else { panic!("not a FeatureCollection") };
    let kinds: Vec<&str> = fc.features.iter().map(|f| f.property("kind").unwrap().as_str().unwrap()).collect();
    assert_eq!(kinds, ["waypoints", "flown"]);
    let line = |f: &geojson::Feature| -> Vec<(f64, f64)> {
        let GeometryValue::LineString { coordinates } = &f.geometry.as_ref().unwrap().value else { panic!() };
        coordinates.iter().map(|p| (p[0], p[1])).collect()
    };
    assert_same_points(&s, &r, &line(&fc.features[0]));
    assert_same_flown(&s, &r, &line(&fc.features[1]));
    let f = &fc.features[1];
    assert_eq!(f.property("name"), fc.features[0].property("name"));
    let times: Vec<f64> =
        f.property("time_s").unwrap().as_array().unwrap().iter().map(|t| t.as_f64().unwrap()).collect();
    assert_eq!(times.len(), flown.times.len());
    for (t, want) in times.iter().zip(&flown.times) {
        assert!((t - want).abs() <= 0.0005 + 1e-9, "{t} vs {want}");
    }
    assert_eq!(f.property("utc").unwrap().as_array().unwrap()[0], "2025-11-12T06:00:00.000Z");

    let gpx = export(&r, ExportFormat::Gpx, geo(&s)).unwrap();
    assert_eq!(xml_points(&gpx, b"type"), ["waypoints", "flown"]);
    assert!(gpx.find("<rte>").unwrap() < gpx.find("<trk>").unwrap(), "{gpx}");
    let pick = |tag: &[u8]| -> Vec<(f64, f64)> {
        xml_points(&gpx, tag)
            .iter()
            .filter(|a| a.contains("lat="))
            .map(|a| {
                let get =
                    |k: &str| a.split(' ').find_map(|kv| kv.strip_prefix(&format!("{k}="))).unwrap().parse().unwrap();
                (get("lon"), get("lat"))
            })
            .collect()
    };
    assert_same_points(&s, &r, &pick(b"rtept"));
    assert_same_flown(&s, &r, &pick(b"trkpt"));
    // Times on both: the route's waypoints and every point of the flown track.
    assert_eq!(xml_points(&gpx, b"time").len(), r.missions[0].times.len() + flown.times.len());

    let kml = export(&r, ExportFormat::Kml, geo(&s)).unwrap();
    let names = xml_points(&kml, b"name");
    assert!(names.iter().any(|n| n == "mission (flown)"), "{names:?}");
    assert_eq!(xml_points(&kml, b"value"), ["waypoints", "flown"]);
    // With an epoch both lines are timed tracks: a <when> per point of each.
    assert_eq!(xml_points(&kml, b"when").len(), r.missions[0].times.len() + flown.times.len());

    let csv = export(&r, ExportFormat::Csv, geo(&s)).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("mission,kind,point,lat,lon,depth_m,time_s,utc"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let of = |kind: &str| -> Vec<(f64, f64)> {
        rows.iter().filter(|c| c[1] == kind).map(|c| (c[4].parse().unwrap(), c[3].parse().unwrap())).collect()
    };
    assert_same_points(&s, &r, &of("waypoints"));
    assert_same_flown(&s, &r, &of("flown"));
    assert_eq!(rows.len(), r.missions[0].times.len() + flown.times.len());

    // A local scenario's CSV labels its rows the same way, in metres.
    let (d, rd) = planned_with_radius("headland", 60.0, None);
    let local = export(&rd, ExportFormat::Csv, geo(&d)).unwrap();
    assert!(local.starts_with("mission,kind,point,x_m,y_m,z_m,time_s\n"), "{local}");
    let n = rd.missions[0].flown.as_ref().unwrap().points.len();
    assert_eq!(local.lines().filter(|l| l.contains(",flown,")).count(), n);
}

/// Without a radius no export names a kind or a flown curve: one line per mission, as before.
#[test]
fn exports_without_a_radius_have_no_flown_line() {
    let (s, r) = planned("salish");
    for f in [ExportFormat::GeoJson, ExportFormat::Gpx, ExportFormat::Kml, ExportFormat::Csv] {
        let text = export(&r, f, geo(&s)).unwrap();
        assert!(!text.contains("flown") && !text.contains("kind") && !text.contains("waypoints"), "{f:?}: {text}");
    }
    let gpx = export(&r, ExportFormat::Gpx, geo(&s)).unwrap();
    assert!(gpx.contains("<trk>") && !gpx.contains("<rte>"), "{gpx}");
}

/// With a radius every export is read back (as `eval` and `plan --init` read it) as the
/// waypoints, not the flown curve: the same points as the plan's, depth included.
#[test]
fn every_export_with_a_radius_reads_back_as_the_waypoints() {
    let (s, r) = planned_with_radius("salish", 500.0, Some("2025-11-12T06:00:00Z"));
    let want = r.missions[0].points();
    for (ext, got) in read_back_every_format(&s, &r) {
        assert_eq!(got.len(), 1, "{ext}");
        assert_eq!(got[0].len(), want.len(), "{ext}");
        for (p, q) in got[0].iter().zip(&want) {
            assert!(p.distance(*q) < 0.03, "{ext}: {p:?} vs {q:?}");
        }
        // Judged again, the route flies the same curve.
        let judged = s.evaluate_paths(&got).unwrap();
        let again = judged[0].flown.as_ref().unwrap();
        assert_eq!(again.points.len(), r.missions[0].flown.as_ref().unwrap().points.len(), "{ext}");
    }
}
