//! The figures of a comparison, for the experiment layer's output writer: the plotting side of
//! [`tidepath_experiments::output::FigureRenderer`].

use super::{render_boxplot_figure, render_convergence_figure, render_paths_figure, PlannerRuns, ProblemRuns};
use crate::PlotPath;
use tidepath::error::Result;
use tidepath::geom::Vec3;
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
                render_convergence_figure(
                    &format!("Convergence — {title} (median and interquartile band)"),
                    &problems,
                )?,
            ),
            ("boxplot.svg".to_string(), render_boxplot_figure(&format!("Final cost — {title}"), &problems)?),
        ];
        if let Some(s) = scenario {
            let best: Vec<(String, Vec<Vec3>)> = c
                .planners
                .iter()
                .filter_map(|pl| {
                    c.records_of(&s.name, pl).min_by(|a, b| a.cost.total_cmp(&b.cost)).map(|r| {
                        let ok = if r.feasible { "feasible" } else { "infeasible" };
                        (
                            format!("{pl} (best cost {}, {ok})", tidepath_experiments::table::num(r.cost)),
                            r.waypoints.iter().map(|p| Vec3::from_array(*p)).collect(),
                        )
                    })
                })
                .collect();
            let paths: Vec<PlotPath> = best.iter().map(|(l, pts)| PlotPath::new(l.clone(), pts)).collect();
            out.push((
                "paths.svg".to_string(),
                render_paths_figure(
                    &format!("{} — best path of each planner over {} runs", s.name, c.runs),
                    &s.world,
                    s.start,
                    s.goal,
                    s.departure_time,
                    &paths,
                )?,
            ));
        }
        Ok(out)
    }
}
