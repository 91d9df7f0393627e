//! "Feasible" holds against the data file's own seabed: every feasible plan of the geographic
//! built-ins, sampled every few metres, keeps at least the vehicle's safety distance above the
//! file's surface, bilinear on the file's own longitude/latitude nodes. That surface is
//! evaluated here, independently of the resampled metric grid the planners see: the file's
//! nodes are read whole (no box, no resampling) and interpolated by this file's own code.

use tidepath_io::geodata::netcdf::read_bathymetry;
use tidepath_io::geodata::{DataFile, GeoGrid, EMBEDDED};
use tidepath_io::scenario::{builtin, builtin_names, PlanRequest, Scenario};

/// Spacing (m) of the samples along each segment: under 1% of the file's 2.4 km cell.
const SAMPLE_SPACING_M: f64 = 20.0;

/// The file's surface at (lon, lat): bilinear between the 4 nodes around it, written out here
/// rather than taken from the library.
fn file_surface(g: &GeoGrid, lon: f64, lat: f64) -> f64 {
    let cell = |axis: &[f64], x: f64| {
        assert!(x >= axis[0] && x <= axis[axis.len() - 1], "{x} outside the file's axis");
        let mut k = 0;
        while k + 2 < axis.len() && axis[k + 1] <= x {
            k += 1;
        }
        (k, (x - axis[k]) / (axis[k + 1] - axis[k]))
    };
    let (i, u) = cell(&g.lon, lon);
    let (j, v) = cell(&g.lat, lat);
    let at = |i: usize, j: usize| g.values[j * g.lon.len() + i];
    let south = at(i, j) * (1.0 - u) + at(i + 1, j) * u;
    let north = at(i, j + 1) * (1.0 - u) + at(i + 1, j + 1) * u;
    south * (1.0 - v) + north * v
}

/// The smallest height above the file's surface along `points` (metric), sampled densely.
fn lowest_clearance(s: &Scenario, g: &GeoGrid, points: &[tidepath::geom::Vec3]) -> (f64, String) {
    let frame = s.frame.as_ref().unwrap();
    let mut worst = (f64::INFINITY, String::new());
    for w in points.windows(2) {
        let n = (w[0].distance(w[1]) / SAMPLE_SPACING_M).ceil().max(1.0) as usize;
        for k in 0..=n {
            let p = w[0] + (w[1] - w[0]) * (k as f64 / n as f64);
            let (lon, lat) = frame.inverse(p.x, p.y);
            let c = p.z - file_surface(g, lon, lat);
            if c < worst.0 {
                worst = (c, frame.place(p.x, p.y));
            }
        }
    }
    worst
}

#[test]
fn feasible_plans_of_the_geographic_builtins_clear_the_files_own_seabed() {
    let (name, bytes) = EMBEDDED.iter().find(|(n, _)| *n == "salish_topobathy.nc").unwrap();
    let file = read_bathymetry(&DataFile::Embedded { name, bytes }, None, None, None, 1).unwrap();
    assert!(file.values.iter().all(|v| v.is_finite()), "the shipped file has no fill values");
    // The geographic built-ins on the file's seabed (ijs2023's are geographic over synthetic
    // seamounts, which have no file to check against).
    let geographic: Vec<&str> = builtin_names()
        .filter(|n| {
            let text = builtin(n).unwrap();
            text.contains("frame = \"geographic\"") && text.contains("salish_topobathy.nc")
        })
        .collect();
    assert_eq!(
        geographic,
        [
            "salish",
            "salish-strait",
            "salish-strait-turns",
            "salish-forecast",
            "forecast-update",
            "amfa-salish-1",
            "amfa-salish-2"
        ]
    );
    let mut checked = 0;
    for id in geographic {
        let s = Scenario::from_toml(builtin(id).unwrap(), &format!("builtin:{id}")).unwrap();
        let safety = s.vehicle.safety_distance;
        // The scenario's own planner, a short swarm, and the raster planners (2-D: 200 cells).
        let mut runs: Vec<PlanRequest> = vec![
            PlanRequest::default(),
            PlanRequest { planner: Some("pso".into()), iterations: Some(40), seed: 2, ..PlanRequest::default() },
        ];
        if s.world.dims == tidepath::world::Dims::Two {
            for p in ["astar", "theta-star"] {
                runs.push(PlanRequest { planner: Some(p.into()), ..PlanRequest::default() });
            }
        }
        for req in runs {
            let r = s.plan(&req, &mut |_| {}).unwrap();
            if !r.status.is_success() {
                continue;
            }
            for m in &r.missions {
                // A vehicle with a turning radius flies the flown curve, its turns checked as
                // chords within the arc tolerance (twice that allowed, for the seabed's slope).
                let (points, slack) = match &m.flown {
                    Some(f) => (
                        f.points.iter().map(|p| tidepath::geom::Vec3::from_array(*p)).collect(),
                        2.0 * s.settings.arc_tolerance,
                    ),
                    None => (m.points(), 0.0),
                };
                let (c, at) = lowest_clearance(&s, &file, &points);
                assert!(
                    c >= safety - slack - 1e-6,
                    "{id} with {:?}: {c:.2} m above the file's own seabed at {at}, less than the safety distance {safety} m",
                    req.planner
                );
            }
            checked += 1;
        }
    }
    // The default plans of all four, at least, are feasible and were checked.
    assert!(checked >= 6, "only {checked} feasible plans to check");
}
