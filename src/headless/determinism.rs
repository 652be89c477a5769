//! Determinism of whole frames: the 8-bit pixels of a frame must not depend on the run, the
//! thread count, the tile size or how a capture is sharded. Uses the hand-built seed scene so it
//! runs without the parser.

use std::path::PathBuf;

use crate::camera::path::CameraPath;
use crate::camera::Camera;
use crate::headless::capture::{capture, frame_t, render_rgb8, sha256_hex, CaptureJob};
use crate::headless::manifest::Manifest;
use crate::headless::{with_threads, Staged};
use crate::render::image::Image;
use crate::render::RenderSettings;
use crate::scene::build::{AccelKind, Scene};
use crate::scene::fixtures::seed_scene;

fn orbit() -> CameraPath {
    let file = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/seed.orbit.path");
    CameraPath::load(&file).unwrap_or_else(|e| panic!("{e}"))
}

fn small() -> RenderSettings {
    RenderSettings { width: 61, height: 47, ..RenderSettings::default() }
}

/// SHA-256 of the 8-bit pixels of frames 0, 2, 5 of 7 along the orbit.
fn hashes(scene: &Scene, threads: usize, settings: &RenderSettings) -> Vec<String> {
    let path = orbit();
    let base = Camera::from_desc(&seed_scene().camera);
    with_threads(threads, || {
        let mut image = Image::default();
        [0, 2, 5]
            .iter()
            .map(|&i| {
                let (rgb, _) = render_rgb8(scene, &path.camera_at(frame_t(i, 7), &base), settings, &mut image);
                sha256_hex(&rgb)
            })
            .collect()
    })
    .unwrap_or_else(|e| panic!("{e}"))
}

fn seed() -> Scene {
    let desc = seed_scene();
    Scene::build(&desc, desc.camera.location, AccelKind::Bvh)
}

#[test]
fn frames_differ_along_the_path() {
    // Guards the tests below: equal hashes mean nothing if every frame were the same.
    let h = hashes(&seed(), 1, &small());
    assert!(h[0] != h[1] && h[1] != h[2], "{h:?}");
}

#[test]
fn frames_are_identical_across_runs() {
    let scene = seed();
    assert_eq!(hashes(&scene, 2, &small()), hashes(&scene, 2, &small()));
    // A freshly built scene, too.
    assert_eq!(hashes(&scene, 2, &small()), hashes(&seed(), 2, &small()));
}

#[test]
fn frames_are_identical_across_thread_counts() {
    let scene = seed();
    let one = hashes(&scene, 1, &small());
    for threads in [2, 8] {
        assert_eq!(hashes(&scene, threads, &small()), one, "{threads} threads");
    }
}

#[test]
fn frames_are_identical_across_tile_sizes() {
    let scene = seed();
    let reference = hashes(&scene, 2, &RenderSettings { tile: 16, ..small() });
    for tile in [8, 37, 1, 1000] {
        assert_eq!(hashes(&scene, 2, &RenderSettings { tile, ..small() }), reference, "tile {tile}");
    }
}

#[test]
fn frames_are_identical_across_accelerators() {
    let desc = seed_scene();
    let bvh = hashes(&seed(), 2, &small());
    for accel in [AccelKind::Grid, AccelKind::None] {
        let scene = Scene::build(&desc, desc.camera.location, accel);
        assert_eq!(hashes(&scene, 2, &small()), bvh, "{accel:?}");
    }
}

/// A scratch folder under the system temp dir, removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("strahl-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
        Scratch(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

#[test]
fn shards_merge_into_the_whole_capture() {
    let staged = Staged { scene: seed(), base: Camera::from_desc(&seed_scene().camera) };
    let path = orbit();
    let job = |start, end| CaptureJob {
        scene_name: "seed".into(),
        path_name: "seed.orbit.path".into(),
        path: &path,
        frames: 5,
        indices: (start..end).collect(),
        done: Vec::new(),
        checkpoint: false,
        settings: RenderSettings { width: 24, height: 18, ..RenderSettings::default() },
        res_scale: 1.0,
        accel: AccelKind::Bvh,
        clock: None,
        quiet: true,
    };
    let dir = Scratch::new("shards");
    let run = |start, end, threads| {
        with_threads(threads, || capture(&staged, &|_| Ok(None), &job(start, end), &dir.0))
            .and_then(|r| r)
            .unwrap_or_else(|e| panic!("{e}"))
    };
    let whole = run(0, 5, 2);
    assert_eq!(whole.frames.len(), 5);
    assert!(dir.0.join("frame_0004.png").is_file());
    let shards = [run(3, 5, 1), run(0, 1, 2), run(1, 3, 2)];
    assert_eq!(shards[0].frames.len(), 2, "a shard lists only its frames");
    let merged = Manifest::merge(&shards).unwrap_or_else(|e| panic!("{e}"));
    assert!(merged.same_content(&whole), "{merged:#?}\nvs\n{whole:#?}");
}
