use clap::Args;
use tidepath::scenario::{builtin, builtin_names, ScenarioSpec, BUILTIN};
use tidepath::Error;

use crate::Outcome;

#[derive(Args)]
pub struct ShowArgs {
    /// Built-in scenario name (see `tidepath scenarios`).
    pub name: String,
}

pub fn list() -> Result<Outcome, Error> {
    for (name, text) in BUILTIN {
        let spec: ScenarioSpec = tidepath::scenario::parse_toml(text, name)?;
        println!("{name:<12} {}", spec.description);
    }
    Ok(Outcome::Success)
}

pub fn show(args: &ShowArgs) -> Result<Outcome, Error> {
    let text = builtin(&args.name).ok_or_else(|| {
        Error::input(
            "NAME",
            format!("no built-in scenario '{}' (known: {})", args.name, builtin_names().collect::<Vec<_>>().join(", ")),
        )
    })?;
    print!("{text}");
    Ok(Outcome::Success)
}
