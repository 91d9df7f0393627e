//! The figures of a comparison, for the experiment layer's output writer: the plotting side of
//! [`tidepath_experiments::output::FigureRenderer`].

use super::{
    render_boxplot_figure, render_convergence_figure_with, render_paths_figure, ConvergenceContext, PlannerRuns,
    ProblemRuns,
};
use crate::{PlanFigure, PlotPath};
use tidepath::error::Result;
use tidepath::geom::Vec3;
use tidepath::planner::MissionPlan;
use tidepath_experiments::compare::Comparison;
use tidepath_experiments::output::FigureRenderer;
use tidepath_io::scenario::Scenario;

/// convergence.svg and boxplot.svg, plus paths.svg (the best path of each planner over the
/// map) when the problem is a scenario.
pub struct ExperimentFigures;

impl FigureRenderer for ExperimentFigures {
    fn names(&self, scenario: bool) -> Vec<&'static str> {
        let mut names = vec!["convergence.svg", "boxplot.svg"];
        if scenario {
            names.push("paths.svg");
        }
        names
    }

    fn render(&self, c: &Comparison, scenario: Option<&Scenario>) -> Result<Vec<(String, String)>> {
        let problems: Vec<ProblemRuns> = c
            .problems
            .iter()
            .map(|p| ProblemRuns {
                problem: p,
                planners: c
                    .planners
                    .iter()
                    .map(|pl| PlannerRuns {
                        planner: pl,
                        search_before_iterations: c.records_of(p, pl).any(super::seeded_by_search),
                        costs: c.records_of(p, pl).map(|r| r.cost).collect(),
                        histories: c
                            .records_of(p, pl)
                            .map(|r| r.history.iter().map(|h| h.unwrap_or(f64::INFINITY)).collect())
                            .collect(),
                    })
                    .collect(),
            })
            .collect();
        let what = if c.is_functions() { "benchmark functions".to_string() } else { c.problems.join(", ") };
        let title = format!("{what}: {} runs per planner", c.runs);
        let mut out = vec![
            (
                "convergence.svg".to_string(),
                render_convergence_figure_with(
                    &format!("Convergence — {title} (median and interquartile band)"),
                    &problems,
                    &ConvergenceContext::of(c),
                )?,
            ),
            ("boxplot.svg".to_string(), render_boxplot_figure(&format!("Final cost — {title}"), &problems)?),
        ];
        if let Some(s) = scenario {
            // Each planner's best run, judged again on the scenario so the figure can mark its
            // violations and time its path (run records keep only the points).
            let best: Vec<(String, Vec<Vec3>, Option<MissionPlan>)> = c
                .planners
                .iter()
                .filter_map(|pl| {
                    c.records_of(&s.name, pl).min_by(|a, b| a.cost.total_cmp(&b.cost)).map(|r| {
                        let ok = if r.feasible { "feasible" } else { "infeasible" };
                        let points: Vec<Vec3> = r.waypoints.iter().map(|p| Vec3::from_array(*p)).collect();
                        let judged = (points.len() >= 2).then(|| s.evaluate(&points).ok()).flatten();
                        (format!("{pl} (best cost {}, {ok})", tidepath_experiments::table::num(r.cost)), points, judged)
                    })
                })
                .collect();
            let reference_points: Vec<Vec3> = c
                .reference
                .as_ref()
                .map(|r| r.waypoints.iter().map(|p| Vec3::from_array(*p)).collect())
                .unwrap_or_default();
            let mut fig =
                PlanFigure::of_scenario(format!("{} — best path of each planner over {} runs", s.name, c.runs), s);
            fig.paths = best
                .iter()
                .map(|(l, pts, judged)| match judged {
                    Some(m) => {
                        let path = PlotPath::new(l.clone(), pts).with_times(&m.times).with_violations(&m.violations);
                        // With a turning radius, the curve the vehicle flies is the line drawn.
                        match (&m.flown, s.vehicle.turn_radius) {
                            (Some(f), Some(r)) => path.with_flown(&f.points, &f.times, r),
                            _ => path,
                        }
                    }
                    None => PlotPath::new(l.clone(), pts),
                })
                .collect();
            fig.reference = c.reference.as_ref().filter(|_| reference_points.len() >= 2).map(|r| {
                let label = format!(
                    "reference: {} (cost {}, {})",
                    r.planner,
                    tidepath_experiments::table::num(r.cost),
                    r.status
                );
                PlotPath::new(label, &reference_points)
            });
            out.push(("paths.svg".to_string(), render_paths_figure(&fig)?));
        }
        Ok(out)
    }
}
