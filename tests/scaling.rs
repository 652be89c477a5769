//! The generated many-object scenes (`scene::generate`, `strahl gen`): the POV text reads back
//! to the same scene, and every accelerator and packet mode renders it to the same bits.

use std::path::PathBuf;

use strahl::camera::Camera;
use strahl::pov::{load_scene, IncludePath};
use strahl::render::image::Image;
use strahl::render::{render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};
use strahl::scene::desc::SceneDesc;
use strahl::scene::generate::{generate, write_pov, Kind};

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("scaling");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    dir.join(name)
}

/// Everything but the source locations, which differ by construction.
fn without_sources(mut d: SceneDesc) -> SceneDesc {
    for o in &mut d.objects {
        o.source = Default::default();
    }
    d
}

#[test]
fn gen_output_parses_to_the_generated_scene() {
    for kind in Kind::ALL {
        let desc = generate(kind, 200);
        let text = write_pov(&desc).unwrap_or_else(|e| panic!("{e}"));
        let path = scratch(&format!("{}.pov", kind.name()));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
        let read = load_scene(&path, &IncludePath { dirs: vec![] }).unwrap_or_else(|e| panic!("{e}"));
        // Numbers are written in shortest round-trip form, so "within print precision" is exact.
        assert_eq!(without_sources(read), without_sources(desc), "{kind:?}");
    }
}

#[test]
fn gen_command_writes_a_loadable_scene() {
    let path = scratch("cli_boxes.pov");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_strahl"))
        .args(["gen", "boxes", "50", "-o"])
        .arg(&path)
        .status()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(status.success());
    let read = load_scene(&path, &IncludePath { dirs: vec![] }).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(without_sources(read), without_sources(generate(Kind::Boxes, 50)));
}

fn pixels(desc: &SceneDesc, accel: AccelKind, packets: bool) -> Vec<[u32; 3]> {
    let scene = Scene::build(desc, desc.camera.location, accel);
    let settings = RenderSettings { width: 96, height: 54, packets, ..RenderSettings::default() };
    let mut image = Image::new(settings.width, settings.height);
    let stats = render(&scene, &Camera::from_desc(&desc.camera), &settings, &mut image);
    assert!(stats.reflected_rays > 0, "the scene should exercise reflection");
    image.pixels.iter().map(|p| p.to_array().map(f32::to_bits)).collect()
}

#[test]
fn accelerators_and_packets_give_identical_images_on_2000_objects() {
    let desc = generate(Kind::Mixed, 2000);
    let reference = pixels(&desc, AccelKind::None, false);
    for (accel, packets) in [
        (AccelKind::None, true),
        (AccelKind::Grid, false),
        (AccelKind::Grid, true),
        (AccelKind::Bvh, false),
        (AccelKind::Bvh, true),
    ] {
        let got = pixels(&desc, accel, packets);
        let differ = got.iter().zip(&reference).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "{accel:?} packets={packets}: {differ} pixels differ from brute force");
    }
}
