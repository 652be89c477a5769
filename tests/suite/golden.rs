//! Golden frames: 3 frames of each shipped camera path through `scenes/seed.pov` at 160×120,
//! compared with the PNGs committed in `tests/golden/`.
//!
//! On the target that wrote the goldens (recorded per frame in `tests/golden/SHA256SUMS`) the
//! 8-bit pixels must match exactly. Elsewhere the frames must be within 45 dB PSNR: other CPUs,
//! libms and compilers may round f32 differently, which moves a few pixels by one step.
//!
//! Regenerate deliberately, after a change that is meant to alter pixels:
//!     STRAHL_REGEN_GOLDEN=1 cargo test --release --test suite golden::

use std::fmt::Write as _;
use std::path::PathBuf;

use strahl::camera::path::CameraPath;
use strahl::camera::Camera;
use strahl::headless::capture::{frame_t, render_rgb8, sha256_hex};
use strahl::headless::metrics::psnr;
use strahl::headless::output::{read_png, write_png};
use strahl::render::image::Image;
use strahl::render::RenderSettings;
use strahl::scene::build::{AccelKind, Scene};

const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;
const FRAMES: u32 = 3;
const PATHS: [&str; 2] = ["seed.orbit.path", "seed.fly.path"];
const MIN_PSNR_DB: f64 = 45.0;
const REGEN: &str = "STRAHL_REGEN_GOLDEN=1 cargo test --release --test golden";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn golden_dir() -> PathBuf {
    root().join("tests").join("golden")
}

fn failure_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root().join("target"), PathBuf::from).join("golden-failures")
}

/// Where a frame's pixels come from: "x86_64-linux" and the like. Exact matches are expected
/// only between runs on the same target.
fn this_target() -> String {
    format!("{}-{}", std::env::consts::ARCH, std::env::consts::OS)
}

/// A rendered frame.
struct Frame {
    name: String,
    rgb: Vec<u8>,
}

fn render_frames() -> Vec<Frame> {
    let scene_file = root().join("scenes").join("seed.pov");
    let (desc, _) = strahl::headless::load(&scene_file, &[])
        .unwrap_or_else(|e| panic!("cannot load {}: {e}", scene_file.display()));
    let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
    let base = Camera::from_desc(&desc.camera);
    let settings = RenderSettings { width: WIDTH, height: HEIGHT, ..RenderSettings::default() };
    let mut image = Image::default();
    let mut frames = Vec::new();
    for path_name in PATHS {
        let path = CameraPath::load(&root().join("scenes").join(path_name)).unwrap_or_else(|e| panic!("{e}"));
        for i in 0..FRAMES {
            // A closed path's last frame repeats its first, so spread its frames over the loop.
            let t = if path.closed { i as f64 / FRAMES as f64 } else { frame_t(i, FRAMES) };
            let camera = path.camera_at(t, &base);
            let (rgb, _) = render_rgb8(&scene, &camera, &settings, &mut image);
            let stem = path_name.trim_end_matches(".path");
            frames.push(Frame { name: format!("{stem}.{i}.png"), rgb });
        }
    }
    frames
}

/// `SHA256SUMS`: one `sha256  file  target` line per golden frame.
fn read_sums() -> Vec<(String, String, String)> {
    let text = std::fs::read_to_string(golden_dir().join("SHA256SUMS")).unwrap_or_default();
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            Some((w.next()?.to_string(), w.next()?.to_string(), w.next()?.to_string()))
        })
        .collect()
}

fn regenerate(frames: &[Frame]) {
    std::fs::create_dir_all(golden_dir()).unwrap_or_else(|e| panic!("{e}"));
    let mut sums = format!("# Golden frames for tests/suite/golden.rs; regenerate with: {REGEN}\n");
    for f in frames {
        write_png(&golden_dir().join(&f.name), WIDTH, HEIGHT, &f.rgb).unwrap_or_else(|e| panic!("{e}"));
        let _ = writeln!(sums, "{}  {}  {}", sha256_hex(&f.rgb), f.name, this_target());
    }
    std::fs::write(golden_dir().join("SHA256SUMS"), sums).unwrap_or_else(|e| panic!("{e}"));
    eprintln!("regenerated {} golden frames in {}", frames.len(), golden_dir().display());
}

/// Amplified absolute difference, so one-step differences are visible.
fn diff_image(a: &[u8], b: &[u8]) -> Vec<u8> {
    a.iter().zip(b).map(|(&x, &y)| ((x as i32 - y as i32).unsigned_abs() * 16).min(255) as u8).collect()
}

fn save_failure(name: &str, actual: &[u8], expected: Option<&[u8]>) -> PathBuf {
    let dir = failure_dir();
    let _ = std::fs::create_dir_all(&dir);
    let stem = name.trim_end_matches(".png");
    let _ = write_png(&dir.join(format!("{stem}.actual.png")), WIDTH, HEIGHT, actual);
    if let Some(expected) = expected {
        let _ = write_png(&dir.join(format!("{stem}.expected.png")), WIDTH, HEIGHT, expected);
        let _ = write_png(&dir.join(format!("{stem}.diff.png")), WIDTH, HEIGHT, &diff_image(actual, expected));
    }
    dir
}

/// Compares one frame with its golden; `None` when it passes.
fn check(frame: &Frame, sums: &[(String, String, String)]) -> Option<String> {
    let file = golden_dir().join(&frame.name);
    let Some((sha, _, target)) = sums.iter().find(|(_, f, _)| *f == frame.name) else {
        let dir = save_failure(&frame.name, &frame.rgb, None);
        return Some(format!(
            "{}: no golden frame (actual written to {}); generate them with: {REGEN}",
            file.display(),
            dir.display()
        ));
    };
    let (w, h, expected) = match read_png(&file) {
        Ok(img) => img,
        Err(e) => return Some(format!("{e}; regenerate with: {REGEN}")),
    };
    if (w, h) != (WIDTH, HEIGHT) {
        return Some(format!(
            "{}: golden is {w}x{h}, expected {WIDTH}x{HEIGHT}; regenerate with: {REGEN}",
            file.display()
        ));
    }
    let actual_sha = sha256_hex(&frame.rgb);
    if actual_sha == *sha {
        return None;
    }
    let db = psnr(&frame.rgb, &expected);
    if db == f64::INFINITY {
        return Some(format!(
            "{}: the PNG matches but SHA256SUMS lists another hash; regenerate with: {REGEN}",
            frame.name
        ));
    }
    if *target != this_target() && db >= MIN_PSNR_DB {
        // A different CPU or libm: small rounding differences are expected, large ones are not.
        eprintln!(
            "note: {} differs from its {target} golden at {db:.1} dB (>= {MIN_PSNR_DB}): accepted on {}",
            frame.name,
            this_target()
        );
        return None;
    }
    let dir = save_failure(&frame.name, &frame.rgb, Some(&expected));
    let why = if *target == this_target() {
        format!("pixels differ from the golden written on this target ({target}), PSNR {db:.2} dB; the exact SHA-256 must match here")
    } else {
        format!("PSNR {db:.2} dB < {MIN_PSNR_DB} dB against the {target} golden (other CPUs or compilers may round f32 differently, but not this much)")
    };
    Some(format!(
        "{}: {why}\n  actual, expected and diff written to {}\n  if the change is intended, regenerate with: {REGEN}",
        frame.name,
        dir.display()
    ))
}

#[test]
fn golden_frames_match() {
    let frames = render_frames();
    if std::env::var_os("STRAHL_REGEN_GOLDEN").is_some_and(|v| v != "0") {
        regenerate(&frames);
        return;
    }
    let sums = read_sums();
    let failures: Vec<String> = frames.iter().filter_map(|f| check(f, &sums)).collect();
    assert!(
        failures.is_empty(),
        "{} of {} golden frames failed:\n{}",
        failures.len(),
        frames.len(),
        failures.join("\n")
    );
}

#[test]
fn golden_diff_image_amplifies_differences() {
    // The failure report's diff must show a one-step difference, not hide it as black.
    assert_eq!(diff_image(&[10, 200, 0], &[11, 200, 255]), vec![16, 0, 255]);
}
