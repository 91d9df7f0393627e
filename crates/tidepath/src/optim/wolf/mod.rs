//! The wolf pack engine shared by `wpa` (the original wolf pack algorithm, Wu, Zhang & Wu 2013)
//! and `mwpa` (its modification in wpa2017, Zhang et al., IEEE Access 2017). Both run the same
//! five phases each iteration; [`Variant`] says which form of scouting, raiding and besieging a
//! run uses. The operators are free functions so tests can check them against hand-computed
//! values; the papers' equations are cited in `wpa.rs` and `mwpa.rs`, and the readings of
//! ambiguous points in docs/papers/wpa2017.md.
//!
//! One iteration, minimising (ranks by cost, ties to the lower index, NaN last):
//!
//! ```text
//! lead <- best wolf;  T <- U{ceil(N/(alpha+1)) .. floor(N/alpha)} (at most N-1)
//! scouts <- the T best after the lead;  ferocious <- the rest
//! scouting   up to T_max rounds over the scouts (stops once a scout beats the lead)
//! calling    each ferocious wolf raids towards the lead until its mean absolute per-dimension
//!            distance is <= d_near, it beats the lead (it becomes the lead), or T_max raids
//! besieging  every wolf but the lead: x + factor * lambda * step_c * |G - x|, greedy
//! renewal    R <- U{ceil(N/(2 beta)) .. floor(N/beta)} (at most N-1) worst wolves replaced by
//!            uniform random wolves
//! step 7     (MWPA) wolves whose path is infeasible become copies of the best feasible wolf
//! ```
//!
//! Random draws, in order, per iteration: T; per scout visit (MWPA only) the two partner scouts
//! then phi (D values) then varphi (D values); per besieged wolf (in index order) one lambda;
//! R; then the renewed wolves' coordinates (wolf by wolf, dimension by dimension). The
//! original WPA's scouting and calling draw nothing.
//!
//! Every moved wolf goes through the objective's repair; every cost goes through the
//! [`Context`], which counts it. Scouting and calling poll [`Context::should_stop`] before
//! every evaluation, so a wall-time limit or Ctrl-C cuts a generation.

use rand::Rng as _;

mod operators;
#[cfg(test)]
mod tests;

pub use operators::*;
use operators::{better, cmp_cost};

use super::{Context, Population};

/// Which operators a run uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Variant {
    /// MWPA's interactive scouting candidate (eq. 23) besides the h directions.
    pub interactive: bool,
    /// MWPA's adaptive raid step (eqs. 25-26).
    pub adaptive: Option<Adaptive>,
    /// MWPA's siege decay c (eq. 29); `None`: the original constant siege step.
    pub decay: Option<f64>,
    /// wpa2017's Step 7: after renewal, every wolf whose path is infeasible becomes a copy of
    /// the best feasible wolf (when the objective reports feasibility and one wolf is feasible).
    pub replace_infeasible: bool,
}

/// MWPA's adaptive raid step: the weight range of eq. 26 and whether the weight compounds
/// over the raids of a calling phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Adaptive {
    pub w_min: f64,
    pub w_max: f64,
    /// `s <- w s` before every raid (from s = step_b at the start of the phase); otherwise
    /// `s = w step_b` for the whole phase.
    pub compound: bool,
}

/// Settings common to both algorithms, as fractions of each dimension's range for the steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Settings {
    pub population: usize,
    pub t_max: usize,
    pub omega: f64,
    pub step_a: f64,
    pub step_b: f64,
    pub step_c: f64,
    pub alpha: f64,
    pub beta: f64,
    pub h: usize,
}

/// Declares a wolf pack optimizer: the struct holding its checked parameters and its
/// [`Pack`], and its [`Optimizer`](super::Optimizer) implementation, identical for `wpa` and
/// `mwpa` (their constructors, which choose the [`Variant`], stay in their own files).
macro_rules! wolf_optimizer {
    ($(#[$meta:meta])* $name:ident, $params:ty, $id:literal) => {
        $(#[$meta])*
        #[derive(Clone, Debug)]
        pub struct $name {
            params: $params,
            pack: super::wolf::Pack,
        }

        impl $name {
            pub fn params(&self) -> &$params {
                &self.params
            }
        }

        impl super::Optimizer for $name {
            fn id(&self) -> &'static str {
                $id
            }

            fn population(&self) -> usize {
                self.params.population
            }

            fn init(&mut self, ctx: &mut super::Context<'_>) {
                self.pack.init(ctx);
            }

            fn step(&mut self, ctx: &mut super::Context<'_>) {
                self.pack.step(ctx);
            }
        }
    };
}
pub(crate) use wolf_optimizer;

/// A wolf pack and its reused buffers.
#[derive(Clone, Debug)]
pub(crate) struct Pack {
    pub settings: Settings,
    pub variant: Variant,
    pub x: Population,
    pub cost: Vec<f64>,
    pub lead: usize,
    /// Siege factor xi (eq. 29); stays 1 for the original WPA.
    pub xi: f64,
    order: Vec<usize>,
    step_a: Vec<f64>,
    step_b: Vec<f64>,
    step_c: Vec<f64>,
    d_near: f64,
    /// The scouting directions p in 1..=h whose sin(2 pi p/h) is not 0 ([`moving_directions`]).
    directions: Vec<usize>,
    /// Scouting candidates: one row per moving direction, and MWPA's interactive one.
    cand: Population,
    cand_cost: Vec<f64>,
    /// The lead's position while others raid or besiege it.
    g: Vec<f64>,
    /// A raiding wolf's step, per dimension.
    s: Vec<f64>,
    phi: Vec<f64>,
    varphi: Vec<f64>,
    /// Siege trials of every wolf but the lead (N - 1 rows) and their costs.
    trial: Population,
    trial_cost: Vec<f64>,
    row: Vec<f64>,
    /// Step 7: each wolf's position when its feasibility was last checked, and the verdict
    /// (`None`: not checked yet), so only wolves that moved are checked again.
    checked_x: Population,
    checked: Vec<Option<bool>>,
}

impl Pack {
    pub fn new(settings: Settings, variant: Variant) -> Self {
        Self {
            settings,
            variant,
            x: Population::zeros(0, 0),
            cost: Vec::new(),
            lead: 0,
            xi: 1.0,
            order: Vec::new(),
            step_a: Vec::new(),
            step_b: Vec::new(),
            step_c: Vec::new(),
            d_near: 0.0,
            directions: Vec::new(),
            cand: Population::zeros(0, 0),
            cand_cost: Vec::new(),
            g: Vec::new(),
            s: Vec::new(),
            phi: Vec::new(),
            varphi: Vec::new(),
            trial: Population::zeros(0, 0),
            trial_cost: Vec::new(),
            row: Vec::new(),
            checked_x: Population::zeros(0, 0),
            checked: Vec::new(),
        }
    }

    pub fn init(&mut self, ctx: &mut Context<'_>) {
        let n = self.settings.population;
        let dim = ctx.dim();
        let ranges: Vec<f64> = (0..dim).map(|d| ctx.range(d)).collect();
        self.step_a = ranges.iter().map(|r| r * self.settings.step_a).collect();
        self.step_b = ranges.iter().map(|r| r * self.settings.step_b).collect();
        self.step_c = ranges.iter().map(|r| r * self.settings.step_c).collect();
        self.d_near = d_near(ctx.lower(), ctx.upper(), self.settings.omega);
        self.x = Population::initial(n, ctx);
        for i in 0..n {
            ctx.repair(self.x.row_mut(i));
        }
        self.cost = vec![f64::INFINITY; n];
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.directions = moving_directions(self.settings.h);
        let rows = self.directions.len() + usize::from(self.variant.interactive);
        self.cand = Population::zeros(rows, dim);
        self.cand_cost = vec![f64::INFINITY; rows];
        self.g = vec![0.0; dim];
        self.s = vec![0.0; dim];
        self.phi = vec![0.0; dim];
        self.varphi = vec![0.0; dim];
        self.trial = Population::zeros(n.saturating_sub(1), dim);
        self.trial_cost = vec![f64::INFINITY; n.saturating_sub(1)];
        self.row = vec![0.0; dim];
        self.order = (0..n).collect();
        self.xi = 1.0;
        self.checked_x = Population::zeros(n, dim);
        self.checked = vec![None; n];
        self.rank();
    }

    /// Sorts `order` by cost (stable: ties keep the lower index) and sets the lead.
    fn rank(&mut self) {
        let cost = &self.cost;
        self.order.clear();
        self.order.extend(0..cost.len());
        self.order.sort_by(|&a, &b| cmp_cost(cost[a], cost[b]));
        self.lead = self.order[0];
    }

    fn halt(ctx: &mut Context<'_>) -> bool {
        ctx.exhausted() || ctx.should_stop()
    }

    pub fn step(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        if n == 0 {
            return;
        }
        self.rank();
        let u: f64 = ctx.rng().random();
        let t = scout_count(n, self.settings.alpha, u);
        if !self.scout(ctx, t) {
            return;
        }
        if !self.call(ctx, t) {
            return;
        }
        self.besiege(ctx);
        self.renew(ctx);
        if self.variant.replace_infeasible {
            self.replace_infeasible(ctx);
        }
    }

    /// Step 7 (wpa2017 section III.B): every wolf whose path violates a constraint becomes a
    /// copy of the best feasible wolf (position and cost; the cost is a pure function of the
    /// position, so nothing is re-evaluated). Each wolf that moved since its last check is
    /// checked once (counted as an evaluation); with no feasible wolf, or an objective without
    /// constraints, the pack is left as it is.
    fn replace_infeasible(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        for i in 0..n {
            if self.checked[i].is_some() && self.checked_x.row(i) == self.x.row(i) {
                continue;
            }
            if Self::halt(ctx) {
                return;
            }
            match ctx.feasible(self.x.row(i)) {
                Some(ok) => {
                    self.checked[i] = Some(ok);
                    self.checked_x.copy_row_from(i, &self.x, i);
                }
                // No constraints (benchmark functions), or the budget ran out.
                None => return,
            }
        }
        let best = (0..n)
            .filter(|&i| self.checked[i] == Some(true))
            .min_by(|&a, &b| cmp_cost(self.cost[a], self.cost[b]).then(a.cmp(&b)));
        let Some(best) = best else { return };
        self.row.copy_from_slice(self.x.row(best));
        for i in 0..n {
            if self.checked[i] == Some(false) {
                self.x.row_mut(i).copy_from_slice(&self.row);
                self.checked_x.row_mut(i).copy_from_slice(&self.row);
                self.checked[i] = Some(true);
                self.cost[i] = self.cost[best];
            }
        }
        self.rank();
    }

    /// Scouting; false when the run must stop.
    fn scout(&mut self, ctx: &mut Context<'_>, t: usize) -> bool {
        let (h, dim) = (self.settings.h, self.x.dim());
        let moves = self.directions.len();
        if self.cand.is_empty() {
            // No direction moves a wolf (h = 1 or 2) and no interactive candidate: nothing to try.
            return true;
        }
        for _ in 0..self.settings.t_max {
            for k in 1..=t {
                if Self::halt(ctx) {
                    return false;
                }
                let i = self.order[k];
                for (r, &p) in self.directions.iter().enumerate() {
                    direction(self.x.row(i), &self.step_a, p, h, self.cand.row_mut(r));
                }
                if self.variant.interactive {
                    // Two other scouts a != b (the difference term is zero with fewer).
                    let (a, b) = if t >= 3 {
                        let a = loop {
                            let r = self.order[1 + ctx.rng().random_range(0..t)];
                            if r != i {
                                break r;
                            }
                        };
                        let b = loop {
                            let r = self.order[1 + ctx.rng().random_range(0..t)];
                            if r != i && r != a {
                                break r;
                            }
                        };
                        (a, b)
                    } else {
                        (i, i)
                    };
                    for v in self.phi.iter_mut() {
                        *v = ctx.rng().random::<f64>();
                    }
                    for v in self.varphi.iter_mut() {
                        *v = 2.0 * ctx.rng().random::<f64>() - 1.0;
                    }
                    let (x, lead, xa, xb) = (self.x.row(i), self.x.row(self.lead), self.x.row(a), self.x.row(b));
                    interactive(x, lead, xa, xb, &self.phi, &self.varphi, &mut self.row);
                    self.cand.row_mut(moves).copy_from_slice(&self.row);
                }
                for r in 0..self.cand.len() {
                    ctx.repair(self.cand.row_mut(r));
                }
                ctx.evaluate_population(&self.cand, &mut self.cand_cost);
                let mut best = 0;
                for r in 1..self.cand_cost.len() {
                    if better(self.cand_cost[r], self.cand_cost[best]) {
                        best = r;
                    }
                }
                if better(self.cand_cost[best], self.cost[i]) {
                    self.cost[i] = self.cand_cost[best];
                    self.x.row_mut(i)[..dim].copy_from_slice(self.cand.row(best));
                }
                if better(self.cost[i], self.cost[self.lead]) {
                    self.lead = i;
                    return true;
                }
            }
        }
        true
    }

    /// Calling (summoning); false when the run must stop.
    fn call(&mut self, ctx: &mut Context<'_>, t: usize) -> bool {
        let n = self.x.len();
        self.g.copy_from_slice(self.x.row(self.lead));
        // The pack's mean cost at the start of the phase, for the adaptive weight.
        let (mut sum, mut cnt) = (0.0, 0usize);
        for &c in &self.cost {
            if c.is_finite() {
                sum += c;
                cnt += 1;
            }
        }
        let f_avg = if cnt > 0 { sum / cnt as f64 } else { f64::INFINITY };
        for k in (t + 1)..n {
            let i = self.order[k];
            if i == self.lead {
                continue;
            }
            self.s.copy_from_slice(&self.step_b);
            // MWPA: the wolf's weight from its cost at this iteration (F^k of eq. 26), applied
            // once to the reset step (eq. 25 per iteration) or before every raid (compounding).
            let mut per_raid = None;
            if let Some(a) = self.variant.adaptive {
                let w = adaptive_weight(self.cost[i], self.cost[self.lead], f_avg, a.w_min, a.w_max);
                if a.compound {
                    per_raid = Some(w);
                } else {
                    self.s.iter_mut().for_each(|s| *s *= w);
                }
            }
            for _ in 0..self.settings.t_max {
                if distance(self.x.row(i), &self.g) <= self.d_near {
                    break;
                }
                if Self::halt(ctx) {
                    return false;
                }
                if let Some(w) = per_raid {
                    self.s.iter_mut().for_each(|s| *s *= w);
                }
                let x = self.x.row_mut(i);
                raid(x, &self.g, &self.s);
                ctx.repair(x);
                let f = ctx.evaluate(self.x.row(i));
                self.cost[i] = f;
                if better(f, self.cost[self.lead]) {
                    self.lead = i;
                    self.g.copy_from_slice(self.x.row(i));
                    break;
                }
            }
        }
        true
    }

    /// Besieging: every wolf but the lead tries one move, evaluated together, kept if better.
    fn besiege(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        if n < 2 {
            return;
        }
        if let Some(c) = self.variant.decay {
            self.xi *= c;
        }
        let lead = self.lead;
        self.g.copy_from_slice(self.x.row(lead));
        for r in 0..n - 1 {
            let i = if r < lead { r } else { r + 1 };
            let lambda = 2.0 * ctx.rng().random::<f64>() - 1.0;
            siege(self.x.row(i), &self.g, &self.step_c, self.xi * lambda, self.trial.row_mut(r));
            ctx.repair(self.trial.row_mut(r));
        }
        ctx.evaluate_population(&self.trial, &mut self.trial_cost);
        for r in 0..n - 1 {
            let i = if r < lead { r } else { r + 1 };
            if better(self.trial_cost[r], self.cost[i]) {
                self.cost[i] = self.trial_cost[r];
                self.x.copy_row_from(i, &self.trial, r);
            }
        }
    }

    /// Renewal: the R worst wolves become uniform random wolves.
    fn renew(&mut self, ctx: &mut Context<'_>) {
        let n = self.x.len();
        self.rank();
        let u: f64 = ctx.rng().random();
        let r = renewal_count(n, self.settings.beta, u);
        for k in (n - r)..n {
            let i = self.order[k];
            for d in 0..self.x.dim() {
                let (lo, hi) = (ctx.lower()[d], ctx.upper()[d]);
                let u: f64 = ctx.rng().random();
                self.x.row_mut(i)[d] = lo + u * (hi - lo);
            }
            ctx.repair(self.x.row_mut(i));
        }
        for k in (n - r)..n {
            if Self::halt(ctx) {
                // Not evaluated: ranked last until evaluated.
                self.cost[self.order[k]] = f64::INFINITY;
                continue;
            }
            let i = self.order[k];
            self.cost[i] = ctx.evaluate(self.x.row(i));
        }
        self.rank();
    }
}
