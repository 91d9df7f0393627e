use tidepath::planner::PLANNERS;
use tidepath::Error;

use crate::Outcome;

pub fn list() -> Result<Outcome, Error> {
    for p in PLANNERS {
        println!("{:<10} {} [{}]", p.id, p.description, p.paper);
    }
    Ok(Outcome::Success)
}
