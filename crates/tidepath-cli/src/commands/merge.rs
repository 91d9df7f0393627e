//! `tidepath merge`: joins the folders of `compare --shard K/N` into what one `compare` writes.

use std::path::{Path, PathBuf};

use clap::Args;
use tidepath::Error;
use tidepath_experiments::output;
use tidepath_experiments::shard::{merge, ShardFile, ShardResults};
use tidepath_io::scenario;
use tidepath_io::Outputs;

use crate::Outcome;

/// Most bytes of a shard's results.json: every run's path and convergence history, for up to
/// `compare`'s limit of runs.
const MAX_RESULTS_BYTES: u64 = 4 << 30;

#[derive(Args)]
pub struct MergeArgs {
    /// The shards' folders (`compare --shard K/N --out DIR`), all N of one compare, any order.
    #[arg(required = true, value_name = "DIR")]
    pub dirs: Vec<PathBuf>,
    /// Write results.json, runs.csv, table.md, convergence.svg, boxplot.svg and paths.svg here,
    /// as one compare --out does.
    #[arg(long)]
    pub out: PathBuf,
    /// The scenario, when the one the shards recorded (a built-in name or a file's path) is not
    /// at hand; it must be the same (its fingerprint is checked).
    #[arg(long)]
    pub scenario: Option<String>,
    /// Also write an OMPL benchmark log (load it with `ompl_benchmark_statistics`).
    #[arg(long)]
    pub ompl_log: Option<PathBuf>,
}

pub fn run(args: &MergeArgs) -> Result<Outcome, Error> {
    // Every output target is checked before anything is read; nothing is written unless the
    // shards join.
    let figures = tidepath_plot::ExperimentFigures;
    let mut outputs = Outputs::new();
    output::declare_results(&mut outputs, "--out", &args.out, &figures, true)?;
    let ompl_id = args.ompl_log.as_deref().map(|p| outputs.declare("--ompl-log", p)).transpose()?;
    let shards = args.dirs.iter().map(|d| read(d, &args.out)).collect::<Result<Vec<_>, _>>()?;
    let (c, info) = merge(&shards)?;
    let (source, field) = match &args.scenario {
        Some(s) => (s.as_str(), "--scenario"),
        None => (info.scenario_argument(), "DIR"),
    };
    let scenario = scenario::load(source).map_err(|e| e.for_field(field))?;
    info.check_scenario(&scenario, field, source)?;
    output::stage_results(&mut outputs, "--out", &args.out, &c, Some(&scenario), &figures)?;
    if let Some(id) = ompl_id {
        outputs.fill(id, output::ompl_log_text(&c));
    }
    outputs.commit()?;
    println!(
        "{} — {} runs per planner, master seed {}, {} shards, {:.1} s of runs\n",
        scenario.name, c.runs, c.master_seed, info.n, c.total_wall_s
    );
    print!("{}", output::table_md(&c));
    println!(
        "\nWrote {}/{{results.json, runs.csv, table.md, convergence.svg, boxplot.svg, paths.svg}}",
        args.out.display()
    );
    Ok(Outcome::Success)
}

/// The shard in `dir`, which must not be the output folder.
fn read(dir: &Path, out: &Path) -> Result<ShardResults, Error> {
    let shown = dir.display().to_string();
    if let (Ok(a), Ok(b)) = (std::fs::canonicalize(dir), std::fs::canonicalize(out)) {
        if a == b {
            return Err(Error::input("--out", format!("'{}' is the shard folder '{shown}'", out.display())));
        }
    }
    let text = tidepath_io::input::read_text(&dir.join("results.json"), "DIR", MAX_RESULTS_BYTES)?;
    let file: ShardFile = serde_json::from_str(&text)
        .map_err(|e| Error::input("DIR", format!("'{shown}/results.json' is not a compare's results.json: {e}")))?;
    Ok(ShardResults { dir: shown, file })
}
