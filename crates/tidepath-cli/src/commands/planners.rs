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
    let w = id_width(r);
    for e in r.entries() {
        print_entry(e, params, w);
    }
    println!();
}

/// The column the descriptions start at: the longest id of the table.
fn id_width<B: Copy>(r: &Registry<B>) -> usize {
    r.entries().iter().map(|e| e.id.len()).max().unwrap_or(0).max(10)
}

fn print_entry<B: Copy>(e: &Entry<B>, params: bool, w: usize) {
    println!("  {:<w$} {} [{}]", e.id, e.description, e.citation);
    if params {
        print_params(e);
    }
}

/// Each parameter once: its range, its default and where it comes from, all read from its
/// one declaration.
fn print_params<B: Copy>(e: &Entry<B>) {
    for p in e.params {
        println!("      {:<22} {}", p.name, p.help());
        println!("      {:<22} {}; default {}; from {}", "", p.range, p.default_text(), p.source);
    }
}

pub fn list(args: &PlannersArgs) -> Result<Outcome, Error> {
    println!("Planners (plan --planner ID; parameters in [planner.params.ID]):");
    let planners = tidepath::planner::registry();
    let w = id_width(&planners);
    for e in planners.entries() {
        println!("  {:<w$} {} [{}]", e.id, e.description, e.citation);
        println!("  {:<w$} can: {}", "", e.build.caps);
        if args.params {
            print_params(e);
        }
    }
    println!();
    section("Encodings ([encoding] kind = \"ID\")", &tidepath::encoding::registry(), args.params);
    section(
        "Cost models ([cost] model = \"ID\"; parameters in [cost.weights])",
        &tidepath::cost::registry(),
        args.params,
    );
    section(
        "Smoothers (plan --smooth ID[:KEY=VALUE,...], or [planner] smoother = \"ID\" with [planner.smoother_params.ID])",
        &tidepath::smoothing::registry(),
        args.params,
    );
    section(
        "Repairs inside the search (plan --repair ID[:KEY=VALUE,...], or [encoding] repair = \"ID\" with [encoding.repair_params.ID]; \"none\": off)",
        &tidepath::repair::registry(),
        args.params,
    );
    if args.params {
        println!("`tidepath vehicles` lists the vehicle kinds and their speed models ([vehicle] keys).");
    } else {
        println!("`tidepath planners --params` lists every parameter with its range and default.");
    }
    Ok(Outcome::Success)
}
