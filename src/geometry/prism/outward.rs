//! Which side of each arc is outside, settled once when the prism is built, so that a side's
//! normal needs no even-odd test of a point beside the hit (that test ran in a crossed cell on
//! every side normal: prism_bezier 2.7 k normals at 160x120 cost 1.4 M instructions in it).
//!
//! Along an arc that no other arc meets, the inside lies on the same side everywhere (even-odd
//! changes only across a curve), and an arc is monotone in `u` and `v`, so the right-hand side
//! of its tangent is the same side along it. An arc is taken as met by another when their
//! boxes overlap more than touching at an end the two share (consecutive arcs); a crossing
//! lies in some cell that lists both, so only arcs listed together are compared. Where that
//! holds, the side is probed either side of the arc's middle; probes that agree, a zero
//! tangent, or an arc that another may meet leave it `PROBE`: the normal then tests its own
//! point as before.

use glam::DVec2;

use crate::geometry::spline::Piece;

/// The normal's outward side: `(tan.y, -tan.x)` (`KEEP`), its opposite (`FLIP`), or asked at
/// the point (`PROBE`).
pub const PROBE: u8 = 0;
pub const KEEP: u8 = 1;
pub const FLIP: u8 = 2;

/// The outward side of each arc of `arcs`, where `lists` (the cells' arc lists; `None`: no
/// grid) shows no other arc near it; `inside` is the section's even-odd test.
pub fn sides<'a>(
    arcs: &[Piece],
    lists: Option<impl Iterator<Item = &'a [u32]>>,
    inside: impl Fn(DVec2) -> bool,
) -> Vec<u8> {
    let Some(lists) = lists else { return vec![PROBE; arcs.len()] };
    let lo = arcs.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(p.lo));
    let hi = arcs.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(p.hi));
    // Shared ends and touching boxes: far above the rounding of the arcs' split ends and their
    // boxes' pads (10⁻⁹ of the size, `Piece::monotone_parts`).
    let thin = 16e-9 * (hi - lo).max_element().max(lo.abs().max(hi.abs()).max_element());
    let mut met = vec![false; arcs.len()];
    for list in lists {
        for (n, &i) in list.iter().enumerate() {
            for &j in &list[n + 1..] {
                if meets(&arcs[i as usize], &arcs[j as usize], thin) {
                    (met[i as usize], met[j as usize]) = (true, true);
                }
            }
        }
    }
    arcs.iter().zip(&met).map(|(p, &met)| if met { PROBE } else { side(p, &inside) }).collect()
}

/// Whether arcs `p` and `q` may meet away from an end they share: their boxes overlap, and not
/// only in a strip `thin` wide through such an end. (Each arc's box has its ends at corners;
/// two that share an end and whose boxes only touch lie on either side of the strip, each
/// monotone across it, so they meet at that end alone.)
fn meets(p: &Piece, q: &Piece, thin: f64) -> bool {
    let (lo, hi) = (p.lo.max(q.lo), p.hi.min(q.hi));
    if lo.x > hi.x || lo.y > hi.y {
        return false;
    }
    if (hi - lo).min_element() > thin {
        return true;
    }
    let ends = |a: &Piece| [DVec2::new(a.cu[0], a.cv[0]), DVec2::new(a.cu[a.degree], a.cv[a.degree])];
    !ends(p).iter().any(|e| ends(q).iter().any(|f| (*e - *f).abs().max_element() <= thin))
}

/// The outward side of arc `p`, met by no other arc: the probes either side of its middle,
/// where they disagree.
fn side(p: &Piece, inside: &impl Fn(DVec2) -> bool) -> u8 {
    let tan = p.tangent(0.5);
    let n2 = DVec2::new(tan.y, -tan.x).normalize_or_zero();
    if n2 == DVec2::ZERO {
        return PROBE;
    }
    let at = p.at(0.5);
    let eps = 1e-6 * (1.0 + at.abs().max_element());
    match (inside(at + eps * n2), inside(at - eps * n2)) {
        (true, false) => FLIP,
        (false, true) => KEEP,
        _ => PROBE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::prism::arc::Slab;
    use crate::geometry::prism::cells::Cells;
    use crate::geometry::spline::even_odd;
    use crate::geometry::test_support::*;

    /// On the star with a hole, every arc's side is settled, and a point just beside any arc on
    /// the side it names is outside, on the other side inside; two overlapping copies of a
    /// curve leave every arc to the probe.
    #[test]
    fn settled_sides_are_outside() {
        let pieces = star_with_hole();
        let arcs: Vec<Piece> = pieces.iter().flat_map(Piece::monotone_parts).collect();
        let slabs: Vec<Slab> = arcs.iter().map(Slab::of).collect();
        let cells = Cells::new(&arcs, &slabs, |q| even_odd(&pieces, q));
        let found = sides(&arcs, cells.lists(), |q| even_odd(&pieces, q));
        assert!(found.iter().all(|&s| s != PROBE), "{found:?}");
        for (p, &s) in arcs.iter().zip(&found) {
            for t in [0.1, 0.4, 0.9] {
                let tan = p.tangent(t);
                let n2 = DVec2::new(tan.y, -tan.x).normalize() * if s == FLIP { -1.0 } else { 1.0 };
                assert!(!even_odd(&pieces, p.at(t) + 1e-4 * n2), "{t}");
                assert!(even_odd(&pieces, p.at(t) - 1e-4 * n2), "{t}");
            }
        }
        let shifted: Vec<Piece> = pieces.iter().map(|p| p.map(|q| q + DVec2::new(0.05, 0.0))).collect();
        let both: Vec<Piece> = pieces.iter().chain(&shifted).copied().collect();
        let arcs: Vec<Piece> = both.iter().flat_map(Piece::monotone_parts).collect();
        let slabs: Vec<Slab> = arcs.iter().map(Slab::of).collect();
        let cells = Cells::new(&arcs, &slabs, |q| even_odd(&both, q));
        let found = sides(&arcs, cells.lists(), |q| even_odd(&both, q));
        assert!(found.iter().filter(|&&s| s == PROBE).count() > arcs.len() / 2, "{found:?}");
    }
}
