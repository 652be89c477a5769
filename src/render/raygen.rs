//! Primary rays: how the renderer turns a camera and a pixel sample into rays.

use glam::{DVec3, Vec3};

use super::blur::BlurStop;
use super::reproject::Pinhole;
use crate::camera::lens::{self, LensRays};
use crate::camera::Camera;
use crate::desc::{Lens, Projection};
use crate::lanes::{Lane, F8, V3};
use crate::ray::Ray;
use crate::scene::build::Scene;
use crate::shading::normal::{self, NormalF32};
use crate::shading::pigment::PatternQuality;

use super::Quality;

/// Camera vectors in render space, f32, and the lens for projections other than plain
/// perspective.
///
/// The plain perspective camera keeps its f32 eight-lane ray code (the seed scene's bits).
/// Every other projection, focal blur and a camera `normal` make each ray in f64
/// (`camera::lens`, then `LensSample`) and round
/// it to f32 once; packets build their lanes from those same single rays, so packets and
/// single rays trace the same bits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RayGen<'a> {
    pub(super) origin: Vec3,
    pub(super) direction: Vec3,
    pub(super) right: Vec3,
    pub(super) up: Vec3,
    /// `None`: POV-Ray's default perspective camera without blur or `normal`.
    pub(super) lens: Option<LensRays<'a>>,
    /// Blur rays averaged per sample (1 without focal blur), after the quality cap; a mesh
    /// camera's rays per pixel.
    pub(super) blur_samples: u32,
    /// When a pixel's blur rays may stop short of `blur_samples` (focal blur's adaptive
    /// sampling); `None`: all are taken.
    pub(super) blur_stop: Option<BlurStop>,
    /// How far primary rays reach (render units): a mesh camera's `max_distance`, else ∞.
    pub(super) max_distance: f32,
    /// The camera's `normal` (its rays then go through `lens`), and the octave cap for it.
    pub(super) normal: Option<&'a NormalF32>,
    pub(super) max_octaves: Option<u32>,
}

impl<'a> RayGen<'a> {
    pub(crate) fn new(camera: &Camera, scene: &'a Scene, quality: &Quality) -> RayGen<'a> {
        let frame = &scene.frame;
        let normal = scene.camera_normal.as_deref();
        let lens = (camera.lens != Lens::default() || normal.is_some()).then(|| {
            LensRays::new(
                &camera.lens,
                (frame.point(camera.location), camera.location),
                frame.vector(camera.direction),
                frame.vector(camera.right),
                frame.vector(camera.up),
                frame.per_unit,
            )
            .with_mesh(scene.camera_mesh.as_deref())
        });
        let max_distance = match camera.lens.projection {
            Projection::Mesh { max_distance, .. } if max_distance > 0.0 => (max_distance * frame.per_unit) as f32,
            _ => f32::INFINITY,
        };
        let blur_samples = camera.lens.blur_samples(quality.max_blur_samples);
        // A mesh camera's rays are its faces', not samples of one blur: all are taken.
        let blur_stop = match camera.lens.projection {
            Projection::Mesh { .. } => None,
            _ => camera.lens.blur.as_ref().and_then(|b| BlurStop::new(b, blur_samples)),
        };
        RayGen {
            origin: frame.point(camera.location).as_vec3(),
            direction: frame.vector(camera.direction).as_vec3(),
            right: frame.vector(camera.right).as_vec3(),
            up: frame.vector(camera.up).as_vec3(),
            lens,
            blur_samples,
            blur_stop,
            max_distance,
            normal,
            max_octaves: quality.max_octaves,
        }
    }

    /// POV-Ray's perspective ray through image coordinates `u, v` in [0, 1] (v down).
    #[inline]
    pub(super) fn ray(&self, u: f32, v: f32) -> Ray {
        Ray::new(self.origin, self.dir_lanes(u, v).vec3())
    }

    /// The unit directions of `ray` for one or eight pixels, with the same operations.
    #[inline(always)]
    pub(super) fn dir_lanes<L: Lane>(&self, u: L, v: L) -> V3<L> {
        let half = L::splat(0.5);
        let d = V3::splat(self.direction)
            .add(V3::splat(self.right).scale(u - half))
            .add(V3::splat(self.up).scale(half - v));
        d.normalize()
    }

    /// The plain perspective camera's vectors in render space, `None` for every other
    /// projection and for focal blur (whose rays do not meet in one point).
    pub(crate) fn pinhole(&self) -> Option<Pinhole> {
        let Self { origin, direction, right, up, .. } = *self;
        self.lens.is_none().then(|| Pinhole::new(origin, direction, right, up))
    }

    /// Whether blocks of this camera's rays may be traced as packets: every pixel must have a
    /// ray (fisheye and omnimax leave corners black, so they go through single rays).
    pub(crate) fn packets(&self) -> bool {
        self.lens.is_none_or(|l| l.covers_image())
    }

    /// The ray of blur sample `s` of sub-sample (sx, sy) of pixel (x, y) through a lens
    /// (`self.lens` is `Some`); `None` where the projection has no ray.
    pub(crate) fn lens_ray(&self, p: &PixelSample, s: u32) -> Option<Ray> {
        let mut ray = self.lens_ray_untilted(p, s)?;
        if let Some(nrm) = self.normal {
            ray.tilt(normal::perturb_normal(nrm, ray.screen_point(), ray.unit_dir(), self.pattern_quality()));
        }
        ray.finish()
    }

    /// `lens_ray` for eight samples at once: the camera `normal` is evaluated eight lanes
    /// wide, with the operations `lens_ray` applies to each, so every lane has its single
    /// ray's bits.
    pub(crate) fn lens_rays8(&self, ps: &[PixelSample; 8], s: u32) -> [Option<Ray>; 8] {
        let mut rays = ps.map(|p| self.lens_ray_untilted(&p, s));
        if let Some(nrm) = self.normal {
            let lane = |i: usize| rays[i].as_ref();
            let at = V3::<F8>::from_lanes(|i| lane(i).map_or(Vec3::ZERO, LensSample::screen_point));
            let d = V3::<F8>::from_lanes(|i| lane(i).map_or(Vec3::Z, LensSample::unit_dir));
            let tilted = normal::perturb_normal_lanes(nrm, at, d, self.pattern_quality());
            for (i, r) in rays.iter_mut().enumerate() {
                if let Some(r) = r {
                    r.tilt(tilted.lane(i));
                }
            }
        }
        rays.map(|r| r?.finish())
    }

    fn pattern_quality(&self) -> PatternQuality {
        PatternQuality { max_octaves: self.max_octaves }
    }

    /// A lens ray before the camera `normal` tilts it.
    fn lens_ray_untilted(&self, p: &PixelSample, s: u32) -> Option<LensSample<'_>> {
        let lens = self.lens.as_ref().expect("lens rays need a lens");
        let PixelSample { x, y, sx, sy, w, h, aa } = *p;
        let cell = |i: u32, si: u32, n: u32, jitter: f64| (i as f64 + (si as f64 + jitter) / aa as f64) / n as f64;
        let sample = if let Projection::Mesh { .. } = lens.projection {
            let uv = (cell(x, sx, w, 0.0), cell(y, sy, h, 0.0));
            let (o, d) = lens.mesh_ray((x, y, w, h), uv, s)?;
            LensSample { o, d, uv, blur: None }
        } else if self.blur_samples > 1 || lens.has_blur() {
            let j = lens::blur_jitter(x, y, sx, sy, s);
            let uv = (cell(x, sx, w, j[2]), cell(y, sy, h, j[3]));
            let (o, d) = lens.ray(uv.0, uv.1)?;
            LensSample { o, d, uv, blur: Some((lens, (j[0], j[1]))) }
        } else {
            let uv = (cell(x, sx, w, 0.5), cell(y, sy, h, 0.5));
            let (o, d) = lens.ray(uv.0, uv.1)?;
            LensSample { o, d, uv, blur: None }
        };
        Some(sample)
    }
}

/// A lens ray on its way: made by the projection, then tilted by the camera `normal`, then
/// moved onto the lens (focal blur).
///
/// POV-Ray 3.7 perturbs the unit direction as it perturbs a surface normal, with the pattern
/// read at the screen point (u − ½, ½ − v, 0) and its slope taken along the world's axes
/// (measured: `gradient x` tilts rays towards −x whichever way the camera looks, and camera
/// transforms leave the pattern alone). The tilt comes before the blur, so a blurred camera
/// focuses where its tilted rays meet the focal plane.
struct LensSample<'a> {
    o: DVec3,
    d: DVec3,
    /// The image point (u, v), v down.
    uv: (f64, f64),
    /// Focal blur's lens and the lens point in [0, 1)².
    blur: Option<(&'a LensRays<'a>, (f64, f64))>,
}

impl LensSample<'_> {
    fn screen_point(&self) -> Vec3 {
        Vec3::new((self.uv.0 - 0.5) as f32, (0.5 - self.uv.1) as f32, 0.0)
    }

    /// The unit direction the camera `normal` tilts (+z for a degenerate one, left untilted).
    fn unit_dir(&self) -> Vec3 {
        self.d.try_normalize().map_or(Vec3::Z, |d| d.as_vec3())
    }

    fn tilt(&mut self, tilted: Vec3) {
        if self.d.try_normalize().is_some() {
            self.d = tilted.as_dvec3();
        }
    }

    fn finish(self) -> Option<Ray> {
        let (o, d) = match self.blur {
            Some((lens, at)) => lens.blurred((self.o, self.d), at),
            None => (self.o, self.d),
        };
        let d = d.try_normalize()?;
        Some(Ray::new(o.as_vec3(), d.as_vec3()))
    }
}

/// Where one sample of a pixel lies: pixel (x, y) of a w×h image, sub-sample (sx, sy) of aa×aa.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PixelSample {
    pub x: u32,
    pub y: u32,
    pub sx: u32,
    pub sy: u32,
    pub w: u32,
    pub h: u32,
    pub aa: u32,
}
