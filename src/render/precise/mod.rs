//! The f64 render path (`--precision f64`, the `reference` preset): the same image as
//! `render::render`, with every ray computed in f64.
//!
//! What is f64: primary rays (from the camera in f64, relative to the render origin), the
//! geometry (`scene::precise`, built from the `SceneDesc`, not widened from the f32 scene),
//! intersection, hit points, geometric normals, the offsets of secondary-ray origins, shadow
//! rays, and the directions of reflected and refracted rays. What stays f32: pigments, normal
//! patterns and the lighting model (`eval_pigment`, `perturb_normal`, `render::shade`), given
//! the f64 hit point cast to f32 (benign: render space is camera-relative, see `trace`), and
//! colours. Rays are traced singly on the same rayon tiles as the f32 path (packets are an f32
//! optimisation); each pixel is a pure function of its inputs and the statistics are integer
//! sums, so images are bit-identical for any thread count.
//!
//! The bounded shapes are found through the f32 BVH's tree refitted with f64 boxes
//! (`accel::precise`), which finds the same hits as f64 brute force (`tests/precision.rs`).

pub mod intersect;
pub mod trace;

use std::fmt;
use std::str::FromStr;

use glam::{DVec3, Vec3};

use crate::camera::Camera;
use crate::geometry::precise::RayD;
use crate::render::image::Image;
use crate::render::stats::RenderStats;
use crate::render::trace::RayKind;
use crate::render::{output_sample, render_tiles, Raster, RenderSettings};
use crate::scene::build::Scene;
use crate::scene::desc::SceneDesc;
use intersect::SceneD;
use trace::TracerD;

/// The arithmetic rays are traced in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Precision {
    /// Single precision, with packets: the fast path.
    #[default]
    F32,
    /// Double precision, single rays: the `reference` preset.
    F64,
}

impl Precision {
    pub const ALL: [Precision; 2] = [Precision::F32, Precision::F64];

    pub fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Precision {
    type Err = String;

    fn from_str(s: &str) -> Result<Precision, String> {
        Precision::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| format!("unknown precision `{s}` (precisions: f32, f64)"))
    }
}

/// Builds what `precision` needs before rendering `scene` (built from `desc`): the f64
/// geometry for `F64`, nothing for `F32`.
pub fn prepare(scene: &Scene, desc: &SceneDesc, precision: Precision) {
    if precision == Precision::F64 {
        scene.prepare_precise(desc);
    }
}

/// Camera vectors in render space, f64.
struct RayGenD {
    origin: DVec3,
    direction: DVec3,
    right: DVec3,
    up: DVec3,
}

impl RayGenD {
    /// POV-Ray's perspective ray through image coordinates `u, v` in [0, 1] (v down).
    fn ray(&self, u: f64, v: f64) -> RayD {
        let d = self.direction + self.right * (u - 0.5) + self.up * (0.5 - v);
        RayD::new(self.origin, d.normalize())
    }
}

/// `render::render` in f64: the same tiles, sampling, clipping and statistics.
///
/// # Panics
/// If `scene.prepare_precise` was not called (see `prepare`).
pub fn render(scene: &Scene, camera: &Camera, settings: &RenderSettings, image: &mut Image) -> RenderStats {
    let Some(scene_d) = SceneD::new(scene) else {
        panic!("an f64 render needs the f64 scene: call render::precise::prepare (or Scene::prepare_precise) first");
    };
    let gen = RayGenD {
        origin: scene.frame.point(camera.location),
        direction: scene.frame.vector(camera.direction),
        right: scene.frame.vector(camera.right),
        up: scene.frame.vector(camera.up),
    };
    render_tiles(settings, image, |t, raster| {
        let Raster { w, h, aa, samples, out } = raster;
        let mut tracer = TracerD::new(scene_d, &settings.quality);
        for y in t.y0..t.y1 {
            for x in t.x0..t.x1 {
                let mut sum = Vec3::ZERO;
                // The order of additions is `render_pixel`'s, which `progressive` relies on.
                samples.each(aa, |sx, sy| {
                    let u = (x as f64 + (sx as f64 + 0.5) / aa as f64) / w as f64;
                    let v = (y as f64 + (sy as f64 + 0.5) / aa as f64) / h as f64;
                    let c = tracer.trace(&gen.ray(u, v), 1, 1.0, RayKind::Primary);
                    if c.is_finite() {
                        sum += output_sample(c, scene.gamma);
                    } else {
                        tracer.stats.bad_samples += 1;
                    }
                });
                // SAFETY: tiles partition the image, so each pixel is written by one task.
                unsafe { out.write((y * w + x) as usize, raster.resolve(sum)) };
            }
        }
        tracer.stats
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_bad_names_say_what_is_allowed() {
        for p in Precision::ALL {
            assert_eq!(p.name().parse::<Precision>(), Ok(p));
            assert_eq!(p.to_string(), p.name());
        }
        assert_eq!(Precision::default(), Precision::F32);
        let e = "f16".parse::<Precision>().unwrap_err();
        assert!(e.contains("`f16`") && e.contains("f32, f64"), "{e}");
    }
}
