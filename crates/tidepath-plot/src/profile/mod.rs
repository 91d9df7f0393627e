//! The vertical profile: each path's z against horizontal distance along it, over the seabed
//! beneath it.
//!
//! Distance is horizontal (along-track) so the seabed appears undistorted, as on a chart
//! section; a steep climb then shows up as a steep line, which is what a reader looks for.
//! A path flown with a turning radius is measured along its flown curve, which is the line
//! drawn; its waypoints are small markers on a thin dashed line, each where the vehicle is
//! nearest it (the middle of its turn).

use plotters::coord::Shift;
use plotters::prelude::*;

mod sections;

use super::flown::Drawn;
use super::style::{self, plot_err, LegendEntry, LengthUnit, Marker, Swatch};
use super::{failure, PlanFigure, PlotPath};
use tidepath::error::Result;
use tidepath::geom::Vec3;
use tidepath::world::Terrain;

/// Seabed samples along the longest path.
const SEABED_SAMPLES: usize = 400;

/// Horizontal distance (m) of every point of `points` from the first, along the path.
fn along_track(points: &[Vec3]) -> Vec<f64> {
    let mut s = 0.0;
    let mut out = Vec::with_capacity(points.len());
    for (k, p) in points.iter().enumerate() {
        if k > 0 {
            let d = (p.truncate() - points[k - 1].truncate()).length();
            if d.is_finite() {
                s += d;
            }
        }
        out.push(s);
    }
    out
}

/// (distance, elevation) of the seabed under `points`, sampled about every `ds` metres and at
/// every waypoint so sharp turns over steep ground are not smoothed away.
fn seabed_under(terrain: &Terrain, points: &[Vec3], dist: &[f64], ds: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for k in 0..points.len() {
        if k + 1 == points.len() || dist[k + 1] <= dist[k] {
            out.push((dist[k], terrain.elevation(points[k].x, points[k].y)));
            continue;
        }
        let n = ((dist[k + 1] - dist[k]) / ds).ceil().max(1.0) as usize;
        for m in 0..n {
            let t = m as f64 / n as f64;
            let p = points[k].lerp(points[k + 1], t);
            out.push((dist[k] + t * (dist[k + 1] - dist[k]), terrain.elevation(p.x, p.y)));
        }
    }
    out.retain(|(s, z)| s.is_finite() && z.is_finite());
    out
}

/// Draws the vertical profile of `fig`'s paths (colours as in the plan view) with the seabed
/// under the first path filled and the seabed under the others dashed, the obstacles the first
/// path's vertical section cuts, and the violated segments and waypoints. With no path to
/// draw (an invalid start, an unreachable goal) it shows the section along the straight line
/// from start to goal, with the start and goal, so the seabed a failure is about is there.
pub fn draw_profile<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, fig: &PlanFigure) -> Result<()> {
    let world = fig.world;
    let straight = [fig.start, fig.goal];
    let no_path = !fig.paths.iter().any(|p| p.points.len() >= 2);
    let section_only = [PlotPath::new("straight line start → goal (no path)", &straight)];
    let paths: &[PlotPath] = if no_path { &section_only } else { &fig.paths };
    let b = world.bounds;
    let unit = LengthUnit::for_extent((b.max.x - b.min.x).max(b.max.y - b.min.y));
    let u = unit.metres;
    let has_terrain = !matches!(world.terrain, Terrain::None);
    // The line of each path (its flown curve when it has one) and the distance along it.
    let drawn: Vec<Drawn> = paths.iter().map(Drawn::of).collect();
    let tracks: Vec<Vec<f64>> = drawn.iter().map(|d| along_track(d.line)).collect();
    let longest = tracks.iter().filter_map(|t| t.last().copied()).fold(0.0, f64::max);
    let ds = (longest / SEABED_SAMPLES as f64).max(1e-6);
    let seabeds: Vec<Vec<(f64, f64)>> = if has_terrain {
        drawn.iter().zip(&tracks).map(|(d, t)| seabed_under(&world.terrain, d.line, t, ds)).collect()
    } else {
        vec![Vec::new(); paths.len()]
    };

    // Vertical range: the domain's water column, stretched to hold every path point and, in a
    // 2-D world (where the column is flat), the seabed under the paths: there the profile is
    // the depth of water under the keel.
    let (mut lo, mut hi) = (b.min.z, b.max.z);
    for z in paths.iter().flat_map(|p| p.points.iter().map(|q| q.z)).filter(|z| z.is_finite()) {
        lo = lo.min(z);
        hi = hi.max(z);
    }
    if world.dims == tidepath::world::Dims::Two {
        for &(_, z) in seabeds.iter().flatten().filter(|(_, z)| z.is_finite()) {
            lo = lo.min(z);
        }
    }
    if !(lo.is_finite() && hi.is_finite()) {
        (lo, hi) = (-1.0, 0.0);
    }
    let pad = ((hi - lo) * 0.03).max(1.0);
    let (lo, hi) = if hi - lo < 2.0 { (lo - 10.0, hi + 10.0) } else { (lo, hi + pad) };
    let x_max = if longest > 0.0 { longest / u } else { (b.max.x - b.min.x).max(1.0) * 0.05 / u };

    // Obstacles cut by the first path's vertical section, where the vehicle was when there.
    let first = &paths[0];
    let cut: Vec<Vec<(f64, f64)>> = {
        let s = sections::samples(drawn[0].line, &tracks[0], drawn[0].times, fig.time, ds);
        world.obstacles.iter().flat_map(|o| sections::obstacle_sections(o, &s, lo, hi)).collect()
    };

    let mut legend: Vec<LegendEntry> = if no_path {
        vec![
            LegendEntry::new("start", Swatch::Marker(Marker::Triangle, style::START)),
            LegendEntry::new("goal", Swatch::Marker(Marker::Star, style::GOAL)),
        ]
    } else {
        paths.iter().enumerate().flat_map(|(i, p)| super::plan_view::path_entries(i, p)).collect()
    };
    let first_seabed = seabeds.iter().position(|s| s.len() >= 2);
    if let Some(k) = first_seabed {
        let label = if no_path {
            "seabed along the straight line start → goal".to_string()
        } else if paths.len() > 1 {
            format!("seabed under {}", paths[k].label)
        } else {
            "seabed".to_string()
        };
        legend.push(LegendEntry::new(
            label,
            Swatch::Fill { color: style::SEABED.to_rgba(), edge: Some(style::SEABED_LINE) },
        ));
        if seabeds.iter().filter(|s| s.len() >= 2).count() > 1 {
            legend.push(LegendEntry::new("seabed under others", Swatch::Dashed(style::MUTED.to_rgba())));
        }
        if fig.safety_distance > 0.0 {
            legend.push(LegendEntry::new(
                format!("seabed + safety distance ({} m)", style::fmt_sig(fig.safety_distance)),
                Swatch::Dashed(style::SEABED_LINE.to_rgba()),
            ));
        }
    }
    if !cut.is_empty() {
        let what = if paths.len() > 1 {
            format!("obstacle cut by the section under {}", first.label)
        } else {
            "obstacle cut by the section".into()
        };
        legend.push(LegendEntry::new(
            what,
            Swatch::Fill { color: style::OBSTACLE_FILL, edge: Some(style::OBSTACLE_EDGE) },
        ));
    }
    let (seg, way) = failure::kinds(paths);
    if !seg.is_empty() {
        legend.push(LegendEntry::new(
            failure::legend_text("violated segment", &seg),
            Swatch::Band(style::WARN.mix(0.65)),
        ));
    }
    if !way.is_empty() {
        legend.push(LegendEntry::new(failure::legend_text("violated waypoint", &way), Swatch::Ring(style::WARN)));
    }
    // A focus at the start or goal is marked on the section; others are off it.
    let end_focus: Vec<(f64, f64, &str)> = fig
        .focus
        .iter()
        .filter_map(|f| {
            let at = |p: Vec3| (f.at.truncate() - p.truncate()).length() < 1e-6 * (1.0 + p.truncate().length());
            let s = if at(fig.start) {
                0.0
            } else if no_path && at(fig.goal) {
                longest
            } else {
                return None;
            };
            Some((s / u, f.at.z, f.label.as_str()))
        })
        .collect();
    for &(_, _, label) in &end_focus {
        legend.push(LegendEntry::new(label, Swatch::Ring(style::WARN)));
    }
    let surface = lo < 0.0 && hi > 0.0;
    if surface {
        legend.push(LegendEntry::new("sea surface", Swatch::Dashed(style::SURFACE.to_rgba())));
    }

    let body = style::caption(area, "Vertical profile")?;
    let (w, _) = body.dim_in_pixel();
    let legend_h = style::legend_height(&legend, w.saturating_sub(70));
    let (legend_area, chart_area) = body.split_vertically(legend_h);
    style::draw_legend(&legend_area.margin(0, 0, 70, 0), &legend)?;

    // A little room beyond both ends, so the start and goal marks are not cut by the frame.
    let x_pad = 0.015 * x_max;
    let ticks_x = style::tick_formatter(0.0..x_max, 8);
    let ticks_y = style::tick_formatter(lo..hi, 7);
    let y_label_w = style::y_label_area(lo..hi, 7, &ticks_y);
    let mut chart = ChartBuilder::on(&chart_area)
        .margin_right(18)
        .margin_top(6)
        .x_label_area_size(46)
        .y_label_area_size(y_label_w)
        .build_cartesian_2d(-x_pad..x_max + x_pad, lo..hi)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(style::GRID)
        .x_labels(8)
        .y_labels(7)
        .x_desc(match (drawn.iter().any(|d| d.flown), drawn.iter().all(|d| d.flown || d.line.len() < 2)) {
            (true, true) => format!("horizontal distance along the flown path ({})", unit.name),
            // A smoothed plan's raw path beside its flown curve.
            (true, false) => format!("horizontal distance along path or flown curve ({})", unit.name),
            _ => format!("horizontal distance along path ({})", unit.name),
        })
        .y_desc("z (m, 0 = sea surface)")
        .x_label_formatter(&ticks_x)
        .y_label_formatter(&ticks_y)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;

    let clamp = |(s, z): (f64, f64)| (s / u, z.clamp(lo, hi));
    for poly in &cut {
        let pts: Vec<(f64, f64)> = poly.iter().copied().map(clamp).collect();
        chart
            .draw_series(std::iter::once(Polygon::new(pts.clone(), style::fill(style::OBSTACLE_FILL))))
            .map_err(plot_err)?;
        let mut outline = pts;
        outline.push(outline[0]);
        chart
            .draw_series(std::iter::once(PathElement::new(outline, style::line(style::OBSTACLE_EDGE, 1))))
            .map_err(plot_err)?;
    }
    for (k, seabed) in seabeds.iter().enumerate().filter(|(_, s)| s.len() >= 2) {
        let pts: Vec<(f64, f64)> = seabed.iter().copied().map(clamp).collect();
        if Some(k) == first_seabed {
            chart
                .draw_series(
                    AreaSeries::new(pts, lo, style::fill(style::SEABED))
                        .border_style(style::line(style::SEABED_LINE, 1)),
                )
                .map_err(plot_err)?;
            if fig.safety_distance > 0.0 {
                let above: Vec<(f64, f64)> =
                    seabed.iter().map(|&(s, z)| (s, z + fig.safety_distance)).map(clamp).collect();
                chart
                    .draw_series(DashedLineSeries::new(above, 5, 4, style::line(style::SEABED_LINE, 1)))
                    .map_err(plot_err)?;
            }
        } else {
            chart
                .draw_series(DashedLineSeries::new(pts, 6, 4, style::line(style::path_color(k).mix(0.8), 1)))
                .map_err(plot_err)?;
        }
    }
    if surface {
        chart
            .draw_series(DashedLineSeries::new(vec![(0.0, 0.0), (x_max, 0.0)], 8, 5, style::line(style::SURFACE, 1)))
            .map_err(plot_err)?;
    }
    // (distance, z) of point j of a path's line, and of waypoint i where the vehicle is
    // nearest it.
    let on_line = |track: &[f64], d: &Drawn, j: usize| -> Option<(f64, f64)> {
        let (s, q) = (track.get(j)?, d.line.get(j)?);
        (s.is_finite() && q.z.is_finite()).then(|| (s / u, q.z.clamp(lo, hi)))
    };
    let at_waypoint = |track: &[f64], d: &Drawn, p: &PlotPath, i: usize| -> Option<(f64, f64)> {
        let (s, q) = (track.get(d.waypoint(i)?)?, p.points.get(i)?);
        (s.is_finite() && q.z.is_finite()).then(|| (s / u, q.z.clamp(lo, hi)))
    };
    for ((p, d), track) in paths.iter().zip(&drawn).zip(&tracks) {
        for v in p.violations.iter().filter(|v| failure::on_segment(v.kind)) {
            let Some(range) = d.segment(v.index) else { continue };
            let band: Vec<(f64, f64)> = range.filter_map(|j| on_line(track, d, j)).collect();
            if band.len() >= 2 {
                chart
                    .draw_series(std::iter::once(PathElement::new(band, style::line(style::WARN.mix(0.65), 12))))
                    .map_err(plot_err)?;
            }
        }
    }
    if !no_path {
        // Flown curves over the other paths, as on the plan view.
        let mut order: Vec<usize> = (0..paths.len()).collect();
        order.sort_by_key(|&i| drawn[i].flown);
        for i in order {
            let (p, d, track) = (&paths[i], &drawn[i], &tracks[i]);
            let color = style::path_color(i);
            let pts: Vec<(f64, f64)> = (0..d.line.len()).filter_map(|j| on_line(track, d, j)).collect();
            if !d.flown {
                if pts.len() >= 2 {
                    chart.draw_series(LineSeries::new(pts.clone(), style::line(color, 2))).map_err(plot_err)?;
                }
                chart.draw_series(pts.iter().map(|&q| Circle::new(q, 3, style::fill(color)))).map_err(plot_err)?;
                continue;
            }
            // The waypoints on a thin dashed line beneath the flown curve, as on the plan view.
            let marks: Vec<(f64, f64)> = (0..p.points.len()).filter_map(|k| at_waypoint(track, d, p, k)).collect();
            if marks.len() >= 2 {
                chart
                    .draw_series(DashedLineSeries::new(marks.clone(), 5, 4, style::line(color, 1)))
                    .map_err(plot_err)?;
            }
            if pts.len() >= 2 {
                chart.draw_series(LineSeries::new(pts, style::line(color, 2))).map_err(plot_err)?;
            }
            // Rings at least a few pixels apart: a tangent polygon's waypoints are dense.
            let px: Vec<(i32, i32)> = marks.iter().map(|q| chart.backend_coord(q)).collect();
            let rings: Vec<(f64, f64)> = marks
                .iter()
                .zip(style::spaced_marks(&px, style::MARK_SPACING_PX))
                .filter_map(|(&q, keep)| keep.then_some(q))
                .collect();
            chart.draw_series(rings.iter().map(|&q| Circle::new(q, 3, style::fill(WHITE)))).map_err(plot_err)?;
            chart.draw_series(rings.iter().map(|&q| Circle::new(q, 3, style::line(color, 1)))).map_err(plot_err)?;
        }
    }
    super::plan_view::time_ticks::draw_on_profile(&chart, fig, paths, &tracks, u, (lo, hi))?;
    for ((p, d), track) in paths.iter().zip(&drawn).zip(&tracks) {
        for v in p.violations.iter().filter(|v| !failure::on_segment(v.kind)) {
            if let Some(q) = at_waypoint(track, d, p, v.index) {
                chart.draw_series(std::iter::once(Circle::new(q, 9, style::line(style::WARN, 2)))).map_err(plot_err)?;
            }
        }
    }
    let px = chart.plotting_area().strip_coord_spec();
    let base = chart.plotting_area().get_base_pixel();
    let to_px = |x: f64, z: f64| {
        let (a, b) = chart.backend_coord(&(x, z.clamp(lo, hi)));
        (a - base.0, b - base.1)
    };
    if no_path {
        style::draw_marker(&px, to_px(0.0, fig.start.z), Marker::Triangle, style::START)?;
        style::draw_marker(&px, to_px(x_max, fig.goal.z), Marker::Star, style::GOAL)?;
    }
    for &(s, z, _) in &end_focus {
        px.draw(&Circle::new(to_px(s, z), 14, style::line(style::WARN, 3))).map_err(plot_err)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn along_track_ignores_depth_changes() {
        let pts = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(3.0, 4.0, -100.0), Vec3::new(3.0, 4.0, -50.0)];
        assert_eq!(along_track(&pts), vec![0.0, 5.0, 5.0]);
    }
}
