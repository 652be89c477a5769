//! Deterministic test scenes of N objects for the scaling benchmarks (issue #4), and a small
//! POV-Ray writer so that POV-Ray 3.7 can render exactly the same scene (`strahl gen`).
//!
//! Positions, sizes and colours come from a hash of (object index, field), never from a random
//! generator, so `generate(kind, n, ..)` is the same scene on every machine and every run. The objects fill
//! a cube whose edge grows with n^(1/3), so the object density (and the depth complexity a ray
//! sees) stays about the same as n grows and frame time measures the accelerator, not the scene.
//!
//! Coordinates are rounded to 1e-4 before they are stored, so the POV file stays short and every
//! number in it reads back to the same f64 (`write_pov` prints the shortest round-trip form).
//!
//! The camera fits the image it is rendered at: its `right` vector is the image's aspect long,
//! and `write_generated` writes it as `right <…>*image_width/image_height`, POV-Ray's own idiom,
//! so a generated file is not stretched at POV-Ray's default 640×480 or at 1280×720.

use glam::DVec3;

use crate::camera::Camera;
use crate::desc::{
    CameraDesc, Color, FinishDesc, GlobalSettings, LightDesc, ObjectDesc, PigmentDesc, PigmentPattern, SceneDesc,
    ShapeDesc, SourceRef, TextureDesc, Transform,
};

mod sheet;
mod write;
pub use write::{write_generated, write_generated_to, write_pov, IoText};

/// Which primitive the generated cloud is made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Spheres,
    Boxes,
    Triangles,
    /// Capped cylinders along random axes.
    Cylinders,
    /// Spheres, boxes and triangles in turn.
    Mixed,
    /// One `mesh2` of N triangles: a bumpy sphere filling the middle of the cube.
    Mesh,
    /// Tori lying in one of the three axis planes (`rotate x*90`, `rotate z*90` or none).
    Tori,
    /// One `mesh2` of exactly N triangles: a rippled sheet across the cube (`sheet`), written
    /// as it is generated, so ten million triangles need no scene in memory.
    Mesh2,
}

impl Kind {
    pub const ALL: [Kind; 8] = [
        Kind::Spheres,
        Kind::Boxes,
        Kind::Triangles,
        Kind::Cylinders,
        Kind::Mixed,
        Kind::Mesh,
        Kind::Tori,
        Kind::Mesh2,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Spheres => "spheres",
            Kind::Boxes => "boxes",
            Kind::Triangles => "triangles",
            Kind::Cylinders => "cylinders",
            Kind::Mixed => "mixed",
            Kind::Mesh => "mesh",
            Kind::Tori => "tori",
            Kind::Mesh2 => "mesh2",
        }
    }

    /// What `n` objects of this kind are called in a sentence: `10000 spheres`.
    pub fn plural(self) -> &'static str {
        match self {
            Kind::Mixed => "mixed objects",
            Kind::Mesh | Kind::Mesh2 => "mesh triangles",
            k => k.name(),
        }
    }

    pub fn parse(s: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == s)
    }

    /// Whether the N objects are the triangles of one mesh rather than a cloud of N objects.
    pub fn is_mesh(self) -> bool {
        matches!(self, Kind::Mesh | Kind::Mesh2)
    }
}

/// Mean distance between neighbouring object centres; objects are about 1 unit across.
const SPACING: f64 = 2.5;
/// One object in this many gets a mirror-like finish (reflection 0.35, phong 0.8).
const REFLECTIVE_EVERY: u64 = 16;

/// Plain colours the objects cycle through by hash.
const PALETTE: [[f64; 3]; 8] = [
    [0.9, 0.2, 0.15],
    [0.2, 0.6, 0.9],
    [0.95, 0.75, 0.2],
    [0.3, 0.8, 0.35],
    [0.75, 0.4, 0.85],
    [0.9, 0.5, 0.1],
    [0.85, 0.85, 0.85],
    [0.25, 0.3, 0.45],
];

/// SplitMix64's finaliser: a well-mixed 64-bit hash of `x`.
fn mix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// A number in [0, 1) from (object, field): the same pair always gives the same number.
fn unit(object: u64, field: u64) -> f64 {
    (mix(object.wrapping_mul(0x1_0000_0001) ^ mix(field)) >> 11) as f64 / (1u64 << 53) as f64
}

/// Rounds to 1e-4 so the written scene is short and reads back exactly.
fn q(v: f64) -> f64 {
    (v * 1e4).round() / 1e4
}

fn qv(v: DVec3) -> DVec3 {
    DVec3::new(q(v.x), q(v.y), q(v.z))
}

/// Edge of the cube the `n` objects fill.
pub fn extent(n: usize) -> f64 {
    SPACING * (n.max(1) as f64).cbrt()
}

fn object_texture(pattern: PigmentPattern, finish: FinishDesc) -> TextureDesc {
    TextureDesc {
        pigment: PigmentDesc { pattern, ..PigmentDesc::default() },
        normal: None,
        finish,
        uv_mapping: false,
        pattern: None,
    }
}

fn object(shape: ShapeDesc, pattern: PigmentPattern, finish: FinishDesc, index: usize) -> ObjectDesc {
    ObjectDesc { shape, ..object_with(object_texture(pattern, finish), index) }
}

/// An untransformed object of `texture`, object `index` of the scene, its shape a placeholder.
fn object_with(texture: TextureDesc, index: usize) -> ObjectDesc {
    ObjectDesc {
        shape: ShapeDesc::Plane { normal: DVec3::Y, distance: 0.0 },
        transform: Default::default(),
        texture: texture.into(),
        interior_texture: None,
        interior: Default::default(),
        no_shadow: false,
        inverse: false,
        hollow: false,
        light_group: None,
        bounded_by: None,
        source: SourceRef { file: "scene::generate".into(), line: index as u32, col: 0 },
    }
}

/// Shape `i` of kind `kind` (Mixed picks one per object) around `center`, and its transform
/// (identity but for tori, which POV-Ray only writes about the origin).
fn shape(kind: Kind, i: u64, center: DVec3) -> (ShapeDesc, Transform) {
    if kind == Kind::Tori {
        return torus(i, center);
    }
    (untransformed(kind, i, center), Transform::default())
}

/// The three orientations of generated tori: `rotate x*90`, `rotate z*90`, none. Built from exact
/// 0/±1 entries as the loader builds a rotation by a multiple of 90°, so the written file reads
/// back to exactly this matrix.
const TORUS_TURNS: [(&str, [f64; 9]); 3] = [
    ("rotate x*90 ", [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0]),
    ("rotate z*90 ", [0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0]),
    ("", [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]),
];

/// Torus `i`: major radius 0.3–0.5, minor 0.08–0.18, in one of three axis planes, at `center`.
fn torus(i: u64, center: DVec3) -> (ShapeDesc, Transform) {
    let u = |f: u64| unit(i, f);
    let shape = ShapeDesc::Torus { major: q(0.3 + 0.2 * u(10)), minor: q(0.08 + 0.1 * u(11)) };
    let turn = glam::DMat4::from_mat3(glam::DMat3::from_cols_array(&TORUS_TURNS[(i % 3) as usize].1));
    let step = |m: glam::DMat4| Transform { matrix: m, inverse: m.inverse() };
    (shape, step(turn).then(&step(glam::DMat4::from_translation(center))))
}

/// Shape `i` of an untransformed kind (Mixed picks one per object) around `center`.
fn untransformed(kind: Kind, i: u64, center: DVec3) -> ShapeDesc {
    let u = |f: u64| unit(i, f);
    let kind = match kind {
        Kind::Mixed => [Kind::Spheres, Kind::Boxes, Kind::Triangles][(i % 3) as usize],
        k => k,
    };
    match kind {
        Kind::Spheres => ShapeDesc::Sphere { center, radius: q(0.35 + 0.3 * u(10)) },
        Kind::Boxes => {
            let half = DVec3::new(0.2 + 0.3 * u(10), 0.2 + 0.3 * u(11), 0.2 + 0.3 * u(12));
            ShapeDesc::Box { corner1: qv(center - half), corner2: qv(center + half) }
        }
        Kind::Triangles | Kind::Mixed | Kind::Mesh | Kind::Tori | Kind::Mesh2 => {
            let corner = |f: u64| qv(center + DVec3::new(u(f) - 0.5, u(f + 1) - 0.5, u(f + 2) - 0.5) * 1.6);
            ShapeDesc::Triangle { a: corner(10), b: corner(13), c: corner(16) }
        }
        Kind::Cylinders => {
            let axis = (DVec3::new(u(10), u(11), u(12)) - 0.5).normalize_or(DVec3::Y) * (0.4 + 0.4 * u(13));
            let radius = q(0.15 + 0.2 * u(14));
            let (base, cap) = (qv(center - axis), qv(center + axis));
            ShapeDesc::Cone { base, base_radius: radius, cap, cap_radius: radius, open: false, cylinder: true }
        }
    }
}

/// About `n` triangles (at least 8) on a sphere in the middle of the cube of edge `edge`, its
/// radius rippled by a few percent: rows of latitude by twice as many columns, each square two
/// triangles, the poles shared vertices.
fn bumpy_sphere(n: usize, edge: f64) -> ShapeDesc {
    use crate::desc::{MeshDesc, MeshFace};
    let rows = ((n as f64 / 4.0).sqrt().round() as usize).max(2);
    let cols = 2 * rows;
    let (center, radius) = (DVec3::new(0.0, 0.8 + 0.5 * edge, 0.0), 0.35 * edge);
    let mut vertices = vec![qv(center + DVec3::Y * radius)];
    for r in 1..rows {
        let theta = std::f64::consts::PI * r as f64 / rows as f64;
        for c in 0..cols {
            let phi = std::f64::consts::TAU * c as f64 / cols as f64;
            let bump = 1.0 + 0.04 * (7.0 * theta).sin() * (9.0 * phi).sin() + 0.001 * unit(r as u64, c as u64);
            let dir = DVec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin());
            vertices.push(qv(center + dir * radius * bump));
        }
    }
    vertices.push(qv(center - DVec3::Y * radius));
    let bottom = vertices.len() as u32 - 1;
    let at = |r: usize, c: usize| (1 + (r - 1) * cols + c % cols) as u32;
    let mut faces = Vec::with_capacity(2 * rows * cols);
    let mut face = |v: [u32; 3]| faces.push(MeshFace { vertices: v, normals: None });
    for c in 0..cols {
        face([0, at(1, c + 1), at(1, c)]);
        face([bottom, at(rows - 1, c), at(rows - 1, c + 1)]);
    }
    for r in 1..rows - 1 {
        for c in 0..cols {
            face([at(r, c), at(r, c + 1), at(r + 1, c)]);
            face([at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)]);
        }
    }
    let mesh = MeshDesc { vertices, faces, ..MeshDesc::default() };
    ShapeDesc::Mesh { mesh: std::sync::Arc::new(mesh), inside_vector: None }
}

/// Length of the camera's `direction` for a unit-long `right`: 60° across a 16:9 image. It stays
/// the same at every aspect, so the vertical field of view does (36°) and the horizontal one is
/// the image's (60° at 16:9, 47° at 4:3), as with POV-Ray's `right x*image_width/image_height`.
fn direction_length() -> f64 {
    0.5 * (16.0 / 9.0) / 30f64.to_radians().tan()
}

/// A scene of `n` objects of `kind` above a checkered floor, lit by two lights, seen by a camera
/// that frames the whole cloud from the front and above, for an image of `width`×`height`
/// (its `right` vector is `width / height` long, so nothing is stretched).
pub fn generate(kind: Kind, n: usize, width: u32, height: u32) -> SceneDesc {
    let mut desc = header(kind, n, width, height);
    if kind == Kind::Mesh2 {
        desc.objects.push(ObjectDesc { shape: sheet::shape(n), ..object_with(sheet::texture(), 1) });
    }
    desc.objects.reserve(n);
    desc.objects.extend(cloud(kind, n));
    desc
}

/// The cloud's objects one at a time (none for the mesh kinds), each a function of its index.
pub fn cloud(kind: Kind, n: usize) -> impl Iterator<Item = ObjectDesc> {
    let edge = extent(n);
    (0..n as u64).filter(move |_| !kind.is_mesh()).map(move |i| {
        // The cube [-edge/2, edge/2] × [0.8, edge + 0.8] × [-edge/2, edge/2], just above the floor.
        let center = qv(DVec3::new((unit(i, 0) - 0.5) * edge, 0.8 + unit(i, 1) * edge, (unit(i, 2) - 0.5) * edge));
        let [r, g, b] = PALETTE[(mix(i ^ 0xC0105) % PALETTE.len() as u64) as usize];
        let finish = if mix(i ^ 0xF1).is_multiple_of(REFLECTIVE_EVERY) {
            FinishDesc { phong: 0.8, reflection: DVec3::splat(0.35), ..FinishDesc::default() }
        } else {
            FinishDesc::default()
        };
        let (shape, transform) = shape(kind, i, center);
        let mut o = object(shape, PigmentPattern::Solid(Color::rgb(r, g, b)), finish, i as usize + 1);
        o.transform = transform.into();
        o
    })
}

/// `generate`'s scene up to its cloud and its mesh2 sheet: camera, lights, the floor, and the
/// `mesh` kind's sphere.
fn header(kind: Kind, n: usize, width: u32, height: u32) -> SceneDesc {
    let edge = extent(n);
    let mut objects = vec![object(
        ShapeDesc::Plane { normal: DVec3::Y, distance: 0.0 },
        PigmentPattern::Checker(Color::rgb(0.9, 0.9, 0.9), Color::rgb(0.25, 0.25, 0.25)),
        FinishDesc::default(),
        0,
    )];
    if kind == Kind::Mesh {
        objects.push(ObjectDesc { shape: bumpy_sphere(n, edge), ..object_with(sheet::texture(), 1) });
    }
    // Explicit camera vectors (no look_at) so the written file and this desc agree exactly.
    let look_at = DVec3::new(0.0, 0.5 * edge, 0.0);
    let location = qv(DVec3::new(0.3 * edge, 0.85 * edge + 2.0, -2.0 * edge - 4.0));
    let like = Camera {
        location,
        direction: DVec3::Z * direction_length(),
        right: DVec3::X,
        up: DVec3::Y,
        lens: Default::default(),
    };
    let cam = Camera::looking_at(location, look_at, None, &like);
    // `right` is unit-long here; scaled as the parser evaluates `<r>*image_width/image_height`,
    // so the written file reads back to exactly this vector.
    let right = cam.right * width as f64 / height as f64;
    let (lx, ly) = (edge + 5.0, 2.0 * edge + 10.0);
    SceneDesc {
        // `write_pov` starts the file with `#version`.
        version_directive: true,
        camera: CameraDesc {
            location: cam.location,
            direction: cam.direction,
            right,
            up: cam.up,
            // `write_pov` writes them, so the scene read back has them given.
            up_or_right_given: true,
            ..CameraDesc::default()
        },
        lights: vec![
            LightDesc {
                position: qv(DVec3::new(-lx, ly, -1.5 * lx)),
                color: DVec3::splat(0.8),
                ..LightDesc::default()
            },
            LightDesc {
                position: qv(DVec3::new(lx, 0.7 * ly, -0.5 * lx)),
                color: DVec3::splat(0.5),
                ..LightDesc::default()
            },
        ],
        background: Color::rgb(0.55, 0.65, 0.85),
        global: GlobalSettings { assumed_gamma: Some(1.0), ..GlobalSettings::default() },
        objects,
        ..SceneDesc::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deterministic_and_sized() {
        for kind in Kind::ALL {
            let a = generate(kind, 300, 640, 480);
            assert_eq!(a, generate(kind, 300, 640, 480), "{kind:?}");
            // The floor plus n objects (one mesh of about n triangles; mesh2's of exactly n).
            match (kind, &a.objects[1].shape) {
                (Kind::Mesh, ShapeDesc::Mesh { mesh, .. }) => {
                    assert_eq!(a.objects.len(), 2);
                    assert!(mesh.faces.len().abs_diff(300) < 30, "{}", mesh.faces.len());
                }
                (Kind::Mesh2, ShapeDesc::Mesh { mesh, .. }) => {
                    assert_eq!(a.objects.len(), 2);
                    assert_eq!(mesh.faces.len(), 300);
                }
                _ => assert_eq!(a.objects.len(), 301),
            }
            assert_eq!(a.lights.len(), 2);
        }
        assert_eq!(generate(Kind::Spheres, 0, 640, 480).objects.len(), 1);
    }

    #[test]
    fn cloud_grows_with_cube_root() {
        let max_x = |d: &SceneDesc| {
            d.objects
                .iter()
                .filter_map(|o| match o.shape {
                    ShapeDesc::Sphere { center, .. } => Some(center.x.abs()),
                    _ => None,
                })
                .fold(0.0, f64::max)
        };
        let (small, big) = (max_x(&generate(Kind::Spheres, 1000, 4, 3)), max_x(&generate(Kind::Spheres, 8000, 4, 3)));
        assert!((big / small - 2.0).abs() < 0.1, "{small} {big}");
        assert!(small <= extent(1000) / 2.0 + 1e-9);
    }

    #[test]
    fn some_reflect_and_kinds_mix() {
        let d = generate(Kind::Mixed, 900, 4, 3);
        let reflective = d.objects.iter().filter(|o| o.texture.finish.reflection != DVec3::ZERO).count();
        assert!((30..=90).contains(&reflective), "{reflective}");
        for k in ["sphere", "box", "triangle"] {
            assert_eq!(d.objects.iter().filter(|o| o.shape.keyword() == k).count(), 300);
        }
    }

    #[test]
    fn write_pov_rejects_what_it_cannot_write() {
        let mut d = generate(Kind::Spheres, 2, 4, 3);
        d.objects[1].shape = ShapeDesc::Polygon { points: vec![] };
        assert!(write_pov(&d).unwrap_err().contains("polygon"));
    }

    #[test]
    fn generated_camera_is_not_stretched_at_any_aspect() {
        // The image-plane vectors are in the aspect of the image: 4:3 at POV-Ray's default
        // 640×480 (the 16:9 `right` once written stretched every default render), 16:9 at 1280×720.
        for (w, h) in [(640, 480), (1280, 720), (480, 640)] {
            let c = generate(Kind::Boxes, 10, w, h).camera;
            let aspect = c.right.length() / c.up.length();
            assert!((aspect - w as f64 / h as f64).abs() < 1e-12, "{w}x{h}: {aspect}");
            assert!(c.right.dot(c.up).abs() < 1e-12 && c.right.dot(c.direction).abs() < 1e-9);
        }
        let text = write_generated(Kind::Boxes, 10).unwrap_or_else(|e| panic!("{e}"));
        assert!(text.contains("*image_width/image_height\n"), "{text}");
    }
}
