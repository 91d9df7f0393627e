//! OMPL benchmark logs (`compare --ompl-log`), so tidepath runs load into the SQLite database that
//! Planner Arena reads, beside OMPL's own planners.
//!
//! Verified with the `ompl` wheel 2.0.1 from PyPI (Python 3.11, SQLite 3.40), whose console
//! script `ompl_benchmark_statistics` parses logs in `ompl/_benchmark_statistics.py`:
//!
//! ```text
//! pip install ompl==2.0.1
//! TIDEPATH_OMPL_LOG=/tmp/tidepath_ompl.log \
//!     cargo test -p tidepath --lib experiments::ompl_log -- --ignored
//! ompl_benchmark_statistics /tmp/tidepath_ompl.log -d /tmp/tidepath_ompl.db
//! python3 crates/tidepath/tests/ompl_check_db.py /tmp/tidepath_ompl.db
//! ```
//!
//! The layout follows a log written by OMPL 2.0.1's own `Benchmark::saveResultsToFile`. What the
//! parser does, and so what this writer guards against:
//! * it keeps only the last word of the `Experiment` and `Running on` lines, so words are joined
//!   with `_` instead of being silently cut;
//! * the setup block ends at the first line starting with `|>>>` (and the parser loops forever if
//!   none comes), so such lines in the setup text are indented;
//! * every run value is followed by `"; "`, the last one included; an empty value, `nan` and
//!   `inf` become NULL, but `-inf` would be stored as text, so no non-finite number is written;
//! * it stores INTEGER columns with SQLite's numeric affinity, which turns integers beyond `i64`
//!   into lossy REALs: derived seeds use all 64 bits, so the seed is a TEXT column;
//! * `(runid, time)` is the key of the progress table, so progress times must differ in a run;
//! * it always creates the `bestPlannerConfigs` views, which fail to query without the `time`
//!   and `solved` columns;
//! * enum descriptions are stored by enum name, first log wins: the `status` enum is copied
//!   verbatim from OMPL 2.0.1 so mixed databases agree.
//!
//! And what Planner Arena needs: the progress page reads the `best_cost` column, enums are drawn
//! as bar charts only when the enum and the column share a name (`stop_reason`), and the
//! performance page shows one version at a time (tidepath's runs carry version `tidepath X.Y.Z`,
//! so they meet OMPL's runs of the same experiment on the regression page).

mod format;
#[cfg(test)]
mod tests;
mod writer;

pub use writer::write_ompl_log;

/// The experiment-level facts of an OMPL log: one log holds one experiment (one problem).
#[derive(Clone, Debug)]
pub struct OmplLogInfo<'a> {
    /// Problem name, Planner Arena's "motion planning problem"; whitespace becomes `_`.
    pub experiment: &'a str,
    /// Machine name; whitespace becomes `_`.
    pub host: &'a str,
    /// Start of the experiment (UNIX seconds), written in UTC as OMPL 2.0.1 does:
    /// `YYYY-MM-DD HH:MM:SS`.
    pub start_unix_s: u64,
    /// Free text shown by Planner Arena as the experiment's setup (scenario, budget, planner
    /// parameters): OMPL keeps per-planner settings in the same place.
    pub setup: &'a str,
    /// Optional CPU description, as OMPL's `lscpu` block.
    pub cpu_info: Option<&'a str>,
    pub master_seed: u64,
    /// The wall-time safety net (s); `None` is written as 0 because the format has no "no limit".
    pub time_limit_s: Option<f64>,
    /// Wall time of the whole experiment (s).
    pub total_time_s: f64,
}
