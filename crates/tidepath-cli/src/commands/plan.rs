use std::path::PathBuf;

use clap::Args;
use tidepath::io::{write_atomic, PlanReport};
use tidepath::plot::{write_plan_figure, PlanFigure, PlotPath};
use tidepath::scenario::{self, PlanRequest, Scenario};
use tidepath::Error;

use crate::progress::DelayedBar;
use crate::Outcome;

#[derive(Args)]
pub struct PlanArgs {
    /// A built-in scenario name (see `tidepath scenarios`) or a scenario TOML file.
    pub scenario: String,
    /// Planner id (see `tidepath planners`); defaults to the scenario's `[planner] id`.
    #[arg(long)]
    pub planner: Option<String>,
    #[command(flatten)]
    pub run: super::budget::BudgetArgs,
    /// Wall-time safety net in seconds; a run stopped by it depends on the machine.
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Smooth the plan (`shortcut`, or `none` to override the scenario's smoother).
    #[arg(long)]
    pub smooth: Option<String>,
    /// Write the plan as JSON here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write an SVG figure here: plan view, vertical profile and convergence.
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

pub fn run(args: &PlanArgs) -> Result<Outcome, Error> {
    let scenario = scenario::load(&args.scenario)?;
    if args.run.jobs.is_some() {
        // Only the first pool configuration counts; a fresh process has none yet.
        let _ = rayon::ThreadPoolBuilder::new().num_threads(crate::jobs(args.run.jobs)?).build_global();
    }
    for (flag, path) in [("--out", &args.out), ("--plot", &args.plot)] {
        if let Some(dir) = path.as_ref().and_then(|p| p.parent()).filter(|d| !d.as_os_str().is_empty()) {
            if !dir.is_dir() {
                return Err(Error::input(flag, format!("folder '{}' does not exist", dir.display())));
            }
        }
    }
    let req = PlanRequest {
        planner: args.planner.clone(),
        seed: args.run.seed,
        run: 0,
        iterations: args.run.iterations,
        evaluations: args.run.evaluations,
        population: args.run.population,
        time_limit_s: args.time_limit,
        parallel: true,
        smoother: args.smooth.clone(),
    };
    let label = req.planner.clone().unwrap_or_else(|| scenario.planner.id.clone());
    let mut bar = DelayedBar::new(&label);
    let report = scenario.plan(&req, &mut |p| bar.update(p));
    bar.finish();
    let report = report?;

    if let Some(out) = &args.out {
        write_atomic(out, report.to_json().as_bytes())?;
    }
    if let Some(plot) = &args.plot {
        write_figure(&scenario, &report, plot)?;
    }
    print_summary(&scenario, &report);
    Ok(if report.feasible { Outcome::Success } else { Outcome::Infeasible })
}

fn write_figure(scenario: &Scenario, report: &PlanReport, out: &std::path::Path) -> Result<(), Error> {
    let raw: Vec<_> = report.waypoints.iter().map(|p| tidepath::Vec3::from_array(*p)).collect();
    let smoothed = report.smoothed.is_some().then(|| report.points());
    let history: Vec<f64> = report.history.iter().map(|h| h.unwrap_or(f64::NAN)).collect();
    let verdict = if report.feasible { "feasible" } else { "INFEASIBLE" };
    let fig = PlanFigure {
        title: format!(
            "{} — {}, seed {}: cost {:.4}, {verdict}",
            scenario.name, report.planner, report.seed, report.cost
        ),
        world: &scenario.world,
        start: scenario.start,
        goal: scenario.goal,
        time: scenario.departure_time,
        paths: match &smoothed {
            None => vec![PlotPath { label: report.planner.clone(), points: &raw }],
            Some(s) => vec![
                PlotPath { label: format!("{} (smoothed)", report.planner), points: s },
                PlotPath { label: format!("{} (raw)", report.planner), points: &raw },
            ],
        },
        histories: vec![(report.planner.clone(), &history)],
    };
    write_plan_figure(&fig, out)
}

pub fn print_summary(scenario: &Scenario, r: &PlanReport) {
    let verdict = if r.feasible { "feasible" } else { "NOT feasible" };
    println!("{} — {} (seed {}): {verdict}", scenario.name, r.planner, r.seed);
    let terms: Vec<String> =
        r.cost_terms.iter().map(|(k, v)| format!("{k} {:.4}", v.as_f64().unwrap_or(f64::NAN))).collect();
    println!("  cost           {:.6}  ({})", r.cost, terms.join(", "));
    if let (Some(raw), Some(s)) = (r.raw_cost, &r.smoothed) {
        println!("  smoothed       {} -> {} waypoints; cost before smoothing {raw:.6}", r.waypoints.len(), s.len());
    }
    let m = &r.metrics;
    println!("  length         {:.1} m", m.length_m);
    println!("  travel time    {:.1} s ({}, {} model)", m.travel_time_s, hms(m.travel_time_s), r.travel_time_model);
    let clearance = m.min_clearance_m.map_or("n/a".to_string(), |c| format!("{c:.1} m"));
    println!(
        "  min clearance  {clearance}; max turn {:.1} deg; max pitch {:.1} deg; collisions {}",
        m.max_turn_deg, m.max_pitch_deg, m.collisions
    );
    println!("  evaluations    {} in {} iterations, wall time {:.3} s", r.evaluations, r.iterations, r.elapsed_s);
    if r.stop_reason == tidepath::optim::StopReason::WallTime {
        println!("  note           stopped by the wall-time limit: this result depends on the machine's speed");
    }
    for v in r.violations.iter().take(8) {
        println!("  violation      {}", v.message);
    }
    if r.violations.len() > 8 {
        println!("  ... and {} more violations", r.violations.len() - 8);
    }
}

fn hms(s: f64) -> String {
    let total = s.round() as u64;
    format!("{}h{:02}m{:02}s", total / 3600, (total % 3600) / 60, total % 60)
}
