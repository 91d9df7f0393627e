//! (mu + lambda) selection for the estimation-of-distribution algorithms (the histogram EDAs
//! and EDA-G): NP parents, NP children, and the best NP of both survive, kept sorted best
//! first so the elite is the first S rows and the best solution is row 0.

use super::model::total_order_key;
use crate::optim::{Context, Population};

/// Parents sorted best first, the children of the current generation, and the reused
/// buffers of the selection.
#[derive(Clone, Debug)]
pub(crate) struct Elitist {
    /// The parents, best first (ties keep their earlier place; NaN counts as +inf).
    pub x: Population,
    pub cost: Vec<f64>,
    /// This generation's children: the algorithm fills them, [`Elitist::evaluate_and_select`]
    /// scores them.
    pub children: Population,
    pub child_cost: Vec<f64>,
    next: Population,
    next_cost: Vec<f64>,
    keys: Vec<u128>,
}

impl Elitist {
    pub fn empty() -> Self {
        Self {
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            children: Population::zeros(0, 0),
            child_cost: Vec::new(),
            next: Population::zeros(0, 0),
            next_cost: Vec::new(),
            keys: Vec::new(),
        }
    }

    /// The initial population ([`Population::initial`], warm starts first), repaired,
    /// evaluated and sorted; the buffers sized for `n` children.
    pub fn init(&mut self, n: usize, ctx: &mut Context<'_>) {
        let dim = ctx.dim();
        let mut x = Population::initial(n, ctx);
        for i in 0..n {
            ctx.repair(x.row_mut(i));
        }
        let mut cost = vec![f64::INFINITY; n];
        ctx.evaluate_population(&x, &mut cost);
        // The initial population is sorted as the "children" of no parents; its buffer then
        // holds the children of later generations.
        self.x = Population::zeros(0, dim);
        self.cost.clear();
        self.next = Population::zeros(n, dim);
        self.next_cost = vec![f64::INFINITY; n];
        self.keys = Vec::with_capacity(2 * n);
        self.children = x;
        self.child_cost = cost;
        self.select();
    }

    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Evaluates the children and keeps the best `NP` of parents and children.
    pub fn evaluate_and_select(&mut self, ctx: &mut Context<'_>) {
        ctx.evaluate_population(&self.children, &mut self.child_cost);
        self.select();
    }

    /// The best `n` (the number of children) of parents and children, best first: a sort of
    /// (cost, index) keys, parents indexed before children, so a child replaces a parent only
    /// with a strictly lower cost and ties keep the earlier place.
    pub fn select(&mut self) {
        let parents = self.x.len();
        let n = self.children.len();
        self.keys.clear();
        let key = |c: f64, i: usize| {
            let c = if c.is_nan() { f64::INFINITY } else { c };
            (u128::from(total_order_key(c)) << 64) | i as u128
        };
        self.keys.extend(self.cost.iter().enumerate().map(|(i, &c)| key(c, i)));
        self.keys.extend(self.child_cost.iter().enumerate().map(|(i, &c)| key(c, parents + i)));
        self.keys.sort_unstable();
        for (slot, &k) in self.keys[..n].iter().enumerate() {
            let i = k as u64 as usize;
            if i < parents {
                self.next.copy_row_from(slot, &self.x, i);
                self.next_cost[slot] = self.cost[i];
            } else {
                self.next.copy_row_from(slot, &self.children, i - parents);
                self.next_cost[slot] = self.child_cost[i - parents];
            }
        }
        std::mem::swap(&mut self.x, &mut self.next);
        std::mem::swap(&mut self.cost, &mut self.next_cost);
        if self.next.len() != n {
            // After the first selection (no parents) the spare buffer takes its full size.
            self.next = Population::zeros(n, self.x.dim());
            self.next_cost = vec![f64::INFINITY; n];
        }
    }
}
