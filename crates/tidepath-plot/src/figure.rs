//! The single-plan figure: plan view on the left, profile and convergence on the right.

use std::path::Path;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::convergence::{draw_convergence, ConvergenceSeries};
use super::plan_view::draw_plan_view;
use super::profile::draw_profile;
use super::style::{self, plot_err};
use super::{PlotGraph, PlotPath};
use tidepath::error::{Error, Result};
use tidepath::geom::Vec3;
use tidepath::planner::Focus;
use tidepath::world::World;

use chrono::{DateTime, Utc};

/// Width and height of the plan figure in pixels.
pub const FIGURE_SIZE: (u32, u32) = (1400, 800);
const TITLE_H: u32 = 40;

/// Everything shown in the figure of one plan (or of several planners' plans on one world).
/// The plan view and the profile draw from it too, so every figure of a world (a plan's, a
/// comparison's best paths) marks the same things the same way.
#[derive(Clone, Debug)]
pub struct PlanFigure<'a> {
    /// Figure title, e.g. "demo — pso, seed 1: cost 1.234, feasible".
    pub title: String,
    pub world: &'a World,
    pub start: Vec3,
    pub goal: Vec3,
    /// Time (s) at which obstacles and currents are drawn, normally the departure time.
    pub time: f64,
    /// The UTC instant of the scenario clock's zero, when the scenario has one: the time a
    /// time-varying field is drawn at is then stated as a date.
    pub epoch: Option<DateTime<Utc>>,
    /// The vehicle's safety distance (m): drawn as a dashed halo around obstacles and as a
    /// line above the seabed on the profile, since that is what a path is judged against.
    pub safety_distance: f64,
    /// Places a failure is about (an invalid start or goal, a bottleneck), marked and
    /// labelled on the plan view.
    pub focus: Vec<Focus>,
    /// One or more paths; they keep the same colour in every panel.
    pub paths: Vec<PlotPath<'a>>,
    /// A reference path (a comparison's or `plan --reference`'s), drawn dashed beneath the
    /// others so the gaps the numbers report can be seen.
    pub reference: Option<PlotPath<'a>>,
    /// Best cost per iteration, per label; a history labelled like a path gets its colour.
    /// May be empty.
    pub histories: Vec<(String, &'a [f64])>,
    /// What iteration 0 of the histories is when something ran before the iterations (a
    /// composite planner's reference search, a warm start), marked on the convergence panel.
    pub history_start: Option<String>,
    /// The histories have one entry per sample (sampling planners: entry k is after sample
    /// k + 1), not per iteration.
    pub history_per_sample: bool,
    /// The planner's search graphs (`plan --graph`, `--plot-graph`), drawn faintly under the
    /// obstacles' outlines and the paths on the plan view; may be empty.
    pub graphs: Vec<PlotGraph<'a>>,
    /// The path (an index into `paths`) the plan view colours by its speed over ground, with
    /// a colour bar, when the world has a current or waves and the path's drawn line has a
    /// time at every point: where the current (or the sea state) helps and where it hinders. A
    /// single plan's figure sets it; a comparison leaves it `None`, so each planner keeps its
    /// own colour.
    pub speed_path: Option<usize>,
    /// The vehicle's speed through still water (m/s), when it flies at one speed (not a wave
    /// glider, whose speed follows the waves): marked on the speed colour bar, the speed over
    /// ground where the current neither helps nor hinders.
    pub still_water_speed: Option<f64>,
}

impl<'a> PlanFigure<'a> {
    /// A figure of `world` with nothing on it but the start and goal; fill in the rest.
    pub fn new(title: impl Into<String>, world: &'a World, start: Vec3, goal: Vec3, time: f64) -> Self {
        Self {
            title: title.into(),
            world,
            start,
            goal,
            time,
            epoch: None,
            safety_distance: 0.0,
            focus: Vec::new(),
            paths: Vec::new(),
            reference: None,
            histories: Vec::new(),
            history_start: None,
            history_per_sample: false,
            graphs: Vec::new(),
            speed_path: None,
            still_water_speed: None,
        }
    }
}

impl<'a> PlanFigure<'a> {
    /// A figure of `scenario`'s world, first mission, departure, clock and safety distance.
    pub fn of_scenario(title: impl Into<String>, scenario: &'a tidepath_io::scenario::Scenario) -> Self {
        let mut fig = Self::new(title, &scenario.world, scenario.start, scenario.goal, scenario.departure_time);
        fig.epoch = scenario.epoch;
        fig.safety_distance = scenario.vehicle.safety_distance;
        // A wave glider's `speed` is only a nominal one (its still-water speed in the highest
        // waves): nothing to mark on the speed bar.
        let v = &scenario.vehicle;
        fig.still_water_speed = (v.speed_range.is_none() && v.glider().is_none()).then_some(v.speed);
        fig
    }
}

/// Renders the figure to SVG text.
pub fn render_plan_figure(fig: &PlanFigure) -> Result<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, FIGURE_SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (w, h) = FIGURE_SIZE;
        let title = style::bold(style::TITLE_PX).pos(Pos::new(HPos::Center, VPos::Center));
        root.draw(&Text::new(fig.title.clone(), (w as i32 / 2, TITLE_H as i32 / 2 + 2), title)).map_err(plot_err)?;
        let body = root.split_vertically(TITLE_H).1.margin(0, 8, 8, 8);

        // A wide domain gets a wider plan view; the right column keeps enough room to read.
        let b = fig.world.bounds;
        let aspect = ((b.max.x - b.min.x) / (b.max.y - b.min.y)).clamp(0.3, 3.0);
        let avail_h = (h - TITLE_H) as f64 - 200.0;
        let left_w = (aspect * avail_h + 200.0).clamp(540.0, 900.0) as u32;
        let (left, right) = body.split_horizontally(left_w);
        draw_plan_view(&left, fig)?;

        let right = right.margin(0, 0, 16, 0);
        // A history takes the colour of the path with the same label, whatever the order.
        let series: Vec<ConvergenceSeries> = fig
            .histories
            .iter()
            .enumerate()
            .map(|(i, (label, values))| ConvergenceSeries {
                color: Some(fig.paths.iter().position(|p| &p.label == label).unwrap_or(i)),
                mark_first: fig.history_start.is_some(),
                first_x: if fig.history_per_sample { 1.0 } else { 0.0 },
                ..ConvergenceSeries::line(label.clone(), values)
            })
            .collect();
        // The same layout with or without a history, so figures of different runs line up;
        // without one the convergence panel says so.
        let (_, rh) = right.dim_in_pixel();
        let (top, bottom) = right.split_vertically(rh / 2);
        draw_profile(&top.margin(0, 10, 0, 0), fig)?;
        draw_convergence(&bottom.margin(10, 0, 0, 0), &series, fig.history_start.as_deref())?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// Renders the figure and writes it to `out` (an `.svg` file).
pub fn write_plan_figure(fig: &PlanFigure, out: &Path) -> Result<()> {
    let svg = render_plan_figure(fig)?;
    std::fs::write(out, svg).map_err(|e| Error::io(out, e))
}
