//! Pigments and normal perturbations, evaluated per hit. (Interim: solid and checker only; the
//! noise patterns land with the shading branch.)

use glam::{Affine3A, DAffine3, DMat4, DVec3, Vec3};

use crate::scene::desc::{NormalDesc, PigmentDesc, PigmentPattern, Transform};

/// A colour with POV-Ray's filter and transmit channels.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgbft {
    pub rgb: Vec3,
    pub filter: f32,
    pub transmit: f32,
}

impl Rgbft {
    pub fn from_desc(c: &crate::scene::desc::Color) -> Rgbft {
        Rgbft { rgb: c.rgb.as_vec3(), filter: c.filter as f32, transmit: c.transmit as f32 }
    }
}

/// Pattern space from render space (world minus `origin`), composed in f64 then cast.
pub fn pattern_from_render(t: &Transform, origin: DVec3) -> Affine3A {
    let m: DMat4 = t.inverse * DMat4::from_translation(origin);
    let a = DAffine3::from_mat4(m);
    Affine3A::from_mat3_translation(a.matrix3.as_mat3(), a.translation.as_vec3())
}

#[derive(Clone, Debug)]
pub enum Pattern {
    Solid(Rgbft),
    Checker(Rgbft, Rgbft),
    Wood(Rgbft),
}

#[derive(Clone, Debug)]
pub struct Pigment {
    pub pattern: Pattern,
    pub pattern_from_render: Affine3A,
}

impl Pigment {
    pub fn from_desc(d: &PigmentDesc, origin: DVec3) -> Pigment {
        let pattern = match &d.pattern {
            PigmentPattern::Solid(c) => Pattern::Solid(Rgbft::from_desc(c)),
            PigmentPattern::Checker(a, b) => Pattern::Checker(Rgbft::from_desc(a), Rgbft::from_desc(b)),
            PigmentPattern::Wood(map) => Pattern::Wood(map.first().map(|e| Rgbft::from_desc(&e.color)).unwrap_or_default()),
        };
        Pigment { pattern, pattern_from_render: pattern_from_render(&d.transform, origin) }
    }

    pub fn may_be_transparent(&self) -> bool {
        match &self.pattern {
            Pattern::Solid(c) | Pattern::Wood(c) => c.filter > 0.0 || c.transmit > 0.0,
            Pattern::Checker(a, b) => a.filter + a.transmit + b.filter + b.transmit > 0.0,
        }
    }

    #[inline]
    pub fn eval(&self, p: Vec3, _max_octaves: Option<u32>) -> Rgbft {
        match &self.pattern {
            Pattern::Solid(c) | Pattern::Wood(c) => *c,
            Pattern::Checker(a, b) => {
                let q = self.pattern_from_render.transform_point3(p);
                let s = q.x.floor() as i64 + q.y.floor() as i64 + q.z.floor() as i64;
                if s & 1 == 0 {
                    *a
                } else {
                    *b
                }
            }
        }
    }
}

#[derive(Clone, Debug)]
pub struct Normal {
    pub amount: f32,
}

impl Normal {
    pub fn from_desc(_d: &NormalDesc, _origin: DVec3) -> Normal {
        Normal { amount: 0.0 }
    }

    #[inline]
    pub fn perturb(&self, _p: Vec3, n: Vec3, _max_octaves: Option<u32>) -> Vec3 {
        n
    }
}
