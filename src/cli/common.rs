//! The options every rendering subcommand shares (`Common`), the acceleration structure's
//! argument, and their checks.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use strahl::headless::{self, CliError};
use strahl::render::precision::Precision;
use strahl::render::preset::Preset;
use strahl::render::resample::MIN_RES_SCALE;
use strahl::render::{Quality, RenderSettings};
use strahl::scene::build::AccelKind;

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum AccelArg {
    Bvh,
    Grid,
    None,
}

impl AccelArg {
    pub(crate) fn name(self) -> &'static str {
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
pub(crate) struct Common {
    /// Image width in pixels.
    #[arg(short = 'W', long, default_value_t = 640, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub(crate) width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long, default_value_t = 480, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub(crate) height: u32,
    /// Extra include folder, searched after the scene's own folder (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR", value_parser = headless::parse_include_dir)]
    pub(crate) include: Vec<PathBuf>,
    /// Worker threads (0 = one per core; at most 4 per core).
    #[arg(long, default_value_t = 0, value_parser = headless::parse_threads)]
    pub(crate) threads: usize,
    /// Speed/accuracy preset: fast, balanced, full (the scene as written; the default) or
    /// reference (4×4 aa, f64). Flags given explicitly override the preset's fields.
    #[arg(long, value_name = "NAME")]
    pub(crate) preset: Option<Preset>,
    /// Trace F×W by F×H pixels (0.1 to 1) and upscale back to W×H, bilinearly. Default 1.
    #[arg(long, value_name = "F", value_parser = parse_res_scale)]
    pub(crate) res_scale: Option<f32>,
    /// Antialiasing: N×N samples per pixel (1 = one ray through each pixel centre, as POV-Ray -A).
    /// Default 1.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16))]
    pub(crate) aa: Option<u32>,
    /// Acceleration structure for bounded objects.
    #[arg(long, value_enum, default_value_t = AccelArg::Bvh)]
    pub(crate) accel: AccelArg,
    /// Override the scene's max_trace_level.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=256))]
    pub(crate) max_depth: Option<u32>,
    /// Trace no shadow rays (every light reaches every point).
    #[arg(long)]
    pub(crate) no_shadows: bool,
    /// Trace every ray singly instead of primary and shadow rays in 8×8 packets (same image).
    #[arg(long)]
    pub(crate) no_packets: bool,
    /// Cap on turbulence/noise octaves (texture detail).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=32))]
    pub(crate) max_octaves: Option<u32>,
    /// Cap on the points of each area light (soft-shadow rays per shading point).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=65536))]
    pub(crate) max_area_samples: Option<u32>,
    /// Arithmetic of intersections: f32, or f64 (each ray's nearest hit re-solved in f64, for
    /// reference images). Default f32; the reference preset uses f64.
    #[arg(long, value_name = "P")]
    pub(crate) precision: Option<Precision>,
    /// Cap on a focal-blur camera's rays per sample (`blur_samples`).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub(crate) max_blur_samples: Option<u32>,
}

/// `--res-scale`: a number in MIN_RES_SCALE..=1.
pub(crate) fn parse_res_scale(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f32>() {
        Ok(f) if (MIN_RES_SCALE..=1.0).contains(&f) => Ok(f),
        _ => Err(format!("`{s}` is not a resolution scale: give a number from {MIN_RES_SCALE} to 1")),
    }
}

impl Common {
    /// The render settings: the preset (default `full`), with every flag given overriding it.
    pub(crate) fn settings(&self) -> RenderSettings {
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
    pub(crate) fn res_scale(&self) -> f32 {
        self.res_scale.unwrap_or(self.preset.unwrap_or(Preset::Full).settings().res_scale)
    }

    /// These options as command-line words, for a job script that runs strahl elsewhere:
    /// every option given, include folders made absolute (tasks start in another folder).
    /// `--threads` is left out: a farm's task takes the cores its scheduler gives it.
    pub(crate) fn to_args(&self) -> Result<Vec<String>, CliError> {
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
pub(crate) fn absolute(path: &std::path::Path) -> Result<PathBuf, CliError> {
    std::fs::canonicalize(path).map_err(|e| CliError::user(format!("{}: {e}", path.display())))
}

/// `--clock` of capture, bench and farm, one text for both.
pub(crate) const CLOCK_HELP: &str =
    "Animate: parse the scene anew for each frame, with `clock` running from A on the first \
                          frame to B on the last (POV-Ray's +KI A +KF B +KFF N), e.g. 0..1";
