//! Seabed shading and contours of the plan view, and the colour bar that explains the shading.

use std::collections::HashMap;

use plotters::prelude::*;

use super::super::contour::{contour_lines, Raster};
use super::super::style::{self, plot_err};
use super::colorbar::ColourBar;
use super::Chart;
use tidepath::error::Result;
use tidepath::world::Terrain;

/// Raster cells across the view for shading and contours.
pub(super) const RASTER_CELLS: usize = 120;

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
pub(super) type Block = (usize, usize, usize, usize, RGBColor);
/// A colour as a hashable key.
type Rgb = (u8, u8, u8);
/// A run of cells [i0, i1) of one colour within a row.
type Run = (usize, usize, Rgb);

/// The colour of each raster cell of the shading: the mean of its corners, which is what the
/// contours see.
fn cell_colours(s: &Seabed) -> Vec<RGBColor> {
    let r = &s.raster;
    let (cx, cy) = (r.nx - 1, r.ny - 1);
    (0..cy)
        .flat_map(|j| (0..cx).map(move |i| (i, j)))
        .map(|(i, j)| {
            let z = 0.25 * (r.at(i, j) + r.at(i + 1, j) + r.at(i, j + 1) + r.at(i + 1, j + 1));
            if z.is_finite() {
                style::elevation_color(z, s.z_min, s.z_max)
            } else {
                style::NO_TERRAIN_BG
            }
        })
        .collect()
}

/// The seabed's shading as blocks of one colour ([`colour_blocks`]).
pub(super) fn seabed_blocks(s: &Seabed) -> Vec<Block> {
    colour_blocks(&cell_colours(s), s.raster.nx - 1, s.raster.ny - 1)
}

/// Covers a grid of `cx` x `cy` cells coloured `colors` (row-major, south row first) with few
/// rectangles: the most common colour becomes one background block and the remaining cells
/// merge into runs along rows, then into stacks of identical runs. This keeps the SVG several
/// times smaller than one `<rect>` per cell. Shared by every shaded map (seabed, waves).
pub(super) fn colour_blocks(colors: &[RGBColor], cx: usize, cy: usize) -> Vec<Block> {
    let key = |c: RGBColor| -> Rgb { (c.0, c.1, c.2) };
    let mut counts: HashMap<Rgb, usize> = HashMap::new();
    for &c in colors {
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

/// Draws `blocks` of raster cells, cell (i, j) spanning [x0 + i dx, x0 + (i + 1) dx] x
/// [y0 + j dy, y0 + (j + 1) dy] metres, on a chart in units of `u` metres.
pub(super) fn draw_blocks<DB: DrawingBackend>(
    chart: &Chart<DB>,
    blocks: &[Block],
    (x0, y0, dx, dy): (f64, f64, f64, f64),
    u: f64,
) -> Result<()> {
    let plot = chart.plotting_area();
    for &(i0, i1, j0, j1, c) in blocks {
        let a = ((x0 + dx * i0 as f64) / u, (y0 + dy * j0 as f64) / u);
        let b = ((x0 + dx * i1 as f64) / u, (y0 + dy * j1 as f64) / u);
        plot.draw(&Rectangle::new([a, b], style::fill(c))).map_err(plot_err)?;
    }
    Ok(())
}

pub(super) fn draw_seabed<DB: DrawingBackend>(chart: &Chart<DB>, s: &Seabed, u: f64) -> Result<()> {
    let r = &s.raster;
    draw_blocks(chart, &seabed_blocks(s), (r.x0, r.y0, r.dx, r.dy), u)?;
    let plot = chart.plotting_area();

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

impl Seabed {
    /// The colour bar of the shading, labelled at the contour levels and the coastline.
    pub(super) fn colour_bar(&self) -> ColourBar {
        let (z_min, z_max) = (self.z_min, self.z_max);
        ColourBar {
            title: "seabed elevation (m)".to_string(),
            lo: z_min,
            hi: z_max,
            step: self.step,
            ticks: colorbar_ticks(self),
            always: Some(0.0),
            mark: None,
            colour: Box::new(move |z| style::elevation_color(z, z_min, z_max)),
        }
    }
}
