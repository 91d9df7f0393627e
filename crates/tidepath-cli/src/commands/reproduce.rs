use std::path::PathBuf;

use clap::Args;
use tidepath::Error;
use tidepath_experiments::reproduce::{paper, reproduce, ClaimVerdict, ReproduceOptions, PAPERS, REPORT_FILE};
use tidepath_io::Outputs;

use crate::progress::RunsBar;
use crate::Outcome;

#[derive(Args)]
pub struct ReproduceArgs {
    /// Which paper's experiments to run (`wpa2017`, `lfhh2019`, `amfa2015`, `ijs2023`, `acopf2016`;
    /// `list` shows all).
    pub paper: String,
    /// Runs per planner and problem.
    #[arg(long, default_value_t = 30)]
    pub runs: u64,
    /// Master seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Wall-time limit per run in seconds (a safety net: runs it stops depend on the machine).
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Parallel runs (default: all cores). Results do not depend on it.
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Reference planner of experiments on scenarios, for the gap column (default: visibility
    /// where it applies, else theta-star; `none` for no reference). Benchmark-function
    /// experiments have a known optimum instead.
    #[arg(long)]
    pub reference: Option<String>,
    /// Output folder for REPORT.md, per-experiment results and figures.
    #[arg(long, default_value = "reproduce")]
    pub out: PathBuf,
    /// A reduced budget for a quick look (lfhh2019: a fifth of the generations, coarser sweeps;
    /// amfa2015: a fifth of the evaluations on the paths); the report states the budget it ran.
    #[arg(long)]
    pub quick: bool,
    /// Run only these parts of the paper, comma-separated (lfhh2019: table2, table3, ablation,
    /// sweeps, its full run takes hours; amfa2015: tables, paths; ijs2023: tables, fleet;
    /// acopf2016: figures, tables, ocean); default: all.
    #[arg(long, value_delimiter = ',')]
    pub only: Vec<String>,
}

pub fn run(args: &ReproduceArgs) -> Result<Outcome, Error> {
    if args.paper == "list" {
        for p in PAPERS {
            println!("{:<12} {} [{}]", p.id, p.description, p.citation);
        }
        return Ok(Outcome::Success);
    }
    let paper = &paper(&args.paper)?;
    if let Some(id) = args.reference.as_deref().filter(|id| *id != "none") {
        tidepath::planner::registry().get(id).map_err(|e| e.for_field("--reference"))?;
    }
    tidepath_experiments::reproduce::check_runs(args.runs)?;
    tidepath_experiments::reproduce::check_only(paper.id, &args.only)?;
    if let Some(t) = args.time_limit {
        tidepath::termination::check_wall_time("--time-limit", t)?;
    }
    let figures = tidepath_plot::ExperimentFigures;
    let mut outputs = Outputs::new();
    outputs.declare_in("--out", &args.out, REPORT_FILE)?;
    let opts = ReproduceOptions {
        runs: args.runs,
        master_seed: args.seed,
        jobs: crate::jobs(args.jobs)?,
        reference: args.reference.clone(),
        stop: Some(crate::stop_flag()),
        time_limit_s: args.time_limit,
        quick: args.quick,
        only: args.only.clone(),
    };
    let bar = std::sync::Mutex::new(None::<RunsBar>);
    let outcomes = reproduce(
        paper,
        &opts,
        &mut outputs,
        &args.out,
        &|done, total| {
            let mut b = bar.lock().expect("progress lock");
            b.get_or_insert_with(|| RunsBar::new(paper.id, total)).set(done);
        },
        &figures,
    );
    if let Some(b) = bar.into_inner().expect("progress lock") {
        b.finish();
    }
    let outcomes = outcomes?;
    outputs.commit()?;
    for o in &outcomes {
        let count = |f: fn(&ClaimVerdict) -> bool| o.claims.iter().filter(|(_, v)| f(v)).count();
        let ok = count(|v| matches!(v, ClaimVerdict::Reproduced { .. }));
        let undecidable = count(|v| matches!(v, ClaimVerdict::Undecidable { .. }));
        let mut line = format!("{}: {} of {} claims reproduced", o.title, ok, o.claims.len());
        if undecidable > 0 {
            line.push_str(&format!(", {undecidable} undecidable with {} runs", o.comparison.runs));
        }
        if let Some(n) = o.paper.runs.filter(|n| *n > o.comparison.runs) {
            line.push_str(&format!(" (the paper reports {n} runs)"));
        }
        println!("{line}");
    }
    println!("Wrote {}", args.out.join("REPORT.md").display());
    if crate::interrupted() {
        println!("Interrupted: the report is marked incomplete.");
        return Ok(Outcome::Interrupted);
    }
    Ok(Outcome::Success)
}
