//! Encodings turn a bounded decision vector into a path (start and goal included). They own
//! their bounds and constraints, so every optimizer gets them for free through `repair`.

pub mod free;
pub mod posture;
pub mod sliced;

pub use free::FreeWaypoints;
pub use posture::{Posture, StepLimit};
pub use sliced::Sliced;

use crate::error::Result;
use crate::geom::{Aabb, Vec3};
use crate::params::{Checked, Range};
use crate::registry::{Entry, Registry};

/// What an encoding is built from: one mission's endpoints, the domain and the height band.
#[derive(Clone, Copy, Debug)]
pub struct EncodingArgs<'a> {
    pub start: Vec3,
    pub goal: Vec3,
    /// Interior waypoints (start and goal come on top).
    pub waypoints: usize,
    pub bounds: &'a Aabb,
    /// The height band a 3-D encoding may use, or `None` in a 2-D world.
    pub z_range: Option<(f64, f64)>,
    /// The sliced encoding's main axis.
    pub axis: SliceAxis,
    /// The sliced encoding's posture limits (ijs2023 eq. 14).
    pub posture: Posture,
}

/// The direction the sliced encoding's planes are spaced along (`[encoding] axis`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SliceAxis {
    /// The horizontal start-to-goal direction: planes across it (wpa2017's x-axis planes when
    /// start and goal share a y).
    #[default]
    Path,
    /// The world's x axis: planes x = const, evenly spaced from the start's x to the goal's
    /// (lfhh2019's lines Y = j, with the paper's travel axis as tidepath's x).
    X,
    /// The world's y axis: planes y = const.
    Y,
}

impl SliceAxis {
    pub fn is_path(&self) -> bool {
        *self == SliceAxis::Path
    }
}

/// The `[encoding]` section: which encoding optimization planners search over.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct EncodingSpec {
    /// "sliced" or "free".
    pub kind: String,
    /// Interior waypoints (start and goal come on top).
    pub waypoints: usize,
    /// The sliced encoding's main axis: "path" (default), "x" or "y".
    #[serde(skip_serializing_if = "SliceAxis::is_path")]
    pub axis: SliceAxis,
    /// The repair applied to every candidate path inside the search (an id of
    /// [`crate::repair::REPAIRS`], or "none"); absent: the optimizer's own
    /// ([`crate::optim::Optimizer::default_repair`]: amfa2015's AMFA excludes and contracts).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repair: Option<String>,
    /// Each repair's parameters, `[encoding.repair_params.ID]`.
    #[serde(skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub repair_params: std::collections::BTreeMap<String, toml::Table>,
    /// The sliced encoding's posture limits (ijs2023 eq. 14), metres between planes: the
    /// largest sideways move (UB) ...
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral_step: Option<f64>,
    /// ... and vertical move (UR).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertical_step: Option<f64>,
    /// The same limits as angles: UB = spacing x tan(heading_limit_deg) ...
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heading_limit_deg: Option<f64>,
    /// ... and UR = spacing x tan(pitch_limit_deg).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pitch_limit_deg: Option<f64>,
}

impl Default for EncodingSpec {
    fn default() -> Self {
        Self {
            kind: "sliced".into(),
            waypoints: 20,
            axis: SliceAxis::Path,
            repair: None,
            repair_params: std::collections::BTreeMap::new(),
            lateral_step: None,
            vertical_step: None,
            heading_limit_deg: None,
            pitch_limit_deg: None,
        }
    }
}

pub type BuildEncoding = fn(&EncodingArgs<'_>) -> Result<Box<dyn Encoding>>;

/// Most interior waypoints an encoding may have: a path of more is no route a vehicle flies.
pub const MAX_WAYPOINTS: usize = 10_000;

crate::params! {
    /// The encodings' one parameter (`[encoding] waypoints`).
    pub struct EncodingParams {
        /// Interior waypoints (start and goal come on top).
        waypoints: usize = 20, Range::integer(1, MAX_WAYPOINTS as u64), "tidepath";
    }
}

impl EncodingSpec {
    /// The spec with its waypoint count checked (`encoding.waypoints` in errors).
    pub fn checked(&self) -> Result<Checked<EncodingParams>> {
        EncodingParams { waypoints: self.waypoints }.checked("encoding")
    }

    /// The posture limits of `[encoding]` (checked: field and value named on error).
    pub fn posture(&self) -> Result<Posture> {
        Posture::from_spec(self.lateral_step, self.heading_limit_deg, self.vertical_step, self.pitch_limit_deg)
    }

    /// The repair to apply inside the search: `[encoding] repair` ("none": none), else
    /// `default` (the optimizer's), built with its `[encoding.repair_params.ID]` table. Every
    /// table under `repair_params` is checked, used or not, so a typo fails before planning.
    pub fn build_repair(&self, default: Option<&str>) -> Result<Option<Box<dyn crate::repair::Repair>>> {
        for (id, table) in &self.repair_params {
            let registry = crate::repair::registry();
            if registry.find(id).is_none() {
                let known = registry.ids().collect::<Vec<_>>().join(", ");
                return Err(crate::error::Error::input(
                    format!("encoding.repair_params.{id}"),
                    format!("unknown repair '{id}' (known: {known})"),
                ));
            }
            crate::repair::build_repair(id, Some(table))?;
        }
        let id = match self.repair.as_deref() {
            Some("none") => return Ok(None),
            Some(id) => id,
            None => match default {
                Some(id) => id,
                None => return Ok(None),
            },
        };
        crate::repair::build_repair(id, self.repair_params.get(id)).map(Some)
    }
}

/// The encodings, selected by `[encoding] kind`.
pub const ENCODINGS: &[Entry<BuildEncoding>] = &[
    Entry {
        id: "sliced",
        description: "one waypoint on each of n planes across the start-goal axis (cannot turn back along it)",
        citation: "wpa2017 section 3.1, lfhh2019 eqs. 12-13, ijs2023 section 3.1 (generalised to any axis)",
        params: EncodingParams::SPECS,
        build: |a| {
            Ok(Box::new(
                Sliced::along(a.start, a.goal, a.waypoints, a.bounds, a.z_range, a.axis)?.with_posture(a.posture)?,
            ))
        },
    },
    Entry {
        id: "free",
        description: "n waypoints anywhere in the domain, visited in order",
        citation: "amfa2015 section 4",
        params: EncodingParams::SPECS,
        build: |a| {
            if !a.axis.is_path() {
                return Err(crate::error::Error::input(
                    "encoding.axis",
                    "only the sliced encoding has an axis; the free encoding places waypoints anywhere",
                ));
            }
            if !a.posture.is_none() {
                return Err(crate::error::Error::input(
                    "encoding.lateral_step",
                    "posture limits (lateral_step, vertical_step, heading_limit_deg, pitch_limit_deg) are the sliced encoding's: its waypoints lie on planes",
                ));
            }
            Ok(Box::new(FreeWaypoints::new(a.start, a.goal, a.waypoints, a.bounds, a.z_range)?))
        },
    },
];

pub fn registry() -> Registry<BuildEncoding> {
    Registry::new("encoding", "encoding.kind", "tidepath planners", ENCODINGS)
}

pub trait Encoding: Send + Sync {
    /// The name used in scenario files.
    fn id(&self) -> &'static str;
    fn dim(&self) -> usize;
    fn lower(&self) -> &[f64];
    fn upper(&self) -> &[f64];
    /// Writes the path for `x` into `out` (cleared first): start, waypoints, goal.
    fn decode_into(&self, x: &[f64], out: &mut Vec<Vec3>);
    /// The decision vector whose path best follows `path` (start and goal included), clamped
    /// to the bounds: how a warm start enters an optimizer's population.
    fn encode(&self, path: &[Vec3]) -> Vec<f64>;
    /// Variables that place one interior waypoint (the sliced encoding: lateral offset, and
    /// height in 3-D; the free encoding: x, y, and z in 3-D). Waypoint k's are
    /// `x[k * waypoint_dim()..(k + 1) * waypoint_dim()]`.
    fn waypoint_dim(&self) -> usize;
    /// Interior waypoint k (0-based) for its variables `v`.
    fn waypoint_at(&self, k: usize, v: &[f64]) -> Vec3;
    /// Sets interior waypoint k's variables in `x` to those that best place it at `p` (its
    /// projection onto the waypoint's plane for the sliced encoding), unclamped: call
    /// [`Encoding::repair`] afterwards.
    fn set_waypoint(&self, x: &mut [f64], k: usize, p: Vec3);
    /// Brings `x` back inside the encoding's feasible set. The default clamps to the bounds.
    fn repair(&self, x: &mut [f64]) {
        for ((v, lo), hi) in x.iter_mut().zip(self.lower()).zip(self.upper()) {
            *v = v.clamp(*lo, *hi);
        }
    }

    fn decode(&self, x: &[f64]) -> Vec<Vec3> {
        let mut out = Vec::new();
        self.decode_into(x, &mut out);
        out
    }
}

/// The point at arc-length fraction `f` in [0, 1] along a polyline.
pub fn point_at_fraction(path: &[Vec3], f: f64) -> Vec3 {
    let total: f64 = path.windows(2).map(|w| w[0].distance(w[1])).sum();
    let mut left = f.clamp(0.0, 1.0) * total;
    for w in path.windows(2) {
        let l = w[0].distance(w[1]);
        if left <= l && l > 0.0 {
            return w[0] + (w[1] - w[0]) * (left / l);
        }
        left -= l;
    }
    path.last().copied().unwrap_or(Vec3::ZERO)
}
