//! Point questions on a prism's arcs (`Piece::monotone_parts`: each runs one way in `u` and in
//! `v`), answered without a polynomial root solve, since a cap test and a normal ask them for
//! every hit (a third of prism_cubic's and prism_bezier's frame went to `roots_between` there).
//!
//! - Even-odd crossing: an arc monotone in `v` meets the level `v = q.y` at most once, and
//!   whether the ends lie on either side of it says whether (half-open, so a joint counts once).
//!   Where that point lies against `q.x` follows from Newton's steps on `v(t) = q.y` inside a
//!   shrinking bracket: every part of the arc is monotone in `u` too, so its `u` lies between
//!   its ends' and the search stops as soon as `q.x` is outside that range (at once for a point
//!   far from the arc), or at the root.
//! - Nearest point: near the arc (as a hit point is) the nearest point is the one root of
//!   `(C(t) − w)·C'(t)` there, and Newton's steps from the chord's projection reach it in a few
//!   steps; the general solve (`closest_t`) stays as the fallback where a step cannot be taken.

use glam::DVec2;

use crate::geometry::spline::{closest_t, Piece};

/// The slab between the two lines parallel to an arc's chord that hold its control points
/// (convex hull), so the arc: a point outside lies at least its distance from the slab from the
/// arc. Where arcs' boxes overlap, as the parts of a bulging piece's do, a point on one arc lies
/// outside the others' slabs, so a normal solves only for the arc the point is on.
#[derive(Clone, Copy, Debug)]
pub struct Slab {
    /// The chord's unit normal (zero for a closed arc: no bound), and the least and greatest
    /// offset along it of the control points, widened as the arcs' boxes are.
    n: DVec2,
    lo: f64,
    hi: f64,
}

impl Slab {
    pub fn of(p: &Piece) -> Slab {
        let (a, b) = (DVec2::new(p.cu[0], p.cv[0]), DVec2::new(p.cu[p.degree], p.cv[p.degree]));
        let n = (b - a).perp().normalize_or_zero();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..=p.degree {
            let off = n.dot(DVec2::new(p.cu[i], p.cv[i]));
            (lo, hi) = (lo.min(off), hi.max(off));
        }
        let pad = 1e-9 * (p.hi - p.lo).max_element().max(p.lo.abs().max(p.hi.abs()).max_element());
        Slab { n, lo: lo - pad, hi: hi + pad }
    }

    /// How far `w` lies outside the slab (0 inside): no more than its distance from the arc.
    #[inline]
    pub fn gap(&self, w: DVec2) -> f64 {
        let off = self.n.dot(w);
        (off - self.hi).max(self.lo - off).max(0.0)
    }

    /// Whether the slab meets the box `[lo, hi]` (its corners' offsets along the normal reach
    /// the slab's).
    #[inline]
    pub fn meets_box(&self, lo: DVec2, hi: DVec2) -> bool {
        let offs = [lo, DVec2::new(hi.x, lo.y), DVec2::new(lo.x, hi.y), hi].map(|c| self.n.dot(c));
        let (min, max) = offs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &o| (a.min(o), b.max(o)));
        max >= self.lo && min <= self.hi
    }
}

/// Whether the ray from `q` towards +u crosses the monotone arc `p` (counted half-open in `v`,
/// as `spline::even_odd` counts a joint once): its ends lie on either side of `q.y` and the
/// arc's point at that height lies right of `q.x`.
#[inline]
pub fn crosses_right(p: &Piece, q: DVec2) -> bool {
    if q.y < p.lo.y || q.y > p.hi.y || q.x > p.hi.x {
        return false;
    }
    let (mut a, mut b) = (p.at(0.0), p.at(1.0));
    if (a.y < q.y) == (b.y < q.y) {
        return false;
    }
    if q.x < p.lo.x {
        return true;
    }
    if p.degree == 1 {
        // A line: the point at that height directly.
        let t = (q.y - a.y) / (b.y - a.y);
        return a.x + t * (b.x - a.x) > q.x;
    }
    // Newton's steps on v(t) = q.y from the chord's crossing, kept inside the bracket (halving
    // it where a step leaves it), until the bracket's ends decide or the root is found.
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let mut t = ((q.y - a.y) / (b.y - a.y)).clamp(0.0, 1.0);
    for _ in 0..60 {
        if q.x < a.x.min(b.x) {
            return true;
        }
        if q.x >= a.x.max(b.x) {
            return false;
        }
        if !(t > t0 && t < t1) {
            t = 0.5 * (t0 + t1);
            if !(t > t0 && t < t1) {
                break;
            }
        }
        let m = p.at(t);
        // Keep the part whose ends lie on either side of `q.y` (exactly one does).
        if (a.y < q.y) != (m.y < q.y) {
            (t1, b) = (t, m);
        } else {
            (t0, a) = (t, m);
        }
        let slope = (3.0 * p.v[3] * t + 2.0 * p.v[2]) * t + p.v[1];
        let step = (m.y - q.y) / slope;
        if step.abs() <= 1e-15 {
            return m.x > q.x;
        }
        t -= step;
    }
    0.5 * (a.x + b.x) > q.x
}

/// The parameter in `[0, 1]` of the point of the monotone arc `p` nearest `w`, for a `w` near
/// the arc (a surface point): Newton's steps on `(C(t) − w)·C'(t)` from the chord's projection,
/// kept in `[0, 1]`, the ends compared at the last; `closest_t` where a step cannot be taken
/// (the function not increasing: `w` far off on the concave side).
pub fn nearest_t(p: &Piece, w: DVec2) -> f64 {
    let (a, b) = (p.at(0.0), p.at(1.0));
    let chord = b - a;
    let len2 = chord.length_squared();
    let mut t = if len2 > 0.0 { ((w - a).dot(chord) / len2).clamp(0.0, 1.0) } else { 0.5 };
    if p.degree == 2 && len2 > 0.0 {
        t = chord_level_quadratic(p, w, chord).unwrap_or(t);
    }
    if p.degree > 1 {
        for _ in 0..16 {
            let (c, d1) = (p.at(t), p.tangent(t));
            let d2 = DVec2::new(6.0 * p.u[3] * t + 2.0 * p.u[2], 6.0 * p.v[3] * t + 2.0 * p.v[2]);
            let g = (c - w).dot(d1);
            let dg = d1.length_squared() + (c - w).dot(d2);
            if !(dg > 0.0) {
                return closest_t(p, w);
            }
            let next = (t - g / dg).clamp(0.0, 1.0);
            // A step this short leaves `next` within rounding of the root (Newton's error
            // squares; one more step, as the bound of 10⁻¹⁴ took, moved no normal).
            let done = (next - t).abs() <= 1e-8;
            t = next;
            if done {
                break;
            }
        }
    }
    let dist = |t: f64| (p.at(t) - w).length_squared();
    let mut best = t;
    for end in [0.0, 1.0] {
        if dist(end) < dist(best) {
            best = end;
        }
    }
    best
}

/// Where a quadratic arc meets the line through `w` across its chord: the root in `[0, 1]` of
/// `(C(t) − w)·chord`, which increases along the arc (it runs one way in `u` and in `v`, as the
/// chord does). For a `w` on the arc, as a surface point is to rounding, that is `w`'s own
/// parameter, so Newton's steps toward the nearest point start within rounding of it and stop
/// after two, where the chord's projection left four or five (prism_quadratic's normal was a
/// fifth of its frame). `None` where there is no such root (the caller's start stays).
fn chord_level_quadratic(p: &Piece, w: DVec2, chord: DVec2) -> Option<f64> {
    let a = p.u[2] * chord.x + p.v[2] * chord.y;
    let b = p.u[1] * chord.x + p.v[1] * chord.y;
    let k = (p.u[0] - w.x) * chord.x + (p.v[0] - w.y) * chord.y;
    let disc = b * b - 4.0 * a * k;
    if !(disc >= 0.0) {
        return None;
    }
    // The stable pair (no cancellation between −b and the root); the increasing branch's root
    // is the one inside, as the function increases there.
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let candidates = [if a != 0.0 { q / a } else { f64::NAN }, if q != 0.0 { k / q } else { f64::NAN }];
    candidates.into_iter().find(|t| (0.0..=1.0).contains(t))
}

#[cfg(test)]
pub mod tests {
    use super::*;
    use crate::desc::SplineKind;
    use crate::geometry::spline::{closed_pieces, even_odd};
    use crate::geometry::test_support::*;

    fn outlines() -> Vec<Vec<Piece>> {
        let q = |x: f64, z: f64| DVec2::new(x, z);
        let star = [q(0.45, 0.0), q(0.12, 0.12), q(0.0, 0.45), q(-0.12, 0.12), q(-0.45, 0.0), q(-0.12, -0.12)];
        let mut pts: Vec<DVec2> = star.into();
        pts.extend([q(0.0, -0.45), q(0.12, -0.12), q(0.45, 0.0)]);
        let quad: Vec<DVec2> = [q(0.12, -0.12)].into_iter().chain(pts.iter().copied()).collect();
        let cubic: Vec<DVec2> = quad.iter().copied().chain([q(0.12, 0.12)]).collect();
        let bez = [
            q(0.45, 0.0),
            q(0.45, 0.3),
            q(0.3, 0.45),
            q(0.0, 0.45),
            q(0.0, 0.45),
            q(-0.1, 0.1),
            q(-0.1, 0.1),
            q(-0.45, 0.0),
            q(-0.45, 0.0),
            q(-0.45, -0.3),
            q(-0.3, -0.45),
            q(0.0, -0.45),
            q(0.0, -0.45),
            q(0.1, -0.1),
            q(0.1, -0.1),
            q(0.45, 0.0),
        ];
        vec![
            star_with_hole(),
            closed_pieces(SplineKind::Quadratic, &quad).expect("quadratic").0,
            closed_pieces(SplineKind::Cubic, &cubic).expect("cubic").0,
            closed_pieces(SplineKind::Bezier, &bez).expect("bezier").0,
        ]
    }

    /// Every fourth point within 10⁻⁶ of the curve `pieces`, the others in [−0.5, 0.5]².
    pub fn sample_point(rand: &mut impl FnMut() -> f64, pieces: &[Piece], i: usize) -> DVec2 {
        if i % 4 == 0 {
            let p = &pieces[(rand() * pieces.len() as f64) as usize];
            p.at(rand()) + 1e-6 * DVec2::new(rand() - 0.5, rand() - 0.5)
        } else {
            DVec2::new(rand() - 0.5, rand() - 0.5)
        }
    }

    /// Over seeded random points (some within 10⁻⁶ of the curve) the arcs' crossings give the
    /// pieces' even-odd answer.
    #[test]
    fn crossings_of_arcs_give_even_odd_of_pieces() {
        let mut rand = uniform(0x1234_5678_9abc_def1u64);
        for pieces in outlines() {
            let arcs: Vec<Piece> = pieces.iter().flat_map(Piece::monotone_parts).collect();
            let mut inside = 0;
            for i in 0..20_000 {
                let w = sample_point(&mut rand, &pieces, i);
                let want = even_odd(&pieces, w);
                let got = arcs.iter().filter(|a| crosses_right(a, w)).count() % 2 == 1;
                assert_eq!(got, want, "{w}");
                inside += want as usize;
            }
            assert!(inside > 2000, "{inside}");
        }
    }

    /// Seeded random points: the slab's gap is never more than the distance to the arc.
    #[test]
    fn slab_gaps_bound_the_distance() {
        let mut rand = uniform(0x3c6e_f372_fe94_f82bu64);
        for pieces in outlines() {
            for arc in pieces.iter().flat_map(Piece::monotone_parts) {
                let slab = Slab::of(&arc);
                for _ in 0..500 {
                    let w = DVec2::new(rand() - 0.5, rand() - 0.5);
                    let dist = (arc.at(closest_t(&arc, w)) - w).length();
                    assert!(slab.gap(w) <= dist + 1e-15, "{w}");
                }
            }
        }
    }

    /// Points near the arcs: the nearest point agrees with the general solve's to 10⁻¹⁰.
    #[test]
    fn nearest_points_agree_with_the_general_solve() {
        let mut rand = uniform(0x0fed_cba9_8765_4321u64);
        for pieces in outlines() {
            for arc in pieces.iter().flat_map(Piece::monotone_parts) {
                for _ in 0..200 {
                    let t = rand();
                    let n = arc.tangent(t).perp().normalize_or_zero();
                    let w = arc.at(t) + (rand() - 0.5) * 1e-3 * n;
                    let (got, want) = (nearest_t(&arc, w), closest_t(&arc, w));
                    let (dg, dw) = ((arc.at(got) - w).length(), (arc.at(want) - w).length());
                    assert!(dg <= dw + 1e-12, "{t}: {got} against {want}");
                    assert!((arc.at(got) - arc.at(want)).length() < 1e-10, "{t}: {got} against {want}");
                }
            }
        }
    }
}
