//! Progressive antialiasing: sum one-sub-sample passes into a still image until it equals the
//! full `--aa N` render. The window uses this when the camera stops; nothing here knows of one.
//!
//! `render` with `subsample: Some((sx, sy))` yields each sub-sample unaveraged. Adding the passes
//! in the order `render_pixel` adds samples (row-major: sy, then sx) and dividing by the same
//! `(aa * aa) as f32` reproduces its arithmetic exactly, so the converged image is bit-identical.

use glam::Vec3;

use crate::render::image::Image;

/// Running per-pixel sums of sub-sample passes over one fixed view.
#[derive(Clone, Debug, Default)]
pub struct Accumulator {
    width: u32,
    height: u32,
    aa: u32,
    passes: u32,
    sum: Vec<Vec3>,
}

impl Accumulator {
    /// Starts over for a view of `width`×`height` with `aa`×`aa` sub-samples, keeping the
    /// allocation.
    pub fn reset(&mut self, width: u32, height: u32, aa: u32) {
        self.width = width;
        self.height = height;
        self.aa = aa.max(1);
        self.passes = 0;
        self.sum.clear();
        self.sum.resize(width as usize * height as usize, Vec3::ZERO);
    }

    /// Passes added so far.
    pub fn passes(&self) -> u32 {
        self.passes
    }

    /// Passes needed to converge.
    pub fn total(&self) -> u32 {
        self.aa * self.aa
    }

    pub fn is_converged(&self) -> bool {
        self.passes >= self.total()
    }

    /// The sub-sample the next pass must trace, or `None` once converged.
    pub fn next_subsample(&self) -> Option<(u32, u32)> {
        (!self.is_converged()).then(|| (self.passes % self.aa, self.passes / self.aa))
    }

    /// Adds a pass rendered with `subsample: self.next_subsample()`.
    pub fn add(&mut self, pass: &Image) {
        debug_assert_eq!((pass.width, pass.height), (self.width, self.height));
        for (s, p) in self.sum.iter_mut().zip(&pass.pixels) {
            *s += *p;
        }
        self.passes += 1;
    }

    /// The mean of the passes so far into `out` (resized to the view).
    pub fn resolve(&self, out: &mut Image) {
        out.resize(self.width, self.height);
        let n = self.passes.max(1) as f32;
        for (o, s) in out.pixels.iter_mut().zip(&self.sum) {
            *o = *s / n;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;
    use crate::render::precision::Precision;
    use crate::render::{render, Quality, RenderSettings};
    use crate::scene::build::{AccelKind, Scene};
    use crate::scene::fixtures::seed_scene as seed_like;

    /// The converged progressive image is the `--aa N` render, bit for bit (so within 1 LSB),
    /// in f32 and in f64 (the window's `reference` preset).
    #[test]
    fn progressive_aa_equals_full_render() {
        let desc = seed_like();
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let camera = Camera::from_desc(&desc.camera);
        for (aa, precision) in [1, 2, 3].into_iter().flat_map(|aa| Precision::ALL.map(|p| (aa, p))) {
            let quality = Quality { precision, ..Quality::default() };
            let settings = RenderSettings { width: 48, height: 36, aa, quality, ..RenderSettings::default() };
            let mut full = Image::default();
            render(&scene, &camera, &settings, &mut full);

            let mut acc = Accumulator::default();
            acc.reset(48, 36, aa);
            let mut pass = Image::default();
            while let Some(sub) = acc.next_subsample() {
                render(&scene, &camera, &RenderSettings { subsample: Some(sub), ..settings }, &mut pass);
                acc.add(&pass);
            }
            assert_eq!(acc.passes(), aa * aa);
            let mut out = Image::default();
            acc.resolve(&mut out);
            assert_eq!(out.pixels, full.pixels, "aa {aa}, {precision}");
            assert_eq!(out.to_rgb8(true), full.to_rgb8(true));
        }
    }

    #[test]
    fn partial_passes_average_what_is_there() {
        let mut acc = Accumulator::default();
        acc.reset(1, 1, 2);
        assert_eq!(acc.next_subsample(), Some((0, 0)));
        acc.add(&Image { width: 1, height: 1, pixels: vec![Vec3::ONE] });
        assert_eq!(acc.next_subsample(), Some((1, 0)));
        acc.add(&Image { width: 1, height: 1, pixels: vec![Vec3::ZERO] });
        assert_eq!(acc.next_subsample(), Some((0, 1)));
        let mut out = Image::default();
        acc.resolve(&mut out);
        assert_eq!(out.pixels, vec![Vec3::splat(0.5)]);
    }
}
