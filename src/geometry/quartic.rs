//! Quartics in closed form, for the torus (`torus::solve`) and quartic polynomials
//! (`poly::Poly`): Ferrari's method through the resolvent cubic (`cubic`), and a Newton polish
//! of each root. Each gives up where it is ill-conditioned, near a double root, so that the
//! caller can fall back on `roots`' isolation.

use super::cubic::{finite, largest_root_lanes, rough_cbrt};
use super::wide::{and, not, or, Mask, W};

/// `x` after two Newton steps on the quartic `c`, or `None` where the last step is above `tol`:
/// Newton converges slowly only near a double root (a grazing ray the closed form's thresholds
/// let through), and there the isolation decides. One lane of [`polish_lanes`].
#[inline(always)]
pub(super) fn polish(c: &[f64; 5], x: f64, tol: f64) -> Option<f64> {
    let (x, ok) = polish_lanes(&c.map(|k| W([k])), W([x]), W([tol]));
    ok[0].then_some(x.0[0])
}

/// [`polish`] in `N` lanes: each lane's `x` after two Newton steps, and whether its last step
/// was within its `tol`.
#[inline(always)]
fn polish_lanes<const N: usize>(c: &[W<N>; 5], mut x: W<N>, tol: W<N>) -> (W<N>, Mask<N>) {
    let k = W::<N>::splat;
    let mut step = k(0.0);
    for _ in 0..2 {
        let f = (((x + c[1]) * x + c[2]) * x + c[3]) * x + c[4];
        let df = ((k(4.0) * x + k(3.0) * c[1]) * x + k(2.0) * c[2]) * x + c[3];
        step = f / df;
        x = W::select(finite(step), x - step, x);
    }
    (x, step.abs().le(tol))
}

/// The closed form declined: the quartic is near a double root, and the caller must isolate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Ill;

/// The first root of the monic quartic `c` in `[lo, hi]`, in ascending order, that `accept`
/// takes (answering what it makes of the root). `Err(Ill)` where the closed form or a polish is
/// ill-conditioned. One lane of [`first_root_lanes`].
#[inline(always)]
pub(super) fn first_root(
    c: &[f64; 5],
    lo: f64,
    hi: f64,
    accept: impl Fn(f64) -> Option<f64>,
) -> Result<Option<f64>, Ill> {
    let take = |s: W<1>| accept(s.0[0]).map_or(([false], s), |v| ([true], W([v])));
    let found = first_root_lanes(&c.map(|k| W([k])), W([lo]), W([hi]), [true], take);
    match found {
        (_, _, [true]) => Err(Ill),
        (v, [true], _) => Ok(Some(v.0[0])),
        _ => Ok(None),
    }
}

/// Per lane of `live`, the first root of the monic quartic `c` in `[lo, hi]`, in ascending
/// order, that `accept` takes (`accept(s)` answers, per lane, whether it takes `s` and the
/// value it makes of it): Ferrari's roots, each polished in turn up to that one, so that roots
/// past it cost nothing. Answers the values, the lanes that found one, and the lanes where the
/// closed form or a polish was ill-conditioned (which the caller must solve otherwise).
#[inline(always)]
pub(super) fn first_root_lanes<const N: usize>(
    c: &[W<N>; 5],
    lo: W<N>,
    hi: W<N>,
    live: Mask<N>,
    accept: impl Fn(W<N>) -> (Mask<N>, W<N>),
) -> (W<N>, Mask<N>, Mask<N>) {
    let k = W::<N>::splat;
    let (mut roots, tol, ill) = ferrari_lanes(c);
    let mut ill = and(ill, live);
    let mut searching = and(live, not(ill));
    let mut value = k(f64::NAN);
    let mut found = [false; N];
    if !searching.iter().any(|&b| b) {
        return (value, found, ill);
    }
    // Ascending (the missing ones, +inf, last): a sorting network of four.
    for (i, j) in [(0, 1), (2, 3), (0, 2), (1, 3), (1, 2)] {
        let swap = roots[j].lt(roots[i]);
        (roots[i], roots[j]) = (W::select(swap, roots[j], roots[i]), W::select(swap, roots[i], roots[j]));
    }
    let far_hi = hi + k(1e-6) * (hi.abs() + k(1.0));
    let far_lo = lo - k(1e-6) * (lo.abs() + k(1.0));
    for x in roots {
        // Far past the span (a polish moves a root by much less): so is every later one, and a
        // missing root (+inf) ends the lane's search too.
        searching = and(searching, not(far_hi.lt(x)));
        // Far before the span: no polish brings it in. A shadow ray leaving the torus has up to
        // three roots behind it, each polished for nothing before.
        let todo = and(searching, not(x.lt(far_lo)));
        if !todo.iter().any(|&b| b) {
            if !searching.iter().any(|&b| b) {
                break;
            }
            continue;
        }
        let (s, converged) = polish_lanes(c, x, tol);
        let bad = and(todo, not(converged));
        ill = or(ill, bad);
        searching = and(searching, not(bad));
        let within = and(and(todo, converged), and(lo.le(s), s.le(hi)));
        let (takes, v) = accept(s);
        let take = and(within, takes);
        value = W::select(take, v, value);
        found = or(found, take);
        searching = and(searching, not(take));
    }
    (value, found, ill)
}

/// Relative size below which a discriminant or the resolvent's root counts as zero: the closed
/// form gives up there (a double or nearly double root) and the caller solves otherwise (the torus: `roots_in`).
const ILL: f64 = 1e-9;

/// The real roots of the monic quartic `c` by Ferrari's method, unpolished, in no particular
/// order, and in `tol` the size below which [`polish`]'s last step must fall; `None` where the
/// closed form is ill-conditioned (near a double root, or with the resolvent's root near zero),
/// which the caller must solve otherwise. One lane of [`ferrari_lanes`].
#[inline(always)]
pub(super) fn ferrari(c: &[f64; 5], out: &mut [f64; 4], tol: &mut f64) -> Option<usize> {
    let (roots, t, ill) = ferrari_lanes(&c.map(|k| W([k])));
    if ill[0] {
        return None;
    }
    *tol = t.0[0];
    let mut n = 0;
    for r in roots {
        if r.0[0] != f64::INFINITY {
            out[n] = r.0[0];
            n += 1;
        }
    }
    Some(n)
}

/// Ferrari's method in `N` lanes: four root slots per lane (+inf where a slot holds no real
/// root; the roots come in the slots' order), `tol`, and the lanes where the closed form is
/// ill-conditioned. Both of the scalar method's cases (biquadratic or not) are worked out for
/// every lane and each lane keeps its own.
#[inline(always)]
fn ferrari_lanes<const N: usize>(c: &[W<N>; 5]) -> ([W<N>; 4], W<N>, Mask<N>) {
    let k = W::<N>::splat;
    let zero = k(0.0);
    // s = y − c₁/4: y⁴ + p·y² + q·y + r = 0.
    let shift = k(0.25) * c[1];
    let s2 = shift * shift;
    let p = c[2] - k(6.0) * s2;
    let q = c[3] - k(2.0) * c[2] * shift + k(8.0) * s2 * shift;
    let r = c[4] - c[3] * shift + c[2] * s2 - k(3.0) * s2 * s2;
    // The size of y²: every quantity below of that dimension is measured against it.
    let size = p.abs() + r.abs().sqrt() + (q * q).map(rough_cbrt);
    let mut ill = or(not(finite(size)), size.0.map(|v| v == 0.0));
    let none = k(f64::INFINITY);
    if ill.iter().all(|&b| b) {
        return ([none; 4], k(0.0), ill);
    }
    let biquadratic = q.abs().le(k(1e-12) * size * size.sqrt());

    // Biquadratic: y² = z with z² + p·z + r = 0. Each case is worked out only where a lane has it.
    let mut bi = [none; 4];
    let mut bi_ill = [false; N];
    if biquadratic.iter().any(|&b| b) {
        let disc = p * p - k(4.0) * r;
        bi_ill = disc.abs().le(k(ILL) * size * size);
        let real = zero.lt(disc);
        let kk = k(-0.5) * (p + disc.sqrt().copysign(p));
        let other = W::select(kk.0.map(|v| v != 0.0), r / kk, zero);
        for (slot, z) in [kk, other].into_iter().enumerate() {
            bi_ill = or(bi_ill, and(real, z.abs().le(k(ILL) * size)));
            let y = z.sqrt();
            let take = and(real, zero.lt(z));
            bi[2 * slot] = W::select(take, y, none);
            bi[2 * slot + 1] = W::select(take, -y, none);
        }
    }

    // (y² + p/2 + m)² = 2m·y² − q·y + (m² + m·p + p²/4 − r): a square when
    // m³ + p·m² + (p²/4 − r)·m − q²/8 = 0; its largest root is positive.
    let mut res = [none; 4];
    let mut res_ill = [false; N];
    if !biquadratic.iter().all(|&b| b) {
        let (m, m_nan) = largest_root_lanes(p, k(0.25) * p * p - r, k(-0.125) * q * q);
        res_ill = or(or(m_nan, not((k(1e-6) * size).lt(m))), not(finite(m)));
        let w = (k(2.0) * m).sqrt();
        let half = k(0.5) * p + m;
        let skew = q / (k(2.0) * w);
        for (slot, sign) in [1.0, -1.0].into_iter().enumerate() {
            // y² ∓ w·y + (p/2 + m ± q/(2w)) = 0.
            let b = k(-sign) * w;
            let cc = half + k(sign) * skew;
            let disc = b * b - k(4.0) * cc;
            res_ill = or(res_ill, disc.abs().le(k(ILL) * size));
            let real = zero.lt(disc);
            let kk = k(-0.5) * (b + disc.sqrt().copysign(b));
            res[2 * slot] = W::select(real, kk, none);
            res[2 * slot + 1] = W::select(real, cc / kk, none);
        }
    }

    ill = or(ill, or(and(biquadratic, bi_ill), and(not(biquadratic), res_ill)));
    let mut roots = [none; 4];
    for j in 0..4 {
        let y = W::select(biquadratic, bi[j], res[j]);
        roots[j] = W::select(y.lt(none), y - shift, none);
    }
    let tol = k(1e-10) * (size.sqrt() + shift.abs());
    (roots, tol, ill)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eight_lanes_give_each_lane_its_own_bits() {
        // Quartics of every case side by side: four real roots, two, none, biquadratic ones,
        // double roots (declined), and random ones; each lane of the eight-lane search must be
        // the one-lane search of its own quartic, bit for bit, declines included.
        let mut state = 0x5eed_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 8.0 - 4.0
        };
        let from_roots = |r: [f64; 4]| {
            let (a, b, c, d) = (r[0], r[1], r[2], r[3]);
            [
                1.0,
                -(a + b + c + d),
                a * b + a * c + a * d + b * c + b * d + c * d,
                -(a * b * c + a * b * d + a * c * d + b * c * d),
                a * b * c * d,
            ]
        };
        let mut quartics = vec![
            from_roots([1.0, 2.0, 3.0, 4.0]),
            from_roots([-1.0, 1.0, -2.0, 2.0]),
            from_roots([0.5, 0.5, 3.0, 4.0]),
            [1.0, 0.0, 1.0, 0.0, 1.0],
            [1.0, 0.0, -5.0, 0.0, 4.0],
            [1.0, -2.0, 2.0, -2.0, 1.0],
        ];
        for _ in 0..400 {
            quartics.push(from_roots([next(), next(), next(), next()]));
            quartics.push([1.0, next(), next(), next(), next()]);
        }
        let mut declined = 0;
        for chunk in quartics.chunks(8) {
            let at = |j: usize| chunk[j % chunk.len()];
            let c: [W<8>; 5] = std::array::from_fn(|k| W(std::array::from_fn(|j| at(j)[k])));
            let (lo, hi) = (W::splat(-3.0), W::splat(3.5));
            let accept = |s: W<8>| (lo.lt(s), s + W::splat(1.0));
            let (v, found, ill) = first_root_lanes(&c, lo, hi, [true; 8], accept);
            for j in 0..8 {
                let one = first_root(&at(j), -3.0, 3.5, |s| (s > -3.0).then_some(s + 1.0));
                match one {
                    Err(Ill) => {
                        assert!(ill[j], "{:?}", at(j));
                        declined += 1;
                    }
                    Ok(None) => assert!(!ill[j] && !found[j], "{:?}", at(j)),
                    Ok(Some(x)) => assert!(!ill[j] && found[j] && x.to_bits() == v.0[j].to_bits(), "{:?}", at(j)),
                }
            }
        }
        assert!(declined > 0, "a double root is declined");
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
