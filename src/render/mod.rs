//! The renderer: primary rays per pixel, traced in tiles on rayon, shaded recursively.
//!
//! `render` is the one entry point for every front end (CLI, capture, bench, window). An image
//! is a pure function of (scene, camera, settings): each pixel is computed independently and
//! statistics are integer sums, so the result never depends on the thread count or tile order.
//!
//! Layer 7 of docs/design/architecture.md: uses `scene` and below; `pov` (probes) and the front ends use it.

pub mod adaptive;
mod block_rows;
mod blur;
pub mod csg;
pub mod image;
pub mod intersect;
pub mod moving_mode;
pub mod packet;
pub mod precision;
pub mod preset;
pub mod probe;
pub mod progressive;
mod raygen;
pub mod reproject;
pub mod resample;
pub mod shade;
pub mod stats;
pub mod trace;
pub mod visibility;

use glam::Vec3;
use rayon::prelude::*;

use crate::accel::packet::Ray8;
use crate::camera::Camera;
use crate::desc::Projection;
use crate::lanes::{Lane, F8, M8, V3};
use crate::ray::Ray;
use crate::scene::build::Scene;
use blur::BlurSum;
use image::Image;
pub(crate) use raygen::{PixelSample, RayGen};
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
    /// f32, or f32 with each nearest hit re-solved in f64 (`render::precision`).
    pub precision: precision::Precision,
    /// Caps the points of each `area_light` grid (rows × columns, both scaled down alike): its
    /// shadow rays per shading point (`shading::light::AreaGrid::capped`).
    pub max_area_samples: Option<u32>,
    /// Caps a focal-blur camera's `blur_samples` (rays per sample).
    pub max_blur_samples: Option<u32>,
}

impl Default for Quality {
    fn default() -> Self {
        Quality {
            max_trace_level: None,
            shadows: true,
            max_octaves: None,
            precision: precision::Precision::F32,
            max_area_samples: None,
            max_blur_samples: None,
        }
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
    /// Trace coherent primary rays and their shadow rays in 8×8 packets (`render::packet`)
    /// when the accelerator is a BVH. The image is the same either way.
    pub packets: bool,
    /// `Some((sx, sy))`: trace only sub-sample (sx, sy) of the aa×aa grid and write it unaveraged
    /// (clipped, or black where non-finite). Summing all aa² such images in row-major (sy, then sx)
    /// order and dividing by aa² gives bit for bit the full `aa` render; `progressive` does that,
    /// so a window can show a picture after one pass and converge to `strahl render --aa N`.
    pub subsample: Option<(u32, u32)>,
    /// Which of the frame's pixels to trace; the image holds only those (`Lattice`).
    pub lattice: Lattice,
}

/// Every `step`-th pixel of a frame across and down, starting at pixel (`x`, `y`): the pixels
/// a reprojecting window traces fresh in one frame. Pixel (i, j) of the image rendered with a
/// lattice is, bit for bit, pixel (x + step·i, y + step·j) of the full render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lattice {
    pub step: u32,
    pub x: u32,
    pub y: u32,
}

impl Lattice {
    /// Every pixel.
    pub const FULL: Lattice = Lattice { step: 1, x: 0, y: 0 };

    /// The image size of this lattice's pixels in a `width`×`height` frame (offsets past the
    /// frame's edge are clamped to it).
    pub fn size(self, width: u32, height: u32) -> (u32, u32) {
        let step = self.step.max(1);
        let n = |len: u32, o: u32| (len - o.min(len - 1)).div_ceil(step);
        (n(width.max(1), self.x), n(height.max(1), self.y))
    }

    /// Whether frame pixel (`x`, `y`) is one of the lattice's.
    #[inline]
    pub fn contains(self, x: u32, y: u32) -> bool {
        let step = self.step.max(1);
        x >= self.x && y >= self.y && (x - self.x).is_multiple_of(step) && (y - self.y).is_multiple_of(step)
    }
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            width: 640,
            height: 480,
            aa: 1,
            quality: Quality::default(),
            tile: 16,
            packets: true,
            subsample: None,
            lattice: Lattice::FULL,
        }
    }
}

/// The primary ray through the centre of pixel (x, y), in render space: what `render` traces
/// for that pixel without antialiasing. For tools that ask what a pixel sees. Where the
/// camera's projection has no ray (a fisheye's corners), the ray along the view axis.
pub fn primary_ray(scene: &Scene, camera: &Camera, width: u32, height: u32, x: u32, y: u32) -> Ray {
    let gen = RayGen::new(camera, scene, &Quality { max_blur_samples: Some(1), ..Quality::default() });
    if gen.lens.is_some() {
        let p = PixelSample { x, y, sx: 0, sy: 0, w: width, h: height, aa: 1 };
        if let Some(r) = gen.lens_ray(&p, 0) {
            return r;
        }
        return Ray::new(gen.origin, gen.direction.normalize());
    }
    gen.ray((x as f32 + 0.5) / width as f32, (y as f32 + 0.5) / height as f32)
}

/// Renders `camera`'s view into `image` (resized to the settings), returning the statistics.
pub fn render(scene: &Scene, camera: &Camera, settings: &RenderSettings, image: &mut Image) -> RenderStats {
    let gen = RayGen::new(camera, scene, &settings.quality);
    // Cameras whose pixels may have no ray (fisheye, omnimax) trace single rays; every other
    // projection and focal blur may use packets (`packet::trace_block` drops its frustum test
    // when the rays do not share an origin).
    let use_packets = settings.packets && packet::supported(scene) && gen.packets();
    let new_tracer = || Tracer::new(scene, &settings.quality);
    render_tiles(settings, image, new_tracer, |tracer, t, raster| {
        let tracer = &mut *tracer;
        if use_packets {
            for by in (t.y0..t.y1).step_by(packet::BLOCK as usize) {
                for bx in (t.x0..t.x1).step_by(packet::BLOCK as usize) {
                    let (bw, bh) = ((t.x1 - bx).min(packet::BLOCK), (t.y1 - by).min(packet::BLOCK));
                    render_block(tracer, &gen, &Block { x: bx, y: by, w: bw, h: bh }, raster);
                }
            }
        } else {
            for j in t.y0..t.y1 {
                for i in t.x0..t.x1 {
                    let (x, y) = raster.frame_pixel(i, j);
                    let c = render_pixel(tracer, &gen, x, y, raster);
                    // SAFETY: tiles partition the image, so each pixel is written by one task.
                    unsafe { raster.out.write((j * raster.out_w + i) as usize, c) };
                }
            }
        }
        std::mem::take(&mut tracer.stats)
    })
}

/// Traces the frame pixels `pixels` (indices `y · width + x` of `settings`' frame) into `out`
/// (as long), each exactly as `render` traces it; the lattice is ignored. For the scattered
/// pixels a reprojecting window traces beside its lattice: 64 at a time as one packet (eight
/// rows of eight) where `render` would use packets, so they cost what a block costs.
pub fn render_pixels(
    scene: &Scene,
    camera: &Camera,
    settings: &RenderSettings,
    pixels: &[u32],
    out: &mut [Vec3],
) -> RenderStats {
    /// Pixels per task: one packet's worth.
    const CHUNK: usize = (packet::BLOCK * packet::BLOCK) as usize;
    assert_eq!(pixels.len(), out.len(), "one output per pixel");
    let gen = RayGen::new(camera, scene, &settings.quality);
    let use_packets = settings.packets && packet::supported(scene) && gen.packets() && gen.lens.is_none();
    let (w, h, aa) = (settings.width.max(1), settings.height.max(1), settings.aa.max(1));
    let samples = Samples::of(settings.subsample, aa);
    // Colours are returned, not written through `out` here.
    let raster =
        Raster { w, h, out_w: w, lattice: Lattice::FULL, aa, samples, out: SharedPixels(std::ptr::null_mut()) };
    let mut stats = pixels
        .par_chunks(CHUNK)
        .zip(out.par_chunks_mut(CHUNK))
        // One tracer (and its block scratch) for a run of chunks on a thread, as `render_tiles`.
        .map_init(
            || Tracer::new(scene, &settings.quality),
            |tracer, (ps, os)| {
                if use_packets {
                    render_listed_block(tracer, &gen, ps, &raster, os);
                } else {
                    for (&p, o) in ps.iter().zip(os) {
                        *o = render_pixel(tracer, &gen, p % w, p / w, raster);
                    }
                }
                std::mem::take(&mut tracer.stats)
            },
        )
        .reduce(RenderStats::default, |mut a, b| {
            a += b;
            a
        });
    stats.pixels = pixels.len() as u64;
    stats.samples = stats.pixels * samples.per_pixel(aa);
    stats
}

/// Up to 64 listed pixels as one packet: lane i of row r is pixel `8r + i` of the list (the
/// last one repeated to fill the packet), each ray made as `block_rays` makes it.
fn render_listed_block(tracer: &mut Tracer, gen: &RayGen, pixels: &[u32], raster: &Raster, out: &mut [Vec3]) {
    let Raster { w, aa, samples, .. } = *raster;
    let lanes = (packet::BLOCK as usize).min(pixels.len());
    let rows = pixels.len().div_ceil(packet::BLOCK as usize);
    let b = Block { x: 0, y: 0, w: lanes as u32, h: rows as u32 };
    let mut sums = [V3::splat(Vec3::ZERO); 8];
    let pixel = |r: usize, i: usize| pixels[(r * 8 + i).min(pixels.len() - 1)];
    samples.each(aa, |sx, sy| {
        let rays: [Ray8; 8] = std::array::from_fn(|r| {
            let (xs, ys) = (F8::from_fn(|i| (pixel(r, i) % w) as f32), F8::from_fn(|i| (pixel(r, i) / w) as f32));
            lane_rays(gen, raster, xs, ys, (sx, sy))
        });
        add_traced(tracer, &rays, &b, &mut sums);
    });
    for (k, o) in out.iter_mut().enumerate() {
        *o = raster.resolve(sums[k / 8].lane(k % 8));
    }
}

/// The pixels `[x0, x1) × [y0, y1)` of one tile.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Tile {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

/// What every tile of a frame shares: the frame's size, the samples to trace and where pixels
/// go. Tiles, blocks and `out` are in image pixels, which are the frame's pixels where the
/// lattice is `Lattice::FULL`.
#[derive(Clone, Copy)]
pub(crate) struct Raster {
    /// The frame's size, which rays are made for.
    pub w: u32,
    pub h: u32,
    /// The image's width (the row stride of `out`).
    pub out_w: u32,
    pub lattice: Lattice,
    pub aa: u32,
    pub samples: Samples,
    pub out: SharedPixels,
}

impl Raster {
    /// The frame pixel that image pixel (`i`, `j`) shows.
    #[inline(always)]
    pub fn frame_pixel(&self, i: u32, j: u32) -> (u32, u32) {
        let Lattice { step, x, y } = self.lattice;
        (x + step * i, y + step * j)
    }

    /// A pixel's value from the sum of its traced samples: the mean over aa×aa, or a single
    /// sub-sample unaveraged (`RenderSettings::subsample`).
    #[inline]
    pub fn resolve(&self, sum: Vec3) -> Vec3 {
        match self.samples {
            // x / 1 is x, bit for bit: one sample per pixel skips three divisions.
            Samples::One(..) => sum,
            Samples::All if self.aa == 1 => sum,
            Samples::All => sum / (self.aa * self.aa) as f32,
        }
    }
}

/// The frame loop: sizes `image`, hands the tiles to rayon, and sums the statistics
/// `trace_tile` returns for each (integers, so the sum never depends on which thread ran which
/// tile), adding the pixel and sample counts. `init` makes the working state (a tracer and its
/// scratch) that a run of tiles on one thread shares, so it is not made again for every
/// 16×16 tile; nothing a tile computes may depend on what an earlier tile left in it.
pub(crate) fn render_tiles<S>(
    settings: &RenderSettings,
    image: &mut Image,
    init: impl Fn() -> S + Sync + Send,
    trace_tile: impl Fn(&mut S, Tile, Raster) -> RenderStats + Sync,
) -> RenderStats {
    let (fw, fh) = (settings.width.max(1), settings.height.max(1));
    let (w, h) = settings.lattice.size(fw, fh);
    let lattice = Lattice {
        step: settings.lattice.step.max(1),
        x: settings.lattice.x.min(fw - 1),
        y: settings.lattice.y.min(fh - 1),
    };
    image.resize(w, h);
    let tile = settings.tile.max(1);
    let tiles_x = w.div_ceil(tile);
    let tiles_y = h.div_ceil(tile);
    let aa = settings.aa.max(1);
    let samples = Samples::of(settings.subsample, aa);
    let raster = Raster { w: fw, h: fh, out_w: w, lattice, aa, samples, out: SharedPixels(image.pixels.as_mut_ptr()) };
    let mut stats = (0..tiles_x * tiles_y)
        .into_par_iter()
        .map_init(&init, |state, t| {
            let (x0, y0) = ((t % tiles_x) * tile, (t / tiles_x) * tile);
            trace_tile(state, Tile { x0, y0, x1: (x0 + tile).min(w), y1: (y0 + tile).min(h) }, raster)
        })
        .reduce(RenderStats::default, |mut a, b| {
            a += b;
            a
        });
    stats.pixels = w as u64 * h as u64;
    stats.samples = stats.pixels * samples.per_pixel(aa);
    stats
}

/// A rectangle of at most 8×8 pixels traced as one packet.
pub(crate) struct Block {
    pub x: u32,
    pub y: u32,
    pub w: u32,
    pub h: u32,
}

impl Samples {
    /// All aa×aa sub-samples, or the one `RenderSettings::subsample` names (clamped to the grid).
    fn of(subsample: Option<(u32, u32)>, aa: u32) -> Samples {
        match subsample {
            Some((sx, sy)) => Samples::One(sx.min(aa - 1), sy.min(aa - 1)),
            None => Samples::All,
        }
    }

    /// Samples traced per pixel.
    fn per_pixel(self, aa: u32) -> u64 {
        match self {
            Samples::All => (aa * aa) as u64,
            Samples::One(..) => 1,
        }
    }

    fn each(self, aa: u32, mut f: impl FnMut(u32, u32)) {
        match self {
            Samples::One(sx, sy) => f(sx, sy),
            Samples::All => {
                for sy in 0..aa {
                    for sx in 0..aa {
                        f(sx, sy)
                    }
                }
            }
        }
    }
}

/// The packet twin of `render_pixel` for a block: the same rays, the same per-sample clipping
/// and the same order of additions, so both give the same bits.
fn render_block(tracer: &mut Tracer, gen: &RayGen, b: &Block, raster: Raster) {
    let Raster { aa, samples, out, .. } = raster;
    let mut sums = [V3::splat(Vec3::ZERO); 8];
    if gen.lens.is_some() {
        samples.each(aa, |sx, sy| render_block_lens(tracer, gen, b, raster, (sx, sy), &mut sums));
    } else {
        samples.each(aa, |sx, sy| trace_sub_block(tracer, gen, b, &raster, (sx, sy), &mut sums));
    }
    for r in 0..b.h {
        for i in 0..b.w {
            let c = raster.resolve(sums[r as usize].lane(i as usize));
            // SAFETY: tiles partition the image and blocks partition tiles.
            unsafe { out.write(((b.y + r) * raster.out_w + b.x + i) as usize, c) };
        }
    }
}

/// Sub-sample (sx, sy) of a block's pixels, traced as packets and added to `sums`.
fn trace_sub_block(
    tracer: &mut Tracer,
    gen: &RayGen,
    b: &Block,
    raster: &Raster,
    sub: (u32, u32),
    sums: &mut [V3<F8>; 8],
) {
    #[cfg(target_arch = "x86_64")]
    if crate::lanes::has_avx2() {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { trace_sub_block_avx2(tracer, gen, b, raster, sub, sums) };
    }
    add_traced(tracer, &block_rays(gen, b, raster, sub), b, sums);
}

/// `trace_sub_block` with the rays made in 256-bit instructions (a division, a square root and a
/// reciprocal per lane: 8 % of a simple scene's frame in SSE). The same operations, so the same
/// bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn trace_sub_block_avx2(
    tracer: &mut Tracer,
    gen: &RayGen,
    b: &Block,
    raster: &Raster,
    sub: (u32, u32),
    sums: &mut [V3<F8>; 8],
) {
    add_traced(tracer, &block_rays(gen, b, raster, sub), b, sums);
}

/// The perspective rays of sub-sample (sx, sy) of a block's pixels, row by row, with the
/// operations `render_pixel` uses for each. Lanes past the block's edge repeat its last pixel;
/// their results are dropped.
#[inline(always)]
pub(crate) fn block_rays(gen: &RayGen, b: &Block, raster: &Raster, sub: (u32, u32)) -> [Ray8; 8] {
    let xs = F8::from_fn(|i| raster.frame_pixel(b.x + (i as u32).min(b.w - 1), 0).0 as f32);
    // A loop, not `std::array::from_fn`, whose closure was compiled out of line, without AVX2.
    let mut rays = [Ray8::ZERO; 8];
    for (r, ray) in rays.iter_mut().enumerate() {
        let y = raster.frame_pixel(0, b.y + (r as u32).min(b.h - 1)).1;
        *ray = lane_rays(gen, raster, xs, F8::splat(y as f32), sub);
    }
    rays
}

/// The perspective rays of sub-sample (sx, sy) of the eight frame pixels (xs, ys): per lane the
/// operations `render_pixel` does for one ray, so every lane has its single ray's bits.
#[inline(always)]
fn lane_rays(gen: &RayGen, raster: &Raster, xs: F8, ys: F8, (sx, sy): (u32, u32)) -> Ray8 {
    let Raster { w, h, aa, .. } = *raster;
    let u = (xs + F8::splat((sx as f32 + 0.5) / aa as f32)) / F8::splat(w as f32);
    let v = (ys + F8::splat((sy as f32 + 0.5) / aa as f32)) / F8::splat(h as f32);
    let d = gen.dir_lanes(u, v);
    Ray8 { o: V3::splat(gen.origin), d, inv: d.recip() }
}

/// Traces one block's rays as packets and adds each valid lane's output sample to `acc`
/// (non-finite samples are counted, not added), as `render_pixel` adds one ray's: eight lanes
/// at a time through the same `output_sample`. A non-finite lane adds +0, which leaves its
/// sum's bits as skipping it would (every sum starts at +0, and `+0 + -0` is `+0`).
#[inline(always)]
fn add_traced(tracer: &mut Tracer, rays: &[Ray8; 8], b: &Block, acc: &mut [V3<F8>; 8]) {
    let colors = packet::trace_block(tracer, rays, b.h as usize, b.w as usize);
    let gamma = tracer.scene.gamma;
    let inf = F8::splat(f32::INFINITY);
    let in_block = M8::from_fn(|i| i < b.w as usize);
    for r in 0..b.h as usize {
        let c = colors[r];
        let finite = F8::and(F8::and(c.x.abs().lt(inf), c.y.abs().lt(inf)), c.z.abs().lt(inf));
        let bad = F8::and(in_block, F8::not(finite));
        if bad.any() {
            tracer.stats.bad_samples += bad.count() as u64;
        }
        acc[r] = acc[r].add(V3::select(finite, output_sample(c, gamma), V3::splat(Vec3::ZERO)));
    }
}

/// Sub-sample (sx, sy) of a block through a lens, added to `sums`: per pixel the mean of its
/// blur rays, each built by `RayGen::lens_ray` as `render_pixel` builds it, added in the same
/// order and stopped after the same sample, so packets give single rays' bits. Each round
/// traces the next blur ray of the pixels still sampling, packed into full rows (Manta's
/// recompaction), so pixels that stopped early cost nothing.
fn render_block_lens(
    tracer: &mut Tracer,
    gen: &RayGen,
    b: &Block,
    raster: Raster,
    (sx, sy): (u32, u32),
    sums: &mut [V3<F8>; 8],
) {
    let Raster { w, h, aa, .. } = raster;
    let gamma = tracer.scene.gamma;
    let mut acc = [[BlurSum::default(); 8]; 8];
    // The pixels still sampling, as (row, lane) in the block, in row order.
    let mut live: Vec<(usize, usize)> =
        (0..b.h as usize).flat_map(|r| (0..b.w as usize).map(move |i| (r, i))).collect();
    for s in 0..gen.blur_samples {
        if live.is_empty() {
            break;
        }
        let sample = |&(r, i): &(usize, usize)| {
            let (x, _) = raster.frame_pixel(b.x + i as u32, 0);
            let (_, y) = raster.frame_pixel(0, b.y + r as u32);
            PixelSample { x, y, sx, sy, w, h, aa }
        };
        // Full rows first, then the rest as one row of fewer lanes (lanes past it repeat its
        // last pixel and are dropped), so the statistics count each traced ray once.
        let full = live.len() / 8 * 8;
        for (start, rows, lanes) in [(0, full / 8, 8), (full, 1, live.len() - full)] {
            if rows == 0 || lanes == 0 {
                continue;
            }
            // Rows past `rows` are never read.
            let mut rays = [Ray8::ZERO; 8];
            for (r, row) in rays[..rows].iter_mut().enumerate() {
                let samples: [PixelSample; 8] =
                    std::array::from_fn(|i| sample(&live[start + r * 8 + i.min(lanes - 1)]));
                // `packets()` admits only projections with a ray for every pixel.
                let lane =
                    gen.lens_rays8(&samples, s).map(|r| r.unwrap_or_else(|| Ray::new(gen.origin, gen.direction)));
                *row = Ray8::from_rays(&lane);
            }
            let colors = packet::trace_block(tracer, &rays, rows, lanes);
            for r in 0..rows {
                for i in 0..lanes {
                    let (pr, pi) = live[start + r * 8 + i];
                    acc[pr][pi].add(checked_sample(tracer, colors[r].lane(i), gamma));
                }
            }
        }
        if let Some(stop) = gen.blur_stop {
            live.retain(|&(r, i)| !acc[r][i].converged(&stop));
        }
    }
    for r in 0..b.h as usize {
        for i in 0..b.w as usize {
            sums[r].set_lane(i, sums[r].lane(i) + acc[r][i].mean());
        }
    }
}

/// One sample as it enters the pixel average: clipped to [0, 1] as POV-Ray does before
/// averaging, and raised to the scene's `assumed_gamma` (POV-Ray 3.7 encodes `v^gamma` as sRGB;
/// measured: `assumed_gamma 2.2` turns a linear 13/255 into 5/255 where 1.0 gives 63/255).
/// Written once for one colour and for eight (`add_traced`), so packets and single rays clip
/// and raise with the same operations.
#[inline(always)]
fn output_sample<L: Lane>(c: V3<L>, gamma: f32) -> V3<L> {
    let (zero, one) = (L::splat(0.0), L::splat(1.0));
    let c = V3 { x: c.x.max(zero).min(one), y: c.y.max(zero).min(one), z: c.z.max(zero).min(one) };
    if gamma == 1.0 {
        c
    } else {
        V3 { x: c.x.map(|v| v.powf(gamma)), y: c.y.map(|v| v.powf(gamma)), z: c.z.map(|v| v.powf(gamma)) }
    }
}

/// Which of a pixel's aa×aa sub-samples to trace.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Samples {
    All,
    One(u32, u32),
}

fn render_pixel(tracer: &mut Tracer, gen: &RayGen, x: u32, y: u32, raster: Raster) -> Vec3 {
    let Raster { w, h, aa, samples, .. } = raster;
    let gamma = tracer.scene.gamma;
    let mut sample = |sx: u32, sy: u32| {
        if gen.lens.is_some() {
            return lens_sample(tracer, gen, &PixelSample { x, y, sx, sy, w, h, aa });
        }
        let u = (x as f32 + (sx as f32 + 0.5) / aa as f32) / w as f32;
        let v = (y as f32 + (sy as f32 + 0.5) / aa as f32) / h as f32;
        let c = tracer.trace(&gen.ray(u, v), 1, 1.0, RayKind::Primary);
        if c.is_finite() {
            output_sample(V3::from_vec3(c), gamma).vec3()
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

/// One sample through a lens: the mean of its blur rays' clipped colours (black where the
/// projection has no ray, as POV-Ray leaves it), stopping early where `RayGen::blur_stop` says.
fn lens_sample(tracer: &mut Tracer, gen: &RayGen, p: &PixelSample) -> Vec3 {
    let gamma = tracer.scene.gamma;
    let mut acc = BlurSum::default();
    let mut traced = 0;
    for s in 0..gen.blur_samples {
        let c = match gen.lens_ray(p, s) {
            Some(ray) => {
                traced += 1;
                let c = tracer.trace_within(&ray, gen.max_distance, RayKind::Primary);
                checked_sample(tracer, c, gamma)
            }
            None => Vec3::ZERO,
        };
        acc.add(c);
        if gen.blur_stop.is_some_and(|stop| acc.converged(&stop)) {
            break;
        }
    }
    match gen.lens.map(|l| l.projection) {
        // A mesh camera's rays without a face leave the average (POV-Ray 3.4.2.2.3.2); other
        // projections' missing rays count as black.
        Some(Projection::Mesh { .. }) if traced > 1 => acc.sum() / traced as f32,
        Some(Projection::Mesh { .. }) => acc.sum(),
        _ => acc.mean(),
    }
}

/// A traced colour as it enters a pixel's sum: `output_sample`, or black for a non-finite
/// colour (counted in the statistics).
#[inline]
fn checked_sample(tracer: &mut Tracer, c: Vec3, gamma: f32) -> Vec3 {
    if c.is_finite() {
        output_sample(V3::from_vec3(c), gamma).vec3()
    } else {
        tracer.stats.bad_samples += 1;
        Vec3::ZERO
    }
}

/// A raw pointer to the image's pixels that tiles may write through concurrently.
#[derive(Clone, Copy)]
pub(crate) struct SharedPixels(*mut Vec3);
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
