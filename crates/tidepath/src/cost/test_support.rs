//! Helpers the cost models' unit tests share: worlds, vehicles and comparisons.

use std::f64::consts::{FRAC_PI_2, PI};

use crate::geom::{Aabb, Vec3};
use crate::vehicle::Vehicle;
use crate::world::terrain::{GaussianPeaks, Terrain};
use crate::world::World;

/// A 3000 x 3000 m box, 1000 m deep, still water, no seabed in it.
pub fn open_world() -> World {
    World::open(Aabb::new(Vec3::new(0.0, 0.0, -1000.0), Vec3::new(3000.0, 3000.0, 0.0)))
}

/// A flat seabed at height `z`.
pub fn flat(z: f64) -> Terrain {
    Terrain::Peaks(GaussianPeaks { base: z, peaks: vec![], ceiling: None })
}

/// A vehicle whose own limits never bind, at `speed` m/s, with the given safety distance.
pub fn free_vehicle(speed: f64, safety: f64) -> Vehicle {
    Vehicle {
        speed,
        max_turn: PI,
        max_pitch: FRAC_PI_2,
        depth_max: 1000.0,
        safety_distance: safety,
        ..Vehicle::default()
    }
}

/// The value of term `name` in a breakdown.
pub fn term(terms: &[(&str, f64)], name: &str) -> f64 {
    terms.iter().find(|t| t.0 == name).unwrap().1
}

/// `a` equals `b` to 1e-12, relative.
pub fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{a} != {b}");
}

/// Each `(table, prefix)`: parsing the weights `table` fails with one line starting with
/// `prefix` (the field, and the rule where given).
pub fn assert_refused<T>(parse: impl Fn(&str) -> crate::error::Result<T>, cases: &[(&str, &str)]) {
    for (table, field) in cases {
        let e = match parse(table) {
            Ok(_) => panic!("{table}: accepted"),
            Err(e) => e.to_string(),
        };
        assert!(e.starts_with(field), "{table}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
}
