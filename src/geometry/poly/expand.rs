//! The polynomial along a ray, for `N` rays at once (`wide::W`): eight lanes of a packet in
//! 256-bit f64 instructions, one for a single ray. Each lane does exactly the arithmetic of a
//! single ray, in the same order (plain IEEE operations, no contraction), so packets and single
//! rays give the same bits, and the coefficients are those the one-lane-at-a-time expansion
//! gave before (kernel images byte for byte).
//!
//! Expanding lane by lane was 56 % of POV-Ray's sample quartic/torus.pov: the table of powers
//! and the term loops' bookkeeping were paid once per lane; here once per packet.

use std::mem::MaybeUninit;

use super::super::wide::W;

/// Index of `s^m` of `(p + s·u)^e` in a triangular table of rows `e = 0, 1, ...`.
#[inline(always)]
fn tri(e: usize, m: usize) -> usize {
    e * (e + 1) / 2 + m
}

/// `table[tri(e, m)]`, for a row `e` that `along_ray` has written (`e ≤ order`, which it
/// asserts of every term before reading its powers).
#[inline(always)]
fn written<const N: usize, const T: usize>(table: &[MaybeUninit<W<N>>; T], e: usize, m: usize) -> W<N> {
    debug_assert!(m <= e);
    // SAFETY: `along_ray` writes rows 0..=order in turn, each before it reads it (row e − 1
    // while writing row e; every row once the table is done), and asks only for those rows.
    unsafe { table[tri(e, m)].assume_init() }
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
    // powers[axis][tri(e, m)]: coefficient of s^m in (p + s·u)^e. Only the rows up to the
    // order are written, and only those are read (no exponent exceeds the order, asserted per
    // term below), so the table is not zeroed first: for a cubic that memset (2.9 KB, a table
    // sized for degree 4, per packet row) was a thirtieth of scenes/kernels/cubic.pov's frame.
    let mut powers = [[MaybeUninit::<W<N>>::uninit(); T]; 3];
    for axis in 0..3 {
        let table = &mut powers[axis];
        table[0].write(W::splat(1.0));
        for e in 1..=order {
            for m in 0..=e {
                // Row e − 1 is written: row 0 above, each later one by the pass before.
                let keep = if m < e { written(table, e - 1, m) * p[axis] } else { zero };
                let step = if m > 0 { written(table, e - 1, m - 1) * u[axis] } else { zero };
                table[tri(e, m)].write(keep + step);
            }
        }
    }
    let mut poly = [zero; K];
    let mut xy = [zero; K];
    for &(c, [i, j, k]) in terms {
        let (i, j, k) = (i as usize, j as usize, k as usize);
        assert!(i.max(j).max(k) <= order, "a term above the polynomial's order");
        xy[..=i + j].fill(zero);
        for a in 0..=i {
            for b in 0..=j {
                xy[a + b] = xy[a + b] + written(&powers[0], i, a) * written(&powers[1], j, b);
            }
        }
        let c = W::splat(c);
        for a in 0..=i + j {
            for b in 0..=k {
                poly[a + b] = poly[a + b] + c * xy[a] * written(&powers[2], k, b);
            }
        }
    }
    poly
}
