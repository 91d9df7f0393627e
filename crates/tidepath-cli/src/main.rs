//! The `tidepath` command-line tool.
//!
//! Exit codes: 0 a plan that can be flown (status exact or feasible) or a command that
//! succeeded, 1 any other plan status (infeasible, timeout, invalid-start, invalid-goal,
//! unreachable), 2 bad input or usage, 130 interrupted by Ctrl-C (what finished is written).

mod commands;
mod progress;
mod usage;

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
    /// List planners, encodings, cost models and smoothers with their papers and parameters.
    Planners(commands::planners::PlannersArgs),
    /// List the vehicle kinds with their speed models (the wave glider's regression).
    Vehicles,
    /// Plan a route on a scenario and print a summary.
    Plan(commands::plan::PlanArgs),
    /// Fly a mission while the world changes (`[[changes]]`), re-planning a window of the route
    /// ahead with any planner; per-phase lines, a simulation JSON and a figure.
    Simulate(commands::simulate::SimulateArgs),
    /// Evaluate a plan JSON against a scenario: cost terms and feasibility.
    Eval(commands::eval::EvalArgs),
    /// Compare planners over many seeded runs: statistics, rank-sum marks, plots.
    Compare(commands::compare::CompareArgs),
    /// Join the folders of `compare --shard K/N` (a cluster job array) into what one compare
    /// writes: results.json, tables and figures.
    Merge(commands::merge::MergeArgs),
    /// Benchmark optimizers on the standard test functions.
    Bench(commands::bench::BenchArgs),
    /// Rerun a paper's experiments and set our numbers beside the paper's in REPORT.md.
    Reproduce(commands::reproduce::ReproduceArgs),
    /// Write an interactive 3-D view (one offline HTML file) of a scenario and any plans.
    View(commands::view::ViewArgs),
}

/// Most worker threads `--jobs` accepts: far more than any machine's cores, few enough that
/// starting them cannot exhaust the process's thread limit.
pub const MAX_JOBS: usize = 256;

/// Worker threads for `--jobs`: the given count, or every core.
pub fn jobs(requested: Option<usize>) -> Result<usize, tidepath::Error> {
    match requested {
        Some(0) => Err(tidepath::Error::input("--jobs", "must be at least 1, got 0")),
        Some(j) if j > MAX_JOBS => {
            Err(tidepath::Error::input("--jobs", format!("must be at most {MAX_JOBS}, got {j}")))
        }
        Some(j) => Ok(j),
        None => Ok(std::thread::available_parallelism().map_or(1, |n| n.get())),
    }
}

/// How a command ended, mapped to the documented exit codes.
pub enum Outcome {
    Success,
    Infeasible,
    /// A plan's status: 0 for exact or feasible, 1 otherwise.
    Status(tidepath::planner::Status),
    /// Stopped by Ctrl-C after writing what finished: exit 130.
    Interrupted,
}

/// True once Ctrl-C was pressed (the flag exists only after [`stop_flag`] was called).
pub fn interrupted() -> bool {
    stop_flag().load(std::sync::atomic::Ordering::Relaxed)
}

/// A second SIGINT within this time of the first is the same Ctrl-C: `timeout -s INT` (and a
/// shell killing a process group) delivers one interrupt twice, to the process and to its
/// group, microseconds apart; a person's second press comes later.
const SAME_INTERRUPT: std::time::Duration = std::time::Duration::from_millis(250);

/// The stop flag Ctrl-C raises: a running plan or experiment stops at its next check and
/// keeps what finished (stop reason `cancelled`, exit 130); a second Ctrl-C (at least
/// [`SAME_INTERRUPT`] later) ends the process at once, after any output commit in progress
/// (so no file is left half-written).
pub fn stop_flag() -> std::sync::Arc<std::sync::atomic::AtomicBool> {
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::{Arc, OnceLock};
    static FLAG: OnceLock<Arc<AtomicBool>> = OnceLock::new();
    static FIRST: OnceLock<std::time::Instant> = OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(false));
        let f = flag.clone();
        let _ = ctrlc::set_handler(move || {
            let first = *FIRST.get_or_init(std::time::Instant::now);
            if f.swap(true, Ordering::SeqCst) && first.elapsed() >= SAME_INTERRUPT {
                let _no_commit_in_progress = tidepath_io::output::commit_lock();
                std::process::exit(130);
            }
        });
        flag
    })
    .clone()
}

/// Parses the command line. Usage errors become one line on stderr (exit 2), like every other
/// input error; `--help` and `--version` print as usual.
fn parse() -> Result<Cli, ExitCode> {
    use clap::error::ErrorKind;
    Cli::try_parse().map_err(|e| match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = e.print();
            ExitCode::SUCCESS
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            ExitCode::from(2)
        }
        _ => {
            eprintln!("{}", usage::one_line(&e.render().to_string()));
            ExitCode::from(2)
        }
    })
}

fn main() -> ExitCode {
    // Piped into `head`, a closed pipe should end the program quietly, as for any Unix tool,
    // not panic in `println!`.
    #[cfg(unix)]
    // SAFETY: restoring the default action of SIGPIPE before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = match parse() {
        Ok(cli) => cli,
        Err(code) => return code,
    };
    // The Ctrl-C handler is in place before any work starts: a SIGINT that arrived before it
    // would end the process at once, with nothing written.
    let _ = stop_flag();
    let result = match cli.command {
        Command::Scenarios => commands::scenarios::list(),
        Command::Scenario(args) => commands::scenarios::show(&args),
        Command::Planners(args) => commands::planners::list(&args),
        Command::Vehicles => commands::vehicles::list(),
        Command::Plan(args) => commands::plan::run(&args),
        Command::Simulate(args) => commands::simulate::run(&args),
        Command::Eval(args) => commands::eval::run(&args),
        Command::Compare(args) => commands::compare::run(&args),
        Command::Merge(args) => commands::merge::run(&args),
        Command::Bench(args) => commands::bench::run(&args),
        Command::Reproduce(args) => commands::reproduce::run(&args),
        Command::View(args) => commands::view::run(&args),
    };
    match result {
        Ok(Outcome::Success) => ExitCode::SUCCESS,
        Ok(Outcome::Infeasible) => ExitCode::from(1),
        Ok(Outcome::Status(s)) => ExitCode::from(s.exit_code() as u8),
        Ok(Outcome::Interrupted) => ExitCode::from(130),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
