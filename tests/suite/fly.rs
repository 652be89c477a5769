//! The fly camera's default speed on real scenes: what `strahl view` starts with, driven through
//! the pure fly model (`strahl::fly`), so no window is needed.

use crate::common;

use std::path::Path;

use common::transform_scene;
use glam::DMat4;
use strahl::camera::Camera;
use strahl::fly::{initial_speed, step, FlyState, InputState};
use strahl::headless::include_path;
use strahl::pov::load_scene;
use strahl::scene::build::{AccelKind, Scene};

/// Seconds of holding W (60 steps a second) until the camera has travelled `distance`.
fn seconds_to_fly(start: FlyState, distance: f64) -> f64 {
    let dt = 1.0 / 60.0;
    let hold = InputState { forward: true, ..Default::default() };
    let mut s = start;
    for frame in 1..=60 * 120 {
        s = step(&s, &hold, dt);
        if (s.position - start.position).length() >= distance {
            return frame as f64 * dt;
        }
    }
    f64::INFINITY
}

/// The speed came from the bounds in render space, which is in the camera's unit of length,
/// while the camera flies in world units: 25 s to reach the seed's sphere, and the same
/// 0.19 units/s whatever the scene's scale. Now the default speed crosses the scene's bounds
/// in a few seconds at every scale.
#[test]
fn default_fly_speed_crosses_the_scene_in_seconds_at_any_scale() {
    let seed = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join("seed.pov");
    let desc = load_scene(&seed, &include_path(&[])).unwrap_or_else(|e| panic!("{e}"));
    let mut extents = Vec::new();
    for scale in [1e-3, 1.0, 1e3] {
        let scaled = transform_scene(&desc, DMat4::from_scale(glam::DVec3::splat(scale)));
        let scene = Scene::build(&scaled, scaled.camera.location, AccelKind::Bvh);
        let (lo, hi) = scene.world_bounds().expect("the seed scene has bounded objects");
        let extent = (hi - lo).length();
        extents.push(extent);
        let fly =
            FlyState::new(Camera::from_desc(&scaled.camera), initial_speed(scene.world_bounds(), scene.frame.unit));
        let seconds = seconds_to_fly(fly, extent);
        assert!((2.0..=10.0).contains(&seconds), "×{scale}: {seconds} s to cross {extent} units");
    }
    // The bounds are in world units: they scale with the scene.
    for (e, scale) in extents.iter().zip([1e-3, 1.0, 1e3]) {
        assert!((e / scale / extents[1] - 1.0).abs() < 1e-5, "extent {e} at ×{scale}");
    }
}
