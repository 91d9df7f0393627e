//! ijs2023's posture limits (eq. 14) hold on the path every optimization planner returns: the
//! sliced encoding enforces them itself, so no planner can break them.

use tidepath::geom::Vec3;
use tidepath::planner::registry;
use tidepath_io::scenario::{PlanRequest, Scenario};

/// `demo` with posture limits: planes 1636 m apart (18 km / 11), at most 400 m sideways and
/// 60 m up or down between them.
fn limited() -> Scenario {
    let text = tidepath_io::scenario::builtin("demo").unwrap().replace(
        "kind = \"sliced\"\nwaypoints = 10\n",
        "kind = \"sliced\"\nwaypoints = 10\nlateral_step = 400.0\nvertical_step = 60.0\n",
    );
    assert!(text.contains("lateral_step"));
    Scenario::from_toml(&text, "demo-posture.toml").unwrap()
}

#[test]
fn every_optimizer_keeps_the_posture_limits() {
    let s = limited();
    let (start, goal) = (s.missions[0].start, s.missions[0].goal);
    let normal = (goal - start).truncate().normalize().perp();
    let lateral = |p: Vec3| (p.truncate() - start.truncate()).dot(normal);
    for entry in registry().entries().iter().filter(|e| e.build.is_optimizer()) {
        let req = PlanRequest {
            planner: Some(entry.id.into()),
            seed: 3,
            evaluations: Some(1500),
            iterations: Some(1_000_000),
            ..PlanRequest::default()
        };
        let report = s.plan(&req, &mut |_| {}).unwrap_or_else(|e| panic!("{}: {e}", entry.id));
        let path: Vec<Vec3> = report.missions[0].waypoints.iter().map(|p| Vec3::from_array(*p)).collect();
        assert_eq!(path.len(), 12, "{}", entry.id);
        // Planes 0 (the start) to 10; the last move, to the goal, is priced, not limited.
        for w in path[..11].windows(2) {
            let (dl, dz) = ((lateral(w[1]) - lateral(w[0])).abs(), (w[1].z - w[0].z).abs());
            assert!(
                dl <= 400.0 + 1e-6 && dz <= 60.0 + 1e-6,
                "{}: step {dl:.3} m sideways, {dz:.3} m vertically",
                entry.id
            );
        }
    }
}

#[test]
fn posture_settings_are_checked() {
    let demo = tidepath_io::scenario::builtin("demo").unwrap();
    for (line, field) in [
        ("lateral_step = 400.0\nheading_limit_deg = 30.0", "encoding.lateral_step"),
        ("pitch_limit_deg = 95.0", "encoding.pitch_limit_deg"),
        ("vertical_step = -3.0", "encoding.vertical_step"),
    ] {
        let text = demo.replace("kind = \"sliced\"\n", &format!("kind = \"sliced\"\n{line}\n"));
        let s = Scenario::from_toml(&text, "t.toml");
        let req = PlanRequest { planner: Some("pso".into()), iterations: Some(2), ..PlanRequest::default() };
        let e = match s {
            Err(e) => e.to_string(),
            Ok(s) => s.plan(&req, &mut |_| {}).unwrap_err().to_string(),
        };
        assert!(e.contains(field) && !e.contains('\n'), "{line}: {e}");
    }
    // Angles: planes 1636 m apart and a 10 degree heading limit give at most 288.5 m sideways.
    let text = demo.replace("kind = \"sliced\"\n", "kind = \"sliced\"\nheading_limit_deg = 10.0\n");
    let s = Scenario::from_toml(&text, "t.toml").unwrap();
    let enc = s.build_encoding().unwrap();
    let path = enc.decode(&vec![5000.0; enc.dim()]);
    let spacing = (s.missions[0].goal - s.missions[0].start).truncate().length() / 11.0;
    let normal = (s.missions[0].goal - s.missions[0].start).truncate().normalize().perp();
    let first = (path[1].truncate() - s.missions[0].start.truncate()).dot(normal);
    assert!((first - spacing * 10f64.to_radians().tan()).abs() < 1e-6, "{first}");
}
