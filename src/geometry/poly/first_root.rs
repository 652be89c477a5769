//! The first root of a polynomial of degree 5 and up in a span, for `Solver::Fast` (POV-Ray's
//! `poly` without `sturm`). The critical-point recursion (`roots::roots_in`) found every root
//! of every derivative, each by Newton steps from the middle of its piece, which on a sextic
//! far from its root shrink by only 5/6 a step: 80 % of scenes/kernels/poly.pov's time.
//!
//! Here the span's Bernstein coefficients decide first (Descartes' rule of signs in that basis:
//! the polynomial has no more roots in the span than they have sign changes, and as many
//! modulo two). All of one sign with a margin far above rounding: no root. One change, every
//! coefficient clear of zero: exactly one root, bracketed by the span's ends, found by Halley
//! steps on the original coefficients from where the control polygon crosses zero (cubic
//! convergence). Anything else is halved (de Casteljau), the near half first, so the search
//! stops at the first root. A span still undecided after `MAX_DEPTH` halvings (near a double
//! root: a grazing ray) goes to the critical points, which do not lose double roots.

use super::super::roots::{certainly_no_root, monotonic_root, on_unit, root_bound, MAX_DEGREE};

/// Halvings before a span goes to the critical points: 2⁻¹⁶ of the span.
const MAX_DEPTH: u32 = 16;

/// The smallest root of `c` (highest degree first, `c[0] ≠ 0`) in `(lo, hi)`, searched only
/// over the span that can hold roots (`roots::root_bound`), not Cauchy's bound (64 for a
/// sextic whose roots are of size 2, where the critical points found a spurious root at −1.3e9
/// for a sextic with roots of size 5e3).
pub(super) fn first_root_within_bound(c: &[f64], lo: f64, hi: f64) -> Option<f64> {
    let bound = root_bound(c);
    let (a, b) = (lo.max(-bound), hi.min(bound));
    if a.is_nan() || b.is_nan() || a >= b {
        return None;
    }
    let n = c.len() - 1;
    if n > MAX_DEGREE {
        return critical_first_root(c, a, b, lo, hi);
    }
    // The tables sized for the degree: zeroing and copying `MAX_DEGREE + 1` slots per halving
    // (the copy a call to `memmove`) was a tenth of scenes/kernels/poly.pov's time.
    match n {
        ..=6 => search_from::<7>(c, n, a, b, lo, hi),
        7..=8 => search_from::<9>(c, n, a, b, lo, hi),
        _ => search_from::<{ MAX_DEGREE + 1 }>(c, n, a, b, lo, hi),
    }
}

/// `first_root_within_bound` over `[a, b]` with tables of `K > n` slots.
#[inline(always)]
fn search_from<const K: usize>(c: &[f64], n: usize, a: f64, b: f64, lo: f64, hi: f64) -> Option<f64> {
    let Some((bern, tol)) = bernstein::<K>(c, a, b) else {
        return critical_first_root(c, a, b, lo, hi);
    };
    let search = Search { c, tol, lo, hi, a, w: b - a };
    search.first(&bern, n, 0.0, 1.0, 0)
}

/// The Bernstein coefficients of `c` (highest degree first, degree at most `MAX_DEGREE`) on
/// `[a, b]`, and the size below which one counts as zero: 10⁻¹⁰ of the sum of the magnitudes
/// that went into them (their rounding is below (n + 1)² ulps of it). `None` for an infinite
/// end or a zero or non-finite magnitude.
fn bernstein<const K: usize>(c: &[f64], a: f64, b: f64) -> Option<([f64; K], f64)> {
    let n = c.len() - 1;
    if !(a.is_finite() && b.is_finite()) {
        return None;
    }
    let (s, magnitude) = on_unit(c, a, b)?;
    // b_i = Σ_{j ≤ i} C(i, j) · s_j / C(n, j): the s_j / C(n, j), then Pascal's triangle summed
    // in place (n passes of neighbour sums), with no division in the inner loop.
    let mut out = [0.0; K];
    for j in 0..=n {
        out[j] = s[j] / BINOMIAL[n][j];
    }
    for k in 1..=n {
        for i in (k..=n).rev() {
            out[i] += out[i - 1];
        }
    }
    Some((out, 1e-10 * magnitude))
}

/// `C(n, j)` for `n` up to `MAX_DEGREE`: a table, not a product and an integer division per
/// coefficient (`idiv`s a tenth of `bernstein`'s time).
const BINOMIAL: [[f64; MAX_DEGREE + 1]; MAX_DEGREE + 1] = {
    let mut t = [[0.0; MAX_DEGREE + 1]; MAX_DEGREE + 1];
    let mut n = 0;
    while n <= MAX_DEGREE {
        let mut c = 1u64;
        let mut j = 0;
        while j <= n {
            t[n][j] = c as f64;
            c = c * (n - j) as u64 / (j + 1) as u64;
            j += 1;
        }
        n += 1;
    }
    t
};

/// One first-root search: the polynomial `c`, the zero margin `tol` of its Bernstein
/// coefficients, the wanted span `(lo, hi)` and the searched one, `a + w·[0, 1]`.
struct Search<'a> {
    c: &'a [f64],
    tol: f64,
    lo: f64,
    hi: f64,
    a: f64,
    w: f64,
}

impl Search<'_> {
    /// The first root in `(lo, hi)` within `a + w·[x0, x1]`, where the Bernstein coefficients
    /// of degree `n` are `b[..=n]` (`n < K`).
    fn first<const K: usize>(&self, b: &[f64; K], n: usize, x0: f64, x1: f64, depth: u32) -> Option<f64> {
        let b_n = &b[..=n];
        let clear = b_n.iter().all(|v| v.abs() > self.tol);
        if clear {
            let changes = b_n.windows(2).filter(|p| (p[0] < 0.0) != (p[1] < 0.0)).count();
            match changes {
                0 => return None,
                1 => {
                    let (s0, s1) = (self.a + self.w * x0, self.a + self.w * x1);
                    let at = b_n.windows(2).position(|p| (p[0] < 0.0) != (p[1] < 0.0)).unwrap_or(0);
                    let cross = (at as f64 + b[at] / (b[at] - b[at + 1])) / n as f64;
                    let r = halley_in(self.c, s0, s1, s0 + (s1 - s0) * cross, b[0] < 0.0);
                    return (r > self.lo && r < self.hi).then_some(r);
                }
                _ => {}
            }
        }
        if depth >= MAX_DEPTH {
            let (s0, s1) = (self.a + self.w * x0, self.a + self.w * x1);
            return critical_first_root(self.c, s0, s1, self.lo, self.hi);
        }
        // de Casteljau at the middle: `left` on [x0, xm], `right` on [xm, x1]. With the
        // degree the tables' (the usual case), the loops' counts are constants, unrolled into
        // registers.
        let (left, right) = if n + 1 == K { halves(b, K - 1) } else { halves(b, n) };
        let xm = 0.5 * (x0 + x1);
        self.first(&left, n, x0, xm, depth + 1).or_else(|| self.first(&right, n, xm, x1, depth + 1))
    }
}

/// The Bernstein coefficients `b[..=n]` on the halves of their span, by de Casteljau.
#[inline(always)]
fn halves<const K: usize>(b: &[f64; K], n: usize) -> ([f64; K], [f64; K]) {
    let (mut left, mut right) = ([0.0; K], [0.0; K]);
    let mut row = *b;
    for k in 0..=n {
        left[k] = row[0];
        right[n - k] = row[n - k];
        for i in 0..n - k {
            row[i] = 0.5 * (row[i] + row[i + 1]);
        }
    }
    (left, right)
}

/// The one root of `c` in `[s0, s1]`, whose ends have opposite signs (`c(s0) < 0` when
/// `neg_at_s0`): Halley steps from `x`, kept inside the shrinking bracket (bisection where a
/// step leaves it), until a step moves by less than a few ulps or `p` is
/// within its rounding of zero.
fn halley_in(c: &[f64], s0: f64, s1: f64, mut x: f64, neg_at_s0: bool) -> f64 {
    let (mut lo, mut hi) = (s0, s1);
    for _ in 0..100 {
        // `p`, `p'`, `p''` and the size of `p`'s rounding (Horner on the magnitudes).
        let (mut f, mut df, mut ddf, mut size) = (0.0, 0.0, 0.0, 0.0);
        for &k in c {
            ddf = ddf * x + 2.0 * df;
            df = df * x + f;
            f = f * x + k;
            size = size * x.abs() + k.abs();
        }
        // At the root to within `p`'s rounding: no step can do better.
        if f.abs() <= 8.0 * f64::EPSILON * size {
            return x;
        }
        // `lo` keeps the sign at `s0`, `hi` the sign at `s1`.
        if (f < 0.0) == neg_at_s0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = 2.0 * f * df / (2.0 * df * df - f * ddf);
        let next = x - step;
        let (l, h) = (lo.min(hi), lo.max(hi));
        let tiny = 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE);
        if step.abs() <= tiny && next >= l && next <= h {
            return next;
        }
        x = if next > l && next < h { next } else { 0.5 * (lo + hi) };
        if h - l <= tiny {
            return x;
        }
    }
    x
}

/// The smallest root of `c` in `(lo, hi)` within `[a, b]`, by critical points: for the spans
/// the Bernstein coefficients leave undecided (near a double root).
fn critical_first_root(c: &[f64], a: f64, b: f64, lo: f64, hi: f64) -> Option<f64> {
    if certainly_no_root(c, a, b) {
        return None;
    }
    let n = c.len() - 1;
    let dc = derivative(c);
    let mut crit = [0.0; MAX_DEGREE];
    let m = roots_pruned(&dc[..n], a, b, &mut crit);
    let mut last = f64::NEG_INFINITY;
    let mut from = a;
    for &to in crit[..m].iter().chain(std::iter::once(&b)) {
        if let Some(r) = monotonic_root(c, from, to) {
            // A root at a critical point (a double root) shows in both neighbours.
            if r > last {
                if r > lo && r < hi {
                    return Some(r);
                }
                last = r;
            }
        }
        from = to;
    }
    None
}

/// `c`'s derivative (highest degree first) in the first `c.len() - 1` slots.
#[inline]
fn derivative(c: &[f64]) -> [f64; MAX_DEGREE + 1] {
    let degree = c.len() - 1;
    let mut dc = [0.0; MAX_DEGREE + 1];
    for (i, k) in c[..degree].iter().enumerate() {
        dc[i] = k * (degree - i) as f64;
    }
    dc
}

/// All roots of `c` in `[lo, hi]`, ascending, into `out`; returns how many. `roots::roots_in`'s
/// recursion, with every level of degree two and up tested first for a span without roots.
fn roots_pruned(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
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
            if certainly_no_root(c, lo, hi) {
                return 0;
            }
            let dc = derivative(c);
            let mut crit = [0.0; MAX_DEGREE];
            let m = roots_pruned(&dc[..degree], lo, hi, &mut crit);
            let mut n = 0;
            let mut a = lo;
            for &b in crit[..m].iter().chain(std::iter::once(&hi)) {
                if let Some(r) = monotonic_root(c, a, b) {
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
