//! `strahl render`: one still image to PNG, then the statistics block; or one shard of it
//! (`--shard I/N`: some of its rows, as a part for `strahl merge`), or the merge of the parts
//! (`--merge`).

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::camera::Camera;
use crate::headless::band::{self, STRIP};
use crate::headless::capture;
use crate::headless::report::{included_files, statistics, Timings};
use crate::headless::shard::{self, ShardSpec};
use crate::headless::still_part::{self, Part};
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
    /// `--shard`: render only this shard's rows, to `OUTPUT.shard-I-of-N.png`.
    pub shard: Option<ShardSpec>,
    /// `--chunk`: the shard's rows are one contiguous band instead of every N-th strip.
    pub chunk: bool,
}

/// What a still's parts must agree on with this command line.
fn identity(args: &RenderArgs) -> still_part::Render {
    still_part::Render::new(&args.scene, &args.settings, args.res_scale, args.accel, &args.clock)
}

/// `render -o OUT.png --merge`: joins the parts beside OUT, checked against this command line.
pub fn run_merge(args: &RenderArgs) -> Result<(), CliError> {
    let parts = still_part::find_parts(&args.output)?;
    still_part::merge(&parts, &args.output, Some(&identity(args)), args.quiet)
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
    let found = args.shard.map(|s| s.resolve(&shard::process_env).map_err(CliError::user)).transpose()?;
    let rows = match &found {
        Some(f) => {
            let (unit, what) = if args.chunk { (1, "rows") } else { (STRIP, "strips of 8 rows") };
            let rows = f.shard.deal(args.settings.height, unit, args.chunk);
            if rows.is_empty() {
                let units = args.settings.height.div_ceil(unit);
                return Err(CliError::user(format!(
                    "shard {} gets no rows: a {}-row image has {units} {what}, so give at most {units} shards{}",
                    f.shard,
                    args.settings.height,
                    if args.chunk { "" } else { " (or --chunk, which deals single rows)" }
                )));
            }
            let part = still_part::part_path(&args.output, f.shard);
            output::check_writable("-o", &part)?;
            Some((f, rows, part))
        }
        None => None,
    };
    let (desc, parse) =
        load_with_clock(&args.scene, &args.include, args.settings.width, args.settings.height, args.clock)?;
    let build_start = Instant::now();
    let camera = Camera::from_desc(&desc.camera);
    let (origin, included) = (desc.camera.location, included_files(&desc.included));
    // The description is dropped while building (`Scene::build_owned`): a scene of millions of
    // objects never holds both at once.
    let scene = Scene::build_owned(desc, origin, args.accel);
    let build = build_start.elapsed();
    let (mut low, mut image) = (Image::default(), Image::default());
    let trace_start = Instant::now();
    let (stats, trace) = match &rows {
        None => {
            let stats = with_threads(args.threads, || {
                render_scaled(&scene, &camera, &args.settings, args.res_scale, &mut low, &mut image)
            })?;
            let trace = trace_start.elapsed();
            output::write_png(&args.output, image.width, image.height, &image.to_rgb8(scene.srgb))?;
            (stats, trace)
        }
        Some((f, rows, part_file)) => {
            let (pixels, stats) = with_threads(args.threads, || {
                band::render_rows(&scene, &camera, &args.settings, args.res_scale, rows)
            })?;
            let trace = trace_start.elapsed();
            image = Image { width: args.settings.width, height: pixels.len() as u32 / args.settings.width, pixels };
            let rgb = image.to_rgb8(scene.srgb);
            let part =
                Part { render: identity(args), shard: f.shard, rows: rows.clone(), sha256: capture::sha256_hex(&rgb) };
            still_part::write(part_file, &part, &rgb)?;
            (stats, trace)
        }
    };
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
        print!("{included}");
        match &rows {
            None => println!("wrote {} ({}x{})", args.output.display(), image.width, image.height),
            Some((f, rows, part)) => println!(
                "wrote shard {} ({}): {} of {} rows, {}",
                f.shard,
                f.source,
                image.height,
                args.settings.height,
                if rows.len() == 1 {
                    format!("rows {}..{}, to {}", rows[0].start, rows[0].end, part.display())
                } else {
                    format!("in {} strips, to {}", rows.len(), part.display())
                }
            ),
        }
        output::flush_stdout();
    }
    Ok(())
}
