//! acopf2016's built-in scenarios (scripts/make_acopf2016_scenarios.py): the wave glider on the
//! paper's 20 x 20 grid map of 1 km cells in environments 1-3 (glider-1 .. glider-3), tidepath's
//! fourth environment (glider-4), and the glider on a synthetic NetCDF forecast off Nihoa
//! (glider-ocean). Each loads with the chosen values; A* on travel time plans each feasibly;
//! the quickest routes behave as the paper says (they keep to the larger waves, ride the
//! current), measured against the shortest ones.

use crate::common;

use tidepath::geom::Vec3;
use tidepath::world::{Terrain, Waves};
use tidepath_io::geodata::{currents::read_currents, waves::read_waves, DataFile, EMBEDDED};
use tidepath_io::scenario::{load, PlanRequest, Scenario};
use tidepath_io::PlanReport;

const GRID: [&str; 4] = ["glider-1", "glider-2", "glider-3", "glider-4"];
const KM: f64 = 1000.0;
/// Nihoa (161.92 W, 23.06 N): the island of glider-ocean.
const NIHOA: (f64, f64) = (-161.92, 23.06);

/// Plans `s` with `planner` whose `objective` is "time" or "length" (A*'s parameter).
fn plan(name: &str, planner: &str, objective: &str) -> (Scenario, PlanReport) {
    let mut s = load(name).unwrap();
    let mut params = toml::Table::new();
    params.insert("objective".into(), toml::Value::String(objective.into()));
    s.planner.params.insert(planner.into(), params);
    let req = PlanRequest { planner: Some(planner.into()), ..PlanRequest::default() };
    let r = s.plan(&req, &mut |_| {}).unwrap();
    let m = &r.missions[0];
    assert!(m.feasible, "{name} / {planner} ({objective}): {}", m.reason);
    common::recheck_plan(&s, &r).unwrap_or_else(|e| panic!("{name}: {e}"));
    (s, r)
}

fn points(r: &PlanReport) -> Vec<Vec3> {
    r.missions[0].points()
}

fn arrival(r: &PlanReport) -> f64 {
    *r.missions[0].times.last().unwrap()
}

fn length(p: &[Vec3]) -> f64 {
    p.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// The length (m) of `p` where `inside` holds, each segment sampled at 1000 midpoints.
fn length_where(p: &[Vec3], inside: impl Fn(Vec3) -> bool) -> f64 {
    const K: usize = 1000;
    p.windows(2)
        .map(|w| {
            let piece = w[0].distance(w[1]) / K as f64;
            (0..K).filter(|&k| inside(w[0].lerp(w[1], (k as f64 + 0.5) / K as f64))).count() as f64 * piece
        })
        .sum()
}

/// The path mirrored in the diagonal x = y.
fn mirror(p: &[Vec3]) -> Vec<Vec3> {
    p.iter().map(|q| Vec3::new(q.y, q.x, q.z)).collect()
}

fn cells(s: &Scenario) -> &tidepath::world::terrain::CellGrid {
    match &s.world.terrain {
        Terrain::Cells(c) => c,
        other => panic!("{}: terrain {other:?}", s.name),
    }
}

/// Every scenario loads without warnings as a wave glider with the paper's regression, the
/// travel-time objective and its planner; the grid scenarios go from cell 1's centre to cell
/// 400's (eq. 3).
#[test]
fn every_glider_scenario_loads_with_its_setting() {
    for name in GRID.iter().copied().chain(["glider-ocean"]) {
        let s = load(name).unwrap();
        assert!(s.warnings.is_empty(), "{name}: {:?}", s.warnings);
        let g = s.vehicle.glider().unwrap_or_else(|| panic!("{name}: not a wave glider"));
        assert_eq!((g.wave_gain, g.current_gain, g.min_speed), (0.1623, 0.2660, 0.05), "{name}");
        assert_eq!(s.cost.model, "general", "{name}");
        let w = &s.cost.weights;
        assert_eq!((w["length"].as_float(), w["time"].as_float()), (Some(0.0), Some(1.0)), "{name}");
        assert_eq!((s.planner.id.as_str(), s.planner.iterations), ("acopf", Some(60)), "{name}");
    }
    for name in GRID {
        let s = load(name).unwrap();
        assert_eq!((s.start.to_array(), s.goal.to_array()), ([500.0, 500.0, 0.0], [19_500.0, 19_500.0, 0.0]), "{name}");
        assert_eq!(s.settings.current_step, 250.0, "{name}");
    }
}

/// One obstacle layout in all four: 20 x 20 cells of 1 km, 73 blocked (18.25 %, within the
/// 15-20 % chosen), symmetric in the diagonal, the 3 x 3 cells at each end free.
#[test]
fn the_grid_map_is_shared_symmetric_and_about_a_sixth_blocked() {
    let first = load("glider-1").unwrap();
    let c = cells(&first);
    assert_eq!((c.x0, c.y0, c.dx, c.dy, c.nx, c.ny), (0.0, 0.0, KM, KM, 20, 20));
    let blocked = |i: usize, j: usize| c.z[j * 20 + i] > 0.0;
    let n = (0..400).filter(|k| blocked(k % 20, k / 20)).count();
    assert_eq!(n, 73);
    assert!((0.15..=0.20).contains(&(n as f64 / 400.0)));
    for i in 0..20 {
        for j in 0..20 {
            assert_eq!(blocked(i, j), blocked(j, i), "cell ({i}, {j})");
        }
    }
    for (i, j) in (0..3).flat_map(|i| (0..3).map(move |j| (i, j))) {
        assert!(!blocked(i, j) && !blocked(19 - i, 19 - j), "({i}, {j})");
    }
    // Hand-picked cells of the map: the plus-shaped island's centre, the gate's islands.
    assert!(blocked(6, 6) && blocked(12, 16) && blocked(16, 12) && !blocked(14, 14));
    for name in &GRID[1..] {
        assert_eq!(cells(&load(name).unwrap()).z, c.z, "{name}");
    }
}

/// The wave heights at cell centres (and between them, bilinear) are the chosen values.
#[test]
fn wave_heights_are_the_chosen_values() {
    let at = |s: &Scenario, x: f64, y: f64| s.world.waves.height(Vec3::new(x * KM, y * KM, 0.0), 0.0);
    let g1 = load("glider-1").unwrap();
    assert_eq!(g1.world.waves, Waves::Uniform(2.0));
    for name in ["glider-2", "glider-3"] {
        let s = load(name).unwrap();
        for y in [0.5, 9.5, 19.5] {
            // 2.0 m up to x = 10 km, then 2.0 - 1.5 (x - 10) / 10.
            for (x, h) in [(0.5, 2.0), (9.5, 2.0), (10.5, 1.925), (15.5, 1.175), (19.5, 0.575), (12.0, 1.7)] {
                assert!((at(&s, x, y) - h).abs() < 1e-12, "{name} at ({x}, {y}): {}", at(&s, x, y));
            }
        }
    }
    // glider-4: 2.0 + 0.05 (row - column).
    let s = load("glider-4").unwrap();
    for (c, r, h) in [(0, 19, 2.95), (19, 0, 1.05), (7, 7, 2.0), (3, 11, 2.4), (15, 2, 1.35)] {
        let got = at(&s, c as f64 + 0.5, r as f64 + 0.5);
        assert!((got - h).abs() < 1e-12, "glider-4 cell ({c}, {r}): {got}");
    }
}

/// glider-3's current: 0.5 m/s toward the south-east at the centres of the cells in
/// {10 < x <= 20, 8 <= y <= 16} km, zero at every other centre; none in glider-1 and -2;
/// glider-4's clockwise eddy is fastest, 0.40 m/s, 6.7 km from its centre (8, 12) km.
#[test]
fn the_currents_are_the_chosen_ones() {
    let s = load("glider-3").unwrap();
    for i in 0..20 {
        for j in 0..20 {
            let (x, y) = (i as f64 + 0.5, j as f64 + 0.5);
            let c = s.world.current.velocity(Vec3::new(x * KM, y * KM, 0.0), 0.0);
            if x > 10.0 && (8.0..=16.0).contains(&y) {
                assert!((c.truncate().length() - 0.5).abs() < 1e-6, "({x}, {y}): {c:?}");
                assert!((c.x + c.y).abs() < 1e-12 && c.x > 0.0, "({x}, {y}) not south-east: {c:?}");
            } else {
                assert_eq!((c.x, c.y), (0.0, 0.0), "({x}, {y})");
            }
        }
    }
    for name in ["glider-1", "glider-2"] {
        let s = load(name).unwrap();
        assert_eq!(s.world.current.velocity(Vec3::new(15_500.0, 12_500.0, 0.0), 0.0), Vec3::ZERO, "{name}");
    }
    let s = load("glider-4").unwrap();
    let v = |x: f64, y: f64| s.world.current.velocity(Vec3::new(x, y, 0.0), 0.0);
    let r = 1.120_906_423_2 * 6000.0;
    let west = v(8000.0 - r, 12_000.0);
    assert!((west.y - 0.40).abs() < 1e-3 && west.x.abs() < 1e-12, "{west:?}");
    let north = v(8000.0, 12_000.0 + r);
    assert!((north.x - 0.40).abs() < 1e-3, "clockwise: east along its north side, {north:?}");
}

/// glider-ocean's forecast (read from the embedded file): every 6 h for 8 days, fill in all
/// three variables at the few nodes within 4 km of Nihoa and nowhere else, heights within
/// [1, 3.5] m and currents at most 0.6 m/s elsewhere; in the scenario the island is land and
/// the loaded waves keep those values.
#[test]
fn the_ocean_forecast_has_gaps_at_the_island_and_the_chosen_ranges() {
    let bytes = EMBEDDED.iter().find(|(n, _)| *n == "glider_ocean.nc").unwrap().1;
    let file = DataFile::Embedded { name: "glider_ocean.nc", bytes };
    let waves = read_waves(&file, None, None, 1).unwrap();
    let cur = read_currents(&file, None, None, 0.0, None, 1).unwrap();
    assert_eq!((waves.variable.as_str(), waves.height.len(), cur.u.len()), ("VHM0", 33, 33));
    assert_eq!(waves.times[0].to_rfc3339(), "2026-06-01T00:00:00+00:00");
    assert_eq!((waves.times[32] - waves.times[0]).num_hours(), 8 * 24);
    for (k, h) in waves.height.iter().enumerate() {
        let gaps: Vec<usize> = (0..h.values.len()).filter(|&n| h.values[n].is_nan()).collect();
        assert!((3..=40).contains(&gaps.len()), "step {k}: {} gaps", gaps.len());
        for &n in &gaps {
            let (lon, lat) = (h.lon[n % h.nx()], h.lat[n / h.nx()]);
            let d = ((lon - NIHOA.0) * 102.4).hypot((lat - NIHOA.1) * 110.75);
            assert!(d < 4.1, "step {k}: a gap {d} km from Nihoa");
            assert!(cur.u[k].values[n].is_nan() && cur.v[k].values[n].is_nan(), "step {k}: node {n}");
        }
        let valid = h.values.iter().filter(|v| !v.is_nan());
        assert!(valid.clone().all(|v| (1.0..=3.5).contains(v)), "step {k}");
        let (lo, hi) = valid.fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        assert!(lo < 1.05 && hi > 3.3, "step {k}: heights {lo}..{hi}");
        let fastest = cur.u[k].values.iter().zip(&cur.v[k].values).map(|(u, v)| u.hypot(*v)).fold(0.0, f64::max);
        assert!(fastest > 0.55 && fastest <= 0.601, "step {k}: {fastest}");
    }
    let s = load("glider-ocean").unwrap();
    let f = s.frame.as_ref().unwrap();
    let (x, y) = f.forward(NIHOA.0, NIHOA.1, "nihoa").unwrap();
    assert!(s.world.terrain.elevation(x, y) > 0.0, "Nihoa is land");
    assert!(s.world.terrain.elevation(x + 20_000.0, y) < -3000.0, "open ocean 20 km east");
    let Waves::Grid(g) = &s.world.waves else { panic!("{:?}", s.world.waves) };
    assert_eq!(g.times.len(), 33);
    assert!(g.height_bound() <= 3.5 && g.height_bound() > 3.3, "{}", g.height_bound());
    assert!(s.start.distance(s.goal) > 150_000.0 && s.start.distance(s.goal) < 160_000.0);
}

/// glider-1: every route has a mirror image in the diagonal that is as long (the map is
/// symmetric and the start and goal lie on the diagonal), and no route is its own mirror:
/// the shortest route comes as two optimal paths of equal length (Fig. 3), both feasible,
/// equally quick in the uniform waves.
#[test]
fn glider1_has_two_optimal_paths_of_equal_length() {
    let (s, r) = plan("glider-1", "astar", "length");
    let p = points(&r);
    let q = mirror(&p);
    assert_ne!(p, q);
    let e = s.evaluate(&q).unwrap();
    assert!(e.feasible, "{:?}", e.violations);
    assert!((length(&p) - length(&q)).abs() < 1e-6);
    assert!((arrival(&r) - e.times.last().unwrap()).abs() < 1e-6);
    // 23 cell moves, 15 of them diagonal: 8 + 15 sqrt 2 km (the blocked diagonal is 19 sqrt 2).
    assert!((length(&p) - (8.0 + 15.0 * 2f64.sqrt()) * KM).abs() < 1e-6, "{}", length(&p));
}

/// glider-2 (Fig. 4): the quickest route keeps to the larger waves. It runs a larger share of
/// its length where x <= 10 km (2 m waves) than the shortest route and its mirror image, and
/// is quicker than both.
#[test]
fn glider2_quickest_route_keeps_to_the_larger_waves() {
    let (s, quick) = plan("glider-2", "astar", "time");
    let (_, short) = plan("glider-2", "astar", "length");
    let west = |p: &[Vec3]| length_where(p, |q| q.x <= 10.0 * KM) / length(p);
    let (pq, ps) = (points(&quick), points(&short));
    let (wq, ws, wm) = (west(&pq), west(&ps), west(&mirror(&ps)));
    eprintln!("glider-2: x <= 10 km share {wq:.3} (quickest) vs {ws:.3} / {wm:.3} (shortest, mirrored)");
    assert!(wq > ws + 0.05 && wq > wm + 0.05, "{wq} vs {ws}, {wm}");
    let t_mirror = *s.evaluate(&mirror(&ps)).unwrap().times.last().unwrap();
    eprintln!("glider-2: {:.0} s quickest, {:.0} s / {t_mirror:.0} s shortest", arrival(&quick), arrival(&short));
    assert!(arrival(&quick) < arrival(&short).min(t_mirror));
    assert!(length(&pq) > length(&ps));
}

/// glider-3 (Fig. 5): with the south-east current the quickest route rides it, running
/// kilometres east inside the band where glider-2's quickest route (along the north edge)
/// runs none, and it is quicker there than glider-2's route would be.
#[test]
fn glider3_quickest_route_rides_the_current() {
    let band = |q: Vec3| q.x > 10.0 * KM && (8.0 * KM..=16.0 * KM).contains(&q.y);
    let (s3, r3) = plan("glider-3", "astar", "time");
    let (_, r2) = plan("glider-2", "astar", "time");
    let (in3, in2) = (length_where(&points(&r3), band), length_where(&points(&r2), band));
    eprintln!("glider-3: {in3:.0} m in the band (glider-2's quickest route: {in2:.0} m)");
    assert!(in3 > in2 + 3.0 * KM, "{in3} vs {in2}");
    let t2_in_3 = *s3.evaluate(&points(&r2)).unwrap().times.last().unwrap();
    eprintln!("glider-3: {:.0} s quickest, {t2_in_3:.0} s on glider-2's route", arrival(&r3));
    assert!(arrival(&r3) < 0.99 * t2_in_3);
}

/// glider-4: the shortest route through the middle meets a head current; the quickest goes
/// round the west and north edges on the eddy and in higher waves, longer by more than 10 %
/// and quicker by more than 10 %.
#[test]
fn glider4_quickest_and_shortest_routes_differ_clearly() {
    let (s, quick) = plan("glider-4", "astar", "time");
    let (_, short) = plan("glider-4", "astar", "length");
    let (pq, ps) = (points(&quick), points(&short));
    let t_mirror = *s.evaluate(&mirror(&ps)).unwrap().times.last().unwrap();
    let t_short = arrival(&short).min(t_mirror);
    eprintln!(
        "glider-4: quickest {:.0} s over {:.0} m; shortest {t_short:.0} s (best of it and its mirror) over {:.0} m",
        arrival(&quick),
        length(&pq),
        length(&ps)
    );
    assert!(t_short > 1.1 * arrival(&quick), "{t_short} vs {}", arrival(&quick));
    assert!(length(&pq) > 1.1 * length(&ps));
}

/// glider-ocean: A* plans the quickest and the shortest route; the quickest bends north-west
/// (into the swell band and the eddy's following flank) by more than 15 km off the straight
/// line, the shortest stays within 8 km of it (its raster staircase), and the quickest is at least 15 % quicker.
#[test]
fn glider_ocean_quickest_route_bends_north_west() {
    let t = std::time::Instant::now();
    let (s, quick) = plan("glider-ocean", "astar", "time");
    let t_quick = t.elapsed();
    let (_, short) = plan("glider-ocean", "astar", "length");
    let d = (s.goal - s.start).truncate().normalize();
    // Signed offset to the left of the start -> goal line (north-west of it).
    let left = |q: Vec3| {
        let r = (q - s.start).truncate();
        d.x * r.y - d.y * r.x
    };
    let most = |p: &[Vec3]| p.iter().map(|q| left(*q)).fold(f64::MIN, f64::max);
    let widest = |p: &[Vec3]| p.iter().map(|q| left(*q).abs()).fold(0.0, f64::max);
    let (pq, ps) = (points(&quick), points(&short));
    eprintln!(
        "glider-ocean: quickest {:.1} h, {:.1} km, {:.1} km north-west of the line (A* {t_quick:.2?}); shortest {:.1} h, {:.1} km, within {:.1} km",
        arrival(&quick) / 3600.0,
        length(&pq) / KM,
        most(&pq) / KM,
        arrival(&short) / 3600.0,
        length(&ps) / KM,
        widest(&ps) / KM
    );
    assert!(most(&pq) > 15.0 * KM);
    assert!(widest(&ps) < 8.0 * KM);
    assert!(arrival(&short) > 1.15 * arrival(&quick));
}

/// The scenarios' own planner, the paper's ACOPF (60 iterations of 30 ants), plans each one
/// feasibly, never quicker than A*'s time-optimal route on the same raster (1 % allowed for the
/// time-varying forecast, where A* by arrival time is not guaranteed exact).
#[test]
fn the_papers_planner_plans_every_scenario_no_quicker_than_astar() {
    for name in GRID.iter().copied().chain(["glider-ocean"]) {
        let s = load(name).unwrap();
        let t = std::time::Instant::now();
        let r = s.plan(&PlanRequest::default(), &mut |_| {}).unwrap();
        let took = t.elapsed();
        let m = &r.missions[0];
        assert!(m.feasible, "{name}: {}", m.reason);
        common::recheck_plan(&s, &r).unwrap_or_else(|e| panic!("{name}: {e}"));
        let (_, best) = plan(name, "astar", "time");
        eprintln!("{name}: acopf {:.0} s ({took:.2?}), astar {:.0} s", arrival(&r), arrival(&best));
        assert!(arrival(&r) >= 0.99 * arrival(&best), "{name}: {} < {}", arrival(&r), arrival(&best));
    }
}
