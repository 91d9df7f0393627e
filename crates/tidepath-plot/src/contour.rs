//! Marching squares on a sampled scalar field, producing joined polylines.
//!
//! Joining the per-cell segments into polylines keeps the SVG small (one `<polyline>` per
//! contour piece instead of thousands of two-point lines) and lets renderers draw smooth joins.
//! Segments are joined through the grid edge they cross, which is exact, so no coordinate
//! tolerance is needed.

use std::collections::HashMap;

/// A scalar field sampled on the nodes of a regular grid: node (i, j) is at
/// (x0 + i dx, y0 + j dy) and stored at `values[j * nx + i]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    pub x0: f64,
    pub y0: f64,
    pub dx: f64,
    pub dy: f64,
    pub nx: usize,
    pub ny: usize,
    pub values: Vec<f64>,
}

impl Raster {
    /// Samples `f` on `nx` x `ny` nodes spanning [x0, x1] x [y0, y1].
    pub fn sample(x0: f64, y0: f64, x1: f64, y1: f64, nx: usize, ny: usize, f: impl Fn(f64, f64) -> f64) -> Self {
        let (nx, ny) = (nx.max(2), ny.max(2));
        let dx = (x1 - x0) / (nx - 1) as f64;
        let dy = (y1 - y0) / (ny - 1) as f64;
        let mut values = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                values.push(f(x0 + dx * i as f64, y0 + dy * j as f64));
            }
        }
        Self { x0, y0, dx, dy, nx, ny, values }
    }

    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.values[j * self.nx + i]
    }

    /// Smallest and largest finite value, or `None` when there is none.
    pub fn finite_range(&self) -> Option<(f64, f64)> {
        let mut it = self.values.iter().copied().filter(|v| v.is_finite());
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), v| (lo.min(v), hi.max(v))))
    }
}

/// Cell edges, named from the cell's point of view.
#[derive(Clone, Copy)]
enum Edge {
    Bottom,
    Right,
    Top,
    Left,
}

/// The contour of `raster` at `level` as polylines of (x, y). Closed loops repeat their first
/// point at the end. Cells with a non-finite corner are skipped, so the field may have holes.
pub fn contour_lines(raster: &Raster, level: f64) -> Vec<Vec<(f64, f64)>> {
    let (nx, ny) = (raster.nx, raster.ny);
    if nx < 2 || ny < 2 || !level.is_finite() {
        return Vec::new();
    }
    // Global edge ids: horizontal edge from node (i, j) to (i+1, j) is 2k, vertical edge from
    // (i, j) to (i, j+1) is 2k+1, with k = j * nx + i. Neighbouring cells share the id.
    let edge_id = |i: usize, j: usize, e: Edge| -> usize {
        match e {
            Edge::Bottom => 2 * (j * nx + i),
            Edge::Top => 2 * ((j + 1) * nx + i),
            Edge::Left => 2 * (j * nx + i) + 1,
            Edge::Right => 2 * (j * nx + i + 1) + 1,
        }
    };
    let point = |i: usize, j: usize, e: Edge| -> (f64, f64) {
        let ((ai, aj), (bi, bj)) = match e {
            Edge::Bottom => ((i, j), (i + 1, j)),
            Edge::Top => ((i, j + 1), (i + 1, j + 1)),
            Edge::Left => ((i, j), (i, j + 1)),
            Edge::Right => ((i + 1, j), (i + 1, j + 1)),
        };
        let (va, vb) = (raster.at(ai, aj), raster.at(bi, bj));
        let t = if vb != va { ((level - va) / (vb - va)).clamp(0.0, 1.0) } else { 0.5 };
        let x = raster.x0 + raster.dx * (ai as f64 + t * (bi as f64 - ai as f64));
        let y = raster.y0 + raster.dy * (aj as f64 + t * (bj as f64 - aj as f64));
        (x, y)
    };

    // Segments as pairs of edge ids, plus the crossing point of every edge id.
    let mut segments: Vec<(usize, usize)> = Vec::new();
    let mut points: HashMap<usize, (f64, f64)> = HashMap::new();
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let (a, b, c, d) = (raster.at(i, j), raster.at(i + 1, j), raster.at(i + 1, j + 1), raster.at(i, j + 1));
            if !(a.is_finite() && b.is_finite() && c.is_finite() && d.is_finite()) {
                continue;
            }
            let case =
                (a >= level) as u8 | ((b >= level) as u8) << 1 | ((c >= level) as u8) << 2 | ((d >= level) as u8) << 3;
            let centre_above = (a + b + c + d) / 4.0 >= level;
            use Edge::*;
            let pairs: &[(Edge, Edge)] = match case {
                0 | 15 => &[],
                1 | 14 => &[(Left, Bottom)],
                2 | 13 => &[(Bottom, Right)],
                3 | 12 => &[(Left, Right)],
                4 | 11 => &[(Right, Top)],
                6 | 9 => &[(Bottom, Top)],
                7 | 8 => &[(Left, Top)],
                // Saddles: the centre value decides which diagonal pair of corners is connected.
                5 if centre_above => &[(Bottom, Right), (Top, Left)],
                5 => &[(Left, Bottom), (Right, Top)],
                10 if centre_above => &[(Left, Bottom), (Right, Top)],
                10 => &[(Bottom, Right), (Top, Left)],
                _ => unreachable!("four corner bits"),
            };
            for &(e0, e1) in pairs {
                let (k0, k1) = (edge_id(i, j, e0), edge_id(i, j, e1));
                points.entry(k0).or_insert_with(|| point(i, j, e0));
                points.entry(k1).or_insert_with(|| point(i, j, e1));
                segments.push((k0, k1));
            }
        }
    }
    chain(&segments).into_iter().map(|ids| ids.iter().map(|k| points[k]).collect()).collect()
}

/// Joins segments sharing an end into maximal chains of edge ids. Every edge id is shared by at
/// most two segments (the two cells on either side), so each chain is a simple walk.
fn chain(segments: &[(usize, usize)]) -> Vec<Vec<usize>> {
    let mut ends: HashMap<usize, Vec<usize>> = HashMap::new();
    for (s, &(a, b)) in segments.iter().enumerate() {
        ends.entry(a).or_default().push(s);
        ends.entry(b).or_default().push(s);
    }
    let mut used = vec![false; segments.len()];
    let mut out = Vec::new();
    let walk = |start_seg: usize, start_id: usize, used: &mut Vec<bool>| -> Vec<usize> {
        let mut ids = vec![start_id];
        let (mut seg, mut at) = (start_seg, start_id);
        loop {
            used[seg] = true;
            let (a, b) = segments[seg];
            let next = if a == at { b } else { a };
            ids.push(next);
            at = next;
            match ends[&at].iter().find(|&&s| !used[s]) {
                Some(&s) => seg = s,
                None => break,
            }
        }
        ids
    };
    // Open chains first, starting at an end used by only one segment; what is left are loops.
    let mut open_starts: Vec<usize> = ends.iter().filter(|(_, v)| v.len() == 1).map(|(&k, _)| k).collect();
    open_starts.sort_unstable();
    for id in open_starts {
        let s = ends[&id][0];
        if !used[s] {
            out.push(walk(s, id, &mut used));
        }
    }
    for s in 0..segments.len() {
        if !used[s] {
            out.push(walk(s, segments[s].0, &mut used));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_contour_is_one_closed_loop_at_the_right_radius() {
        let r = Raster::sample(-2.0, -2.0, 2.0, 2.0, 81, 81, |x, y| (x * x + y * y).sqrt());
        let lines = contour_lines(&r, 1.0);
        assert_eq!(lines.len(), 1);
        let line = &lines[0];
        assert!(line.len() > 40);
        assert_eq!(line.first(), line.last(), "closed loop repeats its first point");
        for &(x, y) in line {
            assert!(((x * x + y * y).sqrt() - 1.0).abs() < 0.01, "point ({x}, {y}) off the circle");
        }
    }

    #[test]
    fn ramp_contour_is_a_straight_open_line() {
        let r = Raster::sample(0.0, 0.0, 10.0, 5.0, 11, 6, |x, _| x);
        let lines = contour_lines(&r, 3.5);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].len(), 6);
        assert!(lines[0].iter().all(|&(x, _)| (x - 3.5).abs() < 1e-12));
        let ys: Vec<f64> = lines[0].iter().map(|p| p.1).collect();
        assert!(ys.contains(&0.0) && ys.contains(&5.0));
    }

    #[test]
    fn saddle_gives_two_separate_pieces() {
        // Corners a, c high and b, d low with a low centre: two arcs cutting off a and c.
        let r = Raster { x0: 0.0, y0: 0.0, dx: 1.0, dy: 1.0, nx: 2, ny: 2, values: vec![1.0, -1.5, -1.5, 1.0] };
        let lines = contour_lines(&r, 0.0);
        assert_eq!(lines.len(), 2);
        assert!(lines.iter().all(|l| l.len() == 2));
    }

    #[test]
    fn non_finite_cells_and_flat_fields_are_skipped() {
        let mut r = Raster::sample(0.0, 0.0, 4.0, 4.0, 5, 5, |x, _| x);
        r.values[12] = f64::NAN;
        let lines = contour_lines(&r, 2.5);
        // The hole at node (2, 2) removes the four cells around it; the contour is cut in two.
        assert_eq!(lines.len(), 2);
        let flat = Raster::sample(0.0, 0.0, 1.0, 1.0, 4, 4, |_, _| 3.0);
        assert!(contour_lines(&flat, 1.0).is_empty());
        assert!(contour_lines(&flat, 3.5).is_empty());
    }
}
