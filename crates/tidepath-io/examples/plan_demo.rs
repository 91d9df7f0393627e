//! Plans the built-in `demo` scenario with every registered planner through the library API;
//! a planner that does not take this world (the visibility graph is 2-D only) says why.
//!
//! cargo run --release -p tidepath-io --example plan_demo

use tidepath::planner::PLANNERS;

use tidepath_io::scenario::{self, PlanRequest};

fn main() -> Result<(), tidepath::Error> {
    let scenario = scenario::load("demo")?;
    for info in PLANNERS {
        let request = PlanRequest { planner: Some(info.id.to_string()), seed: 7, parallel: true, ..Default::default() };
        let plan = match scenario.plan(&request, &mut |_| {}) {
            Ok(plan) => plan,
            Err(tidepath::Error::Input { message, .. }) => {
                println!("{:<10} not for this world: {message}", info.id);
                continue;
            }
            Err(e) => return Err(e),
        };
        println!(
            "{:<10} {:<10} cost {:.4}  length {:>8.0} m  travel time {:>7.0} s  {} evaluations",
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
