//! Failure figures show the cause: violations on the plan view and the profile, the place a
//! failure is about with what is there, obstacle kinds, the safety distance, moving obstacles'
//! time marks, the current's scale, the reference path, and a log cost axis for a wide range.
//!
//! Set `TIDEPATH_PLOT_DIR` to also write the SVGs there, to look at them.

use tidepath::geom::{Aabb, Vec2, Vec3};
use tidepath::path::{Violation, ViolationKind};
use tidepath::planner::Focus;
use tidepath::world::terrain::{GaussianPeaks, Peak};
use tidepath::world::{Current, Obstacle, Shape, Terrain, World};
use tidepath_plot::{render_plan_figure, PlanFigure, PlotPath};

/// The warning colour's strokes (plan view and profile bands, rings, the focus mark).
const WARN: &str = "#FF0028";

/// 10 km x 6 km x 500 m over one seamount, with one obstacle of each kind, the circle moving
/// north at 0.25 m/s, in a uniform 0.3 m/s current.
fn world() -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -500.0), Vec3::new(10_000.0, 6_000.0, 0.0)));
    w.terrain = Terrain::Peaks(GaussianPeaks {
        base: -480.0,
        peaks: vec![Peak { x: 5_000.0, y: 3_000.0, height: 250.0, sigma_x: 1_200.0, sigma_y: 900.0 }],
        ceiling: None,
    });
    w.obstacles = vec![
        Obstacle::fixed(Shape::Sphere { center: Vec3::new(1_000.0, 1_000.0, -200.0), radius: 300.0 }),
        Obstacle::fixed(Shape::Box {
            min: Vec3::new(3_000.0, 4_000.0, -300.0),
            max: Vec3::new(4_000.0, 5_000.0, -100.0),
        }),
        Obstacle::fixed(Shape::Cylinder {
            center: Vec2::new(7_000.0, 1_500.0),
            radius: 400.0,
            z_min: -400.0,
            z_max: -150.0,
        }),
        Obstacle {
            shape: Shape::Circle { center: Vec2::new(6_000.0, 4_500.0), radius: 200.0 },
            velocity: Vec3::new(0.0, -0.25, 0.0),
            window: None,
        },
    ];
    w.current = Current::Uniform(Vec3::new(0.3, 0.0, 0.0));
    w
}

/// Whether the SVG has a text element reading exactly `s`.
fn has_text(svg: &str, s: &str) -> bool {
    svg.contains(&format!("\n{s}\n</text>"))
}

fn save(name: &str, svg: &str) {
    if let Some(dir) = std::env::var_os("TIDEPATH_PLOT_DIR") {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(std::path::Path::new(&dir).join(name), svg).unwrap();
    }
}

/// Shapes stroked in the warning colour, `width` wide, at `opacity`.
fn warn_strokes(svg: &str, opacity: &str, width: u32) -> usize {
    svg.matches(&format!(r#"opacity="{opacity}" fill="none" stroke="{WARN}" stroke-width="{width}""#)).count()
        + svg.matches(&format!(r#"opacity="{opacity}" stroke="{WARN}" stroke-width="{width}""#)).count()
}

#[test]
fn an_infeasible_path_shows_its_violations_obstacle_kinds_and_time_marks() {
    let w = world();
    let (start, goal) = (Vec3::new(500.0, 3_000.0, -250.0), Vec3::new(9_500.0, 3_000.0, -250.0));
    let path = [start, Vec3::new(3_500.0, 4_500.0, -200.0), Vec3::new(6_500.0, 2_000.0, -200.0), goal];
    // 1.5 m/s over about 3,350 + 3,900 + 3,160 m: arrivals after 0, 2,236, 4,839 and 6,948 s.
    let times = [0.0, 2_236.0, 4_839.0, 6_948.0];
    let violations = [
        Violation {
            kind: ViolationKind::Obstacle,
            index: 0,
            message: "segment 0 passes 0.00 m from obstacle 1".into(),
        },
        Violation { kind: ViolationKind::Turn, index: 2, message: "waypoint 2 turn 95 deg".into() },
    ];
    let reference = [start, Vec3::new(5_000.0, 5_500.0, -250.0), goal];
    let history: Vec<f64> = (0..30).map(|i| 2.0 + 1e6 * (-(i as f64)).exp()).collect();
    let mut fig = PlanFigure::new("infeasible", &w, start, goal, 0.0);
    fig.safety_distance = 60.0;
    fig.paths = vec![PlotPath::new("pso", &path).with_times(&times).with_violations(&violations)];
    fig.reference = Some(PlotPath::new("reference: theta-star", &reference));
    fig.histories = vec![("pso".into(), &history)];
    fig.history_start = Some("after a reference search (812 expansions)".into());
    let svg = render_plan_figure(&fig).unwrap();
    save("failure_violations.svg", &svg);

    // The violated segment: a 12-pixel band on the plan view and on the profile; the violated
    // turn: a ring on both.
    assert!(warn_strokes(&svg, "0.65", 12) >= 2, "bands missing");
    assert!(warn_strokes(&svg, "1", 2) >= 2, "waypoint rings missing");
    for text in [
        "violated segment: obstacle",
        "violated waypoint: turn",
        "sphere",
        "box",
        "cylinder (part of the water column)",
        "column through every depth",
        "safety distance (60 m)",
        "seabed + safety distance (60 m)",
        "obstacle cut by the section",
        "reference: theta-star",
        // 0.3 m/s is shown to a scale of 0.2 m/s, the largest of 1, 2, 5 x 10^k not above it.
        // At the mean depth of the first path's points: (-250 - 200 - 200 - 250) / 4 = -225 m.
        "current at z = -225 m, t = 0 s (departure): arrow = 0.2 m/s (fastest 0.3 m/s)",
        // The moving circle makes the picture time-dependent.
        "Plan view at t = 0 s (departure)",
        "after a reference search (812 expansions)",
        "best cost (log scale)",
    ] {
        assert!(svg.contains(text), "{text:?} missing");
    }
    // 6,948 s in at most five marks: every 30 minutes, labelled on the path, and on the
    // obstacle (450 m apart) where clear of its speed label: not the first.
    for (mark, n) in [("+30 min", 1), ("+1 h", 2), ("+90 min", 2)] {
        assert_eq!(svg.matches(&format!("\n{mark}\n</text>")).count(), n, "{mark}");
    }
}

#[test]
fn an_invalid_start_is_marked_with_what_is_there() {
    let w = world();
    // Inside the sphere (obstacle 0), over the seabed at about -480 m.
    let start = Vec3::new(1_000.0, 1_100.0, -200.0);
    let goal = Vec3::new(9_000.0, 5_000.0, -250.0);
    let mut fig = PlanFigure::new("invalid start", &w, start, goal, 0.0);
    fig.safety_distance = 30.0;
    fig.focus = vec![Focus { at: start, label: "invalid start".into() }];
    fig.paths = vec![PlotPath::new("hybrid", &[])];
    let svg = render_plan_figure(&fig).unwrap();
    save("failure_invalid_start.svg", &svg);
    for text in [
        "invalid start",
        "z = -200 m",
        "in obstacle 0 (sphere)",
        "hybrid (no path)",
        "seabed along the straight line start → goal",
        "no convergence history",
    ] {
        assert!(svg.contains(text), "{text:?} missing");
    }
    // The seabed under the start, to the metre: base -480 plus the seamount's tail there.
    let z = w.terrain.elevation(start.x, start.y);
    assert!(svg.contains(&format!("seabed at {z:.0} m ({:.0} m of water)", -z)), "seabed depth missing ({z})");
    // The obstacle it is in is outlined in the warning colour, the mark is a 3-pixel ring.
    assert!(warn_strokes(&svg, "1", 3) >= 2, "obstacle outline or focus ring missing");
}

#[test]
fn a_bottleneck_is_marked_without_a_depth_of_its_own() {
    let w = world();
    let (start, goal) = (Vec3::new(500.0, 3_000.0, -250.0), Vec3::new(9_500.0, 3_000.0, -250.0));
    let mut fig = PlanFigure::new("unreachable", &w, start, goal, 0.0);
    fig.focus = vec![Focus { at: Vec3::new(5_000.0, 3_000.0, -230.0), label: "bottleneck".into() }];
    let svg = render_plan_figure(&fig).unwrap();
    save("failure_bottleneck.svg", &svg);
    assert!(has_text(&svg, "bottleneck"));
    // Its depth is the reachability check's, in the reason: the figure states none of its own.
    assert!(!svg.contains("m of water"));
    assert!(warn_strokes(&svg, "1", 3) >= 1);
}

#[test]
fn convergence_uses_a_log_axis_only_for_a_wide_range() {
    let w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -100.0), Vec3::new(1_000.0, 1_000.0, 0.0)));
    let path = [Vec3::new(100.0, 100.0, -50.0), Vec3::new(900.0, 900.0, -50.0)];
    // From 1e6 down to 2: six decades, labelled at every decade from 1 to 1e6.
    let wide: Vec<f64> = (0..=20).map(|i| 2.0 + 1e6 * 0.5f64.powi(i)).collect();
    let narrow: Vec<f64> = (0..=20).map(|i| 20.0 - 0.5 * i as f64).collect();
    for (history, log) in [(&wide, true), (&narrow, false)] {
        let mut fig = PlanFigure::new("log", &w, path[0], path[1], 0.0);
        fig.paths = vec![PlotPath::new("de", &path)];
        fig.histories = vec![("de".into(), history.as_slice())];
        let svg = render_plan_figure(&fig).unwrap();
        assert_eq!(svg.contains("best cost (log scale)"), log);
        assert_eq!(has_text(&svg, "1e6") && has_text(&svg, "1000") && has_text(&svg, "1e4"), log, "{log}");
    }
}
