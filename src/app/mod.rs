//! `strahl view`: the interactive window. The only code that touches winit, softbuffer and gilrs.
//!
//! Window and gamepad events become an `InputState`; `fly::step` turns that into a camera; the
//! render thread (`render_thread`) traces it with the headless renderer at an adaptive scale and
//! sends frames back; `blit` and `hud` put them on screen. Nothing here traces a ray.
//!
//! Layer 9 of docs/design/architecture.md, the top: uses `headless`, `pov`, `fly`, `render` and below; nothing uses it.

pub mod blit;
pub mod font;
pub mod frame_costs;
pub mod gamepad;
pub mod hud;
pub mod keys;
pub mod playback;
pub mod reload;
pub mod render_thread;
mod window;

use std::path::{Path, PathBuf};

use crate::app::playback::{default_seconds, Playback, ReportContext};
use crate::app::reload::Reloader;
use crate::app::render_thread::Watch;
use crate::camera::path::CameraPath;
use crate::camera::Camera;
use crate::desc::SceneDesc;
use crate::headless::{output, CliError};
use crate::render::preset::Preset;
use crate::render::Quality;
use crate::scene::build::{AccelKind, Scene};

/// Everything `strahl view` was asked for.
#[derive(Clone, Debug)]
pub struct ViewOptions {
    /// Initial window size (physical pixels); the full render resolution follows the window.
    pub width: u32,
    pub height: u32,
    /// Progressive antialiasing converges to N×N samples per pixel.
    pub aa: u32,
    /// The "full" quality preset (from the command line); F2 cycles cheaper ones.
    pub quality: Quality,
    pub threads: usize,
    pub accel: AccelKind,
    pub target_fps: f64,
    /// Present frames until the view has converged or this many have been shown, whichever is
    /// first, then save `screenshot` (if given) from the presented pixels and exit: the scripted
    /// mode CI uses.
    pub frames: Option<u64>,
    /// Where `--frames` saves, and where F12 saves (else a timestamped name).
    pub screenshot: Option<PathBuf>,
    /// The scene file as given: the window's title names it, and so does the report.
    pub scene: PathBuf,
    /// Start with the HUD and help shown (F1 toggles).
    pub hud: bool,
    /// `--path`: play this camera path in real time instead of flying, then exit.
    pub path: Option<PathPlay>,
    /// `--report`: after the path, write frame rate and image quality here (JSON).
    pub report: Option<PathBuf>,
    /// While moving, reuse the frame before (`render::reproject`); `false`: `--no-reproject`.
    pub reproject: bool,
}

/// A camera path to play, and over how many seconds its t runs from 0 to 1.
#[derive(Clone, Debug)]
pub struct PathPlay {
    pub file: PathBuf,
    pub path: CameraPath,
    pub seconds: f64,
}

impl PathPlay {
    /// Loads `file`; `seconds` defaults to [`playback::default_seconds`].
    pub fn load(file: &Path, seconds: Option<f64>) -> Result<PathPlay, CliError> {
        let path = CameraPath::load(file)?;
        let seconds = match seconds {
            Some(s) if s.is_finite() && s > 0.0 && s <= 1e6 => s,
            Some(s) => {
                return Err(CliError::user(format!("--path-seconds must be a positive number of seconds, not {s}")))
            }
            None => default_seconds(&path),
        };
        Ok(PathPlay { file: file.to_path_buf(), path, seconds })
    }
}

/// The message for a machine without a display, pointing at the headless commands.
pub fn no_display(detail: &str) -> CliError {
    CliError::user(format!(
        "cannot open a window: {detail}\n  \
         `strahl view` needs a display (X11 or Wayland). Without one:\n    \
         strahl render SCENE -o out.png     renders a still image\n    \
         strahl capture ...                 renders frames along a camera path"
    ))
}

/// Fails early, with [`no_display`], where no display server can be reached.
pub fn check_display() -> Result<(), CliError> {
    if cfg!(all(unix, not(target_os = "macos"), not(target_os = "ios"), not(target_os = "android"))) {
        let set = |k: &str| std::env::var_os(k).is_some_and(|v| !v.is_empty());
        if !set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("WAYLAND_SOCKET") {
            return Err(no_display("neither DISPLAY nor WAYLAND_DISPLAY is set"));
        }
    }
    Ok(())
}

/// What F2 selects: the command line's settings, then the presets that `strahl tradeoff` put
/// on the seed scene's Pareto front (`render::preset`): each caps the resolution the view
/// renders at while moving and sets the antialiasing a still view converges to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowPreset {
    pub name: &'static str,
    pub quality: Quality,
    pub aa: u32,
    /// Upper bound on the adaptive render scale.
    pub max_scale: f64,
}

/// The presets F2 cycles through, starting with the command line's.
pub fn quality_preset(full: Quality, aa: u32, index: usize) -> WindowPreset {
    let from = |p: Preset| {
        let s = p.settings();
        WindowPreset { name: p.name(), quality: s.quality, aa: s.aa, max_scale: s.res_scale as f64 }
    };
    match index % 4 {
        0 => WindowPreset { name: "command line", quality: full, aa, max_scale: 1.0 },
        1 => from(Preset::Balanced),
        2 => from(Preset::Fast),
        _ => from(Preset::Reference),
    }
}

/// Opens the window on `desc` and runs until it is closed (or `--frames` or the path is done).
pub fn run(desc: &SceneDesc, options: ViewOptions) -> Result<(), CliError> {
    run_watched(desc, None, options)
}

/// [`run`], reloading the scene from disk when `reloader`'s files change (or on F5).
fn run_watched(desc: &SceneDesc, reloader: Option<Reloader>, options: ViewOptions) -> Result<(), CliError> {
    check_display()?;
    if let Some(report) = &options.report {
        output::check_writable("--report", report)?;
    }
    let origin = desc.camera.location;
    let scene = Scene::build(desc, origin, options.accel);
    let camera = Camera::from_desc(&desc.camera);
    let subject = scene.subject_bounds(origin);
    let look_distance = desc.camera.look_at.map(|p| (p - origin).length());
    let speed = crate::fly::scene_speed(subject, scene.frame.unit, look_distance);
    let unmodelled = unmodelled_names(desc);
    let watch = reloader.map(|reloader| Watch { reloader, origin, accel: options.accel });
    let playback = options.path.as_ref().map(|p| Playback::new(p.path.clone(), p.seconds));
    let (Some(playback), Some(report), Some(play)) = (
        window::run(scene, camera, speed, unmodelled, watch, playback, options.clone())?,
        &options.report,
        &options.path,
    ) else {
        return Ok(());
    };
    // The window is closed: now the references can take all the cores. They use the scene as
    // the path started with it (a reload during playback is not reflected).
    eprintln!("comparing {} sampled frames with full-quality renders ...", playback.samples().len());
    let scene = Scene::build(desc, origin, options.accel);
    let cx = ReportContext {
        scene: &options.scene.display().to_string(),
        path: &play.file,
        width: options.width,
        height: options.height,
        target_fps: options.target_fps,
        aa: options.aa,
        quality: options.quality,
        threads: options.threads,
        reproject: options.reproject,
    };
    let json = playback::report(&playback, &scene, &cx)?;
    playback::write_report(report, &json)?;
    let num = |k: &str, f: &str| json.get(k).and_then(|v| v.get(f)).and_then(|v| v.as_f64()).unwrap_or(f64::NAN);
    eprintln!(
        "{}: {:.1} fps presented, frame {:.1} ms median {:.1} ms p95, scale {:.2} mean, PSNR {:.2} dB mean (median {:.2}, p5 {:.2}, min {:.2}, pooled {:.2}), SSIM {:.3} mean",
        report.display(),
        json.get("presented_fps").and_then(|v| v.as_f64()).unwrap_or(0.0),
        num("frame_time_ms", "median"),
        num("frame_time_ms", "p95"),
        num("render_scale", "mean"),
        num("psnr_db", "mean"),
        num("psnr_db", "median"),
        num("psnr_db", "p5"),
        num("psnr_db", "min"),
        json.get("psnr_db_pooled").and_then(|v| v.as_f64()).unwrap_or(f64::NAN),
        num("ssim", "mean"),
    );
    Ok(())
}

/// The names of what the scene uses that strahl does not model, in order of first use: the
/// HUD lists them (the warnings with their locations went to the terminal when it loaded).
pub fn unmodelled_names(desc: &SceneDesc) -> Vec<String> {
    desc.unmodelled.iter().map(|f| f.name.clone()).collect()
}

/// Checks what `strahl view` was given that does not need a display or the scene: the path file
/// parses, `--path-seconds` is sane, the report can be written. Bad arguments exit 2 before any
/// window opens, with or without a display.
pub fn check_options(options: &ViewOptions) -> Result<(), CliError> {
    if options.width == 0 || options.height == 0 {
        return Err(CliError::user(format!(
            "window size must be at least 1x1, not {}x{}",
            options.width, options.height
        )));
    }
    if options.report.is_some() && options.path.is_none() {
        return Err(CliError::user("--report needs --path: it measures a camera path played back"));
    }
    if let Some(report) = &options.report {
        output::check_writable("--report", report)?;
    }
    if let Some(shot) = &options.screenshot {
        output::check_png_path("--screenshot", shot)?;
    }
    Ok(())
}

/// `strahl view SCENE`: checks for a display first (so a headless machine hears about `render`
/// and `capture`, not about the scene), then parses the scene and opens the window. The default
/// `scenes/seed.pov` is also looked for in the source tree, so `cargo run` works from anywhere.
pub fn view_file(path: &Path, include: &[PathBuf], options: ViewOptions) -> Result<(), CliError> {
    check_options(&options)?;
    check_display()?;
    let mut path = path.to_path_buf();
    let bundled = Path::new(env!("CARGO_MANIFEST_DIR")).join(&path);
    if !path.exists() && path.is_relative() && bundled.exists() {
        path = bundled;
    }
    let reloader = Reloader::open(&path, include)?;
    let desc = reloader.last_good().clone();
    run_watched(&desc, Some(reloader), options)
}
