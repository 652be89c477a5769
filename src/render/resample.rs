//! Rendering below the output resolution: the reduced size for a `res_scale`, the bilinear
//! upscale back to the full size, and `render_scaled`, which does both around `render`.
//!
//! The upscale works on the renderer's linear floats, before the 8-bit encoding, so it blends
//! light and not sRGB codes. The window scales its own adaptive-resolution frames in `app::blit`.

use rayon::prelude::*;

use super::image::Image;
use super::stats::RenderStats;
use super::{render, RenderSettings};
use crate::camera::Camera;
use crate::scene::build::Scene;

/// The smallest `res_scale` the CLI accepts: below it a 640-pixel frame is under 64 pixels wide.
pub const MIN_RES_SCALE: f32 = 0.1;

/// The reduced image size for `scale` (clamped to 0..=1), each side rounded and at least 1.
pub fn scaled_size(width: u32, height: u32, scale: f32) -> (u32, u32) {
    let s = if scale.is_finite() { scale.clamp(0.0, 1.0) } else { 1.0 };
    let side = |n: u32| ((n as f32 * s).round() as u32).clamp(1, n.max(1));
    (side(width), side(height))
}

/// Resizes `dst` to `width`×`height` and fills it from `src` by bilinear interpolation with
/// pixel centres aligned (edges clamp), so a same-size call copies `src` exactly.
pub fn upscale_bilinear(src: &Image, dst: &mut Image, width: u32, height: u32) {
    dst.resize(width, height);
    let (sw, sh) = (src.width.max(1) as usize, src.height.max(1) as usize);
    if src.pixels.len() < sw * sh || width == 0 {
        return;
    }
    let (fx, fy) = (sw as f32 / width as f32, sh as f32 / height as f32);
    // Source coordinate of a destination pixel centre: the lower neighbour and the weight of the
    // upper one.
    let tap = |d: usize, f: f32, n: usize| {
        let s = ((d as f32 + 0.5) * f - 0.5).clamp(0.0, (n - 1) as f32);
        let i = (s as usize).min(n - 1);
        (i, (i + 1).min(n - 1), s - i as f32)
    };
    dst.pixels.par_chunks_mut(width as usize).enumerate().for_each(|(y, row)| {
        let (y0, y1, ty) = tap(y, fy, sh);
        let (r0, r1) = (&src.pixels[y0 * sw..][..sw], &src.pixels[y1 * sw..][..sw]);
        for (x, out) in row.iter_mut().enumerate() {
            let (x0, x1, tx) = tap(x, fx, sw);
            let top = r0[x0].lerp(r0[x1], tx);
            let bottom = r1[x0].lerp(r1[x1], tx);
            *out = top.lerp(bottom, ty);
        }
    });
}

/// Renders `settings` at `res_scale` of its size into `low`, then upscales into `image` at the
/// full size. A scale of 1 (or more) renders straight into `image` and leaves `low` alone. Both
/// images keep their allocations, so a caller that reuses them allocates nothing per frame.
pub fn render_scaled(
    scene: &Scene,
    camera: &Camera,
    settings: &RenderSettings,
    res_scale: f32,
    low: &mut Image,
    image: &mut Image,
) -> RenderStats {
    let (w, h) = scaled_size(settings.width, settings.height, res_scale);
    if (w, h) == (settings.width, settings.height) {
        return render(scene, camera, settings, image);
    }
    let stats = render(scene, camera, &RenderSettings { width: w, height: h, ..*settings }, low);
    upscale_bilinear(low, image, settings.width, settings.height);
    stats
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;

    #[test]
    fn scaled_sizes_round_and_stay_positive() {
        assert_eq!(scaled_size(640, 360, 0.25), (160, 90));
        assert_eq!(scaled_size(640, 360, 1.0), (640, 360));
        assert_eq!(scaled_size(64, 48, 0.75), (48, 36));
        assert_eq!(scaled_size(3, 1, 0.1), (1, 1));
        assert_eq!(scaled_size(10, 10, f32::NAN), (10, 10));
        assert_eq!(scaled_size(10, 10, 2.0), (10, 10));
    }

    #[test]
    fn same_size_upscale_is_a_copy() {
        let mut src = Image::new(5, 3);
        for (i, p) in src.pixels.iter_mut().enumerate() {
            *p = Vec3::splat(i as f32 / 15.0);
        }
        let mut dst = Image::default();
        upscale_bilinear(&src, &mut dst, 5, 3);
        assert_eq!(dst.pixels, src.pixels);
    }

    #[test]
    fn upscale_interpolates_between_centres_and_clamps_edges() {
        // Two pixels, 0 and 1, doubled to four: centres at source x = -0.25, 0.25, 0.75, 1.25.
        let src = Image { width: 2, height: 1, pixels: vec![Vec3::ZERO, Vec3::ONE] };
        let mut dst = Image::default();
        upscale_bilinear(&src, &mut dst, 4, 2);
        let xs: Vec<f32> = dst.pixels.iter().map(|p| p.x).collect();
        assert_eq!(xs, vec![0.0, 0.25, 0.75, 1.0, 0.0, 0.25, 0.75, 1.0]);
    }
}
