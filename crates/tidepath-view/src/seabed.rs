//! The seabed as a surface: the terrain sampled on a lattice of at most [`MAX_NODES`] nodes
//! along the longer side.
//!
//! Each node's height is the terrain's own elevation at that place (`Terrain::elevation`, the
//! full grid interpolated as every planner and check sees it), so hovering a node reads the
//! real seabed there; only the triangles between nodes are coarser than the grid. Colours run
//! from dark blue (deep) to pale blue at the sea surface, then sand to brown on land.

use serde_json::{json, Value};
use tidepath::geo::GeoFrame;
use tidepath::world::{Terrain, World};

use crate::lattice::{axis, m, shape};
use crate::{poll, Stopped};

/// Nodes along the longer side: 160 x 160 = 25,600 nodes turn smoothly in a browser with
/// software WebGL and take about 300 kB of the page.
pub const MAX_NODES: usize = 160;

/// The seabed surface (`None` without terrain), with its colour range.
pub fn seabed_json(world: &World, frame: Option<&GeoFrame>, stop: &dyn Fn() -> bool) -> Result<Option<Value>, Stopped> {
    if matches!(world.terrain, Terrain::None) {
        return Ok(None);
    }
    let b = &world.bounds;
    let (nx, ny) = shape(b.max.x - b.min.x, b.max.y - b.min.y, MAX_NODES);
    let xs = axis(b.min.x, b.max.x, nx);
    let ys = axis(b.min.y, b.max.y, ny);
    let mut z = Vec::with_capacity(ny);
    let mut lonlat = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &y in &ys {
        poll(stop)?;
        let row: Vec<f64> = xs.iter().map(|&x| m(world.terrain.elevation(x, y))).collect();
        for &v in row.iter().filter(|v| v.is_finite()) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        z.push(row);
        if let Some(f) = frame {
            let r: Vec<[f64; 2]> = xs
                .iter()
                .map(|&x| {
                    let (lon, lat) = f.inverse(x, y);
                    [crate::lattice::round(lon, 1e-5), crate::lattice::round(lat, 1e-5)]
                })
                .collect();
            lonlat.push(r);
        }
    }
    if !lo.is_finite() {
        return Ok(None);
    }
    // Land is drawn at most a tenth of the water column above the sea surface: a coast with
    // 900 m hills would otherwise fill a scene exaggerated for 300 m of water. Colour and
    // hover keep the true height (`elevation`).
    let sea_top = world.bounds.max.z.max(0.0);
    let cap = sea_top + 0.1 * (sea_top - lo).max(1.0);
    let capped = hi > cap;
    let drawn: Vec<Vec<f64>> = z.iter().map(|row| row.iter().map(|v| v.min(cap)).collect()).collect();
    let x: Vec<f64> = xs.iter().map(|v| m(*v)).collect();
    let y: Vec<f64> = ys.iter().map(|v| m(*v)).collect();
    let mut out = json!({
        "x": x, "y": y, "z": drawn, "elevation": z, "cmin": lo, "cmax": hi,
        "zmax_drawn": if capped { cap } else { hi },
        "colorscale": colorscale(lo, hi),
        "nodes": [nx, ny],
    });
    if frame.is_some() {
        out["lonlat"] = json!(lonlat);
    }
    Ok(Some(out))
}

/// Blues below the sea surface (z = 0), sand to brown above it.
pub fn colorscale(lo: f64, hi: f64) -> Value {
    const DEEP: &str = "#08306b";
    const SHALLOW: &str = "#9ecae1";
    const SHORE: &str = "#e3d7a3";
    const LAND: &str = "#7a5c32";
    if hi <= 0.0 || hi <= lo {
        return json!([[0.0, DEEP], [1.0, SHALLOW]]);
    }
    if lo >= 0.0 {
        return json!([[0.0, SHORE], [1.0, LAND]]);
    }
    let sea = (-lo / (hi - lo)).clamp(0.0, 1.0);
    json!([[0.0, DEEP], [sea, SHALLOW], [sea, SHORE], [1.0, LAND]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use tidepath::geom::{Aabb, Vec3};
    use tidepath::world::terrain::{GaussianPeaks, Peak};

    fn never() -> bool {
        false
    }

    #[test]
    fn nodes_carry_the_terrain_s_own_heights() {
        let peak = Peak { x: 500.0, y: 500.0, height: 600.0, sigma_x: 100.0, sigma_y: 100.0 };
        let peaks = GaussianPeaks { base: -1000.0, peaks: vec![peak], ceiling: None };
        let mut w = World::open(Aabb { min: Vec3::new(0.0, 0.0, -1000.0), max: Vec3::new(1000.0, 1000.0, 0.0) });
        w.terrain = Terrain::Peaks(peaks);
        let s = seabed_json(&w, None, &never).unwrap().unwrap();
        assert_eq!(s["nodes"], json!([MAX_NODES, MAX_NODES]));
        let x: Vec<f64> = serde_json::from_value(s["x"].clone()).unwrap();
        let y: Vec<f64> = serde_json::from_value(s["y"].clone()).unwrap();
        let z: Vec<Vec<f64>> = serde_json::from_value(s["elevation"].clone()).unwrap();
        for (j, i) in [(0, 0), (80, 80), (159, 3), (40, 120)] {
            let want = w.terrain.elevation(x[i], y[j]);
            assert!((z[j][i] - want).abs() <= 0.05 + 1e-9 * want.abs(), "{} vs {want}", z[j][i]);
        }
        assert_eq!(s["cmax"].as_f64().unwrap(), z.iter().flatten().cloned().fold(f64::MIN, f64::max));
    }

    #[test]
    fn no_terrain_no_surface_and_a_stop_is_honoured() {
        let w = World::open(Aabb { min: Vec3::new(0.0, 0.0, -10.0), max: Vec3::new(10.0, 10.0, 0.0) });
        assert!(seabed_json(&w, None, &never).unwrap().is_none());
        let mut w2 = w.clone();
        w2.terrain = Terrain::Peaks(GaussianPeaks { base: -10.0, peaks: vec![], ceiling: None });
        assert_eq!(seabed_json(&w2, None, &|| true), Err(Stopped));
    }

    #[test]
    fn land_is_drawn_low_but_keeps_its_height() {
        let peak = Peak { x: 50.0, y: 50.0, height: 1200.0, sigma_x: 10.0, sigma_y: 10.0 };
        let mut w = World::open(Aabb { min: Vec3::new(0.0, 0.0, -300.0), max: Vec3::new(100.0, 100.0, 0.0) });
        w.terrain = Terrain::Peaks(GaussianPeaks { base: -300.0, peaks: vec![peak], ceiling: None });
        let s = seabed_json(&w, None, &never).unwrap().unwrap();
        let drawn: Vec<Vec<f64>> = serde_json::from_value(s["z"].clone()).unwrap();
        let true_z: Vec<Vec<f64>> = serde_json::from_value(s["elevation"].clone()).unwrap();
        // The sea's deepest node is -300 m: land is cut at 30 m, its colour keeps 900 m.
        assert_eq!(drawn.iter().flatten().cloned().fold(f64::MIN, f64::max), 30.0);
        assert!(true_z.iter().flatten().cloned().fold(f64::MIN, f64::max) > 800.0);
        assert_eq!(s["zmax_drawn"].as_f64(), Some(30.0));
    }

    #[test]
    fn the_colour_scale_turns_at_the_sea_surface() {
        let c = colorscale(-300.0, 100.0);
        assert_eq!(c[1][0].as_f64().unwrap(), 0.75);
        assert_eq!(c[2][1], json!("#e3d7a3"));
        assert_eq!(colorscale(-300.0, -10.0).as_array().unwrap().len(), 2);
    }
}
