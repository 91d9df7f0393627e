//! Flags that `plan` and `compare` share, declared once so they read the same everywhere.

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
    /// Population size (overrides the planners' parameters).
    #[arg(long)]
    pub population: Option<usize>,
    /// Worker threads (default: all cores). Results do not depend on it.
    #[arg(long)]
    pub jobs: Option<usize>,
}
