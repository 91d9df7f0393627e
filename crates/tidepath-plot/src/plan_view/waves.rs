//! The sea state on the plan view: the significant wave height as a colour map, which is what
//! drives acopf2016's wave glider (its speed over ground grows with the height, eqs. 1-2), with
//! its colour bar. Land (seabed above the sea surface, or above a 2-D world's travel plane: a
//! cells map's `#` cells) is drawn over it in one colour, places without wave data (land or fill
//! in a forecast file) in grey. With waves the map shows them in place of the seabed's depths.

use plotters::prelude::*;

use super::super::style::{self, LegendEntry, Swatch};
use super::colorbar::ColourBar;
use super::seabed::{colour_blocks, draw_blocks, RASTER_CELLS};
use super::speed::bar_ticks;
use super::Chart;
use tidepath::error::Result;
use tidepath::geom::{Aabb, Vec3};
use tidepath::world::{Dims, World};

/// Land over the wave colours: the seabed's tan, which no wave colour comes near.
pub(crate) const LAND: RGBColor = style::SEABED;
/// Places without wave data.
pub(crate) const NO_DATA: RGBColor = RGBColor(200, 200, 200);

/// What one raster cell shows.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Cell {
    Height(f64),
    Land,
    NoData,
}

/// The wave height sampled at the centres of a raster of cells over the view.
pub(crate) struct WaveMap {
    /// Cell (i, j) at `cells[j * cx + i]`, south row first.
    cells: Vec<Cell>,
    cx: usize,
    cy: usize,
    /// South-west corner and size of a cell (m).
    x0: f64,
    y0: f64,
    dx: f64,
    dy: f64,
    /// The colour scale: the smallest and largest height of the field over the view at any
    /// time (`Waves::range_hint`), so maps at different times compare.
    pub(crate) lo: f64,
    pub(crate) hi: f64,
}

impl WaveMap {
    /// The map of `world`'s waves over `view` at `time`; `None` in a world without waves.
    pub(crate) fn sample(world: &World, (x0, y0, x1, y1): (f64, f64, f64, f64), time: f64) -> Option<Self> {
        if world.waves.is_none() {
            return None;
        }
        // Land is seabed above the sea surface; in a 2-D world, above the plane it travels in.
        let top = match world.dims {
            Dims::Two => world.bounds.max.z.min(0.0),
            Dims::Three => 0.0,
        };
        let (cx, cy) = (RASTER_CELLS, RASTER_CELLS);
        let (dx, dy) = ((x1 - x0) / cx as f64, (y1 - y0) / cy as f64);
        let mut cells = Vec::with_capacity(cx * cy);
        for j in 0..cy {
            for i in 0..cx {
                let (x, y) = (x0 + dx * (i as f64 + 0.5), y0 + dy * (j as f64 + 0.5));
                let p = Vec3::new(x, y, top);
                cells.push(if world.terrain.elevation(x, y) > top {
                    Cell::Land
                } else if !world.waves.has_data(p) {
                    Cell::NoData
                } else {
                    Cell::Height(world.waves.height(p, time))
                });
            }
        }
        let bounds = Aabb::new(Vec3::new(x0, y0, top), Vec3::new(x1, y1, top));
        let (lo, hi) = world.waves.range_hint(&bounds);
        Some(Self { cells, cx, cy, x0, y0, dx, dy, lo, hi })
    }

    pub(crate) fn color(&self, h: f64) -> RGBColor {
        style::wave_color(h, self.lo, self.hi)
    }

    fn has(&self, kind: Cell) -> bool {
        self.cells.contains(&kind)
    }

    /// The colour bar of the map, labelled at round heights, its ends too when they are
    /// round (a field of 0.5 to 2 m reads "0.5 1.0 1.5 2.0"); at its ends when the range holds
    /// fewer than two round heights.
    pub(crate) fn colour_bar(&self) -> ColourBar {
        let (lo, hi) = (self.lo, self.hi);
        let (mut ticks, step) = bar_ticks(lo, hi);
        let round = |v: f64| ((v / step).round() * step - v).abs() <= 1e-9 * step;
        if ticks.len() >= 2 && !ticks.contains(&lo) {
            ticks.extend([lo, hi].into_iter().filter(|&v| round(v)));
            ticks.sort_by(f64::total_cmp);
        }
        ColourBar {
            title: "significant wave height (m)".to_string(),
            lo,
            hi,
            step,
            ticks,
            always: None,
            mark: None,
            colour: Box::new(move |h| style::wave_color(h, lo, hi)),
        }
    }

    /// Legend entries for what the colour bar does not explain: land and places without data.
    pub(crate) fn legend(&self) -> Vec<LegendEntry> {
        let mut out = Vec::new();
        if self.has(Cell::Land) {
            out.push(LegendEntry::new("land", Swatch::Fill { color: LAND.to_rgba(), edge: None }));
        }
        if self.has(Cell::NoData) {
            out.push(LegendEntry::new(
                "no wave data",
                Swatch::Fill { color: NO_DATA.to_rgba(), edge: Some(style::MUTED) },
            ));
        }
        out
    }
}

pub(crate) fn draw_waves<DB: DrawingBackend>(chart: &Chart<DB>, m: &WaveMap, u: f64) -> Result<()> {
    let colors: Vec<RGBColor> = m
        .cells
        .iter()
        .map(|c| match *c {
            Cell::Height(h) => m.color(h),
            Cell::Land => LAND,
            Cell::NoData => NO_DATA,
        })
        .collect();
    draw_blocks(chart, &colour_blocks(&colors, m.cx, m.cy), (m.x0, m.y0, m.dx, m.dy), u)
}
