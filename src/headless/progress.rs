//! A one-line progress bar on stderr, drawn only when stderr is a terminal, so logs and pipes
//! (CI, `2> file`) stay clean. Long commands (`capture`, `tradeoff`, `scaling`) use it so a run
//! of minutes never sits silent.

use std::cell::Cell;
use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

/// Redraws closer together than this are skipped (except the last one), so a bar updated
/// between short timed frames costs next to nothing and does not flicker.
const REDRAW_EVERY: Duration = Duration::from_millis(50);

pub struct Progress {
    enabled: bool,
    total: u64,
    label: &'static str,
    start: Instant,
    /// Whether to show the estimated time left (off where items differ in cost and the caller
    /// has no way to say by how much).
    eta: bool,
    last_draw: Cell<Option<Instant>>,
}

impl Progress {
    pub fn new(total: u64, label: &'static str, quiet: bool) -> Progress {
        Progress {
            enabled: !quiet && std::io::stderr().is_terminal(),
            total,
            label,
            start: Instant::now(),
            eta: true,
            last_draw: Cell::new(None),
        }
    }

    /// The same bar without the estimated time left: it shows the time so far instead.
    pub fn without_eta(mut self) -> Progress {
        self.eta = false;
        self
    }

    /// `done` of `total` items, all costing about the same.
    pub fn update(&self, done: u64) {
        self.update_weighted(done, done as f64 / self.total.max(1) as f64, "");
    }

    /// `done` items, `fraction` (0..=1) of the work they stand for, and a note naming what runs
    /// now. The caller passes the fraction when it knows items differ in cost (a 4×4
    /// antialiased frame against a quarter-size one), so the bar and the ETA follow the work.
    pub fn update_weighted(&self, done: u64, fraction: f64, note: &str) {
        if !self.enabled {
            return;
        }
        let now = Instant::now();
        let last = done >= self.total;
        if !last && self.last_draw.get().is_some_and(|t| now - t < REDRAW_EVERY) {
            return;
        }
        self.last_draw.set(Some(now));
        let line = self.line(done, fraction, now - self.start, note);
        let mut err = std::io::stderr().lock();
        // `\x1b[K` clears what a longer previous line left to the right.
        let _ = write!(err, "\r{line}\x1b[K");
        let _ = err.flush();
    }

    /// The bar's text: `[####......] 3/17 settings, 2.1/s, ETA 0:12  aa 3`.
    fn line(&self, done: u64, fraction: f64, elapsed: Duration, note: &str) -> String {
        const WIDTH: usize = 30;
        let fraction = if fraction.is_finite() { fraction.clamp(0.0, 1.0) } else { 0.0 };
        let filled = (fraction * WIDTH as f64).round() as usize;
        let secs = elapsed.as_secs_f64();
        let rate = done as f64 / secs.max(1e-9);
        let mut line = format!(
            "[{}{}] {done}/{} {} ({rate:.1}/s",
            "#".repeat(filled),
            ".".repeat(WIDTH - filled),
            self.total,
            self.label
        );
        if self.eta && fraction > 0.0 {
            line.push_str(&format!(", ETA {}", clock(secs * (1.0 - fraction) / fraction)));
        } else if !self.eta {
            line.push_str(&format!(", {} so far", clock(secs)));
        }
        line.push(')');
        if !note.is_empty() {
            line.push_str("  ");
            line.push_str(note);
        }
        line
    }

    /// Takes the bar off its line so the caller can print there (a table row on stdout); the
    /// next update draws it again.
    pub fn clear(&self) {
        if self.enabled {
            let _ = write!(std::io::stderr(), "\r\x1b[K");
            self.last_draw.set(None);
        }
    }

    pub fn finish(&self) {
        if self.enabled {
            let _ = writeln!(std::io::stderr());
        }
    }
}

/// Seconds as `m:ss`, or `h:mm:ss` from an hour on.
fn clock(seconds: f64) -> String {
    let s = seconds.max(0.0).round() as u64;
    if s >= 3600 {
        format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
    } else {
        format!("{}:{:02}", s / 60, s % 60)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bar(total: u64) -> Progress {
        Progress { enabled: true, ..Progress::new(total, "settings", true) }
    }

    #[test]
    fn progress_shows_an_eta_from_the_weighted_fraction() {
        // A quarter of the work in 10 s leaves 30 s, whatever the item count says.
        let line = bar(8).line(6, 0.25, Duration::from_secs(10), "aa 3");
        assert!(line.starts_with(&format!("[{}{}] 6/8 settings", "#".repeat(8), ".".repeat(22))), "{line}");
        assert!(line.contains("ETA 0:30") && line.ends_with("  aa 3"), "{line}");
        let line = bar(8).without_eta().line(2, 0.25, Duration::from_secs(75), "");
        assert!(line.contains("1:15 so far") && !line.contains("ETA"), "{line}");
    }

    #[test]
    fn clock_formats() {
        assert_eq!(clock(0.4), "0:00");
        assert_eq!(clock(61.0), "1:01");
        assert_eq!(clock(3725.0), "1:02:05");
        assert_eq!(clock(-3.0), "0:00");
    }
}
