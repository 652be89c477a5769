//! Noise patterns: bozo, granite, agate, wrinkles, dents, ripples, waves, and the turbulence
//! built into marble and wood, built on `shading::noise` (strahl's own noise, calibrated to
//! POV-Ray's statistics).

use glam::Vec3;

use crate::lanes::{Lane, V3};
use crate::noise::{noise, noise_lanes, turbulence_lanes, TurbulenceF32};

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

/// `marble turbulence A`'s coordinate before the wave: x + A_x · Σ_{i<octaves} ω^i ·
/// (2·noise(λ^i p) − 0.5). POV-Ray 3.7 builds marble's turbulence in rather than warping the
/// point (`Pattern32::build_in_turbulence`), and with scalar noise: on the plane x = 0.5,
/// `marble ramp_wave turbulence 0.02` read back (v − 0.5)/0.02 = 2·bozo − 0.5 to 2e-4 with one
/// octave (clipped to [0, 1], 0.3% of points) and the ω-weighted sum of those at p and λ·p,
/// λ²·p with octaves 2 and 3 (omega 0.7 lambda 3; rms 0.006, the rest a rarer clipping left
/// out); the y and z amounts change nothing. So the veins sit A·Σω^i/2 further along x than a
/// warp would put them (0.5 per octave, 1.05 at the default six).
#[inline(always)]
pub fn marble_turbulent<L: Lane>(p: V3<L>, t: &TurbulenceF32, max_octaves: Option<u32>) -> L {
    let octaves = max_octaves.map_or(t.octaves, |cap| t.octaves.min(cap));
    let mut sum = L::splat(0.0);
    let (mut freq, mut amp) = (1.0f32, 1.0f32);
    for _ in 0..octaves {
        let n = noise_lanes(p.scale(L::splat(freq)));
        sum = sum + (L::splat(2.0) * n - L::splat(0.5)) * L::splat(amp);
        freq *= t.lambda;
        amp *= t.omega;
    }
    p.x + L::splat(t.amount.x) * sum
}

/// POV-Ray 3.7's `wood` does not take `turbulence` as a plain warp. Measured on renders of
/// `wood turbulence A` (no transform): the rings come closer by 1 + 5.9·A (A = 0.005: 2.9%,
/// 0.01: 5.9%, 0.02: 10.4%) whatever the octaves, while `onion` and `gradient` keep their
/// spacing, and the rings wobble far more than the warp predicts. Both fit a cycloidal
/// displacement, x' = x + sin(2π·A·(x + T_x)) with T the vector turbulence (5.9 ≈ 2π is its
/// slope at the origin). With it the DMFWood4 red channel differs from POV-Ray's by 0.035 per
/// pixel on average (0.043 with the warp and a ring-density factor; the rest is our noise).
#[inline(always)]
pub fn wood_cycloidal<L: Lane>(p: V3<L>, t: &TurbulenceF32, max_octaves: Option<u32>) -> V3<L> {
    let turb = turbulence_lanes(p, t, max_octaves);
    let (ax, ay) = (L::splat(t.amount.x), L::splat(t.amount.y));
    V3 { x: p.x + sin_turns((p.x + turb.x) * ax), y: p.y + sin_turns((p.y + turb.y) * ay), z: p.z }
}

/// `sin(2π·x)` by range reduction to one turn and an odd polynomial (max error 1e-6, against
/// `f32::sin`'s ~40 instructions and a libm call; two per wood hit were 3% of the seed scene).
#[inline(always)]
fn sin_turns<L: Lane>(x: L) -> L {
    // y in [-0.5, 0.5] turns, then fold to [-0.25, 0.25] where the polynomial is accurate.
    let y = x - x.map(f32::round);
    let (quarter, half) = (L::splat(0.25), L::splat(0.5));
    let y = L::select(quarter.lt(y), half - y, L::select(y.lt(-quarter), -half - y, y));
    let z = y * y;
    // Taylor coefficients of sin(2πy) up to y^11: (2π)^k / k!, alternating.
    let c = |v: f32| L::splat(v);
    let p = c(6.283_185_5)
        + z * (c(-41.341_7) + z * (c(81.605_25) + z * (c(-76.705_86) + z * (c(42.058_69) + z * c(-15.094_64)))));
    y * p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sin_turns_matches_sin() {
        for i in -20_000..20_000 {
            let x = i as f32 * 0.000_37;
            let want = (x as f64 * std::f64::consts::TAU).sin();
            assert!((sin_turns::<f32>(x) as f64 - want).abs() < 2e-6, "x = {x}");
        }
    }
}
