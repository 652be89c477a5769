//! Quartics in closed form, for the torus (`torus::solve`) and quartic polynomials
//! (`poly::Poly`): Ferrari's method through the resolvent cubic, a Newton polish of each root,
//! and a cube root that is not the library's software routine. Each gives up where it is
//! ill-conditioned, near a double root, so that the caller can fall back on `roots`'
//! isolation.

/// `x` after two Newton steps on the quartic `c`, or `None` where the last step is above `tol`:
/// Newton converges slowly only near a double root (a grazing ray the closed form's thresholds
/// let through), and there the isolation decides.
#[inline(always)]
pub(super) fn polish(c: &[f64; 5], mut x: f64, tol: f64) -> Option<f64> {
    let mut step = 0.0;
    for _ in 0..2 {
        let f = (((x + c[1]) * x + c[2]) * x + c[3]) * x + c[4];
        let df = ((4.0 * x + 3.0 * c[1]) * x + 2.0 * c[2]) * x + c[3];
        step = f / df;
        if step.is_finite() {
            x -= step;
        }
    }
    (step.abs() <= tol).then_some(x)
}

/// The closed form declined: the quartic is near a double root, and the caller must isolate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Ill;

/// The first root of the monic quartic `c` in `[lo, hi]`, in ascending order, that `accept`
/// takes (answering what it makes of the root): Ferrari's roots, each polished in turn up to
/// that one, so roots past it cost nothing. `Err(Ill)` where the closed form or a polish is
/// ill-conditioned.
#[inline(always)]
pub(super) fn first_root<T>(
    c: &[f64; 5],
    lo: f64,
    hi: f64,
    accept: impl Fn(f64) -> Option<T>,
) -> Result<Option<T>, Ill> {
    let mut roots = [0.0; 4];
    let mut tol = 0.0;
    let n = ferrari(c, &mut roots, &mut tol).ok_or(Ill)?;
    // Ascending (at most four): insertion sort.
    for i in 1..n {
        let mut j = i;
        while j > 0 && roots[j - 1] > roots[j] {
            roots.swap(j - 1, j);
            j -= 1;
        }
    }
    for &x in &roots[..n] {
        if x > hi + 1e-6 * (hi.abs() + 1.0) {
            // Far past the span (a polish moves a root by much less): so is every later one.
            return Ok(None);
        }
        if x < lo - 1e-6 * (lo.abs() + 1.0) {
            // Far before the span: no polish brings it in. A shadow ray leaving the torus has
            // up to three roots behind it, each polished for nothing before.
            continue;
        }
        let s = polish(c, x, tol).ok_or(Ill)?;
        if s >= lo && s <= hi {
            if let Some(found) = accept(s) {
                return Ok(Some(found));
            }
        }
    }
    Ok(None)
}

/// Relative size below which a discriminant or the resolvent's root counts as zero: the closed
/// form gives up there (a double or nearly double root) and the caller solves otherwise (the torus: `roots_in`).
const ILL: f64 = 1e-9;

/// The real roots of the monic quartic `c` by Ferrari's method, unpolished, in no particular
/// order, and in `tol` the size below which [`polish`]'s last step must fall; `None` where the
/// closed form is ill-conditioned (near a double root, or with the resolvent's root near zero),
/// which the caller must solve otherwise.
pub(super) fn ferrari(c: &[f64; 5], out: &mut [f64; 4], tol: &mut f64) -> Option<usize> {
    // s = y − c₁/4: y⁴ + p·y² + q·y + r = 0.
    let shift = 0.25 * c[1];
    let s2 = shift * shift;
    let p = c[2] - 6.0 * s2;
    let q = c[3] - 2.0 * c[2] * shift + 8.0 * s2 * shift;
    let r = c[4] - c[3] * shift + c[2] * s2 - 3.0 * s2 * s2;
    // The size of y²: every quantity below of that dimension is measured against it.
    let size = p.abs() + r.abs().sqrt() + rough_cbrt(q * q);
    if !size.is_finite() || size == 0.0 {
        return None;
    }
    let mut ys = [0.0; 4];
    let mut n = 0;
    if q.abs() <= 1e-12 * size * size.sqrt() {
        // Biquadratic: y² = z with z² + p·z + r = 0.
        let disc = p * p - 4.0 * r;
        if disc.abs() <= ILL * size * size {
            return None;
        }
        if disc > 0.0 {
            let k = -0.5 * (p + disc.sqrt().copysign(p));
            let zs = [k, if k != 0.0 { r / k } else { 0.0 }];
            for z in zs {
                if z.abs() <= ILL * size {
                    return None;
                }
                if z > 0.0 {
                    let y = z.sqrt();
                    ys[n] = y;
                    ys[n + 1] = -y;
                    n += 2;
                }
            }
        }
    } else {
        // (y² + p/2 + m)² = 2m·y² − q·y + (m² + m·p + p²/4 − r): a square when
        // m³ + p·m² + (p²/4 − r)·m − q²/8 = 0; its largest root is positive.
        let m = resolvent_root(p, 0.25 * p * p - r, -0.125 * q * q)?;
        if !(m > 1e-6 * size) || !m.is_finite() {
            return None;
        }
        let w = (2.0 * m).sqrt();
        let half = 0.5 * p + m;
        let skew = q / (2.0 * w);
        for sign in [1.0, -1.0] {
            // y² ∓ w·y + (p/2 + m ± q/(2w)) = 0.
            let b = -sign * w;
            let cc = half + sign * skew;
            let disc = b * b - 4.0 * cc;
            if disc.abs() <= ILL * size {
                return None;
            }
            if disc > 0.0 {
                let k = -0.5 * (b + disc.sqrt().copysign(b));
                ys[n] = k;
                ys[n + 1] = cc / k;
                n += 2;
            }
        }
    }
    for (slot, y) in out.iter_mut().zip(&ys[..n]) {
        *slot = y - shift;
    }
    *tol = 1e-10 * (size.sqrt() + shift.abs());
    Some(n)
}

/// ∛x to within a few per cent (x finite, ≥ 0): the exponent divided by three in the bits.
#[inline(always)]
fn rough_cbrt(x: f64) -> f64 {
    f64::from_bits(x.to_bits() / 3 + 0x2a9f_7893_782d_a1ce)
}

/// ∛x to a few ulps: [`rough_cbrt`] and three Halley steps (each triples the digits); the
/// library's `cbrt` is a software routine here that cost 14 % of the torus benchmark.
#[inline(always)]
fn cbrt(x: f64) -> f64 {
    let a = x.abs();
    if a == 0.0 || !a.is_finite() {
        return x;
    }
    let mut y = rough_cbrt(a);
    for _ in 0..3 {
        let y3 = y * y * y;
        y *= (y3 + 2.0 * a) / (2.0 * y3 + a);
    }
    y.copysign(x)
}

/// The largest real root of m³ + a·m² + b·m + c (Viète's form for three real roots, Cardano's
/// for one), polished by a Newton step.
#[inline]
fn resolvent_root(a: f64, b: f64, c: f64) -> Option<f64> {
    // m = y − a/3: y³ + p·y + q = 0.
    const THIRD: f64 = 1.0 / 3.0;
    let shift = a * THIRD;
    let p = b - a * shift;
    let q = c - b * shift + 2.0 * shift * shift * shift;
    let p3 = p * THIRD;
    let h = 0.25 * q * q + p3 * p3 * p3;
    if h.is_nan() {
        return None;
    }
    let mut m = if h <= 0.0 && p < 0.0 {
        // Three real roots, all within ±k; the largest lies in [k/2, k]. Halley's steps from k
        // come down onto it (the cubic is convex there) and triple the digits each, so three
        // or four reach the rounding: cheaper than Viète's `acos` and `cos` (libm's, a tenth
        // of the quartic kernel's frame).
        let k = 2.0 * (-p3).sqrt();
        let mut y = k;
        for _ in 0..6 {
            let g = (y * y + p) * y + q;
            let dg = 3.0 * y * y + p;
            let step = 2.0 * g * dg / (2.0 * dg * dg - 6.0 * y * g);
            if !step.is_finite() {
                break;
            }
            y -= step;
            if step.abs() <= 1e-15 * k {
                break;
            }
        }
        y - shift
    } else {
        let s = h.max(0.0).sqrt();
        let v = cbrt(-0.5 * q + s.copysign(-q));
        (if v == 0.0 { 0.0 } else { v - p3 / v }) - shift
    };
    let g = ((m + a) * m + b) * m + c;
    let dg = (3.0 * m + 2.0 * a) * m + b;
    let step = g / dg;
    if step.is_finite() {
        m -= step;
    }
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_root_is_accurate() {
        let mut state = 77u64;
        let mut range = |a: f64, b: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            a + (b - a) * ((state >> 11) as f64 / (1u64 << 53) as f64)
        };
        for _ in 0..100_000 {
            let x = range(-1.0, 1.0) * 10f64.powf(range(-30.0, 30.0));
            let y = cbrt(x);
            assert!((y - x.cbrt()).abs() <= 4.0 * f64::EPSILON * x.cbrt().abs(), "{x}: {y} vs {}", x.cbrt());
            let r = rough_cbrt(x.abs());
            assert!((r / x.abs().cbrt() - 1.0).abs() < 0.05, "{x}: {r}");
        }
        assert_eq!(cbrt(0.0), 0.0);
        assert_eq!(cbrt(-8.0), -2.0);
    }

    #[test]
    fn four_simple_roots_and_a_double_one() {
        // (x − 1)(x − 2)(x − 3)(x − 4) = x⁴ − 10x³ + 35x² − 50x + 24.
        let c = [1.0, -10.0, 35.0, -50.0, 24.0];
        let (mut out, mut tol) = ([0.0; 4], 0.0);
        let n = ferrari(&c, &mut out, &mut tol).expect("well-conditioned");
        let mut roots: Vec<f64> = out[..n].iter().map(|&x| polish(&c, x, tol).expect("converges")).collect();
        roots.sort_by(f64::total_cmp);
        assert_eq!(roots.len(), 4);
        for (r, want) in roots.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((r - want).abs() < 1e-12, "{roots:?}");
        }
        // (x − 1)²(x² + 1): a double root, which the closed form must leave to the caller.
        let c = [1.0, -2.0, 2.0, -2.0, 1.0];
        assert_eq!(ferrari(&c, &mut out, &mut tol), None);
    }
}
