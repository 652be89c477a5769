//! POV-Ray's adaptive focal blur: `blur_samples` is a most, not a count. A pixel stops taking
//! blur rays once its mean colour is, with probability `confidence`, near the colour more rays
//! would give, `variance` saying how near (POV-Ray 3.7 reference, "Focal Blur": "the process
//! of shooting sample rays is terminated when the estimated color value is very likely (as
//! controlled by the confidence probability) near the real color value"). Where the lens sees
//! one flat colour that happens after `blur_samples`'s minimum; along blurred edges it takes up
//! to the maximum.
//!
//! The test, after each sample from the minimum on: the two-sided `confidence` interval of the
//! mean (normal, from the samples' unbiased variance s²) is at most `variance` wide on either
//! side, in every channel: `z·s/√n ≤ variance`. `variance` is thus a colour difference, as
//! POV-Ray's reference describes it ("in the range of the smallest displayable color
//! difference", default 1/128).
//!
//! Measured against POV-Ray 3.7's statistics (camera rays per pixel, defaults 0.9 and 1/128):
//! on its `camera/focalblur.pov` (at most 120 rays, 320×240) it takes 28 and strahl 28.5. On a
//! blurred two-colour checker at 160×120 a flat colour takes 7 in both (the default minimum);
//! colours 0.04 apart take 27 there and 18 here, 0.1 apart 56 and 110, 0.2 apart 111 and 118.
//!
//! The decision is a pixel's own, from its own samples in sample order, so an image is the same
//! bits on any thread count and with packets or without.

use glam::Vec3;

use crate::desc::FocalBlur;

/// When a pixel's blur samples may stop: the scene's `blur_samples` minimum, `confidence` as
/// the squared normal quantile, and `variance` squared.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BlurStop {
    min: u32,
    z2: f32,
    tolerance2: f32,
}

impl BlurStop {
    /// The stop for `blur` when each sample takes up to `max` rays; `None` where every ray is
    /// taken anyway (a minimum at the maximum, `variance 0`, `confidence` 1 or more).
    pub(crate) fn new(blur: &FocalBlur, max: u32) -> Option<BlurStop> {
        // Two samples at least: one has no variance.
        let min = blur.min_samples.max(2);
        let usable = min < max && blur.variance > 0.0 && blur.confidence < 1.0;
        usable.then(|| {
            let z = normal_quantile(0.5 + 0.5 * blur.confidence.max(0.0));
            BlurStop { min, z2: (z * z) as f32, tolerance2: (blur.variance * blur.variance) as f32 }
        })
    }
}

/// One pixel's blur samples so far: their sum, the sum of their squares and their count.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct BlurSum {
    sum: Vec3,
    squares: Vec3,
    n: u32,
}

impl BlurSum {
    /// Adds one sample (an output colour, or black for a ray that was not traced).
    #[inline]
    pub(crate) fn add(&mut self, c: Vec3) {
        self.sum += c;
        self.squares += c * c;
        self.n += 1;
    }

    /// The sum of the samples.
    pub(crate) fn sum(&self) -> Vec3 {
        self.sum
    }

    /// The mean of the samples (the sum itself for one sample, as a single ray gives it).
    pub(crate) fn mean(&self) -> Vec3 {
        if self.n > 1 {
            self.sum / self.n as f32
        } else {
            self.sum
        }
    }

    /// Whether `stop` ends this pixel's sampling here.
    #[inline]
    pub(crate) fn converged(&self, stop: &BlurStop) -> bool {
        if self.n < stop.min {
            return false;
        }
        let n = self.n as f32;
        let spread = (self.squares - self.sum * (self.sum / n)).max(Vec3::ZERO) / (n - 1.0);
        spread.max_element() * stop.z2 <= stop.tolerance2 * n
    }
}

/// The `p`-quantile of the standard normal distribution (0 < p < 1), by bisection on its
/// distribution function: computed once per render, so plain and accurate beats fast.
fn normal_quantile(p: f64) -> f64 {
    let (mut lo, mut hi) = (-40.0f64, 40.0f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if normal_cdf(mid) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The standard normal distribution function, 0.5·erfc(−x/√2), with erfc by its continued
/// fraction far out and its Taylor series of erf near 0 (both to about 1e-15).
fn normal_cdf(x: f64) -> f64 {
    let t = -x / std::f64::consts::SQRT_2;
    0.5 * erfc(t)
}

fn erfc(x: f64) -> f64 {
    if x < 0.0 {
        return 2.0 - erfc(-x);
    }
    if x < 2.5 {
        // erf(x) = 2/√π Σ (−1)^k x^(2k+1) / (k! (2k+1))
        let mut term = x;
        let mut sum = x;
        let mut k = 0.0;
        while term.abs() > 1e-17 * sum.abs() {
            k += 1.0;
            term *= -x * x / k;
            sum += term / (2.0 * k + 1.0);
        }
        return 1.0 - 2.0 / std::f64::consts::PI.sqrt() * sum;
    }
    // erfc(x) = e^(−x²)/√π · 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + 2/(x + …))))), from the tail.
    let mut f = x;
    for k in (1..60).rev() {
        f = x + (k as f64 / 2.0) / f;
    }
    (-x * x).exp() / std::f64::consts::PI.sqrt() / f
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stop(min: u32, confidence: f64, variance: f64) -> Option<BlurStop> {
        let blur = FocalBlur { min_samples: min, max_samples: 120, confidence, variance, ..FocalBlur::default() };
        BlurStop::new(&blur, 120)
    }

    #[test]
    fn normal_quantiles_match_tables() {
        for (p, z) in [(0.5, 0.0), (0.95, 1.644_853_627), (0.975, 1.959_963_985), (0.999_95, 3.890_591_886)] {
            assert!((normal_quantile(p) - z).abs() < 1e-8, "{p}: {} != {z}", normal_quantile(p));
        }
        assert!((normal_quantile(0.025) + 1.959_963_985).abs() < 1e-8);
    }

    #[test]
    fn flat_pixels_stop_at_the_minimum_and_spread_ones_go_on() {
        let s = stop(4, 0.9, 1.0 / 128.0).expect("adaptive");
        let mut flat = BlurSum::default();
        for k in 0..4 {
            assert!(!flat.converged(&s), "stopped after {k}");
            flat.add(Vec3::splat(0.3));
        }
        assert!(flat.converged(&s));
        // Two colours 0.04 apart: s² ≈ 0.0004, z² ≈ 2.71, (1/128)²: about 19 samples.
        let mut edge = BlurSum::default();
        let mut n = 0;
        while !edge.converged(&s) {
            edge.add(Vec3::splat(if n % 2 == 0 { 0.48 } else { 0.52 }));
            n += 1;
        }
        assert!((17..=21).contains(&n), "{n}");
        // A higher confidence or a smaller variance takes more.
        let strict = stop(4, 0.99, 1.0 / 255.0).expect("adaptive");
        assert!(!edge.converged(&strict));
    }

    #[test]
    fn all_rays_when_nothing_can_stop_early() {
        assert_eq!(stop(4, 0.9, 0.0), None);
        assert_eq!(stop(4, 1.0, 1.0 / 128.0), None);
        assert_eq!(stop(120, 0.9, 1.0 / 128.0), None);
        // One sample has no variance: the minimum is two.
        let s = stop(1, 0.9, 1.0).expect("adaptive");
        let mut one = BlurSum::default();
        one.add(Vec3::ONE);
        assert!(!one.converged(&s));
    }

    #[test]
    fn the_mean_of_one_sample_is_the_sample() {
        let mut one = BlurSum::default();
        one.add(Vec3::new(0.1, 0.2, 0.3));
        assert_eq!(one.mean(), Vec3::new(0.1, 0.2, 0.3));
        one.add(Vec3::new(0.3, 0.2, 0.1));
        assert_eq!(one.mean(), Vec3::new(0.2, 0.2, 0.2));
    }
}
