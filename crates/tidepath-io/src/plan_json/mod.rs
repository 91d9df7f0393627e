//! The plan JSON written by `tidepath plan --out` and read by `tidepath eval` and
//! `plan --init`. Field meanings are documented in README.md ("Plan JSON"); keep the two in
//! step. The format is versioned: version 2 holds one timed path per mission and a status;
//! files written by version 1 (one path at the top level) still load.
//!
//! Optional fields that a reader may ignore without misreading the file (the frame, the
//! search's counters, a mission's `flown` curve) were added within version 3: an older
//! tidepath still reads such a file, and reads the same routes from it. The version goes up
//! only when an older reader would misread a file.

use serde::{Deserialize, Serialize};

use tidepath::geom::Vec3;
use tidepath::path::{Metrics, Violation};
use tidepath::planner::{Focus, MissionPlan, Plan, Status};
use tidepath::termination::StopReason;

mod read;
pub use read::{PlanFile, RouteFrame};

/// The version this build writes. Version 3 adds each mission's own status, reason and
/// distance left to the goal, and the search's checks and graph size; files of versions 1 and
/// 2 still load. A mission's `flown` curve (with a turning radius) is optional and ignored when
/// routes are read back, so it came within version 3.
pub const PLAN_FORMAT_VERSION: u32 = 3;

/// Most points a plan file's path may hold: far beyond any planner's output, small enough to
/// evaluate in well under a second.
pub const MAX_PLAN_POINTS: usize = 100_000;

/// What the plan was made from: everything in the JSON that is not in [`Plan`].
#[derive(Clone, Debug, Default)]
pub struct PlanAbout {
    pub seed: u64,
    pub scenario: String,
    pub scenario_source: String,
    pub cost_model: String,
    pub travel_time_model: String,
    pub time_limit_s: Option<f64>,
    /// The time limit was the default cap (nothing else set one).
    pub default_time_cap: bool,
    /// A warm start was given and the planner uses warm starts.
    pub warm_start: bool,
    /// The cost model's own feasibility rule ([`tidepath::cost::CostModel::feasible_below`]):
    /// a path is feasible under it when its cost is below this.
    pub model_rule_below: Option<f64>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MissionReport {
    pub name: String,
    /// The path, start and goal included, [x, y, z] in metres.
    pub waypoints: Vec<[f64; 3]>,
    /// The path after the smoother, when one ran; every field below then describes it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smoothed: Option<Vec<[f64; 3]>>,
    /// Cost of `waypoints` before smoothing, when a smoother ran.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub raw_cost: Option<f64>,
    /// Arrival time (s, scenario clock) at each point of the final path; with a turning
    /// radius, at an interior waypoint the time halfway round its turn.
    pub times: Vec<f64>,
    /// The through-water speed (m/s) of each segment of the final path, for a vehicle with a
    /// speed range; absent when every segment is flown at the vehicle's cruise speed. `eval`
    /// flies the path at these speeds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speeds: Option<Vec<f64>>,
    /// With a turning radius: the curve the vehicle flies along the final path (a fillet at
    /// each interior waypoint), as the evaluation sampled it, with its times. Absent without a
    /// radius. Never read back as a route: the waypoints are the route.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flown: Option<FlownReport>,
    /// `null` when nothing was planned (the status says why).
    pub cost: Option<f64>,
    /// The weighted terms of the cost model, in the model's order; they sum to `cost`.
    pub cost_terms: serde_json::Map<String, serde_json::Value>,
    /// The cost model's own feasibility rule and whether `cost` meets it, for a model whose
    /// paper has one (lfhh2019: cost below 2); reported beside `feasible`, which is tidepath's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model_rule: Option<ModelRule>,
    pub feasible: bool,
    pub violations: Vec<Violation>,
    pub metrics: Option<Metrics>,
    /// This mission's status and why (version 3; a plan's status is the worst of these).
    #[serde(default = "unknown_status")]
    pub status: Status,
    #[serde(default)]
    pub reason: String,
    /// The distance (m) from the path's last point to the goal when it stops short.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_distance_m: Option<f64>,
    /// The place this mission's failure is about (an invalid start or goal, a bottleneck), for
    /// the figure drawn by the same run; not written to the file.
    #[serde(skip)]
    pub focus: Option<Focus>,
}

/// The flown curve of a mission: points in the file's frame, like its waypoints, and the
/// arrival time at each (s, scenario clock), from the departure to the arrival at the goal.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FlownReport {
    pub points: Vec<[f64; 3]>,
    pub times: Vec<f64>,
}

impl FlownReport {
    fn new(f: &tidepath::path::Flown) -> Self {
        Self { points: points(&f.points), times: f.times.clone() }
    }

    /// The points as vectors (in the file's frame).
    pub fn vectors(&self) -> Vec<Vec3> {
        self.points.iter().map(|p| Vec3::from_array(*p)).collect()
    }
}

/// A cost model's own feasibility rule applied to one mission's cost.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelRule {
    /// The rule: the cost must be below this.
    pub below: f64,
    /// Whether the mission's cost is below it (false without a cost).
    pub met: bool,
}

impl ModelRule {
    /// The rule `cost < below` applied to `cost` (a non-finite cost does not meet it).
    pub fn of(below: f64, cost: f64) -> Self {
        Self { below, met: cost.is_finite() && cost < below }
    }
}

fn unknown_status() -> Status {
    Status::Infeasible
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanReport {
    /// Always "tidepath-plan".
    pub format: String,
    pub version: u32,
    /// The frame of every `waypoints` and `smoothed` list: always "metres" (the scenario's
    /// frame, x east, y north, z up) in files tidepath writes; a geographic plan gives its
    /// paths in longitude, latitude and depth in `geographic.paths` as well. A hand-written
    /// file may say "lonlat" instead (waypoints [longitude, latitude, depth_m], depth
    /// positive down).
    #[serde(default = "metres")]
    pub frame: String,
    pub tidepath_version: String,
    pub planner: String,
    pub seed: u64,
    pub scenario: String,
    pub scenario_source: String,
    pub cost_model: String,
    /// "crab" or "vector-sum": which travel-time model the cost and metrics used.
    pub travel_time_model: String,
    pub status: Status,
    /// One line: why the status is what it is.
    pub reason: String,
    /// True for status exact or feasible.
    pub feasible: bool,
    /// Sum of the missions' costs (`null` when nothing was planned).
    pub cost: Option<f64>,
    pub missions: Vec<MissionReport>,
    pub evaluations: u64,
    pub iterations: u64,
    pub expansions: u64,
    pub samples: u64,
    /// Validator calls made for the planner (OMPL's valid states and motions) and the size of
    /// the graph a graph planner built; 0 where not counted.
    #[serde(default)]
    pub state_checks: u64,
    #[serde(default)]
    pub motion_checks: u64,
    #[serde(default)]
    pub graph_nodes: u64,
    #[serde(default)]
    pub graph_edges: u64,
    /// Whether the run started from a warm start (`--init`) and the planner used it.
    #[serde(default)]
    pub warm_start: bool,
    pub stop_reason: StopReason,
    pub elapsed_s: f64,
    /// The wall-time limit of the run (s), and whether it was the default cap.
    pub time_limit_s: Option<f64>,
    pub default_time_cap: bool,
    /// Best cost after initialisation and after each iteration (null where still infinite).
    pub history: Vec<Option<f64>>,
    /// For geographic scenarios: the frame the metres are in, the clock's UTC zero, and each
    /// mission's path in longitude/latitude.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub geographic: Option<GeoReport>,
    /// The search graphs the planner kept when the run asked for them (`plan --graph`,
    /// `--plot-graph`), one per planned mission of a planner that builds one. Never written to
    /// the plan file (a graph can have 100 000 edges): [`crate::graph_file`] writes them.
    #[serde(skip)]
    pub graphs: Vec<GraphReport>,
    /// A fleet's separation: the closest pair of vehicles and every pair that came too close
    /// (only when the scenario keeps a separation).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fleet: Option<crate::fleet_report::FleetReport>,
}

/// One mission's search graph (a tree or a roadmap), as `plan --graph` writes it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GraphReport {
    /// The mission's name.
    pub mission: String,
    /// "tree" (every edge from parent to child) or "roadmap" (undirected edges).
    pub kind: String,
    /// [x, y, z] in metres, the scenario's frame.
    pub vertices: Vec<[f64; 3]>,
    /// Pairs of indices into `vertices`; in a tree, (parent, child).
    pub edges: Vec<[u32; 2]>,
    /// The start's vertex, and the goal's when the graph reached it.
    pub start: Option<u32>,
    pub goal: Option<u32>,
    /// In a geographic scenario, each vertex as [longitude, latitude, depth_m] (depth positive
    /// down), like `geographic.paths`.
    pub lonlat: Option<Vec<[f64; 3]>>,
}

impl GraphReport {
    fn new(g: &tidepath::planner::SearchGraph, missions: &[MissionPlan]) -> Self {
        Self {
            mission: missions.get(g.mission).map_or_else(|| format!("mission {}", g.mission), |m| m.name.clone()),
            kind: g.kind.to_string(),
            vertices: points(&g.vertices),
            edges: g.edges.clone(),
            start: g.start,
            goal: g.goal,
            lonlat: None,
        }
    }

    /// Whether edges have a direction (a tree's go from parent to child).
    pub fn directed(&self) -> bool {
        self.kind == "tree"
    }

    /// The length (m) of edge `e`; NaN when an index is out of range.
    pub fn edge_length(&self, e: [u32; 2]) -> f64 {
        match (self.vertices.get(e[0] as usize), self.vertices.get(e[1] as usize)) {
            (Some(a), Some(b)) => Vec3::from_array(*a).distance(Vec3::from_array(*b)),
            _ => f64::NAN,
        }
    }
}

/// Where a geographic plan's metres and seconds are on the Earth and the calendar.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GeoReport {
    /// "azimuthal-equidistant-wgs84" (`tidepath::geo`).
    pub projection: String,
    pub origin_lon: f64,
    pub origin_lat: f64,
    /// ISO 8601 UTC of the scenario clock's zero, when the scenario has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub epoch: Option<String>,
    /// Per mission, the final path as [longitude, latitude, depth_m] (depth positive down).
    pub paths: Vec<Vec<[f64; 3]>>,
    /// With a turning radius, per mission its flown curve in the same layout as `paths`
    /// (`null` for a mission without one); absent when no mission has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flown: Option<Vec<Option<Vec<[f64; 3]>>>>,
}

fn metres() -> String {
    "metres".into()
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

fn points(p: &[Vec3]) -> Vec<[f64; 3]> {
    p.iter().map(|q| q.to_array()).collect()
}

impl MissionReport {
    fn new(m: &MissionPlan, rule_below: Option<f64>) -> Self {
        Self {
            name: m.name.clone(),
            waypoints: points(&m.waypoints),
            smoothed: m.smoothed.as_deref().map(points),
            raw_cost: m.raw_cost,
            times: m.times.clone(),
            speeds: m.speeds.clone(),
            flown: m.flown.as_ref().map(FlownReport::new),
            cost: finite(m.cost),
            cost_terms: m.terms.iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect(),
            model_rule: rule_below.filter(|_| !m.waypoints.is_empty()).map(|b| ModelRule::of(b, m.cost)),
            feasible: m.feasible,
            violations: m.violations.clone(),
            metrics: m.metrics,
            status: m.status,
            reason: m.reason.clone(),
            goal_distance_m: m.goal_distance_m,
            focus: m.focus.clone(),
        }
    }

    /// The final path: `smoothed` when present, else `waypoints`.
    pub fn points(&self) -> Vec<Vec3> {
        self.smoothed.as_ref().unwrap_or(&self.waypoints).iter().map(|p| Vec3::from_array(*p)).collect()
    }
}

impl PlanReport {
    pub fn new(plan: &Plan, about: PlanAbout) -> Self {
        let s = &plan.stats;
        Self {
            format: "tidepath-plan".into(),
            version: PLAN_FORMAT_VERSION,
            frame: metres(),
            tidepath_version: env!("CARGO_PKG_VERSION").to_string(),
            planner: plan.planner.clone(),
            seed: about.seed,
            scenario: about.scenario,
            scenario_source: about.scenario_source,
            cost_model: about.cost_model,
            travel_time_model: about.travel_time_model,
            status: plan.status,
            reason: plan.reason.clone(),
            feasible: plan.status.is_success(),
            cost: finite(plan.cost),
            missions: plan.missions.iter().map(|m| MissionReport::new(m, about.model_rule_below)).collect(),
            evaluations: s.evaluations,
            iterations: s.iterations,
            expansions: s.expansions,
            samples: s.samples,
            state_checks: s.state_checks,
            motion_checks: s.motion_checks,
            graph_nodes: s.graph_nodes,
            graph_edges: s.graph_edges,
            warm_start: about.warm_start,
            stop_reason: s.stop_reason,
            elapsed_s: s.elapsed.as_secs_f64(),
            time_limit_s: about.time_limit_s,
            default_time_cap: about.default_time_cap,
            history: s.history.iter().map(|h| finite(*h)).collect(),
            geographic: None,
            graphs: plan.graphs.iter().map(|g| GraphReport::new(g, &plan.missions)).collect(),
            fleet: None,
        }
    }

    /// Adds the geographic frame and the paths in longitude/latitude.
    pub fn with_frame(
        mut self,
        frame: Option<&tidepath::geo::GeoFrame>,
        epoch: Option<chrono::DateTime<chrono::Utc>>,
    ) -> Self {
        if let Some(f) = frame {
            let degrees = |pts: &[Vec3]| -> Vec<[f64; 3]> {
                pts.iter()
                    .map(|p| {
                        let (lon, lat) = f.inverse(p.x, p.y);
                        [(lon * 1e7).round() / 1e7, (lat * 1e7).round() / 1e7, -p.z + 0.0]
                    })
                    .collect()
            };
            let paths = self.missions.iter().map(|m| degrees(&m.points())).collect();
            for g in &mut self.graphs {
                let vertices: Vec<Vec3> = g.vertices.iter().map(|p| Vec3::from_array(*p)).collect();
                g.lonlat = Some(degrees(&vertices));
            }
            let flown = self
                .missions
                .iter()
                .any(|m| m.flown.is_some())
                .then(|| self.missions.iter().map(|m| m.flown.as_ref().map(|c| degrees(&c.vectors()))).collect());
            self.geographic = Some(GeoReport {
                projection: "azimuthal-equidistant-wgs84".into(),
                origin_lon: f.lon0,
                origin_lat: f.lat0,
                epoch: epoch.map(|e| e.to_rfc3339_opts(chrono::SecondsFormat::Secs, true)),
                paths,
                flown,
            });
        }
        self
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("plan report serialises") + "\n"
    }

    /// The cost as a number (+inf when nothing was planned).
    pub fn cost_value(&self) -> f64 {
        self.cost.unwrap_or(f64::INFINITY)
    }

    /// The final path of each mission.
    pub fn paths(&self) -> Vec<Vec<Vec3>> {
        self.missions.iter().map(MissionReport::points).collect()
    }

    /// Summed length of the missions' final paths (m); `None` when nothing was planned.
    pub fn length_m(&self) -> Option<f64> {
        self.missions.iter().map(|m| m.metrics.map(|x| x.length_m)).sum()
    }

    /// Longest travel time of the missions (s): when the whole fleet has arrived.
    pub fn travel_time_s(&self) -> Option<f64> {
        self.missions.iter().map(|m| m.metrics.map(|x| x.travel_time_s)).try_fold(0.0f64, |a, t| t.map(|t| a.max(t)))
    }
}
