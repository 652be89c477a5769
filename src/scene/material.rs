//! Render-ready surface description: pigment, normal perturbation, finish and interior, in f32.

use glam::{DVec3, Vec3};

use crate::scene::desc::{FinishDesc, InteriorDesc, TextureDesc};
use crate::shading::{Normal, Pigment};

/// POV-Ray's finish, with exponents precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Finish {
    pub ambient: Vec3,
    pub diffuse: f32,
    pub brilliance: f32,
    pub phong: f32,
    pub phong_size: f32,
    pub specular: f32,
    /// `1 / roughness`, the Blinn exponent of `specular`.
    pub specular_exponent: f32,
    pub reflection: Vec3,
}

impl Finish {
    pub fn from_desc(f: &FinishDesc) -> Finish {
        Finish {
            ambient: f.ambient.as_vec3(),
            diffuse: f.diffuse as f32,
            brilliance: f.brilliance as f32,
            phong: f.phong as f32,
            phong_size: f.phong_size as f32,
            specular: f.specular as f32,
            specular_exponent: (1.0 / f.roughness.max(1e-6)) as f32,
            reflection: f.reflection.as_vec3(),
        }
    }

    pub fn reflects(&self) -> bool {
        self.reflection.max_element() > 0.0
    }
}

#[derive(Clone, Debug)]
pub struct Material {
    pub pigment: Pigment,
    pub normal: Option<Normal>,
    pub finish: Finish,
    pub ior: f32,
}

impl Material {
    pub fn from_desc(texture: &TextureDesc, interior: &InteriorDesc, origin: DVec3) -> Material {
        Material {
            pigment: Pigment::from_desc(&texture.pigment, origin),
            normal: texture.normal.as_ref().map(|n| Normal::from_desc(n, origin)),
            finish: Finish::from_desc(&texture.finish),
            ior: interior.ior as f32,
        }
    }
}
