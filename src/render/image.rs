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

/// One channel to 8 bits, rounding to nearest as POV-Ray does: the defining formula.
#[inline]
fn encode8_exact(v: f32, srgb: bool) -> u8 {
    let e = if srgb { linear_to_srgb(v) } else { v.clamp(0.0, 1.0) };
    (e * 255.0 + 0.5) as u8
}

/// `SrgbTables::thresholds`: for each code k in 1..=255 the smallest linear value that encodes
/// to at least k.
///
/// `powf` per channel cost ~50 instructions, three times per pixel: at 1280×720 that is some
/// 130 M instructions a frame in the window's blit alone. The encoding is monotonic, so the 255
/// thresholds where the code steps up, found once by bisection on the f32 bit patterns with
/// the exact formula, give the same byte for every input with an 8-step binary search.
/// Values in [0, 1) fall into buckets of 2^`BUCKET_SHIFT` f32 bit patterns (1/128 of an
/// octave); no bucket holds more than one threshold (the steepest code step, 3 300 codes per
/// unit below 0.0032, spans ~20 buckets), so a bucket's first code and one comparison give the
/// byte. Measured in the window: the binary search took 17 ns a pixel (4.3 ms of a 13 ms frame
/// at scale 0.52), the buckets ~3 ns.
const BUCKET_SHIFT: u32 = 16;

struct SrgbTables {
    thresholds: [f32; 255],
    /// The code of each bucket's first value.
    bucket_code: Vec<u8>,
}

fn srgb_tables() -> &'static SrgbTables {
    static T: std::sync::OnceLock<SrgbTables> = std::sync::OnceLock::new();
    T.get_or_init(|| {
        let thresholds: [f32; 255] = std::array::from_fn(|i| {
            let k = i as u8 + 1;
            // Non-negative f32s order like their bit patterns.
            let (mut lo, mut hi) = (0u32, 1.0f32.to_bits());
            while lo < hi {
                let mid = lo + (hi - lo) / 2;
                if encode8_exact(f32::from_bits(mid), true) >= k {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            f32::from_bits(lo)
        });
        let bucket_code = (0..1.0f32.to_bits() >> BUCKET_SHIFT)
            .map(|b| thresholds.partition_point(|&t| t <= f32::from_bits(b << BUCKET_SHIFT)) as u8)
            .collect();
        SrgbTables { thresholds, bucket_code }
    })
}

/// One channel to 8 bits: sRGB-encoded (3.7 gamma handling) or linear (legacy scenes).
#[inline]
pub fn encode8(v: f32, srgb: bool) -> u8 {
    if !srgb {
        return encode8_exact(v, false);
    }
    if v.is_nan() {
        return encode8_exact(v, true);
    }
    let tables = srgb_tables();
    let bits = v.to_bits();
    if bits >= 1.0f32.to_bits() {
        // At least 1, or negative (the sign bit): the ends of the search.
        return tables.thresholds.partition_point(|&t| t <= v) as u8;
    }
    let code = tables.bucket_code[(bits >> BUCKET_SHIFT) as usize];
    code + (code < 255 && tables.thresholds[code as usize] <= v) as u8
}

/// One pixel as a `0RGB` word (softbuffer's format), each channel `encode8`d.
#[inline]
pub fn xrgb(p: Vec3, srgb: bool) -> u32 {
    (encode8(p.x, srgb) as u32) << 16 | (encode8(p.y, srgb) as u32) << 8 | encode8(p.z, srgb) as u32
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
    /// Rows in parallel (in the calling rayon pool).
    pub fn write_xrgb(&self, srgb: bool, out: &mut [u32]) {
        use rayon::prelude::*;
        const CHUNK: usize = 4096;
        out.par_chunks_mut(CHUNK).zip(self.pixels.par_chunks(CHUNK)).for_each(|(o, p)| {
            for (o, p) in o.iter_mut().zip(p) {
                *o = xrgb(*p, srgb);
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_table_matches_the_formula_everywhere() {
        // Every 97th f32 bit pattern in [0, 1], plus the thresholds and their neighbours.
        let one = 1.0f32.to_bits();
        let mut bits = (0..=one).step_by(97).collect::<Vec<u32>>();
        for t in srgb_tables().thresholds {
            bits.extend([t.to_bits() - 1, t.to_bits(), t.to_bits() + 1]);
        }
        for b in bits {
            let v = f32::from_bits(b);
            assert_eq!(encode8(v, true), encode8_exact(v, true), "at {v:e}");
        }
        // Each bucket holds at most one threshold, which the one comparison relies on.
        let tables = srgb_tables();
        let mut per_bucket = vec![0u32; tables.bucket_code.len()];
        for t in tables.thresholds {
            per_bucket[(t.to_bits() >> BUCKET_SHIFT) as usize] += 1;
        }
        assert!(per_bucket.iter().all(|&n| n <= 1), "a bucket holds two thresholds");
        for v in [-1.0, -0.0, 0.0, 1.0, 1.5, f32::INFINITY, f32::NEG_INFINITY, f32::NAN] {
            assert_eq!(encode8(v, true), encode8_exact(v, true), "at {v}");
        }
    }
}
