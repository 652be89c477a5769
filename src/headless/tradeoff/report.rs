//! The trade-off results as rows, their Pareto front, and the text, CSV and Markdown tables.

use std::fmt::Write as _;

use super::{Measure, Setting};
use crate::render::precision::Precision;

/// One measured setting, with its effective knob values.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The flags that select it, without the leading `--`: `res-scale 0.25`, `preset fast`.
    pub name: String,
    pub res_scale: f32,
    pub aa: u32,
    /// The effective `max_trace_level` (the scene's unless overridden).
    pub max_trace_level: u32,
    pub shadows: bool,
    /// `None`: as the scene's textures ask.
    pub max_octaves: Option<u32>,
    pub precision: Precision,
    /// Median frame time, and the lower and upper quartile of the repeats around it (see
    /// `Timing`).
    pub ms: f64,
    pub ms_lo: f64,
    pub ms_hi: f64,
    pub psnr_db: f64,
    pub ssim: f64,
    pub max_abs: u8,
    /// On the Pareto front of (ms, 1 − SSIM); set by `mark_front`.
    pub front: bool,
}

impl Row {
    pub fn new(s: &Setting, scene_level: u32, m: Measure) -> Row {
        Row {
            name: s.name.clone(),
            res_scale: s.res_scale,
            aa: s.aa,
            max_trace_level: s.quality.max_trace_level.unwrap_or(scene_level),
            shadows: s.quality.shadows,
            max_octaves: s.quality.max_octaves,
            precision: s.quality.precision,
            ms: m.ms,
            ms_lo: m.ms,
            ms_hi: m.ms,
            psnr_db: m.psnr_db,
            ssim: m.ssim,
            max_abs: m.max_abs,
            front: false,
        }
    }

    /// The error the front and the plot use: 1 − SSIM, 0 for a perfect match.
    pub fn error(&self) -> f64 {
        (1.0 - self.ssim).max(0.0)
    }

    /// The frame time as measured.
    pub fn timing(&self) -> Timing {
        Timing { lo: self.ms_lo, median: self.ms, hi: self.ms_hi }
    }

    /// Sets the frame time from a measurement.
    pub fn set_timing(&mut self, t: Timing) {
        (self.ms_lo, self.ms, self.ms_hi) = (t.lo, t.median, t.hi);
    }
}

/// A frame time as measured: the median of the repeats and the spread around it, from the lower
/// to the upper quartile (nearest rank; with 3 repeats that is their min and max). Two times
/// whose spreads overlap cannot be told apart on this machine: they tie.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    pub lo: f64,
    pub median: f64,
    pub hi: f64,
}

impl Timing {
    /// A time without spread (a single measurement, or a synthetic one).
    pub fn exact(ms: f64) -> Timing {
        Timing { lo: ms, median: ms, hi: ms }
    }

    fn is_nan(&self) -> bool {
        self.lo.is_nan() || self.median.is_nan() || self.hi.is_nan()
    }
}

/// The rule behind the ★, for the Markdown report.
pub const FRONT_RULE: &str = "★ marks the Pareto front of (ms, 1 − SSIM), with timing noise allowed for: a \
     setting's time is the spread of its repeats from the lower to the upper quartile (with 3 repeats, \
     their min and max; averaged over cameras), and two times tie when their spreads overlap. A setting \
     is off the front when another is at least as close to the reference and clearly faster (the spreads \
     do not overlap), or closer and not clearly slower. Settings with the same error whose times tie, \
     directly or through a chain of ties, count as one point and get one mark, so settings that render \
     the same image are always marked alike.";

/// Indices of the points on the Pareto front of (time, error), both minimised, in order of
/// increasing median time, by the rule in `FRONT_RULE`: points of equal error whose spreads
/// overlap (through chains too) are merged into one point spanning their spreads, and a merged
/// point is dominated by one that is no worse in error, not clearly slower, and either closer
/// or clearly faster. With exact times this is the ordinary Pareto front (equal points are all
/// kept). Points with a NaN coordinate are never on the front.
pub fn pareto_front(points: &[(Timing, f64)]) -> Vec<usize> {
    // (error, lo, hi, members) per merged point.
    let mut groups: Vec<(f64, f64, f64, Vec<usize>)> = Vec::new();
    let mut order: Vec<usize> = (0..points.len()).filter(|&i| !points[i].0.is_nan() && !points[i].1.is_nan()).collect();
    order.sort_by(|&a, &b| points[a].1.total_cmp(&points[b].1).then(points[a].0.lo.total_cmp(&points[b].0.lo)));
    for i in order {
        let (t, e) = points[i];
        // Sorted by error, then start of spread: a point joins the last group when it has the
        // same error and its spread starts before that group's ends.
        match groups.last_mut() {
            Some(g) if g.0 == e && t.lo <= g.2 => {
                g.2 = g.2.max(t.hi);
                g.3.push(i);
            }
            _ => groups.push((e, t.lo, t.hi, vec![i])),
        }
    }
    let dominates = |k: &(f64, f64, f64, Vec<usize>), l: &(f64, f64, f64, Vec<usize>)| {
        let not_slower = k.1 <= l.2;
        let clearly_faster = k.2 < l.1;
        k.0 <= l.0 && not_slower && (k.0 < l.0 || clearly_faster)
    };
    let mut front: Vec<usize> =
        groups.iter().filter(|g| !groups.iter().any(|k| dominates(k, g))).flat_map(|g| g.3.iter().copied()).collect();
    front.sort_by(|&a, &b| points[a].0.median.total_cmp(&points[b].0.median).then(points[a].1.total_cmp(&points[b].1)));
    front
}

/// Sets `front` on the rows on the Pareto front of (ms, 1 − SSIM).
pub fn mark_front(rows: &mut [Row]) {
    let points: Vec<(Timing, f64)> = rows.iter().map(|r| (r.timing(), r.error())).collect();
    let front = pareto_front(&points);
    for (i, r) in rows.iter_mut().enumerate() {
        r.front = front.contains(&i);
    }
}

/// Where and how the figures were taken, for the report headers.
pub struct Context {
    pub scene: String,
    pub width: u32,
    pub height: u32,
    /// "the scene camera" or "N cameras along PATH".
    pub cameras: String,
    pub repeats: u32,
    pub threads: usize,
    pub cpu: String,
}

impl Context {
    fn summary(&self) -> String {
        format!(
            "{} at {}x{}, {}; median of {} timed frames after one warm-up, {} threads on {}",
            self.scene, self.width, self.height, self.cameras, self.repeats, self.threads, self.cpu
        )
    }
}

/// Frame time relative to the `preset full` row (NaN without one).
fn speedup(rows: &[Row], r: &Row) -> f64 {
    rows.iter().find(|f| f.name == "preset full").map_or(f64::NAN, |f| f.ms / r.ms)
}

fn psnr_text(db: f64) -> String {
    if db.is_infinite() {
        "inf".into()
    } else {
        format!("{db:.2}")
    }
}

fn octaves_text(o: Option<u32>) -> String {
    o.map_or("scene".into(), |o| o.to_string())
}

pub const CSV_HEADER: &str =
    "setting,res_scale,aa,max_trace_level,shadows,max_octaves,precision,ms,ms_lo,ms_hi,speedup,psnr_db,ssim,one_minus_ssim,max_abs_err,front";

/// One line per row under `CSV_HEADER`. Numbers are plain decimals (`inf` for a PSNR of an
/// exact match); `max_octaves` is `scene` where the scene's own counts apply; `ms_lo` and
/// `ms_hi` are the spread of the repeats the front allows for (`Timing`).
pub fn csv(rows: &[Row]) -> String {
    let mut o = format!("{CSV_HEADER}\n");
    for r in rows {
        let _ = writeln!(
            o,
            "{},{},{},{},{},{},{},{:.3},{:.3},{:.3},{:.3},{},{:.6},{:.6},{},{}",
            r.name,
            r.res_scale,
            r.aa,
            r.max_trace_level,
            r.shadows,
            octaves_text(r.max_octaves),
            r.precision,
            r.ms,
            r.ms_lo,
            r.ms_hi,
            speedup(rows, r),
            psnr_text(r.psnr_db),
            r.ssim,
            r.error(),
            r.max_abs,
            r.front
        );
    }
    o
}

/// The report as Markdown: what was measured, then the table; the plot sits beside it as
/// `svg_name`.
pub fn markdown(rows: &[Row], ctx: &Context, svg_name: &str) -> String {
    let mut o = format!("# Speed/accuracy trade-off: `{}`\n\n", ctx.scene);
    let _ = writeln!(o, "{}.\n", ctx.summary());
    o.push_str(
        "Errors are against `--preset reference` (4×4 aa, hits re-solved in f64, everything else as the scene asks): PSNR over \
         all cameras' pixels, SSIM (8×8 blocks of luma) averaged over cameras, and the largest 8-bit \
         error of any channel in any frame. Each row moves one knob from `full`, except the presets. \
         Regenerate with `strahl tradeoff`.\n\n",
    );
    let _ = writeln!(o, "{FRONT_RULE}\n");
    o.push_str("| setting | ms | spread | speedup | PSNR dB | SSIM | 1 − SSIM | max abs err | front |\n");
    o.push_str("|---|--:|--:|--:|--:|--:|--:|--:|:-:|\n");
    for r in rows {
        let _ = writeln!(
            o,
            "| `--{}` | {:.2} | {:.2}–{:.2} | {:.2}× | {} | {:.4} | {:.5} | {} | {} |",
            r.name,
            r.ms,
            r.ms_lo,
            r.ms_hi,
            speedup(rows, r),
            psnr_text(r.psnr_db).replace("inf", "∞"),
            r.ssim,
            r.error(),
            r.max_abs,
            if r.front { "★" } else { "" }
        );
    }
    let _ = writeln!(o, "\n![frame time against 1 − SSIM, Pareto front drawn]({svg_name})");
    o
}

/// The table printed to stdout.
pub fn table(rows: &[Row], ctx: &Context) -> String {
    let mut o = format!("{}\n", ctx.summary());
    let width = rows.iter().map(|r| r.name.len()).max().unwrap_or(0).max(7);
    let _ = writeln!(
        o,
        "{:<width$}  {:>9}  {:>15}  {:>7}  {:>7}  {:>7}  {:>8}  {:>7}  front",
        "setting", "ms", "spread", "speedup", "PSNR dB", "SSIM", "1-SSIM", "max err"
    );
    for r in rows {
        let _ = writeln!(
            o,
            "{:<width$}  {:>9.2}  {:>15}  {:>6.2}x  {:>7}  {:>7.4}  {:>8.5}  {:>7}  {}",
            r.name,
            r.ms,
            format!("{:.2}-{:.2}", r.ms_lo, r.ms_hi),
            speedup(rows, r),
            psnr_text(r.psnr_db),
            r.ssim,
            r.error(),
            r.max_abs,
            if r.front { "*" } else { "" }
        );
    }
    o
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Rows with the given (name, ms, ssim), knobs as in `full`.
    pub fn rows(points: &[(&str, f64, f64)]) -> Vec<Row> {
        let mut rows: Vec<Row> = points
            .iter()
            .map(|&(name, ms, ssim)| Row {
                name: name.into(),
                res_scale: 1.0,
                aa: 1,
                max_trace_level: 5,
                shadows: true,
                max_octaves: None,
                precision: Precision::F32,
                ms,
                ms_lo: ms,
                ms_hi: ms,
                psnr_db: if ssim >= 1.0 { f64::INFINITY } else { 20.0 + 20.0 * ssim },
                ssim,
                max_abs: ((1.0 - ssim) * 255.0) as u8,
                front: false,
            })
            .collect();
        mark_front(&mut rows);
        rows
    }

    /// Points with exact times.
    fn exact(points: &[(f64, f64)]) -> Vec<(Timing, f64)> {
        points.iter().map(|&(ms, e)| (Timing::exact(ms), e)).collect()
    }

    /// A point whose repeats spread from `lo` to `hi` around `median`.
    fn spread(lo: f64, median: f64, hi: f64, error: f64) -> (Timing, f64) {
        (Timing { lo, median, hi }, error)
    }

    #[test]
    fn pareto_front_drops_dominated_points() {
        // (ms, error): c is dominated by b (slower and worse); d by a (same ms, worse error).
        let p = exact(&[(10.0, 0.5), (20.0, 0.1), (30.0, 0.2), (10.0, 0.6), (40.0, 0.0)]);
        assert_eq!(pareto_front(&p), vec![0, 1, 4]);
    }

    #[test]
    fn pareto_ties_within_spread_are_marked_alike() {
        // `res-scale 0.5` and `preset fast` render the same image; their medians differ by
        // 0.06 ms of noise inside each other's spread. Whichever comes out faster, both get
        // the same mark (on the front: nothing is clearly faster and as close).
        let slower = |a: f64, b: f64| {
            vec![
                spread(1.40, 1.50, 1.62, 0.19),
                spread(2.52, 2.60 + a, 2.70, 0.10),
                spread(2.55, 2.60 + b, 2.75, 0.10),
                spread(6.00, 6.20, 6.50, 0.064),
            ]
        };
        for p in [slower(0.0, 0.06), slower(0.06, 0.0)] {
            assert_eq!(pareto_front(&p), if p[1].0.median < p[2].0.median { [0, 1, 2, 3] } else { [0, 2, 1, 3] });
        }
        // Exact times would have split them: the 0.06 ms faster one alone on the front.
        let p = exact(&[(2.60, 0.10), (2.66, 0.10)]);
        assert_eq!(pareto_front(&p), vec![0]);
        // A chain of ties at one error is one point: a ties b, b ties c, a and c do not overlap;
        // all three share a mark, here off the front because d is as close and clearly faster
        // than all of them, and on it once d is gone.
        let mut p = vec![
            spread(2.0, 2.05, 2.1, 0.1),
            spread(2.08, 2.12, 2.16, 0.1),
            spread(2.14, 2.2, 2.3, 0.1),
            spread(1.0, 1.1, 1.2, 0.1),
        ];
        assert_eq!(pareto_front(&p), vec![3]);
        p.pop();
        assert_eq!(pareto_front(&p), vec![0, 1, 2]);
        // Clearly faster at the same error still dominates (a over b; c is closer but clearly
        // slower than a, so both stay); so does closer within the spread.
        let p = vec![spread(2.0, 2.1, 2.2, 0.1), spread(2.3, 2.4, 2.5, 0.1), spread(2.25, 2.35, 2.45, 0.05)];
        assert_eq!(pareto_front(&p), vec![0, 2]);
        let p = vec![spread(2.0, 2.1, 2.2, 0.1), spread(2.15, 2.25, 2.35, 0.1), spread(2.1, 2.3, 2.4, 0.05)];
        assert_eq!(pareto_front(&p), vec![2], "the closer one ties both in time");
    }

    #[test]
    fn mark_front_uses_the_spread_of_each_row() {
        let mut r = rows(&[("res-scale 0.5", 2.60, 0.9), ("preset fast", 2.66, 0.9)]);
        assert!(r[0].front && !r[1].front, "exact times: the faster one only");
        r[0].set_timing(Timing { lo: 2.5, median: 2.6, hi: 2.7 });
        r[1].set_timing(Timing { lo: 2.55, median: 2.66, hi: 2.8 });
        mark_front(&mut r);
        assert!(r[0].front && r[1].front);
    }

    #[test]
    fn pareto_front_keeps_ties_and_skips_nan() {
        // Two identical points: neither dominates the other, so both stay.
        let p = exact(&[(5.0, 0.3), (5.0, 0.3), (1.0, f64::NAN), (9.0, 0.1), (9.0, 0.3), (f64::NAN, 0.0)]);
        assert_eq!(pareto_front(&p), vec![0, 1, 3]);
        assert!(pareto_front(&[]).is_empty());
        assert_eq!(pareto_front(&exact(&[(1.0, 1.0)])), vec![0]);
        // Equal x: only the lower y survives; equal y: only the lower x.
        assert_eq!(pareto_front(&exact(&[(2.0, 1.0), (2.0, 0.5), (3.0, 0.5)])), vec![1]);
    }

    #[test]
    fn csv_parses_back() {
        let rows = rows(&[("res-scale 0.25", 2.5, 0.8), ("preset full", 10.0, 0.95), ("preset reference", 160.0, 1.0)]);
        let text = csv(&rows);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], CSV_HEADER);
        assert_eq!(lines.len(), 1 + rows.len());
        let header: Vec<&str> = CSV_HEADER.split(',').collect();
        let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{name}"));
        for (line, row) in lines[1..].iter().zip(&rows) {
            let f: Vec<&str> = line.split(',').collect();
            assert_eq!(f.len(), header.len(), "{line}");
            assert_eq!(f[col("setting")], row.name);
            let num = |name: &str| f[col(name)].parse::<f64>().unwrap_or_else(|e| panic!("{name} in {line}: {e}"));
            assert!((num("ms") - row.ms).abs() < 1e-3);
            assert!((num("ssim") - row.ssim).abs() < 1e-6);
            assert_eq!(num("psnr_db").is_infinite(), row.psnr_db.is_infinite());
            assert_eq!(f[col("front")].parse::<bool>(), Ok(row.front));
            assert_eq!(f[col("max_octaves")], "scene");
            assert_eq!(f[col("precision")], "f32");
        }
        assert_eq!(lines[1].split(',').nth(col("speedup")), Some("4.000"));
    }

    #[test]
    fn markdown_and_table_list_every_row() {
        let rows = rows(&[("aa 2", 40.0, 0.99), ("max-depth 1", 9.0, 0.9), ("preset full", 10.0, 0.95)]);
        let ctx = Context {
            scene: "s.pov".into(),
            width: 64,
            height: 48,
            cameras: "the scene camera".into(),
            repeats: 3,
            threads: 2,
            cpu: "cpu".into(),
        };
        let md = markdown(&rows, &ctx, "plot.svg");
        assert_eq!(md.lines().filter(|l| l.starts_with("| `--")).count(), 3);
        assert!(md.contains("| `--preset full` | 10.00 | 10.00–10.00 | 1.00× |"), "{md}");
        assert!(md.contains(FRONT_RULE), "the md says how ties are marked");
        assert!(md.contains("](plot.svg)"));
        // max-depth 1 is faster but worse than full; full is dominated by nothing; all on the front.
        assert!(rows.iter().all(|r| r.front));
        let t = table(&rows, &ctx);
        assert_eq!(t.lines().count(), 2 + rows.len());
    }
}
