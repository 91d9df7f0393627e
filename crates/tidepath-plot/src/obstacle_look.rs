//! How each kind of obstacle looks, on the map and in the legend: a reader must tell a sphere
//! (which a vehicle can pass over or under) from a column through the whole water column.
//!
//! Drawn in pixels around a circle's centre, since the plan view keeps the domain's aspect
//! ratio and circles stay round.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::style::{self, plot_err};
use tidepath::error::Result;
use tidepath::world::Shape;

/// The look of an obstacle kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum ObstacleLook {
    /// A ball: a light highlight up and to the left.
    Sphere,
    /// A vertical cylinder over part of the water column: hatched.
    Cylinder,
    /// A column through every depth (a 2-D circle, an endless cylinder): dark fill.
    FullDepth,
    /// An axis-aligned box: plain fill (its square outline already tells it apart).
    Box,
}

impl ObstacleLook {
    pub fn of(shape: &Shape) -> Self {
        match *shape {
            Shape::Sphere { .. } => Self::Sphere,
            Shape::Cylinder { z_min, z_max, .. } if z_min == f64::NEG_INFINITY && z_max == f64::INFINITY => {
                Self::FullDepth
            }
            Shape::Cylinder { .. } => Self::Cylinder,
            Shape::Circle { .. } => Self::FullDepth,
            Shape::Box { .. } => Self::Box,
        }
    }

    /// Legend text.
    pub fn label(self) -> &'static str {
        match self {
            Self::Sphere => "sphere",
            Self::Cylinder => "cylinder (part of the water column)",
            Self::FullDepth => "column through every depth",
            Self::Box => "box",
        }
    }

    /// Fill colour of the outline polygon.
    pub fn fill(self) -> RGBAColor {
        match self {
            Self::FullDepth => RGBAColor(150, 150, 150, 0.75),
            _ => style::OBSTACLE_FILL,
        }
    }
}

/// The decoration inside a circle of radius `r` pixels centred at `c` (pixels of `area`).
pub fn draw_circle_decor<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: (i32, i32),
    r: f64,
    look: ObstacleLook,
) -> Result<()> {
    match look {
        ObstacleLook::Sphere if r >= 4.0 => {
            let h = (c.0 - (0.35 * r).round() as i32, c.1 - (0.35 * r).round() as i32);
            let rr = (0.3 * r).round().max(2.0) as u32;
            area.draw(&Circle::new(h, rr, style::fill(WHITE.mix(0.8)))).map_err(plot_err)?;
        }
        ObstacleLook::Cylinder if r >= 4.0 => {
            // Diagonal chords 6 px apart.
            let s = std::f64::consts::FRAC_1_SQRT_2;
            let mut d = -r + 3.0;
            while d < r {
                let half = (r * r - d * d).max(0.0).sqrt();
                let (mx, my) = (c.0 as f64 + d * s, c.1 as f64 + d * s);
                let a = ((mx - half * s).round() as i32, (my + half * s).round() as i32);
                let b = ((mx + half * s).round() as i32, (my - half * s).round() as i32);
                area.draw(&PathElement::new(vec![a, b], style::line(style::OBSTACLE_EDGE.mix(0.55), 1)))
                    .map_err(plot_err)?;
                d += 6.0;
            }
        }
        _ => {}
    }
    Ok(())
}

/// A legend swatch: the look in a 26 x 14 pixel box centred at `c`.
pub fn draw_swatch<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, c: (i32, i32), look: ObstacleLook) -> Result<()> {
    let edge = style::line(style::OBSTACLE_EDGE, 1);
    if look == ObstacleLook::Box {
        let r = [(c.0 - 11, c.1 - 6), (c.0 + 11, c.1 + 6)];
        area.draw(&Rectangle::new(r, style::fill(look.fill()))).map_err(plot_err)?;
        return area.draw(&Rectangle::new(r, edge)).map_err(plot_err);
    }
    area.draw(&Circle::new(c, 8, style::fill(look.fill()))).map_err(plot_err)?;
    draw_circle_decor(area, c, 8.0, look)?;
    area.draw(&Circle::new(c, 8, edge)).map_err(plot_err)
}
