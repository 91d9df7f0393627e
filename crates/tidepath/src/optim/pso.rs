//! Particle swarm optimisation with inertia weight.
//!
//! Follows Shi & Eberhart, "A modified particle swarm optimizer" (IEEE ICEC 1998), the
//! global-best (gbest) form with inertia weight:
//!
//! ```text
//! v_id <- w v_id + c1 r1 (p_id - x_id) + c2 r2 (g_d - x_id)     r1, r2 ~ U(0,1), per dimension
//! v_id <- clamp(v_id, -vmax_d, vmax_d)                            vmax_d = vmax_fraction * range_d
//! x_id <- x_id + v_id
//! ```
//!
//! with `w` decreasing linearly from `w_start` to `w_end` over `w_schedule_iterations`
//! iterations (Shi & Eberhart 1999, "Empirical study of particle swarm optimization"), or
//! constant when no schedule is given.
//!
//! Parameter sets of the papers (docs/papers/wpa2017.md, amfa2015.md and ijs2023.md):
//! * wpa2017 (Zhang et al. 2017, Table 3): w = 0.7, c1 = c2 = 2, 50 particles, vmax = range;
//! * amfa2015 (Liu et al. 2015, section 5, after Li et al.): w = 0.729, c1 = c2 = 1.494,
//!   40 particles, "V_max = X_max": the top of the range, half the box width on its symmetric
//!   ranges (`PsoParams::amfa2015`, vmax = range / 2); the other reading, vmax = the whole
//!   width, is `PsoParams::amfa2015_vmax_range` and the defaults (docs/papers/amfa2015.md A13);
//! * ijs2023 (Guo et al., baselines): w 0.9 -> 0.4 linearly, c1 = c2 = 2, vmax = 0.2 x range,
//!   45 particles.
//!
//! Choices (not fixed by the papers):
//! * Synchronous update: the whole swarm moves with the global best of the previous iteration,
//!   then is evaluated as one population; personal and global bests are updated afterwards.
//! * A coordinate that leaves the box is clamped to the bound and its velocity component set to
//!   zero ("absorbing wall"); then the objective's own repair runs.
//! * Personal bests improve only on a strictly lower cost, so an evaluation past the budget
//!   (+inf) never replaces anything. Global-best ties keep the lower particle index.
//! * Inertia at iteration `k = 1, 2, ...`: `w = w_start + (w_end - w_start) min(k / T, 1)`
//!   with `T = w_schedule_iterations`, so the last scheduled iteration uses exactly `w_end`.

use rand::Rng as _;

use super::MAX_POPULATION;
use super::{clamp, Context, Optimizer, Population};
use crate::error::Result;
use crate::params::{field_error, Bound, Checked, Range};
use crate::rng::unit_f64;
use crate::termination::MAX_COUNT;

crate::params! {
    /// PSO parameters. Defaults: amfa2015's set with the velocity clamp at the box width (see
    /// the module documentation).
    pub struct PsoParams {
        /// Number of particles.
        population: usize = 40, Range::integer(2, MAX_POPULATION as u64), "amfa2015 section 5";
        /// Inertia weight at the start of the run.
        w_start: f64 = 0.729, Range::finite(), "amfa2015 section 5";
        /// Inertia weight reached after `w_schedule_iterations` iterations (equal to w_start
        /// when there is no schedule).
        w_end: f64 = 0.729, Range::finite(), "amfa2015 section 5";
        /// Length of the linear inertia schedule in iterations; absent: constant w_start.
        w_schedule_iterations: Option<u64> = None, Range::integer(1, MAX_COUNT), "Shi & Eberhart 1999";
        /// Cognitive coefficient.
        c1: f64 = 1.494, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Social coefficient.
        c2: f64 = 1.494, Range::Number { lo: Bound::Closed(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
        /// Velocity clamp as a fraction of the box width, per dimension.
        vmax_fraction: f64 = 1.0, Range::Number { lo: Bound::Open(0.0), hi: Bound::Unbounded }, "amfa2015 section 5";
    }
    check = check_schedule;
}

/// Without a schedule the inertia is constant, so w_end must equal w_start.
fn check_schedule(p: &PsoParams, prefix: &str) -> Result<()> {
    if p.w_schedule_iterations.is_none() && p.w_end != p.w_start {
        return Err(field_error(
            prefix,
            "w_end",
            format!(
                "must equal w_start ({}) when w_schedule_iterations is not set, got {}; set \
                 w_schedule_iterations for a linear schedule",
                p.w_start, p.w_end
            ),
        ));
    }
    Ok(())
}

impl PsoParams {
    /// wpa2017 (Zhang et al. 2017, Table 3): w = 0.7, c1 = c2 = 2, 50 particles, vmax = range.
    pub fn wpa2017() -> Self {
        Self {
            population: 50,
            w_start: 0.7,
            w_end: 0.7,
            w_schedule_iterations: None,
            c1: 2.0,
            c2: 2.0,
            vmax_fraction: 1.0,
        }
    }

    /// amfa2015 (Liu et al. 2015, section 5): w = 0.729, c1 = c2 = 1.494, 40 particles, and
    /// "V_max = X_max" read as the top of the range, which on the paper's symmetric ranges is
    /// half the box width (docs/papers/amfa2015.md A13). What `reproduce amfa2015` runs as `pso`.
    pub fn amfa2015() -> Self {
        Self { vmax_fraction: 0.5, ..Self::amfa2015_vmax_range() }
    }

    /// amfa2015's setting with the other reading of "V_max = X_max": the whole box width. The
    /// defaults.
    pub fn amfa2015_vmax_range() -> Self {
        Self {
            population: 40,
            w_start: 0.729,
            w_end: 0.729,
            w_schedule_iterations: None,
            c1: 1.494,
            c2: 1.494,
            vmax_fraction: 1.0,
        }
    }

    /// ijs2023's baseline (Guo et al.): w 0.9 -> 0.4 linearly over `iterations`, c1 = c2 = 2,
    /// vmax = 0.2 x range, 45 particles.
    pub fn ijs2023(iterations: u64) -> Self {
        Self {
            population: 45,
            w_start: 0.9,
            w_end: 0.4,
            w_schedule_iterations: Some(iterations),
            c1: 2.0,
            c2: 2.0,
            vmax_fraction: 0.2,
        }
    }

    /// Inertia weight used in iteration `k` (1-based).
    pub fn inertia(&self, k: u64) -> f64 {
        match self.w_schedule_iterations {
            Some(t) if t > 0 => {
                let frac = (k as f64 / t as f64).min(1.0);
                self.w_start + (self.w_end - self.w_start) * frac
            }
            _ => self.w_start,
        }
    }
}

/// Inertia-weight PSO, built from checked parameters.
#[derive(Clone, Debug)]
pub struct Pso {
    params: PsoParams,
    x: Population,
    v: Vec<f64>,
    cost: Vec<f64>,
    pbest: Population,
    pbest_cost: Vec<f64>,
    gbest: Vec<f64>,
    gbest_cost: f64,
    vmax: Vec<f64>,
    iteration: u64,
    /// The current iteration's random words, two per coordinate (reused, so a step does not
    /// allocate).
    r: Vec<u64>,
}

impl Pso {
    pub fn new(params: Checked<PsoParams>) -> Self {
        Self {
            params: params.into_inner(),
            x: Population::zeros(0, 0),
            v: Vec::new(),
            cost: Vec::new(),
            pbest: Population::zeros(0, 0),
            pbest_cost: Vec::new(),
            gbest: Vec::new(),
            gbest_cost: f64::INFINITY,
            vmax: Vec::new(),
            iteration: 0,
            r: Vec::new(),
        }
    }

    pub fn params(&self) -> &PsoParams {
        &self.params
    }

    /// Personal and global best update after an evaluation of `self.x`.
    fn update_bests(&mut self) {
        for i in 0..self.x.len() {
            if self.cost[i] < self.pbest_cost[i] {
                self.pbest_cost[i] = self.cost[i];
                self.pbest.copy_row_from(i, &self.x, i);
            }
        }
        let mut g = None;
        for i in 0..self.pbest_cost.len() {
            if self.pbest_cost[i] < self.gbest_cost {
                self.gbest_cost = self.pbest_cost[i];
                g = Some(i);
            }
        }
        if let Some(g) = g {
            self.gbest.copy_from_slice(self.pbest.row(g));
        }
    }
}

impl Optimizer for Pso {
    fn id(&self) -> &'static str {
        "pso"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let n = self.params.population;
        let dim = ctx.dim();
        self.vmax = (0..dim).map(|d| self.params.vmax_fraction * ctx.range(d)).collect();
        // Random draws: positions (point by point), then velocities (point by point).
        self.x = Population::initial(n, ctx);
        self.v = vec![0.0; n * dim];
        for i in 0..n {
            for d in 0..dim {
                let u: f64 = ctx.rng().random();
                self.v[i * dim + d] = (2.0 * u - 1.0) * self.vmax[d];
            }
        }
        for i in 0..n {
            ctx.repair(self.x.row_mut(i));
        }
        self.cost = vec![f64::INFINITY; n];
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.pbest = self.x.clone();
        self.pbest_cost = self.cost.clone();
        // Index 0 is the global best until a finite cost beats +inf.
        self.gbest = self.x.row(0).to_vec();
        self.gbest_cost = f64::INFINITY;
        self.update_bests();
        self.iteration = 0;
        self.r = vec![0; 2 * n * dim];
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        self.iteration += 1;
        let w = self.params.inertia(self.iteration);
        let (c1, c2) = (self.params.c1, self.params.c2);
        let dim = self.x.dim();
        let n = self.x.len();
        // The iteration's draws, all at once: r1 then r2 for each dimension of each particle,
        // particle by particle (the order fixes the random stream), as the 64-bit words
        // `random::<f64>()` would take, turned into the same U(0,1) values in the loop.
        self.r.resize(2 * n * dim, 0);
        ctx.rng().fill(&mut self.r[..]);
        let (lower, upper) = (&ctx.lower()[..dim], &ctx.upper()[..dim]);
        let (vmax, gbest) = (&self.vmax[..dim], &self.gbest[..dim]);
        for i in 0..n {
            let x = self.x.row_mut(i);
            let v = &mut self.v[i * dim..(i + 1) * dim];
            let pbest = self.pbest.row(i);
            let r = &self.r[2 * i * dim..2 * (i + 1) * dim];
            let others = pbest.iter().zip(gbest).zip(vmax).zip(lower.iter().zip(upper)).zip(r.chunks_exact(2));
            for ((x, v), ((((&p, &g), &vm), (&lo, &hi)), r)) in x.iter_mut().zip(v.iter_mut()).zip(others) {
                let (r1, r2, xi) = (unit_f64(r[0]), unit_f64(r[1]), *x);
                let nv = w * *v + c1 * r1 * (p - xi) + c2 * r2 * (g - xi);
                let vd = clamp(nv, -vm, vm);
                let nx = xi + vd;
                // Absorbing wall: on the bound, with the velocity component zeroed.
                let outside = (nx < lo) | (nx > hi);
                *v = if outside { 0.0 } else { vd };
                *x = clamp(nx, lo, hi);
            }
            ctx.repair(x);
        }
        ctx.evaluate_population(&self.x, &mut self.cost);
        self.update_bests();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::run;
    use crate::termination::Termination;

    #[test]
    fn defaults_and_presets() {
        let p = PsoParams::default();
        assert_eq!(p, PsoParams::amfa2015_vmax_range());
        assert_eq!(PsoParams::amfa2015(), PsoParams { vmax_fraction: 0.5, ..p.clone() });
        assert_eq!(
            (p.population, p.w_start, p.w_end, p.c1, p.c2, p.vmax_fraction),
            (40, 0.729, 0.729, 1.494, 1.494, 1.0)
        );
        assert!(p.clone().checked("p").is_ok());
        assert!(PsoParams::wpa2017().checked("p").is_ok());
        let p3 = PsoParams::ijs2023(500);
        assert!(p3.clone().checked("p").is_ok());
        assert_eq!(p3.inertia(0), 0.9);
        assert!((p3.inertia(250) - 0.65).abs() < 1e-12);
        assert_eq!(p3.inertia(500), 0.4);
        assert_eq!(p3.inertia(10_000), 0.4);
        assert_eq!(PsoParams::wpa2017().inertia(123), 0.7);
    }

    #[test]
    fn check_rejects_bad_values() {
        let bad = [
            PsoParams { population: 1, ..PsoParams::default() },
            PsoParams { w_start: f64::NAN, ..PsoParams::default() },
            PsoParams { c1: -1.0, ..PsoParams::default() },
            PsoParams { c2: f64::INFINITY, ..PsoParams::default() },
            PsoParams { vmax_fraction: 0.0, ..PsoParams::default() },
            PsoParams { w_end: 0.4, ..PsoParams::default() },
            PsoParams { w_schedule_iterations: Some(0), ..PsoParams::default() },
        ];
        for p in bad {
            let e = p.checked("planner.params.pso").unwrap_err().to_string();
            assert!(e.starts_with("planner.params.pso."), "{e}");
        }
    }

    #[test]
    fn tables_defaults_and_unknown_fields() {
        let t: toml::Table = toml::from_str("population = 10").unwrap();
        let p = PsoParams::from_table(&t, "planner.params.pso").unwrap();
        assert_eq!(*p.get(), PsoParams { population: 10, ..PsoParams::default() });
        let t: toml::Table = toml::from_str("inertia = 0.5").unwrap();
        assert!(PsoParams::from_table(&t, "p").is_err());
        let back = PsoParams::from_table(&PsoParams::ijs2023(7).to_table(), "p").unwrap();
        assert_eq!(*back.get(), PsoParams::ijs2023(7));
        assert_eq!(PsoParams::default(), PsoParams::amfa2015_vmax_range());
    }

    #[test]
    fn stays_in_box_and_converges_on_sphere() {
        let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
        let mut pso = Pso::new(PsoParams::default().checked("p").unwrap());
        let r =
            run(&mut pso, &obj, &Termination::iterations(100), &mut crate::rng::run_rng(3, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-6, "{}", r.best_cost);
        assert!(pso.x.rows().all(|x| x.iter().all(|v| (-5.12..=5.12).contains(v))));
        assert_eq!(pso.gbest_cost, r.best_cost);
    }
}
