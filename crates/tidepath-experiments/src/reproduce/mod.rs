//! `tidepath reproduce PAPER`: each paper registers its experiments (problems, planners,
//! parameters and the paper's own reported numbers); the runner sets our results beside the
//! paper's and states plainly which claims reproduce. A claim that does not reproduce is
//! reported with the data; nothing is tuned to make it hold.

mod acopf2016;
mod amfa2015;
mod claims;
mod ijs2023;
mod lfhh2019;
mod report;
mod wpa2017;

pub use claims::{Claim, ClaimVerdict, Direction, Metric};
pub use report::{PaperCell, PaperTable};

use std::path::Path;

use super::compare::Comparison;
use tidepath::error::{Error, Result};
use tidepath::registry::{Entry, Registry};
use tidepath_io::Outputs;

/// Options shared by every reproduction.
#[derive(Clone, Debug)]
pub struct ReproduceOptions {
    pub runs: u64,
    pub master_seed: u64,
    pub jobs: usize,
    /// The reference planner of experiments on scenarios (their gap column): `None` for each
    /// scenario's default ([`super::compare::default_reference`]), `Some("none")` for none.
    pub reference: Option<String>,
    /// The caller's stop flag (Ctrl-C): experiments not started are left out, and the report
    /// says the reproduction is incomplete.
    pub stop: Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    /// Wall-time limit per run (s), a safety net; `None`: the default cap.
    pub time_limit_s: Option<f64>,
    /// A reduced budget for a quick look (`--quick`): each paper that has one says in its
    /// report what it reduces; the others ignore it.
    pub quick: bool,
    /// The parts of the paper to run (`--only`, [`parts`]); empty: all of them.
    pub only: Vec<String>,
}

/// The parts of a reproduction `--only` can pick, for papers whose full run is long (lfhh2019:
/// hours on two cores); empty for papers that always run everything.
pub fn parts(paper: &str) -> &'static [&'static str] {
    match paper {
        "lfhh2019" => lfhh2019::PARTS,
        "amfa2015" => amfa2015::PARTS,
        "ijs2023" => ijs2023::PARTS,
        "acopf2016" => acopf2016::PARTS,
        _ => &[],
    }
}

/// Checks `--only` against the paper's [`parts`].
pub fn check_only(paper: &str, only: &[String]) -> Result<()> {
    let known = parts(paper);
    if only.is_empty() {
        return Ok(());
    }
    if known.is_empty() {
        return Err(Error::input("--only", format!("{paper} runs all its experiments; leave --only out")));
    }
    match only.iter().find(|p| !known.contains(&p.as_str())) {
        Some(p) => Err(Error::input("--only", format!("`{p}` is not a part of {paper} (known: {})", known.join(", ")))),
        None => Ok(()),
    }
}

impl ReproduceOptions {
    /// Whether part `id` runs: every part when `--only` is not given.
    pub fn wants(&self, id: &str) -> bool {
        self.only.is_empty() || self.only.iter().any(|p| p == id)
    }
}

impl ReproduceOptions {
    /// The reference planner an experiment on `scenario` runs, if any.
    pub fn reference_for(&self, scenario: &tidepath_io::scenario::Scenario) -> Option<String> {
        match self.reference.as_deref() {
            None => Some(super::compare::default_reference(scenario).to_string()),
            Some("none") => None,
            Some(id) => Some(id.to_string()),
        }
    }
}

/// One experiment of a paper, after running it.
pub struct ExperimentOutcome {
    /// File-name-safe id, e.g. `table2-small`.
    pub id: String,
    pub title: String,
    /// Setup in prose: problems, parameters, budget, and every reading we had to choose.
    pub setup: String,
    pub comparison: Comparison,
    pub paper: PaperTable,
    pub claims: Vec<(Claim, ClaimVerdict)>,
    /// Findings computed from the data that the table alone does not make obvious.
    pub notes: Vec<String>,
    /// Further tables (heading, Markdown), after the main one: what the paper prints that is
    /// not a cost (e.g. path length).
    pub tables: Vec<(String, String)>,
    /// The scenario of a scenario experiment, for its map figure (the planners' best paths).
    pub scenario: Option<tidepath_io::scenario::Scenario>,
}

/// Progress callback: (runs finished, runs in total).
pub type ProgressFn<'a> = dyn Fn(usize, usize) + Sync + 'a;

/// Runs every experiment of a paper.
pub type RunPaper = fn(&ReproduceOptions, &ProgressFn<'_>) -> Result<Vec<ExperimentOutcome>>;

/// A registered reproduction: an entry of the one registry type every kind uses; `build` runs
/// its experiments.
pub type Paper = Entry<RunPaper>;

/// The reproduction table: adding a paper's reproduction is a file plus one line here.
pub const PAPERS: &[Paper] = &[
    Entry {
        id: "wpa2017",
        description: "MWPA against PSO and GA on Table 2's functions (Table 4, also at equal evaluations), and \
                      against WPA on the path problem (Table 5, Figs. 8-9)",
        citation: "Zhang et al. 2017 (wpa2017), section IV, Tables 2-5",
        params: &[],
        build: wpa2017::run,
    },
    Entry {
        id: "lfhh2019",
        description:
            "LFHH against FHH, FHH with LTS, EDA-G, adaptive DE, RRT* and PRM* re-planning in dynamic 2-D and \
                      3-D worlds (Tables 2-3), its ablation (Tables 4-5) and parameter study (Figs. 15-16)",
        citation: "Liu et al. 2019 (lfhh2019), section V, Tables 2-5, Figs. 15-16",
        params: &[],
        build: lfhh2019::run,
    },
    Entry {
        id: "amfa2015",
        description: "AMFA against FA, PSO and GA on six functions in small and wide ranges (Tables 2 and 4, every \
                      reading of the baselines' settings side by side), and AMFA's two path experiments on the \
                      Salish seabed with the excluding and contracting operators on and off (Figs. 17-18)",
        citation: "Liu et al. 2015 (amfa2015), section 5, Tables 1-4, Figs. 17-18",
        params: &[],
        build: amfa2015::run,
    },
    Entry {
        id: "ijs2023",
        description: "IJS against JS, QPSO, PSO, HHO and MPA on time-optimal AUV paths over a seamount field, static \
                      and in a meandering jet at 0.5, 0.8 and 1.2 x the AUV's speed (Tables 1-3, the current \
                      penalty of Figs. 14-16), and three AUVs arriving together (section IV-C)",
        citation: "Guo, Chen & Pang 2023 (ijs2023), section IV, Tables 1-3, Figs. 14-17",
        params: &[],
        build: ijs2023::run,
    },
    Entry {
        id: "acopf2016",
        description: "Improved ACOPF against plain ACO planning a wave glider's path on a 20 x 20 grid in the \
                      paper's three environments (Figs. 3-5: fixed waves; waves falling with x; plus a south-east \
                      current band) and a fourth of ours, beside A*'s time and length optima on the same cells",
        citation: "Gao, Zhao, Guan, Wang & Zhang 2016 (acopf2016), section 4, Figs. 3-5",
        params: &[],
        build: acopf2016::run,
    },
];

/// The reproductions as a registry: lists, "known: ..." errors.
pub fn papers() -> Registry<RunPaper> {
    Registry::new("reproduction", "PAPER", "tidepath reproduce list", PAPERS)
}

pub fn paper(id: &str) -> Result<Paper> {
    papers().get(id).copied()
}

/// The report's file in the output folder, declared before any run.
pub const REPORT_FILE: &str = "REPORT.md";

/// Runs `paper` and stages DIR/REPORT.md, per-experiment results and figures into `out`
/// (written when the caller commits it, all or none).
pub fn reproduce(
    paper: &Paper,
    opts: &ReproduceOptions,
    out: &mut Outputs,
    dir: &Path,
    progress: &(dyn Fn(usize, usize) + Sync),
    figures: &dyn super::output::FigureRenderer,
) -> Result<Vec<ExperimentOutcome>> {
    check_runs(opts.runs)?;
    check_only(paper.id, &opts.only)?;
    let outcomes = (paper.build)(opts, progress)?;
    report::stage(out, paper, opts, &outcomes, dir, figures)?;
    Ok(outcomes)
}

/// Statistics need two runs; the count is bounded like every count flag.
pub fn check_runs(runs: u64) -> Result<()> {
    if runs < 2 {
        return Err(Error::input("--runs", format!("needs at least 2 runs for statistics, got {runs}")));
    }
    super::compare::check_runs(runs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reproduction_table_is_a_registry() {
        for p in papers().entries() {
            assert!(!p.description.is_empty() && !p.citation.is_empty(), "{}", p.id);
            assert_eq!(paper(p.id).unwrap().id, p.id);
        }
        let e = paper("nope").unwrap_err().to_string();
        assert!(e.starts_with("PAPER: unknown reproduction 'nope' (known: wpa2017"), "{e}");
    }
}
