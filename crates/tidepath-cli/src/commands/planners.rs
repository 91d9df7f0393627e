use tidepath::planner::PLANNERS;
use tidepath::Error;

use crate::Outcome;

pub fn list() -> Result<Outcome, Error> {
    for p in PLANNERS {
        println!("{:<10} {} [{}]", p.id, p.description, p.paper);
    }
    println!("\nSmoothers (plan --smooth ID, or [planner] smoother = \"ID\"):");
    for (id, description) in tidepath::smoothing::SMOOTHERS {
        println!("{id:<10} {description}");
    }
    Ok(Outcome::Success)
}
