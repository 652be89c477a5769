//! `strahl view --path`: plays a camera path in real time and records what the window showed,
//! then (after the window has closed, so it cannot slow the playback) compares sampled presented
//! frames with full-quality headless renders of the same cameras and writes the `--report`.
//!
//! No window types here: the window hands over its presented 0RGB words and the frame's camera.

use std::path::Path;
use std::time::Instant;

use crate::app::frame_costs::{self, FrameCosts};
use crate::camera::path::CameraPath;
use crate::camera::Camera;
use crate::headless::bench::{cpu_model, percentile};
use crate::headless::json::Json;
use crate::headless::metrics::{psnr, ssim};
use crate::headless::{output, with_threads, CliError};
use crate::render::image::Image;
use crate::render::{render, Quality, RenderSettings};
use crate::scene::build::Scene;

/// Presented frames between samples at the start (frames 1, 11, 21, ...); doubles whenever `MAX_SAMPLES` are held, so
/// the samples always spread over the whole path however long it runs.
const FIRST_STRIDE: u64 = 10;
const MAX_SAMPLES: usize = 20;
/// Path seconds when the keys' times span less than `MIN_KEY_SPAN` (a path written in 0..1).
pub const DEFAULT_SECONDS: f64 = 10.0;
const MIN_KEY_SPAN: f64 = 2.0;
/// A sample identical to its reference has infinite PSNR; it counts as this many dB, so that the
/// mean stays a number (8-bit frames that differ in one value of one pixel score 112 dB at 720p).
pub const PSNR_CAP: f64 = 100.0;

/// How long a path plays without `--path-seconds`: its keys' times read as seconds when they
/// span at least two, else [`DEFAULT_SECONDS`] (a path normalised to 0..1 is not meant as 1 s).
pub fn default_seconds(path: &CameraPath) -> f64 {
    let keys = path.keys();
    let span = keys[keys.len() - 1].time - keys[0].time;
    if span >= MIN_KEY_SPAN {
        span
    } else {
        DEFAULT_SECONDS
    }
}

/// One sampled presented frame: the pixels as shown (upscaled, before the HUD is drawn).
pub struct Sample {
    /// 1-based index among presented frames.
    pub index: u64,
    /// Path position when it was presented.
    pub t: f64,
    pub scale: f64,
    /// The camera the frame was rendered for.
    pub camera: Camera,
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

/// The playback clock and what was recorded along the way.
pub struct Playback {
    path: CameraPath,
    pub seconds: f64,
    start: Option<Instant>,
    end: Option<Instant>,
    last_present: Option<Instant>,
    presented: u64,
    /// Seconds between consecutive fresh presents.
    intervals: Vec<f64>,
    scales: Vec<f64>,
    stride: u64,
    samples: Vec<Sample>,
    /// Each fresh present's non-tracing stages, in order.
    costs: Vec<FrameCosts>,
    /// Fresh presents of reprojected frames.
    reprojected: u64,
}

impl Playback {
    pub fn new(path: CameraPath, seconds: f64) -> Playback {
        Playback {
            path,
            seconds,
            start: None,
            end: None,
            last_present: None,
            presented: 0,
            intervals: Vec::new(),
            scales: Vec::new(),
            stride: FIRST_STRIDE,
            samples: Vec::new(),
            costs: Vec::new(),
            reprojected: 0,
        }
    }

    /// Path position at `now`; the clock starts at the first call.
    pub fn t(&mut self, now: Instant) -> f64 {
        let start = *self.start.get_or_insert(now);
        ((now - start).as_secs_f64() / self.seconds).min(1.0)
    }

    /// The camera at `now` (shaped like `base`), and whether the path has ended.
    pub fn camera(&mut self, now: Instant, base: &Camera) -> (Camera, bool) {
        let t = self.t(now);
        if t >= 1.0 && self.end.is_none() {
            self.end = Some(now);
        }
        (self.path.camera_at(t, base), t >= 1.0)
    }

    pub fn finished(&self) -> bool {
        self.end.is_some()
    }

    /// Whether the next fresh present will be sampled (so the window copies its pixels only then).
    pub fn wants_sample(&self) -> bool {
        !self.finished() && self.presented.is_multiple_of(self.stride)
    }

    /// Records a fresh present at `now` of a frame at `scale` rendered for `camera`; `shown` is
    /// the presented buffer when [`Playback::wants_sample`] said so.
    pub fn presented(&mut self, now: Instant, scale: f64, camera: Camera, shown: Option<(&[u32], u32, u32)>) {
        if self.finished() || self.start.is_none() {
            return;
        }
        self.presented += 1;
        if let Some(prev) = self.last_present.replace(now) {
            self.intervals.push((now - prev).as_secs_f64());
        }
        self.scales.push(scale);
        let Some((buffer, width, height)) = shown else {
            return;
        };
        let t = self.t(now);
        let rgb = buffer[..(width * height) as usize]
            .iter()
            .flat_map(|&p| [(p >> 16) as u8, (p >> 8) as u8, p as u8])
            .collect();
        self.samples.push(Sample { index: self.presented, t, scale, camera, width, height, rgb });
        if self.samples.len() > MAX_SAMPLES {
            self.stride *= 2;
            let stride = self.stride;
            self.samples.retain(|s| (s.index - 1).is_multiple_of(stride));
        }
    }

    /// Records what the last fresh present cost outside tracing and whether its frame was
    /// reprojected (ignored outside the path).
    pub fn costs(&mut self, costs: FrameCosts, reprojected: bool) {
        if !self.finished() && self.start.is_some() {
            self.costs.push(costs);
            self.reprojected += reprojected as u64;
        }
    }

    pub fn frames_presented(&self) -> u64 {
        self.presented
    }

    /// Seconds from the first frame of the path to its end (or to now, if it has not ended).
    pub fn wall_seconds(&self) -> f64 {
        match (self.start, self.end) {
            (Some(s), Some(e)) => (e - s).as_secs_f64(),
            (Some(s), None) => s.elapsed().as_secs_f64(),
            _ => 0.0,
        }
    }

    pub fn samples(&self) -> &[Sample] {
        &self.samples
    }
}

/// What the report says about the run besides the measurements.
pub struct ReportContext<'a> {
    /// The scene file, as given on the command line.
    pub scene: &'a str,
    pub path: &'a Path,
    pub width: u32,
    pub height: u32,
    pub target_fps: f64,
    pub aa: u32,
    pub quality: Quality,
    pub threads: usize,
    /// Moving frames were reprojected (`render::reproject`), not rendered whole.
    pub reproject: bool,
}

fn stats(values: &[f64], unit: f64) -> Json {
    let mut sorted: Vec<f64> = values.iter().map(|v| v * unit).collect();
    sorted.sort_by(f64::total_cmp);
    let mean = if sorted.is_empty() { f64::NAN } else { sorted.iter().sum::<f64>() / sorted.len() as f64 };
    Json::object(vec![
        ("mean", Json::Number(mean)),
        ("median", Json::Number(percentile(&sorted, 50.0))),
        ("p5", Json::Number(percentile(&sorted, 5.0))),
        ("p95", Json::Number(percentile(&sorted, 95.0))),
        ("min", Json::Number(sorted.first().copied().unwrap_or(f64::NAN))),
        ("max", Json::Number(sorted.last().copied().unwrap_or(f64::NAN))),
    ])
}

fn pooled_psnr(sse: f64, values: usize) -> f64 {
    if values == 0 {
        return f64::NAN;
    }
    let mse = sse / values as f64;
    if mse == 0.0 {
        PSNR_CAP
    } else {
        (10.0 * (255.0 * 255.0 / mse).log10()).min(PSNR_CAP)
    }
}

/// Renders the full-quality reference for every sample and builds the report.
pub fn report(playback: &Playback, scene: &Scene, cx: &ReportContext) -> Result<Json, CliError> {
    let mut rows = Vec::new();
    let (mut psnrs, mut ssims, mut sse, mut values) = (Vec::new(), Vec::new(), 0.0, 0usize);
    let mut image = Image::default();
    for s in playback.samples() {
        let settings = RenderSettings {
            width: s.width,
            height: s.height,
            aa: cx.aa,
            quality: cx.quality,
            ..RenderSettings::default()
        };
        with_threads(cx.threads, || render(scene, &s.camera, &settings, &mut image))?;
        let reference = image.to_rgb8(scene.srgb);
        let p = psnr(&s.rgb, &reference).min(PSNR_CAP);
        sse += s.rgb.iter().zip(&reference).map(|(&a, &b)| (a as f64 - b as f64).powi(2)).sum::<f64>();
        values += reference.len();
        let q = ssim(s.width, s.height, &s.rgb, &reference);
        psnrs.push(p);
        ssims.push(q);
        rows.push(Json::object(vec![
            ("frame", Json::Number(s.index as f64)),
            ("t", Json::Number(s.t)),
            ("scale", Json::Number(s.scale)),
            ("psnr_db", Json::Number(p)),
            ("ssim", Json::Number(q)),
        ]));
    }
    let wall = playback.wall_seconds();
    let fps = if wall > 0.0 { playback.frames_presented() as f64 / wall } else { 0.0 };
    let q = cx.quality;
    Ok(Json::object(vec![
        ("scene", Json::str(cx.scene)),
        ("path", Json::str(cx.path.display().to_string())),
        ("width", Json::Number(cx.width as f64)),
        ("height", Json::Number(cx.height as f64)),
        ("path_seconds", Json::Number(playback.seconds)),
        ("target_fps", Json::Number(cx.target_fps)),
        ("reproject", Json::Bool(cx.reproject)),
        // How many presented frames were reprojected (where allowed, the cheaper way is chosen).
        ("reprojected_frames", Json::Number(playback.reprojected as f64)),
        ("wall_seconds", Json::Number(wall)),
        ("frames_presented", Json::Number(playback.frames_presented() as f64)),
        ("presented_fps", Json::Number(fps)),
        ("frame_time_ms", stats(&playback.intervals, 1e3)),
        ("render_scale", stats(&playback.scales, 1.0)),
        // Milliseconds per fresh present outside tracing (render thread and window), by stage.
        ("non_tracing_ms", frame_costs::report(&playback.costs, stats)),
        ("psnr_db", stats(&psnrs, 1.0)),
        // PSNR of all samples' pixels together (of the mean squared error, not the mean of dB):
        // not dominated by a few near-identical frames the way the mean is.
        ("psnr_db_pooled", Json::Number(pooled_psnr(sse, values))),
        ("ssim", stats(&ssims, 1.0)),
        (
            "reference",
            Json::object(vec![
                ("aa", Json::Number(cx.aa as f64)),
                ("max_trace_level", Json::opt_u32(q.max_trace_level)),
                ("shadows", Json::Bool(q.shadows)),
                ("max_octaves", Json::opt_u32(q.max_octaves)),
                ("note", Json::str("full-size headless render() of each sample's camera")),
            ]),
        ),
        ("samples", Json::Array(rows)),
        (
            "machine",
            Json::object(vec![
                ("cpu", Json::str(cpu_model())),
                ("cores", Json::Number(std::thread::available_parallelism().map_or(0, |n| n.get()) as f64)),
            ]),
        ),
    ]))
}

pub fn write_report(path: &Path, report: &Json) -> Result<(), CliError> {
    output::write_atomic(path, report.to_pretty().as_bytes())
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use glam::DVec3;

    use super::*;
    use crate::camera::path::{Key, Spline};

    fn line_path(times: [f64; 2]) -> CameraPath {
        let key = |time, x| Key { time, location: DVec3::new(x, 1.0, -5.0), look_at: DVec3::Y, angle: None };
        CameraPath::new(vec![key(times[0], 0.0), key(times[1], 2.0)], Spline::Centripetal, false, false)
    }

    #[test]
    fn default_seconds_reads_key_times_as_seconds_unless_normalised() {
        assert_eq!(default_seconds(&line_path([0.0, 5.0])), 5.0);
        assert_eq!(default_seconds(&line_path([0.0, 1.0])), DEFAULT_SECONDS);
    }

    #[test]
    fn clock_runs_zero_to_one_and_then_ends() {
        let mut p = Playback::new(line_path([0.0, 1.0]), 2.0);
        let base = Camera::from_desc(&Default::default());
        let t0 = Instant::now();
        let (c, done) = p.camera(t0, &base);
        assert!(!done && (c.location.x - 0.0).abs() < 1e-9);
        let (c, done) = p.camera(t0 + Duration::from_secs(1), &base);
        assert!(!done && (c.location.x - 1.0).abs() < 1e-6, "{c:?}");
        let (c, done) = p.camera(t0 + Duration::from_secs(3), &base);
        assert!(done && p.finished() && (c.location.x - 2.0).abs() < 1e-9);
        assert!((p.wall_seconds() - 3.0).abs() < 1e-9);
    }

    #[test]
    fn samples_thin_out_to_cover_the_whole_run() {
        let mut p = Playback::new(line_path([0.0, 1.0]), 1000.0);
        let base = Camera::from_desc(&Default::default());
        let t0 = Instant::now();
        p.camera(t0, &base);
        let px = [0x102030u32; 4];
        for i in 1..=1000u64 {
            let now = t0 + Duration::from_millis(i * 16);
            let shown = p.wants_sample().then_some((&px[..], 2, 2));
            p.presented(now, 0.5, base, shown);
        }
        assert_eq!(p.frames_presented(), 1000);
        let s = p.samples();
        assert!(s.len() <= MAX_SAMPLES && s.len() >= MAX_SAMPLES / 2, "{}", s.len());
        let stride = s[1].index - s[0].index;
        assert!(s.windows(2).all(|w| w[1].index - w[0].index == stride));
        assert!(s.last().unwrap().index > 900, "samples reach the end of the run");
        assert_eq!(s[0].rgb, [0x10, 0x20, 0x30].repeat(4));
    }

    #[test]
    fn report_compares_samples_with_the_headless_render() {
        let desc = crate::scene::fixtures::seed_scene();
        let scene = Scene::build(&desc, desc.camera.location, crate::scene::build::AccelKind::Bvh);
        let camera = Camera::from_desc(&desc.camera);
        let (w, h) = (32, 24);
        let mut image = Image::default();
        let settings = RenderSettings { width: w, height: h, ..RenderSettings::default() };
        render(&scene, &camera, &settings, &mut image);
        let exact: Vec<u32> = image
            .to_rgb8(scene.srgb)
            .chunks(3)
            .map(|c| (c[0] as u32) << 16 | (c[1] as u32) << 8 | c[2] as u32)
            .collect();
        let mut p = Playback::new(line_path([0.0, 1.0]), 1.0);
        let t0 = Instant::now();
        p.camera(t0, &camera);
        for i in 1..=10 {
            let shown = p.wants_sample().then_some((&exact[..], w, h));
            p.presented(t0 + Duration::from_millis(i * 20), 1.0, camera, shown);
            let blit = Duration::from_micros(100 * i);
            p.costs(FrameCosts { blit, ..FrameCosts::default() }, i % 2 == 0);
        }
        p.camera(t0 + Duration::from_secs(1), &camera);
        p.costs(FrameCosts { blit: Duration::from_secs(9), ..FrameCosts::default() }, true); // after the end
        let cx = ReportContext {
            scene: "seed.pov",
            path: Path::new("p.path"),
            width: w,
            height: h,
            target_fps: 60.0,
            aa: 1,
            quality: Quality::default(),
            threads: 1,
            reproject: true,
        };
        let json = report(&p, &scene, &cx).unwrap();
        assert_eq!(json.get("frames_presented").and_then(Json::as_u64), Some(10));
        assert!((json.get("presented_fps").and_then(Json::as_f64).unwrap() - 10.0).abs() < 1e-9);
        let samples = json.get("samples").and_then(Json::as_array).unwrap();
        assert_eq!(samples.len(), 1);
        // Identical pixels: PSNR at the cap, SSIM exactly 1.
        assert_eq!(samples[0].get("psnr_db").and_then(Json::as_f64), Some(PSNR_CAP));
        assert_eq!(samples[0].get("ssim").and_then(Json::as_f64), Some(1.0));
        assert_eq!(json.get("psnr_db_pooled").and_then(Json::as_f64), Some(PSNR_CAP));
        // Stage costs: the ten presents on the path (0.1 .. 1.0 ms of blit), not the one after.
        assert_eq!(json.get("reprojected_frames").and_then(Json::as_u64), Some(5));
        let costs = json.get("non_tracing_ms").unwrap();
        assert_eq!(costs.get("frames").and_then(Json::as_u64), Some(10));
        let blit = costs.get("blit").unwrap();
        assert!((blit.get("mean").and_then(Json::as_f64).unwrap() - 0.55).abs() < 1e-9);
        assert_eq!(blit.get("max").and_then(Json::as_f64), Some(1.0));
        assert_eq!(costs.get("total").unwrap().get("max").and_then(Json::as_f64), Some(1.0));
        assert_eq!(costs.get("hud").unwrap().get("max").and_then(Json::as_f64), Some(0.0));
    }
}
