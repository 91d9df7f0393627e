//! The scenario file's `[fleet]` section: the separation a fleet's vehicles keep from each
//! other in time, and where a vehicle is outside its mission. Built into
//! `tidepath::fleet::FleetRules`, by mission name.

use serde::{Deserialize, Serialize};

use tidepath::error::{Error, Result};
use tidepath::fleet::{Arrival, FleetRules, Presence};
use tidepath::mission::Mission;

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FleetSpec {
    /// Least distance (m) between any two vehicles at the same moment, each on its own travel
    /// clock (default 0: not checked).
    #[serde(default)]
    pub separation_m: f64,
    /// "stays" (default): a vehicle waits at its start before departing and stays at its goal
    /// after arriving; "leaves": it is in the water only between departure and arrival.
    #[serde(default)]
    pub presence: PresenceId,
    /// Per-pair overrides: `{ vehicles = ["auv-a", "auv-b"], separation_m = 50.0 }`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pairs: Vec<PairSpec>,
    /// "free" (default), "together" (all arrivals within `arrival_tolerance_s`) or "order"
    /// (arrivals in the order of `arrival_order`, mission names). A vehicle arrives when it
    /// reaches its goal: waiting there is not arriving later.
    #[serde(default)]
    pub arrival: ArrivalId,
    /// Seconds between the first and the last arrival that "together" allows.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arrival_tolerance_s: Option<f64>,
    /// Mission names in the order "order" asks them to arrive.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub arrival_order: Vec<String>,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ArrivalId {
    #[default]
    Free,
    Together,
    Order,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PresenceId {
    #[default]
    Stays,
    Leaves,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PairSpec {
    /// The two missions' names.
    pub vehicles: [String; 2],
    pub separation_m: f64,
}

/// The rules of `spec` for `missions`; a warning when a separation is set for one vehicle.
pub fn build_fleet(spec: Option<&FleetSpec>, missions: &[Mission], warnings: &mut Vec<String>) -> Result<FleetRules> {
    let Some(spec) = spec else { return Ok(FleetRules::default()) };
    let index = |k: usize, name: &str| -> Result<usize> {
        missions.iter().position(|m| m.name == name).ok_or_else(|| {
            let names: Vec<&str> = missions.iter().map(|m| m.name.as_str()).collect();
            Error::input(
                format!("fleet.pairs[{k}].vehicles"),
                format!("no mission is named '{name}' (missions: {})", names.join(", ")),
            )
        })
    };
    let mut pairs = Vec::with_capacity(spec.pairs.len());
    for (k, p) in spec.pairs.iter().enumerate() {
        pairs.push((index(k, &p.vehicles[0])?, index(k, &p.vehicles[1])?, p.separation_m));
    }
    let presence = match spec.presence {
        PresenceId::Stays => Presence::Stays,
        PresenceId::Leaves => Presence::Leaves,
    };
    let name_index = |field: &str, name: &str| -> Result<usize> {
        missions.iter().position(|m| m.name == name).ok_or_else(|| {
            let names: Vec<&str> = missions.iter().map(|m| m.name.as_str()).collect();
            Error::input(field, format!("no mission is named '{name}' (missions: {})", names.join(", ")))
        })
    };
    let unused = |field: &str, present: bool, what: &str| -> Result<()> {
        match present {
            true => Err(Error::input(field, format!("is only read with arrival = \"{what}\""))),
            false => Ok(()),
        }
    };
    let arrival = match spec.arrival {
        ArrivalId::Free => {
            unused("fleet.arrival_tolerance_s", spec.arrival_tolerance_s.is_some(), "together")?;
            unused("fleet.arrival_order", !spec.arrival_order.is_empty(), "order")?;
            Arrival::Free
        }
        ArrivalId::Together => {
            unused("fleet.arrival_order", !spec.arrival_order.is_empty(), "order")?;
            let tolerance_s = spec.arrival_tolerance_s.ok_or_else(|| {
                Error::input("fleet.arrival_tolerance_s", "missing: arrival = \"together\" needs it (seconds)")
            })?;
            Arrival::Together { tolerance_s }
        }
        ArrivalId::Order => {
            unused("fleet.arrival_tolerance_s", spec.arrival_tolerance_s.is_some(), "together")?;
            if spec.arrival_order.len() < 2 {
                return Err(Error::input(
                    "fleet.arrival_order",
                    "arrival = \"order\" needs at least two mission names",
                ));
            }
            let order =
                spec.arrival_order.iter().map(|n| name_index("fleet.arrival_order", n)).collect::<Result<Vec<_>>>()?;
            Arrival::Order(order)
        }
    };
    let rules = FleetRules { separation_m: spec.separation_m, pairs, presence, arrival };
    rules.check(missions.len())?;
    if missions.len() < 2 && rules.active(2) {
        warnings.push(
            "fleet.separation_m: the scenario has one mission, so there is no other vehicle to keep apart from".into(),
        );
    }
    Ok(rules)
}

#[cfg(test)]
mod tests {
    use crate::scenario::Scenario;

    fn with_fleet(fleet: &str) -> Result<Scenario, String> {
        let text = crate::scenario::builtin("fleet-crossing")
            .unwrap()
            .replace("[fleet]\nseparation_m = 150.0", &format!("[fleet]\n{fleet}"));
        Scenario::from_toml(&text, "fleet.toml").map_err(|e| e.to_string())
    }

    #[test]
    fn pairs_are_named_by_mission_and_every_value_is_checked() {
        let s = with_fleet("separation_m = 100.0\npresence = \"leaves\"\npairs = [{ vehicles = [\"auv-north\", \"auv-east\"], separation_m = 40.0 }]").unwrap();
        assert_eq!(s.fleet.separation(0, 1), 40.0);
        assert_eq!(s.fleet.presence, tidepath::fleet::Presence::Leaves);
        let e =
            with_fleet("separation_m = 1.0\npairs = [{ vehicles = [\"auv-east\", \"glider\"], separation_m = 1.0 }]")
                .unwrap_err();
        assert!(e.contains("fleet.pairs[0].vehicles") && e.contains("'glider'"), "{e}");
        let e = with_fleet("separation_m = -1.0").unwrap_err();
        assert!(e.contains("fleet.separation_m"), "{e}");
        let e = with_fleet("separation_m = 1.0\npresence = \"floats\"").unwrap_err();
        assert!(e.contains("fleet.presence"), "{e}");
        let e =
            with_fleet("separation_m = 1.0\npairs = [{ vehicles = [\"auv-east\", \"auv-east\"], separation_m = 1.0 }]")
                .unwrap_err();
        assert!(e.contains("fleet.pairs[0]"), "{e}");
    }

    #[test]
    fn arrival_rules_read_by_name_and_refuse_what_they_do_not_use() {
        let s = with_fleet("arrival = \"order\"\narrival_order = [\"auv-north\", \"auv-east\"]").unwrap();
        assert_eq!(s.fleet.arrival, tidepath::fleet::Arrival::Order(vec![1, 0]));
        let s = with_fleet("arrival = \"together\"\narrival_tolerance_s = 30.0").unwrap();
        assert_eq!(s.fleet.arrival, tidepath::fleet::Arrival::Together { tolerance_s: 30.0 });
        for (text, field) in [
            ("arrival = \"together\"", "fleet.arrival_tolerance_s"),
            ("arrival = \"together\"\narrival_tolerance_s = -1.0", "fleet.arrival_tolerance_s"),
            ("arrival_tolerance_s = 30.0", "fleet.arrival_tolerance_s"),
            ("arrival = \"order\"\narrival_order = [\"auv-east\", \"x\"]", "fleet.arrival_order"),
            ("arrival = \"order\"\narrival_order = [\"auv-east\", \"auv-east\"]", "fleet.arrival_order"),
            ("arrival = \"order\"", "fleet.arrival_order"),
            ("arrival = \"soon\"", "fleet.arrival"),
        ] {
            let e = with_fleet(text).unwrap_err();
            assert!(e.contains(field), "{text}: {e}");
        }
    }

    #[test]
    fn a_scenario_without_a_fleet_section_checks_no_separation() {
        let s = crate::scenario::load("demo").unwrap();
        assert!(!s.fleet.active(s.missions.len()));
        assert!(!crate::scenario::builtin("demo").unwrap().contains("[fleet]"));
    }
}
