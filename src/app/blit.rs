//! Scales a rendered frame (0RGB at the internal resolution) onto the window's buffer.
//!
//! Nearest neighbour: at reduced scale the blocky look reads as "still refining", costs one load
//! per pixel, and at scale 1 it is an exact copy, so the presented pixels are the rendered ones.

/// Reusable column lookup, rebuilt only when either size changes.
#[derive(Default)]
pub struct Blitter {
    key: (u32, u32),
    columns: Vec<u32>,
}

impl Blitter {
    /// Fills `dst` (`dw`×`dh`) from `src` (`sw`×`sh`).
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
            // Centre sampling: destination pixel x covers source (x + 0.5) · sw / dw.
            self.columns.extend((0..dw as u64).map(|x| (((2 * x + 1) * sw as u64) / (2 * dw as u64)) as u32));
        }
        let mut prev_row = usize::MAX;
        for y in 0..dh as usize {
            let sy = ((2 * y as u64 + 1) * sh as u64 / (2 * dh as u64)) as usize;
            let (before, row) = dst.split_at_mut(y * dw_);
            let row = &mut row[..dw_];
            if sy == prev_row {
                // Same source row as the line above: copy it instead of gathering again.
                row.copy_from_slice(&before[(y - 1) * dw_..]);
                continue;
            }
            let line = &src[sy * sw_..(sy + 1) * sw_];
            for (d, &c) in row.iter_mut().zip(&self.columns) {
                *d = line[c as usize];
            }
            prev_row = sy;
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
    fn doubling_repeats_each_pixel() {
        let src = vec![1, 2, 3, 4];
        let mut dst = vec![0; 16];
        Blitter::default().blit(&src, 2, 2, &mut dst, 4, 4);
        assert_eq!(dst, vec![1, 1, 2, 2, 1, 1, 2, 2, 3, 3, 4, 4, 3, 3, 4, 4]);
    }

    #[test]
    fn odd_sizes_stay_in_bounds() {
        let mut b = Blitter::default();
        for (sw, sh, dw, dh) in [(7, 5, 640, 480), (128, 96, 13, 7), (1, 1, 3, 3), (3, 3, 1, 1)] {
            let src = vec![7u32; (sw * sh) as usize];
            let mut dst = vec![0; (dw * dh) as usize];
            b.blit(&src, sw, sh, &mut dst, dw, dh);
            assert!(dst.iter().all(|&p| p == 7));
        }
    }
}
