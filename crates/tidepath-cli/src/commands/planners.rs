//! `tidepath planners`: every registry table, read from the tables themselves.

use clap::Args;
use tidepath::registry::{Entry, Registry};
use tidepath::Error;

use crate::Outcome;

#[derive(Args)]
pub struct PlannersArgs {
    /// Also list each component's parameters with their ranges and defaults.
    #[arg(long)]
    pub params: bool,
}

fn section<B: Copy>(title: &str, r: &Registry<B>, params: bool) {
    println!("{title}:");
    for e in r.entries() {
        print_entry(e, params);
    }
    println!();
}

fn print_entry<B: Copy>(e: &Entry<B>, params: bool) {
    println!("  {:<10} {} [{}]", e.id, e.description, e.citation);
    if params {
        let defaults = (e.defaults)();
        for p in e.params {
            let d = defaults.get(p.name).map_or("none".to_string(), |v| v.to_string());
            println!("      {:<22} {} (default {d}; {})", p.name, p.help, p.range);
        }
    }
}

pub fn list(args: &PlannersArgs) -> Result<Outcome, Error> {
    section(
        "Planners (plan --planner ID; parameters in [planner.params.ID])",
        &tidepath::planner::registry(),
        args.params,
    );
    section("Encodings ([encoding] kind = \"ID\")", &tidepath::encoding::registry(), args.params);
    section(
        "Cost models ([cost] model = \"ID\"; parameters in [cost.weights])",
        &tidepath::cost::registry(),
        args.params,
    );
    section(
        "Smoothers (plan --smooth ID, or [planner] smoother = \"ID\")",
        &tidepath::smoothing::registry(),
        args.params,
    );
    if !args.params {
        println!("`tidepath planners --params` lists every parameter with its range and default.");
    }
    Ok(Outcome::Success)
}
