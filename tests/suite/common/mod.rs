//! Helpers shared by the integration tests (each test file is its own crate and includes this
//! module with `mod common;`).

// Each test crate that includes this module uses only part of it.
#![allow(dead_code)]

pub mod compare;

use glam::DMat4;
use strahl::desc::{CameraDesc, SceneDesc, Transform};

/// Applies the world transform `m` (after everything else) to camera, lights, objects and
/// pattern transforms, so the scene looks the same from the moved camera.
pub fn transform_scene(desc: &SceneDesc, m: DMat4) -> SceneDesc {
    let t = Transform { matrix: m, inverse: m.inverse() };
    let mut out = desc.clone();
    let c = &mut out.camera;
    *c = CameraDesc {
        location: m.transform_point3(c.location),
        direction: m.transform_vector3(c.direction),
        right: m.transform_vector3(c.right),
        up: m.transform_vector3(c.up),
        sky: m.transform_vector3(c.sky),
        look_at: c.look_at.map(|p| m.transform_point3(p)),
        angle: c.angle,
        ..*c
    };
    for l in &mut out.lights {
        l.position = m.transform_point3(l.position);
    }
    for o in &mut out.objects {
        o.transform = o.transform.then(&t);
        let texture = o.texture_mut();
        texture.pigment.transform = texture.pigment.transform.then(&t);
        if let Some(n) = &mut texture.normal {
            n.transform = n.transform.then(&t);
        }
    }
    out
}
