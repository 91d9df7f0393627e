//! A fleet's separation and arrivals as the plan file and the summaries give them: the
//! closest pair of vehicles, every pair too close, and the spread of the arrivals.

use serde::{Deserialize, Serialize};

/// The fleet's separation, as the plan file gives it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FleetReport {
    /// The closest approach of any two vehicles (`null` when no two are in the water together).
    pub closest: Option<ApproachReport>,
    /// Pairs closer than their separation.
    pub conflicts: Vec<ApproachReport>,
    /// The arrivals: spread, first and last, and whether the fleet's rule holds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arrival: Option<ArrivalReport>,
    /// The fleet's cost terms (`separation`, `arrival`): what a joint optimizer adds to the
    /// missions' costs while a rule is broken; the plan's `cost` includes them.
    #[serde(default)]
    pub cost_terms: serde_json::Map<String, serde_json::Value>,
}

impl FleetReport {
    /// The sum of the fleet's cost terms.
    pub fn cost(&self) -> f64 {
        self.cost_terms.values().filter_map(|v| v.as_f64()).sum()
    }
}

/// A fleet's arrivals.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ArrivalReport {
    /// "free", "together within 60 s" or "order auv-a, auv-b, auv-c".
    pub rule: String,
    /// Last arrival minus first (s).
    pub spread_s: f64,
    pub first: String,
    pub first_s: f64,
    pub last: String,
    pub last_s: f64,
    /// Whether the arrivals keep the rule.
    pub kept: bool,
}

/// Two vehicles at their closest.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ApproachReport {
    /// The two missions' names.
    pub vehicles: [String; 2],
    pub distance_m: f64,
    pub time_s: f64,
    /// Where each vehicle is then.
    pub positions: [[f64; 3]; 2],
    /// The separation this pair must keep.
    pub separation_m: f64,
}

impl FleetReport {
    pub fn new(check: &tidepath::fleet::FleetCheck, rules: &tidepath::fleet::FleetRules, names: &[String]) -> Self {
        let approach = |a: usize, b: usize, x: &tidepath::fleet::Approach| ApproachReport {
            vehicles: [names[a].clone(), names[b].clone()],
            distance_m: x.distance,
            time_s: x.time,
            positions: [x.at_a.to_array(), x.at_b.to_array()],
            separation_m: rules.separation(a, b),
        };
        let rule = match &rules.arrival {
            tidepath::fleet::Arrival::Free => "free".to_string(),
            tidepath::fleet::Arrival::Together { tolerance_s } => format!("together within {tolerance_s} s"),
            tidepath::fleet::Arrival::Order(o) => {
                format!("order {}", o.iter().map(|&i| names[i].as_str()).collect::<Vec<_>>().join(", "))
            }
        };
        Self {
            closest: check.closest.as_ref().map(|(a, b, x)| approach(*a, *b, x)),
            conflicts: check.conflicts.iter().map(|c| approach(c.a, c.b, &c.approach)).collect(),
            arrival: check.arrival.as_ref().map(|a| ArrivalReport {
                rule,
                spread_s: a.spread_s,
                first: names[a.first.0].clone(),
                first_s: a.first.1,
                last: names[a.last.0].clone(),
                last_s: a.last.1,
                kept: a.broken.is_none(),
            }),
            cost_terms: check.terms().iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect(),
        }
    }

    /// One line for summaries: "closest approach 212.4 m (auv-a and auv-b at t = 812.3 s);
    /// separation kept" or "... 2 pairs closer than their separation".
    pub fn line(&self) -> String {
        let closest = match &self.closest {
            Some(c) => format!(
                "closest approach {:.1} m ({} and {} at t = {:.1} s)",
                c.distance_m, c.vehicles[0], c.vehicles[1], c.time_s
            ),
            None => "no two vehicles in the water at once".to_string(),
        };
        let separation = match self.conflicts.len() {
            0 => format!("{closest}; separation kept"),
            n => format!("{closest}; {n} pair(s) closer than their separation"),
        };
        let terms: Vec<String> =
            self.cost_terms.iter().map(|(k, v)| format!("{k} {:.4}", v.as_f64().unwrap_or(f64::NAN))).collect();
        let cost = format!("fleet cost {:.4} ({})", self.cost(), terms.join(", "));
        match &self.arrival {
            Some(a) => format!(
                "{separation}; arrivals spread over {:.1} s ({} first, {} last), {}: {}; {cost}",
                a.spread_s,
                a.first,
                a.last,
                a.rule,
                if a.kept { "kept" } else { "broken" }
            ),
            None => format!("{separation}; {cost}"),
        }
    }
}

/// One line on a path's segment speeds for `plan` and `eval`: slowest, fastest and the
/// length-weighted mean through the water ("0.41 to 2.06 m/s through the water, 1.12 m/s on
/// average over the length").
pub fn speeds_line(points: &[tidepath::geom::Vec3], speeds: &[f64]) -> String {
    let (mut lo, mut hi, mut len, mut weighted) = (f64::INFINITY, 0.0f64, 0.0, 0.0);
    for (w, &v) in points.windows(2).zip(speeds) {
        let l = w[0].distance(w[1]);
        (lo, hi, len, weighted) = (lo.min(v), hi.max(v), len + l, weighted + l * v);
    }
    let mean = if len > 0.0 { weighted / len } else { hi };
    format!("{lo:.2} to {hi:.2} m/s through the water, {mean:.2} m/s on average over the length")
}

#[cfg(test)]
mod tests {
    use tidepath::geom::Vec3;

    #[test]
    fn speeds_line_weights_the_mean_by_length() {
        let p = [Vec3::ZERO, Vec3::new(100.0, 0.0, 0.0), Vec3::new(100.0, 300.0, 0.0)];
        // (100 * 1 + 300 * 2) / 400 = 1.75
        assert_eq!(
            super::speeds_line(&p, &[1.0, 2.0]),
            "1.00 to 2.00 m/s through the water, 1.75 m/s on average over the length"
        );
    }
}
