//! `[world.waves]` and wave gliders (acopf2016) in scenario files: each kind of sea state
//! builds and answers the hand-computed height at points and times; forecast files are read
//! by standard name or by name, their land and fill become gaps a glider may not enter (an
//! AUV may); every bad value is one line naming the field or the file; a glider plans with
//! A* at the regression's speed; missions given by eq. 3 cell numbers land on cell centres.

use std::path::PathBuf;

use tidepath::geom::Vec3;
use tidepath::validity::{StateIssue, Validator};
use tidepath::vehicle::Vehicle;
use tidepath::world::Waves;
use tidepath_io::scenario::{PlanRequest, Scenario};

/// A 2-D wave-glider scenario over 2 km x 2 km with `waves` as its `[world.waves]` body.
fn glider(waves: &str) -> String {
    format!(
        r#"
name = "glider"
[world]
dimensions = 2
bounds = {{ min = [0.0, 0.0, 0.0], max = [2000.0, 2000.0, 0.0] }}
[world.waves]
{waves}
[vehicle]
kind = "wave-glider"
max_turn_deg = 180.0
[mission]
start = [100.0, 100.0, 0.0]
goal = [1900.0, 1500.0, 0.0]
[planner]
id = "astar"
"#
    )
}

fn load(text: &str) -> Scenario {
    Scenario::from_toml(text, "waves.toml").unwrap_or_else(|e| panic!("{e}"))
}

fn refused(text: &str) -> String {
    let e = Scenario::from_toml(text, "waves.toml").map(|_| ()).unwrap_err().to_string();
    assert!(!e.contains('\n'), "one line: {e}");
    e
}

fn at(x: f64, y: f64) -> Vec3 {
    Vec3::new(x, y, 0.0)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn uniform_waves_hold_everywhere_and_set_the_gliders_nominal_speed() {
    let s = load(&glider("kind = \"uniform\"\nheight = 1.5"));
    assert_eq!(s.world.waves, Waves::Uniform(1.5));
    assert_eq!(s.world.waves.height(at(1234.0, 5.0), 1e6), 1.5);
    // The still-water speed in the highest waves: 0.1623 * 1.5 = 0.24345 m/s.
    assert!(close(s.vehicle.speed, 0.24345, 1e-12), "{}", s.vehicle.speed);
    assert!(close(s.missions[0].vehicle.speed, 0.24345, 1e-12));
    assert!(s.vehicle.glider().is_some());
}

#[test]
fn grid_waves_are_bilinear_in_space_and_linear_in_time_with_gaps() {
    let s = load(&glider(
        "kind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [1000.0, 1000.0]\nshape = [3, 2]\ntimes = [0.0, 3600.0]\n\
         height = [[0.0, 1.0, 2.0, 3.0, 4.0, 5.0], [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]]\nno_data = [5]",
    ));
    let w = &s.world.waves;
    // Nodes 0, 1, 3, 4 at time 0: the middle of the first cell is their mean, 2.0.
    assert!(close(w.height(at(500.0, 500.0), 0.0), 2.0, 1e-12));
    // Later layer +1; halfway in time +0.5.
    assert!(close(w.height(at(500.0, 500.0), 3600.0), 3.0, 1e-12));
    assert!(close(w.height(at(500.0, 500.0), 1800.0), 2.5, 1e-12));
    // A quarter along x in the first cell, on its south edge: 0.25.
    assert!(close(w.height(at(250.0, 0.0), 0.0), 0.25, 1e-12));
    assert!(w.has_data(at(500.0, 500.0)));
    assert!(!w.has_data(at(1500.0, 500.0)), "the cell next to node 5 has no data");
    // The glider's nominal speed is set from the largest node value, 6 m: 0.9738 m/s.
    assert!(close(s.vehicle.speed, 0.1623 * 6.0, 1e-12));
}

#[test]
fn cell_waves_sit_at_cell_centres_rows_north_first() {
    let s =
        load(&glider("kind = \"cells\"\norigin = [0.0, 0.0]\nresolution = 1000.0\nheights = [[1.0, 2.0], [3.0, 4.0]]"));
    let w = &s.world.waves;
    // South row [3, 4] at y = 500, north row [1, 2] at y = 1500.
    assert!(close(w.height(at(500.0, 500.0), 0.0), 3.0, 1e-12));
    assert!(close(w.height(at(1500.0, 500.0), 0.0), 4.0, 1e-12));
    assert!(close(w.height(at(500.0, 1500.0), 0.0), 1.0, 1e-12));
    assert!(close(w.height(at(1000.0, 1000.0), 0.0), 2.5, 1e-12));
    // One row: doubled, so the height does not change north to south.
    let one = load(&glider("kind = \"cells\"\norigin = [0.0, 0.0]\nresolution = 1000.0\nheights = [[1.0, 3.0]]"));
    for y in [0.0, 500.0, 2000.0] {
        assert!(close(one.world.waves.height(at(1000.0, y), 0.0), 2.0, 1e-12), "y = {y}");
    }
}

fn data(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/geo").join(name).display().to_string()
}

/// A geographic glider scenario inside the wave fixtures' 6 x 5 nodes (-125..-124.5 E,
/// 48.0..48.4 N), reading `file`.
fn geographic(file: &str, extra: &str) -> String {
    format!(
        r#"
name = "geo-glider"
[world]
dimensions = 2
frame = "geographic"
bounds = {{ min = [-124.95, 48.05, 0.0], max = [-124.52, 48.38, 0.0] }}
[world.waves]
kind = "file"
path = "{}"
{extra}
[vehicle]
kind = "wave-glider"
[mission]
start = [-124.9, 48.1, 0.0]
goal = [-124.7, 48.2, 0.0]
"#,
        data(file)
    )
}

/// The fixtures' height: 1 m + 2 m per degree east of 125 W + 0.1 m per hour.
fn fixture_height(lon: f64, hours: f64) -> f64 {
    1.0 + 2.0 * (lon + 125.0) + 0.1 * hours
}

#[test]
fn a_copernicus_wave_file_is_read_by_standard_name_on_its_clock() {
    let s = load(&geographic("waves_copernicus.nc", ""));
    assert_eq!(s.epoch.unwrap().to_rfc3339(), "2025-11-12T00:00:00+00:00");
    let f = s.frame.as_ref().unwrap();
    for (lon, lat) in [(-124.9, 48.1), (-124.75, 48.2), (-124.65, 48.15)] {
        let (x, y) = f.forward(lon, lat, "p").unwrap();
        for hours in [0.0, 1.5, 3.0, 6.0] {
            let h = s.world.waves.height(at(x, y), hours * 3600.0);
            assert!(close(h, fixture_height(lon, hours), 2e-3), "({lon}, {lat}) at {hours} h: {h}");
        }
    }
    // Land (fill) on the north-east 2 x 2 nodes: a gap, named in a warning.
    let (x, y) = f.forward(-124.55, 48.35, "p").unwrap();
    assert!(!s.world.waves.has_data(at(x, y)));
    assert!(
        s.warnings.iter().any(|w| w.starts_with("world.waves: ") && w.contains("no wave data")),
        "{:?}",
        s.warnings
    );
    // A glider may not be there; an AUV may (waves do not concern it).
    let glider = Validator::new(&s.world, &s.vehicle, &s.settings);
    assert_eq!(glider.state(at(x, y), 0.0), Err(StateIssue::NoWaveData));
    assert!(glider.state(s.start, 0.0).is_ok());
    let auv = Vehicle::default();
    assert!(Validator::new(&s.world, &auv, &s.settings).state(at(x, y), 0.0).is_ok());
    // The nominal speed from the highest wave node: at most 1 + 2 * 0.5 + 0.6 = 2.6 m.
    assert!(s.vehicle.speed <= 0.1623 * 2.6 + 1e-9 && s.vehicle.speed > 0.1623 * 2.0, "{}", s.vehicle.speed);
}

#[test]
fn a_wavewatch_file_is_read_by_name_with_longitudes_to_360_and_latitudes_descending() {
    let s = load(&geographic("waves_ww3.nc", ""));
    assert_eq!(s.epoch.unwrap().to_rfc3339(), "2025-11-12T00:00:00+00:00");
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    let f = s.frame.as_ref().unwrap();
    let (x, y) = f.forward(-124.8, 48.3, "p").unwrap();
    // Layers at 0 and 6 h; 3 h is their mean.
    for hours in [0.0, 3.0, 6.0] {
        let h = s.world.waves.height(at(x, y), hours * 3600.0);
        assert!(close(h, fixture_height(-124.8, hours), 2e-3), "{hours} h: {h}");
    }
    // Named explicitly, in another case.
    let named = load(&geographic("waves_ww3.nc", "variable = \"HS\""));
    assert_eq!(named.world.waves, s.world.waves);
}

#[test]
fn bad_wave_files_are_one_line_naming_the_file_and_the_variable() {
    let e = refused(&geographic("waves_malformed.nc", ""));
    assert!(e.contains("waves_malformed.nc") && e.contains("`VHM0`") && e.contains("not monotonic"), "{e}");
    let e = refused(&geographic("waves_copernicus.nc", "variable = \"swell\""));
    assert!(e.starts_with("world.waves.variable: `swell` not found") && e.contains("VHM0"), "{e}");
    // A current file holds no wave height.
    let e = refused(&geographic("currents_copernicus.nc", ""));
    assert!(e.contains("currents_copernicus.nc") && e.contains("no significant wave height"), "{e}");
    let e = refused(&geographic("nowhere.nc", ""));
    assert!(e.contains("nowhere.nc"), "{e}");
    // Files need a geographic frame.
    let local = glider("kind = \"file\"\npath = \"waves.nc\"");
    assert!(refused(&local).starts_with("world.waves.kind: \"file\" reads longitude/latitude"));
}

#[test]
fn bad_wave_values_and_glider_settings_are_named() {
    let uniform = glider("kind = \"uniform\"\nheight = 1.5");
    let cases: Vec<(String, &str)> = vec![
        (glider("kind = \"uniform\"\nheight = -0.5"), "world.waves.height: must be a significant wave height from 0 to 30 m, got -0.5"),
        (glider("kind = \"uniform\"\nheight = 31.0"), "world.waves.height"),
        (glider("kind = \"uniform\"\nheight = nan"), "world.waves.height"),
        (glider("kind = \"swell\"\nheight = 1.0"), "world.waves"),
        (glider("kind = \"uniform\"\nheight = 1.0\nperiod = 8.0"), "period"),
        (
            glider("kind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [1000.0, 1000.0]\nshape = [3, 2]\ntimes = [0.0]\nheight = [[1.0, 1.0, 1.0]]"),
            "world.waves.height: layer 0 has 3 values; the grid has 3 x 2 = 6 nodes",
        ),
        (
            glider("kind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [1000.0, 1000.0]\nshape = [2, 2]\ntimes = [0.0]\nheight = [[1.0, 1.0, -1.0, 1.0]]"),
            "world.waves.height: layer 0, value 2",
        ),
        (
            glider("kind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [1000.0, 1000.0]\nshape = [2, 2]\ntimes = [0.0]\nheight = [[1.0, 1.0, 40.0, 1.0]]"),
            "world.waves.height: layer 0, value 2 (node i = 0, j = 1) is 40 m",
        ),
        (glider("kind = \"cells\"\norigin = [0.0, 0.0]\nresolution = 1000.0\nheights = [[1.0, 2.0], [3.0]]"), "world.waves.heights[1]"),
        (uniform.replace("dimensions = 2", "dimensions = 3").replace("max = [2000.0, 2000.0, 0.0]", "max = [2000.0, 2000.0, 10.0]"), "vehicle.kind: \"wave-glider\" rides the sea surface"),
        (uniform.replace("[world.waves]\nkind = \"uniform\"\nheight = 1.5", ""), "world.waves: missing: vehicle.kind = \"wave-glider\""),
        (uniform.replace("kind = \"wave-glider\"", "wave_gain = 0.2"), "vehicle.wave_gain: = 0.2 belongs to a wave glider"),
        (uniform.replace("kind = \"wave-glider\"", "min_speed = 0.1"), "vehicle.min_speed"),
        (uniform.replace("kind = \"wave-glider\"", "kind = \"wave-glider\"\nspeed_max = 2.0"), "vehicle.speed_max: = 2: a wave glider's speed"),
        (uniform.replace("kind = \"wave-glider\"", "kind = \"wave-glider\"\nwave_gain = 11.0"), "vehicle.wave_gain: must be in [0, 10], got 11"),
        (uniform.replace("kind = \"wave-glider\"", "kind = \"wave-glider\"\ncurrent_gain = -0.1"), "vehicle.current_gain"),
        (uniform.replace("kind = \"wave-glider\"", "kind = \"wave-glider\"\nmin_speed = 0.0"), "vehicle.min_speed: must be in (0, 5], got 0"),
        (uniform.replace("kind = \"wave-glider\"", "kind = \"glider\""), "vehicle.kind"),
    ];
    for (text, want) in cases {
        let e = refused(&text);
        assert!(e.contains(want), "want `{want}` in: {e}");
    }
}

/// A fleet mission's own `[missions.vehicle]` goes through the same checks.
#[test]
fn a_fleet_gliders_own_vehicle_is_checked_against_the_world() {
    let text = glider("kind = \"uniform\"\nheight = 2.0").replace("kind = \"wave-glider\"\n", "").replace(
        "[mission]\nstart = [100.0, 100.0, 0.0]\ngoal = [1900.0, 1500.0, 0.0]",
        "[[missions]]\nname = \"auv\"\nstart = [100.0, 100.0, 0.0]\ngoal = [1900.0, 1500.0, 0.0]\n\
             [[missions]]\nname = \"glider\"\nstart = [100.0, 1900.0, 0.0]\ngoal = [1900.0, 100.0, 0.0]\n\
             [missions.vehicle]\nkind = \"wave-glider\"\nwave_gain = 0.2",
    );
    let s = load(&text);
    assert!(s.missions[0].vehicle.glider().is_none());
    let g = s.missions[1].vehicle.glider().unwrap();
    assert_eq!((g.wave_gain, g.current_gain, g.min_speed), (0.2, 0.2660, 0.05));
    assert!(close(s.missions[1].vehicle.speed, 0.4, 1e-12));
    let e = refused(&text.replace("[world.waves]\nkind = \"uniform\"\nheight = 2.0", ""));
    assert!(e.starts_with("world.waves: missing: missions[1].vehicle.kind"), "{e}");
}

/// Uniform waves of 2 m and a uniform current (0.2, 0.1) m/s: every segment of A*'s plan is
/// flown at 0.1623 * 2 + 0.2660 (c . d) m/s, d its heading, so the travel time is the sum of
/// length / speed over its segments.
#[test]
fn a_glider_plans_with_astar_at_the_regressions_speed() {
    let text = glider("kind = \"uniform\"\nheight = 2.0")
        .replace("[world.waves]", "[world.current]\nkind = \"uniform\"\nvelocity = [0.2, 0.1, 0.0]\n[world.waves]");
    let s = load(&text);
    let r = s.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
    let m = &r.missions[0];
    assert!(m.status.is_success(), "{}", m.reason);
    let path = m.points();
    assert!(path.len() >= 2);
    let mut expected = 0.0;
    for w in path.windows(2) {
        let len = w[0].distance(w[1]);
        let d = (w[1] - w[0]) / len;
        let v = 0.1623 * 2.0 + 0.2660 * (0.2 * d.x + 0.1 * d.y);
        expected += len / v;
    }
    let took = m.times.last().unwrap() - m.times[0];
    assert!(close(took, expected, 1e-6 * expected), "{took} vs {expected}");
    let metrics = m.metrics.as_ref().unwrap();
    assert!(close(metrics.travel_time_s, expected, 1e-6 * expected));
    // The straight line at 0.1623 * 2 + 0.266 * (0.2 * 0.8 + 0.1 * 0.6) = 0.38311 m/s: 5873 s;
    // A*'s plan on its lattice is no faster.
    assert!(took >= 2250.0 / 0.38311 - 1e-6, "{took}");
}

const CELLS: &str = r#"
name = "cells"
[world]
dimensions = 2
bounds = { min = [0.0, 0.0, -20.0], max = [200.0, 200.0, 0.0] }
[world.terrain]
kind = "cells"
origin = [0.0, 0.0]
resolution = 10.0
elevations = [ROWS]
[world.waves]
kind = "uniform"
height = 1.0
[vehicle]
kind = "wave-glider"
max_turn_deg = 180.0
[mission]
start_cell = 1
goal_cell = 400
[planner]
id = "astar"
"#;

fn cells(mission: &str) -> String {
    let row = format!("[{}]", vec!["-20.0"; 20].join(", "));
    CELLS.replace("ROWS", &vec![row; 20].join(", ")).replace("start_cell = 1\ngoal_cell = 400", mission)
}

#[test]
fn cell_numbers_put_the_mission_on_cell_centres() {
    let s = load(&cells("start_cell = 1\ngoal_cell = 400"));
    // acopf2016's check scaled by a = 10: cell 1 at (5, 5), cell 400 at (195, 195), on the
    // top of the domain (z = 0).
    assert_eq!((s.start, s.goal), (Vec3::new(5.0, 5.0, 0.0), Vec3::new(195.0, 195.0, 0.0)));
    // Cell 20 ends the first row (the mod = 0 case); the other end's z is kept.
    let s = load(&cells("start = [100.0, 100.0, -1.0]\ngoal_cell = 20"));
    assert_eq!(s.goal, Vec3::new(195.0, 5.0, -1.0));
    let cases = [
        (
            "start_cell = 401\ngoal_cell = 400",
            "mission.start_cell: is 401; the terrain grid's cells are numbered 1 to 400",
        ),
        ("start_cell = 0\ngoal_cell = 400", "mission.start_cell: is 0"),
        (
            "start_cell = 1\nstart = [5.0, 5.0, 0.0]\ngoal_cell = 400",
            "mission.start_cell: = 1: give start or start_cell, not both",
        ),
        ("start_cell = 1", "mission.goal: missing: give goal = [x, y, z] or goal_cell = N"),
    ];
    for (mission, want) in cases {
        let e = refused(&cells(mission));
        assert!(e.contains(want), "want `{want}` in: {e}");
    }
    let no_cells = glider("kind = \"uniform\"\nheight = 1.0").replace("start = [100.0, 100.0, 0.0]", "start_cell = 3");
    assert!(refused(&no_cells).starts_with("mission.start_cell: numbers the cells of [world.terrain] kind = \"cells\""));
    // A CLI --from replaces a cell start by a point.
    let s = load(&cells("start_cell = 1\ngoal_cell = 400"));
    let moved = s.with_endpoints(Some("50,60"), None).unwrap();
    assert_eq!((moved.start, moved.goal), (Vec3::new(50.0, 60.0, 0.0), Vec3::new(195.0, 195.0, 0.0)));
}

/// The spec printed back (as `scenario` listings and exports do) keeps the waves, the glider
/// and the cell numbers, and loads into the same scenario.
#[test]
fn waves_glider_and_cells_survive_a_round_trip() {
    for text in [
        cells("start_cell = 1\ngoal_cell = 400"),
        glider("kind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [1000.0, 1000.0]\nshape = [2, 2]\ntimes = [0.0]\nheight = [[1.0, 2.0, 3.0, 4.0]]\nno_data = [3]")
            .replace("kind = \"wave-glider\"", "kind = \"wave-glider\"\nwave_gain = 0.2\nmin_speed = 0.1"),
    ] {
        let s = load(&text);
        let printed = toml::to_string(&s.spec).unwrap();
        assert!(printed.contains("kind = \"wave-glider\"") && printed.contains("[world.waves]"), "{printed}");
        let again = load(&printed);
        assert_eq!(toml::to_string(&again.spec).unwrap(), printed);
        assert_eq!((again.world.waves, again.start, again.goal), (s.world.waves.clone(), s.start, s.goal));
        assert_eq!(again.vehicle.propulsion, s.vehicle.propulsion);
    }
    // An AUV prints no kind (older files' form is kept).
    let auv = toml::to_string(&tidepath_io::scenario::spec::VehicleSpec::default()).unwrap();
    assert!(!auv.contains("kind"), "{auv}");
}

/// The reader alone: times decoded from each file's units, the height at the nodes exactly
/// (float32 of the formula), land as NaN, the variable found by standard name or by name.
#[test]
fn the_wave_reader_decodes_times_values_and_land() {
    use tidepath_io::geodata::waves::read_waves;
    use tidepath_io::geodata::DataFile;
    let file = |n: &str| DataFile::Path(PathBuf::from(data(n)));
    let c = read_waves(&file("waves_copernicus.nc"), None, None, 1).unwrap();
    assert_eq!(c.variable, "VHM0");
    let hours: Vec<i64> = c.times.iter().map(|t| (*t - c.times[0]).num_hours()).collect();
    assert_eq!((c.times[0].to_rfc3339().as_str(), hours), ("2025-11-12T00:00:00+00:00", vec![0, 3, 6]));
    let g = &c.height[2];
    assert_eq!((g.lon.len(), g.lat.len()), (6, 5));
    // Node (lon -124.8, lat 48.1) at 6 h: 1 + 0.4 + 0.6 = 2.0 m.
    assert!(close(g.values[6 + 2], 2.0, 1e-6), "{}", g.values[8]);
    let nan: Vec<usize> = (0..30).filter(|&k| g.values[k].is_nan()).collect();
    assert_eq!(nan, [22, 23, 28, 29], "the north-east 2 x 2 nodes are land");
    let w = read_waves(&file("waves_ww3.nc"), None, None, 1).unwrap();
    assert_eq!((w.variable.as_str(), w.times.len()), ("hs", 2));
    assert_eq!(w.times[1] - w.times[0], chrono::Duration::hours(6));
    // Rows south first and longitudes in -180..180 whatever the file's order.
    assert!(close(w.height[0].lon[0], -125.0, 1e-9) && close(w.height[0].lat[0], 48.0, 1e-9));
    assert!(close(w.height[1].values[5], fixture_height(-124.5, 6.0), 1e-6));
}
