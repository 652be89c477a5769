//! The polynomial along a ray, for `N` rays at once (`wide::W`): eight lanes of a packet in
//! 256-bit f64 instructions, one for a single ray. Each lane does exactly the arithmetic of a
//! single ray, in the same order (plain IEEE operations, no contraction), so packets and single
//! rays give the same bits, and the coefficients are those the one-lane-at-a-time expansion
//! gave before (kernel images byte for byte).
//!
//! Expanding lane by lane was 56 % of POV-Ray's sample quartic/torus.pov: the table of powers
//! and the term loops' bookkeeping were paid once per lane; here once per packet.

use super::super::wide::W;

/// Index of `s^m` of `(p + s·u)^e` in a triangular table of rows `e = 0, 1, ...`.
#[inline(always)]
fn tri(e: usize, m: usize) -> usize {
    e * (e + 1) / 2 + m
}

/// The coefficients (lowest degree first, `[..=order]`) of the polynomial with `terms`
/// (coefficient and exponents of x, y, z) along `p + s·u`, per lane. `K > order` sizes the
/// result and `T = K (K + 1) / 2` the table of powers (sized for the order: zeroing one for
/// degree 16 on every ray cost a fifth of objects/csg/hfclip.pov's time).
#[inline(always)]
pub(super) fn along_ray<const N: usize, const K: usize, const T: usize>(
    terms: &[(f64, [u8; 3])],
    order: usize,
    p: [W<N>; 3],
    u: [W<N>; 3],
) -> [W<N>; K] {
    debug_assert!(order < K && T == K * (K + 1) / 2);
    let zero = W::splat(0.0);
    // powers[axis][tri(e, m)]: coefficient of s^m in (p + s·u)^e.
    let mut powers = [[zero; T]; 3];
    for axis in 0..3 {
        let table = &mut powers[axis];
        table[0] = W::splat(1.0);
        for e in 1..=order {
            for m in 0..=e {
                let keep = if m < e { table[tri(e - 1, m)] * p[axis] } else { zero };
                let step = if m > 0 { table[tri(e - 1, m - 1)] * u[axis] } else { zero };
                table[tri(e, m)] = keep + step;
            }
        }
    }
    let mut poly = [zero; K];
    let mut xy = [zero; K];
    for &(c, [i, j, k]) in terms {
        let (i, j, k) = (i as usize, j as usize, k as usize);
        xy[..=i + j].fill(zero);
        for a in 0..=i {
            for b in 0..=j {
                xy[a + b] = xy[a + b] + powers[0][tri(i, a)] * powers[1][tri(j, b)];
            }
        }
        let c = W::splat(c);
        for a in 0..=i + j {
            for b in 0..=k {
                poly[a + b] = poly[a + b] + c * xy[a] * powers[2][tri(k, b)];
            }
        }
    }
    poly
}
