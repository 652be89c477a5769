//! Comparing strahl's renders with POV-Ray 3.7's: the machinery `tests/suite/reference.rs` (the
//! project's own reference scenes, 640×480) and `tests/suite/samples.rs` (POV-Ray's sample scenes,
//! 320×240) share. A [`Suite`] names the image size, where the expected images lie and where
//! failures write theirs; its comparisons return a [`Report`] (the figures, printed as lines,
//! and what failed) so that a caller rendering many scenes at once can print them as a table.
//!
//! - [`Suite::compare_psnr`]: the whole image, pixel for pixel.
//! - [`Suite::compare_regions`]: for scenes with noise patterns, which can't match POV-Ray pixel
//!   for pixel (strahl's noise is its own, not POV-Ray's lattice): the image is split by what
//!   each pixel's primary ray hits; a region where POV-Ray's image is flat must match pixel for
//!   pixel, a textured one by its blurred colour and its texture strength.
//! - [`Suite::compare_psnr_by_region`]: the same split for scenes without noise whose figure is
//!   held down by one known difference, each region with its own floor.

use std::ops::RangeInclusive;
use std::path::{Path, PathBuf};

use strahl::camera::Camera;
use strahl::headless::metrics::{psnr, psnr_from_mse, ssim};
use strahl::headless::{include_path, output};
use strahl::pov::{load_scene_with_options, Clock, ParseOptions};
use strahl::render::image::Image;
use strahl::render::intersect::HitShape;
use strahl::render::stats::RenderStats;
use strahl::render::{primary_ray, render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A set of POV-Ray renders to compare against.
pub struct Suite {
    pub width: u32,
    pub height: u32,
    /// Folder of the expected images, `<name>.png`.
    pub expected: PathBuf,
    /// Folder failures write `<name>.actual.png`, `.expected.png` and `.diff.png` into.
    pub failures: PathBuf,
    /// How to regenerate the expected images, for failure messages.
    pub regenerate: &'static str,
}

/// A scene rendered by strahl, with what the region split needs to trace its primary rays again.
pub struct Rendered {
    pub scene: Scene,
    pub camera: Camera,
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
    pub stats: RenderStats,
}

/// What one comparison measured and found.
pub struct Report {
    /// The figures, one line each, prefixed with the scene's name.
    pub lines: Vec<String>,
    /// What missed its bound; empty when the scene passes.
    pub failures: Vec<String>,
    /// PSNR of the whole image.
    pub psnr: f64,
    /// Each region's figures (the region comparisons only).
    pub figures: Vec<(Option<u32>, RegionFigures)>,
}

impl Report {
    fn new(name: &str, r: &Rendered, exp: &[u8]) -> Report {
        let p = psnr(&r.rgb, exp);
        let mut report = Report { lines: Vec::new(), failures: Vec::new(), psnr: p, figures: Vec::new() };
        report.lines.push(format!(
            "{name}: whole image PSNR {p:.2} dB, SSIM {:.4} against POV-Ray 3.7",
            ssim(r.width, r.height, &r.rgb, exp)
        ));
        if r.stats.bad_samples != 0 {
            report.failures.push(format!("{} NaN or infinite samples", r.stats.bad_samples));
        }
        report
    }

    pub fn print(&self) {
        for l in &self.lines {
            println!("{l}");
        }
    }
}

impl Suite {
    /// Renders `path` at the suite's size as `strahl render` does: parsed for that image size
    /// (`image_width`), a still image's clock, includes found beside the scene first, then on
    /// POV-Ray's include path; one sample per pixel.
    pub fn render(&self, path: &Path) -> Result<Rendered, String> {
        let options = ParseOptions { image_width: self.width, image_height: self.height, clock: Clock::default() };
        let desc = load_scene_with_options(path, &include_path(&[]), &options).map_err(|e| e.to_string())?;
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let camera = Camera::from_desc(&desc.camera);
        let mut image = Image::default();
        let settings = RenderSettings { width: self.width, height: self.height, ..RenderSettings::default() };
        let stats = render(&scene, &camera, &settings, &mut image);
        let rgb = image.to_rgb8(scene.srgb);
        Ok(Rendered { scene, camera, width: self.width, height: self.height, rgb, stats })
    }

    pub fn expected(&self, name: &str) -> Result<Vec<u8>, String> {
        let path = self.expected.join(format!("{name}.png"));
        let (w, h, rgb) = output::read_png(&path).map_err(|e| e.to_string())?;
        if (w, h) != (self.width, self.height) {
            return Err(format!("{} is {w}×{h}, not {}×{}", path.display(), self.width, self.height));
        }
        Ok(rgb)
    }

    /// Writes actual, expected and 4× amplified difference next to each other.
    pub fn write_failure(&self, name: &str, actual: &[u8], expected: &[u8]) -> PathBuf {
        let dir = &self.failures;
        std::fs::create_dir_all(dir).unwrap_or_else(|e| panic!("create {}: {e}", dir.display()));
        let diff: Vec<u8> = actual
            .iter()
            .zip(expected)
            .map(|(a, b)| ((*a as i32 - *b as i32).unsigned_abs() * 4).min(255) as u8)
            .collect();
        for (suffix, img) in [("actual", actual), ("expected", expected), ("diff", &diff[..])] {
            output::write_png(&dir.join(format!("{name}.{suffix}.png")), self.width, self.height, img)
                .expect("write failure image");
        }
        dir.clone()
    }

    /// `Err` with the failures (after writing the images) when the report has any.
    pub fn verdict(&self, name: &str, report: &Report, r: &Rendered, exp: &[u8]) -> Result<(), String> {
        if report.failures.is_empty() {
            return Ok(());
        }
        let dir = self.write_failure(name, &r.rgb, exp);
        Err(format!(
            "{name} differs from POV-Ray: {}; images in {}; regenerate references with `{}` only if POV-Ray changed",
            report.failures.join("; "),
            dir.display(),
            self.regenerate
        ))
    }

    /// The whole image against `min_db`.
    pub fn compare_psnr(&self, name: &str, r: &Rendered, exp: &[u8], min_db: f64) -> Report {
        let mut report = Report::new(name, r, exp);
        if report.psnr < min_db {
            report.failures.push(format!("PSNR {:.2} dB < {min_db} dB", report.psnr));
        }
        report
    }

    /// The region split for scenes with noise patterns (see the module's comment): a region
    /// where POV-Ray's image is flat must reach `flat_db` pixel for pixel, a textured one its
    /// blurred colour `blurred_db` and a texture strength within `strength` of POV-Ray's.
    pub fn compare_regions(&self, name: &str, r: &Rendered, exp: &[u8], bounds: &RegionBounds) -> Report {
        let mut report = Report::new(name, r, exp);
        let (w, h) = (r.width, r.height);
        for (id, mask) in region_masks(r) {
            let theirs9 = windows(exp, w, h, &mask, 9, 9);
            let p = psnr(&pick(&r.rgb, &mask), &pick(exp, &mask));
            let fig = if median(&theirs9.detrended) < FLAT_DETRENDED {
                if p < bounds.flat_db {
                    report.failures.push(format!("{}: flat PSNR {p:.2} dB < {} dB", region_label(id), bounds.flat_db));
                }
                RegionFigures::Flat { psnr: p }
            } else {
                let ours9 = windows(&r.rgb, w, h, &mask, 9, 9);
                // Half-overlapping blur windows: the figure depends less on where the grid falls.
                let step = bounds.blur / 2 + 1;
                let (ours, theirs) =
                    (windows(&r.rgb, w, h, &mask, bounds.blur, step), windows(exp, w, h, &mask, bounds.blur, step));
                let mse = ours
                    .means
                    .iter()
                    .zip(&theirs.means)
                    .map(|(a, b)| (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>() / 3.0)
                    .sum::<f64>()
                    / ours.means.len().max(1) as f64;
                let blurred_db = psnr_from_mse(mse);
                let (strength_ours, strength_theirs) = (mean(&ours9.stds), mean(&theirs9.stds));
                let ratio = strength_ours / strength_theirs;
                if blurred_db < bounds.blurred_db {
                    report.failures.push(format!(
                        "{}: blurred-colour PSNR {blurred_db:.2} dB < {} dB",
                        region_label(id),
                        bounds.blurred_db
                    ));
                }
                let exception = bounds.strength_exceptions.iter().find(|e| Some(e.0) == id);
                let allowed = exception.map_or(bounds.strength.clone(), |e| e.1..=e.2);
                if let Some(e) = exception {
                    report.lines.push(format!("{name}: {}: strength allowed {:?}: {}", region_label(id), allowed, e.3));
                }
                if !allowed.contains(&ratio) {
                    report
                        .failures
                        .push(format!("{}: texture strength ratio {ratio:.2} outside {allowed:?}", region_label(id)));
                }
                RegionFigures::Textured { psnr: p, blurred_db, strength_ours, strength_theirs }
            };
            report.lines.push(format!(
                "{name}: {} ({} pixels): {}",
                region_label(id),
                mask.iter().filter(|k| **k).count(),
                fig.describe()
            ));
            report.figures.push((id, fig));
        }
        report
    }

    /// Per-region PSNR for scenes without noise whose whole-image figure is held down by one
    /// known difference: every region must reach `min_db` except the listed ones, which keep
    /// their own floor and the reason for it.
    pub fn compare_psnr_by_region(
        &self,
        name: &str,
        r: &Rendered,
        exp: &[u8],
        min_db: f64,
        exceptions: &[(Option<u32>, f64, &str)],
    ) -> Report {
        let mut report = Report::new(name, r, exp);
        for (id, mask) in region_masks(r) {
            let p = psnr(&pick(&r.rgb, &mask), &pick(exp, &mask));
            let (floor, why) = match exceptions.iter().find(|e| e.0 == id) {
                Some(&(_, floor, why)) => (floor, why),
                None => (min_db, ""),
            };
            report.lines.push(format!(
                "{name}: {} ({} pixels): PSNR {p:.2} dB (floor {floor}{}{why})",
                region_label(id),
                mask.iter().filter(|k| **k).count(),
                if why.is_empty() { "" } else { ": " }
            ));
            if p < floor {
                report.failures.push(format!("{}: PSNR {p:.2} dB < {floor} dB", region_label(id)));
            }
            report.figures.push((id, RegionFigures::Flat { psnr: p }));
        }
        report
    }

    fn render_and_expected(&self, name: &str, path: &Path) -> (Rendered, Vec<u8>) {
        let r = self.render(path).unwrap_or_else(|e| panic!("{name}: {e}"));
        let exp = self.expected(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        (r, exp)
    }

    fn print_or_panic(&self, name: &str, report: &Report, r: &Rendered, exp: &[u8]) {
        report.print();
        if let Err(e) = self.verdict(name, report, r, exp) {
            panic!("{e}");
        }
    }

    /// Renders, compares the whole image with `min_db`, prints the figures; panics on failure.
    pub fn check_psnr(&self, name: &str, path: &Path, min_db: f64) {
        let (r, exp) = self.render_and_expected(name, path);
        self.print_or_panic(name, &self.compare_psnr(name, &r, &exp, min_db), &r, &exp);
    }

    /// [`Suite::compare_regions`] on a render of `path`, printed; panics on failure.
    pub fn check_regions(&self, name: &str, path: &Path, bounds: &RegionBounds) -> Vec<(Option<u32>, RegionFigures)> {
        let (r, exp) = self.render_and_expected(name, path);
        let report = self.compare_regions(name, &r, &exp, bounds);
        self.print_or_panic(name, &report, &r, &exp);
        report.figures
    }

    /// [`Suite::compare_psnr_by_region`] on a render of `path`, printed; panics on failure.
    pub fn check_psnr_by_region(&self, name: &str, path: &Path, min_db: f64, exceptions: &[(Option<u32>, f64, &str)]) {
        let (r, exp) = self.render_and_expected(name, path);
        let report = self.compare_psnr_by_region(name, &r, &exp, min_db, exceptions);
        self.print_or_panic(name, &report, &r, &exp);
    }
}

/// Per-pixel region: which material the primary ray hits (`None`: the background).
fn regions(r: &Rendered) -> Vec<Option<u32>> {
    let (w, h) = (r.width, r.height);
    let mut stats = RenderStats::default();
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let ray = primary_ray(&r.scene, &r.camera, w, h, x, y);
            out.push(r.scene.intersect(&ray, f32::INFINITY, &mut stats).map(|hit| match hit.shape {
                HitShape::Plane(_) | HitShape::Prim(_) | HitShape::Face { .. } => r.scene.material_of(hit.shape),
            }));
        }
    }
    out
}

/// Pixels whose 5×5 neighbourhood lies entirely in `region`: away from silhouettes, where one
/// pixel of geometric difference is not a shading difference.
fn interior(reg: &[Option<u32>], w: u32, h: u32, region: Option<u32>) -> Vec<bool> {
    let at = |x: i32, y: i32| reg[(y.clamp(0, h as i32 - 1) as u32 * w + x.clamp(0, w as i32 - 1) as u32) as usize];
    let mut m = vec![false; (w * h) as usize];
    for y in 0..h as i32 {
        for x in 0..w as i32 {
            m[(y as u32 * w + x as u32) as usize] = (-2..=2).all(|dy| (-2..=2).all(|dx| at(x + dx, y + dy) == region));
        }
    }
    m
}

/// Statistics of the `k`×`k` windows (centres on a grid of step `step`) that lie inside the mask.
struct Windows {
    /// Mean colour of each window.
    means: Vec<[f64; 3]>,
    /// Standard deviation of each window (channels averaged): the local contrast.
    stds: Vec<f64>,
    /// Standard deviation left after removing each channel's best plane `a + b·x + c·y`:
    /// shading gradients (a lit sphere, a light's falloff) leave nothing here, texture does.
    detrended: Vec<f64>,
}

fn windows(rgb: &[u8], w: u32, hgt: u32, mask: &[bool], k: i32, step: i32) -> Windows {
    let mut out = Windows { means: Vec::new(), stds: Vec::new(), detrended: Vec::new() };
    let h = k / 2;
    // Σx² over the window's offsets (the same for x and y): the plane fit's denominator.
    let sxx: f64 = (-h..=h).map(|d| (d * d) as f64).sum::<f64>() * k as f64;
    for cy in (h..hgt as i32 - h).step_by(step as usize) {
        for cx in (h..w as i32 - h).step_by(step as usize) {
            let px: Vec<(i32, i32, usize)> = (-h..=h)
                .flat_map(|dy| (-h..=h).map(move |dx| (dx, dy, ((cy + dy) as u32 * w + (cx + dx) as u32) as usize)))
                .collect();
            if !px.iter().all(|&(_, _, i)| mask[i]) {
                continue;
            }
            let n = px.len() as f64;
            let (mut mean, mut var, mut res) = ([0.0f64; 3], 0.0, 0.0);
            for c in 0..3 {
                let v = |i: usize| rgb[i * 3 + c] as f64;
                let m = px.iter().map(|&(_, _, i)| v(i)).sum::<f64>() / n;
                let bx = px.iter().map(|&(dx, _, i)| (v(i) - m) * dx as f64).sum::<f64>() / sxx;
                let by = px.iter().map(|&(_, dy, i)| (v(i) - m) * dy as f64).sum::<f64>() / sxx;
                var += px.iter().map(|&(_, _, i)| (v(i) - m).powi(2)).sum::<f64>() / n;
                res +=
                    px.iter().map(|&(dx, dy, i)| (v(i) - m - bx * dx as f64 - by * dy as f64).powi(2)).sum::<f64>() / n;
                mean[c] = m;
            }
            out.means.push(mean);
            out.stds.push((var / 3.0).sqrt());
            out.detrended.push((res / 3.0).sqrt());
        }
    }
    out
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(s.len() / 2).copied().unwrap_or(0.0)
}

/// A region is flat where POV-Ray's image has (nearly) no local variance there: the median
/// 9×9 window keeps under this many levels of 255 once shading gradients are removed.
const FLAT_DETRENDED: f64 = 1.0;

/// Regions with fewer interior pixels are not judged (a sliver between two objects).
const MIN_REGION_PIXELS: usize = 400;

/// The region split's bounds.
#[derive(Clone, Debug)]
pub struct RegionBounds {
    /// PSNR floor of each flat region, pixel for pixel.
    pub flat_db: f64,
    /// PSNR floor of each textured region's blurred colour (means of `blur`×`blur` windows).
    pub blurred_db: f64,
    /// Side of the blur windows: wider than a feature of the noise, so the means compare the
    /// average look rather than where each feature happens to lie.
    pub blur: i32,
    /// Allowed ratio of strahl's texture strength (mean std-dev of 9×9 windows) to POV-Ray's.
    pub strength: RangeInclusive<f64>,
    /// Regions whose strength ratio is known to differ, each with its own allowed range (a
    /// regression guard around the measured figure) and the reason.
    pub strength_exceptions: &'static [(u32, f64, f64, &'static str)],
}

/// What the region split measured on one region.
#[derive(Debug)]
pub enum RegionFigures {
    Flat {
        psnr: f64,
    },
    /// `psnr` is pixel for pixel, for information (noise differs there by design).
    Textured {
        psnr: f64,
        blurred_db: f64,
        strength_ours: f64,
        strength_theirs: f64,
    },
}

impl RegionFigures {
    fn describe(&self) -> String {
        match self {
            RegionFigures::Flat { psnr } => format!("flat, PSNR {psnr:.2} dB"),
            RegionFigures::Textured { psnr, blurred_db, strength_ours, strength_theirs } => format!(
                "textured, PSNR {psnr:.2} dB, blurred colour {blurred_db:.2} dB, strength {strength_ours:.2} vs POV-Ray {strength_theirs:.2} (ratio {:.2})",
                strength_ours / strength_theirs
            ),
        }
    }

    /// PSNR pixel for pixel, whichever kind of region.
    pub fn psnr(&self) -> f64 {
        match self {
            RegionFigures::Flat { psnr } | RegionFigures::Textured { psnr, .. } => *psnr,
        }
    }
}

pub fn region_label(region: Option<u32>) -> String {
    region.map_or("background".to_string(), |m| format!("material {m}"))
}

fn pick(img: &[u8], m: &[bool]) -> Vec<u8> {
    img.chunks(3).zip(m).filter(|(_, &k)| k).flat_map(|(p, _)| p.to_vec()).collect()
}

/// Each region's interior mask, in order (background first, then materials in file order),
/// without the regions too small to judge.
fn region_masks(r: &Rendered) -> Vec<(Option<u32>, Vec<bool>)> {
    let reg = regions(r);
    let mut ids: Vec<Option<u32>> = reg.clone();
    ids.sort();
    ids.dedup();
    ids.into_iter()
        .map(|id| (id, interior(&reg, r.width, r.height, id)))
        .filter(|(_, m)| m.iter().filter(|k| **k).count() >= MIN_REGION_PIXELS)
        .collect()
}
