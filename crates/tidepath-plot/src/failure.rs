//! What went wrong, in words the plan view and the profile share: which violations are about
//! a segment and which about a waypoint, their short names, and what lies at the place a
//! failure is about (the seabed under it, the obstacles it is in).

use tidepath::path::ViolationKind;
use tidepath::planner::Focus;
use tidepath::world::Terrain;

use super::{style, PlanFigure, PlotPath};

/// Whether a violation's index is a segment's (joining waypoints i and i + 1) rather than a
/// waypoint's.
pub fn on_segment(kind: ViolationKind) -> bool {
    matches!(
        kind,
        ViolationKind::Terrain
            | ViolationKind::Obstacle
            | ViolationKind::Current
            | ViolationKind::Pitch
            | ViolationKind::Separation
    )
}

/// A violation kind in a word or two, for legends.
pub fn short_name(kind: ViolationKind) -> &'static str {
    match kind {
        ViolationKind::Terrain => "seabed or land",
        ViolationKind::Obstacle => "obstacle",
        ViolationKind::Current => "current",
        ViolationKind::Pitch => "pitch",
        ViolationKind::Bounds => "outside the domain",
        ViolationKind::Depth => "depth band",
        ViolationKind::Turn => "turn",
        ViolationKind::Endpoint => "misses start or goal",
        ViolationKind::Separation => "too close to another vehicle",
        ViolationKind::Arrival => "fleet arrival",
    }
}

/// The distinct kinds of the paths' violations, segment kinds and waypoint kinds apart, each
/// in the order first met.
pub fn kinds(paths: &[PlotPath]) -> (Vec<ViolationKind>, Vec<ViolationKind>) {
    let (mut seg, mut way) = (Vec::new(), Vec::new());
    for v in paths.iter().flat_map(|p| p.violations) {
        let list = if on_segment(v.kind) { &mut seg } else { &mut way };
        if !list.contains(&v.kind) {
            list.push(v.kind);
        }
    }
    (seg, way)
}

/// Legend text for a list of kinds: "violated segment: obstacle, seabed or land".
pub fn legend_text(what: &str, kinds: &[ViolationKind]) -> String {
    format!("{what}: {}", kinds.iter().map(|k| short_name(*k)).collect::<Vec<_>>().join(", "))
}

/// Obstacles within the safety distance of a focus at the figure's time (inside, or too
/// close): the obstacles an invalid start or goal is in.
pub fn obstacles_at(fig: &PlanFigure, f: &Focus) -> Vec<usize> {
    let margin = fig.safety_distance.max(0.0);
    (0..fig.world.obstacles.len())
        .filter(|&k| {
            let d = fig.world.obstacles[k].shape_at(fig.time).distance_to_point(f.at);
            d <= margin
        })
        .collect()
}

/// What lies at a focus on the start or goal, in a few words per fact: "z = -5 m",
/// "seabed at -31 m (31 m of water)", "land 12 m high", "in obstacle 2 (sphere)", "14 m from
/// obstacle 0 (box)". Nothing for other places (a bottleneck): their reason states the depth
/// the check found on its raster, which the seabed at one point need not equal.
pub fn what_is_there(fig: &PlanFigure, f: &Focus) -> Vec<String> {
    let mut out = Vec::new();
    if f.at != fig.start && f.at != fig.goal {
        return out;
    }
    if fig.world.dims == tidepath::world::Dims::Three {
        out.push(format!("z = {} m", style::fmt_num(f.at.z, 1.0)));
    }
    if !matches!(fig.world.terrain, Terrain::None) {
        let z = fig.world.terrain.elevation(f.at.x, f.at.y);
        if z > 0.0 {
            out.push(format!("land {} m high", style::fmt_num(z, 1.0)));
        } else if z.is_finite() {
            out.push(format!("seabed at {} m ({} m of water)", style::fmt_num(z, 1.0), style::fmt_num(-z, 1.0)));
        }
    }
    for k in obstacles_at(fig, f) {
        let shape = fig.world.obstacles[k].shape_at(fig.time);
        let kind = super::obstacle_look::ObstacleLook::of(&shape).label();
        let kind = kind.split(" (").next().unwrap_or(kind);
        let d = shape.distance_to_point(f.at);
        if d > 0.0 {
            out.push(format!("{} m from obstacle {k} ({kind})", style::fmt_sig(d)));
        } else {
            out.push(format!("in obstacle {k} ({kind})"));
        }
    }
    out
}
