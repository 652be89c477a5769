//! A lathe of straight pieces (`linear_spline`) solved eight lanes at once in f64: each piece is
//! a cone frustum, and a ray meets it where a quadratic in the piece's parameter vanishes
//! (`lathe::Squares`), so every lane's roots come in closed form, without the per-lane
//! branches of `bernstein` and `lathe::Lathe::solve` (which took two fifths of the
//! lathe_linear kernel scene's frame). Lanes level with the axis are left to that scalar solve.
//!
//! Each lane gives the bits the scalar solve gives: the same quadratic (`roots_between`'s
//! stable formula, one Newton step per root), the same map from the piece's parameter to the
//! ray's, and the same nearest root past `t_min` as the lane rounds it (`hit_lanes_f64`'s
//! retries). Only the scalar solve's own culls (slab, `RadialRay::misses`) are left out: they
//! skip pieces whose roots lie out of range, so they change no answer.

use super::revolved::Candidates;
use super::wide::{and, not, Mask, W, WV};
use crate::ray::MISS;

/// One straight piece: the ray's quadratic in its parameter `t` is
/// `k_y2·y2(t) + k_y·y(t) − k_r2·r2(t) + k_1` (lowest power first, as `lathe::Squares`), and the
/// piece's height is `v(t)` (`spline::Piece::at`'s cubic, zero above the first power).
#[derive(Clone, Copy, Debug)]
pub struct Cone {
    pub y: [f64; 3],
    pub y2: [f64; 3],
    pub r2: [f64; 3],
    pub v: [f64; 4],
}

/// Which lanes of `r` lie in `[0, 1]`.
#[inline(always)]
fn inside<const N: usize>(r: W<N>) -> Mask<N> {
    and(W::splat(0.0).le(r), r.le(W::splat(1.0)))
}

/// One Newton step for `a·t² + b·t + k` from `r`, where the step is a number (Horner from
/// zero, as `bernstein` evaluates, for the same bits).
#[inline(always)]
fn newton<const N: usize>(a: W<N>, b: W<N>, k: W<N>, r: W<N>) -> W<N> {
    let zero = W::splat(0.0);
    let (mut f, mut df) = (zero, zero);
    for c in [a, b, k] {
        df = df * r + f;
        f = f * r + c;
    }
    let step = f / df;
    r - W::select(std::array::from_fn(|i| df.0[i] != 0.0 && step.0[i].is_finite()), step, zero)
}

/// The roots in `[0, 1]` of `a·t² + b·t + k` per lane, as `bernstein::roots_between` gives them
/// (its stable formula, then one Newton step per root): the lower, and the upper where it lies
/// above the lower, each with the lanes that have it.
#[inline(always)]
fn roots_unit<const N: usize>(a: W<N>, b: W<N>, k: W<N>) -> [(W<N>, Mask<N>); 2] {
    let (zero, one) = (W::splat(0.0), W::splat(1.0));
    let disc = b * b - W::splat(4.0) * a * k;
    let q = W::splat(-0.5) * (b + disc.sqrt().copysign(b));
    let q_zero = and(q.le(zero), zero.le(q));
    let r0 = W::select(q_zero, zero, q / a);
    let r1 = W::select(q_zero, zero, k / W::select(q_zero, one, q));
    let (r0, r1) = (newton(a, b, k, r0), newton(a, b, k, r1));
    let (lower, upper) = (r0.zip(r1, f64::min), r0.zip(r1, f64::max));
    let real: Mask<N> = std::array::from_fn(|i| a.0[i] != 0.0 && disc.0[i] >= 0.0);
    let (in_lower, in_upper) = (and(real, inside(lower)), and(real, inside(upper)));
    let upper_ok = and(in_upper, std::array::from_fn(|i| !in_lower[i] || upper.0[i] > lower.0[i]));
    // A zero leading coefficient leaves a line (a NaN one the quadratic, with no root).
    let line: Mask<N> = std::array::from_fn(|i| a.0[i] == 0.0 && b.0[i] != 0.0);
    let flat = -k / b;
    let first = W::select(line, flat, lower);
    let in_flat = inside(flat);
    let first_ok: Mask<N> = std::array::from_fn(|i| if line[i] { in_flat[i] } else { in_lower[i] });
    [(first, first_ok), (upper, and(upper_ok, not(line)))]
}

/// The nearest hit per lane of `o + s·d` (object space) in `(s_min, s_max)` with the pieces
/// `cones` (lane `i` with piece `k` only where `candidates` keeps it), as `hit_lanes_f64`
/// answers it: the first root the lane's rounding (`round`) puts above `s_min`, rounded, at
/// most `s_max`; `MISS` for none. Lanes in `skip` are not solved (`MISS`).
#[inline(always)]
pub fn hit<const N: usize>(
    cones: &[Cone],
    candidates: &Candidates,
    skip: Mask<N>,
    o: WV<N>,
    d: WV<N>,
    s_min: W<N>,
    s_max: W<N>,
    round: impl Fn(f64) -> f64 + Copy,
) -> W<N> {
    // The polynomial's multiples of y², y, 1 and r² (`lathe::Squares`), as the scalar solve.
    let dh2 = d.x * d.x + d.z * d.z;
    let (ax, az) = (o.x * d.y - o.y * d.x, o.z * d.y - o.y * d.z);
    let (k_y2, k_y, k_1, k_r2) = (dh2, W::splat(2.0) * (ax * d.x + az * d.z), ax * ax + az * az, d.y * d.y);
    let mut best = s_max;
    for (k, cone) in cones.iter().enumerate() {
        let lanes = candidates.lanes(k);
        if (0..N).all(|i| lanes >> i & 1 == 0 || skip[i]) {
            continue;
        }
        let term = |j: usize| k_y2 * W::splat(cone.y2[j]) + k_y * W::splat(cone.y[j]) - k_r2 * W::splat(cone.r2[j]);
        let (a, b, c) = (term(2), term(1), term(0) + k_1);
        let live: Mask<N> = std::array::from_fn(|i| lanes >> i & 1 != 0 && !skip[i]);
        for (t, ok) in roots_unit(a, b, c) {
            let v = cone.v.map(W::splat);
            let y = ((v[3] * t + v[2]) * t + v[1]) * t + v[0];
            let s = (y - o.y) / d.y;
            let keep = std::array::from_fn(|i| {
                let (s, lo) = (s.0[i], s_min.0[i]);
                ok[i] & live[i] & (s > lo) & (s < best.0[i]) & (round(s) > lo)
            });
            best = W::select(keep, s, best);
        }
    }
    W(std::array::from_fn(|i| if best.0[i] < s_max.0[i] { round(best.0[i]).min(s_max.0[i]) } else { MISS as f64 }))
}
