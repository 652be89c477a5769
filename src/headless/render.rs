//! `strahl render`: one still image to PNG, then the statistics block.

use std::path::PathBuf;
use std::time::Instant;

use crate::camera::Camera;
use crate::headless::report::{included_files, statistics, Timings};
use crate::headless::{load_sized, output, peak_memory_bytes, with_threads, CliError};
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
}

pub fn run(args: &RenderArgs) -> Result<(), CliError> {
    output::check_png_path("-o", &args.output)?;
    let (desc, parse) = load_sized(&args.scene, &args.include, args.settings.width, args.settings.height)?;
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
