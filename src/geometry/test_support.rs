//! What the shape tests share: a seeded random source, polynomials of chosen roots and a prism
//! outline with many pieces.

use glam::DVec2;

use super::spline::{closed_pieces, Piece};
use crate::desc::SplineKind;

/// Uniform numbers in [0, 1) from an xorshift of `seed`: the same sequence on every run.
pub fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Coefficients of `scale·∏ (x − r)`, highest power first.
pub fn from_roots(roots: &[f64], scale: f64) -> Vec<f64> {
    let mut c = vec![scale];
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

/// A linear star with a cubic hole in it: many pieces, some level, of two kinds.
pub fn star_with_hole() -> Vec<Piece> {
    let q = |x: f64, z: f64| DVec2::new(x, z);
    let star = [q(0.45, 0.0), q(0.12, 0.12), q(0.0, 0.45), q(-0.12, 0.12), q(-0.45, 0.0), q(-0.12, -0.12)];
    let mut pts: Vec<DVec2> = star.into();
    pts.extend([q(0.0, -0.45), q(0.12, -0.12), q(0.45, 0.0)]);
    let mut pieces = closed_pieces(SplineKind::Linear, &pts).expect("star").0;
    let hole = [q(0.1, 0.0), q(0.0, 0.05), q(-0.1, 0.0), q(0.0, -0.05), q(0.1, 0.0), q(0.0, 0.05), q(-0.1, 0.0)];
    pieces.extend(closed_pieces(SplineKind::Cubic, &hole).expect("hole").0);
    pieces
}
