//! Headless front ends: `render`, `capture`, `merge`, `farm`, `bench`, `tradeoff`, `survey`, `path orbit`, and the shared plumbing (loading,
//! errors, thread pools, JSON, image metrics). Nothing here touches a window.
//!
//! Layer 9 of docs/design/architecture.md, the top: uses `pov`, `render` and below; only `app` and `main` use it.

pub mod band;
pub mod bench;
pub mod capture;
#[cfg(test)]
mod determinism;
pub mod farm;
pub mod json;
pub mod manifest;
pub mod metrics;
pub mod orbit;
pub mod output;
pub mod povray_ini;
pub mod progress;
pub mod render;
pub mod report;
pub mod scaling;
pub mod shard;
pub mod still_part;
pub mod survey;
pub mod tradeoff;

use std::fmt;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::camera::Camera;
use crate::desc::SceneDesc;
use crate::error::LocatedError;
use crate::pov::{load_scene_with_messages, Clock, IncludePath, ParseOptions};
use crate::render::RenderSettings;
use crate::scene::build::{AccelKind, Scene};

/// An error for the user, with the process exit code it maps to.
#[derive(Debug)]
pub struct CliError {
    pub message: String,
    /// 2 for bad input of any kind (scene, path, arguments, unwritable output).
    pub code: i32,
}

impl CliError {
    pub fn user(message: impl Into<String>) -> CliError {
        CliError { message: message.into(), code: 2 }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl From<LocatedError> for CliError {
    fn from(e: LocatedError) -> CliError {
        CliError::user(e.to_string())
    }
}

/// The project's own include folder (`scenes/include`), found next to the executable's source
/// tree at build time, so a fresh clone needs no POV-Ray installation.
pub fn project_include_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join("include")
}

/// The include path in POV-Ray's order: `-L` dirs, then POV-Ray's own include folders where it
/// is installed, then the project's bundled copies (the fallback on a machine without
/// POV-Ray). The including file's own folder is searched first by the parser.
pub fn include_path(user_dirs: &[PathBuf]) -> IncludePath {
    let mut dirs = user_dirs.to_vec();
    dirs.extend(povray_ini::povray_include_dirs());
    dirs.push(project_include_dir());
    IncludePath { dirs }
}

/// Parses a scene, timing it, with POV-Ray's default `image_width`/`image_height` (640×480).
pub fn load(path: &Path, user_dirs: &[PathBuf]) -> Result<(SceneDesc, Duration), CliError> {
    load_sized(path, user_dirs, 640, 480)
}

/// Parses a scene for an image of `width`×`height`, which `image_width`/`image_height` report,
/// printing what the scene printed (`#debug` text, warnings such as POV-Ray's "Scale by 0.0
/// changed to 1.0") to stderr. The scene sees a still image's clock (0, `clock_on` false).
pub fn load_sized(
    path: &Path,
    user_dirs: &[PathBuf],
    width: u32,
    height: u32,
) -> Result<(SceneDesc, Duration), CliError> {
    load_with_clock(path, user_dirs, width, height, Clock::default())
}

/// [`load_sized`] for one frame of an animation: the scene reads `clock`, `frame_number` and the
/// rest from `clock`, so each frame of `--clock A..B` is parsed anew, as POV-Ray does.
pub fn load_with_clock(
    path: &Path,
    user_dirs: &[PathBuf],
    width: u32,
    height: u32,
    clock: Clock,
) -> Result<(SceneDesc, Duration), CliError> {
    let start = Instant::now();
    let options = ParseOptions { image_width: width, image_height: height, clock };
    let (desc, messages) = load_scene_with_messages(path, &include_path(user_dirs), &options)?;
    for m in messages {
        eprint!("{m}");
    }
    Ok((desc, start.elapsed()))
}

/// A scene ready to render along a camera path: built with render space centred on the scene's
/// own camera (so a frame's pixels do not depend on which frame came first), and that camera,
/// whose projection the path's cameras keep.
pub struct Staged {
    pub scene: Scene,
    pub base: Camera,
}

impl Staged {
    /// Builds `desc` with render space centred on its camera.
    pub fn new(desc: &SceneDesc, accel: AccelKind) -> Staged {
        let scene = Scene::build(desc, desc.camera.location, accel);
        Staged { scene, base: Camera::from_desc(&desc.camera) }
    }

    /// Parses `path` at `clock` for the settings' image size and builds it;
    /// also returns the time parsing and building took together.
    pub fn load(
        path: &Path,
        user_dirs: &[PathBuf],
        settings: &RenderSettings,
        accel: AccelKind,
        clock: Clock,
    ) -> Result<(Staged, Duration), CliError> {
        let start = Instant::now();
        let (desc, _) = load_with_clock(path, user_dirs, settings.width, settings.height, clock)?;
        Ok((Staged::new(&desc, accel), start.elapsed()))
    }
}

/// The cores rayon would use by default (one worker per core).
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// The most worker threads any command accepts: four per core, and at least 16 so determinism
/// checks can oversubscribe a small machine. Beyond that threads only cost (1 000 threads took 37×
/// as long as 2 on two cores), and around 10⁵ the OS refuses their stacks.
pub fn max_threads() -> usize {
    (4 * cores()).max(16)
}

/// Checks a thread count (0 = one per core) against [`max_threads`].
pub fn check_threads(threads: usize) -> Result<usize, String> {
    let max = max_threads();
    if threads > max {
        return Err(format!(
            "{threads} threads is too many: this machine has {} cores; give at most {max} (4 per core), or 0 for one per core",
            cores()
        ));
    }
    Ok(threads)
}

/// `--threads N` as clap parses it, so a bad count fails before any work.
pub fn parse_threads(s: &str) -> Result<usize, String> {
    let n: usize =
        s.trim().parse().map_err(|_| format!("`{s}` is not a thread count: give a whole number, 0 = one per core"))?;
    check_threads(n)
}

/// `-L DIR` as clap parses it: the folder must exist, or a typo would silently leave includes
/// unresolved until some `#include` fails far from the cause.
pub fn parse_include_dir(s: &str) -> Result<PathBuf, String> {
    let dir = PathBuf::from(s);
    if dir.is_dir() {
        Ok(dir)
    } else if dir.exists() {
        Err(format!("{s} is not a folder"))
    } else {
        Err(format!("include folder {s} does not exist"))
    }
}

/// Runs `f` on a rayon pool of `threads` workers (0 = one per core), at most [`max_threads`].
pub fn with_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T, CliError> {
    check_threads(threads).map_err(CliError::user)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| CliError::user(format!("cannot start {threads} threads: {e}")))?;
    Ok(pool.install(f))
}

/// Peak resident memory of this process in bytes, where the OS reports it.
pub fn peak_memory_bytes() -> Option<u64> {
    status_bytes("VmHWM:")
}

/// Resident memory of this process now, in bytes, where the OS reports it.
pub fn resident_memory_bytes() -> Option<u64> {
    status_bytes("VmRSS:")
}

/// A `kB` line of /proc/self/status in bytes.
fn status_bytes(key: &str) -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(key))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}
