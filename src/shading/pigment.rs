//! Render-ready pigments: a closed enum evaluated per hit at a render-space point.
//!
//! Solid colours return before any transform or noise work; only turbulent patterns pay for noise.

use glam::{Affine3A, DMat4, DVec3, Vec3};

use super::noise::{warp, TurbulenceF32};
use super::pattern::{checker, wood, ColorMap, Rgbft};
use crate::scene::desc::{PigmentDesc, PigmentPattern};

/// Per-frame knobs that trade pattern fidelity for speed.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PatternQuality {
    /// Caps every turbulence's octave count; `None` renders them as written.
    pub max_octaves: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PigmentPattern32 {
    Solid(Rgbft),
    Checker([Rgbft; 2]),
    /// `ring_scale` multiplies the ring radius (see `WOOD_TURBULENCE_RING_GAIN`).
    Wood { map: ColorMap, ring_scale: f32 },
}

/// POV-Ray 3.7's `wood` does not treat `turbulence` like other patterns. Rendering
/// `wood turbulence A` (no transform) and locating the ring crests along the x axis: the rings
/// come closer by a factor 1 + 5.9·A (A = 0.005: 2.9%, 0.01: 5.9%, 0.02: 10.4% over radius 10),
/// with the same figures for `octaves 1` and `3` and for `omega 0.01`, while `onion` and
/// `gradient` under the same turbulence keep their spacing. We have not found the mechanism,
/// so we reproduce the measured ring density on top of the ordinary vector warp; the extra
/// wobble POV-Ray shows (phase std ≈ 0.1 ring at A = 0.04) is not reproduced.
const WOOD_TURBULENCE_RING_GAIN: f64 = 5.9;

#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    pub pattern: PigmentPattern32,
    pub turbulence: Option<TurbulenceF32>,
    /// Render space (world minus the render origin) → pattern space.
    pub pattern_from_render: Affine3A,
}

/// `pattern_from_world ∘ translate(render_origin)`, composed in f64 then cast: the translation is
/// where the render origin sits in pattern space, so f32 keeps precision near the camera.
pub fn pattern_from_render(world_from_pattern_inverse: &DMat4, render_origin: DVec3) -> Affine3A {
    let m = *world_from_pattern_inverse * DMat4::from_translation(render_origin);
    Affine3A::from_mat4(m.as_mat4())
}

impl Pigment {
    pub fn from_desc(d: &PigmentDesc, render_origin: DVec3) -> Pigment {
        let pattern = match &d.pattern {
            PigmentPattern::Solid(c) => PigmentPattern32::Solid(Rgbft::from_desc(c)),
            PigmentPattern::Checker(a, b) => {
                PigmentPattern32::Checker([Rgbft::from_desc(a), Rgbft::from_desc(b)])
            }
            PigmentPattern::Wood(map) => PigmentPattern32::Wood {
                map: ColorMap::from_desc(map),
                ring_scale: d.turbulence.map_or(1.0, |t| {
                    (1.0 + WOOD_TURBULENCE_RING_GAIN * 0.5 * (t.amount.x + t.amount.y)) as f32
                }),
            },
        };
        Pigment {
            pattern,
            turbulence: d.turbulence.as_ref().map(TurbulenceF32::from_desc),
            pattern_from_render: pattern_from_render(&d.transform.inverse, render_origin),
        }
    }

    /// Pattern-space point for a render-space hit, turbulence applied.
    #[inline]
    fn pattern_point(&self, p_render: Vec3, q: PatternQuality) -> Vec3 {
        let p = self.pattern_from_render.transform_point3(p_render);
        match &self.turbulence {
            Some(t) => warp(p, t, q.max_octaves),
            None => p,
        }
    }
}

/// The pigment's colour at a render-space point.
#[inline]
pub fn eval_pigment(pig: &Pigment, p_render: Vec3, q: PatternQuality) -> Rgbft {
    match &pig.pattern {
        PigmentPattern32::Solid(c) => *c,
        PigmentPattern32::Checker(c) => c[checker(pig.pattern_point(p_render, q)) as usize],
        PigmentPattern32::Wood { map, ring_scale } => {
            let p = pig.pattern_point(p_render, q);
            map.lookup(wood(Vec3::new(p.x * ring_scale, p.y * ring_scale, p.z)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::desc::{Color, ColorMapEntry, Transform};

    fn scaled(s: DVec3) -> Transform {
        let m = DMat4::from_scale(s);
        Transform { matrix: m, inverse: m.inverse() }
    }

    #[test]
    fn render_origin_is_folded_into_the_pattern_transform() {
        let desc = PigmentDesc {
            pattern: PigmentPattern::Checker(Color::WHITE, Color::BLACK),
            turbulence: None,
            transform: scaled(DVec3::splat(2.0)),
        };
        let origin = DVec3::new(1000.25, 3.0, -500.5);
        let pig = Pigment::from_desc(&desc, origin);
        for w in [DVec3::new(1001.0, 0.0, -499.0), DVec3::new(998.9, 0.5, -503.7)] {
            let expect = checker((w / 2.0).as_vec3());
            let got = eval_pigment(&pig, (w - origin).as_vec3(), PatternQuality::default());
            assert_eq!(got, Rgbft::from_desc(if expect == 0 { &Color::WHITE } else { &Color::BLACK }));
        }
    }

    #[test]
    fn wood_without_turbulence_follows_the_map() {
        let desc = PigmentDesc {
            pattern: PigmentPattern::Wood(vec![
                ColorMapEntry { value: 0.0, color: Color::BLACK },
                ColorMapEntry { value: 1.0, color: Color::WHITE },
            ]),
            turbulence: None,
            transform: Transform::default(),
        };
        let pig = Pigment::from_desc(&desc, DVec3::ZERO);
        let c = eval_pigment(&pig, Vec3::new(0.25, 0.0, 3.0), PatternQuality::default());
        assert!((c.rgb - Vec3::splat(0.5)).abs().max_element() < 1e-6);
    }
}
