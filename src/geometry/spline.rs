//! POV-Ray's 2-D splines for `prism` and `lathe` (and TrueType glyph outlines), turned into
//! pieces that the shapes solve: each piece is a polynomial curve of degree ≤ 3 in `t ∈ [0, 1]`
//! with the box of its Bézier control points (the curve lies inside it: convex hull).
//!
//! Which points are control points (POV-Ray 3.7 reference, 3.4.6.x Prism and Lathe):
//! - `linear_spline`: every point lies on the curve; each pair is a straight piece.
//! - `quadratic_spline`: the first point is a control point; the piece from `P[i]` to `P[i+1]`
//!   is the quadratic through both whose tangent at `P[i]` is `(P[i+1] − P[i−1]) / 2`
//!   (measured against `povray` renders of a closed quadratic prism: within a pixel).
//! - `cubic_spline`: the first and last points are control points; the piece from `P[i]` to
//!   `P[i+1]` is the Catmull-Rom cubic (tangents `(P[i+1] − P[i−1]) / 2`, `(P[i+2] − P[i]) / 2`).
//! - `bezier_spline`: four points per piece, the cubic Bézier of them.
//!
//! A prism's sub-curve closes where a point repeats its first on-curve point (the first point
//! for linear, the second for quadratic and cubic, the first of a Bézier group's end points).

use glam::DVec2;

use super::bernstein::{roots_between, MAX as MAX_B};
use super::roots::MAX_DEGREE;
use crate::desc::SplineKind;

/// One piece: `(u(t), v(t)) = Σ c[k] tᵏ` for `t ∈ [0, 1]` (lowest power first), with the box
/// of its control points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    pub u: [f64; 4],
    pub v: [f64; 4],
    /// Highest power with a nonzero coefficient as built (1 for lines, 2, 3).
    pub degree: usize,
    /// The Bézier control points (`degree + 1` of them): the piece's Bernstein coefficients on
    /// `[0, 1]`, so `a·u + b·v + k` there has the coefficients `a·cu[i] + b·cv[i] + k`.
    pub cu: [f64; 4],
    pub cv: [f64; 4],
    pub lo: DVec2,
    pub hi: DVec2,
}

impl Piece {
    /// The straight piece from `a` to `b`.
    pub fn line(a: DVec2, b: DVec2) -> Piece {
        let d = b - a;
        Piece::from_power([a, d, DVec2::ZERO, DVec2::ZERO], 1, &[a, b])
    }

    /// The quadratic Bézier of `p0, p1, p2`.
    pub fn quadratic_bezier(p0: DVec2, p1: DVec2, p2: DVec2) -> Piece {
        let c1 = 2.0 * (p1 - p0);
        let c2 = p0 - 2.0 * p1 + p2;
        Piece::from_power([p0, c1, c2, DVec2::ZERO], 2, &[p0, p1, p2])
    }

    /// The cubic Bézier of `p0..p3`.
    pub fn cubic_bezier(p: [DVec2; 4]) -> Piece {
        let c1 = 3.0 * (p[1] - p[0]);
        let c2 = 3.0 * (p[0] - 2.0 * p[1] + p[2]);
        let c3 = p[3] - p[0] + 3.0 * (p[1] - p[2]);
        Piece::from_power([p[0], c1, c2, c3], 3, &p)
    }

    /// The cubic Hermite piece from `a` to `b` with end tangents `ta`, `tb`.
    fn hermite(a: DVec2, ta: DVec2, b: DVec2, tb: DVec2) -> Piece {
        Piece::cubic_bezier([a, a + ta / 3.0, b - tb / 3.0, b])
    }

    /// The piece of power coefficients `c` and control points `hull` (`degree + 1`).
    fn from_power(c: [DVec2; 4], degree: usize, hull: &[DVec2]) -> Piece {
        let lo = hull.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(*p));
        let hi = hull.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(*p));
        let (mut cu, mut cv) = ([0.0; 4], [0.0; 4]);
        for (i, p) in hull.iter().enumerate() {
            (cu[i], cv[i]) = (p.x, p.y);
        }
        Piece { u: c.map(|p| p.x), v: c.map(|p| p.y), degree, cu, cv, lo, hi }
    }

    /// The Bernstein coefficients on `[0, 1]` of `a·u(t) + b·v(t) + k` (`degree + 1` of them).
    #[inline]
    pub fn combine_bernstein(&self, a: f64, b: f64, k: f64) -> [f64; MAX_B + 1] {
        let mut out = [0.0; MAX_B + 1];
        for i in 0..=self.degree {
            out[i] = a * self.cu[i] + b * self.cv[i] + k;
        }
        out
    }

    pub fn at(&self, t: f64) -> DVec2 {
        let h = |c: &[f64; 4]| ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
        DVec2::new(h(&self.u), h(&self.v))
    }

    pub fn tangent(&self, t: f64) -> DVec2 {
        let h = |c: &[f64; 4]| (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1];
        DVec2::new(h(&self.u), h(&self.v))
    }

    /// `a·u(t) + b·v(t) + k`, highest power first (for `geometry::bernstein`), trimmed to the
    /// piece's degree.
    pub fn combine(&self, a: f64, b: f64, k: f64) -> ([f64; 4], usize) {
        let mut c = [0.0; 4];
        for (i, slot) in c.iter_mut().enumerate().take(self.degree + 1) {
            let p = self.degree - i;
            *slot = a * self.u[p] + b * self.v[p] + if p == 0 { k } else { 0.0 };
        }
        (c, self.degree + 1)
    }

    /// The piece's control points (`degree + 1` of them).
    fn control(&self) -> [DVec2; 4] {
        std::array::from_fn(|i| DVec2::new(self.cu[i], self.cv[i]))
    }

    /// The part of the piece for `t ∈ [t0, t1]` (`0 ≤ t0 < t1 ≤ 1`), reparametrised to `[0, 1]`:
    /// its control points by de Casteljau (split at `t1`, then the left part at `t0 / t1`).
    pub fn part(&self, t0: f64, t1: f64) -> Piece {
        let n = self.degree;
        let split = |p: [DVec2; 4], t: f64| {
            let (mut left, mut right, mut w) = ([DVec2::ZERO; 4], [DVec2::ZERO; 4], p);
            left[0] = w[0];
            right[n] = w[n];
            for k in 1..=n {
                for i in 0..=n - k {
                    w[i] = w[i].lerp(w[i + 1], t);
                }
                left[k] = w[0];
                right[n - k] = w[n - k];
            }
            (left, right)
        };
        let p = if t1 < 1.0 { split(self.control(), t1).0 } else { self.control() };
        let p = if t0 > 0.0 { split(p, t0 / t1).1 } else { p };
        match n {
            1 => Piece::line(p[0], p[1]),
            2 => Piece::quadratic_bezier(p[0], p[1], p[2]),
            _ => Piece::cubic_bezier(p),
        }
    }

    /// The piece cut where `u` or `v` turns (the roots of `u'` and `v'` inside `(0, 1)`), so that
    /// each part runs one way in both: the box of its ends holds it, far tighter than its
    /// control points' box where the piece bulges. Each part's `lo` and `hi` are that box,
    /// widened by 10⁻⁹ of the piece's size (a turning point found to rounding overshoots its
    /// part's end by the square of that error).
    pub fn monotone_parts(&self) -> Vec<Piece> {
        let mut cuts = vec![0.0, 1.0];
        for c in [&self.u, &self.v] {
            // u'(t) = c1 + 2 c2 t + 3 c3 t², highest power first.
            let d = [3.0 * c[3], 2.0 * c[2], c[1]];
            let mut roots = [0.0; MAX_DEGREE];
            let m = roots_between(&d[3 - self.degree..], 0.0, 1.0, &mut roots);
            cuts.extend(roots[..m].iter().filter(|&&t| t > 1e-9 && t < 1.0 - 1e-9));
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|a, b| *a - *b < 1e-9);
        let pad = 1e-9 * (self.hi - self.lo).max_element().max(self.lo.abs().max(self.hi.abs()).max_element());
        cuts.windows(2)
            .map(|w| {
                let mut part = if cuts.len() == 2 { *self } else { self.part(w[0], w[1]) };
                let (a, b) = (part.at(0.0), part.at(1.0));
                part.lo = part.lo.max(a.min(b) - pad);
                part.hi = part.hi.min(a.max(b) + pad);
                part
            })
            .collect()
    }

    /// The same piece with every point mapped by `f` (affine maps only).
    pub fn map(&self, f: impl Fn(DVec2) -> DVec2) -> Piece {
        let o = f(DVec2::ZERO);
        let p = |k: usize| DVec2::new(self.u[k], self.v[k]);
        let lin = |q: DVec2| f(q) - o;
        let c = [f(p(0)), lin(p(1)), lin(p(2)), lin(p(3))];
        let hull: Vec<DVec2> = (0..=self.degree).map(|i| f(DVec2::new(self.cu[i], self.cv[i]))).collect();
        Piece::from_power(c, self.degree, &hull)
    }
}

/// Why points do not make a spline, for a located error.
pub type SplineError = String;

/// Tangent of the quadratic and cubic splines at `b` from its neighbours.
fn tangent(prev: DVec2, next: DVec2) -> DVec2 {
    0.5 * (next - prev)
}

/// The pieces of the open spline through `points` (a lathe's outline).
pub fn open_pieces(kind: SplineKind, points: &[DVec2]) -> Result<Vec<Piece>, SplineError> {
    let n = points.len();
    let (least, rule) = match kind {
        SplineKind::Linear => (2, "at least 2 points"),
        SplineKind::Quadratic => (3, "at least 3 points (the first is a control point)"),
        SplineKind::Cubic => (4, "at least 4 points (the first and last are control points)"),
        SplineKind::Bezier => (4, "4 points per segment"),
    };
    if n < least || (kind == SplineKind::Bezier && !n.is_multiple_of(4)) {
        return Err(format!("{} needs {rule}, found {n}", kind.keyword()));
    }
    Ok(match kind {
        SplineKind::Linear => points.windows(2).map(|w| Piece::line(w[0], w[1])).collect(),
        SplineKind::Quadratic => points.windows(3).map(|w| quadratic(w[0], w[1], w[2])).collect(),
        SplineKind::Cubic => points.windows(4).map(|w| cubic(w[0], w[1], w[2], w[3])).collect(),
        SplineKind::Bezier => points.chunks(4).map(|c| Piece::cubic_bezier([c[0], c[1], c[2], c[3]])).collect(),
    })
}

fn quadratic(prev: DVec2, a: DVec2, b: DVec2) -> Piece {
    let d = tangent(prev, b);
    Piece::quadratic_bezier(a, a + 0.5 * d, b)
}

fn cubic(prev: DVec2, a: DVec2, b: DVec2, next: DVec2) -> Piece {
    Piece::hermite(a, tangent(prev, b), b, tangent(a, next))
}

/// The pieces of a prism's closed sub-curves, in order; every sub-curve must close, except
/// that a linear spline's last one is closed by a line as POV-Ray does (with a warning: the
/// flag returned says so).
pub fn closed_pieces(kind: SplineKind, points: &[DVec2]) -> Result<(Vec<Piece>, bool), SplineError> {
    let n = points.len();
    let mut pieces = Vec::new();
    let mut start = 0;
    let mut curves = 0;
    // Points a sub-curve needs before it can close: first on-curve point, two more, the repeat.
    let (lead, trail, least) = match kind {
        SplineKind::Linear => (0, 0, 3),
        SplineKind::Quadratic => (1, 0, 4),
        SplineKind::Cubic => (1, 1, 5),
        SplineKind::Bezier => (0, 0, 4),
    };
    while start < n {
        let first = start + lead;
        let close = match kind {
            SplineKind::Bezier => (start..n).skip(3).step_by(4).find(|&i| points[i] == points[start]),
            _ => (first + 1..n).find(|&i| points[i] == points[first]),
        };
        let close = close.filter(|&c| c + trail < n);
        if close.is_none() && kind == SplineKind::Linear && n - start >= 3 {
            pieces.extend(points[start..].windows(2).map(|w| Piece::line(w[0], w[1])));
            pieces.push(Piece::line(points[n - 1], points[start]));
            return Ok((pieces, true));
        }
        let Some(close) = close else {
            return Err(format!(
                "{} sub-curve {} starting at point {} is not closed{}",
                kind.keyword(),
                curves + 1,
                start + 1,
                match kind {
                    SplineKind::Linear => " (repeat its first point)",
                    SplineKind::Quadratic => " (repeat its second point: the first is a control point)",
                    SplineKind::Cubic => {
                        " (repeat its second point, then one control point: the first and last are control points)"
                    }
                    SplineKind::Bezier => " (end a segment of 4 points on its first point)",
                }
            ));
        };
        let end = close + trail;
        if end + 1 - start < least {
            return Err(format!(
                "{} sub-curve {} starting at point {} has {} points; it needs at least {least}",
                kind.keyword(),
                curves + 1,
                start + 1,
                end + 1 - start
            ));
        }
        let sub = &points[start..=end];
        match kind {
            SplineKind::Linear => pieces.extend(sub.windows(2).map(|w| Piece::line(w[0], w[1]))),
            SplineKind::Quadratic => pieces.extend(sub.windows(3).map(|w| quadratic(w[0], w[1], w[2]))),
            SplineKind::Cubic => pieces.extend(sub.windows(4).map(|w| cubic(w[0], w[1], w[2], w[3]))),
            SplineKind::Bezier => pieces.extend(sub.chunks(4).map(|c| Piece::cubic_bezier([c[0], c[1], c[2], c[3]]))),
        }
        curves += 1;
        start = end + 1;
    }
    if pieces.is_empty() {
        return Err(format!("{} needs points", kind.keyword()));
    }
    Ok((pieces, false))
}

/// Even-odd: whether `q` lies inside the curves `pieces`, by the crossings of the ray from `q`
/// towards +u (prism sections, lathe outlines).
pub fn even_odd(pieces: &[Piece], q: DVec2) -> bool {
    even_odd_of(pieces, q)
}

/// `even_odd` over any collection of the curves' pieces that holds every piece spanning `q`'s
/// height (the others are passed over anyway; the parity does not depend on the order).
pub fn even_odd_of<'a>(pieces: impl IntoIterator<Item = &'a Piece>, q: DVec2) -> bool {
    let mut inside = false;
    for p in pieces {
        if q.y < p.lo.y || q.y > p.hi.y || q.x > p.hi.x {
            continue;
        }
        let (a, b) = (p.at(0.0), p.at(1.0));
        if q.x < p.lo.x {
            // Wholly to the right: the parity is whether the ends lie on opposite sides.
            inside ^= (a.y < q.y) != (b.y < q.y);
            continue;
        }
        let (c, n) = p.combine(0.0, 1.0, -q.y);
        let mut roots = [0.0; MAX_DEGREE];
        let k = roots_between(&c[..n], 0.0, 1.0, &mut roots);
        for &t in &roots[..k] {
            // Half-open in t, so a joint is counted once.
            if t < 1.0 && p.at(t).x > q.x {
                inside = !inside;
            }
        }
    }
    inside
}

/// For a part that runs one way in both coordinates (`Piece::monotone_parts`), the parameter
/// where its longer coordinate equals `w`'s, and how far the other coordinate is from `w`'s
/// there: for a point on the part that distance is its rounding, for a point off it at least
/// (about) the point's distance along that axis. One monotone equation of degree ≤ 3, by
/// Newton's steps kept in a shrinking bracket, instead of `closest_t`'s nearest-point
/// polynomial of degree `2·deg − 1` (a lathe's normal asks this of each part whose box holds
/// its point).
pub fn along_monotone(p: &Piece, w: DVec2) -> (f64, f64) {
    let ext = p.hi - p.lo;
    let (c, target, other, at_other) = if ext.y >= ext.x { (&p.v, w.y, &p.u, w.x) } else { (&p.u, w.x, &p.v, w.y) };
    let f = |t: f64| ((c[3] * t + c[2]) * t + c[1]) * t + c[0] - target;
    let df = |t: f64| (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1];
    let (f0, f1) = (f(0.0), f(1.0));
    let t = if f0 == f1 {
        0.5
    } else if (f0 <= 0.0) == (f1 <= 0.0) {
        // The coordinate is outside the part's range: the nearer end.
        if f0.abs() <= f1.abs() {
            0.0
        } else {
            1.0
        }
    } else {
        let rising = f0 < f1;
        let (mut a, mut b) = (0.0f64, 1.0f64);
        let mut t = f0 / (f0 - f1);
        for _ in 0..32 {
            let v = f(t);
            if v == 0.0 {
                break;
            }
            if (v < 0.0) == rising {
                a = t;
            } else {
                b = t;
            }
            let step = v / df(t);
            let next = t - step;
            let next = if next > a && next < b { next } else { 0.5 * (a + b) };
            let done = (next - t).abs() <= 1e-12 || b - a <= 1e-15;
            t = next;
            if done {
                break;
            }
        }
        t
    };
    let o = ((other[3] * t + other[2]) * t + other[1]) * t + other[0];
    (t, (o - at_other).abs())
}

/// The parameter in [0, 1] of the point of `p` nearest `w`.
pub fn closest_t(p: &Piece, w: DVec2) -> f64 {
    // (C(t) − w)·C'(t) = 0: degree 2·deg − 1.
    let deg = p.degree;
    let du = |k: usize| if k == 0 { p.u[0] - w.x } else { p.u[k] };
    let dv = |k: usize| if k == 0 { p.v[0] - w.y } else { p.v[k] };
    let mut prod = [0.0; 6]; // lowest power first
    for i in 0..=deg {
        for j in 1..=deg {
            prod[i + j - 1] += j as f64 * (du(i) * p.u[j] + dv(i) * p.v[j]);
        }
    }
    let n = 2 * deg; // coefficients: powers 0..2·deg − 1
    let mut c = [0.0; 6];
    for (i, slot) in c[..n].iter_mut().enumerate() {
        *slot = prod[n - 1 - i];
    }
    let mut roots = [0.0; MAX_DEGREE];
    let m = roots_between(&c[..n], 0.0, 1.0, &mut roots);
    let dist = |t: f64| (p.at(t) - w).length_squared();
    let mut best = if dist(0.0) <= dist(1.0) { 0.0 } else { 1.0 };
    for &t in &roots[..m] {
        if dist(t) < dist(best) {
            best = t;
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn pieces_pass_through_their_points_with_the_documented_tangents() {
        let pts = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(1.0, 0.0)];
        let (q, _) = closed_pieces(SplineKind::Quadratic, &pts).expect("closed");
        assert_eq!(q.len(), 3);
        assert_eq!(q[0].at(0.0), pts[1]);
        assert!((q[0].at(1.0) - pts[2]).length() < 1e-15);
        assert!((q[0].tangent(0.0) - 0.5 * (pts[2] - pts[0])).length() < 1e-15);
        // The bulge measured from povray: x = 1.1245 at z = 0.345 (t = 0.4695).
        assert!((q[0].at(0.4695).x - 1.1245).abs() < 1e-3);

        let cubic_pts = [p(3.0, -5.0), p(3.0, 5.0), p(-5.0, 0.0), p(3.0, -5.0), p(3.0, 5.0), p(-5.0, 0.0)];
        let (c, _) = closed_pieces(SplineKind::Cubic, &cubic_pts).expect("closed");
        assert_eq!(c.len(), 3);
        for (i, piece) in c.iter().enumerate() {
            assert!((piece.at(0.0) - cubic_pts[i + 1]).length() < 1e-12);
            assert!((piece.at(1.0) - cubic_pts[i + 2]).length() < 1e-12);
            assert!((piece.tangent(0.0) - 0.5 * (cubic_pts[i + 2] - cubic_pts[i])).length() < 1e-12);
        }
        // C1 across joints.
        assert!((c[0].tangent(1.0) - c[1].tangent(0.0)).length() < 1e-12);
    }

    #[test]
    fn sub_curves_close_where_the_documents_say() {
        let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 0.0)];
        let two: Vec<DVec2> = square.iter().chain(square.iter()).map(|q| *q * 2.0 + p(5.0, 0.0)).collect();
        assert_eq!(closed_pieces(SplineKind::Linear, &two).map(|v| v.0.len()), Ok(6));
        // An open linear outline is closed by a line (POV-Ray warns); two points are too few.
        assert_eq!(closed_pieces(SplineKind::Linear, &square[..3]).map(|v| (v.0.len(), v.1)), Ok((3, true)));
        let err = closed_pieces(SplineKind::Linear, &square[..2]).expect_err("open");
        assert!(err.contains("not closed"), "{err}");
        let err = closed_pieces(SplineKind::Quadratic, &square).expect_err("open");
        assert!(err.contains("repeat its second point"), "{err}");
        let bez =
            [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(0.0, 1.0), p(-1.0, 1.0), p(-1.0, 0.0), p(0.0, 0.0)];
        assert_eq!(closed_pieces(SplineKind::Bezier, &bez).map(|v| v.0.len()), Ok(2));
        let err = closed_pieces(SplineKind::Bezier, &bez[..6]).expect_err("open");
        assert!(err.contains("bezier_spline sub-curve 1"), "{err}");
        let err = open_pieces(SplineKind::Cubic, &square[..3]).expect_err("few");
        assert_eq!(err, "cubic_spline needs at least 4 points (the first and last are control points), found 3");
        assert_eq!(open_pieces(SplineKind::Quadratic, &square).map(|v| v.len()), Ok(2));
    }

    #[test]
    fn pieces_lie_inside_their_boxes_and_combine_evaluates_them() {
        let b = Piece::cubic_bezier([p(0.0, 0.0), p(2.0, 3.0), p(-1.0, 3.0), p(1.0, 0.0)]);
        for i in 0..=100 {
            let t = i as f64 / 100.0;
            let q = b.at(t);
            assert!(q.cmpge(b.lo - 1e-12).all() && q.cmple(b.hi + 1e-12).all(), "{q}");
            let (c, n) = b.combine(2.0, -1.0, 0.5);
            let e = c[..n].iter().fold(0.0, |acc, k| acc * t + k);
            assert!((e - (2.0 * q.x - q.y + 0.5)).abs() < 1e-12);
        }
        let line = Piece::line(p(1.0, 1.0), p(3.0, 2.0));
        assert_eq!(line.combine(1.0, 0.0, 0.0), ([2.0, 1.0, 0.0, 0.0], 2));
    }

    /// Seeded random lines, quadratics and cubics cut into monotone parts: a point on a part
    /// (at a random parameter, or an end) is found again by `along_monotone` on it, with an
    /// offset and a point within 10⁻⁷ of it (where the longer axis turns flat at a part's end,
    /// rounding moves the parameter by its square root); a point moved off the part by
    /// 10⁻³ across its longer axis reports an offset of at least (about) that.
    #[test]
    fn along_monotone_finds_points_on_monotone_parts() {
        let mut rand = crate::geometry::test_support::uniform(0x3c6e_f372_fe94_f82b);
        let mut checked = 0;
        for case in 0..3000 {
            let q = |r: &mut dyn FnMut() -> f64| p(r() * 2.0 - 1.0, r() * 2.0 - 1.0);
            let piece = match case % 3 {
                0 => Piece::line(q(&mut rand), q(&mut rand)),
                1 => Piece::quadratic_bezier(q(&mut rand), q(&mut rand), q(&mut rand)),
                _ => Piece::cubic_bezier([q(&mut rand), q(&mut rand), q(&mut rand), q(&mut rand)]),
            };
            for part in piece.monotone_parts() {
                let ext = part.hi - part.lo;
                if ext.max_element() < 1e-6 {
                    continue;
                }
                for k in 0..4 {
                    let t = [0.0, 1.0, rand(), rand()][k];
                    let w = part.at(t);
                    let (s, off) = along_monotone(&part, w);
                    assert!(off < 1e-7 && (part.at(s) - w).length() < 1e-7, "case {case}: {t} {s} {off}");
                    let across = if ext.y >= ext.x { p(1e-3, 0.0) } else { p(0.0, 1e-3) };
                    let (_, off) = along_monotone(&part, w + across);
                    assert!(off > 0.9e-3, "case {case}: {off}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 10_000, "{checked}");
    }
}
