//! Opens the window on a hand-built copy of `scenes/seed.pov`, without the parser:
//! `cargo run --example view_seed [-- --frames N --screenshot shot.png --reference ref.png --hud on]`.
//! `--reference` also writes the headless render of the same camera, for comparison.

use std::path::PathBuf;

use strahl::app::{run, ViewOptions};
use strahl::camera::Camera;
use strahl::headless::output::write_png;
use strahl::render::image::Image;
use strahl::render::{render, Quality, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};
use strahl::scene::testing::seed_like;

fn main() {
    let mut options = ViewOptions {
        width: 640,
        height: 480,
        aa: 1,
        quality: Quality::default(),
        threads: 0,
        accel: AccelKind::Bvh,
        target_fps: 60.0,
        frames: None,
        screenshot: None,
        title: "strahl - seed (built in)".into(),
        hud: false,
        path: None,
        report: None,
    };
    let mut reference: Option<PathBuf> = None;
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        let value = pair.get(1).cloned().unwrap_or_default();
        match pair[0].as_str() {
            "--frames" => options.frames = value.parse().ok(),
            "--screenshot" => options.screenshot = Some(value.into()),
            "--reference" => reference = Some(value.into()),
            "--hud" => options.hud = value == "on",
            "--aa" => options.aa = value.parse().unwrap_or(1),
            other => eprintln!("ignoring {other}"),
        }
    }
    let desc = seed_like();
    if let Some(path) = reference {
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let settings = RenderSettings {
            width: options.width,
            height: options.height,
            aa: options.aa,
            ..RenderSettings::default()
        };
        let mut image = Image::default();
        render(
            &scene,
            &Camera::from_desc(&desc.camera),
            &settings,
            &mut image,
        );
        if let Err(e) = write_png(&path, image.width, image.height, &image.to_rgb8(scene.srgb)) {
            eprintln!("error: {e}");
        }
    }
    if let Err(e) = run(&desc, options) {
        eprintln!("error: {e}");
        std::process::exit(e.code);
    }
}
