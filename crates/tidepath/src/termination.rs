//! When a planner stops: one type for every kind of planner (OMPL's
//! `PlannerTerminationCondition` is the model).
//!
//! A [`Termination`] combines any of: iterations (optimizers), evaluations (cost calls), node
//! expansions (graph search), samples (sampling planners), wall time, a target cost, and an
//! external stop flag the caller owns (Ctrl-C in the CLI, the Python bindings later). It is
//! checked once when built ([`Termination::check`]): a non-finite, negative or absurd value is
//! an input error naming the flag or field it came from. Each planner counts its own unit and
//! polls [`Watch::stop_reason`] inside its inner loops, so a budget is never overrun by a
//! long inner loop.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::error::{Error, Result};

/// The largest wall-time limit accepted (s): 30 days. Anything longer is a typo, and
/// `Duration` cannot hold values near 1e20 s.
pub const MAX_WALL_TIME_S: f64 = 30.0 * 24.0 * 3600.0;
/// The largest iteration, evaluation, expansion or sample count accepted: 10^12. At a
/// microsecond each this is eleven days; larger values only hide a typo.
pub const MAX_COUNT: u64 = 1_000_000_000_000;

/// Why a run stopped. Separate from what it found (the plan's status).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StopReason {
    MaxIterations,
    MaxEvaluations,
    MaxExpansions,
    MaxSamples,
    /// The wall-time limit fired: the result depends on the machine's speed.
    WallTime,
    /// The best cost reached the target cost.
    TargetCost,
    /// The caller's stop flag was raised (Ctrl-C, Python, a viewer).
    Cancelled,
    /// The planner finished on its own: a search that exhausted its space or proved its answer.
    Completed,
}

impl StopReason {
    pub fn id(self) -> &'static str {
        match self {
            StopReason::MaxIterations => "max_iterations",
            StopReason::MaxEvaluations => "max_evaluations",
            StopReason::MaxExpansions => "max_expansions",
            StopReason::MaxSamples => "max_samples",
            StopReason::WallTime => "wall_time",
            StopReason::TargetCost => "target_cost",
            StopReason::Cancelled => "cancelled",
            StopReason::Completed => "completed",
        }
    }
}

/// Limits on one planning run. Build with the setters, then [`Termination::check`].
#[derive(Clone, Debug, Default)]
pub struct Termination {
    pub max_iterations: Option<u64>,
    pub max_evaluations: Option<u64>,
    pub max_expansions: Option<u64>,
    pub max_samples: Option<u64>,
    pub wall_time: Option<Duration>,
    pub target_cost: Option<f64>,
    /// Raised by the caller to stop the run early; the run reports [`StopReason::Cancelled`].
    pub stop: Option<Arc<AtomicBool>>,
    /// When the run's one clock started. The planner layer's `solve` sets it once, so every stage
    /// of a run (reachability, rasters, the planner and its sub-searches, the smoother)
    /// measures its wall time from the same instant and no stage restarts the clock.
    pub started: Option<Instant>,
}

impl PartialEq for Termination {
    fn eq(&self, o: &Self) -> bool {
        self.max_iterations == o.max_iterations
            && self.max_evaluations == o.max_evaluations
            && self.max_expansions == o.max_expansions
            && self.max_samples == o.max_samples
            && self.wall_time == o.wall_time
            && self.target_cost == o.target_cost
    }
}

/// A count limit checked against [`MAX_COUNT`]; `field` names where the value came from.
pub fn check_count(field: &str, v: u64) -> Result<u64> {
    if v == 0 {
        return Err(Error::input(field, "must be at least 1, got 0"));
    }
    if v > MAX_COUNT {
        return Err(Error::input(field, format!("must be at most {MAX_COUNT}, got {v}")));
    }
    Ok(v)
}

/// Shortest wall-time limit: a microsecond.
pub const MIN_WALL_TIME_S: f64 = 1e-6;

/// A wall-time limit in seconds checked to be positive, finite and at most [`MAX_WALL_TIME_S`].
pub fn check_wall_time(field: &str, s: f64) -> Result<Duration> {
    if !(s > 0.0 && s.is_finite()) {
        return Err(Error::input(field, format!("must be a positive, finite number of seconds, got {s:?}")));
    }
    if s > MAX_WALL_TIME_S {
        return Err(Error::input(field, format!("must be at most {MAX_WALL_TIME_S} s (30 days), got {s:?}")));
    }
    if s < MIN_WALL_TIME_S {
        // Shorter than a microsecond rounds to no time at all on some clocks.
        return Err(Error::input(field, format!("must be at least {MIN_WALL_TIME_S:?} s (a microsecond), got {s:?}")));
    }
    Ok(Duration::from_secs_f64(s))
}

impl Termination {
    pub fn iterations(n: u64) -> Self {
        Self { max_iterations: Some(n), ..Self::default() }
    }

    pub fn evaluations(n: u64) -> Self {
        Self { max_evaluations: Some(n), ..Self::default() }
    }

    pub fn with_wall_time(mut self, d: Duration) -> Self {
        self.wall_time = Some(d);
        self
    }

    pub fn with_stop_flag(mut self, flag: Arc<AtomicBool>) -> Self {
        self.stop = Some(flag);
        self
    }

    /// True when no count limit is set: only time, target or the stop flag can end the run.
    pub fn has_count_limit(&self) -> bool {
        self.max_iterations.is_some()
            || self.max_evaluations.is_some()
            || self.max_expansions.is_some()
            || self.max_samples.is_some()
    }

    /// Rejects zero, negative, non-finite and absurd values, naming the setting.
    pub fn check(&self) -> Result<()> {
        for (name, v) in [
            ("iterations", self.max_iterations),
            ("evaluations", self.max_evaluations),
            ("expansions", self.max_expansions),
            ("samples", self.max_samples),
        ] {
            if let Some(v) = v {
                check_count(name, v)?;
            }
        }
        if let Some(d) = self.wall_time {
            check_wall_time("time_limit", d.as_secs_f64())?;
        }
        if let Some(t) = self.target_cost {
            if !t.is_finite() {
                return Err(Error::input("target_cost", format!("must be finite, got {t}")));
            }
        }
        Ok(())
    }

    /// The run's watch: on the run's clock when it has started, else on a clock starting now.
    pub fn start(&self) -> Watch<'_> {
        Watch { limits: self, started: self.started.unwrap_or_else(Instant::now) }
    }

    /// This termination with its clock started now, unless it already runs.
    pub fn started_now(&self) -> Self {
        let mut t = self.clone();
        t.started.get_or_insert_with(Instant::now);
        t
    }

    /// The instant the wall-time limit passes, on the run's clock.
    pub fn deadline(&self) -> Option<Instant> {
        let start = self.started.unwrap_or_else(Instant::now);
        self.wall_time.and_then(|d| start.checked_add(d))
    }

    /// The cheap poll every loop of a run makes: `Some` once the stop flag is raised or the
    /// deadline has passed (count limits are each planner's own to check).
    pub fn interrupted(&self) -> Option<StopReason> {
        if self.stop.as_ref().is_some_and(|f| f.load(Ordering::Relaxed)) {
            return Some(StopReason::Cancelled);
        }
        if self.deadline().is_some_and(|d| Instant::now() >= d) {
            return Some(StopReason::WallTime);
        }
        None
    }

    /// A termination for one stage of a run that may use `fraction` of the time left: the
    /// stage's deadline comes at that share of what remains, on the same clock, so a composite
    /// planner splits its budget and never restarts it. Stop flag and counts are kept.
    pub fn share_of_remaining(&self, fraction: f64) -> Self {
        let mut t = self.started_now();
        if let (Some(start), Some(limit)) = (t.started, t.wall_time) {
            let used = start.elapsed().min(limit);
            t.wall_time = Some(used + (limit - used).mul_f64(fraction.clamp(0.0, 1.0)));
        }
        t
    }

    /// The limits the search crate polls: the stop flag and the deadline, on the run's clock.
    pub fn search_limits(&self, max_expansions: Option<u64>) -> tidepath_search::Limits<'_> {
        tidepath_search::Limits { max_expansions, stop: self.stop.as_deref(), deadline: self.deadline() }
    }
}

/// Maps the search crate's stop reasons to the run's.
pub fn from_search_stop(r: tidepath_search::StopReason) -> StopReason {
    match r {
        tidepath_search::StopReason::MaxExpansions => StopReason::MaxExpansions,
        tidepath_search::StopReason::StopFlag => StopReason::Cancelled,
        tidepath_search::StopReason::Deadline => StopReason::WallTime,
    }
}

/// What a planner has used so far, in its own units.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Usage {
    pub iterations: u64,
    pub evaluations: u64,
    pub expansions: u64,
    pub samples: u64,
}

/// A running termination condition: the limits and the start time.
#[derive(Clone, Debug)]
pub struct Watch<'a> {
    pub limits: &'a Termination,
    started: Instant,
}

impl Watch<'_> {
    pub fn elapsed(&self) -> Duration {
        self.started.elapsed()
    }

    /// True once the caller raised the stop flag.
    pub fn cancelled(&self) -> bool {
        self.limits.stop.as_ref().is_some_and(|f| f.load(Ordering::Relaxed))
    }

    /// True once the wall-time limit has passed.
    pub fn timed_out(&self) -> bool {
        self.limits.wall_time.is_some_and(|t| self.started.elapsed() >= t)
    }

    /// The first limit reached by `used` with best cost `best`, or `None` to go on.
    /// Count limits are tested first so a run that ends on its count reports that, not time.
    pub fn stop_reason(&self, used: Usage, best: f64) -> Option<StopReason> {
        let l = self.limits;
        let over = |limit: Option<u64>, v: u64| limit.is_some_and(|m| v >= m);
        if over(l.max_evaluations, used.evaluations) {
            return Some(StopReason::MaxEvaluations);
        }
        if over(l.max_iterations, used.iterations) {
            return Some(StopReason::MaxIterations);
        }
        if over(l.max_expansions, used.expansions) {
            return Some(StopReason::MaxExpansions);
        }
        if over(l.max_samples, used.samples) {
            return Some(StopReason::MaxSamples);
        }
        if l.target_cost.is_some_and(|t| best <= t) {
            return Some(StopReason::TargetCost);
        }
        if self.cancelled() {
            return Some(StopReason::Cancelled);
        }
        if self.timed_out() {
            return Some(StopReason::WallTime);
        }
        None
    }

    /// Fraction of the binding limit used, in [0, 1], for progress bars.
    pub fn fraction(&self, used: Usage) -> f64 {
        let l = self.limits;
        let part = |limit: Option<u64>, v: u64| limit.map(|m| v as f64 / m.max(1) as f64);
        [
            part(l.max_iterations, used.iterations),
            part(l.max_evaluations, used.evaluations),
            part(l.max_expansions, used.expansions),
            part(l.max_samples, used.samples),
            l.wall_time.map(|t| self.elapsed().as_secs_f64() / t.as_secs_f64().max(1e-9)),
        ]
        .into_iter()
        .flatten()
        .fold(0.0, f64::max)
        .min(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn absurd_values_are_input_errors_naming_the_setting() {
        for bad in [1e20, -1.0, f64::NAN, f64::INFINITY, 0.0] {
            let e = check_wall_time("--time-limit", bad).unwrap_err().to_string();
            assert!(e.starts_with("--time-limit: must"), "{bad}: {e}");
            assert!(!e.contains('\n'));
        }
        assert_eq!(check_wall_time("t", 1.5).unwrap(), Duration::from_millis(1500));
        assert!(check_count("--iterations", 0).is_err());
        assert!(check_count("--iterations", u64::MAX).unwrap_err().to_string().contains("at most"));
        let t = Termination { target_cost: Some(f64::NAN), ..Termination::iterations(5) };
        assert!(t.check().unwrap_err().to_string().starts_with("target_cost"));
    }

    #[test]
    fn counts_before_time_and_every_limit_fires() {
        let t = Termination { max_expansions: Some(10), target_cost: Some(1.0), ..Termination::iterations(3) };
        let w = t.start();
        assert_eq!(w.stop_reason(Usage::default(), 5.0), None);
        assert_eq!(w.stop_reason(Usage { iterations: 3, ..Usage::default() }, 5.0), Some(StopReason::MaxIterations));
        assert_eq!(w.stop_reason(Usage { expansions: 10, ..Usage::default() }, 5.0), Some(StopReason::MaxExpansions));
        assert_eq!(w.stop_reason(Usage::default(), 1.0), Some(StopReason::TargetCost));
        let flag = Arc::new(AtomicBool::new(false));
        let t = Termination::default().with_stop_flag(flag.clone());
        let w = t.start();
        assert_eq!(w.stop_reason(Usage::default(), 0.0), None);
        flag.store(true, Ordering::Relaxed);
        assert_eq!(w.stop_reason(Usage::default(), 0.0), Some(StopReason::Cancelled));
        let t = Termination::default().with_wall_time(Duration::ZERO);
        assert_eq!(t.start().stop_reason(Usage::default(), 0.0), Some(StopReason::WallTime));
    }
}
