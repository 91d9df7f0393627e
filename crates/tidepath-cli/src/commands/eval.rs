use std::path::PathBuf;

use clap::Args;
use tidepath::io::PlanFile;
use tidepath::scenario;
use tidepath::Error;

use crate::Outcome;

#[derive(Args)]
pub struct EvalArgs {
    /// A built-in scenario name or a scenario TOML file.
    pub scenario: String,
    /// A plan JSON (as written by `tidepath plan --out`); only `waypoints` is required.
    pub plan: PathBuf,
}

pub fn run(args: &EvalArgs) -> Result<Outcome, Error> {
    let scenario = scenario::load(&args.scenario)?;
    let plan = PlanFile::read(&args.plan)?;
    let points = plan.points();
    let eval = scenario.evaluate(&points)?;

    println!("{} — {} ({} waypoints)", scenario.name, args.plan.display(), points.len());
    if points.first() != Some(&scenario.start) || points.last() != Some(&scenario.goal) {
        println!("  note: the path does not start and end at this scenario's start and goal");
    }
    println!("  cost terms ({} model):", scenario.cost.model);
    for (name, value) in &eval.terms {
        println!("    {name:<12} {value:>14.9}");
    }
    println!("    {:<12} {:>14.9}", "total", eval.cost);
    if let Some(recorded) = plan.cost {
        let rel = (eval.cost - recorded).abs() / recorded.abs().max(f64::MIN_POSITIVE);
        println!("  recorded cost {recorded:.9}; relative difference {rel:.2e}");
    }
    let m = &eval.metrics;
    let clearance = m.min_clearance_m.map_or("n/a".to_string(), |c| format!("{c:.1} m"));
    println!(
        "  length {:.1} m; travel time {:.1} s; max turn {:.1} deg; max pitch {:.1} deg; min clearance {clearance}",
        m.length_m, m.travel_time_s, m.max_turn_deg, m.max_pitch_deg
    );
    if eval.feasible {
        println!("  verdict: feasible");
        Ok(Outcome::Success)
    } else {
        println!("  verdict: NOT feasible, {} violation(s):", eval.violations.len());
        for v in &eval.violations {
            println!("    - {}", v.message);
        }
        Ok(Outcome::Infeasible)
    }
}
