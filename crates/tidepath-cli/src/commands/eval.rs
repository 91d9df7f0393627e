use std::path::PathBuf;

use clap::Args;
use tidepath::Error;
use tidepath_io::scenario;

use crate::Outcome;

#[derive(Args)]
pub struct EvalArgs {
    /// A built-in scenario name or a scenario TOML file.
    pub scenario: String,
    /// The routes: a plan JSON (as written by `tidepath plan --out`, any format version; a
    /// hand-written one needs only `waypoints` or `missions[].waypoints`, and `"frame":
    /// "lonlat"` for [longitude, latitude, depth] points) or an export as written or edited in
    /// GIS tools (.geojson, .gpx, .kml, .csv); one route per mission, in order. Times in the
    /// file are ignored: routes are flown on the scenario's clock.
    pub plan: PathBuf,
}

/// Most violations listed per mission: a hostile plan can have hundreds of thousands.
const MAX_LISTED: usize = 100;

pub fn run(args: &EvalArgs) -> Result<Outcome, Error> {
    let scenario = scenario::load(&args.scenario)?;
    let plan = tidepath_io::routes::read(&args.plan)?;
    let paths = scenario.route_paths(&plan, &args.plan.display().to_string())?;
    let judged = scenario.evaluate_routes(&paths, &plan.speeds)?;

    let what = match plan.format {
        "plan JSON" => format!("plan format version {}", plan.version),
        other => format!("{other}; its times, if any, ignored"),
    };
    println!("{} — {} ({what})", scenario.name, args.plan.display());
    // The cost model's own feasibility rule, printed beside tidepath's verdict.
    let rule_below = scenario.cost_model()?.feasible_below();
    let mut total = 0.0;
    let several = judged.len() > 1;
    for (k, m) in judged.iter().enumerate() {
        total += m.cost;
        let radius = scenario.missions.get(k).map_or(scenario.vehicle.turn_radius, |v| v.vehicle.turn_radius);
        let indent = if several { "    " } else { "  " };
        if several {
            println!("  mission {} ({} waypoints):", m.name, m.waypoints.len());
        } else {
            println!("  {} waypoints", m.waypoints.len());
        }
        println!("{indent}cost terms ({} model):", scenario.cost.model);
        for (name, value) in &m.terms {
            println!("{indent}  {name:<12} {value:>14.9}");
        }
        println!("{indent}  {:<12} {:>14.9}", "total", m.cost);
        if let Some(x) = &m.metrics {
            let clearance = x.min_clearance_m.map_or("n/a".to_string(), |c| format!("{c:.1} m"));
            let arrival = m.times.last().copied().unwrap_or(f64::NAN);
            let utc = tidepath_io::export::utc(scenario.epoch, arrival).map_or(String::new(), |u| format!(", {u}"));
            println!(
                "{indent}length {:.1} m; travel time {:.1} s (arrives at t = {arrival:.1} s{utc}); max turn {:.1} deg; max pitch {:.1} deg; min clearance {clearance}",
                x.length_m,
                x.travel_time_s,
                x.max_turn_deg,
                x.max_pitch_deg
            );
            if let Some(line) = radius.and_then(|r| super::plan::turns_line(x, r)) {
                println!("{indent}turns: {line}");
            }
            if let Some(v) = &m.speeds {
                println!("{indent}speeds: {}", tidepath_io::fleet_report::speeds_line(m.path(), v));
            }
        }
        if m.feasible {
            println!("{indent}verdict: feasible");
        } else {
            println!("{indent}verdict: NOT feasible, {} violation(s):", m.violations.len());
            for v in m.violations.iter().take(MAX_LISTED) {
                println!("{indent}  - {}", v.message);
            }
            if m.violations.len() > MAX_LISTED {
                println!("{indent}  ... and {} more", m.violations.len() - MAX_LISTED);
            }
        }
        if let Some(below) = rule_below {
            let rule = tidepath_io::plan_json::ModelRule::of(below, m.cost);
            let verdict = if rule.met { "met" } else { "not met" };
            println!("{indent}{} rule: F < {below}: {verdict} (F = {:.9})", scenario.cost.model, m.cost);
        }
    }
    if several {
        println!("  total cost {total:.9}");
    }
    if let Some(check) = scenario.fleet_check(&judged) {
        let names: Vec<String> = judged.iter().map(|m| m.name.clone()).collect();
        println!("  fleet: {}", tidepath_io::FleetReport::new(&check, &scenario.fleet, &names).line());
        // The plan's cost includes the fleet's terms.
        total += check.penalty();
        println!("  total cost with the fleet's terms {total:.9}");
    }
    if let Some(recorded) = plan.cost {
        let rel = (total - recorded).abs() / recorded.abs().max(f64::MIN_POSITIVE);
        println!("  recorded cost {recorded:.9}; relative difference {rel:.2e}");
    }
    let feasible = judged.iter().all(|m| m.feasible);
    Ok(if feasible { Outcome::Success } else { Outcome::Infeasible })
}
