//! The scenario file's `[[changes]]` (world changes revealed during a mission) and
//! `[simulate]` (the mission loop's settings) sections, as plain serde types.
//! `changes_build.rs` checks them and turns them into `tidepath::world::changes::Change` and
//! `tidepath::simulate::SimParams`.
//!
//! A change is a flat record, not a tagged enum, so that a type error names the exact field
//! (`changes[2].strength`); which fields a kind needs is checked when the scenario is built,
//! and a field the kind does not use is an error naming it.

use serde::{Deserialize, Serialize};

use super::spec::{CurrentSpec, ObstacleSpec};

/// One world change: exactly one trigger (`at_time`, `at` or `after_distance`), its `kind`,
/// and the fields that kind needs.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChangeSpec {
    /// Trigger: the time on the scenario clock (s) at which the change is revealed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at_time: Option<f64>,
    /// Trigger: the UTC instant (ISO 8601, e.g. "2025-11-12T05:00:00Z") at which the change
    /// is revealed; needs the scenario clock's zero (`world.epoch`, an ISO departure or a
    /// forecast file's first time).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<String>,
    /// Trigger: the distance (m) travelled along the route since departure after which the
    /// change is revealed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub after_distance: Option<f64>,
    /// What changes: "move-obstacle", "obstacle-velocity", "add-obstacle", "remove-obstacle",
    /// "move-vortex", "vortex-strength" or "current".
    pub kind: ChangeKindId,
    /// The obstacle a move-obstacle, obstacle-velocity or remove-obstacle change acts on: its
    /// index in the obstacle list as it is when the change applies (`world.obstacles` in
    /// order, then the obstacles added by earlier add-obstacle changes; removing one shifts
    /// the indices of those after it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub obstacle: Option<usize>,
    /// The vortex of `world.current` (kind = "vortices") a move-vortex or vortex-strength
    /// change acts on: its index in `vortices`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vortex: Option<usize>,
    /// The new centre. move-obstacle: [x, y] in a 2-D world, [x, y, z] in a 3-D one
    /// ([longitude, latitude(, z)] in a geographic scenario, projected like
    /// `world.obstacles`' centres); the obstacle is there at the change's time and keeps its
    /// velocity. move-vortex: [x, y] in metres, in the local frame in a geographic scenario
    /// too, as `world.current.vortices` are. May be left out with `random`: the draw then
    /// displaces the centre the obstacle or vortex has when the change applies, so successive
    /// changes add up to a random walk.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub center: Option<Vec<f64>>,
    /// obstacle-velocity: the obstacle's new velocity (m/s), [vx, vy] or [vx, vy, vz]; east
    /// and north in a geographic scenario, as `world.obstacles`' velocities are (turned into
    /// the frame at the obstacle's charted centre: `world.obstacles`, then the obstacles the
    /// changes listed before add, by index). The obstacle keeps its place at the change's
    /// time and moves on at this velocity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity: Option<Vec<f64>>,
    /// vortex-strength: the vortex's new circulation strength (m^2/s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strength: Option<f64>,
    /// add-obstacle: the new obstacle, a table exactly like a `[[world.obstacles]]` entry
    /// (its shape is where it is at time 0, as for every obstacle).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub add: Option<ObstacleSpec>,
    /// current: the new current (a newer forecast), a table exactly like `[world.current]`,
    /// including kind = "file" for a NetCDF forecast in a geographic scenario (its times are
    /// read on the scenario clock).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub current: Option<CurrentSpec>,
    /// move-obstacle, add-obstacle, move-vortex: a random displacement of the centre the
    /// change sets, drawn from the run's seed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub random: Option<RandomSpec>,
}

/// The kinds of change, as written in `kind`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ChangeKindId {
    /// `obstacle`, `center`; optional `random`.
    MoveObstacle,
    /// `obstacle`, `velocity`.
    ObstacleVelocity,
    /// `add`; optional `random`.
    AddObstacle,
    /// `obstacle`.
    RemoveObstacle,
    /// `vortex`, `center`; optional `random`.
    MoveVortex,
    /// `vortex`, `strength`.
    VortexStrength,
    /// `current`.
    Current,
}

impl ChangeKindId {
    /// The name written in the file.
    pub fn id(self) -> &'static str {
        match self {
            ChangeKindId::MoveObstacle => "move-obstacle",
            ChangeKindId::ObstacleVelocity => "obstacle-velocity",
            ChangeKindId::AddObstacle => "add-obstacle",
            ChangeKindId::RemoveObstacle => "remove-obstacle",
            ChangeKindId::MoveVortex => "move-vortex",
            ChangeKindId::VortexStrength => "vortex-strength",
            ChangeKindId::Current => "current",
        }
    }
}

/// A random displacement of a change's centre (lfhh2019's random environment changes).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomSpec {
    /// "gaussian" (each axis normal with standard deviation `scale`) or "uniform" (each axis
    /// uniform on [-scale, scale]).
    pub law: LawId,
    /// Metres, >= 0.
    pub scale: f64,
    /// Draws tried while the displaced obstacle covers the vehicle or its goal, before the
    /// change is skipped (default 100, lfhh2019's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_draws: Option<u64>,
}

/// The law of a random displacement, as written in `law`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LawId {
    Gaussian,
    Uniform,
}

/// The mission loop's settings (`tidepath::simulate::SimParams`); every field optional.
/// Fields given apply on top of `preset`, or of the defaults when there is none.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimulateSpec {
    /// "lfhh2019": start from lfhh2019's rule (window 20, grown by 1 waypoint while the
    /// window's piece is infeasible, a re-plan at every change, no warm start) instead of the
    /// defaults.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preset: Option<PresetId>,
    /// Waypoints ahead of the vehicle the first re-planned window reaches (default 20, >= 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub window: Option<usize>,
    /// How the window grows while no feasible piece is found: "double" (default) or "add".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub growth: Option<GrowthId>,
    /// When a re-planned window is good enough: "route" (default: the route spliced from it
    /// is feasible to the goal) or "window" (its piece is, lfhh2019's rule; the preset's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub accept: Option<AcceptId>,
    /// Waypoints added per growth step with growth = "add" (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub growth_step: Option<usize>,
    /// When a change leads to a re-plan: "when-infeasible" (default: only when the route
    /// ahead breaks on the world as now known) or "always" (at every change).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub policy: Option<PolicyId>,
    /// Warm-start planners that take one from the old route's piece in the window (default
    /// true).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub warm_start: Option<bool>,
    /// Moving obstacles are known only within this range (m, > 0) of the vehicle, counted
    /// from their surface; fixed obstacles are charted. Absent: every obstacle is known from
    /// departure.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensor_range: Option<f64>,
}

/// Presets of `[simulate]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PresetId {
    /// `tidepath::simulate::SimParams::LFHH2019`.
    Lfhh2019,
}

/// `[simulate] growth`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum GrowthId {
    Double,
    Add,
}

/// `[simulate] accept`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum AcceptId {
    Route,
    Window,
}

/// `[simulate] policy`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PolicyId {
    WhenInfeasible,
    Always,
}
