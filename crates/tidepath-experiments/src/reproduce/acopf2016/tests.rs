use super::paper::{ENVIRONMENTS, PAPER_OBJECTIVE};
use super::runs::{along_path, budget, converged_at, run_setting, Measure};
use super::tables::{gaps, median_iqr, versus};
use super::verdicts::{converges_faster, follows_waves, quicker, shorter, two_optima, uses_current, Word};
use crate::output::FigureRenderer;
use crate::reproduce::{check_only, paper, reproduce, ClaimVerdict, ReproduceOptions};
use tidepath::geom::{Aabb, Vec3};
use tidepath::world::{Current, Waves, World};
use tidepath_io::Outputs;

fn opts(runs: u64, jobs: usize) -> ReproduceOptions {
    ReproduceOptions {
        runs,
        master_seed: 7,
        jobs,
        reference: None,
        stop: None,
        time_limit_s: None,
        quick: true,
        only: Vec::new(),
    }
}

/// Stands in for the plotting layer: one SVG per figure it is asked for, naming what it drew.
struct Sketch;

impl FigureRenderer for Sketch {
    fn names(&self, scenario: bool) -> Vec<&'static str> {
        if scenario {
            vec!["paths.svg"]
        } else {
            Vec::new()
        }
    }

    fn render(
        &self,
        c: &crate::compare::Comparison,
        scenario: Option<&tidepath_io::scenario::Scenario>,
    ) -> tidepath::error::Result<Vec<(String, String)>> {
        Ok(scenario
            .map(|s| {
                let reference = c.reference.as_ref().map_or("none", |r| r.planner.as_str());
                vec![("paths.svg".to_string(), format!("<svg>{} {} {reference}</svg>", s.name, c.planners.join(" ")))]
            })
            .unwrap_or_default())
    }
}

/// `--quick` at two runs end to end: REPORT.md with every environment, the claims and the
/// tables, each experiment's results.json, and a plan view per environment (not for the
/// objective = cost variant) with A*'s quickest path as its reference.
#[test]
fn a_quick_run_writes_the_report_the_results_and_the_figures() {
    let dir = tempfile::tempdir().unwrap();
    let mut out = Outputs::new();
    let p = paper("acopf2016").unwrap();
    let outcomes = reproduce(&p, &opts(2, 2), &mut out, dir.path(), &|_, _| {}, &Sketch).unwrap();
    out.commit().unwrap();
    assert_eq!(outcomes.len(), ENVIRONMENTS.len() + 2);
    let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
    for needle in [
        "## Fig. 3: environment 1, fixed wave height, no current (`glider-1`)",
        "## Fig. 5: environment 3, falling waves and a south-east current band (`glider-3`)",
        "### Runs at the paper's setting (objective = length), beside A*'s optima",
        "| planner | success | length (m) | gap to A* length (%) | travel time (s) | gap to A* time (%) |",
        "| astar, objective = time (optimal on the cells) | once |",
        "| astar, objective = length (optimal on the cells) | once |",
        "In environment 1 there are two optimal paths of equal length (section 4, Fig. 3): **",
        "- ACOPF converges faster than ACO",
        "- ACOPF's paths follow the larger waves",
        "- ACOPF's paths use the current",
        "### Travel time when the ants reward it",
        "![best path of each planner](fig4-glider-2/paths.svg)",
        "### Gap to the optimum on a forecast",
        "| acopf | length | 2 of 2 |",
        "| aco | cost |",
        "A*'s quickest path on the same cells:",
    ] {
        assert!(md.contains(needle), "{needle} missing from\n{md}");
    }
    for e in &ENVIRONMENTS {
        let json = std::fs::read_to_string(dir.path().join(e.id).join("results.json")).unwrap();
        assert!(json.contains("\"acopf\"") && json.contains("\"aco\""), "{}", e.id);
        let svg = std::fs::read_to_string(dir.path().join(e.id).join("paths.svg")).unwrap();
        assert_eq!(svg, format!("<svg>{} acopf aco astar, objective = time</svg>", e.scenario));
    }
    assert!(dir.path().join("objective-cost/results.json").exists());
    assert!(!dir.path().join("objective-cost/paths.svg").exists());
    // Three claims in every environment, one more in environments 2 and 3.
    let claims: Vec<usize> = outcomes.iter().map(|o| o.claims.len()).collect();
    assert_eq!(claims, [3, 4, 4, 3, 0, 0]);
    assert!(dir.path().join("ocean-glider-ocean/results.json").exists());
    assert!(check_only("acopf2016", &["maps".to_string()]).is_err());
}

/// The same runs with one job and with two: identical records but for the wall times.
#[test]
fn runs_do_not_depend_on_the_number_of_jobs() {
    let s = tidepath_io::scenario::load("glider-3").unwrap();
    let run = |jobs| {
        let o = opts(2, jobs);
        let mut c = run_setting(std::slice::from_ref(&s), PAPER_OBJECTIVE, &budget(&o), &o, &|_| {}).unwrap();
        for r in &mut c.records {
            r.elapsed_s = 0.0;
        }
        c.records
    };
    let one = run(1);
    assert_eq!(one.len(), 4);
    assert_eq!(one, run(2));
}

/// A successful run of `planner` with [length, time, iterations to converge, wave height,
/// band share].
fn m(planner: &str, run: u64, v: [f64; 5]) -> Measure {
    Measure {
        planner: planner.into(),
        run,
        success: true,
        length: v[0],
        time: v[1],
        converged: v[2],
        wave_mean: v[3],
        west_share: 0.5,
        band_share: Some(v[4]),
        key: vec![[run as i64, 0]],
    }
}

/// Five runs each: ACOPF better on every measure, then the same data the other way round.
fn synthetic(acopf_better: bool) -> Vec<Measure> {
    let (good, bad) = if acopf_better { ("acopf", "aco") } else { ("aco", "acopf") };
    let mut v = Vec::new();
    for i in 0..5 {
        let x = i as f64;
        v.push(m(good, i, [28.0 + x, 90.0 + x, 5.0 + x, 2.0 - 0.01 * x, 0.4 + 0.01 * x]));
    }
    for i in 0..5 {
        let x = i as f64;
        v.push(m(bad, i, [35.0 + x, 120.0 + x, 40.0 + x, 1.0 - 0.01 * x, 0.1 + 0.01 * x]));
    }
    v
}

/// Every two-sample verdict follows the data: reproduced when ACOPF's runs are better,
/// contradicted when the same values are swapped, undecidable with two runs each.
#[test]
fn verdicts_change_with_the_data() {
    type Judge = fn(&str, &[Measure]) -> (crate::reproduce::Claim, ClaimVerdict);
    let judges: [Judge; 5] = [converges_faster, shorter, quicker, follows_waves, uses_current];
    let p = 2.0 / 252.0;
    for judge in judges {
        assert_eq!(judge("e", &synthetic(true)).1, ClaimVerdict::Reproduced { p });
        assert_eq!(judge("e", &synthetic(false)).1, ClaimVerdict::Contradicted { p });
    }
    let few: Vec<Measure> = synthetic(true).into_iter().filter(|m| m.run < 2).collect();
    assert!(matches!(shorter("e", &few).1, ClaimVerdict::Undecidable { .. }));
    // A failed ACOPF run ranks after every ACO path: two of five failing ties the test.
    let mut failing = synthetic(true);
    for x in failing.iter_mut().filter(|m| m.planner == "acopf" && m.run < 3) {
        x.success = false;
    }
    assert!(matches!(shorter("e", &failing).1, ClaimVerdict::Inconclusive { .. }));
}

/// Claim 4 counts ACOPF's distinct paths of A*'s optimal length: two or more reproduce it,
/// one partly, none (or no optimum) not.
#[test]
fn two_optima_counts_distinct_optimal_paths() {
    let mut v = synthetic(true);
    // ACOPF's lengths are 28..32: runs 0 and 1 at 28 on two different paths.
    v[1].length = 28.0;
    let r = two_optima(&v, Some(28.0));
    assert_eq!((r.at_optimum, r.distinct, r.runs, r.verdict), (2, 2, 5, Word::Reproduced));
    assert!(r.note().contains("**reproduced**") && r.note().contains("2 of its 5 runs"), "{}", r.note());
    v[1].key = v[0].key.clone();
    assert_eq!(two_optima(&v, Some(28.0)).verdict, Word::Partly);
    assert_eq!(two_optima(&v, Some(27.0)).verdict, Word::NotReproduced);
    assert_eq!(two_optima(&v, None).verdict, Word::NotReproduced);
    // A failed run on an optimal-length path does not count.
    v[1].success = false;
    assert_eq!(two_optima(&v, Some(28.0)).at_optimum, 1);
}

/// Gaps by hand: 110 against 100 is +10 %, 99 is -1 %; no optimum, no gap. And on
/// environment 1 (one wave height, no current: one speed everywhere) A*'s quickest path is a
/// shortest one, so T* = L* / v with v = 0.1623 H.
#[test]
fn gaps_are_against_astars_optimum() {
    let g = gaps(&[110.0, 99.0], Some(100.0));
    assert!((g[0] - 10.0).abs() < 1e-12 && (g[1] + 1.0).abs() < 1e-12, "{g:?}");
    assert!(gaps(&[1.0], None)[0].is_nan());
    let s = tidepath_io::scenario::load("glider-1").unwrap();
    let o = opts(2, 1);
    let (time, length) = super::environment::optima_of(&s, &o).unwrap();
    let (time, length) = (time.unwrap(), length.unwrap());
    assert!(time.optimal && length.optimal, "{} / {}", time.reason, length.reason);
    let (time, length) = (time.reference, length.reference);
    let h = s.world.waves.height(s.start, 0.0);
    let v = (0.1623 * h).max(0.05);
    let (t, l) = (time.travel_time_s.unwrap(), length.length_m.unwrap());
    assert!((t - l / v).abs() <= 1e-6 * t, "T* {t}, L* {l}, v {v}");
    assert!((time.length_m.unwrap() - l).abs() <= 1e-9 * l);
}

/// The iteration of convergence: the first entry equal to the last, counted from 1, or from 0
/// when the history starts with the initial best.
#[test]
fn convergence_is_read_from_the_history() {
    let h = [None, Some(30.0), Some(28.0), Some(28.0), Some(28.0)];
    assert_eq!(converged_at(&h, 5), Some(3));
    assert_eq!(converged_at(&h, 4), Some(2));
    assert_eq!(converged_at(&[None, None], 2), None);
    assert_eq!(converged_at(&[Some(5.0)], 1), Some(1));
}

/// Shares along a path by hand: a straight line from x = 0 to x = 20 over a 20 m wide world
/// lies half in the western half; uniform waves are their own mean; a current everywhere puts
/// the whole path in the band, no current gives no band.
#[test]
fn along_path_weighs_by_length() {
    let mut world = World::open(Aabb::new(Vec3::new(0.0, 0.0, -1.0), Vec3::new(20.0, 20.0, 1.0)));
    world.waves = Waves::Uniform(1.5);
    let path = [Vec3::new(0.0, 5.0, 0.0), Vec3::new(20.0, 5.0, 0.0)];
    let a = along_path(&path, &world);
    assert_eq!((a.wave_mean, a.band_share), (1.5, None));
    assert!((a.west_share - 0.5).abs() < 1e-12, "{a:?}");
    world.current = Current::Uniform(Vec3::new(0.3, -0.3, 0.0));
    assert_eq!(along_path(&path, &world).band_share, Some(1.0));
    assert_eq!(median_iqr(&[1.0, 2.0, 3.0, 4.0, 5.0, f64::INFINITY]), "3.000 [2.000, 4.000]");
    assert_eq!(versus(&[1.0, 2.0, 3.0, 4.0, 5.0], &[6.0, 7.0, 8.0, 9.0, 10.0]), "lower (p = 0.007937)");
}
