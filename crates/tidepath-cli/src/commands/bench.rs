use std::path::PathBuf;

use clap::{Args, Subcommand, ValueEnum};
use tidepath::optim::functions::Function;
use tidepath::Error;
use tidepath_experiments::compare::{compare_functions, FunctionProblem, RunBudget};
use tidepath_experiments::output;
use tidepath_experiments::runner::RunControl;
use tidepath_io::Outputs;

use crate::progress::RunsBar;
use crate::Outcome;

#[derive(Args)]
pub struct BenchArgs {
    #[command(subcommand)]
    pub what: BenchWhat,
}

#[derive(Subcommand)]
pub enum BenchWhat {
    /// Benchmark functions (Sphere, Rastrigin, ...): the optimizer tests of wpa2017 and amfa2015.
    Functions(FunctionsArgs),
}

#[derive(Clone, Copy, ValueEnum)]
pub enum RangeKind {
    /// The standard domain of each function.
    Standard,
    /// amfa2015 Table 1 (small ranges).
    Small,
    /// amfa2015 Table 3 (wide ranges).
    Wide,
    /// wpa2017 Table 2: each function's own dimension and range (overrides --dim).
    Wpa2017,
}

#[derive(Args)]
pub struct FunctionsArgs {
    /// Comma-separated optimizer ids; the first is the reference for the rank-sum marks.
    /// Optimizers: pso, ga, de, wpa, mwpa, fa, amfa, js, ijs, qpso, hho, mpa, lfhh, fhh,
    /// fhh-lts, eda-g, ade (`tidepath planners` describes them).
    #[arg(long, value_delimiter = ',', required = true)]
    pub algos: Vec<String>,
    /// Comma-separated functions: sphere, rosenbrock, rastrigin, griewank, ackley, zakharov, easom, trid, quadric.
    #[arg(long, value_delimiter = ',', required = true)]
    pub funcs: Vec<String>,
    /// Dimension (Easom is always 2).
    #[arg(long, default_value_t = 30)]
    pub dim: usize,
    /// Search range.
    #[arg(long, value_enum, default_value_t = RangeKind::Standard)]
    pub range: RangeKind,
    /// Population size for every optimizer (default: each optimizer's own).
    #[arg(long)]
    pub population: Option<usize>,
    /// A paper's parameter set for the optimizers it covers (`wpa2017`: Table 3 for mwpa, wpa,
    /// pso and ga; `lfhh2019`: Table 1 for lfhh, fhh, fhh-lts, eda-g and ade; `amfa2015`:
    /// section 5 for amfa, fa, pso (V_max half the box width) and ga; `amfa2015-vmax-range`: the
    /// same with PSO's V_max the whole width); the others keep their defaults. `--population`
    /// still overrides it.
    #[arg(long)]
    pub preset: Option<String>,
    /// Evaluations per run.
    #[arg(long, default_value_t = 60_000)]
    pub evaluations: u64,
    /// Wall-time limit per run in seconds (a safety net).
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Runs per pair.
    #[arg(long, default_value_t = 30)]
    pub runs: u64,
    /// Parallel runs (default: all cores). Results do not depend on it.
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Master seed; each run's seed is derived from it (printed per run in runs.csv), so the
    /// same seed repeats every run bit for bit.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write results.json, runs.csv, table.md, convergence.svg and boxplot.svg here.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

pub fn run(args: &BenchArgs) -> Result<Outcome, Error> {
    match &args.what {
        BenchWhat::Functions(f) => functions(f),
    }
}

/// Largest `--dim`: the benchmark functions' published settings go to 120.
pub const MAX_DIM: usize = 100_000;

fn functions(args: &FunctionsArgs) -> Result<Outcome, Error> {
    let jobs = crate::jobs(args.jobs)?;
    if args.dim == 0 || args.dim > MAX_DIM {
        return Err(Error::input("--dim", format!("must be in [1, {MAX_DIM}], got {}", args.dim)));
    }
    let mut problems = Vec::new();
    for name in &args.funcs {
        let function = Function::from_id(name).ok_or_else(|| {
            Error::input(
                "--funcs",
                format!(
                    "unknown function '{name}' (known: {})",
                    Function::ALL.iter().map(|f| f.id()).collect::<Vec<_>>().join(", ")
                ),
            )
        })?;
        let mut dim = function.fixed_dim().unwrap_or(args.dim);
        let (lo, hi, tag) = match args.range {
            RangeKind::Wpa2017 => {
                let (d, lo, hi) = function
                    .wpa2017_setting()
                    .ok_or_else(|| Error::input("--range", format!("wpa2017 gives no setting for {name}")))?;
                dim = d;
                (lo, hi, "wpa2017")
            }
            RangeKind::Standard => {
                let (lo, hi) = function.default_range(dim);
                (lo, hi, "standard")
            }
            RangeKind::Small => {
                let (lo, hi) = function
                    .small_range()
                    .ok_or_else(|| Error::input("--range", format!("amfa2015 gives no small range for {name}")))?;
                (lo, hi, "small")
            }
            RangeKind::Wide => {
                let (lo, hi) = function
                    .wide_range()
                    .ok_or_else(|| Error::input("--range", format!("amfa2015 gives no wide range for {name}")))?;
                (lo, hi, "wide")
            }
        };
        problems.push(FunctionProblem { function, dim, lower: lo, upper: hi, label: format!("{name}-d{dim}-{tag}") });
    }
    // Memory before any allocation: every optimizer's population times the largest dimension.
    let largest = problems.iter().map(|p| p.dim).max().unwrap_or(0);
    let preset = |id: &str| match &args.preset {
        Some(p) => tidepath::planner::presets::preset_params(p, id),
        None => Ok(None),
    };
    let factory = |id: &str| tidepath::planner::build_optimizer(id, preset(id)?.as_ref(), args.population);
    for id in &args.algos {
        let opt = factory(id)?;
        tidepath::optim::check_memory(opt.population(), largest)?;
    }
    let budget = RunBudget {
        evaluations: Some(args.evaluations),
        population: args.population,
        time_limit_s: args.time_limit,
        ..RunBudget::default()
    };
    tidepath_experiments::compare::check_runs(args.runs)?;
    tidepath::termination::check_count("--evaluations", args.evaluations)?;
    let figures = tidepath_plot::ExperimentFigures;
    let mut outputs = Outputs::new();
    if let Some(dir) = &args.out {
        output::declare_results(&mut outputs, "--out", dir, &figures, false)?;
    }
    let bar = RunsBar::new("bench", problems.len() * args.algos.len() * args.runs as usize);
    let stop = crate::stop_flag();
    let on_done = |n| bar.set(n);
    let control = RunControl { jobs, stop: Some(&stop), on_done: &on_done };
    let result = compare_functions(&problems, &args.algos, args.runs, args.seed, &budget, control, Some(&factory));
    bar.finish();
    let c = result?;
    if let Some(dir) = &args.out {
        output::stage_results(&mut outputs, "--out", dir, &c, None, &figures)?;
    }
    outputs.commit()?;
    println!(
        "{} runs per pair, {} evaluations each, master seed {}, {:.1} s\n",
        args.runs, args.evaluations, args.seed, c.total_wall_s
    );
    // The same text as table.md: the incomplete note, the table and its legend.
    print!("{}", output::table_md(&c));
    Ok(if c.complete { Outcome::Success } else { Outcome::Interrupted })
}
