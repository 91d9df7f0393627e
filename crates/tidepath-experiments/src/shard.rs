//! Cluster job arrays: `compare --shard K/N` runs the K-th of N shares of a comparison's runs,
//! and [`merge`] joins the shares into the comparison one `compare` would have made.
//!
//! The runs are enumerated in their canonical order ([`crate::runner::tasks`]: problem, then
//! planner, then run index) and run i (0-based) belongs to share (i mod N) + 1: round robin, so
//! every share gets a mix of planners and about the same work. A run keeps the seed it has in
//! an unsharded compare (derived from the master seed and its labels, not from its share), so
//! the joined records are the ones a single compare computes, bit for bit; only timing fields
//! differ. Share 1 also runs the reference planner, once, as a single compare does.
//!
//! A shard writes only `results.json` ([`ShardFile`]): the [`Comparison`] of its share's runs
//! with a `shard` block ([`ShardInfo`]) holding its share and what [`merge`] checks beyond the
//! comparison's own settings. Its tables and figures would describe a part of the runs, so it
//! writes none; `merge` writes them all, through the same output code as `compare`.

use serde::{Deserialize, Serialize};

use super::compare::{comparison_of, set_reference, Comparison};
use super::runner::tasks;
use super::RunRecord;
use tidepath::error::{Error, Result};
use tidepath::rng::derive_seed;
use tidepath_io::scenario::Scenario;

/// The K-th of N shares of an experiment's runs (1 <= K <= N).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Share {
    pub k: u64,
    pub n: u64,
}

impl Share {
    /// Parses `--shard K/N`.
    pub fn parse(text: &str) -> Result<Self> {
        let bad = |why: &str| Error::input("--shard", format!("'{text}' {why}"));
        let (k, n) = text.split_once('/').ok_or_else(|| bad("is not K/N (e.g. 2/8)"))?;
        let number =
            |s: &str| s.trim().parse::<u64>().map_err(|_| bad("is not K/N with whole numbers K and N (e.g. 2/8)"));
        let (k, n) = (number(k)?, number(n)?);
        if n == 0 || k == 0 || k > n {
            return Err(bad("must have 1 <= K <= N"));
        }
        Ok(Self { k, n })
    }

    /// Whether run `index` (0-based, canonical order) is in this share.
    pub fn owns(&self, index: usize) -> bool {
        index as u64 % self.n + 1 == self.k
    }

    /// How many of `total` runs are in this share.
    pub fn size(&self, total: usize) -> usize {
        (total as u64 + self.n - self.k) as usize / self.n as usize
    }

    /// The items of this share, in their order.
    pub fn select<T>(&self, items: Vec<T>) -> Vec<T> {
        items.into_iter().enumerate().filter(|(i, _)| self.owns(*i)).map(|(_, t)| t).collect()
    }
}

impl std::fmt::Display for Share {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}

/// The `shard` block of a shard's `results.json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ShardInfo {
    pub k: u64,
    pub n: u64,
    /// Runs in this share, finished or not.
    pub share_runs: usize,
    /// The scenario, for `merge` to draw the paths figure: `builtin:NAME` or the file's path.
    pub scenario: String,
    /// Fingerprint of the scenario as loaded (its TOML's content, 16 hex digits).
    pub scenario_hash: String,
    /// Fingerprint of the encoding the runs used (the scenario's, with `--repair`).
    pub encoding_hash: String,
}

impl ShardInfo {
    /// The block of `share` of a comparison of `c.planned_runs()` runs on `scenario`.
    pub fn new(share: Share, c: &Comparison, scenario: &Scenario) -> Self {
        Self {
            k: share.k,
            n: share.n,
            share_runs: share.size(c.planned_runs()),
            scenario: scenario.source.clone(),
            scenario_hash: fingerprint(&scenario.spec),
            encoding_hash: fingerprint(&scenario.encoding),
        }
    }

    pub fn share(&self) -> Share {
        Share { k: self.k, n: self.n }
    }

    /// The argument `scenario::load` takes to load the scenario again.
    pub fn scenario_argument(&self) -> &str {
        self.scenario.strip_prefix("builtin:").unwrap_or(&self.scenario)
    }

    /// Refuses `scenario` (loaded from `shown`, named by `field`) unless it is the one the
    /// shards ran.
    pub fn check_scenario(&self, scenario: &Scenario, field: &str, shown: &str) -> Result<()> {
        let hash = fingerprint(&scenario.spec);
        if hash != self.scenario_hash {
            return Err(Error::input(
                field,
                format!(
                    "'{shown}' is not the scenario the shards ran (fingerprint {hash}, theirs {})",
                    self.scenario_hash
                ),
            ));
        }
        Ok(())
    }
}

/// A stable fingerprint of `value`'s JSON form: 16 hex digits.
pub fn fingerprint<T: Serialize>(value: &T) -> String {
    let json = serde_json::to_string(value).expect("settings serialise");
    format!("{:016x}", derive_seed(0, &[&json]))
}

/// A shard's `results.json`: its comparison, and the `shard` block (`None` when the file is a
/// whole comparison's).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ShardFile {
    #[serde(flatten)]
    pub comparison: Comparison,
    #[serde(default)]
    pub shard: Option<ShardInfo>,
}

impl ShardFile {
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).expect("comparison serialises") + "\n"
    }
}

/// One shard's `results.json`, and where it was read from (for messages).
pub struct ShardResults {
    pub dir: String,
    pub file: ShardFile,
}

impl ShardResults {
    fn info(&self) -> Result<&ShardInfo> {
        self.file.shard.as_ref().ok_or_else(|| {
            Error::input("DIR", format!("'{}' holds no shard (its results.json has no `shard` block)", self.dir))
        })
    }

    /// `shard K/N ('DIR')`, for messages.
    fn name(&self) -> String {
        let share = self.file.shard.as_ref().map_or("?".into(), |s| s.share().to_string());
        format!("shard {share} ('{}')", self.dir)
    }
}

/// The settings every shard of one compare shares, each named for messages.
fn settings(c: &Comparison, s: &ShardInfo) -> [(&'static str, String); 11] {
    let smoother = c.smoother.as_ref().map_or("none".into(), |s| s.describe());
    [
        ("the shard count N", s.n.to_string()),
        ("tidepath version", c.tidepath_version.clone()),
        ("kind", c.kind.clone()),
        ("scenario (fingerprint)", s.scenario_hash.clone()),
        ("encoding (fingerprint; --repair)", s.encoding_hash.clone()),
        ("planners", c.planners.join(",")),
        ("runs", c.runs.to_string()),
        ("master seed", c.master_seed.to_string()),
        ("budget", c.budget.describe()),
        ("reference", c.reference_planner.clone().unwrap_or("none".into())),
        ("smoother", smoother),
    ]
}

/// Joins the shards of one compare: every setting equal, every share present once and
/// complete, each holding exactly its runs. Returns the comparison a single compare makes
/// (no `shard` block; its wall time the sum of the shards') and the shards' common block.
pub fn merge(shards: &[ShardResults]) -> Result<(Comparison, ShardInfo)> {
    let first = shards.first().ok_or_else(|| Error::input("DIR", "name at least one shard's folder"))?;
    let info = first.info()?;
    let ours = env!("CARGO_PKG_VERSION");
    if first.file.comparison.tidepath_version != ours {
        let v = &first.file.comparison.tidepath_version;
        return Err(Error::input("DIR", format!("{} was written by tidepath {v}; this is {ours}", first.name())));
    }
    let expected = settings(&first.file.comparison, info);
    for s in &shards[1..] {
        for ((what, a), (_, b)) in expected.iter().zip(settings(&s.file.comparison, s.info()?)) {
            if *a != b {
                return Err(Error::input(
                    "DIR",
                    format!("{} differs in {what}: {b}; {} has {a}", s.name(), first.name()),
                ));
            }
        }
    }
    // Each share exactly once.
    let n = info.n as usize;
    let mut by_share: Vec<Option<&ShardResults>> = vec![None; n];
    for s in shards {
        let k = s.info()?.k as usize;
        if k == 0 || k > n {
            return Err(Error::input("DIR", format!("{} is not a share of {n}", s.name())));
        }
        if let Some(other) = by_share[k - 1] {
            return Err(Error::input("DIR", format!("shard {k}/{n} is given twice: '{}' and '{}'", other.dir, s.dir)));
        }
        by_share[k - 1] = Some(s);
    }
    let mut parts = Vec::with_capacity(n);
    for (i, s) in by_share.into_iter().enumerate() {
        let s = s.ok_or_else(|| Error::input("DIR", format!("shard {}/{n} is missing", i + 1)))?;
        let c = &s.file.comparison;
        if !c.complete {
            let why =
                format!("is incomplete ({} of {} runs finished); run it again", c.finished_runs, s.info()?.share_runs);
            return Err(Error::input("DIR", format!("{} {why}", s.name())));
        }
        parts.push(s);
    }
    let c = &first.file.comparison;
    let records = interleave(c, &parts)?;
    let planned = records.len();
    let total_wall_s = parts.iter().map(|s| s.file.comparison.total_wall_s).sum();
    let budget = c.budget.clone();
    let mut merged = comparison_of(
        &c.kind,
        c.problems.clone(),
        &c.planners,
        (c.runs, c.master_seed),
        budget,
        records,
        planned,
        total_wall_s,
    );
    merged.smoother = c.smoother.clone();
    merged.reference_planner = c.reference_planner.clone();
    set_reference(&mut merged, parts[0].file.comparison.reference.clone());
    Ok((merged, info.clone()))
}

/// Every run in canonical order, run i taken from share (i mod N) + 1, which must hold exactly
/// its runs, in order.
fn interleave(c: &Comparison, parts: &[&ShardResults]) -> Result<Vec<RunRecord>> {
    let all = tasks(c.master_seed, &c.problems, &c.planners, c.runs);
    let mut next: Vec<_> = parts.iter().map(|s| s.file.comparison.records.iter()).collect();
    let mut records = Vec::with_capacity(all.len());
    for (i, t) in all.iter().enumerate() {
        let s = i % parts.len();
        let want = format!("run {} of {} on {} (seed {})", t.run, t.planner, t.problem, t.seed);
        let r = next[s].next().ok_or_else(|| Error::input("DIR", format!("{} lacks {want}", parts[s].name())))?;
        if (&r.problem, &r.planner, r.run, r.seed) != (&t.problem, &t.planner, t.run, t.seed) {
            let got = format!("run {} of {} on {} (seed {})", r.run, r.planner, r.problem, r.seed);
            return Err(Error::input("DIR", format!("{} has {got} where {want} belongs", parts[s].name())));
        }
        records.push(r.clone());
    }
    for (s, rest) in parts.iter().zip(&mut next) {
        if rest.next().is_some() {
            return Err(Error::input("DIR", format!("{} has more runs than its share", s.name())));
        }
    }
    Ok(records)
}

#[cfg(test)]
mod tests;
