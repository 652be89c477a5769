//! Reprojection: frames for a moving camera that trace a quarter of their pixels, trace more
//! only where detail needs it, and reuse the rest from the frame before, at full resolution.
//!
//! Each frame, in this order (after the render cache of Walter et al. 1999, checkerboard
//! rendering, and adaptive sampling's "trace where neighbours disagree"):
//!
//! 1. **Visibility** (`render::visibility`): what every pixel's primary ray hits (object and
//!    depth, eight bytes a pixel), found as `render` finds it but not shaded.
//! 2. **The lattice**: one pixel of every 2×2 square is traced and shaded, exactly as a full
//!    render traces it; the phase turns every frame ((0,0), (1,1), (1,0), (0,1)).
//! 3. **Each other pixel** looks at its two or four lattice neighbours on its own object:
//!    - none (a silhouette, a thin object), colours more than `CONTRAST` apart (an edge in the
//!      texture), or a neighbour that differs that much from its own lattice neighbours (detail
//!      finer than the lattice, as towards a checkered horizon): the pixel is **traced**, in
//!      packets of 64 (`render::render_pixels`);
//!    - else its hit point is projected into the previous frame's camera and the previous
//!      colours around it are blended bilinearly over the taps that saw the same object at the
//!      same depth (within what the surface's slope on screen allows), held to the neighbours'
//!      colours ± `MARGIN` (**reused**). Objects that reflect or transmit look different from
//!      every position, so they reuse nothing unless the camera is exactly where it was;
//!    - else the neighbours' mean (**filled**).
//!
//! Every pixel's colour so comes from samples of the object its own ray hits: a moving camera
//! never shows a colour from a different object. A camera that holds still copies the previous
//! frame where its pixels see the same object, so after four frames every pixel is its fresh
//! trace and the frame is the full render's bytes. Everything is decided per pixel on fixed
//! inputs, so a frame is the same whatever the thread count. Colours are kept as shown (`0RGB`
//! words), which is what the window needs and what PSNR measures.
//!
//! What it costs and buys is measured in `docs/perf/view-fly.md`: where shading is dear (area
//! lights) frames come about 1.5× faster at the same PSNR; on the seed scene, whose packets
//! shade a pixel in about 150 cycles, the bookkeeping costs about what it saves.

use glam::{Mat3, Vec3};
use rayon::prelude::*;

use crate::camera::Camera;
use crate::render::image::{xrgb, Image};
use crate::render::stats::RenderStats;
use crate::render::visibility::{Seen, Visibility};
use crate::render::{render, render_pixels, Lattice, RayGen, RenderSettings};
use crate::scene::build::Scene;

/// The lattice phases in the order frames take them: each next one diagonal or across from the
/// last, so that consecutive frames spread their fresh pixels.
const PHASES: [(u32, u32); 4] = [(0, 0), (1, 1), (1, 0), (0, 1)];
/// Depth may differ by this fraction and still be the same surface (beside the slope's share).
const DEPTH_TOLERANCE: f32 = 0.01;
/// How many pixels' worth of the surface's depth slope a tap may lie off.
const SLOPE_PIXELS: f32 = 2.0;
/// Lattice neighbours whose colours differ by more than this (in any channel, of 255 as
/// shown) show detail between them, so the pixel is traced.
const CONTRAST: f32 = 10.0;
/// How far outside its lattice neighbours' colours a reused colour may lie (of 255).
const MARGIN: f32 = 0.5 * CONTRAST;

/// A perspective camera's vectors in render space (`RayGen`'s): the eye, and the directions
/// to the image's centre, right edge and top edge, as POV-Ray's `direction`, `right`, `up`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pinhole {
    pub origin: Vec3,
    pub direction: Vec3,
    pub right: Vec3,
    pub up: Vec3,
    /// From a direction to (k, k(u - ½), k(½ - v)); `None` for degenerate cameras.
    to_image: Option<Mat3>,
}

impl Pinhole {
    pub fn new(origin: Vec3, direction: Vec3, right: Vec3, up: Vec3) -> Pinhole {
        let m = Mat3::from_cols(direction, right, up);
        let to_image = (m.determinant().abs() > f32::MIN_POSITIVE).then(|| m.inverse());
        Pinhole { origin, direction, right, up, to_image }
    }

    /// Where the ray towards `d` (from the eye) crosses the image: (u, v) with u right and v
    /// down, the image spanning [0, 1]²; `None` behind the eye or for degenerate cameras.
    #[inline]
    pub fn project_dir(&self, d: Vec3) -> Option<(f32, f32)> {
        // d = k (direction + (u - ½) right + (½ - v) up), solved for (k, k(u - ½), k(½ - v)).
        let c = self.to_image? * d;
        (c.x > 0.0).then(|| (c.y / c.x + 0.5, 0.5 - c.z / c.x))
    }

    /// `project_dir` of the direction from the eye to point `p`.
    #[inline]
    pub fn project(&self, p: Vec3) -> Option<(f32, f32)> {
        self.project_dir(p - self.origin)
    }

    /// The unit direction of the ray through the centre of pixel (x, y) of a w×h image (as
    /// `RayGen` makes it, up to rounding).
    #[inline]
    pub fn pixel_dir(&self, x: u32, y: u32, w: u32, h: u32) -> Vec3 {
        let (u, v) = ((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
        (self.direction + self.right * (u - 0.5) + self.up * (0.5 - v)).normalize()
    }
}

/// Where a frame's pixels came from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReprojectStats {
    /// Traced on the lattice.
    pub lattice: u64,
    /// Blended from the previous frame.
    pub reused: u64,
    /// The mean of same-object lattice neighbours.
    pub filled: u64,
    /// Traced because nothing else could stand for them.
    pub traced: u64,
}

impl ReprojectStats {
    /// The fraction of the frame's pixels that were traced and shaded.
    pub fn traced_share(&self) -> f64 {
        let all = self.lattice + self.reused + self.filled + self.traced;
        (self.lattice + self.traced) as f64 / all.max(1) as f64
    }
}

/// What one pixel became in step 3 or 4, before the traced ones are known.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Source {
    Lattice,
    Reused,
    Filled,
    Trace,
}

/// A frame as shown: its camera, what its pixels saw, and their `0RGB` colours.
#[derive(Default)]
struct Shown {
    camera: Option<Pinhole>,
    seen: Visibility,
    pixels: Vec<u32>,
}

/// Renders a moving camera's frames by reprojection; holds the frame before.
#[derive(Default)]
pub struct Reprojector {
    /// Frames since the last `reset` (the lattice phase is `frames % 4`).
    frames: u64,
    current: Shown,
    history: Shown,
    lattice: Image,
    lattice_px: Vec<u32>,
    /// Per lattice pixel: it differs by more than `CONTRAST` from a lattice neighbour.
    busy: Vec<bool>,
    sources: Vec<Source>,
    missing: Vec<u32>,
    traced: Vec<Vec3>,
    full: Image,
}

impl Reprojector {
    /// Whether `camera` can be reprojected in `scene`: a plain perspective camera without
    /// focal blur (other projections render without reuse).
    pub fn supports(scene: &Scene, camera: &Camera) -> bool {
        RayGen::new(camera, scene, &Default::default()).pinhole().is_some()
    }

    /// Forgets the previous frame (a new scene). A new size keeps it: the previous frame is
    /// reprojected from its own resolution, so the window's adaptive scale can change while
    /// the history lasts.
    pub fn reset(&mut self) {
        self.frames = 0;
        self.history.camera = None;
    }

    /// The next frame of `camera` at `settings`' size and quality, as `0RGB` words (`srgb`:
    /// the scene's output encoding), with one sample per pixel (`aa`, `subsample` and `lattice`
    /// are ignored); returns the pixels and the render statistics.
    pub fn frame(
        &mut self,
        scene: &Scene,
        camera: &Camera,
        settings: &RenderSettings,
    ) -> (&[u32], RenderStats, ReprojectStats) {
        let settings = RenderSettings { aa: 1, subsample: None, lattice: Lattice::FULL, ..*settings };
        let (w, h) = (settings.width.max(1), settings.height.max(1));
        let n = w as usize * h as usize;
        let srgb = scene.srgb;
        let Some(pinhole) = RayGen::new(camera, scene, &settings.quality).pinhole() else {
            self.reset();
            let stats = render(scene, camera, &settings, &mut self.full);
            self.history.pixels.resize(n, 0);
            self.full.write_xrgb(srgb, &mut self.history.pixels);
            return (&self.history.pixels, stats, ReprojectStats { lattice: n as u64, ..Default::default() });
        };
        let mut stats = self.current.seen.trace(scene, camera, w, h, &settings.quality);
        let (x, y) = PHASES[(self.frames % PHASES.len() as u64) as usize];
        let lattice = Lattice { step: 2, x: x.min(w - 1), y: y.min(h - 1) };
        stats += render(scene, camera, &RenderSettings { lattice, ..settings }, &mut self.lattice);
        self.lattice_px.resize(self.lattice.pixels.len(), 0);
        self.lattice.write_xrgb(srgb, &mut self.lattice_px);
        mark_busy(&self.lattice_px, self.lattice.width, &mut self.busy);

        self.current.pixels.resize(n, 0);
        self.sources.resize(n, Source::Lattice);
        let history = &self.history;
        let cx = Context {
            w,
            h,
            lattice,
            lattice_width: self.lattice.width,
            lattice_px: &self.lattice_px,
            busy: &self.busy,
            seen: &self.current.seen.seen,
            camera: pinhole,
            history: history.camera.map(|camera| History {
                camera,
                w: history.seen.width,
                h: history.seen.height,
                seen: &history.seen.seen,
                colors: &history.pixels,
            }),
            still: history.camera == Some(pinhole) && (history.seen.width, history.seen.height) == (w, h),
        };
        self.current
            .pixels
            .par_chunks_mut(w as usize)
            .zip(self.sources.par_chunks_mut(w as usize))
            .enumerate()
            .for_each(|(y, (row, sources))| {
                for (x, (c, s)) in row.iter_mut().zip(sources.iter_mut()).enumerate() {
                    (*c, *s) = cx.pixel(x as u32, y as u32);
                }
            });

        let mut counts = ReprojectStats::default();
        self.missing.clear();
        for (i, s) in self.sources.iter().enumerate() {
            match s {
                Source::Lattice => counts.lattice += 1,
                Source::Reused => counts.reused += 1,
                Source::Filled => counts.filled += 1,
                Source::Trace => self.missing.push(i as u32),
            }
        }
        counts.traced = self.missing.len() as u64;
        self.traced.clear();
        self.traced.resize(self.missing.len(), Vec3::ZERO);
        stats += render_pixels(scene, camera, &settings, &self.missing, &mut self.traced);
        for (&i, &c) in self.missing.iter().zip(&self.traced) {
            self.current.pixels[i as usize] = xrgb(c, srgb);
        }
        stats.pixels = n as u64;
        stats.samples = stats.pixels;
        self.frames += 1;
        self.current.camera = Some(pinhole);
        // The frame just made is the next one's history; the old history's buffers are reused.
        std::mem::swap(&mut self.history, &mut self.current);
        (&self.history.pixels, stats, counts)
    }
}

/// Marks the lattice pixels that differ by more than `CONTRAST` in a channel from the next one
/// across or down the lattice (both are marked).
fn mark_busy(px: &[u32], width: u32, busy: &mut Vec<bool>) {
    let w = width.max(1) as usize;
    busy.clear();
    busy.resize(px.len(), false);
    let differ = |a: u32, b: u32| (unpack(a) - unpack(b)).abs().max_element() > CONTRAST;
    for i in 0..px.len() {
        let right = i % w + 1 < w && differ(px[i], px[i + 1]);
        let down = i + w < px.len() && differ(px[i], px[i + w]);
        if right {
            busy[i] = true;
            busy[i + 1] = true;
        }
        if down {
            busy[i] = true;
            busy[i + w] = true;
        }
    }
}

/// A `0RGB` word's channels, 0–255.
#[inline]
fn unpack(c: u32) -> Vec3 {
    Vec3::new(((c >> 16) & 255) as f32, ((c >> 8) & 255) as f32, (c & 255) as f32)
}

/// Channels in 0–255 as a `0RGB` word, rounded.
#[inline]
fn pack(c: Vec3) -> u32 {
    let c = (c + Vec3::splat(0.5)).clamp(Vec3::ZERO, Vec3::splat(255.0));
    (c.x as u32) << 16 | (c.y as u32) << 8 | c.z as u32
}

/// What deciding one pixel reads.
struct Context<'a> {
    w: u32,
    h: u32,
    lattice: Lattice,
    lattice_width: u32,
    lattice_px: &'a [u32],
    busy: &'a [bool],
    seen: &'a [Seen],
    /// The frame's own camera.
    camera: Pinhole,
    history: Option<History<'a>>,
    /// The camera is exactly where the previous frame's was, at the same size.
    still: bool,
}

/// The previous frame: its camera and size, what its pixels saw, their colours.
#[derive(Clone, Copy)]
struct History<'a> {
    camera: Pinhole,
    w: u32,
    h: u32,
    seen: &'a [Seen],
    colors: &'a [u32],
}

/// A pixel's lattice neighbours on its own object: their mean and the box of their colours
/// (channels 0–255).
struct Neighbours {
    mean: Vec3,
    lo: Vec3,
    hi: Vec3,
    /// How much their depths differ from the pixel's, at most: the surface's slope on screen
    /// (large where it is seen at a grazing angle).
    slope: f32,
    /// One of them differs from a lattice neighbour of its own by more than `CONTRAST`: the
    /// pixel lies in detail finer than the lattice (towards the horizon, most often), where
    /// neighbours that agree may do so by chance.
    busy: bool,
}

impl Context<'_> {
    #[inline]
    fn at(&self, x: u32, y: u32) -> usize {
        (y * self.w + x) as usize
    }

    /// The colour of lattice pixel (x, y) (the lattice's step is 2 and its offsets 0 or 1, so
    /// halving finds its place in the lattice image).
    #[inline]
    fn lattice_color(&self, x: u32, y: u32) -> u32 {
        self.lattice_px[((y >> 1) * self.lattice_width + (x >> 1)) as usize]
    }

    #[inline]
    fn on_lattice(&self, x: u32, y: u32) -> bool {
        (x & 1) == self.lattice.x && (y & 1) == self.lattice.y
    }

    /// Pixel (x, y)'s colour and where it came from (`Source::Trace`: not known yet).
    fn pixel(&self, x: u32, y: u32) -> (u32, Source) {
        if self.on_lattice(x, y) {
            return (self.lattice_color(x, y), Source::Lattice);
        }
        let i = self.at(x, y);
        let here = self.seen[i];
        if let (true, Some(history)) = (self.still, self.history) {
            if history.seen[i].id == here.id {
                return (history.colors[i], Source::Reused);
            }
        }
        // Detail the lattice cannot stand for (an edge in the texture, aliasing towards the
        // horizon, a corner of the object) is traced.
        let Some(n) = self.neighbours(x, y, here) else {
            return (0, Source::Trace);
        };
        if n.busy || (n.hi - n.lo).max_element() > CONTRAST {
            return (0, Source::Trace);
        }
        match self.reuse(x, y, here, n.slope) {
            // Stale colours (a highlight that moved) are held to what the lattice shows here.
            Some(c) => (pack(c.clamp(n.lo - Vec3::splat(MARGIN), n.hi + Vec3::splat(MARGIN))), Source::Reused),
            None => (pack(n.mean), Source::Filled),
        }
    }

    /// The previous frame's colour (0–255) of the surface point pixel (x, y) sees, from the
    /// taps around where it saw it that saw the same object at the same depth.
    fn reuse(&self, x: u32, y: u32, here: Seen, slope: f32) -> Option<Vec3> {
        let History { camera, w: hw, h: hh, seen, colors } = self.history?;
        if here.view_dependent() {
            return None;
        }
        let dir = self.camera.pixel_dir(x, y, self.w, self.h);
        let (miss, point) = (here.is_miss(), self.camera.origin + dir * here.depth);
        let (u, v) = if miss { camera.project_dir(dir)? } else { camera.project(point)? };
        let (px, py) = (u * hw as f32 - 0.5, v * hh as f32 - 0.5);
        if !(px > -1.0 && py > -1.0 && px < hw as f32 && py < hh as f32) {
            return None;
        }
        let (x0, y0) = (px.floor(), py.floor());
        let (fx, fy) = (px - x0, py - y0);
        // Depths compare from the previous eye, where the taps' depths were measured.
        let depth = if miss { 0.0 } else { (point - camera.origin).length() };
        // A coarser history's taps lie further off, in this frame's pixels.
        let coarser = (self.w as f32 / hw as f32).max(1.0);
        let tolerance = DEPTH_TOLERANCE * depth + SLOPE_PIXELS * slope * coarser;
        let (mut sum, mut weight) = (Vec3::ZERO, 0.0);
        for (dx, dy, wt) in
            [(0, 0, (1.0 - fx) * (1.0 - fy)), (1, 0, fx * (1.0 - fy)), (0, 1, (1.0 - fx) * fy), (1, 1, fx * fy)]
        {
            let (tx, ty) = (x0 as i64 + dx, y0 as i64 + dy);
            if wt <= 0.0 || tx < 0 || ty < 0 || tx >= hw as i64 || ty >= hh as i64 {
                continue;
            }
            let t = (ty as u32 * hw + tx as u32) as usize;
            let tap = seen[t];
            if tap.id != here.id || (!miss && (tap.depth - depth).abs() > tolerance) {
                continue;
            }
            sum += unpack(colors[t]) * wt;
            weight += wt;
        }
        (weight > 0.0).then(|| sum / weight)
    }

    /// The lattice pixels next to (x, y) (not on the lattice) that see `here`'s object: two
    /// across or two up and down where x or y is on the lattice's columns or rows, else the
    /// four diagonal ones; `None` where none sees it.
    fn neighbours(&self, x: u32, y: u32, here: Seen) -> Option<Neighbours> {
        // Steps to the lattice's columns and rows: none where x or y is on them.
        let steps = |on: bool| -> &'static [i64] {
            if on {
                &[0]
            } else {
                &[-1, 1]
            }
        };
        let (xs, ys) = (steps((x & 1) == self.lattice.x), steps((y & 1) == self.lattice.y));
        let (mut sum, mut count, mut slope, mut busy) = (Vec3::ZERO, 0u32, 0.0f32, false);
        let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        let mut visit = |nx: i64, ny: i64| {
            if nx < 0 || ny < 0 || nx >= self.w as i64 || ny >= self.h as i64 {
                return;
            }
            let (nx, ny) = (nx as u32, ny as u32);
            let n = self.seen[self.at(nx, ny)];
            if n.id != here.id {
                return;
            }
            if !here.is_miss() {
                slope = slope.max((n.depth - here.depth).abs());
            }
            busy |= self.busy[((ny >> 1) * self.lattice_width + (nx >> 1)) as usize];
            let c = unpack(self.lattice_color(nx, ny));
            sum += c;
            count += 1;
            lo = lo.min(c);
            hi = hi.max(c);
        };
        for dy in ys {
            for dx in xs {
                visit(x as i64 + dx, y as i64 + dy);
            }
        }
        (count > 0).then(|| Neighbours { mean: sum / count as f32, lo, hi, slope, busy })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::build::AccelKind;
    use crate::scene::fixtures::seed_scene as seed_like;

    fn seed() -> (Scene, Camera) {
        let desc = seed_like();
        (Scene::build(&desc, desc.camera.location, AccelKind::Bvh), Camera::from_desc(&desc.camera))
    }

    fn full(scene: &Scene, camera: &Camera, settings: &RenderSettings) -> Vec<u32> {
        let mut image = Image::default();
        render(scene, camera, settings, &mut image);
        let mut px = vec![0; image.pixels.len()];
        image.write_xrgb(scene.srgb, &mut px);
        px
    }

    /// Pixel (i, j) of a lattice render is pixel (x + step·i, y + step·j) of the full render,
    /// bit for bit, through packets and single rays, for odd sizes and every phase.
    #[test]
    fn lattice_pixels_are_the_full_renders_pixels() {
        let (scene, camera) = seed();
        for packets in [true, false] {
            let settings = RenderSettings { width: 45, height: 29, packets, ..RenderSettings::default() };
            let mut whole = Image::default();
            render(&scene, &camera, &settings, &mut whole);
            for lattice in
                [Lattice { step: 2, x: 1, y: 0 }, Lattice { step: 2, x: 0, y: 1 }, Lattice { step: 3, x: 2, y: 1 }]
            {
                let mut part = Image::default();
                render(&scene, &camera, &RenderSettings { lattice, ..settings }, &mut part);
                assert_eq!((part.width, part.height), lattice.size(45, 29));
                for j in 0..part.height {
                    for i in 0..part.width {
                        let (x, y) = (lattice.x + lattice.step * i, lattice.y + lattice.step * j);
                        assert!(lattice.contains(x, y));
                        let (a, b) = (part.pixels[(j * part.width + i) as usize], whole.pixels[(y * 45 + x) as usize]);
                        assert_eq!(a, b, "{lattice:?} pixel ({x}, {y}), packets {packets}");
                    }
                }
            }
        }
    }

    /// Listed pixels, traced 64 to a packet or one by one, are the full render's pixels.
    #[test]
    fn listed_pixels_are_the_full_renders_pixels() {
        let (scene, camera) = seed();
        let (w, h) = (41u32, 23u32);
        let mut whole = Image::default();
        let settings = RenderSettings { width: w, height: h, ..RenderSettings::default() };
        render(&scene, &camera, &settings, &mut whole);
        // Scattered and in runs, 131 of them (two full packets and a partial one).
        let list: Vec<u32> = (0..w * h).filter(|i| i % 7 == 3 || (200..230).contains(i)).take(131).collect();
        assert_eq!(list.len(), 131);
        for packets in [true, false] {
            let mut out = vec![Vec3::ZERO; list.len()];
            render_pixels(&scene, &camera, &RenderSettings { packets, ..settings }, &list, &mut out);
            for (&p, &c) in list.iter().zip(&out) {
                assert_eq!(c, whole.pixels[p as usize], "pixel {p}, packets {packets}");
            }
        }
    }

    /// A camera that stops shows, four frames later, the full render's bytes.
    #[test]
    fn a_still_camera_converges_to_the_full_render() {
        let (scene, camera) = seed();
        let settings = RenderSettings { width: 64, height: 36, ..RenderSettings::default() };
        let mut rp = Reprojector::default();
        let moved = Camera { location: camera.location + DVec3::new(0.3, 0.1, -0.2), ..camera };
        rp.frame(&scene, &moved, &settings);
        let expected = full(&scene, &camera, &settings);
        let mut shown = Vec::new();
        for k in 0..PHASES.len() {
            let (px, _, counts) = rp.frame(&scene, &camera, &settings);
            shown = px.to_vec();
            if k == 0 {
                assert!(counts.reused > 0, "the first still frame reuses the moving one: {counts:?}");
            }
        }
        let differ = shown.iter().zip(&expected).filter(|(a, b)| a != b).count();
        assert_eq!(differ, 0, "{differ} pixels differ after four still frames");
    }

    /// Moving frames are the same with one thread and with three.
    #[test]
    fn frames_do_not_depend_on_the_thread_count() {
        let (scene, camera) = seed();
        let settings = RenderSettings { width: 80, height: 45, ..RenderSettings::default() };
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| {
                let mut rp = Reprojector::default();
                (0..6)
                    .map(|k| {
                        let step = DVec3::new(0.05 * k as f64, 0.02 * k as f64, 0.0);
                        let c = Camera { location: camera.location + step, ..camera };
                        let (px, _, counts) = rp.frame(&scene, &c, &settings);
                        (px.to_vec(), counts)
                    })
                    .collect::<Vec<_>>()
            })
        };
        let (one, three) = (run(1), run(3));
        assert!(one.iter().skip(1).all(|(_, c)| c.reused > 0), "frames reuse their predecessors");
        assert!(one == three, "thread count changed a frame");
    }

    #[test]
    fn projection_inverts_the_pixel_rays() {
        let p = Pinhole::new(
            Vec3::new(1.0, 2.0, 3.0),
            Vec3::new(0.2, -0.1, 1.5),
            Vec3::new(1.33, 0.1, 0.0),
            Vec3::new(0.0, 1.0, 0.05),
        );
        for (x, y) in [(0, 0), (17, 5), (63, 35), (31, 18)] {
            let d = p.pixel_dir(x, y, 64, 36);
            let (u, v) = p.project(p.origin + d * 7.5).expect("in front");
            assert!(
                (u * 64.0 - 0.5 - x as f32).abs() < 1e-3 && (v * 36.0 - 0.5 - y as f32).abs() < 1e-3,
                "({x}, {y}) -> ({u}, {v})"
            );
        }
        assert_eq!(p.project(p.origin - p.direction), None, "behind the eye");
    }
}
