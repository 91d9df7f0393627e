//! Scenarios embedded in the binary, so a newcomer can plan without writing a file.

/// (name, TOML text).
pub const BUILTIN: &[(&str, &str)] =
    &[("demo", include_str!("../../scenarios/demo.toml")), ("salish", include_str!("../../scenarios/salish.toml"))];

pub fn builtin(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

pub fn builtin_names() -> impl Iterator<Item = &'static str> {
    BUILTIN.iter().map(|(n, _)| *n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{PlanRequest, Scenario};

    #[test]
    fn every_builtin_scenario_loads_and_plans() {
        for (name, text) in BUILTIN {
            let s = Scenario::from_toml(text, name).unwrap_or_else(|e| panic!("{name}: {e}"));
            let req = PlanRequest { iterations: Some(3), ..PlanRequest::default() };
            let r = s.plan(&req, &mut |_| {}).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(r.missions[0].waypoints.len(), s.encoding.waypoints + 2, "{name}");
        }
    }
}
