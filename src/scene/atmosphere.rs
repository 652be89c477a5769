//! What rays meet besides surfaces: the `sky_sphere` seen where they miss, and `fog` and
//! `rainbow` applied to every ray segment (primary, reflected and refracted, as POV-Ray does;
//! shadow rays are not fogged). Built from `SceneDesc` into render space (distances and
//! heights scaled by the render frame); evaluated by `render::trace`.
//!
//! A scene without any of them pays one predictable branch per ray (`Atmosphere::is_empty`).

use glam::{DMat4, Vec3};

use crate::camera::frame::RenderFrame;
use crate::desc::{FogDesc, RainbowDesc, SceneDesc, SkySphereDesc};
use crate::shading::pattern::{ColorMap, Rgbft};
use crate::shading::pigment::{eval_pigment, PatternQuality, Pigment};

/// Depth given to rays that miss everything: POV-Ray's maximum distance, so a constant fog
/// covers the sky completely.
pub const MISS_DEPTH: f32 = 1e7;

#[derive(Clone, Debug, Default)]
pub struct Atmosphere {
    pub sky: Option<SkySphere>,
    pub fogs: Vec<Fog>,
    pub rainbows: Vec<Rainbow>,
}

#[derive(Clone, Debug)]
pub struct SkySphere {
    /// Bottom layer first. Evaluated on the unit direction (world orientation: render space is
    /// only shifted and scaled), so the pigments are built with an identity render frame.
    pub layers: Vec<Pigment>,
    pub emission: Vec3,
}

#[derive(Clone, Copy, Debug)]
pub struct Fog {
    pub ground: bool,
    /// `distance`, render units.
    pub distance: f32,
    pub color: Rgbft,
    /// Ground fog: `fog_offset` as a render-space height along `up`, `fog_alt` in render units.
    pub offset: f32,
    pub alt: f32,
    pub up: Vec3,
}

#[derive(Clone, Debug)]
pub struct Rainbow {
    pub direction: Vec3,
    /// Inner edge and width, radians.
    pub start: f32,
    pub width: f32,
    pub distance: f32,
    pub jitter: f32,
    /// Unit vectors across `direction`: `up` (the arc's zero angle) and `right`.
    pub up: Vec3,
    pub right: Vec3,
    /// Halves of `arc_angle` and `falloff_angle`, radians.
    pub half_arc: f32,
    pub half_falloff: f32,
    pub map: ColorMap,
}

impl Atmosphere {
    pub fn build(desc: &SceneDesc, frame: &RenderFrame) -> Atmosphere {
        Atmosphere {
            sky: desc.sky_sphere.as_ref().map(SkySphere::build),
            fogs: desc.fogs.iter().filter(|f| f.distance > 0.0).map(|f| Fog::build(f, frame)).collect(),
            rainbows: desc.rainbows.iter().filter_map(|r| Rainbow::build(r, frame)).collect(),
        }
    }

    /// Whether rays see nothing but surfaces and the background colour.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.sky.is_none() && self.fogs.is_empty() && self.rainbows.is_empty()
    }

    /// Whether anything applies to rays between surfaces (fog, rainbow).
    #[inline]
    pub fn along_rays(&self) -> bool {
        !self.fogs.is_empty() || !self.rainbows.is_empty()
    }

    /// The colour of a ray that misses everything.
    pub fn miss(&self, dir: Vec3, background: Rgbft, q: PatternQuality) -> Vec3 {
        match &self.sky {
            Some(sky) => sky.eval(dir, background, q),
            None => background.rgb,
        }
    }

    /// `color` seen through the fogs and rainbows along a ray from `origin` along unit `dir`
    /// for `depth` render units (`MISS_DEPTH` for a miss).
    ///
    /// Fogs combine as POV-Ray 3.7 renders them (measured with two fogs and with transmit):
    /// what is behind is multiplied by every fog's transmittance, and each fog adds its colour
    /// times its own opacity, so layers add up rather than cover each other. A fog colour's
    /// transmit is a floor on its transmittance `T` (`transmit 0.3`: at least 30% of what is
    /// behind shows) and its filter tints what passes: the colour is
    /// `behind · T · (1 − filter + filter · C) + (1 − T) · C`, fitted to POV-Ray 3.7 to the
    /// unit in nine filter/transmit/distance cases over a coloured object.
    pub fn along(&self, origin: Vec3, dir: Vec3, depth: f32, color: Vec3) -> Vec3 {
        let mut passed = Vec3::ONE;
        let mut added = Vec3::ZERO;
        for fog in &self.fogs {
            let t = fog.transmittance(origin, dir, depth).max(fog.color.transmit.min(1.0));
            let filter = fog.color.filter;
            passed *= t * (Vec3::splat(1.0 - filter) + fog.color.rgb * filter);
            added += fog.color.rgb * (1.0 - t);
        }
        let mut color = color * passed + added;
        for rainbow in &self.rainbows {
            if let Some((c, amount)) = rainbow.color(dir) {
                let through = (-depth / rainbow.distance).exp();
                color = mix(color, c, amount * (1.0 - through));
            }
        }
        color
    }
}

/// `color` behind a fraction `amount` of a layer coloured `layer`: its filter tints and its
/// transmit passes what is behind, as in a pigment (POV-Ray's fog colour semantics: transmit
/// 0.3 shows at least 30% of the background).
#[inline]
fn mix(color: Vec3, layer: Rgbft, amount: f32) -> Vec3 {
    let behind = color * (layer.rgb * layer.filter + Vec3::splat(layer.transmit));
    let own = layer.rgb * (1.0 - layer.filter - layer.transmit);
    color * (1.0 - amount) + (own + behind) * amount
}

impl SkySphere {
    fn build(d: &SkySphereDesc) -> SkySphere {
        SkySphere {
            layers: d.pigments.iter().map(|p| Pigment::from_desc(p, &DMat4::IDENTITY)).collect(),
            emission: d.emission.as_vec3(),
        }
    }

    /// Layers over the background, bottom first: each shows where its filter and transmit
    /// are zero and lets the layers below through where they are not.
    pub fn eval(&self, dir: Vec3, background: Rgbft, q: PatternQuality) -> Vec3 {
        let mut color = background.rgb;
        for layer in &self.layers {
            let c = eval_pigment(layer, dir, q);
            color = mix(color, c, 1.0);
        }
        color * self.emission
    }
}

impl Fog {
    fn build(d: &FogDesc, frame: &RenderFrame) -> Fog {
        let up = d.up.normalize_or_zero();
        let up = if up == glam::DVec3::ZERO { glam::DVec3::Y } else { up };
        Fog {
            ground: d.fog_type == 2,
            distance: (d.distance * frame.per_unit) as f32,
            color: Rgbft::from_desc(&d.color),
            offset: ((d.offset - frame.origin.dot(up)) * frame.per_unit) as f32,
            alt: (d.alt * frame.per_unit) as f32,
            up: up.as_vec3(),
        }
    }

    /// The fraction of light that crosses the fog over `depth` along the ray.
    pub fn transmittance(&self, origin: Vec3, dir: Vec3, depth: f32) -> f32 {
        let density = if self.ground { self.ground_depth(origin, dir, depth) } else { depth };
        (-density / self.distance).exp()
    }

    /// ∫ density dt along the ray: density 1 below `offset`, `1 / (1 + ((h − offset)/alt)²)`
    /// above, integrated analytically over the heights the segment spans. (POV-Ray's manual
    /// writes `1 / (1 + (h − offset)/alt)²`, but 3.7 renders the form used here: measured on
    /// a ground fog seen from above it, the manual's form gives 23% less fog in the sky.)
    fn ground_depth(&self, origin: Vec3, dir: Vec3, depth: f32) -> f32 {
        let h0 = origin.dot(self.up);
        let dy = dir.dot(self.up);
        let alt = self.alt.max(1e-9);
        // Antiderivative of the density over height, 0 at the offset.
        let g = |h: f32| {
            let x = h - self.offset;
            if x <= 0.0 {
                x
            } else {
                alt * (x / alt).atan()
            }
        };
        let density = |h: f32| {
            let x = (h - self.offset).max(0.0) / alt;
            1.0 / (1.0 + x * x)
        };
        if dy.abs() < 1e-6 {
            return depth * density(h0);
        }
        let h1 = h0 + depth * dy;
        ((g(h1) - g(h0)) / dy).max(0.0)
    }
}

impl Rainbow {
    fn build(d: &RainbowDesc, frame: &RenderFrame) -> Option<Rainbow> {
        let direction = d.direction.normalize_or_zero();
        if direction == glam::DVec3::ZERO || d.width <= 0.0 {
            return None;
        }
        let mut up = d.up - direction * d.up.dot(direction);
        if up.length() < 1e-9 {
            up = direction.any_orthonormal_vector();
        }
        let up = up.normalize();
        let right = direction.cross(up);
        let distance = if d.distance > 0.0 { d.distance * frame.per_unit } else { f64::from(MISS_DEPTH) };
        Some(Rainbow {
            direction: direction.as_vec3(),
            start: (d.angle - d.width / 2.0).to_radians() as f32,
            width: d.width.to_radians() as f32,
            distance: distance as f32,
            jitter: d.jitter as f32,
            up: up.as_vec3(),
            right: right.as_vec3(),
            half_arc: (d.arc_angle / 2.0).to_radians() as f32,
            half_falloff: (d.falloff_angle.min(d.arc_angle) / 2.0).to_radians() as f32,
            map: ColorMap::from_desc(&d.color_map),
        })
    }

    /// The rainbow's colour along `dir` and how much of it shows (the arc's soft ends), or
    /// `None` outside its band or arc.
    pub fn color(&self, dir: Vec3) -> Option<(Rgbft, f32)> {
        let angle = dir.dot(self.direction).clamp(-1.0, 1.0).acos();
        let mut index = (angle - self.start) / self.width;
        if !(0.0..=1.0).contains(&index) {
            return None;
        }
        if self.jitter != 0.0 {
            let (r, _) = crate::shading::light::hash2(&[dir.x.to_bits(), dir.y.to_bits(), dir.z.to_bits()]);
            index += self.jitter * (r - 0.5);
        }
        let around = dir.dot(self.right).atan2(dir.dot(self.up)).abs();
        let amount = if around > self.half_arc {
            return None;
        } else if around > self.half_falloff && self.half_arc > self.half_falloff {
            1.0 - (around - self.half_falloff) / (self.half_arc - self.half_falloff)
        } else {
            1.0
        };
        Some((self.map.lookup(index.clamp(0.0, 1.0)), amount))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fog(ground: bool) -> Fog {
        Fog { ground, distance: 10.0, color: Rgbft::default(), offset: 0.0, alt: 1.0, up: Vec3::Y }
    }

    #[test]
    fn constant_fog_is_exponential_in_depth() {
        let f = fog(false);
        assert_eq!(f.transmittance(Vec3::ZERO, Vec3::Z, 0.0), 1.0);
        assert!((f.transmittance(Vec3::ZERO, Vec3::Z, 10.0) - (-1f32).exp()).abs() < 1e-6);
    }

    #[test]
    fn ground_fog_is_dense_below_its_offset_and_thins_above() {
        let f = fog(true);
        let below = f.transmittance(Vec3::new(0.0, -1.0, 0.0), Vec3::X, 10.0);
        assert!((below - (-1f32).exp()).abs() < 1e-5, "{below}");
        // At offset + alt the density is 1/2.
        let at_alt = f.transmittance(Vec3::new(0.0, 1.0, 0.0), Vec3::X, 10.0);
        assert!((at_alt - (-0.5f32).exp()).abs() < 1e-5, "{at_alt}");
        // Straight up from the ground through all of it: ∫0^∞ 1/(1+h²) dh = π/2.
        let up = f.transmittance(Vec3::ZERO, Vec3::Y, 1e7);
        assert!((up - (-std::f32::consts::FRAC_PI_2 / 10.0).exp()).abs() < 1e-4, "{up}");
    }

    #[test]
    fn fogs_add_their_colours_and_transmit_is_a_floor() {
        let f = |transmit: f32, rgb: f32| Fog {
            color: Rgbft { rgb: Vec3::splat(rgb), filter: 0.0, transmit },
            ..fog(false)
        };
        let one = Atmosphere { fogs: vec![f(0.3, 0.5)], ..Atmosphere::default() };
        // Seen through all of it: 30% of what is behind, 70% fog.
        let c = one.along(Vec3::ZERO, Vec3::Z, MISS_DEPTH, Vec3::ONE);
        assert!((c - Vec3::splat(0.3 + 0.35)).abs().max_element() < 1e-6, "{c}");
        // Thin: the floor does not apply.
        let t = (-0.1f32).exp();
        let c = one.along(Vec3::ZERO, Vec3::Z, 1.0, Vec3::ONE);
        assert!((c - Vec3::splat(t + 0.5 * (1.0 - t))).abs().max_element() < 1e-6, "{c}");
        let two = Atmosphere { fogs: vec![f(0.0, 0.5), f(0.0, 0.25)], ..Atmosphere::default() };
        let c = two.along(Vec3::ZERO, Vec3::Z, MISS_DEPTH, Vec3::ONE);
        assert!((c - Vec3::splat(0.75)).abs().max_element() < 1e-6, "{c}");
    }

    #[test]
    fn fog_colour_filter_and_transmit() {
        let grey = Rgbft { rgb: Vec3::splat(0.5), filter: 0.0, transmit: 0.3 };
        // Fully fogged: 70% fog, 30% of what is behind.
        let c = mix(Vec3::ONE, grey, 1.0);
        assert!((c - Vec3::splat(0.35 + 0.3)).abs().max_element() < 1e-6, "{c}");
        assert_eq!(mix(Vec3::ONE, grey, 0.0), Vec3::ONE);
    }
}
