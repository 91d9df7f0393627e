//! Scenarios embedded in the binary, so a newcomer can plan without writing a file. One table
//! entry each: the id, a line, the source of its data, and the TOML text.

use tidepath::registry::{Entry, Registry};

pub const BUILTIN: &[Entry<&str>] = &[
    Entry {
        id: "demo",
        description:
            "3-D AUV transit over seamounts, past a moving sphere, a wreck and an exclusion zone, through three eddies",
        citation: "tidepath (synthetic)",
        params: &[],
        build: include_str!("../../scenarios/demo.toml"),
    },
    Entry {
        id: "salish",
        description: "2-D surface transit up the Strait of Juan de Fuca on a real elevation grid, with a flood tide",
        citation: "elevation: matplotlib's topobathy sample (Strait of Juan de Fuca)",
        params: &[],
        build: include_str!("../../scenarios/salish.toml"),
    },
    Entry {
        id: "salish-strait",
        description:
            "3-D AUV transit from west of Cape Flattery to Haro Strait on the real seabed, at least 20 m above it",
        citation: "elevation: matplotlib's topobathy sample (Strait of Juan de Fuca)",
        params: &[],
        build: include_str!("../../scenarios/salish-strait.toml"),
    },
    Entry {
        id: "salish-strait-turns",
        description: "salish-strait by an AUV with a 40 m turning radius: every turn is flown as an arc",
        citation: "elevation: matplotlib's topobathy sample (Strait of Juan de Fuca)",
        params: &[],
        build: include_str!("../../scenarios/salish-strait-turns.toml"),
    },
    Entry {
        id: "salish-forecast",
        description:
            "2-D surface transit up the Strait of Juan de Fuca through a tidal current forecast read from NetCDF",
        citation:
            "elevation: matplotlib's topobathy sample; currents: synthetic M2 tide (scripts/make_salish_forecast.py)",
        params: &[],
        build: include_str!("../../scenarios/salish-forecast.toml"),
    },
    Entry {
        id: "headland",
        description: "2-D surface transit to a goal in a bay that opens away from the start: the route must turn back",
        citation: "tidepath (synthetic)",
        params: &[],
        build: include_str!("../../scenarios/headland.toml"),
    },
    Entry {
        id: "forecast-update",
        description: "salish-forecast, with a newer current forecast arriving two hours into the transit",
        citation: "elevation: matplotlib's topobathy sample; currents: two synthetic M2 forecasts (scripts/make_salish_forecast.py)",
        params: &[],
        build: include_str!("../../scenarios/forecast-update.toml"),
    },
    Entry {
        id: "coastal-traffic",
        description:
            "2-D coastal transit past islands and a breakwater while ships cross the lane, seen within 1.5 km",
        citation: "tidepath (synthetic)",
        params: &[],
        build: include_str!("../../scenarios/coastal-traffic.toml"),
    },
    Entry {
        id: "fleet-crossing",
        description: "2-D: two vehicles whose straight routes cross at the same moment; they must keep 150 m apart",
        citation: "tidepath (synthetic)",
        params: &[],
        build: include_str!("../../scenarios/fleet-crossing.toml"),
    },
    Entry {
        id: "wpa-threats",
        description: "3-D: wpa2017's path experiment, a 50 km cube over Gaussian threat peaks, flown with Dubins turns of 300 m",
        citation: "Zhang et al. 2017 (wpa2017), section IV.B; peak values ours (the paper prints only Figure 2)",
        params: &[],
        build: include_str!("../../scenarios/wpa-threats.toml"),
    },
    Entry {
        id: "fleet-rendezvous",
        description: "3-D: three AUVs over the demo seabed meet at one point, arriving within 60 s of each other, 100 m apart, each choosing its speeds in 0.5-4 kn",
        citation: "tidepath (synthetic; speeds and arrival rule after ijs2023 section IV.C)",
        params: &[],
        build: include_str!("../../scenarios/fleet-rendezvous.toml"),
    },
    Entry {
        id: "lfhh-2d",
        description: "2-D: lfhh2019's experiment, 12 circles and 4 Lamb-Oseen vortices that move five times, 40 x 20 km",
        citation: "lfhh2019, Table 2; obstacles and vortices drawn by scripts/make_lfhh2019_scenarios.py (the paper prints none)",
        params: &[],
        build: include_str!("../../scenarios/lfhh-2d.toml"),
    },
    Entry {
        id: "lfhh-3d-1",
        description: "3-D: lfhh2019's scenario 1, 10 spheres over one Gaussian seabed peak in 4 vortices, moving five times",
        citation: "lfhh2019, Tables 3 and 5; spheres, vortices and peak drawn or chosen by scripts/make_lfhh2019_scenarios.py",
        params: &[],
        build: include_str!("../../scenarios/lfhh-3d-1.toml"),
    },
    Entry {
        id: "lfhh-3d-2",
        description: "3-D: lfhh2019's scenario 2, 10 spheres over two Gaussian seabed peaks in 4 vortices, moving five times",
        citation: "lfhh2019, Tables 3 and 5; spheres, vortices and peaks drawn or chosen by scripts/make_lfhh2019_scenarios.py",
        params: &[],
        build: include_str!("../../scenarios/lfhh-3d-2.toml"),
    },
    Entry {
        id: "lfhh-3d-3",
        description: "3-D: lfhh2019's scenario 3, 10 spheres over three Gaussian seabed peaks in 4 vortices, moving five times",
        citation: "lfhh2019, Tables 3 and 5; spheres, vortices and peaks drawn or chosen by scripts/make_lfhh2019_scenarios.py",
        params: &[],
        build: include_str!("../../scenarios/lfhh-3d-3.toml"),
    },
    Entry {
        id: "amfa-salish-1",
        description: "3-D: amfa2015's experiment 1 on the Salish continental slope, 30 free route points, 300 m -> 300 m deep",
        citation: "amfa2015, section 5.2 (Fig. 17), mirrored on matplotlib's topobathy sample (the paper's chart is not available)",
        params: &[],
        build: include_str!("../../scenarios/amfa-salish-1.toml"),
    },
    Entry {
        id: "amfa-salish-2",
        description: "3-D: amfa2015's experiment 2 on the Salish continental slope, 30 free route points, 230 m -> 450 m deep",
        citation: "amfa2015, section 5.2 (Fig. 18), mirrored on matplotlib's topobathy sample (the paper's chart is not available)",
        params: &[],
        build: include_str!("../../scenarios/amfa-salish-2.toml"),
    },
    Entry {
        id: "ijs-static-1",
        description: "3-D: ijs2023's static experiment I (Table 1) over a seamount field with radar cylinders, spheres and cubes, 40 points with posture limits, time-optimal",
        citation: "ijs2023, Table 1 and Fig. 9, on a synthetic seamount field (the paper's DEM is not available)",
        params: &[],
        build: include_str!("../../scenarios/ijs-static-1.toml"),
    },
    Entry {
        id: "ijs-static-2",
        description: "3-D: ijs2023's static experiment II (Fig. 10), same world, another start and goal",
        citation: "ijs2023, Fig. 10, on a synthetic seamount field",
        params: &[],
        build: include_str!("../../scenarios/ijs-static-2.toml"),
    },
    Entry {
        id: "ijs-static-3",
        description: "3-D: ijs2023's static experiment III (Fig. 11), same world, another start and goal",
        citation: "ijs2023, Fig. 11, on a synthetic seamount field",
        params: &[],
        build: include_str!("../../scenarios/ijs-static-3.toml"),
    },
    Entry {
        id: "ijs-static-4",
        description: "3-D: ijs2023's static experiment IV (Fig. 12), same world, another start and goal",
        citation: "ijs2023, Fig. 12, on a synthetic seamount field",
        params: &[],
        build: include_str!("../../scenarios/ijs-static-4.toml"),
    },
    Entry {
        id: "ijs-current",
        description: "3-D: ijs2023's experiment I in a meandering jet at 0.5 x the AUV's speed (Table 2): time plus current-angle penalty",
        citation: "ijs2023, Table 2 and Fig. 13 (jet: eqs. 27-28), on a synthetic seamount field",
        params: &[],
        build: include_str!("../../scenarios/ijs-current.toml"),
    },
    Entry {
        id: "ijs-strong-0.8",
        description: "3-D: ijs2023's experiment I in a meandering jet at 0.8 x the AUV's speed (Table 3)",
        citation: "ijs2023, Table 3, on a synthetic seamount field",
        params: &[],
        build: include_str!("../../scenarios/ijs-strong-0.8.toml"),
    },
    Entry {
        id: "ijs-strong-1.2",
        description: "3-D: ijs2023's experiment I in a meandering jet at 1.2 x the AUV's speed (Table 3): the current outruns the AUV",
        citation: "ijs2023, Table 3, on a synthetic seamount field",
        params: &[],
        build: include_str!("../../scenarios/ijs-strong-1.2.toml"),
    },
    Entry {
        id: "ijs-fleet",
        description: "3-D: ijs2023's fleet (section IV-C): three AUVs from Fig. 17's starts at 0.5-4 knots in a weak jet, one goal, arriving together 100 m apart",
        citation: "ijs2023, section IV-C and Fig. 17, on a synthetic seamount field (fleet rules chosen: A15)",
        params: &[],
        build: include_str!("../../scenarios/ijs-fleet.toml"),
    },
    Entry {
        id: "glider-1",
        description: "2-D: acopf2016's environment 1, a wave glider on a 20 x 20 grid map of 1 km cells in 2 m waves, no current: two optimal paths of equal length",
        citation: "Gao et al. 2016 (acopf2016), section 4, environment 1 (Fig. 3); obstacle layout and cell size ours (scripts/make_acopf2016_scenarios.py)",
        params: &[],
        build: include_str!("../../scenarios/glider-1.toml"),
    },
    Entry {
        id: "glider-2",
        description: "2-D: acopf2016's environment 2, 2 m waves up to x = 10 km falling to 0.5 m at x = 20 km, no current: the quickest route keeps to the larger waves",
        citation: "Gao et al. 2016 (acopf2016), section 4, environment 2 (Fig. 4); wave heights ours (scripts/make_acopf2016_scenarios.py)",
        params: &[],
        build: include_str!("../../scenarios/glider-2.toml"),
    },
    Entry {
        id: "glider-3",
        description: "2-D: acopf2016's environment 3, glider-2's waves and a 0.5 m/s south-east current in {10 < x <= 20, 8 <= y <= 16} km: the quickest route rides it",
        citation: "Gao et al. 2016 (acopf2016), section 4, environment 3 (Fig. 5); wave heights and current speed ours (scripts/make_acopf2016_scenarios.py)",
        params: &[],
        build: include_str!("../../scenarios/glider-3.toml"),
    },
    Entry {
        id: "glider-4",
        description: "2-D: a wave glider on acopf2016's grid map in a north-west swell and a clockwise eddy: the short route meets a head current, the long one rides the eddy",
        citation: "tidepath's design (acopf2016 mentions a fourth environment without describing it; scripts/make_acopf2016_scenarios.py)",
        params: &[],
        build: include_str!("../../scenarios/glider-4.toml"),
    },
    Entry {
        id: "glider-ocean",
        description: "2-D: a wave glider crossing 155 km of open Pacific off Nihoa (Hawaii) on a wave and current forecast read from NetCDF: the quickest route bends into the swell and the eddy",
        citation: "tidepath (synthetic forecast: scripts/make_acopf2016_scenarios.py)",
        params: &[],
        build: include_str!("../../scenarios/glider-ocean.toml"),
    },
];

pub fn registry() -> Registry<&'static str> {
    Registry::new("built-in scenario", "SCENARIO", "tidepath scenarios", BUILTIN)
}

/// The TOML text of built-in scenario `name`.
pub fn builtin(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|e| e.id == name).map(|e| e.build)
}

pub fn builtin_names() -> impl Iterator<Item = &'static str> {
    BUILTIN.iter().map(|e| e.id)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{PlanRequest, Scenario};

    #[test]
    fn every_builtin_scenario_loads_and_plans() {
        for e in BUILTIN {
            let s = Scenario::from_toml(e.build, &format!("builtin:{}", e.id))
                .unwrap_or_else(|err| panic!("{}: {err}", e.id));
            assert!(s.warnings.is_empty(), "{}: {:?}", e.id, s.warnings);
            // A short run where the default planner counts iterations; a search runs whole.
            let counts_iterations = tidepath::planner::registry()
                .find(&s.planner.id)
                .is_some_and(|p| p.build.caps.counts_unit(tidepath::planner::Unit::Iterations));
            let req = PlanRequest { iterations: counts_iterations.then_some(3), ..PlanRequest::default() };
            let r = s.plan(&req, &mut |_| {}).unwrap_or_else(|err| panic!("{}: {err}", e.id));
            let w = &r.missions[0].waypoints;
            assert!(w.len() >= 2, "{}", e.id);
            assert_eq!((w[0], w[w.len() - 1]), (s.start.to_array(), s.goal.to_array()), "{}", e.id);
        }
    }

    /// wpa2017's world: the 50 km cube, the paper's start and goal (its heights h are
    /// z = h - 50 km), the straight line blocked by the threat peaks, both ends clear of them;
    /// a short MWPA run finds a feasible path, smoothed by Dubins curves of 300 m.
    #[test]
    fn wpa_threats_is_the_papers_path_experiment() {
        let s = Scenario::from_toml(builtin("wpa-threats").unwrap(), "builtin:wpa-threats").unwrap();
        let b = s.world.bounds;
        assert_eq!((b.min.to_array(), b.max.to_array()), ([0.0, 0.0, -50_000.0], [50_000.0, 50_000.0, 0.0]));
        assert_eq!(s.start.to_array(), [3_000.0, 15_000.0, 40_000.0 - 50_000.0]);
        assert_eq!(s.goal.to_array(), [30_000.0, 10_000.0, 10_000.0 - 50_000.0]);
        let seabed = |x: f64, y: f64| s.world.terrain.elevation(x, y);
        let d_safe = s.vehicle.safety_distance;
        assert_eq!(d_safe, 500.0);
        for p in [s.start, s.goal] {
            assert!(p.z > seabed(p.x, p.y) + d_safe, "{p:?} is not clear of the seabed");
        }
        let blocked = (0..=1000).any(|i| {
            let p = s.start + (s.goal - s.start) * (i as f64 / 1000.0);
            p.z < seabed(p.x, p.y)
        });
        assert!(blocked, "the straight path must cross the threat terrain");
        // The cap h_max = 45 km.
        assert!(seabed(13_000.0, 22_000.0) <= -5_000.0);
        assert_eq!((s.planner.id.as_str(), s.cost.model.as_str()), ("mwpa", "wpa2017"));
        let req = PlanRequest { iterations: Some(15), population: Some(40), ..PlanRequest::default() };
        let r = s.plan(&req, &mut |_| {}).unwrap();
        let m = &r.missions[0];
        assert!(m.feasible, "{}", m.reason);
        assert_eq!(m.waypoints.len(), 32, "30 interior planes");
        let smoothed = m.smoothed.as_ref().expect("the dubins smoother runs");
        assert!(smoothed.len() >= 2);
    }
}
