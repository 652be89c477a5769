//! Reprojection (`render::reproject`) on real scenes: what a moving window shows, frame by frame.

use std::path::Path;
use std::time::Instant;

use strahl::camera::path::CameraPath;
use strahl::camera::Camera;
use strahl::headless::metrics::psnr;
use strahl::pov::{load_scene, IncludePath};
use strahl::render::image::Image;
use strahl::render::reproject::Reprojector;
use strahl::render::{render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};

fn seed() -> (Scene, Camera) {
    let include = IncludePath { dirs: vec!["scenes/include".into()] };
    let desc = load_scene(Path::new("scenes/seed.pov"), &include).expect("the seed scene loads");
    let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
    (scene, Camera::from_desc(&desc.camera))
}

/// Tuning aid (`cargo test --release --test suite reproject:: -- --ignored --nocapture`): PSNR against
/// full renders and time per frame along the shipped paths, at 60 frames a second of path.
#[test]
#[ignore]
fn along_the_paths() {
    let (scene, base) = seed();
    let (w, h) = (1280, 720);
    for name in ["fly", "orbit"] {
        let path = CameraPath::load(Path::new(&format!("scenes/seed.{name}.path"))).unwrap();
        let frames = 300;
        let mut rp = Reprojector::default();
        let mut full = Image::default();
        let settings = RenderSettings { width: w, height: h, ..RenderSettings::default() };
        let (mut ps, mut ts) = (Vec::new(), Vec::new());
        for k in 0..frames {
            let camera = path.camera_at(k as f64 / (frames - 1) as f64, &base);
            let start = Instant::now();
            let (img, _, counts) = rp.frame(&scene, &camera, &settings);
            ts.push(start.elapsed().as_secs_f64() * 1e3);
            let shown = rgb(img);
            if k % 30 == 0 {
                render(&scene, &camera, &settings, &mut full);
                let reference = full.to_rgb8(scene.srgb);
                let p = psnr(&shown, &reference).min(100.0);
                ps.push(p);
                eprintln!(
                    "{name} {k:3} {:6.2} dB {:6.1} ms traced {:.3} {:?}",
                    p,
                    ts[k],
                    counts.traced_share(),
                    counts
                );
            }
        }
        ps.sort_by(f64::total_cmp);
        ts.sort_by(f64::total_cmp);
        let mean = ps.iter().sum::<f64>() / ps.len() as f64;
        eprintln!(
            "{name}: PSNR mean {mean:.2} median {:.2} min {:.2}; frame median {:.1} ms",
            ps[ps.len() / 2],
            ps[0],
            ts[ts.len() / 2]
        );
    }
}

/// Objects in flat colours (ambient 1, diffuse 0): a full render shows each object's own colour
/// in every pixel it covers, so a reprojected frame that matches the full render byte for byte
/// shows no pixel from a different object. The camera slides past a thin pole and overlapping
/// spheres, uncovering what they hid.
const FLAT: &str = r#"
#declare F = finish { ambient 1 diffuse 0 };
camera { location <0, 1.5, -6> look_at <0, 1, 0> }
background { rgb <0.2, 0.3, 0.9> }
plane { y, 0 pigment { rgb <0.5, 0.5, 0.5> } finish { F } }
sphere { <-0.8, 1, 0>, 1 pigment { rgb <1, 0, 0> } finish { F } }
sphere { <0.6, 1.2, 1.2>, 1 pigment { rgb <0, 1, 0> } finish { F } }
cylinder { <0.2, 0, -2>, <0.2, 3, -2>, 0.015 pigment { rgb <1, 1, 0> } finish { F } }
box { <1.5, 0, -1>, <2.2, 0.7, -0.3> pigment { rgb <1, 0, 1> } finish { F } }
"#;

#[test]
fn a_moving_camera_never_shows_another_objects_colour() {
    let reused = slide_past_flat_objects("flat", |_| (160, 90));
    assert!(reused > 0, "the frames reuse pixels");
}

/// The window's adaptive scale changes the frame size while the camera moves: the previous
/// frame is reprojected from its own size, and still shows no other object's colour.
#[test]
fn the_history_survives_a_change_of_size() {
    let sizes = [(160, 90), (144, 81), (176, 99), (120, 68)];
    let reused = slide_past_flat_objects("flat-sizes", |k| sizes[k % sizes.len()]);
    assert!(reused > 0, "frames after a size change reuse pixels");
}

/// Slides the camera through 24 frames of [`FLAT`], frame `k` at `size(k)`, asserting that
/// every reprojected frame is the full render's bytes; returns how many pixels were reused
/// (frames after the first; the first traced ones are asserted too).
fn slide_past_flat_objects(name: &str, size: impl Fn(usize) -> (u32, u32)) -> u64 {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("reproject");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("{name}.pov"));
    std::fs::write(&file, FLAT).unwrap();
    let desc = load_scene(&file, &IncludePath::default()).expect("the flat scene loads");
    let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
    let base = Camera::from_desc(&desc.camera);
    let mut rp = Reprojector::default();
    let mut full = Image::default();
    let (mut reused, mut traced) = (0, 0);
    for k in 0..24 {
        let (width, height) = size(k);
        let settings = RenderSettings { width, height, ..RenderSettings::default() };
        let camera = Camera {
            location: base.location + glam::DVec3::new(0.06 * k as f64, 0.01 * k as f64, 0.02 * k as f64),
            ..base
        };
        let (shown, _, counts) = rp.frame(&scene, &camera, &settings);
        let shown = rgb(shown);
        render(&scene, &camera, &settings, &mut full);
        let reference = full.to_rgb8(scene.srgb);
        let wrong = shown.chunks(3).zip(reference.chunks(3)).filter(|(a, b)| a != b).count();
        assert_eq!(wrong, 0, "frame {k}: {wrong} pixels show another object's colour ({counts:?})");
        if k > 0 {
            reused += counts.reused;
            traced += counts.traced;
        }
    }
    assert!(traced > 0, "the frames trace detail: {traced} traced");
    reused
}

fn rgb(pixels: &[u32]) -> Vec<u8> {
    pixels.iter().flat_map(|&p| [(p >> 16) as u8, (p >> 8) as u8, p as u8]).collect()
}
