//! The heads-up display and help overlay, drawn into the presented framebuffer after the blit.

use std::time::Duration;

use glam::DVec3;

use crate::app::font::{Canvas, GLYPH};
use crate::app::render_thread::Progress;
use crate::render::precision::Precision;

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
    /// Average and 95th percentile of the gaps between frames presented while moving.
    pub frame_avg: f64,
    pub frame_p95: f64,
    /// How long the frame on screen took to render.
    pub render_time: Duration,
    pub scale: f64,
    pub internal: (u32, u32),
    pub rays_per_s: f64,
    pub position: DVec3,
    pub speed: f64,
    pub quality: &'a str,
    /// The arithmetic the quality preset traces in.
    pub precision: Precision,
    /// Moving, refining or converged: what the frame on screen is.
    pub progress: Progress,
    /// What the scene uses that strahl renders without (`SceneDesc::unmodelled`), by name.
    pub unmodelled: &'a [String],
}

const TEXT: u32 = 0xf0f0f0;
const ACCENT: u32 = 0xffc040;
/// The "not modelled" lines: a warning, but not the red of an error.
const WARN: u32 = 0xff9a50;
/// The widest "not modelled" line, in characters: about the width of the HUD's other lines.
const UNMODELLED_COLS: usize = 36;
/// "not modelled" lines at most; the rest is counted ("+3 more").
const UNMODELLED_ROWS: usize = 3;
/// Gap between the panels and the window's edges, and between panels.
const MARGIN: i32 = 8;

fn text_scale(width: u32) -> u32 {
    if width >= 1600 {
        2
    } else {
        1
    }
}

/// A rectangle of window pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    pub x: i32,
    pub y: i32,
    pub w: u32,
    pub h: u32,
}

impl Rect {
    pub fn right(&self) -> i32 {
        self.x + self.w as i32
    }

    pub fn bottom(&self) -> i32 {
        self.y + self.h as i32
    }

    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x < o.right() && o.x < self.right() && self.y < o.bottom() && o.y < self.bottom()
    }
}

fn line_height(scale: u32) -> u32 {
    (GLYPH + 3) * scale
}

/// The size of a panel holding `lines`: text plus padding on each side.
fn panel_size<'a>(lines: impl ExactSizeIterator<Item = &'a str>, scale: u32) -> (u32, u32) {
    let rows = lines.len() as u32;
    let cols = lines.map(|l| l.chars().count()).max().unwrap_or(0) as u32;
    let pad = 4 * scale;
    (cols * GLYPH * scale + 2 * pad, rows * line_height(scale) + 2 * pad)
}

fn panel(canvas: &mut Canvas, at: Rect, lines: &[(String, u32)], scale: u32) {
    let pad = 4 * scale;
    canvas.shade(at.x, at.y, at.w, at.h, 80);
    for (i, (line, color)) in lines.iter().enumerate() {
        canvas.text(at.x + pad as i32, at.y + (pad + i as u32 * line_height(scale)) as i32, line, *color, scale);
    }
}

/// `v` to three significant digits, so a speed or position reads the same at any scene scale.
fn significant(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || !a.is_finite() {
        format!("{v}")
    } else if (1e-2..1e5).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.2e}")
    }
}

/// The HUD's lines. While moving, frames presented per second and their spacing; once the view
/// is still no new frames arrive for long stretches, so the spacing would read as a slow
/// renderer: the HUD shows the render time of the frame on screen and how far it has refined.
pub fn hud_lines(info: &HudInfo) -> Vec<(String, u32)> {
    let p = info.position;
    let (head, timing) = match info.progress {
        Progress::Moving => {
            let fps = if info.frame_avg > 0.0 { 1.0 / info.frame_avg } else { 0.0 };
            (
                format!("{fps:6.1} fps   moving"),
                format!("frame {:6.1} ms avg {:6.1} ms p95", info.frame_avg * 1e3, info.frame_p95 * 1e3),
            )
        }
        progress => {
            let state = match progress {
                p if p.is_converged() => "converged".to_string(),
                Progress::Refining { pass, total } => format!("AA {pass}/{total}"),
                Progress::Moving => unreachable!("handled above"),
            };
            (state, format!("render {:6.1} ms (last frame)", info.render_time.as_secs_f64() * 1e3))
        }
    };
    let mut lines = vec![
        (head, ACCENT),
        (timing, TEXT),
        (format!("scale {:4.2}  ({} x {})", info.scale, info.internal.0, info.internal.1), TEXT),
        (format!("{:7.2} Mrays/s", info.rays_per_s / 1e6), TEXT),
        (format!("pos <{}, {}, {}>", significant(p.x), significant(p.y), significant(p.z)), TEXT),
        (format!("speed {}/s", significant(info.speed)), TEXT),
        (format!("quality {} ({})", info.quality, info.precision), TEXT),
    ];
    lines.extend(unmodelled_lines(info.unmodelled, UNMODELLED_COLS, UNMODELLED_ROWS).into_iter().map(|l| (l, WARN)));
    lines
}

/// "not modelled: media, radiosity" as rows of at most `cols` characters (a name longer than
/// a row is cut with `~`), at most `rows` of them, the last ending "+N more" when names are
/// left over. No rows for a scene that uses nothing unmodelled.
pub fn unmodelled_lines(names: &[String], cols: usize, rows: usize) -> Vec<String> {
    if names.is_empty() || rows == 0 {
        return Vec::new();
    }
    let cols = cols.max(16);
    let fit = |name: &str, room: usize| -> String {
        if name.chars().count() <= room {
            name.to_string()
        } else {
            name.chars().take(room.saturating_sub(1)).chain(['~']).collect()
        }
    };
    let mut out = vec![String::from("not modelled:")];
    for (i, name) in names.iter().enumerate() {
        let last_row = out.len() == rows;
        let more = names.len() - i - 1;
        // On the last row, keep room for "+N more" unless this is the last name.
        let tail = if last_row && more > 0 { format!(", +{more} more").len() } else { 0 };
        let sep = if out.last().is_some_and(|l| l.ends_with(':')) { " " } else { ", " };
        let row = out.last_mut().unwrap_or_else(|| unreachable!("out starts with one row"));
        let used = row.chars().count() + sep.len();
        let name_len = name.chars().count();
        if used + name_len + tail <= cols {
            row.push_str(sep);
            row.push_str(name);
            continue;
        }
        if !last_row && 2 + name_len.min(cols - 2) <= cols {
            // A new row, indented under the label.
            if !row.ends_with(':') {
                row.push(',');
            }
            out.push(format!("  {}", fit(name, cols - 2)));
            continue;
        }
        // The last row is full: count what is left, this name included.
        let left = names.len() - i;
        let note = format!(" +{left} more");
        let row = out.last_mut().unwrap_or_else(|| unreachable!("out starts with one row"));
        while row.chars().count() + note.len() > cols {
            row.pop();
        }
        row.push_str(&note);
        break;
    }
    out
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

/// Where the HUD (`hud`: its lines) and the help go in a `width`×`height` window: the HUD at the
/// top left, the help at the top right where both fit side by side, else under the HUD, so they
/// never cover each other where the window has room for both.
pub fn overlay_layout(width: u32, hud: &[(String, u32)]) -> (Rect, Rect) {
    let scale = text_scale(width);
    let (hw, hh) = panel_size(hud.iter().map(|(l, _)| l.as_str()), scale);
    let (pw, ph) = panel_size(HELP.iter().copied(), scale);
    let hud = Rect { x: MARGIN, y: MARGIN, w: hw, h: hh };
    let beside = width as i32 - MARGIN - pw as i32;
    let help = if beside >= hud.right() + MARGIN {
        Rect { x: beside, y: MARGIN, w: pw, h: ph }
    } else {
        Rect { x: MARGIN, y: hud.bottom() + MARGIN, w: pw, h: ph }
    };
    (hud, help)
}

/// The HUD and the key help, laid out by [`overlay_layout`].
pub fn draw_hud_and_help(canvas: &mut Canvas, info: &HudInfo) {
    let scale = text_scale(canvas.width);
    let hud = hud_lines(info);
    let (hud_at, help_at) = overlay_layout(canvas.width, &hud);
    panel(canvas, hud_at, &hud, scale);
    let help: Vec<(String, u32)> = HELP.iter().map(|l| (l.to_string(), TEXT)).collect();
    panel(canvas, help_at, &help, scale);
}

/// Red-ish, readable on both the dark panel and a bright scene.
const ERROR: u32 = 0xff6060;
/// Lines of a scene error shown: `file:line:col: message`, the source line and the caret.
const ERROR_LINES: usize = 4;

/// `message`'s first [`ERROR_LINES`] lines as rows of at most `cols` characters. The first line
/// (`file:line:col: message`) breaks at spaces where it can; the others (the source line and
/// its caret) break at exactly `cols`, so the caret stays under its column within the rows.
pub fn wrap_error(message: &str, cols: usize) -> Vec<String> {
    let cols = cols.max(1);
    let mut rows = Vec::new();
    for (i, line) in message.lines().take(ERROR_LINES).enumerate() {
        // Tabs would draw as one glyph and break the caret's column: widen them to one space.
        let mut rest: Vec<char> = line.replace('\t', " ").chars().collect();
        loop {
            if rest.len() <= cols {
                rows.push(rest.iter().collect());
                break;
            }
            let mut cut = cols;
            if i == 0 {
                if let Some(space) = rest[1..=cols].iter().rposition(|&c| c == ' ') {
                    cut = space + 1;
                }
            }
            let row: String = rest[..cut].iter().collect();
            rows.push(row.trim_end().to_string());
            rest.drain(..cut);
            if i == 0 {
                let spaces = rest.iter().take_while(|&&c| c == ' ').count();
                rest.drain(..spaces);
            }
        }
    }
    rows
}

/// A failed reload's located error, along the bottom edge, wrapped to the window's width and
/// kept to its lower third. Drawn whether or not the HUD is on: the scene on screen is the last
/// good one, and the user must see why their edit is not.
pub fn draw_error(canvas: &mut Canvas, message: &str) {
    let scale = text_scale(canvas.width);
    let cols = ((canvas.width.saturating_sub(2 * MARGIN as u32 + 8 * scale) / (GLYPH * scale)) as usize).max(8);
    let max_rows = ((canvas.height / 3 / line_height(scale)) as usize).max(2);
    let mut lines: Vec<(String, u32)> = vec![("reload failed, showing the last good scene:".into(), TEXT)];
    let mut rows = wrap_error(message, cols);
    if rows.len() > max_rows - 1 {
        rows.truncate(max_rows - 2);
        rows.push("...".into());
    }
    lines.extend(rows.into_iter().map(|r| (r, ERROR)));
    let (w, h) = panel_size(lines.iter().map(|(l, _)| l.as_str()), scale);
    let y = canvas.height as i32 - h as i32 - MARGIN;
    panel(canvas, Rect { x: MARGIN, y: y.max(0), w, h }, &lines, scale);
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

    fn info(progress: Progress) -> HudInfo<'static> {
        HudInfo {
            frame_avg: 0.698,
            frame_p95: 0.800,
            render_time: Duration::from_micros(23_400),
            scale: 1.0,
            internal: (640, 480),
            rays_per_s: 2e7,
            position: DVec3::new(-1234.5678, 0.001234, 98765.4),
            speed: 2.23,
            quality: "command line",
            precision: Precision::F64,
            progress,
            unmodelled: &[],
        }
    }

    #[test]
    fn hud_and_help_draw_on_tiny_surfaces() {
        let info = info(Progress::Moving);
        for (w, h) in [(1, 1), (50, 20), (640, 480)] {
            let mut px = vec![0x808080; (w * h) as usize];
            let mut c = Canvas { pixels: &mut px, width: w, height: h };
            draw_hud_and_help(&mut c, &info);
            draw_error(&mut c, "s.pov:2:3: unknown keyword `locaton`\n    locaton <0,0,0>\n    ^");
        }
    }

    /// At 640×480 the help box was drawn over the HUD (`quality command linright mouse`).
    #[test]
    fn hud_and_help_do_not_overlap_at_640x480() {
        for (w, h) in [(640u32, 480u32), (800, 600), (1280, 720), (1920, 1080), (3840, 2160)] {
            for progress in [Progress::Moving, Progress::Refining { pass: 9, total: 9 }] {
                let lines = hud_lines(&info(progress));
                let (hud, help) = overlay_layout(w, &lines);
                assert!(!hud.overlaps(&help), "{w}x{h}: {hud:?} and {help:?}");
                for r in [hud, help] {
                    assert!(r.x >= 0 && r.y >= 0 && r.right() <= w as i32 && r.bottom() <= h as i32, "{w}x{h}: {r:?}");
                }
                // The panels are as wide as their text: nothing is drawn past them.
                let scale = text_scale(w);
                assert_eq!(panel_size(lines.iter().map(|(l, _)| l.as_str()), scale), (hud.w, hud.h));
            }
        }
        // Wide windows keep them side by side at the top.
        let (hud, help) = overlay_layout(1280, &hud_lines(&info(Progress::Moving)));
        assert_eq!((hud.y, help.y), (MARGIN, MARGIN));
    }

    /// A reload error longer than the window was cut off at the right edge.
    #[test]
    fn a_long_reload_error_wraps_to_the_window_width() {
        let source = format!("  locaton <0, 2, -5> {}", "x".repeat(100));
        let message = format!("s.pov:2:3: unknown keyword `locaton` in camera (expected one of: location, look_at, angle, right, up, direction, sky)\n{source}\n  ^");
        let cols = 40;
        let rows = wrap_error(&message, cols);
        assert!(rows.iter().all(|r| r.chars().count() <= cols), "{rows:#?}");
        // The message breaks between words and loses none of them.
        let words: Vec<&str> = message.lines().next().unwrap().split(' ').collect();
        let head: Vec<&String> = rows.iter().take_while(|r| !r.starts_with("  locaton")).collect();
        assert!(head.len() >= 3, "{rows:#?}");
        let rewrapped: Vec<&str> = head.iter().flat_map(|r| r.split(' ')).collect();
        assert_eq!(rewrapped, words);
        // The source line breaks at exactly `cols`, every character kept, and the caret follows.
        let src_rows = &rows[head.len()..rows.len() - 1];
        assert_eq!(src_rows.concat(), source);
        assert_eq!(rows.last().unwrap(), "  ^");

        // Drawn at 640×480, the error takes several rows, all inside the window.
        let (w, h) = (640u32, 480u32);
        let mut px = vec![0x808080; (w * h) as usize];
        draw_error(&mut Canvas { pixels: &mut px, width: w, height: h }, &message);
        let red_rows: Vec<usize> =
            (0..h as usize).filter(|y| px[y * w as usize..(y + 1) * w as usize].contains(&ERROR)).collect();
        let text_rows = red_rows.windows(2).filter(|p| p[1] > p[0] + 1).count() + 1;
        assert!(text_rows >= 4, "{text_rows} rows of error text");
        let rightmost = (0..w as usize).rev().find(|&x| (0..h as usize).any(|y| px[y * w as usize + x] == ERROR));
        assert!(rightmost.unwrap() < w as usize - MARGIN as usize, "text reaches the edge");
    }

    /// A still view showed `1.4 fps / frame 698 ms`: the gap between presented frames.
    #[test]
    fn still_hud_shows_render_time_and_converged_not_the_frame_gap() {
        let text = |p| hud_lines(&info(p)).iter().map(|(l, _)| l.clone()).collect::<Vec<_>>().join("\n");
        let converged = text(Progress::Refining { pass: 4, total: 4 });
        assert!(converged.contains("converged") && converged.contains("render   23.4 ms"), "{converged}");
        assert!(!converged.contains("fps") && !converged.contains("698"), "{converged}");
        let refining = text(Progress::Refining { pass: 2, total: 4 });
        assert!(refining.contains("AA 2/4") && refining.contains("23.4 ms") && !refining.contains("fps"), "{refining}");
        let moving = text(Progress::Moving);
        assert!(moving.contains("1.4 fps   moving") && moving.contains("698.0 ms avg"), "{moving}");
        assert!(!moving.contains("converged"), "{moving}");
    }

    #[test]
    fn unmodelled_features_are_named_in_short_rows() {
        let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert!(unmodelled_lines(&[], 36, 3).is_empty());
        assert_eq!(unmodelled_lines(&names(&["media", "radiosity"]), 36, 3), ["not modelled: media, radiosity"]);
        let many = names(&[
            "media",
            "radiosity",
            "photons",
            "area_illumination",
            "fog turbulence",
            "interior_texture",
            "projected_through",
        ]);
        let rows = unmodelled_lines(&many, 36, 3);
        assert!(rows.len() <= 3 && rows.iter().all(|r| r.chars().count() <= 36), "{rows:#?}");
        assert!(rows[0].starts_with("not modelled: media"), "{rows:#?}");
        let last = rows.last().unwrap();
        assert!(last.ends_with(" more"), "{rows:#?}");
        // Every name is shown or counted.
        let shown = rows.join(" ").matches(',').count();
        let counted: usize = last.rsplit('+').next().unwrap().trim_end_matches(" more").parse().unwrap();
        assert!(shown + 1 + counted >= many.len() - 1, "{rows:#?}");
        let long = names(&[&"x".repeat(100)]);
        let rows = unmodelled_lines(&long, 36, 3);
        assert!(rows.iter().all(|r| r.chars().count() <= 36), "{rows:#?}");

        // In the HUD, in their own colour, after the other lines; the layout still fits.
        let mut i = info(Progress::Moving);
        let list = names(&["media", "radiosity"]);
        i.unmodelled = &list;
        let lines = hud_lines(&i);
        assert_eq!(lines.last().unwrap(), &("not modelled: media, radiosity".to_string(), WARN));
        let (hud, help) = overlay_layout(640, &lines);
        assert!(!hud.overlaps(&help));
    }

    #[test]
    fn speeds_and_positions_keep_three_significant_digits() {
        assert_eq!(significant(0.00223), "2.23e-3");
        assert_eq!(significant(2.234), "2.23");
        assert_eq!(significant(-1234.5678), "-1235");
        assert_eq!(significant(0.0), "0");
    }
}
