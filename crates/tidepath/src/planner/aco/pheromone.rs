//! Pheromone on the directed edges (`8 c + d`, A8) and its updates after each iteration:
//!
//! * basic ant colony (acopf2016 eqs. 4-6): τ ← (1 − ρ) τ + ρ Σ_k Q/L_k, the sum over the
//!   completed ants whose tour used the edge;
//! * improved (eqs. 11-13): τ ← (1 − ρ) τ + ρ (Σ_k Q/L_k + Q/L_best [on the iteration best's
//!   edges] − Q/L_worst [on the worst's]).
//!
//! Every edge evaporates; τ is then clamped to [[`TAU_MIN`], [`TAU_MAX`]] (the worst-path term
//! could drive it negative: A8). Only ants that reached the goal deposit or count as best and
//! worst (A9). L_k is the tour's cost in cell units (see the planner's readings).

/// The clamp on τ (acopf2016 A8).
pub const TAU_MIN: f64 = 1e-3;
pub const TAU_MAX: f64 = 1e3;

/// The completed tours of one iteration: their edges, stored end to end, and lengths.
#[derive(Clone, Debug, Default)]
pub struct Tours {
    edges: Vec<u32>,
    /// (first edge, end, L).
    spans: Vec<(usize, usize, f64)>,
}

impl Tours {
    pub fn clear(&mut self) {
        self.edges.clear();
        self.spans.clear();
    }

    /// Adds a completed tour with edges `edges` and length `l` (> 0).
    pub fn push(&mut self, edges: &[u32], l: f64) {
        let s = self.edges.len();
        self.edges.extend_from_slice(edges);
        self.spans.push((s, self.edges.len(), l));
    }

    pub fn len(&self) -> usize {
        self.spans.len()
    }

    pub fn is_empty(&self) -> bool {
        self.spans.is_empty()
    }

    /// Tour k's edges and length.
    pub fn get(&self, k: usize) -> (&[u32], f64) {
        let (s, e, l) = self.spans[k];
        (&self.edges[s..e], l)
    }

    /// The shortest and the longest tour (the first of equals), if any.
    pub fn best_and_worst(&self) -> Option<(usize, usize)> {
        if self.spans.is_empty() {
            return None;
        }
        let (mut best, mut worst) = (0, 0);
        for (k, &(_, _, l)) in self.spans.iter().enumerate() {
            if l < self.spans[best].2 {
                best = k;
            }
            if l > self.spans[worst].2 {
                worst = k;
            }
        }
        Some((best, worst))
    }
}

/// One iteration's update of `tau` by the completed `tours`: eqs. 4-6 (`elite` false) or
/// eqs. 11-13 (`elite` true), then the clamp.
pub fn update(tau: &mut [f64], tours: &Tours, rho: f64, q: f64, elite: bool) {
    for t in tau.iter_mut() {
        *t *= 1.0 - rho;
    }
    for k in 0..tours.len() {
        let (edges, l) = tours.get(k);
        deposit(tau, edges, rho * q / l);
    }
    if elite {
        if let Some((best, worst)) = tours.best_and_worst() {
            let (edges, l) = tours.get(best);
            deposit(tau, edges, rho * q / l);
            let (edges, l) = tours.get(worst);
            deposit(tau, edges, -rho * q / l);
        }
    }
    for t in tau.iter_mut() {
        *t = t.clamp(TAU_MIN, TAU_MAX);
    }
}

fn deposit(tau: &mut [f64], edges: &[u32], amount: f64) {
    for &e in edges {
        tau[e as usize] += amount;
    }
}
