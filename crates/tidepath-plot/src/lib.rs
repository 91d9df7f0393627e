//! SVG figures of plans: plan view, vertical profile and convergence.
//!
//! Figures are SVG so the default build needs no system libraries (no fonts, no bitmap
//! encoders): text is written as SVG `<text>` and rendered by the viewer. Each panel is a
//! function drawing into any plotters [`DrawingArea`], so reports other than the single-plan
//! figure (a comparison's paths, convergence bands) reuse the same panels and look the same.
//!
//! [`DrawingArea`]: plotters::drawing::DrawingArea

pub mod contour;
mod convergence;
pub mod experiment;
mod failure;
mod figure;
mod flown;
mod log_axis;
mod obstacle_look;
mod plan_view;
mod profile;
mod simulation;
pub mod style;
mod time_label;

pub use convergence::{draw_convergence, wants_log_scale, ConvergenceSeries};
pub use experiment::ExperimentFigures;
pub use figure::{render_plan_figure, write_plan_figure, PlanFigure, FIGURE_SIZE};
pub use plan_view::draw_plan_view;
pub use profile::draw_profile;
pub use simulation::{render_simulation_figure, write_simulation_figure, SimPanel, SimulationFigure};
pub use tidepath::planner::Focus;

use tidepath::geom::Vec3;
use tidepath::path::Violation;

/// A labelled path to draw; borrowed so callers can plot plans without copying waypoints.
#[derive(Clone, Debug)]
pub struct PlotPath<'a> {
    pub label: String,
    pub points: &'a [Vec3],
    /// Arrival time (s, scenario clock) at each point, when known: moving obstacles are then
    /// drawn where they are when the vehicle passes, with time marks on both.
    pub times: &'a [f64],
    /// The constraints this path violates (indices into `points`), marked on the plan view
    /// and the profile so a figure of an infeasible path shows where it fails.
    pub violations: &'a [Violation],
    /// With a turning radius: the curve the vehicle flies along `points`. It is then drawn as
    /// the path's line, with the waypoints as small markers on a thin dashed line.
    pub flown: Option<FlownLine<'a>>,
}

/// The curve a vehicle with a turning radius flies along a path's waypoints (the fillet model,
/// `tidepath::kinematics::fillet`), as the evaluation sampled it.
#[derive(Clone, Copy, Debug)]
pub struct FlownLine<'a> {
    pub points: &'a [Vec3],
    /// Arrival time at each point (s, scenario clock); may be empty.
    pub times: &'a [f64],
    /// The vehicle's turning radius (m): places the flown curve's pieces on the waypoints'
    /// segments, where violations are reported.
    pub radius: f64,
}

/// A planner's search graph (a tree or a roadmap), drawn faintly under the paths.
#[derive(Clone, Copy, Debug)]
pub struct PlotGraph<'a> {
    /// The mission it belongs to, named in the legend when a plan has several.
    pub label: Option<&'a str>,
    /// "tree" or "roadmap".
    pub kind: &'a str,
    /// [x, y, z] in metres; the plan view draws x and y.
    pub vertices: &'a [[f64; 3]],
    /// Pairs of indices into `vertices`.
    pub edges: &'a [[u32; 2]],
}

impl<'a> PlotPath<'a> {
    pub fn new(label: impl Into<String>, points: &'a [Vec3]) -> Self {
        Self { label: label.into(), points, times: &[], violations: &[], flown: None }
    }

    pub fn with_times(self, times: &'a [f64]) -> Self {
        Self { times, ..self }
    }

    pub fn with_violations(self, violations: &'a [Violation]) -> Self {
        Self { violations, ..self }
    }

    /// The curve flown along the waypoints by a vehicle of turning radius `radius` (m), with
    /// its times; a curve of fewer than two points is not drawn.
    pub fn with_flown(self, points: &'a [Vec3], times: &'a [f64], radius: f64) -> Self {
        Self { flown: Some(FlownLine { points, times, radius }), ..self }
    }
}
