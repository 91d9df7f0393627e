//! The `tidepath` command-line tool.
//!
//! Exit codes: 0 success, 1 no feasible plan found, 2 bad input or usage.

mod commands;
mod progress;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "tidepath",
    version,
    about = "Plan safe, fast, energy-aware routes for marine robots and compare planners."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// List the built-in scenarios, one line each.
    Scenarios,
    /// Print a built-in scenario's TOML, to copy and edit.
    Scenario(commands::scenarios::ShowArgs),
    /// List planner ids with a one-line description and their paper.
    Planners,
    /// Plan a route on a scenario and print a summary.
    Plan(commands::plan::PlanArgs),
    /// Evaluate a plan JSON against a scenario: cost terms and feasibility.
    Eval(commands::eval::EvalArgs),
    /// Compare planners over many seeded runs: statistics, rank-sum marks, plots.
    Compare(commands::compare::CompareArgs),
    /// Benchmark optimizers on the standard test functions.
    Bench(commands::bench::BenchArgs),
    /// Rerun a paper's experiments and set our numbers beside the paper's in REPORT.md.
    Reproduce(commands::reproduce::ReproduceArgs),
}

/// Worker threads for `--jobs`: the given count, or every core.
pub fn jobs(requested: Option<usize>) -> Result<usize, tidepath::Error> {
    match requested {
        Some(0) => Err(tidepath::Error::input("--jobs", "must be at least 1, got 0")),
        Some(j) => Ok(j),
        None => Ok(std::thread::available_parallelism().map_or(1, |n| n.get())),
    }
}

/// How a command ended, mapped to the documented exit codes.
pub enum Outcome {
    Success,
    Infeasible,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Scenarios => commands::scenarios::list(),
        Command::Scenario(args) => commands::scenarios::show(&args),
        Command::Planners => commands::planners::list(),
        Command::Plan(args) => commands::plan::run(&args),
        Command::Eval(args) => commands::eval::run(&args),
        Command::Compare(args) => commands::compare::run(&args),
        Command::Bench(args) => commands::bench::run(&args),
        Command::Reproduce(args) => commands::reproduce::run(&args),
    };
    match result {
        Ok(Outcome::Success) => ExitCode::SUCCESS,
        Ok(Outcome::Infeasible) => ExitCode::from(1),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
