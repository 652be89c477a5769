//! `strahl tradeoff`: measures what each speed/accuracy knob buys. Renders the `reference`
//! preset once per camera, then times every knob setting (one at a time, from `full`: resolution,
//! trace depth, shadows, octaves, f64 precision, antialiasing) and every preset, and scores its frames against the reference (PSNR, SSIM, largest 8-bit error).
//!
//! Timing is bench-style: per setting and camera one untimed frame (the one scored, and the
//! warm-up), then `repeats` timed frames into pre-allocated images, median; nothing is encoded or
//! allocated inside the timed part, and the settings take turns so machine noise spreads evenly. The
//! reports (table, CSV, Markdown, SVG plot with the Pareto front) live in `tradeoff::report` and
//! `tradeoff::svg`. The output folder is checked first (before the scene is even parsed) but
//! created only once everything is computed, so a bad argument or scene leaves nothing behind
//! and a bad `-o` costs no rendering. On a terminal a progress bar shows each phase (scoring,
//! then timing, with an ETA weighted by what each setting cost to score).

mod report;
mod svg;

use std::path::PathBuf;
use std::time::Instant;

pub use report::{csv, mark_front, markdown, pareto_front, table, Context, Row, Timing, FRONT_RULE};
pub use svg::plot;

use crate::camera::path::CameraPath;
use crate::camera::Camera;
use crate::headless::bench::{cpu_model, percentile};
use crate::headless::capture::frame_t;
use crate::headless::progress::Progress;
use crate::headless::{load_sized, metrics, output, with_threads, CliError};
use crate::render::image::Image;
use crate::render::precision::Precision;
use crate::render::preset::Preset;
use crate::render::resample::render_scaled;
use crate::render::{Quality, RenderSettings};
use crate::scene::build::{AccelKind, Scene};

/// Error maps multiply the 8-bit difference by this, so a 1-step error is visible (8/255).
pub const ERROR_GAIN: u8 = 8;

/// One point of the sweep: the flags that select it (`name`, as `--name`) and what they set.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    pub name: String,
    pub res_scale: f32,
    pub aa: u32,
    pub quality: Quality,
}

impl Setting {
    fn knob(name: String, change: impl FnOnce(&mut Setting)) -> Setting {
        let full = Preset::Full.settings();
        let mut s = Setting { name, res_scale: full.res_scale, aa: full.aa, quality: full.quality };
        change(&mut s);
        s
    }

    fn preset(p: Preset) -> Setting {
        let s = p.settings();
        Setting { name: format!("preset {p}"), res_scale: s.res_scale, aa: s.aa, quality: s.quality }
    }

    /// The name as a file name: `res-scale 0.25` → `res-scale-0.25`.
    pub fn slug(&self) -> String {
        self.name.replace(' ', "-")
    }

    fn render_settings(&self, width: u32, height: u32) -> RenderSettings {
        RenderSettings { width, height, aa: self.aa, quality: self.quality, ..RenderSettings::default() }
    }
}

/// The sweep, in report order: each knob moved alone away from `full`, then every preset.
pub fn sweep() -> Vec<Setting> {
    let mut s = Vec::new();
    for f in [0.25f32, 0.5, 0.75] {
        s.push(Setting::knob(format!("res-scale {f}"), |s| s.res_scale = f));
    }
    for d in 1..=3 {
        s.push(Setting::knob(format!("max-depth {d}"), |s| s.quality.max_trace_level = Some(d)));
    }
    s.push(Setting::knob("no-shadows".into(), |s| s.quality.shadows = false));
    for o in 0..=2 {
        s.push(Setting::knob(format!("max-octaves {o}"), |s| s.quality.max_octaves = Some(o)));
    }
    s.push(Setting::knob("precision f64".into(), |s| s.quality.precision = Precision::F64));
    for n in [4, 16] {
        s.push(Setting::knob(format!("max-area-samples {n}"), |s| s.quality.max_area_samples = Some(n)));
    }
    // Focal-blur rays per sample (the same image as `full` on scenes without focal blur).
    for n in [4, 16] {
        s.push(Setting::knob(format!("max-blur-samples {n}"), |s| s.quality.max_blur_samples = Some(n)));
    }
    for aa in 2..=3 {
        s.push(Setting::knob(format!("aa {aa}"), |s| s.aa = aa));
    }
    s.extend(Preset::ALL.map(Setting::preset));
    s
}

/// What one setting measured, over all cameras.
#[derive(Clone, Debug, PartialEq)]
pub struct Measure {
    /// Mean over cameras of the median frame time.
    pub ms: f64,
    /// PSNR of the mean squared error over all cameras (the PSNR of the frames as one image).
    pub psnr_db: f64,
    /// Mean over cameras.
    pub ssim: f64,
    /// The largest 8-bit error of any channel in any camera's frame.
    pub max_abs: u8,
}

/// Renders `setting` once per camera, untimed, and scores it against `refs` (8-bit RGB, one
/// per camera). Returns the measure without `ms`, and camera 0's frame. Call inside the pool.
pub fn score(
    scene: &Scene,
    cameras: &[Camera],
    refs: &[Vec<u8>],
    setting: &Setting,
    frame: &mut Frame,
) -> (Measure, Vec<u8>) {
    let settings = setting.render_settings(frame.image.width, frame.image.height);
    let (mut mse, mut ssim, mut max_abs) = (0.0, 0.0, 0u8);
    let mut first = Vec::new();
    for (i, (camera, reference)) in cameras.iter().zip(refs).enumerate() {
        render_scaled(scene, camera, &settings, setting.res_scale, &mut frame.low, &mut frame.image);
        let rgb = frame.image.to_rgb8(scene.srgb);
        mse += metrics::mse(&rgb, reference);
        ssim += metrics::ssim(settings.width, settings.height, &rgb, reference);
        max_abs = max_abs.max(metrics::max_abs_diff(&rgb, reference));
        if i == 0 {
            first = rgb;
        }
    }
    let n = cameras.len().max(1) as f64;
    (Measure { ms: f64::NAN, psnr_db: metrics::psnr_from_mse(mse / n), ssim: ssim / n, max_abs }, first)
}

/// The images a render writes: the output and the reduced-size one, allocated once at full size
/// so nothing is allocated while timing.
pub struct Frame {
    pub image: Image,
    pub low: Image,
}

impl Frame {
    pub fn new(width: u32, height: u32) -> Frame {
        Frame { image: Image::new(width, height), low: Image::new(width, height) }
    }
}

/// Each setting's frame time over `repeats` frames per camera: the median and the quartiles
/// (`Timing`), each averaged over cameras. The settings take turns frame by frame, so load that
/// comes and goes on a shared machine falls on all of them alike rather than on whichever ran
/// at the time. The caller renders every setting once before (`score`), which is the warm-up.
/// `done(repeat, setting)` is called after each setting's frames of a round, outside the timed
/// part (for a progress bar).
pub fn time_settings(
    scene: &Scene,
    cameras: &[Camera],
    settings: &[Setting],
    repeats: u32,
    frame: &mut Frame,
    mut done: impl FnMut(u32, usize),
) -> Vec<Timing> {
    let (w, h) = (frame.image.width, frame.image.height);
    let render_settings: Vec<RenderSettings> = settings.iter().map(|s| s.render_settings(w, h)).collect();
    // times[setting][camera][repeat], allocated before the first timed frame.
    let mut times = vec![vec![Vec::with_capacity(repeats as usize); cameras.len()]; settings.len()];
    for r in 0..repeats {
        for (i, (s, rs)) in settings.iter().zip(&render_settings).enumerate() {
            for (c, camera) in cameras.iter().enumerate() {
                let start = Instant::now();
                render_scaled(scene, camera, rs, s.res_scale, &mut frame.low, &mut frame.image);
                times[i][c].push(start.elapsed().as_secs_f64() * 1e3);
            }
            done(r, i);
        }
    }
    let n = cameras.len().max(1) as f64;
    times
        .iter()
        .map(|per_camera| {
            let mut t = Timing { lo: 0.0, median: 0.0, hi: 0.0 };
            for camera in per_camera {
                let mut sorted = camera.clone();
                sorted.sort_by(f64::total_cmp);
                t.lo += percentile(&sorted, 25.0) / n;
                t.median += percentile(&sorted, 50.0) / n;
                t.hi += percentile(&sorted, 75.0) / n;
            }
            t
        })
        .collect()
}

/// |a − b| per channel times `ERROR_GAIN`, clipped: black where a frame matches the reference.
pub fn error_map(a: &[u8], b: &[u8]) -> Vec<u8> {
    a.iter().zip(b).map(|(&x, &y)| x.abs_diff(y).saturating_mul(ERROR_GAIN)).collect()
}

pub struct TradeoffArgs {
    pub scene: PathBuf,
    pub include: Vec<PathBuf>,
    pub path: Option<PathBuf>,
    /// Cameras along `path`; ignored without one.
    pub frames: u32,
    pub width: u32,
    pub height: u32,
    pub output: PathBuf,
    pub threads: usize,
    pub repeats: u32,
    pub accel: AccelKind,
}

/// Everything the run produced, before anything is written.
struct Results {
    rows: Vec<Row>,
    reference: Vec<u8>,
    error_maps: Vec<(String, Vec<u8>)>,
}

fn run_sweep(scene: &Scene, cameras: &[Camera], args: &TradeoffArgs) -> Results {
    let reference = Setting::preset(Preset::Reference);
    let ref_settings = reference.render_settings(args.width, args.height);
    let mut frame = Frame::new(args.width, args.height);
    let settings = sweep();
    // Scoring: the reference, then each setting once per camera. Costs differ a hundredfold
    // and are not known yet, so this bar shows the time so far rather than a guess.
    let n_cam = cameras.len() as u64;
    let scored = n_cam * (1 + settings.len() as u64);
    let scoring = Progress::new(scored, "frames scored", false).without_eta();
    scoring.update_weighted(0, 0.0, "reference");
    let mut refs: Vec<Vec<u8>> = cameras
        .iter()
        .map(|c| {
            render_scaled(scene, c, &ref_settings, reference.res_scale, &mut frame.low, &mut frame.image);
            frame.image.to_rgb8(scene.srgb)
        })
        .collect();
    let (mut rows, mut error_maps, mut cost) = (Vec::new(), Vec::new(), Vec::new());
    for (i, s) in settings.iter().enumerate() {
        let done = n_cam * (1 + i as u64);
        scoring.update_weighted(done, done as f64 / scored as f64, &s.name);
        let start = Instant::now();
        let (m, first) = score(scene, cameras, &refs, s, &mut frame);
        cost.push(start.elapsed().as_secs_f64());
        error_maps.push((s.slug(), error_map(&first, &refs[0])));
        rows.push(Row::new(s, scene.max_trace_level, m));
    }
    scoring.update(scored);
    scoring.finish();
    // Timing: every round costs what scoring each setting did, so the ETA weights by that.
    let timing = Progress::new(n_cam * settings.len() as u64 * args.repeats as u64, "frames timed", false);
    let round: f64 = cost.iter().sum::<f64>().max(1e-9);
    let (mut frames, mut work) = (0, 0.0);
    timing.update_weighted(0, 0.0, &settings[0].name);
    let times = time_settings(scene, cameras, &settings, args.repeats, &mut frame, |r, i| {
        frames += n_cam;
        work += cost[i];
        // Name what runs next: the following setting, or the first one of the next round.
        let (r, i) = if i + 1 < settings.len() { (r, i + 1) } else { (r + 1, 0) };
        let note = if r < args.repeats {
            format!("round {}/{}: {}", r + 1, args.repeats, settings[i].name)
        } else {
            String::new()
        };
        timing.update_weighted(frames, work / (round * args.repeats as f64), &note);
    });
    timing.finish();
    for (row, t) in rows.iter_mut().zip(times) {
        row.set_timing(t);
    }
    mark_front(&mut rows);
    Results { rows, reference: refs.swap_remove(0), error_maps }
}

/// `strahl tradeoff SCENE ...`: checks every argument and loads everything before rendering,
/// and renders everything before writing, so an error leaves no folder or half a report.
pub fn run(args: &TradeoffArgs) -> Result<(), CliError> {
    if args.path.is_some() && args.frames == 0 {
        return Err(CliError::user("--frames must be at least 1"));
    }
    if args.repeats < 3 {
        return Err(CliError::user("--repeats must be at least 3 (the median of fewer is noise)"));
    }
    output::check_folder_writable("-o", &args.output)?;
    output::check_folder_writable("-o", &args.output.join("errors"))?;
    let path = args.path.as_deref().map(CameraPath::load).transpose()?;
    let (desc, _) = load_sized(&args.scene, &args.include, args.width, args.height)?;
    let scene = Scene::build(&desc, desc.camera.location, args.accel);
    // The reference preset and the precision knob trace in f64.
    let base = Camera::from_desc(&desc.camera);
    let cameras: Vec<Camera> = match &path {
        Some(p) => (0..args.frames).map(|i| p.camera_at(frame_t(i, args.frames), &base)).collect(),
        None => vec![base],
    };
    let (results, threads) =
        with_threads(args.threads, || (run_sweep(&scene, &cameras, args), rayon::current_num_threads()))?;

    let camera_text = match &args.path {
        Some(p) => format!("{} cameras along {}", cameras.len(), p.display()),
        None => "the scene camera".to_string(),
    };
    let context = Context {
        scene: args.scene.display().to_string(),
        width: args.width,
        height: args.height,
        cameras: camera_text,
        repeats: args.repeats,
        threads,
        cpu: cpu_model(),
    };
    let errors = args.output.join("errors");
    output::create_dir(&errors)?;
    output::write_atomic(&args.output.join("tradeoff.csv"), csv(&results.rows).as_bytes())?;
    output::write_atomic(
        &args.output.join("tradeoff.md"),
        markdown(&results.rows, &context, "tradeoff.svg").as_bytes(),
    )?;
    output::write_atomic(&args.output.join("tradeoff.svg"), plot(&results.rows, &context).as_bytes())?;
    output::write_png(&args.output.join("reference.png"), args.width, args.height, &results.reference)?;
    for (slug, map) in &results.error_maps {
        output::write_png(&errors.join(format!("{slug}.png")), args.width, args.height, map)?;
    }
    print!("{}", table(&results.rows, &context));
    output::flush_stdout();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_moves_one_knob_at_a_time() {
        let full = Preset::Full.settings();
        let s = sweep();
        assert_eq!(s.len(), 3 + 3 + 1 + 3 + 1 + 2 + 2 + 2 + 4);
        let names: Vec<&str> = s.iter().map(|s| s.name.as_str()).collect();
        assert!(names.contains(&"res-scale 0.25") && names.contains(&"no-shadows") && names.contains(&"aa 3"));
        assert!(names.contains(&"precision f64"));
        assert_eq!(names[names.len() - 4..], ["preset fast", "preset balanced", "preset full", "preset reference"]);
        for k in &s[..s.len() - 4] {
            let changed = [
                k.res_scale != full.res_scale,
                k.aa != full.aa,
                k.quality.max_trace_level != full.quality.max_trace_level,
                k.quality.shadows != full.quality.shadows,
                k.quality.max_octaves != full.quality.max_octaves,
                k.quality.precision != full.quality.precision,
                k.quality.max_area_samples != full.quality.max_area_samples,
                k.quality.max_blur_samples != full.quality.max_blur_samples,
            ];
            assert_eq!(changed.iter().filter(|&&c| c).count(), 1, "{}", k.name);
        }
        assert_eq!(s[0].slug(), "res-scale-0.25");
    }

    #[test]
    fn error_map_amplifies_and_clips() {
        assert_eq!(error_map(&[10, 10, 200], &[10, 12, 0]), vec![0, 16, 255]);
    }
}
