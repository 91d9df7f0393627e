//! Seabed shading and contours of the plan view, and the colour bar that explains the shading.

use std::collections::HashMap;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::super::contour::{contour_lines, Raster};
use super::super::style::{self, plot_err};
use super::Chart;
use tidepath::error::Result;
use tidepath::world::Terrain;

/// Raster cells across the view for shading and contours.
const RASTER_CELLS: usize = 120;

/// Seabed sampled over the view, with the derived contour levels.
pub(super) struct Seabed {
    pub(super) raster: Raster,
    pub(super) z_min: f64,
    pub(super) z_max: f64,
    pub(super) levels: Vec<f64>,
    pub(super) step: f64,
}

impl Seabed {
    pub(super) fn sample(terrain: &Terrain, x0: f64, y0: f64, x1: f64, y1: f64) -> Option<Self> {
        if matches!(terrain, Terrain::None) {
            return None;
        }
        let raster = Raster::sample(x0, y0, x1, y1, RASTER_CELLS + 1, RASTER_CELLS + 1, |x, y| terrain.elevation(x, y));
        let (z_min, z_max) = raster.finite_range()?;
        let (mut levels, step) = style::nice_levels(z_min, z_max, 8);
        // The zero level is drawn separately as the coastline.
        levels.retain(|v| v.abs() > step * 1e-9);
        Some(Self { raster, z_min, z_max, levels, step })
    }

    pub(super) fn has_land(&self) -> bool {
        self.z_max > 0.0 && self.z_min < 0.0
    }
}

/// A block of raster cells [i0, i1) x [j0, j1) of one colour.
type Block = (usize, usize, usize, usize, RGBColor);
/// A colour as a hashable key.
type Rgb = (u8, u8, u8);
/// A run of cells [i0, i1) of one colour within a row.
type Run = (usize, usize, Rgb);

/// Covers the raster with few rectangles: the most common colour becomes one background block
/// and the remaining cells merge into runs along rows, then into stacks of identical runs. This
/// keeps the SVG several times smaller than one `<rect>` per cell.
pub(super) fn seabed_blocks(s: &Seabed) -> Vec<Block> {
    let r = &s.raster;
    let (cx, cy) = (r.nx - 1, r.ny - 1);
    // Each cell takes the mean of its corners, which is what the contours see.
    let colors: Vec<RGBColor> = (0..cy)
        .flat_map(|j| (0..cx).map(move |i| (i, j)))
        .map(|(i, j)| {
            let z = 0.25 * (r.at(i, j) + r.at(i + 1, j) + r.at(i, j + 1) + r.at(i + 1, j + 1));
            if z.is_finite() {
                style::elevation_color(z, s.z_min, s.z_max)
            } else {
                style::NO_TERRAIN_BG
            }
        })
        .collect();
    let key = |c: RGBColor| -> Rgb { (c.0, c.1, c.2) };
    let mut counts: HashMap<Rgb, usize> = HashMap::new();
    for &c in &colors {
        *counts.entry(key(c)).or_default() += 1;
    }
    let background = colors.iter().copied().max_by_key(|&c| (counts[&key(c)], key(c))).unwrap_or(style::NO_TERRAIN_BG);
    let mut blocks: Vec<Block> = vec![(0, cx, 0, cy, background)];
    // Open stacks: run (i0, i1, colour) -> first row.
    let mut open: HashMap<Run, usize> = HashMap::new();
    for j in 0..=cy {
        let mut next = HashMap::new();
        if j < cy {
            let row = &colors[j * cx..(j + 1) * cx];
            let mut i0 = 0;
            for i in 1..=cx {
                if i == cx || row[i] != row[i0] {
                    if row[i0] != background {
                        let k = (i0, i, key(row[i0]));
                        next.insert(k, open.remove(&k).unwrap_or(j));
                    }
                    i0 = i;
                }
            }
        }
        let mut closed: Vec<_> = open.drain().collect();
        closed.sort_unstable();
        blocks.extend(closed.into_iter().map(|((i0, i1, (cr, cg, cb)), j0)| (i0, i1, j0, j, RGBColor(cr, cg, cb))));
        open = next;
    }
    blocks
}

pub(super) fn draw_seabed<DB: DrawingBackend>(chart: &Chart<DB>, s: &Seabed, u: f64) -> Result<()> {
    let r = &s.raster;
    let plot = chart.plotting_area();
    for (i0, i1, j0, j1, c) in seabed_blocks(s) {
        let a = ((r.x0 + r.dx * i0 as f64) / u, (r.y0 + r.dy * j0 as f64) / u);
        let b = ((r.x0 + r.dx * i1 as f64) / u, (r.y0 + r.dy * j1 as f64) / u);
        plot.draw(&Rectangle::new([a, b], style::fill(c))).map_err(plot_err)?;
    }

    let scaled = |line: Vec<(f64, f64)>| line.into_iter().map(|(x, y)| (x / u, y / u)).collect::<Vec<_>>();
    for &level in &s.levels {
        let lines = contour_lines(r, level);
        for l in lines {
            plot.draw(&PathElement::new(scaled(l), style::line(style::CONTOUR, 1))).map_err(plot_err)?;
        }
    }
    if s.has_land() {
        let lines = contour_lines(r, 0.0);
        for l in lines {
            plot.draw(&PathElement::new(scaled(l), style::line(style::COAST, 2))).map_err(plot_err)?;
        }
    }
    Ok(())
}

/// Labelled ticks of the colour bar: the contour levels, and the coastline level.
fn colorbar_ticks(s: &Seabed) -> Vec<f64> {
    if s.levels.is_empty() {
        // A (nearly) flat seabed has no contours; its extremes are all there is to say.
        let mut ends = vec![s.z_min, s.z_max];
        ends.dedup();
        return ends;
    }
    let mut ticks: Vec<f64> = s.levels.clone();
    if s.has_land() {
        ticks.push(0.0);
        ticks.sort_by(f64::total_cmp);
    }
    ticks
}

/// How many ticks to skip between labels so labels stay `min_gap` pixels apart on a bar of
/// `len` pixels.
fn label_every(s: &Seabed, len: f64, min_gap: f64) -> usize {
    let span = s.z_max - s.z_min;
    let px_per_step = if span > 0.0 { len * s.step / span } else { len };
    (min_gap / px_per_step).ceil().max(1.0) as usize
}

/// Pixel runs [k0, k1) of one colour along a colour bar `len` pixels long, where pixel k shows
/// the elevation `z_at((k + 0.5) / len)`; runs keep the bar to a few dozen SVG elements.
fn gradient_runs(len: u32, z_at: impl Fn(f64) -> f64, s: &Seabed) -> Vec<(i32, i32, RGBColor)> {
    let n = len.max(2) as i32;
    let mut runs: Vec<(i32, i32, RGBColor)> = Vec::new();
    for k in 0..n {
        let c = style::elevation_color(z_at((k as f64 + 0.5) / n as f64), s.z_min, s.z_max);
        match runs.last_mut() {
            Some(last) if last.2 == c => last.1 = k + 1,
            _ => runs.push((k, k + 1, c)),
        }
    }
    runs
}

/// Vertical colour bar of the seabed shading, labelled at the contour levels.
pub(super) fn draw_colorbar_vertical<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, s: &Seabed) -> Result<()> {
    let (_, h) = area.dim_in_pixel();
    let (bar_x0, bar_x1) = (0i32, 16i32);
    let span = s.z_max - s.z_min;
    let y_of = |z: f64| -> i32 {
        if span > 0.0 {
            ((s.z_max - z) / span * (h as f64 - 1.0)).round() as i32
        } else {
            h as i32 / 2
        }
    };
    for (k0, k1, c) in gradient_runs(h, |t| s.z_max - span * t, s) {
        area.draw(&Rectangle::new([(bar_x0, k0), (bar_x1, k1)], style::fill(c))).map_err(plot_err)?;
    }
    area.draw(&Rectangle::new([(bar_x0, 0), (bar_x1, h as i32 - 1)], style::line(BLACK, 1))).map_err(plot_err)?;
    let every = label_every(s, h as f64, 16.0);
    let label = style::font(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (k, &z) in colorbar_ticks(s).iter().enumerate() {
        let y = y_of(z);
        area.draw(&PathElement::new(vec![(bar_x0, y), (bar_x1 + 3, y)], style::line(BLACK.mix(0.7), 1)))
            .map_err(plot_err)?;
        if k % every == 0 || z == 0.0 {
            area.draw(&Text::new(style::fmt_num(z, s.step), (bar_x1 + 6, y), label.clone())).map_err(plot_err)?;
        }
    }
    let title =
        style::font(style::AXIS_DESC_PX).pos(Pos::new(HPos::Center, VPos::Center)).transform(FontTransform::Rotate270);
    area.draw(&Text::new("seabed elevation (m)", (bar_x1 + 70, h as i32 / 2), title)).map_err(plot_err)?;
    Ok(())
}

/// Horizontal colour bar `bar_w` pixels long with labels under it and its title to the right.
pub(super) fn draw_colorbar_horizontal<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    s: &Seabed,
    bar_w: u32,
) -> Result<()> {
    let (bar_y0, bar_y1) = (10i32, 24i32);
    let span = s.z_max - s.z_min;
    let x_of = |z: f64| -> i32 {
        if span > 0.0 {
            ((z - s.z_min) / span * (bar_w as f64 - 1.0)).round() as i32
        } else {
            bar_w as i32 / 2
        }
    };
    for (k0, k1, c) in gradient_runs(bar_w, |t| s.z_min + span * t, s) {
        area.draw(&Rectangle::new([(k0, bar_y0), (k1, bar_y1)], style::fill(c))).map_err(plot_err)?;
    }
    area.draw(&Rectangle::new([(0, bar_y0), (bar_w as i32 - 1, bar_y1)], style::line(BLACK, 1))).map_err(plot_err)?;
    let ticks = colorbar_ticks(s);
    let widest = ticks.iter().map(|&z| style::fmt_num(z, s.step).len()).max().unwrap_or(1);
    let every = label_every(s, bar_w as f64, style::text_width(&"0".repeat(widest), style::TICK_PX) + 10.0);
    let label = style::font(style::TICK_PX).pos(Pos::new(HPos::Center, VPos::Top));
    for (k, &z) in ticks.iter().enumerate() {
        let x = x_of(z);
        area.draw(&PathElement::new(vec![(x, bar_y0), (x, bar_y1 + 3)], style::line(BLACK.mix(0.7), 1)))
            .map_err(plot_err)?;
        if k % every == 0 || z == 0.0 {
            area.draw(&Text::new(style::fmt_num(z, s.step), (x, bar_y1 + 5), label.clone())).map_err(plot_err)?;
        }
    }
    let title = style::font(style::AXIS_DESC_PX).pos(Pos::new(HPos::Left, VPos::Center));
    area.draw(&Text::new("seabed elevation (m)", (bar_w as i32 + 14, (bar_y0 + bar_y1) / 2), title))
        .map_err(plot_err)?;
    Ok(())
}
