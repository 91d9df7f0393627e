//! Latitude/longitude on the plan view of a geographic world: meridians and parallels drawn
//! through the map (they curve slightly in the azimuthal equidistant frame) and axis ticks
//! where they cross the bottom and left edges, labelled in degrees.

use tidepath::geo::GeoFrame;

/// Lines of constant longitude and latitude over a view, and where they meet its edges.
pub(super) struct Graticule {
    /// (label, polyline in metres) per meridian and per parallel.
    pub lines: Vec<Vec<(f64, f64)>>,
    /// Metric x on the bottom edge and its label, per meridian crossing it.
    pub x_ticks: Vec<(f64, String)>,
    /// Metric y on the left edge and its label, per parallel crossing it.
    pub y_ticks: Vec<(f64, String)>,
}

/// A round step (degrees) giving about `target` lines over `span` degrees.
fn nice_step(span: f64, target: usize) -> f64 {
    const STEPS: &[f64] = &[0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 15.0, 30.0];
    let raw = span / target.max(1) as f64;
    STEPS.iter().copied().find(|&s| s >= raw).unwrap_or(30.0)
}

fn decimals(step: f64) -> usize {
    if step >= 1.0 {
        0
    } else if step >= 0.1 && (step * 10.0).fract().abs() < 1e-9 {
        1
    } else {
        2
    }
}

fn lon_label(lon: f64, d: usize) -> String {
    let l = tidepath::geo::normalise_lon(lon);
    let h = if l < 0.0 {
        "W"
    } else if l > 0.0 && l < 180.0 {
        "E"
    } else {
        ""
    };
    format!("{:.*}°{h}", d, l.abs())
}

fn lat_label(lat: f64, d: usize) -> String {
    let h = if lat < 0.0 {
        "S"
    } else if lat > 0.0 {
        "N"
    } else {
        ""
    };
    format!("{:.*}°{h}", d, lat.abs())
}

/// Finds t in [a, b] where the monotonic `f` equals `target` (bisection); `None` outside.
fn solve(f: impl Fn(f64) -> f64, target: f64, a: f64, b: f64) -> Option<f64> {
    let (fa, fb) = (f(a) - target, f(b) - target);
    // An end on the target is the answer: bisecting from it (0.0's sign is +) would run to
    // the other end.
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() {
        return None;
    }
    let (mut lo, mut hi) = (a, b);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (f(mid) - target).signum() == fa.signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

impl Graticule {
    /// The graticule over the metric view `(x0, y0, x1, y1)`, about `nx` meridians and `ny`
    /// parallels.
    pub fn new(frame: &GeoFrame, (x0, y0, x1, y1): (f64, f64, f64, f64), nx: usize, ny: usize) -> Self {
        // Longitudes relative to the origin so the antimeridian does not split the range.
        let lon_at = |x: f64, y: f64| {
            let (lon, _) = frame.inverse(x, y);
            frame.lon0 + tidepath::geo::normalise_lon(lon - frame.lon0)
        };
        let lat_at = |x: f64, y: f64| frame.inverse(x, y).1;
        let mut lon_r = (f64::INFINITY, f64::NEG_INFINITY);
        let mut lat_r = (f64::INFINITY, f64::NEG_INFINITY);
        for k in 0..=16 {
            let f = k as f64 / 16.0;
            for (x, y) in
                [(x0 + f * (x1 - x0), y0), (x0 + f * (x1 - x0), y1), (x0, y0 + f * (y1 - y0)), (x1, y0 + f * (y1 - y0))]
            {
                let (lo, la) = (lon_at(x, y), lat_at(x, y));
                lon_r = (lon_r.0.min(lo), lon_r.1.max(lo));
                lat_r = (lat_r.0.min(la), lat_r.1.max(la));
            }
        }
        let (sx, sy) = (nice_step(lon_r.1 - lon_r.0, nx), nice_step(lat_r.1 - lat_r.0, ny));
        let (dx, dy) = (decimals(sx), decimals(sy));
        let mut lines = Vec::new();
        let mut x_ticks = Vec::new();
        let mut y_ticks = Vec::new();
        const SAMPLES: usize = 48;
        // A meridian or parallel as a polyline in the frame: point k of SAMPLES + 1.
        let curve = |at: &dyn Fn(f64) -> (f64, f64)| -> Vec<(f64, f64)> {
            (0..=SAMPLES)
                .filter_map(|k| {
                    let (lon, lat) = at(k as f64);
                    frame.forward(lon, lat, "graticule").ok()
                })
                .collect()
        };
        let mut lon = (lon_r.0 / sx).ceil() * sx;
        while lon <= lon_r.1 && lines.len() < 64 {
            lines.push(curve(&|k| (lon, lat_r.0 + (lat_r.1 - lat_r.0) * k / SAMPLES as f64)));
            if let Some(x) = solve(|x| lon_at(x, y0), lon, x0, x1) {
                x_ticks.push((x, lon_label(lon, dx)));
            }
            lon += sx;
        }
        let mut lat = (lat_r.0 / sy).ceil() * sy;
        while lat <= lat_r.1 && lines.len() < 128 {
            lines.push(curve(&|k| (lon_r.0 + (lon_r.1 - lon_r.0) * k / SAMPLES as f64, lat)));
            if let Some(y) = solve(|y| lat_at(x0, y), lat, y0, y1) {
                y_ticks.push((y, lat_label(lat, dy)));
            }
            lat += sy;
        }
        Self { lines, x_ticks, y_ticks }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_fall_on_round_degrees_at_the_edges() {
        let f = GeoFrame::new(-124.0, 48.5, "o").unwrap();
        let g = Graticule::new(&f, (-80e3, -50e3, 80e3, 50e3), 5, 4);
        assert!(g.x_ticks.len() >= 3 && g.y_ticks.len() >= 3, "{:?} {:?}", g.x_ticks, g.y_ticks);
        for (x, label) in &g.x_ticks {
            let (lon, _) = f.inverse(*x, -50e3);
            let want: f64 = label.trim_end_matches("°W").parse::<f64>().unwrap();
            assert!((lon + want).abs() < 1e-6, "{label}: {lon}");
        }
        for (y, label) in &g.y_ticks {
            let (_, lat) = f.inverse(-80e3, *y);
            assert!((lat - label.trim_end_matches("°N").parse::<f64>().unwrap()).abs() < 1e-6, "{label}: {lat}");
        }
        assert_eq!(lon_label(-124.5, 1), "124.5°W");
    }

    /// A meridian through the view's corner (a frame whose origin is the corner) ticks that
    /// corner, not the opposite edge.
    #[test]
    fn a_meridian_on_the_edge_is_ticked_there() {
        let f = GeoFrame::new(-123.4, 48.3, "o").unwrap();
        let g = Graticule::new(&f, (0.0, 0.0, 40e3, 30e3), 4, 4);
        for (x, label) in &g.x_ticks {
            let (lon, _) = f.inverse(*x, 0.0);
            let want: f64 = label.trim_end_matches("°W").parse::<f64>().unwrap();
            assert!((lon + want).abs() < 1e-6, "{label} at x = {x}: {lon}");
        }
        for (y, label) in &g.y_ticks {
            let (_, lat) = f.inverse(0.0, *y);
            assert!((lat - label.trim_end_matches("°N").parse::<f64>().unwrap()).abs() < 1e-6, "{label}: {lat}");
        }
        assert!(g.x_ticks.iter().any(|(x, l)| l == "123.4°W" && x.abs() < 1e-6), "{:?}", g.x_ticks);
        assert_eq!(solve(|x| x, 0.0, 0.0, 1.0), Some(0.0));
        assert_eq!(solve(|x| x, 1.0, 0.0, 1.0), Some(1.0));
        assert_eq!(lat_label(-3.25, 2), "3.25°S");
    }
}
