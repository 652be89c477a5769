//! A lathe of straight pieces (`linear_spline`) solved eight lanes at once in f64: each piece is
//! a cone frustum, and a ray meets it where a quadratic in the piece's parameter vanishes
//! (`lathe::Squares`), so every lane's roots come in closed form, without the per-lane
//! branches of `bernstein` and `lathe::Lathe::solve` (which took two fifths of the
//! lathe_linear kernel scene's frame). Lanes level with the axis are left to that scalar solve.
//!
//! Each lane gives the bits the scalar solve gives: the same quadratic, whose roots the scalar
//! solve takes from `roots_unit` here (one lane), the same map from the piece's parameter to
//! the ray's (a product by `1 / d.y`, as it takes it), and the same nearest root past `t_min`
//! as the lane rounds it (`hit_lanes_f64`'s retries). Only the scalar solve's own culls (slab,
//! `RadialRay::misses`) are left out: they skip pieces whose roots lie out of range, so they
//! change no answer.

use glam::DVec2;

use super::revolved::Candidates;
use super::spline::Piece;
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

/// Whether `a·t² + b·t + k` may vanish on `[0, 1]`: its Bernstein coefficients there (`k`,
/// `k + b/2`, `a + b + k`) bound it, so where all three have one sign (nonzero) it has no root
/// there. Both solves (`hit` and `lathe::Lathe::solve`) ask this first, so they skip the same
/// pieces and keep giving the same bits; most pieces a lane is not culled from end here, before
/// the square root and the four divisions of its roots.
#[inline(always)]
pub fn may_cross(a: f64, b: f64, k: f64) -> bool {
    let (b0, b1, b2) = (k, k + 0.5 * b, a + b + k);
    !((b0 > 0.0 && b1 > 0.0 && b2 > 0.0) || (b0 < 0.0 && b1 < 0.0 && b2 < 0.0))
}

/// Which lanes of `r` lie in `[0, 1]`.
#[inline(always)]
fn inside<const N: usize>(r: W<N>) -> Mask<N> {
    and(W::splat(0.0).le(r), r.le(W::splat(1.0)))
}

/// The roots in `[0, 1]` of `a·t² + b·t + k` per lane, by the stable formula (no cancellation
/// between `−b` and the square root): the lower, and the upper where it lies above the lower,
/// each with the lanes that have it. Each is good to a few f64 ulps of the piece's parameter
/// (a Newton step after it, as `bernstein::roots_between` takes, moved no f32 hit and cost two
/// of the six divisions per piece).
#[inline(always)]
pub fn roots_unit<const N: usize>(a: W<N>, b: W<N>, k: W<N>) -> [(W<N>, Mask<N>); 2] {
    let (zero, one) = (W::splat(0.0), W::splat(1.0));
    let disc = b * b - W::splat(4.0) * a * k;
    let q = W::splat(-0.5) * (b + disc.sqrt().copysign(b));
    let q_zero = and(q.le(zero), zero.le(q));
    let r0 = W::select(q_zero, zero, q / a);
    let r1 = W::select(q_zero, zero, k / W::select(q_zero, one, q));
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
    let inv_dy = W::splat(1.0) / d.y;
    let mut best = s_max;
    for (k, cone) in cones.iter().enumerate() {
        let lanes = candidates.lanes(k);
        if (0..N).all(|i| lanes >> i & 1 == 0 || skip[i]) {
            continue;
        }
        let term = |j: usize| k_y2 * W::splat(cone.y2[j]) + k_y * W::splat(cone.y[j]) - k_r2 * W::splat(cone.r2[j]);
        let (a, b, c) = (term(2), term(1), term(0) + k_1);
        // Plain loops, not `array::from_fn` closures: those were compiled out of line, without
        // AVX2 (a twentieth of the lathe_linear kernel scene's frame).
        let mut live = [false; N];
        for i in 0..N {
            live[i] = lanes >> i & 1 != 0 && !skip[i] && may_cross(a.0[i], b.0[i], c.0[i]);
        }
        if !live.contains(&true) {
            continue;
        }
        for (t, ok) in roots_unit(a, b, c) {
            let v = cone.v.map(W::splat);
            let y = ((v[3] * t + v[2]) * t + v[1]) * t + v[0];
            let s = (y - o.y) * inv_dy;
            let mut keep = [false; N];
            for i in 0..N {
                let (s, lo) = (s.0[i], s_min.0[i]);
                keep[i] = ok[i] & live[i] & (s > lo) & (s < best.0[i]) & (round(s) > lo);
            }
            best = W::select(keep, s, best);
        }
    }
    let mut out = [MISS as f64; N];
    for i in 0..N {
        if best.0[i] < s_max.0[i] {
            out[i] = round(best.0[i]).min(s_max.0[i]);
        }
    }
    W(out)
}

/// Whether the straight outline `pieces` (in order, joined end to start) bounds a simple
/// polygon, closed by itself or by the axis (both its ends at `r = 0`, where no point right of
/// the axis sees the closing edge), and if so whether it runs counter-clockwise in `(r, y)`
/// (`Some(true)`): then every piece's right-hand normal `(tan.y, −tan.x)` points out of the
/// even-odd inside, and clockwise into it. `None` where that is not shown (pieces that meet
/// other than at their joints, even collinear ones, or ends apart off the axis): a normal is
/// then oriented by an even-odd test beside its point, as for curved outlines.
pub fn outward_right(pieces: &[Piece]) -> Option<bool> {
    // The control points: the joints to the bit, where the power form's `at(1)` rounds.
    let (start, end) = (|p: &Piece| DVec2::new(p.cu[0], p.cv[0]), |p: &Piece| DVec2::new(p.cu[1], p.cv[1]));
    if pieces.iter().any(|p| p.degree != 1) || pieces.windows(2).any(|w| end(&w[0]) != start(&w[1])) {
        return None;
    }
    let mut pts: Vec<DVec2> = pieces.iter().map(start).collect();
    let (first, last) = (pts.first().copied()?, end(pieces.last()?));
    if last != first {
        if !(first.x == 0.0 && last.x == 0.0) {
            return None;
        }
        pts.push(last);
    }
    let n = pts.len();
    if n < 3 {
        return None;
    }
    let cross = |a: DVec2, b: DVec2| a.x * b.y - a.y * b.x;
    let edge = |i: usize| (pts[i], pts[(i + 1) % n]);
    for i in 0..n {
        for j in i + 1..n {
            let ((a, b), (c, d)) = (edge(i), edge(j));
            if j == i + 1 || (i == 0 && j == n - 1) {
                // Neighbours share a corner `q`: they must not fold back along each other.
                let (p, q, r) = if j == i + 1 { (a, b, d) } else { (b, a, c) };
                if p == q || r == q || (cross(p - q, r - q) == 0.0 && (p - q).dot(r - q) > 0.0) {
                    return None;
                }
                continue;
            }
            // Others must lie apart: one edge wholly on one side of the other's line.
            let one_side = |u: f64, v: f64| (u > 0.0 && v > 0.0) || (u < 0.0 && v < 0.0);
            if !one_side(cross(b - a, c - a), cross(b - a, d - a))
                && !one_side(cross(d - c, a - c), cross(d - c, b - c))
            {
                return None;
            }
        }
    }
    let area: f64 = (0..n).map(|i| cross(pts[i], pts[(i + 1) % n])).sum();
    (area != 0.0).then_some(area > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::SplineKind;
    use crate::geometry::spline::{even_odd, open_pieces};

    /// Straight outlines either way round, closed by the axis or by themselves: each piece's
    /// right-hand normal points out of the even-odd inside beside its middle exactly where
    /// `outward_right` says; outlines that cross, touch, fold back or end apart off the axis
    /// are not told.
    #[test]
    fn outward_right_agrees_with_even_odd() {
        let p = DVec2::new;
        let vase = vec![p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
        let ring = vec![p(0.2, 0.0), p(0.5, 0.0), p(0.6, 0.5), p(0.5, 1.0), p(0.2, 1.0), p(0.3, 0.5), p(0.2, 0.0)];
        let reversed = |v: &Vec<DVec2>| v.iter().rev().copied().collect::<Vec<_>>();
        let mut told = [0, 0];
        for pts in [vase.clone(), reversed(&vase), ring.clone(), reversed(&ring)] {
            let pieces = open_pieces(SplineKind::Linear, &pts).expect("outline");
            let out = outward_right(&pieces).expect("a simple polygon");
            for piece in &pieces {
                let (m, tan) = (piece.at(0.5), piece.tangent(0.5));
                let n2 = DVec2::new(tan.y, -tan.x).normalize();
                assert_eq!(even_odd(&pieces, m + 1e-6 * n2), !out, "{pts:?}");
            }
            told[usize::from(out)] += 1;
        }
        assert_eq!(told, [2, 2]);
        for pts in [
            // Crossing itself, touching itself, folding back, ends apart off the axis.
            vec![p(0.0, 0.0), p(0.5, 0.5), p(0.5, 0.0), p(0.2, 0.6), p(0.0, 0.6)],
            vec![p(0.0, 0.0), p(0.5, 0.0), p(0.5, 1.0), p(0.2, 0.5), p(0.5, 0.5), p(0.0, 1.0)],
            vec![p(0.0, 0.0), p(0.5, 0.0), p(0.3, 0.0), p(0.0, 1.0)],
            vec![p(0.1, 0.0), p(0.5, 0.0), p(0.5, 1.0), p(0.0, 1.0)],
        ] {
            let pieces = open_pieces(SplineKind::Linear, &pts).expect("outline");
            assert_eq!(outward_right(&pieces), None, "{pts:?}");
        }
    }
}
