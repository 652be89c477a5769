//! Real roots of polynomials in an interval, in f64, for the shapes whose surfaces are
//! polynomials of degree above one (torus, quadric, cubic, quartic, poly, blob; `sor`, `lathe`
//! and `prism` later). Three solvers, one entry point (`smallest_root_by`):
//!
//! - **Critical points** (`roots_in`, `smallest_root`; the torus, blobs, and polys of degree
//!   above four without `sturm`): the roots of the derivative (found the same way, recursively)
//!   cut the interval into pieces on which the polynomial is monotonic, so each piece holds at
//!   most one root, found where the sign changes by Newton steps kept inside a shrinking
//!   bracket. It does not lose double roots (grazing rays) or small roots to cancellation.
//! - **Closed form** (`Solver::Fast` for degrees 2 to 4: quadric, cubic and quartic without
//!   `sturm`, as POV-Ray solves them): the stable quadratic, Cardano's form or Halley's steps and deflation for
//!   cubics (`cubic`, eight lanes at once for packets), and
//!   Ferrari's resolvent for quartics (`quartic::ferrari`, the torus's), each root polished by
//!   two Newton steps. Fast, but a cubic's double root (a ray grazing the surface) may come
//!   out as a pair of complex roots and be lost, and a quartic whose coefficients span many
//!   orders of magnitude loses its small roots to cancellation in the resolvent: specks along
//!   silhouettes, POV-Ray's failure mode that its `sturm` keyword exists for. A quartic near a
//!   double root, which Ferrari's form declines, goes to the critical points.
//! - **Sturm sequences** (`Solver::Sturm`, POV-Ray's `sturm`; in `sturm`): bisection by counts
//!   of roots until each piece holds one. It counts double roots too, so grazing hits are kept;
//!   it costs a chain of `degree` polynomials per ray and a few dozen chain evaluations per root.
//!
//! The tests at the bottom pit the three against each other at the extremes (double roots,
//! roots 1e-6 apart, coefficient ratios of 1e12).

use super::cubic::smallest_root_lanes;
use super::quartic::ferrari;
use super::sturm::sturm_roots;
use super::wide::W;

/// Highest degree handled (POV-Ray's `poly` takes orders 2 to 15 here).
pub const MAX_DEGREE: usize = 16;

/// How a polynomial shape finds its roots: POV-Ray's default or its `sturm`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Solver {
    /// Closed forms up to degree 4, critical points above.
    #[default]
    Fast,
    /// Sturm-sequence isolation.
    Sturm,
}

/// The smallest root of `c` (highest degree first) in `(lo, hi)` by `solver`, if any.
pub fn smallest_root_by(solver: Solver, c: &[f64], lo: f64, hi: f64) -> Option<f64> {
    let first = c.iter().position(|&k| k != 0.0).unwrap_or(c.len());
    let c = &c[first..];
    let degree = c.len().saturating_sub(1);
    if degree == 0 {
        return None;
    }
    if solver == Solver::Fast && degree == 3 {
        let s = smallest_root_lanes(&[W([c[0]]), W([c[1]]), W([c[2]]), W([c[3]])], W([lo]), W([hi])).0[0];
        return (!s.is_nan()).then_some(s);
    }
    // Cauchy's bound: every root lies within it, so infinite ends become finite ones.
    let bound = 1.0 + c[1..].iter().fold(0.0f64, |m, k| m.max((k / c[0]).abs()));
    let (lo, hi) = (lo.max(-bound), hi.min(bound));
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return None;
    }
    let mut roots = [0.0; MAX_DEGREE];
    let n = match (solver, degree) {
        (_, 0) => 0,
        (Solver::Fast, 1..=4) => match closed_form(c, &mut roots) {
            Some(n) => n,
            // A quartic near a double root, where Ferrari's form declines: the critical points
            // do not lose it.
            None => return smallest_root(c, lo, hi),
        },
        (Solver::Fast, _) => return smallest_root(c, lo, hi),
        (Solver::Sturm, _) => sturm_roots(c, lo, hi, &mut roots),
    };
    roots[..n]
        .iter()
        .copied()
        .filter(|&r| r > lo && r < hi)
        .fold(None, |m: Option<f64>, r| Some(m.map_or(r, |m| m.min(r))))
}

/// A bound on the roots of `c` (highest degree first, `c[0] ≠ 0`): every complex root has
/// modulus at most this. Fujiwara's bound, `2·max |cᵢ/c₀|^(1/i)` (the last term halved), which
/// unlike Cauchy's `1 + max |cᵢ/c₀|` grows as the roots do, not as their product: a sextic's
/// roots of size 2 give 4 here, 64 there. The `i`-th roots are taken from the exponent bits
/// (within 7 %) and padded by 10 %, so the bound stays a bound without `powf`. Infinite or NaN
/// where a coefficient is.
pub fn root_bound(c: &[f64]) -> f64 {
    // v^(1/i) from log2 v ≈ the exponent bits read as a fixed-point number, divided by `i` as
    // by a constant (a multiply and shifts): six 64-bit `idiv`s per sextic's bound were 8 % of
    // scenes/kernels/poly.pov's time.
    bound_dividing(c, |e, i| match i {
        1 => e,
        2 => e / 2,
        3 => e / 3,
        4 => e / 4,
        5 => e / 5,
        6 => e / 6,
        7 => e / 7,
        8 => e / 8,
        9 => e / 9,
        10 => e / 10,
        11 => e / 11,
        12 => e / 12,
        13 => e / 13,
        14 => e / 14,
        15 => e / 15,
        16 => e / 16,
        _ => e / i as i64,
    })
}

/// `root_bound` with the exponent bits `e` of `|cᵢ/c₀|` divided by `i` by `divide(e, i)`.
#[inline(always)]
fn bound_dividing(c: &[f64], divide: impl Fn(i64, usize) -> i64) -> f64 {
    const ONE: i64 = 0x3ff0_0000_0000_0000;
    let n = c.len() - 1;
    let mut m = 0.0f64;
    for (i, &k) in c.iter().enumerate().skip(1) {
        let v = (k / c[0]).abs() * if i == n { 0.5 } else { 1.0 };
        if v == 0.0 {
            continue;
        }
        if !v.is_finite() {
            return v;
        }
        m = m.max(f64::from_bits((divide(v.to_bits() as i64 - ONE, i) + ONE) as u64));
    }
    2.2 * m
}

/// `p(x)` for coefficients highest degree first (Horner).
#[inline]
pub(super) fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().fold(0.0, |acc, &k| acc * x + k)
}

/// The smallest root of `c` (highest degree first, `c.len() - 1 ≤ MAX_DEGREE`) in `(lo, hi)`,
/// if any.
pub fn smallest_root(c: &[f64], lo: f64, hi: f64) -> Option<f64> {
    let mut roots = [0.0; MAX_DEGREE];
    let n = roots_in(c, lo, hi, &mut roots);
    roots[..n].iter().copied().find(|&r| r > lo && r < hi)
}

/// The lowest degree `roots_in` tests for a span without roots first: quartics (blob, torus)
/// and the degree-4 and 6 polynomials of quadratic and cubic lathes and prisms.
const SKIP_TEST_DEGREE: usize = 4;

/// All roots of `c` in `[lo, hi]`, ascending, into `out`; returns how many.
///
/// A span of a polynomial of degree [`SKIP_TEST_DEGREE`] or more that the curve certainly does
/// not cross ([`certainly_no_root`]) is answered at once. The test is made here only, not again
/// for each derivative of the recursion, and not for lower degrees, whose empty spans the
/// critical points already settle in a few evaluations: testing every level made prism2.pov
/// 25 % slower, and testing quadratics made lathe1a.pov's linear lathe 9 % slower.
pub fn roots_in(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let first = c.iter().position(|&k| k != 0.0).unwrap_or(c.len());
    if c.len() - first > SKIP_TEST_DEGREE && certainly_no_root(&c[first..], lo, hi) {
        return 0;
    }
    critical_point_roots(c, lo, hi, out)
}

/// [`roots_in`] without the up-front test: the derivative's roots cut `[lo, hi]` into monotonic
/// pieces, recursively.
fn critical_point_roots(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    // Drop leading zeros: the degree is what the coefficients say.
    let first = c.iter().position(|&k| k != 0.0).unwrap_or(c.len());
    let c = &c[first..];
    let degree = c.len().saturating_sub(1);
    match degree {
        0 => 0,
        1 => {
            let r = -c[1] / c[0];
            if r >= lo && r <= hi {
                out[0] = r;
                1
            } else {
                0
            }
        }
        _ => {
            // Critical points split [lo, hi] into monotonic pieces.
            let mut dc = [0.0; MAX_DEGREE + 1];
            for (i, k) in c[..degree].iter().enumerate() {
                dc[i] = k * (degree - i) as f64;
            }
            let mut crit = [0.0; MAX_DEGREE];
            let m = critical_point_roots(&dc[..degree], lo, hi, &mut crit);
            let mut n = 0;
            let mut a = lo;
            for &b in crit[..m].iter().chain(std::iter::once(&hi)) {
                if let Some(r) = monotonic_root(c, a, b) {
                    // A root at a critical point (a double root) shows in both neighbours.
                    if n == 0 || r > out[n - 1] {
                        out[n] = r;
                        n += 1;
                    }
                }
                a = b;
            }
            n
        }
    }
}

/// Whether `c` (highest power first, degree 1 to `MAX_DEGREE`) has no root in `[lo, hi]` for
/// certain: its Bernstein coefficients on the interval all have one sign, with a margin far
/// above their rounding error. The polynomial lies in their convex hull, so it cannot reach
/// zero there. `false` says nothing (an infinite end, a coefficient near zero).
///
/// `roots_in` asks this first, so a span the curve does not cross costs one change of basis
/// instead of the critical points' Newton solves. It never changes a root found: a skipped
/// span has none, and every other span is solved as before. On
/// `objects/blob.pov` (five rays in six miss the blob inside its box) `monotonic_root` took
/// 63 % of the time.
pub(super) fn certainly_no_root(c: &[f64], lo: f64, hi: f64) -> bool {
    let n = c.len().saturating_sub(1);
    if n == 0 || n > MAX_DEGREE || !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return false;
    }
    let Some((a, magnitude)) = on_unit(c, lo, hi) else {
        return false;
    };
    // Rounding is below (n + 1)² ulps of `magnitude`; the margin is 10⁴ times more.
    let tol = 1e-10 * magnitude;
    // b_i = Σ_{j ≤ i} C(i, j) / C(n, j) · a_j.
    let mut sign = 0.0;
    for i in 0..=n {
        let (mut b, mut cij, mut cnj) = (0.0, 1.0, 1.0);
        for (j, &aj) in a[..=i].iter().enumerate() {
            b += cij / cnj * aj;
            cij = cij * (i - j) as f64 / (j + 1) as f64;
            cnj = cnj * (n - j) as f64 / (j + 1) as f64;
        }
        if b.is_nan() || b.abs() <= tol || (sign != 0.0 && b.signum() != sign) {
            return false;
        }
        sign = b.signum();
    }
    true
}

/// `c` (highest degree first, degree `n` at most `MAX_DEGREE`) on `[lo, hi]` as a polynomial in
/// s on `[0, 1]`: `a[j]`, the coefficient of s^j of p(lo + w·s), by a Taylor shift (repeated
/// synthetic division) and a scaling by the width; and the sum of the magnitudes that went into
/// them (the same for |p|'s coefficients and |lo|), which bounds their rounding. `None` for a zero
/// or non-finite magnitude.
pub(super) fn on_unit(c: &[f64], lo: f64, hi: f64) -> Option<([f64; MAX_DEGREE + 1], f64)> {
    let n = c.len() - 1;
    let (mut a, mut m) = ([0.0f64; MAX_DEGREE + 1], [0.0f64; MAX_DEGREE + 1]);
    for j in 0..=n {
        a[j] = c[n - j];
        m[j] = c[n - j].abs();
    }
    for i in 0..n {
        for j in (i..n).rev() {
            a[j] += lo * a[j + 1];
            m[j] += lo.abs() * m[j + 1];
        }
    }
    let w = hi - lo;
    let mut wj = 1.0;
    for j in 0..=n {
        a[j] *= wj;
        m[j] *= wj;
        wj *= w;
    }
    let magnitude: f64 = m[..=n].iter().sum();
    (magnitude.is_finite() && magnitude != 0.0).then_some((a, magnitude))
}

/// The root of `c` in `[a, b]`, where `c` is monotonic, if its sign changes or it touches zero.
pub(super) fn monotonic_root(c: &[f64], a: f64, b: f64) -> Option<f64> {
    let (fa, fb) = (eval(c, a), eval(c, b));
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if (fa < 0.0) == (fb < 0.0) {
        return None;
    }
    let (mut lo, mut hi) = if fa < 0.0 { (a, b) } else { (b, a) };
    let mut x = 0.5 * (a + b);
    for _ in 0..100 {
        let fx = eval(c, x);
        if fx == 0.0 {
            return Some(x);
        }
        if fx < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        // A Newton step if it stays inside the bracket, else bisection.
        let degree = c.len() - 1;
        let dfx = c[..degree].iter().enumerate().fold(0.0, |acc, (i, &k)| acc * x + k * (degree - i) as f64);
        let newton = x - fx / dfx;
        let (l, h) = if lo < hi { (lo, hi) } else { (hi, lo) };
        let next = if newton > l && newton < h { newton } else { 0.5 * (lo + hi) };
        if next == x || (h - l) <= 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE) {
            return Some(next);
        }
        x = next;
    }
    Some(x)
}

/// Real roots of `c` (degree 1, 2 or 4, leading coefficient non-zero; cubics go to `cubic`) by closed formulas, each
/// polished by Newton steps; returns how many, in no particular order, or `None` for a quartic
/// that Ferrari's form (`quartic::ferrari`, the torus's) declines as ill-conditioned.
fn closed_form(c: &[f64], out: &mut [f64; MAX_DEGREE]) -> Option<usize> {
    let degree = c.len() - 1;
    let a = c[0];
    let n = match degree {
        1 => {
            out[0] = -c[1] / a;
            1
        }
        2 => quadratic(c[1] / a, c[2] / a, out),
        _ => {
            let (mut four, mut tol) = ([0.0; 4], 0.0);
            let n = ferrari(&[1.0, c[1] / a, c[2] / a, c[3] / a, c[4] / a], &mut four, &mut tol)?;
            out[..n].copy_from_slice(&four[..n]);
            n
        }
    };
    for r in &mut out[..n] {
        for _ in 0..2 {
            let (f, df) = eval_with_derivative(c, *r);
            if df != 0.0 && (f / df).is_finite() {
                *r -= f / df;
            }
        }
    }
    Some(n)
}

/// `p(x)` and `p'(x)` together (Horner).
#[inline]
fn eval_with_derivative(c: &[f64], x: f64) -> (f64, f64) {
    let (mut f, mut df) = (0.0, 0.0);
    for &k in c {
        df = df * x + f;
        f = f * x + k;
    }
    (f, df)
}

/// x² + b·x + c = 0, the stable way (no cancellation between −b and the square root).
fn quadratic(b: f64, c: f64, out: &mut [f64]) -> usize {
    let disc = b * b - 4.0 * c;
    if disc.is_nan() || disc < 0.0 {
        return 0;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    if q == 0.0 {
        out[0] = 0.0;
        return 1;
    }
    out[0] = q;
    out[1] = c / q;
    2
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_support::from_roots;

    /// Every root lies within `root_bound`, for seeded random roots of degree 1 to 12 at every
    /// scale (with a complex pair, whose modulus counts too), and the bound is not loose: below
    /// 5 times the largest root where the roots are of one size.
    #[test]
    fn root_bound_holds_and_is_tight() {
        let mut r = crate::geometry::test_support::uniform(0xb0_0d);
        for case in 0..20_000 {
            let degree = 1 + case % 12;
            let scale = 10f64.powf(r() * 10.0 - 4.0);
            let roots: Vec<f64> = (0..degree).map(|_| (2.0 * r() - 1.0) * scale).collect();
            let mut c = from_roots(&roots, 1.0);
            let lead = 10f64.powf(r() * 6.0 - 3.0) * if r() < 0.5 { -1.0 } else { 1.0 };
            let biggest = roots.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for k in &mut c {
                *k *= lead;
            }
            let bound = root_bound(&c);
            assert!(bound >= biggest, "case {case}: {bound} < {biggest} for {roots:?}");
            // Times (x² + m²): a complex pair of modulus m.
            let m = 1.5 * biggest;
            let mut with_pair = vec![0.0; c.len() + 2];
            for (i, &k) in c.iter().enumerate() {
                with_pair[i] += k;
                with_pair[i + 2] += k * m * m;
            }
            assert!(root_bound(&with_pair) >= m, "case {case}: pair of modulus {m}");
        }
        let c = from_roots(&[2.0, -2.0, 1.9, -1.9, 1.95, 2.05], 1.0);
        let bound = root_bound(&c);
        assert!((2.05..5.0 * 2.05).contains(&bound), "{bound}");
        assert_eq!(root_bound(&[1.0, 0.0, 0.0]), 0.0);
        assert!(root_bound(&[1.0, f64::NAN, 1.0]).is_nan());
    }

    #[test]
    fn finds_every_root_of_quartics_in_order() {
        for roots in
            [vec![-3.0, -1.0, 0.5, 2.0], vec![1.0, 1.0 + 1e-6, 5.0, 7.0], vec![1e-3, 2e-3, 1e3, 2e3], vec![-2.0, 4.0]]
        {
            let c = from_roots(&roots, 1.0);
            let mut out = [0.0; MAX_DEGREE];
            let n = roots_in(&c, -10.0, 1e4, &mut out);
            assert_eq!(n, roots.len(), "{roots:?}: {:?}", &out[..n]);
            for (a, b) in out[..n].iter().zip(&roots) {
                assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{roots:?}: {:?}", &out[..n]);
            }
        }
    }

    #[test]
    fn a_double_root_is_found_once() {
        let c = from_roots(&[2.0, 2.0, 3.0, 3.0], 1.0);
        let mut out = [0.0; MAX_DEGREE];
        let n = roots_in(&c, 0.0, 10.0, &mut out);
        assert!(n >= 1 && (out[0] - 2.0).abs() < 1e-6, "{:?}", &out[..n]);
        assert_eq!(smallest_root(&from_roots(&[-1.0, 4.0], 1.0), 0.0, 10.0), Some(4.0));
        assert_eq!(smallest_root(&from_roots(&[-1.0, 4.0], 1.0), 5.0, 10.0), None);
    }

    /// The Bernstein test only ever skips spans without a root: over seeded random real roots
    /// (some doubled, some clustered), scales and intervals, a skipped interval holds none of
    /// them, and it does skip most intervals far from the roots.
    #[test]
    fn no_root_test_never_skips_a_root() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut rand = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut skipped, mut far) = (0, 0);
        for case in 0..20_000 {
            let degree = 1 + case % 6;
            let spread = [1e-3, 1.0, 1e3][case % 3];
            let mut roots: Vec<f64> = (0..degree).map(|_| (rand() * 2.0 - 1.0) * spread).collect();
            if case % 5 == 0 && degree > 1 {
                roots[1] = roots[0];
            }
            if case % 7 == 0 && degree > 1 {
                roots[1] = roots[0] * (1.0 + 1e-9);
            }
            let scale = [1.0, -3e-7, 2e5][case % 3];
            let c: Vec<f64> = from_roots(&roots, 1.0).iter().map(|k| k * scale).collect();
            let lo = (rand() * 2.4 - 1.2) * spread;
            let hi = lo + rand() * spread;
            let holds = roots.iter().any(|&r| r >= lo && r <= hi);
            let skip = certainly_no_root(&c, lo, hi);
            assert!(!(skip && holds), "case {case}: {roots:?} in [{lo}, {hi}] skipped");
            let gap = roots.iter().map(|&r| (r - lo).abs().min((r - hi).abs())).fold(f64::INFINITY, f64::min);
            if !holds && gap > 0.5 * (hi - lo) + 0.2 * spread {
                far += 1;
                skipped += skip as usize;
            }
        }
        assert!(skipped * 10 > far * 8, "only {skipped} of {far} root-free far intervals skipped");
        // A root on an end, or a double root touching zero inside, is never skipped.
        assert!(!certainly_no_root(&from_roots(&[1.0, 1.0], 1.0), 0.0, 2.0));
        assert!(!certainly_no_root(&from_roots(&[2.0], 1.0), 0.0, 2.0));
        assert!(certainly_no_root(&from_roots(&[3.0, 5.0], 1.0), 0.0, 2.0));
        assert!(!certainly_no_root(&from_roots(&[3.0, 5.0], 1.0), 0.0, f64::INFINITY));
    }

    /// `roots::root_bound`'s divisions by constants are the plain divisions to the bit, on seeded random
    /// polynomials of every degree with coefficients from 1e-30 to 1e30, some zero, some
    /// negative, some infinite.
    #[test]
    fn bound_is_the_roots_bound_to_the_bit() {
        let mut r = crate::geometry::test_support::uniform(0x0b0d_5eed);
        for case in 0..20_000 {
            let n = 1 + case % MAX_DEGREE;
            let c: Vec<f64> = (0..=n)
                .map(|i| match (r() * 10.0) as u32 {
                    0 if i > 0 => 0.0,
                    1 if case % 97 == 0 => f64::INFINITY,
                    _ => (2.0 * r() - 1.0) * 10f64.powf(r() * 60.0 - 30.0),
                })
                .collect();
            let (a, b) = (root_bound(&c), bound_by_division(&c));
            assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()), "{c:?}: {a} vs {b}");
        }
    }

    /// `roots::root_bound` as first written: the exponent bits divided by the degree at run
    /// time.
    fn bound_by_division(c: &[f64]) -> f64 {
        bound_dividing(c, |e, i| e / i as i64)
    }
}

#[cfg(test)]
mod solver_tests {
    use super::*;
    use crate::geometry::test_support::from_roots;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs().max(1.0)
    }

    #[test]
    fn every_solver_finds_the_smallest_root_of_well_separated_polynomials() {
        for roots in [
            vec![0.5, 2.0],
            vec![-1.0, 0.25, 3.0],
            vec![-3.0, -1.0, 0.5, 2.0],
            vec![0.1, 0.2, 0.3, 0.4, 0.5, 7.0],
            vec![1e-3, 2e-3, 1e3, 2e3],
        ] {
            for scale in [1.0, -1e-9, 1e9] {
                let c = from_roots(&roots, scale);
                for solver in [Solver::Fast, Solver::Sturm] {
                    let r = smallest_root_by(solver, &c, 0.0, f64::INFINITY).expect("a root");
                    let want = roots.iter().copied().filter(|&r| r > 0.0).fold(f64::INFINITY, f64::min);
                    assert!(close(r, want, 1e-9), "{solver:?} {roots:?} x{scale}: {r} vs {want}");
                }
            }
        }
    }

    #[test]
    fn sturm_counts_double_and_clustered_roots_and_skips_complex_pairs() {
        // A grazing ray: a double root at 2 (the quartic touches zero), then two more.
        let c = from_roots(&[2.0, 2.0, 5.0, 6.0], 1.0);
        let r = smallest_root_by(Solver::Sturm, &c, 0.0, 100.0).expect("double root");
        assert!(close(r, 2.0, 1e-6), "{r}");
        let mut out = [0.0; MAX_DEGREE];
        let n = sturm_roots(&c, 0.0, 100.0, &mut out);
        assert_eq!(n, 3, "{:?}", &out[..n]);
        // Roots 1e-6 apart stay two roots.
        let c = from_roots(&[1.0, 1.0 + 1e-6, 3.0, 4.0], 1.0);
        let n = sturm_roots(&c, 0.0, 10.0, &mut out);
        assert_eq!(n, 4, "{:?}", &out[..n]);
        // Clustered roots are ill-conditioned: each is good to about 1e-9 here.
        assert!(out[0] < out[1] && close(out[1], 1.0 + 1e-6, 1e-8) && close(out[0], 1.0, 1e-8), "{:?}", &out[..n]);
        // (x² + 1)(x − 3)(x − 4): the complex pair is no root.
        let c = [1.0, -7.0, 13.0, -7.0, 12.0];
        assert!(close(smallest_root_by(Solver::Sturm, &c, 0.0, 10.0).expect("3"), 3.0, 1e-12));
        assert!(close(smallest_root_by(Solver::Fast, &c, 0.0, 10.0).expect("3"), 3.0, 1e-12));
        // Nothing in an interval without roots.
        assert_eq!(smallest_root_by(Solver::Sturm, &c, 4.5, 10.0), None);
        assert_eq!(smallest_root_by(Solver::Fast, &c, 4.5, 10.0), None);
    }

    #[test]
    fn huge_coefficient_ratios() {
        // Roots 1e-4 and 1e4: coefficients spanning 1e16.
        // Sturm keeps the small root; Ferrari's resolvent loses it to cancellation (a few per
        // cent here), which is what `sturm` is for in POV-Ray too.
        let c = from_roots(&[1e-4, 3e-4, 1e4, 3e4], 1.0);
        let r = smallest_root_by(Solver::Sturm, &c, 0.0, f64::INFINITY).expect("small root");
        assert!((r - 1e-4).abs() < 1e-12, "sturm: {r}");
        let r = smallest_root_by(Solver::Fast, &c, 0.0, f64::INFINITY).expect("small root");
        assert!((r - 1e-4).abs() < 1e-5, "fast: {r}");
        // Degree above 4 without sturm falls back to critical points.
        let c = from_roots(&[-2.0, 1.5, 1.5, 4.0, 9.0, 11.0], 3.0);
        let r = smallest_root_by(Solver::Fast, &c, 0.0, 20.0).expect("double root");
        assert!(close(r, 1.5, 1e-6), "{r}");
    }
}
