//! `strahl path orbit SCENE -o FILE`: writes a closed orbit of the scene's camera around its
//! `look_at` (the geometry is `camera::orbit`'s), so any scene can be benched and flown along a
//! path (`strahl bench --path`, `strahl view --path --report`).

use std::path::{Path, PathBuf};

use crate::camera::orbit::Orbit;
use crate::camera::path::CameraPath;
use crate::headless::{load, output, CliError};
use crate::scene::build::{AccelKind, Scene};

/// Keys on the circle when `--frames` is not given: 45° apart, as `scenes/seed.orbit.path`.
pub const DEFAULT_KEYS: u32 = 8;
/// Seconds one turn takes when `--seconds` is not given (the key times; `view --path` plays
/// a path in its key times' seconds).
pub const DEFAULT_SECONDS: f64 = 10.0;
/// The longest turn accepted, as `view --path-seconds` accepts.
pub const MAX_SECONDS: f64 = 1e6;

pub struct OrbitArgs {
    pub scene: PathBuf,
    pub include: Vec<PathBuf>,
    pub output: PathBuf,
    /// Keys around the circle (the file has one more, closing it).
    pub keys: u32,
    pub seconds: f64,
    pub quiet: bool,
}

/// `--seconds` as clap parses it: a positive, finite number of seconds up to [`MAX_SECONDS`].
pub fn parse_seconds(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 && v <= MAX_SECONDS => Ok(v),
        _ => Err(format!("`{s}` is not a length of time: give a positive number of seconds, at most {MAX_SECONDS}")),
    }
}

/// Loads the scene, picks its orbit and writes the path file (atomically: a failure leaves no
/// file). The output is checked before the scene is read.
pub fn run(args: &OrbitArgs) -> Result<(), CliError> {
    output::check_writable("-o", &args.output)?;
    if !(args.seconds.is_finite() && args.seconds > 0.0 && args.seconds <= MAX_SECONDS) {
        return Err(CliError::user(format!("--seconds must be a positive number of seconds, not {}", args.seconds)));
    }
    let (desc, _) = load(&args.scene, &args.include)?;
    // Bounds only: no accelerator is needed.
    let scene = Scene::build(&desc, desc.camera.location, AccelKind::None);
    let subject = scene.subject_bounds(desc.camera.location);
    let orbit = Orbit::for_camera(&desc.camera, subject);
    let text = orbit.path_text(&display_name(&args.scene), args.keys, args.seconds);
    // What is written must read back: a path that `view` or `bench` refused would be a bug here.
    CameraPath::parse(&args.output.display().to_string(), &text)
        .map_err(|e| CliError::user(format!("internal error: the orbit does not parse back: {e}")))?;
    output::write_atomic(&args.output, text.as_bytes())?;
    if !args.quiet {
        let c = orbit.centre;
        let size = subject
            .map_or("no bounded objects".to_string(), |(lo, hi)| format!("subject {:.4} across", (hi - lo).length()));
        eprintln!(
            "{}: orbit around <{:.4}, {:.4}, {:.4}>, radius {:.4}, height {:.4}, {} keys, {} s ({size})",
            args.output.display(),
            c.x,
            c.y,
            c.z,
            orbit.radius,
            orbit.height,
            args.keys + 1,
            args.seconds
        );
    }
    Ok(())
}

/// The scene's file name, for the comment at the top of the path file.
fn display_name(scene: &Path) -> String {
    scene.file_name().map_or_else(|| scene.display().to_string(), |n| n.to_string_lossy().into_owned())
}
