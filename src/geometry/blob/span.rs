//! The roots of a blob's quartic over one span of a ray (`Blob::search`): Ferrari's closed form,
//! polished, where it is well-conditioned, else isolation, with a bisection where the ends'
//! signs differ and that finds nothing; and for shadow rays, whether a span certainly holds a
//! root without placing it.

use super::super::quartic::{ferrari, polish};
use super::super::roots::{roots_in, MAX_DEGREE};

/// Horner, highest power first.
fn eval(k: &[f64; 5], u: f64) -> f64 {
    k.iter().fold(0.0, |acc, &c| acc * u + c)
}

/// The roots of `k` in `(lo, hi]`, ascending, into `out`: by critical points, or, where the
/// ends' signs differ and that finds nothing, the one bisection finds.
fn roots_above(k: &[f64; 5], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let n = roots_in(k, lo, hi, out);
    let first = out[..n].iter().position(|&r| r > lo).unwrap_or(n);
    if first < n {
        out.copy_within(first..n, 0);
        return n - first;
    }
    let (mut a, mut b) = (lo, hi);
    let (fa, fb) = (eval(k, a), eval(k, b));
    // Only a strict change of sign (not a NaN) brackets a root.
    if (fa * fb).is_nan() || fa * fb >= 0.0 {
        return 0;
    }
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        if (eval(k, m) < 0.0) == (fa < 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    out[0] = b;
    1
}

/// The roots of `k` in `(lo, hi]`, ascending: Ferrari's closed form with each root polished
/// (`quartic`), as the torus solves, where that is well-conditioned and the span is finite;
/// else, and where the ends' signs differ yet the closed form finds no root there, by
/// `roots_above`. Roots within a part in 10⁹ outside the span count as in it, so that one on
/// the end two spans share is not lost to rounding in both.
pub(super) fn span_roots(k: &[f64; 5], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    if k[0] != 0.0 && lo.is_finite() && hi.is_finite() {
        let c = [1.0, k[1] / k[0], k[2] / k[0], k[3] / k[0], k[4] / k[0]];
        let (mut r, mut tol) = ([0.0; 4], 0.0);
        if let Some(n) = ferrari(&c, &mut r, &mut tol) {
            r[..n].sort_unstable_by(f64::total_cmp);
            let eps = 1e-9 * (lo.abs() + hi.abs() + 1.0);
            let mut m = 0;
            let mut polished = true;
            for &x in &r[..n] {
                // Far outside the span (a polish moves a root by much less): not wanted.
                let far = 1e-6 * (lo.abs() + hi.abs() + 1.0);
                if x < lo - far || x > hi + far {
                    continue;
                }
                let Some(x) = polish(&c, x, tol) else {
                    polished = false;
                    break;
                };
                if x > lo - eps && x <= hi + eps {
                    out[m] = x;
                    m += 1;
                }
            }
            // Only a strict change of sign (not a NaN) brackets a root the closed form missed.
            if polished && (m > 0 || !(eval(k, lo) * eval(k, hi) < 0.0)) {
                return m;
            }
        }
    }
    roots_above(k, lo, hi, out)
}

/// Where `span_roots(k, lo, hi)` certainly finds a root: `k`'s signs at the span's ends (finite)
/// differ, as `span_roots` evaluates them, so it answers at least one root (the closed form's,
/// or failing that `roots_above`'s), each within `[lo − eps, hi + eps]`, the range answered.
/// Only the first root's position costs the closed form and its polish, which a shadow ray does
/// not need.
pub(super) fn bracket(k: &[f64; 5], lo: f64, hi: f64) -> Option<(f64, f64)> {
    if !(lo.is_finite() && hi.is_finite() && eval(k, lo) * eval(k, hi) < 0.0) {
        return None;
    }
    let eps = 1e-9 * (lo.abs() + hi.abs() + 1.0);
    Some((lo - eps, hi + eps))
}
