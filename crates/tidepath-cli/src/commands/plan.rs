use std::path::PathBuf;

use clap::Args;
use tidepath::Error;
use tidepath_io::export::{export, ExportFormat, Georef};
use tidepath_io::graph_file::{self, GraphFormat};
use tidepath_io::scenario::{self, PlanRequest, Scenario};
use tidepath_io::{Outputs, PlanReport};
use tidepath_plot::{render_plan_figure, PlanFigure, PlotGraph, PlotPath};

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
    /// Wall-time limit in seconds. Without it (and without the scenario's
    /// `planner.time_limit_s`) a default cap of 600 s applies; a run stopped by time depends on
    /// the machine.
    #[arg(long)]
    pub time_limit: Option<f64>,
    #[command(flatten)]
    pub smoothing: super::budget::SmoothArgs,
    #[command(flatten)]
    pub repairing: super::budget::RepairArgs,
    /// Start from this plan JSON (a warm start): optimizers seed part of their population with
    /// its paths.
    #[arg(long)]
    pub init: Option<PathBuf>,
    /// Also run this reference planner and print the plan's gap to it (cost, length, time).
    #[arg(long)]
    pub reference: Option<String>,
    /// Write the plan here, in the format of the extension: .json (tidepath's plan), .geojson,
    /// .csv, .kml, .gpx (the last three in latitude/longitude need a geographic scenario).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Replace the start: LON,LAT[,DEPTH] in a geographic scenario (depth in m, positive
    /// down), X,Y[,Z] in metres in a local one.
    #[arg(long, allow_hyphen_values = true)]
    pub from: Option<String>,
    /// Replace the goal, as --from.
    #[arg(long, allow_hyphen_values = true)]
    pub to: Option<String>,
    /// Write an SVG figure here: plan view, vertical profile and convergence.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Write an interactive 3-D view here (.html, opens offline): the seabed, obstacles,
    /// currents, the plan's paths (and the --reference's) with hover and playback.
    #[arg(long)]
    pub view: Option<PathBuf>,
    /// Write the planner's search graph (its tree or roadmap, one per mission) here: .graphml
    /// or .json by the extension. Only planners that build one (see `tidepath planners`).
    #[arg(long)]
    pub graph: Option<PathBuf>,
    /// Draw the planner's search graph faintly under the paths of the --plot figure (also
    /// drawn whenever --graph is given with --plot).
    #[arg(long)]
    pub plot_graph: bool,
    /// How a fleet is planned: `planner` (as the planner does: optimizers jointly, the others
    /// one after another, each alone) or `sequential` (one after another, each around the
    /// vehicles planned before it as moving obstacles, keeping `[fleet] separation_m`).
    #[arg(long, value_enum, default_value = "planner")]
    pub fleet: FleetArg,
}

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum FleetArg {
    Planner,
    Sequential,
}

impl FleetArg {
    pub fn mode(self) -> tidepath::planner::FleetMode {
        match self {
            FleetArg::Planner => tidepath::planner::FleetMode::AsPlanner,
            FleetArg::Sequential => tidepath::planner::FleetMode::Sequential,
        }
    }
}

pub fn run(args: &PlanArgs) -> Result<Outcome, Error> {
    let mut scenario = scenario::load(&args.scenario)?;
    if args.from.is_some() || args.to.is_some() {
        scenario = scenario.with_endpoints(args.from.as_deref(), args.to.as_deref())?;
    }
    for w in &scenario.warnings {
        eprintln!("warning: {w}");
    }
    args.repairing.apply(&mut scenario.encoding)?;
    if args.run.jobs.is_some() {
        // Only the first pool configuration counts; a fresh process has none yet.
        let _ = rayon::ThreadPoolBuilder::new().num_threads(crate::jobs(args.run.jobs)?).build_global();
    }
    // Every flag and every output target is checked before any planning: a refusal costs no
    // time and leaves nothing behind.
    let mut outputs = Outputs::new();
    let out_id = args.out.as_deref().map(|p| outputs.declare("--out", p)).transpose()?;
    let plot_id = args.plot.as_deref().map(|p| outputs.declare("--plot", p)).transpose()?;
    let graph_id = args.graph.as_deref().map(|p| outputs.declare("--graph", p)).transpose()?;
    let view_id = args.view.as_deref().map(|p| tidepath_view::declare_output(&mut outputs, "--view", p)).transpose()?;
    let out_format = args.out.as_deref().map(|p| ExportFormat::of(p, "--out")).transpose()?;
    let graph_format = args.graph.as_deref().map(|p| GraphFormat::of(p, "--graph")).transpose()?;
    if args.plot_graph && args.plot.is_none() {
        return Err(Error::input("--plot-graph", "draws on the --plot figure; give --plot FILE.svg too"));
    }
    if let Some(f) = out_format {
        f.check(scenario.frame.as_ref(), "--out")?;
    }
    let init = match &args.init {
        Some(path) => {
            let file = tidepath_io::routes::read(path)?;
            Some(scenario.route_paths(&file, &path.display().to_string())?)
        }
        None => None,
    };
    let (smoother, smoother_params) = match args.smoothing.parsed()? {
        Some((id, params)) => (Some(id), params),
        None => (None, None),
    };
    let req = PlanRequest {
        planner: args.planner.clone(),
        seed: args.run.seed,
        run: 0,
        iterations: args.run.iterations,
        evaluations: args.run.evaluations,
        expansions: args.run.expansions,
        samples: args.run.samples,
        target_cost: args.run.target_cost,
        population: args.run.population,
        time_limit_s: args.time_limit,
        parallel: true,
        smoother,
        smoother_params,
        init,
        stop: Some(crate::stop_flag()),
        record_graph: args.graph.is_some() || args.plot_graph,
        fleet: args.fleet.mode(),
    };
    scenario.check_request(&req).map_err(|e| match &e {
        // Only --plot-graph asked for the graph: the refusal names it.
        Error::Input { field, .. } if field == "--graph" && args.graph.is_none() => e.for_field("--plot-graph"),
        _ => e,
    })?;
    let reference_req = args.reference.as_ref().map(|id| PlanRequest {
        planner: Some(id.clone()),
        seed: args.run.seed,
        time_limit_s: args.time_limit,
        parallel: true,
        stop: req.stop.clone(),
        ..PlanRequest::default()
    });
    if let Some(r) = &reference_req {
        scenario.check_request(r).map_err(|e| e.for_field("--reference"))?;
    }

    let label = req.planner.clone().unwrap_or_else(|| scenario.planner.id.clone());
    let mut bar = DelayedBar::new(&label);
    let report = scenario.plan(&req, &mut |p| bar.update(p));
    bar.finish();
    let report = report?;
    let reference = match &reference_req {
        Some(r) => Some(scenario.plan(r, &mut |_| {}).map_err(|e| e.for_field("--reference"))?),
        None => None,
    };

    // Every file or none.
    if let (Some(id), Some(format)) = (out_id, out_format) {
        let geo = Georef { frame: scenario.frame.as_ref(), epoch: scenario.epoch };
        outputs.fill(id, export(&report, format, geo)?);
    }
    if let (Some(id), Some(format)) = (graph_id, graph_format) {
        outputs.fill(id, graph_file::write(&report, format)?);
    }
    if let Some(id) = plot_id {
        outputs.fill(id, figure(&scenario, &report, reference.as_ref())?);
    }
    if let Some(id) = view_id {
        let mut routes = tidepath_view::report_routes(&report);
        if let Some(r) = reference.as_ref().filter(|r| r.status.is_success()) {
            for mut route in tidepath_view::report_routes(r) {
                route.label = format!("reference: {}", route.label);
                routes.push(route);
            }
        }
        let cost = report.cost.map_or("none".to_string(), |c| format!("{c:.4}"));
        let title =
            format!("{} — {}, seed {}: cost {cost}, {}", scenario.name, report.planner, report.seed, report.status);
        let input =
            tidepath_view::ViewInput { scenario: &scenario, title, routes, simulation: None, simulation_mission: 0 };
        match super::view::build(&input) {
            Some(html) => outputs.fill(id, html),
            None => return Ok(Outcome::Interrupted),
        }
    }
    outputs.commit()?;
    print_summary(&scenario, &report);
    if let Some(reference) = reference {
        match (reference.status.is_success(), reference.cost, report.cost) {
            (true, Some(rc), Some(c)) => {
                let pct = |a: Option<f64>, b: Option<f64>| match (a, b) {
                    (Some(a), Some(b)) if b > 0.0 => format!("{:+.3}%", 100.0 * (a - b) / b),
                    _ => "n/a".into(),
                };
                println!(
                    "  reference      {} ({}): cost {rc:.6}; gap: cost {}, length {}, time {}",
                    reference.planner,
                    reference.status,
                    pct(Some(c), Some(rc)),
                    pct(report.length_m(), reference.length_m()),
                    pct(report.travel_time_s(), reference.travel_time_s())
                );
            }
            _ => println!("  reference      {} ({}): {}", reference.planner, reference.status, reference.reason),
        }
    }
    if report.stop_reason == tidepath::termination::StopReason::Cancelled {
        return Ok(Outcome::Interrupted);
    }
    Ok(Outcome::Status(report.status))
}

fn figure(scenario: &Scenario, report: &PlanReport, reference: Option<&PlanReport>) -> Result<String, Error> {
    let history: Vec<f64> = report.history.iter().map(|h| h.unwrap_or(f64::NAN)).collect();
    let cost = report.cost.map_or("none".to_string(), |c| format!("{c:.4}"));
    let to_points = |p: &[[f64; 3]]| p.iter().map(|q| tidepath::Vec3::from_array(*q)).collect::<Vec<_>>();
    let several = report.missions.len() > 1;
    // (label, points, mission, flown curve with its times and the vehicle's radius): the
    // mission's times, violations and flown curve describe its final path.
    type Drawn<'r> = (String, Vec<tidepath::Vec3>, Option<&'r tidepath_io::MissionReport>, Option<Flown<'r>>);
    type Flown<'r> = (Vec<tidepath::Vec3>, &'r [f64], f64);
    let mut owned: Vec<Drawn> = Vec::new();
    for (k, m) in report.missions.iter().enumerate() {
        let name = if several { format!("{} {}", report.planner, m.name) } else { report.planner.clone() };
        let radius = scenario.missions.get(k).map_or(scenario.vehicle.turn_radius, |x| x.vehicle.turn_radius);
        let flown = m.flown.as_ref().zip(radius).map(|(f, r)| (f.vectors(), f.times.as_slice(), r));
        match &m.smoothed {
            None => owned.push((name, to_points(&m.waypoints), Some(m), flown)),
            // A smoother that gave the path back unchanged leaves nothing raw to show beside
            // the flown curve.
            Some(s) if flown.is_some() && *s == m.waypoints => {
                owned.push((format!("{name} (smoothed)"), to_points(s), Some(m), flown));
            }
            Some(s) => {
                owned.push((format!("{name} (smoothed)"), to_points(s), Some(m), flown));
                owned.push((format!("{name} (raw)"), to_points(&m.waypoints), None, None));
            }
        }
    }
    let reference_points = reference.filter(|r| r.status.is_success()).map(|r| r.missions[0].points());
    let mut fig = PlanFigure::of_scenario(
        format!("{} — {}, seed {}: cost {cost}, {}", scenario.name, report.planner, report.seed, report.status),
        scenario,
    );
    fig.focus = report.missions.iter().filter_map(|m| m.focus.clone()).collect();
    // A fleet's closest approach, marked between the two vehicles.
    if let Some(c) = report.fleet.as_ref().and_then(|f| f.closest.as_ref()) {
        let at = tidepath::Vec3::from_array(c.positions[0]).lerp(tidepath::Vec3::from_array(c.positions[1]), 0.5);
        let label = format!(
            "closest approach: {} and {}, {:.0} m apart at t = {:.0} s",
            c.vehicles[0], c.vehicles[1], c.distance_m, c.time_s
        );
        fig.focus.push(tidepath::planner::Focus { at, label });
    }
    fig.paths = owned
        .iter()
        .map(|(label, pts, m, flown)| {
            let path = match m {
                Some(m) => PlotPath::new(label.clone(), pts).with_times(&m.times).with_violations(&m.violations),
                None => PlotPath::new(label.clone(), pts),
            };
            match flown {
                Some((points, times, r)) => path.with_flown(points, times, *r),
                None => path,
            }
        })
        .collect();
    // One mission's final path (the smoothed one when smoothed) is coloured by its speed over
    // ground when the world has a current; a fleet's paths keep a colour each.
    fig.speed_path = (!several && !owned.is_empty()).then_some(0);
    // The search graph, faintly under everything the run found.
    fig.graphs = report
        .graphs
        .iter()
        .map(|g| PlotGraph {
            label: (report.graphs.len() > 1).then_some(g.mission.as_str()),
            kind: &g.kind,
            vertices: &g.vertices,
            edges: &g.edges,
        })
        .collect();
    fig.reference = reference
        .zip(reference_points.as_ref())
        .map(|(r, pts)| PlotPath::new(format!("reference: {}", r.planner), pts));
    fig.histories = vec![(report.planner.clone(), &history)];
    // A search before the iterations (a composite planner's reference) or a warm start is
    // where iteration 0 comes from.
    // A sampling planner's history has one entry per sample (PRM*'s expansions are its
    // queries, not a search before the samples).
    fig.history_per_sample = report.samples > 0 && report.iterations == 0;
    fig.history_start = if fig.history_per_sample {
        None
    } else if report.expansions > 0 && history.len() as u64 > report.iterations {
        // An entry before the first iteration: the search's result. (The ant colonies count
        // their steps as expansions but record one entry per iteration.)
        Some(format!("after a reference search ({} expansions)", report.expansions))
    } else if report.warm_start && !history.is_empty() {
        Some("includes the warm start (--init)".to_string())
    } else {
        None
    };
    render_plan_figure(&fig)
}

pub fn print_summary(scenario: &Scenario, r: &PlanReport) {
    println!("{} — {} (seed {}): {}: {}", scenario.name, r.planner, r.seed, r.status, r.reason);
    let several = r.missions.len() > 1;
    for (k, m) in r.missions.iter().enumerate() {
        let indent = if several {
            println!("  mission {}: {}: {}", m.name, m.status, m.reason);
            "    "
        } else {
            "  "
        };
        if m.waypoints.is_empty() {
            println!("{indent}no path");
            continue;
        }
        if let Some(d) = m.goal_distance_m {
            println!("{indent}goal distance  {d:.1} m left from the path's last point to the goal");
        }
        let terms: Vec<String> =
            m.cost_terms.iter().map(|(k, v)| format!("{k} {:.4}", v.as_f64().unwrap_or(f64::NAN))).collect();
        let cost = m.cost.map_or("none".to_string(), |c| format!("{c:.6}"));
        println!("{indent}cost           {cost}  ({})", terms.join(", "));
        if let Some(rule) = &m.model_rule {
            // The cost model's own feasibility rule, beside tidepath's verdict (the status).
            let verdict = if rule.met { "met" } else { "not met" };
            let label = format!("{} rule", r.cost_model);
            println!("{indent}{label:<15}F < {}: {verdict} (F = {cost})", rule.below);
        }
        if let (Some(raw), Some(s)) = (m.raw_cost, &m.smoothed) {
            // The planner's own polyline length beside the smoothed one printed below (wpa2017
            // reports both: the optimizer's polyline and the Dubins-smoothed path).
            let raw_length: f64 = m
                .waypoints
                .windows(2)
                .map(|w| w[0].iter().zip(&w[1]).map(|(a, b)| (b - a) * (b - a)).sum::<f64>().sqrt())
                .sum();
            println!(
                "{indent}smoothed       {} -> {} waypoints; before smoothing: cost {raw:.6}, length {raw_length:.1} m",
                m.waypoints.len(),
                s.len()
            );
        }
        if let Some(x) = &m.metrics {
            println!("{indent}length         {:.1} m", x.length_m);
            let arrival = m.times.last().copied().unwrap_or(f64::NAN);
            let utc = tidepath_io::export::utc(scenario.epoch, arrival).map_or(String::new(), |u| format!(" ({u})"));
            println!(
                "{indent}travel time    {:.1} s ({}, {} model); arrives at t = {arrival:.1} s{utc}",
                x.travel_time_s,
                hms(x.travel_time_s),
                r.travel_time_model,
            );
            if let Some(v) = &m.speeds {
                println!("{indent}speeds         {}", tidepath_io::fleet_report::speeds_line(&m.points(), v));
            }
            let clearance = x.min_clearance_m.map_or("n/a".to_string(), |c| format!("{c:.1} m"));
            println!(
                "{indent}min clearance  {clearance}; max turn {:.1} deg; max pitch {:.1} deg; collisions {}",
                x.max_turn_deg, x.max_pitch_deg, x.collisions
            );
            let radius = scenario.missions.get(k).map_or(scenario.vehicle.turn_radius, |v| v.vehicle.turn_radius);
            if let Some(line) = radius.and_then(|r| turns_line(x, r)) {
                println!("{indent}turns          {line}");
            }
        }
        for v in m.violations.iter().take(8) {
            println!("{indent}violation      {}", v.message);
        }
        if m.violations.len() > 8 {
            println!("{indent}... and {} more violations", m.violations.len() - 8);
        }
    }
    if let Some(f) = &r.fleet {
        println!("  fleet          {}", f.line());
    }
    // What this planner counted: evaluations and iterations (optimizers), expansions (graph
    // search), samples (sampling planners), and the graph it built.
    let mut parts = Vec::new();
    if r.evaluations > 0 || r.iterations > 0 {
        parts.push(format!("{} evaluations in {} iterations", r.evaluations, r.iterations));
    }
    if r.samples > 0 {
        parts.push(format!("{} samples", r.samples));
    }
    if r.expansions > 0 {
        parts.push(format!("{} expansions", r.expansions));
    }
    if r.samples > 0 && r.graph_nodes > 0 {
        parts.push(format!("{} vertices, {} edges, {} motion checks", r.graph_nodes, r.graph_edges, r.motion_checks));
    }
    let work = if parts.is_empty() { "no counted work".to_string() } else { parts.join(", ") };
    println!("  search         {work}, wall time {:.3} s, stopped by {}", r.elapsed_s, r.stop_reason.id());
    if let Some(limit) = r.time_limit_s {
        let source = if r.default_time_cap { " (default cap; change with --time-limit)" } else { "" };
        println!("  time limit     {limit} s{source}");
    }
    if r.stop_reason == tidepath::termination::StopReason::WallTime {
        let what = if r.default_time_cap { "the default wall-time cap" } else { "the wall-time limit" };
        println!("  note           stopped by {what}: this result depends on the machine's speed");
    }
}

/// The turns flown by a vehicle of turning radius `r` (m), for summaries: "radius >= 30.0 m
/// (curvature <= 0.0333 /m), vehicle 30 m", or "none: straight legs only, vehicle 30 m";
/// `None` when the metrics do not say (a plan file written before turns were measured).
pub fn turns_line(x: &tidepath::path::Metrics, r: f64) -> Option<String> {
    let curvature = x.max_curvature_per_m?;
    Some(match x.min_turn_radius_m {
        None => format!("none: straight legs only, vehicle {r} m"),
        Some(m) => {
            let k = if curvature.is_finite() { format!("<= {curvature:.4} /m") } else { "unbounded".into() };
            let tight = if m < r * (1.0 - 1e-9) { ", tighter than the vehicle can turn" } else { "" };
            format!("radius >= {m:.1} m (curvature {k}), vehicle {r} m{tight}")
        }
    })
}

fn hms(s: f64) -> String {
    let total = s.round() as u64;
    format!("{}h{:02}m{:02}s", total / 3600, (total % 3600) / 60, total % 60)
}
