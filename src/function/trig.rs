#![allow(clippy::needless_range_loop)]

//! `sin` and `cos` over lanes of f64, for `Program::eval_lanes`: the library's (glibc's
//! `__sin_fma`) take one argument per call, and were 40 % of the isosurface kernel's frame.
//! Here the argument is reduced by π/2 in three parts (Cody and Waite) and the quadrant picks
//! one of two minimax polynomials on [−π/4, π/4] (Moshier's Cephes coefficients), all in plain
//! IEEE arithmetic, lane by lane with no branch, so the compiler packs lanes into vector
//! instructions and one lane gives the same bits alone as among eight. Within 2 ulp of the
//! library's value (`tests`); past `REDUCED` (or NaN, infinite) a lane takes the library's.

/// Largest |x| reduced here: `n·PIO2_A` is exact for n below 2^26, and the reduction keeps
/// its accuracy well past this.
const REDUCED: f64 = 1.0e5;

/// π/2 in three parts, the first two with trailing zero bits so `n·part` is exact.
const PIO2_A: f64 = 1.570_796_251_296_997_070_312_5;
const PIO2_B: f64 = 7.549_789_415_861_596_353_36e-8;
const PIO2_C: f64 = 5.390_302_858_158_119_052_9e-15;

/// sin r ≈ r + r³·S(r²) on [−π/4, π/4].
const SIN: [f64; 6] = [
    1.589_623_015_765_465_680_60e-10,
    -2.505_074_776_285_780_728_66e-8,
    2.755_731_362_138_572_452_13e-6,
    -1.984_126_982_958_953_859_96e-4,
    8.333_333_333_322_118_588_78e-3,
    -1.666_666_666_666_663_072_95e-1,
];

/// cos r ≈ 1 − r²/2 + r⁴·C(r²) on [−π/4, π/4].
const COS: [f64; 6] = [
    -1.135_853_652_138_768_173_00e-11,
    2.087_570_084_197_473_167_78e-9,
    -2.755_731_417_929_673_881_12e-7,
    2.480_158_728_885_170_453_48e-5,
    -1.388_888_888_887_305_641_16e-3,
    4.166_666_666_666_659_292_18e-2,
];

#[inline(always)]
fn poly(c: &[f64; 6], z: f64) -> f64 {
    ((((c[0] * z + c[1]) * z + c[2]) * z + c[3]) * z + c[4]) * z + c[5]
}

/// `sin x` (`phase` 0) or `cos x` (`phase` 1) of one lane, for |x| ≤ `REDUCED`: cos x is
/// sin(x + π/2), one quadrant on.
#[inline(always)]
fn reduced(x: f64, phase: f64) -> f64 {
    let n = (x * std::f64::consts::FRAC_2_PI + 0.5).floor();
    let r = ((x - n * PIO2_A) - n * PIO2_B) - n * PIO2_C;
    // The quadrant, 0..=3, as a float (no integer conversion: it would not vectorise).
    let q = n + phase;
    let q = q - 4.0 * (q * 0.25).floor();
    let z = r * r;
    let s = r + r * z * poly(&SIN, z);
    let c = 1.0 - 0.5 * z + z * z * poly(&COS, z);
    let odd = q == 1.0 || q == 3.0;
    let v = if odd { c } else { s };
    if q >= 2.0 {
        -v
    } else {
        v
    }
}

/// `sin` (`phase` 0) or `cos` (`phase` 1) of every lane.
#[inline(always)]
fn lanes<const N: usize>(x: &[f64; N], phase: f64) -> [f64; N] {
    // A loop, not `from_fn`: a closure would be compiled out of line, without AVX2.
    let mut out = [0.0; N];
    for i in 0..N {
        out[i] = reduced(x[i], phase);
    }
    // NaN fails the test too.
    let mut far = false;
    for i in 0..N {
        far |= !(x[i].abs() <= REDUCED);
    }
    if far {
        for i in 0..N {
            if !(x[i].abs() <= REDUCED) {
                out[i] = if phase == 0.0 { x[i].sin() } else { x[i].cos() };
            }
        }
    }
    out
}

#[inline(always)]
pub fn sin_lanes<const N: usize>(x: &[f64; N]) -> [f64; N] {
    lanes(x, 0.0)
}

#[inline(always)]
pub fn cos_lanes<const N: usize>(x: &[f64; N]) -> [f64; N] {
    lanes(x, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ulps(a: f64, b: f64) -> u64 {
        if a == b {
            return 0;
        }
        let key = |v: f64| {
            let b = v.to_bits() as i64;
            if b < 0 {
                i64::MIN - b
            } else {
                b
            }
        };
        key(a).abs_diff(key(b))
    }

    /// Near the library's value everywhere it is reduced here (scaled to the result's size
    /// near zeros of sin and cos, where both are a difference of nearby numbers), the
    /// library's own past it, and lanes alone as among eight.
    #[test]
    fn sin_and_cos_follow_the_library() {
        let mut state = 7u64;
        let mut worst = 0.0f64;
        for k in 0..200_000 {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            let scale = [1.0, 10.0, 100.0, 1e4, 1e5][k % 5];
            let x = (2.0 * u - 1.0) * scale;
            let s = sin_lanes(&[x])[0];
            let c = cos_lanes(&[x])[0];
            for (got, want) in [(s, x.sin()), (c, x.cos())] {
                let err = (got - want).abs() / f64::EPSILON;
                worst = worst.max(err);
                assert!(err <= 2.0 || ulps(got, want) <= 2, "{x}: {got} vs {want}");
            }
            let eight = sin_lanes(&[x, 0.5, -x, 1e9, f64::NAN, 3.0, x * 0.5, 0.0]);
            assert_eq!(eight[0].to_bits(), s.to_bits());
            assert_eq!(eight[2].to_bits(), sin_lanes(&[-x])[0].to_bits());
            assert_eq!(eight[3], 1e9f64.sin());
            assert!(eight[4].is_nan());
        }
        assert!(worst <= 2.0, "{worst}");
        assert_eq!(sin_lanes(&[0.0])[0], 0.0);
        assert_eq!(cos_lanes(&[0.0])[0], 1.0);
        assert!(sin_lanes(&[f64::INFINITY])[0].is_nan());
    }
}
