//! Dijkstra on the tangent visibility graph, and turning its route into
//! pieces (segments, arcs) and a polyline.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::geometry::on_circle;
use super::{Edge, EdgeKind, Graph, Piece, VisPath};

#[derive(Debug, Clone, Copy)]
struct Open {
    d: f64,
    node: usize,
}
impl PartialEq for Open {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Open {}
impl PartialOrd for Open {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Open {
    fn cmp(&self, o: &Self) -> Ordering {
        o.d.total_cmp(&self.d).then_with(|| o.node.cmp(&self.node))
    }
}

/// A route through the graph: each node with the edge used to reach it.
type Route = Vec<(usize, Option<Edge>)>;

/// Dijkstra from `s` to `t`; returns the length and the route.
pub(super) fn dijkstra(g: &Graph, s: usize, t: usize) -> Option<(f64, Route)> {
    let n = g.nodes.len();
    let mut d = vec![f64::INFINITY; n];
    let mut from: Vec<Option<(usize, Edge)>> = vec![None; n];
    let mut done = vec![false; n];
    let mut heap = BinaryHeap::new();
    d[s] = 0.0;
    heap.push(Open { d: 0.0, node: s });
    while let Some(Open { d: du, node: u }) = heap.pop() {
        if done[u] {
            continue;
        }
        done[u] = true;
        if u == t {
            let mut route = vec![(t, from[t].map(|f| f.1))];
            let mut c = t;
            while let Some((p, _)) = from[c] {
                route.push((p, from[p].map(|f| f.1)));
                c = p;
            }
            route.reverse();
            return Some((du, route));
        }
        for e in &g.adj[u] {
            let nd = du + e.len;
            if nd < d[e.to] {
                d[e.to] = nd;
                from[e.to] = Some((u, *e));
                heap.push(Open { d: nd, node: e.to });
            }
        }
    }
    None
}

pub(super) fn build_path(g: &Graph, length: f64, route: &[(usize, Option<Edge>)], arc_step: f64) -> VisPath {
    let mut pieces = Vec::new();
    let mut polyline = vec![g.nodes[route[0].0].pos];
    for w in route.windows(2) {
        let (a, b) = (w[0].0, w[1].0);
        let edge = w[1].1.expect("every node after the first was reached by an edge");
        let (pa, pb) = (g.nodes[a].pos, g.nodes[b].pos);
        match edge.kind {
            EdgeKind::Segment => {
                if edge.len > 0.0 {
                    pieces.push(Piece::Segment { from: pa, to: pb });
                    polyline.push(pb);
                }
            }
            EdgeKind::Arc { circle, sweep } => {
                let c = g.scene.circles[circle];
                let start_angle = g.nodes[a].on.expect("arc edges join tangent points").1;
                if sweep != 0.0 {
                    pieces.push(Piece::Arc { centre: c.centre, radius: c.radius, start_angle, sweep });
                    let steps = (sweep.abs() / arc_step).ceil().max(1.0) as usize;
                    for k in 1..steps {
                        polyline.push(on_circle(&c, start_angle + sweep * k as f64 / steps as f64));
                    }
                    polyline.push(pb);
                }
            }
        }
    }
    if polyline.len() == 1 {
        polyline.push(g.nodes[route[route.len() - 1].0].pos);
    }
    VisPath { length, pieces, polyline }
}
