//! The image lookup kernel of `image_map`, `bump_map` and `image_pattern`: a pattern-space
//! point is wrapped onto the image (`map_type`), then the texel (or a blend of four) gives a
//! colour with filter and transmit, or a value in [0, 1].
//!
//! Checked against POV-Ray 3.7 renders of a 16×16 test image (tests/reference/images):
//! planar maps x, y ∈ [0, 1] with the image's top row at y = 1 and repeat in both directions;
//! `once` leaves the outside clear (the object behind shows); `interpolate 2` blends the four
//! texel centres around the point in working (linear) colour, wrapping at the edges; spherical
//! maps u = atan2(z, x) / 2π (0.75 facing −z, rising towards +x) and v = 0.5 + asin(y/r) / π.
//!
//! Images are looked up lane by lane: a texel fetch has no lane arithmetic to share.

use glam::Vec3;

use super::pattern::{Rgbft, RgbftLanes};
use crate::desc::{ImageMapDesc, ImageMapping};
use crate::image_file::Image;
use crate::lanes::{Lane, V3};

/// Tilt (the slope of the normal) per unit height difference per texel and unit `bump_size`:
/// measured on POV-Ray 3.7, a 16-texel grey ramp (1/15 a texel) with `bump_size` 1, 3, 10, 30
/// and 45 tilts by slopes 0.0667, 0.2, 0.667, 2.0 and 3.0, under any uniform scale.
const BUMP_GAIN: f32 = 1.0;

/// A render-ready image: working-space texels and values, and how to wrap them.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageLookup {
    width: usize,
    height: usize,
    /// Row-major, top row first.
    texels: Vec<Rgbft>,
    /// What `image_pattern` and `bump_map` read: intensity, index / 255, or alpha.
    values: Vec<f32>,
    mapping: ImageMapping,
    interpolate: u32,
    once: bool,
}

/// sRGB's transfer function, stored value → linear.
fn srgb_decode(v: f32) -> f32 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

impl ImageLookup {
    pub fn from_desc(d: &ImageMapDesc) -> ImageLookup {
        let img: &Image = &d.image;
        let decode = |v: f32| match (d.decode_gamma, d.file_gamma) {
            (Some(g), file) if g > 0.0 => {
                let linear = match file {
                    Some(fg) if fg > 0.0 => v.powf(fg as f32),
                    _ => srgb_decode(v),
                };
                linear.powf(1.0 / g as f32)
            }
            _ => v,
        };
        let (mut texels, mut values) = (Vec::with_capacity(img.width * img.height), Vec::new());
        values.reserve(img.width * img.height);
        for y in 0..img.height {
            for x in 0..img.width {
                let [r, g, b, a] = img.rgba(x, y);
                let index = img.index(x, y);
                // Alpha shows as transmit; `filter`/`transmit` N (palette entries) or `all`.
                let (mut filter, mut transmit) = (0.0f32, 1.0 - a);
                for (which, v) in &d.filter {
                    if which.is_none() || *which == index {
                        filter = *v as f32;
                    }
                }
                for (which, v) in &d.transmit {
                    if which.is_none() || *which == index {
                        transmit = *v as f32;
                    }
                }
                let rgb = Vec3::new(decode(r), decode(g), decode(b));
                texels.push(Rgbft { rgb, filter, transmit });
                values.push(match index {
                    _ if d.use_alpha => a,
                    Some(i) if d.use_index => i as f32 / 255.0,
                    // Intensity as POV-Ray's grey: 0.297 R + 0.589 G + 0.114 B of the stored values.
                    _ => 0.297 * r + 0.589 * g + 0.114 * b,
                });
            }
        }
        ImageLookup {
            width: img.width,
            height: img.height,
            texels,
            values,
            mapping: d.mapping,
            interpolate: d.interpolate,
            once: d.once,
        }
    }

    /// The finite-difference step of a `bump_map` normal in pattern units (one texel) and the
    /// factor on a height difference over it, `BUMP_GAIN` per unit `bump_size`
    /// (`shading::normal` differentiates over the point's texel and the two either side of it
    /// on the next row, as POV-Ray 3.7 does). The step is negative in y: image rows run down.
    pub fn normal_step(&self) -> (f32, f32) {
        let step = 1.0 / self.width.max(self.height) as f32;
        (step, BUMP_GAIN)
    }

    /// Whether any texel lets light through, or the outside of a `once` image does.
    pub fn may_be_transparent(&self) -> bool {
        self.once || self.texels.iter().any(|t| t.filter > 0.0 || t.transmit > 0.0)
    }

    /// The image coordinates (u, v) ∈ [0, 1)² of a pattern-space point, v = 1 at the top row;
    /// `None` outside a `once` image.
    fn uv(&self, p: Vec3) -> Option<(f32, f32)> {
        let turn = std::f32::consts::TAU;
        let around = |x: f32, z: f32| {
            let u = z.atan2(x) / turn;
            u - u.floor()
        };
        let (u, v) = match self.mapping {
            ImageMapping::Planar => (p.x, p.y),
            ImageMapping::Spherical => {
                let r = p.length();
                let v = if r > 0.0 { 0.5 + (p.y / r).clamp(-1.0, 1.0).asin() / std::f32::consts::PI } else { 0.5 };
                (around(p.x, p.z), v)
            }
            ImageMapping::Cylindrical => (around(p.x, p.z), p.y),
            ImageMapping::Torus => {
                // Measured: v = 0.5 at the outer equator, rising over the top (0.75) to the
                // inner equator (1.0 = 0.0) and round underneath.
                let ring = (p.x * p.x + p.z * p.z).sqrt() - 1.0;
                let v = 0.5 + p.y.atan2(ring) / turn;
                (around(p.x, p.z), v - v.floor())
            }
        };
        if self.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
            return None;
        }
        Some((u - u.floor(), v - v.floor()))
    }

    /// Texel column and row wrapped into the image.
    fn wrap(&self, x: i64, y: i64) -> usize {
        let (w, h) = (self.width as i64, self.height as i64);
        (y.rem_euclid(h) * w + x.rem_euclid(w)) as usize
    }

    /// The four texels around (u, v) with their weights: bilinear (2) or POV-Ray's
    /// normalized distance (4: each weighted by its closeness to the point); one texel for 0.
    fn taps(&self, u: f32, v: f32) -> ([usize; 4], [f32; 4]) {
        let fx = u * self.width as f32;
        let fy = (1.0 - v) * self.height as f32;
        if self.interpolate != 2 && self.interpolate != 4 {
            let i = self.wrap((fx as i64).min(self.width as i64 - 1), (fy as i64).min(self.height as i64 - 1));
            return ([i; 4], [1.0, 0.0, 0.0, 0.0]);
        }
        // Texel centres lie at i + 0.5.
        let (gx, gy) = (fx - 0.5, fy - 0.5);
        let (x0, y0) = (gx.floor(), gy.floor());
        let (tx, ty) = (gx - x0, gy - y0);
        let (x0, y0) = (x0 as i64, y0 as i64);
        let idx = [self.wrap(x0, y0), self.wrap(x0 + 1, y0), self.wrap(x0, y0 + 1), self.wrap(x0 + 1, y0 + 1)];
        let w = if self.interpolate == 2 {
            [(1.0 - tx) * (1.0 - ty), tx * (1.0 - ty), (1.0 - tx) * ty, tx * ty]
        } else {
            let d = [(tx, ty), (1.0 - tx, ty), (tx, 1.0 - ty), (1.0 - tx, 1.0 - ty)];
            let mut w = d.map(|(a, b)| (std::f32::consts::SQRT_2 - (a * a + b * b).sqrt()).max(0.0));
            let total: f32 = w.iter().sum();
            w.iter_mut().for_each(|x| *x /= total.max(1e-6));
            w
        };
        (idx, w)
    }

    /// The colour at a pattern-space point.
    pub fn color(&self, p: Vec3) -> Rgbft {
        let Some((u, v)) = self.uv(p) else {
            return Rgbft { rgb: Vec3::ZERO, filter: 0.0, transmit: 1.0 };
        };
        let (idx, w) = self.taps(u, v);
        if w[0] == 1.0 {
            return self.texels[idx[0]];
        }
        let mut out = Rgbft { rgb: Vec3::ZERO, filter: 0.0, transmit: 0.0 };
        for (i, w) in idx.into_iter().zip(w) {
            let t = self.texels[i];
            out.rgb += t.rgb * w;
            out.filter += t.filter * w;
            out.transmit += t.transmit * w;
        }
        out
    }

    /// The value (intensity, index or alpha) at a pattern-space point; 0 outside `once`.
    pub fn value(&self, p: Vec3) -> f32 {
        let Some((u, v)) = self.uv(p) else { return 0.0 };
        let (idx, w) = self.taps(u, v);
        idx.into_iter().zip(w).map(|(i, w)| self.values[i] * w).sum()
    }

    /// `color` lane by lane.
    pub fn color_lanes<L: Lane>(&self, p: V3<L>) -> RgbftLanes<L> {
        RgbftLanes::from_lanes(|i| self.color(p.lane(i)))
    }

    /// `value` lane by lane.
    pub fn value_lanes<L: Lane>(&self, p: V3<L>) -> L {
        L::from_fn(|i| self.value(p.lane(i)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image_file::{Channels, Image};
    use std::sync::Arc;

    fn desc(interpolate: u32, once: bool, mapping: ImageMapping) -> ImageMapDesc {
        // 2×2 grey: 0 1 / 0.5 0 (top row first).
        let image = Image {
            width: 2,
            height: 2,
            channels: Channels::Grey,
            max: 255,
            samples: vec![0, 255, 128, 0],
            palette: Vec::new(),
        };
        ImageMapDesc {
            file: "t.png".into(),
            format: "png".into(),
            image: Arc::new(image),
            mapping,
            interpolate,
            once,
            use_index: false,
            use_alpha: false,
            filter: vec![(None, 0.25)],
            transmit: Vec::new(),
            decode_gamma: None,
            file_gamma: None,
        }
    }

    #[test]
    fn planar_texels_repeat_and_once_is_clear_outside() {
        let l = ImageLookup::from_desc(&desc(0, false, ImageMapping::Planar));
        // Top-right texel (x ≥ 0.5, y ≥ 0.5) is white; bottom-left is 0.5.
        assert_eq!(l.color(Vec3::new(0.75, 0.75, 0.0)).rgb, Vec3::ONE);
        assert!((l.color(Vec3::new(0.25, 0.25, 3.0)).rgb.x - 128.0 / 255.0).abs() < 1e-6);
        assert_eq!(l.color(Vec3::new(2.75, -0.25, 0.0)).rgb, Vec3::ONE);
        assert_eq!(l.color(Vec3::new(0.75, 0.75, 0.0)).filter, 0.25);
        let once = ImageLookup::from_desc(&desc(0, true, ImageMapping::Planar));
        assert_eq!(once.color(Vec3::new(1.5, 0.5, 0.0)).transmit, 1.0);
        assert_eq!(once.value(Vec3::new(-0.5, 0.5, 0.0)), 0.0);
    }

    #[test]
    fn interpolation_blends_texel_centres_and_keeps_weights_whole() {
        for mode in [2, 4] {
            let l = ImageLookup::from_desc(&desc(mode, false, ImageMapping::Planar));
            // At a texel centre the texel itself (bilinear), or mostly it (4).
            let centre = l.value(Vec3::new(0.75, 0.75, 0.0));
            assert!(if mode == 2 { (centre - 1.0).abs() < 1e-5 } else { centre > 0.5 }, "{mode}: {centre}");
            // Halfway between the top texels: their mean (bilinear); between them (4, which
            // gives the other row some weight too).
            let mid = l.value(Vec3::new(0.5, 0.75, 0.0));
            if mode == 2 {
                assert!((mid - 0.5).abs() < 1e-5, "{mode}: {mid}");
            } else {
                assert!(mid > 0.2 && mid < 0.8, "{mode}: {mid}");
            }
            for k in 0..100 {
                let p = Vec3::new(k as f32 * 0.0371, k as f32 * 0.0173, 0.0);
                let v = l.value(p);
                assert!((-1e-6..=1.0 + 1e-6).contains(&v));
            }
        }
    }

    #[test]
    fn spherical_faces_minus_z_at_three_quarters() {
        let l = ImageLookup::from_desc(&desc(0, false, ImageMapping::Spherical));
        let (u, v) = l.uv(Vec3::new(0.0, 0.0, -1.0)).unwrap();
        assert!((u - 0.75).abs() < 1e-6 && (v - 0.5).abs() < 1e-6);
        let (_, top) = l.uv(Vec3::new(0.0, 0.999, 0.01)).unwrap();
        assert!(top > 0.95);
    }

    #[test]
    fn lanes_match_single_points() {
        use crate::lanes::F8;
        let l = ImageLookup::from_desc(&desc(2, false, ImageMapping::Cylindrical));
        let p = |i: usize| Vec3::new(i as f32 * 0.3 - 1.0, i as f32 * 0.11, 0.4 - i as f32 * 0.2);
        let wide = l.value_lanes(V3::<F8>::from_lanes(p));
        let col = l.color_lanes(V3::<F8>::from_lanes(p));
        for i in 0..8 {
            assert_eq!(wide.get(i).to_bits(), l.value(p(i)).to_bits());
            assert_eq!(col.lane(i), l.color(p(i)));
        }
    }
}
