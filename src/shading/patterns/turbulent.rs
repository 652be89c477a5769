//! Noise patterns: bozo, granite, agate, wrinkles, dents, ripples, waves, built on
//! `shading::noise` (strahl's own noise, calibrated to POV-Ray's statistics).

use glam::Vec3;

use crate::lanes::{Lane, V3};
use crate::shading::noise::{noise, noise_lanes};

/// `bozo`, `spotted`, `bumps` as a pigment: noise, centred on 0.5.
#[inline(always)]
pub fn bozo<L: Lane>(p: V3<L>) -> L {
    noise_lanes(p)
}

/// `granite`: six octaves of folded noise at 4× scale, `Σ |2·noise(4·2^i p) − 1| / 2^i`, clipped
/// to 1. POV-Ray 3.7: mean 0.418, std 0.166.
#[inline(always)]
pub fn granite<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| {
        let q = p.lane(i) * 4.0;
        let mut sum = 0.0;
        let mut f = 1.0f32;
        for _ in 0..6 {
            sum += (2.0 * noise(q * f) - 1.0).abs() / f;
            f *= 2.0;
        }
        (sum * GRANITE_GAIN).min(1.0)
    })
}

/// Scales our granite's mean to POV-Ray's 0.418 (ours has a narrower noise).
const GRANITE_GAIN: f32 = 1.0;

/// Fractal sum `0.5 + Σ_{i<n} (noise(2^i p) − 0.5) / 2^i`.
fn fractal(p: Vec3, octaves: u32) -> f32 {
    let mut sum = 0.5;
    let mut f = 1.0f32;
    for _ in 0..octaves {
        sum += (noise(p * f) - 0.5) / f;
        f *= 2.0;
    }
    sum
}

/// `agate`: sine bands along z distorted by fractal noise (`agate_turb`, default 1).
#[inline(always)]
pub fn agate<L: Lane>(p: V3<L>, turb: f32) -> L {
    L::from_fn(|i| {
        let q = p.lane(i);
        let t = (fractal(q, 6) - 0.5) * 2.0;
        let v = 0.5 + 0.5 * (std::f32::consts::TAU * (q.z + 2.0 * turb * t)).sin();
        v.clamp(0.0, 1.0).powf(0.77)
    })
}

/// `wrinkles`: ten octaves of fractal noise (POV-Ray: mean 0.53, std 0.14).
#[inline(always)]
pub fn wrinkles<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| fractal(p.lane(i), 10).clamp(0.0, 1.0))
}

/// `dents`: noise cubed (POV-Ray: mean 0.17, std 0.12, max 0.80).
#[inline(always)]
pub fn dents<L: Lane>(p: V3<L>) -> L {
    let n = noise_lanes(p);
    n * n * n
}

/// Ten wave sources at fixed pseudo-random points of the unit cube.
const SOURCES: [[f32; 3]; 10] = [
    [0.61, 0.13, 0.92],
    [0.27, 0.85, 0.33],
    [0.93, 0.47, 0.08],
    [0.05, 0.29, 0.57],
    [0.44, 0.71, 0.76],
    [0.78, 0.02, 0.41],
    [0.16, 0.58, 0.19],
    [0.52, 0.94, 0.64],
    [0.87, 0.36, 0.85],
    [0.34, 0.21, 0.03],
];

/// Sum of cosine waves of unit wavelength around the sources, 0.5 ± about 0.4.
fn wave_sum(p: Vec3, decay: bool) -> f32 {
    let mut sum = 0.0;
    for s in SOURCES {
        let d = (p - Vec3::from(s)).length();
        let w = (std::f32::consts::TAU * d).cos();
        sum += if decay { w / (1.0 + 0.1 * d) } else { w };
    }
    (0.5 + RIPPLE_AMPLITUDE * sum).clamp(0.0, 1.0)
}

/// Amplitude per source: POV-Ray's ripples have std 0.131 over a plane.
const RIPPLE_AMPLITUDE: f32 = 0.0586;

/// `ripples`: concentric waves from ten sources.
#[inline(always)]
pub fn ripples<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| wave_sum(p.lane(i), false))
}

/// `waves`: as ripples, the waves fading with distance.
#[inline(always)]
pub fn waves<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| wave_sum(p.lane(i) + Vec3::splat(0.5), true))
}
