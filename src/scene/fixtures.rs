//! Hand-built scenes for tests and benchmarks that must not depend on the parser.
//!
//! `seed_scene` is `scenes/seed.pov` written out as a `SceneDesc`, with the textures the
//! renderer core supports today (bumps and the wood box become plain finishes/colours), so the
//! capture, bench and determinism tests have a real scene before `pov::load_scene` exists.

use glam::{DMat4, DVec3};

use crate::camera::Camera;
use crate::desc::{
    CameraDesc, Color, FinishDesc, LightDesc, ObjectDesc, PigmentDesc, PigmentPattern, SceneDesc, ShapeDesc, SourceRef,
    TextureDesc, Transform,
};

/// The seed scene's camera: location <3,3,-1>, look_at <0,1,2>, POV-Ray's default lens.
pub fn seed_camera() -> Camera {
    let base = Camera::from_desc(&CameraDesc::default());
    Camera::looking_at(DVec3::new(3.0, 3.0, -1.0), DVec3::new(0.0, 1.0, 2.0), None, &base)
}

fn object(shape: ShapeDesc, pattern: PigmentPattern, finish: FinishDesc, transform: Transform) -> ObjectDesc {
    ObjectDesc {
        shape,
        transform: transform.into(),
        texture: TextureDesc {
            pigment: PigmentDesc { pattern, ..PigmentDesc::default() },
            normal: None,
            finish,
            uv_mapping: false,
            pattern: None,
        }
        .into(),
        interior_texture: None,
        interior: Default::default(),
        no_shadow: false,
        inverse: false,
        hollow: false,
        light_group: None,
        bounded_by: None,
        source: SourceRef { file: "fixtures::seed_scene".into(), line: 0, col: 0 },
    }
}

/// `scenes/seed.pov` by hand: three white lights, a checkered floor, an orange phong sphere and
/// a tan box turned by -20° about y.
pub fn seed_scene() -> SceneDesc {
    let cam = seed_camera();
    let rotate = DMat4::from_rotation_y((-20f64).to_radians());
    let box_transform = Transform { matrix: rotate, inverse: rotate.inverse() };
    SceneDesc {
        // As `scenes/seed.pov`, whose included colors.inc runs `#version`.
        version_directive: true,
        camera: CameraDesc {
            location: cam.location,
            direction: cam.direction,
            right: cam.right,
            up: cam.up,
            look_at: Some(DVec3::new(0.0, 1.0, 2.0)),
            ..CameraDesc::default()
        },
        lights: [DVec3::new(0.0, 4.0, -3.0), DVec3::new(0.0, 6.0, -4.0), DVec3::new(6.0, 4.0, -3.0)]
            .into_iter()
            .map(|position| LightDesc { position, ..LightDesc::default() })
            .collect(),
        objects: vec![
            object(
                ShapeDesc::Plane { normal: DVec3::Y, distance: 0.0 },
                PigmentPattern::Checker(Color::WHITE, Color::BLACK),
                FinishDesc::default(),
                Transform::default(),
            ),
            object(
                ShapeDesc::Sphere { center: DVec3::new(0.0, 2.0, 4.0), radius: 2.0 },
                PigmentPattern::Solid(Color::rgb(1.0, 0.5, 0.0)),
                FinishDesc { phong: 1.0, ..FinishDesc::default() },
                Transform::default(),
            ),
            object(
                ShapeDesc::Box { corner1: DVec3::new(-1.0, 0.0, -0.5), corner2: DVec3::new(1.0, 2.0, 1.5) },
                // colors.inc's Tan.
                PigmentPattern::Solid(Color::rgb(0.858824, 0.576471, 0.439216)),
                FinishDesc::default(),
                box_transform,
            ),
        ],
        ..SceneDesc::default()
    }
}
