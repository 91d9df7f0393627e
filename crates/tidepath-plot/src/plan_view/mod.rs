//! The plan view: seabed shading and contours (or the significant wave height, in a world
//! with waves), obstacles and currents at one time, and paths.
//!
//! The map keeps the domain's aspect ratio (a distorted map misleads about turning and about
//! distances to obstacles), so the plot size is computed (in `map`, which every plan view
//! shares, the simulation figure's too) from the available area rather than left to plotters.

mod colorbar;
mod graph;
mod graticule;
mod map;
mod obstacles;
mod overlays;
mod seabed;
mod speed;
#[cfg(test)]
mod tests;
pub(crate) mod time_ticks;
mod waves;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::obstacle_look::ObstacleLook;
use super::style::{self, LegendEntry, Marker, Swatch};
use super::{failure, time_label, PlanFigure, PlotPath};
use obstacles::{draw_mark_labels, draw_tracks, mark_times};
use overlays::{draw_paths, draw_reference, draw_violated_segments, draw_violated_waypoints, scale_speed, Quiver};
use seabed::Seabed;
use speed::{draw_speed_path, SpeedPath};
use tidepath::error::{Error, Result};
use tidepath::world::{Current, World};
use waves::WaveMap;

pub(crate) use map::{draw_map, map_frame, MapSpec};
pub(crate) use obstacles::{
    draw_obstacle_motion, draw_obstacles, draw_safety_halos, draw_unseen, position_at, SpeedLabels, UNSEEN_EDGE,
};
pub(crate) use overlays::{draw_endpoints, draw_focus, to_px, LabelBox};

pub(crate) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The region shown: the domain, grown to hold every path point, start, goal and focus so
/// nothing is squashed against the frame.
fn view_rect(fig: &PlanFigure) -> Result<(f64, f64, f64, f64)> {
    let b = fig.world.bounds;
    let (mut x0, mut y0, mut x1, mut y1) = (b.min.x, b.min.y, b.max.x, b.max.y);
    if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite() && x1 > x0 && y1 > y0) {
        return Err(Error::input(
            "world.bounds",
            format!("cannot plot a domain without horizontal extent: {:?} .. {:?}", b.min, b.max),
        ));
    }
    let paths = fig.paths.iter().chain(&fig.reference).flat_map(|p| p.points.iter());
    let extra = paths.chain([&fig.start, &fig.goal]).chain(fig.focus.iter().map(|f| &f.at));
    for p in extra.filter(|p| p.x.is_finite() && p.y.is_finite()) {
        x0 = x0.min(p.x);
        x1 = x1.max(p.x);
        y0 = y0.min(p.y);
        y1 = y1.max(p.y);
    }
    Ok((x0, y0, x1, y1))
}

/// Whether the safety halo around obstacles is worth drawing on a map of `view` at most `w`
/// pixels wide: at least two pixels wide (thinner, it would only thicken the outline).
pub(crate) fn halos_wide(world: &World, safety_distance: f64, (x0, _, x1, _): (f64, f64, f64, f64), w: u32) -> bool {
    !world.obstacles.is_empty() && safety_distance / (x1 - x0) * f64::from(w) >= 2.0
}

/// Depth at which currents are drawn: where the first path travels, else mid-depth.
fn current_depth(world: &World, paths: &[PlotPath]) -> f64 {
    let zs: Vec<f64> =
        paths.iter().find(|p| !p.points.is_empty()).map(|p| p.points.iter().map(|q| q.z).collect()).unwrap_or_default();
    let zs: Vec<f64> = zs.into_iter().filter(|z| z.is_finite()).collect();
    if zs.is_empty() {
        0.5 * (world.bounds.min.z + world.bounds.max.z)
    } else {
        zs.iter().sum::<f64>() / zs.len() as f64
    }
}

/// Whether the picture depends on the time it is drawn at: a current or waves that change
/// with time, or an obstacle that moves. Its caption then says which time it shows.
pub(crate) fn time_varying(world: &World) -> bool {
    let current = match &world.current {
        Current::Jet(_) => true,
        Current::Grid(g) => !g.is_steady(),
        Current::None | Current::Uniform(_) | Current::Vortices(_) => false,
    };
    current || !world.waves.is_steady() || world.obstacles.iter().any(obstacles::is_moving)
}

/// The instant the map shows, for captions and legends: "t = 0 s (departure)".
fn shown_at(fig: &PlanFigure) -> String {
    format!("{} (departure)", time_label::instant(fig.time, fig.epoch))
}

/// Draws the plan view (x east, y north) of `fig` with its legend and, when there is a
/// seabed or waves, a colour bar. Paths take colours [`style::path_color`] in order.
pub fn draw_plan_view<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, fig: &PlanFigure) -> Result<()> {
    let (world, time, paths) = (fig.world, fig.time, fig.paths.as_slice());
    let view = view_rect(fig)?;
    let mut spec = MapSpec::new(world, view, time, current_depth(world, paths));
    let marks = mark_times(fig);
    // In a current, the plan's path coloured by its speed over ground, with its colour bar.
    let by_speed = SpeedPath::of(fig);

    // The scale arrow's length is known once the map is laid out; its legend entry keeps a
    // place as wide as the longest arrow can be and gets its length there.
    let (w, _) = area.dim_in_pixel();
    // The safety halo is drawn when it is at least two pixels wide (thinner, it would only
    // thicken the outline); the map is at most the area's width, which decides it before the
    // layout, since the legend says whether it is there.
    let halos = halos_wide(world, fig.safety_distance, view, w);
    spec.legend = legend_entries(fig, &Shown::of(&spec), !marks.is_empty(), halos, by_speed.as_ref());
    spec.extra_bar = by_speed.as_ref().map(SpeedPath::colour_bar);
    spec.caption =
        Some(if time_varying(world) { format!("Plan view at {}", shown_at(fig)) } else { "Plan view".to_string() });
    draw_map(area, spec, |chart, u| {
        // The search graph under the obstacles' outlines and the paths, which stay readable.
        graph::draw_graphs(chart, fig, u)?;
        let warn: Vec<usize> = fig.focus.iter().flat_map(|f| failure::obstacles_at(fig, f)).collect();
        draw_obstacles(chart, fig, u, &warn)?;
        if halos {
            draw_safety_halos(chart, fig, u)?;
        }
        draw_tracks(chart, fig, u, &marks)?;
        draw_violated_segments(chart, paths, u)?;
        draw_paths(chart, paths, u, by_speed.as_ref().map(|s| s.index))?;
        // Over the other paths (a smoothed plan's raw path), which would otherwise hide it.
        if let Some(s) = &by_speed {
            draw_speed_path(chart, s, u)?;
        }
        // Over the paths, dashed: a path that is the reference (an exact planner's) shows through.
        if let Some(r) = &fig.reference {
            draw_reference(chart, r, u)?;
        }
        draw_violated_waypoints(chart, paths, u)?;
        draw_obstacle_motion(chart, fig, u, SpeedLabels::All, &mut Vec::new())?;
        draw_mark_labels(chart, fig, u, &marks)?;
        time_ticks::draw_on_plan(chart, fig, u)?;
        draw_endpoints(chart, paths, fig.start, fig.goal, u)?;
        draw_focus(chart, fig, u)?;
        Ok(())
    })
}

/// A path's legend entries: its line with a waypoint dot; or, flown with a turning radius,
/// the flown curve and the waypoints apart.
pub(crate) fn path_entries(i: usize, p: &PlotPath) -> Vec<LegendEntry> {
    let color = style::path_color(i);
    if p.points.is_empty() {
        return vec![LegendEntry::new(format!("{} (no path)", p.label), Swatch::Path(color))];
    }
    match p.flown.filter(|f| f.points.len() >= 2) {
        None => vec![LegendEntry::new(&p.label, Swatch::Path(color))],
        Some(f) => vec![
            LegendEntry::new(
                format!("{}: flown, turns of radius {} m", p.label, style::fmt_sig(f.radius)),
                Swatch::Line { color: color.to_rgba(), width: 3 },
            ),
            LegendEntry::new(format!("{}: waypoints (corners cut)", p.label), Swatch::Waypoints(color)),
        ],
    }
}

/// Longest scale arrow in the legend (pixels): the longest current arrow is 0.8 of the arrow
/// spacing, about 45 pixels on the widest map.
const MAX_SCALE_ARROW_PX: i32 = 48;

/// What the map under the paths shows of the world: the seabed's shading or the waves', and
/// the current arrows.
struct Shown<'s> {
    seabed: Option<&'s Seabed>,
    waves: Option<&'s WaveMap>,
    quiver: Option<&'s Quiver>,
}

impl<'s> Shown<'s> {
    fn of(spec: &'s MapSpec) -> Self {
        Self { seabed: spec.seabed.as_ref(), waves: spec.waves.as_ref(), quiver: spec.quiver.as_ref() }
    }
}

fn legend_entries(
    fig: &PlanFigure,
    shown: &Shown,
    marks: bool,
    halos: bool,
    by_speed: Option<&SpeedPath>,
) -> Vec<LegendEntry> {
    let (world, paths) = (fig.world, fig.paths.as_slice());
    let mut out: Vec<LegendEntry> = Vec::new();
    for (i, p) in paths.iter().enumerate() {
        let mut entries = path_entries(i, p);
        // The coloured path's line (its first entry) says what its colours mean.
        if let (Some(s), Some(first)) = (by_speed.filter(|s| s.index == i), entries.first_mut()) {
            *first = s.legend_label(&first.label);
        }
        out.extend(entries);
    }
    if let Some(r) = &fig.reference {
        out.push(LegendEntry::new(&r.label, Swatch::DashedPath(style::REFERENCE)));
    }
    out.push(LegendEntry::new("start", Swatch::Marker(Marker::Triangle, style::START)));
    out.push(LegendEntry::new("goal", Swatch::Marker(Marker::Star, style::GOAL)));
    out.extend(time_ticks::legend(fig));
    out.extend(graph::legend_entries(fig));
    let (seg, way) = failure::kinds(paths);
    if !seg.is_empty() {
        out.push(LegendEntry::new(failure::legend_text("violated segment", &seg), Swatch::Band(style::WARN.mix(0.65))));
    }
    if !way.is_empty() {
        out.push(LegendEntry::new(failure::legend_text("violated waypoint", &way), Swatch::Ring(style::WARN)));
    }
    for f in &fig.focus {
        out.push(LegendEntry::new(&f.label, Swatch::Ring(style::WARN)));
    }
    let marks = marks.then_some("obstacle (dashed) and vehicle (◇) at the same time after departure");
    let when = time_varying(world).then(|| shown_at(fig));
    out.extend(world_legend(fig, shown, halos, marks, when));
    out
}

/// The legend entries of what a map shows of `fig.world` at `fig.time`: the obstacles' kinds,
/// their safety halo (when `halos`), moving obstacles' velocity and, when `marks` gives its
/// text, their time marks; the current's scale arrow (saying `when`, the instant shown, for a
/// time-varying world), the seabed's contours and the coastline, or the waves' land and gaps.
fn world_legend(
    fig: &PlanFigure,
    shown: &Shown,
    halos: bool,
    marks: Option<&str>,
    when: Option<String>,
) -> Vec<LegendEntry> {
    let world = fig.world;
    let mut out = Vec::new();
    let mut looks: Vec<ObstacleLook> = world
        .obstacles
        .iter()
        .map(|o| ObstacleLook::of(&o.shape))
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    looks.sort();
    for look in looks {
        out.push(LegendEntry::new(look.label(), Swatch::Obstacle(look)));
    }
    if !world.obstacles.is_empty() && halos {
        out.push(LegendEntry::new(
            format!("safety distance ({} m)", style::fmt_sig(fig.safety_distance)),
            Swatch::Dashed(style::OBSTACLE_EDGE.mix(0.7)),
        ));
    }
    if world.obstacles.iter().any(obstacles::is_moving) {
        out.push(LegendEntry::new("obstacle velocity", Swatch::Arrow(style::OBSTACLE_EDGE)));
        if let Some(marks) = marks {
            out.push(LegendEntry::new(marks, Swatch::Diamond(style::OBSTACLE_EDGE)));
        }
    }
    if let Some(q) = shown.quiver {
        let at = if world.dims == tidepath::world::Dims::Two {
            "current".to_string()
        } else {
            format!("current at z = {} m", style::fmt_num(q.z, 1.0))
        };
        let when = when.as_ref().map(|w| format!(", {w}")).unwrap_or_default();
        out.push(LegendEntry::new(
            format!(
                "{at}{when}: arrow = {} m/s (fastest {} m/s)",
                style::fmt_sig(scale_speed(q.max_speed)),
                style::fmt_sig(q.max_speed)
            ),
            Swatch::ScaledArrow { color: style::CURRENT, len_px: MAX_SCALE_ARROW_PX },
        ));
    }
    if let Some(m) = shown.waves {
        out.extend(m.legend());
    }
    if let Some(s) = shown.seabed {
        if !s.levels.is_empty() {
            out.push(LegendEntry::new(
                format!("elevation contours every {} m", style::fmt_sig(s.step)),
                Swatch::Line { color: style::CONTOUR.mix(1.6), width: 1 },
            ));
        }
        if s.has_land() {
            out.push(LegendEntry::new("coastline", Swatch::Line { color: style::COAST.to_rgba(), width: 2 }));
        }
    }
    out
}

/// [`world_legend`] of a map laid out by `spec`.
pub(crate) fn map_legend(
    fig: &PlanFigure,
    spec: &MapSpec,
    halos: bool,
    marks: Option<&str>,
    when: Option<String>,
) -> Vec<LegendEntry> {
    world_legend(fig, &Shown::of(spec), halos, marks, when)
}
