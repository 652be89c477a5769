//! The renderer's output: linear RGB floats, and their 8-bit encodings.

use glam::Vec3;

#[derive(Clone, Debug, Default)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    /// Row-major, top row first, linear light.
    pub pixels: Vec<Vec3>,
}

/// sRGB transfer function (IEC 61966-2-1), on a value clipped to [0, 1].
#[inline]
pub fn linear_to_srgb(v: f32) -> f32 {
    let v = v.clamp(0.0, 1.0);
    if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

#[inline]
pub fn srgb_to_linear(v: f32) -> f32 {
    if v <= 0.040_45 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// One channel to 8 bits, rounding to nearest as POV-Ray does.
#[inline]
pub fn encode8(v: f32, srgb: bool) -> u8 {
    let e = if srgb { linear_to_srgb(v) } else { v.clamp(0.0, 1.0) };
    (e * 255.0 + 0.5) as u8
}

impl Image {
    pub fn new(width: u32, height: u32) -> Image {
        Image { width, height, pixels: vec![Vec3::ZERO; width as usize * height as usize] }
    }

    /// Resizes in place, reusing the allocation when it is large enough.
    pub fn resize(&mut self, width: u32, height: u32) {
        self.width = width;
        self.height = height;
        self.pixels.resize(width as usize * height as usize, Vec3::ZERO);
    }

    /// Interleaved 8-bit RGB, as written to PNG and hashed by `capture`.
    pub fn to_rgb8(&self, srgb: bool) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.pixels.len() * 3);
        for p in &self.pixels {
            out.extend_from_slice(&[encode8(p.x, srgb), encode8(p.y, srgb), encode8(p.z, srgb)]);
        }
        out
    }

    /// Writes `0RGB` words (softbuffer's format) into `out`, which must hold width × height.
    pub fn write_xrgb(&self, srgb: bool, out: &mut [u32]) {
        for (o, p) in out.iter_mut().zip(&self.pixels) {
            *o = (encode8(p.x, srgb) as u32) << 16 | (encode8(p.y, srgb) as u32) << 8 | encode8(p.z, srgb) as u32;
        }
    }
}
