//! The command line's shape: the subcommands and their arguments (clap), with the options the
//! rendering subcommands share in `common` and the cluster front end in `slurm`. `main` runs
//! what they parse.

mod common;
mod slurm;

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use strahl::headless;
use strahl::headless::capture::{ClockRange, FrameRange};
use strahl::headless::shard::ShardSpec;

pub(crate) use common::*;
pub(crate) use slurm::*;

#[derive(Parser)]
#[command(name = "strahl", version, about = "A real-time CPU ray tracer for POV-Ray scenes", long_about = None)]
pub(crate) struct Cli {
    /// Without a subcommand, opens the window on scenes/seed.pov (`strahl view`).
    #[command(subcommand)]
    pub(crate) command: Option<Command>,
}

#[derive(Subcommand)]
pub(crate) enum Command {
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
pub(crate) enum PathCmd {
    /// A closed orbit around the scene camera's look_at, at the camera's distance and height,
    /// starting at the scene camera: a path for `bench --path` and `view --path --report`.
    Orbit(OrbitCmd),
}

#[derive(Args)]
pub(crate) struct OrbitCmd {
    /// The POV-Ray scene file.
    pub(crate) scene: PathBuf,
    /// The path file to write (replaced only once complete).
    #[arg(short = 'o', long, value_name = "FILE")]
    pub(crate) output: PathBuf,
    /// Keys around the circle (the file holds one more, repeating the first).
    #[arg(long, value_name = "N", default_value_t = headless::orbit::DEFAULT_KEYS, value_parser = clap::value_parser!(u32).range(3..=100_000))]
    pub(crate) frames: u32,
    /// Seconds one turn takes: the key times run from 0 to S.
    #[arg(long, value_name = "S", allow_hyphen_values = true, default_value_t = headless::orbit::DEFAULT_SECONDS, value_parser = headless::orbit::parse_seconds)]
    pub(crate) seconds: f64,
    /// Extra include folder, searched after the scene's own folder (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR", value_parser = headless::parse_include_dir)]
    pub(crate) include: Vec<PathBuf>,
    /// Print nothing but errors.
    #[arg(short, long)]
    pub(crate) quiet: bool,
}

#[derive(Args)]
pub(crate) struct RenderCmd {
    /// The POV-Ray scene file.
    pub(crate) scene: PathBuf,
    /// Output PNG (checked before rendering: its folder must exist and the name end in .png).
    #[arg(short = 'o', long, default_value = "out.png")]
    pub(crate) output: PathBuf,
    /// Print no statistics.
    #[arg(short, long)]
    pub(crate) quiet: bool,
    /// A POV-Ray .ini whose animation (Initial_Frame, Final_Frame, Initial_Clock, Final_Clock)
    /// the scene is parsed for: its first frame, or --frame's. Other .ini settings are not read.
    #[arg(long, value_name = "FILE")]
    pub(crate) ini: Option<PathBuf>,
    /// With --ini: the frame number to render (POV-Ray's frame_number).
    #[arg(long, value_name = "K", requires = "ini")]
    pub(crate) frame: Option<u32>,
    /// Render only shard I of N (from 0): every N-th strip of 8 rows, at the full image's size,
    /// to OUTPUT.shard-I-of-N.png; `auto` reads I and N from a Slurm, AWS Batch or (with
    /// auto/N) Kubernetes job array. `--merge` or `strahl merge` joins the parts.
    #[arg(long, value_name = "I/N", conflicts_with = "merge")]
    pub(crate) shard: Option<ShardSpec>,
    /// With --shard: one contiguous band of rows per shard instead of interleaved strips.
    #[arg(long, requires = "shard")]
    pub(crate) chunk: bool,
    /// Join the parts that `--shard` wrote beside OUTPUT into OUTPUT, checking that they were
    /// rendered with this command line's scene, size and settings; renders nothing.
    #[arg(long)]
    pub(crate) merge: bool,
    #[command(flatten)]
    pub(crate) common: Common,
}

#[derive(Args)]
pub(crate) struct MergeCmd {
    /// The parts (`render --shard I/N` writes OUTPUT.shard-I-of-N.png), every shard of one render.
    #[arg(required = true, value_name = "PART")]
    pub(crate) parts: Vec<PathBuf>,
    /// The whole image to write (PNG; written only once every part checks out).
    #[arg(short = 'o', long, value_name = "PNG")]
    pub(crate) output: PathBuf,
    /// Print nothing but errors.
    #[arg(short, long)]
    pub(crate) quiet: bool,
}

#[derive(Args)]
#[command(override_usage = "strahl capture <SCENE> --path <PATH> --frames <N> -o <DIR> [OPTIONS]\n       \
                            strahl capture --merge <DIR>... -o <DIR>")]
pub(crate) struct CaptureCmd {
    /// The POV-Ray scene file (required unless --merge).
    #[arg(required_unless_present = "merge")]
    pub(crate) scene: Option<PathBuf>,
    /// Camera path file, see docs/camera-paths.md (required unless --merge).
    #[arg(long, required_unless_present = "merge")]
    pub(crate) path: Option<PathBuf>,
    /// Frames in the whole capture; frame i is at t = i/(N-1) on the path (required unless --merge).
    #[arg(long, value_name = "N", required_unless_present = "merge", value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) frames: Option<u32>,
    /// Render only frames START..END (END excluded) of the N, e.g. to shard across machines.
    #[arg(long, value_name = "START..END", conflicts_with = "shard")]
    pub(crate) frames_range: Option<FrameRange>,
    /// Render only shard I of N (from 0): frames I, I+N, I+2N, ...; `auto` reads I and N from a
    /// Slurm, AWS Batch or (with auto/N) Kubernetes job array. A shard rerun into its folder
    /// skips the frames its manifest lists as done, so a requeued task resumes.
    #[arg(long, value_name = "I/N")]
    pub(crate) shard: Option<ShardSpec>,
    /// With --shard: deal each shard one contiguous run of frames instead of every N-th frame.
    #[arg(long, requires = "shard")]
    pub(crate) chunk: bool,
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, help = CLOCK_HELP)]
    pub(crate) clock: Option<ClockRange>,
    /// Output folder: created if missing. It must be empty or hold this same capture (same scene,
    /// path, size, frame count, clock range and settings; its frames are replaced), so frames of
    /// two captures never mix.
    #[arg(short = 'o', long, value_name = "DIR")]
    pub(crate) output: PathBuf,
    /// Let -o name a folder of another capture: delete strahl's frame_NNNN.png and manifest.json
    /// there first (other files are left alone).
    #[arg(long, conflicts_with = "merge")]
    pub(crate) force: bool,
    /// Tile edge in pixels (does not change the pixels).
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub(crate) tile: u32,
    /// Merge the manifests (and frames) of shard folders into -o DIR instead of rendering.
    #[arg(long, num_args = 1.., value_name = "DIR", conflicts_with_all = ["scene", "path", "frames", "frames_range", "clock", "shard"])]
    pub(crate) merge: Vec<PathBuf>,
    /// Print nothing but errors, and no progress bar.
    #[arg(short, long)]
    pub(crate) quiet: bool,
    #[command(flatten)]
    pub(crate) common: Common,
}

#[derive(Args)]
pub(crate) struct BenchCmd {
    /// The POV-Ray scene file.
    pub(crate) scene: PathBuf,
    /// Camera path to follow; without it the scene's camera stays still.
    #[arg(long)]
    pub(crate) path: Option<PathBuf>,
    /// Timed frames.
    #[arg(long, value_name = "N", default_value_t = 30, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) frames: u32,
    /// Untimed frames rendered first.
    #[arg(long, value_name = "K", default_value_t = 3)]
    pub(crate) warmup: u32,
    /// Also write the results as JSON.
    #[arg(long, value_name = "FILE")]
    pub(crate) json: Option<PathBuf>,
    /// Tile edge in pixels.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub(crate) tile: u32,
    /// Also run the bench at 1, 2, ... all cores and print a scaling table.
    #[arg(long)]
    pub(crate) threads_sweep: bool,
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, help = CLOCK_HELP)]
    pub(crate) clock: Option<ClockRange>,
    #[command(flatten)]
    pub(crate) common: Common,
}

#[derive(Args)]
pub(crate) struct TradeoffCmd {
    /// The POV-Ray scene file.
    pub(crate) scene: PathBuf,
    /// Camera path: measure at --frames cameras along it instead of the scene camera.
    #[arg(long)]
    pub(crate) path: Option<PathBuf>,
    /// Cameras along --path (default 3); frame i is at t = i/(N-1).
    #[arg(long, value_name = "N", requires = "path", value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub(crate) frames: Option<u32>,
    /// Timed renders per setting and camera, after one warm-up; the median is reported.
    #[arg(long, value_name = "R", default_value_t = 3, value_parser = clap::value_parser!(u32).range(3..=1000))]
    pub(crate) repeats: u32,
    /// Image width in pixels.
    #[arg(short = 'W', long, default_value_t = 640, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub(crate) width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long, default_value_t = 480, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub(crate) height: u32,
    /// Output folder (created; files in it are replaced).
    #[arg(short = 'o', long, value_name = "DIR")]
    pub(crate) output: PathBuf,
    /// Extra include folder, searched after the scene's own folder (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR", value_parser = headless::parse_include_dir)]
    pub(crate) include: Vec<PathBuf>,
    /// Worker threads (0 = one per core; at most 4 per core).
    #[arg(long, default_value_t = 0, value_parser = headless::parse_threads)]
    pub(crate) threads: usize,
    /// Acceleration structure for bounded objects.
    #[arg(long, value_enum, default_value_t = AccelArg::Bvh)]
    pub(crate) accel: AccelArg,
}

#[derive(Args)]
pub(crate) struct ViewCmd {
    /// The POV-Ray scene file.
    #[arg(default_value = "scenes/seed.pov")]
    pub(crate) scene: PathBuf,
    /// Frame rate the adaptive resolution aims at while the camera moves.
    #[arg(long, value_name = "FPS", default_value_t = 60.0)]
    pub(crate) target_fps: f64,
    /// Present frames until the view has converged (or N were shown), save --screenshot, exit.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    pub(crate) frames: Option<u64>,
    /// PNG written by --frames and by F12 (default for F12: strahl-<time>.png).
    #[arg(long, value_name = "PNG")]
    pub(crate) screenshot: Option<PathBuf>,
    /// Start with the HUD and key help shown (F1 toggles them).
    #[arg(long)]
    pub(crate) hud: bool,
    /// Play this camera path in real time (adaptive resolution as when flying), then exit.
    #[arg(long, value_name = "FILE", conflicts_with = "frames")]
    pub(crate) path: Option<PathBuf>,
    /// Seconds the path takes (default: its key times if they span 2 or more, else 10).
    #[arg(long, value_name = "S", requires = "path")]
    pub(crate) path_seconds: Option<f64>,
    /// After the path, write presented fps, frame times, render scale and PSNR/SSIM against
    /// full-quality renders to this JSON file.
    #[arg(long, value_name = "FILE", requires = "path")]
    pub(crate) report: Option<PathBuf>,
    /// While moving, render every frame afresh at the adaptive resolution instead of tracing a
    /// quarter of the pixels and reusing the rest from the frame before.
    #[arg(long)]
    pub(crate) no_reproject: bool,
    #[command(flatten)]
    pub(crate) common: Common,
}
