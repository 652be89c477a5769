//! A hand-built `SceneDesc` close to `scenes/seed.pov`, for tests and demos that must not depend
//! on the parser. It is data only; it approximates `DMFWood4` with a two-colour wood map.

use glam::{DMat4, DVec3};

use crate::camera::Camera;
use crate::scene::desc::{
    CameraDesc, Color, ColorMapEntry, FinishDesc, LightDesc, NormalDesc, NormalPattern, ObjectDesc,
    PigmentDesc, PigmentPattern, SceneDesc, ShapeDesc, TextureDesc, Transform,
};

fn transform(m: DMat4) -> Transform {
    Transform {
        matrix: m,
        inverse: m.inverse(),
    }
}

fn object(shape: ShapeDesc, texture: TextureDesc, t: Transform) -> ObjectDesc {
    ObjectDesc {
        shape,
        transform: t,
        texture,
        interior: Default::default(),
        source: Default::default(),
    }
}

fn pigment(pattern: PigmentPattern, t: Transform) -> PigmentDesc {
    PigmentDesc {
        pattern,
        turbulence: None,
        transform: t,
    }
}

/// `scenes/seed.pov` as `pov::lower` would produce it, give or take the wood texture.
pub fn seed_like() -> SceneDesc {
    let base = Camera::from_desc(&CameraDesc::default());
    let cam = Camera::looking_at(
        DVec3::new(3.0, 3.0, -1.0),
        DVec3::new(0.0, 1.0, 2.0),
        None,
        &base,
    );
    let camera = CameraDesc {
        location: cam.location,
        direction: cam.direction,
        right: cam.right,
        up: cam.up,
        look_at: Some(DVec3::new(0.0, 1.0, 2.0)),
        ..CameraDesc::default()
    };
    let white = DVec3::ONE;
    let lights = [
        DVec3::new(0.0, 4.0, -3.0),
        DVec3::new(0.0, 6.0, -4.0),
        DVec3::new(6.0, 4.0, -3.0),
    ]
    .map(|position| LightDesc {
        position,
        color: white,
    })
    .to_vec();

    let plane = object(
        ShapeDesc::Plane {
            normal: DVec3::Y,
            distance: 0.0,
        },
        TextureDesc {
            pigment: pigment(
                PigmentPattern::Checker(Color::WHITE, Color::BLACK),
                Transform::default(),
            ),
            ..TextureDesc::default()
        },
        Transform::default(),
    );
    let sphere = object(
        ShapeDesc::Sphere {
            center: DVec3::new(0.0, 2.0, 4.0),
            radius: 2.0,
        },
        TextureDesc {
            pigment: pigment(
                PigmentPattern::Solid(Color::rgb(1.0, 0.5, 0.0)),
                Transform::default(),
            ),
            normal: Some(NormalDesc {
                pattern: NormalPattern::Bumps(0.4),
                turbulence: None,
                transform: transform(DMat4::from_scale(DVec3::splat(0.2))),
            }),
            finish: FinishDesc {
                phong: 1.0,
                ..FinishDesc::default()
            },
        },
        Transform::default(),
    );
    let rotate = transform(DMat4::from_rotation_y((-20f64).to_radians()));
    let wood = PigmentPattern::Wood(vec![
        ColorMapEntry {
            value: 0.0,
            color: Color::rgb(0.66, 0.45, 0.25),
        },
        ColorMapEntry {
            value: 1.0,
            color: Color::rgb(0.4, 0.22, 0.1),
        },
    ]);
    let wood_space = transform(DMat4::from_scale(DVec3::splat(2.0))).then(&rotate);
    let cuboid = object(
        ShapeDesc::Box {
            corner1: DVec3::new(-1.0, 0.0, -0.5),
            corner2: DVec3::new(1.0, 2.0, 1.5),
        },
        TextureDesc {
            pigment: pigment(wood, wood_space),
            ..TextureDesc::default()
        },
        rotate,
    );
    SceneDesc {
        camera,
        lights,
        objects: vec![plane, sphere, cuboid],
        ..SceneDesc::default()
    }
}
