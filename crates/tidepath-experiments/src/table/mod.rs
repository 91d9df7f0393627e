//! Per-planner rows of a comparison: the statistics the papers report, computed once.

use serde::{Deserialize, Serialize};

use super::stats::{compare_to_reference, Summary};
use super::RunRecord;
use tidepath::planner::Status;

/// Significance level of the rank-sum marks (lfhh2019 uses 0.05).
pub const ALPHA: f64 = 0.05;

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PlannerRow {
    pub problem: String,
    pub planner: String,
    pub runs: usize,
    pub best: f64,
    pub mean: f64,
    pub std: f64,
    pub worst: f64,
    pub median: f64,
    /// Share of runs whose path is feasible.
    pub success_rate: f64,
    /// Means over all runs; `None` for function benchmarks.
    pub mean_length_m: Option<f64>,
    pub mean_travel_time_s: Option<f64>,
    pub mean_evaluations: f64,
    /// Timing field: mean wall time per run (s).
    pub mean_wall_s: f64,
    /// Runs whose cost is exactly 0, and below 1e-300 (amfa2015's "0 times" columns).
    pub zeros_exact: usize,
    pub zeros_tiny: usize,
    /// Two-sided Wilcoxon rank-sum test against the first planner: `+` the first planner is
    /// significantly better, `≈` no significant difference, `-` significantly worse. `None`
    /// for the first planner itself.
    pub mark: Option<String>,
    pub p_value: Option<f64>,
    /// Gap of the mean and of the best cost to the reference plan's cost, in percent.
    #[serde(default)]
    pub gap_percent: Option<f64>,
    #[serde(default)]
    pub best_gap_percent: Option<f64>,
    /// How many runs ended with each plan status, in order of severity (scenario runs only).
    #[serde(default)]
    pub statuses: Vec<(String, usize)>,
}

fn mean(xs: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = xs.fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    if n == 0 {
        f64::NAN
    } else {
        s / n as f64
    }
}

/// Rows for one problem; `planners` in report order, the first is the reference.
pub fn rows_for(problem: &str, planners: &[String], records: &[RunRecord]) -> Vec<PlannerRow> {
    let of = |p: &str| records.iter().filter(|r| r.problem == problem && r.planner == p).collect::<Vec<_>>();
    let reference: Vec<f64> = planners.first().map(|p| of(p).iter().map(|r| r.cost).collect()).unwrap_or_default();
    planners
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let runs = of(p);
            let costs: Vec<f64> = runs.iter().map(|r| r.cost).collect();
            let s = Summary::of(&costs);
            let (mark, p_value) = if i == 0 || costs.is_empty() || reference.is_empty() {
                (None, None)
            } else {
                let (m, r) = compare_to_reference(&reference, &costs, ALPHA);
                (Some(m.symbol().to_string()), Some(r.p_value))
            };
            let opt_mean = |f: &dyn Fn(&RunRecord) -> Option<f64>| {
                let v: Vec<f64> = runs.iter().filter_map(|r| f(r)).collect();
                (!v.is_empty()).then(|| mean(v.into_iter()))
            };
            PlannerRow {
                problem: problem.to_string(),
                planner: p.clone(),
                runs: runs.len(),
                best: s.as_ref().map_or(f64::NAN, |s| s.best),
                mean: s.as_ref().map_or(f64::NAN, |s| s.mean),
                std: s.as_ref().map_or(f64::NAN, |s| s.std),
                worst: s.as_ref().map_or(f64::NAN, |s| s.worst),
                median: s.as_ref().map_or(f64::NAN, |s| s.median),
                success_rate: if runs.is_empty() {
                    0.0
                } else {
                    runs.iter().filter(|r| r.feasible).count() as f64 / runs.len() as f64
                },
                mean_length_m: opt_mean(&|r| r.length_m),
                mean_travel_time_s: opt_mean(&|r| r.travel_time_s),
                mean_evaluations: mean(runs.iter().map(|r| r.evaluations as f64)),
                mean_wall_s: mean(runs.iter().map(|r| r.elapsed_s)),
                zeros_exact: costs.iter().filter(|c| **c == 0.0).count(),
                zeros_tiny: costs.iter().filter(|c| c.abs() < 1e-300).count(),
                mark,
                p_value,
                gap_percent: None,
                best_gap_percent: None,
                statuses: Status::ALL
                    .iter()
                    .map(|st| (st.id().to_string(), runs.iter().filter(|r| r.status == Some(*st)).count()))
                    .filter(|(_, n)| *n > 0)
                    .collect(),
            }
        })
        .collect()
}

/// Compact number for tables: 4 significant digits, scientific outside [1e-3, 1e5).
pub fn num(x: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-3..1e5).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.3e}")
    }
}

/// The Markdown table `compare` prints.
pub fn markdown(rows: &[PlannerRow], functions: bool) -> String {
    let reference = rows.first().map(|r| r.planner.as_str()).unwrap_or("");
    // A column for each status that occurred, in order of severity.
    let statuses: Vec<&str> = Status::ALL
        .iter()
        .map(|s| s.id())
        .filter(|id| rows.iter().any(|r| r.statuses.iter().any(|(n, c)| n == id && *c > 0)))
        .collect();
    let mut out = String::new();
    if functions {
        out.push_str(&format!(
            "| problem | planner | best | mean | std | worst | f = 0 | f < 1e-300 | evals/run | wall s/run | vs {reference} |\n"
        ));
        out.push_str("|---|---|---|---|---|---|---|---|---|---|---|\n");
    } else {
        let extra: String = statuses.iter().map(|s| format!(" {s} |")).collect();
        out.push_str(&format!(
            "| planner | best | mean | std | worst | gap % best / mean | success |{extra} length m | travel s | evals/run | wall s/run | vs {reference} |\n"
        ));
        out.push_str(&format!("|---|---|---|---|---|---|---|{}---|---|---|---|---|\n", "---|".repeat(statuses.len())));
    }
    for r in rows {
        let mark = match (&r.mark, r.p_value) {
            (Some(m), Some(p)) => format!("{m} (p={})", num(p)),
            _ => "ref".into(),
        };
        let opt = |v: Option<f64>| v.map_or("-".to_string(), num);
        if functions {
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} | {} | {} | {:.0} | {} | {} |\n",
                r.problem,
                r.planner,
                num(r.best),
                num(r.mean),
                num(r.std),
                num(r.worst),
                r.zeros_exact,
                r.zeros_tiny,
                r.mean_evaluations,
                num(r.mean_wall_s),
                mark
            ));
        } else {
            let gap = match (r.best_gap_percent, r.gap_percent) {
                (Some(b), Some(m)) => format!("{b:.2} / {m:.2}"),
                _ => "-".to_string(),
            };
            let counts: String = statuses
                .iter()
                .map(|s| format!(" {} |", r.statuses.iter().find(|(n, _)| n == s).map_or(0, |(_, c)| *c)))
                .collect();
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} | {gap} | {:.0}% |{counts} {} | {} | {:.0} | {} | {} |\n",
                r.planner,
                num(r.best),
                num(r.mean),
                num(r.std),
                num(r.worst),
                100.0 * r.success_rate,
                opt(r.mean_length_m),
                opt(r.mean_travel_time_s),
                r.mean_evaluations,
                num(r.mean_wall_s),
                mark
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_four_significant_digits() {
        assert_eq!(num(1.23456), "1.235");
        assert_eq!(num(123.456), "123.5");
        assert_eq!(num(0.0), "0");
        assert_eq!(num(1.5e-7), "1.500e-7");
        assert_eq!(num(2.5e6), "2.500e6");
    }
}
