//! Obstacles for the page: per epoch of the true world, the fixed ones merged into one mesh
//! and each moving (or time-windowed) one as its own mesh with its velocity and the interval it
//! is shown in.
//!
//! A plan view has one epoch (the scenario's world, always). A simulation's true world changes
//! at its change events (an obstacle moved, a ship appeared): each epoch's obstacles are shown
//! from its start to the next one's, so the playback shows what the vehicle met.

use serde_json::{json, Value};
use tidepath::world::{Obstacle, Shape};

use crate::meshes::{shape_mesh, Detail, Mesh};
use crate::{poll, Stopped};

/// One epoch: shown from `from` until `to` (`None`: unbounded), with these obstacles.
pub struct EpochObstacles<'a> {
    pub from: Option<f64>,
    pub to: Option<f64>,
    pub obstacles: &'a [Obstacle],
}

/// A shape in words, for the hover text.
pub fn describe(shape: &Shape) -> String {
    match shape {
        Shape::Sphere { radius, .. } => format!("sphere, radius {radius:.0} m"),
        Shape::Cylinder { radius, z_min, z_max, .. } if z_min.is_finite() || z_max.is_finite() => {
            format!("cylinder, radius {radius:.0} m, z {z_min:.0} to {z_max:.0} m")
        }
        Shape::Cylinder { radius, .. } => format!("cylinder, radius {radius:.0} m, full depth"),
        Shape::Box { min, max } => {
            let d = *max - *min;
            format!("box {:.0} x {:.0} x {:.0} m", d.x, d.y, d.z)
        }
        Shape::Circle { radius, .. } => format!("circle, radius {radius:.0} m"),
    }
}

/// Every epoch's meshes (an empty list without obstacles).
pub fn obstacles_json(
    epochs: &[EpochObstacles<'_>],
    z_lo: f64,
    z_hi: f64,
    stop: &dyn Fn() -> bool,
) -> Result<Value, Stopped> {
    let mut out = Vec::new();
    let detail = Detail::for_count(epochs.iter().map(|e| e.obstacles.len()).max().unwrap_or(0));
    for e in epochs {
        let mut fixed = Mesh::default();
        for (k, o) in e.obstacles.iter().enumerate() {
            if k % 64 == 0 {
                poll(stop)?;
            }
            let mesh = shape_mesh(&o.shape, z_lo, z_hi, detail);
            if o.is_fixed() {
                fixed.append(&mesh);
                continue;
            }
            // The obstacle's own window, cut to the epoch's.
            let (w0, w1) = o.window.map_or((None, None), |(a, b)| (Some(a), Some(b)));
            let from = max_opt(e.from, w0);
            let to = min_opt(e.to, w1);
            let v = o.velocity;
            let speed = v.length();
            let what = describe(&o.shape);
            let name = if speed > 0.0 {
                format!("obstacle {k}: {what}, moving {speed:.2} m/s")
            } else {
                format!("obstacle {k}: {what}")
            };
            out.push(json!({
                "name": name, "moving": speed > 0.0, "mesh": mesh.to_json(),
                "velocity": [v.x, v.y, v.z], "from": from, "to": to,
            }));
        }
        if fixed.vertices() > 0 {
            let n = e.obstacles.iter().filter(|o| o.is_fixed()).count();
            out.push(json!({
                "name": format!("{n} fixed obstacle{}", if n == 1 { "" } else { "s" }), "moving": false,
                "mesh": fixed.to_json(), "velocity": [0.0, 0.0, 0.0], "from": e.from, "to": e.to,
            }));
        }
    }
    Ok(Value::Array(out))
}

fn max_opt(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.max(b)),
        (a, b) => a.or(b),
    }
}

fn min_opt(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tidepath::geom::{Vec2, Vec3};

    fn never() -> bool {
        false
    }

    #[test]
    fn fixed_obstacles_merge_and_moving_ones_keep_their_velocity_and_window() {
        let fixed = Obstacle::fixed(Shape::Circle { center: Vec2::new(0.0, 0.0), radius: 5.0 });
        let fixed2 = Obstacle::fixed(Shape::Box { min: Vec3::ZERO, max: Vec3::ONE });
        let mut ship = Obstacle::moving(Shape::Sphere { center: Vec3::ZERO, radius: 2.0 }, Vec3::new(1.0, 0.0, 0.0));
        ship.window = Some((10.0, 50.0));
        let obs = [fixed, ship, fixed2];
        let e = [EpochObstacles { from: None, to: Some(30.0), obstacles: &obs }];
        let j = obstacles_json(&e, -10.0, 0.0, &never).unwrap();
        let a = j.as_array().unwrap();
        assert_eq!(a.len(), 2);
        assert_eq!(a[0]["name"], "obstacle 1: sphere, radius 2 m, moving 1.00 m/s");
        assert_eq!((a[0]["from"].as_f64(), a[0]["to"].as_f64()), (Some(10.0), Some(30.0)));
        assert_eq!(a[1]["name"], "2 fixed obstacles");
        // The circle's prism (42 vertices) and the box's 8 corners in one mesh.
        assert_eq!(a[1]["mesh"]["x"].as_array().unwrap().len(), 42 + 8);
        assert!(a[1]["to"].as_f64() == Some(30.0) && a[1]["from"].is_null());
    }
}
