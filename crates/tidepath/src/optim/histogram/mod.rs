//! Fixed-height histogram estimation of distribution: `fhh` (Tsutsui et al.'s FHH, a baseline
//! of lfhh2019), `fhh-lts` (FHH with lfhh2019's learning transformation, eq. 14) and `lfhh`
//! (lfhh2019, Liu et al., IEEE Access 2019: the learning FHH with periodic path smoothing and
//! safe-cell sampling). One engine; the three ids differ only in what their parameters switch
//! on. The histogram and the transformation are pure functions in [`model`] (eq. 1 printed
//! without its closing parenthesis is read as the midpoint `(a[q-1] + a[q]) / 2` of two
//! neighbours of the sorted elite, 0-based, `q = floor((k - 1) S / binNum)`; see
//! docs/papers/lfhh2019.md A1 and docs/papers/shared.md, FHH).
//!
//! One generation, minimising, the population kept sorted best first:
//!
//! ```text
//! gen <- gen + 1                                        (1 in the first step)
//! if lfhh and gen mod T == 0 and the objective is a path:     # eq. 15
//!     children <- [smooth(p) for p in population]           (Context::smooth_path)
//! else:
//!     for each variable j:
//!         values <- the j-th values of the S best            (fhh-lts, lfhh: v + lambda (best_j - v), eq. 14)
//!         sort values; edges_j <- bins of eqs. 1-2
//!     NP children, each variable: a bin uniformly, then a value uniformly inside it
//!         (lfhh, waypoints of 2+ variables: safe-cell sampling, below)
//! evaluate the children; population <- best NP of parents and children   ((mu + lambda))
//! ```
//!
//! Choices and readings:
//! * **S and binNum.** `binNum <= S` is required (`bins` above `elite` is an input error naming
//!   `bins`): eq. 1's `a[q-1]` needs `q >= 1`, which holds for every bin exactly then. `S <= NP`
//!   is not an error: an elite larger than the population is the whole population, and the
//!   bins are then at most that many, so `--population 50` runs FHH with S = binNum = 50
//!   rather than failing on the paper's S = 100.
//! * **Smoothing (lfhh).** Every T-th generation (`gen mod T == 0`, gen counted from 1 as in
//!   the paper's loop) the children are the parents smoothed by the objective
//!   ([`Context::smooth_path`]: eq. 15 in Jacobi form, endpoints fixed, then repaired), one per
//!   parent, and no random number is drawn. An objective that is not a path (a benchmark
//!   function) answers `false`; that generation then samples from the histograms as usual.
//! * **Safe-cell sampling (lfhh, Fig. 11 and Algorithm 2).** [`Context::waypoint_groups`]
//!   gives the variables that place one waypoint each. For a group of two or more variables
//!   (a 3-D waypoint's lateral and vertical position) one bin is drawn per variable; the box
//!   of those bins is offered to [`Context::region_free`], and all the group's bins are drawn
//!   again while it answers "no free cell", at most `safe_draws` draws in all (the last draw is
//!   then accepted, docs/papers/lfhh2019.md A9; an unknown answer accepts). The values are
//!   then drawn uniformly inside the accepted bins. Groups of one variable (2-D paths) and
//!   variables in no group (benchmark functions, where there are no groups) are sampled one
//!   by one. Groups that overlap an earlier group or leave the vector are ignored.
//! * **Random draws, in order,** per child (in row order), per variable or group in variable
//!   order: one 64-bit word per variable sampled alone, and one word per variable of a group
//!   for each draw of its bins. A word picks the bin and the place inside it at once
//!   ([`split_word`]: `binNum U = bin + fraction`, both uniform and independent), so a group's
//!   accepted words also place its values (the fraction is independent of the bin the
//!   free-cell test looked at).
//! * Ties in the selection keep the parent; NaN costs count as +inf. Sampled children go
//!   through the objective's repair. Sampling polls [`Context::should_stop`] every
//!   [`POLL_CHILDREN`] children (every child when it asks `region_free` or smooths), so a
//!   wall-time limit or Ctrl-C cuts a generation; the children left are not evaluated.

pub mod model;
mod select;
#[cfg(test)]
mod tests;

use std::ops::Range as Span;

use rand::{Rng as _, RngCore as _};

pub use model::{bin_edges, bin_index, boundary_index, lts, sample_in, sort_values, split_word, total_order_key};
pub(crate) use select::Elitist;

use super::{Context, Optimizer, MAX_POPULATION};
use crate::error::Result;
use crate::params::{field_error, Checked, Range};
use crate::termination::MAX_COUNT;

/// Children sampled between two polls of the stop flag and the deadline when sampling asks
/// the objective nothing (a child costs tens of nanoseconds per variable there).
pub const POLL_CHILDREN: usize = 16;

/// `bins <= elite`, the condition of eq. 1 (see the module documentation).
fn check_bins(bins: usize, elite: usize, prefix: &str) -> Result<()> {
    if bins > elite {
        return Err(field_error(prefix, "bins", format!("must be at most elite (S = {elite}), got {bins}")));
    }
    Ok(())
}

crate::params! {
    /// FHH parameters (lfhh2019 Table 1, the FHH baseline).
    pub struct FhhParams {
        /// Population NP (parents; as many children per generation).
        population: usize = 200, Range::integer(2, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Elite S: the best solutions the histograms are built from (at most the population;
        /// a larger value uses the whole population).
        elite: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Bins binNum per variable (at most elite).
        bins: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
    }
    check = check_fhh;
}

fn check_fhh(p: &FhhParams, prefix: &str) -> Result<()> {
    check_bins(p.bins, p.elite, prefix)
}

crate::params! {
    /// FHH with the learning transformation (lfhh2019 Table 1, the FHH+LTS baseline).
    pub struct FhhLtsParams {
        /// Population NP (parents; as many children per generation).
        population: usize = 200, Range::integer(2, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Elite S: the best solutions the histograms are built from (at most the population;
        /// a larger value uses the whole population).
        elite: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Bins binNum per variable (at most elite).
        bins: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Learning factor lambda of eq. 14: each elite value moves this fraction of the way to
        /// the best solution's value before the histogram is built.
        lambda: f64 = 0.08, Range::closed(0.0, 1.0), "lfhh2019 Table 1";
    }
    check = check_fhh_lts;
}

fn check_fhh_lts(p: &FhhLtsParams, prefix: &str) -> Result<()> {
    check_bins(p.bins, p.elite, prefix)
}

crate::params! {
    /// LFHH parameters (lfhh2019 Table 1).
    pub struct LfhhParams {
        /// Population NP (parents; as many children per generation).
        population: usize = 200, Range::integer(2, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Elite S: the best solutions the histograms are built from (at most the population;
        /// a larger value uses the whole population).
        elite: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Bins binNum per variable (at most elite).
        bins: usize = 100, Range::integer(1, MAX_POPULATION as u64), "lfhh2019 Table 1";
        /// Learning factor lambda of eq. 14: each elite value moves this fraction of the way to
        /// the best solution's value before the histogram is built.
        lambda: f64 = 0.08, Range::closed(0.0, 1.0), "lfhh2019 Table 1";
        /// Smoothing period T: every T-th generation smooths the paths (eq. 15) instead of
        /// sampling.
        period: u64 = 5, Range::integer(1, MAX_COUNT), "lfhh2019 Table 1";
        /// Most draws of a waypoint's bins while they hold no free cell (safe-cell sampling);
        /// the last draw is accepted.
        safe_draws: usize = 100, Range::integer(1, 1_000_000), "lfhh2019 A9 (chosen)";
    }
    check = check_lfhh;
}

fn check_lfhh(p: &LfhhParams, prefix: &str) -> Result<()> {
    check_bins(p.bins, p.elite, prefix)
}

impl FhhParams {
    /// lfhh2019 Table 1: NP = 200, S = 100, binNum = 100 (the defaults).
    pub fn lfhh2019() -> Self {
        Self { population: 200, elite: 100, bins: 100 }
    }
}

impl FhhLtsParams {
    /// lfhh2019 Table 1: NP = 200, S = 100, binNum = 100, lambda = 0.08 (the defaults).
    pub fn lfhh2019() -> Self {
        Self { population: 200, elite: 100, bins: 100, lambda: 0.08 }
    }
}

impl LfhhParams {
    /// lfhh2019 Table 1: NP = 200, S = 100, binNum = 100, lambda = 0.08, T = 5, and at most 100
    /// safe-cell draws (A9) (the defaults).
    pub fn lfhh2019() -> Self {
        Self { population: 200, elite: 100, bins: 100, lambda: 0.08, period: 5, safe_draws: 100 }
    }
}

/// What a run of the engine uses; the three ids switch parts on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Settings {
    pub population: usize,
    pub elite: usize,
    pub bins: usize,
    /// Eq. 14's lambda; `None`: plain FHH.
    pub lambda: Option<f64>,
    /// Smoothing period T; `None`: never smooth.
    pub period: Option<u64>,
    /// Safe-cell sampling with at most this many draws per waypoint; `None`: every variable
    /// is sampled alone.
    pub safe_draws: Option<usize>,
}

/// How the variables of a child are sampled, in variable order.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Block {
    /// One variable from its own histogram.
    Single(usize),
    /// The variables of waypoint group `group` ([`Context::waypoint_groups`]), by safe-cell
    /// sampling.
    Group { group: usize, vars: Span<usize> },
}

/// The sampling blocks of `dim` variables given the objective's waypoint groups: every group
/// of two or more variables inside `0..dim` that overlaps no earlier one is a [`Block::Group`];
/// every other variable is a [`Block::Single`]. Ordered by first variable.
pub(crate) fn blocks(dim: usize, groups: &[Span<usize>]) -> Vec<Block> {
    let mut owner: Vec<Option<usize>> = vec![None; dim];
    for (g, vars) in groups.iter().enumerate() {
        let usable = vars.len() >= 2 && vars.end <= dim && owner[vars.clone()].iter().all(Option::is_none);
        if usable {
            owner[vars.clone()].iter_mut().for_each(|o| *o = Some(g));
        }
    }
    let mut out = Vec::new();
    let mut j = 0;
    while j < dim {
        match owner[j] {
            Some(g) => {
                let vars = groups[g].clone();
                j = vars.end;
                out.push(Block::Group { group: g, vars });
            }
            None => {
                out.push(Block::Single(j));
                j += 1;
            }
        }
    }
    out
}

/// The histogram EDA engine and its reused buffers.
#[derive(Clone, Debug)]
pub(crate) struct Engine {
    pub settings: Settings,
    pub pop: Elitist,
    /// Generations done, counted from 1 in the first step.
    pub generation: u64,
    /// The elite S and bins binNum of this run (at most the population; see the module
    /// documentation).
    pub elite: usize,
    pub bins: usize,
    /// Histogram edges, `bins + 1` per variable.
    pub edges: Vec<f64>,
    pub blocks: Vec<Block>,
    /// Whether any block is a group (safe-cell sampling asks the objective).
    grouped: bool,
    /// Generations whose children were smoothed paths.
    pub smoothed: u64,
    /// One variable's (transformed) elite values, sorted.
    column: Vec<f64>,
    /// Sort keys of `column`.
    keys: Vec<u64>,
    /// One child's random words.
    words: Vec<u64>,
    /// The box of a group's drawn bins.
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl Engine {
    pub fn new(settings: Settings) -> Self {
        Self {
            settings,
            pop: Elitist::empty(),
            generation: 0,
            elite: 0,
            bins: 0,
            edges: Vec::new(),
            blocks: Vec::new(),
            grouped: false,
            smoothed: 0,
            column: Vec::new(),
            keys: Vec::new(),
            words: Vec::new(),
            lo: Vec::new(),
            hi: Vec::new(),
        }
    }

    pub fn init(&mut self, ctx: &mut Context<'_>) {
        let n = self.settings.population;
        let dim = ctx.dim();
        self.pop.init(n, ctx);
        self.generation = 0;
        self.smoothed = 0;
        self.elite = self.settings.elite.min(n).max(1);
        self.bins = self.settings.bins.min(self.elite).max(1);
        self.column = vec![0.0; self.elite];
        self.keys = Vec::with_capacity(self.elite);
        self.edges = vec![0.0; dim * (self.bins + 1)];
        self.words = vec![0; dim];
        self.blocks = match self.settings.safe_draws {
            Some(_) => blocks(dim, &ctx.waypoint_groups()),
            None => (0..dim).map(Block::Single).collect(),
        };
        self.grouped = self.blocks.iter().any(|b| matches!(b, Block::Group { .. }));
        self.lo = vec![0.0; dim];
        self.hi = vec![0.0; dim];
    }

    pub fn step(&mut self, ctx: &mut Context<'_>) {
        if self.pop.len() == 0 {
            return;
        }
        self.generation += 1;
        let smoothing = self.settings.period.is_some_and(|t| self.generation % t == 0);
        if smoothing && self.smooth(ctx) {
            self.smoothed += 1;
        } else {
            self.build_model(ctx);
            self.sample(ctx);
        }
        self.pop.evaluate_and_select(ctx);
    }

    /// Children = the parents smoothed by the objective (eq. 15). False when the objective
    /// has no path to smooth (then nothing is drawn and the caller samples).
    fn smooth(&mut self, ctx: &mut Context<'_>) -> bool {
        let pop = &mut self.pop;
        for i in 0..pop.len() {
            if ctx.should_stop() {
                break; // The rest are not evaluated.
            }
            pop.children.copy_row_from(i, &pop.x, i);
            if !ctx.smooth_path(pop.children.row_mut(i)) && i == 0 {
                return false;
            }
        }
        true
    }

    /// The histograms of every variable from the elite (after eq. 14 when lambda is set).
    pub(crate) fn build_model(&mut self, ctx: &Context<'_>) {
        let dim = self.pop.x.dim();
        let (s, bins) = (self.elite, self.bins);
        let flat = self.pop.x.as_flat();
        let best = &flat[..dim];
        for j in 0..dim {
            let rows = flat.chunks_exact(dim).take(s);
            match self.settings.lambda {
                Some(l) => {
                    for (c, row) in self.column.iter_mut().zip(rows) {
                        *c = lts(row[j], best[j], l);
                    }
                }
                None => {
                    for (c, row) in self.column.iter_mut().zip(rows) {
                        *c = row[j];
                    }
                }
            }
            sort_values(&mut self.column, &mut self.keys);
            let edges = &mut self.edges[j * (bins + 1)..(j + 1) * (bins + 1)];
            bin_edges(&self.column, bins, ctx.lower()[j], ctx.upper()[j], edges);
        }
    }

    /// NP children from the histograms.
    fn sample(&mut self, ctx: &mut Context<'_>) {
        let Self { pop, edges, blocks, grouped, words, lo, hi, bins, settings, .. } = self;
        let (bins, stride, grouped) = (*bins, *bins + 1, *grouped);
        let dim = pop.x.dim();
        let max_draws = settings.safe_draws.unwrap_or(1);
        for i in 0..pop.len() {
            let poll = grouped || i % POLL_CHILDREN == 0;
            if poll && ctx.should_stop() {
                return; // The rest are not evaluated.
            }
            let child = pop.children.row_mut(i);
            if !grouped {
                ctx.rng().fill(&mut words[..dim]);
                for ((j, c), &w) in child.iter_mut().enumerate().zip(words.iter()) {
                    let (b, u) = split_word(w, bins);
                    *c = sample_in(&edges[j * stride..], b, u);
                }
            } else {
                for block in blocks.iter() {
                    match block {
                        Block::Single(j) => {
                            let (b, u) = split_word(ctx.rng().next_u64(), bins);
                            child[*j] = sample_in(&edges[j * stride..], b, u);
                        }
                        Block::Group { group, vars } => {
                            let len = vars.len();
                            let mut draws = 0;
                            loop {
                                ctx.rng().fill(&mut words[..len]);
                                for (v, j) in vars.clone().enumerate() {
                                    let b = bin_index(words[v], bins);
                                    lo[v] = edges[j * stride + b];
                                    hi[v] = edges[j * stride + b + 1];
                                }
                                draws += 1;
                                if draws >= max_draws || ctx.region_free(*group, &lo[..len], &hi[..len]) != Some(false)
                                {
                                    break;
                                }
                            }
                            // The accepted words' fractions place the values inside their bins.
                            for (v, j) in vars.clone().enumerate() {
                                let (b, u) = split_word(words[v], bins);
                                child[j] = sample_in(&edges[j * stride..], b, u);
                            }
                        }
                    }
                }
            }
            ctx.repair(child);
        }
    }
}

/// A histogram EDA planner: `fhh`, `fhh-lts` or `lfhh`.
#[derive(Clone, Debug)]
pub struct Histogram {
    id: &'static str,
    engine: Engine,
}

impl Histogram {
    /// FHH: no transformation, no smoothing, every variable sampled alone.
    pub fn fhh(params: Checked<FhhParams>) -> Self {
        let p = params.into_inner();
        Self::with(
            "fhh",
            Settings {
                population: p.population,
                elite: p.elite,
                bins: p.bins,
                lambda: None,
                period: None,
                safe_draws: None,
            },
        )
    }

    /// FHH with eq. 14's learning transformation.
    pub fn fhh_lts(params: Checked<FhhLtsParams>) -> Self {
        let p = params.into_inner();
        Self::with(
            "fhh-lts",
            Settings {
                population: p.population,
                elite: p.elite,
                bins: p.bins,
                lambda: Some(p.lambda),
                period: None,
                safe_draws: None,
            },
        )
    }

    /// LFHH: the transformation, smoothing every T-th generation and safe-cell sampling.
    pub fn lfhh(params: Checked<LfhhParams>) -> Self {
        let p = params.into_inner();
        Self::with(
            "lfhh",
            Settings {
                population: p.population,
                elite: p.elite,
                bins: p.bins,
                lambda: Some(p.lambda),
                period: Some(p.period),
                safe_draws: Some(p.safe_draws),
            },
        )
    }

    fn with(id: &'static str, settings: Settings) -> Self {
        Self { id, engine: Engine::new(settings) }
    }
}

impl Optimizer for Histogram {
    fn id(&self) -> &'static str {
        self.id
    }

    fn population(&self) -> usize {
        self.engine.settings.population
    }

    fn init(&mut self, ctx: &mut Context<'_>) {
        self.engine.init(ctx);
    }

    fn step(&mut self, ctx: &mut Context<'_>) {
        self.engine.step(ctx);
    }
}
