//! The `strahl` command line: parses arguments, runs one subcommand, prints one error.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

use strahl::headless::{self, CliError};
use strahl::render::{Quality, RenderSettings};
use strahl::scene::build::AccelKind;

#[derive(Parser)]
#[command(name = "strahl", version, about = "A real-time CPU ray tracer for POV-Ray scenes", long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render one still image of a scene to PNG and print POV-Ray-style statistics.
    Render(RenderCmd),
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

fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        Command::Render(r) => headless::render::run(&headless::render::RenderArgs {
            scene: r.scene,
            include: r.common.include.clone(),
            output: r.output,
            settings: r.common.settings(),
            threads: r.common.threads,
            accel: r.common.accel.into(),
            quiet: r.quiet,
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
