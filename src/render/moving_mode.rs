//! Which way the window makes a moving frame: traced whole, or reprojected (`render::reproject`)
//! — chosen by what each costs on this scene, measured while flying. Pure logic on measured
//! frame times, like `adaptive`; the render thread feeds it and obeys it.
//!
//! Reprojection pays where shading is dear (area lights: 1.46× the frame rate at the same PSNR)
//! and costs where it is cheap (the seed scene: 1.7× the time per pixel of a whole frame, so the
//! adaptive scale drops from 0.57 to 0.44). So the mode in use runs, and every `PROBE_EVERY`
//! moving frames `PROBE_FRAMES` are made the other way, at the same scale; the first of them only
//! warms reprojection's history and is not counted. After a probe the cheaper mode (per
//! full-resolution frame, by more than `SWITCH_MARGIN`) is used until the next. Probe frames are
//! kept from the scale controller, so a dearer probe never lowers the scale.

/// How a moving frame is made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Whole,
    Reprojected,
}

impl Mode {
    fn index(self) -> usize {
        self as usize
    }

    fn other(self) -> Mode {
        match self {
            Mode::Whole => Mode::Reprojected,
            Mode::Reprojected => Mode::Whole,
        }
    }
}

/// Moving frames in the chosen mode between probes (about two seconds at 60 fps).
pub const PROBE_EVERY: u32 = 120;
/// Frames of a probe, the first not counted.
pub const PROBE_FRAMES: u32 = 3;
/// The first probe comes early, once the controller has settled a little.
const FIRST_PROBE_AFTER: u32 = 10;
/// The other mode must be this much cheaper to take over.
const SWITCH_MARGIN: f64 = 0.9;
/// Weight of a new frame in the chosen mode's smoothed cost (a probe's frames weigh half).
const ALPHA: f64 = 0.15;
const PROBE_ALPHA: f64 = 0.5;

/// What a recorded frame changed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Recorded {
    /// The frame was in the chosen mode: the scale controller should learn from it.
    Chosen,
    /// A probe frame: the controller must not see it.
    Probe,
    /// A probe ended and the other mode took over; its cost per full-resolution frame is this
    /// many times the old one's (to rescale the controller's estimate at once).
    Switched(f64),
}

#[derive(Clone, Debug)]
pub struct ModeChoice {
    chosen: Mode,
    /// Smoothed seconds per full-resolution frame, per mode (`Mode::index`).
    cost: [Option<f64>; 2],
    since_probe: u32,
    /// Frames of the running probe still to make (0: none running).
    probing: u32,
}

impl Default for ModeChoice {
    fn default() -> ModeChoice {
        ModeChoice { chosen: Mode::Whole, cost: [None; 2], since_probe: PROBE_EVERY - FIRST_PROBE_AFTER, probing: 0 }
    }
}

impl ModeChoice {
    /// The mode for the next moving frame.
    pub fn next(&self) -> Mode {
        if self.probing > 0 {
            self.chosen.other()
        } else {
            self.chosen
        }
    }

    /// The mode in use between probes.
    pub fn chosen(&self) -> Mode {
        self.chosen
    }

    /// Records that a moving frame made in `mode` (as `next` said) at `scale` took `seconds`.
    pub fn record(&mut self, mode: Mode, scale: f64, seconds: f64) -> Recorded {
        let sample = (seconds.is_finite() && seconds > 0.0 && scale > 0.0).then(|| seconds / (scale * scale));
        if mode == self.chosen && self.probing == 0 {
            self.learn(mode, sample, ALPHA);
            self.since_probe += 1;
            if self.since_probe >= PROBE_EVERY {
                self.since_probe = 0;
                self.probing = PROBE_FRAMES;
            }
            return Recorded::Chosen;
        }
        // A probe frame; the first only warms the history.
        if self.probing < PROBE_FRAMES {
            self.learn(mode, sample, PROBE_ALPHA);
        }
        self.probing = self.probing.saturating_sub(1);
        if self.probing > 0 {
            return Recorded::Probe;
        }
        match (self.cost[self.chosen.index()], self.cost[self.chosen.other().index()]) {
            (Some(now), Some(other)) if other < now * SWITCH_MARGIN => {
                self.chosen = self.chosen.other();
                Recorded::Switched(other / now)
            }
            _ => Recorded::Probe,
        }
    }

    fn learn(&mut self, mode: Mode, sample: Option<f64>, alpha: f64) {
        let Some(sample) = sample else { return };
        let c = &mut self.cost[mode.index()];
        *c = Some(match *c {
            Some(old) => old + alpha * (sample - old),
            None => sample,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Flies `frames` frames at scale 0.5 where a full-resolution frame costs `whole` or
    /// `reprojected` seconds (a probe's first reprojected frame `cold` times dearer); returns the
    /// modes made and what each record said.
    fn fly(whole: f64, reprojected: f64, cold: f64, frames: usize) -> (Vec<Mode>, Vec<Recorded>) {
        let mut choice = ModeChoice::default();
        let (mut modes, mut said) = (Vec::new(), Vec::new());
        let mut previous = None;
        for _ in 0..frames {
            let mode = choice.next();
            let warm = previous == Some(mode);
            let full = match mode {
                Mode::Whole => whole,
                Mode::Reprojected if warm => reprojected,
                Mode::Reprojected => reprojected * cold,
            };
            said.push(choice.record(mode, 0.5, full * 0.25));
            modes.push(mode);
            previous = Some(mode);
        }
        (modes, said)
    }

    #[test]
    fn a_cheaper_reprojection_takes_over_after_the_first_probe() {
        // Cold frames three times dearer: only the warm ones count.
        let (modes, said) = fly(0.040, 0.025, 3.0, 40);
        assert!(modes[..FIRST_PROBE_AFTER as usize].iter().all(|&m| m == Mode::Whole));
        let switched = said.iter().position(|s| matches!(s, Recorded::Switched(_))).expect("it switches");
        assert_eq!(switched, (FIRST_PROBE_AFTER + PROBE_FRAMES) as usize - 1);
        let Recorded::Switched(ratio) = said[switched] else { unreachable!() };
        assert!((ratio - 0.025 / 0.040).abs() < 1e-9, "ratio {ratio}");
        assert!(modes[switched + 1..].iter().all(|&m| m == Mode::Reprojected));
    }

    #[test]
    fn a_dearer_reprojection_is_only_probed() {
        let (modes, said) = fly(0.024, 0.041, 1.0, 1000);
        assert!(!said.iter().any(|s| matches!(s, Recorded::Switched(_))));
        let probes = modes.iter().filter(|&&m| m == Mode::Reprojected).count();
        // The first probe after 10 frames, then one every PROBE_EVERY chosen frames.
        assert_eq!(probes as u32, PROBE_FRAMES * (1 + (1000 - 10 - 3) / (PROBE_EVERY + PROBE_FRAMES)));
        // Probe frames are kept from the controller; chosen frames are not.
        for (m, s) in modes.iter().zip(&said) {
            assert_eq!(*m == Mode::Whole, *s == Recorded::Chosen, "{m:?} {s:?}");
        }
    }

    #[test]
    fn a_margin_keeps_near_equal_modes_from_flapping() {
        let (_, said) = fly(0.030, 0.029, 1.0, 2000);
        assert!(!said.iter().any(|s| matches!(s, Recorded::Switched(_))));
    }

    #[test]
    fn bad_timings_teach_nothing() {
        let mut choice = ModeChoice::default();
        for _ in 0..500 {
            let mode = choice.next();
            assert!(!matches!(choice.record(mode, 0.5, f64::NAN), Recorded::Switched(_)));
        }
        assert_eq!(choice.chosen(), Mode::Whole);
    }
}
