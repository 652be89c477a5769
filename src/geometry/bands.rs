//! Pieces of closed curves bucketed by height, so that an even-odd test (`spline::even_odd`)
//! visits only the pieces whose height span could hold the point's height: a glyph's outline
//! has dozens of pieces, and a test of a prism's cap otherwise looks at every one of them.
//!
//! The section's height range is cut into equal bands; a piece is listed in every band from
//! the one holding its lowest height to the one holding its highest. The band of a height is
//! a monotone function of it, so a point whose height lies in a piece's span falls in one of
//! that piece's bands: the test gives the same parity as over all pieces, bit for bit.

use glam::DVec2;

use super::spline::{even_odd_of, Piece};

#[derive(Clone, Debug)]
pub struct Bands {
    /// The lowest height and bands per unit height.
    y0: f64,
    scale: f64,
    /// The pieces' box: outside it nothing is inside (every crossing pairs up).
    lo: DVec2,
    hi: DVec2,
    /// Band `i` lists `index[start[i]..start[i + 1]]`.
    start: Vec<u32>,
    index: Vec<u32>,
}

impl Bands {
    pub fn new(pieces: &[Piece]) -> Bands {
        let lo = pieces.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(p.lo));
        let hi = pieces.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(p.hi));
        let n = pieces.len().clamp(1, 256);
        let span = hi.y - lo.y;
        let scale = if span > 0.0 && span.is_finite() { n as f64 / span } else { 0.0 };
        let mut bands = Bands { y0: lo.y, scale, lo, hi, start: vec![0; n + 1], index: Vec::new() };
        let mut lists = vec![Vec::new(); n];
        for (i, p) in pieces.iter().enumerate() {
            for list in &mut lists[bands.band(p.lo.y)..=bands.band(p.hi.y)] {
                list.push(i as u32);
            }
        }
        for (b, list) in lists.iter().enumerate() {
            bands.index.extend(list);
            bands.start[b + 1] = bands.index.len() as u32;
        }
        bands
    }

    /// The band of height `y`, clamped to the bands (NaN: the first).
    fn band(&self, y: f64) -> usize {
        let last = self.start.len() - 2;
        ((y - self.y0) * self.scale).clamp(0.0, last as f64) as usize
    }

    /// Whether `q` lies inside the curves `pieces` (those this was built from), by even-odd.
    pub fn inside(&self, pieces: &[Piece], q: DVec2) -> bool {
        even_odd_of(self.candidates(q).iter().map(|&i| &pieces[i as usize]), q)
    }

    /// The indices of the pieces that can cross the ray from `q` towards +u (none outside the
    /// pieces' box): what an even-odd test of `q` visits.
    #[inline]
    pub fn candidates(&self, q: DVec2) -> &[u32] {
        if !(q.x >= self.lo.x && q.x <= self.hi.x && q.y >= self.lo.y && q.y <= self.hi.y) {
            return &[];
        }
        let b = self.band(q.y);
        &self.index[self.start[b] as usize..self.start[b + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::SplineKind;
    use crate::geometry::spline::{closed_pieces, even_odd};
    use crate::geometry::test_support::*;

    /// Over seeded random points, and points on the pieces' joints and end heights (where a
    /// band edge or a piece's span ends), the banded test answers as even-odd over all pieces.
    #[test]
    fn bands_answer_as_all_pieces() {
        let mut rand = uniform(0x9e37_79b9_7f4a_7c15u64);
        let q = |x: f64, y: f64| DVec2::new(x, y);
        // A star with a hole of another kind, and a quadratic outline: many pieces, some level.
        let pieces = star_with_hole();
        let quad = [q(1.0, 1.0), q(2.0, 1.0), q(2.0, 2.0), q(1.0, 2.0), q(1.0, 1.0), q(2.0, 1.0)];
        let quad = closed_pieces(SplineKind::Quadratic, &quad).expect("quadratic").0;
        for outline in [pieces, quad] {
            let bands = Bands::new(&outline);
            let (lo, hi) = (bands.lo, bands.hi);
            let mut points: Vec<DVec2> = outline.iter().flat_map(|p| [p.at(0.0), p.at(0.5), p.lo, p.hi]).collect();
            points.extend((0..20_000).map(|_| lo - 0.1 + (hi - lo + 0.2) * DVec2::new(rand(), rand())));
            let mut inside = 0;
            for w in points {
                let want = even_odd(&outline, w);
                assert_eq!(bands.inside(&outline, w), want, "{w}");
                inside += want as usize;
            }
            assert!(inside > 1000, "the points reach the inside: {inside}");
        }
    }
}
