//! Sturm sequences (POV-Ray's `sturm`): the number of distinct real roots of a polynomial in an
//! interval is the difference of the sign changes of its Sturm chain at the interval's ends, so
//! the interval is bisected until each piece holds one root, which `roots::monotonic_root`
//! polishes inside its bracket. It counts double roots too, so grazing hits are kept. One of
//! the three solvers `roots::smallest_root_by` chooses from (the tests there compare them).

use super::roots::{eval, monotonic_root, MAX_DEGREE};

/// The Sturm chain of `c` (highest degree first): `p₀ = p`, `p₁ = p'`, `pₖ₊₁ = −(pₖ₋₁ mod pₖ)`,
/// each stored highest degree first in a row of `MAX_DEGREE + 1`; returns the rows and their
/// degrees.
fn sturm_chain(c: &[f64]) -> ([[f64; MAX_DEGREE + 1]; MAX_DEGREE + 1], [usize; MAX_DEGREE + 1], usize) {
    let mut rows = [[0.0; MAX_DEGREE + 1]; MAX_DEGREE + 1];
    let mut degrees = [0; MAX_DEGREE + 1];
    let degree = c.len() - 1;
    // Normalised to a leading coefficient of ±1 so the zero test below is relative.
    let lead = c[0].abs();
    for (i, &k) in c.iter().enumerate() {
        rows[0][i] = k / lead;
    }
    degrees[0] = degree;
    let (head, tail) = rows.split_at_mut(1);
    for (i, (d, &k)) in tail[0].iter_mut().zip(&head[0][..degree]).enumerate() {
        *d = k * (degree - i) as f64;
    }
    degrees[1] = degree - 1;
    let mut count = 2;
    while degrees[count - 1] > 0 {
        let (u, du) = (rows[count - 2], degrees[count - 2]);
        let (v, dv) = (rows[count - 1], degrees[count - 1]);
        // Remainder of u / v.
        let mut rem = u;
        for i in 0..=(du - dv) {
            let f = rem[i] / v[0];
            for j in 0..=dv {
                rem[i + j] -= f * v[j];
            }
        }
        let r = &rem[du - dv + 1..=du];
        let scale = u[..=du].iter().fold(0.0f64, |m, k| m.max(k.abs()));
        let first = r.iter().position(|k| k.abs() > 1e-12 * scale);
        let Some(first) = first else { break };
        let r = &r[first..];
        let lead = r[0].abs();
        for (j, &k) in r.iter().enumerate() {
            rows[count][j] = -k / lead;
        }
        degrees[count] = r.len() - 1;
        count += 1;
    }
    (rows, degrees, count)
}

/// Sign changes of the chain at `x`, zeros skipped.
fn sign_changes(rows: &[[f64; MAX_DEGREE + 1]], degrees: &[usize], x: f64) -> u32 {
    let mut changes = 0;
    let mut last = 0.0;
    for (row, &d) in rows.iter().zip(degrees) {
        let v = eval(&row[..=d], x);
        if v != 0.0 {
            if last != 0.0 && (v < 0.0) != (last < 0.0) {
                changes += 1;
            }
            last = v;
        }
    }
    changes
}

/// Distinct real roots of `c` in `(lo, hi]` by Sturm sequences, ascending; returns how many.
/// Infinite ends are replaced by Cauchy's bound on the roots.
pub fn sturm_roots(c: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    let first = c.iter().position(|&k| k != 0.0).unwrap_or(c.len());
    let c = &c[first..];
    if c.len() < 2 {
        return 0;
    }
    let bound = 1.0 + c[1..].iter().fold(0.0f64, |m, k| m.max((k / c[0]).abs()));
    let (lo, hi) = (lo.max(-bound), hi.min(bound));
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return 0;
    }
    let (rows, degrees, count) = sturm_chain(c);
    let (rows, degrees) = (&rows[..count], &degrees[..count]);
    let mut n = 0;
    // Intervals still holding more than one root, with their sign changes at each end.
    let mut stack = [(0.0, 0.0, 0u32, 0u32); 64];
    let mut top = 1;
    stack[0] = (lo, hi, sign_changes(rows, degrees, lo), sign_changes(rows, degrees, hi));
    while top > 0 {
        top -= 1;
        let (a, b, sa, sb) = stack[top];
        let roots = sa.saturating_sub(sb);
        if roots == 0 {
            continue;
        }
        let tiny = (b - a) <= 1e-14 * a.abs().max(b.abs()).max(1e-300);
        if roots == 1 || tiny || top + 2 > stack.len() {
            // One root in (a, b]: bracketed by a sign change, or (a double root) not.
            let r = monotonic_root(c, a, b).unwrap_or_else(|| {
                // No sign change: an even-multiplicity root; bisect on the chain's count.
                let (mut a, mut b, sa_) = (a, b, sa);
                for _ in 0..200 {
                    let m = 0.5 * (a + b);
                    if m <= a || m >= b {
                        break;
                    }
                    if sign_changes(rows, degrees, m) < sa_ {
                        b = m;
                    } else {
                        a = m;
                    }
                }
                0.5 * (a + b)
            });
            if n < out.len() {
                out[n] = r;
                n += 1;
            }
            continue;
        }
        let m = 0.5 * (a + b);
        let sm = sign_changes(rows, degrees, m);
        // Upper half first on the stack, so the lower is taken next: roots come out ascending.
        stack[top] = (m, b, sm, sb);
        stack[top + 1] = (a, m, sa, sm);
        top += 2;
    }
    n
}
