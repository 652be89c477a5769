//! The heads-up display and help overlay, drawn into the presented framebuffer after the blit.

use std::time::Duration;

use glam::DVec3;

use crate::app::font::{Canvas, GLYPH};
use crate::render::precise::Precision;

/// The last frame intervals, for average and 95th-percentile frame time.
#[derive(Clone, Debug)]
pub struct FrameTimes {
    times: Vec<f64>,
    next: usize,
    /// Scratch for the percentile, kept to avoid an allocation per frame.
    sorted: Vec<f64>,
}

impl FrameTimes {
    pub fn new(capacity: usize) -> FrameTimes {
        FrameTimes { times: Vec::with_capacity(capacity), next: 0, sorted: Vec::with_capacity(capacity) }
    }

    pub fn push(&mut self, d: Duration) {
        let s = d.as_secs_f64();
        if self.times.len() < self.times.capacity() {
            self.times.push(s);
        } else {
            self.times[self.next] = s;
            self.next = (self.next + 1) % self.times.len();
        }
    }

    /// (average, p95) in seconds; zero before any frame.
    pub fn summary(&mut self) -> (f64, f64) {
        if self.times.is_empty() {
            return (0.0, 0.0);
        }
        let avg = self.times.iter().sum::<f64>() / self.times.len() as f64;
        self.sorted.clear();
        self.sorted.extend_from_slice(&self.times);
        self.sorted.sort_by(f64::total_cmp);
        let i = ((self.sorted.len() as f64 * 0.95).ceil() as usize).clamp(1, self.sorted.len()) - 1;
        (avg, self.sorted[i])
    }
}

/// What the HUD shows, gathered by the window each frame.
pub struct HudInfo<'a> {
    pub frame_avg: f64,
    pub frame_p95: f64,
    pub scale: f64,
    pub internal: (u32, u32),
    pub rays_per_s: f64,
    pub position: DVec3,
    pub speed: f64,
    pub quality: &'a str,
    /// The arithmetic the quality preset traces in.
    pub precision: Precision,
    /// e.g. "moving" or "AA 3/9".
    pub state: &'a str,
}

const TEXT: u32 = 0xf0f0f0;
const ACCENT: u32 = 0xffc040;

fn text_scale(width: u32) -> u32 {
    if width >= 1600 {
        2
    } else {
        1
    }
}

fn panel(canvas: &mut Canvas, x: i32, y: i32, lines: &[(String, u32)], scale: u32) {
    let line_h = (GLYPH + 3) * scale;
    let cols = lines.iter().map(|(l, _)| l.len()).max().unwrap_or(0) as u32;
    let pad = 4 * scale;
    canvas.shade(x, y, cols * GLYPH * scale + 2 * pad, lines.len() as u32 * line_h + 2 * pad, 80);
    for (i, (line, color)) in lines.iter().enumerate() {
        canvas.text(x + pad as i32, y + (pad + i as u32 * line_h) as i32, line, *color, scale);
    }
}

pub fn draw_hud(canvas: &mut Canvas, info: &HudInfo) {
    let fps = if info.frame_avg > 0.0 { 1.0 / info.frame_avg } else { 0.0 };
    let p = info.position;
    let lines = [
        (format!("{fps:6.1} fps   {}", info.state), ACCENT),
        (format!("frame {:6.1} ms avg {:6.1} ms p95", info.frame_avg * 1e3, info.frame_p95 * 1e3), TEXT),
        (format!("scale {:4.2}  ({} x {})", info.scale, info.internal.0, info.internal.1), TEXT),
        (format!("{:7.2} Mrays/s", info.rays_per_s / 1e6), TEXT),
        (format!("pos <{:.2}, {:.2}, {:.2}>", p.x, p.y, p.z), TEXT),
        (format!("speed {:.2}/s  quality {} ({})", info.speed, info.quality, info.precision), TEXT),
    ];
    panel(canvas, 8, 8, &lines, text_scale(canvas.width));
}

pub const HELP: &[&str] = &[
    "WASD / arrows   move",
    "E / Space       up",
    "Q / Ctrl        down",
    "Shift / Alt     faster / slower",
    "wheel           speed in steps",
    "right mouse     look (Esc releases)",
    "Esc             release mouse, quit",
    "R               reset camera",
    "F2              quality preset",
    "F5              reload scene (also on save)",
    "F12             screenshot PNG",
    "P               print camera {}",
    "F1 / Start      this help + HUD",
    "pad: sticks move/look, triggers",
    "     down/up, bumpers speed",
];

pub fn draw_help(canvas: &mut Canvas) {
    let scale = text_scale(canvas.width);
    let lines: Vec<(String, u32)> = HELP.iter().map(|l| (l.to_string(), TEXT)).collect();
    let w = (HELP.iter().map(|l| l.len()).max().unwrap_or(0) as u32 * GLYPH + 8) * scale;
    let x = canvas.width as i32 - w as i32 - 8;
    panel(canvas, x.max(8), 8, &lines, scale);
}

/// Red-ish, readable on both the dark panel and a bright scene.
const ERROR: u32 = 0xff6060;
/// Lines of a scene error shown: `file:line:col: message`, the source line and the caret.
const ERROR_LINES: usize = 4;

/// A failed reload's located error, along the bottom edge. Drawn whether or not the HUD is on:
/// the scene on screen is the last good one, and the user must see why their edit is not.
pub fn draw_error(canvas: &mut Canvas, message: &str) {
    let scale = text_scale(canvas.width);
    let cols = ((canvas.width.saturating_sub(32) / (GLYPH * scale)) as usize).max(8);
    let mut lines: Vec<(String, u32)> = vec![("reload failed, showing the last good scene:".into(), TEXT)];
    for line in message.lines().take(ERROR_LINES) {
        // Tabs would draw as one glyph and break the caret's column: widen them to one space.
        let line: String = line.replace('\t', " ").chars().take(cols).collect();
        lines.push((line, ERROR));
    }
    let line_h = (GLYPH + 3) * scale;
    let height = lines.len() as u32 * line_h + 8 * scale;
    let y = canvas.height as i32 - height as i32 - 8;
    panel(canvas, 8, y.max(0), &lines, scale);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_time_summary() {
        let mut t = FrameTimes::new(100);
        assert_eq!(t.summary(), (0.0, 0.0));
        for i in 1..=200 {
            t.push(Duration::from_millis(if i % 20 == 0 { 100 } else { 10 }));
        }
        let (avg, p95) = t.summary();
        assert!((avg - 0.0145).abs() < 1e-9, "{avg}");
        assert!((p95 - 0.100).abs() < 1e-9 || (p95 - 0.010).abs() < 1e-9);
    }

    #[test]
    fn a_reload_error_is_drawn_in_red_along_the_bottom() {
        let (w, h) = (640u32, 480u32);
        let mut px = vec![0x808080; (w * h) as usize];
        let mut c = Canvas { pixels: &mut px, width: w, height: h };
        let long = "x".repeat(500);
        draw_error(&mut c, &format!("s.pov:2:3: unknown keyword `locaton`\n  locaton {long}\n  ^\nmore\nand more"));
        let red_rows: Vec<usize> =
            (0..h as usize).filter(|y| px[y * w as usize..(y + 1) * w as usize].contains(&ERROR)).collect();
        assert!(!red_rows.is_empty());
        assert!(red_rows[0] > h as usize / 2, "the message sits in the lower half");
        assert!(px[..w as usize * 8].iter().all(|&p| p == 0x808080), "the top (HUD) is untouched");
    }

    #[test]
    fn hud_and_help_draw_on_tiny_surfaces() {
        let info = HudInfo {
            frame_avg: 0.016,
            frame_p95: 0.020,
            scale: 0.5,
            internal: (320, 240),
            rays_per_s: 2e7,
            position: DVec3::ONE,
            speed: 2.0,
            quality: "full",
            precision: Precision::F64,
            state: "moving",
        };
        for (w, h) in [(1, 1), (50, 20), (640, 480)] {
            let mut px = vec![0x808080; (w * h) as usize];
            let mut c = Canvas { pixels: &mut px, width: w, height: h };
            draw_hud(&mut c, &info);
            draw_help(&mut c);
            draw_error(&mut c, "s.pov:2:3: unknown keyword `locaton`\n    locaton <0,0,0>\n    ^");
        }
    }
}
