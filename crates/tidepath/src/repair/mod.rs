//! Repair operators: deterministic moves of a path's interior waypoints, applied in place, that
//! any planner can use inside its search (the objective's repair, `[encoding] repair`) and any
//! plan can go through afterwards (the `exclude`, `contract` and `exclude-contract` smoothers).
//!
//! amfa2015's two operators (section 4.3, eqs. 9-10; readings A9, A10 and A14 of
//! docs/papers/amfa2015.md):
//!
//! * [`Exclude`] (eq. 9 read as A9): a route point inside an obstacle or the seabed (within the
//!   vehicle's safety distance, as the validator judges a state) is moved along the outward
//!   normal of the local surface onto that surface plus a margin δ.
//! * [`Contract`] (eq. 10 read as A10): each route point is pulled part of the way toward the
//!   midpoint of its (already updated) neighbours, P' = P + k((P'_{i−1} + P'_{i+1})/2 − P); a
//!   pull that would make the point invalid is undone.
//! * [`ExcludeContract`]: exclude, then contract (the order chosen in A14).
//!
//! Moving obstacles are met where they are when the vehicle gets there: each point's time is
//! the arrival time along the path as repaired so far (the previous point's time plus the
//! segment's travel time through the current, at the segment's speed), recomputed after every
//! move. The start and the goal never move.

pub mod contract;
pub mod exclude;
mod segments;

#[cfg(test)]
mod tests;

pub use contract::{Contract, ContractParams};
pub use exclude::{Exclude, ExcludeParams};

use crate::error::Result;
use crate::geom::Vec3;
use crate::params::{Bound, Range};
use crate::path::PathModel;
use crate::registry::{Entry, Registry};
use crate::world::Dims;

/// A repair operator: moves interior waypoints of a path in place.
pub trait Repair: Send + Sync {
    /// The id used in scenarios (`[encoding] repair`) and on the command line.
    fn id(&self) -> &'static str;
    /// Repairs `points` (start and goal included; they never move) in place. Deterministic:
    /// no randomness. Allocation-free: world point queries only.
    fn apply(&self, model: &PathModel<'_>, points: &mut [Vec3]);
}

/// Builds a repair from its parameter table; the prefix names the table in errors.
pub type BuildRepair = fn(&toml::Table, &str) -> Result<Box<dyn Repair>>;

/// amfa2015's resistance coefficient k (section 5.2).
pub const RESISTANCE: f64 = 0.9553;

/// The range of the exclusion margin (m): zero or more.
pub(crate) const MARGIN_RANGE: Range = Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded };
/// The range of the resistance coefficient: (0, 1), as eq. 10 states.
pub(crate) const RESISTANCE_RANGE: Range = Range::Number { lo: Bound::Open(0.0), hi: Bound::Open(1.0) };

crate::params! {
    /// Parameters of excluding then contracting.
    pub struct ExcludeContractParams {
        /// Exclusion margin δ beyond the safety distance (m); absent: 1 % of the world's
        /// depth range (its z extent), or 0.1 % of its larger horizontal side in a 2-D world.
        margin: Option<f64> = None, MARGIN_RANGE, "amfa2015 eq. 9 (A9: δ chosen)";
        /// Also move out segments that cut an obstacle's or the seabed's envelope between two
        /// clear route points (tidepath's addition; the paper excludes points only).
        segments: bool = true, Range::Flag, "tidepath (docs/papers/amfa2015.md A9)";
        /// Resistance coefficient k of the contraction: the fraction of the way toward the
        /// neighbours' midpoint a point moves.
        k: f64 = RESISTANCE, RESISTANCE_RANGE, "amfa2015 eq. 10 and section 5.2";
    }
}

/// Exclude, then contract (amfa2015's order, A14).
#[derive(Clone, Debug, Default)]
pub struct ExcludeContract {
    exclude: Exclude,
    contract: Contract,
}

impl ExcludeContract {
    pub fn new(params: crate::params::Checked<ExcludeContractParams>) -> Self {
        let p = params.into_inner();
        Self { exclude: Exclude::with_margin(p.margin, p.segments), contract: Contract::with_k(p.k) }
    }
}

impl Repair for ExcludeContract {
    fn id(&self) -> &'static str {
        "exclude-contract"
    }

    fn apply(&self, model: &PathModel<'_>, points: &mut [Vec3]) {
        self.exclude.apply(model, points);
        self.contract.apply(model, points);
    }
}

/// The repairs, selected by `[encoding] repair` (inside a search) and as smoothers (after it).
pub const REPAIRS: &[Entry<BuildRepair>] = &[
    Entry {
        id: "exclude",
        description: "move route points inside an obstacle or the seabed out along the surface normal, onto the safety envelope plus a margin; then segments cutting an envelope between clear points",
        citation: "amfa2015 section 4.3.1, eq. 9 (read as A9)",
        params: ExcludeParams::SPECS,
        build: |t, prefix| Ok(Box::new(Exclude::new(ExcludeParams::from_table(t, prefix)?))),
    },
    Entry {
        id: "contract",
        description: "pull each route point k of the way toward its neighbours' midpoint, unless that makes it invalid",
        citation: "amfa2015 section 4.3.2, eq. 10 (read as A10)",
        params: ContractParams::SPECS,
        build: |t, prefix| Ok(Box::new(Contract::new(ContractParams::from_table(t, prefix)?))),
    },
    Entry {
        id: "exclude-contract",
        description: "exclude, then contract (AMFA's repair of every candidate path)",
        citation: "amfa2015 section 4.3 (order: A14)",
        params: ExcludeContractParams::SPECS,
        build: |t, prefix| Ok(Box::new(ExcludeContract::new(ExcludeContractParams::from_table(t, prefix)?))),
    },
];

pub fn registry() -> Registry<BuildRepair> {
    Registry::new("repair", "encoding.repair", "tidepath planners", REPAIRS)
}

/// Repair `id` with its parameter table (`None`: its defaults); parameter errors name
/// `encoding.repair_params.ID`.
pub fn build_repair(id: &str, params: Option<&toml::Table>) -> Result<Box<dyn Repair>> {
    build_repair_prefixed(id, params, &format!("encoding.repair_params.{id}"))
}

/// Repair `id` with its parameter table, errors naming `prefix.FIELD` (a smoother's table,
/// say).
pub fn build_repair_prefixed(id: &str, params: Option<&toml::Table>, prefix: &str) -> Result<Box<dyn Repair>> {
    let build = registry().get(id)?.build;
    build(&params.cloned().unwrap_or_default(), prefix)
}

/// The default exclusion margin δ for `model`'s world: 1 % of its depth range (the z extent of
/// the domain, A9), or, in a 2-D world or one without depth, 0.1 % of its larger horizontal
/// side.
pub fn default_margin(model: &PathModel<'_>) -> f64 {
    let size = model.world.bounds.size();
    let depth = size.z;
    let m = if model.world.dims == Dims::Three && depth.is_finite() && depth > 0.0 {
        0.01 * depth
    } else {
        1e-3 * size.x.max(size.y)
    };
    if m.is_finite() {
        m
    } else {
        0.0
    }
}

/// `p` clamped into the domain and, in 3-D, into the vehicle's depth band (where the band and
/// the domain overlap); a 2-D world keeps z.
pub(crate) fn clamp_to_domain(model: &PathModel<'_>, p: Vec3) -> Vec3 {
    let b = &model.world.bounds;
    let x = p.x.clamp(b.min.x.min(b.max.x), b.max.x.max(b.min.x));
    let y = p.y.clamp(b.min.y.min(b.max.y), b.max.y.max(b.min.y));
    let z = match model.world.dims {
        Dims::Two => p.z,
        Dims::Three => {
            let lo = b.min.z.max(model.vehicle.z_min());
            let hi = b.max.z.min(model.vehicle.z_max());
            if lo <= hi {
                p.z.clamp(lo, hi)
            } else {
                p.z.clamp(b.min.z.min(b.max.z), b.max.z.max(b.min.z))
            }
        }
    };
    // NaN coordinates stay NaN (clamp keeps them): the validator then rejects the point.
    Vec3::new(x, y, z)
}

/// Arrival time at `b` for segment `i` (a -> b) left at `t0`.
#[inline]
pub(crate) fn arrival(model: &PathModel<'_>, i: usize, a: Vec3, b: Vec3, t0: f64) -> f64 {
    t0 + model.segment_time(i, a, b, t0).0
}
