//! The scenario file format (TOML), as plain serde types. `build.rs` turns a spec into the
//! runtime model and checks every value; this file only says what may be written.
//!
//! Unknown keys are errors, so a typo is reported instead of silently ignored. New sections
//! are added as optional fields, so older files keep loading.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

pub use super::changes_spec::*;
pub use super::waves_spec::*;
pub use tidepath::encoding::EncodingSpec;

pub type P3 = [f64; 3];
pub type P2 = [f64; 2];

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioSpec {
    pub name: String,
    #[serde(default)]
    pub description: String,
    pub world: WorldSpec,
    #[serde(default)]
    pub vehicle: VehicleSpec,
    /// One mission (`[mission]`), or a fleet (`[[missions]]`): exactly one of the two.
    #[serde(default)]
    pub mission: Option<MissionSpec>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub missions: Vec<FleetMissionSpec>,
    #[serde(default)]
    pub model: ModelSpec,
    #[serde(default)]
    pub cost: CostSpec,
    #[serde(default)]
    pub encoding: EncodingSpec,
    #[serde(default)]
    pub planner: PlannerSpec,
    /// World changes revealed during the mission (`[[changes]]`), for `tidepath simulate`;
    /// `plan` ignores them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub changes: Vec<ChangeSpec>,
    /// The mission loop's settings (`[simulate]`); defaults when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simulate: Option<SimulateSpec>,
    /// The separation a fleet's vehicles keep from each other (`[fleet]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fleet: Option<super::fleet_spec::FleetSpec>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WorldSpec {
    /// 2 (horizontal plane) or 3.
    #[serde(default = "three")]
    pub dimensions: u8,
    /// `local` (metres, the default) or `geographic`: bounds, positions of missions and
    /// obstacles as [longitude, latitude, z] in degrees and metres, projected when loaded
    /// (`tidepath::geo`).
    #[serde(default)]
    pub frame: FrameKind,
    /// The UTC instant of the scenario clock's zero (ISO 8601), for ISO departures and
    /// forecast files; defaults to the earliest ISO departure.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub epoch: Option<String>,
    pub bounds: BoundsSpec,
    #[serde(default)]
    pub terrain: TerrainSpec,
    #[serde(default)]
    pub obstacles: Vec<ObstacleSpec>,
    #[serde(default)]
    pub current: CurrentSpec,
    /// The sea state (`[world.waves]`), read by wave gliders; absent: no waves.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub waves: Option<WavesSpec>,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrameKind {
    #[default]
    Local,
    Geographic,
}

fn three() -> u8 {
    3
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoundsSpec {
    pub min: P3,
    pub max: P3,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum TerrainSpec {
    #[default]
    None,
    /// Base level plus Gaussian peaks (wpa2017 eq. 1, lfhh2019 eq. 11).
    Peaks {
        base: f64,
        #[serde(default)]
        peaks: Vec<PeakSpec>,
        #[serde(default)]
        ceiling: Option<f64>,
    },
    /// Node elevations on a regular grid, row-major by y then x.
    Grid { origin: P2, spacing: P2, shape: [usize; 2], elevations: Vec<f64> },
    /// A grid given cell by cell, constant inside each cell (occupancy grids): a `map` of
    /// rows (`#` land, `.` water) or one elevation per cell; rows run north to south, as a
    /// map is read.
    Cells(CellsSpec),
    /// A bathymetry file on longitude/latitude (NetCDF or ESRI ASCII grid), for geographic
    /// scenarios: read inside the box, resampled onto a metric grid.
    File {
        /// Relative to the scenario file's folder.
        path: String,
        /// The elevation or depth variable (NetCDF); found by name and standard name if absent.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        variable: Option<String>,
        /// `up` (elevation) or `down` (depth); from the variable's attributes if absent.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        positive: Option<String>,
        /// Keep every n-th node of the file.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        decimate: Option<usize>,
        /// Spacing (m) of the metric grid; defaults to the file's own.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        resolution: Option<f64>,
    },
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CellsSpec {
    /// South-west corner of the grid (m).
    pub origin: P2,
    /// Side of a (square) cell (m).
    pub resolution: f64,
    /// Rows from north to south, one character per cell: `#` land, `.` water.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map: Option<Vec<String>>,
    /// Water depth (m, positive) of the `.` cells; default the domain's depth (-bounds.min.z),
    /// or 10 m where the domain is flat.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub water_depth: Option<f64>,
    /// Height (m) of the `#` cells above the sea surface (default 10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub land_height: Option<f64>,
    /// Instead of `map`: one elevation per cell (m, negative below the surface), rows from
    /// north to south.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub elevations: Option<Vec<Vec<f64>>>,
}

/// A current given per cell, at the cells' centres (bilinear between them).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurrentCellsSpec {
    /// South-west corner of the grid (m).
    pub origin: P2,
    /// Side of a (square) cell (m).
    pub resolution: f64,
    /// Eastward and northward components (m/s), rows from north to south.
    pub u: Vec<Vec<f64>>,
    pub v: Vec<Vec<f64>>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PeakSpec {
    pub x: f64,
    pub y: f64,
    pub height: f64,
    pub sigma_x: f64,
    pub sigma_y: f64,
}

/// The shapes an obstacle can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ObstacleKind {
    /// `center` [x, y, z], `radius`.
    Sphere,
    /// Vertical cylinder: `center` [x, y], `radius`, optional `z_min` / `z_max` (omit both for
    /// the full water column).
    Cylinder,
    /// Axis-aligned box: `min`, `max` [x, y, z].
    Box,
    /// Disc in a 2-D world: `center` [x, y], `radius`.
    Circle,
}

/// One obstacle. A flat record (not a tagged enum) so that a type error names the exact field,
/// e.g. `world.obstacles[3].radius`; which fields a kind needs is checked when the world is built.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObstacleSpec {
    pub kind: ObstacleKind,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub center: Option<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z_min: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z_max: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min: Option<P3>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max: Option<P3>,
    /// Constant velocity (m/s); the shape is where it is at time 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity: Option<P3>,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum CurrentSpec {
    #[default]
    None,
    Uniform {
        velocity: P3,
    },
    /// Lamb-Oseen vortices (lfhh2019 eqs. 3-5).
    Vortices {
        vortices: Vec<VortexSpec>,
    },
    /// ijs2023's meandering jet mapped onto `region` (defaults to the domain rectangle).
    Jet(JetSpec),
    /// A current forecast file (NetCDF: Copernicus Marine, HYCOM or any CF file), for
    /// geographic scenarios: read inside the box at one depth level, resampled to metres.
    File {
        /// Relative to the scenario file's folder.
        path: String,
        /// Eastward and northward velocity variables; found by name and standard name if absent.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        u: Option<String>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        v: Option<String>,
        /// Depth (m, positive down) of the level to read: the nearest one (default 0).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        depth: Option<f64>,
        /// Spacing (m) of the metric grid; defaults to the file's own.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        resolution: Option<f64>,
    },
    /// One u, v per cell of a grid given cell by cell (with terrain `kind = "cells"`).
    Cells(CurrentCellsSpec),
    /// u, v on a regular grid at several times; bilinear in space, linear in time.
    Grid {
        origin: P2,
        spacing: P2,
        shape: [usize; 2],
        times: Vec<f64>,
        u: Vec<Vec<f64>>,
        v: Vec<Vec<f64>>,
        /// Nodes (row-major indices) without data: motions through their cells are invalid.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        no_data: Vec<usize>,
    },
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VortexSpec {
    pub x: f64,
    pub y: f64,
    pub strength: f64,
    pub core_radius: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JetSpec {
    /// [x_min, y_min, x_max, y_max] of the world rectangle the jet is mapped onto.
    #[serde(default)]
    pub region: Option<[f64; 4]>,
    /// Current speed (m/s) everywhere, direction from the jet (ijs2023's |v_c| = ratio |v|).
    #[serde(default)]
    pub speed: Option<f64>,
    /// Alternatively scale so the jet's fastest point moves at this speed (m/s).
    #[serde(default)]
    pub max_speed: Option<f64>,
    /// `speed` as a ratio of the scenario's `[vehicle] speed` (ijs2023: 0.5, 0.8, 1.2; 0.2 for
    /// its fleet).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_ratio: Option<f64>,
    /// `max_speed` as a ratio of the scenario's `[vehicle] speed`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_speed_ratio: Option<f64>,
    /// Seconds per jet time unit (default 2000).
    #[serde(default)]
    pub time_scale: Option<f64>,
    /// Overrides of the jet's constants (defaults: docs/papers/shared.md#meandering-jet).
    #[serde(default)]
    pub kappa: Option<f64>,
    #[serde(default)]
    pub eps: Option<f64>,
    #[serde(default)]
    pub eta: Option<f64>,
    #[serde(default)]
    pub alpha0: Option<f64>,
    #[serde(default)]
    pub beta: Option<f64>,
    #[serde(default)]
    pub gamma: Option<f64>,
    #[serde(default)]
    pub omega0: Option<f64>,
    /// Jet-unit intervals the region maps onto (defaults [0, 10] and [-3, 3]).
    #[serde(default)]
    pub jet_x: Option<[f64; 2]>,
    #[serde(default)]
    pub jet_y: Option<[f64; 2]>,
}

/// Vehicle limits; every field has a default (a generic 1.5 m/s survey AUV).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct VehicleSpec {
    /// `auv` (thrusters, the default) or `wave-glider` (driven by the waves: acopf2016).
    #[serde(skip_serializing_if = "VehicleKind::is_auv")]
    pub kind: VehicleKind,
    /// The glider's speed regression (acopf2016 eqs. 1-2): m/s per metre of significant wave
    /// height (default 0.1623), m/s per m/s of current along the heading (default 0.2660),
    /// and the slowest speed over ground (m/s, default 0.05). Wave gliders only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wave_gain: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub current_gain: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_speed: Option<f64>,
    /// Cruise speed through the water (m/s): every segment's speed without a range, the
    /// default speed and the time normalisation with one.
    pub speed: f64,
    /// Lowest and highest through-water speed (m/s) a plan may give a segment; with either,
    /// speed becomes a decision (one alone pairs with `speed`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_min: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_max: Option<f64>,
    /// Minimum turning radius (m); none: only `max_turn_deg` limits turns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turn_radius: Option<f64>,
    pub max_turn_deg: f64,
    pub max_pitch_deg: f64,
    pub depth_min: f64,
    pub depth_max: f64,
    pub safety_distance: f64,
}

impl Default for VehicleSpec {
    fn default() -> Self {
        let v = tidepath::vehicle::Vehicle::default();
        Self {
            kind: VehicleKind::Auv,
            wave_gain: None,
            current_gain: None,
            min_speed: None,
            speed: v.speed,
            speed_min: None,
            speed_max: None,
            turn_radius: None,
            max_turn_deg: v.max_turn.to_degrees(),
            max_pitch_deg: v.max_pitch.to_degrees(),
            depth_min: v.depth_min,
            depth_max: v.depth_max,
            safety_distance: v.safety_distance,
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MissionSpec {
    /// The mission's name in plans, messages and exports ("mission" when not given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Start and goal as points, or as cells of the terrain's `kind = "cells"` grid numbered
    /// by acopf2016's eq. 3 (`start_cell`, `goal_cell`, 1-based from the south-west): exactly
    /// one of each pair.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start: Option<P3>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal: Option<P3>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_cell: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_cell: Option<usize>,
    #[serde(default)]
    pub departure_time: f64,
    /// Departure as an ISO 8601 UTC instant (instead of `departure_time` seconds).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub departure: Option<String>,
}

/// One vehicle of a fleet: its own mission and, optionally, its own vehicle limits (else the
/// scenario's `[vehicle]`).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FleetMissionSpec {
    pub name: String,
    pub start: P3,
    pub goal: P3,
    #[serde(default)]
    pub departure_time: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub departure: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vehicle: Option<VehicleSpec>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ModelSpec {
    /// "crab" (default) or "vector-sum" (ijs2023 eq. 17).
    pub travel_time: tidepath::path::TravelModel,
    /// Longest sub-step (m) for integrating travel time through the current.
    pub current_step: Option<f64>,
    /// Largest distance (m) between a flown turn and the chords it is checked on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arc_tolerance: Option<f64>,
}

impl Default for ModelSpec {
    fn default() -> Self {
        Self { travel_time: tidepath::path::TravelModel::Crab, current_step: None, arc_tolerance: None }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CostSpec {
    pub model: String,
    /// Model-specific weights, checked by the model.
    pub weights: toml::Table,
}

impl Default for CostSpec {
    fn default() -> Self {
        Self { model: "general".into(), weights: toml::Table::new() }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PlannerSpec {
    /// The planner `plan` uses when `--planner` is not given: `hybrid` unless the scenario
    /// says otherwise (it is the most reliable on the built-in scenarios, see README).
    pub id: String,
    pub iterations: Option<u64>,
    pub evaluations: Option<u64>,
    /// Limits in the units graph and sampling planners count; a limit in a unit the planner
    /// does not count is left aside (it is a default for whichever planner runs).
    pub expansions: Option<u64>,
    pub samples: Option<u64>,
    /// Stop once the best cost is at most this.
    pub target_cost: Option<f64>,
    /// Wall-time safety net (s); results that hit it depend on the machine.
    pub time_limit_s: Option<f64>,
    pub population: Option<usize>,
    /// Per-planner parameters: `[planner.params.pso]`, `[planner.params.ga]`, ...
    pub params: BTreeMap<String, toml::Table>,
    /// A smoother every plan goes through (`shortcut`), or none.
    pub smoother: Option<String>,
    /// Per-smoother parameters: `[planner.smoother_params.shortcut]`, ...
    pub smoother_params: BTreeMap<String, toml::Table>,
}

impl Default for PlannerSpec {
    fn default() -> Self {
        Self {
            id: "hybrid".into(),
            iterations: Some(200),
            evaluations: None,
            expansions: None,
            samples: None,
            target_cost: None,
            time_limit_s: None,
            population: None,
            params: BTreeMap::new(),
            smoother: None,
            smoother_params: BTreeMap::new(),
        }
    }
}
