//! One of acopf2016's environments at the paper's setting (the ants deposit Q/L, L the path
//! length, eqs. 6 and 11-13): ACOPF and ACO over `--runs` runs, A*'s time and length optima on
//! the same cells, the tables, the claims, and (part `figures`) the plan view of the best
//! paths over the wave-height map with the current.

use super::super::{ExperimentOutcome, PaperTable, ReproduceOptions};
use super::paper::{Environment, CURRENT_ENV, ENVIRONMENTS, PAPER_OBJECTIVE, PLANNERS, TWO_OPTIMA_ENV, WAVES_ENV};
use super::runs::{ants, astar_optimum, budget, measure_reference, measures, run_setting, Measure, Optimum};
use super::tables::{median_iqr, runs_table, where_table, Optima, LEGEND};
use super::verdicts::{converges_faster, follows_waves, quicker, shorter, successful, two_optima, uses_current};
use crate::compare::{gap_percent, run_reference, Comparison, Reference, RunBudget};
use crate::table::num;
use tidepath::error::Result;
use tidepath_io::scenario::Scenario;

/// The reference's name in the report and on the plan view: A* run for the quickest path.
pub const TIME_REFERENCE: &str = "astar, objective = time";

/// A*'s optima on `scenario` (travel time, length).
pub fn optima_of(scenario: &Scenario, opts: &ReproduceOptions) -> Result<(Option<Optimum>, Option<Optimum>)> {
    Ok((astar_optimum(scenario, "time", opts)?, astar_optimum(scenario, "length", opts)?))
}

/// The gap column of the main table: against A*'s time optimum by default, or the planner
/// `--reference` names (`none`: no column).
pub fn set_reference(
    c: &mut Comparison,
    scenario: &Scenario,
    time_optimum: Option<&Optimum>,
    opts: &ReproduceOptions,
) -> Result<()> {
    let reference = match opts.reference.as_deref() {
        Some("none") => None,
        None | Some("astar") => {
            time_optimum.map(|o| Reference { planner: TIME_REFERENCE.into(), ..o.reference.clone() })
        }
        Some(id) => run_reference(scenario, id, opts.master_seed, &RunBudget::default(), opts.stop.clone())?,
    };
    c.reference_planner = reference.as_ref().map(|r| r.planner.clone());
    if let Some(r) = &reference {
        for row in &mut c.rows {
            row.gap_percent = row.feasible_mean.map(|m| gap_percent(m, r.cost));
            row.best_gap_percent = row.feasible_best.map(|b| gap_percent(b, r.cost));
        }
    }
    c.reference = reference;
    Ok(())
}

/// A*'s rows of the tables: its time-optimal and length-optimal paths.
pub fn astar_rows(scenario: &Scenario, time: Option<&Optimum>, length: Option<&Optimum>) -> Vec<Measure> {
    [(time, "time"), (length, "length")]
        .into_iter()
        .filter_map(|(o, objective)| o.map(|o| measure_reference(&o.reference, &o.label(objective), &scenario.world)))
        .collect()
}

pub fn experiment(
    index: usize,
    opts: &ReproduceOptions,
    figures: bool,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<ExperimentOutcome> {
    let env: &Environment = &ENVIRONMENTS[index];
    let scenario = tidepath_io::scenario::load(env.scenario)?;
    let budget = budget(opts);
    let mut c = run_setting(std::slice::from_ref(&scenario), PAPER_OBJECTIVE, &budget, opts, progress)?;
    let (time, length) = if c.complete { optima_of(&scenario, opts)? } else { (None, None) };
    set_reference(&mut c, &scenario, time.as_ref(), opts)?;
    let problem = scenario.name.clone();
    let ms = measures(&c, &problem, &scenario.world);
    let astar = astar_rows(&scenario, time.as_ref(), length.as_ref());
    let optima = Optima {
        time: time.as_ref().and_then(|o| o.reference.travel_time_s),
        length: length.as_ref().and_then(|o| o.reference.length_m),
    };

    let mut claims = vec![converges_faster(&problem, &ms), shorter(&problem, &ms), quicker(&problem, &ms)];
    let mut notes = Vec::new();
    if index == TWO_OPTIMA_ENV {
        notes.push(two_optima(&ms, optima.length).note());
    }
    let astar_of = |prefix: &str, f: fn(&Measure) -> f64| {
        astar.iter().find(|a| a.planner.starts_with(prefix)).map_or("—".into(), |a| num(f(a)))
    };
    if index == WAVES_ENV {
        claims.push(follows_waves(&problem, &ms));
        let w = |p: &str| median_iqr(&successful(&ms, p, |m| m.wave_mean));
        let s = |p: &str| median_iqr(&successful(&ms, p, |m| m.west_share));
        notes.push(format!(
            "Waves along the path (claim 5), medians [IQR] over the successful runs: ACOPF {} m, ACO {} m; A*'s \
             shortest path {} m, A*'s quickest path {} m. Share of the length at x <= 10 cells: ACOPF {}, ACO {}; \
             A*'s shortest path {}, A*'s quickest path {}.",
            w("acopf"),
            w("aco"),
            astar_of("astar, objective = length", |a| a.wave_mean),
            astar_of("astar, objective = time", |a| a.wave_mean),
            s("acopf"),
            s("aco"),
            astar_of("astar, objective = length", |a| a.west_share),
            astar_of("astar, objective = time", |a| a.west_share),
        ));
    }
    if index == CURRENT_ENV {
        claims.push(uses_current(&problem, &ms));
        let b = |p: &str| median_iqr(&successful(&ms, p, |m| m.band_share.unwrap_or(f64::NAN)));
        let a = |prefix: &str| astar_of(prefix, |a| a.band_share.unwrap_or(f64::NAN));
        notes.push(format!(
            "Share of the path length inside the current band (claim 6), medians [IQR] over the successful runs: \
             ACOPF {}, ACO {}; A*'s quickest path {}, A*'s shortest path {}.",
            b("acopf"),
            b("aco"),
            a("astar, objective = time"),
            a("astar, objective = length"),
        ));
    }
    for (o, what) in [(&time, "quickest"), (&length, "shortest")] {
        if let Some(o) = o {
            notes.push(format!(
                "A*'s {what} path on the same cells: {} s over {} m (A*: \"{}\"){}.",
                o.reference.travel_time_s.map_or("—".into(), num),
                o.reference.length_m.map_or("—".into(), num),
                o.reason,
                if what == "quickest" {
                    "; the gap column of the first table and the plan view's reference are this path"
                } else {
                    ""
                }
            ));
        }
    }
    notes.push(
        "The convergence figure plots each run's history: the scenario's cost (the glider's travel time, as \
         every planner reports it) of the ants' best tour after each iteration, the tour being the shortest \
         found (the ants reward length here). The iterations-to-converge column is the iteration at which \
         that tour was first found."
            .to_string(),
    );
    let tables = vec![
        (
            format!("Runs at the paper's setting (objective = length), beside A*'s optima\n\n{LEGEND}"),
            runs_table(&ms, &PLANNERS, optima, &astar),
        ),
        ("Where the paths go".to_string(), where_table(&ms, &PLANNERS, &astar, index == CURRENT_ENV)),
    ];
    Ok(ExperimentOutcome {
        id: env.id.into(),
        title: format!("{} (`{}`)", env.title, env.scenario),
        setup: format!(
            "The built-in scenario `{}`: {}. Start cell 1, goal cell 400 (eq. 3). ACOPF (eqs. 7-13) and ACO (eqs. \
             4-6 and 9), both with the ants depositing Q/L for the path length L (the paper's setting, \
             `objective = length`), T = {} iterations of K = {} ants{}, rho = 0.85, Q = 6, a = 0.3, b = 0.7, the \
             constants the paper leaves open as in docs/papers/acopf2016.md A7; {} runs per planner. The glider's \
             travel time comes from the plan's evaluation (speed 0.1623 H + 0.266 c cos theta, at least 0.05 m/s, on \
             every piece). A run succeeds when it reaches the goal on a feasible path. Iterations to converge: the \
             iteration at which the run's final best was first found, read from its progress history.",
            env.scenario,
            env.setup,
            budget.iterations.unwrap_or(0),
            ants(opts),
            if opts.quick { " (--quick: fewer than the paper's T = 60, K = 30)" } else { "" },
            opts.runs,
        ),
        comparison: c,
        paper: PaperTable { source: env.figure.into(), runs: None, cells: Vec::new() },
        claims,
        notes,
        tables,
        scenario: figures.then_some(scenario),
    })
}
