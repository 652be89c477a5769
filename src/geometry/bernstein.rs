//! Real roots of a low-degree polynomial in an interval by Bernstein subdivision, for the spline
//! shapes (`lathe`, `sor`, `prism`, and the spline helpers' parity and nearest-point solves),
//! whose per-piece polynomials (degree 1 to 6) are solved once per ray and piece.
//!
//! The polynomial is written in the Bernstein basis of the interval. Its curve lies in the
//! convex hull of those coefficients, and the number of their sign changes bounds the number of
//! roots inside (Descartes' rule for the Bernstein basis), with the same parity. So:
//!
//! - no sign change: no root (most pieces a ray passes near but misses end here, after one
//!   change of basis);
//! - one sign change: exactly one root, bracketed by the ends' opposite signs, polished by
//!   `roots::monotonic_root` (Newton kept inside the bracket) on the polynomial as given;
//! - more: the interval is halved (de Casteljau, exact halves of the coefficients' hull) and
//!   each half is looked at again, the lower first, so roots come out ascending.
//!
//! This replaces `roots_in`'s critical points for these shapes: those find every root of every
//! derivative to full precision first (five nested Newton solves for a degree-6 lathe piece),
//! which took 60–88 % of the spline kernels' time. The roots are the same: `monotonic_root` on
//! the same polynomial converges to within a few f64 ulps of the one root in its bracket, either
//! way. A pair of roots closer than the subdivision's floor (a ray grazing the surface) is
//! dropped unless its bracket's ends differ in sign, as the critical points also drop a double
//! root whose critical value does not reach zero.

use super::roots::{roots_in, MAX_DEGREE};

/// Highest degree solved by subdivision; above it `roots_in` answers.
pub const MAX: usize = 7;

/// Halvings before a span with several sign changes is given up: its width is then below
/// 2⁻⁴⁸ of the interval, far below what an f32 hit resolves.
const MAX_DEPTH: u32 = 48;

/// `1 / C(n, j)` for `n ≤ MAX`.
const INV_BINOM: [[f64; MAX + 1]; MAX + 1] = {
    let mut t = [[0.0; MAX + 1]; MAX + 1];
    let mut n = 0;
    while n <= MAX {
        let mut c = 1.0;
        let mut j = 0;
        while j <= n {
            t[n][j] = 1.0 / c;
            c = c * (n - j) as f64 / (j + 1) as f64;
            j += 1;
        }
        n += 1;
    }
    t
};

/// `p(x)` for coefficients highest degree first (Horner), as `roots` evaluates.
#[inline]
fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().fold(0.0, |acc, &k| acc * x + k)
}

/// Sign changes among the nonzero coefficients.
#[inline]
fn sign_changes(b: &[f64]) -> u32 {
    let mut changes = 0;
    let mut last = 0.0f64;
    for &v in b {
        if v != 0.0 {
            if last != 0.0 && (v < 0.0) != (last < 0.0) {
                changes += 1;
            }
            last = v;
        }
    }
    changes
}

/// The Bernstein coefficients of the two halves of `b` (degree `n`), by de Casteljau.
#[inline]
fn halve(b: &[f64; MAX + 1], n: usize) -> ([f64; MAX + 1], [f64; MAX + 1]) {
    let (mut left, mut right) = ([0.0; MAX + 1], [0.0; MAX + 1]);
    let mut w = *b;
    left[0] = w[0];
    right[n] = w[n];
    for k in 1..=n {
        for i in 0..=n - k {
            w[i] = 0.5 * (w[i] + w[i + 1]);
        }
        left[k] = w[0];
        right[n - k] = w[n - k];
    }
    (left, right)
}

/// The roots of the quadratic `c` in `[lo, hi]`, ascending: the stable formula (no
/// cancellation between `−b` and the square root), each root then one Newton step from exact.
/// A double root counts where the discriminant is not negative, as the critical point's value
/// decides it for `roots_in`.
fn quadratic_between(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let (a, b, k) = (c[0], c[1], c[2]);
    let disc = b * b - 4.0 * a * k;
    if !(disc >= 0.0) {
        return 0;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let (mut r0, mut r1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, k / q) };
    for r in [&mut r0, &mut r1] {
        let (f, df) = eval_with_derivative(c, *r);
        if df != 0.0 && (f / df).is_finite() {
            *r -= f / df;
        }
    }
    let (r0, r1) = (r0.min(r1), r0.max(r1));
    let mut n = 0;
    for r in [r0, r1] {
        if r >= lo && r <= hi && (n == 0 || r > out[n - 1]) {
            out[n] = r;
            n += 1;
        }
    }
    n
}

/// `p(x)` and `p'(x)` (Horner).
#[inline]
fn eval_with_derivative(c: &[f64], x: f64) -> (f64, f64) {
    let (mut f, mut df) = (0.0, 0.0);
    for &k in c {
        df = df * x + f;
        f = f * x + k;
    }
    (f, df)
}

/// The root of `c` between `x0` and `x1`, where its sign changes (negative at `x0` if
/// `neg_at_x0`): Newton steps from `guess`, kept inside the shrinking bracket (bisection where a
/// step would leave it), until a step moves `x` by less than `rel` of the bracket's scale (a
/// simple root is then good to about its square) or the bracket closes.
fn polish(c: &[f64], x0: f64, x1: f64, neg_at_x0: bool, guess: f64, rel: f64) -> f64 {
    let (mut a, mut b) = (x0, x1);
    let tol = rel * (x0.abs().max(x1.abs()) + (x1 - x0).abs());
    let mut x = if guess > x0.min(x1) && guess < x0.max(x1) { guess } else { 0.5 * (x0 + x1) };
    for _ in 0..100 {
        let (f, df) = eval_with_derivative(c, x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == neg_at_x0 {
            a = x;
        } else {
            b = x;
        }
        let newton = x - f / df;
        let (l, h) = (a.min(b), a.max(b));
        // A step this small has converged (checked before the bracket: the last step may
        // round onto the end just moved to `x`, which is no reason to bisect).
        if (newton - x).abs() <= tol {
            return newton.clamp(l, h);
        }
        let next = if newton > l && newton < h { newton } else { 0.5 * (a + b) };
        if h - l <= 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE) {
            return next;
        }
        x = next;
    }
    x
}

/// How closely `roots_between` and `roots_unit` pin a root: `polish` stops once a Newton step
/// is below this part of the bracket's scale.
const PRECISE: f64 = 1e-13;

/// The looser stop of `roots_between_to` and `roots_unit_to` for a shape whose roots end as f32
/// hits (`lathe`, `sor`): a simple root is then good to about 10⁻¹⁶ of its scale (the square of
/// the last step), one near a double root (where Newton only halves its error) to 10⁻⁸, below
/// an f32 ulp; it saves the last Newton step, which only confirms the one before (a sixth of
/// the sor kernel's time).
pub const FOR_F32: f64 = 1e-8;

/// All roots of `c` (highest degree first) in `[lo, hi]` (finite), ascending, into `out`;
/// returns how many. A root at an end counts where `c` is exactly zero there.
pub fn roots_between(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    roots_between_to(c, lo, hi, PRECISE, out)
}

/// `roots_between`, each root polished until a Newton step is below `rel` of its bracket's
/// scale (`FOR_F32`) where subdivision isolates it (degree 3 to `MAX`).
pub fn roots_between_to(c: &[f64], lo: f64, hi: f64, rel: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let first = c.iter().position(|&k| k != 0.0).unwrap_or(c.len());
    let c = &c[first..];
    let n = c.len().saturating_sub(1);
    if n == 0 {
        return 0;
    }
    if n == 1 {
        // A line: its root as `roots_in` gives it.
        let r = -c[1] / c[0];
        if r >= lo && r <= hi {
            out[0] = r;
            return 1;
        }
        return 0;
    }
    if n == 2 {
        return quadratic_between(c, lo, hi, out);
    }
    if n > MAX || !(lo.is_finite() && hi.is_finite()) {
        return roots_in(c, lo, hi, out);
    }
    if !(lo < hi) {
        return 0;
    }
    // p(lo + w·u) = Σ a[j]·u^j by Taylor shift (repeated synthetic division), then scaled.
    let mut a = [0.0f64; MAX + 1];
    for j in 0..=n {
        a[j] = c[n - j];
    }
    if lo != 0.0 {
        for i in 0..n {
            for j in (i..n).rev() {
                a[j] += lo * a[j + 1];
            }
        }
    }
    let w = hi - lo;
    if w != 1.0 {
        let mut wj = w;
        for x in &mut a[1..=n] {
            *x *= wj;
            wj *= w;
        }
    }
    let b = to_bernstein(&a[..=n]);
    isolate_all(c, b, lo, hi, rel, out)
}

/// The Bernstein coefficients on `[0, 1]` of `Σ a[j]·u^j` (lowest power first, degree ≤ 7):
/// `b[i] = Σ_{j ≤ i} C(i, j)·a[j] / C(n, j)`, by repeated prefix sums.
pub fn to_bernstein(a: &[f64]) -> [f64; MAX + 1] {
    let n = a.len() - 1;
    let mut b = [0.0f64; MAX + 1];
    for j in 0..=n {
        b[j] = a[j] * INV_BINOM[n][j];
    }
    for k in 0..n {
        for i in (k + 1..=n).rev() {
            b[i] += b[i - 1];
        }
    }
    b
}

/// All roots in `[0, 1]` of `c` (highest power first, degree 3 to 7, leading coefficient not
/// necessarily nonzero) whose Bernstein coefficients on `[0, 1]` the caller has already (`b`,
/// as `to_bernstein` gives them), ascending; returns how many. For shapes that form both
/// bases from per-piece tables, without a change of basis per ray.
pub fn roots_unit(c: &[f64], b: [f64; MAX + 1], out: &mut [f64; MAX_DEGREE]) -> usize {
    isolate_all(c, b, 0.0, 1.0, PRECISE, out)
}

/// `roots_unit` polished to `rel` (`roots_between_to`).
pub fn roots_unit_to(c: &[f64], b: [f64; MAX + 1], rel: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    isolate_all(c, b, 0.0, 1.0, rel, out)
}

/// Whether `roots_unit_to(c, b, ..)` finds exactly one root, known without solving: the ends'
/// values (as `isolate_all` takes them) are nonzero and the Bernstein coefficients change sign
/// once, the case it answers by `Span::single`. For shadow rays, which need a root, not where.
pub fn one_root_unit(c: &[f64], mut b: [f64; MAX + 1]) -> bool {
    let n = c.len() - 1;
    let (f_lo, f_hi) = (eval(c, 0.0), eval(c, 1.0));
    b[0] = f_lo;
    b[n] = f_hi;
    f_lo != 0.0 && f_hi != 0.0 && !b[..=n].iter().any(|x| x.is_nan()) && sign_changes(&b[..=n]) == 1
}

fn isolate_all(c: &[f64], mut b: [f64; MAX + 1], lo: f64, hi: f64, rel: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let n = c.len() - 1;
    // The ends are the polynomial's values there, evaluated as `roots` evaluates them, so the
    // signs at a piece's joints agree with the critical points' answer.
    let (f_lo, f_hi) = (eval(c, lo), eval(c, hi));
    b[0] = f_lo;
    b[n] = f_hi;
    // Most pieces a ray passes near but misses end here.
    let changes = sign_changes(&b[..=n]);
    if changes == 0 && f_lo != 0.0 && f_hi != 0.0 {
        return 0;
    }
    if b[..=n].iter().any(|x| x.is_nan()) {
        return 0;
    }
    let span = Span { c, n, lo, hi, w: hi - lo, rel };
    // One sign change and nonzero ends (most rays that meet a piece): its one root, as
    // `Span::isolate` finds it, without the recursion's setup.
    if changes == 1 && f_lo != 0.0 && f_hi != 0.0 {
        out[0] = span.single(0.0, 1.0, &b);
        return 1;
    }
    let mut found = Found { out, count: 0 };
    if f_lo == 0.0 {
        found.push(lo);
    }
    span.isolate(&mut found, 0.0, 1.0, 0, &b);
    found.count
}

/// Roots found so far, ascending.
struct Found<'a> {
    out: &'a mut [f64; MAX_DEGREE],
    count: usize,
}

impl Found<'_> {
    /// A root on a halving point may come from both halves: it is kept once.
    #[inline]
    fn push(&mut self, r: f64) {
        if self.count < self.out.len() && (self.count == 0 || r > self.out[self.count - 1]) {
            self.out[self.count] = r;
            self.count += 1;
        }
    }
}

/// The polynomial being solved: `c` (degree `n`) on `[lo, hi]`, `w = hi − lo`, its roots
/// polished to `rel` (`polish`).
struct Span<'a> {
    c: &'a [f64],
    n: usize,
    lo: f64,
    hi: f64,
    w: f64,
    rel: f64,
}

impl Span<'_> {
    /// `x` at `u` of the unit interval.
    #[inline]
    fn at(&self, u: f64) -> f64 {
        if u == 1.0 {
            self.hi
        } else {
            self.lo + self.w * u
        }
    }

    /// The one root in `[u0, u1]`, whose Bernstein coefficients `b` change sign once, between
    /// nonzero ends: the control polygon crosses zero once, near the root, and Newton starts
    /// there (`polish`).
    #[inline]
    fn single(&self, u0: f64, u1: f64, b: &[f64; MAX + 1]) -> f64 {
        let n = self.n;
        let i = (0..n).find(|&i| (b[i] < 0.0) != (b[i + 1] < 0.0) && b[i + 1] != 0.0).unwrap_or(0);
        let k = (0..=i).rev().find(|&k| b[k] != 0.0).unwrap_or(0);
        let (p, q) = (b[k], b[i + 1]);
        let u = (k as f64 + (i + 1 - k) as f64 * p / (p - q)) / n as f64;
        let guess = self.at(u0 + (u1 - u0) * u);
        polish(self.c, self.at(u0), self.at(u1), b[0] < 0.0, guess, self.rel)
    }

    /// The inner roots of the span `[u0, u1]` with Bernstein coefficients `b`, then its upper
    /// end if the polynomial is zero there.
    fn isolate(&self, found: &mut Found, u0: f64, u1: f64, depth: u32, b: &[f64; MAX + 1]) {
        let (n, c) = (self.n, self.c);
        let (b0, bn) = (b[0], b[n]);
        let changes = sign_changes(&b[..=n]);
        if changes == 1 && b0 != 0.0 && bn != 0.0 {
            found.push(self.single(u0, u1, b));
        } else if changes >= 1 && depth < MAX_DEPTH {
            let (left, right) = halve(b, n);
            let m = 0.5 * (u0 + u1);
            self.isolate(found, u0, m, depth + 1, &left);
            self.isolate(found, m, u1, depth + 1, &right);
            return;
        } else if changes >= 1 && (b0 < 0.0) != (bn < 0.0) && b0 != 0.0 && bn != 0.0 {
            let (x0, x1) = (self.at(u0), self.at(u1));
            found.push(polish(c, x0, x1, b0 < 0.0, 0.5 * (x0 + x1), self.rel));
        }
        if bn == 0.0 {
            found.push(self.at(u1));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_support::*;

    /// Agrees with the critical points (`roots_in`) over seeded random polynomials of degree 1
    /// to 7 with simple, clustered and double roots, on random intervals: the same count of
    /// roots with a sign change, at the same places.
    #[test]
    fn agrees_with_the_critical_points() {
        let mut rand = uniform(0x9e37_79b9_7f4a_7c15u64);
        let mut found = 0;
        for case in 0..20_000 {
            let degree = 1 + case % 7;
            let spread = [1e-3, 1.0, 1e3][case % 3];
            let mut roots: Vec<f64> = (0..degree).map(|_| (rand() * 2.0 - 1.0) * spread).collect();
            if case % 5 == 0 && degree > 2 {
                // A pair 1e-4 apart: separated by subdivision.
                roots[1] = roots[0] + 1e-4 * spread;
            }
            let scale = [1.0, -3e-7, 2e5][case % 3];
            let c = from_roots(&roots, scale);
            let lo = (rand() * 2.4 - 1.2) * spread;
            let hi = lo + rand() * spread;
            let (mut a, mut b) = ([0.0; MAX_DEGREE], [0.0; MAX_DEGREE]);
            let na = roots_in(&c, lo, hi, &mut a);
            let nb = roots_between(&c, lo, hi, &mut b);
            assert_eq!(na, nb, "case {case}: {roots:?} in [{lo}, {hi}]: {:?} vs {:?}", &a[..na], &b[..nb]);
            // Each root is within its conditioning of a true one: the rounding of p near it
            // over the slope there (clustered roots are good to fewer digits).
            for &x in &b[..nb] {
                let r = roots.iter().copied().min_by(|p, q| (p - x).abs().total_cmp(&(q - x).abs())).unwrap();
                let noise = c.iter().fold(0.0, |acc, k: &f64| acc * r.abs() + k.abs()) * f64::EPSILON;
                let slope: f64 = roots.iter().filter(|&&q| q != r).map(|q| r - q).product::<f64>() * scale;
                let bound = 1e3 * noise / slope.abs() + 1e-12 * spread;
                assert!((x - r).abs() <= bound, "case {case}: {x} vs {r} (bound {bound}): {roots:?}");
            }
            assert!(b[..nb].windows(2).all(|w| w[0] < w[1]), "ascending: {:?}", &b[..nb]);
            // Polished to f32's needs (`FOR_F32`): the same roots, each within 10⁻⁸ of its
            // bracket's scale of the precise one (well below an f32 ulp of it).
            let mut f = [0.0; MAX_DEGREE];
            let nf = roots_between_to(&c, lo, hi, FOR_F32, &mut f);
            assert_eq!(nf, nb, "case {case}: {:?} vs {:?}", &f[..nf], &b[..nb]);
            for (&x, &y) in f[..nf].iter().zip(&b[..nb]) {
                let bound = 1e-8 * (lo.abs().max(hi.abs()) + (hi - lo)) + 1e3 * f64::EPSILON * x.abs();
                assert!((x - y).abs() <= bound, "case {case}: {x} vs {y} (bound {bound})");
            }
            found += nb;
        }
        assert!(found > 10_000, "{found}");
    }

    #[test]
    fn exact_zeros_at_the_ends_and_midpoints() {
        let mut out = [0.0; MAX_DEGREE];
        // −(1 − t)²: a double root at the upper end (a ray down a lathe's axis).
        let n = roots_between(&[-1.0, 2.0, -1.0], 0.0, 1.0, &mut out);
        assert_eq!(&out[..n], &[1.0]);
        // −t²: at the lower end.
        let n = roots_between(&[-1.0, 0.0, 0.0], 0.0, 1.0, &mut out);
        assert_eq!(&out[..n], &[0.0]);
        // Roots at 0, 0.5 (a halving point) and 1, once each.
        let c = from_roots(&[0.0, 0.5, 1.0, 0.25], 1.0);
        let n = roots_between(&c, 0.0, 1.0, &mut out);
        assert_eq!(n, 4, "{:?}", &out[..n]);
        assert!(out[0] == 0.0 && out[3] == 1.0, "{:?}", &out[..n]);
        assert!((out[1] - 0.25).abs() < 1e-14 && (out[2] - 0.5).abs() < 1e-14, "{:?}", &out[..n]);
        // A double root inside without a sign change is not a crossing; one with is.
        let n = roots_between(&from_roots(&[0.3, 0.3], 1.0), 0.0, 1.0, &mut out);
        assert!(n == 0 || (n == 1 && (out[0] - 0.3).abs() < 1e-6), "{:?}", &out[..n]);
        let n = roots_between(&from_roots(&[0.3, 0.3, 0.3], 1.0), 0.0, 1.0, &mut out);
        assert_eq!(n, 1);
        assert!((out[0] - 0.3).abs() < 1e-5, "{}", out[0]);
        // No roots: a complex pair.
        assert_eq!(roots_between(&[1.0, 0.0, 1.0], -5.0, 5.0, &mut out), 0);
    }
}
