//! Adaptive resolution: the render scale that keeps a moving camera at the target frame rate.
//! Pure logic on measured frame times; the window's render thread feeds it and obeys it.

/// The smallest scale: 20% of the window's width and height (4% of its pixels).
pub const MIN_SCALE: f64 = 0.2;
pub const MAX_SCALE: f64 = 1.0;

/// Picks the internal render scale (a fraction of the window's width and height) frame by frame.
///
/// The model: a frame's cost is proportional to its pixel count, so a frame that took `t` seconds
/// at scale `s` says a full-resolution frame costs `c = t / s²`. The controller keeps a smoothed
/// estimate of `c` and aims at `s* = sqrt(HEADROOM · target / c)`, clamped to
/// [`MIN_SCALE`, `MAX_SCALE`]. Four things keep it steady:
///
/// - **Smoothing**: `c` is an exponential moving average (weight `ALPHA` = 0.15), which cuts
///   per-frame noise to about a quarter of its spread.
/// - **Spike bypass**: a frame costing more than `SPIKE` = 1.6× the average replaces it outright.
///   Random jitter of ±30% never gets there, a real slowdown (heavier part of the scene) does, so
///   the scale drops at once instead of after the average catches up.
/// - **Deadband with hysteresis**: the scale only moves down when `s*` is 7% below it and only
///   moves up when `s*` is 10% above it; in between it stays put, so noise around the balance
///   point cannot make it hunt.
/// - **Rate limits**: at most halving per frame going down (recover fast), at most +8% per frame
///   going up (creep back, re-measuring as it goes), which avoids overshooting into a slow frame.
#[derive(Clone, Debug)]
pub struct ScaleController {
    /// Seconds per frame the controller aims at.
    target: f64,
    scale: f64,
    /// Smoothed seconds per full-resolution frame; `None` before the first measurement.
    cost: Option<f64>,
}

const ALPHA: f64 = 0.15;
const SPIKE: f64 = 1.6;
/// Aim a little under the target so that the balance point sits inside the frame budget.
const HEADROOM: f64 = 0.9;
const DOWN_BAND: f64 = 0.93;
const UP_BAND: f64 = 1.10;
const MAX_DOWN: f64 = 0.5;
const MAX_UP: f64 = 1.08;

impl ScaleController {
    /// A controller aiming at `target_fps` frames per second, starting at half resolution (a
    /// guess that the first frame corrects either way).
    pub fn new(target_fps: f64) -> ScaleController {
        let fps = if target_fps.is_finite() && target_fps > 0.0 { target_fps } else { 60.0 };
        ScaleController { target: 1.0 / fps, scale: 0.5, cost: None }
    }

    /// The scale to render the next moving frame at.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Target seconds per frame.
    pub fn target(&self) -> f64 {
        self.target
    }

    /// Multiplies the smoothed cost by `factor` (frames are about to cost that much more or less,
    /// as when the window changes how it makes them); the next `update` aims by it.
    pub fn rescale_cost(&mut self, factor: f64) {
        if let (Some(c), true) = (&mut self.cost, factor.is_finite() && factor > 0.0) {
            *c *= factor;
        }
    }

    /// Reports that a frame rendered at `scale` took `seconds`; returns the next scale.
    pub fn update(&mut self, scale: f64, seconds: f64) -> f64 {
        if !(seconds.is_finite() && seconds > 0.0 && scale > 0.0) {
            return self.scale;
        }
        let sample = seconds / (scale * scale);
        let cost = match self.cost {
            Some(c) if sample <= c * SPIKE => c + ALPHA * (sample - c),
            _ => sample,
        };
        self.cost = Some(cost);
        let ideal = (HEADROOM * self.target / cost).sqrt().clamp(MIN_SCALE, MAX_SCALE);
        if ideal < self.scale * DOWN_BAND {
            self.scale = ideal.max(self.scale * MAX_DOWN);
        } else if ideal > self.scale * UP_BAND || (ideal == MAX_SCALE && self.scale < MAX_SCALE) {
            self.scale = ideal.min(self.scale * MAX_UP);
        }
        self.scale = self.scale.clamp(MIN_SCALE, MAX_SCALE);
        self.scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A machine whose frame at scale `s` costs a fixed overhead plus `full` seconds × pixels.
    fn frame_time(full: f64, s: f64) -> f64 {
        0.001 + full * s * s
    }

    /// splitmix64, so the jitter is the same on every run.
    fn jitter(state: &mut u64) -> f64 {
        *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    #[test]
    fn steady_load_converges_and_stays() {
        let mut c = ScaleController::new(60.0);
        let mut history = Vec::new();
        for _ in 0..200 {
            let s = c.scale();
            c.update(s, frame_time(0.040, s));
            history.push(c.scale());
        }
        let settled = history[20];
        assert!(history[20..].iter().all(|&s| s == settled), "keeps moving: {:?}", &history[..40]);
        let t = frame_time(0.040, settled);
        assert!(t <= c.target() * 1.1 && t >= c.target() * 0.6, "frame time {t} at scale {settled}");
    }

    #[test]
    fn fast_scene_runs_at_full_resolution() {
        let mut c = ScaleController::new(60.0);
        for _ in 0..60 {
            let s = c.scale();
            c.update(s, frame_time(0.004, s));
        }
        assert_eq!(c.scale(), MAX_SCALE);
    }

    #[test]
    fn sudden_slowdown_recovers_within_a_few_frames() {
        let mut c = ScaleController::new(60.0);
        for _ in 0..100 {
            let s = c.scale();
            c.update(s, frame_time(0.030, s));
        }
        // The camera turns towards something four times as expensive.
        let mut over = 0;
        for i in 0..50 {
            let s = c.scale();
            let t = frame_time(0.120, s);
            if t > c.target() * 1.25 {
                over = i + 1;
            }
            c.update(s, t);
        }
        assert!(over <= 3, "frames over budget until frame {over}");
    }

    #[test]
    fn slowdown_to_the_floor_clamps() {
        let mut c = ScaleController::new(60.0);
        for _ in 0..20 {
            let s = c.scale();
            c.update(s, frame_time(10.0, s));
        }
        assert_eq!(c.scale(), MIN_SCALE);
        c.update(MIN_SCALE, f64::NAN);
        assert_eq!(c.scale(), MIN_SCALE);
    }

    #[test]
    fn noisy_machine_does_not_oscillate() {
        let mut c = ScaleController::new(60.0);
        let mut seed = 42;
        let mut changes = 0;
        let mut last_dir = 0i8;
        let mut prev = c.scale();
        for _ in 0..1000 {
            let s = c.scale();
            let noise = 1.0 + 0.6 * (jitter(&mut seed) - 0.5); // ±30%
            c.update(s, frame_time(0.040, s) * noise);
            let dir = (c.scale() - prev).partial_cmp(&0.0).map_or(0, |o| o as i8);
            if dir != 0 {
                if last_dir != 0 && dir != last_dir {
                    changes += 1;
                }
                last_dir = dir;
            }
            prev = c.scale();
        }
        assert!(changes <= 10, "{changes} direction changes in 1000 noisy frames");
        let t = frame_time(0.040, c.scale());
        assert!(t <= c.target() * 1.2, "settled at {} ({t} s)", c.scale());
    }
}
