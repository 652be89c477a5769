//! `strahl render`: one still image to PNG, then the statistics block.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::camera::Camera;
use crate::headless::report::{included_files, statistics, Timings};
use crate::headless::{load_with_clock, output, peak_memory_bytes, povray_ini, with_threads, CliError};
use crate::pov::Clock;
use crate::render::image::Image;
use crate::render::resample::render_scaled;
use crate::render::RenderSettings;
use crate::scene::build::{AccelKind, Scene};

pub struct RenderArgs {
    pub scene: PathBuf,
    pub include: Vec<PathBuf>,
    pub output: PathBuf,
    pub settings: RenderSettings,
    /// Fraction of the output size to trace, upscaled back (1 = every pixel).
    pub res_scale: f32,
    pub threads: usize,
    pub accel: AccelKind,
    pub quiet: bool,
    /// The frame the scene is parsed for (a still image unless `--ini` names an animation).
    pub clock: Clock,
}

/// The clock of frame `frame` (its first frame when `None`) of the animation a POV-Ray `.ini`
/// describes; a still image's clock when it describes none and no frame was asked for.
pub fn clock_from_ini(ini: &Path, frame: Option<u32>) -> Result<Clock, CliError> {
    let text =
        std::fs::read_to_string(ini).map_err(|e| CliError::user(format!("{}: cannot read: {e}", ini.display())))?;
    let Some(a) = povray_ini::animation(&text) else {
        return match frame {
            None => Ok(Clock::default()),
            Some(_) => Err(CliError::user(format!(
                "{}: --frame needs an animation, and this .ini names no Initial_Frame or Final_Frame",
                ini.display()
            ))),
        };
    };
    let (first, last) = (a.initial_frame, a.final_frame.max(a.initial_frame));
    let number = frame.unwrap_or(first);
    if !(first..=last).contains(&number) {
        return Err(CliError::user(format!("--frame {number} is outside the animation's frames {first}..{last}")));
    }
    Ok(Clock::numbered(first, last, a.initial_clock, a.final_clock, number))
}

pub fn run(args: &RenderArgs) -> Result<(), CliError> {
    output::check_png_path("-o", &args.output)?;
    let (desc, parse) =
        load_with_clock(&args.scene, &args.include, args.settings.width, args.settings.height, args.clock)?;
    let build_start = Instant::now();
    let scene = Scene::build(&desc, desc.camera.location, args.accel);
    let build = build_start.elapsed();
    let camera = Camera::from_desc(&desc.camera);
    let (mut low, mut image) = (Image::default(), Image::default());
    let trace_start = Instant::now();
    let stats = with_threads(args.threads, || {
        render_scaled(&scene, &camera, &args.settings, args.res_scale, &mut low, &mut image)
    })?;
    let trace = trace_start.elapsed();
    output::write_png(&args.output, image.width, image.height, &image.to_rgb8(scene.srgb))?;
    if !args.quiet {
        let name = args.scene.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let max_level = args.settings.quality.max_trace_level.unwrap_or(scene.max_trace_level);
        print!(
            "{}",
            statistics(
                &name,
                image.width,
                image.height,
                &stats,
                max_level,
                &Timings { parse, build, trace },
                peak_memory_bytes()
            )
        );
        print!("{}", included_files(&desc.included));
        println!("wrote {} ({}x{})", args.output.display(), image.width, image.height);
        output::flush_stdout();
    }
    Ok(())
}
