use std::path::PathBuf;

use clap::Args;
use tidepath::Error;
use tidepath_experiments::compare::{compare_share, default_reference, request, Comparison, RunBudget, Smoothing};
use tidepath_experiments::output;
use tidepath_experiments::runner::RunControl;
use tidepath_experiments::shard::{ShardFile, ShardInfo, Share};
use tidepath_io::scenario;
use tidepath_io::Outputs;

use crate::progress::RunsBar;
use crate::Outcome;

#[derive(Args)]
pub struct CompareArgs {
    /// A built-in scenario name or a scenario TOML file.
    pub scenario: String,
    /// Comma-separated planner ids; the first is the reference for the rank-sum marks.
    #[arg(long, value_delimiter = ',', required = true)]
    pub planners: Vec<String>,
    /// Runs per planner.
    #[arg(long, default_value_t = 30)]
    pub runs: u64,
    #[command(flatten)]
    pub run: super::budget::BudgetArgs,
    #[command(flatten)]
    pub smoothing: super::budget::SmoothArgs,
    #[command(flatten)]
    pub repairing: super::budget::RepairArgs,
    /// Wall-time limit per run in seconds (a safety net: runs it stops depend on the machine).
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Write results.json, runs.csv, table.md, convergence.svg, boxplot.svg and paths.svg here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Reference planner for the gap column (percent above its cost); `none` for no reference.
    /// Default: `visibility` where it applies, else `theta-star`.
    #[arg(long)]
    pub reference: Option<String>,
    /// Write an interactive 3-D view here (.html, opens offline) with the best path of each
    /// planner (lowest cost over its runs), judged again on the scenario.
    #[arg(long, conflicts_with = "shard")]
    pub view: Option<PathBuf>,
    /// Also write an OMPL benchmark log (load it with `ompl_benchmark_statistics`).
    #[arg(long, conflicts_with = "shard")]
    pub ompl_log: Option<PathBuf>,
    /// Run only the K-th of N shares of the runs (run i goes to share (i mod N) + 1; seeds as
    /// without it) and write just results.json to --out; `tidepath merge` joins the N folders
    /// into what one compare writes. For cluster job arrays.
    #[arg(long, value_name = "K/N", requires = "out")]
    pub shard: Option<String>,
}

pub fn run(args: &CompareArgs) -> Result<Outcome, Error> {
    let share = args.shard.as_deref().map(Share::parse).transpose()?;
    // A shard records where its scenario is, for `merge` to draw it from any folder.
    let source = match share {
        Some(_) if scenario::builtin(&args.scenario).is_none() => absolute(&args.scenario),
        _ => args.scenario.clone(),
    };
    let mut scenario = scenario::load(&source)?;
    args.repairing.apply(&mut scenario.encoding)?;
    let jobs = crate::jobs(args.run.jobs)?;
    tidepath_experiments::compare::check_runs(args.runs)?;
    let mut budget = args.run.budget(args.time_limit);
    budget.smoother = args.smoothing.parsed()?.map(|(id, params)| Smoothing { id, params });
    if let Some(id) = budget.smoother.as_ref().map(|s| s.id.as_str()).filter(|id| *id != "none") {
        tidepath::smoothing::registry().get(id).map_err(|e| e.for_field("--smooth"))?;
    }
    let reference = match args.reference.as_deref() {
        Some("none") => None,
        Some(id) => Some(id.to_string()),
        None => Some(default_reference(&scenario).to_string()),
    };
    // Every planner, the reference and every output target are checked before the first run.
    for p in &args.planners {
        tidepath::planner::registry().get(p).map_err(|e| e.for_field("--planners"))?;
        scenario.check_request(&request(&budget, p, args.run.seed))?;
    }
    if let Some(id) = &reference {
        let r = RunBudget { time_limit_s: budget.time_limit_s, ..RunBudget::default() };
        scenario.check_request(&request(&r, id, args.run.seed)).map_err(|e| e.for_field("--reference"))?;
    }
    let figures = tidepath_plot::ExperimentFigures;
    let mut outputs = Outputs::new();
    // A shard writes only results.json (see `tidepath_experiments::shard`).
    if let Some(dir) = &args.out {
        match share {
            None => output::declare_results(&mut outputs, "--out", dir, &figures, true)?,
            Some(_) => {
                outputs.declare_in("--out", dir, "results.json")?;
            }
        }
    }
    let ompl_id = args.ompl_log.as_deref().map(|p| outputs.declare("--ompl-log", p)).transpose()?;
    let view_id = args.view.as_deref().map(|p| tidepath_view::declare_output(&mut outputs, "--view", p)).transpose()?;

    let all = args.planners.len() * args.runs as usize;
    let total = share.map_or(all, |s| s.size(all));
    let bar = RunsBar::new("compare", total);
    let stop = crate::stop_flag();
    let on_done = |n| bar.set(n);
    let control = RunControl { jobs, stop: Some(&stop), on_done: &on_done };
    let (planners, seed) = (&args.planners, args.run.seed);
    let result = compare_share(&scenario, planners, args.runs, seed, &budget, control, reference.as_deref(), share);
    bar.finish();
    let c = result?;
    if let (Some(share), Some(dir)) = (share, &args.out) {
        return write_shard(outputs, dir, share, c, &scenario);
    }
    if let Some(dir) = &args.out {
        output::stage_results(&mut outputs, "--out", dir, &c, Some(&scenario), &figures)?;
    }
    if let Some(id) = ompl_id {
        outputs.fill(id, output::ompl_log_text(&c));
    }
    if let Some(id) = view_id {
        let routes = super::view::comparison_routes(&scenario, &c)?;
        let title = format!("{} — best path of each planner over {} runs, master seed {}", scenario.name, c.runs, seed);
        let input =
            tidepath_view::ViewInput { scenario: &scenario, title, routes, simulation: None, simulation_mission: 0 };
        match super::view::build(&input) {
            Some(html) => outputs.fill(id, html),
            None => return Ok(Outcome::Interrupted),
        }
    }
    outputs.commit()?;
    println!(
        "{} — {} runs per planner, master seed {}, {:.1} s\n",
        scenario.name, args.runs, args.run.seed, c.total_wall_s
    );
    // The same text as table.md: the incomplete note, the reference, the smoother, the table
    // and its legend.
    print!("{}", output::table_md(&c));
    if let Some(dir) = &args.out {
        println!(
            "\nWrote {}/{{results.json, runs.csv, table.md, convergence.svg, boxplot.svg, paths.svg}}",
            dir.display()
        );
    }
    Ok(if c.complete { Outcome::Success } else { Outcome::Interrupted })
}

/// `path` made absolute (as given when it cannot be resolved: loading it then says why).
fn absolute(path: &str) -> String {
    std::fs::canonicalize(path).map_or_else(|_| path.to_string(), |p| p.display().to_string())
}

/// Writes a shard's results.json (its comparison and `shard` block) into `dir` and says so.
fn write_shard(
    mut outputs: Outputs,
    dir: &std::path::Path,
    share: Share,
    c: Comparison,
    scenario: &scenario::Scenario,
) -> Result<Outcome, Error> {
    let file = ShardFile { shard: Some(ShardInfo::new(share, &c, scenario)), comparison: c };
    outputs.stage_in("--out", dir, "results.json", file.json().as_bytes())?;
    outputs.commit()?;
    let c = &file.comparison;
    println!(
        "{} — shard {share}: {} of {} runs, master seed {}, {:.1} s\nWrote {}; join the {} shards with \
         `tidepath merge DIR... --out OUT`",
        scenario.name,
        c.finished_runs,
        share.size(c.planned_runs()),
        c.master_seed,
        c.total_wall_s,
        dir.join("results.json").display(),
        share.n
    );
    Ok(if c.complete { Outcome::Success } else { Outcome::Interrupted })
}
