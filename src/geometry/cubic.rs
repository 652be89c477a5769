//! Cubics in closed form, `N` lanes at a time in f64 (`wide::W`): the largest real root, for
//! the resolvent of Ferrari's quartic (`quartic`), and every real root, for cubic polynomials
//! (`poly::Poly` through `roots::smallest_root_by`). Neither calls the library's `acos`, `cos`
//! or `cbrt` (software routines here, a sixth of scenes/kernels/cubic.pov's frame when the
//! roots came from Viète's form): three real roots are found by Halley's steps onto the largest
//! and the quadratic left when it is divided out, one real root by Cardano's form with the
//! cube root below. One lane is the `N = 1` case of the same code, so packets and single rays
//! agree to the bit.

use super::wide::{and, not, or, Mask, W};

/// Lane-wise `v.is_finite()`.
#[inline(always)]
pub(super) fn finite<const N: usize>(v: W<N>) -> Mask<N> {
    v.0.map(f64::is_finite)
}

/// ∛x to within a few per cent (x finite, ≥ 0): the exponent divided by three in the bits.
#[inline(always)]
pub(super) fn rough_cbrt(x: f64) -> f64 {
    f64::from_bits(x.to_bits() / 3 + 0x2a9f_7893_782d_a1ce)
}

/// ∛x to a few ulps per lane: [`rough_cbrt`] and three Halley steps (each triples the digits);
/// the library's `cbrt` is a software routine here that cost 14 % of the torus benchmark.
#[cfg(test)]
#[inline(always)]
pub(super) fn cbrt<const N: usize>(x: W<N>) -> W<N> {
    cbrt_steps(x, 3)
}

/// [`cbrt`] with `steps` Halley steps: two give ten digits.
#[inline(always)]
fn cbrt_steps<const N: usize>(x: W<N>, steps: usize) -> W<N> {
    let a = x.abs();
    let mut y = a.map(rough_cbrt);
    for _ in 0..steps {
        let y3 = y * y * y;
        y = y * ((y3 + W::splat(2.0) * a) / (W::splat(2.0) * y3 + a));
    }
    let plain = or(a.0.map(|v| v == 0.0), not(finite(a)));
    W::select(plain, x, y.copysign(x))
}

/// How closely [`Depressed`] finds a root before its caller's Newton steps: to the rounding
/// (`FULL`), or to ten digits (`ROUGH`), which one Newton step then takes to the rounding.
#[derive(Clone, Copy)]
struct Settle {
    /// The last Halley step's size, relative to the roots' bound, that ends the iteration.
    halley: f64,
    cbrt_steps: usize,
}

const FULL: Settle = Settle { halley: 1e-15, cbrt_steps: 3 };
const ROUGH: Settle = Settle { halley: 1e-9, cbrt_steps: 2 };

/// m³ + a·m² + b·m + c = 0 moved to its depressed form y³ + p·y + q = 0 (m = y − shift), with
/// the lanes that have three real roots (a double one counting) and those that are NaN.
struct Depressed<const N: usize> {
    shift: W<N>,
    p: W<N>,
    q: W<N>,
    /// q²/4 + (p/3)³: negative with three distinct real roots, zero at a double one.
    h: W<N>,
    three: Mask<N>,
    nan: Mask<N>,
}

const THIRD: f64 = 1.0 / 3.0;

impl<const N: usize> Depressed<N> {
    #[inline(always)]
    fn of(a: W<N>, b: W<N>, c: W<N>) -> Depressed<N> {
        let k = W::<N>::splat;
        let shift = a * k(THIRD);
        let p = b - a * shift;
        let q = c - b * shift + k(2.0) * shift * shift * shift;
        let p3 = p * k(THIRD);
        let h = k(0.25) * q * q + p3 * p3 * p3;
        let nan = h.0.map(f64::is_nan);
        let three = and(h.le(k(0.0)), p.lt(k(0.0)));
        Depressed { shift, p, q, h, three, nan }
    }

    /// The largest real root `y` of y³ + p·y + q per lane (the only one where there is one).
    #[inline(always)]
    fn largest(&self) -> W<N> {
        self.largest_of(self.q, FULL)
    }

    /// The real root of largest magnitude per lane: never one of a double pair (whose
    /// magnitude is half of the third's), so Halley's steps reach it fast. It is the largest
    /// root of the cubic with `q` made non-positive (y ↦ −y where `q` is positive), its sign
    /// turned back.
    #[inline(always)]
    fn farthest(&self, settle: Settle) -> W<N> {
        let positive = W::<N>::splat(0.0).lt(self.q);
        let z = self.largest_of(-self.q.abs(), settle);
        W::select(positive, -z, z)
    }

    /// The largest real root of y³ + p·y + q per lane, for this cubic's `p` and `three`.
    #[inline(always)]
    fn largest_of(&self, q: W<N>, settle: Settle) -> W<N> {
        let k = W::<N>::splat;
        let (p, three) = (self.p, self.three);
        let p3 = p * k(THIRD);
        let mut y = k(0.0);
        if !three.iter().all(|&t| t) {
            // One real root: Cardano.
            let h = k(0.25) * q * q + p3 * p3 * p3;
            let s = h.max(k(0.0)).sqrt();
            let v = cbrt_steps(k(-0.5) * q + s.copysign(-q), settle.cbrt_steps);
            let zero: Mask<N> = v.0.map(|v| v == 0.0);
            y = W::select(zero, k(0.0), v - p3 / v);
        }
        if three.iter().any(|&t| t) {
            // Three real roots, all within ±r; the largest lies in [r/2, r]. Halley's steps from
            // r come down onto it (the cubic is convex there) and triple the digits each where
            // it is simple, so three or four reach the rounding: cheaper than Viète's `acos`
            // and `cos`.
            let r = k(2.0) * (-p3).sqrt();
            let mut z = r;
            let mut running = three;
            for _ in 0..6 {
                let g = (z * z + p) * z + q;
                let dg = k(3.0) * z * z + p;
                let step = k(2.0) * g * dg / (k(2.0) * dg * dg - k(6.0) * z * g);
                let moving = and(running, finite(step));
                z = W::select(moving, z - step, z);
                running = and(moving, not(step.abs().le(k(settle.halley) * r)));
                if !running.iter().any(|&b| b) {
                    break;
                }
            }
            y = W::select(three, z, y);
        }
        y
    }
}

/// Per lane, the largest real root of m³ + a·m² + b·m + c, polished by a Newton step; and the
/// lanes where it is NaN from the start.
#[inline(always)]
pub(super) fn largest_root_lanes<const N: usize>(a: W<N>, b: W<N>, c: W<N>) -> (W<N>, Mask<N>) {
    let d = Depressed::of(a, b, c);
    let m = d.largest() - d.shift;
    let g = ((m + a) * m + b) * m + c;
    let dg = (W::splat(3.0) * m + W::splat(2.0) * a) * m + b;
    let step = g / dg;
    (W::select(finite(step), m - step, m), d.nan)
}

/// Per lane, the real roots of x³ + a·x² + b·x + c, unpolished, in no particular order (+inf in
/// a slot without one): the root of largest magnitude, and where there are three, the two of
/// the quadratic left when it is divided out. A double root comes twice.
#[inline(always)]
pub(super) fn roots_lanes<const N: usize>(a: W<N>, b: W<N>, c: W<N>) -> [W<N>; 3] {
    roots_of(&Depressed::of(a, b, c), FULL)
}

/// [`roots_lanes`] to ten digits (for a caller that polishes each with two Newton steps), and
/// the lanes where they are ill-conditioned: NaN, or near a double root,
/// where `|h|` is below `ill` times its terms' size (`h` is −¾·δ²·r⁴ for a pair `δ` apart at
/// `r` from the third root's mirror, so `ill` = 10⁻⁶ flags pairs closer than about a
/// thousandth of their distance from the centre). There the pair is found to only the square
/// root of the rounding, or the rounding decides whether it is real at all (a grazing ray).
#[inline(always)]
pub(super) fn roots_lanes_conditioned<const N: usize>(a: W<N>, b: W<N>, c: W<N>, ill: f64) -> ([W<N>; 3], Mask<N>) {
    let d = Depressed::of(a, b, c);
    let p3 = d.p * W::splat(THIRD);
    let size = W::splat(0.25) * d.q * d.q + (p3 * p3 * p3).abs();
    let near_double = d.h.abs().le(W::splat(ill) * size);
    (roots_of(&d, ROUGH), or(d.nan, or(near_double, not(finite(size)))))
}

#[inline(always)]
fn roots_of<const N: usize>(d: &Depressed<N>, settle: Settle) -> [W<N>; 3] {
    let k = W::<N>::splat;
    let none = k(f64::INFINITY);
    let y = d.farthest(settle);
    let mut roots = [W::select(d.nan, none, y - d.shift), none, none];
    if d.three.iter().any(|&t| t) {
        // y² + y₀·y + (y₀² + p) = 0, y₀ the farthest: the stable quadratic (no cancellation
        // between −y₀ and the root), its discriminant kept from rounding below zero at a double
        // root.
        let (b2, c2) = (y, y * y + d.p);
        let disc = (b2 * b2 - k(4.0) * c2).max(k(0.0));
        let kk = k(-0.5) * (b2 + disc.sqrt().copysign(b2));
        let other = W::select(kk.0.map(|v| v != 0.0), c2 / kk, k(0.0));
        roots[1] = W::select(d.three, kk - d.shift, none);
        roots[2] = W::select(d.three, other - d.shift, none);
    }
    roots
}

/// Per lane, the smallest root in `(lo, hi)` of the cubic `c` (highest degree first, `c[0] ≠ 0`
/// in every lane), NaN where there is none: [`roots_lanes`] of the monic cubic, each root
/// polished by two Newton steps on `c` (each taken only where it lowers |c|; none for a root
/// far outside the span), the span first cut to Cauchy's bound.
#[inline(always)]
pub(super) fn smallest_root_lanes<const N: usize>(c: &[W<N>; 4], lo: W<N>, hi: W<N>) -> W<N> {
    let k = W::<N>::splat;
    let monic = [c[1] / c[0], c[2] / c[0], c[3] / c[0]];
    // Cauchy's bound: every root lies within it, so infinite ends become finite ones.
    let bound = k(1.0) + monic.iter().fold(k(0.0), |m, v| m.zip(v.abs(), f64::max));
    let (lo, hi) = (lo.zip(-bound, f64::max), hi.zip(bound, f64::min));
    let mut best = k(f64::NAN);
    let eval = |x: W<N>| c.iter().fold(k(0.0), |f, &v| f * x + v);
    // A root far outside the span stays out (a polish moves one by far less): it is not
    // polished, and a slot no lane needs polished costs nothing.
    let far = k(1e-6) * (lo.abs() + hi.abs() + k(1.0));
    for mut r in roots_lanes(monic[0], monic[1], monic[2]) {
        let near = and(finite(r), and((lo - far).lt(r), r.lt(hi + far)));
        if near.iter().any(|&b| b) {
            let mut f = eval(r);
            for _ in 0..2 {
                let df = c[..3].iter().enumerate().fold(k(0.0), |d, (i, &v)| d * r + k((3 - i) as f64) * v);
                let next = r - f / df;
                // A step that does not lower |f| is not taken: near a double root, where the
                // derivative vanishes, Newton's step leaves the root for another or for none.
                let f_next = eval(next);
                let take = and(and(near, finite(next)), f_next.abs().le(f.abs()));
                r = W::select(take, next, r);
                f = W::select(take, f_next, f);
            }
        }
        let inside = and(lo.lt(r), r.lt(hi));
        best = W::select(and(inside, not(best.le(r))), r, best);
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_support::uniform;

    #[test]
    fn cube_root_is_accurate() {
        let cbrt = |x: f64| cbrt(W([x])).0[0];
        let mut r = uniform(77);
        for _ in 0..100_000 {
            let x = (2.0 * r() - 1.0) * 10f64.powf(60.0 * r() - 30.0);
            let y = cbrt(x);
            assert!((y - x.cbrt()).abs() <= 4.0 * f64::EPSILON * x.cbrt().abs(), "{x}: {y} vs {}", x.cbrt());
            let rough = rough_cbrt(x.abs());
            assert!((rough / x.abs().cbrt() - 1.0).abs() < 0.05, "{x}: {rough}");
        }
        assert_eq!(cbrt(0.0), 0.0);
        assert_eq!(cbrt(-8.0), -2.0);
    }

    /// Seeded random cubics with three, two (a double) or one real roots at scales 1e-4 to 1e4,
    /// away from zero by up to ten times their spread: the smallest root, and the next past a
    /// point just beyond it, are found to a part in 10⁹ of the roots' size once polished. A
    /// double root may be lost to rounding (a grazing ray, as with any closed form), but no
    /// root is ever made up.
    #[test]
    fn roots_of_random_cubics() {
        let mut r = uniform(0xc0b1c);
        let (mut three, mut one, mut doubles_found) = (0, 0, 0);
        let w = |v: f64| W([v]);
        let smallest = |c: &[f64; 4], lo: f64| smallest_root_lanes(&c.map(w), w(lo), w(f64::INFINITY)).0[0];
        for case in 0..20_000 {
            let scale = 10f64.powf(8.0 * r() - 4.0);
            let centre = (2.0 * r() - 1.0) * scale * 10.0;
            let x0 = centre + (2.0 * r() - 1.0) * scale;
            let double = case % 7 == 0;
            let x1 = if double { x0 } else { centre + (2.0 * r() - 1.0) * scale };
            let lead = (0.5 + r()) * if r() < 0.5 { -1.0 } else { 1.0 };
            // (x − x0)(x − x1)(x − x2), or (x − x0)(x² − 2·re·x + re² + im²) with one real root.
            let (c, real) = if case % 3 == 2 {
                let (re, im) = (centre + (2.0 * r() - 1.0) * scale, (0.1 + r()) * scale);
                let (b, cc) = (-2.0 * re, re * re + im * im);
                one += 1;
                ([lead, lead * (b - x0), lead * (cc - x0 * b), lead * -x0 * cc], vec![x0])
            } else {
                let x2 = centre + (2.0 * r() - 1.0) * scale;
                three += 1;
                let (s1, s2, s3) = (x0 + x1 + x2, x0 * x1 + x1 * x2 + x0 * x2, x0 * x1 * x2);
                ([lead, -lead * s1, lead * s2, -lead * s3], vec![x0, x1, x2])
            };
            let size = scale * 11.0;
            // A double root is as far off as rounding the coefficients (a few ulps of the roots'
            // size cubed) moves it: the square root of that over the third root's distance.
            let far = real.iter().fold(size, |m, x| m.max(x.abs()));
            let third = real.last().map_or(size, |&x2| (x2 - x0).abs().max(1e-3 * size));
            let tol = 1e-9 * size + if double { 16.0 * (f64::EPSILON * far.powi(3) / third).sqrt() } else { 0.0 };
            let near_real = |s: f64| real.iter().any(|&x| (s - x).abs() <= tol);
            let lost_double = |s: f64| double && real.len() == 3 && (s.is_nan() || !near_real(s) || s > x0 + tol);
            let want = real.iter().copied().fold(f64::INFINITY, f64::min);
            let s = smallest(&c, f64::NEG_INFINITY);
            assert!(s.is_nan() || near_real(s), "case {case}: made-up root {s} for {real:?}");
            if !(double && want == x0 && real.len() == 3) {
                assert!((s - want).abs() <= tol, "case {case}: {s} vs {want} for {c:?}");
            }
            // Past the smallest: the next one (or none).
            let lo = want + 1e-3 * scale;
            let next = real.iter().copied().filter(|&x| x > lo).fold(f64::INFINITY, f64::min);
            let s = smallest(&c, lo);
            assert!(s.is_nan() || (near_real(s) && s > lo), "case {case}: made-up root {s} past {lo} for {real:?}");
            if next.is_finite() && !(double && next == x0) {
                assert!((s - next).abs() <= tol, "case {case}: {s} vs next {next}");
            }
            doubles_found += (double && real.len() == 3 && !lost_double(smallest(&c, x0 - 1e-3 * scale))) as u32;
        }
        assert!(three > 10_000 && one > 5_000 && doubles_found > 0, "{three} {one} {doubles_found}");
        // Eight lanes at once, each its own cubic and span: the bits of one lane alone.
        for _ in 0..2_000 {
            let c: [W<8>; 4] = std::array::from_fn(|_| W(std::array::from_fn(|_| (2.0 * r() - 1.0) * 10.0)));
            let lo = W(std::array::from_fn(|_| -10.0 * r()));
            let hi = W(std::array::from_fn(|_| 10.0 * r()));
            let wide = smallest_root_lanes(&c, lo, hi);
            for j in 0..8 {
                let one = smallest_root_lanes(&c.map(|v| W([v.0[j]])), W([lo.0[j]]), W([hi.0[j]]));
                assert_eq!(wide.0[j].to_bits(), one.0[0].to_bits(), "lane {j}");
            }
        }
    }
}
