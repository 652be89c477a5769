//! `strahl view`: the interactive window. The only code that touches winit, softbuffer and gilrs.
//!
//! Window and gamepad events become an `InputState`; `fly::step` turns that into a camera; the
//! render thread (`render_thread`) traces it with the headless renderer at an adaptive scale and
//! sends frames back; `blit` and `hud` put them on screen. Nothing here traces a ray.

pub mod blit;
pub mod font;
pub mod gamepad;
pub mod hud;
pub mod keys;
pub mod render_thread;
mod window;

use std::path::{Path, PathBuf};

use crate::camera::Camera;
use crate::headless::{load, CliError};
use crate::render::Quality;
use crate::scene::build::{AccelKind, Scene};
use crate::scene::desc::SceneDesc;

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
    pub title: String,
    /// Start with the HUD and help shown (F1 toggles).
    pub hud: bool,
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
    if cfg!(all(
        unix,
        not(target_os = "macos"),
        not(target_os = "ios"),
        not(target_os = "android")
    )) {
        let set = |k: &str| std::env::var_os(k).is_some_and(|v| !v.is_empty());
        if !set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("WAYLAND_SOCKET") {
            return Err(no_display("neither DISPLAY nor WAYLAND_DISPLAY is set"));
        }
    }
    Ok(())
}

/// Quality presets F2 cycles through: the command line's, then two cheaper ones.
pub fn quality_preset(full: Quality, index: usize) -> (&'static str, Quality) {
    match index % 3 {
        0 => ("full", full),
        1 => (
            "fast",
            Quality {
                max_trace_level: Some(full.max_trace_level.unwrap_or(u32::MAX).min(2)),
                max_octaves: Some(2),
                ..full
            },
        ),
        _ => (
            "draft",
            Quality {
                max_trace_level: Some(1),
                shadows: false,
                max_octaves: Some(1),
            },
        ),
    }
}

/// A flying speed that suits the scene's size: a tenth of its bounded extent per second.
fn initial_speed(scene: &Scene, camera: &Camera) -> f64 {
    let bounds = scene.prim_bounds();
    let (mut lo, mut hi) = (glam::Vec3::splat(f32::MAX), glam::Vec3::splat(f32::MIN));
    for b in &bounds {
        lo = lo.min(b.min);
        hi = hi.max(b.max);
    }
    let extent = if bounds.is_empty() {
        0.0
    } else {
        (hi - lo).length() as f64
    };
    if extent.is_finite() && extent > 1e-6 {
        (extent / 10.0).clamp(1e-3, 1e5)
    } else {
        camera.direction.length().max(1.0) * 2.0
    }
}

/// Opens the window on `desc` and runs until it is closed (or `--frames` is done).
pub fn run(desc: &SceneDesc, options: ViewOptions) -> Result<(), CliError> {
    check_display()?;
    let scene = Scene::build(desc, desc.camera.location, options.accel);
    let camera = Camera::from_desc(&desc.camera);
    let speed = initial_speed(&scene, &camera);
    window::run(scene, camera, speed, options)
}

/// `strahl view SCENE`: checks for a display first (so a headless machine hears about `render`
/// and `capture`, not about the scene), then parses the scene and opens the window. The default
/// `scenes/seed.pov` is also looked for in the source tree, so `cargo run` works from anywhere.
pub fn view_file(path: &Path, include: &[PathBuf], options: ViewOptions) -> Result<(), CliError> {
    check_display()?;
    let mut path = path.to_path_buf();
    let bundled = Path::new(env!("CARGO_MANIFEST_DIR")).join(&path);
    if !path.exists() && path.is_relative() && bundled.exists() {
        path = bundled;
    }
    let (desc, _) = load(&path, include)?;
    run(&desc, options)
}
