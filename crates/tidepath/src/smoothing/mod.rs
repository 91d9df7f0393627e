//! Smoothing and repair operators: components any planner's output can go through, as in
//! OMPL's `PathSimplifier`. The paper-specific ones (Dubins for wpa2017, B-splines with
//! midpoint insertion for ijs2023, excluding and contracting for amfa2015) join this folder.

pub mod bspline;
pub mod dubins;
pub mod repair_smoother;
pub mod shortcut;

pub use shortcut::Shortcut;

use crate::cost::CostModel;
use crate::error::Result;
use crate::geom::Vec3;
use crate::path::PathModel;
use crate::registry::{Entry, Registry};
use crate::termination::Termination;

pub trait Smoother: Send + Sync {
    /// The id used on the command line and in scenarios.
    fn id(&self) -> &'static str;
    /// A path with the same start and goal that is never worse under `cost`, and never
    /// infeasible when `points` is feasible. Polls `termination` (the run's clock and stop
    /// flag) in its loops and returns its best path so far when it fires.
    fn smooth(
        &self,
        model: &PathModel<'_>,
        cost: &dyn CostModel,
        points: &[Vec3],
        termination: &Termination,
    ) -> Vec<Vec3>;
}

/// Builds a smoother from its `[planner.smoother_params.ID]` table; the prefix names the
/// table in errors.
pub type BuildSmoother = fn(&toml::Table, &str) -> Result<Box<dyn Smoother>>;

/// The smoothers, selected by `--smooth` or `[planner] smoother`.
pub const SMOOTHERS: &[Entry<BuildSmoother>] = &[
    Entry {
        id: "shortcut",
        description: "drop waypoints whose bypass is feasible and no costlier",
        citation: "tidepath (the deterministic form of OMPL's PathSimplifier::reduceVertices)",
        params: shortcut::ShortcutParams::SPECS,
        build: |t, prefix| Ok(Box::new(Shortcut::new(shortcut::ShortcutParams::from_table(t, prefix)?))),
    },
    Entry {
        id: "dubins",
        description: "Dubins curves of the turning radius through the waypoints (3-D: Dubins airplane), written as a flyable tangent polygon",
        citation: "Dubins 1957; Owen, Beard & McLain 2014; as in wpa2017",
        params: dubins::DubinsParams::SPECS,
        build: |t, prefix| Ok(Box::new(dubins::DubinsSmoother::new(dubins::DubinsParams::from_table(t, prefix)?))),
    },
    Entry {
        id: "bspline",
        description: "a clamped cubic B-spline with the waypoints and their legs' midpoints as control points, refitted with more midpoints where it hits something (kept if no worse)",
        citation: "ijs2023 section III-D, eqs. 25-26, Fig. 8 (A11); Elbanhawi et al. 2015",
        params: bspline::BsplineParams::SPECS,
        build: |t, prefix| Ok(Box::new(bspline::BsplineSmoother::new(bspline::BsplineParams::from_table(t, prefix)?))),
    },
    Entry {
        id: "exclude",
        description: "amfa2015's excluding operator once: route points inside an obstacle or the seabed pushed out along the surface normal (kept if no costlier)",
        citation: "amfa2015 section 4.3.1, eq. 9 (read as A9)",
        params: crate::repair::ExcludeParams::SPECS,
        build: |t, prefix| repair_smoother::RepairSmoother::build("exclude", t, prefix),
    },
    Entry {
        id: "contract",
        description: "amfa2015's contracting operator once: each route point pulled toward its neighbours' midpoint (kept if no costlier)",
        citation: "amfa2015 section 4.3.2, eq. 10 (read as A10)",
        params: crate::repair::ContractParams::SPECS,
        build: |t, prefix| repair_smoother::RepairSmoother::build("contract", t, prefix),
    },
    Entry {
        id: "exclude-contract",
        description: "amfa2015's excluding then contracting operators once (kept if no costlier)",
        citation: "amfa2015 section 4.3 (order: A14)",
        params: crate::repair::ExcludeContractParams::SPECS,
        build: |t, prefix| repair_smoother::RepairSmoother::build("exclude-contract", t, prefix),
    },
];

pub fn registry() -> Registry<BuildSmoother> {
    Registry::new("smoother", "smoother", "tidepath planners", SMOOTHERS)
}

/// Smoother `id` of `registry` with its parameter table (`None`: its defaults).
pub fn build_smoother_with(
    registry: &Registry<BuildSmoother>,
    id: &str,
    params: Option<&toml::Table>,
) -> Result<Box<dyn Smoother>> {
    let entry = registry.get(id)?;
    (entry.build)(&params.cloned().unwrap_or_default(), &format!("planner.smoother_params.{id}"))
}

/// Built-in smoother `id` with its parameter table (`None`: its defaults).
pub fn build_smoother(id: &str, params: Option<&toml::Table>) -> Result<Box<dyn Smoother>> {
    build_smoother_with(&registry(), id, params)
}
