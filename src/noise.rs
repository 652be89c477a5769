//! Lattice gradient noise with POV-Ray's character: `noise` (scalar, centred on 0.5), `dnoise`
//! (vector, centred on 0) and `turbulence` (octave sums of `dnoise`).
//!
//! Our own Perlin-style noise, not POV-Ray's tables: unit lattice, cubic s-curve blending
//! (`3t² − 2t³`, as POV-Ray uses), gradients picked by a fixed permutation that a const fn builds
//! from an integer hash at compile time. No state, no allocation, no RNG crate: the same point
//! always gives the same value on every thread.
//!
//! Calibration against POV-Ray 3.7.0.10 (orthographic 320×240 views of a plane at z = −0.37
//! covering 40×30 units; `examples/pattern_calibration.rs` redoes it):
//! - `f_noise3d` (POV-Ray's `Noise`): mean 0.505, std 0.122, range [0.06, 0.94]; autocorrelation
//!   0.56 at a lag of 0.5 units and 0.06 at 1 unit.
//! - `gradient x/y/z` with `turbulence 0.1 octaves 1` gives one `DNoise` component: std 0.249,
//!   0.248, 0.258, range about ±0.9, same autocorrelation as `Noise`.
//!
//! The two scale constants below are set so ours has the same standard deviations; the lattice
//! spacing and s-curve give a similar autocorrelation: ours 0.50 at 0.5 units and 0.02 at 1 unit,
//! so POV-Ray's features are about 10% larger (the lag where it falls to 0.5: 0.55 vs 0.50).

use glam::{Mat3A, Vec3, Vec3A};

use crate::lanes::{Lane, V3};

/// The noise lattice repeats every this many units on each axis: `cell` and `dnoise_lanes`
/// wrap the lattice coordinates with `& 255`. Patterns made of noise repeat with it, which
/// lets `pattern_space::pattern_from_render` drop whole periods from a far pattern origin.
pub const LATTICE_PERIOD: f64 = 256.0;

/// Turbulence of a pattern, render-ready (from a `desc::Turbulence`: `shading::pattern_space`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurbulenceF32 {
    /// Displacement per axis (`turbulence <x,y,z>`), in pattern units.
    pub amount: Vec3,
    pub octaves: u32,
    /// Amplitude multiplier per octave.
    pub omega: f32,
    /// Frequency multiplier per octave.
    pub lambda: f32,
}

/// Scales our raw gradient noise (std 0.2547 over 200k random points, see
/// `tests::raw_noise_spread`) to POV-Ray's `Noise` std of 0.122.
const NOISE_SCALE: f32 = 0.122 / 0.2547;
/// Scales each raw component to POV-Ray's `DNoise` component std of 0.251 (mean of x, y, z).
const DNOISE_SCALE: f32 = 0.251 / 0.2547;

/// A 32-bit integer mixer (xorshift–multiply rounds, constants from the public "hash prospector"
/// search for low-bias 32-bit permutations). Bijective, so distinct inputs stay distinct.
const fn mix32(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

/// A permutation of 0..=255 by a Fisher–Yates shuffle driven by `mix32`, doubled to 512
/// entries so `PERM[PERM[x] + y]` never needs a mask.
const fn build_perm() -> [u8; 512] {
    let mut p = [0u8; 256];
    let mut i = 0;
    while i < 256 {
        p[i] = i as u8;
        i += 1;
    }
    let mut i = 255;
    while i > 0 {
        let j = (mix32(0x5eed_0000 + i as u32) % (i as u32 + 1)) as usize;
        let t = p[i];
        p[i] = p[j];
        p[j] = t;
        i -= 1;
    }
    let mut out = [0u8; 512];
    let mut i = 0;
    while i < 512 {
        out[i] = p[i & 255];
        i += 1;
    }
    out
}

static PERM: [u8; 512] = build_perm();

/// Perlin's 12 cube-edge directions, padded to 16 with four repeats so a 4-bit index picks one
/// without a modulo (the repeats form a tetrahedron, so no direction is favoured).
const GRADIENTS: [Vec3; 16] = [
    Vec3::new(1.0, 1.0, 0.0),
    Vec3::new(-1.0, 1.0, 0.0),
    Vec3::new(1.0, -1.0, 0.0),
    Vec3::new(-1.0, -1.0, 0.0),
    Vec3::new(1.0, 0.0, 1.0),
    Vec3::new(-1.0, 0.0, 1.0),
    Vec3::new(1.0, 0.0, -1.0),
    Vec3::new(-1.0, 0.0, -1.0),
    Vec3::new(0.0, 1.0, 1.0),
    Vec3::new(0.0, -1.0, 1.0),
    Vec3::new(0.0, 1.0, -1.0),
    Vec3::new(0.0, -1.0, -1.0),
    Vec3::new(1.0, 1.0, 0.0),
    Vec3::new(-1.0, 1.0, 0.0),
    Vec3::new(0.0, -1.0, 1.0),
    Vec3::new(0.0, -1.0, -1.0),
];

/// Per lattice hash: three gradients (one per `dnoise` component) as the rows of a matrix, so a
/// corner's three dot products are one `Mat3 * Vec3`. 256 × 36 bytes = 9 KiB, L1-resident.
/// Row 0 doubles as the scalar `noise` gradient.
const fn build_grad3() -> [Mat3A; 256] {
    let mut t = [Mat3A::ZERO; 256];
    let mut i = 0;
    while i < 256 {
        let h = mix32(0xd1ce_0000 ^ i as u32);
        let g0 = GRADIENTS[(h & 15) as usize];
        let g1 = GRADIENTS[((h >> 8) & 15) as usize];
        let g2 = GRADIENTS[((h >> 16) & 15) as usize];
        // Columns hold the x, y, z parts of the three gradients, so M * d = (g0·d, g1·d, g2·d).
        t[i] =
            Mat3A::from_cols(Vec3A::new(g0.x, g1.x, g2.x), Vec3A::new(g0.y, g1.y, g2.y), Vec3A::new(g0.z, g1.z, g2.z));
        i += 1;
    }
    t
}

/// 16-byte aligned columns: the per-corner product is three SIMD multiply-adds (the seed
/// scene's dnoise went from 360 to about 250 instructions a call, measured with callgrind).
static GRAD3: [Mat3A; 256] = build_grad3();

/// `GRAD3` as bits, for computing gradients eight lanes at a time without gathering floats:
/// bit `3j + k` is set where component `k` of gradient `j` is non-zero, bit `16 + 3j + k` where
/// it is negative.
const fn build_grad_bits() -> [u32; 256] {
    let mut t = [0u32; 256];
    let mut i = 0;
    while i < 256 {
        let h = mix32(0xd1ce_0000 ^ i as u32);
        let g =
            [GRADIENTS[(h & 15) as usize], GRADIENTS[((h >> 8) & 15) as usize], GRADIENTS[((h >> 16) & 15) as usize]];
        let mut bits = 0;
        let mut j = 0;
        while j < 3 {
            let c = [g[j].x, g[j].y, g[j].z];
            let mut k = 0;
            while k < 3 {
                if c[k] != 0.0 {
                    bits |= 1 << (3 * j + k);
                }
                if c[k] < 0.0 {
                    bits |= 1 << (16 + 3 * j + k);
                }
                k += 1;
            }
            j += 1;
        }
        t[i] = bits;
        i += 1;
    }
    t
}

/// `build_grad_bits()[PERM[i]]`: the last step of the corner hash and the gradient lookup in one load.
const fn build_perm_grad_bits() -> [u32; 512] {
    let (perm, grad) = (build_perm(), build_grad_bits());
    let mut t = [0u32; 512];
    let mut i = 0;
    while i < 512 {
        t[i] = grad[perm[i] as usize];
        i += 1;
    }
    t
}

static PERM_GRAD_BITS: [u32; 512] = build_perm_grad_bits();

/// The lattice cell around `p`: corner hashes, offset from the low corner, s-curve weights.
struct Cell {
    /// Hash of corner (i, j, k) at index `i | j << 1 | k << 2`.
    hash: [u8; 8],
    frac: Vec3,
    weight: Vec3,
}

#[inline]
fn cell(p: Vec3) -> Cell {
    let floor = p.floor();
    let frac = p - floor;
    // `as i32` saturates for huge inputs; `& 255` wraps the lattice every 256 units.
    let x = (floor.x as i32 & 255) as usize;
    let y = (floor.y as i32 & 255) as usize;
    let z = (floor.z as i32 & 255) as usize;
    let a = PERM[x] as usize + y;
    let b = PERM[x + 1] as usize + y;
    let (aa, ab) = (PERM[a] as usize + z, PERM[a + 1] as usize + z);
    let (ba, bb) = (PERM[b] as usize + z, PERM[b + 1] as usize + z);
    let hash = [PERM[aa], PERM[ba], PERM[ab], PERM[bb], PERM[aa + 1], PERM[ba + 1], PERM[ab + 1], PERM[bb + 1]];
    let weight = frac * frac * (Vec3::splat(3.0) - 2.0 * frac);
    Cell { hash, frac, weight }
}

/// Offset of `frac` from corner `c` (bits: x, y, z).
#[inline]
fn corner_offset(frac: Vec3, c: usize) -> Vec3 {
    frac - Vec3::new((c & 1) as f32, ((c >> 1) & 1) as f32, ((c >> 2) & 1) as f32)
}

/// Trilinear blend of eight corner values with s-curve weights.
#[inline]
fn blend<T>(v: [T; 8], w: Vec3) -> T
where
    T: Copy + std::ops::Sub<Output = T> + std::ops::Add<Output = T> + std::ops::Mul<f32, Output = T>,
{
    let lerp = |a: T, b: T, t: f32| a + (b - a) * t;
    let x00 = lerp(v[0], v[1], w.x);
    let x10 = lerp(v[2], v[3], w.x);
    let x01 = lerp(v[4], v[5], w.x);
    let x11 = lerp(v[6], v[7], w.x);
    lerp(lerp(x00, x10, w.y), lerp(x01, x11, w.y), w.z)
}

/// Raw gradient noise in about [-1, 1], zero on lattice points.
#[inline]
fn raw_noise(p: Vec3) -> f32 {
    let c = cell(p);
    let mut v = [0.0f32; 8];
    for (i, v) in v.iter_mut().enumerate() {
        // Row 0 of the matrix is the scalar gradient.
        let m = &GRAD3[c.hash[i] as usize];
        *v = Vec3::new(m.x_axis.x, m.y_axis.x, m.z_axis.x).dot(corner_offset(c.frac, i));
    }
    blend(v, c.weight)
}

/// Where the scalar noise's lattice sits: POV-Ray's `Noise` is not pinned to 0.5 on integer
/// points (measured: bozo on the plane z = 0 at the 196 points (i, j, 0), 1 ≤ i, j ≤ 14, has
/// std 0.141, as anywhere else), while gradient noise is zero on its lattice, so a pattern on
/// a plane through lattice points (a floor at y = 0, a box face at z = 0) showed a grid of
/// grey dots that `granite`'s folded octaves drew as lines. Moving our lattice off the integer
/// points by this keeps the statistics and puts its zeros where planes seldom lie. On a plane
/// the feature size depends on how far the plane is from the lattice (the nearer, the more
/// the noise turns 2D-like and finer): z moves by 0.74, so the calibration plane z = −0.37
/// stays 0.37 from it (autocorrelation 0.50 at 0.5 units, as before) and z = 0 lies 0.26 off.
/// `dnoise` keeps the integer lattice: the seed scene's bumps and wood turbulence use it.
const NOISE_OFFSET: Vec3 = Vec3::new(0.414_213_56, 0.732_050_8, 0.74);

/// POV-Ray-style scalar noise: centred on 0.5, std 0.122, clipped to [0, 1].
#[inline]
pub fn noise(p: Vec3) -> f32 {
    (0.5 + NOISE_SCALE * raw_noise(p + NOISE_OFFSET)).clamp(0.0, 1.0)
}

/// `noise` for one or eight points, lane by lane with the scalar kernel (the same bits).
#[inline(always)]
pub fn noise_lanes<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| noise(p.lane(i)))
}

/// POV-Ray-style vector noise: three independent gradient noises sharing one lattice walk,
/// each component centred on 0 with std 0.251 (range about ±1).
#[inline]
pub fn dnoise(p: Vec3) -> Vec3 {
    dnoise_lanes(V3::from_vec3(p)).vec3()
}

/// `dnoise` for one or eight points, bit-identical lane by lane. The lattice hashes are looked
/// up lane by lane; everything else is lane arithmetic. A gradient component is −1, 0 or 1, so
/// its product with the offset is a sign flip or a zero (`Lane::times_unit` on `PERM_GRAD_BITS`),
/// and the products are summed in `Mat3A * Vec3A` order.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // `lane` picks one lane of `floor` and of every corner's bits
pub fn dnoise_lanes<L: Lane>(p: V3<L>) -> V3<L> {
    let floor = V3 { x: p.x.floor(), y: p.y.floor(), z: p.z.floor() };
    let frac = p.sub(floor);
    let (three, two) = (L::splat(3.0), L::splat(2.0));
    let weight = V3 {
        x: frac.x * frac.x * (three - two * frac.x),
        y: frac.y * frac.y * (three - two * frac.y),
        z: frac.z * frac.z * (three - two * frac.z),
    };
    // Gradient bits of corner (i, j, k) at index `i | j << 1 | k << 2`, per lane.
    let mut bits = [[0u32; 8]; 8];
    for lane in 0..L::WIDTH {
        // `as i32` saturates for huge inputs; `& 255` wraps the lattice every 256 units.
        let x = (floor.x.get(lane) as i32 & 255) as usize;
        let y = (floor.y.get(lane) as i32 & 255) as usize;
        let z = (floor.z.get(lane) as i32 & 255) as usize;
        let a = PERM[x] as usize + y;
        let b = PERM[x + 1] as usize + y;
        let (aa, ab) = (PERM[a] as usize + z, PERM[a + 1] as usize + z);
        let (ba, bb) = (PERM[b] as usize + z, PERM[b + 1] as usize + z);
        let corners = [aa, ba, ab, bb, aa + 1, ba + 1, ab + 1, bb + 1];
        for (c, &corner) in corners.iter().enumerate() {
            bits[c][lane] = PERM_GRAD_BITS[corner];
        }
    }
    let c = |i: usize| corner_dot(&bits[i], frac, i);
    let x00 = lerp3(c(0), c(1), weight.x);
    let x10 = lerp3(c(2), c(3), weight.x);
    let x01 = lerp3(c(4), c(5), weight.x);
    let x11 = lerp3(c(6), c(7), weight.x);
    lerp3(lerp3(x00, x10, weight.y), lerp3(x01, x11, weight.y), weight.z).scale(L::splat(DNOISE_SCALE))
}

#[inline(always)]
fn lerp3<L: Lane>(a: V3<L>, b: V3<L>, t: L) -> V3<L> {
    a.add(b.sub(a).scale(t))
}

/// Corner `c`'s three gradients dotted with the offset from it, per lane.
#[inline(always)]
fn corner_dot<L: Lane>(bits: &[u32; 8], frac: V3<L>, c: usize) -> V3<L> {
    let (zero, one) = (L::splat(0.0), L::splat(1.0));
    let d = V3 {
        x: if c & 1 == 0 { frac.x - zero } else { frac.x - one },
        y: if c & 2 == 0 { frac.y - zero } else { frac.y - one },
        z: if c & 4 == 0 { frac.z - zero } else { frac.z - one },
    };
    V3 {
        x: d.x.times_unit(bits, 0) + d.y.times_unit(bits, 1) + d.z.times_unit(bits, 2),
        y: d.x.times_unit(bits, 3) + d.y.times_unit(bits, 4) + d.z.times_unit(bits, 5),
        z: d.x.times_unit(bits, 6) + d.y.times_unit(bits, 7) + d.z.times_unit(bits, 8),
    }
}

/// POV-Ray's vector turbulence: `Σ_{i<octaves} ω^i · dnoise(λ^i · p)`, with the octave count
/// capped at `max_octaves` (a quality knob; `None` = as written).
#[inline]
pub fn turbulence(p: Vec3, t: &TurbulenceF32, max_octaves: Option<u32>) -> Vec3 {
    turbulence_lanes(V3::from_vec3(p), t, max_octaves).vec3()
}

/// `turbulence` for one or eight points.
#[inline(always)]
pub fn turbulence_lanes<L: Lane>(p: V3<L>, t: &TurbulenceF32, max_octaves: Option<u32>) -> V3<L> {
    let octaves = match max_octaves {
        Some(cap) => t.octaves.min(cap),
        None => t.octaves,
    };
    let mut sum = V3::splat(Vec3::ZERO);
    let mut freq = 1.0f32;
    let mut amp = 1.0f32;
    for _ in 0..octaves {
        sum = sum.add(dnoise_lanes(p.scale(L::splat(freq))).scale(L::splat(amp)));
        freq *= t.lambda;
        amp *= t.omega;
    }
    sum
}

/// The point a turbulent pattern is evaluated at: `p + amount ⊙ turbulence(p)`.
#[inline]
pub fn warp(p: Vec3, t: &TurbulenceF32, max_octaves: Option<u32>) -> Vec3 {
    warp_lanes(V3::from_vec3(p), t, max_octaves).vec3()
}

/// `warp` for one or eight points.
#[inline(always)]
pub fn warp_lanes<L: Lane>(p: V3<L>, t: &TurbulenceF32, max_octaves: Option<u32>) -> V3<L> {
    p.add(V3::splat(t.amount).mul(turbulence_lanes(p, t, max_octaves)))
}

#[cfg(test)]
mod tests;
