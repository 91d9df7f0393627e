//! RRT*'s tree: vertices with their parent, cost from the start and arrival time, and the
//! re-parenting that rewiring does, with the re-timing of a subtree it implies.

use super::Edges;
use crate::geom::Vec3;
use crate::termination::Termination;

pub const ROOT: u32 = 0;
const NO_PARENT: u32 = u32::MAX;

/// How often (in vertices) a subtree walk polls the clock and the stop flag.
const POLL_EVERY: usize = 64;

#[derive(Default)]
pub struct Tree {
    pub pos: Vec<Vec3>,
    pub parent: Vec<u32>,
    /// Additive cost from the start (the cost model's `motion_cost` summed).
    pub cost: Vec<f64>,
    /// Arrival time (s, scenario clock).
    pub time: Vec<f64>,
    pub children: Vec<Vec<u32>>,
    /// Scratch for subtree walks: (vertex, new cost, new time).
    walk: Vec<(u32, f64, f64)>,
    stack: Vec<u32>,
}

impl Tree {
    pub fn new(root: Vec3, departure: f64) -> Self {
        let mut t = Self::default();
        t.push(root, NO_PARENT, 0.0, departure);
        t
    }

    pub fn len(&self) -> usize {
        self.pos.len()
    }

    fn push(&mut self, p: Vec3, parent: u32, cost: f64, time: f64) -> u32 {
        let id = self.pos.len() as u32;
        self.pos.push(p);
        self.parent.push(parent);
        self.cost.push(cost);
        self.time.push(time);
        self.children.push(Vec::new());
        id
    }

    /// Adds `p` as a child of `parent`, reached at `cost` and `time`.
    pub fn add(&mut self, p: Vec3, parent: u32, cost: f64, time: f64) -> u32 {
        let id = self.push(p, parent, cost, time);
        self.children[parent as usize].push(id);
        id
    }

    /// The parent's position of `v` (`None` for the root): the heading into `v`.
    #[inline]
    pub fn from(&self, v: u32) -> Option<Vec3> {
        let p = self.parent[v as usize];
        (p != NO_PARENT).then(|| self.pos[p as usize])
    }

    /// The start-to-`v` path.
    pub fn path_to(&self, v: u32) -> Vec<Vec3> {
        let mut out = Vec::new();
        let mut at = v;
        while at != NO_PARENT {
            out.push(self.pos[at as usize]);
            at = self.parent[at as usize];
        }
        out.reverse();
        out
    }

    /// Tree edges as (parent, child) pairs.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        (1..self.len() as u32).map(|v| [self.parent[v as usize], v]).collect()
    }

    /// Makes `new_parent` the parent of `q`, reached at `cost` and `time`, and moves q's
    /// subtree with it.
    ///
    /// In a world that does not change in time an edge's cost and validity do not depend on
    /// when it is flown, so the subtree's costs and times shift by q's change. In a world that
    /// does, every edge below q is priced again at its new departure time; the rewire is
    /// refused (false, nothing changed) when one of them becomes invalid, when the vertex
    /// `keep` (the goal) would get dearer, or when `termination` stops the walk.
    #[allow(clippy::too_many_arguments)]
    pub fn reparent(
        &mut self,
        q: u32,
        new_parent: u32,
        cost: f64,
        time: f64,
        edges: &mut Edges<'_>,
        keep: Option<u32>,
        termination: &Termination,
    ) -> bool {
        let (dc, dt) = (cost - self.cost[q as usize], time - self.time[q as usize]);
        if !edges.time_varying {
            self.stack.clear();
            self.stack.push(q);
            while let Some(v) = self.stack.pop() {
                self.cost[v as usize] += dc;
                self.time[v as usize] += dt;
                self.stack.extend_from_slice(&self.children[v as usize]);
            }
        } else {
            // New (cost, time) of every vertex of the subtree, parents before children.
            self.walk.clear();
            self.walk.push((q, cost, time));
            let mut k = 0;
            while k < self.walk.len() {
                if k % POLL_EVERY == POLL_EVERY - 1 && termination.interrupted().is_some() {
                    return false;
                }
                let (v, c, t) = self.walk[k];
                if keep == Some(v) && c > self.cost[v as usize] {
                    return false;
                }
                for j in 0..self.children[v as usize].len() {
                    let w = self.children[v as usize][j];
                    match edges.price(self.pos[v as usize], self.pos[w as usize], t) {
                        Some((ec, arrival)) => self.walk.push((w, c + ec, arrival)),
                        None => return false,
                    }
                }
                k += 1;
            }
            for &(v, c, t) in &self.walk {
                self.cost[v as usize] = c;
                self.time[v as usize] = t;
            }
        }
        let old = self.parent[q as usize];
        let siblings = &mut self.children[old as usize];
        if let Some(k) = siblings.iter().position(|&c| c == q) {
            siblings.swap_remove(k);
        }
        self.parent[q as usize] = new_parent;
        self.children[new_parent as usize].push(q);
        true
    }
}
