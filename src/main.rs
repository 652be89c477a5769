//! The `strahl` command line: parses arguments, runs one subcommand, prints one error.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

use strahl::headless::capture::{self, ClockRange, FrameRange};
use strahl::headless::farm::{self, SlurmJob, Work};
use strahl::headless::shard::{ShardSpec, MAX_SHARDS};
use strahl::headless::{self, bench, still_part, tradeoff, CliError};
use strahl::render::precision::Precision;
use strahl::render::preset::Preset;
use strahl::render::resample::MIN_RES_SCALE;
use strahl::render::{Quality, RenderSettings};
use strahl::scene::build::AccelKind;

#[derive(Parser)]
#[command(name = "strahl", version, about = "A real-time CPU ray tracer for POV-Ray scenes", long_about = None)]
struct Cli {
    /// Without a subcommand, opens the window on scenes/seed.pov (`strahl view`).
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Render one still image of a scene to PNG and print POV-Ray-style statistics.
    Render(RenderCmd),
    /// Render frames along a camera path to DIR/frame_NNNN.png plus DIR/manifest.json.
    Capture(CaptureCmd),
    /// Join the parts of a still rendered with `render --shard I/N` into the whole image.
    Merge(MergeCmd),
    /// Render on a cluster: write (and submit) a scheduler's job script for a sharded capture
    /// or still (see docs/farm.md).
    #[command(subcommand)]
    Farm(FarmCmd),
    /// Time render() over frames and report frame-time percentiles and rays per second.
    Bench(BenchCmd),
    /// Measure every speed/accuracy knob and preset against the reference render: frame time,
    /// PSNR, SSIM and largest error, to DIR/tradeoff.{csv,md,svg} and DIR/errors/*.png.
    Tradeoff(TradeoffCmd),
    /// Fly through a scene in a window: adaptive resolution while moving, progressive
    /// antialiasing when still (converging to `strahl render` of the same camera).
    View(ViewCmd),
    /// BVH build and frame time against object count on generated scenes (or --intersection-share).
    Scaling(headless::scaling::ScalingCmd),
    /// Write a generated many-object scene (spheres, boxes, triangles, cylinders, mixed, mesh, tori) as a POV-Ray file.
    Gen(headless::scaling::GenCmd),
    /// Render every .pov under a folder (e.g. POV-Ray's samples) at a small size and count how
    /// many render, grouping the others by their first error.
    Survey(headless::survey::SurveyCmd),
    /// Generate a camera path for a scene (see docs/camera-paths.md).
    #[command(subcommand)]
    Path(PathCmd),
}

#[derive(Subcommand)]
enum PathCmd {
    /// A closed orbit around the scene camera's look_at, at the camera's distance and height,
    /// starting at the scene camera: a path for `bench --path` and `view --path --report`.
    Orbit(OrbitCmd),
}

#[derive(Args)]
struct OrbitCmd {
    /// The POV-Ray scene file.
    scene: PathBuf,
    /// The path file to write (replaced only once complete).
    #[arg(short = 'o', long, value_name = "FILE")]
    output: PathBuf,
    /// Keys around the circle (the file holds one more, repeating the first).
    #[arg(long, value_name = "N", default_value_t = headless::orbit::DEFAULT_KEYS, value_parser = clap::value_parser!(u32).range(3..=100_000))]
    frames: u32,
    /// Seconds one turn takes: the key times run from 0 to S.
    #[arg(long, value_name = "S", allow_hyphen_values = true, default_value_t = headless::orbit::DEFAULT_SECONDS, value_parser = headless::orbit::parse_seconds)]
    seconds: f64,
    /// Extra include folder, searched after the scene's own folder (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR", value_parser = headless::parse_include_dir)]
    include: Vec<PathBuf>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
}

#[derive(Clone, Copy, ValueEnum)]
enum AccelArg {
    Bvh,
    Grid,
    None,
}

impl AccelArg {
    fn name(self) -> &'static str {
        match self {
            AccelArg::Bvh => "bvh",
            AccelArg::Grid => "grid",
            AccelArg::None => "none",
        }
    }
}

impl From<AccelArg> for AccelKind {
    fn from(a: AccelArg) -> AccelKind {
        match a {
            AccelArg::Bvh => AccelKind::Bvh,
            AccelArg::Grid => AccelKind::Grid,
            AccelArg::None => AccelKind::None,
        }
    }
}

/// Options every rendering subcommand shares.
#[derive(Args)]
struct Common {
    /// Image width in pixels.
    #[arg(short = 'W', long, default_value_t = 640, value_parser = clap::value_parser!(u32).range(1..=16384))]
    width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long, default_value_t = 480, value_parser = clap::value_parser!(u32).range(1..=16384))]
    height: u32,
    /// Extra include folder, searched after the scene's own folder (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR", value_parser = headless::parse_include_dir)]
    include: Vec<PathBuf>,
    /// Worker threads (0 = one per core; at most 4 per core).
    #[arg(long, default_value_t = 0, value_parser = headless::parse_threads)]
    threads: usize,
    /// Speed/accuracy preset: fast, balanced, full (the scene as written; the default) or
    /// reference (4×4 aa, f64). Flags given explicitly override the preset's fields.
    #[arg(long, value_name = "NAME")]
    preset: Option<Preset>,
    /// Trace F×W by F×H pixels (0.1 to 1) and upscale back to W×H, bilinearly. Default 1.
    #[arg(long, value_name = "F", value_parser = parse_res_scale)]
    res_scale: Option<f32>,
    /// Antialiasing: N×N samples per pixel (1 = one ray through each pixel centre, as POV-Ray -A).
    /// Default 1.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16))]
    aa: Option<u32>,
    /// Acceleration structure for bounded objects.
    #[arg(long, value_enum, default_value_t = AccelArg::Bvh)]
    accel: AccelArg,
    /// Override the scene's max_trace_level.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=256))]
    max_depth: Option<u32>,
    /// Trace no shadow rays (every light reaches every point).
    #[arg(long)]
    no_shadows: bool,
    /// Trace every ray singly instead of primary and shadow rays in 8×8 packets (same image).
    #[arg(long)]
    no_packets: bool,
    /// Cap on turbulence/noise octaves (texture detail).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=32))]
    max_octaves: Option<u32>,
    /// Cap on the points of each area light (soft-shadow rays per shading point).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=65536))]
    max_area_samples: Option<u32>,
    /// Arithmetic of intersections: f32, or f64 (each ray's nearest hit re-solved in f64, for
    /// reference images). Default f32; the reference preset uses f64.
    #[arg(long, value_name = "P")]
    precision: Option<Precision>,
    /// Cap on a focal-blur camera's rays per sample (`blur_samples`).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=10000))]
    max_blur_samples: Option<u32>,
}

/// `--res-scale`: a number in MIN_RES_SCALE..=1.
fn parse_res_scale(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f32>() {
        Ok(f) if (MIN_RES_SCALE..=1.0).contains(&f) => Ok(f),
        _ => Err(format!("`{s}` is not a resolution scale: give a number from {MIN_RES_SCALE} to 1")),
    }
}

impl Common {
    /// The render settings: the preset (default `full`), with every flag given overriding it.
    fn settings(&self) -> RenderSettings {
        let preset = self.preset.unwrap_or(Preset::Full).settings();
        RenderSettings {
            width: self.width,
            height: self.height,
            aa: self.aa.unwrap_or(preset.aa),
            quality: Quality {
                max_trace_level: self.max_depth.or(preset.quality.max_trace_level),
                shadows: preset.quality.shadows && !self.no_shadows,
                max_octaves: self.max_octaves.or(preset.quality.max_octaves),
                precision: self.precision.unwrap_or(preset.quality.precision),
                max_area_samples: self.max_area_samples.or(preset.quality.max_area_samples),
                max_blur_samples: self.max_blur_samples.or(preset.quality.max_blur_samples),
            },
            packets: !self.no_packets,
            ..RenderSettings::default()
        }
    }

    /// The fraction of the size to trace: `--res-scale`, else the preset's.
    fn res_scale(&self) -> f32 {
        self.res_scale.unwrap_or(self.preset.unwrap_or(Preset::Full).settings().res_scale)
    }

    /// These options as command-line words, for a job script that runs strahl elsewhere:
    /// every option given, include folders made absolute (tasks start in another folder).
    /// `--threads` is left out: a farm's task takes the cores its scheduler gives it.
    fn to_args(&self) -> Result<Vec<String>, CliError> {
        let mut a = vec!["-W".to_string(), self.width.to_string(), "-H".into(), self.height.to_string()];
        for dir in &self.include {
            a.extend(["-L".into(), absolute(dir)?.display().to_string()]);
        }
        let mut opt = |flag: &str, v: Option<String>| {
            if let Some(v) = v {
                a.extend([flag.to_string(), v]);
            }
        };
        opt("--preset", self.preset.map(|p| p.name().to_string()));
        opt("--res-scale", self.res_scale.map(|f| f.to_string()));
        opt("--aa", self.aa.map(|n| n.to_string()));
        opt("--accel", Some(self.accel.name().to_string()));
        opt("--max-depth", self.max_depth.map(|n| n.to_string()));
        opt("--max-octaves", self.max_octaves.map(|n| n.to_string()));
        opt("--max-area-samples", self.max_area_samples.map(|n| n.to_string()));
        opt("--precision", self.precision.map(|p| p.name().to_string()));
        opt("--max-blur-samples", self.max_blur_samples.map(|n| n.to_string()));
        if self.no_shadows {
            a.push("--no-shadows".into());
        }
        if self.no_packets {
            a.push("--no-packets".into());
        }
        Ok(a)
    }
}

/// `path` from the root, for a job script run in another folder (and checked to exist now,
/// rather than in every task later).
fn absolute(path: &std::path::Path) -> Result<PathBuf, CliError> {
    std::fs::canonicalize(path).map_err(|e| CliError::user(format!("{}: {e}", path.display())))
}

/// `--clock` of capture and bench, one text for both.
const CLOCK_HELP: &str = "Animate: parse the scene anew for each frame, with `clock` running from A on the first \
                          frame to B on the last (POV-Ray's +KI A +KF B +KFF N), e.g. 0..1";

#[derive(Args)]
struct RenderCmd {
    /// The POV-Ray scene file.
    scene: PathBuf,
    /// Output PNG (checked before rendering: its folder must exist and the name end in .png).
    #[arg(short = 'o', long, default_value = "out.png")]
    output: PathBuf,
    /// Print no statistics.
    #[arg(short, long)]
    quiet: bool,
    /// A POV-Ray .ini whose animation (Initial_Frame, Final_Frame, Initial_Clock, Final_Clock)
    /// the scene is parsed for: its first frame, or --frame's. Other .ini settings are not read.
    #[arg(long, value_name = "FILE")]
    ini: Option<PathBuf>,
    /// With --ini: the frame number to render (POV-Ray's frame_number).
    #[arg(long, value_name = "K", requires = "ini")]
    frame: Option<u32>,
    /// Render only shard I of N (from 0): every N-th strip of 8 rows, at the full image's size,
    /// to OUTPUT.shard-I-of-N.png; `auto` reads I and N from a Slurm, AWS Batch or (with
    /// auto/N) Kubernetes job array. `--merge` or `strahl merge` joins the parts.
    #[arg(long, value_name = "I/N", conflicts_with = "merge")]
    shard: Option<ShardSpec>,
    /// With --shard: one contiguous band of rows per shard instead of interleaved strips.
    #[arg(long, requires = "shard")]
    chunk: bool,
    /// Join the parts that `--shard` wrote beside OUTPUT into OUTPUT, checking that they were
    /// rendered with this command line's scene, size and settings; renders nothing.
    #[arg(long)]
    merge: bool,
    #[command(flatten)]
    common: Common,
}

#[derive(Args)]
struct MergeCmd {
    /// The parts (`render --shard I/N` writes OUTPUT.shard-I-of-N.png), every shard of one render.
    #[arg(required = true, value_name = "PART")]
    parts: Vec<PathBuf>,
    /// The whole image to write (PNG; written only once every part checks out).
    #[arg(short = 'o', long, value_name = "PNG")]
    output: PathBuf,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
}

#[derive(Subcommand)]
enum FarmCmd {
    /// Write DIR/strahl.sbatch: a Slurm job array over the shards (logs DIR/logs/%x_%A_%a.out)
    /// and a merge job that runs once every shard succeeded. With --path, a capture (merged
    /// into DIR/frames); without, a still in bands (merged into DIR/SCENE.png).
    Slurm(SlurmCmd),
}

#[derive(Args)]
#[command(
    override_usage = "strahl farm slurm <SCENE> [--path <PATH> --frames <N>] -o <DIR> --tasks <N> [--submit] [OPTIONS]"
)]
struct SlurmCmd {
    /// The POV-Ray scene file.
    scene: PathBuf,
    /// Camera path: farm a capture of --frames frames along it (without it: a still).
    #[arg(long, requires = "frames")]
    path: Option<PathBuf>,
    /// Frames in the capture (with --path).
    #[arg(long, value_name = "N", requires = "path", value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    frames: Option<u32>,
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, requires = "path", help = CLOCK_HELP)]
    clock: Option<ClockRange>,
    /// Output folder: the script, logs/, parts/ and the merged result (created if missing).
    #[arg(short = 'o', long, value_name = "DIR")]
    output: PathBuf,
    /// Array tasks (shards).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=MAX_SHARDS as i64))]
    tasks: u32,
    /// Cores per task; each task renders with this many threads.
    #[arg(long, value_name = "C", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=4096))]
    cpus_per_task: u32,
    /// Time limit per task, in Slurm's syntax (e.g. 01:00:00).
    #[arg(long, value_name = "T")]
    time: Option<String>,
    /// Slurm partition.
    #[arg(long, value_name = "NAME")]
    partition: Option<String>,
    /// Another #SBATCH option, verbatim (repeatable), e.g. --sbatch=--account=proj.
    #[arg(long = "sbatch", value_name = "OPTION", allow_hyphen_values = true)]
    sbatch: Vec<String>,
    /// Slurm job name (default: strahl-SCENE).
    #[arg(long, value_name = "NAME")]
    job_name: Option<String>,
    /// Deal each shard contiguous frames or rows instead of interleaved ones.
    #[arg(long)]
    chunk: bool,
    /// The strahl executable the tasks run (default: this one).
    #[arg(long, value_name = "PATH")]
    strahl: Option<PathBuf>,
    /// Submit the array and the merge with sbatch and print their job ids.
    #[arg(long)]
    submit: bool,
    #[command(flatten)]
    common: Common,
}

/// `strahl farm slurm`: checks the job, writes the script, and submits it where asked.
fn farm_slurm(f: SlurmCmd) -> Result<(), CliError> {
    if f.common.threads != 0 {
        return Err(CliError::user("--threads is not for a farm: each task uses --cpus-per-task threads"));
    }
    let scene = absolute(&f.scene)?;
    let stem = scene.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "strahl".into());
    let mut args = vec![scene.display().to_string()];
    let work = match (&f.path, f.frames) {
        (Some(path), Some(frames)) => {
            if f.tasks > frames {
                return Err(CliError::user(format!(
                    "--tasks {} is more than the {frames} frames: give at most {frames}",
                    f.tasks
                )));
            }
            args.extend([
                "--path".into(),
                absolute(path)?.display().to_string(),
                "--frames".into(),
                frames.to_string(),
            ]);
            if let Some(c) = f.clock {
                args.push(format!("--clock={c}"));
            }
            args.extend(f.common.to_args()?);
            Work::Capture { args }
        }
        _ => {
            let (unit, what) = if f.chunk { (1, "rows") } else { (headless::band::STRIP, "strips of 8 rows") };
            let units = f.common.height.div_ceil(unit);
            if f.tasks > units {
                return Err(CliError::user(format!(
                    "--tasks {} is more than the image's {units} {what}: give at most {units}",
                    f.tasks
                )));
            }
            args.extend(f.common.to_args()?);
            Work::Still { args, name: stem.clone() }
        }
    };
    let strahl = match &f.strahl {
        Some(p) => absolute(p)?,
        None => std::env::current_exe()
            .map_err(|e| CliError::user(format!("cannot find this strahl executable ({e}); give --strahl")))?,
    };
    headless::output::check_folder_writable("-o", &f.output)?;
    headless::output::create_dir(&f.output)?;
    let job = SlurmJob {
        strahl,
        dir: absolute(&f.output)?,
        name: f.job_name.unwrap_or_else(|| format!("strahl-{stem}")),
        tasks: f.tasks,
        cpus_per_task: f.cpus_per_task,
        time: f.time,
        partition: f.partition,
        extra: f.sbatch,
        chunk: f.chunk,
        work,
    };
    let script = farm::write(&job)?;
    println!("wrote {}", script.display());
    if f.submit {
        let ids = farm::submit(&job, &script)?;
        println!("array job {} ({} shards), logs in {}", ids.array, job.tasks, job.dir.join("logs").display());
        println!("merge job {} (afterok:{}), result: {}", ids.merge, ids.array, job.result().display());
    } else {
        println!("submit with: bash {}", script.display());
    }
    headless::output::flush_stdout();
    Ok(())
}

#[derive(Args)]
#[command(override_usage = "strahl capture <SCENE> --path <PATH> --frames <N> -o <DIR> [OPTIONS]\n       \
                            strahl capture --merge <DIR>... -o <DIR>")]
struct CaptureCmd {
    /// The POV-Ray scene file (required unless --merge).
    #[arg(required_unless_present = "merge")]
    scene: Option<PathBuf>,
    /// Camera path file, see docs/camera-paths.md (required unless --merge).
    #[arg(long, required_unless_present = "merge")]
    path: Option<PathBuf>,
    /// Frames in the whole capture; frame i is at t = i/(N-1) on the path (required unless --merge).
    #[arg(long, value_name = "N", required_unless_present = "merge", value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    frames: Option<u32>,
    /// Render only frames START..END (END excluded) of the N, e.g. to shard across machines.
    #[arg(long, value_name = "START..END", conflicts_with = "shard")]
    frames_range: Option<FrameRange>,
    /// Render only shard I of N (from 0): frames I, I+N, I+2N, ...; `auto` reads I and N from a
    /// Slurm, AWS Batch or (with auto/N) Kubernetes job array. A shard rerun into its folder
    /// skips the frames its manifest lists as done, so a requeued task resumes.
    #[arg(long, value_name = "I/N")]
    shard: Option<ShardSpec>,
    /// With --shard: deal each shard one contiguous run of frames instead of every N-th frame.
    #[arg(long, requires = "shard")]
    chunk: bool,
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, help = CLOCK_HELP)]
    clock: Option<ClockRange>,
    /// Output folder: created if missing. It must be empty or hold this same capture (same scene,
    /// path, size, frame count, clock range and settings; its frames are replaced), so frames of
    /// two captures never mix.
    #[arg(short = 'o', long, value_name = "DIR")]
    output: PathBuf,
    /// Let -o name a folder of another capture: delete strahl's frame_NNNN.png and manifest.json
    /// there first (other files are left alone).
    #[arg(long, conflicts_with = "merge")]
    force: bool,
    /// Tile edge in pixels (does not change the pixels).
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=4096))]
    tile: u32,
    /// Merge the manifests (and frames) of shard folders into -o DIR instead of rendering.
    #[arg(long, num_args = 1.., value_name = "DIR", conflicts_with_all = ["scene", "path", "frames", "frames_range", "clock", "shard"])]
    merge: Vec<PathBuf>,
    /// Print nothing but errors, and no progress bar.
    #[arg(short, long)]
    quiet: bool,
    #[command(flatten)]
    common: Common,
}

#[derive(Args)]
struct BenchCmd {
    /// The POV-Ray scene file.
    scene: PathBuf,
    /// Camera path to follow; without it the scene's camera stays still.
    #[arg(long)]
    path: Option<PathBuf>,
    /// Timed frames.
    #[arg(long, value_name = "N", default_value_t = 30, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    frames: u32,
    /// Untimed frames rendered first.
    #[arg(long, value_name = "K", default_value_t = 3)]
    warmup: u32,
    /// Also write the results as JSON.
    #[arg(long, value_name = "FILE")]
    json: Option<PathBuf>,
    /// Tile edge in pixels.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=4096))]
    tile: u32,
    /// Also run the bench at 1, 2, ... all cores and print a scaling table.
    #[arg(long)]
    threads_sweep: bool,
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, help = CLOCK_HELP)]
    clock: Option<ClockRange>,
    #[command(flatten)]
    common: Common,
}

#[derive(Args)]
struct TradeoffCmd {
    /// The POV-Ray scene file.
    scene: PathBuf,
    /// Camera path: measure at --frames cameras along it instead of the scene camera.
    #[arg(long)]
    path: Option<PathBuf>,
    /// Cameras along --path (default 3); frame i is at t = i/(N-1).
    #[arg(long, value_name = "N", requires = "path", value_parser = clap::value_parser!(u32).range(1..=10_000))]
    frames: Option<u32>,
    /// Timed renders per setting and camera, after one warm-up; the median is reported.
    #[arg(long, value_name = "R", default_value_t = 3, value_parser = clap::value_parser!(u32).range(3..=1000))]
    repeats: u32,
    /// Image width in pixels.
    #[arg(short = 'W', long, default_value_t = 640, value_parser = clap::value_parser!(u32).range(1..=16384))]
    width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long, default_value_t = 480, value_parser = clap::value_parser!(u32).range(1..=16384))]
    height: u32,
    /// Output folder (created; files in it are replaced).
    #[arg(short = 'o', long, value_name = "DIR")]
    output: PathBuf,
    /// Extra include folder, searched after the scene's own folder (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR", value_parser = headless::parse_include_dir)]
    include: Vec<PathBuf>,
    /// Worker threads (0 = one per core; at most 4 per core).
    #[arg(long, default_value_t = 0, value_parser = headless::parse_threads)]
    threads: usize,
    /// Acceleration structure for bounded objects.
    #[arg(long, value_enum, default_value_t = AccelArg::Bvh)]
    accel: AccelArg,
}

#[derive(Args)]
struct ViewCmd {
    /// The POV-Ray scene file.
    #[arg(default_value = "scenes/seed.pov")]
    scene: PathBuf,
    /// Frame rate the adaptive resolution aims at while the camera moves.
    #[arg(long, value_name = "FPS", default_value_t = 60.0)]
    target_fps: f64,
    /// Present frames until the view has converged (or N were shown), save --screenshot, exit.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    frames: Option<u64>,
    /// PNG written by --frames and by F12 (default for F12: strahl-<time>.png).
    #[arg(long, value_name = "PNG")]
    screenshot: Option<PathBuf>,
    /// Start with the HUD and key help shown (F1 toggles them).
    #[arg(long)]
    hud: bool,
    /// Play this camera path in real time (adaptive resolution as when flying), then exit.
    #[arg(long, value_name = "FILE", conflicts_with = "frames")]
    path: Option<PathBuf>,
    /// Seconds the path takes (default: its key times if they span 2 or more, else 10).
    #[arg(long, value_name = "S", requires = "path")]
    path_seconds: Option<f64>,
    /// After the path, write presented fps, frame times, render scale and PSNR/SSIM against
    /// full-quality renders to this JSON file.
    #[arg(long, value_name = "FILE", requires = "path")]
    report: Option<PathBuf>,
    /// While moving, render every frame afresh at the adaptive resolution instead of tracing a
    /// quarter of the pixels and reusing the rest from the frame before.
    #[arg(long)]
    no_reproject: bool,
    #[command(flatten)]
    common: Common,
}

fn view(v: ViewCmd) -> Result<(), CliError> {
    if !(v.target_fps.is_finite() && v.target_fps > 0.0) {
        return Err(CliError::user(format!("--target-fps must be a positive number, not {}", v.target_fps)));
    }
    if v.common.res_scale.is_some() {
        return Err(CliError::user(
            "--res-scale is for render, capture and bench: the window picks its own resolution while the camera moves",
        ));
    }
    let settings = v.common.settings();
    let options = strahl::app::ViewOptions {
        width: v.common.width,
        height: v.common.height,
        aa: settings.aa,
        quality: settings.quality,
        threads: v.common.threads,
        accel: v.common.accel.into(),
        target_fps: v.target_fps,
        frames: v.frames,
        screenshot: v.screenshot,
        scene: v.scene.clone(),
        hud: v.hud,
        path: v.path.as_deref().map(|p| strahl::app::PathPlay::load(p, v.path_seconds)).transpose()?,
        report: v.report,
        reproject: !v.no_reproject,
    };
    strahl::app::view_file(&v.scene, &v.common.include, options)
}

fn run(cli: Cli) -> Result<(), CliError> {
    // No subcommand means `strahl view` with its defaults, so `cargo run` opens the window.
    let command = match cli.command {
        Some(c) => c,
        None => match Cli::parse_from(["strahl", "view"]).command {
            Some(c) => c,
            None => unreachable!("`strahl view` parses to the view command"),
        },
    };
    match command {
        Command::View(v) => view(v),
        Command::Scaling(s) => headless::scaling::run_scaling(&s),
        Command::Gen(g) => headless::scaling::run_gen(&g),
        Command::Survey(s) => headless::survey::run(&s),
        Command::Path(PathCmd::Orbit(o)) => headless::orbit::run(&headless::orbit::OrbitArgs {
            scene: o.scene,
            include: o.include,
            output: o.output,
            keys: o.frames,
            seconds: o.seconds,
            quiet: o.quiet,
        }),
        Command::Merge(m) => still_part::merge(&m.parts, &m.output, None, m.quiet),
        Command::Farm(FarmCmd::Slurm(f)) => farm_slurm(f),
        Command::Render(r) => {
            let merge = r.merge;
            let args = headless::render::RenderArgs {
                clock: match &r.ini {
                    Some(ini) => headless::render::clock_from_ini(ini, r.frame)?,
                    None => strahl::pov::Clock::default(),
                },
                scene: r.scene,
                include: r.common.include.clone(),
                output: r.output,
                settings: r.common.settings(),
                res_scale: r.common.res_scale(),
                threads: r.common.threads,
                accel: r.common.accel.into(),
                quiet: r.quiet,
                shard: r.shard,
                chunk: r.chunk,
            };
            if merge {
                headless::render::run_merge(&args)
            } else {
                headless::render::run(&args)
            }
        }
        Command::Capture(c) if !c.merge.is_empty() => capture::run_merge(&c.merge, &c.output),
        Command::Capture(c) => capture::run(&capture::CaptureArgs {
            // clap enforces these unless --merge is given, which the arm above handles.
            scene: c.scene.unwrap_or_default(),
            path: c.path.unwrap_or_default(),
            frames: c.frames.unwrap_or(0),
            include: c.common.include.clone(),
            range: c.frames_range,
            shard: c.shard,
            chunk: c.chunk,
            output: c.output,
            settings: RenderSettings { tile: c.tile, ..c.common.settings() },
            res_scale: c.common.res_scale(),
            threads: c.common.threads,
            accel: c.common.accel.into(),
            clock: c.clock,
            quiet: c.quiet,
            force: c.force,
        }),
        Command::Tradeoff(t) => tradeoff::run(&tradeoff::TradeoffArgs {
            scene: t.scene,
            include: t.include,
            path: t.path,
            frames: t.frames.unwrap_or(3),
            width: t.width,
            height: t.height,
            output: t.output,
            threads: t.threads,
            repeats: t.repeats,
            accel: t.accel.into(),
        }),
        Command::Bench(b) => bench::run(&bench::BenchArgs {
            scene: b.scene,
            include: b.common.include.clone(),
            path: b.path,
            frames: b.frames,
            warmup: b.warmup,
            json: b.json,
            settings: RenderSettings { tile: b.tile, ..b.common.settings() },
            res_scale: b.common.res_scale(),
            threads: b.common.threads,
            accel: b.common.accel.into(),
            threads_sweep: b.threads_sweep,
            clock: b.clock,
        }),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.code as u8)
        }
    }
}
