//! `strahl capture`: renders frames along a camera path to PNGs plus `manifest.json`, whole or
//! as a shard (`--frames-range a..b`, or `--shard I/N`, which also resumes a killed shard), and
//! merges shard manifests (`--merge`).
//!
//! Frame i of N sits at t = i/(N-1) on the path, independent of the shard that renders it, and
//! render space is always centred on the scene's own camera, so a frame's pixels depend only on
//! (scene, path, N, i, settings): shards merge into exactly what one run would have written.
//! With `--clock A..B` (POV-Ray's `+KI +KF +KFF`) frame i's scene is parsed and built anew at
//! frame i's clock of the whole capture, so that holds for animated scenes too.

use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::time::Instant;

use sha2::{Digest, Sha256};

use crate::camera::path::CameraPath;
use crate::camera::Camera;
use crate::headless::json::Json;
use crate::headless::manifest::{frame_file_name, CameraRecord, FrameRecord, Manifest};
use crate::headless::progress::Progress;
use crate::headless::shard::{self, ShardSpec};
use crate::headless::{output, with_threads, CliError, Staged};
use crate::pov::Clock;
use crate::render::image::Image;
use crate::render::resample::render_scaled;
use crate::render::{render, RenderSettings};
use crate::scene::build::{AccelKind, Scene};

/// Frames `start..end` (half-open) of a capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameRange {
    pub start: u32,
    pub end: u32,
}

impl FromStr for FrameRange {
    type Err = String;

    fn from_str(s: &str) -> Result<FrameRange, String> {
        let bad = || format!("`{s}` is not a frame range: write START..END, e.g. 0..12 (END excluded)");
        let (a, b) = s.split_once("..").ok_or_else(bad)?;
        let start: u32 = a.trim().parse().map_err(|_| bad())?;
        let end: u32 = b.trim().parse().map_err(|_| bad())?;
        if end <= start {
            return Err(format!("frame range `{s}` is empty: END must be greater than START"));
        }
        Ok(FrameRange { start, end })
    }
}

impl fmt::Display for FrameRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

impl FrameRange {
    /// Checks the range against the capture's frame count.
    pub fn within(self, frames: u32) -> Result<FrameRange, CliError> {
        if self.end > frames {
            return Err(CliError::user(format!(
                "--frames-range {self} is out of bounds: the capture has frames 0..{frames}"
            )));
        }
        Ok(self)
    }
}

/// `--clock A..B`: the clock on the first frame and on the last (POV-Ray's `+KI` and `+KF`).
/// B below A runs the clock backwards; A equal to B holds it still while `clock_on` is true.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClockRange {
    pub from: f64,
    pub to: f64,
}

impl FromStr for ClockRange {
    type Err = String;

    fn from_str(s: &str) -> Result<ClockRange, String> {
        let bad =
            || format!("`{s}` is not a clock range: write A..B, e.g. 0..1 (the clock on the first and last frame)");
        let (a, b) = s.split_once("..").ok_or_else(bad)?;
        let from: f64 = a.trim().parse().map_err(|_| bad())?;
        let to: f64 = b.trim().parse().map_err(|_| bad())?;
        // Either would hand the scene NaN or infinite clocks.
        if !(from.is_finite() && to.is_finite()) {
            return Err(format!("clock range `{s}`: A and B must be finite numbers"));
        }
        if !(to - from).is_finite() {
            return Err(format!("clock range `{s}`: A and B are too far apart for a clock step"));
        }
        Ok(ClockRange { from, to })
    }
}

impl fmt::Display for ClockRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", self.from, self.to)
    }
}

impl ClockRange {
    /// The clock values frame `index` of `frames` is parsed with.
    pub fn frame(self, index: u32, frames: u32) -> Clock {
        Clock::frame(self.from, self.to, index, frames)
    }

    /// `{"from": A, "to": B}`, as the manifest and the bench report record it.
    pub fn to_json(self) -> Json {
        Json::object(vec![("from", Json::Number(self.from)), ("to", Json::Number(self.to))])
    }
}

/// The clock frame `index` of `frames` is parsed with: a still image's without `--clock`.
pub fn frame_clock(clock: Option<ClockRange>, index: u32, frames: u32) -> Clock {
    clock.map_or(Clock::default(), |c| c.frame(index, frames))
}

/// Path position of frame `i` of `n`: 0 for the first, 1 for the last, 0 when there is one.
pub fn frame_t(i: u32, n: u32) -> f64 {
    if n <= 1 {
        0.0
    } else {
        i as f64 / (n - 1) as f64
    }
}

/// Lower-case hex SHA-256 of a byte buffer.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

/// Everything `capture` needs besides the loaded scene; `scene_name`/`path_name` go into the
/// manifest as written by the user.
pub struct CaptureJob<'a> {
    pub scene_name: String,
    pub path_name: String,
    pub path: &'a CameraPath,
    pub frames: u32,
    /// The frames to render, ascending: a range of them, or the ones dealt to a shard.
    pub indices: Vec<u32>,
    /// Frames of this capture already rendered and checked (a resumed shard's): listed in the
    /// manifest with the new ones, not rendered again.
    pub done: Vec<FrameRecord>,
    /// Write the manifest after every frame, so that a shard killed mid-way (a requeued job
    /// array task) leaves a manifest of the frames it finished, which its rerun then skips.
    pub checkpoint: bool,
    pub settings: RenderSettings,
    /// Fraction of the output size to trace, upscaled back (1 = every pixel).
    pub res_scale: f32,
    pub accel: AccelKind,
    /// `--clock`: each frame's scene is parsed at its own clock (recorded in the manifest).
    pub clock: Option<ClockRange>,
    pub quiet: bool,
}

/// What, besides the camera, decides the pixels: recorded so shards of different settings never
/// merge. (Tile size and thread count are left out on purpose: they do not change pixels.)
pub fn settings_json(s: &RenderSettings, res_scale: f32, accel: AccelKind) -> Json {
    let mut fields = vec![
        ("res_scale", Json::Number(res_scale as f64)),
        ("aa", Json::Number(s.aa as f64)),
        ("max_trace_level", Json::opt_u32(s.quality.max_trace_level)),
        ("shadows", Json::Bool(s.quality.shadows)),
        ("max_octaves", Json::opt_u32(s.quality.max_octaves)),
        ("precision", Json::str(s.quality.precision.name())),
        ("accel", Json::str(accel.name())),
    ];
    // These caps change pixels too; written only when given, so manifests without them keep
    // the fields they always had (and still merge with shards written before).
    if let Some(n) = s.quality.max_area_samples {
        fields.push(("max_area_samples", Json::Number(n as f64)));
    }
    if let Some(n) = s.quality.max_blur_samples {
        fields.push(("max_blur_samples", Json::Number(n as f64)));
    }
    Json::object(fields)
}

/// Renders one frame into `image` and returns its 8-bit RGB pixels and the render time in ms.
pub fn render_rgb8(scene: &Scene, camera: &Camera, settings: &RenderSettings, image: &mut Image) -> (Vec<u8>, f64) {
    let start = Instant::now();
    render(scene, camera, settings, image);
    let ms = start.elapsed().as_secs_f64() * 1e3;
    (image.to_rgb8(scene.srgb), ms)
}

/// The manifest of `job` before any frame is rendered: what identifies the capture.
fn header(job: &CaptureJob) -> Manifest {
    Manifest {
        scene: job.scene_name.clone(),
        path: job.path_name.clone(),
        width: job.settings.width,
        height: job.settings.height,
        frame_count: job.frames,
        settings: settings_json(&job.settings, job.res_scale, job.accel),
        clock: job.clock,
        frames: Vec::new(),
    }
}

/// Renders the job's frames into `out_dir` (which must exist) and returns their manifest, which
/// the caller writes. Runs on the current rayon pool. Frame `index` is rendered from
/// `own_scene(index)` where that gives one (a scene parsed at the frame's clock), else from
/// `shared`; parsing is not counted in `render_ms`.
pub fn capture(
    shared: &Staged,
    own_scene: &dyn Fn(u32) -> Result<Option<Staged>, CliError>,
    job: &CaptureJob,
    out_dir: &Path,
) -> Result<Manifest, CliError> {
    let mut image = Image::new(job.settings.width, job.settings.height);
    let mut low = Image::default();
    let progress = Progress::new(job.indices.len() as u64, "frames", job.quiet);
    let pause = frame_delay();
    let mut frames = job.done.clone();
    for (k, &index) in job.indices.iter().enumerate() {
        let own = own_scene(index)?;
        let Staged { scene, base } = own.as_ref().unwrap_or(shared);
        let t = frame_t(index, job.frames);
        let (location, look_at, angle) = job.path.sample(t);
        let camera = Camera::looking_at(location, look_at, angle, base);
        let start = Instant::now();
        render_scaled(scene, &camera, &job.settings, job.res_scale, &mut low, &mut image);
        let render_ms = start.elapsed().as_secs_f64() * 1e3;
        let rgb = image.to_rgb8(scene.srgb);
        let file = frame_file_name(index);
        output::write_png(&out_dir.join(&file), image.width, image.height, &rgb)?;
        frames.push(FrameRecord {
            index,
            t,
            file,
            camera: CameraRecord::new(&camera, look_at),
            sha256: sha256_hex(&rgb),
            render_ms,
        });
        if job.checkpoint {
            write_manifest(out_dir, &sorted(frames.clone(), job))?;
        }
        if let Some(pause) = pause {
            std::thread::sleep(pause);
        }
        progress.update(k as u64 + 1);
    }
    progress.finish();
    Ok(sorted(frames, job))
}

/// `STRAHL_FRAME_DELAY_MS=N`: a pause of N ms after each frame. Only for tests that must catch
/// a shard in the middle of its frames (the Slurm test kills one there and requeues it: at
/// 64×48 a frame takes milliseconds, too fast to catch); unset, nothing waits.
fn frame_delay() -> Option<std::time::Duration> {
    let ms: u64 = std::env::var("STRAHL_FRAME_DELAY_MS").ok()?.trim().parse().ok()?;
    (ms > 0).then(|| std::time::Duration::from_millis(ms.min(60_000)))
}

/// The job's manifest listing `frames`, in index order.
fn sorted(mut frames: Vec<FrameRecord>, job: &CaptureJob) -> Manifest {
    frames.sort_by_key(|f| f.index);
    Manifest { frames, ..header(job) }
}

/// The frames among `wanted` that folder `dir` already holds for this capture: listed in its
/// manifest (which must be of the same capture) with a PNG whose pixels match the listed
/// SHA-256. Anything else (no manifest, another capture's, a frame file missing or cut short by
/// a kill) is rendered again.
fn already_done(dir: &Path, this: &Manifest, wanted: &[u32]) -> Vec<FrameRecord> {
    let Ok(found) = Manifest::read(dir) else {
        return Vec::new();
    };
    if !found.same_header(this) {
        return Vec::new();
    }
    found
        .frames
        .into_iter()
        .filter(|f| wanted.binary_search(&f.index).is_ok() && f.file == frame_file_name(f.index))
        .filter(|f| output::read_png(&dir.join(&f.file)).is_ok_and(|(_, _, rgb)| sha256_hex(&rgb) == f.sha256))
        .collect()
}

/// Deletes the temporary files of strahl's frames and manifest that a killed run left in `dir`
/// (`.frame_0003.png.1234.tmp`): nothing reads them, and they would pile up with every requeue.
fn remove_stale_temporaries(dir: &Path) {
    let Ok(listing) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in listing.filter_map(|e| e.ok()) {
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.starts_with('.') && name.ends_with(".tmp") && is_capture_file(&name) {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

pub fn write_manifest(dir: &Path, manifest: &Manifest) -> Result<(), CliError> {
    output::write_atomic(&dir.join("manifest.json"), manifest.to_json().to_pretty().as_bytes())
}

/// A file that `capture` writes into its folder: a frame, the manifest, or a temporary of either.
fn is_capture_file(name: &str) -> bool {
    let name = name
        .strip_prefix('.')
        .and_then(|n| n.strip_suffix(".tmp"))
        .map_or(name, |n| n.rsplit_once('.').map_or(n, |(a, _)| a));
    name == "manifest.json" || (name.starts_with("frame_") && name.ends_with(".png"))
}

/// What to do to the output folder once the scene has loaded, decided before anything changes.
#[derive(Debug, PartialEq)]
enum OutputPlan {
    /// Missing: create it.
    Create,
    /// Empty, or holding frames of this same capture (which it replaces): use it as it is.
    Use,
    /// `--force` on a folder of another capture: delete these files of strahl's first.
    Clear(Vec<PathBuf>),
}

/// Checks `-o DIR` before any work, without changing it. A folder holding another capture's
/// frames is refused (its `frame_0010.png` would survive a 5-frame capture and mix with the new
/// frames under `ffmpeg -i frame_%04d.png`) unless `force`, which deletes strahl's own files
/// there and nothing else.
fn plan_output(dir: &Path, this: &Manifest, force: bool) -> Result<OutputPlan, CliError> {
    let shown = dir.display();
    output::check_folder_writable("-o", dir)?;
    if !dir.exists() {
        return Ok(OutputPlan::Create);
    }
    let listing = std::fs::read_dir(dir).map_err(|e| CliError::user(format!("-o {shown}: cannot read folder: {e}")))?;
    let mut names: Vec<String> =
        listing.filter_map(|e| e.ok()).map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    if names.is_empty() || Manifest::read(dir).is_ok_and(|m| m.same_header(this)) {
        return Ok(OutputPlan::Use);
    }
    let ours: Vec<PathBuf> = names.iter().filter(|n| is_capture_file(n)).map(|n| dir.join(n)).collect();
    if force {
        return Ok(OutputPlan::Clear(ours));
    }
    let examples: Vec<&str> = names.iter().take(3).map(String::as_str).collect();
    let more = if names.len() > 3 { ", ..." } else { "" };
    Err(CliError::user(format!(
        "-o {shown}: the folder is not empty ({} files: {}{more}) and holds no manifest of this capture \
         (same scene, path, size, frame count, clock range and settings); its frames would mix with the new ones. \
         Give an empty or new folder, or --force to delete strahl's frame_NNNN.png and manifest.json there first",
        names.len(),
        examples.join(", ")
    )))
}

fn apply_output_plan(dir: &Path, plan: OutputPlan) -> Result<(), CliError> {
    match plan {
        OutputPlan::Create => output::create_dir(dir),
        OutputPlan::Use => Ok(()),
        OutputPlan::Clear(files) => files.iter().try_for_each(|f| {
            std::fs::remove_file(f).map_err(|e| CliError::user(format!("{}: cannot delete: {e}", f.display())))
        }),
    }
}

pub struct CaptureArgs {
    pub scene: PathBuf,
    pub include: Vec<PathBuf>,
    pub path: PathBuf,
    pub frames: u32,
    pub range: Option<FrameRange>,
    /// `--shard`: render only the frames dealt to this shard, resuming where a killed run of
    /// the same shard stopped.
    pub shard: Option<ShardSpec>,
    /// `--chunk`: deal each shard one contiguous run of frames instead of every N-th frame.
    pub chunk: bool,
    pub output: PathBuf,
    pub settings: RenderSettings,
    pub res_scale: f32,
    pub threads: usize,
    pub accel: AccelKind,
    /// `--clock A..B`: parse the scene anew for each frame at its clock.
    pub clock: Option<ClockRange>,
    pub quiet: bool,
    /// Delete strahl's frames and manifest from an output folder of another capture.
    pub force: bool,
}

/// `strahl capture SCENE --path P ...`. Everything a user can get wrong (frame count, range,
/// output folder, path file, scene) is checked before the output folder is created or changed
/// and before a frame is rendered. With `--clock` that covers the scene at the first frame's
/// clock; a scene that fails only at a later clock fails when that frame comes.
pub fn run(args: &CaptureArgs) -> Result<(), CliError> {
    if args.frames == 0 {
        return Err(CliError::user("--frames must be at least 1"));
    }
    let range = args.range.unwrap_or(FrameRange { start: 0, end: args.frames }).within(args.frames)?;
    let found = args.shard.map(|s| s.resolve(&shard::process_env).map_err(CliError::user)).transpose()?;
    let indices: Vec<u32> = match &found {
        Some(f) => f.shard.items(args.frames, 1, args.chunk),
        None => (range.start..range.end).collect(),
    };
    let path = CameraPath::load(&args.path)?;
    let mut job = CaptureJob {
        scene_name: args.scene.display().to_string(),
        path_name: args.path.display().to_string(),
        path: &path,
        frames: args.frames,
        indices,
        done: Vec::new(),
        checkpoint: found.is_some(),
        settings: args.settings,
        res_scale: args.res_scale,
        accel: args.accel,
        clock: args.clock,
        quiet: args.quiet,
    };
    let this = header(&job);
    let plan = plan_output(&args.output, &this, args.force)?;
    let load = |index| {
        let clock = frame_clock(args.clock, index, args.frames);
        Staged::load(&args.scene, &args.include, &args.settings, args.accel, clock).map(|(s, _)| s)
    };
    // The scene of the shard's first frame, so that scene errors come before the folder changes;
    // without --clock it is every frame's scene.
    let first_index = job.indices.first().copied().unwrap_or(0);
    let first = load(first_index)?;
    let own_scene = |index| if args.clock.is_some() && index != first_index { load(index).map(Some) } else { Ok(None) };
    // A shard resumes: a requeued task finds the frames its killed run finished and skips them.
    if found.is_some() && plan == OutputPlan::Use {
        job.done = already_done(&args.output, &this, &job.indices);
        job.indices.retain(|i| job.done.binary_search_by_key(i, |f| f.index).is_err());
        remove_stale_temporaries(&args.output);
    }
    apply_output_plan(&args.output, plan)?;
    if let Some(f) = &found {
        if !args.quiet {
            let resumed = if job.done.is_empty() {
                String::new()
            } else {
                format!(", resuming: {} already done, {} to render", job.done.len(), job.indices.len())
            };
            println!(
                "shard {} ({}): {} of {} frames{resumed}",
                f.shard,
                f.source,
                job.done.len() + job.indices.len(),
                args.frames
            );
            output::flush_stdout();
        }
    }
    let manifest = with_threads(args.threads, || capture(&first, &own_scene, &job, &args.output))??;
    write_manifest(&args.output, &manifest)?;
    if !args.quiet {
        let rendered: Vec<&FrameRecord> =
            manifest.frames.iter().filter(|f| job.indices.binary_search(&f.index).is_ok()).collect();
        let total: f64 = rendered.iter().map(|f| f.render_ms).sum();
        let clock = args.clock.map_or(String::new(), |c| format!(", clock {c}, scene parsed per frame"));
        let which = match &found {
            Some(f) => format!("shard {}", f.shard),
            None => format!("frames {range}"),
        };
        println!(
            "captured {which} of {} to {} ({} rendered, {:.1} ms/frame{clock})",
            args.frames,
            args.output.display(),
            rendered.len(),
            total / rendered.len().max(1) as f64
        );
        output::flush_stdout();
    }
    Ok(())
}

/// `strahl capture --merge DIR... -o OUT`: checks every shard's PNGs against its manifest,
/// copies them into OUT (unless already there) and writes the merged manifest.
pub fn run_merge(dirs: &[PathBuf], out: &Path) -> Result<(), CliError> {
    let parts = dirs.iter().map(|d| Manifest::read(d)).collect::<Result<Vec<_>, _>>()?;
    let merged = Manifest::merge(&parts).map_err(|e| CliError::user(format!("cannot merge: {e}")))?;
    // Verify before writing anything, so a bad shard leaves OUT untouched.
    let mut copies = Vec::new();
    for (dir, part) in dirs.iter().zip(&parts) {
        for f in &part.frames {
            let src = dir.join(&f.file);
            let (_, _, rgb) = output::read_png(&src)?;
            if sha256_hex(&rgb) != f.sha256 {
                return Err(CliError::user(format!("{}: pixels do not match the manifest's sha256", src.display())));
            }
            copies.push((src, out.join(&f.file)));
        }
    }
    output::create_dir(out)?;
    for (src, dst) in copies {
        let same = matches!((src.canonicalize(), dst.canonicalize()), (Ok(a), Ok(b)) if a == b);
        if !same {
            let bytes =
                std::fs::read(&src).map_err(|e| CliError::user(format!("{}: cannot read: {e}", src.display())))?;
            output::write_atomic(&dst, &bytes)?;
        }
    }
    write_manifest(out, &merged)?;
    println!("merged {} shards, {} frames, into {}", dirs.len(), merged.frames.len(), out.display());
    output::flush_stdout();
    Ok(())
}
