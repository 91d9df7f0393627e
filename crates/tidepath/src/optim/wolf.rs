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

use std::cmp::Ordering;
use std::f64::consts::PI;

use rand::Rng as _;

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

/// Number of scouts: a uniform integer in `[ceil(n/(alpha+1)), floor(n/alpha)]`, kept in
/// `[0, n-1]` (the lead is never a scout).
pub fn scout_count(n: usize, alpha: f64, u: f64) -> usize {
    uniform_count(n as f64 / (alpha + 1.0), n as f64 / alpha, n, u)
}

/// A uniform integer in `[ceil(lo), floor(hi)]` from `u` in [0, 1), at most `n - 1` (an empty
/// interval gives `ceil(lo)`).
fn uniform_count(lo: f64, hi: f64, n: usize, u: f64) -> usize {
    let lo = lo.ceil() as usize;
    let hi = (hi.floor() as usize).max(lo);
    let t = lo + ((u * (hi - lo + 1) as f64) as usize).min(hi - lo);
    t.min(n.saturating_sub(1))
}

/// Number of renewed wolves: a uniform integer in `[ceil(n/(2 beta)), floor(n/beta)]`, kept in
/// `[0, n-1]` (the lead is never renewed).
pub fn renewal_count(n: usize, beta: f64, u: f64) -> usize {
    uniform_count(n as f64 / (2.0 * beta), n as f64 / beta, n, u)
}

/// d_near = (1/(D omega)) sum_d |max_d - min_d| (wpa2017 eq. 27; the original WPA's rule).
pub fn d_near(lower: &[f64], upper: &[f64], omega: f64) -> f64 {
    let d = lower.len().max(1) as f64;
    lower.iter().zip(upper).map(|(lo, hi)| (hi - lo).abs()).sum::<f64>() / (d * omega)
}

/// The distance compared with d_near: the mean absolute per-dimension difference.
pub fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f64>() / a.len().max(1) as f64
}

/// The directions p in 1..=h that move a wolf: sin(2 pi p/h) is 0 exactly when h divides 2p
/// (p = h/2 and p = h), and such a candidate is the wolf itself, which can never be strictly
/// better than it is. The paper's loop evaluates them; tidepath does not, which changes no
/// move a wolf makes (in floating point sin(pi) is 1.2e-16, a shift below the last bit of any
/// coordinate that is not within 1e-16 of 0) and saves h/2 evaluations in every h of
/// scouting's direction candidates when h is even.
pub fn moving_directions(h: usize) -> Vec<usize> {
    (1..=h).filter(|&p| (2 * p) % h != 0).collect()
}

/// Scouting direction p of h (eq. 22 read as sin(2 pi p/h)): `out = x + sin(2 pi p/h) step_a`.
pub fn direction(x: &[f64], step_a: &[f64], p: usize, h: usize, out: &mut [f64]) {
    let s = (2.0 * PI * p as f64 / h as f64).sin();
    for ((o, &x), &a) in out.iter_mut().zip(x).zip(step_a) {
        *o = x + s * a;
    }
}

/// MWPA's interactive candidate (eq. 23): `out = x + phi (lead - x) + varphi (xa - xb)`.
pub fn interactive(x: &[f64], lead: &[f64], xa: &[f64], xb: &[f64], phi: &[f64], varphi: &[f64], out: &mut [f64]) {
    for d in 0..out.len() {
        out[d] = x[d] + phi[d] * (lead[d] - x[d]) + varphi[d] * (xa[d] - xb[d]);
    }
}

/// One raid: `x_d += step_d sign(g_d - x_d)`, with sign(0) = 0 (a coordinate already on the
/// lead's stays).
pub fn raid(x: &mut [f64], g: &[f64], step: &[f64]) {
    for ((x, &g), &s) in x.iter_mut().zip(g).zip(step) {
        let diff = g - *x;
        let sign = if diff > 0.0 {
            1.0
        } else if diff < 0.0 {
            -1.0
        } else {
            0.0
        };
        *x += s * sign;
    }
}

/// One siege move: `out_d = x_d + factor step_c_d |g_d - x_d|`, `factor` = lambda (WPA) or
/// xi lambda (MWPA, eq. 28).
pub fn siege(x: &[f64], g: &[f64], step_c: &[f64], factor: f64, out: &mut [f64]) {
    for d in 0..out.len() {
        out[d] = x[d] + factor * step_c[d] * (g[d] - x[d]).abs();
    }
}

/// The adaptive raid weight (eq. 26 as read in docs/papers/wpa2017.md): from the wolf's own
/// cost f, the pack's best f_min and mean f_avg,
/// `w_min + (w_max - w_min)(f - f_min)/(f_avg - f_min)` when f <= f_avg, else w_max;
/// w_min when f_avg == f_min.
pub fn adaptive_weight(f: f64, f_min: f64, f_avg: f64, w_min: f64, w_max: f64) -> f64 {
    if f > f_avg || f.is_nan() {
        w_max
    } else if f_avg <= f_min {
        w_min
    } else {
        (w_min + (w_max - w_min) * (f - f_min) / (f_avg - f_min)).clamp(w_min, w_max)
    }
}

fn cmp_cost(a: f64, b: f64) -> Ordering {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => Ordering::Equal,
        (true, false) => Ordering::Greater,
        (false, true) => Ordering::Less,
        _ => a.partial_cmp(&b).expect("not NaN"),
    }
}

/// True when `a` is strictly better than `b` (NaN is never better).
#[inline]
fn better(a: f64, b: f64) -> bool {
    a < b || (b.is_nan() && !a.is_nan())
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::{Objective, Scratch};

    /// (x - 0.2)^2 + (y - 0.2)^2 on [0, 1]^2, feasible only where x >= 0.5: the unconstrained
    /// optimum is infeasible.
    struct HalfPlane;

    impl Objective for HalfPlane {
        fn dim(&self) -> usize {
            2
        }
        fn lower(&self) -> &[f64] {
            &[0.0, 0.0]
        }
        fn upper(&self) -> &[f64] {
            &[1.0, 1.0]
        }
        fn evaluate(&self, x: &[f64], _: &mut Scratch) -> f64 {
            (x[0] - 0.2).powi(2) + (x[1] - 0.2).powi(2)
        }
        fn feasible(&self, x: &[f64], _: &mut Scratch) -> Option<bool> {
            Some(x[0] >= 0.5)
        }
    }

    fn pack(replace_infeasible: bool) -> Pack {
        let settings = Settings {
            population: 4,
            t_max: 1,
            omega: 50.0,
            step_a: 0.01,
            step_b: 0.02,
            step_c: 0.005,
            alpha: 4.0,
            beta: 5.0,
            h: 4,
        };
        Pack::new(settings, Variant { interactive: true, adaptive: None, decay: Some(0.99), replace_infeasible })
    }

    /// Puts wolves at `rows` and evaluates them, as `init` would have.
    fn place(p: &mut Pack, ctx: &mut Context<'_>, rows: &[[f64; 2]]) {
        p.init(ctx);
        for (i, r) in rows.iter().enumerate() {
            p.x.row_mut(i).copy_from_slice(r);
        }
        ctx.evaluate_population(&p.x, &mut p.cost);
        p.rank();
    }

    /// x^2 + y^2 on [-10, 10]^2, steps of 1 (step_a, step_b) and 0.5 (step_c) per dimension,
    /// d_near = 20 / 20 = 1; wolves: the lead at (0.1, 0), then (2, 2), (5, 5), (-6, 6).
    fn sphere_pack(ctx: &mut Context<'_>, variant: Variant) -> Pack {
        let settings = Settings {
            population: 4,
            t_max: 10,
            omega: 20.0,
            step_a: 0.05,
            step_b: 0.05,
            step_c: 0.025,
            alpha: 3.0,
            beta: 2.0,
            h: 4,
        };
        let mut p = Pack::new(settings, variant);
        place(&mut p, ctx, &[[0.1, 0.0], [2.0, 2.0], [5.0, 5.0], [-6.0, 6.0]]);
        p
    }

    const WPA: Variant = Variant { interactive: false, adaptive: None, decay: None, replace_infeasible: false };

    #[test]
    fn scouting_moves_a_scout_to_its_best_direction_until_it_beats_the_lead() {
        let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mut p = sphere_pack(&mut ctx, WPA);
        assert_eq!((scout_count(4, 3.0, 0.5), p.lead, p.order[1]), (1, 0, 1));
        let before = ctx.evaluations();
        assert!(p.scout(&mut ctx, 1));
        // Round 1 from (2, 2): x + sin(2 pi p/4) for p = 1, 3 (p = 2, 4 leave it where it is and
        // are not evaluated) = (3, 3) 18, (1, 1) 2: to (1, 1). Round 2: (2, 2) 8, (0, 0) 0:
        // (0, 0) beats the lead (0.01) and scouting ends: 4 evaluations.
        assert_eq!(ctx.evaluations() - before, 4);
        assert_eq!(p.x.row(1), &[0.0, 0.0]);
        assert_eq!((p.cost[1], p.lead), (0.0, 1));
        // The others did not move.
        assert_eq!([p.x.row(2), p.x.row(3)], [&[5.0, 5.0][..], &[-6.0, 6.0][..]]);
    }

    #[test]
    fn only_directions_that_move_a_wolf_are_tried() {
        assert_eq!(moving_directions(4), [1, 3]);
        assert_eq!(moving_directions(6), [1, 2, 4, 5]);
        assert_eq!(moving_directions(3), [1, 2]);
        assert!(moving_directions(1).is_empty() && moving_directions(2).is_empty());
        // With no moving direction and no interactive candidate, scouting costs nothing.
        let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mut p = sphere_pack(&mut ctx, WPA);
        p.settings.h = 2;
        p.init(&mut ctx);
        let before = ctx.evaluations();
        assert!(p.scout(&mut ctx, 1));
        assert_eq!(ctx.evaluations(), before);
    }

    #[test]
    fn calling_raids_each_ferocious_wolf_to_d_near_or_past_the_lead() {
        let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mut p = sphere_pack(&mut ctx, WPA);
        let before = ctx.evaluations();
        assert!(p.call(&mut ctx, 1));
        // (5, 5) raids by 1 per dimension to (1, 1): mean distance to (0.1, 0) 0.95 <= d_near.
        assert_eq!(p.x.row(2), &[1.0, 1.0]);
        // (-6, 6) raids to (-1, 1) (distance 1.05) and on to (0, 0), which beats the lead.
        assert_eq!(p.x.row(3), &[0.0, 0.0]);
        assert_eq!((p.lead, p.cost[3]), (3, 0.0));
        assert_eq!(ctx.evaluations() - before, 4 + 6);
        // T_max caps the raids of a phase: one raid each.
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mut p = sphere_pack(&mut ctx, WPA);
        p.settings.t_max = 1;
        p.call(&mut ctx, 1);
        assert_eq!([p.x.row(2), p.x.row(3)], [&[4.0, 4.0][..], &[-5.0, 5.0][..]]);
    }

    #[test]
    fn the_siege_moves_each_wolf_along_one_scaled_step_and_keeps_only_improvements() {
        let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
        let mut rng = crate::rng::run_rng(3, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mwpa = Variant { decay: Some(0.9), ..WPA };
        let mut p = sphere_pack(&mut ctx, mwpa);
        let (x0, c0) = (p.x.clone(), p.cost.clone());
        p.besiege(&mut ctx);
        assert_eq!(p.xi, 0.9);
        assert_eq!(p.x.row(0), x0.row(0), "the lead does not move");
        let mut moved = 0;
        for (i, &c) in c0.iter().enumerate().skip(1) {
            let (old, new) = (x0.row(i), p.x.row(i));
            if old == new {
                continue;
            }
            moved += 1;
            assert!(p.cost[i] < c);
            // x' = x + xi lambda step_c |G - x| with one lambda in [-1, 1] for both dimensions.
            let lambdas: Vec<f64> =
                (0..2).map(|d| (new[d] - old[d]) / (0.9 * 0.5 * (x0.row(0)[d] - old[d]).abs())).collect();
            assert!((lambdas[0] - lambdas[1]).abs() < 1e-12 && lambdas[0].abs() <= 1.0, "{lambdas:?}");
        }
        assert!(moved > 0, "with these draws some wolf improves");
    }

    #[test]
    fn renewal_replaces_only_the_worst_wolves() {
        let f = FunctionObjective::new(Function::Sphere, 2, -10.0, 10.0);
        for seed in 0..20 {
            let mut rng = crate::rng::run_rng(seed, 0);
            let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
            let mut p = sphere_pack(&mut ctx, WPA);
            let x0 = p.x.clone();
            let before = ctx.evaluations();
            p.renew(&mut ctx);
            let renewed: Vec<usize> = (0..4).filter(|&i| p.x.row(i) != x0.row(i)).collect();
            // N = 4, beta = 2: R in [1, 2]; the two worst are (-6, 6) and (5, 5).
            assert!(matches!(renewed.as_slice(), [3] | [2, 3]), "seed {seed}: {renewed:?}");
            assert_eq!(ctx.evaluations() - before, renewed.len() as u64);
            for &i in &renewed {
                assert_eq!(p.cost[i], p.x.row(i).iter().map(|v| v * v).sum::<f64>());
            }
        }
    }

    #[test]
    fn step_7_copies_the_best_feasible_wolf_over_infeasible_ones() {
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&HalfPlane, &mut rng, None, false, &[]);
        let mut p = pack(true);
        // Costs 0.0 (infeasible, the lead), 0.41 (feasible: 0.09 + 0.32), 0.25 (feasible:
        // 0.25 + 0), 0.68 (infeasible: 0.04 + 0.64).
        let rows = [[0.2, 0.2], [0.5, 0.2 + 0.32f64.sqrt()], [0.7, 0.2], [0.0, 1.0]];
        place(&mut p, &mut ctx, &rows);
        let before = ctx.evaluations();
        p.replace_infeasible(&mut ctx);
        // Four checks, each counted.
        assert_eq!(ctx.evaluations(), before + 4);
        let x: Vec<Vec<f64>> = p.x.rows().map(|r| r.to_vec()).collect();
        assert_eq!(x, vec![vec![0.7, 0.2], rows[1].to_vec(), vec![0.7, 0.2], vec![0.7, 0.2]]);
        assert!((p.cost[0] - 0.25).abs() < 1e-15 && p.cost[3] == p.cost[2], "{:?}", p.cost);
        assert_eq!(p.lead, 0, "ties go to the lower index");
        // Nothing moved: no wolf is checked again.
        p.replace_infeasible(&mut ctx);
        assert_eq!(ctx.evaluations(), before + 4);
        // One wolf moves: only it is checked.
        p.x.row_mut(1)[0] = 0.1;
        p.replace_infeasible(&mut ctx);
        assert_eq!(ctx.evaluations(), before + 5);
        assert_eq!(p.x.row(1), &[0.7, 0.2]);
    }

    #[test]
    fn step_7_leaves_the_pack_alone_without_a_feasible_wolf_or_constraints() {
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&HalfPlane, &mut rng, None, false, &[]);
        let mut p = pack(true);
        let rows = [[0.2, 0.2], [0.1, 0.9], [0.3, 0.3], [0.0, 1.0]];
        place(&mut p, &mut ctx, &rows);
        p.replace_infeasible(&mut ctx);
        let x: Vec<Vec<f64>> = p.x.rows().map(|r| r.to_vec()).collect();
        assert_eq!(x, rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>());
        // A benchmark function reports no feasibility: no check is made or counted.
        let f = FunctionObjective::new(Function::Sphere, 2, 0.0, 1.0);
        let mut rng = crate::rng::run_rng(1, 0);
        let mut ctx = Context::new(&f, &mut rng, None, false, &[]);
        let mut p = pack(true);
        place(&mut p, &mut ctx, &rows);
        let before = ctx.evaluations();
        p.replace_infeasible(&mut ctx);
        assert_eq!(ctx.evaluations(), before);
    }

    #[test]
    fn step_7_runs_in_mwpa_only_and_keeps_the_run_feasible() {
        // A whole run: with Step 7 every wolf ends feasible once one is; without it (WPA's
        // skeleton) the pack keeps infeasible wolves that beat every feasible one.
        for (replace, all_feasible) in [(true, true), (false, false)] {
            let mut rng = crate::rng::run_rng(7, 0);
            let mut ctx = Context::new(&HalfPlane, &mut rng, Some(5_000), false, &[]);
            let mut p = pack(replace);
            p.settings.population = 20;
            p.init(&mut ctx);
            for _ in 0..10 {
                p.step(&mut ctx);
            }
            let feasible = p.x.rows().all(|r| r[0] >= 0.5);
            assert_eq!(feasible, all_feasible, "replace_infeasible = {replace}");
        }
    }
}
