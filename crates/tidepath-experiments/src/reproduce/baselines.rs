//! amfa2015 (Liu, Zhao, Gao & Liu 2015), Tables 2 and 4: the PSO and GA rows, with DE beside
//! them for reference, and the GA under the other reading of its mutation rate. Six functions, D = 30, population 40, 60,000 evaluations, small
//! (Table 1) and wide (Table 3) ranges. AMFA and FA join these tables in the firefly issue.

use super::report::same_magnitude;
use super::{Claim, ExperimentOutcome, PaperCell, PaperTable, ReproduceOptions};
use crate::compare::{compare_functions, FunctionProblem, RunBudget};
use crate::runner::RunControl;
use tidepath::error::Result;
use tidepath::optim::de::{De, DeParams};
use tidepath::optim::functions::Function;
use tidepath::optim::ga::{Ga, GaParams};
use tidepath::optim::pso::{Pso, PsoParams};
use tidepath::optim::Optimizer;

const FUNCTIONS: [Function; 6] = [
    Function::Sphere,
    Function::Rosenbrock,
    Function::Rastrigin,
    Function::Griewank,
    Function::Ackley,
    Function::Zakharov,
];
const DIM: usize = 30;
const POPULATION: usize = 40;
const EVALUATIONS: u64 = 60_000;
/// Runs per cell of the paper's tables ("30 runs", docs/papers/amfa2015.md#baselines).
const PAPER_RUNS: u64 = 30;
/// The GA under the alternative reading of its mutation rate; reported, never used for claims.
const GA_PER_CHROMOSOME: &str = "ga-pm-per-chromosome";

/// (best, mean, std, "0" times) per function in FUNCTIONS order, as printed.
type Rows = [(f64, f64, f64, u32); 6];

const TABLE2_PSO: Rows = [
    (5.05e-41, 1.75e-36, 9.19e-36, 0),
    (1.27e-2, 2.17e-1, 0.75, 0),
    (1.00, 4.88, 2.24, 0),
    (0.0, 5.6e-3, 8.3e-3, 7),
    (1.42e-14, 3.02e-1, 5.68e-1, 0),
    (4.6e-6, 6.7e-5, 6.8e-5, 0),
];
const TABLE2_GA: Rows = [
    (9.64e-7, 4.91e-6, 4.56e-6, 0),
    (7.8507, 51.3280, 29.7729, 0),
    (43.78, 58.04, 8.28, 0),
    (1.14e-7, 2.30e-2, 4.40e-2, 0),
    (1.34, 2.34, 3.71e-1, 0),
    (9.8e1, 1.8e2, 4.6e1, 0),
];
const TABLE4_PSO: Rows = [
    (5.23e-39, 8.73e-35, 2.16e-34, 0),
    (2.58e-2, 8.61e-1, 1.46, 0),
    (2.98, 6.40, 2.38, 0),
    (0.0, 2.30e-2, 2.85e-2, 2),
    (2.13e-14, 1.63, 1.12, 0),
    (4.8e1, 3.3e2, 2.8e2, 0),
];
const TABLE4_GA: Rows = [
    (3.42e-4, 1.71e-3, 1.52e-3, 0),
    (2.88, 7.67e1, 4.98e1, 0),
    (1.99e1, 6.08e1, 3.15e1, 0),
    (4.85e-4, 5.45e-2, 5.30e-2, 0),
    (4.10e-3, 7.7e-3, 3.1e-3, 0),
    (1.5e4, 3.0e4, 6.2e3, 0),
];

/// The paper's settings: PSO w = 0.729, c1 = c2 = 1.494, V_max = X_max; GA binary, 20 bits,
/// roulette, single-point crossover pc = 0.6, pm = 1/n per bit (docs/papers/shared.md#ga); DE/rand/1/bin
/// F = 0.5, CR = 0.9 (ours, not in the paper). Population 40 for all.
fn factory(id: &str) -> Result<Box<dyn Optimizer>> {
    let prefix = format!("baselines.{id}");
    Ok(match id {
        "pso" => Box::new(Pso::new(PsoParams { population: POPULATION, ..PsoParams::amfa2015() }.checked(&prefix)?)),
        "ga" => Box::new(Ga::new(GaParams { population: POPULATION, ..GaParams::amfa2015() }.checked(&prefix)?)),
        // The other reading of the paper's "pm = 1/n": once per chromosome of D x 20 bits.
        GA_PER_CHROMOSOME => Box::new(Ga::new(
            GaParams { population: POPULATION, mutation_rate: Some(1.0 / (DIM as f64 * 20.0)), ..GaParams::amfa2015() }
                .checked(&prefix)?,
        )),
        "de" => Box::new(De::new(DeParams { population: POPULATION, ..DeParams::default() }.checked(&prefix)?)),
        other => return Err(tidepath::error::Error::input("planner", format!("baselines has no planner '{other}'"))),
    })
}

fn table(source: &str, labels: &[String], pso: &Rows, ga: &Rows) -> PaperTable {
    let mut cells = Vec::new();
    for (i, label) in labels.iter().enumerate() {
        for (planner, rows) in [("pso", pso), ("ga", ga)] {
            let (best, mean, std, zeros) = rows[i];
            cells.push(PaperCell {
                problem: label.clone(),
                planner: planner.into(),
                best: Some(best),
                mean: Some(mean),
                std: Some(std),
                zeros: Some(zeros),
                ..PaperCell::default()
            });
        }
    }
    PaperTable { source: source.into(), runs: Some(PAPER_RUNS), cells }
}

/// The orderings the paper's table implies between PSO and GA (by mean).
fn claims(labels: &[String], pso: &Rows, ga: &Rows, range: &str) -> Vec<Claim> {
    labels
        .iter()
        .enumerate()
        .map(|(i, label)| {
            let f = FUNCTIONS[i].id();
            if pso[i].1 <= ga[i].1 {
                Claim::lower(label, "pso", "ga", format!("PSO reaches lower costs than GA on {f} ({range} range)"))
            } else {
                Claim::lower(label, "ga", "pso", format!("GA reaches lower costs than PSO on {f} ({range} range)"))
            }
        })
        .collect()
}

pub(super) fn run(opts: &ReproduceOptions, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<ExperimentOutcome>> {
    let planners: Vec<String> = ["pso", "ga", GA_PER_CHROMOSOME, "de"].iter().map(|s| s.to_string()).collect();
    let budget = RunBudget {
        evaluations: Some(EVALUATIONS),
        population: Some(POPULATION),
        time_limit_s: opts.time_limit_s,
        ..RunBudget::default()
    };
    let mut outcomes = Vec::new();
    let experiments = [
        ("table2-small", "Table 2: small ranges", "small", "amfa2015, Table 2", &TABLE2_PSO, &TABLE2_GA),
        ("table4-wide", "Table 4: wide ranges", "wide", "amfa2015, Table 4", &TABLE4_PSO, &TABLE4_GA),
    ];
    let per_experiment = FUNCTIONS.len() * planners.len() * opts.runs as usize;
    let total = per_experiment * experiments.len();
    for (k, (id, title, range, source, pso, ga)) in experiments.into_iter().enumerate() {
        let problems: Vec<FunctionProblem> = FUNCTIONS
            .iter()
            .map(|&f| {
                let (lo, hi) = if range == "small" { f.small_range() } else { f.wide_range() }.expect("amfa2015 range");
                FunctionProblem {
                    function: f,
                    dim: DIM,
                    lower: lo,
                    upper: hi,
                    label: format!("{}-d{DIM}-{range}", f.id()),
                }
            })
            .collect();
        let labels: Vec<String> = problems.iter().map(|p| p.label.clone()).collect();
        let done = k * per_experiment;
        if opts.stop.as_ref().is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed)) {
            break;
        }
        let on_done = |n| progress(done + n, total);
        let control = RunControl { jobs: opts.jobs, stop: opts.stop.as_ref(), on_done: &on_done };
        let comparison =
            compare_functions(&problems, &planners, opts.runs, opts.master_seed, &budget, control, Some(&factory))?;
        let claims = claims(&labels, pso, ga, range);
        let checked: Vec<_> = claims
            .into_iter()
            .map(|c| {
                let v = c.check(&comparison);
                (c, v)
            })
            .collect();
        let within = |planner: &str| {
            labels
                .iter()
                .enumerate()
                .filter(|(i, label)| {
                    comparison
                        .rows
                        .iter()
                        .any(|r| &r.problem == *label && r.planner == planner && same_magnitude(ga[*i].1, r.mean))
                })
                .count()
        };
        let notes = vec![format!(
            "Mutation-rate reading: the GA's mean is within a factor of 10 of the paper's GA mean on {} of 6 \
             functions with pm = 1/D per bit (`ga`, the reading docs/papers/shared.md#ga prescribes) and on {} of 6 with \
             pm = 1/(D x 20) per bit (`ga-pm-per-chromosome`).",
            within("ga"),
            within(GA_PER_CHROMOSOME)
        )];
        let ranges: Vec<String> =
            problems.iter().map(|p| format!("{} [{}, {}]", p.function.id(), p.lower, p.upper)).collect();
        outcomes.push(ExperimentOutcome {
            id: id.into(),
            title: title.into(),
            setup: format!(
                "D = {DIM}, population {POPULATION}, {EVALUATIONS} evaluations per run, {} runs. Ranges: {}. \
                 PSO: w = 0.729, c1 = c2 = 1.494, V_max = range (paper). GA: binary, 20 bits per variable, roulette \
                 selection, single-point crossover pc = 0.6, bit mutation pm = 1/D per bit (the paper's pm = 1/n read \
                 per bit, docs/papers/shared.md#ga), elitism 1 (ours; the paper is silent). `ga-pm-per-chromosome` is the same GA with the other \
                 reading of pm = 1/n, 1/(D x 20) per bit (about one flip per chromosome); it is shown to measure how \
                 much the reading matters and takes no part in the claims. DE/rand/1/bin, F = 0.5, CR = 0.9 \
                 is ours, for reference only. Functions use the standard definitions (the paper prints Griewank with \
                 Rosenbrock's formula); the paper's Ackley ranges (±2.768, ±23.768) are kept although the usual one is \
                 ±32.768.",
                opts.runs,
                ranges.join(", ")
            ),
            comparison,
            paper: table(source, &labels, pso, ga),
            claims: checked,
            notes,
            tables: Vec::new(),
            scenario: None,
        });
    }
    Ok(outcomes)
}
