//! The colour maps of the figures' fields: depth and land, speed over ground along a path, and
//! significant wave height, each a ramp of its own so no two fields read alike.

use plotters::prelude::RGBColor;

/// Blue for water (dark = deep, light = shallow) and sand to tan for land. `z_min`/`z_max` is
/// the elevation range being shown; water shades span [z_min, min(z_max, 0)].
pub fn elevation_color(z: f64, z_min: f64, z_max: f64) -> RGBColor {
    const WATER: [(f64, [f64; 3]); 5] = [
        (0.0, [38.0, 84.0, 150.0]),
        (0.35, [72.0, 132.0, 196.0]),
        (0.65, [132.0, 182.0, 226.0]),
        (0.88, [192.0, 222.0, 241.0]),
        (1.0, [228.0, 242.0, 250.0]),
    ];
    const LAND: [(f64, [f64; 3]); 2] = [(0.0, [236.0, 219.0, 170.0]), (1.0, [176.0, 136.0, 80.0])];
    // Quantised so neighbouring raster cells share colours and merge into fewer SVG rects.
    let quant = |t: f64| (t.clamp(0.0, 1.0) * 40.0).round() / 40.0;
    if z > 0.0 {
        let t = if z_max > 0.0 { quant(z / z_max) } else { 0.0 };
        ramp(&LAND, t)
    } else {
        let top = z_max.min(0.0);
        let t = if top > z_min { quant((z - z_min) / (top - z_min)) } else { 0.5 };
        ramp(&WATER, t)
    }
}

/// Speed over ground along a path, `lo` to `hi`: pale yellow (slow) through orange to dark
/// red (fast), apart from the seabed's blues. Quantised to 32 shades so neighbouring segments
/// share colours and merge into fewer SVG elements.
pub fn speed_color(v: f64, lo: f64, hi: f64) -> RGBColor {
    const SPEED: [(f64, [f64; 3]); 5] = [
        (0.0, [255.0, 241.0, 150.0]),
        (0.3, [254.0, 196.0, 79.0]),
        (0.55, [241.0, 121.0, 32.0]),
        (0.8, [200.0, 40.0, 30.0]),
        (1.0, [118.0, 0.0, 38.0]),
    ];
    let t = if hi > lo { ((v - lo) / (hi - lo)).clamp(0.0, 1.0) } else { 0.5 };
    ramp(&SPEED, (t * 32.0).round() / 32.0)
}

/// Significant wave height, `lo` to `hi`: a viridis-like ramp from slate blue (calm) through
/// teal and green to yellow (high seas), apart from the seabed's blues and the speed path's
/// yellow-to-red. Its dark end is lightened so current arrows (dark, with a pale halo) stay
/// readable over it. Quantised to 40 shades so neighbouring cells merge into fewer SVG rects.
pub fn wave_color(h: f64, lo: f64, hi: f64) -> RGBColor {
    const WAVES: [(f64, [f64; 3]); 5] = [
        (0.0, [86.0, 62.0, 140.0]),
        (0.25, [64.0, 112.0, 166.0]),
        (0.5, [46.0, 160.0, 150.0]),
        (0.75, [112.0, 205.0, 108.0]),
        (1.0, [250.0, 230.0, 60.0]),
    ];
    let t = if hi > lo { ((h - lo) / (hi - lo)).clamp(0.0, 1.0) } else { 0.5 };
    ramp(&WAVES, (t * 40.0).round() / 40.0)
}

/// The dark outline under a path coloured by speed, so it stands out over the seabed.
pub const SPEED_OUTLINE: RGBColor = RGBColor(25, 20, 20);

fn ramp(stops: &[(f64, [f64; 3])], t: f64) -> RGBColor {
    for w in stops.windows(2) {
        let (t0, c0) = w[0];
        let (t1, c1) = w[1];
        if t <= t1 {
            let u = if t1 > t0 { ((t - t0) / (t1 - t0)).clamp(0.0, 1.0) } else { 0.0 };
            let c = |k: usize| (c0[k] + (c1[k] - c0[k]) * u).round() as u8;
            return RGBColor(c(0), c(1), c(2));
        }
    }
    let c = stops[stops.len() - 1].1;
    RGBColor(c[0] as u8, c[1] as u8, c[2] as u8)
}
