//! A fuzz harness on stable Rust: structured generation and mutation of scenario TOML, plan
//! JSON and planning requests, driving the library entry points the CLI uses. Every case must
//! end in an input error or a result: no panic, bounded time, and no partial output file.
//!
//! CI runs `TIDEPATH_FUZZ_CASES` cases (default 300, seeded, well under a minute). A longer
//! run: `TIDEPATH_FUZZ_CASES=100000 TIDEPATH_FUZZ_SEED=7 cargo test --release -p tidepath-io
//! --test io fuzz:: -- --nocapture`. A failing case prints its seed and case number; rerun it with
//! `TIDEPATH_FUZZ_SEED=S TIDEPATH_FUZZ_FROM=N TIDEPATH_FUZZ_CASES=1`.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use tidepath_io::scenario::{builtin, PlanRequest, Scenario};
use tidepath_io::{Outputs, PlanFile};

/// A case taking longer than this is a hang: the watchdog stops the whole test.
const HANG: Duration = Duration::from_secs(60);

fn corpus() -> Vec<String> {
    vec![
        builtin("demo").unwrap().to_string(),
        builtin("salish").unwrap().to_string(),
        include_str!("data/fleet.toml").to_string(),
        include_str!("data/moving_jet.toml").to_string(),
        include_str!("data/tidal_grid.toml").to_string(),
        include_str!("data/cells_wall.toml").to_string(),
    ]
}

/// Values that have broken parsers and planners before: extremes, zero, negative zero, wrong
/// types, huge sizes.
fn nasty(rng: &mut ChaCha8Rng) -> toml::Value {
    use toml::Value::*;
    match rng.random_range(0..22) {
        0 => Float(1e308),
        1 => Float(-1e308),
        2 => Float(1e15),
        3 => Float(1e20),
        4 => Float(0.0),
        5 => Float(-0.0),
        6 => Float(-1.0),
        7 => Integer(i64::MAX),
        8 => Integer(i64::MIN),
        9 => Integer(0),
        10 => Integer(1_000_000_000),
        11 => Integer(-1),
        12 => String("x".repeat(rng.random_range(0..40))),
        13 => Boolean(true),
        14 => Array(vec![]),
        15 => Array(vec![Float(1e12), Float(-1e12), Float(0.0)]),
        16 => Table(toml::Table::new()),
        17 => Float(f64::MIN_POSITIVE),
        18 => Float(rng.random_range(-1e6..1e6)),
        19 => Integer(rng.random_range(-10..100_000)),
        20 => Float(1e-300),
        _ => Array(vec![Integer(1 << 40), Integer(1 << 40)]),
    }
}

/// Every path to a leaf of `v`, as keys and array indices.
#[derive(Clone, Debug)]
enum Step {
    Key(String),
    Index(usize),
}

fn leaves(v: &toml::Value, path: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    match v {
        toml::Value::Table(t) => {
            for (k, x) in t {
                path.push(Step::Key(k.clone()));
                out.push(path.clone());
                leaves(x, path, out);
                path.pop();
            }
        }
        toml::Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                path.push(Step::Index(i));
                out.push(path.clone());
                leaves(x, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

fn at<'a>(v: &'a mut toml::Value, path: &[Step]) -> Option<&'a mut toml::Value> {
    let mut cur = v;
    for s in path {
        cur = match (s, cur) {
            (Step::Key(k), toml::Value::Table(t)) => t.get_mut(k)?,
            (Step::Index(i), toml::Value::Array(a)) => a.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(cur)
}

/// One structured mutation of a TOML document: replace, delete or grow a node.
fn mutate_toml(text: &str, rng: &mut ChaCha8Rng) -> String {
    let Ok(table) = text.parse::<toml::Table>() else { return text.to_string() };
    let mut doc = toml::Value::Table(table);
    for _ in 0..rng.random_range(1..4) {
        let mut paths = Vec::new();
        leaves(&doc, &mut Vec::new(), &mut paths);
        if paths.is_empty() {
            break;
        }
        let path = paths[rng.random_range(0..paths.len())].clone();
        match rng.random_range(0..10) {
            0 => {
                // Delete the node.
                if let Some((last, parent)) = path.split_last() {
                    match (last, at(&mut doc, parent)) {
                        (Step::Key(k), Some(toml::Value::Table(t))) => {
                            t.remove(k);
                        }
                        (Step::Index(i), Some(toml::Value::Array(a))) if *i < a.len() => {
                            a.remove(*i);
                        }
                        _ => {}
                    }
                }
            }
            1 => {
                // Grow an array by repeating its first element.
                if let Some(toml::Value::Array(a)) = at(&mut doc, &path) {
                    if let Some(first) = a.first().cloned() {
                        let n = [2, 50, 2000][rng.random_range(0..3)];
                        a.extend(std::iter::repeat_n(first, n));
                    }
                }
            }
            2 => {
                // An unknown key next to it.
                if let Some((_, parent)) = path.split_last() {
                    if let Some(toml::Value::Table(t)) = at(&mut doc, parent) {
                        t.insert("zz_unknown".into(), nasty(rng));
                    }
                }
            }
            _ => {
                if let Some(node) = at(&mut doc, &path) {
                    *node = nasty(rng);
                }
            }
        }
    }
    toml::to_string(&doc).unwrap_or_else(|_| text.to_string())
}

/// Byte-level damage: flips, truncation, insertions.
fn mutate_bytes(text: &str, rng: &mut ChaCha8Rng) -> String {
    let mut b = text.as_bytes().to_vec();
    for _ in 0..rng.random_range(1..6) {
        if b.is_empty() {
            break;
        }
        let i = rng.random_range(0..b.len());
        match rng.random_range(0..4) {
            0 => b[i] ^= 1 << rng.random_range(0..8),
            1 => b.truncate(i),
            2 => {
                let chars = b"[]{}=\",.\n-0e9";
                b.insert(i, chars[rng.random_range(0..chars.len())]);
            }
            _ => b[i] = rng.random(),
        }
    }
    String::from_utf8_lossy(&b).into_owned()
}

/// One structured mutation of a plan JSON: numbers to extremes, arrays cut or grown, types
/// swapped.
fn mutate_json(v: &mut serde_json::Value, rng: &mut ChaCha8Rng, depth: usize) {
    use serde_json::Value as J;
    let pick = rng.random_range(0..12);
    match v {
        J::Number(_) if pick < 6 => {
            *v = match rng.random_range(0..6) {
                0 => J::from(1e12),
                1 => J::from(-1e300),
                2 => J::from(0.0),
                3 => J::from(u64::MAX),
                4 => J::String("1".into()),
                _ => J::Null,
            }
        }
        J::Array(a) if !a.is_empty() => match pick {
            0 => a.truncate(rng.random_range(0..a.len())),
            1 => {
                let first = a[0].clone();
                a.extend(std::iter::repeat_n(first, [1, 30, 3000][rng.random_range(0..3)]));
            }
            _ if depth < 6 => {
                let i = rng.random_range(0..a.len());
                mutate_json(&mut a[i], rng, depth + 1);
            }
            _ => {}
        },
        J::Object(o) if !o.is_empty() => {
            let keys: Vec<String> = o.keys().cloned().collect();
            let k = &keys[rng.random_range(0..keys.len())];
            if pick == 0 {
                o.remove(k);
            } else if depth < 6 {
                mutate_json(o.get_mut(k).unwrap(), rng, depth + 1);
            }
        }
        _ => {}
    }
}

struct Stats {
    loaded: u64,
    planned: u64,
    plan_files: u64,
    evaluated: u64,
    outputs: u64,
}

/// One case: a scenario (mutated or not), maybe a plan, maybe its JSON mutated and evaluated,
/// maybe the outputs staged to a hostile target.
fn case(seed: u64, corpus: &[String], dir: &std::path::Path, stats: &mut Stats) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    if rng.random_range(0..20) == 0 {
        special_scenario_file(dir, &mut rng);
        return;
    }
    let base = &corpus[rng.random_range(0..corpus.len())];
    let text = match rng.random_range(0..10) {
        0 => base.clone(),
        1 | 2 => mutate_bytes(base, &mut rng),
        _ => mutate_toml(base, &mut rng),
    };
    if std::env::var_os("TIDEPATH_FUZZ_DUMP").is_some() {
        eprintln!("--- case {seed} scenario:\n{text}");
    }
    // As a built-in, so `salish`'s data file resolves to the embedded copy.
    let Ok(s) = Scenario::from_toml(&text, "builtin:fuzz") else { return };
    stats.loaded += 1;
    let req = PlanRequest {
        // Mostly the optimizers (fast); every tenth case one of the other planners. Both lists
        // come from the planner table, plus a case in four left to the scenario's own planner.
        planner: {
            let (optimizers, others): (Vec<&tidepath::registry::Entry<tidepath::planner::BuildPlanner>>, Vec<_>) =
                tidepath::planner::PLANNERS.iter().partition(|e| e.build.is_optimizer());
            let pool = if rng.random_range(0..10) == 0 { others } else { optimizers };
            let k = rng.random_range(0..pool.len() + pool.len() / 3 + 1);
            pool.get(k).map(|e| e.id.to_string())
        },
        seed: rng.random(),
        iterations: Some(rng.random_range(1..4)),
        population: [None, Some(4), Some(8)][rng.random_range(0..3)],
        time_limit_s: Some(0.3),
        smoother: {
            let ids: Vec<&str> = tidepath::smoothing::SMOOTHERS.iter().map(|e| e.id).collect();
            let k = rng.random_range(0..ids.len() * 2);
            ids.get(k).map(|s| s.to_string())
        },
        ..PlanRequest::default()
    };
    let Ok(report) = s.plan(&req, &mut |_| {}) else { return };
    stats.planned += 1;
    let mut json: serde_json::Value = serde_json::from_str(&report.to_json()).unwrap();
    for _ in 0..rng.random_range(0..4) {
        mutate_json(&mut json, &mut rng, 0);
    }
    let mut plan_text = json.to_string();
    if rng.random_range(0..4) == 0 {
        plan_text = mutate_bytes(&plan_text, &mut rng);
    }
    if let Ok(plan) = PlanFile::parse(&plan_text, "fuzz.json") {
        stats.plan_files += 1;
        if s.evaluate_paths(&plan.mission_paths()).is_ok() {
            stats.evaluated += 1;
        }
    }
    // Outputs: a hostile target must leave the folder exactly as it was, the user's files in
    // `keep/` included, whatever `..` steps through folders that do not exist.
    let before = listing(dir);
    let json_path = dir.join(format!("p{seed}.json"));
    // (folder, file name, where the file lands if written)
    let keep = dir.join("keep");
    let (folder, name, lands) = match rng.random_range(0..9) {
        0 => (dir.join("missing-folder"), "x.svg".to_string(), dir.join("missing-folder/x.svg")),
        1 => (dir.to_path_buf(), String::new(), dir.to_path_buf()),
        2 => (dir.to_path_buf(), "link.svg".to_string(), dir.join("link.svg")),
        3 => (dir.join(format!("new{seed}/..")), format!("p{seed}.svg"), dir.join(format!("p{seed}.svg"))),
        4 => {
            let n = ["results.json", "blocked.svg"][rng.random_range(0..2)];
            (dir.join(format!("new{seed}/../keep")), n.to_string(), keep.join(n))
        }
        5 => (dir.join(format!("a{seed}/b/../../keep")), "blocked.svg".to_string(), keep.join("blocked.svg")),
        6 => {
            let d = dir.join(format!("made{seed}/deeper"));
            (d.clone(), format!("p{seed}.svg"), d.join(format!("p{seed}.svg")))
        }
        _ => (dir.to_path_buf(), format!("p{seed}.svg"), dir.join(format!("p{seed}.svg"))),
    };
    let as_file = rng.random_range(0..2) == 0 || name.is_empty();
    // As the CLI does: declare both, fill, commit; a failure anywhere leaves nothing.
    let write = || -> tidepath::Result<()> {
        let mut out = Outputs::new();
        out.stage("--out", &json_path, report.to_json().as_bytes())?;
        if as_file {
            out.stage("--plot", &folder.join(&name), b"<svg/>")?;
        } else {
            out.stage_in("--plot", &folder, &name, b"<svg/>")?;
        }
        out.commit()
    };
    if write().is_ok() {
        stats.outputs += 1;
        std::fs::remove_file(&json_path).unwrap();
        std::fs::remove_file(&lands).unwrap();
        // Folders the commit made (and only those) go too.
        for made in lands.ancestors().skip(1).take_while(|p| *p != dir) {
            let rel = format!("{}/", made.strip_prefix(dir).unwrap().display());
            if !before.contains(&rel) {
                std::fs::remove_dir(made).unwrap();
            }
        }
    }
    assert_eq!(listing(dir), before, "case {seed}: a write changed the folder");
}

/// A scenario path that is no scenario file: a FIFO (which would block a reader forever),
/// `/dev/zero`, a folder, a sparse file far beyond the size limit. Loading must refuse it at
/// once, naming it.
fn special_scenario_file(dir: &std::path::Path, rng: &mut ChaCha8Rng) {
    let special = dir.join("special");
    std::fs::create_dir_all(&special).unwrap();
    let path = special.join(format!("s{}.toml", rng.random::<u32>()));
    match rng.random_range(0..4) {
        0 => assert!(std::process::Command::new("mkfifo").arg(&path).status().is_ok_and(|s| s.success())),
        1 => std::os::unix::fs::symlink("/dev/zero", &path).unwrap(),
        2 => std::fs::create_dir(&path).unwrap(),
        _ => std::fs::File::create(&path)
            .unwrap()
            .set_len([65u64 << 20, 1 << 30, 3 << 30][rng.random_range(0..3)])
            .unwrap(),
    }
    let e = tidepath_io::scenario::load(path.to_str().unwrap()).unwrap_err().to_string();
    assert!(e.starts_with("SCENARIO:") && !e.contains('\n'), "{e}");
    std::fs::remove_dir_all(&special).unwrap();
}

/// Every entry under `dir`, recursively, with the contents of small files.
fn listing(dir: &std::path::Path) -> Vec<String> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let meta = std::fs::symlink_metadata(&p).unwrap();
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if meta.is_dir() {
            v.push(format!("{name}/"));
            v.extend(listing(&p).into_iter().map(|c| format!("{name}/{c}")));
        } else if meta.is_file() {
            v.push(format!("{name}: {}", std::fs::read_to_string(&p).unwrap_or_default()));
        } else {
            v.push(name);
        }
    }
    v.sort();
    v
}

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// Tells the hang watchdog to stop when dropped.
struct WatchdogOff(Arc<AtomicBool>);

impl Drop for WatchdogOff {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

#[test]
fn fuzz_scenarios_plans_and_outputs() {
    let cases = env("TIDEPATH_FUZZ_CASES", 300);
    let master = env("TIDEPATH_FUZZ_SEED", 2026);
    let from = env("TIDEPATH_FUZZ_FROM", 0);
    let corpus = corpus();
    let dir = tempfile::tempdir().unwrap();
    std::os::unix::fs::symlink("/dev/null", dir.path().join("link.svg")).unwrap();
    std::fs::create_dir_all(dir.path().join("keep/blocked.svg")).unwrap();
    std::fs::write(dir.path().join("keep/thesis.tex"), "the user's own file").unwrap();
    let current = Arc::new(AtomicU64::new(u64::MAX));
    let watched = current.clone();
    let started = Arc::new(std::sync::Mutex::new(Instant::now()));
    let clock = started.clone();
    // The watchdog ends with this test, passed or failed (the guard's drop): the test binary
    // goes on with other tests afterwards.
    let finished = WatchdogOff(Arc::new(AtomicBool::new(false)));
    let over = finished.0.clone();
    std::thread::spawn(move || loop {
        std::thread::sleep(Duration::from_secs(1));
        if over.load(Ordering::Relaxed) {
            return;
        }
        let since = clock.lock().unwrap().elapsed();
        if since > HANG {
            eprintln!("fuzz: case {} has run for {since:?}: a hang", watched.load(Ordering::Relaxed));
            std::process::exit(101);
        }
    });
    let mut stats = Stats { loaded: 0, planned: 0, plan_files: 0, evaluated: 0, outputs: 0 };
    let t = Instant::now();
    let mut slowest = (Duration::ZERO, 0);
    for n in from..from + cases {
        let seed = master.wrapping_mul(1_000_003).wrapping_add(n);
        current.store(n, Ordering::Relaxed);
        *started.lock().unwrap() = Instant::now();
        let t0 = Instant::now();
        let r = catch_unwind(AssertUnwindSafe(|| case(seed, &corpus, dir.path(), &mut stats)));
        if r.is_err() {
            panic!("fuzz case {n} (TIDEPATH_FUZZ_SEED={master} TIDEPATH_FUZZ_FROM={n} TIDEPATH_FUZZ_CASES=1) panicked");
        }
        slowest = slowest.max((t0.elapsed(), n));
    }
    drop(finished);
    eprintln!(
        "fuzz: {cases} cases in {:.1} s (slowest: case {} in {:.2} s); {} scenarios loaded, {} planned, {} plan files parsed, {} evaluated, {} output sets written",
        t.elapsed().as_secs_f64(),
        slowest.1,
        slowest.0.as_secs_f64(),
        stats.loaded,
        stats.planned,
        stats.plan_files,
        stats.evaluated,
        stats.outputs
    );
    // The harness must reach the deep entry points, not stop at the parser.
    if cases >= 100 {
        assert!(stats.loaded * 10 >= cases, "only {} of {cases} scenarios loaded", stats.loaded);
        assert!(stats.evaluated > 0 && stats.outputs > 0);
    }
}
