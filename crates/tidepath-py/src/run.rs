//! Long runs from Python: on a worker thread with the GIL released, the calling thread polling
//! for signals every 50 ms; a signal (Ctrl-C) raises the library's stop flag, the run winds
//! down within its next termination check and the signal's exception (KeyboardInterrupt) is
//! raised.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::Arc;
use std::time::Duration;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// How often the calling thread checks for signals while a run goes on.
const POLL: Duration = Duration::from_millis(50);

/// Runs `f` on a scoped thread and waits for it without the GIL, checking Python's signal
/// handlers every [`POLL`]. On a signal, `stop` is raised, `f` is awaited (it sees the flag
/// through the run's termination) and the handler's exception is returned.
pub fn interruptible<T, F>(py: Python<'_>, stop: &Arc<AtomicBool>, f: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce() -> T + Send,
{
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel();
        s.spawn(move || {
            let _ = tx.send(f());
        });
        let mut rx = rx;
        let mut interrupted: Option<PyErr> = None;
        loop {
            let (back, got) = py.detach(move || {
                let got = rx.recv_timeout(POLL);
                (rx, got)
            });
            rx = back;
            match got {
                Ok(v) => return interrupted.map_or(Ok(v), Err),
                Err(RecvTimeoutError::Timeout) => {
                    if interrupted.is_none() {
                        if let Err(e) = py.check_signals() {
                            stop.store(true, Ordering::Relaxed);
                            interrupted = Some(e);
                        }
                    }
                }
                // The worker panicked: the scope re-raises its panic when it ends.
                Err(RecvTimeoutError::Disconnected) => {
                    return Err(interrupted.unwrap_or_else(|| PyRuntimeError::new_err("the run panicked")))
                }
            }
        }
    })
}
