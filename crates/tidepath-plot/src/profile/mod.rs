//! The vertical profile: each path's z against horizontal distance along it, over the seabed
//! beneath it.
//!
//! Distance is horizontal (along-track) so the seabed appears undistorted, as on a chart
//! section; a steep climb then shows up as a steep line, which is what a reader looks for.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::style::{self, plot_err, LegendEntry, LengthUnit, Swatch};
use super::PlotPath;
use tidepath::error::Result;
use tidepath::geom::Vec3;
use tidepath::world::{Terrain, World};

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

/// Draws the vertical profile of `paths` (colours as in the plan view) with the seabed under
/// the first path filled and the seabed under the others dashed.
pub fn draw_profile<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    world: &World,
    paths: &[PlotPath],
) -> Result<()> {
    let b = world.bounds;
    let unit = LengthUnit::for_extent((b.max.x - b.min.x).max(b.max.y - b.min.y));
    let u = unit.metres;
    let has_terrain = !matches!(world.terrain, Terrain::None);
    let tracks: Vec<Vec<f64>> = paths.iter().map(|p| along_track(p.points)).collect();
    let longest = tracks.iter().filter_map(|t| t.last().copied()).fold(0.0, f64::max);
    let ds = (longest / SEABED_SAMPLES as f64).max(1e-6);
    let seabeds: Vec<Vec<(f64, f64)>> = if has_terrain {
        paths.iter().zip(&tracks).map(|(p, t)| seabed_under(&world.terrain, p.points, t, ds)).collect()
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

    let mut legend: Vec<LegendEntry> =
        paths.iter().enumerate().map(|(i, p)| LegendEntry::new(&p.label, Swatch::Path(style::path_color(i)))).collect();
    let first_seabed = seabeds.iter().position(|s| s.len() >= 2);
    if let Some(k) = first_seabed {
        let label = if paths.len() > 1 { format!("seabed under {}", paths[k].label) } else { "seabed".to_string() };
        legend.push(LegendEntry::new(
            label,
            Swatch::Fill { color: style::SEABED.to_rgba(), edge: Some(style::SEABED_LINE) },
        ));
        if seabeds.iter().filter(|s| s.len() >= 2).count() > 1 {
            legend.push(LegendEntry::new("seabed under others", Swatch::Dashed(style::MUTED.to_rgba())));
        }
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

    let mut chart = ChartBuilder::on(&chart_area)
        .margin_right(18)
        .margin_top(6)
        .x_label_area_size(46)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..x_max, lo..hi)
        .map_err(plot_err)?;
    let ticks_x = style::tick_formatter(0.0..x_max, 8);
    let ticks_y = style::tick_formatter(lo..hi, 7);
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(style::GRID)
        .x_labels(8)
        .y_labels(7)
        .x_desc(format!("horizontal distance along path ({})", unit.name))
        .y_desc("z (m, 0 = sea surface)")
        .x_label_formatter(&ticks_x)
        .y_label_formatter(&ticks_y)
        .label_style(style::font(style::TICK_PX))
        .axis_desc_style(style::font(style::AXIS_DESC_PX))
        .draw()
        .map_err(plot_err)?;

    let clamp = |(s, z): (f64, f64)| (s / u, z.clamp(lo, hi));
    for (k, seabed) in seabeds.iter().enumerate().filter(|(_, s)| s.len() >= 2) {
        let pts: Vec<(f64, f64)> = seabed.iter().copied().map(clamp).collect();
        if Some(k) == first_seabed {
            chart
                .draw_series(
                    AreaSeries::new(pts, lo, style::fill(style::SEABED))
                        .border_style(style::line(style::SEABED_LINE, 1)),
                )
                .map_err(plot_err)?;
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
    for (i, (p, track)) in paths.iter().zip(&tracks).enumerate() {
        let color = style::path_color(i);
        let pts: Vec<(f64, f64)> = track
            .iter()
            .zip(p.points)
            .filter(|(s, q)| s.is_finite() && q.z.is_finite())
            .map(|(s, q)| (s / u, q.z.clamp(lo, hi)))
            .collect();
        if pts.len() >= 2 {
            chart.draw_series(LineSeries::new(pts.clone(), style::line(color, 2))).map_err(plot_err)?;
        }
        chart.draw_series(pts.iter().map(|&q| Circle::new(q, 3, style::fill(color)))).map_err(plot_err)?;
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
