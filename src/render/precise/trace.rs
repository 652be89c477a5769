//! Recursive tracing in f64: `render::trace` with rays, hit points, geometric normals,
//! secondary-ray origins, shadow rays, reflection and refraction directions in f64.
//!
//! The pigment, the normal pattern (bumps) and the local lighting model are the f32 functions
//! (`eval_pigment`, `perturb_normal`, `render::shade`), fed the f64 hit point and vectors cast
//! to f32. Render space is centred on the camera, so that cast rounds by a relative 6e-8 of the
//! point's distance from the camera, like any f32 value, and is not amplified by anything: what
//! the f64 path removes is the error of the intersection itself, which grows as 1/cos for
//! grazing rays and moves the point along the ray.

use glam::{DVec3, Vec3};

use super::intersect::{HitD, SceneD};
use crate::geometry::lanes::V3;
use crate::geometry::precise::{offset_origin, shadow_t_max, RayD};
use crate::render::shade::{self, LightSample, LocalHit};
use crate::render::stats::RenderStats;
use crate::render::trace::{RayKind, ADC_BAILOUT, MAX_SHADOW_LAYERS};
use crate::render::Quality;
use crate::scene::material::Material;
use crate::shading::normal::perturb_normal;
use crate::shading::pattern::Rgbft;
use crate::shading::pigment::{eval_pigment, PatternQuality};

pub struct TracerD<'a> {
    pub scene: SceneD<'a>,
    pub quality: &'a Quality,
    pub stats: RenderStats,
}

/// A hit, ready for lighting.
struct SurfaceD<'a> {
    p: DVec3,
    /// Geometric normal turned towards the incoming ray.
    facing: DVec3,
    /// `facing` after the normal pattern; `facing` itself where there is none.
    normal: DVec3,
    entering: bool,
    material: &'a Material,
    ior: f64,
    pigment: Rgbft,
}

impl<'a> TracerD<'a> {
    pub fn new(scene: SceneD<'a>, quality: &'a Quality) -> TracerD<'a> {
        TracerD { scene, quality, stats: RenderStats::default() }
    }

    fn pattern_quality(&self) -> PatternQuality {
        PatternQuality { max_octaves: self.quality.max_octaves }
    }

    fn max_level(&self) -> u32 {
        self.quality.max_trace_level.unwrap_or(self.scene.scene.max_trace_level).max(1)
    }

    /// Colour seen along `ray`, as `Tracer::trace`.
    pub fn trace(&mut self, ray: &RayD, level: u32, weight: f32, kind: RayKind) -> Vec3 {
        self.stats.count_ray(kind, level);
        match self.scene.intersect(ray, f64::INFINITY, &mut self.stats) {
            Some(hit) => {
                let surface = self.surface(ray, &hit);
                self.shade(ray, &surface, level, weight)
            }
            None => self.scene.scene.background.rgb,
        }
    }

    fn surface(&self, ray: &RayD, hit: &HitD) -> SurfaceD<'a> {
        let scene = self.scene.scene;
        let p = ray.at(hit.t);
        let material_index = scene.material_of(hit.shape) as usize;
        let material = &scene.materials[material_index];
        let geometric = self.scene.normal_at(hit.shape, p);
        let entering = geometric.dot(ray.dir) < 0.0;
        let facing = if entering { geometric } else { -geometric };
        let p32 = p.as_vec3();
        let normal = match &material.normal {
            Some(n) => perturb_normal(n, p32, facing.as_vec3(), self.pattern_quality()).as_dvec3(),
            None => facing,
        };
        let pigment = eval_pigment(&material.pigment, p32, self.pattern_quality());
        SurfaceD { p, facing, normal, entering, material, ior: self.scene.geo.iors[material_index], pigment }
    }

    /// As `Tracer::shade_surface` with `Shadows::Trace`.
    fn shade(&mut self, ray: &RayD, s: &SurfaceD, level: u32, weight: f32) -> Vec3 {
        let scene = self.scene.scene;
        let finish = &s.material.finish;
        let c = s.pigment.rgb;
        let hit = LocalHit {
            color: V3::from_vec3(c),
            opacity: shade::opacity(s.pigment.filter, s.pigment.transmit),
            normal: V3::from_vec3(s.normal.as_vec3()),
            ray_dir: V3::from_vec3(ray.dir.as_vec3()),
        };
        let reflected = shade::reflect(hit.ray_dir, hit.normal);
        let mut color = shade::ambient(finish, scene.ambient_light, &hit);
        for (i, light) in scene.lights.iter().enumerate() {
            let position = self.scene.geo.lights[i];
            let Some(l) = light_direction(s, position) else { continue };
            let passed = if !self.quality.shadows || light.shadowless {
                Vec3::ONE
            } else {
                let origin = offset_origin(s.p, s.facing, l);
                let ray = RayD::new(origin, l);
                self.shadow(&ray, shadow_t_max(origin, position), position)
            };
            if passed == Vec3::ZERO {
                continue;
            }
            let sample =
                LightSample { dir: V3::from_vec3(l.as_vec3()), color: V3::from_vec3(light.color * passed), on: true };
            color = shade::add_light(finish, &hit, reflected, color, &sample);
        }
        let mut color = color.vec3();

        if level < self.max_level() {
            if finish.reflects() {
                let w = weight * finish.reflection.max_element();
                if w >= ADC_BAILOUT {
                    let dir = (ray.dir - 2.0 * ray.dir.dot(s.normal) * s.normal).normalize();
                    let r = RayD::new(offset_origin(s.p, s.facing, dir), dir);
                    color += finish.reflection * self.trace(&r, level + 1, w, RayKind::Reflected);
                }
            }
            let transmit = c * s.pigment.filter + Vec3::splat(s.pigment.transmit);
            let w = weight * transmit.max_element();
            if w >= ADC_BAILOUT {
                color += transmit * self.refract(ray, s, level, w);
            }
        }
        color
    }

    /// Snell's law in f64, total internal reflection as in `Tracer::refract`.
    fn refract(&mut self, ray: &RayD, s: &SurfaceD, level: u32, weight: f32) -> Vec3 {
        let eta = if s.entering { 1.0 / s.ior } else { s.ior };
        let cos_i = -ray.dir.dot(s.normal);
        let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        let dir = if eta == 1.0 {
            ray.dir
        } else if k < 0.0 {
            ray.dir + 2.0 * cos_i * s.normal
        } else {
            eta * ray.dir + (eta * cos_i - k.sqrt()) * s.normal
        };
        let dir = dir.normalize();
        let r = RayD::new(offset_origin(s.p, s.facing, dir), dir);
        self.trace(&r, level + 1, weight, RayKind::Refracted)
    }

    /// Light passed along a shadow ray, as `Tracer::shadow`.
    fn shadow(&mut self, ray: &RayD, t_max: f64, light: DVec3) -> Vec3 {
        self.stats.shadow_rays += 1;
        let scene = self.scene.scene;
        if !scene.features.transparency {
            let blocked = self.scene.occluded_towards(ray, t_max, light, &mut self.stats);
            return if blocked { Vec3::ZERO } else { Vec3::ONE };
        }
        let mut pass = Vec3::ONE;
        let (mut ray, mut t_max) = (*ray, t_max);
        for _ in 0..MAX_SHADOW_LAYERS {
            let Some(hit) = self.scene.intersect(&ray, t_max, &mut self.stats) else {
                return pass;
            };
            let p = ray.at(hit.t);
            if scene.casts_shadow(hit.shape) {
                let material = &scene.materials[scene.material_of(hit.shape) as usize];
                let pig = eval_pigment(&material.pigment, p.as_vec3(), self.pattern_quality());
                pass *= pig.rgb * pig.filter + Vec3::splat(pig.transmit);
                if pass.max_element() < ADC_BAILOUT {
                    return Vec3::ZERO;
                }
            }
            let n = self.scene.normal_at(hit.shape, p);
            let next = offset_origin(p, n, ray.dir);
            t_max = shadow_t_max(next, light);
            ray = RayD::new(next, ray.dir);
        }
        Vec3::ZERO
    }
}

/// The unit direction to a light, or `None` when it is behind the surface as the viewer sees
/// it, as `render::trace::light_direction`.
fn light_direction(s: &SurfaceD, light: DVec3) -> Option<DVec3> {
    let to_light = light - s.p;
    let dist = to_light.length();
    if dist == 0.0 {
        return None;
    }
    let l = to_light / dist;
    (s.normal.dot(l) > 0.0 && s.facing.dot(l) > 0.0).then_some(l)
}
