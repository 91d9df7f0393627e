//! Plans the built-in `demo` scenario with each available planner through the library API.
//!
//! cargo run --release -p tidepath --example plan_demo

use tidepath::planner::PLANNERS;

use tidepath_io::scenario::{self, PlanRequest};

fn main() -> Result<(), tidepath::Error> {
    let scenario = scenario::load("demo")?;
    for info in PLANNERS {
        let request = PlanRequest { planner: Some(info.id.to_string()), seed: 7, parallel: true, ..Default::default() };
        let plan = scenario.plan(&request, &mut |_| {})?;
        println!(
            "{:<4} {:<10} cost {:.4}  length {:>8.0} m  travel time {:>7.0} s  {} evaluations",
            plan.planner,
            plan.status,
            plan.cost_value(),
            plan.length_m().unwrap_or(f64::NAN),
            plan.travel_time_s().unwrap_or(f64::NAN),
            plan.evaluations
        );
    }
    Ok(())
}
