//! The scene's box: its vertical range, the default vertical exaggeration, and longitude and
//! latitude ticks for geographic scenarios.
//!
//! Depths are small beside distances (300 m of water over a 60 km strait): drawn to scale the
//! seabed is a flat sheet. The page stretches z by an exaggeration the user sets; the default
//! makes the water column about a third as tall as the scene is wide.

use serde_json::{json, Value};
use tidepath::geo::GeoFrame;
use tidepath::geom::Aabb;

/// The vertical extent a view shows, as a share of its longer horizontal side, by default.
const DEFAULT_HEIGHT_SHARE: f64 = 0.35;
/// The largest exaggeration the slider offers.
pub const MAX_EXAGGERATION: f64 = 1000.0;

/// The exaggeration that shows a column of `z_extent` metres as [`DEFAULT_HEIGHT_SHARE`] of a
/// scene `horizontal` metres wide, rounded to 1, 2 or 5 times a power of ten (at least 1).
pub fn default_exaggeration(horizontal: f64, z_extent: f64) -> f64 {
    if !(horizontal > 0.0 && z_extent > 0.0) {
        return 1.0;
    }
    let raw = DEFAULT_HEIGHT_SHARE * horizontal / z_extent;
    if raw <= 1.0 {
        return 1.0;
    }
    nice(raw).min(MAX_EXAGGERATION)
}

/// `x` rounded down to 1, 2 or 5 times a power of ten.
pub fn nice(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    let f = x / p;
    let m = if f >= 5.0 {
        5.0
    } else if f >= 2.0 {
        2.0
    } else {
        1.0
    };
    m * p
}

/// A tick step for a span: about five ticks, at 1, 2 or 5 times a power of ten.
fn step_for(span: f64) -> f64 {
    nice((span / 5.0).max(1e-9))
}

/// Ticks on the x (east) axis in longitude and on the y (north) axis in latitude, each placed
/// where that meridian or parallel crosses the middle of the domain (the local frame bends
/// them only slightly over a few hundred kilometres; hover text gives each point exactly).
pub fn geo_ticks(frame: &GeoFrame, b: &Aabb) -> Value {
    let (xm, ym) = (0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y));
    let (lon_lo, lat_mid) = frame.inverse(b.min.x, ym);
    let (lon_hi, _) = frame.inverse(b.max.x, ym);
    let (lon_mid, lat_lo) = frame.inverse(xm, b.min.y);
    let (_, lat_hi) = frame.inverse(xm, b.max.y);
    let mut x = (Vec::new(), Vec::new());
    let mut y = (Vec::new(), Vec::new());
    for v in ticks(lon_lo, lon_hi) {
        if let Ok((px, _)) = frame.forward(v, lat_mid, "view") {
            x.0.push(crate::lattice::m(px));
            x.1.push(degrees(v, 'E', 'W'));
        }
    }
    for v in ticks(lat_lo, lat_hi) {
        if let Ok((_, py)) = frame.forward(lon_mid, v, "view") {
            y.0.push(crate::lattice::m(py));
            y.1.push(degrees(v, 'N', 'S'));
        }
    }
    json!({ "x": { "vals": x.0, "text": x.1 }, "y": { "vals": y.0, "text": y.1 } })
}

/// Tick values from `lo` to `hi` (either order) at a round step.
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let (lo, hi) = (lo.min(hi), lo.max(hi));
    if hi <= lo || hi.is_nan() || lo.is_nan() {
        return Vec::new();
    }
    let step = step_for(hi - lo);
    // A whisker of slack: 157.1 / 0.1 is 1571.0000000000002 in floating point.
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).take(50).map(|k| (k as f64 * step * 1e9).round() / 1e9).collect()
}

/// "157.25°E", "19.6°N": as many decimals as the value needs (at most four).
pub fn degrees(v: f64, pos: char, neg: char) -> String {
    let a = v.abs();
    let mut s = format!("{a:.4}");
    while s.ends_with('0') {
        s.pop();
    }
    if s.ends_with('.') {
        s.pop();
    }
    format!("{s}°{}", if v < 0.0 { neg } else { pos })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exaggeration_makes_the_column_a_third_of_the_width() {
        // 60 km wide, 300 m deep: 0.35 * 60000 / 300 = 70, rounded down to 50.
        assert_eq!(default_exaggeration(60_000.0, 300.0), 50.0);
        // A cube is drawn to scale.
        assert_eq!(default_exaggeration(50_000.0, 50_000.0), 1.0);
        assert_eq!(default_exaggeration(0.0, 10.0), 1.0);
        assert_eq!(default_exaggeration(1e9, 1e-3), MAX_EXAGGERATION);
    }

    #[test]
    fn nice_rounds_down_to_one_two_five() {
        assert_eq!(nice(7.0), 5.0);
        assert_eq!(nice(19.9), 10.0);
        assert_eq!(nice(0.03), 0.02);
    }

    #[test]
    fn ticks_fall_on_round_values_inside_the_span() {
        assert_eq!(ticks(157.1, 157.6), vec![157.1, 157.2, 157.3, 157.4, 157.5, 157.6]);
        assert_eq!(ticks(19.9, 19.6), vec![19.6, 19.65, 19.7, 19.75, 19.8, 19.85, 19.9]);
        assert!(ticks(1.0, 1.0).is_empty());
    }

    #[test]
    fn degrees_name_the_hemisphere() {
        assert_eq!(degrees(-123.5, 'E', 'W'), "123.5°W");
        assert_eq!(degrees(19.0, 'N', 'S'), "19°N");
        assert_eq!(degrees(157.25, 'E', 'W'), "157.25°E");
    }

    #[test]
    fn geographic_ticks_land_on_their_meridians() {
        let f = GeoFrame::new(157.35, 19.75, "test").unwrap();
        let (x0, y0) = f.forward(157.1, 19.6, "t").unwrap();
        let (x1, y1) = f.forward(157.6, 19.9, "t").unwrap();
        let b = Aabb { min: tidepath::Vec3::new(x0, y0, -6500.0), max: tidepath::Vec3::new(x1, y1, 0.0) };
        let t = geo_ticks(&f, &b);
        let text: Vec<&str> = t["x"]["text"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
        assert!(text.contains(&"157.3°E"), "{text:?}");
        // The 157.35°E meridian (the frame's origin) would sit at x = 0: ticks are ordered east.
        let vals: Vec<f64> = t["x"]["vals"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        assert!(vals.windows(2).all(|w| w[0] < w[1]));
        assert!(vals.iter().all(|v| *v >= x0 - 1.0 && *v <= x1 + 1.0));
    }
}
