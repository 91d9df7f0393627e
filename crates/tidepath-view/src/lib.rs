//! The interactive 3-D viewer: one self-contained HTML file that opens offline.
//!
//! A plan view and a profile hide where a path skims a seamount or how a vehicle dodges a
//! moving ship; the view lets an engineer turn the scene, hover a point for its time, depth
//! and clearance, and replay the mission. [`render_view`] turns a scenario, the routes to show
//! and (for `simulate`) the simulation into the scene as JSON ([`scene`]), and embeds it with
//! plotly.js (vendored, see `vendor/plotly.js-gl3d-dist-min/README.md`) and the viewer's own
//! script (`assets/viewer.js`) in one page ([`html`]). Nothing is fetched when the page opens.
//!
//! What is drawn, and why it is sized as it is:
//! - the seabed as a surface sampled on a lattice of at most [`seabed::MAX_NODES`] nodes a
//!   side: each node's height is the terrain's own value at that place (the full grid,
//!   interpolated as the planners see it), so hovering a node reads the real seabed;
//! - obstacles as triangle meshes ([`meshes`]); fixed ones in one trace, moving ones each in
//!   its own, moved by the page along their velocity (and, in a simulation, per epoch);
//! - currents as cones on a subsampled lattice and waves as a colour on the sea surface, with a
//!   frame per sampled time when they vary ([`flow`]);
//! - every route as a line with hover text (time, depth, clearance, its segment's additive
//!   cost terms) and a vehicle marker the time slider moves ([`routes`]).
//!
//! Building a view polls `stop` in every loop over the input (routes' points, obstacles,
//! lattices), so Ctrl-C ends it within a second and nothing is written.

pub mod axes;
pub mod flow;
pub mod html;
pub mod lattice;
pub mod meshes;
pub mod obstacles;
pub mod routes;
pub mod scene;
pub mod seabed;

use tidepath::geom::Vec3;
use tidepath::path::Violation;
use tidepath::simulate::Simulation;
use tidepath_io::scenario::Scenario;

pub use html::render_view;

/// One route to show: a mission's final path with its clock and verdict.
#[derive(Clone, Debug)]
pub struct ViewRoute {
    /// The legend's label ("theta-star", "pso auv-2 (best of 10 runs)").
    pub label: String,
    /// The colour group: routes of one planner share a colour.
    pub group: String,
    /// The scenario mission the route flies (its vehicle and clock).
    pub mission: usize,
    /// The path's points (start and goal included) and the arrival time at each.
    pub points: Vec<Vec3>,
    pub times: Vec<f64>,
    /// Each segment's through-water speed when the plan chose them (a speed range).
    pub speeds: Option<Vec<f64>>,
    /// With a turning radius: the curve actually flown, with its times (drawn instead of the
    /// polyline, which stays as the hover points).
    pub flown: Option<(Vec<Vec3>, Vec<f64>)>,
    pub cost: Option<f64>,
    pub terms: Vec<(String, f64)>,
    pub status: String,
    pub feasible: bool,
    pub violations: Vec<Violation>,
}

impl ViewRoute {
    /// A mission of a plan report (`plan --view`): its final (smoothed, when smoothed) path.
    pub fn from_report(label: String, group: String, mission: usize, m: &tidepath_io::MissionReport) -> Self {
        let vec = |ps: &[[f64; 3]]| ps.iter().map(|p| Vec3::from_array(*p)).collect::<Vec<_>>();
        Self {
            label,
            group,
            mission,
            points: vec(m.smoothed.as_deref().unwrap_or(&m.waypoints)),
            times: m.times.clone(),
            speeds: m.speeds.clone(),
            flown: m.flown.as_ref().map(|f| (f.vectors(), f.times.clone())),
            cost: m.cost,
            terms: m.cost_terms.iter().filter_map(|(k, v)| v.as_f64().map(|x| (k.clone(), x))).collect(),
            status: m.status.to_string(),
            feasible: m.feasible,
            violations: m.violations.clone(),
        }
    }

    /// A path judged on the scenario (`view PLAN.json`, `compare --view`).
    pub fn from_plan(label: String, group: String, mission: usize, m: &tidepath::planner::MissionPlan) -> Self {
        Self {
            label,
            group,
            mission,
            points: m.path().to_vec(),
            times: m.times.clone(),
            speeds: m.speeds.clone(),
            flown: m.flown.as_ref().map(|f| (f.points.clone(), f.times.clone())),
            cost: Some(m.cost),
            terms: m.terms.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
            status: m.status.to_string(),
            feasible: m.feasible,
            violations: m.violations.clone(),
        }
    }
}

/// Declares a view output in `outputs` (written all or nothing on commit), refusing any
/// extension but .html: a view is never a plan file. The CLI's `--view`/`--out` and Python's
/// `Scenario.view(path=...)` share this rule.
pub fn declare_output(
    outputs: &mut tidepath_io::Outputs,
    field: &str,
    path: &std::path::Path,
) -> tidepath::error::Result<tidepath_io::OutputId> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if !matches!(ext.as_deref(), Some("html" | "htm")) {
        return Err(tidepath::Error::input(field, format!("`{}`: the view is written as .html", path.display())));
    }
    outputs.declare(field, path)
}

/// The routes of a plan report, one per mission (the smoothed path where smoothed, missions
/// with nothing planned left out); a fleet's vehicles each get their own colour.
pub fn report_routes(report: &tidepath_io::PlanReport) -> Vec<ViewRoute> {
    let several = report.missions.len() > 1;
    report
        .missions
        .iter()
        .enumerate()
        .filter(|(_, m)| m.waypoints.len() >= 2)
        .map(|(k, m)| {
            let label = if several { format!("{} {}", report.planner, m.name) } else { report.planner.clone() };
            ViewRoute::from_report(label.clone(), label, k, m)
        })
        .collect()
}

/// Everything one view shows.
pub struct ViewInput<'a> {
    pub scenario: &'a Scenario,
    /// The page's title line.
    pub title: String,
    pub routes: Vec<ViewRoute>,
    /// A `simulate` run: its executed track plays back, each phase's re-planned route appears
    /// at the phase's time, and obstacles and currents follow its epochs.
    pub simulation: Option<&'a Simulation>,
    /// The simulation's mission index (its vehicle).
    pub simulation_mission: usize,
}

/// Building the view was stopped (Ctrl-C): nothing is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stopped;

/// The stop check every loop polls.
pub(crate) fn poll(stop: &dyn Fn() -> bool) -> Result<(), Stopped> {
    if stop() {
        Err(Stopped)
    } else {
        Ok(())
    }
}
