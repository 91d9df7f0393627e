//! `tidepath vehicles`: the speed model of each vehicle kind, read by a user before choosing
//! one; the wave glider's regression (acopf2016 eqs. 1-2) with its keys, defaults and ranges.

use super::tidepath;

#[test]
fn vehicles_lists_the_glider_regression_with_its_keys() {
    let o = tidepath(&["vehicles"], &[]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8(o.stdout).unwrap();
    // Both kinds, each leading its line.
    for id in ["auv", "wave-glider"] {
        assert!(out.lines().any(|l| l.split_whitespace().next() == Some(id)), "{id} missing: {out}");
    }
    // The formula as the core writes it, with eq. 1's coefficients.
    assert!(out.contains("speed over ground = max(0.05, 0.1623 H + 0.266 c_along) m/s"), "{out}");
    // Each key with its range and default on the line after its help.
    for (key, range, default) in [
        ("wave_gain", "in [0, 10]", "0.1623"),
        ("current_gain", "in [0, 10]", "0.266"),
        ("min_speed", "in (0, 5]", "0.05"),
    ] {
        let mut lines = out.lines().skip_while(|l| l.split_whitespace().next() != Some(key));
        assert!(lines.next().is_some(), "{key} missing: {out}");
        let facts = lines.next().unwrap_or_default();
        assert!(facts.contains(&format!("{range}; default {default};")), "{key}: {facts}");
    }
    // The travel models an AUV's speed combines with the current by, and the paper's misprint.
    assert!(out.contains("\"crab\" or \"vector-sum\""), "{out}");
    assert!(out.contains("0.2260") && out.contains("misprint"), "{out}");
}

#[test]
fn vehicles_has_help_and_planners_points_to_it() {
    let o = tidepath(&["vehicles", "--help"], &[]);
    assert_eq!(o.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&o.stdout).contains("Usage: tidepath vehicles"));
    let o = tidepath(&["planners", "--params"], &[]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.trim_end().lines().last().is_some_and(|l| l.contains("`tidepath vehicles`")), "{out}");
}
