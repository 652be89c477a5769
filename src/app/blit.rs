//! Scales a rendered frame (0RGB at the internal resolution) onto the window's buffer.
//!
//! Bilinear: while the camera moves the view renders at a reduced scale, and bilinear
//! reconstruction is closer to the full-resolution image than blocky nearest-neighbour pixels
//! (measured along `seed.fly.path` at 1280×720: docs/perf/view-fly.md). At scale 1 it is an exact copy,
//! so a converged view presents exactly the rendered pixels.

/// A source index pair and the weight (0..=256) of the second, per destination column or row.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Tap {
    a: u32,
    b: u32,
    w: u32,
}

/// Reusable lookup tables and row buffers, rebuilt only when a size changes.
#[derive(Default)]
pub struct Blitter {
    key: (u32, u32),
    columns: Vec<Tap>,
    /// Source rows already interpolated horizontally: (source row, pixels).
    rows: [(usize, Vec<u32>); 2],
}

/// Taps for resampling `src` samples onto `dst` samples, pixel centres aligned.
fn taps(src: u32, dst: u32) -> impl Iterator<Item = Tap> {
    (0..dst).map(move |x| {
        let s = ((x as f64 + 0.5) * src as f64 / dst as f64 - 0.5).max(0.0);
        let a = (s.floor() as u32).min(src - 1);
        let b = (a + 1).min(src - 1);
        Tap { a, b, w: ((s - a as f64) * 256.0).round().min(256.0) as u32 }
    })
}

/// Blends two 0RGB pixels, `w`/256 of `b`: red and blue in one multiply, green in another.
#[inline]
fn lerp(a: u32, b: u32, w: u32) -> u32 {
    let v = 256 - w;
    let rb = (((a & 0x00ff_00ff) * v + (b & 0x00ff_00ff) * w) >> 8) & 0x00ff_00ff;
    let g = (((a & 0x0000_ff00) * v + (b & 0x0000_ff00) * w) >> 8) & 0x0000_ff00;
    rb | g
}

impl Blitter {
    pub fn blit(&mut self, src: &[u32], sw: u32, sh: u32, dst: &mut [u32], dw: u32, dh: u32) {
        if sw == 0 || sh == 0 || dw == 0 || dh == 0 {
            dst.fill(0);
            return;
        }
        let (sw_, dw_) = (sw as usize, dw as usize);
        if sw == dw && sh == dh {
            dst[..sw_ * sh as usize].copy_from_slice(&src[..sw_ * sh as usize]);
            return;
        }
        if self.key != (sw, dw) {
            self.key = (sw, dw);
            self.columns.clear();
            self.columns.extend(taps(sw, dw));
            for row in &mut self.rows {
                *row = (usize::MAX, vec![0; dw_]);
            }
        }
        // The cached rows belong to the previous frame's pixels.
        for row in &mut self.rows {
            row.0 = usize::MAX;
        }
        for (y, t) in taps(sh, dh).enumerate() {
            let (a, b) = (t.a as usize, t.b as usize);
            // Moving down, the old bottom row becomes the new top row: reuse it.
            if self.rows[0].0 != a && self.rows[1].0 == a {
                self.rows.swap(0, 1);
            }
            for (slot, want) in [(0, a), (1, b)] {
                if self.rows[slot].0 != want {
                    let line = &src[want * sw_..(want + 1) * sw_];
                    let out = &mut self.rows[slot];
                    for (o, c) in out.1.iter_mut().zip(&self.columns) {
                        *o = lerp(line[c.a as usize], line[c.b as usize], c.w);
                    }
                    out.0 = want;
                }
            }
            let row = &mut dst[y * dw_..(y + 1) * dw_];
            let (top, bottom) = (&self.rows[0].1, &self.rows[1].1);
            for ((d, &p), &q) in row.iter_mut().zip(top).zip(bottom) {
                *d = lerp(p, q, t.w);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_size_is_an_exact_copy() {
        let src: Vec<u32> = (0..12).collect();
        let mut dst = vec![0; 12];
        Blitter::default().blit(&src, 4, 3, &mut dst, 4, 3);
        assert_eq!(src, dst);
    }

    #[test]
    fn doubling_blends_between_neighbours() {
        // One row, black then white: the doubled row ramps between them.
        let src = vec![0x000000, 0xffffff];
        let mut dst = vec![0; 4];
        Blitter::default().blit(&src, 2, 1, &mut dst, 4, 1);
        assert_eq!(dst[0], 0x000000);
        assert_eq!(dst[3], 0xffffff);
        let mid = |p: u32| p & 0xff;
        assert!(mid(dst[1]) > 0x30 && mid(dst[1]) < 0x50, "{:06x}", dst[1]);
        assert!(mid(dst[2]) > 0xb0 && mid(dst[2]) < 0xd0, "{:06x}", dst[2]);
        // Channels do not bleed into each other.
        assert!(dst.iter().all(|&p| p & 0xff == (p >> 8) & 0xff && p & 0xff == (p >> 16) & 0xff));
    }

    #[test]
    fn odd_sizes_stay_in_bounds_and_keep_flat_colours() {
        let mut b = Blitter::default();
        for (sw, sh, dw, dh) in [(7, 5, 640, 480), (128, 96, 13, 7), (1, 1, 3, 3), (3, 3, 1, 1)] {
            let src = vec![0x123456u32; (sw * sh) as usize];
            let mut dst = vec![0; (dw * dh) as usize];
            b.blit(&src, sw, sh, &mut dst, dw, dh);
            assert!(dst.iter().all(|&p| p == 0x123456));
        }
    }

    #[test]
    fn a_new_frame_of_the_same_size_is_not_served_from_the_cache() {
        let mut b = Blitter::default();
        let mut dst = vec![0; 16];
        b.blit(&[1; 4], 2, 2, &mut dst, 4, 4);
        b.blit(&[0x0000ff; 4], 2, 2, &mut dst, 4, 4);
        assert!(dst.iter().all(|&p| p == 0x0000ff));
    }
}
