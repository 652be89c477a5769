//! Render-ready pigments: a closed enum evaluated per hit at a render-space point.
//!
//! Solid colours return before any transform or noise work; only turbulent patterns pay for noise.

use glam::{Affine3A, DMat4, Vec3};

use super::noise::{turbulence_lanes, warp_lanes, TurbulenceF32};
use super::pattern::{checker_lanes, wood_lanes, ColorMap, Rgbft, RgbftLanes};
use crate::lanes::{Lane, V3};
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
    /// Turbulence displaces wood cycloidally (see `wood_cycloidal`), not by the plain warp.
    Wood(ColorMap),
}

/// POV-Ray 3.7's `wood` does not take `turbulence` as a plain warp. Measured on renders of
/// `wood turbulence A` (no transform): the rings come closer by 1 + 5.9·A (A = 0.005: 2.9%,
/// 0.01: 5.9%, 0.02: 10.4%) whatever the octaves, while `onion` and `gradient` keep their
/// spacing, and the rings wobble far more than the warp predicts. Both fit a cycloidal
/// displacement, x' = x + sin(2π·A·(x + T_x)) with T the vector turbulence (5.9 ≈ 2π is its
/// slope at the origin). With it the DMFWood4 red channel differs from POV-Ray's by 0.035 per
/// pixel on average (0.043 with the warp and a ring-density factor; the rest is our noise).
#[inline(always)]
fn wood_cycloidal<L: Lane>(p: V3<L>, t: &TurbulenceF32, max_octaves: Option<u32>) -> V3<L> {
    let turb = turbulence_lanes(p, t, max_octaves);
    let (ax, ay) = (L::splat(t.amount.x), L::splat(t.amount.y));
    V3 { x: p.x + sin_turns((p.x + turb.x) * ax), y: p.y + sin_turns((p.y + turb.y) * ay), z: p.z }
}

/// `sin(2π·x)` by range reduction to one turn and an odd polynomial (max error 1e-6, against
/// `f32::sin`'s ~40 instructions and a libm call; two per wood hit were 3% of the seed scene).
#[inline(always)]
fn sin_turns<L: Lane>(x: L) -> L {
    // y in [-0.5, 0.5] turns, then fold to [-0.25, 0.25] where the polynomial is accurate.
    let y = x - x.map(f32::round);
    let (quarter, half) = (L::splat(0.25), L::splat(0.5));
    let y = L::select(quarter.lt(y), half - y, L::select(y.lt(-quarter), -half - y, y));
    let z = y * y;
    // Taylor coefficients of sin(2πy) up to y^11: (2π)^k / k!, alternating.
    let c = |v: f32| L::splat(v);
    let p = c(6.283_185_5)
        + z * (c(-41.341_7) + z * (c(81.605_25) + z * (c(-76.705_86) + z * (c(42.058_69) + z * c(-15.094_64)))));
    y * p
}

#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    pub pattern: PigmentPattern32,
    pub turbulence: Option<TurbulenceF32>,
    /// Render space (`scene::build::RenderFrame`) → pattern space.
    pub pattern_from_render: Affine3A,
    /// Error of a pattern-space point per render-space unit of the hit's distance from the
    /// camera (render space's origin), through `pattern_from_render`'s largest row. Measured on a
    /// floor 8.3e4 units from the camera: 0.07 f32 epsilons of the distance; a quarter epsilon
    /// covers that 4× over and moves checker edges by at most 0.1 pixel there. The checker
    /// widens its tolerance by this times the distance.
    pub slack_per_render: f32,
}

/// `pattern_from_world ∘ world_from_render`, composed in f64 then cast: its translation is
/// where the render origin sits in pattern space, so f32 keeps precision near the camera.
pub fn pattern_from_render(world_from_pattern_inverse: &DMat4, world_from_render: &DMat4) -> Affine3A {
    let m = *world_from_pattern_inverse * *world_from_render;
    Affine3A::from_mat4(m.as_mat4())
}

impl Pigment {
    pub fn from_desc(d: &PigmentDesc, world_from_render: &DMat4) -> Pigment {
        let pattern = match &d.pattern {
            PigmentPattern::Solid(c) => PigmentPattern32::Solid(Rgbft::from_desc(c)),
            PigmentPattern::Checker(a, b) => PigmentPattern32::Checker([Rgbft::from_desc(a), Rgbft::from_desc(b)]),
            PigmentPattern::Wood(map) => PigmentPattern32::Wood(ColorMap::from_desc(map)),
        };
        let pattern_from_render = pattern_from_render(&d.transform.inverse, world_from_render);
        let m = pattern_from_render.matrix3;
        let row_norm = (0..3).map(|r| m.row(r).abs().element_sum()).fold(0.0, f32::max);
        Pigment {
            pattern,
            turbulence: d.turbulence.as_ref().map(TurbulenceF32::from_desc),
            pattern_from_render,
            slack_per_render: 0.25 * f32::EPSILON * row_norm,
        }
    }

    /// Pattern-space point for a render-space hit, turbulence applied.
    #[inline(always)]
    fn pattern_point<L: Lane>(&self, p_render: V3<L>, q: PatternQuality) -> V3<L> {
        let p = p_render.transform_point(&self.pattern_from_render);
        match &self.turbulence {
            Some(t) => warp_lanes(p, t, q.max_octaves),
            None => p,
        }
    }
}

/// The pigment's colour at a render-space point.
#[inline]
pub fn eval_pigment(pig: &Pigment, p_render: Vec3, q: PatternQuality) -> Rgbft {
    eval_pigment_lanes(pig, V3::from_vec3(p_render), q).lane(0)
}

/// `eval_pigment` for one or eight render-space points.
#[inline(always)]
pub fn eval_pigment_lanes<L: Lane>(pig: &Pigment, p_render: V3<L>, q: PatternQuality) -> RgbftLanes<L> {
    match &pig.pattern {
        PigmentPattern32::Solid(c) => RgbftLanes::splat(*c),
        PigmentPattern32::Checker(c) => {
            let p = pig.pattern_point(p_render, q);
            let slack = p_render.max_abs() * L::splat(pig.slack_per_render);
            RgbftLanes::select(checker_lanes(p, slack), RgbftLanes::splat(c[1]), RgbftLanes::splat(c[0]))
        }
        PigmentPattern32::Wood(map) => {
            let p = p_render.transform_point(&pig.pattern_from_render);
            let p = match &pig.turbulence {
                Some(t) => wood_cycloidal(p, t, q.max_octaves),
                None => p,
            };
            map.lookup_lanes(wood_lanes(p))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn sin_turns_matches_sin() {
        for i in -20_000..20_000 {
            let x = i as f32 * 0.000_37;
            let want = (x as f64 * std::f64::consts::TAU).sin();
            assert!((sin_turns::<f32>(x) as f64 - want).abs() < 2e-6, "x = {x}");
        }
    }
    use crate::scene::desc::{Color, ColorMapEntry, Transform};
    use crate::shading::pattern::checker;

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
        let (origin, unit) = (DVec3::new(1000.25, 3.0, -500.5), 0.3);
        let world_from_render = DMat4::from_translation(origin) * DMat4::from_scale(DVec3::splat(unit));
        let pig = Pigment::from_desc(&desc, &world_from_render);
        for w in [DVec3::new(1001.0, 0.0, -499.0), DVec3::new(998.9, 0.5, -503.7)] {
            let expect = checker((w / 2.0).as_vec3());
            let got = eval_pigment(&pig, ((w - origin) / unit).as_vec3(), PatternQuality::default());
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
        let pig = Pigment::from_desc(&desc, &DMat4::IDENTITY);
        let c = eval_pigment(&pig, Vec3::new(0.25, 0.0, 3.0), PatternQuality::default());
        assert!((c.rgb - Vec3::splat(0.5)).abs().max_element() < 1e-6);
    }

    #[test]
    fn eight_lanes_match_one_lane_bit_for_bit() {
        use crate::lanes::F8;
        use crate::scene::desc::Turbulence;
        let map = vec![
            ColorMapEntry { value: 0.1, color: Color::WHITE },
            ColorMapEntry { value: 0.5, color: Color::BLACK },
            ColorMapEntry { value: 0.5, color: Color::WHITE },
            ColorMapEntry { value: 0.9, color: Color::BLACK },
        ];
        let turbulence = Some(Turbulence { amount: DVec3::new(0.04, 0.3, 0.1), octaves: 3, omega: 0.5, lambda: 2.0 });
        let pigments = [
            PigmentDesc {
                pattern: PigmentPattern::Wood(map.clone()),
                turbulence,
                transform: scaled(DVec3::new(0.05, 0.05, 1.0)),
            },
            PigmentDesc { pattern: PigmentPattern::Wood(map), turbulence: None, transform: Transform::default() },
            PigmentDesc {
                pattern: PigmentPattern::Checker(Color::WHITE, Color::BLACK),
                turbulence,
                transform: scaled(DVec3::splat(0.7)),
            },
        ];
        for desc in &pigments {
            let pig = Pigment::from_desc(desc, &DMat4::from_translation(DVec3::new(3.0, 1.0, -2.0)));
            for k in 0..500 {
                let p = |i: usize| {
                    let j = (k * 8 + i) as f32;
                    Vec3::new((j * 0.731).sin() * 7.0, (j * 0.377).cos() * 3.0, j * 0.013 - 2.0)
                };
                let wide = eval_pigment_lanes(&pig, V3::<F8>::from_lanes(p), PatternQuality::default());
                for i in 0..8 {
                    let one = eval_pigment(&pig, p(i), PatternQuality::default());
                    let w = wide.lane(i);
                    assert_eq!(w.rgb.to_array().map(f32::to_bits), one.rgb.to_array().map(f32::to_bits));
                    assert_eq!(
                        (w.filter.to_bits(), w.transmit.to_bits()),
                        (one.filter.to_bits(), one.transmit.to_bits())
                    );
                }
            }
        }
    }
}
