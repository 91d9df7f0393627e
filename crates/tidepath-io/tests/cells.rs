//! Grids given cell by cell in scenario files: a map of `#` and `.` (or per-cell elevations)
//! and a per-cell current. A* searches the map's own cells; routes never enter a land cell
//! (re-checked by dense sampling); the lengths are those of the grid and of the geometry.

use crate::common;

use tidepath::planner::Status;
use tidepath_io::scenario::{PlanRequest, Scenario};

const WALL: &str = r#"
name = "wall"
[world]
dimensions = 2
bounds = { min = [0.0, 0.0, -20.0], max = [700.0, 500.0, 0.0] }
[world.terrain]
kind = "cells"
origin = [0.0, 0.0]
resolution = 100.0
map = [
  ".......",
  "...#...",
  "...#...",
  "...#...",
  ".......",
]
[vehicle]
speed = 2.0
max_turn_deg = 180.0
safety_distance = 1.0
[mission]
start = [150.0, 250.0, -1.0]
goal = [550.0, 250.0, -1.0]
[planner]
id = "astar"
"#;

fn plan(text: &str, planner: &str) -> tidepath_io::PlanReport {
    let s = Scenario::from_toml(text, "cells.toml").unwrap();
    let req = PlanRequest { planner: Some(planner.to_string()), ..PlanRequest::default() };
    let r = s.plan(&req, &mut |_| {}).unwrap();
    if r.status.is_success() {
        common::recheck_plan(&s, &r).unwrap();
    }
    r
}

fn length(r: &tidepath_io::PlanReport) -> f64 {
    r.missions[0].points().windows(2).map(|w| w[0].distance(w[1])).sum()
}

#[test]
fn a_wall_of_cells_is_passed_around() {
    let s = Scenario::from_toml(WALL, "cells.toml").unwrap();
    // The map reads north first: the wall is column 3, rows 1 to 3 from the south.
    assert_eq!(s.world.terrain.elevation(350.0, 150.0), 10.0);
    assert_eq!(s.world.terrain.elevation(350.0, 50.0), -20.0);
    assert_eq!(s.world.terrain.elevation(250.0, 250.0), -20.0);
    // The straight line crosses the wall.
    assert!(!s.evaluate(&[s.missions[0].start, s.missions[0].goal]).unwrap().feasible);
    // A* on the map's cells, whose moves never cut the corner of a blocked cell: around the
    // wall's end along the outer row, 2 diagonal and 4 straight moves between cell centres.
    let astar_len = 200.0 * 2f64.sqrt() + 400.0;
    let r = plan(WALL, "astar");
    assert_eq!(r.status, Status::Exact, "{}", r.reason);
    assert!((length(&r) - astar_len).abs() < 1e-6, "{}", length(&r));
    // Geometry: the shortest route touches the wall's corners (300, 400) and (400, 400):
    // 2 x 150 sqrt 2 + 100. Theta* on the cells is between it and A*; the default planner
    // comes within 1% of it.
    let exact = 300.0 * 2f64.sqrt() + 100.0;
    let theta = length(&plan(WALL, "theta-star"));
    assert!(theta >= exact - 1e-6 && theta <= astar_len + 1e-6, "{theta}");
    let hybrid = plan(WALL, "hybrid");
    assert!(hybrid.status.is_success(), "{}", hybrid.reason);
    assert!(length(&hybrid) <= exact * 1.01, "{} vs {exact}", length(&hybrid));
}

#[test]
fn a_closed_ring_of_cells_is_unreachable_and_bad_maps_are_named() {
    let ring = WALL.replace(
        r#"map = [
  ".......",
  "...#...",
  "...#...",
  "...#...",
  ".......",
]"#,
        r#"map = [
  "....###",
  "....#..",
  "....#..",
  "....#..",
  "....###",
]"#,
    );
    let r = plan(&ring, "astar");
    assert_eq!(r.status, Status::Unreachable, "{}", r.reason);
    let e = |from: &str, to: &str| {
        Scenario::from_toml(&WALL.replace(from, to), "c.toml").map(|_| ()).unwrap_err().to_string()
    };
    assert!(e("\"...#...\",\n  \".......\",\n]", "\"...#...\",\n  \"...\",\n]").contains("world.terrain.map[4]"));
    assert!(e("\"...#...\",\n  \".......\",\n]", "\"...#...\",\n  \"..x....\",\n]").contains("column 2 is 'x'"));
    assert!(e("resolution = 100.0", "resolution = -1.0").contains("world.terrain.resolution"));
    assert!(e("map = [", "elevations = [[-5.0]]\nmap = [").contains("either map or elevations"));
}

/// Per-cell elevations and a per-cell current: a channel of deep cells through shallows, and
/// a current in the channel that the quickest route rides.
#[test]
fn per_cell_elevations_and_currents() {
    let text = r#"
name = "channel"
[world]
dimensions = 2
bounds = { min = [0.0, 0.0, 0.0], max = [400.0, 300.0, 0.0] }
[world.terrain]
kind = "cells"
origin = [0.0, 0.0]
resolution = 100.0
elevations = [
  [-2.0, -2.0, -2.0, -2.0],
  [-30.0, -30.0, -30.0, -30.0],
  [-2.0, -2.0, -2.0, -2.0],
]
[world.current]
kind = "cells"
origin = [0.0, 0.0]
resolution = 100.0
u = [[0.0, 0.0, 0.0, 0.0], [1.0, 1.0, 1.0, 1.0], [0.0, 0.0, 0.0, 0.0]]
v = [[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]]
[vehicle]
speed = 2.0
max_turn_deg = 180.0
safety_distance = 5.0
[mission]
start = [50.0, 150.0, 0.0]
goal = [350.0, 150.0, 0.0]
"#;
    let s = Scenario::from_toml(text, "c.toml").unwrap();
    assert_eq!(s.world.terrain.elevation(150.0, 150.0), -30.0);
    assert_eq!(s.world.terrain.elevation(150.0, 250.0), -2.0);
    // At the middle row's cell centres the current is the cell's (nodes at the centres).
    let c = s.world.current.velocity(tidepath::geom::Vec3::new(250.0, 150.0, 0.0), 0.0);
    assert_eq!((c.x, c.y), (1.0, 0.0));
    let r = plan(text, "astar");
    assert_eq!(r.status, Status::Exact, "{}", r.reason);
    // Straight down the channel with the current: 300 m at 3 m/s.
    let t = r.missions[0].times.last().unwrap();
    assert!((t - 100.0).abs() < 1e-6, "{t}");
}
