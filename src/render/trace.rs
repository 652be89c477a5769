//! Recursive ray tracing (chapter 24.5): `trace` finds the nearest hit, `shade` lights it with
//! POV-Ray's finish model and recurses into reflected and refracted rays.
//!
//! The local model is the chapter's formula in POV-Ray's terms:
//! `I = ambient·C·ambient_light + Σ_lights S·L·(diffuse·C·(N·L)^brilliance + phong·(R·L)^phong_size
//!      + specular·(N·H)^(1/roughness)) + reflection·I_r + (filter·C + transmit)·I_t`,
//! where `S` is the light passed by the shadow ray (tinted by transparent objects on the way).

use glam::Vec3;

use crate::geometry::uv::UvMap;
use crate::lanes::V3;
use crate::ray::{offset_origin, shadow_t_max, Ray};
use crate::render::block_rows::BlockRows;
use crate::render::intersect::{Hit, HitShape};
use crate::render::precision::Precision;
use crate::render::shade::{self, LightSample, LocalHit};
pub use crate::render::stats::RayKind;
use crate::render::stats::RenderStats;
use crate::render::Quality;
use crate::scene::atmosphere::MISS_DEPTH;
use crate::scene::build::{Light, Scene, ShapeKind};
use crate::scene::material::{Blend, Material, Select};
use crate::shading::light::{self, AreaGrid};
use crate::shading::normal::perturb_normal;
use crate::shading::pattern::Rgbft;
use crate::shading::pigment::{eval_pigment, eval_surface_pigment_lanes, surface_pattern_value, PatternQuality};

/// POV-Ray's `adc_bailout`: rays that could change the pixel by less than one 8-bit step are
/// not traced.
pub(crate) const ADC_BAILOUT: f32 = 1.0 / 255.0;
/// Transparent surfaces a shadow ray may pass before it counts as blocked.
pub(crate) const MAX_SHADOW_LAYERS: u32 = 16;

pub struct Tracer<'a> {
    pub scene: &'a Scene,
    pub quality: &'a Quality,
    pub stats: RenderStats,
    /// Scratch for adaptive area-light sampling (`light::adaptive_visibility`), kept between
    /// shading points so no point allocates.
    area_cache: Vec<Option<Vec3>>,
    /// A packet block's working rows (`render::packet`), made on the first block and reused
    /// by every later one: built zeroed per 8×8 block, they were about 15 KB of stores a block.
    pub(crate) block: Option<Box<BlockRows>>,
}

impl<'a> Tracer<'a> {
    pub fn new(scene: &'a Scene, quality: &'a Quality) -> Tracer<'a> {
        Tracer { scene, quality, stats: RenderStats::default(), area_cache: Vec::new(), block: None }
    }

    #[inline]
    pub fn pattern_quality(&self) -> PatternQuality {
        PatternQuality { max_octaves: self.quality.max_octaves }
    }

    /// Whether nearest hits are re-solved in f64 (`Precision::F64`).
    #[inline]
    pub fn refines(&self) -> bool {
        self.quality.precision == Precision::F64
    }

    fn max_level(&self) -> u32 {
        self.quality.max_trace_level.unwrap_or(self.scene.max_trace_level).max(1)
    }

    /// Colour seen along `ray`. `level` is 1 for primary rays; `weight` is how much this ray can
    /// still change the pixel; `inside_ior` is the index of refraction the ray travels in.
    pub fn trace(&mut self, ray: &Ray, level: u32, weight: f32, kind: RayKind) -> Vec3 {
        self.trace_limited(ray, f32::INFINITY, level, weight, kind)
    }

    /// A primary ray that sees only what lies nearer than `max` (a mesh camera's
    /// `max_distance`; ∞ for every other camera).
    pub fn trace_within(&mut self, ray: &Ray, max: f32, kind: RayKind) -> Vec3 {
        self.trace_limited(ray, max, 1, 1.0, kind)
    }

    #[inline(always)]
    fn trace_limited(&mut self, ray: &Ray, max: f32, level: u32, weight: f32, kind: RayKind) -> Vec3 {
        self.stats.count_ray(kind, level);
        let hit = self.nearest_hit(ray, max);
        self.shade_hit(ray, hit.as_ref(), level, weight)
    }

    /// The nearest hit nearer than `max` as `trace` shades it (refined in f64 where the
    /// tracer refines), not shaded.
    #[inline(always)]
    pub fn nearest_hit(&mut self, ray: &Ray, max: f32) -> Option<Hit> {
        match self.scene.intersect(ray, max, &mut self.stats) {
            Some(hit) if self.refines() => Some(self.scene.refine(ray, hit)),
            hit => hit,
        }
    }

    /// The colour of `ray` given its nearest hit (refined already): shaded, or the background
    /// and sky where it missed, seen through fog and rainbows.
    #[inline]
    pub fn shade_hit(&mut self, ray: &Ray, hit: Option<&Hit>, level: u32, weight: f32) -> Vec3 {
        let color = match hit {
            Some(hit) => self.shade(ray, hit, level, weight),
            None if self.scene.atmosphere.is_empty() => return self.scene.background.rgb,
            None => self.sky(ray),
        };
        if !self.scene.atmosphere.along_rays() {
            return color;
        }
        self.through_atmosphere(ray, hit, color)
    }

    /// Out of line: most scenes have no sky sphere.
    #[inline(never)]
    fn sky(&self, ray: &Ray) -> Vec3 {
        self.scene.atmosphere.miss(ray.dir, self.scene.background, self.pattern_quality())
    }

    /// Out of line: most scenes have no fog or rainbow.
    #[inline(never)]
    fn through_atmosphere(&self, ray: &Ray, hit: Option<&Hit>, color: Vec3) -> Vec3 {
        let depth = hit.map_or(MISS_DEPTH, |h| h.t);
        self.scene.atmosphere.along(ray.origin, ray.dir, depth, color)
    }

    fn shade(&mut self, ray: &Ray, hit: &Hit, level: u32, weight: f32) -> Vec3 {
        let surface = self.surface(ray, hit);
        self.shade_surface(ray, &surface, level, weight, Shadows::Trace)
    }

    /// Everything about a hit that lighting needs, computed once.
    #[inline]
    pub fn surface(&self, ray: &Ray, hit: &Hit) -> Surface<'a> {
        let scene = self.scene;
        let p = ray.at(hit.t);
        let mut material = &scene.materials[scene.material_of(hit.shape) as usize];
        let geometric = scene.normal_at(hit.shape, p);
        // POV-Ray shades the side the ray sees: flip the normal towards the viewer.
        let entering = geometric.dot(ray.dir) < 0.0;
        if let (false, Some(inside)) = (entering, material.inside) {
            material = &scene.materials[inside as usize];
        }
        let facing = if entering { geometric } else { -geometric };
        self.dressed(p, facing, entering, hit.shape, material)
    }

    /// `surface` as `material` of a pattern of materials shows it.
    fn surface_as<'s>(&self, s: &Surface<'s>, material: &'s Material) -> Surface<'s> {
        self.dressed(s.p, s.facing, s.entering, s.shape, material)
    }

    /// A hit's surface in `material`: its normal pattern and pigment at `p`.
    #[inline(always)]
    fn dressed<'s>(
        &self,
        p: Vec3,
        facing: Vec3,
        entering: bool,
        shape: HitShape,
        material: &'s Material,
    ) -> Surface<'s> {
        let normal = match &material.normal {
            Some(n) => perturb_normal(n, p, facing, self.pattern_quality()),
            None => facing,
        };
        let outward = if entering { facing } else { -facing };
        let pigment = self.pigment_at(material, shape, p, outward);
        Surface { p, facing, normal, entering, material, pigment, shape }
    }

    /// `material`'s pigment at hit point `p` of `shape` (unit outward normal `outward`, which
    /// `slope` reads): in 3-D pattern space, or at the surface's (u, v, 0) for a uv-mapped
    /// material.
    #[inline(always)]
    fn pigment_at(&self, material: &Material, shape: HitShape, p: Vec3, outward: Vec3) -> Rgbft {
        match &material.uv {
            None => {
                let (p, n) = (V3::from_vec3(p), V3::from_vec3(outward));
                eval_surface_pigment_lanes(&material.pigment, p, n, self.pattern_quality()).lane(0)
            }
            Some(uv) => self.uv_pigment(material, uv, shape, p),
        }
    }

    /// Out of line: most materials are not uv-mapped. (u, v) become the world point
    /// (u, v, 0) seen from render space, so the pigment's own transforms apply to them.
    #[inline(never)]
    fn uv_pigment(&self, material: &Material, uv: &UvMap, shape: HitShape, p: Vec3) -> Rgbft {
        let scene = self.scene;
        let face = match shape {
            // A prism's faces are its sides and caps, not a mesh's.
            HitShape::Face { prim, face } if scene.prims[prim as usize].kind != ShapeKind::Prism => {
                let data = &scene.meshes[scene.prims[prim as usize].index as usize].data;
                let t = &data.triangles[face as usize];
                let corners = [t.v0, t.v0 + t.e1, t.v0 + t.e2].map(|v| v.as_dvec3());
                data.source_face.get(face as usize).map(|&f| (f as usize, corners))
            }
            _ => None,
        };
        let st = uv.uv(p.as_dvec3(), face);
        let q = scene.frame.point(glam::DVec3::new(st.x, st.y, 0.0)).as_vec3();
        eval_pigment(&material.pigment, q, self.pattern_quality())
    }

    /// Lights `surface` and recurses into reflection and refraction. `shadows` says whether
    /// shadow rays are traced here or were traced already, as packets (`render::packet`).
    pub fn shade_surface(&mut self, ray: &Ray, surface: &Surface, level: u32, weight: f32, shadows: Shadows) -> Vec3 {
        if let Some(blend) = &surface.material.blend {
            return self.shade_blend(ray, surface, blend, level, weight, shadows);
        }
        let Surface { p, facing, normal, entering, material, pigment, .. } = *surface;
        let finish = &material.finish;
        let c = pigment.rgb;
        let (mut color, reflected_dir) = self.lit(ray, surface, shadows);

        if level < self.max_level() {
            let reflection = self.reflect_into(ray, surface, reflected_dir, level, weight, &mut color);
            let mut transmit = c * pigment.filter + Vec3::splat(pigment.transmit);
            if finish.conserve_energy {
                transmit *= (Vec3::ONE - reflection).max(Vec3::ZERO);
            }
            let w = weight * transmit.max_element();
            if w >= ADC_BAILOUT {
                color += transmit * self.refract(ray, p, facing, normal, entering, material.ior, level, w);
            }
        }
        faded(color, material, ray, p, entering)
    }

    /// Ambient and every light's diffuse and highlights at `surface`, with the mirror direction.
    #[inline(always)]
    fn lit(&mut self, ray: &Ray, surface: &Surface, shadows: Shadows) -> (Vec3, Vec3) {
        let scene = self.scene;
        let Surface { p, facing, normal, material, pigment, .. } = *surface;
        let finish = &material.finish;
        let hit = LocalHit {
            color: V3::from_vec3(pigment.rgb),
            opacity: shade::opacity(pigment.filter, pigment.transmit),
            normal: V3::from_vec3(normal),
            ray_dir: V3::from_vec3(ray.dir),
        };
        let reflected = shade::reflect(hit.ray_dir, hit.normal);
        let mut color = shade::ambient(finish, scene.ambient_light, &hit);
        for (i, light) in scene.lights.iter().enumerate() {
            if !material.lit_by(i) {
                continue;
            }
            let (l, passed) = match shadows {
                Shadows::Given(lit) => {
                    let l = lit[i];
                    if l == Vec3::ZERO {
                        continue;
                    }
                    (l, Vec3::ONE)
                }
                Shadows::Trace if !light.is_point() => {
                    let Some(lit) = self.light_arriving(ray, surface, i, light) else { continue };
                    lit
                }
                Shadows::Trace => {
                    let Some(l) = light_direction(surface, light.position) else { continue };
                    let passed = if !self.quality.shadows || light.shadowless {
                        Vec3::ONE
                    } else {
                        self.shadow(&shadow_ray(p, facing, l, light.position))
                    };
                    if passed == Vec3::ZERO {
                        continue;
                    }
                    (l, passed)
                }
            };
            let sample = LightSample { dir: V3::from_vec3(l), color: V3::from_vec3(light.color * passed), on: true };
            color = shade::add_light(finish, &hit, reflected, color, &sample);
        }
        (color.vec3(), reflected.vec3())
    }

    /// Adds the finish's reflection (a traced ray) to `color`; returns how much it reflects.
    #[inline(always)]
    fn reflect_into(
        &mut self,
        ray: &Ray,
        surface: &Surface,
        reflected_dir: Vec3,
        level: u32,
        weight: f32,
        color: &mut Vec3,
    ) -> Vec3 {
        let Surface { p, facing, normal, material, pigment, .. } = *surface;
        let finish = &material.finish;
        let mut reflection = Vec3::ZERO;
        if finish.reflects() {
            let exponent;
            (reflection, exponent) = finish.reflection_at(-ray.dir.dot(normal), pigment.rgb, material.ior);
            let w = weight * reflection.max_element();
            if w >= ADC_BAILOUT {
                let r = Ray::new(offset_origin(p, facing, reflected_dir), reflected_dir.normalize());
                let mut seen = self.trace(&r, level + 1, w, RayKind::Reflected);
                if exponent != 1.0 {
                    // Measured on POV-Ray 3.7 (a mirror of a grey background, 0.25):
                    // exponent 0.5 shows 0.063, exponent 2 shows 0.50: seen^(1/exponent).
                    seen = seen.max(Vec3::ZERO).powf(1.0 / exponent);
                }
                *color += reflection * seen;
            }
        }
        reflection
    }

    /// Layered textures (`texture { A } texture { B }`), each layer shaded with its own finish,
    /// top first, as POV-Ray 3.7 does (measured on a red diffuse layer under partly
    /// transparent ones, tests/reference/scenes/layers.pov): a layer's ambient, diffuse and
    /// highlights (its own pigment's opacity weighting ambient and diffuse, not the
    /// highlights) are dimmed by what the layers above let through (filter tinted, transmit
    /// not), but its reflection is added whole, untinted, once any light reaches the layer;
    /// layers under an opaque one are not seen at all; what all the layers let through
    /// refracts once, into the object. Each layer is lit and reflects by its own normal (the
    /// surface's where it has none), and the refraction takes the top layer's
    /// (tests/reference/scenes/layers_normal.pov).
    #[inline(never)]
    fn shade_layers(
        &mut self,
        ray: &Ray,
        surface: &Surface,
        layers: &[Material],
        level: u32,
        weight: f32,
        shadows: Shadows,
    ) -> Vec3 {
        let Surface { p, facing, normal, entering, material, .. } = *surface;
        let mut above = Vec3::ONE;
        let mut color = Vec3::ZERO;
        for layer in layers.iter().rev() {
            let outward = if entering { facing } else { -facing };
            let pigment = self.pigment_at(layer, surface.shape, p, outward);
            // Each layer is lit by its own normal; `normal`, the top layer's, refracts.
            let normal = match &layer.normal {
                Some(n) => perturb_normal(n, p, facing, self.pattern_quality()),
                None => facing,
            };
            let s = Surface { material: layer, pigment, normal, ..*surface };
            let (lit, reflected_dir) = self.lit(ray, &s, shadows);
            color += above * lit;
            if level < self.max_level() {
                self.reflect_into(ray, &s, reflected_dir, level, weight, &mut color);
            }
            above *= pigment.rgb * pigment.filter + Vec3::splat(pigment.transmit);
            if above == Vec3::ZERO {
                break;
            }
        }
        let w = weight * above.max_element();
        if level < self.max_level() && w >= ADC_BAILOUT {
            color += above * self.refract(ray, p, facing, normal, entering, material.ior, level, w);
        }
        faded(color, material, ray, p, entering)
    }

    /// Out of line: most materials are not patterns of materials. Each material the pattern
    /// shows at the hit is shaded whole (its normal, finish and recursion) and the colours
    /// blended by the pattern's weights, as POV-Ray blends a `texture_map`.
    #[inline(never)]
    fn shade_blend<'s>(
        &mut self,
        ray: &Ray,
        surface: &Surface<'s>,
        blend: &'s Blend,
        level: u32,
        weight: f32,
        shadows: Shadows,
    ) -> Vec3 {
        if blend.select == Select::Layers {
            return self.shade_layers(ray, surface, &blend.entries, level, weight, shadows);
        }
        let outward = if surface.entering { surface.facing } else { -surface.facing };
        let v = surface_pattern_value(&blend.selector, surface.p, outward, self.pattern_quality());
        let mut color = Vec3::ZERO;
        blend.for_each_weight(v, |i, w| {
            let s = self.surface_as(surface, &blend.entries[i]);
            color += w * self.shade_surface(ray, &s, level, weight * w, shadows);
        });
        color
    }

    /// The colour arriving through a transparent surface: Snell's law with the chapter's
    /// formula; under total internal reflection the ray reflects instead, as in POV-Ray.
    #[allow(clippy::too_many_arguments)]
    fn refract(
        &mut self,
        ray: &Ray,
        p: Vec3,
        facing: Vec3,
        normal: Vec3,
        entering: bool,
        ior: f32,
        level: u32,
        weight: f32,
    ) -> Vec3 {
        // n = n1/n2 across the surface; rays leave an object into air (ior 1).
        let eta = if entering { 1.0 / ior } else { ior };
        let cos_i = -ray.dir.dot(normal);
        let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        let dir = if eta == 1.0 {
            ray.dir
        } else if k < 0.0 {
            // Total internal reflection.
            ray.dir + 2.0 * cos_i * normal
        } else {
            eta * ray.dir + (eta * cos_i - k.sqrt()) * normal
        };
        let dir = dir.normalize();
        let r = Ray::new(offset_origin(p, facing, dir), dir);
        self.trace(&r, level + 1, weight, RayKind::Refracted)
    }

    /// For a light that is not a plain point light: the unit direction it arrives from at
    /// `surface` and the fraction of its colour that arrives (spot or cylinder falloff, fading,
    /// and what its shadow rays pass), or `None` when none does. Kept out of line so that
    /// `shade_surface`, which point-light scenes run per pixel, stays as small as before.
    #[inline(never)]
    fn light_arriving(&mut self, ray: &Ray, surface: &Surface, index: usize, light: &Light) -> Option<(Vec3, Vec3)> {
        let p = surface.p;
        // Direction to the light, and where shadow rays towards it end.
        let (l, target) = if light.parallel {
            let l = -light.axis;
            (l, p + l * (light.position - p).dot(l))
        } else {
            let to = light.position - p;
            let dist = to.length();
            if dist == 0.0 {
                return None;
            }
            (to / dist, light.position)
        };
        if !(surface.normal.dot(l) > 0.0 && surface.facing.dot(l) > 0.0) {
            return None;
        }
        let mut factor = light::beam_factor(light.beam, light.axis, light.tightness, p - light.position);
        if light.fade_distance > 0.0 {
            factor *= light::fade((light.position - p).length(), light.fade_distance, light.fade_power);
        }
        if factor <= 0.0 {
            return None;
        }
        let mut passed = Vec3::splat(factor);
        if self.quality.shadows && !light.shadowless {
            passed *= match light.area {
                Some(grid) => self.area_shadow(ray, surface, index, light, grid),
                // A parallel light's shadows start at its plane: parts of the scene beyond it
                // neither cast nor receive them (POV-Ray 3.7).
                None if light.parallel && (target - p).dot(l) <= 0.0 => Vec3::ONE,
                None => self.shadow(&shadow_ray(p, surface.facing, l, target)),
            };
        }
        (passed != Vec3::ZERO).then_some((l, passed))
    }

    /// The light passed from an area light: one shadow ray per grid point (single rays, not
    /// packets: each shading point has its own targets), averaged, or POV-Ray's adaptive
    /// corner-first subdivision with `adaptive N`. Jitter comes from a hash of the hit point,
    /// the ray's direction (which stand for the pixel, sample and frame), the light and the
    /// grid point, so an image is the same at any thread count.
    #[inline(never)]
    fn area_shadow(&mut self, ray: &Ray, s: &Surface, index: usize, light: &Light, grid: AreaGrid) -> Vec3 {
        let grid = grid.capped(self.quality.max_area_samples);
        let (a1, a2) = grid.axes(s.p - light.position);
        let seed = [
            s.p.x.to_bits(),
            s.p.y.to_bits(),
            s.p.z.to_bits(),
            ray.dir.x.to_bits(),
            ray.dir.y.to_bits(),
            ray.dir.z.to_bits(),
            index as u32,
        ];
        let centre = light.position;
        let sample = |tracer: &mut Tracer, i: u32, j: u32| -> Vec3 {
            let jitter = if grid.jitter {
                let mut words = [0u32; 8];
                words[..7].copy_from_slice(&seed);
                words[7] = j * grid.size1 + i;
                light::hash2(&words)
            } else {
                (0.5, 0.5)
            };
            let target = centre + grid.offset(a1, a2, i, j, jitter);
            let to = target - s.p;
            let dist = to.length();
            if dist == 0.0 {
                return Vec3::ONE;
            }
            let l = to / dist;
            // A point of the light behind the surface lights nothing there.
            if s.facing.dot(l) <= 0.0 {
                return Vec3::ZERO;
            }
            tracer.shadow(&shadow_ray(s.p, s.facing, l, target))
        };
        match grid.adaptive {
            Some(min_depth) => {
                let mut cache = std::mem::take(&mut self.area_cache);
                let v = light::adaptive_visibility(grid.size1, grid.size2, min_depth, &mut cache, &mut |i, j| {
                    sample(self, i, j)
                });
                self.area_cache = cache;
                v
            }
            None => {
                let mut sum = Vec3::ZERO;
                for j in 0..grid.size2 {
                    for i in 0..grid.size1 {
                        sum += sample(self, i, j);
                    }
                }
                sum / (grid.size1 * grid.size2) as f32
            }
        }
    }

    /// Light from a point light passed along `shadow`: one for a clear path, zero when blocked,
    /// tinted by the filter and transmit of transparent surfaces on the way.
    fn shadow(&mut self, shadow: &ShadowRay) -> Vec3 {
        self.stats.shadow_rays += 1;
        let scene = self.scene;
        if !scene.features.transparency {
            let blocked = scene.occluded_towards(&shadow.ray, shadow.t_max, shadow.light, &mut self.stats);
            return if blocked { Vec3::ZERO } else { Vec3::ONE };
        }
        let mut pass = Vec3::ONE;
        let mut ray = shadow.ray;
        let mut t_max = shadow.t_max;
        for _ in 0..MAX_SHADOW_LAYERS {
            let Some(hit) = scene.intersect(&ray, t_max, &mut self.stats) else {
                return pass;
            };
            let p = ray.at(hit.t);
            let n = scene.normal_at(hit.shape, p);
            if scene.casts_shadow(hit.shape) {
                let material = &scene.materials[scene.material_of(hit.shape) as usize];
                let pig = self.pigment_at(material, hit.shape, p, n);
                pass *= pig.rgb * pig.filter + Vec3::splat(pig.transmit);
                // Leaving a fading object: the light crossed it since the last surface.
                if let (Some(fade), true) = (&material.fade, n.dot(ray.dir) > 0.0) {
                    pass *= fade.attenuation(hit.t * ray.dir.length());
                }
                if pass.max_element() < ADC_BAILOUT {
                    return Vec3::ZERO;
                }
            }
            let next = offset_origin(p, n, ray.dir);
            t_max = shadow_t_max(next, shadow.light);
            ray = Ray::new(next, ray.dir);
        }
        Vec3::ZERO
    }
}

/// What `surface` computes for a hit.
#[derive(Clone, Copy)]
pub struct Surface<'a> {
    pub p: Vec3,
    /// Geometric normal turned towards the incoming ray.
    pub facing: Vec3,
    /// `facing` after the normal pattern (bumps).
    pub normal: Vec3,
    /// Whether the ray comes from outside (against the outward normal).
    pub entering: bool,
    pub material: &'a Material,
    pub pigment: Rgbft,
    /// What was hit (for a uv-mapped material's surface coordinates).
    pub shape: HitShape,
}

/// Where light visibility comes from while shading.
#[derive(Clone, Copy)]
pub enum Shadows<'p> {
    /// Trace a shadow ray per light now.
    Trace,
    /// Already traced (opaque scenes, as packets): per light in scene order, the unit direction
    /// to a light that reaches the point unblocked, or zero.
    Given(&'p [Vec3]),
}

/// A shadow ray from a surface towards a light, and where it must stop.
#[derive(Clone, Copy, Debug)]
pub struct ShadowRay {
    pub ray: Ray,
    pub t_max: f32,
    pub light: Vec3,
}

/// The unit direction from a surface point to a light, or `None` when the light is behind the
/// surface as the viewer sees it (or on the point itself).
#[inline]
pub fn light_direction(s: &Surface, light: Vec3) -> Option<Vec3> {
    let to_light = light - s.p;
    let dist = to_light.length();
    if dist == 0.0 {
        return None;
    }
    let l = to_light / dist;
    (s.normal.dot(l) > 0.0 && s.facing.dot(l) > 0.0).then_some(l)
}

/// The shadow ray from `p` (geometric normal `facing`) along `l` to a light. Packets and single
/// rays both build their shadow rays here, so they test the same rays bit for bit.
#[inline]
pub fn shadow_ray(p: Vec3, facing: Vec3, l: Vec3, light: Vec3) -> ShadowRay {
    let origin = offset_origin(p, facing, l);
    ShadowRay { ray: Ray::new(origin, l), t_max: shadow_t_max(origin, light), light }
}

/// `color` seen at `p` on `ray`: where the ray leaves the object, what is seen there travelled
/// through it from the ray's origin, dimmed by its interior's `fade_distance`/`fade_power`.
#[inline(always)]
fn faded(color: Vec3, material: &Material, ray: &Ray, p: Vec3, entering: bool) -> Vec3 {
    match &material.fade {
        Some(fade) if !entering => color * fade.attenuation((p - ray.origin).length()),
        _ => color,
    }
}
