//! `tidepath simulate`: fly a mission while the world changes, re-planning a window of the
//! route ahead with any planner; per-phase lines on stdout, the simulation file and figure.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use tidepath::simulate::{Acceptance, Growth, ReplanPolicy};
use tidepath::Error;
use tidepath_io::scenario::{self, Scenario};
use tidepath_io::simulation::{simulation_json, SimReport, SimRequest};
use tidepath_io::Outputs;
use tidepath_plot::{render_simulation_figure, SimPanel, SimulationFigure};

use crate::Outcome;

#[derive(Clone, Copy, ValueEnum)]
pub enum AcceptArg {
    /// The route spliced from the window is feasible to the goal.
    Route,
    /// The window's piece is feasible (lfhh2019).
    Window,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum PolicyArg {
    /// Re-plan only when a change makes the route ahead infeasible.
    WhenInfeasible,
    /// Re-plan at every change (lfhh2019; an operator replanning on each new forecast).
    Always,
}

#[derive(Args)]
pub struct SimulateArgs {
    /// A built-in scenario name (see `tidepath scenarios`) or a scenario TOML file; its
    /// `[[changes]]` say what changes when, its `[simulate]` how the loop re-plans.
    pub scenario: String,
    /// Planner id for every (re-)plan (see `tidepath planners`); defaults to the scenario's.
    #[arg(long)]
    pub planner: Option<String>,
    #[command(flatten)]
    pub run: super::budget::BudgetArgs,
    /// Wall-time limit of each re-plan in seconds (default: the scenario's
    /// `planner.time_limit_s`, else 600).
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Wall-time limit of the whole simulation in seconds (default 600).
    #[arg(long)]
    pub total_time_limit: Option<f64>,
    /// When to re-plan (default: the scenario's `[simulate] policy`, else when-infeasible).
    #[arg(long, value_enum)]
    pub replan: Option<PolicyArg>,
    /// When a re-planned window is good enough: `route` (the route spliced from it is feasible
    /// to the goal; the default) or `window` (its piece is: lfhh2019's rule, the default of
    /// `[simulate] preset = "lfhh2019"`).
    #[arg(long, value_enum)]
    pub accept: Option<AcceptArg>,
    /// Waypoints ahead of the vehicle the first re-planned window reaches (default 20).
    #[arg(long)]
    pub window: Option<usize>,
    /// How a window with no feasible piece grows: `double`, or `add:N` (N waypoints more;
    /// lfhh2019 adds 1).
    #[arg(long)]
    pub growth: Option<String>,
    /// Moving obstacles are known only within this range (m) of the vehicle (default: the
    /// scenario's `[simulate] sensor_range`; without one, all are known from departure).
    #[arg(long)]
    pub sensor_range: Option<f64>,
    /// Plan every window cold, even with planners that take a warm start.
    #[arg(long)]
    pub cold: bool,
    /// Write the simulation here (JSON): every phase and the executed track with its times.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write an SVG figure here: the executed track coloured by phase, and a panel per phase.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Write an interactive 3-D view here (.html, opens offline): the executed track plays
    /// back with the obstacles and currents of each moment and each phase's route ahead.
    #[arg(long)]
    pub view: Option<PathBuf>,
}

fn growth(text: &str) -> Result<Growth, Error> {
    match text.trim() {
        "double" => Ok(Growth::Double),
        t => match t.strip_prefix("add:").or(t.strip_prefix("add=")).map(str::parse::<usize>) {
            Some(Ok(n)) => Ok(Growth::Add(n)),
            _ => Err(Error::input("--growth", format!("`{text}` is not `double` or `add:N` (e.g. add:1)"))),
        },
    }
}

pub fn run(args: &SimulateArgs) -> Result<Outcome, Error> {
    let scenario = scenario::load(&args.scenario)?;
    for w in &scenario.warnings {
        eprintln!("warning: {w}");
    }
    if args.run.jobs.is_some() {
        let _ = rayon::ThreadPoolBuilder::new().num_threads(crate::jobs(args.run.jobs)?).build_global();
    }
    if args.run.target_cost.is_some() {
        return Err(Error::input("--target-cost", "a simulation has no single cost to stop at"));
    }
    let mut outputs = Outputs::new();
    let out_id = args.out.as_deref().map(|p| outputs.declare("--out", p)).transpose()?;
    let plot_id = args.plot.as_deref().map(|p| outputs.declare("--plot", p)).transpose()?;
    let view_id = args.view.as_deref().map(|p| tidepath_view::declare_output(&mut outputs, "--view", p)).transpose()?;
    if let Some(p) = &args.out {
        if p.extension().and_then(|e| e.to_str()) != Some("json") {
            return Err(Error::input("--out", format!("`{}`: the simulation is written as .json", p.display())));
        }
    }
    let req = SimRequest {
        planner: args.planner.clone(),
        seed: args.run.seed,
        iterations: args.run.iterations,
        evaluations: args.run.evaluations,
        expansions: args.run.expansions,
        samples: args.run.samples,
        population: args.run.population,
        time_limit_s: args.time_limit,
        total_time_limit_s: args.total_time_limit,
        window: args.window,
        growth: args.growth.as_deref().map(growth).transpose()?,
        policy: args.replan.map(|p| match p {
            PolicyArg::WhenInfeasible => ReplanPolicy::WhenInfeasible,
            PolicyArg::Always => ReplanPolicy::Always,
        }),
        sensor_range: args.sensor_range,
        warm_start: args.cold.then_some(false),
        accept: args.accept.map(|a| match a {
            AcceptArg::Route => Acceptance::Route,
            AcceptArg::Window => Acceptance::Window,
        }),
        parallel: true,
        stop: Some(crate::stop_flag()),
    };
    scenario.check_sim_request(&req)?;
    let report = scenario.simulate(&req)?;
    if let Some(id) = out_id {
        outputs.fill(id, simulation_json(&scenario, &report));
    }
    if let Some(id) = plot_id {
        outputs.fill(id, figure(&scenario, &report)?);
    }
    if let Some(id) = view_id {
        match view(&scenario, &report) {
            Some(html) => outputs.fill(id, html),
            None => return Ok(Outcome::Interrupted),
        }
    }
    outputs.commit()?;
    print_phases(&scenario, &report);
    if report.interrupted() && crate::interrupted() {
        return Ok(Outcome::Interrupted);
    }
    Ok(if report.sim.reached { Outcome::Success } else { Outcome::Infeasible })
}

fn print_phases(scenario: &Scenario, r: &SimReport) {
    let sim = &r.sim;
    let p = &r.params;
    let growth = match p.growth {
        Growth::Double => "doubling".to_string(),
        Growth::Add(n) => format!("+{n}"),
    };
    let sensor = p.sensor_range.map_or(String::new(), |s| format!(", sensor range {s} m"));
    println!(
        "{} — {} (seed {}): re-plan {}, window {} waypoints ({growth}, accepting a feasible {}){sensor}",
        scenario.name,
        r.planner,
        r.seed,
        tidepath_io::simulation::policy_id(p.policy),
        p.window,
        tidepath_io::simulation::accept_id(p.accept)
    );
    for (k, ph) in sim.phases.iter().enumerate() {
        let mut line = format!("  phase {k:<3} t = {:>9.1} s  {}", ph.time, ph.event);
        if let Some(problem) = &ph.route_problem {
            line.push_str(&format!("; route ahead blocked: {problem}"));
        }
        match &ph.replan {
            Some(x) if k == 0 => line.push_str(&format!(
                "; planned the route: {}{}, {:.3} s",
                x.status,
                if x.cost.is_finite() { format!(", cost {:.4}", x.cost) } else { String::new() },
                x.planning_s
            )),
            Some(x) => {
                let windows: Vec<String> = x.windows.iter().map(|w| w.to_string()).collect();
                let cost = if x.cost.is_finite() { format!(", cost {:.4}", x.cost) } else { String::new() };
                let warm = if x.warm { ", warm" } else { "" };
                line.push_str(&format!(
                    "; planned window {}: {}{cost}{warm}, {:.3} s",
                    windows.join(" -> "),
                    x.status,
                    x.planning_s
                ));
                if !x.status.is_success() {
                    line.push_str(&format!(" ({})", x.reason));
                }
            }
            None if ph.revealed && ph.route_problem.is_none() => line.push_str("; route ahead still feasible"),
            None => {}
        }
        println!("{line}");
    }
    let arrival = sim
        .arrival()
        .and_then(|t| tidepath_io::export::utc(scenario.epoch, t).map(|u| format!(" ({u})")))
        .unwrap_or_default();
    println!("  outcome   {}{arrival}", sim.reason);
    println!("  track     {:.1} m flown in {} points", sim.track.travelled, sim.track.points.len());
    let check = if sim.track_violations.is_empty() {
        "no violation".to_string()
    } else {
        format!("{} violations, the first: {}", sim.track_violations.len(), sim.track_violations[0])
    };
    println!("  re-check  against the true world at each moment: {check}");
    println!("  search    {} phases, wall time {:.3} s", sim.phases.len(), r.elapsed_s);
    if !sim.complete {
        println!("  note      incomplete: the phases done are kept");
    }
}

fn figure(scenario: &Scenario, r: &SimReport) -> Result<String, Error> {
    let sim = &r.sim;
    let known: Vec<_> = (0..sim.phases.len()).map(|k| sim.known(&scenario.world, k)).collect();
    let failed_at = (!sim.reached && sim.complete).then(|| sim.phases.len() - 1);
    let phases = sim
        .phases
        .iter()
        .zip(&known)
        .enumerate()
        .map(|(k, (p, (world, unseen)))| {
            let what = match &p.replan {
                Some(x) => format!("planned: {}", x.status),
                None => "route kept".to_string(),
            };
            SimPanel {
                label: format!("phase {k}, t = {:.0} s: {}; {what}", p.time, p.event),
                known: world,
                unseen: unseen.clone(),
                time: p.time,
                position: p.position,
                old_route: &p.route_before,
                new_route: &p.route_after,
                piece: p.replan.as_ref().filter(|x| x.status.is_success()).map(|x| x.piece.as_slice()),
                failed: failed_at == Some(k),
            }
        })
        .collect();
    let focus = sim
        .phases
        .iter()
        .filter_map(|p| p.replan.as_ref().and_then(|x| x.focus.clone()))
        .filter(|_| !sim.reached)
        .collect();
    let fig = SimulationFigure {
        title: format!("{} — simulate with {}, seed {}", scenario.name, r.planner, r.seed),
        epoch: scenario.epoch,
        safety_distance: scenario.missions[0].vehicle.safety_distance,
        start: scenario.missions[0].start,
        goal: scenario.missions[0].goal,
        track: &sim.track.points,
        track_times: &sim.track.times,
        phases,
        outcome: sim.reason.clone(),
        focus,
    };
    render_simulation_figure(&fig)
}

/// The view of a simulation: its executed track as the route that plays back.
fn view(scenario: &Scenario, report: &tidepath_io::simulation::SimReport) -> Option<String> {
    let sim = &report.sim;
    let track = tidepath_view::ViewRoute {
        label: format!("{} track", report.planner),
        group: report.planner.clone(),
        mission: 0,
        points: sim.track.points.clone(),
        times: sim.track.times.clone(),
        speeds: None,
        flown: None,
        cost: None,
        terms: Vec::new(),
        status: if sim.reached { "reached".to_string() } else { "not reached".to_string() },
        feasible: sim.reached && sim.track_violations.is_empty(),
        violations: Vec::new(),
    };
    let title = format!("{} — simulate with {}, seed {}: {}", scenario.name, report.planner, report.seed, sim.reason);
    let input =
        tidepath_view::ViewInput { scenario, title, routes: vec![track], simulation: Some(sim), simulation_mission: 0 };
    super::view::build(&input)
}
