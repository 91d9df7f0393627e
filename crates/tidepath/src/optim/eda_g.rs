//! EDA-G, the Gaussian estimation-of-distribution baseline of lfhh2019.
//!
//! lfhh2019 cites the PBIL_C family (Sebag & Ducoulombier 1998) without further detail
//! (docs/papers/lfhh2019.md A14); tidepath uses the UMDA_c form (chosen; docs/papers/shared.md,
//! EDA-G):
//!
//! ```text
//! per variable j, over the S best:  mu_j = mean,  sigma_j = max(std, 1e-3 (hi_j - lo_j))
//! NP children:  x_j = clamp(mu_j + sigma_j z,  lo_j, hi_j),   z ~ N(0, 1) per child and variable
//! population <- best NP of parents and children
//! ```
//!
//! Choices:
//! * The standard deviation is the maximum-likelihood one (divided by S, as UMDA_c estimates
//!   it), floored at 1e-3 of the variable's range so the model cannot collapse onto a point.
//! * A child's value outside the box is clamped to the bound, then the objective's repair runs.
//! * An elite larger than the population is the whole population (so `--population 50` runs
//!   with S = 50).
//! * Random draws, in order: per child (in row order), one standard normal per variable
//!   (`rand_distr::StandardNormal`, ziggurat). Selection as in the histogram EDAs: ties keep
//!   the parent, NaN counts as +inf. Sampling polls [`Context::should_stop`] every
//!   [`POLL_CHILDREN`] children.

use rand::Rng as _;
use rand_distr::StandardNormal;

use super::histogram::{Elitist, POLL_CHILDREN};
use super::{clamp, Context, Optimizer, MAX_POPULATION};
use crate::params::{Checked, Range};

/// The floor of every standard deviation, as a fraction of the variable's range.
pub const SIGMA_FLOOR: f64 = 1e-3;

crate::params! {
    /// EDA-G parameters (lfhh2019 Table 1).
    pub struct EdaGParams {
        /// Population NP (parents; as many children per generation).
        population: usize = 200, Range::integer(2, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Elite S: the best solutions the normals are fitted to (at most the population; a
        /// larger value uses the whole population).
        elite: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
    }
}

impl EdaGParams {
    /// lfhh2019 Table 1: NP = 200, S = 100 (the defaults).
    pub fn lfhh2019() -> Self {
        Self { population: 200, elite: 100 }
    }
}

/// The mean and the floored maximum-likelihood standard deviation of each column of the first
/// `s` rows of `rows` (row-major, `mean.len()` columns); `floor[j]` is column j's floor.
pub fn fit(rows: &[f64], s: usize, floor: &[f64], mean: &mut [f64], sigma: &mut [f64]) {
    let dim = mean.len();
    mean.fill(0.0);
    sigma.fill(0.0);
    for row in rows.chunks_exact(dim).take(s) {
        for (m, &v) in mean.iter_mut().zip(row) {
            *m += v;
        }
    }
    let inv = 1.0 / s as f64;
    mean.iter_mut().for_each(|m| *m *= inv);
    for row in rows.chunks_exact(dim).take(s) {
        for ((q, &m), &v) in sigma.iter_mut().zip(mean.iter()).zip(row) {
            *q += (v - m) * (v - m);
        }
    }
    for (q, &f) in sigma.iter_mut().zip(floor) {
        *q = (*q * inv).sqrt().max(f);
    }
}

/// UMDA_c with a floored standard deviation, built from checked parameters.
#[derive(Clone, Debug)]
pub struct EdaG {
    params: EdaGParams,
    pop: Elitist,
    mean: Vec<f64>,
    sigma: Vec<f64>,
    floor: Vec<f64>,
}

impl EdaG {
    pub fn new(params: Checked<EdaGParams>) -> Self {
        Self {
            params: params.into_inner(),
            pop: Elitist::empty(),
            mean: Vec::new(),
            sigma: Vec::new(),
            floor: Vec::new(),
        }
    }

    pub fn params(&self) -> &EdaGParams {
        &self.params
    }
}

impl Optimizer for EdaG {
    fn id(&self) -> &'static str {
        "eda-g"
    }

    fn population(&self) -> usize {
        self.params.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        let dim = ctx.dim();
        self.pop.init(self.params.population, ctx);
        self.mean = vec![0.0; dim];
        self.sigma = vec![0.0; dim];
        self.floor = (0..dim).map(|j| SIGMA_FLOOR * ctx.range(j)).collect();
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        let n = self.pop.len();
        if n == 0 {
            return;
        }
        let s = self.params.elite.min(n);
        fit(self.pop.x.as_flat(), s, &self.floor, &mut self.mean, &mut self.sigma);
        for i in 0..n {
            if i % POLL_CHILDREN == 0 && ctx.should_stop() {
                break; // The rest are not evaluated.
            }
            let child = self.pop.children.row_mut(i);
            for (j, c) in child.iter_mut().enumerate() {
                let z: f64 = ctx.rng().sample(StandardNormal);
                *c = clamp(self.mean[j] + self.sigma[j] * z, ctx.lower()[j], ctx.upper()[j]);
            }
            ctx.repair(child);
        }
        self.pop.evaluate_and_select(ctx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::functions::{Function, FunctionObjective};
    use crate::optim::run;
    use crate::termination::Termination;

    #[test]
    fn defaults_and_check() {
        let p = EdaGParams::default();
        assert_eq!((p.population, p.elite), (200, 100));
        assert!(EdaGParams { population: 1, ..p.clone() }.checked("p").is_err());
        assert!(EdaGParams { elite: 0, ..p.clone() }.checked("p").is_err());
        // An elite above the population is allowed: the whole population is the elite.
        assert!(EdaGParams { population: 50, ..p }.checked("p").is_ok());
    }

    #[test]
    fn fit_by_hand_and_the_floor() {
        // Columns: (1, 3, 5, 100) and (2, 2, 2, 100); only the first three rows are the elite.
        let rows = [1.0, 2.0, 3.0, 2.0, 5.0, 2.0, 100.0, 100.0];
        let (mut mean, mut sigma) = ([0.0; 2], [0.0; 2]);
        fit(&rows, 3, &[0.01, 0.01], &mut mean, &mut sigma);
        assert_eq!(mean, [3.0, 2.0]);
        // Column 0: deviations -2, 0, 2: variance 8/3 (divided by S). Column 1: 0, floored.
        assert!((sigma[0] - (8.0f64 / 3.0).sqrt()).abs() < 1e-15, "{}", sigma[0]);
        assert_eq!(sigma[1], 0.01);
    }

    #[test]
    fn a_collapsed_population_keeps_the_floor_and_stays_in_the_box() {
        // Every parent at one point: children spread with sigma = 1e-3 of the range (20 here).
        let obj = FunctionObjective::new(Function::Sphere, 3, -10.0, 10.0);
        let mut rng = crate::rng::run_rng(5, 0);
        let mut ctx = Context::new(&obj, &mut rng, None, false, &[]);
        let mut eda = EdaG::new(EdaGParams { population: 400, elite: 400 }.checked("p").unwrap());
        eda.init(&mut ctx);
        for i in 0..400 {
            eda.pop.x.row_mut(i).copy_from_slice(&[9.995, 1.0, -2.0]);
        }
        eda.step(&mut ctx);
        let kids = &eda.pop.children;
        let col = |j: usize| kids.rows().map(move |r| r[j]);
        let sd = |j: usize| {
            let m = col(j).sum::<f64>() / 400.0;
            (col(j).map(|v| (v - m).powi(2)).sum::<f64>() / 400.0).sqrt()
        };
        // Sample std of 400 normal draws: within 15 % of 0.02 with near certainty.
        for j in [1, 2] {
            assert!((sd(j) - 0.02).abs() < 0.003, "column {j}: {}", sd(j));
        }
        // Column 0 sits 0.005 (a quarter sigma) below the bound: the draws above are clamped.
        assert!(col(0).all(|v| v <= 10.0));
        assert!(col(0).filter(|&v| v == 10.0).count() > 100);
    }

    #[test]
    fn converges_on_sphere_and_never_worsens() {
        let obj = FunctionObjective::new(Function::Sphere, 5, -5.12, 5.12);
        let mut eda = EdaG::new(EdaGParams::default().checked("p").unwrap());
        let r =
            run(&mut eda, &obj, &Termination::iterations(150), &mut crate::rng::run_rng(1, 0), false, &[], &mut |_| {});
        assert!(r.best_cost < 1e-4, "{}", r.best_cost);
        assert!(r.history.windows(2).all(|w| w[1] <= w[0]));
        assert_eq!(eda.pop.cost[0], r.best_cost);
        assert!(eda.pop.cost.windows(2).all(|w| w[0] <= w[1]), "population not sorted");
    }

    #[test]
    fn same_seed_same_bits() {
        let obj = FunctionObjective::new(Function::Rastrigin, 6, -5.12, 5.12);
        let go = |seed| {
            let mut eda = EdaG::new(EdaGParams { population: 30, elite: 10 }.checked("p").unwrap());
            run(
                &mut eda,
                &obj,
                &Termination::iterations(20),
                &mut crate::rng::run_rng(seed, 0),
                false,
                &[],
                &mut |_| {},
            )
        };
        let (a, b, c) = (go(3), go(3), go(4));
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&a.best_x), bits(&b.best_x));
        assert_eq!(bits(&a.history), bits(&b.history));
        assert_ne!(bits(&a.history), bits(&c.history));
    }
}
