//! Optimizer overhead: every optimizer in the planner registry against a bare loop over the
//! same work, 60,000 evaluations of Rastrigin in 30 dimensions (population 40). The objective
//! is the floor; the target is that no optimizer takes more than 1.5x the bare loop.
//!
//! `bare` evaluates 60,000 fixed points drawn uniformly in the Rastrigin box, through the same
//! `&dyn Objective` call the optimizers use. Start-up is excluded from both: building the
//! optimizer from the registry and drawing the bare loop's points happen outside the timed
//! part; the optimizer's `init` (its first 40 evaluations) is timed, as part of the 60,000.
//!
//! The cost of an evaluation depends on the point (libm's `cos` takes data-dependent branches,
//! and an optimizer's points are far more regular than uniform ones), so each optimizer also
//! gets `replay-ID`: the same bare loop over the 60,000 points that optimizer evaluates in the
//! timed run, recorded once beforehand. Its ratio is the optimizer's own overhead on exactly
//! its evaluation work.
//!
//! Time is the benchmark thread's CPU time (on Unix; wall time elsewhere): the machines this
//! runs on are often shared, and CPU time does not count the time other processes hold the
//! core. Every run here is single-threaded (the test functions are too cheap for rayon, see
//! `Objective::parallel_hint`), so the thread's CPU time is the whole cost.
//!
//! After the measurements the bench prints each optimizer's time over both floors (from
//! criterion's own estimates, the median) and keeps the table in
//! `target/criterion/optim_overhead/ratios.txt`.

use std::path::PathBuf;
use std::sync::Mutex;
use std::time::SystemTime;

use criterion::measurement::Measurement;
use criterion::{black_box, BatchSize, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath::optim::functions::{Function, FunctionObjective};
use tidepath::optim::{run, Objective, Scratch, StopReason, Termination};
use tidepath::planner::{build_optimizer, registry, BuildPlanner};
use tidepath::rng::run_rng;

const EVALUATIONS: u64 = 60_000;
const DIM: usize = 30;
const POPULATION: usize = 40;
const GROUP: &str = "optim_overhead";

fn objective() -> FunctionObjective {
    FunctionObjective::with_default_range(Function::Rastrigin, DIM)
}

/// The ids of every optimizer in the planner registry (pso, ga, de, ...).
fn optimizer_ids() -> Vec<&'static str> {
    registry().entries().iter().filter(|e| matches!(e.build, BuildPlanner::Optimizer(_))).map(|e| e.id).collect()
}

/// The bare loop's points: `EVALUATIONS` rows of `DIM` values, uniform in the box, fixed seed.
fn bare_points(obj: &FunctionObjective) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(2024);
    let mut points = Vec::with_capacity(EVALUATIONS as usize * DIM);
    for _ in 0..EVALUATIONS {
        for d in 0..DIM {
            let (lo, hi) = (obj.lower[d], obj.upper[d]);
            points.push(lo + rng.random::<f64>() * (hi - lo));
        }
    }
    points
}

/// Records every point evaluated, in order, around the real objective.
struct Recorder<'a> {
    inner: &'a FunctionObjective,
    points: Mutex<Vec<f64>>,
}

impl Objective for Recorder<'_> {
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn lower(&self) -> &[f64] {
        self.inner.lower()
    }
    fn upper(&self) -> &[f64] {
        self.inner.upper()
    }
    fn evaluate(&self, x: &[f64], scratch: &mut Scratch) -> f64 {
        self.points.lock().expect("recorder lock").extend_from_slice(x);
        self.inner.evaluate(x, scratch)
    }
    fn repair(&self, x: &mut [f64]) {
        self.inner.repair(x)
    }
    fn parallel_hint(&self) -> bool {
        self.inner.parallel_hint()
    }
}

fn bare_loop(obj: &dyn Objective, points: &[f64], scratch: &mut Scratch) -> f64 {
    let mut best = f64::INFINITY;
    for x in points.chunks_exact(DIM) {
        best = best.min(obj.evaluate(black_box(x), scratch));
    }
    best
}

fn bench<M: Measurement>(c: &mut Criterion<M>) {
    let obj = objective();
    assert!(!obj.parallel_hint(), "runs must be single-threaded for the thread's CPU time to be their cost");
    let budget = Termination::evaluations(EVALUATIONS);
    let mut group = c.benchmark_group(GROUP);
    group.sample_size(20);

    let points = bare_points(&obj);
    let mut scratch = Scratch::default();
    group.bench_function("bare", |b| b.iter(|| bare_loop(&obj, &points, &mut scratch)));

    for id in optimizer_ids() {
        let make = || build_optimizer(id, None, Some(POPULATION)).expect("registry optimizer builds");
        // Once outside the timing, the timed run's points: exactly the budget, same results.
        let recorder = Recorder { inner: &obj, points: Mutex::new(Vec::new()) };
        let recorded = run(make().as_mut(), &recorder, &budget, &mut run_rng(1, 0), true, &[], &mut |_| {});
        assert_eq!((recorded.evaluations, recorded.stop_reason), (EVALUATIONS, StopReason::MaxEvaluations), "{id}");
        let replay = recorder.points.into_inner().expect("recorder lock");
        assert_eq!(replay.len(), EVALUATIONS as usize * DIM, "{id}");
        let check = run(make().as_mut(), &obj, &budget, &mut run_rng(1, 0), true, &[], &mut |_| {});
        assert_eq!(check.history, recorded.history, "{id}: seeded runs differ");

        group.bench_function(id, |b| {
            b.iter_batched(
                make,
                |mut opt| run(opt.as_mut(), &obj, &budget, &mut run_rng(1, 0), true, &[], &mut |_| {}).best_cost,
                BatchSize::LargeInput,
            )
        });
        group.bench_function(format!("replay-{id}"), |b| b.iter(|| bare_loop(&obj, &replay, &mut scratch)));
    }
    group.finish();
}

/// Criterion's output folder, as criterion finds it: `CRITERION_HOME`, else `criterion` in the
/// target directory this bench was built in.
fn criterion_dir() -> PathBuf {
    match std::env::var_os("CRITERION_HOME") {
        Some(home) => PathBuf::from(home),
        None => PathBuf::from(env!("CARGO_TARGET_TMPDIR")).parent().expect("target/tmp has a parent").join("criterion"),
    }
}

/// Criterion's median estimate (ns) of benchmark `id`, if it was measured by this process.
fn median_ns(id: &str, since: SystemTime) -> Option<f64> {
    let file = criterion_dir().join(GROUP).join(id).join("new").join("estimates.json");
    let fresh = std::fs::metadata(&file).and_then(|m| m.modified()).is_ok_and(|t| t >= since);
    if !fresh {
        return None;
    }
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&file).ok()?).ok()?;
    json["median"]["point_estimate"].as_f64()
}

/// Prints and keeps each optimizer's median time over the bare loop's and over its replay's.
fn ratios(since: SystemTime) {
    let bare = median_ns("bare", since);
    let mut table = format!(
        "Rastrigin-{DIM}, {EVALUATIONS} evaluations, population {POPULATION} (criterion medians)\n\
         {:<6} {:>10}   {:>10} {:>7}   {:>10} {:>7}\n",
        "", "optimizer", "bare", "ratio", "replay", "ratio"
    );
    let ms = |t: Option<f64>| t.map_or("-".to_string(), |t| format!("{:.2} ms", t / 1e6));
    let ratio = |a: Option<f64>, b: Option<f64>| a.zip(b).map_or("-".to_string(), |(a, b)| format!("{:.2}x", a / b));
    let mut any = false;
    for id in optimizer_ids() {
        let (t, replay) = (median_ns(id, since), median_ns(&format!("replay-{id}"), since));
        any |= t.is_some();
        table += &format!(
            "{id:<6} {:>10}   {:>10} {:>7}   {:>10} {:>7}\n",
            ms(t),
            ms(bare),
            ratio(t, bare),
            ms(replay),
            ratio(t, replay)
        );
    }
    if !any {
        return; // Nothing measured in this process (a filter, or `--test`).
    }
    print!("\n{table}");
    let out = criterion_dir().join(GROUP).join("ratios.txt");
    if let Err(e) = std::fs::write(&out, &table) {
        eprintln!("could not write {}: {e}", out.display());
    }
}

/// The calling thread's CPU time, as a criterion measurement.
#[cfg(unix)]
mod cpu_time {
    use std::time::Duration;

    use criterion::measurement::{Measurement, ValueFormatter};
    use criterion::Throughput;

    pub struct ThreadCpuTime;

    fn now() -> Duration {
        let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
        // SAFETY: `t` is a valid, writable timespec; the clock id is a constant the C library
        // defines.
        let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
        assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
        Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
    }

    impl Measurement for ThreadCpuTime {
        type Intermediate = Duration;
        type Value = Duration;

        fn start(&self) -> Duration {
            now()
        }
        fn end(&self, started: Duration) -> Duration {
            now() - started
        }
        fn add(&self, a: &Duration, b: &Duration) -> Duration {
            *a + *b
        }
        fn zero(&self) -> Duration {
            Duration::ZERO
        }
        fn to_f64(&self, v: &Duration) -> f64 {
            v.as_nanos() as f64
        }
        fn formatter(&self) -> &dyn ValueFormatter {
            &CpuFormatter
        }
    }

    struct CpuFormatter;

    impl ValueFormatter for CpuFormatter {
        fn scale_values(&self, typical_ns: f64, values: &mut [f64]) -> &'static str {
            let (factor, unit) = if typical_ns < 1e3 {
                (1.0, "ns cpu")
            } else if typical_ns < 1e6 {
                (1e-3, "µs cpu")
            } else if typical_ns < 1e9 {
                (1e-6, "ms cpu")
            } else {
                (1e-9, "s cpu")
            };
            values.iter_mut().for_each(|v| *v *= factor);
            unit
        }
        fn scale_throughputs(&self, _typical: f64, throughput: &Throughput, values: &mut [f64]) -> &'static str {
            let per = match throughput {
                Throughput::Bytes(n) | Throughput::BytesDecimal(n) | Throughput::Elements(n) => *n as f64,
            };
            values.iter_mut().for_each(|v| *v = per * 1e9 / *v);
            "per cpu s"
        }
        fn scale_for_machines(&self, _values: &mut [f64]) -> &'static str {
            "ns"
        }
    }
}

fn main() {
    let since = SystemTime::now();
    #[cfg(unix)]
    let mut c = Criterion::default().with_measurement(cpu_time::ThreadCpuTime).configure_from_args();
    #[cfg(not(unix))]
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
    ratios(since);
}
