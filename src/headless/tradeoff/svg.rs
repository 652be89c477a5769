//! The trade-off plot as hand-written SVG: frame time against 1 − SSIM, both on log axes (the
//! settings span two decades of time and several of error), one labelled circle per setting, and
//! the Pareto front drawn as a line through its (filled) points.

use std::fmt::Write as _;

use super::report::{Context, Row};

const WIDTH: f64 = 900.0;
const HEIGHT: f64 = 560.0;
/// Plot area: room on the left and bottom for tick labels, on the right for point labels.
const LEFT: f64 = 80.0;
const RIGHT: f64 = WIDTH - 40.0;
const TOP: f64 = 50.0;
const BOTTOM: f64 = HEIGHT - 60.0;

/// A log axis from `lo` to `hi` (both positive) onto pixels `a..b`.
struct LogAxis {
    lo: f64,
    hi: f64,
    a: f64,
    b: f64,
}

impl LogAxis {
    /// The span of the positive values plus a margin (1..10 if there are none).
    fn around(values: impl Iterator<Item = f64>, a: f64, b: f64) -> LogAxis {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.filter(|v| v.is_finite() && *v > 0.0) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if lo > hi {
            (lo, hi) = (1.0, 10.0);
        }
        // A margin of ×1.4 each way, so no point sits on a frame edge and the leftmost label fits.
        LogAxis { lo: lo / 1.4, hi: hi * 1.4, a, b }
    }

    /// Pixel of `v`; values at or below `lo` (an exact match's error of 0) sit on the edge.
    fn map(&self, v: f64) -> f64 {
        let v = if v.is_finite() && v > self.lo { v.min(self.hi) } else { self.lo };
        self.a + (v / self.lo).log10() / (self.hi / self.lo).log10() * (self.b - self.a)
    }

    /// Ticks inside the axis at 1, 2 and 5 per decade over up to three decades, else at whole
    /// decades.
    fn ticks(&self) -> Vec<(f64, String)> {
        let (k0, k1) = (self.lo.log10().floor() as i32, self.hi.log10().ceil() as i32);
        let steps: &[f64] = if (self.hi / self.lo).log10() <= 3.0 { &[1.0, 2.0, 5.0] } else { &[1.0] };
        let mut out = Vec::new();
        for k in k0..=k1 {
            for &m in steps {
                let v = m * 10f64.powi(k);
                if (self.lo..=self.hi).contains(&v) {
                    let label = if (-3..=4).contains(&k) {
                        format!("{:.*}", (-k).max(0) as usize, v)
                    } else {
                        format!("{m}e{k}")
                    };
                    out.push((v, label));
                }
            }
        }
        out
    }
}

/// Average width of a character at font size 12, and how far text reaches above and below its
/// baseline, in pixels.
const CHAR: f64 = 6.6;
const ASCENT: f64 = 10.0;
const DESCENT: f64 = 3.0;

/// A box labels must not overlap: (left, right, top, bottom).
type Box = (f64, f64, f64, f64);

/// Writes one label per point, left to right. Settings that cost the same often land on one
/// spot (knobs the scene does not use change nothing), so a label that would overlap a point or
/// a label already placed moves down below it, with a leader line back to its point.
fn labels(o: &mut String, rows: &[Row], x: &LogAxis, y: &LogAxis) {
    let mut order: Vec<(f64, f64, &str)> =
        rows.iter().map(|r| (x.map(r.ms), y.map(r.error()), r.name.as_str())).collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let mut taken: Vec<Box> = order.iter().map(|&(px, py, _)| (px - 5.0, px + 5.0, py - 5.0, py + 5.0)).collect();
    for (px, py, name) in order {
        let width = CHAR * name.chars().count() as f64;
        // Labels go left of points in the right quarter so they stay inside the picture.
        let right_side = px <= RIGHT - (RIGHT - LEFT) / 4.0;
        let left = if right_side { px + 8.0 } else { px - 8.0 - width };
        let mut base = py - 6.0;
        // Each step moves the baseline below one box it hit, so the loop ends.
        while let Some(&(_, _, _, bottom)) =
            taken.iter().find(|&&(l, r, t, b)| l < left + width && left < r && t < base + DESCENT && base - ASCENT < b)
        {
            base = bottom + ASCENT + 0.5;
        }
        taken.push((left, left + width, base - ASCENT, base + DESCENT));
        let (tx, anchor) = if right_side { (left, "start") } else { (left + width, "end") };
        if base > py + 1.0 {
            let _ = writeln!(
                o,
                r##"<line x1="{px:.1}" y1="{py:.1}" x2="{tx:.1}" y2="{:.1}" stroke="#9a9a9a"/>"##,
                base - 4.0
            );
        }
        let _ = writeln!(o, r#"<text x="{tx:.1}" y="{base:.1}" text-anchor="{anchor}">{}</text>"#, escape(name));
    }
}

/// Font size of the title line.
const TITLE_SIZE: f64 = 15.0;

/// The title, `Speed against error: SCENE at WxH, CAMERAS`, cut to what fits between the left
/// margin and the right edge: scene and path names can be any length, so the long ones lose
/// their middle (`elide`), the camera text keeping up to half the room.
fn title(ctx: &Context) -> String {
    let fits = ((WIDTH - LEFT - 10.0) / (CHAR * TITLE_SIZE / 12.0)) as usize;
    let (lead, size) = ("Speed against error: ", format!(" at {}x{}, ", ctx.width, ctx.height));
    let room = fits.saturating_sub(lead.len() + size.len());
    let (scene, cameras) = (ctx.scene.chars().count(), ctx.cameras.chars().count());
    let for_cameras = cameras.min((room / 2).max(room.saturating_sub(scene)));
    format!("{lead}{}{size}{}", elide(&ctx.scene, room - for_cameras), elide(&ctx.cameras, for_cameras))
}

/// `text` in at most `max` characters: a long one loses its middle to a `…`, keeping about a
/// third from the start and the rest from the end, more if the file name (after the last `/`)
/// needs it, so a path keeps where it starts and what it names.
fn elide(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_string();
    }
    let keep = max.saturating_sub(1);
    let file = text.rfind('/').map_or(0, |i| text[i..].chars().count());
    let tail = (keep - keep / 3).max(file).min(keep);
    let head = keep - tail;
    let mut out: String = text.chars().take(head).collect();
    out.push('…');
    out.extend(text.chars().skip(n - tail));
    out
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The SVG document.
pub fn plot(rows: &[Row], ctx: &Context) -> String {
    let x = LogAxis::around(rows.iter().map(|r| r.ms), LEFT, RIGHT);
    let y = LogAxis::around(rows.iter().map(Row::error), BOTTOM, TOP);
    let mut o = String::new();
    let _ = writeln!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(o, r#"<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>"#);
    let _ = writeln!(o, r#"<text x="{LEFT}" y="24" font-size="{TITLE_SIZE}">{}</text>"#, escape(&title(ctx)));
    for (v, label) in x.ticks() {
        let px = x.map(v);
        let _ = writeln!(o, r##"<line x1="{px:.1}" y1="{TOP}" x2="{px:.1}" y2="{BOTTOM}" stroke="#e4e4e4"/>"##);
        let _ = writeln!(o, r#"<text x="{px:.1}" y="{}" text-anchor="middle">{label}</text>"#, BOTTOM + 18.0);
    }
    for (v, label) in y.ticks() {
        let py = y.map(v);
        let _ = writeln!(o, r##"<line x1="{LEFT}" y1="{py:.1}" x2="{RIGHT}" y2="{py:.1}" stroke="#e4e4e4"/>"##);
        let _ = writeln!(o, r#"<text x="{}" y="{:.1}" text-anchor="end">{label}</text>"#, LEFT - 6.0, py + 4.0);
    }
    let _ = writeln!(
        o,
        r#"<rect x="{LEFT}" y="{TOP}" width="{}" height="{}" fill="none" stroke="black"/>"#,
        RIGHT - LEFT,
        BOTTOM - TOP
    );
    let _ = writeln!(
        o,
        r#"<text x="{}" y="{}" text-anchor="middle">median ms per frame (log scale)</text>"#,
        (LEFT + RIGHT) / 2.0,
        HEIGHT - 18.0
    );
    let _ = writeln!(
        o,
        r#"<text transform="translate(20 {}) rotate(-90)" text-anchor="middle">1 − SSIM against the reference (log scale; 0 on the bottom edge)</text>"#,
        (TOP + BOTTOM) / 2.0
    );
    // The front, in order of increasing time (`mark_front` keeps no order, so sort here).
    let mut front: Vec<&Row> = rows.iter().filter(|r| r.front).collect();
    front.sort_by(|a, b| a.ms.total_cmp(&b.ms));
    let points: Vec<String> = front.iter().map(|r| format!("{:.1},{:.1}", x.map(r.ms), y.map(r.error()))).collect();
    let _ =
        writeln!(o, r##"<polyline points="{}" fill="none" stroke="#d62728" stroke-width="1.5"/>"##, points.join(" "));
    for r in rows {
        let (px, py) = (x.map(r.ms), y.map(r.error()));
        let (fill, radius) = if r.front { ("#d62728", 5.0) } else { ("#9a9a9a", 4.0) };
        let _ = writeln!(
            o,
            r#"<circle cx="{px:.1}" cy="{py:.1}" r="{radius}" fill="{fill}" stroke="black" stroke-width="0.5"><title>{} ({:.2} ms, SSIM {:.4})</title></circle>"#,
            escape(&r.name),
            r.ms,
            r.ssim
        );
    }
    labels(&mut o, rows, &x, &y);
    let _ = writeln!(
        o,
        r##"<text x="{}" y="{}" text-anchor="end" fill="#d62728">● Pareto front (no setting is both faster and closer)</text>"##,
        RIGHT - 6.0,
        TOP + 16.0
    );
    o.push_str("</svg>\n");
    o
}

#[cfg(test)]
mod tests {
    use super::super::report::tests::rows;
    use super::*;

    /// Checks that tags nest and attributes are quoted: enough to catch a broken writer.
    fn well_formed(svg: &str) -> Result<(), String> {
        let mut stack = Vec::new();
        let mut rest = svg;
        while let Some(start) = rest.find('<') {
            let end = rest[start..].find('>').ok_or("unclosed tag")? + start;
            let tag = &rest[start + 1..end];
            if !tag.matches('"').count().is_multiple_of(2) {
                return Err(format!("unbalanced quotes in <{tag}>"));
            }
            if let Some(name) = tag.strip_prefix('/') {
                if stack.pop() != Some(name.trim().to_string()) {
                    return Err(format!("</{name}> closes nothing open"));
                }
            } else if !tag.ends_with('/') {
                stack.push(tag.split_whitespace().next().unwrap_or("").to_string());
            }
            rest = &rest[end + 1..];
        }
        if stack.is_empty() {
            Ok(())
        } else {
            Err(format!("unclosed: {stack:?}"))
        }
    }

    fn ctx() -> Context {
        Context {
            scene: "a<b>.pov".into(),
            width: 64,
            height: 48,
            cameras: "the scene camera".into(),
            repeats: 3,
            threads: 1,
            cpu: "cpu".into(),
        }
    }

    #[test]
    fn one_circle_per_setting_and_well_formed() {
        let rows = rows(&[
            ("res-scale 0.25", 1.5, 0.7),
            ("no-shadows", 8.0, 0.6),
            ("preset full", 10.0, 0.95),
            ("aa 2", 38.0, 0.99),
            ("preset reference", 150.0, 1.0),
        ]);
        let svg = plot(&rows, &ctx());
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        well_formed(&svg).unwrap_or_else(|e| panic!("{e}\n{svg}"));
        assert_eq!(svg.matches("<circle").count(), rows.len());
        assert!(svg.contains("a&lt;b&gt;.pov"));
        // The front (all but no-shadows, which is slower and worse than res-scale 0.25) is one
        // polyline through 4 points, filled red.
        let front = rows.iter().filter(|r| r.front).count();
        assert_eq!(front, 4);
        assert_eq!(svg.matches("r=\"5\" fill=\"#d62728\"").count(), front);
        let line = svg.lines().find(|l| l.starts_with("<polyline")).unwrap_or_default();
        assert_eq!(line.split("points=\"").nth(1).unwrap_or("").split('"').next().unwrap_or("").split(' ').count(), 4);
    }

    #[test]
    fn empty_and_exact_inputs_still_plot() {
        let svg = plot(&[], &ctx());
        well_formed(&svg).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(svg.matches("<circle").count(), 0);
        let svg = plot(&rows(&[("preset reference", 100.0, 1.0)]), &ctx());
        well_formed(&svg).unwrap_or_else(|e| panic!("{e}"));
        assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
    }

    #[test]
    fn svg_title_of_a_long_scene_path_stays_inside_the_width() {
        let deep = format!("/home/someone/{}/scenes/very_long_scene_name.pov", "nested/folder".repeat(20));
        let along = format!("9 cameras along /srv/{}/orbit.path", "x".repeat(150));
        let rows = rows(&[("preset full", 10.0, 0.95)]);
        for (scene, cameras) in [(deep.as_str(), "the scene camera"), ("s.pov", along.as_str()), (&deep, &along)] {
            let ctx = Context { scene: scene.into(), cameras: cameras.into(), ..ctx() };
            let svg = plot(&rows, &ctx);
            well_formed(&svg).unwrap_or_else(|e| panic!("{e}"));
            let line = svg.lines().find(|l| l.contains("Speed against error")).unwrap_or_default();
            let text = line.split('>').nth(1).unwrap_or("").split('<').next().unwrap_or("");
            let text = text.replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
            let width = text.chars().count() as f64 * CHAR * TITLE_SIZE / 12.0;
            assert!(LEFT + width <= WIDTH, "{width} px from {LEFT} overflows {WIDTH}: {text}");
            // What tells the runs apart stays: the size and the ends of the names.
            assert!(text.contains(" at 64x48, "), "{text}");
            let file = scene.rsplit('/').next().unwrap_or_default();
            assert!(text.contains(file) && text.contains(&cameras[cameras.len() - 10..]), "{text}");
        }
        // Short names are left whole.
        assert_eq!(title(&ctx()), "Speed against error: a<b>.pov at 64x48, the scene camera");
        assert_eq!(elide("abcdefghij", 4), "a…ij");
        assert_eq!(elide("abc", 3), "abc");
    }

    #[test]
    fn log_ticks() {
        let a = LogAxis::around([3.0, 40.0].into_iter(), 0.0, 100.0);
        let labels: Vec<String> = a.ticks().into_iter().map(|(_, l)| l).collect();
        assert_eq!(labels, ["5", "10", "20", "50"]);
        assert!((a.map(3.0 / 1.4) - 0.0).abs() < 1e-9 && (a.map(40.0 * 1.4) - 100.0).abs() < 1e-9);
        assert_eq!(a.map(0.0), 0.0, "0 sits on the low edge");
        let e = LogAxis::around([0.002, 0.3].into_iter(), 0.0, 1.0);
        let labels: Vec<String> = e.ticks().into_iter().map(|(_, l)| l).collect();
        assert_eq!(labels, ["0.002", "0.005", "0.01", "0.02", "0.05", "0.1", "0.2"]);
        let wide = LogAxis::around([1e-5, 0.5].into_iter(), 0.0, 1.0);
        let labels: Vec<String> = wide.ticks().into_iter().map(|(_, l)| l).collect();
        assert_eq!(labels, ["1e-5", "1e-4", "0.001", "0.01", "0.1"]);
    }
}
