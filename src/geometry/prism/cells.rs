//! A uniform grid over a prism's section that answers most point questions without looking at
//! an arc: a cell no arc passes through lies wholly inside or wholly outside (even-odd is
//! constant off the curves), so a cap test there is one lookup, and a cell lists the arcs that
//! pass through it, so a normal looks only at those. Cells that arcs cross leave the even-odd
//! test to `Bands` and the normal's search to the caller's fallback.
//!
//! An arc is listed in a cell when its box and its chord slab (`arc::Slab`) both meet the cell
//! widened by 10⁻⁹ of the section's size, far above the rounding of a point's cell: a point
//! whose cell lists no arc lies off every curve, and the cell's state is the even-odd answer
//! at its centre.

use glam::DVec2;

use super::arc::Slab;
use crate::geometry::spline::Piece;

#[derive(Clone, Debug)]
pub struct Cells {
    /// The grid's lower corner, cells per unit along u and v, a cell's size, and cells per side
    /// (0: no grid, every question falls back).
    lo: DVec2,
    scale: DVec2,
    size: DVec2,
    n: usize,
    /// Per cell (row-major, v rows): `OUTSIDE`, `INSIDE` or `CROSSED`.
    state: Vec<u8>,
    /// Cell `c` lists `index[start[c]..start[c + 1]]`, in increasing arc order.
    start: Vec<u32>,
    index: Vec<u32>,
}

const OUTSIDE: u8 = 0;
const INSIDE: u8 = 1;
const CROSSED: u8 = 2;

impl Cells {
    /// The grid over `arcs` (with their `slabs`), `inside` the even-odd test it stands in for.
    pub fn new(arcs: &[Piece], slabs: &[Slab], inside: impl Fn(DVec2) -> bool) -> Cells {
        let lo = arcs.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(p.lo));
        let hi = arcs.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(p.hi));
        let size = (hi - lo).max_element();
        let empty = Cells {
            lo,
            scale: DVec2::ZERO,
            size: DVec2::ZERO,
            n: 0,
            state: Vec::new(),
            start: vec![0],
            index: Vec::new(),
        };
        if !(size > 0.0 && size.is_finite()) {
            return empty;
        }
        // Widened by 10⁻⁶ so that points on the outline (normals) fall in the grid.
        let widen = 1e-6 * size;
        let (lo, hi) = (lo - widen, hi + widen);
        // 2.5·√arcs cells a side, at least 16 (prism_linear's star: a fifth of its cells
        // crossed). Four·√arcs made text's 128 glyph grids cost 5M instructions more to build
        // and rendered no faster (394.1M against 396.7M at 640x480).
        let n = ((2.5 * (arcs.len() as f64).sqrt()).ceil() as usize).clamp(16, 64);
        let scale = n as f64 / (hi - lo);
        let pad = 1e-9 * size.max(lo.abs().max(hi.abs()).max_element());
        let mut cells = Cells {
            lo,
            scale,
            size: (hi - lo) / n as f64,
            n,
            state: vec![OUTSIDE; n * n],
            start: vec![0; n * n + 1],
            index: Vec::new(),
        };
        // (cell, arc) for every arc meeting a cell, in arc order; then sorted by cell, stably.
        let mut pairs = Vec::new();
        for (k, (p, slab)) in arcs.iter().zip(slabs).enumerate() {
            let (i0, j0) = cells.clamped(p.lo - pad);
            let (i1, j1) = cells.clamped(p.hi + pad);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    let (c_lo, c_hi) = cells.corners(i, j);
                    if slab.meets_box(c_lo - pad, c_hi + pad) {
                        pairs.push((j * n + i, k as u32));
                    }
                }
            }
        }
        for &(c, _) in &pairs {
            cells.start[c + 1] += 1;
        }
        for c in 0..n * n {
            cells.start[c + 1] += cells.start[c];
        }
        let mut fill = cells.start.clone();
        cells.index = vec![0; pairs.len()];
        for &(c, k) in &pairs {
            cells.index[fill[c] as usize] = k;
            fill[c] += 1;
        }
        // Neighbouring cells of a row that no arc meets lie on the same side of every curve:
        // one even-odd test per run of them.
        for j in 0..n {
            let mut run = None;
            for i in 0..n {
                let c = j * n + i;
                cells.state[c] = if cells.start[c + 1] > cells.start[c] {
                    run = None;
                    CROSSED
                } else {
                    let inside = *run.get_or_insert_with(|| {
                        let (c_lo, c_hi) = cells.corners(i, j);
                        inside(0.5 * (c_lo + c_hi))
                    });
                    if inside {
                        INSIDE
                    } else {
                        OUTSIDE
                    }
                };
            }
        }
        cells
    }

    /// The cell holding `q`, clamped to the grid (NaN: the first).
    fn clamped(&self, q: DVec2) -> (usize, usize) {
        let f = ((q - self.lo) * self.scale).clamp(DVec2::ZERO, DVec2::splat((self.n - 1) as f64));
        (f.x as usize, f.y as usize)
    }

    /// Cell `(i, j)`'s lower and upper corners.
    fn corners(&self, i: usize, j: usize) -> (DVec2, DVec2) {
        let at = |i: usize, j: usize| self.lo + DVec2::new(i as f64, j as f64) * self.size;
        (at(i, j), at(i + 1, j + 1))
    }

    /// The cell holding `q` and its `(i, j)`, `None` outside the grid.
    #[inline]
    fn cell(&self, q: DVec2) -> Option<(usize, usize, usize)> {
        let f = (q - self.lo) * self.scale;
        let n = self.n as f64;
        if !(f.x >= 0.0 && f.x < n && f.y >= 0.0 && f.y < n) {
            return None;
        }
        // Through i32: a conversion to usize costs several instructions more.
        let (i, j) = (f.x as i32 as usize, f.y as i32 as usize);
        Some((j * self.n + i, i, j))
    }

    /// Whether `q` lies inside, where its cell decides that (no arc passes through it).
    #[inline]
    pub fn inside(&self, q: DVec2) -> Option<bool> {
        let (c, _, _) = self.cell(q)?;
        match self.state[c] {
            OUTSIDE => Some(false),
            INSIDE => Some(true),
            _ => None,
        }
    }

    /// Every cell's arc list; `None` without a grid.
    pub fn lists(&self) -> Option<impl Iterator<Item = &[u32]>> {
        (self.n > 0).then(|| self.start.windows(2).map(|w| &self.index[w[0] as usize..w[1] as usize]))
    }

    /// The arcs listed in `q`'s cell and how far `q` lies inside the cell: every other arc lies
    /// at least that far from `q`. `None` outside the grid.
    #[inline]
    pub fn near(&self, q: DVec2) -> Option<(&[u32], f64)> {
        let (c, i, j) = self.cell(q)?;
        let (c_lo, c_hi) = self.corners(i, j);
        let margin = (q - c_lo).min(c_hi - q).min_element();
        Some((&self.index[self.start[c] as usize..self.start[c + 1] as usize], margin))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::prism::arc::tests::sample_point;
    use crate::geometry::spline::even_odd;
    use crate::geometry::test_support::*;

    /// Over seeded random points the cells that decide agree with even-odd over all pieces,
    /// most points are decided by their cell, and every arc that passes within a point's
    /// margin of it is listed in its cell.
    #[test]
    fn cells_decide_as_even_odd_and_list_the_near_arcs() {
        let mut rand = uniform(0x7f4a_7c15_9e37_79b9u64);
        let pieces = star_with_hole();
        let arcs: Vec<Piece> = pieces.iter().flat_map(Piece::monotone_parts).collect();
        let slabs: Vec<Slab> = arcs.iter().map(Slab::of).collect();
        let cells = Cells::new(&arcs, &slabs, |q| even_odd(&pieces, q));
        let mut decided = 0;
        for i in 0..20_000 {
            let w = sample_point(&mut rand, &pieces, i);
            if let Some(inside) = cells.inside(w) {
                assert_eq!(inside, even_odd(&pieces, w), "{w}");
                decided += 1;
            }
            if let Some((list, margin)) = cells.near(w) {
                for (k, arc) in arcs.iter().enumerate() {
                    let dist = (arc.at(crate::geometry::spline::closest_t(arc, w)) - w).length();
                    if dist < margin {
                        assert!(list.contains(&(k as u32)), "{w}: arc {k} at {dist} < {margin}");
                    }
                }
            }
        }
        // A quarter of the points lie near the curves, a fifth outside the grid.
        assert!(decided > 6_000, "{decided}");
    }
}
