//! A planner's search graph (an RRT* tree, a PRM* roadmap) under the paths: thin, faint grey
//! edges in x and y (a 3-D graph seen from above), drawn over the seabed and under the
//! obstacles' outlines and the paths, so where the planner searched shows without hiding what
//! it found. Where edges crowd, their faint lines add up to a darker grey.

use plotters::prelude::*;

use super::super::style::{self, plot_err, LegendEntry, Swatch};
use super::super::PlanFigure;
use super::Chart;
use tidepath::error::Result;

/// Most edges drawn in one figure: beyond it every k-th edge of each graph is drawn (the same
/// ones on every run), and the legend says so. 200 000 lines make an SVG of about 20 MB.
pub(crate) const MAX_DRAWN_EDGES: usize = 200_000;

/// An edge: 1 px (the narrowest line plotters draws) of a grey at a quarter of its strength.
const EDGE: RGBAColor = RGBAColor(110, 110, 110, 0.25);

/// Every how many edges one is drawn: 1 up to [`MAX_DRAWN_EDGES`] edges in all.
fn stride(fig: &PlanFigure) -> usize {
    let total: usize = fig.graphs.iter().map(|g| g.edges.len()).sum();
    total.div_ceil(MAX_DRAWN_EDGES).max(1)
}

/// Draws every graph's edges (or every k-th, see [`MAX_DRAWN_EDGES`]).
pub(super) fn draw_graphs<DB: DrawingBackend>(chart: &Chart<DB>, fig: &PlanFigure, u: f64) -> Result<()> {
    let k = stride(fig);
    let line = style::line(EDGE, 1);
    let plot = chart.plotting_area();
    for g in &fig.graphs {
        let at = |i: u32| {
            g.vertices.get(i as usize).filter(|p| p[0].is_finite() && p[1].is_finite()).map(|p| (p[0] / u, p[1] / u))
        };
        for e in g.edges.iter().step_by(k) {
            if let (Some(a), Some(b)) = (at(e[0]), at(e[1])) {
                plot.draw(&PathElement::new(vec![a, b], line)).map_err(plot_err)?;
            }
        }
    }
    Ok(())
}

/// One legend entry per graph: "search tree (N vertices)", "roadmap (N vertices, M edges)",
/// with the mission when the plan has several and the share drawn when not all are.
pub(super) fn legend_entries(fig: &PlanFigure) -> Vec<LegendEntry> {
    let k = stride(fig);
    fig.graphs
        .iter()
        .map(|g| {
            let of = g.label.map_or(String::new(), |m| format!(" of {m}"));
            let (n, m) = (g.vertices.len(), g.edges.len());
            let mut text = if g.kind == "tree" {
                format!("search tree{of} ({n} vertices")
            } else {
                format!("{}{of} ({n} vertices, {m} edges", g.kind)
            };
            if k > 1 {
                text.push_str(&format!("; every {} edge drawn, {} of {m}", ordinal(k), m.div_ceil(k)));
            }
            text.push(')');
            LegendEntry::new(text, Swatch::Line { color: EDGE.mix(2.4), width: 1 })
        })
        .collect()
}

/// "2nd", "3rd", "11th", ...
fn ordinal(k: usize) -> String {
    let suffix = match (k % 10, k % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{k}{suffix}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PlotGraph;
    use tidepath::geom::{Aabb, Vec3};
    use tidepath::world::World;

    #[test]
    fn a_huge_graph_is_thinned_and_the_legend_says_so() {
        let world = World::open(Aabb::new(Vec3::new(0.0, 0.0, -10.0), Vec3::new(100.0, 100.0, 0.0)));
        let vertices = [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
        let edges = vec![[0u32, 1u32]; MAX_DRAWN_EDGES + 1];
        let mut fig = PlanFigure::new("t", &world, Vec3::ZERO, Vec3::ONE, 0.0);
        fig.graphs = vec![PlotGraph { label: None, kind: "roadmap", vertices: &vertices, edges: &edges }];
        assert_eq!(stride(&fig), 2);
        let e = legend_entries(&fig);
        assert_eq!(e[0].label, "roadmap (2 vertices, 200001 edges; every 2nd edge drawn, 100001 of 200001)");
        fig.graphs[0].edges = &edges[..3];
        fig.graphs[0].kind = "tree";
        fig.graphs[0].label = Some("b");
        assert_eq!(legend_entries(&fig)[0].label, "search tree of b (2 vertices)");
        assert_eq!([ordinal(1), ordinal(12), ordinal(22), ordinal(103)], ["1st", "12th", "22nd", "103rd"]);
    }

    /// Each edge is one faint line, drawn before the path (so under it); edges to a vertex
    /// that is not there or not finite are left out.
    #[test]
    fn edges_are_drawn_faintly_under_the_path() {
        let world = World::open(Aabb::new(Vec3::new(0.0, 0.0, -10.0), Vec3::new(100.0, 100.0, 0.0)));
        let vertices = [[10.0, 10.0, -5.0], [50.0, 80.0, -5.0], [90.0, 20.0, -5.0], [f64::NAN, 0.0, 0.0]];
        let edges = [[0, 1], [0, 2], [2, 3], [1, 7]];
        let path = [Vec3::new(10.0, 10.0, -5.0), Vec3::new(90.0, 90.0, -5.0)];
        let mut fig = PlanFigure::new("t", &world, path[0], path[1], 0.0);
        fig.paths = vec![crate::PlotPath::new("p", &path)];
        fig.graphs = vec![PlotGraph { label: None, kind: "tree", vertices: &vertices, edges: &edges }];
        let svg = crate::render_plan_figure(&fig).unwrap();
        let edge = "opacity=\"0.25\" stroke=\"#6E6E6E\"";
        assert_eq!(svg.matches(edge).count(), 2, "two drawable edges");
        let c = style::path_color(0);
        let path_at = svg.find(&format!("stroke=\"#{:02X}{:02X}{:02X}\"", c.0, c.1, c.2)).expect("the path is drawn");
        assert!(svg.rfind(edge).unwrap() < path_at, "an edge is drawn over the path");
        assert!(svg.contains("search tree (4 vertices)"));
    }
}
