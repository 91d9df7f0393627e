//! Flags that `plan` and `compare` share, declared once so they read the same everywhere.
//! A limit in a unit a planner does not count is refused for that planner, naming the flag.

use clap::Args;

#[derive(Args)]
pub struct BudgetArgs {
    /// Master seed; the same seed reproduces a run bit for bit.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Iteration budget per run (overrides the scenario).
    #[arg(long)]
    pub iterations: Option<u64>,
    /// Evaluation budget per run (overrides the scenario).
    #[arg(long)]
    pub evaluations: Option<u64>,
    /// Node expansions per run, for graph planners (overrides the scenario).
    #[arg(long)]
    pub expansions: Option<u64>,
    /// Samples per run, for sampling planners (overrides the scenario).
    #[arg(long)]
    pub samples: Option<u64>,
    /// Stop a run once its best cost is at most this (overrides the scenario).
    #[arg(long, allow_hyphen_values = true)]
    pub target_cost: Option<f64>,
    /// Population size (overrides the planners' parameters).
    #[arg(long)]
    pub population: Option<usize>,
    /// Worker threads (default: all cores). Results do not depend on it.
    #[arg(long)]
    pub jobs: Option<usize>,
}

impl BudgetArgs {
    /// These limits as an experiment's budget, with `time_limit_s` (no smoother: `--smooth` is
    /// its own flag).
    pub fn budget(&self, time_limit_s: Option<f64>) -> tidepath_experiments::compare::RunBudget {
        tidepath_experiments::compare::RunBudget {
            iterations: self.iterations,
            evaluations: self.evaluations,
            expansions: self.expansions,
            samples: self.samples,
            target_cost: self.target_cost,
            population: self.population,
            time_limit_s,
            smoother: None,
        }
    }
}

/// `--smooth`, shared by `plan` and `compare` so that it reads and parses the same in both.
#[derive(Args)]
pub struct SmoothArgs {
    /// Smooth every planned path: a smoother id with optional parameters, `ID[:KEY=VALUE,...]`
    /// (e.g. `shortcut:passes=3`), or `none` to override the scenario's smoother.
    #[arg(long)]
    pub smooth: Option<String>,
}

impl SmoothArgs {
    /// The smoother id and its parameters, when `--smooth` was given.
    pub fn parsed(&self) -> Result<Option<(String, Option<toml::Table>)>, tidepath::Error> {
        self.smooth.as_deref().map(parse_smooth).transpose()
    }
}

/// `--repair`, shared by `plan` and `compare`: the repair optimizer planners apply to every
/// candidate path inside their search.
#[derive(Args)]
pub struct RepairArgs {
    /// Repair every candidate path inside optimizer planners' search (overrides the
    /// scenario's `[encoding] repair`): a repair id with optional parameters,
    /// `ID[:KEY=VALUE,...]` (e.g. `exclude-contract:margin=5`), or `none`. Default: the
    /// optimizer's own (AMFA: `exclude-contract`), else none. See `tidepath planners`.
    #[arg(long)]
    pub repair: Option<String>,
}

impl RepairArgs {
    /// Writes `--repair` into the scenario's `[encoding]`, after checking the id and its
    /// parameters (a bad id names `--repair`, a bad parameter its `encoding.repair_params`
    /// field).
    pub fn apply(&self, encoding: &mut tidepath::encoding::EncodingSpec) -> Result<(), tidepath::Error> {
        let Some(text) = self.repair.as_deref() else { return Ok(()) };
        let (id, params) = parse_id_params(text, "--repair", "--repair exclude-contract:margin=5")?;
        if id == "none" {
            if params.is_some() {
                return Err(tidepath::Error::input("--repair", "`none` takes no parameters"));
            }
        } else {
            tidepath::repair::registry().get(&id).map_err(|e| e.for_field("--repair"))?;
            tidepath::repair::build_repair(&id, params.as_ref())?;
        }
        if let Some(t) = params {
            encoding.repair_params.insert(id.clone(), t);
        }
        encoding.repair = Some(id);
        Ok(())
    }
}

/// Parses `--smooth ID[:KEY=VALUE,...]` into the smoother id and its parameter table (values
/// as TOML would read them: `passes=3`, `radius=25.5`, `mode="fast"`).
pub fn parse_smooth(text: &str) -> Result<(String, Option<toml::Table>), tidepath::Error> {
    parse_id_params(text, "--smooth", "--smooth shortcut:passes=3")
}

/// Parses `ID[:KEY=VALUE,...]` given to `flag` (errors name it and show `example`).
fn parse_id_params(text: &str, flag: &str, example: &str) -> Result<(String, Option<toml::Table>), tidepath::Error> {
    let Some((id, rest)) = text.split_once(':') else {
        return Ok((text.to_string(), None));
    };
    let mut table = toml::Table::new();
    for pair in rest.split(',').filter(|p| !p.trim().is_empty()) {
        let (k, v) = pair
            .split_once('=')
            .ok_or_else(|| tidepath::Error::input(flag, format!("`{pair}` is not KEY=VALUE (e.g. {example})")))?;
        let parsed: toml::Table = toml::from_str(&format!("v = {}", v.trim())).map_err(|_| {
            tidepath::Error::input(flag, format!("`{}` is not a value (a number, true/false or \"text\")", v.trim()))
        })?;
        table.insert(k.trim().to_string(), parsed["v"].clone());
    }
    Ok((id.to_string(), Some(table)))
}
