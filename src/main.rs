//! The `strahl` command line: parses arguments, runs one subcommand, prints one error.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

use strahl::headless::capture::{self, FrameRange};
use strahl::headless::{self, bench, CliError};
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
    /// Time render() over frames and report frame-time percentiles and rays per second.
    Bench(BenchCmd),
    /// Fly through a scene in a window: adaptive resolution while moving, progressive
    /// antialiasing when still (converging to `strahl render` of the same camera).
    View(ViewCmd),
    /// BVH build and frame time against object count on generated scenes (or --intersection-share).
    Scaling(headless::scaling::ScalingCmd),
    /// Write a generated many-object scene (spheres, boxes, triangles, mixed) as a POV-Ray file.
    Gen(headless::scaling::GenCmd),
}

#[derive(Clone, Copy, ValueEnum)]
enum AccelArg {
    Bvh,
    Grid,
    None,
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
    #[arg(short = 'L', long = "include-path", value_name = "DIR")]
    include: Vec<PathBuf>,
    /// Worker threads (0 = one per core).
    #[arg(long, default_value_t = 0)]
    threads: usize,
    /// Antialiasing: N×N samples per pixel (1 = one ray through each pixel centre, as POV-Ray -A).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=16))]
    aa: u32,
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
}

impl Common {
    fn settings(&self) -> RenderSettings {
        RenderSettings {
            width: self.width,
            height: self.height,
            aa: self.aa,
            quality: Quality { max_trace_level: self.max_depth, shadows: !self.no_shadows, max_octaves: self.max_octaves },
            packets: !self.no_packets,
            ..RenderSettings::default()
        }
    }
}

#[derive(Args)]
struct RenderCmd {
    /// The POV-Ray scene file.
    scene: PathBuf,
    /// Output PNG.
    #[arg(short = 'o', long, default_value = "out.png")]
    output: PathBuf,
    /// Print no statistics.
    #[arg(short, long)]
    quiet: bool,
    #[command(flatten)]
    common: Common,
}

#[derive(Args)]
struct CaptureCmd {
    /// The POV-Ray scene file.
    #[arg(required_unless_present = "merge")]
    scene: Option<PathBuf>,
    /// Camera path file (see docs/camera-paths.md).
    #[arg(long, required_unless_present = "merge")]
    path: Option<PathBuf>,
    /// Frames in the whole capture; frame i is at t = i/(N-1) on the path.
    #[arg(long, value_name = "N", required_unless_present = "merge", value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    frames: Option<u32>,
    /// Render only frames START..END (END excluded) of the N, e.g. to shard across machines.
    #[arg(long, value_name = "START..END")]
    frames_range: Option<FrameRange>,
    /// Output folder.
    #[arg(short = 'o', long, value_name = "DIR")]
    output: PathBuf,
    /// Tile edge in pixels (does not change the pixels).
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=4096))]
    tile: u32,
    /// Merge the manifests (and frames) of shard folders into -o DIR instead of rendering.
    #[arg(long, num_args = 1.., value_name = "DIR", conflicts_with_all = ["scene", "path", "frames", "frames_range"])]
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
    #[command(flatten)]
    common: Common,
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
    #[arg(long, value_name = "N")]
    frames: Option<u64>,
    /// PNG written by --frames and by F12 (default for F12: strahl-<time>.png).
    #[arg(long, value_name = "PNG")]
    screenshot: Option<PathBuf>,
    /// Start with the HUD and key help shown (F1 toggles them).
    #[arg(long)]
    hud: bool,
    #[command(flatten)]
    common: Common,
}

fn view(v: ViewCmd) -> Result<(), CliError> {
    if !(v.target_fps.is_finite() && v.target_fps > 0.0) {
        return Err(CliError::user(format!("--target-fps must be a positive number, not {}", v.target_fps)));
    }
    let options = strahl::app::ViewOptions {
        width: v.common.width,
        height: v.common.height,
        aa: v.common.aa,
        quality: v.common.settings().quality,
        threads: v.common.threads,
        accel: v.common.accel.into(),
        target_fps: v.target_fps,
        frames: v.frames,
        screenshot: v.screenshot,
        title: format!("strahl - {}", v.scene.display()),
        hud: v.hud,
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
        Command::Render(r) => headless::render::run(&headless::render::RenderArgs {
            scene: r.scene,
            include: r.common.include.clone(),
            output: r.output,
            settings: r.common.settings(),
            threads: r.common.threads,
            accel: r.common.accel.into(),
            quiet: r.quiet,
        }),
        Command::Capture(c) if !c.merge.is_empty() => capture::run_merge(&c.merge, &c.output),
        Command::Capture(c) => capture::run(&capture::CaptureArgs {
            // clap enforces these unless --merge is given, which the arm above handles.
            scene: c.scene.unwrap_or_default(),
            path: c.path.unwrap_or_default(),
            frames: c.frames.unwrap_or(0),
            include: c.common.include.clone(),
            range: c.frames_range,
            output: c.output,
            settings: RenderSettings {
                tile: c.tile,
                ..c.common.settings()
            },
            threads: c.common.threads,
            accel: c.common.accel.into(),
            quiet: c.quiet,
        }),
        Command::Bench(b) => bench::run(&bench::BenchArgs {
            scene: b.scene,
            include: b.common.include.clone(),
            path: b.path,
            frames: b.frames,
            warmup: b.warmup,
            json: b.json,
            settings: RenderSettings {
                tile: b.tile,
                ..b.common.settings()
            },
            threads: b.common.threads,
            accel: b.common.accel.into(),
            threads_sweep: b.threads_sweep,
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
