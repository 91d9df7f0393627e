//! "No route" said honestly: a strait walled from shore to shore is proved unreachable; one
//! walled all but a narrow passage is not, and a search that finds nothing says what it
//! searched and where the optimistic check still connects start and goal.

use std::process::{Command, Output};

fn tidepath(args: &[&str], cwd: &std::path::Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tidepath")).args(args).current_dir(cwd).output().expect("tidepath runs")
}

/// The salish-strait built-in, depth band 15-120 m, with an exclusion box from the surface to
/// 200 m across the Strait of Juan de Fuca from its south side up to latitude `north`.
fn walled(dir: &std::path::Path, north: f64, south: f64) -> String {
    let base = tidepath(&["scenario", "salish-strait"], dir);
    let toml = String::from_utf8(base.stdout).unwrap();
    let wall = format!(
        "[[world.obstacles]]\nkind = \"box\"\nmin = [-124.3, {south}, -300.0]\nmax = [-124.0, {north}, 0.0]\n\n[vehicle]"
    );
    let toml = toml
        .replacen("[vehicle]", &wall, 1)
        .replace("depth_min = 10.0", "depth_min = 15.0")
        .replace("depth_max = 150.0", "depth_max = 120.0");
    let path = dir.join(format!("walled-{north}.toml"));
    std::fs::write(&path, toml).unwrap();
    path.to_string_lossy().into_owned()
}

fn first_line(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).lines().next().unwrap_or_default().to_string()
}

#[test]
fn a_strait_walled_from_shore_to_shore_is_proved_unreachable() {
    let dir = tempfile::tempdir().unwrap();
    let s = walled(dir.path(), 48.9, 47.9);
    let o = tidepath(&["plan", &s, "--planner", "theta-star"], dir.path());
    assert_eq!(o.status.code(), Some(1));
    let line = first_line(&o);
    assert!(line.contains("unreachable: goal unreachable: fixed obstacles"), "{line}");
}

#[test]
fn a_search_that_finds_no_route_names_the_optimistic_connection() {
    let dir = tempfile::tempdir().unwrap();
    // Open water of 0.3 degrees is left only along the north shore: the 80-cell raster of
    // the 3-D grid planners cannot pass, the 640 m cells of the reachability check can.
    let s = walled(dir.path(), 48.35, 48.15);
    let o = tidepath(&["plan", &s, "--planner", "theta-star", "--plot", "f.svg"], dir.path());
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    let line = first_line(&o);
    assert!(
        line.contains("infeasible: no route on the 26-connected 80 x 39 x 16 raster (searched completely)"),
        "{line}"
    );
    // The place named is the passage at the box's north-east corner (124.00 W, 48.35 N).
    assert!(
        line.contains("not proved unreachable: the optimistic check connects start and goal through (48.3"),
        "{line}"
    );
    assert!(line.contains(" N, 124.00") && line.contains("try a finer raster"), "{line}");
    // The figure marks the place.
    let svg = std::fs::read_to_string(dir.path().join("f.svg")).unwrap();
    assert!(svg.contains("narrowest passage"), "the figure does not mark the passage");
    // A composite planner whose reference failed says so before its fallback's violation.
    let o = tidepath(&["plan", &s, "--planner", "hybrid", "--iterations", "5"], dir.path());
    let line = first_line(&o);
    assert!(line.contains("infeasible: its reference search (astar) found no route on the"), "{line}");
    assert!(line.contains("; its fallback path: segment"), "{line}");
}
