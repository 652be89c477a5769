//! The one root in `[0, 1]` of a polynomial whose Bernstein coefficients there change sign
//! once (the common case of a ray crossing one cubic piece of a prism's outline): Halley steps
//! from the control polygon's crossing, kept inside the shrinking bracket.
//!
//! `bernstein::roots_unit` answers this case too, with Newton steps until one moves `t` by less
//! than 10⁻¹³ (four or five evaluations on the kernel scenes: a third of prism_bezier's time).
//! Halley's step converges cubically: the root lies within `K·step³` of the step's end, with
//! `K = p''²/(4p'²) − p'''/(6p')`, so the search stops once that bound is below 10⁻¹⁵: two or
//! three evaluations, each of `p` and its first three derivatives together.
//!
//! The coefficients come as fixed-size arrays (the sign scan unrolls), and the derivatives'
//! coefficients are formed once per root, so a step evaluates four short Horner chains rather
//! than the nested one that carried all four derivatives through every coefficient.

/// A polynomial of degree at most 3 with its derivatives' coefficients, highest power first.
struct Derivatives {
    c: [f64; 4],
    d1: [f64; 3],
    d2: [f64; 2],
    d3: f64,
}

impl Derivatives {
    /// Those of `c` (highest power first, 1 to 4 coefficients).
    #[inline]
    fn of<const N: usize>(c: &[f64; N]) -> Derivatives {
        let mut p = [0.0; 4];
        p[4 - N..].copy_from_slice(c);
        Derivatives { c: p, d1: [3.0 * p[0], 2.0 * p[1], p[2]], d2: [6.0 * p[0], 2.0 * p[1]], d3: 6.0 * p[0] }
    }

    /// `p(x)`, `p'(x)`, `p''(x)` and `p'''(x)`.
    #[inline]
    fn at(&self, x: f64) -> (f64, f64, f64, f64) {
        let (c, d1, d2) = (&self.c, &self.d1, &self.d2);
        let f = ((c[0] * x + c[1]) * x + c[2]) * x + c[3];
        (f, (d1[0] * x + d1[1]) * x + d1[2], d2[0] * x + d2[1], self.d3)
    }
}

/// `p(x)`, `p'(x)`, `p''(x)` and `p'''(x)` for coefficients highest degree first.
#[cfg(test)]
fn eval3<const N: usize>(c: &[f64; N], x: f64) -> (f64, f64, f64, f64) {
    Derivatives::of(c).at(x)
}

/// Where the Bernstein coefficients `b` change sign once, with nonzero ends and no zero between
/// them; `None` for any other sign pattern (no change, several, or a zero), which the caller
/// solves the general way.
#[inline]
pub fn single_change<const N: usize>(b: &[f64; N]) -> Option<usize> {
    let mut at = None;
    for i in 0..N - 1 {
        if b[i] == 0.0 || b[i + 1] == 0.0 || b[i].is_nan() || b[i + 1].is_nan() {
            return None;
        }
        if (b[i] < 0.0) != (b[i + 1] < 0.0) {
            if at.is_some() {
                return None;
            }
            at = Some(i);
        }
    }
    at
}

/// The root in `(0, 1)` of `c` (highest power first) whose Bernstein coefficients on `[0, 1]`
/// are `b` (as many), where `single_change(b)` is `Some(i)`: `p` then has exactly one root
/// there, with `b[0]`'s sign at 0 and `b[n]`'s at 1 (the coefficients' ends are the
/// polynomial's end values).
pub fn single_root<const N: usize>(c: &[f64; N], b: &[f64; N], i: usize) -> f64 {
    let n = N - 1;
    // The control polygon crosses zero between its points i and i + 1, near the root.
    let mut x = (i as f64 + b[i] / (b[i] - b[i + 1])) / n as f64;
    let neg_at_0 = b[0] < 0.0;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let p = Derivatives::of(c);
    for _ in 0..100 {
        let (f, df, ddf, dddf) = p.at(x);
        if f == 0.0 {
            return x;
        }
        // `lo` keeps the sign at 0, `hi` the sign at 1.
        if (f < 0.0) == neg_at_0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = 2.0 * f * df / (2.0 * df * df - f * ddf);
        let next = x - step;
        let (l, h) = (lo.min(hi), lo.max(hi));
        // Cubic convergence: the root is within about K·step³ of `next`, K·p'² compared with
        // p'² here rather than K divided out (one division a step instead of three: they were
        // most of a step's time).
        let k_df2 = 0.25 * ddf * ddf + (dddf * df / 6.0).abs();
        if df != 0.0 && k_df2 * step.abs().powi(3) <= 1e-15 * (df * df) {
            return next.clamp(l, h);
        }
        x = if next > l && next < h { next } else { 0.5 * (lo + hi) };
        if h - l <= 4.0 * f64::EPSILON {
            return x;
        }
    }
    x
}

/// How many times the coefficients `b` change sign; `None` where one is zero or NaN.
#[inline]
fn changes(b: &[f64; 4]) -> Option<usize> {
    if b.iter().any(|&x| x == 0.0 || x.is_nan()) {
        return None;
    }
    Some(b.windows(2).filter(|w| (w[0] < 0.0) != (w[1] < 0.0)).count())
}

/// The roots in `(0, 1)` of the cubic of Bernstein coefficients `b` on `[0, 1]`, where they
/// change sign more than once (a ray's plane meeting an S-shaped prism arc): its coefficients on
/// each half (de Casteljau at ½) often change sign at most once, and then each half's root is
/// `single_root`'s, far cheaper than the general isolation. `None` where a half still changes
/// sign more than once or a coefficient is zero: the caller solves the general way. The roots
/// come in ascending order; returns how many.
pub fn cubic_roots_by_halves(b: &[f64; 4], out: &mut [f64]) -> Option<usize> {
    let (l1, m1, r1) = (0.5 * (b[0] + b[1]), 0.5 * (b[1] + b[2]), 0.5 * (b[2] + b[3]));
    let (l2, r2) = (0.5 * (l1 + m1), 0.5 * (m1 + r1));
    let mid = 0.5 * (l2 + r2);
    let halves = [[b[0], l1, l2, mid], [mid, r2, r1, b[3]]];
    let counts = [changes(&halves[0])?, changes(&halves[1])?];
    if counts[0] > 1 || counts[1] > 1 {
        return None;
    }
    let mut m = 0;
    for (k, h) in halves.iter().enumerate() {
        if counts[k] == 0 {
            continue;
        }
        // Power coefficients on the half, highest first.
        let c = [h[3] - h[0] + 3.0 * (h[1] - h[2]), 3.0 * (h[0] - 2.0 * h[1] + h[2]), 3.0 * (h[1] - h[0]), h[0]];
        let i = single_change(h)?;
        out[m] = 0.5 * (k as f64 + single_root(&c, h, i));
        m += 1;
    }
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::bernstein::{roots_between, roots_unit, to_bernstein, MAX};
    use crate::geometry::roots::MAX_DEGREE;
    use crate::geometry::test_support::uniform;

    /// The first `N` of `v` as an array.
    fn fixed<const N: usize>(v: &[f64]) -> [f64; N] {
        std::array::from_fn(|i| v[i])
    }

    /// Seeded random cubics and quadratics (roots spread over [0, 1], some 10⁻⁶ from an end or
    /// from a second root outside, coefficients scaled by 10⁻⁸ to 10⁸) whose Bernstein
    /// coefficients change sign once: the root agrees with `roots_unit`'s to 10⁻¹² (or to the
    /// root's condition near a double root).
    #[test]
    fn one_sign_change_gives_roots_units_root() {
        let mut rand = uniform(0x6a09_e667_f3bc_c908u64);
        let mut tested = 0;
        for case in 0..20_000 {
            let n = 2 + case % 2;
            // Roots: one in [0, 1], others anywhere near; sometimes squeezed to an end.
            let mut r: Vec<f64> = (0..n).map(|_| rand() * 3.0 - 1.0).collect();
            r[0] = match case % 5 {
                0 => 1e-6 * rand(),
                1 => 1.0 - 1e-6 * rand(),
                _ => rand(),
            };
            if case % 7 == 0 {
                r[1] = r[0] + if rand() < 0.5 { 1e-6 } else { -1e-6 } * (1.0 + rand());
            }
            let scale = 10f64.powf(rand() * 16.0 - 8.0) * if rand() < 0.5 { -1.0 } else { 1.0 };
            // Power coefficients, lowest first, from the roots.
            let mut low = vec![scale];
            for &root in &r {
                let mut next = vec![0.0; low.len() + 1];
                for (j, &a) in low.iter().enumerate() {
                    next[j] -= root * a;
                    next[j + 1] += a;
                }
                low = next;
            }
            let b = to_bernstein(&low);
            let b = &b[..=n];
            let Some(i) = (if n == 3 { single_change(&fixed::<4>(b)) } else { single_change(&fixed::<3>(b)) }) else {
                continue;
            };
            let c: Vec<f64> = low.iter().rev().copied().collect();
            let mut roots = [0.0; MAX_DEGREE];
            let m = if n == 3 {
                let mut bb = [0.0; MAX + 1];
                bb[..=n].copy_from_slice(b);
                roots_unit(&c, bb, &mut roots)
            } else {
                roots_between(&c, 0.0, 1.0, &mut roots)
            };
            assert_eq!(m, 1, "{c:?}: {:?}", &roots[..m]);
            let t = if n == 3 {
                single_root(&fixed::<4>(&c), &fixed::<4>(b), i)
            } else {
                single_root(&fixed::<3>(&c), &fixed::<3>(b), i)
            };
            // To 10⁻¹², or to what rounding the coefficients moves a root near a double one.
            let (_, slope, _, _) =
                if n == 3 { eval3(&fixed::<4>(&c), roots[0]) } else { eval3(&fixed::<3>(&c), roots[0]) };
            let tol = 1e-12 + 8.0 * f64::EPSILON * c.iter().map(|k| k.abs()).sum::<f64>() / slope.abs();
            assert!((t - roots[0]).abs() <= tol, "{c:?}: {t} against {}", roots[0]);
            tested += 1;
        }
        assert!(tested > 5000, "{tested}");
    }

    /// Seeded random cubics with two or three roots in [0, 1] (some close together): where the
    /// halves answer, they give `roots_unit`'s roots to 10⁻¹² (or the roots' condition).
    #[test]
    fn halves_give_roots_units_roots() {
        let mut rand = uniform(0xbb67_ae85_84ca_a73bu64);
        let mut answered = 0;
        for case in 0..20_000 {
            let mut r: Vec<f64> = (0..3).map(|_| rand() * 1.4 - 0.2).collect();
            if case % 5 == 0 {
                r[1] = r[0] + 1e-4 * (rand() - 0.5);
            }
            let scale = 10f64.powf(rand() * 8.0 - 4.0) * if rand() < 0.5 { -1.0 } else { 1.0 };
            let mut low = vec![scale];
            for &root in &r {
                let mut next = vec![0.0; low.len() + 1];
                for (j, &a) in low.iter().enumerate() {
                    next[j] -= root * a;
                    next[j + 1] += a;
                }
                low = next;
            }
            let bb = to_bernstein(&low);
            let b = [bb[0], bb[1], bb[2], bb[3]];
            if changes(&b).is_none_or(|n| n < 2) {
                continue;
            }
            let c: Vec<f64> = low.iter().rev().copied().collect();
            let mut want = [0.0; MAX_DEGREE];
            let n = roots_unit(&c, bb, &mut want);
            let mut got = [0.0; 4];
            let Some(m) = cubic_roots_by_halves(&b, &mut got) else { continue };
            answered += 1;
            // The ends' values from the power form may differ in sign from the Bernstein
            // coefficients' only at a root within rounding of an end: none here.
            assert_eq!(m, n, "{c:?}: {:?} against {:?}", &got[..m], &want[..n]);
            for (g, w) in got[..m].iter().zip(&want[..n]) {
                let (_, slope, _, _) = eval3(&fixed::<4>(&c), *w);
                let tol = 1e-12 + 8.0 * f64::EPSILON * c.iter().map(|k| k.abs()).sum::<f64>() / slope.abs();
                assert!((g - w).abs() <= tol, "{c:?}: {g} against {w}");
            }
        }
        assert!(answered > 2000, "{answered}");
    }

    #[test]
    fn other_sign_patterns_are_left_to_the_general_solve() {
        assert_eq!(single_change(&[1.0, -1.0, 1.0, -1.0]), None);
        assert_eq!(single_change(&[1.0, 2.0, 3.0]), None);
        assert_eq!(single_change(&[1.0, 0.0, -1.0]), None);
        assert_eq!(single_change(&[0.0, 1.0, -1.0]), None);
        assert_eq!(single_change(&[1.0, 2.0, -1.0, -3.0]), Some(1));
    }
}
