use clap::Args;
use tidepath::Error;
use tidepath_io::scenario::BUILTIN;

use crate::Outcome;

#[derive(Args)]
pub struct ShowArgs {
    /// Built-in scenario name (see `tidepath scenarios`).
    pub name: String,
}

pub fn list() -> Result<Outcome, Error> {
    let width = BUILTIN.iter().map(|e| e.id.len()).max().unwrap_or(0);
    for e in BUILTIN {
        println!("{:<width$}  {} [{}]", e.id, e.description, e.citation);
    }
    Ok(Outcome::Success)
}

pub fn show(args: &ShowArgs) -> Result<Outcome, Error> {
    let mut registry = tidepath_io::scenario::registry();
    registry.field = "NAME";
    print!("{}", registry.get(&args.name)?.build);
    Ok(Outcome::Success)
}
