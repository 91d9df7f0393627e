//! The metric rectangle that covers a longitude/latitude rectangle, for the domain and for
//! box obstacles of geographic scenarios.
//!
//! In the azimuthal projection a parallel of latitude is a curve (an arc about the pole) and
//! meridians converge, so the rectangle of a lon/lat box's four projected corners misses a
//! band along its edges (up to about 2 km for a 4-degree box at 49 N). An exclusion zone must
//! be at least the area the user wrote: the cover is the smallest frame-aligned rectangle
//! holding the whole projected boundary, sampled densely, grown by the most a sampled edge
//! can bow out between two samples.

use tidepath::error::Result;
use tidepath::geo::GeoFrame;

use crate::geodata::GeoBox;

/// Samples along each edge of the box.
const EDGE_SAMPLES: usize = 256;

/// Smallest radius of curvature of a projected parallel or meridian considered (m). A
/// parallel's image is nearly a circle about the pole, of radius about R cot(lat): 110 km at
/// 89 N (the frame's limit); meridians are nearly straight. Between two samples a chord of
/// length c then bows out at most c^2 / (8 R).
const MIN_CURVATURE_RADIUS_M: f64 = 50_000.0;

/// The cover of one lon/lat box in a frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cover {
    pub lo: [f64; 2],
    pub hi: [f64; 2],
    /// Area of the projected lon/lat box (m^2), from its sampled boundary.
    pub area: f64,
}

impl Cover {
    /// How much larger the cover is than the box it covers (0.01 = 1 %).
    pub fn excess(&self) -> f64 {
        let rect = (self.hi[0] - self.lo[0]) * (self.hi[1] - self.lo[1]);
        if self.area > 0.0 {
            rect / self.area - 1.0
        } else {
            0.0
        }
    }
}

/// The cover of `b` in `frame`; `field` names the input in errors.
pub fn cover(frame: &GeoFrame, b: &GeoBox, field: &str) -> Result<Cover> {
    let (w, e) = (b.west, b.east_unwrapped());
    let (s, n) = (b.south, b.north);
    // The boundary counter-clockwise: south edge west to east, east edge, north edge east to
    // west, west edge.
    let mut ring = Vec::with_capacity(4 * EDGE_SAMPLES);
    for k in 0..4 * EDGE_SAMPLES {
        let f = (k % EDGE_SAMPLES) as f64 / EDGE_SAMPLES as f64;
        let (lon, lat) = match k / EDGE_SAMPLES {
            0 => (w + f * (e - w), s),
            1 => (e, s + f * (n - s)),
            2 => (e - f * (e - w), n),
            _ => (w, n - f * (n - s)),
        };
        ring.push(frame.forward(tidepath::geo::normalise_lon(lon), lat, field)?);
    }
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let (mut area2, mut longest) = (0.0, 0.0f64);
    for (k, &(x, y)) in ring.iter().enumerate() {
        let (nx, ny) = ring[(k + 1) % ring.len()];
        lo = [lo[0].min(x), lo[1].min(y)];
        hi = [hi[0].max(x), hi[1].max(y)];
        area2 += x * ny - nx * y;
        longest = longest.max((nx - x).hypot(ny - y));
    }
    // The most an edge bows out between two samples, plus a centimetre for rounding.
    let bow = longest * longest / (8.0 * MIN_CURVATURE_RADIUS_M) + 0.01;
    Ok(Cover { lo: [lo[0] - bow, lo[1] - bow], hi: [hi[0] + bow, hi[1] + bow], area: area2.abs() / 2.0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every point of a 4-degree lon/lat box, edges included, projects inside its cover, and
    /// the cover is not much larger than the box (the meridians' convergence, about 3 %).
    #[test]
    fn the_cover_holds_every_point_of_the_box() {
        let frame = GeoFrame::new(-124.0, 49.0, "t").unwrap();
        let b = GeoBox::new(-126.0, 48.0, -122.0, 50.0, "t").unwrap();
        let c = cover(&frame, &b, "t").unwrap();
        for i in 0..=97 {
            for j in 0..=89 {
                let (lon, lat) = (-126.0 + 4.0 * i as f64 / 97.0, 48.0 + 2.0 * j as f64 / 89.0);
                let (x, y) = frame.forward(lon, lat, "t").unwrap();
                assert!(x >= c.lo[0] && x <= c.hi[0] && y >= c.lo[1] && y <= c.hi[1], "({lon}, {lat})");
            }
        }
        // The corners' rectangle misses the middle of the south edge by about 2 km.
        let corners: Vec<(f64, f64)> =
            [(-126.0, 48.0), (-122.0, 48.0)].iter().map(|&(lon, lat)| frame.forward(lon, lat, "t").unwrap()).collect();
        let (_, mid_south) = frame.forward(-124.0, 48.0, "t").unwrap();
        let miss = corners[0].1.min(corners[1].1) - mid_south;
        assert!(miss > 1500.0 && miss < 2500.0, "{miss}");
        assert!(c.lo[1] <= mid_south);
        assert!(c.excess() > 0.0 && c.excess() < 0.05, "{}", c.excess());
    }
}
