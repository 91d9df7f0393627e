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
//! The estimation-of-distribution planners (`fhh`, `fhh-lts`, `lfhh`, `eda-g`) run here with
//! their elite clamped to the population (S = binNum = 40 instead of lfhh2019's 100 of 200):
//! per generation they sort every variable's elite, so their overhead over a replay of
//! converged points (which libm's `cos` evaluates quickly) is larger than the other optimizers'.
//!
//! Time is the benchmark thread's CPU time (on Unix; wall time elsewhere): the machines this
//! runs on are often shared, and CPU time does not count the time other processes hold the
//! core. Every run here is single-threaded (the test functions are too cheap for rayon, see
//! `Objective::parallel_hint`), so the thread's CPU time is the whole cost.
//!
//! After criterion's measurements (each benchmark's own statistics), the ratios come from
//! paired rounds: the bare loop, then each optimizer next to its replay, 21 times over, so a
//! change in the machine's load hits both sides of a ratio alike (ratios of medians measured
//! minutes apart do not have that). The bench prints each optimizer's median ratio with its
//! quartiles over both floors and keeps the table in `target/criterion/optim_overhead/ratios.txt`.
//!
//! `OPTIM_OVERHEAD_IDS=js,qpso cargo bench -p tidepath --bench optim_overhead` measures only
//! the listed optimizers (and the bare loop); the table then holds only them.

use std::path::PathBuf;
use std::sync::Mutex;
use std::time::SystemTime;

use criterion::measurement::Measurement;
use criterion::{black_box, BatchSize, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath::optim::functions::{Function, FunctionObjective};
use tidepath::optim::{run, Objective, Optimizer, Scratch, StopReason, Termination};
use tidepath::planner::{build_optimizer, registry};
use tidepath::rng::run_rng;

const EVALUATIONS: u64 = 60_000;
const DIM: usize = 30;
const POPULATION: usize = 40;
const GROUP: &str = "optim_overhead";

fn objective() -> FunctionObjective {
    FunctionObjective::with_default_range(Function::Rastrigin, DIM)
}

/// The ids of every optimizer in the planner registry (pso, ga, de, ...), or of those listed
/// in `OPTIM_OVERHEAD_IDS` (comma-separated).
fn optimizer_ids() -> Vec<&'static str> {
    let only = std::env::var("OPTIM_OVERHEAD_IDS").ok();
    let listed = |id: &str| only.as_deref().is_none_or(|l| l.split(',').any(|x| x.trim() == id));
    registry().entries().iter().filter(|e| e.build.is_optimizer() && listed(e.id)).map(|e| e.id).collect()
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

fn make(id: &str) -> Box<dyn Optimizer> {
    build_optimizer(id, None, Some(POPULATION)).expect("registry optimizer builds")
}

fn run_once(opt: &mut dyn Optimizer, obj: &dyn Objective) -> f64 {
    run(opt, obj, &Termination::evaluations(EVALUATIONS), &mut run_rng(1, 0), true, &[], &mut |_| {}).best_cost
}

/// The work measured: the bare loop's points, and each optimizer with the points it evaluates.
struct Work {
    obj: FunctionObjective,
    points: Vec<f64>,
    optimizers: Vec<(&'static str, Vec<f64>)>,
}

impl Work {
    fn new() -> Self {
        let obj = objective();
        assert!(!obj.parallel_hint(), "runs must be single-threaded for the thread's CPU time to be their cost");
        let budget = Termination::evaluations(EVALUATIONS);
        let optimizers = optimizer_ids()
            .into_iter()
            .map(|id| {
                // The timed runs' points, recorded once: exactly the budget, same results.
                let recorder = Recorder { inner: &obj, points: Mutex::new(Vec::new()) };
                let recorded = run(make(id).as_mut(), &recorder, &budget, &mut run_rng(1, 0), true, &[], &mut |_| {});
                let stop = (recorded.evaluations, recorded.stop_reason);
                assert_eq!(stop, (EVALUATIONS, StopReason::MaxEvaluations), "{id}");
                let replay = recorder.points.into_inner().expect("recorder lock");
                assert_eq!(replay.len(), EVALUATIONS as usize * DIM, "{id}");
                assert_eq!(run_once(make(id).as_mut(), &obj), recorded.best_cost, "{id}: seeded runs differ");
                (id, replay)
            })
            .collect();
        Self { points: bare_points(&obj), obj, optimizers }
    }
}

fn bench<M: Measurement>(c: &mut Criterion<M>, work: &Work) {
    let obj = &work.obj;
    let mut group = c.benchmark_group(GROUP);
    group.sample_size(20);
    let mut scratch = Scratch::default();
    group.bench_function("bare", |b| b.iter(|| bare_loop(obj, &work.points, &mut scratch)));
    for (id, replay) in &work.optimizers {
        group.bench_function(*id, |b| {
            b.iter_batched(|| make(id), |mut opt| run_once(opt.as_mut(), obj), BatchSize::LargeInput)
        });
        group.bench_function(format!("replay-{id}"), |b| b.iter(|| bare_loop(obj, replay, &mut scratch)));
    }
    group.finish();
}

/// Paired rounds: in each round the bare loop, then every optimizer next to its replay (in
/// alternating order), so a change in the machine's load hits both sides of a ratio alike.
/// Returns each optimizer's per-round ratios over the bare loop and over its replay.
fn paired<M: Measurement>(m: &M, work: &Work, rounds: usize) -> Vec<(&'static str, Vec<f64>, Vec<f64>)> {
    let time = |f: &mut dyn FnMut()| {
        let start = m.start();
        f();
        m.to_f64(&m.end(start))
    };
    let mut scratch = Scratch::default();
    let mut out: Vec<_> = work.optimizers.iter().map(|(id, _)| (*id, Vec::new(), Vec::new())).collect();
    for round in 0..rounds {
        let bare = time(&mut || {
            black_box(bare_loop(&work.obj, &work.points, &mut scratch));
        });
        for ((id, replay), (_, over_bare, over_replay)) in work.optimizers.iter().zip(&mut out) {
            let mut opt = make(id);
            let mut t_opt = || {
                time(&mut || {
                    black_box(run_once(opt.as_mut(), &work.obj));
                })
            };
            let mut t_replay = || {
                time(&mut || {
                    black_box(bare_loop(&work.obj, replay, &mut scratch));
                })
            };
            let (t, r) = if round % 2 == 0 {
                let t = t_opt();
                (t, t_replay())
            } else {
                let r = t_replay();
                (t_opt(), r)
            };
            over_bare.push(t / bare);
            over_replay.push(t / r);
        }
    }
    out
}

/// Median and quartiles.
fn quartiles(v: &mut [f64]) -> (f64, f64, f64) {
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((v.len() - 1) as f64 * q).round() as usize];
    (at(0.5), at(0.25), at(0.75))
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

const ROUNDS: usize = 21;

/// Prints and keeps the table: criterion's medians, and the ratios from paired rounds.
fn report<M: Measurement>(m: &M, work: &Work, since: SystemTime) {
    if median_ns("bare", since).is_none() {
        return; // Not measured in this process (a filter, or `--test`).
    }
    let ms = |t: Option<f64>| t.map_or("-".to_string(), |t| format!("{:.2} ms", t / 1e6));
    let mut table = format!(
        "Rastrigin-{DIM}, {EVALUATIONS} evaluations, population {POPULATION}\n\
         criterion medians: bare {}{}\n\
         ratios: median [quartiles] of {ROUNDS} paired rounds\n\
         {:<8} {:>24} {:>24}\n",
        ms(median_ns("bare", since)),
        work.optimizers
            .iter()
            .map(|(id, _)| format!(
                ", {id} {} (replay {})",
                ms(median_ns(id, since)),
                ms(median_ns(&format!("replay-{id}"), since))
            ))
            .collect::<String>(),
        "",
        "over bare",
        "over replay",
    );
    for (id, mut over_bare, mut over_replay) in paired(m, work, ROUNDS) {
        let cell = |v: &mut [f64]| {
            let (med, lo, hi) = quartiles(v);
            format!("{med:.2}x [{lo:.2}-{hi:.2}]")
        };
        table += &format!("{id:<8} {:>24} {:>24}\n", cell(&mut over_bare), cell(&mut over_replay));
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
    let work = Work::new();
    #[cfg(unix)]
    let (mut c, m) = (Criterion::default().with_measurement(cpu_time::ThreadCpuTime), cpu_time::ThreadCpuTime);
    #[cfg(not(unix))]
    let (mut c, m) = (Criterion::default(), criterion::measurement::WallTime);
    c = c.configure_from_args();
    bench(&mut c, &work);
    c.final_summary();
    report(&m, &work, since);
}
