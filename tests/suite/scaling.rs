//! The generated many-object scenes (`scene::generate`, `strahl gen`): the POV text reads back
//! to the same scene at any image size, and every accelerator and packet mode renders it to the
//! same bits; `strahl scaling` prints each row once and skips slow cells with a note.

use std::path::PathBuf;

use strahl::camera::Camera;
use strahl::desc::SceneDesc;
use strahl::pov::{load_scene, load_scene_with_options, IncludePath, ParseOptions};
use strahl::render::image::Image;
use strahl::render::{render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};
use strahl::scene::generate::{generate, write_generated, write_pov, Kind};

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

fn strahl(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_strahl"))
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("cannot run strahl: {e}"))
}

#[test]
fn gen_output_parses_to_the_generated_scene() {
    for kind in Kind::ALL {
        let path = scratch(&format!("{}.pov", kind.name()));
        std::fs::write(&path, write_generated(kind, 200).unwrap_or_else(|e| panic!("{e}")))
            .unwrap_or_else(|e| panic!("{e}"));
        // Read at two image sizes: the camera follows `image_width`/`image_height`.
        for (w, h) in [(640, 480), (1280, 720)] {
            let options = ParseOptions { image_width: w, image_height: h, ..Default::default() };
            let read = load_scene_with_options(&path, &IncludePath { dirs: vec![] }, &options)
                .unwrap_or_else(|e| panic!("{e}"));
            // Numbers are written in shortest round-trip form, so "within print precision" is exact.
            assert_eq!(without_sources(read), without_sources(generate(kind, 200, w, h)), "{kind:?} {w}x{h}");
        }
        // `write_pov` writes the vectors as they are.
        let desc = generate(kind, 200, 1280, 720);
        std::fs::write(&path, write_pov(&desc).unwrap_or_else(|e| panic!("{e}"))).unwrap_or_else(|e| panic!("{e}"));
        let read = load_scene(&path, &IncludePath { dirs: vec![] }).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(without_sources(read), without_sources(desc), "{kind:?}");
    }
}

#[test]
fn gen_says_which_file_it_wrote() {
    let path = scratch("cli_boxes.pov");
    let out = strahl(&["gen", "boxes", "50", "-o", &path.display().to_string()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout), format!("wrote {} (50 boxes)\n", path.display()));
    let read = load_scene(&path, &IncludePath { dirs: vec![] }).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(without_sources(read), without_sources(generate(Kind::Boxes, 50, 640, 480)));
    let out = strahl(&["gen", "mixed", "30", "-o", &path.display().to_string()]);
    assert!(String::from_utf8_lossy(&out.stdout).ends_with("(30 mixed objects)\n"));
}

#[test]
fn gen_camera_is_not_stretched_at_the_default_640x480() {
    // POV-Ray's default `right` is <1.33, 0, 0> for its default 4:3 image; the file `gen` wrote
    // had a fixed 16:9 `right`, so every default render was squeezed sideways.
    let path = scratch("cli_aspect.pov");
    assert!(strahl(&["gen", "spheres", "20", "-o", &path.display().to_string()]).status.success());
    for (w, h) in [(640, 480), (1280, 720), (300, 300)] {
        let options = ParseOptions { image_width: w, image_height: h, ..Default::default() };
        let c = load_scene_with_options(&path, &IncludePath { dirs: vec![] }, &options)
            .unwrap_or_else(|e| panic!("{e}"))
            .camera;
        let aspect = c.right.length() / c.up.length();
        assert!((aspect - w as f64 / h as f64).abs() < 1e-9, "{w}x{h}: right/up = {aspect}");
    }
}

#[test]
fn scaling_prints_each_row_once_and_notes_skipped_cells() {
    // A budget of 0 s skips every slow cell it can predict: brute force from the BVH's cost
    // per test at once, the grid from its own first cell at the second count.
    let out = strahl(&[
        "scaling",
        "--counts",
        "40,80",
        "-W",
        "24",
        "-H",
        "16",
        "--frames",
        "1",
        "--warmup",
        "0",
        "--slow-budget",
        "0",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", String::from_utf8_lossy(&out.stderr));
    let lines: Vec<&str> = stdout.lines().collect();
    let starts = |n: &str| lines.iter().filter(|l| l.split_whitespace().next() == Some(n)).count();
    assert_eq!((starts("N"), starts("40"), starts("80")), (1, 1, 1), "{stdout}");
    let row = |n: &str| lines.iter().find(|l| l.split_whitespace().next() == Some(n)).copied().unwrap_or_default();
    // Columns: N, build ms, nodes, depth, bvh+pkt, bvh-pkt, grid, none, ...
    let cell = |n: &str, i: usize| row(n).split_whitespace().nth(i).unwrap_or_default().to_string();
    assert_ne!(cell("40", 6), "-", "{stdout}");
    assert_eq!((cell("40", 7), cell("80", 6), cell("80", 7)), ("-".into(), "-".into(), "-".into()), "{stdout}");
    assert!(stdout.contains("note: brute force at N = 40 skipped: predicted"), "{stdout}");
    assert!(stdout.contains("note: grid at N = 80 skipped: predicted"), "{stdout}");
    let e = strahl(&["scaling", "--counts", "10", "--slow-budget", "-1"]);
    assert_eq!(e.status.code(), Some(2));
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
    let desc = generate(Kind::Mixed, 2000, 96, 54);
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

#[test]
fn gen_mesh2_with_normals_reads_back_smooth() {
    // `--normals` adds one normal per vertex, which the face indices index too (POV-Ray's rule
    // for a mesh2 without normal_indices): every face reads back smooth, the vertices unchanged.
    let path = scratch("cli_mesh2.pov");
    let out = strahl(&["gen", "mesh2", "501", "--normals", "-o", &path.display().to_string()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).ends_with("(501 mesh triangles)\n"));
    let read = load_scene(&path, &IncludePath { dirs: vec![] }).unwrap_or_else(|e| panic!("{e}"));
    let flat = generate(Kind::Mesh2, 501, 640, 480);
    let (strahl::desc::ShapeDesc::Mesh { mesh, .. }, strahl::desc::ShapeDesc::Mesh { mesh: flat, .. }) =
        (&read.objects[1].shape, &flat.objects[1].shape)
    else {
        panic!("no mesh2 read back");
    };
    assert_eq!(mesh.faces.len(), 501);
    assert_eq!(mesh.vertices, flat.vertices);
    assert_eq!(mesh.normals.len(), mesh.vertices.len());
    assert!(mesh.faces.iter().all(|f| f.normals == Some(f.vertices)));
    // Only mesh2 has normals to write.
    let out = strahl(&["gen", "spheres", "5", "--normals", "-o", &path.display().to_string()]);
    assert!(!out.status.success());
}
