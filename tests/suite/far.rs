//! Scenes written in place far from the origin (issue #13, section 1): in-place twins.
//!
//! `polys` holds the polynomial surfaces (unbounded quadrics, quartics with and without
//! `sturm`), whose roots are found in f64 per lane: their twins test the root finding scaled by
//! 1e-4 and 1e5 and moved up to 1e7.
//!
//! `tests/suite/extremes.rs` moves a whole `SceneDesc` with one matrix; here the scene is *written*
//! far away, as a user would write it: box corners at x = 1e6, `translate -P rotate y*30
//! translate P`, sphere centres, light positions and textures `translate P`. Each template in
//! `tests/far/` is expanded into literal numbers for an offset P and a scale S and rendered at
//! one sample per pixel, and compared with the same template at P = 0, S = 1.
//!
//! The forms a template may use (numbers are f64 literals, printed back with `{:e}`, which
//! round-trips):
//! - `@p(x, y, z)`: the point P + S·(x, y, z); `@px(x)`, `@py(y)`, `@pz(z)`: one coordinate of it;
//! - `@s(v)`: the length S·v; `@v(x, y, z)`: the vector S·(x, y, z);
//! - `@P`: the vector P.
//!
//! Aims: identical bytes where f64 holds the written scene exactly (S = 1 and integer offsets,
//! whose sums with the templates' dyadic numbers are exact), and at least 45 dB elsewhere, up to
//! 1e7. `cargo test --release --test suite far:: -- --nocapture` prints the table; failures leave the
//! actual, expected and 4× difference images in `target/far-failures/`.

use std::path::{Path, PathBuf};

use glam::DVec3;
use strahl::camera::Camera;
use strahl::headless::include_path;
use strahl::headless::metrics::psnr;
use strahl::pov::load_scene;
use strahl::render::image::Image;
use strahl::render::{render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};

const W: u32 = 160;
const H: u32 = 120;
const MIN_PSNR_DB: f64 = 45.0;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The numbers inside `@form(...)`, starting just after the `(` at `rest`; returns them and the
/// length consumed, `)` included.
fn args(rest: &str) -> (Vec<f64>, usize) {
    let close = rest.find(')').unwrap_or_else(|| panic!("unclosed `@..(` in a template near {rest:.40}"));
    let nums = rest[..close]
        .split(',')
        .map(|s| s.trim().parse::<f64>().unwrap_or_else(|e| panic!("bad number {s:?} in a template: {e}")))
        .collect();
    (nums, close + 1)
}

/// `template` with its `@` forms replaced by the numbers for offset `p` and scale `s`.
fn expand(template: &str, p: DVec3, s: f64) -> String {
    let num = |x: f64| format!("{x:e}");
    let vec = |v: DVec3| format!("<{}, {}, {}>", num(v.x), num(v.y), num(v.z));
    let mut out = String::with_capacity(template.len() * 2);
    let mut rest = template;
    while let Some(at) = rest.find('@') {
        out.push_str(&rest[..at]);
        rest = &rest[at + 1..];
        // Longest names first: `px(` before `p(`, `P` last.
        let forms: [(&str, usize); 7] = [("px(", 1), ("py(", 1), ("pz(", 1), ("p(", 3), ("s(", 1), ("v(", 3), ("P", 0)];
        let (name, arity) = forms
            .iter()
            .find(|(name, _)| rest.starts_with(name))
            .unwrap_or_else(|| panic!("unknown `@` form in a template near @{rest:.20}"));
        rest = &rest[name.len()..];
        if *arity == 0 {
            out.push_str(&vec(p));
            continue;
        }
        let (a, used) = args(rest);
        assert_eq!(a.len(), *arity, "`@{name}` takes {arity} numbers, got {a:?}");
        rest = &rest[used..];
        let text = match *name {
            "px(" => num(p.x + s * a[0]),
            "py(" => num(p.y + s * a[0]),
            "pz(" => num(p.z + s * a[0]),
            "p(" => vec(p + s * DVec3::new(a[0], a[1], a[2])),
            "s(" => num(s * a[0]),
            "v(" => vec(s * DVec3::new(a[0], a[1], a[2])),
            _ => unreachable!(),
        };
        out.push_str(&text);
    }
    out.push_str(rest);
    out
}

/// Expands `template` for (p, s), writes it to a scratch file (the loader reads files, for
/// `#include`) and renders it at one sample per pixel.
fn render_twin(name: &str, template: &str, p: DVec3, s: f64) -> Vec<u8> {
    let dir = root().join("target/far-scratch");
    std::fs::create_dir_all(&dir).expect("create target/far-scratch");
    let path = dir.join(format!("{}.pov", stem(name)));
    std::fs::write(&path, expand(template, p, s)).expect("write scratch scene");
    let desc = load_scene(&path, &include_path(&[])).unwrap_or_else(|e| panic!("{name}: {e}"));
    let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
    let camera = Camera::from_desc(&desc.camera);
    let mut image = Image::default();
    let settings = RenderSettings { width: W, height: H, aa: 1, ..RenderSettings::default() };
    let stats = render(&scene, &camera, &settings, &mut image);
    assert_eq!(stats.bad_samples, 0, "{name}: {} NaN or infinite samples", stats.bad_samples);
    image.to_rgb8(scene.srgb)
}

fn stem(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '.' { c } else { '_' }).collect()
}

/// Writes actual, expected and 4× difference images to `target/far-failures/`.
fn write_failure(name: &str, actual: &[u8], expected: &[u8]) -> PathBuf {
    let dir = root().join("target/far-failures");
    std::fs::create_dir_all(&dir).expect("create target/far-failures");
    let diff: Vec<u8> =
        actual.iter().zip(expected).map(|(a, b)| ((*a as i32 - *b as i32).unsigned_abs() * 4).min(255) as u8).collect();
    for (suffix, img) in [("actual", actual), ("expected", expected), ("diff", &diff[..])] {
        let file = dir.join(format!("{}.{suffix}.png", stem(name)));
        strahl::headless::output::write_png(&file, W, H, img).expect("write png");
    }
    dir
}

/// Whether f64 holds the scene written for (p, s) exactly: S = 1 and integer offsets, whose
/// sums with the templates' dyadic numbers need no rounding.
fn exact(p: DVec3, s: f64) -> bool {
    s == 1.0 && p.to_array().iter().all(|c| c.fract() == 0.0)
}

/// Offsets on the x axis, off the axes, and one that f64 does not hold exactly.
const ON_AXIS: [(f64, f64, f64); 3] = [(1e5, 0.0, 0.0), (1e6, 0.0, 0.0), (1e7, 0.0, 0.0)];
const OFF_AXIS: (f64, f64, f64) = (1e6, -3e5, 7e5);
const INEXACT: (f64, f64, f64) = (123456.789, 0.0, 654321.123);
/// Scales with offsets: for each, P/S is an even integer on every axis, so the seed scene's
/// floor checker (scaled by S, not moved) stays the same.
const SCALED: [((f64, f64, f64), f64); 4] =
    [((1e5, 0.0, 0.0), 1e-4), ((1e6, 0.0, 0.0), 1e-4), ((1e6, 0.0, 0.0), 1e5), ((1e7, 0.0, 0.0), 1e5)];

/// The (offset, scale) cases of a template; `floor_fixed`: its floor checker does not move with
/// P, so P/S must be an even integer (the inexact offset would show another floor).
fn cases(floor_fixed: bool) -> Vec<(DVec3, f64)> {
    let v = |(x, y, z): (f64, f64, f64)| DVec3::new(x, y, z);
    let mut c: Vec<(DVec3, f64)> = ON_AXIS.iter().map(|&p| (v(p), 1.0)).collect();
    c.push((v(OFF_AXIS), 1.0));
    if !floor_fixed {
        c.push((v(INEXACT), 1.0));
    }
    c.extend(SCALED.iter().map(|&(p, s)| (v(p), s)));
    c
}

/// The seed template with its camera's `direction`, `right` and `up` written scaled by S as
/// well (POV-Ray's defaults, <0, 0, 1>, <1.33, 0, 0> and <0, 1, 0>, times S).
fn with_scaled_camera_vectors(template: &str) -> String {
    let look_at = "    look_at @p(0, 1, 2)";
    assert!(template.contains(look_at), "the seed template's camera changed");
    template.replace(look_at, &format!("    direction @v(0, 0, 1) right @v(1.33, 0, 0) up @v(0, 1, 0)\n{look_at}"))
}

/// Twins that miss 45 dB for a known reason, with the floor they must keep and the reason.
///
/// - `seed`, scaled by S (its camera vectors at POV-Ray's defaults, not scaled):
///   `render::RayGen` casts the camera's direction, right and up multiplied by 1/unit, a factor
///   that changes with S, so a primary ray's unnormalised direction takes other f32 roundings
///   and the checker at the horizon, 1 sample per pixel, picks other checks on 9 to 29 pixels
///   (37.3 to 45.9 dB). `seed, camera × S` writes those vectors scaled by S too and reaches
///   88.8 and 92.7 dB at S = 1e-4, which shows that the rays differ, not the scene.
/// - `seed, camera × S` at S = 1e5: the floor's checker, not moved with the scene, has its
///   origin P/S = 10 and 100 checks from the scene's, so its translation becomes other f32
///   numbers than at the origin (13 and, reduced, 7, against 3;
///   `shading::pigment::pattern_from_render`) and 5 horizon pixels pick other checks (42.5 and
///   44.5 dB). Nothing is imprecise there: those numbers are as exact as 3.
fn known_limit(scene: &str, s: f64) -> Option<(f64, &'static str)> {
    match scene {
        "seed" if s != 1.0 => Some((35.0, "primary rays")),
        "seed, camera × S" if s == 1e5 => Some((40.0, "floor checker numbers")),
        _ => None,
    }
}

/// Every template, rendered at each offset and scale, against itself at the origin.
#[test]
fn scenes_written_in_place_far_away_render_like_at_the_origin() {
    // (name, template file, whether its floor checker stays put, how the file is changed)
    type Edit = fn(&str) -> String;
    let templates: [(&str, &str, bool, Option<Edit>); 7] = [
        ("seed", "seed", true, None),
        ("seed, camera × S", "seed", true, Some(with_scaled_camera_vectors)),
        ("reflection", "reflection", false, None),
        ("refraction", "refraction", false, None),
        ("wood", "wood", false, None),
        ("ellipsoid", "ellipsoid", false, None),
        ("polys", "polys", false, None),
    ];
    let _ = std::fs::remove_dir_all(root().join("target/far-failures"));
    let mut failures = Vec::new();
    println!("{:>16} {:>34} {:>7}  {:>10} {:>8}  aim", "scene", "P", "S", "PSNR dB", "differ");
    for (scene, file, floor_fixed, edit) in templates {
        let file = root().join("tests/far").join(format!("{file}.pov"));
        let template = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let template = match edit {
            Some(f) => f(&template),
            None => template,
        };
        let base = render_twin(&format!("{scene}.origin"), &template, DVec3::ZERO, 1.0);
        for (p, s) in cases(floor_fixed) {
            let name = format!("{scene} P=<{:e},{:e},{:e}> S={s:e}", p.x, p.y, p.z);
            let img = render_twin(&name, &template, p, s);
            let db = psnr(&img, &base);
            let differing = img.chunks(3).zip(base.chunks(3)).filter(|(a, b)| a != b).count();
            let identical = exact(p, s);
            let limit = known_limit(scene, s);
            let floor = limit.map_or(MIN_PSNR_DB, |(f, _)| f);
            let aim = match (identical, limit) {
                (true, _) => "identical".to_string(),
                (false, None) => format!(">= {MIN_PSNR_DB} dB"),
                (false, Some((f, why))) => format!(">= {f} dB (known limit: {why})"),
            };
            let pv = format!("<{:e}, {:e}, {:e}>", p.x, p.y, p.z);
            println!("{scene:>16} {pv:>34} {s:>7e}  {db:>10.2} {differing:>8}  {aim}");
            let failed = if identical { differing > 0 } else { db < floor };
            if failed {
                let dir = write_failure(&name, &img, &base);
                failures.push(format!("{name}: {db:.2} dB, {differing} pixels differ (aim {aim}; {})", dir.display()));
            }
        }
    }
    assert!(failures.is_empty(), "in-place twins differ from the scene at the origin:\n{}", failures.join("\n"));
}

/// The expansion itself: forms, arities and round-tripping numbers.
#[test]
fn templates_expand_to_round_tripping_numbers() {
    let p = DVec3::new(123456.789, -3e5, 0.0);
    let s = 1e-4;
    let text = expand("a @p(1, -0.5, 2) b @px(3) @s(0.2) @v(1, 2, 3) -@P c", p, s);
    let want = format!(
        "a <{:e}, {:e}, {:e}> b {:e} {:e} <{:e}, {:e}, {:e}> -<{:e}, {:e}, {:e}> c",
        p.x + s,
        p.y + s * -0.5,
        p.z + s * 2.0,
        p.x + s * 3.0,
        s * 0.2,
        s,
        s * 2.0,
        s * 3.0,
        p.x,
        p.y,
        p.z
    );
    assert_eq!(text, want);
    for word in text.split([' ', '<', '>', ',']).filter(|w| w.contains('e')) {
        let x: f64 = word.parse().expect("a number");
        assert_eq!(format!("{x:e}"), word);
    }
    assert!(Path::new(&root().join("tests/far/seed.pov")).exists());
}
