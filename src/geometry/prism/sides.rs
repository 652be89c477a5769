//! The prism's sides: where the ray's plane through the sweep axis (`a·u + b·v + k = 0` in
//! the section) crosses each arc, and which crossing is the nearest along the ray.
//!
//! Straight arcs (all of a `linear_spline` prism's, most of a glyph's) are kept apart in a
//! compact list (`Line`): their crossing is one division, and a loop over 80-byte records with
//! no degree dispatch and no queue costs a fraction of the general one (prism_linear: the
//! side loop was a third of the frame). Curved arcs are bounded along the ray and solved
//! nearest first.
//!
//! Both lists are sorted by their boxes' least `u`, so a footprint test stops at the first box
//! that starts past the footprint (a standing glyph's footprints are narrow in `u`: its box
//! loop was a third of its `solve`, most of it mispredicted jumps). The nearest crossing is the
//! least whatever the order, so the bits are those of the arcs' own order.

use glam::{DVec2, DVec3};

use super::Prism;
use crate::geometry::bernstein::{roots_between, roots_unit};
use crate::geometry::halley::{cubic_roots_by_halves, single_change, single_root};
use crate::geometry::roots::MAX_DEGREE;
use crate::geometry::spline::Piece;

/// A straight arc: its box, its ends (the Bézier control points, where `a·u + b·v + k` is
/// evaluated as for any piece) and its power coefficient `u[1], v[1]`, so its point at `t` is
/// computed as `Piece::at` computes it (`u[1]·t + u[0]`, the higher powers being zero).
/// (Four lines to a record, tested without branches, cost prism_linear 17 % more instructions.)
#[derive(Clone, Copy, Debug)]
pub struct Line {
    lo: DVec2,
    hi: DVec2,
    c0: DVec2,
    c1: DVec2,
    step: DVec2,
}

impl Line {
    /// The lines of the straight arcs of `arcs`, by their boxes' least `u`, and each one's
    /// index in `arcs` (apart, so a record stays 80 bytes: it is read only for a crossing taken).
    pub fn all(arcs: &[Piece]) -> (Vec<Line>, Vec<u32>) {
        let mut lines: Vec<(Line, u32)> =
            (arcs.iter().enumerate()).filter(|(_, p)| p.degree == 1).map(|(i, p)| (Line::of(p), i as u32)).collect();
        lines.sort_by(|a, b| a.0.lo.x.total_cmp(&b.0.lo.x));
        lines.into_iter().unzip()
    }

    /// The line of a degree-1 piece.
    fn of(p: &Piece) -> Line {
        Line {
            lo: p.lo,
            hi: p.hi,
            c0: DVec2::new(p.cu[0], p.cv[0]),
            c1: DVec2::new(p.cu[1], p.cv[1]),
            step: DVec2::new(p.u[1], p.v[1]),
        }
    }
}

/// A curved arc's box, its control points and its index in `Prism::arcs`: what the footprint,
/// hull and projection tests read, 104 bytes a curve. The control points are padded to four
/// with copies of the last, so those tests run over four values without a loop over the degree
/// (its bounds and the zeroed array of `Piece::combine_bernstein` were a third of the curve
/// loop), and a copy changes no minimum, maximum or sign.
#[derive(Clone, Copy, Debug)]
pub struct Curve {
    lo: DVec2,
    hi: DVec2,
    cu: [f64; 4],
    cv: [f64; 4],
    index: u32,
}

impl Curve {
    /// The curved arcs of `arcs`, by their boxes' least `u`.
    pub fn all(arcs: &[Piece]) -> Vec<Curve> {
        let mut curves: Vec<Curve> = (arcs.iter().enumerate())
            .filter(|(_, p)| p.degree > 1)
            .map(|(i, p)| {
                let pad = |c: &[f64; 4]| std::array::from_fn(|k| c[k.min(p.degree)]);
                Curve { lo: p.lo, hi: p.hi, cu: pad(&p.cu), cv: pad(&p.cv), index: i as u32 }
            })
            .collect();
        curves.sort_by(|a, b| a.lo.x.total_cmp(&b.lo.x));
        curves
    }

    /// `a·cu[i] + b·cv[i] + k` at the four control points: the arc's Bernstein coefficients
    /// of the plane's polynomial (the last repeated), as `Piece::combine_bernstein` forms them.
    #[inline(always)]
    fn hull(&self, a: f64, b: f64, k: f64) -> [f64; 4] {
        let mut h = [0.0; 4];
        for i in 0..4 {
            h[i] = a * self.cu[i] + b * self.cv[i] + k;
        }
        h
    }
}

/// A ray `o + s·d` (object space) as the sides see it: its plane through the sweep axis,
/// `a·u + b·v + k = 0` in the section (linear: the vertical plane of the ray; conic: the plane
/// of ray and apex), the box of the section it covers over the height slab (infinite for a
/// cone), `dd = d.x² + d.z²`, and the least `s` a crossing may have.
pub struct SideRay {
    pub o: DVec3,
    pub d: DVec3,
    pub plane: (f64, f64, f64),
    pub f_lo: DVec2,
    pub f_hi: DVec2,
    pub dd: f64,
    pub lo: f64,
}

/// The nearest crossing found so far: its `s` (the interval's upper end until one is found)
/// and the index in `Prism::arcs` of the arc it lies on, which the hit hands on to the normal.
pub struct Nearest {
    pub s: f64,
    pub arc: u32,
}

impl Prism {
    /// Lowers `near` to the nearest crossing in `(r.lo, near.s)` of the straight sides, skipping
    /// those whose box the ray's footprint misses (an infinite footprint, a cone's, skips none)
    /// and those the plane passes on one side.
    #[inline]
    pub(super) fn cross_lines(&self, r: &SideRay, near: &mut Nearest) {
        let ((a, b, k), f_lo, f_hi) = (r.plane, r.f_lo, r.f_hi);
        for (j, l) in self.lines.iter().enumerate() {
            // Sorted by `lo.x`: the rest start past the footprint too.
            if l.lo.x > f_hi.x {
                break;
            }
            if f_lo.x > l.hi.x || f_lo.y > l.hi.y || f_hi.y < l.lo.y {
                continue;
            }
            // The Bernstein coefficients of the line's `a·u + b·v + k`: its end values.
            let (e0, e1) = (a * l.c0.x + b * l.c0.y + k, a * l.c1.x + b * l.c1.y + k);
            if (e0 > 0.0 && e1 > 0.0) || (e0 < 0.0 && e1 < 0.0) {
                continue;
            }
            // Where the end values' interpolation is zero (no root for a line on the plane
            // itself, 0/0).
            let t = e0 / (e0 - e1);
            if (0.0..=1.0).contains(&t) {
                let w = DVec2::new(l.step.x * t + l.c0.x, l.step.y * t + l.c0.y);
                if self.take(w, r, &mut near.s) {
                    near.arc = self.line_arcs[j];
                }
            }
        }
    }

    /// `cross_lines` for the curved arcs. A linear sweep's crossing with an arc lies between its
    /// control points' projections on the ray's direction in the section (convex hull), scaled
    /// by `dd`: an arc wholly before `lo` needs no solve, and the arcs are solved nearest first,
    /// until the next starts past the nearest crossing found.
    pub(super) fn cross_curves(&self, r: &SideRay, near: &mut Nearest) {
        let (o, d, (a, b, k), f_lo, f_hi, dd, lo) = (r.o, r.d, r.plane, r.f_lo, r.f_hi, r.dd, r.lo);
        let mut queue = [(0.0, 0u32); 16];
        let mut queued = 0;
        for (j, c) in self.curves.iter().enumerate() {
            if c.lo.x > f_hi.x {
                break;
            }
            if f_lo.x > c.hi.x || f_lo.y > c.hi.y || f_hi.y < c.lo.y {
                continue;
            }
            // The plane misses the arc's control points (all on one side): it misses the arc
            // (convex hull). These are the Bernstein coefficients of the arc's polynomial.
            let h = c.hull(a, b, k);
            let (h_lo, h_hi) = (h[0].min(h[1]).min(h[2].min(h[3])), h[0].max(h[1]).max(h[2].max(h[3])));
            if h_lo > 0.0 || h_hi < 0.0 {
                continue;
            }
            if self.conic {
                self.cross(c, r, near);
                continue;
            }
            let (mut q_lo, mut q_hi, mut size) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64);
            for j in 0..4 {
                let (du, dv) = (c.cu[j] - o.x, c.cv[j] - o.z);
                let q = du * d.x + dv * d.z;
                (q_lo, q_hi) = (q_lo.min(q), q_hi.max(q));
                size = size.max(du.abs() * d.x.abs() + dv.abs() * d.z.abs());
            }
            // Padded far above the rounding of `q` and of the root's point.
            let pad = 1e-9 * size;
            if q_hi + pad < lo * dd || q_lo - pad > near.s * dd {
                continue;
            }
            if queued == queue.len() {
                self.cross(c, r, near);
            } else {
                queue[queued] = (q_lo - pad, j as u32);
                queued += 1;
            }
        }
        let queue = &mut queue[..queued];
        queue.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        for &(start, j) in queue.iter() {
            if start > near.s * dd {
                break;
            }
            self.cross(&self.curves[j as usize], r, near);
        }
    }

    /// Lowers `near` to the nearest crossing in `(lo, near.s)` of the side over curved arc `curve` by
    /// the ray `o + s·d`, whose plane through the sweep axis is `a·u + b·v + k = 0` in the
    /// section (`dd = d.x² + d.z²`, for a linear sweep).
    fn cross(&self, curve: &Curve, r: &SideRay, near: &mut Nearest) {
        let (a, b, k) = r.plane;
        let p = &self.arcs[curve.index as usize];
        let mut roots = [0.0; MAX_DEGREE];
        let (c, n) = p.combine(a, b, k);
        // Lines are `cross_lines`'s.
        let m = match p.degree {
            2 => roots_between(&c[..n], 0.0, 1.0, &mut roots),
            // A cubic whose hull crosses the line once: its one root, by Halley's steps; else on
            // each half where that holds there.
            _ => {
                let bz = curve.hull(a, b, k);
                match single_change(&bz) {
                    Some(i) => {
                        roots[0] = single_root(&c, &bz, i);
                        1
                    }
                    None => match cubic_roots_by_halves(&bz, &mut roots) {
                        Some(m) => m,
                        None => roots_unit(&c[..n], p.combine_bernstein(a, b, k), &mut roots),
                    },
                }
            }
        };
        for &t in &roots[..m] {
            if self.take(p.at(t), r, &mut near.s) {
                near.arc = curve.index;
            }
        }
    }

    /// Lowers `hi` to the ray's `s` at the side's point over `w` (a crossing of the ray's plane
    /// with an arc) where it lies in `(lo, hi)` and within the heights; whether it did.
    #[inline]
    fn take(&self, w: DVec2, r: &SideRay, hi: &mut f64) -> bool {
        let (o, d) = (r.o, r.d);
        let s = if self.conic {
            // o + s·d = y·(u, 1, v) for the y it reaches: s from the better-conditioned axis.
            let (nx, dx) = (w.x * o.y - o.x, d.x - w.x * d.y);
            let (nz, dz) = (w.y * o.y - o.z, d.z - w.y * d.y);
            if dx.abs() >= dz.abs() {
                nx / dx
            } else {
                nz / dz
            }
        } else {
            ((w.x - o.x) * d.x + (w.y - o.z) * d.z) / r.dd
        };
        if s > r.lo && s < *hi {
            let y = o.y + s * d.y;
            if y >= self.h1 && y <= self.h2 {
                *hi = s;
                return true;
            }
        }
        false
    }
}
