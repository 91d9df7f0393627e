//! Fork safety. A process started by `fork` (Python's default for `multiprocessing` and
//! `ProcessPoolExecutor` on Linux before 3.14) inherits the library's cached rayon thread pools
//! without their threads: a run handed to one of them would wait forever. The package
//! registers [`after_fork_in_child`] with `os.register_at_fork`; from then on plans evaluate
//! their populations on the calling thread (results are identical either way) and
//! comparisons use a worker count whose pool was not inherited (results do not depend on it).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use pyo3::prelude::*;

static FORKED: AtomicBool = AtomicBool::new(false);

/// Worker counts of the pools this process has used, and of those inherited dead at a fork.
static POOLS: Mutex<(Vec<usize>, Vec<usize>)> = Mutex::new((Vec::new(), Vec::new()));

/// Called in the child after a fork (registered by `tidepath/__init__.py`).
#[pyfunction]
pub fn after_fork_in_child() {
    FORKED.store(true, Ordering::Relaxed);
    let mut p = POOLS.lock().unwrap_or_else(|e| e.into_inner());
    let used = std::mem::take(&mut p.0);
    p.1.extend(used);
}

/// Whether this process was forked from one that may have started pool threads.
pub fn forked() -> bool {
    FORKED.load(Ordering::Relaxed)
}

/// The worker count to run `jobs` workers' work with: `jobs` unless its pool was inherited
/// from before a fork, else the smallest count whose pool was not.
pub fn pool_jobs(jobs: usize) -> usize {
    let mut p = POOLS.lock().unwrap_or_else(|e| e.into_inner());
    let j = if p.1.contains(&jobs) { (1..).find(|j| !p.1.contains(j)).unwrap_or(jobs) } else { jobs };
    if !p.0.contains(&j) {
        p.0.push(j);
    }
    j
}
