//! Where a presented frame's time goes besides tracing (issue #17, part 3): measured per fresh
//! present while a `--path` plays, and summarised in the `--report`.
//!
//! The stages, in the order a frame passes them:
//! - `encode`: on the render thread, the traced image into 0RGB words (sRGB encoding), or the
//!   reprojector's finished words into the frame (one copy: the reprojector keeps its own as the
//!   next frame's history);
//! - `handoff`: from the render thread sending the frame to the window starting to present it
//!   (the channel, the wake-up, winit's redraw request);
//! - `acquire`: softbuffer handing out the window's buffer;
//! - `blit`: the frame scaled onto the buffer (bilinear; an exact copy at scale 1);
//! - `hud`: the overlay drawn into the buffer (zero when the HUD is off);
//! - `present`: softbuffer putting the buffer on screen.

use std::time::Duration;

use crate::headless::json::Json;

/// One fresh present's non-tracing stages.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameCosts {
    /// The tracing itself (the frame's render time less `encode`), for comparison; not a stage.
    pub trace: Duration,
    pub encode: Duration,
    pub handoff: Duration,
    pub acquire: Duration,
    pub blit: Duration,
    pub hud: Duration,
    pub present: Duration,
}

impl FrameCosts {
    const STAGES: [&'static str; 6] = ["encode", "handoff", "acquire", "blit", "hud", "present"];

    fn stages(&self) -> [Duration; 6] {
        [self.encode, self.handoff, self.acquire, self.blit, self.hud, self.present]
    }

    pub fn total(&self) -> Duration {
        self.stages().iter().sum()
    }
}

/// Milliseconds per stage (their per-frame total, and the tracing beside them) over `costs`, each as `stats` summarises
/// a list of seconds.
pub fn report(costs: &[FrameCosts], stats: impl Fn(&[f64], f64) -> Json) -> Json {
    let column = |f: &dyn Fn(&FrameCosts) -> Duration| costs.iter().map(|c| f(c).as_secs_f64()).collect::<Vec<_>>();
    let mut fields: Vec<(&str, Json)> = FrameCosts::STAGES
        .iter()
        .enumerate()
        .map(|(i, &name)| (name, stats(&column(&|c: &FrameCosts| c.stages()[i]), 1e3)))
        .collect();
    fields.push(("total", stats(&column(&FrameCosts::total), 1e3)));
    fields.push(("trace", stats(&column(&|c: &FrameCosts| c.trace), 1e3)));
    fields.push(("frames", Json::Number(costs.len() as f64)));
    Json::object(fields)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn total_adds_every_stage() {
        let ms = Duration::from_millis;
        let c = FrameCosts {
            trace: ms(100),
            encode: ms(1),
            handoff: ms(2),
            acquire: ms(3),
            blit: ms(4),
            hud: ms(5),
            present: ms(6),
        };
        assert_eq!(c.total(), ms(21));
        assert_eq!(FrameCosts::default().total(), Duration::ZERO);
    }
}
