//! Figures of a plan flown with a turning radius: the flown curve is the path's line, the
//! waypoints small hollow markers on a thin dashed line, each with a legend entry; the profile
//! runs along the flown curve; violated segments are marked on the part of the curve the
//! vehicle flies for them. Without a radius the figure is as before.
//!
//! Set `TIDEPATH_PLOT_DIR` to also write the SVGs there, to look at them.

use tidepath::geom::Vec3;
use tidepath_io::scenario::{PlanRequest, Scenario};
use tidepath_io::PlanReport;
use tidepath_plot::{render_plan_figure, PlanFigure, PlotPath};

/// The first path colour (orange) and the warning colour, as the SVG writes them.
const ORANGE: &str = "#FF7F0E";
const WARN: &str = "#FF0028";

/// `headland` with a turning radius (m) or none, planned by `astar`: with 300 m its corners
/// do not fit and the turn at the headland's tip brushes the breakwater.
fn planned(radius: Option<f64>) -> (Scenario, PlanReport) {
    let mut text = tidepath_io::scenario::builtin("headland").unwrap().to_string();
    if let Some(r) = radius {
        text = text.replace("[vehicle]\n", &format!("[vehicle]\nturn_radius = {r}\n"));
    }
    let s = Scenario::from_toml(&text, "builtin:headland").unwrap();
    let r = s.plan(&PlanRequest { planner: Some("astar".into()), ..PlanRequest::default() }, &mut |_| {}).unwrap();
    (s, r)
}

fn figure(s: &Scenario, r: &PlanReport) -> String {
    let m = &r.missions[0];
    let (points, flown) = (m.points(), m.flown.as_ref().map(|f| f.vectors()));
    let mut fig = PlanFigure::of_scenario("headland", s);
    let path = PlotPath::new("astar", &points).with_times(&m.times).with_violations(&m.violations);
    fig.paths = vec![match (&flown, s.vehicle.turn_radius) {
        (Some(f), Some(radius)) => path.with_flown(f, &m.flown.as_ref().unwrap().times, radius),
        _ => path,
    }];
    let svg = render_plan_figure(&fig).unwrap();
    if let Some(dir) = std::env::var_os("TIDEPATH_PLOT_DIR") {
        std::fs::create_dir_all(&dir).unwrap();
        let name = format!("flown-{}.svg", s.vehicle.turn_radius.map_or("none".into(), |r| r.to_string()));
        std::fs::write(std::path::Path::new(&dir).join(name), &svg).unwrap();
    }
    svg
}

fn has_text(svg: &str, s: &str) -> bool {
    svg.contains(&format!("\n{s}\n</text>"))
}

/// The point lists of the polylines stroked in `color`, `width` wide, at `opacity`.
fn polylines(svg: &str, opacity: &str, color: &str, width: u32) -> Vec<Vec<(i32, i32)>> {
    let head = format!(r#"<polyline fill="none" opacity="{opacity}" stroke="{color}" stroke-width="{width}" points=""#);
    svg.match_indices(&head)
        .map(|(i, _)| {
            let rest = &svg[i + head.len()..];
            rest[..rest.find('"').unwrap()]
                .split_whitespace()
                .map(|xy| {
                    let (x, y) = xy.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

#[test]
fn a_flown_curve_is_the_line_with_the_waypoints_marked_apart() {
    let (s, r) = planned(Some(300.0));
    let m = &r.missions[0];
    let flown = m.flown.as_ref().expect("a radius gives a flown curve");
    let svg = figure(&s, &r);
    // Legend entries in the plan view and in the profile.
    for label in ["astar: flown, turns of radius 300 m", "astar: waypoints (corners cut)"] {
        assert_eq!(svg.matches(&format!("\n{label}\n</text>")).count(), 2, "{label}");
    }
    assert!(!has_text(&svg, "astar"), "the plain path entry is replaced");
    assert!(has_text(&svg, "horizontal distance along the flown path (km)"));
    // The plan view's line is the flown curve, every point of it; the profile's too.
    let lines = polylines(&svg, "1", ORANGE, 3);
    assert!(
        lines.iter().any(|l| l.len() == flown.points.len()),
        "{:?}",
        lines.iter().map(Vec::len).collect::<Vec<_>>()
    );
    assert_eq!(polylines(&svg, "1", ORANGE, 2).iter().map(Vec::len).max(), Some(flown.points.len()));
    // Waypoints are small hollow markers, on the plan view and on the profile (and two in the
    // legend swatch of each panel), at least a few pixels apart: the first and last always,
    // the others where they do not crowd.
    let hollow = format!(r#"r="3" opacity="1" fill="none" stroke="{ORANGE}" stroke-width="1""#);
    let rings = svg.matches(&hollow).count() - 4;
    assert!(rings >= 4 && rings <= 2 * m.waypoints.len(), "{rings} rings for {} waypoints", m.waypoints.len());
    // No filled waypoint dots but the legend's.
    assert_eq!(svg.matches(&format!(r#"r="3" opacity="1" fill="{ORANGE}""#)).count(), 0);

    // Violated segments: a band per violation in each panel, along the flown curve, so a
    // band of a segment whose turn is in it has more than the two ends of a straight segment.
    let on_segment: Vec<usize> = m
        .violations
        .iter()
        .filter(|v| matches!(v.kind, tidepath::path::ViolationKind::Obstacle | tidepath::path::ViolationKind::Terrain))
        .map(|v| v.index)
        .collect();
    assert!(!on_segment.is_empty(), "{:?}", m.violations);
    let bands = polylines(&svg, "0.65", WARN, 12);
    assert_eq!(bands.len(), 2 * on_segment.len());
    assert!(bands.iter().all(|b| b.len() > 2), "{:?}", bands.iter().map(Vec::len).collect::<Vec<_>>());
    // The turns that do not fit are ringed at their waypoints.
    let turns = m.violations.iter().filter(|v| v.kind == tidepath::path::ViolationKind::Turn).count();
    assert!(turns > 0);
    let rings = format!(r#"r="9" opacity="1" fill="none" stroke="{WARN}" stroke-width="2""#);
    assert_eq!(svg.matches(&rings).count(), 2 * turns);
}

/// Text elements reading a whole number, as (x, y, number): the tick labels.
fn numbers(svg: &str) -> Vec<(i32, i32, f64)> {
    let mut out = Vec::new();
    for (i, _) in svg.match_indices("<text x=\"") {
        let rest = &svg[i + 9..];
        let x: i32 = rest.split('"').next().unwrap().parse().unwrap();
        let y: i32 = rest[rest.find("y=\"").unwrap() + 3..].split('"').next().unwrap().parse().unwrap();
        let body = &rest[rest.find(">\n").unwrap() + 2..];
        if let Ok(v) = body[..body.find("\n</text>").unwrap()].parse::<f64>() {
            out.push((x, y, v));
        }
    }
    out
}

/// The profile runs along the flown curve: read on its distance axis, its line is as long as
/// the flown curve, which is shorter than the waypoints' polyline.
#[test]
fn the_profile_measures_the_flown_distance() {
    let (s, r) = planned(Some(300.0));
    let m = &r.missions[0];
    let horizontal = |p: &[Vec3]| p.windows(2).map(|w| (w[1] - w[0]).truncate().length()).sum::<f64>();
    let flown = horizontal(&m.flown.as_ref().unwrap().vectors());
    let polyline = horizontal(&m.points());
    assert!(flown < polyline - 150.0, "{flown} vs {polyline}");
    let svg = figure(&s, &r);
    // The profile's line (2 px wide) and its distance ticks: the labels under its left end.
    let line = polylines(&svg, "1", ORANGE, 2).into_iter().max_by_key(Vec::len).unwrap();
    let (x0, x1) = (line[0].0, line[line.len() - 1].0);
    let ticks: Vec<(i32, f64)> = {
        let all = numbers(&svg);
        let zero =
            all.iter().find(|&&(x, _, v)| v == 0.0 && (x - x0).abs() <= 2).expect("a 0 tick under the line's start");
        all.iter().filter(|t| t.1 == zero.1 && t.0 >= zero.0).map(|&(x, _, v)| (x, v)).collect()
    };
    let (first, last) = (ticks[0], ticks[ticks.len() - 1]);
    assert!(last.1 >= 10.0, "{ticks:?}");
    let km_per_px = (last.1 - first.1) / f64::from(last.0 - first.0);
    let drawn = f64::from(x1 - first.0) * km_per_px * 1000.0;
    // A pixel is about 35 m here.
    assert!((drawn - flown).abs() < 80.0, "the line spans {drawn:.0} m; flown {flown:.0} m, polyline {polyline:.0} m");
}

/// Without a radius the figure has no flown curve: a line with a dot at every waypoint.
#[test]
fn without_a_radius_the_figure_is_as_before() {
    let (s, r) = planned(None);
    assert!(r.missions[0].flown.is_none());
    let svg = figure(&s, &r);
    assert!(!svg.contains("flown") && !svg.contains("corners cut"));
    assert_eq!(svg.matches("\nastar\n</text>").count(), 2);
    assert!(has_text(&svg, "horizontal distance along path (km)"));
    let dots = format!(r#"r="3" opacity="1" fill="{ORANGE}""#);
    // A dot per waypoint on the plan view and the profile, and one in each legend.
    assert_eq!(svg.matches(&dots).count(), 2 * r.missions[0].waypoints.len() + 2);
}

/// A flown curve is drawn over a path without one (a smoothed plan's raw path, listed after
/// it), which would otherwise hide it; colours stay with the paths' order.
#[test]
fn a_flown_curve_is_drawn_over_other_paths() {
    let (s, r) = planned(Some(300.0));
    let m = &r.missions[0];
    let (points, flown) = (m.points(), m.flown.as_ref().unwrap());
    let curve = flown.vectors();
    let mut fig = PlanFigure::of_scenario("headland", &s);
    fig.paths =
        vec![PlotPath::new("smoothed", &points).with_flown(&curve, &flown.times, 300.0), PlotPath::new("raw", &points)];
    let svg = render_plan_figure(&fig).unwrap();
    let magenta = r##"stroke="#C81E82" stroke-width="3" points=""##;
    let orange = format!(r#"stroke="{ORANGE}" stroke-width="3" points=""#);
    // The first line of each colour is the plan view's (the legend's swatches come later).
    let (raw, curve_at) = (svg.find(magenta).unwrap(), svg.find(&orange).unwrap());
    assert!(raw < curve_at, "the flown curve is drawn before the raw path");
    assert!(has_text(&svg, "horizontal distance along path or flown curve (km)"));
}
