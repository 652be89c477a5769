//! Property tests (issue #6, part 4): the loader never panics, random scenes render without NaN,
//! every accelerator finds the same hits as brute force, and a printed scene loads back as the
//! same scene. Inputs under `tests/regressions/` (fuzzer finds) must load without panicking.
//!
//! Scenes are generated from a proptest-chosen seed with a small deterministic generator, so a
//! failure names the seed that reproduces it.

use std::path::PathBuf;

use glam::{DMat4, DVec2, DVec3, Vec3};
use proptest::prelude::*;
use strahl::camera::Camera;
use strahl::desc::{
    BlobComponent, BlobShape, CameraDesc, Color, ColorMapEntry, FinishDesc, InteriorDesc, LightDesc, NormalDesc,
    NormalPattern, ObjectDesc, PatternDesc, PigmentDesc, PigmentPattern, PolyForm, SceneDesc, ShapeDesc, SourceRef,
    SplineKind, TextureDesc, Transform, Turbulence, Warp,
};
use strahl::headless::include_path;
use strahl::pov::load_scene;
use strahl::ray::Ray;
use strahl::render::image::Image;
use strahl::render::intersect::Hit;
use strahl::render::stats::RenderStats;
use strahl::render::{render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};
use strahl::scene::print::to_pov;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A scratch file per test thread (the loader reads files, for `#include`).
fn scratch(tag: &str) -> PathBuf {
    let dir = root().join("target/properties-scratch");
    std::fs::create_dir_all(&dir).expect("create scratch dir");
    dir.join(format!("{tag}-{:?}.pov", std::thread::current().id()).replace(['(', ')'], ""))
}

fn load_bytes(tag: &str, bytes: &[u8]) -> Result<SceneDesc, String> {
    let path = scratch(tag);
    std::fs::write(&path, bytes).expect("write scratch scene");
    load_scene(&path, &include_path(&[])).map_err(|e| e.to_string())
}

/// SplitMix64: deterministic, seeded, good enough to spread shapes around.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn f(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn v(&mut self, lo: f64, hi: f64) -> DVec3 {
        DVec3::new(self.f(lo, hi), self.f(lo, hi), self.f(lo, hi))
    }
    fn pick(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn color(&mut self) -> Color {
        let mut c = Color::rgb(self.f(0.0, 1.0), self.f(0.0, 1.0), self.f(0.0, 1.0));
        if self.pick(4) == 0 {
            c.filter = self.f(0.0, 0.6);
            c.transmit = self.f(0.0, 0.4);
        }
        c
    }
    fn unit(&mut self) -> DVec3 {
        loop {
            let v = self.v(-1.0, 1.0);
            if v.length() > 0.1 && v.length() <= 1.0 {
                return v.normalize();
            }
        }
    }
}

fn xf(m: DMat4) -> Transform {
    Transform { matrix: m, inverse: m.inverse() }
}

/// A random affine transform: scale (sometimes non-uniform), rotation, translation.
fn random_transform(r: &mut Rng) -> Transform {
    match r.pick(4) {
        0 => Transform::default(),
        1 => xf(DMat4::from_translation(r.v(-3.0, 3.0))),
        _ => {
            let s = if r.pick(2) == 0 { DVec3::splat(r.f(0.3, 2.0)) } else { r.v(0.3, 2.0) };
            let rot = DMat4::from_rotation_z(r.f(-3.2, 3.2))
                * DMat4::from_rotation_y(r.f(-3.2, 3.2))
                * DMat4::from_rotation_x(r.f(-3.2, 3.2));
            xf(DMat4::from_translation(r.v(-3.0, 3.0)) * rot * DMat4::from_scale(s))
        }
    }
}

fn random_texture(r: &mut Rng, object: &Transform) -> TextureDesc {
    let pattern = match r.pick(3) {
        0 => PigmentPattern::Solid(r.color()),
        1 => PigmentPattern::Checker(r.color(), r.color()),
        _ => {
            let mut map: Vec<ColorMapEntry> =
                (0..2 + r.pick(3)).map(|_| ColorMapEntry { value: r.f(0.0, 1.0), color: r.color() }).collect();
            map.sort_by(|a, b| a.value.total_cmp(&b.value));
            PigmentPattern::Wood(map)
        }
    };
    let turbulence = (r.pick(3) == 0).then(|| Turbulence {
        amount: r.v(0.0, 0.5),
        octaves: 1 + r.pick(6) as u32,
        omega: r.f(0.3, 0.7),
        lambda: r.f(1.5, 2.5),
    });
    let pigment = PigmentDesc { pattern, turbulence, transform: random_transform(r).then(object) };
    let normal = (r.pick(4) == 0).then(|| NormalDesc {
        pattern: NormalPattern::Bumps(r.f(0.0, 1.0)),
        turbulence: None,
        transform: xf(DMat4::from_scale(DVec3::splat(r.f(0.1, 1.0)))).then(object),
        slope_map: Vec::new(),
        accuracy: 0.02,
    });
    let finish = FinishDesc {
        ambient: DVec3::splat(r.f(0.0, 0.3)),
        diffuse: r.f(0.0, 1.0),
        brilliance: r.f(0.5, 3.0),
        phong: if r.pick(2) == 0 { 0.0 } else { r.f(0.0, 1.0) },
        phong_size: r.f(1.0, 200.0),
        specular: if r.pick(2) == 0 { 0.0 } else { r.f(0.0, 1.0) },
        roughness: r.f(0.001, 0.2),
        reflection: if r.pick(3) == 0 { DVec3::splat(r.f(0.0, 0.8)) } else { DVec3::ZERO },
        metallic: if r.pick(3) == 0 { r.f(0.0, 1.0) } else { 0.0 },
        ..FinishDesc::default()
    };
    TextureDesc { pigment, normal, finish, uv_mapping: false, pattern: None }
}

fn random_shape(r: &mut Rng) -> ShapeDesc {
    match r.pick(16) {
        14 => random_mesh(r),
        0 => ShapeDesc::Sphere { center: r.v(-4.0, 4.0), radius: r.f(0.05, 2.0) },
        1 => {
            let (a, b) = (r.v(-4.0, 4.0), r.v(-4.0, 4.0));
            // Keep every side at least 0.01 long: a flat box is legal but not interesting here.
            ShapeDesc::Box { corner1: a, corner2: a + (b - a).abs().max(DVec3::splat(0.01)) }
        }
        2 => loop {
            let (a, b, c) = (r.v(-4.0, 4.0), r.v(-4.0, 4.0), r.v(-4.0, 4.0));
            if (b - a).cross(c - a).length() > 1e-2 {
                break ShapeDesc::Triangle { a, b, c };
            }
        },
        3 => ShapeDesc::Plane { normal: r.unit() * r.f(0.5, 2.0), distance: r.f(-5.0, 5.0) },
        4 => {
            let base = r.v(-4.0, 4.0);
            let cap = base + r.unit() * r.f(0.3, 3.0);
            let cylinder = r.pick(2) == 0;
            let base_radius = r.f(0.05, 1.5);
            let cap_radius = if cylinder { base_radius } else { r.f(0.0, 1.5) };
            ShapeDesc::Cone { base, base_radius, cap, cap_radius, open: r.pick(3) == 0, cylinder }
        }
        5 => {
            let radius = r.f(0.1, 2.0);
            let hole = if r.pick(2) == 0 { 0.0 } else { radius * r.f(0.0, 0.9) };
            ShapeDesc::Disc { center: r.v(-4.0, 4.0), normal: r.unit() * r.f(0.5, 2.0), radius, hole }
        }
        6 => {
            let major = r.f(0.2, 2.0);
            ShapeDesc::Torus { major, minor: major * r.f(0.05, 0.9) }
        }
        // Polynomial surfaces, mostly unbounded (outside the accelerator): a random quadric,
        // or a random quartic (x⁴ + y⁴ + z⁴ plus random lower terms), with or without sturm.
        8 => {
            let mut coefficients: Vec<f64> = (0..10).map(|_| r.f(-1.0, 1.0)).collect();
            coefficients[9] = r.f(-2.0, 0.5);
            ShapeDesc::Poly { order: 2, coefficients, sturm: false, written: PolyForm::Quadric }
        }
        9 => {
            let terms = strahl::geometry::poly::term_exponents(4);
            let coefficients = terms
                .iter()
                .map(|e| match e {
                    [4, 0, 0] | [0, 4, 0] | [0, 0, 4] => 1.0,
                    [0, 0, 0] => -r.f(0.5, 3.0),
                    e if e.iter().sum::<u8>() < 4 => r.f(-0.5, 0.5),
                    _ => 0.0,
                })
                .collect();
            ShapeDesc::Poly { order: 4, coefficients, sturm: r.pick(2) == 0, written: PolyForm::Quartic }
        }
        10 => ShapeDesc::Superellipsoid { e: r.f(0.1, 2.5), n: r.f(0.1, 2.5) },
        11 => random_prism(r),
        12 => random_sor(r),
        13 => random_blob(r),
        _ => {
            let (c, n) = (r.v(-3.0, 3.0), r.unit());
            let u = n.any_orthonormal_vector();
            let w = n.cross(u);
            let k = 3 + r.pick(4);
            let points = (0..k)
                .map(|i| {
                    let a = std::f64::consts::TAU * i as f64 / k as f64;
                    c + (u * a.cos() + w * a.sin()) * r.f(0.5, 1.5)
                })
                .collect();
            ShapeDesc::Polygon { points }
        }
    }
}

/// A blob of 1 to 5 sphere and cylinder components near a centre, some negative, some under a
/// scale and rotation of their own.
fn random_blob(r: &mut Rng) -> ShapeDesc {
    let c = r.v(-3.0, 3.0);
    let components = (0..1 + r.pick(5))
        .map(|i| {
            let at = c + r.v(-0.8, 0.8);
            let shape = if r.pick(3) == 0 {
                BlobShape::Cylinder { base: at, cap: at + r.v(-1.0, 1.0) }
            } else {
                BlobShape::Sphere { center: at }
            };
            let transform = if r.pick(3) == 0 {
                let m = DMat4::from_translation(at)
                    * DMat4::from_rotation_y(r.f(0.0, 3.0))
                    * DMat4::from_scale(DVec3::new(r.f(0.5, 1.5), r.f(0.5, 1.5), r.f(0.5, 1.5)))
                    * DMat4::from_translation(-at);
                Transform { matrix: m, inverse: m.inverse() }
            } else {
                Transform::default()
            };
            // The first is positive, so the blob is never empty.
            let strength = if i > 0 && r.pick(4) == 0 { -r.f(0.5, 2.0) } else { r.f(0.5, 2.0) };
            BlobComponent { shape, radius: r.f(0.4, 1.5), strength, transform }
        })
        .collect();
    ShapeDesc::Blob { components, threshold: r.f(0.2, 0.8) }
}

/// A mesh: a closed star-shaped octahedron (solid through a random `inside_vector`, its
/// faces sometimes smooth), or an open soup of 2 to 12 triangles (not solid).
fn random_mesh(r: &mut Rng) -> ShapeDesc {
    use strahl::desc::{MeshDesc, MeshFace};
    let c = r.v(-3.0, 3.0);
    let mut mesh = MeshDesc::default();
    let inside_vector = if r.pick(3) > 0 {
        let axes = [DVec3::X, DVec3::Y, DVec3::Z];
        mesh.vertices = axes.iter().flat_map(|&a| [c + a * r.f(0.3, 2.0), c - a * r.f(0.3, 2.0)]).collect();
        let smooth = r.pick(2) == 0;
        if smooth {
            mesh.normals = mesh.vertices.iter().map(|&v| v - c + r.v(-0.3, 0.3)).collect();
        }
        for (x, y, z) in [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)] {
            let v = [x, y, z];
            mesh.faces.push(MeshFace { vertices: v, normals: smooth.then_some(v) });
        }
        Some(r.unit())
    } else {
        for _ in 0..2 + r.pick(11) {
            let k = mesh.vertices.len() as u32;
            mesh.vertices.extend([c + r.v(-1.5, 1.5), c + r.v(-1.5, 1.5), c + r.v(-1.5, 1.5)]);
            mesh.faces.push(MeshFace { vertices: [k, k + 1, k + 2], normals: None });
        }
        None
    };
    ShapeDesc::Mesh { mesh: std::sync::Arc::new(mesh), inside_vector }
}

/// A surface of revolution through 4 to 7 points at rising heights, sometimes open.
fn random_sor(r: &mut Rng) -> ShapeDesc {
    let mut y = r.f(-2.0, 1.0);
    let points = (0..4 + r.pick(4))
        .map(|_| {
            y += r.f(0.1, 1.0);
            DVec2::new(r.f(0.05, 1.5), y)
        })
        .collect();
    ShapeDesc::Sor { points, open: r.pick(4) == 0 }
}

/// A star-shaped outline of 3 to 6 points around a centre, as each spline type closes it,
/// swept linearly or conically, sometimes open.
fn random_prism(r: &mut Rng) -> ShapeDesc {
    let c = DVec2::new(r.f(-3.0, 3.0), r.f(-3.0, 3.0));
    let k = 3 + r.pick(4) as usize;
    let ring: Vec<DVec2> = (0..k)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / k as f64;
            c + DVec2::new(a.cos(), a.sin()) * r.f(0.4, 1.5)
        })
        .collect();
    let spline = [SplineKind::Linear, SplineKind::Quadratic, SplineKind::Cubic, SplineKind::Bezier][r.pick(4) as usize];
    let points: Vec<DVec2> = match spline {
        SplineKind::Linear => ring.iter().chain(&ring[..1]).copied().collect(),
        SplineKind::Quadratic => ring[k - 1..].iter().chain(&ring).chain(&ring[..1]).copied().collect(),
        SplineKind::Cubic => ring[k - 1..].iter().chain(&ring).chain(&ring[..2]).copied().collect(),
        SplineKind::Bezier => (0..k)
            .flat_map(|i| {
                let (a, b) = (ring[i], ring[(i + 1) % k]);
                [a, a + (b - a) / 3.0 + (c - a) * 0.2, b - (b - a) / 3.0, b]
            })
            .collect(),
    };
    let conic = r.pick(3) == 0;
    let h1 = if conic { r.f(0.3, 1.0) } else { r.f(-3.0, 3.0) };
    let h2 = h1 + r.f(0.1, 2.0);
    ShapeDesc::Prism { spline, conic, h1, h2, points, open: r.pick(4) == 0 }
}

fn random_scene(seed: u64, objects: usize) -> SceneDesc {
    let r = &mut Rng(seed);
    let location = r.v(-10.0, 10.0);
    let forward = (r.v(-2.0, 2.0) - location).normalize_or(DVec3::Z);
    let right = DVec3::Y.cross(forward).normalize_or(DVec3::X);
    let up = forward.cross(right);
    let camera = CameraDesc {
        location,
        direction: forward * r.f(0.7, 2.0),
        right: right * 4.0 / 3.0,
        up,
        sky: DVec3::Y,
        look_at: None,
        angle: None,
        ..CameraDesc::default()
    };
    let lights = (0..1 + r.pick(3))
        .map(|_| LightDesc {
            position: r.v(-10.0, 10.0),
            color: r.v(0.2, 1.0),
            shadowless: r.pick(4) == 0,
            ..LightDesc::default()
        })
        .collect();
    let objects = (0..objects)
        .map(|i| {
            let shape = random_shape(r);
            let transform = random_transform(r);
            let texture = random_texture(r, &transform);
            let ior = if r.pick(3) == 0 { r.f(0.8, 2.4) } else { 1.0 };
            let source = SourceRef { file: "generated".into(), line: i as u32 + 1, col: 1 };
            ObjectDesc {
                shape,
                transform: transform.into(),
                texture: texture.into(),
                interior_texture: None,
                interior: InteriorDesc { ior, fade: None },
                no_shadow: r.pick(5) == 0,
                inverse: false,
                hollow: false,
                light_group: None,
                bounded_by: None,
                source,
            }
        })
        .collect();
    let mut desc = SceneDesc { camera, lights, objects, ..SceneDesc::default() };
    desc.background = r.color();
    desc.global.assumed_gamma = (r.pick(2) == 0).then_some(1.0);
    desc.global.max_trace_level = 1 + r.pick(8) as u32;
    desc.global.ambient_light = r.v(0.5, 1.0);
    desc
}

/// Words and punctuation of the language, glued at random: reaches deeper than raw bytes.
fn token_soup() -> impl Strategy<Value = String> {
    let words = prop::sample::select(vec![
        "sphere",
        "box",
        "plane",
        "triangle",
        "polygon",
        "camera",
        "light_source",
        "pigment",
        "finish",
        "normal",
        "texture",
        "interior",
        "ior",
        "checker",
        "wood",
        "color_map",
        "color",
        "rgb",
        "rgbft",
        "bumps",
        "turbulence",
        "octaves",
        "rotate",
        "scale",
        "translate",
        "location",
        "look_at",
        "angle",
        "direction",
        "right",
        "up",
        "sky",
        "global_settings",
        "assumed_gamma",
        "max_trace_level",
        "background",
        "#declare",
        "#local",
        "#version",
        "#ifdef",
        "#ifndef",
        "#end",
        "#include \"colors.inc\"",
        "Foo",
        "x",
        "y",
        "z",
        "{",
        "}",
        "<",
        ">",
        "[",
        "]",
        "(",
        ")",
        ",",
        ";",
        "=",
        "+",
        "-",
        "*",
        "/",
        "0",
        "1",
        "-1",
        "0.5",
        "1e300",
        "1e-300",
        "3",
        "\"",
        ".",
        "sin(",
        "vlength(",
        "pi",
        "White",
        "//",
        "/*",
        "*/",
    ]);
    prop::collection::vec(words, 0..60).prop_map(|w| w.join(" "))
}

/// Relative/absolute closeness for values printed and parsed back.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0)
}
fn close3(a: DVec3, b: DVec3) -> bool {
    close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z)
}
fn close_color(a: &Color, b: &Color) -> bool {
    close3(a.rgb, b.rgb) && close(a.filter, b.filter) && close(a.transmit, b.transmit)
}
fn close_xf(a: &Transform, b: &Transform) -> bool {
    a.matrix.to_cols_array().iter().zip(b.matrix.to_cols_array()).all(|(p, q)| close(*p, q))
}

/// Patterns whose numbers print exactly; the spaces warps work in are transforms, which print
/// rounded.
fn same_pattern(a: &PatternDesc, b: &PatternDesc) -> bool {
    let strip = |p: &PatternDesc| PatternDesc { warps: Vec::new(), ..p.clone() };
    strip(a) == strip(b)
        && a.warps.len() == b.warps.len()
        && a.warps.iter().zip(&b.warps).all(|(x, y)| {
            let warp_ok = match (x.warp, y.warp) {
                // Orientations are normalised again when read back.
                (
                    Warp::Mapping { map: m1, orientation: o1, dist_exp: d1 },
                    Warp::Mapping { map: m2, orientation: o2, dist_exp: d2 },
                ) => m1 == m2 && close3(o1, o2) && d1 == d2,
                (p, q) => p == q,
            };
            warp_ok && x.inherited == y.inherited && close_xf(&x.space, &y.space)
        })
}

/// Field-by-field equality up to float rounding; `Err` names the first field that differs.
fn same_scene(a: &SceneDesc, b: &SceneDesc) -> Result<(), String> {
    check(close(a.version, b.version), "version".into())?;
    check(a.global.assumed_gamma == b.global.assumed_gamma, "assumed_gamma".into())?;
    check(a.global.max_trace_level == b.global.max_trace_level, "max_trace_level".into())?;
    check(close3(a.global.ambient_light, b.global.ambient_light), "ambient_light".into())?;
    check(close_color(&a.background, &b.background), "background".into())?;
    let (ca, cb) = (&a.camera, &b.camera);
    for (x, y, name) in [
        (ca.location, cb.location, "location"),
        (ca.direction, cb.direction, "direction"),
        (ca.right, cb.right, "right"),
        (ca.up, cb.up, "up"),
        (ca.sky, cb.sky, "sky"),
    ] {
        check(close3(x, y), format!("camera {name}: {x} vs {y}"))?;
    }
    match (&a.camera_normal, &b.camera_normal) {
        (None, None) => {}
        (Some(na), Some(nb)) => check(
            close_xf(&na.transform, &nb.transform) && format!("{:?}", na.pattern) == format!("{:?}", nb.pattern),
            format!("camera normal: {na:?} vs {nb:?}"),
        )?,
        _ => return Err("camera normal given in one scene only".into()),
    }
    check(a.lights.len() == b.lights.len(), "light count".into())?;
    for (i, (la, lb)) in a.lights.iter().zip(&b.lights).enumerate() {
        check(close3(la.position, lb.position) && close3(la.color, lb.color), format!("light {i}"))?;
    }
    check(a.objects.len() == b.objects.len(), "object count".into())?;
    for (i, (oa, ob)) in a.objects.iter().zip(&b.objects).enumerate() {
        same_object(&format!("object {i}"), oa, ob)?;
    }
    Ok(())
}

/// One object (and a CSG node's children) against its printed and reloaded self.
fn same_object(label: &str, oa: &ObjectDesc, ob: &ObjectDesc) -> Result<(), String> {
    let shape_ok = match (&oa.shape, &ob.shape) {
        (ShapeDesc::Sphere { center: c1, radius: r1 }, ShapeDesc::Sphere { center: c2, radius: r2 }) => {
            close3(*c1, *c2) && close(*r1, *r2)
        }
        (ShapeDesc::Plane { normal: n1, distance: d1 }, ShapeDesc::Plane { normal: n2, distance: d2 }) => {
            close3(*n1, *n2) && close(*d1, *d2)
        }
        (ShapeDesc::Box { corner1: a1, corner2: b1 }, ShapeDesc::Box { corner1: a2, corner2: b2 }) => {
            close3(*a1, *a2) && close3(*b1, *b2)
        }
        (ShapeDesc::Triangle { a: a1, b: b1, c: c1 }, ShapeDesc::Triangle { a: a2, b: b2, c: c2 }) => {
            close3(*a1, *a2) && close3(*b1, *b2) && close3(*c1, *c2)
        }
        (ShapeDesc::Polygon { points: p1 }, ShapeDesc::Polygon { points: p2 }) => {
            p1.len() == p2.len() && p1.iter().zip(p2).all(|(p, q)| close3(*p, *q))
        }
        (
            ShapeDesc::Cone { base: b1, base_radius: r1, cap: c1, cap_radius: s1, open: o1, cylinder: y1 },
            ShapeDesc::Cone { base: b2, base_radius: r2, cap: c2, cap_radius: s2, open: o2, cylinder: y2 },
        ) => close3(*b1, *b2) && close(*r1, *r2) && close3(*c1, *c2) && close(*s1, *s2) && o1 == o2 && y1 == y2,
        (
            ShapeDesc::Disc { center: c1, normal: n1, radius: r1, hole: h1 },
            ShapeDesc::Disc { center: c2, normal: n2, radius: r2, hole: h2 },
        ) => close3(*c1, *c2) && close3(*n1, *n2) && close(*r1, *r2) && close(*h1, *h2),
        (ShapeDesc::Torus { major: a1, minor: b1 }, ShapeDesc::Torus { major: a2, minor: b2 }) => {
            close(*a1, *a2) && close(*b1, *b2)
        }
        (
            ShapeDesc::Poly { order: o1, coefficients: c1, sturm: s1, written: w1 },
            ShapeDesc::Poly { order: o2, coefficients: c2, sturm: s2, written: w2 },
        ) => o1 == o2 && s1 == s2 && w1 == w2 && c1.len() == c2.len() && c1.iter().zip(c2).all(|(a, b)| close(*a, *b)),
        (ShapeDesc::Superellipsoid { e: e1, n: n1 }, ShapeDesc::Superellipsoid { e: e2, n: n2 }) => {
            close(*e1, *e2) && close(*n1, *n2)
        }
        (
            ShapeDesc::Prism { spline: s1, conic: c1, h1: a1, h2: b1, points: p1, open: o1 },
            ShapeDesc::Prism { spline: s2, conic: c2, h1: a2, h2: b2, points: p2, open: o2 },
        ) => {
            s1 == s2
                && c1 == c2
                && o1 == o2
                && close(*a1, *a2)
                && close(*b1, *b2)
                && p1.len() == p2.len()
                && p1.iter().zip(p2).all(|(p, q)| close(p.x, q.x) && close(p.y, q.y))
        }
        (ShapeDesc::Lathe { spline: s1, points: p1 }, ShapeDesc::Lathe { spline: s2, points: p2 }) => {
            s1 == s2 && p1.len() == p2.len() && p1.iter().zip(p2).all(|(p, q)| close(p.x, q.x) && close(p.y, q.y))
        }
        (ShapeDesc::Blob { components: c1, threshold: t1 }, ShapeDesc::Blob { components: c2, threshold: t2 }) => {
            close(*t1, *t2)
                && c1.len() == c2.len()
                && c1.iter().zip(c2).all(|(a, b)| {
                    let shapes = match (a.shape, b.shape) {
                        (BlobShape::Sphere { center: p }, BlobShape::Sphere { center: q }) => close3(p, q),
                        (BlobShape::Cylinder { base: p, cap: q }, BlobShape::Cylinder { base: u, cap: v }) => {
                            close3(p, u) && close3(q, v)
                        }
                        _ => false,
                    };
                    shapes
                        && close(a.radius, b.radius)
                        && close(a.strength, b.strength)
                        && a.transform.matrix.abs_diff_eq(b.transform.matrix, 1e-6)
                })
        }
        (
            ShapeDesc::Julia { param: p1, function: f1, max_iteration: m1, precision: q1, slice: s1 },
            ShapeDesc::Julia { param: p2, function: f2, max_iteration: m2, precision: q2, slice: s2 },
        ) => {
            let close4 = |a: glam::DVec4, b: glam::DVec4| (0..4).all(|i| close(a[i], b[i]));
            f1 == f2 && m1 == m2 && close(*q1, *q2) && close4(**p1, **p2) && close4(s1.0, s2.0) && close(s1.1, s2.1)
        }
        (ShapeDesc::Sor { points: p1, open: o1 }, ShapeDesc::Sor { points: p2, open: o2 }) => {
            o1 == o2 && p1.len() == p2.len() && p1.iter().zip(p2).all(|(p, q)| close(p.x, q.x) && close(p.y, q.y))
        }
        (
            ShapeDesc::Text { font: f1, string: s1, thickness: t1, offset: o1, .. },
            ShapeDesc::Text { font: f2, string: s2, thickness: t2, offset: o2, .. },
        ) => f1 == f2 && s1 == s2 && close(*t1, *t2) && close3(**o1, **o2),
        // Vertices are written in shortest round-trip form and stay in object space: exact.
        (ShapeDesc::Mesh { mesh: m1, inside_vector: i1 }, ShapeDesc::Mesh { mesh: m2, inside_vector: i2 }) => {
            m1 == m2 && i1 == i2
        }
        (a @ ShapeDesc::HeightField { .. }, b @ ShapeDesc::HeightField { .. }) => a == b,
        (ShapeDesc::Csg { op: o1, children: c1 }, ShapeDesc::Csg { op: o2, children: c2 }) => {
            check(
                o1 == o2 && c1.len() == c2.len(),
                format!("{label}: {o1:?} of {} vs {o2:?} of {}", c1.len(), c2.len()),
            )?;
            for (k, (x, y)) in c1.iter().zip(c2).enumerate() {
                same_object(&format!("{label}, child {k}"), x, y)?;
            }
            true
        }
        _ => false,
    };
    check(oa.inverse == ob.inverse, format!("{label}: inverse"))?;
    check(shape_ok, format!("{label}: shape {:?} vs {:?}", oa.shape, ob.shape))?;
    check(close_xf(&oa.transform.transform(), &ob.transform.transform()), format!("{label}: transform"))?;
    check(close(oa.interior.ior, ob.interior.ior), format!("{label}: ior"))?;
    let (ta, tb) = (&oa.texture, &ob.texture);
    let pattern_ok = match (&ta.pigment.pattern, &tb.pigment.pattern) {
        (PigmentPattern::Solid(x), PigmentPattern::Solid(y)) => close_color(x, y),
        (PigmentPattern::Checker(x1, x2), PigmentPattern::Checker(y1, y2)) => {
            close_color(x1, y1) && close_color(x2, y2)
        }
        (PigmentPattern::Wood(m1), PigmentPattern::Wood(m2)) => {
            m1.len() == m2.len()
                && m1.iter().zip(m2).all(|(p, q)| close(p.value, q.value) && close_color(&p.color, &q.color))
        }
        // A list's entries carry the transforms composed over them, which print rounded.
        (PigmentPattern::List(p, l), PigmentPattern::List(q, m)) => {
            same_pattern(p, q)
                && l.len() == m.len()
                && l.iter().zip(m).all(|(x, y)| {
                    x.pattern == y.pattern && x.turbulence == y.turbulence && close_xf(&x.transform, &y.transform)
                })
        }
        (PigmentPattern::Mapped(p, m1), PigmentPattern::Mapped(q, m2)) => same_pattern(p, q) && m1 == m2,
        // Entries warped by the map's pattern carry transforms, which print rounded.
        (PigmentPattern::PigmentMap(p, e1), PigmentPattern::PigmentMap(q, e2)) => {
            same_pattern(p, q)
                && e1.len() == e2.len()
                && e1.iter().zip(e2).all(|((v1, x), (v2, y))| {
                    v1 == v2
                        && x.turbulence == y.turbulence
                        && close_xf(&x.transform, &y.transform)
                        && match (&x.pattern, &y.pattern) {
                            (PigmentPattern::Mapped(p, m1), PigmentPattern::Mapped(q, m2)) => {
                                same_pattern(p, q) && m1 == m2
                            }
                            (a, b) => a == b,
                        }
                })
        }
        // The pattern kinds, maps and lists print their numbers exactly (shortest round trip).
        (x, y) => x == y,
    };
    check(pattern_ok, format!("{label}: pigment pattern {:?} vs {:?}", ta.pigment.pattern, tb.pigment.pattern))?;
    let turb_ok = |x: &Option<Turbulence>, y: &Option<Turbulence>| match (x, y) {
        (None, None) => true,
        (Some(p), Some(q)) => {
            close3(p.amount, q.amount) && p.octaves == q.octaves && close(p.omega, q.omega) && close(p.lambda, q.lambda)
        }
        _ => false,
    };
    check(turb_ok(&ta.pigment.turbulence, &tb.pigment.turbulence), format!("{label}: pigment turbulence"))?;
    check(close_xf(&ta.pigment.transform, &tb.pigment.transform), format!("{label}: pigment transform"))?;
    let normal_ok = match (&ta.normal, &tb.normal) {
        (None, None) => true,
        (Some(p), Some(q)) => {
            let same_pattern = match (&p.pattern, &q.pattern) {
                (NormalPattern::Bumps(x), NormalPattern::Bumps(y)) => close(*x, *y),
                (x, y) => x == y,
            };
            same_pattern
                && turb_ok(&p.turbulence, &q.turbulence)
                && close_xf(&p.transform, &q.transform)
                && p.slope_map == q.slope_map
                && close(p.accuracy, q.accuracy)
        }
        _ => false,
    };
    check(normal_ok, format!("{label}: normal"))?;
    let (fa, fb) = (&ta.finish, &tb.finish);
    let finish_ok = close3(fa.ambient, fb.ambient)
        && close(fa.diffuse, fb.diffuse)
        && close(fa.brilliance, fb.brilliance)
        && close(fa.phong, fb.phong)
        && close(fa.phong_size, fb.phong_size)
        && close(fa.specular, fb.specular)
        && close(fa.roughness, fb.roughness)
        && close3(fa.reflection, fb.reflection)
        && close(fa.metallic, fb.metallic);
    check(finish_ok, format!("{label}: finish"))?;
    Ok(())
}

fn check(ok: bool, what: String) -> Result<(), String> {
    if ok {
        Ok(())
    } else {
        Err(what)
    }
}

fn same_hit(a: Option<Hit>, b: Option<Hit>) -> Result<(), String> {
    match (a, b) {
        (None, None) => Ok(()),
        (Some(p), Some(q)) if p.shape == q.shape && (p.t - q.t).abs() <= 1e-5 * p.t.abs().max(1.0) => Ok(()),
        _ => Err(format!("{a:?} vs {b:?}")),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn loading_arbitrary_bytes_never_panics(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        let _ = load_bytes("bytes", &bytes);
    }

    #[test]
    fn loading_token_soup_never_panics(src in token_soup()) {
        if let Ok(desc) = load_bytes("soup", src.as_bytes()) {
            let _ = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_scenes_render_without_nan(seed in any::<u64>(), n in 1usize..24) {
        let desc = random_scene(seed, n);
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let settings = RenderSettings { width: 48, height: 36, ..RenderSettings::default() };
        let stats = render(&scene, &Camera::from_desc(&desc.camera), &settings, &mut Image::default());
        prop_assert_eq!(stats.bad_samples, 0, "seed {}", seed);
    }

    #[test]
    fn accelerators_agree_with_brute_force(seed in any::<u64>(), n in 1usize..80) {
        let desc = random_scene(seed, n);
        let build = |kind| Scene::build(&desc, desc.camera.location, kind);
        let (bvh, grid, none) = (build(AccelKind::Bvh), build(AccelKind::Grid), build(AccelKind::None));
        let r = &mut Rng(seed ^ 0x5eed);
        let mut stats = RenderStats::default();
        for _ in 0..200 {
            let origin = r.v(-8.0, 8.0).as_vec3();
            // A quarter of the rays have axis-aligned directions, with zero components.
            let dir = if r.pick(4) == 0 {
                [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z][r.pick(6) as usize]
            } else {
                r.unit().as_vec3()
            };
            let ray = Ray::new(origin, dir);
            let t_max = if r.pick(3) == 0 { r.f(0.1, 10.0) as f32 } else { f32::INFINITY };
            let truth = none.intersect(&ray, t_max, &mut stats);
            // `no_shadow` objects are hit by rays but not by occlusion queries, so occlusion is
            // compared with brute-force occlusion, not with the nearest hit.
            let truth_blocked = none.occluded(&ray, t_max, &mut stats);
            for (name, scene) in [("bvh", &bvh), ("grid", &grid)] {
                let hit = scene.intersect(&ray, t_max, &mut stats);
                prop_assert!(same_hit(truth, hit).is_ok(), "seed {} {}: {:?}", seed, name, same_hit(truth, hit));
                prop_assert_eq!(
                    scene.occluded(&ray, t_max, &mut stats),
                    truth_blocked,
                    "seed {} {} occluded", seed, name
                );
            }
        }
    }

    #[test]
    fn printed_scene_loads_back_the_same(seed in any::<u64>(), n in 0usize..12) {
        let desc = random_scene(seed, n);
        let src = to_pov(&desc);
        let back = load_bytes("print", src.as_bytes()).map_err(|e| TestCaseError::fail(format!("{e}\n{src}")))?;
        prop_assert!(same_scene(&desc, &back).is_ok(), "seed {}: {:?}\n{}", seed, same_scene(&desc, &back), src);
    }
}

/// The shipped scenes print and load back as themselves too (declared textures, includes,
/// `look_at` cameras: all folded into plain values).
#[test]
fn shipped_scenes_print_and_load_back() {
    let mut scenes = vec![root().join("scenes/seed.pov"), root().join("tests/extremes/scene.pov")];
    for e in std::fs::read_dir(root().join("tests/reference/scenes")).expect("reference scenes") {
        let path = e.expect("dir entry").path();
        // Scenes only, not the images they read (hf.pgm); and not those with functions, which
        // are kept compiled and printed as a comment (no source to write back).
        let compiled = [
            "isosurfaces.pov",
            "parametrics.pov",
            "patterns_function.pov",
            "functions_pigment.pov",
            // Mesh cameras, which the printer does not write yet.
            "cameras_mesh.pov",
            "cameras_mesh_rows.pov",
            // The object pattern's solid is equal only to itself: compared by its render in
            // `printed_textures_render_the_same_bytes`.
            "texture_patterns.pov",
        ]
        .iter()
        .any(|n| path.ends_with(n));
        if path.extension().is_some_and(|x| x == "pov") && !compiled {
            scenes.push(path);
        }
    }
    for path in scenes {
        let desc = load_scene(&path, &include_path(&[])).unwrap_or_else(|e| panic!("{e}"));
        let src = to_pov(&desc);
        let back = load_bytes("shipped", src.as_bytes()).unwrap_or_else(|e| panic!("{}: {e}\n{src}", path.display()));
        if let Err(e) = same_scene(&desc, &back) {
            panic!("{}: {e}\n{src}", path.display());
        }
    }
}

/// Layered textures (composited or shaded layer by layer, with their own normals and
/// finishes), patterns of whole textures (`texture_map`, lists of textures, `tiles`,
/// `material_map`, layered entries declared by name), the `object` pattern and `uv_mapping`
/// (boxes, spheres, tori, meshes' `uv_vectors`) print and load back as the same picture: the printed scene renders the original's
/// bytes.
#[test]
fn printed_textures_render_the_same_bytes() {
    let rgb = |d: &SceneDesc| {
        let scene = Scene::build(d, d.camera.location, AccelKind::Bvh);
        let settings = RenderSettings { width: 160, height: 120, ..RenderSettings::default() };
        let mut image = Image::default();
        render(&scene, &Camera::from_desc(&d.camera), &settings, &mut image);
        image.to_rgb8(scene.srgb)
    };
    for name in
        ["layered", "layers_finish", "layers_normal", "tiles", "materials", "texture_patterns", "uv_box", "uv_mapping"]
    {
        let path = root().join("tests/reference/scenes").join(format!("{name}.pov"));
        let desc = load_scene(&path, &include_path(&[])).unwrap_or_else(|e| panic!("{e}"));
        let src = to_pov(&desc);
        let mut back = load_bytes(name, src.as_bytes()).unwrap_or_else(|e| panic!("{name}: {e}\n{src}"));
        // The camera prints without `look_at`, whose distance is the render's unit of length
        // (`RenderFrame`): the same view in other f32 numbers. Textures are what is compared.
        back.camera = desc.camera;
        let (a, b) = (rgb(&desc), rgb(&back));
        let differ = a.chunks(3).zip(b.chunks(3)).filter(|(x, y)| x != y).count();
        assert_eq!(differ, 0, "{name}: {differ} of {} pixels differ\n{src}", a.len() / 3);
    }
}

/// Every input the fuzzer once crashed on loads (or fails to) without panicking.
#[test]
fn fuzzer_regressions_do_not_panic() {
    let dir = root().join("tests/regressions");
    let mut count = 0;
    for e in std::fs::read_dir(&dir).expect("tests/regressions") {
        let path = e.expect("dir entry").path();
        if path.extension().is_some_and(|x| x == "md") {
            continue;
        }
        let loaded = load_scene(&path, &include_path(&[]));
        if let Ok(desc) = loaded {
            let _ = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        }
        count += 1;
    }
    println!("{count} regression inputs loaded without panicking");
}

/// A random solid for CSG: any shape `random_shape` makes (flat and unbounded ones included:
/// they are legal children), sometimes `inverse`.
fn csg_leaf(r: &mut Rng) -> ObjectDesc {
    ObjectDesc {
        shape: random_shape(r),
        transform: random_transform(r).into(),
        texture: TextureDesc::default().into(),
        interior_texture: None,
        interior: InteriorDesc::default(),
        no_shadow: false,
        inverse: r.pick(6) == 0,
        hollow: false,
        light_group: None,
        bounded_by: None,
        source: SourceRef::default(),
    }
}

/// A random CSG tree of depth up to `depth` over random solids.
fn csg_tree(r: &mut Rng, depth: u32) -> ObjectDesc {
    use strahl::desc::CsgOp;
    if depth == 0 || r.pick(3) == 0 {
        return csg_leaf(r);
    }
    let op = [CsgOp::Intersection, CsgOp::Difference, CsgOp::Merge, CsgOp::Union, CsgOp::Clip][r.pick(5) as usize];
    let children = (0..2 + r.pick(2)).map(|_| csg_tree(r, depth - 1)).collect();
    ObjectDesc { shape: ShapeDesc::Csg { op, children }, inverse: r.pick(8) == 0, ..csg_leaf(r) }
}

fn csg_scene(object: ObjectDesc) -> Scene {
    let desc = SceneDesc { objects: vec![object], ..SceneDesc::default() };
    Scene::build(&desc, DVec3::ZERO, AccelKind::Bvh)
}

/// Every solid's `inside` against the parity of its surface crossings: a ray from a point
/// crosses a closed surface an odd number of times exactly when the point is inside. Counting
/// crossings walks each ray with `t_min` set to the last one, as CSG does, so this also checks
/// that every shape finds the root after a given one.
#[test]
fn inside_agrees_with_crossing_parity() {
    use strahl::ray::MISS;
    let r = &mut Rng(0x1A51DE);
    let (mut checked, mut inside_count) = (0, 0);
    for _ in 0..400 {
        let leaf = csg_leaf(r);
        let leaf_shape = leaf.shape.clone();
        let leaf_transform = leaf.transform.transform();
        let flat = matches!(
            leaf.shape,
            ShapeDesc::Triangle { .. }
                | ShapeDesc::Polygon { .. }
                | ShapeDesc::Disc { .. }
                | ShapeDesc::Mesh { inside_vector: None, .. }
        );
        // An open cone is a solid with holes in its surface: no parity to count.
        if matches!(
            leaf.shape,
            ShapeDesc::Cone { open: true, .. }
                | ShapeDesc::Prism { open: true, .. }
                | ShapeDesc::Sor { open: true, .. }
        ) {
            continue;
        }
        let scene = csg_scene(ObjectDesc { inverse: false, ..leaf });
        // Planes stay outside the primitives (and are checked as CSG leaves below).
        let Some(&p) = scene.prims.first() else { continue };
        let b = scene.bounds_of(&p);
        // An unbounded solid's inside reaches infinity: a ray may cross into it and never out.
        if !(b.min.is_finite() && b.max.is_finite()) {
            continue;
        }
        let (c, h) = ((b.min + b.max) * 0.5, (b.max - b.min) * 0.6);
        // So may a bounded surface's (a quadric ellipsoid with its outside as the solid).
        if scene.inside_prim(&p, strahl::lanes::V3::from_vec3(c + h * 1e3)) {
            continue;
        }
        for _ in 0..50 {
            let origin = c + h * r.v(-1.0, 1.0).as_vec3();
            let ray = Ray::new(origin, r.unit().as_vec3());
            let mut t = 0.0f32;
            let mut crossings = Vec::new();
            while crossings.len() < 16 {
                let next = scene.hit_prim_in(&p, &ray.lanes(), t, MISS);
                if next == MISS {
                    break;
                }
                crossings.push(next);
                t = next;
            }
            // Grazing rays and points on the surface decide nothing.
            let scale = 1.0 + origin.length();
            let near = |a: f32, b: f32| (a - b).abs() < 1e-3 * scale;
            if crossings.first().is_some_and(|&c| c < 1e-3 * scale) || crossings.windows(2).any(|w| near(w[0], w[1])) {
                continue;
            }
            let inside = scene.inside_prim(&p, strahl::lanes::V3::from_vec3(origin));
            if flat {
                assert!(!inside, "a flat shape has no inside");
                continue;
            }
            assert_eq!(
                inside,
                crossings.len() % 2 == 1,
                "{:?} at {origin} along {}: {crossings:?} {:?} {:?}",
                p.kind,
                ray.dir,
                leaf_shape,
                leaf_transform
            );
            checked += 1;
            inside_count += inside as usize;
        }
    }
    assert!(checked > 5000 && inside_count > 300, "{checked} rays checked, {inside_count} from inside");
}

/// Where a CSG child's surface crosses `ray`, from every crossing of its leaves tested one by
/// one: a leaf's crossings; a node's surface children's crossings where the other children
/// agree (a union: always; a merge: none contains the point; the rest: all contain it).
fn csg_reference(scene: &Scene, target: strahl::scene::csg::CsgTarget, ray: &Ray) -> Vec<f32> {
    use strahl::ray::MISS;
    use strahl::scene::csg::{CsgRule, CsgTarget};
    match target {
        CsgTarget::Leaf(i) => {
            let (mut out, mut from) = (Vec::new(), 0.0f32);
            while out.len() < 64 {
                let c = scene.hit_prim_in(&scene.prims[i as usize], &ray.lanes(), from, MISS);
                if c == MISS {
                    break;
                }
                out.push(c);
                from = c;
            }
            out
        }
        CsgTarget::Node(k) => {
            let n = scene.csg[k as usize];
            let kids = &scene.csg_children[n.children()];
            let inside = |c: &strahl::scene::csg::CsgChild, t: f32| {
                let p = strahl::lanes::V3::from_vec3(ray.at(t));
                let raw = match c.target {
                    CsgTarget::Leaf(i) => scene.inside_prim(&scene.prims[i as usize], p),
                    CsgTarget::Node(m) => scene.inside_node(m, p),
                };
                raw != c.inverse
            };
            let mut out = Vec::new();
            for (i, c) in kids[..n.surfaces as usize].iter().enumerate() {
                for t in csg_reference(scene, c.target, ray) {
                    let mut others = kids.iter().enumerate().filter(|(j, _)| *j != i).map(|(_, o)| inside(o, t));
                    let keep = match n.rule {
                        CsgRule::Union => true,
                        CsgRule::Merge => !others.any(|x| x),
                        CsgRule::All => others.all(|x| x),
                    };
                    if keep {
                        out.push(t);
                    }
                }
            }
            out
        }
    }
}

/// The CSG node's nearest surface against `csg_reference`, built from its leaves' crossings
/// and the nodes' inside tests rather than the node's own search. Packets must give the single
/// ray's bits, and f64 a `t` within rounding of f32's.
#[test]
fn csg_surfaces_match_a_crossing_reference() {
    use strahl::lanes::{Lane, F8};
    use strahl::ray::MISS;
    use strahl::scene::csg::CsgTarget;
    let r = &mut Rng(0xC5C);
    let (mut compared, mut hits) = (0, 0);
    for _ in 0..400 {
        let scene = csg_scene(csg_tree(r, 3));
        let Some(&node) = scene.prims.first() else { continue };
        if node.kind != strahl::scene::build::ShapeKind::Csg {
            continue;
        }
        for _ in 0..40 {
            let ray = Ray::new(r.v(-9.0, 9.0).as_vec3(), r.unit().as_vec3());
            let (t, leaf) = scene.hit_csg(node.index, &ray.lanes(), 0.0, f32::INFINITY);
            // The same through eight lanes, each a different ray but this one in lane 3.
            let mut rays = [Ray::new(r.v(-9.0, 9.0).as_vec3(), r.unit().as_vec3()); 8];
            rays[3] = ray;
            let packet = strahl::accel::packet::Ray8::from_fn(|i| (rays[i].origin, rays[i].dir, rays[i].inv_dir));
            let (t8, _) = scene.hit_csg(node.index, &packet, F8::splat(0.0), F8::splat(MISS));
            assert_eq!(t8.0[3].to_bits(), t.to_bits(), "packet lane against the single ray");
            let (t64, _) = scene.hit_csg(node.index, &ray.lanes_f64(), 0.0, f64::INFINITY);
            // Reference: every leaf crossing.
            let mut crossings = Vec::new();
            for leaf in &scene.prims[scene.first_leaf as usize..] {
                let mut from = 0.0f32;
                while crossings.len() < 200 {
                    let c = scene.hit_prim_in(leaf, &ray.lanes(), from, MISS);
                    if c == MISS {
                        break;
                    }
                    crossings.push(c);
                    from = c;
                }
            }
            crossings.sort_by(f32::total_cmp);
            let scale = 1.0 + ray.origin.length();
            if crossings.windows(2).any(|w| w[1] - w[0] < 2e-3 * scale) || crossings.first().is_some_and(|&c| c < 2e-3)
            {
                continue;
            }
            let expected = csg_reference(&scene, CsgTarget::Node(node.index), &ray).into_iter().min_by(f32::total_cmp);
            match expected {
                Some(e) => {
                    assert!(
                        (t - e).abs() <= 1e-4 * scale,
                        "node hit {t}, reference {e}, crossings {crossings:?}, ray {ray:?}, nodes {:?}, children {:?}, leaves {:?}",
                        scene.csg,
                        scene.csg_children,
                        &scene.prims[scene.first_leaf as usize..]
                    );
                    assert!(leaf as usize >= scene.first_leaf as usize, "the hit names a leaf");
                    // Relative too: a plane met at a grazing angle far away is ill-conditioned.
                    // The solids lie within 10 of the origin, so a hit far beyond is such a
                    // plane, whose f32 `t` is off by f32's epsilon over the cosine of the angle:
                    // no bound of rounding holds there.
                    let tol = 1e-3 * scale as f64 + 1e-5 * e as f64;
                    assert!(
                        e > 100.0 * scale || (t64 - e as f64).abs() <= tol,
                        "f64 {t64} against {e}: {:?}",
                        scene.prims[leaf as usize]
                    );
                    hits += 1;
                }
                None => assert_eq!(t, MISS, "node hit {t} where the reference has none: {crossings:?}"),
            }
            compared += 1;
        }
    }
    assert!(compared > 3000 && hits > 250, "{compared} rays compared, {hits} hits");
}

/// `intersection`, `difference` and `clipped_by` of many boxes, spheres and ellipsoids (the
/// children whose crossings the node keeps, `csg::has_span`; 70 of them are more than it keeps)
/// against a reference from each child's crossings and the children's own inside tests: the
/// same nearest hit and the same leaf, and packets the single ray's bits.
#[test]
fn csg_of_convex_solids_matches_the_inside_test_reference() {
    use strahl::desc::CsgOp;
    use strahl::lanes::{Lane, F8};
    use strahl::ray::MISS;
    use strahl::scene::csg::{CsgRule, CsgTarget};
    let r = &mut Rng(0x5BA4);
    let (mut compared, mut hits, mut spans) = (0, 0, 0);
    for case in 0..120 {
        let count = [2, 3, 8, 40, 70][case % 5];
        let children = (0..count)
            .map(|_| {
                let shape = match r.pick(3) {
                    0 => ShapeDesc::Sphere { center: r.v(-0.5, 0.5), radius: r.f(0.8, 1.6) },
                    1 => ShapeDesc::Box { corner1: r.v(-1.5, -0.5), corner2: r.v(0.5, 1.5) },
                    // An ellipsoid: a sphere under a non-uniform scale.
                    _ => ShapeDesc::Sphere { center: DVec3::ZERO, radius: 1.0 },
                };
                let transform = match &shape {
                    ShapeDesc::Sphere { radius, .. } if *radius == 1.0 => {
                        xf(DMat4::from_rotation_y(r.f(-3.2, 3.2)) * DMat4::from_scale(r.v(0.8, 1.8)))
                    }
                    _ if r.pick(2) == 0 => xf(DMat4::from_rotation_x(r.f(-3.2, 3.2))),
                    _ => Transform::default(),
                };
                ObjectDesc { shape, transform: transform.into(), inverse: r.pick(10) == 0, ..csg_leaf(r) }
            })
            .collect();
        let op = [CsgOp::Intersection, CsgOp::Difference, CsgOp::Clip][r.pick(3) as usize];
        let scene = csg_scene(ObjectDesc { shape: ShapeDesc::Csg { op, children }, inverse: false, ..csg_leaf(r) });
        let Some(&node) = scene.prims.first() else { continue };
        let n = scene.csg[node.index as usize];
        assert_eq!(n.rule, CsgRule::All);
        spans += n.spans as usize;
        let kids = &scene.csg_children[n.children()];
        for _ in 0..60 {
            // From afar towards the middle, so that most rays meet the node.
            let origin = r.unit().as_vec3() * 8.0;
            let ray = Ray::new(origin, (r.v(-1.0, 1.0).as_vec3() - origin).normalize());
            let (t, leaf) = scene.hit_csg(node.index, &ray.lanes(), 0.0, f32::INFINITY);
            let mut rays = [Ray::new(r.unit().as_vec3() * 8.0, -r.unit().as_vec3()); 8];
            rays[5] = ray;
            let packet = strahl::accel::packet::Ray8::from_fn(|i| (rays[i].origin, rays[i].dir, rays[i].inv_dir));
            let (t8, leaf8) = scene.hit_csg(node.index, &packet, F8::splat(0.0), F8::splat(MISS));
            assert_eq!((t8.0[5].to_bits(), leaf8.0[5].to_bits()), (t.to_bits(), leaf.to_bits()), "lane against ray");
            // Reference: each surface child's crossings, kept where every other child's own
            // inside test agrees; the nearest wins, the first child's on a tie.
            let mut all = Vec::new();
            let mut expected: Option<(f32, u32)> = None;
            for (i, c) in kids.iter().enumerate() {
                let CsgTarget::Leaf(l) = c.target else { panic!("leaves only") };
                let mut from = 0.0f32;
                loop {
                    let x = scene.hit_prim_in(&scene.prims[l as usize], &ray.lanes(), from, MISS);
                    if x == MISS {
                        break;
                    }
                    all.push(x);
                    from = x;
                    let p = strahl::lanes::V3::from_vec3(ray.at(x));
                    let kept = kids.iter().enumerate().filter(|&(j, _)| j != i).all(|(_, o)| {
                        let CsgTarget::Leaf(m) = o.target else { unreachable!() };
                        scene.inside_prim(&scene.prims[m as usize], p) != o.inverse
                    });
                    if kept && i < n.surfaces as usize && expected.is_none_or(|(e, _)| x < e) {
                        expected = Some((x, l));
                    }
                }
            }
            all.sort_by(f32::total_cmp);
            // Two crossings within rounding of each other (an edge) decide by rounding.
            if all.windows(2).any(|w| w[1] - w[0] < 1e-3) {
                continue;
            }
            match expected {
                Some((e, l)) => {
                    assert_eq!((t, leaf as u32), (e, l), "case {case}: ray {ray:?}");
                    hits += 1;
                }
                None => assert_eq!(t, MISS, "case {case}: ray {ray:?}"),
            }
            compared += 1;
        }
    }
    assert!(spans > 80 && compared > 3000 && hits > 1000, "{spans} nodes with spans, {compared} rays, {hits} hits");
}

/// A `bicubic_patch` with random control points around a 6-unit square and random steps, read
/// through the parser (which tessellates it into a mesh).
fn random_patch(r: &mut Rng, case: u64) -> strahl::desc::MeshDesc {
    let points: Vec<String> = (0..16)
        .map(|k| {
            let base = DVec3::new((k % 4) as f64 * 2.0 - 3.0, 0.0, (k / 4) as f64 * 2.0 - 3.0);
            let p = base + r.v(-1.5, 1.5);
            format!("<{}, {}, {}>", p.x, p.y, p.z)
        })
        .collect();
    let text =
        format!("bicubic_patch {{ type 1 u_steps {} v_steps {} {} }}", 1 + r.pick(4), 1 + r.pick(4), points.join(", "));
    let dir = std::env::temp_dir().join(format!("strahl-props-patch-{}-{case}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("patch.pov");
    std::fs::write(&path, text).unwrap();
    let desc = strahl::pov::load_scene(&path, &strahl::pov::IncludePath::default()).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    match &desc.objects[0].shape {
        ShapeDesc::Mesh { mesh, .. } => (**mesh).clone(),
        other => panic!("a patch lowers to a mesh, not {other:?}"),
    }
}

/// Meshes (triangle soups and bicubic patches): eight-lane packets give the single-ray distances bit for bit, and both agree with
/// brute force over the same triangles placed one by one as `triangle` objects (the mesh's own
/// BVH, its object-space transform and the face it reports, against no accelerator at all).
#[test]
fn mesh_packets_single_rays_and_brute_force_agree() {
    use strahl::desc::{MeshDesc, MeshFace};
    use strahl::lanes::{Lane, F8, V3};
    use strahl::ray::{RayLanes, MISS};
    use strahl::render::intersect::HitShape;
    let r = &mut Rng(0x3E54);
    let (mut hits, mut rays, mut disagree) = (0, 0, 0);
    for case in 0..24 {
        let mut mesh = MeshDesc::default();
        if case % 3 == 2 {
            // A bicubic patch, tessellated by the parser as a scene would have it (its smooth
            // normals dropped: the brute-force triangles below are flat).
            mesh = random_patch(r, case);
            mesh.normals.clear();
            mesh.faces.iter_mut().for_each(|f| f.normals = None);
        }
        for _ in 0..(50 + r.pick(300)) * u64::from(case % 3 != 2) {
            let k = mesh.vertices.len() as u32;
            let c = r.v(-3.0, 3.0);
            mesh.vertices.extend([c + r.v(-0.7, 0.7), c + r.v(-0.7, 0.7), c + r.v(-0.7, 0.7)]);
            mesh.faces.push(MeshFace { vertices: [k, k + 1, k + 2], normals: None });
        }
        let transform = random_transform(r);
        let object = |shape| ObjectDesc { shape, transform: transform.into(), ..csg_leaf(&mut Rng(case)) };
        let triangles: Vec<ObjectDesc> = mesh
            .faces
            .iter()
            .map(|f| {
                let [a, b, c] = f.vertices.map(|i| mesh.vertices[i as usize]);
                object(ShapeDesc::Triangle { a, b, c })
            })
            .map(|o| ObjectDesc { inverse: false, ..o })
            .collect();
        let mesh_object = ObjectDesc {
            inverse: false,
            ..object(ShapeDesc::Mesh { mesh: std::sync::Arc::new(mesh), inside_vector: None })
        };
        let one = Scene::build(
            &SceneDesc { objects: vec![mesh_object], ..SceneDesc::default() },
            DVec3::ZERO,
            AccelKind::Bvh,
        );
        let brute =
            Scene::build(&SceneDesc { objects: triangles, ..SceneDesc::default() }, DVec3::ZERO, AccelKind::None);
        let prim = one.prims[0];
        let mut stats = RenderStats::default();
        for _ in 0..40 {
            let origin = r.v(-8.0, 8.0).as_vec3();
            let aim = r.v(-3.0, 3.0).as_vec3();
            let dirs: [Vec3; 8] = std::array::from_fn(|_| (aim + r.v(-0.5, 0.5).as_vec3() - origin).normalize());
            let packet = RayLanes::<F8>::new(V3::splat(origin), V3::from_lanes(|i| dirs[i]));
            let t8 = one.hit_prim(&prim, &packet, F8::splat(MISS));
            // Lanes of one packet with limits of their own (an idle lane at 0, a short one, a
            // few at a random distance): the packet's walk of the mesh BVH masks each lane.
            let far = r.f(2.0, 16.0) as f32;
            let limits = F8::from_fn(|i| [MISS, 0.0, far, MISS, 0.5, far, far * 0.5, MISS][i]);
            let t8_limited = one.hit_prim(&prim, &packet, limits);
            for (i, d) in dirs.iter().enumerate() {
                let ray = Ray::new(origin, *d);
                let t1 = one.hit_prim(&prim, &ray.lanes(), MISS);
                assert_eq!(t8.0[i].to_bits(), t1.to_bits(), "case {case}: lane {i} of the packet");
                let t1_limited = one.hit_prim(&prim, &ray.lanes(), limits.0[i]);
                assert_eq!(t8_limited.0[i].to_bits(), t1_limited.to_bits(), "case {case}: lane {i}, limited");
                let hit = one.intersect(&ray, f32::INFINITY, &mut stats);
                let truth = brute.intersect(&ray, f32::INFINITY, &mut stats);
                rays += 1;
                match (hit, truth) {
                    (None, None) => {}
                    (Some(h), Some(b)) if (h.t - b.t).abs() <= 1e-4 * b.t.max(1.0) => {
                        hits += 1;
                        let HitShape::Face { face, .. } = h.shape else { panic!("a mesh hit names its face") };
                        let p = ray.at(h.t);
                        let (n, m) = (one.normal_at(h.shape, p), brute.normal_at(b.shape, p));
                        // Coplanar faces can tie; a different face at the same t must lie in the same plane.
                        assert!(n.dot(m).abs() > 0.999, "case {case}: face {face}'s normal {n} vs {m}");
                    }
                    // Rays through an edge shared in f32 by one side and not the other.
                    _ => disagree += 1,
                }
            }
        }
    }
    assert!(hits > 1000, "{hits} of {rays} rays hit");
    assert!(disagree * 1000 < rays, "{disagree} of {rays} rays disagree with brute force");
}
