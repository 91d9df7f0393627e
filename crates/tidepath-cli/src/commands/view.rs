//! `tidepath view`: the interactive 3-D view of a scenario and any plans, as one offline HTML
//! file; and the `--view` output `plan`, `simulate` and `compare` share.

use std::path::{Path, PathBuf};

use clap::Args;
use tidepath::Error;
use tidepath_io::scenario::{self, Scenario};
use tidepath_io::Outputs;
use tidepath_view::{render_view, ViewInput, ViewRoute};

use crate::Outcome;

#[derive(Args)]
pub struct ViewArgs {
    /// A built-in scenario name (see `tidepath scenarios`) or a scenario TOML file.
    pub scenario: String,
    /// Plans to show: plan JSON (as `plan --out` writes) or exports (.geojson, .gpx, .kml,
    /// .csv), one route per mission. Each is flown on the scenario's clock and judged, as
    /// `eval` does, so hover times and verdicts are the scenario's.
    pub plans: Vec<PathBuf>,
    /// Write the view here: one self-contained .html file that opens offline.
    #[arg(short = 'o', long)]
    pub out: PathBuf,
}

pub fn run(args: &ViewArgs) -> Result<Outcome, Error> {
    let scenario = scenario::load(&args.scenario)?;
    for w in &scenario.warnings {
        eprintln!("warning: {w}");
    }
    let mut outputs = Outputs::new();
    let id = tidepath_view::declare_output(&mut outputs, "--out", &args.out)?;
    let mut routes = Vec::new();
    for (k, path) in args.plans.iter().enumerate() {
        let file = tidepath_io::routes::read(path)?;
        let paths = scenario.route_paths(&file, &path.display().to_string())?;
        let judged = scenario.evaluate_routes(&paths, &file.speeds)?;
        let stem = path.file_stem().map_or_else(|| format!("plan {}", k + 1), |s| s.to_string_lossy().into_owned());
        let name = match &file.planner {
            Some(p) if !p.is_empty() => format!("{p} ({stem})"),
            _ => stem,
        };
        let several = judged.len() > 1;
        for (i, m) in judged.iter().enumerate() {
            // A fleet's vehicles each get a colour; several plans of one vehicle, one each.
            let label = if several { format!("{name} {}", m.name) } else { name.clone() };
            routes.push(ViewRoute::from_plan(label.clone(), label, i, m));
        }
    }
    let title = match args.plans.len() {
        0 => scenario.name.clone(),
        1 => format!("{} — {}", scenario.name, args.plans[0].display()),
        n => format!("{} — {n} plans", scenario.name),
    };
    let input = ViewInput { scenario: &scenario, title, routes, simulation: None, simulation_mission: 0 };
    let Some(html) = build(&input) else { return Ok(Outcome::Interrupted) };
    outputs.fill(id, html);
    outputs.commit()?;
    println!("Wrote {} ({:.1} MB)", args.out.display(), file_mb(&args.out));
    Ok(Outcome::Success)
}

/// The page, or `None` when Ctrl-C stopped it (nothing is written then). After a run that
/// Ctrl-C already stopped, the view of what finished is built to the end (it takes seconds at
/// most); a second Ctrl-C still ends the process at once.
pub fn build(input: &ViewInput<'_>) -> Option<String> {
    use std::sync::atomic::Ordering;
    let flag = crate::stop_flag();
    let already = flag.load(Ordering::Relaxed);
    let stop = move || !already && flag.load(Ordering::Relaxed);
    render_view(input, &stop).ok()
}

/// Each planner's best run of a comparison (lowest cost), every mission of it, judged on the
/// scenario again for its clock and verdict.
pub fn comparison_routes(
    scenario: &Scenario,
    c: &tidepath_experiments::compare::Comparison,
) -> Result<Vec<ViewRoute>, Error> {
    let mut out = Vec::new();
    for pl in &c.planners {
        let Some(best) = c.records_of(&scenario.name, pl).min_by(|a, b| a.cost.total_cmp(&b.cost)) else { continue };
        let paths: Vec<Vec<tidepath::Vec3>> = if best.missions.is_empty() {
            vec![best.waypoints.iter().map(|p| tidepath::Vec3::from_array(*p)).collect()]
        } else {
            best.missions.iter().map(|m| m.waypoints.iter().map(|p| tidepath::Vec3::from_array(*p)).collect()).collect()
        };
        if paths.len() != scenario.missions.len() || paths.iter().any(|p| p.len() < 2) {
            continue;
        }
        let judged = scenario.evaluate_routes(&paths, &vec![None; paths.len()])?;
        let several = judged.len() > 1;
        for (k, m) in judged.iter().enumerate() {
            let base = format!("{pl} (best of {} runs, run {})", c.runs, best.run);
            let label = if several { format!("{base} {}", m.name) } else { base };
            out.push(ViewRoute::from_plan(label, pl.clone(), k, m));
        }
    }
    Ok(out)
}

fn file_mb(path: &Path) -> f64 {
    std::fs::metadata(path).map_or(0.0, |m| m.len() as f64 / 1e6)
}
