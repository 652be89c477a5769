//! Image comparison metrics on 8-bit RGB buffers: PSNR and a block SSIM, for golden-frame tests,
//! quality/speed trade-off reports and anything else that must say how far apart two frames are.

/// Peak signal-to-noise ratio in dB over all channels; `f64::INFINITY` for identical images.
/// Panics if the buffers differ in length (comparing different sizes is a caller bug).
pub fn psnr(a: &[u8], b: &[u8]) -> f64 {
    psnr_from_mse(mse(a, b))
}

/// Mean squared error over all channels, in 8-bit steps squared; 0 for empty buffers. Averaging
/// this over several frames and then taking `psnr_from_mse` gives the PSNR of all of them.
/// Panics if the buffers differ in length.
pub fn mse(a: &[u8], b: &[u8]) -> f64 {
    assert_eq!(a.len(), b.len(), "psnr: images differ in size");
    if a.is_empty() {
        return 0.0;
    }
    let sse: u64 = a.iter().zip(b).map(|(&x, &y)| (x as i64 - y as i64).pow(2) as u64).sum();
    sse as f64 / a.len() as f64
}

/// PSNR in dB of an 8-bit mean squared error; `f64::INFINITY` for 0.
pub fn psnr_from_mse(mse: f64) -> f64 {
    if mse <= 0.0 {
        return f64::INFINITY;
    }
    10.0 * (255.0 * 255.0 / mse).log10()
}

/// The largest difference of any channel of any pixel, in 8-bit steps.
pub fn max_abs_diff(a: &[u8], b: &[u8]) -> u8 {
    a.iter().zip(b).map(|(&x, &y)| x.abs_diff(y)).max().unwrap_or(0)
}

/// Block size of `ssim`: 8×8 non-overlapping windows, the cheap variant of Wang et al. (2004).
const SSIM_BLOCK: usize = 8;

/// Mean structural similarity of the luma (Rec. 601 weights) of two `width`×`height` RGB
/// images over 8×8 blocks; 1.0 for identical images. Partial blocks at the edges are included.
pub fn ssim(width: u32, height: u32, a: &[u8], b: &[u8]) -> f64 {
    let (w, h) = (width as usize, height as usize);
    assert_eq!(a.len(), w * h * 3, "ssim: first image has the wrong size");
    assert_eq!(b.len(), w * h * 3, "ssim: second image has the wrong size");
    let luma = |img: &[u8], i: usize| {
        0.299 * img[3 * i] as f64 + 0.587 * img[3 * i + 1] as f64 + 0.114 * img[3 * i + 2] as f64
    };
    // Stabilising constants for a dynamic range of 255, as in the paper.
    let c1 = (0.01f64 * 255.0).powi(2);
    let c2 = (0.03f64 * 255.0).powi(2);
    let (mut total, mut blocks) = (0.0, 0usize);
    for by in (0..h).step_by(SSIM_BLOCK) {
        for bx in (0..w).step_by(SSIM_BLOCK) {
            let (mut sa, mut sb, mut saa, mut sbb, mut sab, mut n) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
            for y in by..(by + SSIM_BLOCK).min(h) {
                for x in bx..(bx + SSIM_BLOCK).min(w) {
                    let (p, q) = (luma(a, y * w + x), luma(b, y * w + x));
                    sa += p;
                    sb += q;
                    saa += p * p;
                    sbb += q * q;
                    sab += p * q;
                    n += 1.0;
                }
            }
            let (ma, mb) = (sa / n, sb / n);
            let (va, vb, cov) = (saa / n - ma * ma, sbb / n - mb * mb, sab / n - ma * mb);
            total += ((2.0 * ma * mb + c1) * (2.0 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
            blocks += 1;
        }
    }
    if blocks == 0 {
        1.0
    } else {
        total / blocks as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient(w: usize, h: usize) -> Vec<u8> {
        (0..w * h * 3).map(|i| ((i * 7) % 256) as u8).collect()
    }

    #[test]
    fn identical_images_are_infinitely_close() {
        let a = gradient(16, 8);
        assert_eq!(psnr(&a, &a), f64::INFINITY);
        assert!((ssim(16, 8, &a, &a) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn known_noise_gives_known_psnr() {
        // ±5 on every value: MSE = 25, PSNR = 20·log10(255/5) = 34.15 dB.
        let a = vec![128u8; 300];
        let b: Vec<u8> = (0..300).map(|i| if i % 2 == 0 { 133 } else { 123 }).collect();
        assert!((psnr(&a, &b) - 20.0 * (255.0f64 / 5.0).log10()).abs() < 1e-9);
        // One value off by 255 in 3·100 values: MSE = 255²/300, PSNR = 10·log10(300) = 24.77 dB.
        let mut c = vec![0u8; 300];
        c[17] = 255;
        assert!((psnr(&vec![0u8; 300], &c) - 10.0 * 300f64.log10()).abs() < 1e-9);
    }

    #[test]
    fn ssim_drops_with_structure_loss() {
        let a = gradient(32, 32);
        let flat = vec![128u8; a.len()];
        let s = ssim(32, 32, &a, &flat);
        assert!(s < 0.5, "{s}");
        let slightly: Vec<u8> = a.iter().map(|&v| v.saturating_add(1)).collect();
        assert!(ssim(32, 32, &a, &slightly) > 0.99);
    }
}
