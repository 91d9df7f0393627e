//! A progress bar on stderr that appears only for runs longer than a second and never when
//! stderr is not a terminal (indicatif hides itself there), so logs and pipes stay clean.

use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use tidepath::optim::Progress;

pub struct DelayedBar {
    bar: ProgressBar,
    shown: bool,
}

const DELAY: Duration = Duration::from_secs(1);
const SCALE: u64 = 1000;

impl DelayedBar {
    pub fn new(label: &str) -> Self {
        let bar = ProgressBar::with_draw_target(Some(SCALE), ProgressDrawTarget::hidden());
        bar.set_style(
            ProgressStyle::with_template("{prefix} [{bar:30}] {percent:>3}% {msg} ({elapsed})")
                .expect("static template")
                .progress_chars("=> "),
        );
        bar.set_prefix(label.to_string());
        Self { bar, shown: false }
    }

    pub fn update(&mut self, p: &Progress) {
        if !self.shown && p.elapsed >= DELAY {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar.set_position((p.fraction * SCALE as f64) as u64);
        self.bar.set_message(format!("best {:.6}", p.best_cost));
    }

    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}

/// Counts finished runs of an experiment; shared by worker threads.
pub struct RunsBar {
    bar: ProgressBar,
}

impl RunsBar {
    pub fn new(label: &str, total: usize) -> Self {
        let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} runs ({elapsed}, eta {eta})")
                .expect("static template")
                .progress_chars("=> "),
        );
        bar.set_prefix(label.to_string());
        Self { bar }
    }

    pub fn set(&self, done: usize) {
        self.bar.set_position(done as u64);
    }

    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}
