//! A one-line progress bar on stderr, drawn only when stderr is a terminal, so logs and pipes
//! (CI, `2> file`) stay clean.

use std::io::{IsTerminal, Write};
use std::time::Instant;

pub struct Progress {
    enabled: bool,
    total: u64,
    label: &'static str,
    start: Instant,
}

impl Progress {
    pub fn new(total: u64, label: &'static str, quiet: bool) -> Progress {
        Progress { enabled: !quiet && std::io::stderr().is_terminal(), total, label, start: Instant::now() }
    }

    pub fn update(&self, done: u64) {
        if !self.enabled {
            return;
        }
        const WIDTH: u64 = 30;
        let filled = (done * WIDTH).checked_div(self.total).unwrap_or(WIDTH) as usize;
        let rate = done as f64 / self.start.elapsed().as_secs_f64().max(1e-9);
        let bar = format!("{}{}", "#".repeat(filled), ".".repeat(WIDTH as usize - filled));
        let mut err = std::io::stderr().lock();
        let _ = write!(err, "\r[{bar}] {done}/{} {} ({rate:.1}/s)", self.total, self.label);
        let _ = err.flush();
    }

    pub fn finish(&self) {
        if self.enabled {
            let _ = writeln!(std::io::stderr());
        }
    }
}
