//! `strahl bench`: times `render()` over a fixed set of frames (a still camera, or a camera
//! path) and reports frame-time percentiles, rays per second by kind and the machine.
//!
//! The timed loop does nothing but `render()` into one pre-allocated image: cameras are computed
//! before it, and nothing is encoded or written, so the figures are the renderer's alone.
//! Warm-up frames (caches, page faults, rayon's thread start-up) run first and are not counted.
//! With `--clock A..B` each timed frame's scene is parsed and built anew at its clock, outside
//! the frame's timing; that time is reported on its own.

use std::convert::Infallible;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use crate::camera::path::CameraPath;
use crate::camera::Camera;
use crate::headless::capture::{frame_clock, frame_t, ClockRange};
use crate::headless::json::Json;
use crate::headless::{output, with_threads, CliError, Staged};
use crate::render::image::Image;
use crate::render::resample::render_scaled;
use crate::render::stats::RenderStats;
use crate::render::RenderSettings;
use crate::scene::build::{AccelKind, Scene};

/// Frame-time summary in milliseconds; percentiles by nearest rank.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTimes {
    pub median_ms: f64,
    pub p95_ms: f64,
    pub p99_ms: f64,
    pub max_ms: f64,
}

/// The nearest-rank `p`-th percentile (0 < p ≤ 100) of ascending `sorted`: the smallest value
/// with at least p% of the values at or below it. `NaN` for an empty slice.
pub fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = ((p / 100.0) * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

pub fn frame_times(times_ms: &[f64]) -> FrameTimes {
    let mut sorted = times_ms.to_vec();
    sorted.sort_by(f64::total_cmp);
    FrameTimes {
        median_ms: percentile(&sorted, 50.0),
        p95_ms: percentile(&sorted, 95.0),
        p99_ms: percentile(&sorted, 99.0),
        max_ms: sorted.last().copied().unwrap_or(f64::NAN),
    }
}

/// The CPU's model name from /proc/cpuinfo, or "unknown".
pub fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into())
}

/// One timed run: per-frame times and the summed statistics of the timed frames.
pub struct Run {
    pub threads: usize,
    pub times_ms: Vec<f64>,
    pub stats: RenderStats,
    pub seconds: f64,
    /// With `--clock`: milliseconds spent parsing and building each timed frame's scene, which
    /// `times_ms` leaves out. Empty otherwise.
    pub parse_ms: Vec<f64>,
}

impl Run {
    /// Million rays per second of `count` rays over the timed frames.
    pub fn mrays(&self, count: u64) -> f64 {
        count as f64 / self.seconds.max(1e-12) / 1e6
    }
}

/// Renders `warmup` untimed frames, then times each camera once. Call inside the thread pool.
pub fn timed_run(scene: &Scene, cameras: &[Camera], warmup: u32, settings: &RenderSettings) -> Run {
    timed_run_scaled(scene, cameras, warmup, settings, 1.0)
}

/// `timed_run` tracing `res_scale` of the size and upscaling back; the upscale is timed too,
/// since a frame is not done without it.
pub fn timed_run_scaled(
    scene: &Scene,
    cameras: &[Camera],
    warmup: u32,
    settings: &RenderSettings,
    res_scale: f32,
) -> Run {
    let Ok(run) = timed_frames(scene, cameras, warmup, settings, res_scale, |_| Ok::<_, Infallible>(None));
    run
}

/// A timed frame's own scene (parsed at the frame's `--clock` value) and the camera it is seen
/// from, with the milliseconds parsing and building took.
pub struct OwnFrame {
    pub staged: Staged,
    pub camera: Camera,
    pub parse_ms: f64,
}

/// [`timed_run_scaled`], but timed frame i is rendered from `own_frame(i)` where that gives one
/// (made before its timer starts; its parse time goes to `Run::parse_ms`). Warm-up frames use
/// `scene`.
pub fn timed_frames<E>(
    scene: &Scene,
    cameras: &[Camera],
    warmup: u32,
    settings: &RenderSettings,
    res_scale: f32,
    mut own_frame: impl FnMut(usize) -> Result<Option<OwnFrame>, E>,
) -> Result<Run, E> {
    // Allocated once at full size: `render` resizes in place and never reallocates after this.
    let mut image = Image::new(settings.width, settings.height);
    let mut low = Image::new(settings.width, settings.height);
    for i in 0..warmup as usize {
        render_scaled(scene, &cameras[i % cameras.len()], settings, res_scale, &mut low, &mut image);
    }
    let mut times_ms = Vec::with_capacity(cameras.len());
    let mut parse_ms = Vec::new();
    let mut stats = RenderStats::default();
    for (i, camera) in cameras.iter().enumerate() {
        let own = own_frame(i)?;
        parse_ms.extend(own.as_ref().map(|o| o.parse_ms));
        let (scene, camera) = own.as_ref().map_or((scene, camera), |o| (&o.staged.scene, &o.camera));
        let start = Instant::now();
        let s = render_scaled(scene, camera, settings, res_scale, &mut low, &mut image);
        times_ms.push(start.elapsed().as_secs_f64() * 1e3);
        stats += s;
    }
    let seconds = times_ms.iter().sum::<f64>() / 1e3;
    Ok(Run { threads: rayon::current_num_threads(), times_ms, stats, seconds, parse_ms })
}

pub struct BenchArgs {
    pub scene: PathBuf,
    pub include: Vec<PathBuf>,
    pub path: Option<PathBuf>,
    pub frames: u32,
    pub warmup: u32,
    pub json: Option<PathBuf>,
    pub settings: RenderSettings,
    /// Fraction of the output size to trace, upscaled back (1 = every pixel).
    pub res_scale: f32,
    pub threads: usize,
    pub accel: AccelKind,
    pub threads_sweep: bool,
    /// `--clock A..B`: parse each timed frame's scene at its clock.
    pub clock: Option<ClockRange>,
}

fn quality_json(s: &RenderSettings, res_scale: f32) -> Json {
    Json::object(vec![
        ("res_scale", Json::Number(res_scale as f64)),
        ("aa", Json::Number(s.aa as f64)),
        ("max_trace_level", Json::opt_u32(s.quality.max_trace_level)),
        ("shadows", Json::Bool(s.quality.shadows)),
        ("max_octaves", Json::opt_u32(s.quality.max_octaves)),
        ("precision", Json::str(s.quality.precision.name())),
    ])
}

fn quality_text(s: &RenderSettings, res_scale: f32, scene_level: u32) -> String {
    let octaves = s.quality.max_octaves.map_or("scene".to_string(), |o| o.to_string());
    format!(
        "res_scale {res_scale}, aa {}x{}, max_trace_level {}, shadows {}, max_octaves {octaves}, precision {}",
        s.aa,
        s.aa,
        s.quality.max_trace_level.unwrap_or(scene_level),
        if s.quality.shadows { "on" } else { "off" },
        s.quality.precision
    )
}

/// The human-readable report.
pub fn report(args: &BenchArgs, run: &Run, scene_level: u32, cpu: &str) -> String {
    let t = frame_times(&run.times_ms);
    let s = &run.stats;
    let secondary = s.reflected_rays + s.refracted_rays;
    let mut o = String::new();
    let camera = args.path.as_ref().map_or("still scene camera".to_string(), |p| format!("path {}", p.display()));
    let _ = writeln!(
        o,
        "bench {} {}x{}, {} frames (+{} warm-up), {camera}",
        args.scene.display(),
        args.settings.width,
        args.settings.height,
        args.frames,
        args.warmup
    );
    let _ = writeln!(o, "cpu:        {cpu}");
    let _ = writeln!(
        o,
        "threads:    {}   accel: {}   packets: {}",
        run.threads,
        args.accel.name(),
        if args.settings.packets { "on" } else { "off" }
    );
    let _ = writeln!(o, "quality:    {}", quality_text(&args.settings, args.res_scale, scene_level));
    let _ = writeln!(
        o,
        "frame time: median {:.2} ms   p95 {:.2} ms   p99 {:.2} ms   max {:.2} ms",
        t.median_ms, t.p95_ms, t.p99_ms, t.max_ms
    );
    let _ = writeln!(o, "fps:        {:.1} (from the median)", 1e3 / t.median_ms);
    if let Some(clock) = args.clock {
        let _ = writeln!(
            o,
            "clock:      {clock}, scene parsed and built anew for every timed frame: median {:.2} ms, not in frame time",
            frame_times(&run.parse_ms).median_ms
        );
    }
    let _ = writeln!(
        o,
        "rays:       {:.2} Mrays/s total   primary {:.2}   shadow {:.2}   secondary {:.2}",
        run.mrays(s.total_rays()),
        run.mrays(s.primary_rays),
        run.mrays(s.shadow_rays),
        run.mrays(secondary)
    );
    o
}

/// The `--json` object.
pub fn report_json(args: &BenchArgs, run: &Run, cpu: &str, sweep: &[Run]) -> Json {
    let t = frame_times(&run.times_ms);
    let s = &run.stats;
    let secondary = s.reflected_rays + s.refracted_rays;
    let mut fields = vec![
        ("scene", Json::str(args.scene.display().to_string())),
        ("path", args.path.as_ref().map_or(Json::Null, |p| Json::str(p.display().to_string()))),
        ("width", Json::Number(args.settings.width as f64)),
        ("height", Json::Number(args.settings.height as f64)),
        ("frames", Json::Number(args.frames as f64)),
        ("warmup", Json::Number(args.warmup as f64)),
        ("median_ms", Json::Number(t.median_ms)),
        ("p95_ms", Json::Number(t.p95_ms)),
        ("p99_ms", Json::Number(t.p99_ms)),
        ("max_ms", Json::Number(t.max_ms)),
        ("fps_median", Json::Number(1e3 / t.median_ms)),
        ("mrays_per_s", Json::Number(run.mrays(s.total_rays()))),
        (
            "mrays_per_s_by_kind",
            Json::object(vec![
                ("primary", Json::Number(run.mrays(s.primary_rays))),
                ("shadow", Json::Number(run.mrays(s.shadow_rays))),
                ("secondary", Json::Number(run.mrays(secondary))),
            ]),
        ),
        (
            "rays",
            Json::object(vec![
                ("primary", Json::Number(s.primary_rays as f64)),
                ("shadow", Json::Number(s.shadow_rays as f64)),
                ("reflected", Json::Number(s.reflected_rays as f64)),
                ("refracted", Json::Number(s.refracted_rays as f64)),
            ]),
        ),
        ("threads", Json::Number(run.threads as f64)),
        ("accel", Json::str(args.accel.name())),
        ("packets", Json::Bool(args.settings.packets)),
        ("quality", quality_json(&args.settings, args.res_scale)),
        ("cpu", Json::str(cpu)),
        ("frame_ms", Json::Array(run.times_ms.iter().map(|&v| Json::Number(v)).collect())),
    ];
    if let Some(clock) = args.clock {
        fields.push(("clock", clock.to_json()));
        fields.push(("parse_median_ms", Json::Number(frame_times(&run.parse_ms).median_ms)));
        fields.push(("parse_ms", Json::Array(run.parse_ms.iter().map(|&v| Json::Number(v)).collect())));
    }
    if !sweep.is_empty() {
        fields.push(("threads_sweep", sweep_json(sweep)));
    }
    Json::object(fields)
}

fn sweep_json(sweep: &[Run]) -> Json {
    let base = frame_times(&sweep[0].times_ms).median_ms;
    Json::Array(
        sweep
            .iter()
            .map(|r| {
                let m = frame_times(&r.times_ms).median_ms;
                Json::object(vec![
                    ("threads", Json::Number(r.threads as f64)),
                    ("median_ms", Json::Number(m)),
                    ("speedup", Json::Number(base / m)),
                ])
            })
            .collect(),
    )
}

/// The scaling table: frame time and speedup over one thread, per thread count.
pub fn sweep_table(sweep: &[Run]) -> String {
    let mut o = String::from("threads  median ms  speedup\n");
    if let Some(first) = sweep.first() {
        let base = frame_times(&first.times_ms).median_ms;
        for r in sweep {
            let m = frame_times(&r.times_ms).median_ms;
            let _ = writeln!(o, "{:>7}  {:>9.2}  {:>6.2}x", r.threads, m, base / m);
        }
    }
    o
}

/// `load: parse … ms, build … ms, N primitives (T mesh triangles); peak memory … after
/// parsing, … after building, … resident once the description is dropped (… bytes per
/// primitive)`: what loading cost, measured
/// as the OS sees it (VmHWM and VmRSS), so a primitive's real footprint shows (issue #14:
/// 2 000 000 spheres took 2.4 GB).
fn load_line(scene: &Scene, parse: Duration, build: Duration, memory: [Option<u64>; 3]) -> String {
    let [parsed, peak, resident] = memory;
    let prims = scene.prims.len() + scene.planes.len();
    let triangles: usize = scene.meshes.iter().map(|m| m.data.triangles.len()).sum();
    let mb = |b: Option<u64>| b.map_or("?".to_string(), |b| format!("{:.1} MB", b as f64 / 1048576.0));
    let mut o = format!(
        "load: parse {:.1} ms, build {:.1} ms, {prims} primitives",
        parse.as_secs_f64() * 1e3,
        build.as_secs_f64() * 1e3
    );
    if triangles > 0 {
        let _ = write!(o, " ({triangles} mesh triangles)");
    }
    let _ = write!(
        o,
        "; peak memory {} after parsing, {} after building, {} resident once the description is dropped",
        mb(parsed),
        mb(peak),
        mb(resident)
    );
    if let Some(r) = resident {
        let _ = write!(o, " ({:.0} bytes per primitive)", r as f64 / prims.max(triangles).max(1) as f64);
    }
    o
}

pub fn run(args: &BenchArgs) -> Result<(), CliError> {
    if args.frames == 0 {
        return Err(CliError::user("--frames must be at least 1"));
    }
    if let Some(file) = &args.json {
        output::check_writable("--json", file)?;
    }
    let path = args.path.as_deref().map(CameraPath::load).transpose()?;
    let load = |i| {
        Staged::load(&args.scene, &args.include, &args.settings, args.accel, frame_clock(args.clock, i, args.frames))
    };
    // The first frame's scene: every frame's without --clock, and the warm-up frames' with it.
    // Loaded in two timed stages, with the memory each leaves, for the load line of the report.
    let (desc, parse) = crate::headless::load_with_clock(
        &args.scene,
        &args.include,
        args.settings.width,
        args.settings.height,
        frame_clock(args.clock, 0, args.frames),
    )?;
    let parsed = crate::headless::peak_memory_bytes();
    let build_start = Instant::now();
    let first = Staged::new(&desc, args.accel);
    let build = build_start.elapsed();
    let peak = crate::headless::peak_memory_bytes();
    drop(desc);
    let memory = [parsed, peak, crate::headless::resident_memory_bytes()];
    println!("{}", load_line(&first.scene, parse, build, memory));
    let camera_at = |i: u32, base: &Camera| path.as_ref().map_or(*base, |p| p.camera_at(frame_t(i, args.frames), base));
    let cameras: Vec<Camera> = (0..args.frames).map(|i| camera_at(i, &first.base)).collect();
    let own_frame = |i: usize| -> Result<Option<OwnFrame>, CliError> {
        if args.clock.is_none() {
            return Ok(None);
        }
        let (staged, parse) = load(i as u32)?;
        let camera = camera_at(i as u32, &staged.base);
        Ok(Some(OwnFrame { staged, camera, parse_ms: parse.as_secs_f64() * 1e3 }))
    };
    let timed = |threads| {
        with_threads(threads, || {
            timed_frames(&first.scene, &cameras, args.warmup, &args.settings, args.res_scale, &own_frame)
        })?
    };
    let main_run = timed(args.threads)?;
    let cpu = cpu_model();
    print!("{}", report(args, &main_run, first.scene.max_trace_level, &cpu));
    let mut sweep = Vec::new();
    if args.threads_sweep {
        for n in 1..=crate::headless::cores() {
            sweep.push(timed(n)?);
        }
        print!("\n{}", sweep_table(&sweep));
    }
    output::flush_stdout();
    if let Some(file) = &args.json {
        output::write_atomic(file, report_json(args, &main_run, &cpu, &sweep).to_pretty().as_bytes())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::fixtures::seed_scene;

    #[test]
    fn nearest_rank_percentiles() {
        // 1..=20 ms in shuffled order: median = 10 (rank 10), p95 = 19 (rank 19), p99 = 20.
        let times: Vec<f64> = (1..=20).map(|i| ((i * 7) % 20 + 1) as f64).collect();
        let t = frame_times(&times);
        assert_eq!((t.median_ms, t.p95_ms, t.p99_ms, t.max_ms), (10.0, 19.0, 20.0, 20.0));
        // Odd count: median is the middle value; a single value is every percentile.
        assert_eq!(percentile(&[1.0, 2.0, 3.0], 50.0), 2.0);
        assert_eq!(frame_times(&[4.5]), FrameTimes { median_ms: 4.5, p95_ms: 4.5, p99_ms: 4.5, max_ms: 4.5 });
        assert!(percentile(&[], 50.0).is_nan());
        // Small samples: p95 of 10 values is rank 10 (the max), not an interpolation.
        let ten: Vec<f64> = (1..=10).map(f64::from).collect();
        assert_eq!(percentile(&ten, 95.0), 10.0);
        assert_eq!(percentile(&ten, 50.0), 5.0);
    }

    #[test]
    fn timed_run_counts_only_timed_frames() {
        let desc = seed_scene();
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let cam = Camera::from_desc(&desc.camera);
        let settings = RenderSettings { width: 16, height: 12, ..RenderSettings::default() };
        let run =
            with_threads(1, || timed_run(&scene, &[cam, cam, cam], 2, &settings)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(run.times_ms.len(), 3);
        assert_eq!(run.threads, 1);
        assert_eq!(run.stats.primary_rays, 3 * 16 * 12);
        assert!(run.stats.shadow_rays > 0);
    }
}
