//! ijs2023 states its current's magnitude as a ratio of the AUV's speed: `speed_ratio` and
//! `max_speed_ratio` on a jet multiply `[vehicle] speed`.

use tidepath::geom::Vec3;
use tidepath_io::scenario::Scenario;

fn jet_scenario(current: &str, speed: f64) -> String {
    format!(
        r#"name = "jet-ratio"
[world]
dimensions = 3
bounds = {{ min = [0.0, 0.0, -500.0], max = [10000.0, 6000.0, 0.0] }}
[world.current]
kind = "jet"
{current}
[vehicle]
speed = {speed}
[mission]
start = [500.0, 3000.0, -100.0]
goal = [9500.0, 3000.0, -100.0]
"#
    )
}

fn speed_at(s: &Scenario, p: Vec3) -> f64 {
    s.world.current.velocity(p, 0.0).truncate().length()
}

#[test]
fn speed_ratio_gives_that_share_of_the_vehicle_speed_everywhere_the_jet_flows() {
    for (ratio, vehicle) in [(0.5, 1.542), (0.8, 1.542), (1.2, 2.0)] {
        let s = Scenario::from_toml(&jet_scenario(&format!("speed_ratio = {ratio}"), vehicle), "t.toml").unwrap();
        for p in [Vec3::new(1000.0, 3000.0, -50.0), Vec3::new(7000.0, 1500.0, -50.0), Vec3::new(4000.0, 4500.0, -300.0)]
        {
            let v = speed_at(&s, p);
            assert!((v - ratio * vehicle).abs() < 1e-9, "ratio {ratio}: {v} at {p:?}");
        }
        // The same as the absolute form.
        let abs =
            Scenario::from_toml(&jet_scenario(&format!("speed = {}", ratio * vehicle), vehicle), "t.toml").unwrap();
        let p = Vec3::new(3333.0, 2222.0, -10.0);
        assert_eq!(s.world.current.velocity(p, 100.0), abs.world.current.velocity(p, 100.0));
    }
}

#[test]
fn max_speed_ratio_scales_the_fastest_point() {
    let s = Scenario::from_toml(&jet_scenario("max_speed_ratio = 1.2", 1.5), "t.toml").unwrap();
    let peak = s.world.current.max_speed_hint(&s.world.bounds, 0.0);
    assert!((peak - 1.8).abs() < 0.01 * 1.8, "peak {peak}");
}

#[test]
fn ratio_errors_name_the_field() {
    for (line, field) in [
        ("speed_ratio = -0.5", "world.current.speed_ratio"),
        ("max_speed_ratio = nan", "world.current.max_speed_ratio"),
        ("speed_ratio = 0.5\nspeed = 1.0", "world.current"),
    ] {
        let e = Scenario::from_toml(&jet_scenario(line, 1.5), "t.toml").unwrap_err().to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{line}: {e}");
    }
}
