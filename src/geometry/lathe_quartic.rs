//! A lathe of quadratic pieces (`quadratic_spline`) solved eight lanes at once in f64: a ray
//! meets a piece of degree 2 in its parameter `t` where a quartic in `t` vanishes
//! (`lathe::Squares`), which Ferrari's closed form solves for every lane together
//! (`quartic::first_root_lanes`, as the torus), in place of the per-lane Bernstein isolation
//! and polish of every root of every piece (two fifths of the lathe_quadratic kernel scene's
//! frame). Lanes level with the axis are left to the scalar solve (`lathe::Lathe::solve`), and
//! so is one piece of one lane where the closed form declines: a leading coefficient small
//! beside the others (a root far off, which the monic form would carry with large
//! coefficients), or a root near a double one (a grazing ray).
//!
//! Each lane does a single ray's arithmetic, and its answer is the least over the pieces of
//! each piece's own first crossing in `(s_min, s_max)`, which depends on no other piece or lane:
//! the order the pieces are taken in, and the pieces passed over because their height slab lies
//! beyond a crossing already found, change no answer. So packets and single rays give the same
//! bits, and a shadow ray may stop at its first crossing: `blocks` misses where `hit` does.

use super::quartic::first_root_lanes;
use super::revolved::{along, Candidates};
use super::wide::{and, Mask, W, WV};
use crate::ray::MISS;

/// One piece of degree 2: the ray's quartic in its parameter `t` is
/// `k_y2·y2(t) + k_y·y(t) − k_r2·r2(t) + k_1` (lowest power first, as `lathe::Squares`), in
/// both bases; its height is `y(t)`, within `y_lo ..= y_hi`, rising with `t` where `rising`.
#[derive(Clone, Copy, Debug)]
pub struct Quad {
    pub y: [f64; 5],
    pub y2: [f64; 5],
    pub r2: [f64; 5],
    pub y_b: [f64; 5],
    pub y2_b: [f64; 5],
    pub r2_b: [f64; 5],
    pub y_lo: f64,
    pub y_hi: f64,
    pub rising: bool,
}

/// Below this part of the other coefficients' size, a leading coefficient is left to the
/// scalar solve: the monic quartic would have a root beyond a thousand times the piece's
/// span, and coefficients as large, whose rounding Newton's polish need not overcome.
const SMALL_LEAD: f64 = 1e-3;

/// The nearest hit per lane of `o + s·d` (object space) in `(s_min, s_max)` with the pieces
/// `quads` (lane `i` with piece `k` only where `candidates` keeps it), as `hit_lanes_f64`
/// answers it: the first root the lane's rounding (`round`) puts above `s_min`, rounded, at
/// most `s_max`; `MISS` for none. Lanes in `skip` are not solved (`MISS`). `alone(i, k, s_min,
/// s_max)` answers piece `k` for lane `i` where the closed form declines, as this does. With
/// `any` (a shadow ray), a lane stops at its first crossing in the order it meets the pieces.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn hit<const N: usize>(
    quads: &[Quad],
    candidates: &Candidates,
    skip: Mask<N>,
    o: WV<N>,
    d: WV<N>,
    s_min: W<N>,
    s_max: W<N>,
    round: impl Fn(f64) -> f64 + Copy,
    any: bool,
    alone: impl Fn(usize, usize, f64, f64) -> Option<f64>,
) -> W<N> {
    let k = W::<N>::splat;
    // The quartic's multiples of y², y, 1 and r² (`lathe::Squares`), as the scalar solve.
    let dh2 = d.x * d.x + d.z * d.z;
    let (ax, az) = (o.x * d.y - o.y * d.x, o.z * d.y - o.y * d.z);
    let (k_y2, k_y, k_1, k_r2) = (dh2, k(2.0) * (ax * d.x + az * d.z), ax * ax + az * az, d.y * d.y);
    let inv_dy = k(1.0) / d.y;
    let (zero, mut best) = (k(0.0), s_max);
    let skip = bits(skip);
    // Each lane takes the pieces in the order its ray meets them (`along`), so that a crossing
    // found early lets it pass over the later pieces, and a shadow ray stops at the same
    // crossing in a packet as alone: the lanes climbing first, then the falling ones.
    let mut down = 0u8;
    for i in 0..N {
        down |= u8::from(d.y.0[i] < 0.0) << i;
    }
    let passes = [(!down & !skip, 0.0), (down & !skip, -1.0)];
    for (pass, dir) in passes {
        if pass == 0 {
            continue;
        }
        for p in along(quads.len(), dir) {
            let q = &quads[p];
            let mut lanes = candidates.lanes(p) & pass;
            if any {
                lanes &= !bits(best.lt(s_max));
            }
            if lanes == 0 {
                continue;
            }
            // The height slab along the ray (widened by a part in 10⁹, as the scalar solve): a lane
            // whose slab starts past its best has nothing nearer here.
            let (a, b) = ((k(q.y_lo) - o.y) * inv_dy, (k(q.y_hi) - o.y) * inv_dy);
            let pad = k(1e-9) * (a.abs() + b.abs());
            let (a, b) = (a.min(b) - pad, a.max(b) + pad);
            // No root in [0, 1] where the Bernstein coefficients have one sign (convex hull).
            let term = |j: usize| k_y2 * k(q.y2_b[j]) + k_y * k(q.y_b[j]) - k_r2 * k(q.r2_b[j]) + k_1;
            let (b0, b1, b2, b3, b4) = (term(0), term(1), term(2), term(3), term(4));
            let (low, high) = (b0.min(b1).min(b2).min(b3).min(b4), b0.max(b1).max(b2).max(b3).max(b4));
            let meets = and(and(s_min.lt(b), a.lt(best)), and(low.le(zero), zero.le(high)));
            lanes &= bits(meets);
            if lanes == 0 {
                continue;
            }
            // Highest power first, as the solvers take it.
            let power = |j: usize| k_y2 * k(q.y2[j]) + k_y * k(q.y[j]) - k_r2 * k(q.r2[j]);
            let c = [power(4), power(3), power(2), power(1), power(0) + k_1];
            let rest = c[1].abs() + c[2].abs() + c[3].abs() + c[4].abs();
            let small = bits(c[0].abs().le(k(SMALL_LEAD) * rest));
            let closed = lanes & !small;
            let mut declined = lanes & small;
            if closed != 0 {
                let piece = PieceQuartic { c, d_y: d.y, o_y: o.y, inv_dy, s_min, s_max };
                let (s, found, ill) = match closed.count_ones() {
                    n if N > 2 && n <= 2 => piece.solve_few::<2>(q, closed, round),
                    n if N > 4 && n <= 4 => piece.solve_few::<4>(q, closed, round),
                    _ => piece.solve(q, mask(closed), round),
                };
                best = W::select(and(found, s.lt(best)), s, best);
                declined |= bits(ill);
            }
            for i in (0..N).filter(|&i| declined >> i & 1 != 0) {
                if let Some(s) = alone(i, p, s_min.0[i], s_max.0[i]) {
                    best.0[i] = best.0[i].min(s);
                }
            }
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

/// Bit `i` for lane `i` of `m`.
#[inline(always)]
fn bits<const N: usize>(m: Mask<N>) -> u8 {
    let mut b = 0u8;
    for (i, &on) in m.iter().enumerate() {
        b |= u8::from(on) << i;
    }
    b
}

/// The lanes of bits `b`.
#[inline(always)]
fn mask<const N: usize>(b: u8) -> Mask<N> {
    let mut m = [false; N];
    for (i, on) in m.iter_mut().enumerate() {
        *on = b >> i & 1 != 0;
    }
    m
}

/// One piece's quartic along `N` rays (highest power first), with what maps its roots to the
/// rays' `s` and the spans they are taken in.
#[derive(Clone, Copy)]
struct PieceQuartic<const N: usize> {
    c: [W<N>; 5],
    d_y: W<N>,
    o_y: W<N>,
    inv_dy: W<N>,
    s_min: W<N>,
    s_max: W<N>,
}

impl<const N: usize> PieceQuartic<N> {
    /// `solve` for at most `M` lanes `live` (bit `i` for lane `i`), gathered into `M` lanes
    /// and scattered back.
    #[inline(always)]
    fn solve_few<const M: usize>(
        &self,
        q: &Quad,
        live: u8,
        round: impl Fn(f64) -> f64 + Copy,
    ) -> (W<N>, Mask<N>, Mask<N>) {
        let (mut at, mut n) = ([0usize; M], 0);
        for i in (0..N).filter(|&i| live >> i & 1 != 0) {
            at[n] = i;
            n += 1;
        }
        for slot in n..M {
            at[slot] = at[0];
        }
        let g = |w: W<N>| W(at.map(|i| w.0[i]));
        let few = PieceQuartic {
            c: self.c.map(g),
            d_y: g(self.d_y),
            o_y: g(self.o_y),
            inv_dy: g(self.inv_dy),
            s_min: g(self.s_min),
            s_max: g(self.s_max),
        };
        let (s, found, ill) = few.solve(q, mask((1u8 << n) - 1), round);
        let (mut out, mut f, mut bad) = (W::splat(f64::NAN), [false; N], [false; N]);
        for slot in 0..n {
            (out.0[at[slot]], f[at[slot]], bad[at[slot]]) = (s.0[slot], found[slot], ill[slot]);
        }
        (out, f, bad)
    }

    /// Per `live` lane, the first crossing in `(s_min, s_max)` that `round` puts above
    /// `s_min`, the lanes that found one, and the lanes the closed form declined. The quartic
    /// is made monic and oriented so that its roots ascend as the ray's `s` does: in `x = t`
    /// where the piece's height climbs along the ray, in `x = −t` (odd powers negated,
    /// exactly) where it falls, over `[0, 1]` or `[−1, 0]`.
    #[inline(always)]
    fn solve(&self, q: &Quad, live: Mask<N>, round: impl Fn(f64) -> f64 + Copy) -> (W<N>, Mask<N>, Mask<N>) {
        let PieceQuartic { c, d_y, o_y, inv_dy, s_min, s_max } = *self;
        let k = W::<N>::splat;
        let up: Mask<N> = if q.rising { k(0.0).lt(d_y) } else { d_y.lt(k(0.0)) };
        let inv = k(1.0) / c[0];
        let odd = |v: W<N>| W::select(up, v, -v);
        let monic = [k(1.0), odd(c[1] * inv), c[2] * inv, odd(c[3] * inv), c[4] * inv];
        let (lo, hi) = (W::select(up, k(0.0), k(-1.0)), W::select(up, k(1.0), k(0.0)));
        let accept = |x: W<N>| {
            let t = W::select(up, x, -x);
            let s = ((k(q.y[2]) * t + k(q.y[1])) * t + k(q.y[0]) - o_y) * inv_dy;
            let mut take = [false; N];
            for i in 0..N {
                let v = s.0[i];
                take[i] = v > s_min.0[i] && round(v) > s_min.0[i] && v < s_max.0[i];
            }
            (take, s)
        };
        first_root_lanes(&monic, lo, hi, live, accept)
    }
}
