//! A single plan's path in a current is coloured by its speed over ground on the plan view,
//! with a colour bar; in still water, or when the figure does not ask for it (a comparison),
//! the path keeps its own colour.

use tidepath::geom::{Aabb, Vec3};
use tidepath::world::{Current, World};
use tidepath_plot::style::{path_color, speed_color};
use tidepath_plot::{render_plan_figure, PlanFigure, PlotPath};

const CRUISE: f64 = 1.5;

/// 10 km x 4 km, a current of 0.5 m/s to the east.
fn world(current: Current) -> World {
    let mut w = World::open(Aabb::new(Vec3::new(0.0, 0.0, -200.0), Vec3::new(10_000.0, 4_000.0, 0.0)));
    w.current = current;
    w
}

/// East with the current (2 m/s over ground), then back west against it (1 m/s).
fn there_and_back() -> (Vec<Vec3>, Vec<f64>) {
    let pts = vec![
        Vec3::new(1_000.0, 1_000.0, -50.0),
        Vec3::new(9_000.0, 1_000.0, -50.0),
        Vec3::new(1_000.0, 3_000.0, -50.0),
    ];
    let back = pts[1].distance(pts[2]);
    (pts, vec![0.0, 8_000.0 / 2.0, 8_000.0 / 2.0 + back / 1.0])
}

fn hex(c: plotters::style::RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// Polylines stroked with `color` at `width` pixels.
fn strokes(svg: &str, color: &str, width: u32) -> usize {
    svg.lines()
        .filter(|l| {
            l.contains("<polyline")
                && l.contains(&format!("stroke=\"{color}\""))
                && l.contains(&format!("stroke-width=\"{width}\""))
        })
        .count()
}

fn figure<'a>(world: &'a World, pts: &'a [Vec3], times: &'a [f64], speed_path: Option<usize>) -> PlanFigure<'a> {
    let mut fig = PlanFigure::new("speed", world, pts[0], pts[2], 0.0);
    fig.paths = vec![PlotPath::new("ijs", pts).with_times(times)];
    fig.speed_path = speed_path;
    fig.still_water_speed = Some(CRUISE);
    fig
}

#[test]
fn a_plan_in_a_current_is_coloured_by_its_speed_over_ground() {
    let w = world(Current::Uniform(Vec3::new(0.5, 0.0, 0.0)));
    let (pts, times) = there_and_back();
    let svg = render_plan_figure(&figure(&w, &pts, &times, Some(0))).unwrap();
    assert!(svg.contains("speed over ground (m/s)"), "no speed colour bar");
    assert!(svg.contains("ijs, coloured by speed over ground (mark on the bar: 1.5 m/s, through still water)"));
    // The fast leg and the slow one, each in its colour at either end of the map.
    let (fast, slow) = (hex(speed_color(2.0, 1.0, 2.0)), hex(speed_color(1.0, 1.0, 2.0)));
    assert_ne!(fast, slow);
    assert_eq!(strokes(&svg, &fast, 4), 1, "fast segment {fast} not drawn once");
    assert_eq!(strokes(&svg, &slow, 4), 1, "slow segment {slow} not drawn once");
    // Labelled at round speeds, the ends of the bar the path's slowest and fastest.
    for label in ["1.2", "1.4", "1.6", "1.8"] {
        assert!(svg.contains(&format!(">\n{label}\n</text>")), "colour bar label {label} missing");
    }
    // The plan view draws no line of the path's own colour; the profile's legend still does.
    let own = hex(path_color(0));
    assert_eq!(strokes(&svg, &own, 3), 1, "the path's own colour on the plan view");
}

#[test]
fn still_water_and_comparisons_keep_the_path_colour() {
    let (pts, times) = there_and_back();
    let still = world(Current::None);
    let current = world(Current::Uniform(Vec3::new(0.5, 0.0, 0.0)));
    let own = hex(path_color(0));
    for (w, speed_path) in [(&still, Some(0)), (&current, None)] {
        let svg = render_plan_figure(&figure(w, &pts, &times, speed_path)).unwrap();
        assert!(!svg.contains("speed over ground"), "coloured by speed: {speed_path:?}");
        // The plan view's line and its legend's, the profile's legend.
        assert_eq!(strokes(&svg, &own, 3), 3, "the path not in its own colour");
    }
    // A path without times has no speed to show.
    let svg = render_plan_figure(&figure(&current, &pts, &[], Some(0))).unwrap();
    assert!(!svg.contains("speed over ground"));
}
