//! Render-ready surface description: pigment, normal perturbation, finish and interior, in f32.

use glam::{DMat4, Vec3};

use crate::lanes::Lane;
use crate::scene::desc::{FinishDesc, InteriorDesc, TextureDesc};
use crate::shading::normal::NormalF32;
use crate::shading::pattern::Rgbft;
use crate::shading::pigment::{Pigment, PigmentPattern32};

/// A shading exponent. Whole numbers up to 256 (POV-Ray's default `phong_size 40`, the seed's
/// `brilliance 1`, `roughness 0.05` → 20) are raised by repeated squaring, which costs a few
/// multiplies against `powf`'s ~160 instructions per call (measured with callgrind on the seed
/// scene, where it was 6% of all instructions); others fall back to `powf`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Exponent {
    One,
    Whole(u32),
    Real(f32),
}

impl Exponent {
    pub fn new(e: f64) -> Exponent {
        if e == 1.0 {
            Exponent::One
        } else if (0.0..=256.0).contains(&e) && e.fract() == 0.0 {
            Exponent::Whole(e as u32)
        } else {
            Exponent::Real(e as f32)
        }
    }

    /// `x` raised to this exponent, for `x` in (0, 1].
    #[inline]
    pub fn pow(self, x: f32) -> f32 {
        self.pow_lanes(x)
    }

    /// `pow` for one or eight lanes, with the same operations in the same order.
    #[inline(always)]
    pub fn pow_lanes<L: Lane>(self, x: L) -> L {
        match self {
            Exponent::One => x,
            Exponent::Whole(mut n) => {
                let (mut base, mut acc) = (x, L::splat(1.0));
                while n > 0 {
                    if n & 1 == 1 {
                        acc = acc * base;
                    }
                    base = base * base;
                    n >>= 1;
                }
                acc
            }
            Exponent::Real(e) => x.map(|v| v.powf(e)),
        }
    }
}

/// POV-Ray's finish, with exponents precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Finish {
    pub ambient: Vec3,
    pub diffuse: f32,
    pub brilliance: Exponent,
    pub phong: f32,
    pub phong_size: Exponent,
    pub specular: f32,
    /// `1 / roughness`, the Blinn exponent of `specular`.
    pub specular_exponent: Exponent,
    pub reflection: Vec3,
}

impl Finish {
    pub fn from_desc(f: &FinishDesc) -> Finish {
        Finish {
            ambient: f.ambient.as_vec3(),
            diffuse: f.diffuse as f32,
            brilliance: Exponent::new(f.brilliance),
            phong: f.phong as f32,
            phong_size: Exponent::new(f.phong_size),
            specular: f.specular as f32,
            specular_exponent: Exponent::new(1.0 / f.roughness.max(1e-6)),
            reflection: f.reflection.as_vec3(),
        }
    }

    pub fn reflects(&self) -> bool {
        self.reflection.max_element() > 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::Exponent;

    #[test]
    fn whole_exponents_match_powf_closely() {
        for e in [0.0, 1.0, 2.0, 20.0, 40.0, 255.0, 2.5] {
            for x in [0.001f32, 0.3, 0.77, 0.999, 1.0] {
                let want = x.powf(e as f32);
                let got = Exponent::new(e).pow(x);
                assert!((got - want).abs() <= 1e-5 * want.max(1e-30) + 1e-30, "{x}^{e}: {got} vs {want}");
            }
        }
    }
}

#[derive(Clone, Debug)]
pub struct Material {
    pub pigment: Pigment,
    pub normal: Option<NormalF32>,
    pub finish: Finish,
    pub ior: f32,
    /// Which of the scene's lights light this surface (`light_group`), by light index; `None`
    /// (every scene without light groups): all of them.
    pub lights: Option<std::sync::Arc<[bool]>>,
}

impl Material {
    /// Whether light `index` of the scene lights this surface.
    #[inline]
    pub fn lit_by(&self, index: usize) -> bool {
        self.lights.as_ref().is_none_or(|mask| mask[index])
    }

    /// Whether any point of the pigment lets light through (filter or transmit above zero).
    pub fn may_be_transparent(&self) -> bool {
        let see_through = |c: &Rgbft| c.filter > 0.0 || c.transmit > 0.0;
        match &self.pigment.pattern {
            PigmentPattern32::Solid(c) => see_through(c),
            PigmentPattern32::Checker(cs) => cs.iter().any(see_through),
            PigmentPattern32::Wood(map) => map.entries().iter().any(|(_, c)| see_through(c)),
        }
    }

    /// `world_from_render`: `RenderFrame::world_from_render` of the scene being built.
    pub fn from_desc(texture: &TextureDesc, interior: &InteriorDesc, world_from_render: &DMat4) -> Material {
        Material {
            pigment: Pigment::from_desc(&texture.pigment, world_from_render),
            normal: texture.normal.as_ref().map(|n| NormalF32::from_desc(n, world_from_render)),
            finish: Finish::from_desc(&texture.finish),
            ior: interior.ior as f32,
            lights: None,
        }
    }
}
