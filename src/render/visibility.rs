//! The visibility pass: what each pixel's primary ray hits, found as `render` finds it (packets
//! where `render` uses them, the same rays) but not shaded. A reprojecting window knows from it,
//! for every pixel, which object it shows and where, before it decides what to trace.

use rayon::prelude::*;

use crate::camera::Camera;
use crate::ray::Ray;
use crate::render::intersect::Hit;
use crate::render::packet::{self, NO_HIT};
use crate::render::stats::RenderStats;
use crate::render::trace::Tracer;
use crate::render::{block_rays, Block, Lattice, PixelSample, Quality, Raster, RayGen, Samples, SharedPixels};
use crate::scene::build::Scene;

/// The id of a pixel whose ray hits nothing.
pub const MISS_ID: u32 = NO_HIT;
/// Set in the id of objects whose colour changes with the direction they are seen from beyond
/// highlights: they reflect or may transmit. (Object ids stay below it: `packet::object_id`
/// counts primitives from 0 and planes from 2³¹.)
pub const VIEW_DEPENDENT: u32 = 1 << 30;

/// What one pixel's primary ray sees: eight bytes, since a frame holds one per pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seen {
    /// The hit's distance from the eye along the pixel's unit ray (render units; ∞ for a miss).
    pub depth: f32,
    /// The object hit (`packet::object_id`, with `VIEW_DEPENDENT` where it applies), or `MISS_ID`.
    pub id: u32,
}

impl Seen {
    pub fn is_miss(self) -> bool {
        self.id == MISS_ID
    }

    pub fn view_dependent(self) -> bool {
        !self.is_miss() && self.id & VIEW_DEPENDENT != 0
    }
}

impl Default for Seen {
    fn default() -> Self {
        Seen { depth: f32::INFINITY, id: MISS_ID }
    }
}

/// What every pixel of a `width`×`height` frame sees, row-major.
#[derive(Clone, Debug, Default)]
pub struct Visibility {
    pub width: u32,
    pub height: u32,
    pub seen: Vec<Seen>,
}

impl Visibility {
    /// Finds what every pixel of `camera`'s `width`×`height` frame sees (one ray through each
    /// pixel's centre); the statistics count the intersection tests.
    pub fn trace(&mut self, scene: &Scene, camera: &Camera, width: u32, height: u32, quality: &Quality) -> RenderStats {
        let (w, h) = (width.max(1), height.max(1));
        self.width = w;
        self.height = h;
        // Every pixel is written below.
        self.seen.resize(w as usize * h as usize, Seen::default());
        let gen = RayGen::new(camera, scene, quality);
        let looks = |m: &crate::scene::material::Material| m.reflects() || m.may_be_transparent();
        // An interior texture counts for its object: either side may be what a pixel shows.
        let dependent: Vec<bool> = scene
            .materials
            .iter()
            .map(|m| looks(m) || m.inside.is_some_and(|i| looks(&scene.materials[i as usize])))
            .collect();
        let cx = Looks { scene, view_dependent: &dependent };
        let use_packets = packet::supported(scene) && gen.packets();
        let raster = Raster {
            w,
            h,
            out_w: w,
            lattice: Lattice::FULL,
            aa: 1,
            samples: Samples::All,
            out: SharedPixels(std::ptr::null_mut()),
        };
        let band = packet::BLOCK as usize * w as usize;
        self.seen
            .par_chunks_mut(band)
            .enumerate()
            .map(|(k, rows)| {
                let mut tracer = Tracer::new(scene, quality);
                let y0 = k as u32 * packet::BLOCK;
                let bh = (h - y0).min(packet::BLOCK);
                for bx in (0..w).step_by(packet::BLOCK as usize) {
                    let b = Block { x: bx, y: y0, w: (w - bx).min(packet::BLOCK), h: bh };
                    if use_packets {
                        see_block(&mut tracer, &cx, &gen, &b, &raster, rows);
                    } else {
                        for r in 0..b.h {
                            for i in 0..b.w {
                                let (x, y) = (b.x + i, b.y + r);
                                rows[(r * w + x) as usize] = see_ray(&mut tracer, &cx, &gen, x, y, &raster);
                            }
                        }
                    }
                }
                tracer.stats
            })
            .reduce(RenderStats::default, |mut a, b| {
                a += b;
                a
            })
    }
}

/// A block's hits through packets: `render_block`'s rays and `trace_block`'s search.
fn see_block(tracer: &mut Tracer, cx: &Looks, gen: &RayGen, b: &Block, raster: &Raster, rows: &mut [Seen]) {
    let rays = if gen.lens.is_some() {
        std::array::from_fn(|r| {
            let y = b.y + (r as u32).min(b.h - 1);
            let lane: [Ray; 8] = std::array::from_fn(|i| {
                let x = b.x + (i as u32).min(b.w - 1);
                lens_ray(gen, x, y, raster)
            });
            crate::accel::packet::Ray8::from_rays(&lane)
        })
    } else {
        block_rays(gen, b, raster, (0, 0))
    };
    let hits = packet::primary_hits(tracer, &rays, b.h as usize, b.w as usize);
    for r in 0..b.h as usize {
        for i in 0..b.w as usize {
            let seen = match hits.hit(r, i) {
                Some(hit) => cx.seen(hit),
                None => Seen::default(),
            };
            rows[r * raster.w as usize + b.x as usize + i] = seen;
        }
    }
}

/// One pixel's hit through a single ray, as `render_pixel` traces it.
fn see_ray(tracer: &mut Tracer, cx: &Looks, gen: &RayGen, x: u32, y: u32, raster: &Raster) -> Seen {
    let ray = if gen.lens.is_some() {
        lens_ray(gen, x, y, raster)
    } else {
        gen.ray((x as f32 + 0.5) / raster.w as f32, (y as f32 + 0.5) / raster.h as f32)
    };
    match tracer.nearest_hit(&ray, f32::INFINITY) {
        Some(hit) => cx.seen(hit),
        None => Seen::default(),
    }
}

/// A lens camera's ray through the pixel's centre; the view axis where the projection has none.
fn lens_ray(gen: &RayGen, x: u32, y: u32, raster: &Raster) -> Ray {
    let p = PixelSample { x, y, sx: 0, sy: 0, w: raster.w, h: raster.h, aa: 1 };
    gen.lens_ray(&p, 0).unwrap_or_else(|| Ray::new(gen.origin, gen.direction.normalize()))
}

/// What the pass needs to know of the scene's materials.
struct Looks<'a> {
    scene: &'a Scene,
    /// Per material: whether it reflects or may transmit.
    view_dependent: &'a [bool],
}

impl Looks<'_> {
    /// What a primary ray (of unit direction) sees at `hit`.
    #[inline]
    fn seen(&self, hit: Hit) -> Seen {
        let flag = if self.view_dependent[self.scene.material_of(hit.shape) as usize] { VIEW_DEPENDENT } else { 0 };
        Seen { depth: hit.t, id: packet::object_id(hit.shape) | flag }
    }
}
