//! Real roots of polynomials in an interval, in f64, for the shapes whose surfaces are
//! polynomials of degree above two (the torus now; quartics, `sor`, `lathe` and `prism` later).
//!
//! The method isolates roots by the polynomial's own critical points: the roots of the
//! derivative (found the same way, recursively) cut the interval into pieces on which the
//! polynomial is monotonic, so each piece holds at most one root, found where the sign changes
//! by Newton steps kept inside a shrinking bracket. Unlike a closed-form quartic it does not
//! lose double roots (grazing rays) or small roots to cancellation, and it finds every root, so
//! POV-Ray's `sturm` (Sturm sequences for the same robustness) needs nothing more here.

/// Highest degree handled.
pub const MAX_DEGREE: usize = 8;

/// `p(x)` for coefficients highest degree first (Horner).
#[inline]
fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().fold(0.0, |acc, &k| acc * x + k)
}

/// The smallest root of `c` (highest degree first, `c.len() - 1 ≤ MAX_DEGREE`) in `(lo, hi)`,
/// if any.
pub fn smallest_root(c: &[f64], lo: f64, hi: f64) -> Option<f64> {
    let mut roots = [0.0; MAX_DEGREE];
    let n = roots_in(c, lo, hi, &mut roots);
    roots[..n].iter().copied().find(|&r| r > lo && r < hi)
}

/// All roots of `c` in `[lo, hi]`, ascending, into `out`; returns how many.
pub fn roots_in(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
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
            let m = roots_in(&dc[..degree], lo, hi, &mut crit);
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

/// The root of `c` in `[a, b]`, where `c` is monotonic, if its sign changes or it touches zero.
fn monotonic_root(c: &[f64], a: f64, b: f64) -> Option<f64> {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Coefficients of ∏ (x − r).
    fn from_roots(roots: &[f64]) -> Vec<f64> {
        let mut c = vec![1.0];
        for &r in roots {
            let mut next = vec![0.0; c.len() + 1];
            for (i, &k) in c.iter().enumerate() {
                next[i] += k;
                next[i + 1] -= k * r;
            }
            c = next;
        }
        c
    }

    #[test]
    fn finds_every_root_of_quartics_in_order() {
        for roots in
            [vec![-3.0, -1.0, 0.5, 2.0], vec![1.0, 1.0 + 1e-6, 5.0, 7.0], vec![1e-3, 2e-3, 1e3, 2e3], vec![-2.0, 4.0]]
        {
            let c = from_roots(&roots);
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
        let c = from_roots(&[2.0, 2.0, 3.0, 3.0]);
        let mut out = [0.0; MAX_DEGREE];
        let n = roots_in(&c, 0.0, 10.0, &mut out);
        assert!(n >= 1 && (out[0] - 2.0).abs() < 1e-6, "{:?}", &out[..n]);
        assert_eq!(smallest_root(&from_roots(&[-1.0, 4.0]), 0.0, 10.0), Some(4.0));
        assert_eq!(smallest_root(&from_roots(&[-1.0, 4.0]), 5.0, 10.0), None);
    }
}
