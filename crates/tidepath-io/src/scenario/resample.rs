//! Longitude/latitude grids onto the local metric frame: the regular metric grid every file
//! layer is resampled onto, and the seabed resampled as a conservative envelope.
//!
//! # Why an envelope, and why it holds
//!
//! Validity in the core checks clearance against the metric grid's own surface, bilinear
//! between its nodes. An engineer checks a route against the file's surface, bilinear between
//! the file's nodes in longitude/latitude. A metric grid that merely samples the file at its
//! nodes smooths every shoal that falls between them (a -1 m node among -199 m nodes read as
//! -47 m at Race Rocks), so "feasible" could pass below the file's seabed. The resampled
//! seabed is therefore an upper envelope of the file's surface F:
//!
//! 1. Inside a metric cell the core's surface is the bilinear blend of the cell's 4 corner
//!    nodes: a convex combination (weights (1-u)(1-v), u(1-v), (1-u)v, uv, all >= 0, sum 1), so
//!    it is at least the smallest of the 4 corners everywhere in the cell.
//! 2. So if every corner of a cell is at least max F over that cell, the metric surface is at
//!    least F at every point of the cell. A node is a corner of up to 4 cells: each node is set
//!    to max F over the union of the (up to) 4 cells around it, its *footprint* (clipped at the
//!    grid's edge). Then the metric surface is >= F everywhere in the metric domain.
//! 3. max F over the footprint is bounded by max F over the footprint's longitude/latitude
//!    bounding box B (the footprint lies inside B). F is bilinear inside each file cell, so on
//!    the part of B inside one file cell (an axis-aligned rectangle) its maximum sits at a
//!    corner of that part. Those corners are the points of the lattice Xs x Ys, where Xs holds
//!    B's west and east edges and the file longitudes strictly between them, and Ys likewise
//!    for latitudes: max F over B is exactly the max of F over that lattice.
//! 4. B is found from the footprint's boundary mapped back to degrees: its 8 boundary nodes
//!    (subdivided for cells over [`EDGE_PIECE_M`]) and a pad of [`PAD_FRACTION`] of B's size
//!    on every side, which covers how far the image of a straight metric edge bows away from
//!    the chord between its mapped ends (a second-order effect, under 1e-3 of the edge for the
//!    sizes and distances tidepath allows; tested in `footprint_box_holds_the_mapped_edges`).
//!
//! A node whose lattice meets a file node without data, or reaches past the grid read, is no
//! data: it becomes land (at least [`NO_DATA_ELEVATION`]). The price of the envelope is that
//! shoals and coasts grow by up to one metric cell; a finer `resolution` shrinks that.
//! Floating-point rounding of the bilinear blend (a few ulps) is far below any clearance.

use super::spec::TerrainSpec;
use crate::geodata::GeoGrid;
use tidepath::error::{Error, Result};
use tidepath::geo::GeoFrame;

/// Elevation (m) given to nodes without data: land, above the sea surface.
pub const NO_DATA_ELEVATION: f64 = 10.0;

/// Most nodes of a resampled metric grid: 4 million (a 2000 x 2000 grid). A finer request is
/// coarsened to fit, with a warning.
pub const MAX_GRID_NODES: usize = 4_000_000;

/// Finest and coarsest `resolution` (m) of a resampled grid: a centimetre is finer than any
/// survey; beyond 1,000 km there is nothing left to resample.
pub const MIN_RESOLUTION_M: f64 = 0.01;
pub const MAX_RESOLUTION_M: f64 = 1e6;

/// The default metric spacing is the file's own divided by this. The seabed envelope widens
/// shoals and coasts by up to one metric cell; at the file's own spacing that closed the
/// built-in Salish passages to the default planners (a 2.4 km file), a third keeps the widening
/// to a third of a file cell for 9 times the nodes.
pub const DEFAULT_REFINEMENT: f64 = 3.0;

/// Longest piece (m) of a footprint edge mapped back to degrees by its ends alone; longer
/// edges are cut into pieces this long, so the bow of each piece stays second order.
pub const EDGE_PIECE_M: f64 = 2_000.0;

/// Pad added on every side of a footprint's longitude/latitude box, as a fraction of the box's
/// width and height: 20 times the worst bow measured by the test.
pub const PAD_FRACTION: f64 = 0.02;

/// A regular metric grid over `lo`..`hi` and where each of its nodes lies in degrees: found
/// once per data file and used for every layer resampled onto it (bathymetry, or each time
/// step of u and v), since the geodesic computations are the costly part.
///
/// The grid starts at `lo` (the metric domain's south-west corner) and ends exactly at `hi`:
/// nx = ceil(width / resolution) + 1 nodes, so the spacing is the resolution or slightly less.
pub(crate) struct MetricGrid {
    pub origin: [f64; 2],
    pub spacing: [f64; 2],
    pub shape: [usize; 2],
    /// (lon, lat) of each node, row-major.
    pub lonlat: Vec<(f64, f64)>,
}

impl MetricGrid {
    /// Spacing `resolution`, by default [`DEFAULT_REFINEMENT`] times finer than `g`'s own at
    /// its middle latitude (the smaller of its east-west and north-south spacings); coarsened (with a warning naming `field`) to stay
    /// within `max_nodes` (at most [`MAX_GRID_NODES`]).
    pub fn new(
        g: &GeoGrid,
        frame: &GeoFrame,
        (lo, hi): ([f64; 2], [f64; 2]),
        resolution: Option<f64>,
        max_nodes: usize,
        field: &str,
        warnings: &mut Vec<String>,
    ) -> Result<Self> {
        let lat_mid = (g.lat[0] + g.lat[g.ny() - 1]) / 2.0;
        let native = {
            let dlon = (g.lon[g.nx() - 1] - g.lon[0]) / (g.nx() - 1) as f64;
            let dlat = (g.lat[g.ny() - 1] - g.lat[0]) / (g.ny() - 1) as f64;
            (dlon * 111_320.0 * lat_mid.to_radians().cos()).min(dlat * 110_540.0)
        };
        let mut spacing = match resolution {
            Some(r) if (MIN_RESOLUTION_M..=MAX_RESOLUTION_M).contains(&r) => r,
            Some(r) => {
                return Err(Error::input(
                    field,
                    format!("must be from {MIN_RESOLUTION_M} to {MAX_RESOLUTION_M} m, got {r:?}"),
                ))
            }
            None => (native / DEFAULT_REFINEMENT).max(MIN_RESOLUTION_M),
        };
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        let nodes = |sp: f64| ((w / sp).ceil() as usize + 1, (h / sp).ceil() as usize + 1);
        let (mut nx, mut ny) = nodes(spacing);
        let max_nodes = max_nodes.clamp(4, MAX_GRID_NODES);
        if (nx as f64) * (ny as f64) > max_nodes as f64 {
            spacing *= ((nx as f64 * ny as f64) / max_nodes as f64).sqrt() * 1.01;
            (nx, ny) = nodes(spacing);
            while nx * ny > max_nodes && nx * ny > 4 {
                spacing *= 1.01;
                (nx, ny) = nodes(spacing);
            }
            warnings.push(format!("{field}: resampled at {spacing:.0} m so the grid stays within {max_nodes} nodes"));
        }
        let (dx, dy) = (w / (nx - 1) as f64, h / (ny - 1) as f64);
        let mut lonlat = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                lonlat.push(frame.inverse(lo[0] + i as f64 * dx, lo[1] + j as f64 * dy));
            }
        }
        Ok(Self { origin: lo, spacing: [dx, dy], shape: [nx, ny], lonlat })
    }

    /// The metric position of node `k`.
    pub fn xy(&self, k: usize) -> (f64, f64) {
        let [nx, _] = self.shape;
        (self.origin[0] + (k % nx) as f64 * self.spacing[0], self.origin[1] + (k / nx) as f64 * self.spacing[1])
    }

    /// `g` bilinear at every node, `NaN` where it has no data. `valid_only` leaves out corners
    /// without data ([`GeoGrid::sample_valid`]) instead of giving up on the node.
    pub fn sample(&self, g: &GeoGrid, valid_only: bool) -> Vec<f64> {
        self.lonlat
            .iter()
            .map(|&(lon, lat)| {
                let lon = into_range(g, lon);
                let value = if valid_only { g.sample_valid(lon, lat) } else { g.sample(lon, lat) };
                value.filter(|v| v.is_finite()).unwrap_or(f64::NAN)
            })
            .collect()
    }

    /// The longitude/latitude box holding the footprint of node (i, j): the metric cells
    /// around it (clipped at the grid's edge), mapped back to degrees, padded by
    /// [`PAD_FRACTION`]. Longitudes are continuous about the node's own (in `g`'s range).
    fn footprint_box(&self, frame: &GeoFrame, g: &GeoGrid, i: usize, j: usize) -> [f64; 4] {
        let [nx, ny] = self.shape;
        let (i0, i1, j0, j1) = (i.saturating_sub(1), (i + 1).min(nx - 1), j.saturating_sub(1), (j + 1).min(ny - 1));
        let centre = into_range(g, self.lonlat[j * nx + i].0);
        let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
        let mut add = |(lon, lat): (f64, f64)| {
            let lon = centre + tidepath::geo::normalise_lon(lon - centre);
            b = [b[0].min(lon), b[1].min(lat), b[2].max(lon), b[3].max(lat)];
        };
        // The boundary of the footprint rectangle walks through these nodes.
        let ring = [(i0, j0), (i, j0), (i1, j0), (i1, j), (i1, j1), (i, j1), (i0, j1), (i0, j)];
        let pieces = |d: f64| (d / EDGE_PIECE_M).ceil().max(1.0) as usize;
        for (k, &(a, c)) in ring.iter().enumerate() {
            add(self.lonlat[c * nx + a]);
            let (b2, d2) = ring[(k + 1) % ring.len()];
            let (xa, ya) = self.xy(c * nx + a);
            let (xb, yb) = self.xy(d2 * nx + b2);
            let n = pieces((xb - xa).hypot(yb - ya));
            for s in 1..n {
                let f = s as f64 / n as f64;
                add(frame.inverse(xa + f * (xb - xa), ya + f * (yb - ya)));
            }
        }
        let (pw, ph) = (PAD_FRACTION * (b[2] - b[0]) + 1e-9, PAD_FRACTION * (b[3] - b[1]) + 1e-9);
        [b[0] - pw, b[1] - ph, b[2] + pw, b[3] + ph]
    }
}

/// `lon` shifted by a multiple of 360 into `g`'s longitude range (which may run past 180).
fn into_range(g: &GeoGrid, lon: f64) -> f64 {
    g.lon[0] + (lon - g.lon[0]).rem_euclid(360.0)
}

/// The maximum of `g`'s bilinear surface over a longitude/latitude box: the max over the
/// lattice of the box's edges and the file's axis values strictly inside it (point 3 of the
/// module's argument).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum BoxMax {
    Value(f64),
    /// Some lattice point has a no-data corner; the largest value seen otherwise.
    NoData(f64),
    /// The box reaches past the grid that was read (past the file's edge).
    Outside,
}

pub(crate) fn max_over_box(g: &GeoGrid, [west, south, east, north]: [f64; 4]) -> BoxMax {
    let (lon, lat) = (&g.lon, &g.lat);
    if west < lon[0] || east > lon[lon.len() - 1] || south < lat[0] || north > lat[lat.len() - 1] {
        return BoxMax::Outside;
    }
    let inner = |axis: &[f64], a: f64, b: f64| {
        let from = axis.partition_point(|&v| v <= a);
        let to = axis.partition_point(|&v| v < b);
        axis[from..to.max(from)].to_vec()
    };
    let mut xs = vec![west, east];
    xs.extend(inner(lon, west, east));
    let mut ys = vec![south, north];
    ys.extend(inner(lat, south, north));
    let (mut best, mut missing) = (f64::NEG_INFINITY, false);
    for &y in &ys {
        for &x in &xs {
            match g.sample(x, y) {
                Some(v) if v.is_finite() => best = best.max(v),
                _ => missing = true,
            }
        }
    }
    if missing {
        BoxMax::NoData(best)
    } else {
        BoxMax::Value(best)
    }
}

/// The bathymetry resampled onto a metric grid over `lo`..`hi` as the conservative envelope of
/// the module's argument; nodes without data are land, counted in warnings that say where.
pub(crate) fn resample(
    g: &GeoGrid,
    frame: &GeoFrame,
    lo: [f64; 2],
    hi: [f64; 2],
    resolution: Option<f64>,
    warnings: &mut Vec<String>,
) -> Result<TerrainSpec> {
    let m = MetricGrid::new(g, frame, (lo, hi), resolution, MAX_GRID_NODES, "world.terrain.resolution", warnings)?;
    let [nx, ny] = m.shape;
    let mut z = Vec::with_capacity(nx * ny);
    let (mut fill, mut outside): (Vec<usize>, Vec<usize>) = (Vec::new(), Vec::new());
    for j in 0..ny {
        for i in 0..nx {
            let k = j * nx + i;
            let fb = m.footprint_box(frame, g, i, j);
            z.push(match max_over_box(g, fb) {
                BoxMax::Value(v) => v,
                BoxMax::NoData(v) => {
                    fill.push(k);
                    v.max(NO_DATA_ELEVATION)
                }
                BoxMax::Outside => {
                    outside.push(k);
                    NO_DATA_ELEVATION
                }
            });
        }
    }
    if let Some(&k) = fill.first() {
        let (x, y) = m.xy(k);
        warnings.push(format!(
            "world.terrain: {} of {} nodes are next to nodes without data in the file (fill) and are taken as land; the first at {}",
            fill.len(),
            z.len(),
            frame.place(x, y)
        ));
    }
    if let Some(&k) = outside.first() {
        let (x, y) = m.xy(k);
        let (w, e) = (tidepath::geo::normalise_lon(g.lon[0]), tidepath::geo::normalise_lon(g.lon[g.nx() - 1]));
        warnings.push(format!(
            "world.terrain: {} of {} nodes lie beyond the file's data (it ends at longitudes {w:.4} to {e:.4}, latitudes {:.4} to {:.4} here) and are taken as land; the first at {}. The metric domain is the rectangle holding the projected box, so it reaches past the box's curved edges: give world.bounds a box inside the file",
            outside.len(),
            z.len(),
            g.lat[0],
            g.lat[g.ny() - 1],
            frame.place(x, y)
        ));
    }
    Ok(TerrainSpec::Grid { origin: m.origin, spacing: m.spacing, shape: m.shape, elevations: z })
}

/// Whether a metric point is water (seabed below the sea surface) in a resampled terrain grid,
/// judged at its nearest node; everything is water without terrain.
pub(crate) fn water_test(terrain: &TerrainSpec) -> impl Fn(f64, f64) -> bool + '_ {
    move |x, y| match terrain {
        TerrainSpec::Grid { origin, spacing, shape, elevations } => {
            let i = (((x - origin[0]) / spacing[0]).round().max(0.0) as usize).min(shape[0] - 1);
            let j = (((y - origin[1]) / spacing[1]).round().max(0.0) as usize).min(shape[1] - 1);
            elevations[j * shape[0] + i] < 0.0
        }
        _ => true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tidepath::world::grid::RegularGrid2;

    fn tent() -> GeoGrid {
        // Longitudes 0, 1, 2; latitudes 0, 1; a 10 m spike at (1, 0).
        GeoGrid::new(vec![0.0, 1.0, 2.0], vec![0.0, 1.0], vec![0.0, 10.0, 0.0, 0.0, 0.0, 0.0], "t").unwrap()
    }

    #[test]
    fn max_over_a_box_is_at_the_lattice_of_its_edges_and_the_file_nodes() {
        let g = tent();
        // Inside one file cell: the corners (0.75, 0) = 7.5 and (0.75, 0.5) = 3.75 lead.
        assert_eq!(max_over_box(&g, [0.25, 0.0, 0.75, 0.5]), BoxMax::Value(7.5));
        // North of the spike: along lat 0.6 the surface is 10 * 0.4 at lon 1, the file node's
        // longitude inside the box.
        assert_eq!(max_over_box(&g, [0.5, 0.6, 1.5, 1.0]), BoxMax::Value(4.0));
        assert_eq!(max_over_box(&g, [0.5, 0.0, 1.5, 1.0]), BoxMax::Value(10.0));
        assert_eq!(max_over_box(&g, [1.5, 0.0, 2.5, 1.0]), BoxMax::Outside);
        let mut holes = tent();
        holes.values[5] = f64::NAN;
        // The no-data node (2, 1) has weight at every point of the box: nothing but no data.
        assert_eq!(max_over_box(&holes, [1.2, 0.1, 1.8, 0.9]), BoxMax::NoData(f64::NEG_INFINITY));
        // Across into the cell west of it, the spike is seen, and so is the no-data corner.
        assert_eq!(max_over_box(&holes, [0.5, 0.0, 1.5, 0.5]), BoxMax::NoData(10.0));
        // The spike seen from (0.8, 0.1): 10 x 0.8 x 0.9.
        let BoxMax::Value(v) = max_over_box(&holes, [0.2, 0.1, 0.8, 0.9]) else { panic!() };
        assert!((v - 7.2).abs() < 1e-12, "{v}");
    }

    /// The whole argument at once: on a spiky file, the metric grid's own bilinear surface is
    /// at or above the file's surface at every one of 20,000 points of the domain.
    #[test]
    fn the_metric_surface_is_nowhere_below_the_files() {
        let (nx, ny) = (11, 9);
        let lon: Vec<f64> = (0..nx).map(|i| -124.0 + 0.01 * i as f64).collect();
        let lat: Vec<f64> = (0..ny).map(|j| 48.0 + 0.01 * j as f64).collect();
        // Alternating deep and shallow nodes: the worst case for a smoothing resample.
        let values: Vec<f64> =
            (0..nx * ny).map(|k| if (k * 7919) % 5 == 0 { -1.0 } else { -100.0 - (k % 13) as f64 }).collect();
        let g = GeoGrid::new(lon, lat, values, "t").unwrap();
        let frame = GeoFrame::new(-123.95, 48.04, "f").unwrap();
        let (lo, hi) = ([-3000.0, -3500.0], [3000.0, 3500.0]);
        for resolution in [None, Some(450.0), Some(1700.0)] {
            let mut warnings = Vec::new();
            let TerrainSpec::Grid { origin, spacing, shape, elevations } =
                resample(&g, &frame, lo, hi, resolution, &mut warnings).unwrap()
            else {
                panic!("a grid")
            };
            assert!(warnings.is_empty(), "{warnings:?}");
            let grid =
                RegularGrid2::new(origin[0], origin[1], spacing[0], spacing[1], shape[0], shape[1], "g").unwrap();
            let mut state = 12345u64;
            let mut unit = || {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                (state >> 11) as f64 / (1u64 << 53) as f64
            };
            for _ in 0..20_000 {
                let (x, y) = (lo[0] + unit() * (hi[0] - lo[0]), lo[1] + unit() * (hi[1] - lo[1]));
                let (plon, plat) = frame.inverse(x, y);
                let file = g.sample(plon, plat).unwrap();
                let metric = grid.bilinear(&elevations, x, y);
                assert!(metric >= file - 1e-9, "{resolution:?}: at ({x}, {y}) {metric} below the file's {file}");
            }
            // And no higher than the file's highest node.
            assert!(elevations.iter().all(|&z| z <= -1.0), "{resolution:?}");
        }
    }

    /// The padded box of a footprint holds its edges mapped back to degrees, sampled densely:
    /// near the origin and 1,900 km from it, at mid and high latitude, for cells from 10 m to
    /// 50 km.
    #[test]
    fn footprint_box_holds_the_mapped_edges() {
        let g = GeoGrid::new(vec![-180.0, 180.0], vec![-90.0, 90.0], vec![0.0; 4], "t").unwrap();
        for (lon0, lat0) in [(-124.0, 48.5), (10.0, 80.0), (179.5, -17.0)] {
            let frame = GeoFrame::new(lon0, lat0, "f").unwrap();
            for (cx, cy) in [(0.0, 0.0), (1.3e6, 1.3e6), (-1.9e6, 0.0), (0.0, -1.9e6)] {
                for h in [10.0, 2_400.0, 50_000.0] {
                    let origin = [cx - h, cy - h];
                    let m = MetricGrid {
                        origin,
                        spacing: [h, h],
                        shape: [3, 3],
                        lonlat: (0..9)
                            .map(|k| frame.inverse(origin[0] + (k % 3) as f64 * h, origin[1] + (k / 3) as f64 * h))
                            .collect(),
                    };
                    let [w, s, e, n] = m.footprint_box(&frame, &g, 1, 1);
                    let centre = m.lonlat[4].0;
                    for k in 0..=400 {
                        let f = k as f64 / 400.0 * 2.0 * h;
                        for (x, y) in [(f, 0.0), (f, 2.0 * h), (0.0, f), (2.0 * h, f)] {
                            let (lon, lat) = frame.inverse(origin[0] + x, origin[1] + y);
                            let lon = centre + tidepath::geo::normalise_lon(lon - centre);
                            assert!(
                                (w..=e).contains(&lon) && (s..=n).contains(&lat),
                                "origin ({lon0}, {lat0}), centre ({cx}, {cy}), cell {h}: ({lon}, {lat}) outside {:?}",
                                [w, s, e, n]
                            );
                        }
                    }
                }
            }
        }
    }
}
