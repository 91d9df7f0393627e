//! `[[changes]]` and `[simulate]`: every kind and trigger with hand-checked values, every
//! error naming its field, geographic changes projected as the world is, the built-in
//! scenarios that use them, and scenarios without them loading exactly as before.

use tidepath::geom::{Vec2, Vec3};
use tidepath::simulate::{Acceptance, Growth, ReplanPolicy, SimParams};
use tidepath::world::changes::{Change, ChangeKind, Law, RandomShift, Trigger};
use tidepath::world::{Current, Obstacle, Shape};

use super::spec::ScenarioSpec;
use super::{builtin, Scenario, BUILTIN, MAX_CHANGES};

/// A 3-D local world with three obstacles (a moving sphere, a cylinder, a box) and two
/// vortices; `extra` is appended (changes, `[simulate]`, `world.epoch`).
fn local(extra: &str) -> String {
    format!(
        r#"
name = "t"
[world]
dimensions = 3
bounds = {{ min = [0.0, 0.0, -500.0], max = [10000.0, 8000.0, 0.0] }}
[[world.obstacles]]
kind = "sphere"
center = [5000.0, 4000.0, -200.0]
radius = 300.0
velocity = [1.0, 0.0, 0.0]
[[world.obstacles]]
kind = "cylinder"
center = [2000.0, 6000.0]
radius = 200.0
[[world.obstacles]]
kind = "box"
min = [7000.0, 1000.0, -400.0]
max = [7500.0, 1500.0, -100.0]
[world.current]
kind = "vortices"
vortices = [
  {{ x = 3000.0, y = 3000.0, strength = 500.0, core_radius = 800.0 }},
  {{ x = 7000.0, y = 5000.0, strength = -400.0, core_radius = 600.0 }},
]
[mission]
start = [500.0, 500.0, -100.0]
goal = [9500.0, 7500.0, -100.0]
{extra}
"#
    )
}

fn load(text: &str) -> tidepath::Result<Scenario> {
    Scenario::from_toml(text, "test.toml")
}

/// The changes of `local(extra)`.
fn changes(extra: &str) -> Vec<Change> {
    load(&local(extra)).unwrap_or_else(|e| panic!("{e}\n{extra}")).changes
}

fn one(extra: &str) -> Change {
    let c = changes(extra);
    assert_eq!(c.len(), 1, "{extra}");
    c.into_iter().next().unwrap()
}

/// The error of `local(extra)`, as printed.
fn error(extra: &str) -> String {
    match load(&local(extra)) {
        Ok(_) => panic!("loaded: {extra}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn every_kind_parses_into_its_change() {
    let at = |kind: ChangeKind| Change { trigger: Trigger::AtTime(60.0), kind, random: None };
    let cases = [
        (
            "kind = \"move-obstacle\"\nobstacle = 0\ncenter = [6000.0, 4500.0, -250.0]",
            ChangeKind::MoveObstacle { index: 0, center: Vec3::new(6000.0, 4500.0, -250.0) },
        ),
        (
            "kind = \"obstacle-velocity\"\nobstacle = 1\nvelocity = [0.0, -2.5, 0.1]",
            ChangeKind::ObstacleVelocity { index: 1, velocity: Vec3::new(0.0, -2.5, 0.1) },
        ),
        (
            // Two components: no vertical speed.
            "kind = \"obstacle-velocity\"\nobstacle = 2\nvelocity = [3.0, 4.0]",
            ChangeKind::ObstacleVelocity { index: 2, velocity: Vec3::new(3.0, 4.0, 0.0) },
        ),
        (
            "kind = \"add-obstacle\"\nadd = { kind = \"cylinder\", center = [4000.0, 2000.0], radius = 150.0, z_min = -300.0, z_max = -50.0, velocity = [0.0, 1.5, 0.0] }",
            ChangeKind::AddObstacle(Obstacle {
                shape: Shape::Cylinder { center: Vec2::new(4000.0, 2000.0), radius: 150.0, z_min: -300.0, z_max: -50.0 },
                velocity: Vec3::new(0.0, 1.5, 0.0), window: None
            }),
        ),
        ("kind = \"remove-obstacle\"\nobstacle = 2", ChangeKind::RemoveObstacle { index: 2 }),
        (
            "kind = \"move-vortex\"\nvortex = 1\ncenter = [6500.0, 5200.0]",
            ChangeKind::MoveVortex { index: 1, center: Vec2::new(6500.0, 5200.0) },
        ),
        (
            "kind = \"vortex-strength\"\nvortex = 0\nstrength = -750.0",
            ChangeKind::VortexStrength { index: 0, strength: -750.0 },
        ),
        (
            "kind = \"current\"\ncurrent = { kind = \"uniform\", velocity = [0.3, -0.2, 0.0] }",
            ChangeKind::ReplaceCurrent(Current::Uniform(Vec3::new(0.3, -0.2, 0.0))),
        ),
    ];
    for (body, kind) in cases {
        assert_eq!(one(&format!("[[changes]]\nat_time = 60.0\n{body}")), at(kind), "{body}");
    }
}

#[test]
fn a_current_change_takes_every_current_kind_of_the_world() {
    let c = one(
        "[[changes]]\nat_time = 10.0\nkind = \"current\"\n[changes.current]\nkind = \"grid\"\norigin = [0.0, 0.0]\nspacing = [5000.0, 4000.0]\nshape = [3, 3]\ntimes = [0.0, 3600.0]\nu = [[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1], [0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2]]\nv = [[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]]",
    );
    let ChangeKind::ReplaceCurrent(Current::Grid(g)) = c.kind else { panic!("{c:?}") };
    assert_eq!(g.times, vec![0.0, 3600.0]);
    assert_eq!(g.u[1][4], 0.2);
    let c = one(
        "[[changes]]\nat_time = 10.0\nkind = \"current\"\ncurrent = { kind = \"vortices\", vortices = [ { x = 1.0, y = 2.0, strength = 3.0, core_radius = 4.0 } ] }",
    );
    let ChangeKind::ReplaceCurrent(Current::Vortices(v)) = c.kind else { panic!("{c:?}") };
    assert_eq!((v[0].x, v[0].y, v[0].strength, v[0].core_radius), (1.0, 2.0, 3.0, 4.0));
}

#[test]
fn random_shifts_default_to_lfhh2019s_redraw_limit() {
    let c = one(
        "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 1\ncenter = [1.0, 2.0, 3.0]\nrandom = { law = \"gaussian\", scale = 1000.0 }",
    );
    assert_eq!(c.random, Some(RandomShift { law: Law::Gaussian, scale: 1000.0, max_draws: 100, from_current: false }));
    assert_eq!(RandomShift::LFHH2019_MAX_DRAWS, 100);
    for kind in [
        "kind = \"add-obstacle\"\nadd = { kind = \"sphere\", center = [1.0, 2.0, -3.0], radius = 4.0 }",
        "kind = \"move-vortex\"\nvortex = 0\ncenter = [1.0, 2.0]",
    ] {
        let c = one(&format!(
            "[[changes]]\nafter_distance = 10.0\n{kind}\nrandom = {{ law = \"uniform\", scale = 250.0, max_draws = 7 }}"
        ));
        assert_eq!(
            c.random,
            Some(RandomShift { law: Law::Uniform, scale: 250.0, max_draws: 7, from_current: false }),
            "{kind}"
        );
    }
}

/// A random move without a centre steps from where the obstacle or vortex is; without
/// `random` the centre is still required.
#[test]
fn a_random_move_without_a_centre_steps_from_the_current_one() {
    for kind in ["kind = \"move-obstacle\"\nobstacle = 1", "kind = \"move-vortex\"\nvortex = 0"] {
        let c =
            one(&format!("[[changes]]\nafter_distance = 10.0\n{kind}\nrandom = {{ law = \"gaussian\", scale = 9.0 }}"));
        assert_eq!(c.random, Some(RandomShift { law: Law::Gaussian, scale: 9.0, max_draws: 100, from_current: true }));
    }
    let e = error("[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 1");
    assert!(e.starts_with("changes[0].center: missing"), "{e}");
}

#[test]
fn each_trigger_reads_on_the_scenario_clock() {
    let body = "kind = \"remove-obstacle\"\nobstacle = 0";
    assert_eq!(one(&format!("[[changes]]\nat_time = 1500.5\n{body}")).trigger, Trigger::AtTime(1500.5));
    assert_eq!(one(&format!("[[changes]]\nafter_distance = 2500.0\n{body}")).trigger, Trigger::AfterDistance(2500.0));
    // An instant is seconds after world.epoch; `[world] epoch` is set by the line after [world].
    let text = local(&format!("[[changes]]\nat = \"2025-11-12T06:30:00Z\"\n{body}"))
        .replace("dimensions = 3", "dimensions = 3\nepoch = \"2025-11-12T05:00:00Z\"");
    assert_eq!(load(&text).unwrap().changes[0].trigger, Trigger::AtTime(5400.0));
    // Or after the earliest ISO departure when there is no epoch.
    let text =
        local(&format!("departure = \"2025-11-12T06:00:00Z\"\n[[changes]]\nat = \"2025-11-12T06:00:10Z\"\n{body}"));
    assert_eq!(load(&text).unwrap().changes[0].trigger, Trigger::AtTime(10.0));
    // Changes keep the file's order.
    let c = changes(&format!(
        "[[changes]]\nat_time = 9.0\n{body}\n[[changes]]\nat_time = 1.0\nkind = \"vortex-strength\"\nvortex = 1\nstrength = 2.0"
    ));
    assert_eq!((c[0].trigger, c[1].trigger), (Trigger::AtTime(9.0), Trigger::AtTime(1.0)));
}

#[test]
fn every_error_names_its_field_and_value() {
    let remove = "kind = \"remove-obstacle\"\nobstacle = 0";
    let cases: Vec<(String, &str)> = vec![
        (
            format!("[[changes]]\n{remove}"),
            "changes[0]: give exactly one trigger (at_time, at or after_distance), got none",
        ),
        (
            format!("[[changes]]\nat_time = 1.0\nafter_distance = 2.0\n{remove}"),
            "changes[0]: give exactly one trigger (at_time, at or after_distance), got at_time and after_distance",
        ),
        (
            format!("[[changes]]\nat_time = 1.0\n{remove}\n[[changes]]\nat_time = 1.0\n{remove}\n[[changes]]\nat_time = -5.0\n{remove}"),
            "changes[2].at_time: must be finite and >= 0, got -5",
        ),
        (
            format!("[[changes]]\nafter_distance = -1.5\n{remove}"),
            "changes[0].after_distance: must be finite and >= 0, got -1.5",
        ),
        (
            format!("[[changes]]\nat = \"2025-11-12T05:00:00Z\"\n{remove}"),
            "changes[0].at: `2025-11-12T05:00:00Z` needs the scenario clock's zero: give world.epoch or an ISO mission departure",
        ),
        (
            format!("departure = \"2025-11-12T06:00:00Z\"\n[[changes]]\nat = \"2025-11-12T05:00:00Z\"\n{remove}"),
            "changes[0].at: `2025-11-12T05:00:00Z` is before the scenario clock's zero 2025-11-12T06:00:00Z (world.epoch, else the earliest ISO departure)",
        ),
        (
            format!("departure = \"2025-11-12T06:00:00Z\"\n[[changes]]\nat = \"noon\"\n{remove}"),
            "changes[0].at: `noon` is not an ISO 8601 UTC instant (e.g. 2025-11-12T06:00:00Z)",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"remove-obstacle\"\nobstacle = 0\ncenter = [1.0, 2.0, 3.0]".into(),
            "changes[0].center: is not a field of kind = \"remove-obstacle\"",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0".into(),
            "changes[0].center: missing: kind = \"move-obstacle\" needs it",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"vortex-strength\"\nvortex = 0\nstrength = 1.0\nrandom = { law = \"gaussian\", scale = 1.0 }".into(),
            "changes[0].random: is not a field of kind = \"vortex-strength\" (only move-obstacle, add-obstacle and move-vortex set a centre)",
        ),
        (
            format!("[[changes]]\nat_time = 0.0\nkind = \"add-obstacle\"\nadd = {{ kind = \"circle\", center = [1.0, 2.0], radius = 3.0 }}\n[[changes]]\nat_time = 0.0\n{remove}\n[[changes]]\nat_time = 0.0\nkind = \"obstacle-velocity\"\nobstacle = 7\nvelocity = [1.0, 0.0]"),
            "changes[2].obstacle: 7 does not exist (the world has 3 obstacles and the changes before this one add 1)",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"remove-obstacle\"\nobstacle = 3".into(),
            "changes[0].obstacle: 3 does not exist (the world has 3 obstacles and the changes before this one add none)",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"vortex-strength\"\nvortex = 2\nstrength = 1.0".into(),
            "changes[0].vortex: 2 does not exist (world.current has 2, and no current before this one has more than 2)",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0\ncenter = [1.0, 2.0]".into(),
            "changes[0].center: needs [x, y, z] in a 3-D world, got 2 coordinates",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-vortex\"\nvortex = 0\ncenter = [1.0, 2.0, 3.0]".into(),
            "changes[0].center: a vortex centre needs 2 coordinates [x, y] (metres), got 3",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"obstacle-velocity\"\nobstacle = 0\nvelocity = [200.0, 0.0]".into(),
            "changes[0].velocity: must be at most 100 m/s, got [200.0, 0.0]",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"obstacle-velocity\"\nobstacle = 0\nvelocity = [1.0]".into(),
            "changes[0].velocity: needs 2 or 3 components [vx, vy(, vz)], got 1",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"add-obstacle\"\nadd = { kind = \"sphere\", center = [1.0, 2.0, 3.0], radius = -4.0 }".into(),
            "changes[0].add.radius: must be positive, got -4",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"add-obstacle\"\nadd = { kind = \"box\", min = [1.0, 2.0, 3.0], max = [4.0, 5.0, 6.0], radius = 4.0 }".into(),
            "changes[0].add.radius: is not a field of kind = \"box\"",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"vortices\", vortices = [ { x = 1.0, y = 2.0, strength = 3.0, core_radius = 0.0 } ] }".into(),
            "changes[0].current.vortices[0].core_radius: must be positive, got 0",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"jet\", speed = 0.5, max_speed = 1.0 }".into(),
            // The jet builder names world.current; the name is rewritten.
            "changes[0].current: a jet needs exactly one of `speed`",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"file\", path = \"f.nc\" }".into(),
            "changes[0].current.kind: \"file\" reads longitude/latitude data: set world.frame = \"geographic\"",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0\ncenter = [1.0, 2.0, 3.0]\nrandom = { law = \"uniform\", scale = -1.0 }".into(),
            "changes[0].random.scale: must be finite and >= 0 (m), got -1",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0\ncenter = [1.0, 2.0, 3.0]\nrandom = { law = \"uniform\", scale = 1.0, max_draws = 0 }".into(),
            "changes[0].random.max_draws: must be from 1 to 10000, got 0",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0\ncenter = [1.0, 2.0, 3.0]\nrandom = { law = \"cauchy\", scale = 1.0 }".into(),
            "changes[0].random.law: unknown variant `cauchy`",
        ),
        // Decoding errors name the field too.
        ("[[changes]]\nat_time = 0.0\nkind = \"teleport\"".into(), "changes[0].kind: unknown variant `teleport`"),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"vortex-strength\"\nvortex = 0\nstrength = \"big\"".into(),
            "changes[0].strength: invalid type",
        ),
        ("[[changes]]\nat_time = 0.0\nkind = \"remove-obstacle\"\nobstacle = -1".into(), "changes[0].obstacle: invalid value"),
        ("[[changes]]\nat_time = 0.0\nkind = \"remove-obstacle\"\nindex = 0".into(), "changes[0].index: unknown field `index`"),
        ("[simulate]\nwindow = 0".into(), "simulate.window: must be from 1 to 10000 waypoints, got 0"),
        (
            "[simulate]\ngrowth = \"double\"\ngrowth_step = 2".into(),
            "simulate.growth_step: only with growth = \"add\" (growth is \"double\")",
        ),
        (
            "[simulate]\ngrowth_step = 2".into(),
            "simulate.growth_step: only with growth = \"add\" (the default growth is \"double\")",
        ),
        ("[simulate]\ngrowth = \"add\"\ngrowth_step = 0".into(), "simulate.growth_step: must be from 1 to 10000 waypoints, got 0"),
        ("[simulate]\nsensor_range = 0.0".into(), "simulate.sensor_range: must be finite and > 0 (m), got 0"),
        ("[simulate]\nsensor_range = -3.0".into(), "simulate.sensor_range: must be finite and > 0 (m), got -3"),
        ("[simulate]\npolicy = \"never\"".into(), "simulate.policy: unknown variant `never`"),
        ("[simulate]\naccept = \"piece\"".into(), "simulate.accept: unknown variant `piece`"),
        ("[simulate]\npreset = \"lfhh2020\"".into(), "simulate.preset: unknown variant `lfhh2020`"),
        ("[simulate]\nwindows = 3".into(), "simulate.windows: unknown field `windows`"),
        ("[simulate]\nsensor_range = nan".into(), "simulate.sensor_range"),
    ];
    for (extra, want) in cases {
        let got = error(&extra);
        assert!(got.starts_with(want), "{extra}\n got: {got}\nwant: {want}");
        assert!(!got.contains('\n'), "{got}");
    }
}

#[test]
fn a_vortex_change_needs_vortices_somewhere_before_it() {
    let no_vortices = |extra: &str| {
        local(extra).replace(
            "kind = \"vortices\"\nvortices = [\n  { x = 3000.0, y = 3000.0, strength = 500.0, core_radius = 800.0 },\n  { x = 7000.0, y = 5000.0, strength = -400.0, core_radius = 600.0 },\n]",
            "kind = \"uniform\"\nvelocity = [0.1, 0.0, 0.0]",
        )
    };
    let strength = "[[changes]]\nat_time = 5.0\nkind = \"vortex-strength\"\nvortex = 0\nstrength = 1.0";
    let e = load(&no_vortices(strength)).unwrap_err().to_string();
    assert_eq!(
        e,
        "changes[0].vortex: needs a current made of vortices: world.current has none, nor does a current change before this one"
    );
    // A current change listed before it that brings vortices makes it valid.
    let bring = "[[changes]]\nat_time = 1.0\nkind = \"current\"\ncurrent = { kind = \"vortices\", vortices = [ { x = 1.0, y = 2.0, strength = 3.0, core_radius = 4.0 } ] }\n";
    let s = load(&no_vortices(&format!("{bring}{strength}"))).unwrap();
    assert_eq!(s.changes[1].kind, ChangeKind::VortexStrength { index: 0, strength: 1.0 });
}

#[test]
fn at_most_max_changes() {
    let one = "[[changes]]\nat_time = 0.0\nkind = \"vortex-strength\"\nvortex = 0\nstrength = 1.0\n";
    assert_eq!(changes(&one.repeat(MAX_CHANGES)).len(), MAX_CHANGES);
    assert_eq!(error(&one.repeat(MAX_CHANGES + 1)), "changes: at most 4096 changes, got 4097");
}

#[test]
fn a_2d_move_takes_x_y() {
    let text = local("[[changes]]\nat_time = 3.0\nkind = \"move-obstacle\"\nobstacle = 2\ncenter = [100.0, 200.0]")
        .replace("dimensions = 3", "dimensions = 2");
    let s = load(&text).unwrap();
    assert_eq!(s.changes[0].kind, ChangeKind::MoveObstacle { index: 2, center: Vec3::new(100.0, 200.0, 0.0) });
}

/// A geographic scenario without data files: one obstacle of each positioned kind, all at
/// (lon, lat) = (-124.1, 48.6) away from the frame's origin so the meridian convergence shows,
/// and `extra` appended.
fn geographic(extra: &str) -> String {
    format!(
        r#"
name = "g"
[world]
dimensions = 2
frame = "geographic"
bounds = {{ min = [-125.0, 48.0, 0.0], max = [-123.0, 49.0, 0.0] }}
[[world.obstacles]]
kind = "circle"
center = [-124.1, 48.6]
radius = 300.0
velocity = [3.0, 4.0, 0.0]
[[world.obstacles]]
kind = "box"
min = [-123.6, 48.2, -10.0]
max = [-123.5, 48.3, 10.0]
[mission]
start = [-124.8, 48.1, 0.0]
goal = [-123.2, 48.9, 0.0]
departure = "2025-11-12T03:00:00Z"
{extra}
"#
    )
}

#[test]
fn geographic_changes_are_projected_as_the_worlds_obstacles_are() {
    let s = load(&geographic(
        r#"
[[changes]]
at_time = 100.0
kind = "move-obstacle"
obstacle = 1
center = [-124.1, 48.6]
[[changes]]
at = "2025-11-12T04:00:00Z"
kind = "add-obstacle"
add = { kind = "circle", center = [-124.1, 48.6], radius = 300.0, velocity = [3.0, 4.0, 0.0] }
[[changes]]
at_time = 200.0
kind = "obstacle-velocity"
obstacle = 0
velocity = [3.0, 4.0]
[[changes]]
at_time = 300.0
kind = "add-obstacle"
add = { kind = "box", min = [-123.6, 48.2, -10.0], max = [-123.5, 48.3, 10.0] }
[[changes]]
at_time = 0.0
kind = "current"
current = { kind = "vortices", vortices = [ { x = 1.0, y = 2.0, strength = 3.0, core_radius = 4.0 } ] }
"#,
    ))
    .unwrap();
    let world = &s.world.obstacles;
    let Shape::Circle { center, .. } = world[0].shape else { panic!() };
    // The centre is where world.obstacles' same lon/lat went, and not the origin (it is 70 km off).
    assert_eq!(s.changes[0].kind, ChangeKind::MoveObstacle { index: 1, center: center.extend(0.0) });
    assert!(center.length() > 10_000.0, "{center}");
    // An added obstacle is the world obstacle it copies, velocity turned the same way.
    assert_eq!(s.changes[1].kind, ChangeKind::AddObstacle(world[0].clone()));
    assert_eq!(s.changes[1].trigger, Trigger::AtTime(3600.0));
    // A velocity east/north becomes the frame's x/y at the obstacle's centre, as the world's.
    assert_eq!(s.changes[2].kind, ChangeKind::ObstacleVelocity { index: 0, velocity: world[0].velocity });
    assert_ne!(world[0].velocity, Vec3::new(3.0, 4.0, 0.0), "the convergence turns it");
    assert!((world[0].velocity.length() - 5.0).abs() < 1e-9);
    assert_eq!(s.changes[3].kind, ChangeKind::AddObstacle(world[1].clone()));
    // Vortices stay metres in the local frame, as world.current.vortices do.
    let ChangeKind::ReplaceCurrent(Current::Vortices(v)) = &s.changes[4].kind else { panic!() };
    assert_eq!((v[0].x, v[0].y), (1.0, 2.0));
    let s = load(&geographic(
        "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"vortices\", vortices = [ { x = 1.0, y = 2.0, strength = 3.0, core_radius = 4.0 } ] }\n[[changes]]\nat_time = 400.0\nkind = \"move-vortex\"\nvortex = 0\ncenter = [1000.0, -2000.0]",
    ))
    .unwrap();
    assert_eq!(s.changes[1].kind, ChangeKind::MoveVortex { index: 0, center: Vec2::new(1000.0, -2000.0) });
}

#[test]
fn geographic_change_errors_name_the_field() {
    for (extra, want) in [
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0\ncenter = [-124.1, 95.0]",
            "changes[0].center: latitude must be within [-90, 90] degrees, got 95",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"move-obstacle\"\nobstacle = 0\ncenter = [-124.1, 48.0, 1.0, 2.0]",
            "changes[0].center: needs [longitude, latitude] in a 2-D world, got 4 coordinates",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"add-obstacle\"\nadd = { kind = \"circle\", center = [-124.1, 95.0], radius = 1.0 }",
            "changes[0].add.center: latitude must be within [-90, 90] degrees, got 95",
        ),
        (
            // A missing file is named as the world's forecast file is, by its path.
            "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"file\", path = \"nowhere/forecast.nc\" }",
            "nowhere/forecast.nc: ",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"file\", path = \"forecast.tif\" }",
            "changes[0].current.path: `forecast.tif`: current forecasts are read from NetCDF (.nc)",
        ),
        (
            "[[changes]]\nat_time = 0.0\nkind = \"current\"\ncurrent = { kind = \"file\", path = \"f.nc\", depth = -1.0 }",
            "changes[0].current.depth: must be from 0 to 12000 m, got -1",
        ),
    ] {
        let e = load(&geographic(extra)).unwrap_err().to_string();
        assert!(e.starts_with(want), "{extra}\n got: {e}\nwant: {want}");
    }
}

#[test]
fn forecast_update_replaces_the_current_with_the_newer_forecast_on_the_same_clock() {
    let s = Scenario::from_toml(builtin("forecast-update").unwrap(), "builtin:forecast-update").unwrap();
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_eq!(s.changes.len(), 1);
    let c = &s.changes[0];
    // Departure 03:00Z is the clock's zero; the forecast arrives at 05:00Z.
    assert_eq!(c.trigger, Trigger::AtTime(7200.0));
    assert_eq!(c.random, None);
    let ChangeKind::ReplaceCurrent(Current::Grid(new)) = &c.kind else { panic!("{:?}", c.trigger) };
    let Current::Grid(old) = &s.world.current else { panic!() };
    // The same grid, other values; times on the scenario clock: the first file starts at
    // 00:00Z (3 h before the zero), the newer one at 03:00Z (the zero), not at its own first time.
    assert_eq!(new.grid, old.grid);
    assert_eq!((old.times[0], new.times[0]), (-10_800.0, 0.0));
    assert_eq!((old.times.len(), new.times.len()), (49, 31));
    assert_eq!(new.gaps, old.gaps);
    assert_ne!(new.u, old.u);
    // At the change's time the two forecasts disagree somewhere in the strait.
    let at = |g: &tidepath::world::current::CurrentGrid, k: usize| {
        let i = g.times.iter().position(|&t| t == 7200.0).unwrap();
        (g.u[i][k], g.v[i][k])
    };
    let k = (0..new.u[0].len()).find(|k| !new.gaps.contains(k) && at(new, *k).0 != 0.0).unwrap();
    assert_ne!(at(new, k), at(old, k));
    assert_eq!(s.simulate, SimParams { policy: ReplanPolicy::Always, ..SimParams::default() });
}

#[test]
fn coastal_traffic_gives_ships_new_courses_and_a_newcomer() {
    let s = Scenario::from_toml(builtin("coastal-traffic").unwrap(), "builtin:coastal-traffic").unwrap();
    assert_eq!(s.simulate, SimParams { sensor_range: Some(1500.0), ..SimParams::default() });
    let kinds: Vec<(Trigger, &ChangeKind)> = s.changes.iter().map(|c| (c.trigger, &c.kind)).collect();
    assert_eq!(kinds.len(), 4);
    assert_eq!(
        kinds[0],
        (Trigger::AtTime(500.0), &ChangeKind::ObstacleVelocity { index: 3, velocity: Vec3::new(0.0, -5.0, 0.0) })
    );
    let ChangeKind::AddObstacle(o) = kinds[3].1 else { panic!() };
    // The patrol boat appears where the comments say.
    assert_eq!(o.shape_at(2900.0), Shape::Circle { center: Vec2::new(7000.0, 1400.0), radius: 100.0 });
    // Every ship is moving or anchored in the domain at departure but the newcomer.
    assert_eq!(s.world.obstacles.len(), 6);
}

#[test]
fn simulate_defaults_and_the_lfhh2019_preset() {
    let sim = |extra: &str| load(&local(extra)).unwrap_or_else(|e| panic!("{e}")).simulate;
    assert_eq!(sim(""), SimParams::default());
    assert_eq!(sim("[simulate]"), SimParams::default());
    assert_eq!(
        SimParams::default(),
        SimParams {
            window: 20,
            growth: Growth::Double,
            accept: Acceptance::Route,
            policy: ReplanPolicy::WhenInfeasible,
            warm_start: true,
            sensor_range: None
        }
    );
    assert_eq!(sim("[simulate]\npreset = \"lfhh2019\""), SimParams::LFHH2019);
    assert_eq!(SimParams::LFHH2019.growth, Growth::Add(1));
    assert_eq!(SimParams::LFHH2019.accept, Acceptance::Window);
    assert_eq!(
        sim("[simulate]\npreset = \"lfhh2019\"\naccept = \"route\""),
        SimParams { accept: Acceptance::Route, ..SimParams::LFHH2019 }
    );
    assert_eq!(
        sim("[simulate]\naccept = \"window\""),
        SimParams { accept: Acceptance::Window, ..SimParams::default() }
    );
    // Fields apply on top of the preset.
    assert_eq!(
        sim("[simulate]\npreset = \"lfhh2019\"\ngrowth_step = 3\nwarm_start = false"),
        SimParams { growth: Growth::Add(3), warm_start: false, ..SimParams::LFHH2019 }
    );
    assert_eq!(
        sim("[simulate]\npreset = \"lfhh2019\"\ngrowth = \"double\""),
        SimParams { growth: Growth::Double, ..SimParams::LFHH2019 }
    );
    assert_eq!(
        sim("[simulate]\nwindow = 5\ngrowth = \"add\"\npolicy = \"always\"\nsensor_range = 800.0"),
        SimParams {
            window: 5,
            growth: Growth::Add(1),
            accept: Acceptance::Route,
            policy: ReplanPolicy::Always,
            warm_start: true,
            sensor_range: Some(800.0)
        }
    );
    assert_eq!(
        sim("[simulate]\ngrowth = \"add\"\ngrowth_step = 4\npolicy = \"when-infeasible\""),
        SimParams { growth: Growth::Add(4), ..SimParams::default() }
    );
}

#[test]
fn scenarios_without_the_sections_load_and_print_as_before() {
    // The built-ins with changes: two of their own, and lfhh2019's four.
    let with_changes = |id: &str| ["forecast-update", "coastal-traffic"].contains(&id) || id.starts_with("lfhh-");
    for e in BUILTIN.iter().filter(|e| !with_changes(e.id)) {
        let source = format!("builtin:{}", e.id);
        let s = Scenario::from_toml(e.build, &source).unwrap();
        assert!(s.changes.is_empty(), "{}", e.id);
        assert_eq!(s.simulate, SimParams::default(), "{}", e.id);
        assert!(s.spec.simulate.is_none() && s.spec.changes.is_empty());
        // Printed back, the spec has no trace of the new sections, and reads back the same.
        let printed = toml::to_string(&s.spec).unwrap();
        assert!(!printed.contains("changes") && !printed.contains("simulate"), "{}:\n{printed}", e.id);
        let again: ScenarioSpec = super::parse_toml(&printed, &source).unwrap();
        assert_eq!(toml::to_string(&again).unwrap(), printed, "{}", e.id);
        let t = Scenario::from_spec(again, &source).unwrap();
        assert_eq!(t.world.obstacles, s.world.obstacles, "{}", e.id);
        assert_eq!(t.world.current, s.world.current, "{}", e.id);
        assert_eq!(t.missions[0].start, s.missions[0].start, "{}", e.id);
    }
    // A spec with the sections prints them and reads back the same.
    let s = Scenario::from_toml(builtin("coastal-traffic").unwrap(), "builtin:coastal-traffic").unwrap();
    let printed = toml::to_string(&s.spec).unwrap();
    assert!(printed.contains("[[changes]]") && printed.contains("[simulate]"), "{printed}");
    let t = Scenario::from_spec(super::parse_toml(&printed, "x").unwrap(), "builtin:coastal-traffic").unwrap();
    assert_eq!((t.changes, t.simulate), (s.changes, s.simulate));
}
