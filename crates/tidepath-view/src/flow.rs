//! Currents as cones on a subsampled lattice and waves as a colour on the sea surface, with
//! one frame per sampled time when they change.
//!
//! A current that varies in time (a meandering jet, a tidal forecast, a forecast update during
//! a simulation) is sampled at [`FRAMES`] times over the view's clock and at every time the
//! flowing current is replaced; a frame identical to the one before is dropped, so a steady
//! current is one frame. The page shows the last frame at or before the slider's time.

use serde_json::{json, Value};
use tidepath::geom::Vec3;
use tidepath::world::{Current, Terrain, World};

use crate::lattice::{axis, round, shape};
use crate::{poll, Stopped};

/// Cones along the longer side (12 x 12 x 3 levels: enough to read a gyre, few enough to see
/// through), wave-colour nodes along the longer side, and sampled times.
pub const CONES_SIDE: usize = 12;
pub const WAVES_SIDE: usize = 48;
pub const FRAMES: usize = 24;

/// Which current flows from when: `(from, current)` in time order (one piece for a plan).
pub type CurrentPieces<'a> = [(f64, &'a Current)];

/// The sample times: [`FRAMES`] even steps over [t0, t1] and every piece's start inside it.
pub fn sample_times(t0: f64, t1: f64, pieces: &CurrentPieces<'_>) -> Vec<f64> {
    let mut ts = if t1 > t0 { axis(t0, t1, FRAMES) } else { vec![t0] };
    ts.extend(pieces.iter().map(|p| p.0).filter(|t| *t > t0 && *t <= t1));
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    ts
}

fn current_at<'a>(pieces: &CurrentPieces<'a>, t: f64) -> &'a Current {
    pieces.iter().rev().find(|p| p.0 <= t).or(pieces.first()).map(|p| p.1).expect("at least one current")
}

/// The travel plane of a 2-D world and the sea surface of a 3-D one.
pub fn surface_z(world: &World) -> f64 {
    match world.dims {
        tidepath::world::Dims::Two => world.bounds.max.z,
        tidepath::world::Dims::Three => world.bounds.max.z.min(0.0),
    }
}

/// The lattice points cones stand on: three levels in each water column of a 3-D world (at a
/// fifth, half and four fifths of the column between the seabed and the top), one at the
/// travel plane of a 2-D world; none on land.
fn cone_points(world: &World) -> Vec<Vec3> {
    let b = &world.bounds;
    let (nx, ny) = shape(b.max.x - b.min.x, b.max.y - b.min.y, CONES_SIDE);
    // Half a cell in from the edges: cones at the border hide behind the axes.
    let (hx, hy) = ((b.max.x - b.min.x) / (2 * nx) as f64, (b.max.y - b.min.y) / (2 * ny) as f64);
    let top = surface_z(world);
    let mut out = Vec::new();
    for y in axis(b.min.y + hy, b.max.y - hy, ny) {
        for x in axis(b.min.x + hx, b.max.x - hx, nx) {
            let floor = match world.terrain {
                Terrain::None => b.min.z,
                _ => world.terrain.elevation(x, y).max(b.min.z),
            };
            match world.dims {
                tidepath::world::Dims::Two => {
                    // A 2-D world's box is its travel plane: only land (terrain above it) is dry.
                    if matches!(world.terrain, Terrain::None) || world.terrain.elevation(x, y) < top {
                        out.push(Vec3::new(x, y, top));
                    }
                }
                tidepath::world::Dims::Three => {
                    if top - floor > 0.0 {
                        out.extend([0.2, 0.5, 0.8].map(|f| Vec3::new(x, y, floor + f * (top - floor))));
                    }
                }
            }
        }
    }
    out
}

/// Cones and their frames (`None` when no current flows anywhere at any sampled time).
pub fn currents_json(
    world: &World,
    pieces: &CurrentPieces<'_>,
    times: &[f64],
    stop: &dyn Fn() -> bool,
) -> Result<Option<Value>, Stopped> {
    if pieces.iter().all(|p| matches!(p.1, Current::None)) {
        return Ok(None);
    }
    let pts: Vec<Vec3> = cone_points(world);
    let pts: Vec<Vec3> = pts.into_iter().filter(|p| pieces.iter().any(|c| c.1.has_data(*p))).collect();
    if pts.is_empty() {
        return Ok(None);
    }
    let mut frames: Vec<Value> = Vec::new();
    let mut last: Option<Vec<[f64; 3]>> = None;
    let mut top_speed: f64 = 0.0;
    for &t in times {
        poll(stop)?;
        let c = current_at(pieces, t);
        let uvw: Vec<[f64; 3]> = pts
            .iter()
            .map(|p| {
                let v = if c.has_data(*p) { c.velocity(*p, t) } else { Vec3::ZERO };
                [round(v.x, 1e-3), round(v.y, 1e-3), round(v.z, 1e-3)]
            })
            .collect();
        if last.as_ref() == Some(&uvw) {
            continue;
        }
        top_speed = uvw.iter().map(|v| Vec3::from_array(*v).length()).fold(top_speed, f64::max);
        let col = |k: usize| uvw.iter().map(|v| v[k]).collect::<Vec<f64>>();
        frames.push(json!({ "t": t, "u": col(0), "v": col(1), "w": col(2) }));
        last = Some(uvw);
    }
    if top_speed == 0.0 {
        return Ok(None);
    }
    let m = crate::lattice::m;
    Ok(Some(json!({
        "x": pts.iter().map(|p| m(p.x)).collect::<Vec<_>>(),
        "y": pts.iter().map(|p| m(p.y)).collect::<Vec<_>>(),
        "z": pts.iter().map(|p| m(p.z)).collect::<Vec<_>>(),
        "max_speed": round(top_speed, 1e-3),
        "frames": frames,
    })))
}

/// The sea state as a colour on the surface and its frames (`None` without waves).
pub fn waves_json(world: &World, times: &[f64], stop: &dyn Fn() -> bool) -> Result<Option<Value>, Stopped> {
    if world.waves.is_none() {
        return Ok(None);
    }
    let b = &world.bounds;
    let (nx, ny) = shape(b.max.x - b.min.x, b.max.y - b.min.y, WAVES_SIDE);
    let (xs, ys) = (axis(b.min.x, b.max.x, nx), axis(b.min.y, b.max.y, ny));
    let z = surface_z(world);
    let steady = world.waves.is_steady();
    let mut frames: Vec<Value> = Vec::new();
    let mut last: Option<Vec<Vec<Option<f64>>>> = None;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &t in if steady { &times[..1.min(times.len())] } else { times } {
        let mut h = Vec::with_capacity(ny);
        for &y in &ys {
            poll(stop)?;
            h.push(
                xs.iter()
                    .map(|&x| {
                        let p = Vec3::new(x, y, z);
                        let v = world.waves.height(p, t);
                        (world.waves.has_data(p) && v.is_finite()).then(|| round(v, 1e-2))
                    })
                    .collect::<Vec<_>>(),
            );
        }
        if last.as_ref() == Some(&h) {
            continue;
        }
        for v in h.iter().flatten().flatten() {
            lo = lo.min(*v);
            hi = hi.max(*v);
        }
        frames.push(json!({ "t": t, "h": h }));
        last = Some(h);
    }
    if !lo.is_finite() {
        return Ok(None);
    }
    let m = crate::lattice::m;
    Ok(Some(json!({
        "x": xs.iter().map(|v| m(*v)).collect::<Vec<_>>(),
        "y": ys.iter().map(|v| m(*v)).collect::<Vec<_>>(),
        "z": m(z),
        "hmin": lo, "hmax": if hi > lo { hi } else { lo + 0.01 },
        "frames": frames,
    })))
}

#[cfg(test)]
mod tests {
    use super::*;
    use tidepath::geom::Aabb;
    use tidepath::world::Waves;

    fn never() -> bool {
        false
    }

    fn world() -> World {
        World::open(Aabb { min: Vec3::new(0.0, 0.0, -100.0), max: Vec3::new(1000.0, 500.0, 0.0) })
    }

    #[test]
    fn a_steady_current_is_one_frame_of_its_velocity() {
        let c = Current::Uniform(Vec3::new(0.5, -0.25, 0.0));
        let w = world();
        let times = sample_times(0.0, 600.0, &[(f64::NEG_INFINITY, &c)]);
        assert_eq!(times.len(), FRAMES);
        let j = currents_json(&w, &[(f64::NEG_INFINITY, &c)], &times, &never).unwrap().unwrap();
        let frames = j["frames"].as_array().unwrap();
        assert_eq!(frames.len(), 1);
        assert!(frames[0]["u"].as_array().unwrap().iter().all(|u| u.as_f64() == Some(0.5)));
        assert!(frames[0]["v"].as_array().unwrap().iter().all(|v| v.as_f64() == Some(-0.25)));
        // 12 x 6 columns, three levels each, all inside the box.
        assert_eq!(j["x"].as_array().unwrap().len(), 12 * 7 * 3);
        assert!(j["z"].as_array().unwrap().iter().all(|z| (-100.0..=0.0).contains(&z.as_f64().unwrap())));
        assert_eq!(j["max_speed"].as_f64().unwrap(), 0.559);
    }

    #[test]
    fn a_forecast_update_starts_a_frame_at_its_time() {
        let (a, b) = (Current::Uniform(Vec3::new(0.5, 0.0, 0.0)), Current::Uniform(Vec3::new(0.0, 1.0, 0.0)));
        let pieces = [(f64::NEG_INFINITY, &a), (250.0, &b)];
        let times = sample_times(0.0, 600.0, &pieces);
        assert!(times.contains(&250.0));
        let j = currents_json(&world(), &pieces, &times, &never).unwrap().unwrap();
        let frames = j["frames"].as_array().unwrap();
        assert_eq!(frames.len(), 2);
        assert_eq!(frames[1]["t"].as_f64(), Some(250.0));
        assert_eq!(frames[1]["v"][0].as_f64(), Some(1.0));
    }

    #[test]
    fn a_2d_world_s_cones_stand_on_its_plane_but_not_on_land() {
        use tidepath::world::terrain::{GaussianPeaks, Peak};
        let mut w = World::open(Aabb { min: Vec3::new(0.0, 0.0, 0.0), max: Vec3::new(1000.0, 1000.0, 0.0) });
        w.dims = tidepath::world::Dims::Two;
        // An island in the middle of 100 m of water.
        let island = Peak { x: 500.0, y: 500.0, height: 200.0, sigma_x: 100.0, sigma_y: 100.0 };
        w.terrain = Terrain::Peaks(GaussianPeaks { base: -100.0, peaks: vec![island], ceiling: None });
        let c = Current::Uniform(Vec3::new(0.3, 0.0, 0.0));
        let j = currents_json(&w, &[(0.0, &c)], &[0.0], &never).unwrap().unwrap();
        let (x, y) = (j["x"].as_array().unwrap(), j["y"].as_array().unwrap());
        assert!(j["z"].as_array().unwrap().iter().all(|z| z.as_f64() == Some(0.0)));
        assert!(x.len() > 100 && x.len() < 144, "{} cones", x.len());
        for (a, b) in x.iter().zip(y) {
            assert!(w.terrain.elevation(a.as_f64().unwrap(), b.as_f64().unwrap()) < 0.0);
        }
    }

    #[test]
    fn no_current_and_no_waves_draw_nothing() {
        let w = world();
        assert!(currents_json(&w, &[(0.0, &Current::None)], &[0.0], &never).unwrap().is_none());
        assert!(waves_json(&w, &[0.0], &never).unwrap().is_none());
    }

    #[test]
    fn uniform_waves_colour_every_node() {
        let mut w = world();
        w.waves = Waves::Uniform(1.5);
        let j = waves_json(&w, &[0.0, 10.0], &never).unwrap().unwrap();
        assert_eq!(j["frames"].as_array().unwrap().len(), 1);
        assert_eq!(j["frames"][0]["h"][3][7].as_f64(), Some(1.5));
        assert_eq!(j["z"].as_f64(), Some(0.0));
    }
}
