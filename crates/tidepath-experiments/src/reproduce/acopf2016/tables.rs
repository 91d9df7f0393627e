//! The tables of acopf2016's reproduction: per planner the median and interquartile range of
//! path length, travel time, iterations to converge and the gaps to A*'s optima, the success
//! rate, and where the paths go (wave height, western half, current band), each of ACO's cells
//! marked against ACOPF's by the two-sided rank-sum test.

use super::runs::Measure;
use super::verdicts::{of, ranked, successful};
use crate::compare::gap_percent;
use crate::stats::{rank_sum_test, smallest_p, Summary};
use crate::table::{num, ALPHA};

/// `median [q1, q3]` of the finite values, or "—".
pub fn median_iqr(v: &[f64]) -> String {
    median_iqr_with(v, num)
}

/// [`median_iqr`] with each number written by `f`.
pub fn median_iqr_with(v: &[f64], f: fn(f64) -> String) -> String {
    let finite: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
    Summary::of(&finite).map_or("—".into(), |s| format!("{} [{}, {}]", f(s.median), f(s.q1), f(s.q3)))
}

/// A gap in percent, two decimals and its sign (0.00 for rounding noise of equal values).
pub fn pct(x: f64) -> String {
    let x = if x.abs() < 5e-3 { 0.0 } else { x };
    format!("{x:+.2}")
}

/// An iteration count or its median, one decimal.
pub fn iters(x: f64) -> String {
    format!("{x:.1}")
}

/// The rank-sum test of `a` against `b` in words from `a`'s side: lower / higher (p), ≈ (p),
/// or undecidable (too few runs for any p below alpha). NaN values take no part.
pub fn versus(a: &[f64], b: &[f64]) -> String {
    let clean = |v: &[f64]| v.iter().copied().filter(|x| !x.is_nan()).collect::<Vec<_>>();
    let (a, b) = (clean(a), clean(b));
    if a.is_empty() || b.is_empty() {
        return "—".into();
    }
    let r = rank_sum_test(&a, &b);
    if r.p_value < ALPHA {
        let word = if r.u_x < (a.len() * b.len()) as f64 / 2.0 { "lower" } else { "higher" };
        format!("{word} (p = {})", num(r.p_value))
    } else if smallest_p(r.method, a.len(), b.len()) >= ALPHA {
        "undecidable".into()
    } else {
        format!("≈ (p = {})", num(r.p_value))
    }
}

/// The optima a run is measured against: A*'s travel time (s) and length (m) on the same cells.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Optima {
    pub time: Option<f64>,
    pub length: Option<f64>,
}

/// The gaps (%) of each of `values` to `optimum`: (v - v*) / v* x 100; NaN without an optimum.
pub fn gaps(values: &[f64], optimum: Option<f64>) -> Vec<f64> {
    values.iter().map(|v| optimum.map_or(f64::NAN, |o| gap_percent(*v, o))).collect()
}

/// A cell of planner `p`'s row: its values, and ACO's marked against ACOPF's on `marked`.
fn cell(p: &str, values: &[f64], marked: (&[f64], &[f64])) -> String {
    cell_with(p, values, marked, num)
}

fn cell_with(p: &str, values: &[f64], marked: (&[f64], &[f64]), f: fn(f64) -> String) -> String {
    let m = median_iqr_with(values, f);
    if p == "acopf" {
        m
    } else {
        format!("{m}; {}", versus(marked.0, marked.1))
    }
}

fn success(ms: &[Measure], p: &str) -> String {
    let n = of(ms, p).count();
    let k = of(ms, p).filter(|m| m.success).count();
    if n == 0 {
        return "—".into();
    }
    format!("{:.0} % ({k} of {n})", 100.0 * k as f64 / n as f64)
}

/// The main table of one environment: one row per planner over its runs, then A*'s optima.
pub fn runs_table(ms: &[Measure], planners: &[&str], optima: Optima, astar: &[Measure]) -> String {
    let mut t = String::from(
        "| planner | success | length (m) | gap to A* length (%) | travel time (s) | gap to A* time (%) | iterations to \
         converge |\n|---|---|---|---|---|---|---|\n",
    );
    for p in planners {
        let len = successful(ms, p, |m| m.length);
        let time = successful(ms, p, |m| m.time);
        let conv: Vec<f64> = of(ms, p).map(|m| m.converged).collect();
        let (rl, rl0) = (ranked(ms, p, |m| m.length), ranked(ms, "acopf", |m| m.length));
        let (rt, rt0) = (ranked(ms, p, |m| m.time), ranked(ms, "acopf", |m| m.time));
        let conv0: Vec<f64> = of(ms, "acopf").map(|m| m.converged).collect();
        t += &format!(
            "| {p} | {} | {} | {} | {} | {} | {} |\n",
            success(ms, p),
            cell(p, &len, (&rl, &rl0)),
            cell_with(p, &gaps(&len, optima.length), (&rl, &rl0), pct),
            cell(p, &time, (&rt, &rt0)),
            cell_with(p, &gaps(&time, optima.time), (&rt, &rt0), pct),
            cell_with(p, &conv, (&conv, &conv0), iters),
        );
    }
    for a in astar {
        let g = |v: f64, o: Option<f64>| o.map_or("—".into(), |o| pct(gap_percent(v, o)));
        t += &format!(
            "| {} | once | {} | {} | {} | {} | — |\n",
            a.planner,
            num(a.length),
            g(a.length, optima.length),
            num(a.time),
            g(a.time, optima.time)
        );
    }
    t
}

/// Where the paths go, over the successful runs: mean wave height along the path, share of
/// the length in the western half (x <= 10 cells), and with `band` the share in the current
/// band (environment 3's; elsewhere the current, if any, is no band).
pub fn where_table(ms: &[Measure], planners: &[&str], astar: &[Measure], band: bool) -> String {
    let mut t = String::from("| planner | mean wave height along the path (m) | share of length at x <= 10 cells |");
    t += if band { " share of length in the current band |\n|---|---|---|---|\n" } else { "\n|---|---|---|\n" };
    for p in planners {
        let f = |g: fn(&Measure) -> f64| (successful(ms, p, g), successful(ms, "acopf", g));
        let (w, w0) = f(|m| m.wave_mean);
        let (s, s0) = f(|m| m.west_share);
        t += &format!("| {p} | {} | {} |", cell(p, &w, (&w, &w0)), cell(p, &s, (&s, &s0)));
        if band {
            let (b, b0) = f(|m| m.band_share.unwrap_or(f64::NAN));
            t += &format!(" {} |", cell(p, &b, (&b, &b0)));
        }
        t.push('\n');
    }
    for a in astar {
        t += &format!("| {} | {} | {} |", a.planner, num(a.wave_mean), num(a.west_share));
        if band {
            t += &format!(" {} |", a.band_share.map_or("—".into(), num));
        }
        t.push('\n');
    }
    t
}

/// The legend under the tables.
pub const LEGEND: &str = "Cells: median [first quartile, third quartile] over the successful runs (iterations: \
     over the runs that found a path). ACO's cells end with the two-sided Wilcoxon rank-sum test of ACO against \
     ACOPF on that column (alpha 0.05; lower / higher = ACO's values significantly lower / higher than ACOPF's, ≈ = \
     no significant difference, undecidable = too few runs for any p below 0.05); for length, time and their gaps \
     the test ranks failed runs after every successful one. Gaps: (value - A*'s optimum) / A*'s optimum x 100, A* \
     run once on the same cells with `objective = time` (travel time) and `objective = length`.";
