//! The renderer: primary rays per pixel, traced in tiles on rayon, shaded recursively.
//!
//! `render` is the one entry point for every front end (CLI, capture, bench, window). An image
//! is a pure function of (scene, camera, settings): each pixel is computed independently and
//! statistics are integer sums, so the result never depends on the thread count or tile order.

pub mod adaptive;
pub mod image;
pub mod intersect;
pub mod progressive;
pub mod stats;
pub mod trace;

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use crate::camera::Camera;
use crate::geometry::ray::Ray;
use crate::scene::build::Scene;
use image::Image;
use stats::RenderStats;
use trace::{RayKind, Tracer};

/// Accuracy knobs. `Quality::default()` renders exactly what the scene asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quality {
    /// Overrides the scene's `max_trace_level`.
    pub max_trace_level: Option<u32>,
    pub shadows: bool,
    /// Caps turbulence and noise octaves (texture detail).
    pub max_octaves: Option<u32>,
}

impl Default for Quality {
    fn default() -> Self {
        Quality { max_trace_level: None, shadows: true, max_octaves: None }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// N×N samples per pixel on a regular grid; 1 = one ray through the pixel centre.
    pub aa: u32,
    pub quality: Quality,
    /// Tile edge in pixels.
    pub tile: u32,
    /// `Some((sx, sy))`: trace only sub-sample (sx, sy) of the aa×aa grid and write it unaveraged
    /// (clipped, or black where non-finite). Summing all aa² such images in row-major (sy, then sx)
    /// order and dividing by aa² gives bit for bit the full `aa` render; `progressive` does that,
    /// so a window can show a picture after one pass and converge to `strahl render --aa N`.
    pub subsample: Option<(u32, u32)>,
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings { width: 640, height: 480, aa: 1, quality: Quality::default(), tile: 16, subsample: None }
    }
}

/// Camera vectors in render space, f32.
#[derive(Clone, Copy, Debug)]
struct RayGen {
    origin: Vec3,
    direction: Vec3,
    right: Vec3,
    up: Vec3,
}

impl RayGen {
    fn new(camera: &Camera, origin: DVec3) -> RayGen {
        RayGen {
            origin: (camera.location - origin).as_vec3(),
            direction: camera.direction.as_vec3(),
            right: camera.right.as_vec3(),
            up: camera.up.as_vec3(),
        }
    }

    /// POV-Ray's perspective ray through image coordinates `u, v` in [0, 1] (v down).
    #[inline]
    fn ray(&self, u: f32, v: f32) -> Ray {
        let d = self.direction + (u - 0.5) * self.right + (0.5 - v) * self.up;
        Ray::new(self.origin, d.normalize())
    }
}

/// Renders `camera`'s view into `image` (resized to the settings), returning the statistics.
pub fn render(scene: &Scene, camera: &Camera, settings: &RenderSettings, image: &mut Image) -> RenderStats {
    let (w, h) = (settings.width.max(1), settings.height.max(1));
    image.resize(w, h);
    let gen = RayGen::new(camera, scene.origin);
    let tile = settings.tile.max(1);
    let tiles_x = w.div_ceil(tile);
    let tiles_y = h.div_ceil(tile);
    let aa = settings.aa.max(1);
    let samples = match settings.subsample {
        Some((sx, sy)) => Samples::One(sx.min(aa - 1), sy.min(aa - 1)),
        None => Samples::All,
    };
    let out = SharedPixels(image.pixels.as_mut_ptr());
    let mut stats = (0..tiles_x * tiles_y)
        .into_par_iter()
        .map(|t| {
            let (tx, ty) = (t % tiles_x, t / tiles_x);
            let mut tracer = Tracer::new(scene, &settings.quality);
            for y in ty * tile..((ty + 1) * tile).min(h) {
                for x in tx * tile..((tx + 1) * tile).min(w) {
                    let c = render_pixel(&mut tracer, &gen, x, y, w, h, aa, samples);
                    // SAFETY: tiles partition the image, so each pixel is written by one task.
                    unsafe { out.write((y * w + x) as usize, c) };
                }
            }
            tracer.stats
        })
        .reduce(RenderStats::default, |mut a, b| {
            a += b;
            a
        });
    stats.pixels = w as u64 * h as u64;
    stats.samples = match samples {
        Samples::All => stats.pixels * (aa * aa) as u64,
        Samples::One(..) => stats.pixels,
    };
    stats
}

/// Which of a pixel's aa×aa sub-samples to trace.
#[derive(Clone, Copy, Debug)]
enum Samples {
    All,
    One(u32, u32),
}

#[allow(clippy::too_many_arguments)]
fn render_pixel(tracer: &mut Tracer, gen: &RayGen, x: u32, y: u32, w: u32, h: u32, aa: u32, samples: Samples) -> Vec3 {
    let mut sample = |sx: u32, sy: u32| {
        let u = (x as f32 + (sx as f32 + 0.5) / aa as f32) / w as f32;
        let v = (y as f32 + (sy as f32 + 0.5) / aa as f32) / h as f32;
        let c = tracer.trace(&gen.ray(u, v), 1, 1.0, RayKind::Primary);
        if c.is_finite() {
            // POV-Ray clips each sample before averaging.
            c.clamp(Vec3::ZERO, Vec3::ONE)
        } else {
            tracer.stats.bad_samples += 1;
            Vec3::ZERO
        }
    };
    match samples {
        Samples::One(sx, sy) => sample(sx, sy),
        Samples::All => {
            // Adding ZERO for a bad sample leaves the sum as skipping it would, and keeps the
            // order of additions the one `progressive::Accumulator` reproduces.
            let mut sum = Vec3::ZERO;
            for sy in 0..aa {
                for sx in 0..aa {
                    sum += sample(sx, sy);
                }
            }
            sum / (aa * aa) as f32
        }
    }
}

/// A raw pointer to the image's pixels that tiles may write through concurrently.
#[derive(Clone, Copy)]
struct SharedPixels(*mut Vec3);
// SAFETY: only used to write disjoint pixels from different tiles.
unsafe impl Send for SharedPixels {}
unsafe impl Sync for SharedPixels {}

impl SharedPixels {
    /// # Safety
    /// `i` must be in bounds and written by no other thread during the render.
    #[inline]
    unsafe fn write(self, i: usize, c: Vec3) {
        *self.0.add(i) = c;
    }
}
