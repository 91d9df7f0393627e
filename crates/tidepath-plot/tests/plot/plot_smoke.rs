//! Smoke tests of the plan figure: it renders for rich and for bare worlds and the SVG carries
//! the labels a reader needs.
//!
//! Set `TIDEPATH_PLOT_DIR` to also write the SVGs there, to look at them.

use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::world::current::LambOseen;
use tidepath::world::terrain::{GaussianPeaks, Peak};
use tidepath::world::{Current, Dims, Obstacle, Shape, Terrain, World};
use tidepath_plot::{render_plan_figure, write_plan_figure, PlanFigure, PlotPath};

fn peak(x: f64, y: f64, height: f64, sigma: f64) -> Peak {
    Peak { x, y, height, sigma_x: sigma, sigma_y: sigma * 0.8 }
}

/// 20 km x 12 km x 1000 m with three seamounts, an island, four obstacles and two vortices.
fn rich_world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(20_000.0, 12_000.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -900.0,
        peaks: vec![
            peak(5_000.0, 7_500.0, 750.0, 2_200.0),
            peak(11_000.0, 3_500.0, 700.0, 1_800.0),
            peak(15_500.0, 9_000.0, 600.0, 2_500.0),
            peak(16_500.0, 2_500.0, 1_150.0, 1_400.0),
        ],
        ceiling: None,
    });
    w.obstacles = vec![
        Obstacle {
            shape: Shape::Sphere { center: Vec3::new(8_000.0, 9_000.0, -400.0), radius: 600.0 },
            velocity: Vec3::new(0.4, -0.2, 0.0),
            window: None,
        },
        Obstacle::fixed(Shape::Box {
            min: Vec3::new(12_500.0, 6_000.0, -800.0),
            max: Vec3::new(14_000.0, 7_200.0, -200.0),
        }),
        Obstacle::fixed(Shape::Circle { center: Vec2::new(8_500.0, 4_500.0), radius: 700.0 }),
        Obstacle::fixed(Shape::Cylinder {
            center: Vec2::new(3_000.0, 3_500.0),
            radius: 500.0,
            z_min: -900.0,
            z_max: -300.0,
        }),
    ];
    w.current = Current::Vortices(vec![
        LambOseen { x: 6_000.0, y: 4_000.0, strength: 4_000.0, core_radius: 1_500.0 },
        LambOseen { x: 14_000.0, y: 8_500.0, strength: -5_000.0, core_radius: 2_000.0 },
    ]);
    w
}

fn wiggly_path(start: Vec3, goal: Vec3, n: usize) -> Vec<Vec3> {
    let d = (goal - start).truncate().normalize();
    let side = Vec3::new(-d.y, d.x, 0.0);
    (0..n)
        .map(|k| {
            let t = k as f64 / (n - 1) as f64;
            let bump = (t * std::f64::consts::PI).sin();
            let zigzag = if k % 2 == 0 { 250.0 } else { -250.0 };
            let mut p =
                start.lerp(goal, t) + side * bump * (1_800.0 * (t * 2.0 * std::f64::consts::TAU).sin() + zigzag);
            p.z = start.z + (goal.z - start.z) * t - 450.0 * bump;
            p
        })
        .collect()
}

fn out_dir() -> Option<std::path::PathBuf> {
    std::env::var_os("TIDEPATH_PLOT_DIR").map(std::path::PathBuf::from)
}

fn assert_readable(svg: &str, title: &str) {
    assert!(svg.starts_with("<svg"), "not an SVG: {}", &svg[..svg.len().min(80)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains(title), "title missing");
    for label in ["Plan view", "Vertical profile", "horizontal distance along path", "z (m, 0 = sea surface)"] {
        assert!(svg.contains(label), "label {label:?} missing");
    }
    assert!(!svg.contains("NaN") && !svg.contains("inf"), "non-finite number in the SVG");
}

/// Each path colour appears on at least one polyline (the path itself, also in the legend).
fn polylines_with_stroke(svg: &str, color: &str) -> usize {
    svg.lines().filter(|l| l.contains("<polyline") && l.contains(&format!("stroke=\"{color}\""))).count()
}

#[test]
fn rich_world_figure_has_all_panels() {
    let world = rich_world();
    let (start, goal) = (Vec3::new(1_000.0, 1_500.0, -80.0), Vec3::new(19_000.0, 10_500.0, -150.0));
    let a = wiggly_path(start, goal, 20);
    let b: Vec<Vec3> = [start, Vec3::new(10_000.0, 800.0, -500.0), goal].to_vec();
    let mut history: Vec<f64> = vec![f64::INFINITY; 3];
    history.extend((0..150).map(|i| 1.0 + 2_000.0 * (-(i as f64) / 12.0).exp()));
    history[40] = f64::NAN;
    let title = "demo — pso, seed 1: cost 1.234, feasible";
    let fig = PlanFigure {
        title: title.into(),
        world: &world,
        start,
        goal,
        time: 0.0,
        epoch: None,
        safety_distance: 0.0,
        focus: vec![],
        reference: None,
        history_start: None,
        history_per_sample: false,
        graphs: vec![],
        speed_path: None,
        still_water_speed: None,
        paths: vec![PlotPath::new("pso", &a), PlotPath::new("straight", &b)],
        histories: vec![("pso".into(), &history)],
    };
    let svg = render_plan_figure(&fig).unwrap();
    assert_readable(&svg, title);
    for label in
        ["x east (km)", "y north (km)", "iteration", "best cost (log scale)", "seabed elevation (m)", "coastline"]
    {
        assert!(svg.contains(label), "label {label:?} missing");
    }
    assert!(polylines_with_stroke(&svg, "#FF7F0E") >= 2, "first path not drawn");
    assert!(polylines_with_stroke(&svg, "#C81E82") >= 2, "second path not drawn");
    if let Some(dir) = out_dir() {
        std::fs::create_dir_all(&dir).unwrap();
        write_plan_figure(&fig, &dir.join("rich.svg")).unwrap();
    }
}

#[test]
fn bare_world_with_empty_history_and_single_point_path() {
    let world = World::open(Aabb::new(Vec3::new(-500.0, 0.0, -200.0), Vec3::new(1_500.0, 800.0, 0.0)));
    let (start, goal) = (Vec3::new(-400.0, 100.0, -50.0), Vec3::new(1_400.0, 700.0, -120.0));
    let path = [start, Vec3::new(600.0, 300.0, -180.0), goal];
    let lonely = [Vec3::new(200.0, 600.0, -20.0)];
    let fig = PlanFigure {
        title: "bare & empty".into(),
        world: &world,
        start,
        goal,
        time: 30.0,
        epoch: None,
        safety_distance: 0.0,
        focus: vec![],
        reference: None,
        history_start: None,
        history_per_sample: false,
        graphs: vec![],
        speed_path: None,
        still_water_speed: None,
        paths: vec![PlotPath::new("direct", &path), PlotPath::new("one point", &lonely)],
        histories: vec![],
    };
    let svg = render_plan_figure(&fig).unwrap();
    assert_readable(&svg, "bare &amp; empty");
    assert!(svg.contains("x east (m)") && svg.contains("y north (m)"));
    assert!(!svg.contains("seabed elevation"), "no colour bar without a seabed");
    assert!(polylines_with_stroke(&svg, "#FF7F0E") >= 2);
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bare.svg");
    write_plan_figure(&fig, &file).unwrap();
    assert_eq!(std::fs::read_to_string(&file).unwrap(), svg);
    if let Some(dir) = out_dir() {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("bare.svg"), &svg).unwrap();
    }
}

#[test]
fn two_d_world_with_uniform_current_and_flat_history() {
    let mut world = World::open(Aabb::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(3_000.0, 3_000.0, 0.0)));
    world.dims = Dims::Two;
    world.current = Current::Uniform(Vec3::new(0.3, 0.1, 0.0));
    world.obstacles = vec![Obstacle::fixed(Shape::Circle { center: Vec2::new(1_500.0, 1_500.0), radius: 400.0 })];
    let path = [Vec3::new(100.0, 100.0, 0.0), Vec3::new(1_500.0, 2_300.0, 0.0), Vec3::new(2_900.0, 2_900.0, 0.0)];
    let flat = [4.0, 4.0];
    let fig = PlanFigure {
        title: "2-D".into(),
        world: &world,
        start: path[0],
        goal: path[2],
        time: 0.0,
        epoch: None,
        safety_distance: 0.0,
        focus: vec![],
        reference: None,
        history_start: None,
        history_per_sample: false,
        graphs: vec![],
        speed_path: None,
        still_water_speed: None,
        paths: vec![PlotPath::new("de", &path)],
        histories: vec![("de".into(), &flat)],
    };
    let svg = render_plan_figure(&fig).unwrap();
    assert_readable(&svg, "2-D");
    assert!(svg.contains("best cost") && !svg.contains("log scale"));
    if let Some(dir) = out_dir() {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("two_d.svg"), &svg).unwrap();
    }
}

#[test]
fn tall_grid_world_with_many_planners_and_moving_obstacles() {
    use tidepath::world::terrain::ElevationGrid;
    use tidepath::world::RegularGrid2;
    let mut world = World::open(Aabb::new(Vec3::new(0.0, 0.0, -300.0), Vec3::new(3_000.0, 6_000.0, 0.0)));
    let grid = RegularGrid2::new(0.0, 0.0, 100.0, 100.0, 31, 61, "terrain").unwrap();
    let z: Vec<f64> = (0..61)
        .flat_map(|j| (0..31).map(move |i| -280.0 + 120.0 * ((i as f64) / 5.0).sin() * ((j as f64) / 9.0).cos()))
        .collect();
    world.terrain = Terrain::Grid(ElevationGrid::new(grid, z, "terrain").unwrap());
    world.obstacles = vec![
        Obstacle {
            shape: Shape::Sphere { center: Vec3::new(1_500.0, 3_000.0, -150.0), radius: 200.0 },
            velocity: Vec3::new(-0.3, 0.0, 0.0),
            window: None,
        },
        Obstacle {
            shape: Shape::Circle { center: Vec2::new(800.0, 4_500.0), radius: 150.0 },
            velocity: Vec3::new(0.0, 0.5, 0.0),
            window: None,
        },
    ];
    world.current = Current::Uniform(Vec3::new(0.0, 0.2, 0.0));
    let (start, goal) = (Vec3::new(300.0, 200.0, -50.0), Vec3::new(2_700.0, 5_800.0, -60.0));
    let paths: Vec<Vec<Vec3>> = (0..5).map(|k| wiggly_path(start, goal, 6 + 3 * k)).collect();
    let names = ["pso", "de", "ga", "random search", "straight line baseline"];
    let histories: Vec<Vec<f64>> =
        (0..3).map(|k| (0..40).map(|i| 50.0 + 10.0 * k as f64 - i as f64).collect()).collect();
    let fig = PlanFigure {
        title: "tall".into(),
        world: &world,
        start,
        goal,
        time: 600.0,
        epoch: None,
        safety_distance: 0.0,
        focus: vec![],
        reference: None,
        history_start: None,
        history_per_sample: false,
        graphs: vec![],
        speed_path: None,
        still_water_speed: None,
        paths: paths.iter().zip(names).map(|(p, n)| PlotPath::new(n, p)).collect(),
        histories: histories.iter().zip(names).map(|(h, n)| (n.to_string(), h.as_slice())).collect(),
    };
    let svg = render_plan_figure(&fig).unwrap();
    assert_readable(&svg, "tall");
    assert!(svg.contains("Plan view at t = 600 s") && svg.contains("seabed elevation (m)"));
    for n in names {
        assert!(svg.contains(n), "legend entry {n:?} missing");
    }
    if let Some(dir) = out_dir() {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("tall.svg"), &svg).unwrap();
    }
}
