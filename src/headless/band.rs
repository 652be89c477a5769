//! Some rows of a still, rendered bit for bit as the whole image renders them: what
//! `render --shard` traces.
//!
//! The rows are traced at the full image's size through `render::render_pixels`, which gives
//! every listed pixel exactly the colour `render` gives it, for every camera and antialiasing
//! setting: strahl's antialiasing is a fixed grid per pixel, with nothing adaptive that looks
//! at a neighbour, so a seam between two parts is no different from any other row boundary.
//! (POV-Ray's adaptive `+AM1`/`+AM2` compares neighbours, which is why its own row split
//! differs at the seam.) The list is ordered in 8×8 blocks, so each 64-pixel chunk that
//! `render_pixels` traces as one packet is the block `render` would trace.
//!
//! Below full resolution (`--res-scale`) the whole image is a bilinear upscale of a smaller
//! render, so an output row depends on two rows of it: those rows, with a row's margin, are
//! traced, and the upscale of that partial low image gives the requested rows exactly.

use std::ops::Range;

use glam::Vec3;

use crate::camera::Camera;
use crate::render::image::Image;
use crate::render::resample::{scaled_size, upscale_bilinear};
use crate::render::stats::RenderStats;
use crate::render::{render_pixels, RenderSettings};
use crate::scene::build::Scene;

/// Rows dealt to shards together when they are interleaved: one packet block high, so every
/// block of a part is a whole block of the image.
pub const STRIP: u32 = 8;

/// Pixels per block side (`render::packet::BLOCK`).
const BLOCK: u32 = 8;

/// Renders the rows `rows` (ascending, disjoint, within the image) of the `settings`-sized
/// still at `res_scale`, as `render_scaled` renders them in the whole image: their linear
/// pixels, row-major, the rows in the order given. Runs on the current rayon pool.
pub fn render_rows(
    scene: &Scene,
    camera: &Camera,
    settings: &RenderSettings,
    res_scale: f32,
    rows: &[Range<u32>],
) -> (Vec<Vec3>, RenderStats) {
    let (w, h) = (settings.width.max(1), settings.height.max(1));
    let (lw, lh) = scaled_size(w, h, res_scale);
    if (lw, lh) == (w, h) {
        return trace_rows(scene, camera, settings, rows);
    }
    let low_settings = RenderSettings { width: lw, height: lh, ..*settings };
    let low_rows = low_rows_needed(rows, h, lh);
    let (traced, stats) = trace_rows(scene, camera, &low_settings, &low_rows);
    // Rows not needed stay black: no requested output row reads them.
    let mut low = Image::new(lw, lh);
    let mut src = traced.chunks_exact(lw as usize);
    for y in low_rows.iter().flat_map(|r| r.clone()) {
        let row = src.next().unwrap_or(&[]);
        low.pixels[(y * lw) as usize..][..row.len()].copy_from_slice(row);
    }
    let mut full = Image::default();
    upscale_bilinear(&low, &mut full, w, h);
    let out =
        rows.iter().flat_map(|r| full.pixels[(r.start * w) as usize..(r.end * w) as usize].iter().copied()).collect();
    (out, stats)
}

/// The rows of an `lh`-row image that the bilinear upscale to `h` rows reads for output rows
/// `rows`: output row d samples source position (d + ½)·lh/h − ½ and the rows either side of
/// it, so rows ⌊a·lh/h⌋ − 1 to ⌈b·lh/h⌉ + 1 cover a..b with a row to spare against rounding.
fn low_rows_needed(rows: &[Range<u32>], h: u32, lh: u32) -> Vec<Range<u32>> {
    let f = lh as f64 / h as f64;
    let mut out: Vec<Range<u32>> = Vec::new();
    for r in rows {
        let a = ((r.start as f64 * f).floor() as u32).saturating_sub(1);
        let b = ((r.end as f64 * f).ceil() as u32 + 1).min(lh);
        match out.last_mut() {
            Some(last) if a <= last.end => last.end = last.end.max(b),
            _ => out.push(a..b),
        }
    }
    out
}

/// Traces rows `rows` at the settings' size through `render_pixels`, in 8×8 blocks (blocks cut
/// by a part's edge are padded to 64 by repeating their last row and column, whose extra
/// results are dropped), and returns them row-major.
fn trace_rows(
    scene: &Scene,
    camera: &Camera,
    settings: &RenderSettings,
    rows: &[Range<u32>],
) -> (Vec<Vec3>, RenderStats) {
    let w = settings.width.max(1);
    let mut list = Vec::new();
    // For each listed pixel, where its colour goes in the output (None: padding).
    let mut slots: Vec<Option<usize>> = Vec::new();
    let mut base = 0usize;
    for r in rows {
        for by in r.clone().step_by(BLOCK as usize) {
            let bh = (r.end - by).min(BLOCK);
            for bx in (0..w).step_by(BLOCK as usize) {
                let bw = (w - bx).min(BLOCK);
                for j in 0..BLOCK {
                    for i in 0..BLOCK {
                        let (x, y) = (bx + i.min(bw - 1), by + j.min(bh - 1));
                        list.push(y * w + x);
                        let inside = i < bw && j < bh;
                        slots.push(inside.then(|| base + ((y - r.start) * w + x) as usize));
                    }
                }
            }
        }
        base += r.len() * w as usize;
    }
    let mut traced = vec![Vec3::ZERO; list.len()];
    let mut stats = render_pixels(scene, camera, settings, &list, &mut traced);
    let mut out = vec![Vec3::ZERO; base];
    for (slot, c) in slots.into_iter().zip(traced) {
        if let Some(k) = slot {
            out[k] = c;
        }
    }
    let aa = settings.aa.max(1) as u64;
    stats.pixels = base as u64;
    stats.samples = stats.pixels * aa * aa;
    (out, stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::resample::render_scaled;
    use crate::scene::fixtures::seed_scene;

    fn seed() -> (Scene, Camera) {
        let desc = seed_scene();
        (
            Scene::build(&desc, desc.camera.location, crate::scene::build::AccelKind::Bvh),
            Camera::from_desc(&desc.camera),
        )
    }

    /// Any rows, cut anywhere (mid-block, single rows, the last row), are the whole render's.
    #[test]
    fn rows_are_the_whole_renders_rows() {
        let (scene, camera) = seed();
        for (w, h, aa, scale) in [(37u32, 29u32, 1u32, 1.0f32), (24, 21, 2, 1.0), (37, 29, 1, 0.5), (30, 23, 2, 0.7)] {
            let settings = RenderSettings { width: w, height: h, aa, ..RenderSettings::default() };
            let (mut low, mut whole) = (Image::default(), Image::default());
            render_scaled(&scene, &camera, &settings, scale, &mut low, &mut whole);
            let rows = [0..3, 5..6, 9..20, (h - 1)..h];
            let (px, stats) = render_rows(&scene, &camera, &settings, scale, &rows);
            let expected: Vec<Vec3> =
                rows.iter().flat_map(|r| whole.pixels[(r.start * w) as usize..(r.end * w) as usize].to_vec()).collect();
            assert_eq!(px.len(), expected.len());
            for (k, (a, b)) in px.iter().zip(&expected).enumerate() {
                assert_eq!(a, b, "{w}x{h} aa {aa} scale {scale}: pixel {k} of the rows");
            }
            if scale == 1.0 {
                assert_eq!(stats.pixels, px.len() as u64, "statistics count the traced pixels");
            }
        }
    }

    #[test]
    fn low_rows_cover_the_upscales_taps() {
        assert_eq!(low_rows_needed(&[0..8, 16..24], 48, 24), vec![0..5, 7..13]);
        assert_eq!(low_rows_needed(&[0..8, 8..16], 48, 24), vec![0..9]);
        assert_eq!(low_rows_needed(&[40..48], 48, 24), vec![19..24]);
    }
}
