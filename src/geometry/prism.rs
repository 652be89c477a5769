//! POV-Ray's `prism` (3.4.6.x Prism): closed 2-D curves in the xz-plane (pieces from
//! `spline`), swept along y from `h1` to `h2` (`linear_sweep`), or scaled by y towards the
//! origin (`conic_sweep`: the point (x, y, z) lies on the sweep of (x/y, z/y)). Inside is even-odd
//! over all sub-curves, so where an even number overlap there is a hole; the caps are the
//! inside at `h1` and `h2`, left off when `open`. TrueType glyphs (`text`) are prisms too.
//!
//! A side is solved per piece: its points satisfy one polynomial in the piece's parameter `t`
//! (degree 1 to 3), solved by `bernstein` in f64 per lane, as the torus is (no 8-wide arithmetic).
//! Pieces are skipped without solving when the ray's footprint misses the box of their control
//! points, or its line (in the plane of the curve) passes them all on one side: they hold the
//! piece. `sturm` changes nothing: the roots are isolated robustly already (`bernstein`).
//!
//! Object space is the prism as written, moved to its centre and scaled to unit size in f64
//! (only scaled for `conic_sweep`, whose apex is the origin), so a prism written at 1e6 or
//! 1e-4 keeps its digits before the frame becomes f32.

use glam::{DAffine3, DVec2, DVec3, Vec3};

mod arc;
mod cells;
mod diamond;
mod normal;
mod outward;
mod sides;

use super::bands::Bands;
use super::cuboid::{frame_for, BoxFrame};
use super::spline::Piece;
use super::{affine_f32, transformed_bounds, CullBox, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

/// The faces `hit_faces` names for the caps at `h1` and `h2` (a side's face is its arc's index).
pub const FACE_H1: u32 = u32::MAX - 2;
pub const FACE_H2: u32 = u32::MAX - 1;

#[derive(Clone, Debug)]
pub struct Prism {
    pub frame: BoxFrame,
    /// The pieces cut where they turn in u or v (`Piece::monotone_parts`), each with the box of
    /// its ends: what the sides are solved on, as fewer rays reach those boxes and hulls.
    arcs: Vec<Piece>,
    /// Each arc's slab along its chord (`arc::Slab`): with its box, how near a point it can be.
    slabs: Vec<arc::Slab>,
    /// The arcs by height, for the even-odd test of caps and `inside` (`arc::crosses_right`)
    /// where `cells` leaves it open.
    bands: Bands,
    /// The section's grid: inside or outside for most points, and the arcs near them.
    cells: cells::Cells,
    /// Each arc's outward side where it is settled (`outward`), for the normal.
    outward: Vec<u8>,
    /// The straight arcs apart (`sides::Line`) with each one's index in `arcs`, and the curved
    /// ones' boxes (`sides::Curve`).
    lines: Vec<sides::Line>,
    line_arcs: Vec<u32>,
    curves: Vec<sides::Curve>,
    /// Heights in object space, `h1 < h2`.
    h1: f64,
    h2: f64,
    conic: bool,
    open: bool,
    /// The pieces as moved, for the tests' brute force.
    #[cfg(test)]
    pieces: Vec<Piece>,
    pub min: Vec3,
    pub max: Vec3,
    /// The object-space box eight lanes are tested against first, so that only lanes whose ray
    /// crosses it are solved in f64 (`hit`).
    cull: CullBox,
    /// The turned box a linear sweep's lanes are tested against next (`diamond`).
    diamond: Option<diamond::Diamond>,
}

impl Prism {
    /// The prism of `pieces` (xz-plane, as written) between heights `h1` and `h2` under
    /// `render_from_object` (composed in f64).
    pub fn new(render_from_object: DAffine3, pieces: &[Piece], h1: f64, h2: f64, conic: bool, open: bool) -> Prism {
        let (h1, h2) = (h1.min(h2), h1.max(h2));
        let lo = pieces.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(p.lo));
        let hi = pieces.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(p.hi));
        let (local, pieces, h1, h2) = if conic {
            // Uniform scale keeps x/y and z/y: the curves stay as written, the heights scale.
            let s = h1.abs().max(h2.abs()) * (1.0 + lo.abs().max(hi.abs()).max_element());
            let s = if s > 0.0 && s.is_finite() { s } else { 1.0 };
            (DAffine3::from_scale(DVec3::splat(s)), pieces.to_vec(), h1 / s, h2 / s)
        } else {
            let c = 0.5 * (lo + hi);
            let cy = 0.5 * (h1 + h2);
            let s = 0.5 * (hi - lo).max_element().max(h2 - h1);
            let s = if s > 0.0 && s.is_finite() { s } else { 1.0 };
            let local = DAffine3::from_translation(DVec3::new(c.x, cy, c.y)) * DAffine3::from_scale(DVec3::splat(s));
            let moved = pieces.iter().map(|p| p.map(|q| (q - c) / s)).collect();
            (local, moved, (h1 - cy) / s, (h2 - cy) / s)
        };
        let xf = affine_f32(&(render_from_object * local));
        let lo = pieces.iter().fold(DVec2::splat(f64::INFINITY), |m, p| m.min(p.lo));
        let hi = pieces.iter().fold(DVec2::splat(f64::NEG_INFINITY), |m, p| m.max(p.hi));
        let (blo, bhi) = if conic {
            // The curves scaled by each end height (and by 0 where the apex lies between).
            let mut b = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
            for h in [h1, h2] {
                for q in [lo * h, hi * h] {
                    b = (b.0.min(DVec3::new(q.x, h, q.y)), b.1.max(DVec3::new(q.x, h, q.y)));
                }
            }
            b
        } else {
            (DVec3::new(lo.x, h1, lo.y), DVec3::new(hi.x, h2, hi.y))
        };
        let (min, max) = transformed_bounds(&xf, blo.as_vec3(), bhi.as_vec3());
        let cull = CullBox::new(blo, bhi);
        // Widened by a few f32 ulps: the box's corners were rounded.
        let pad = (max - min).max(min.abs().max(max.abs())) * 4.0 * f32::EPSILON;
        let arcs: Vec<Piece> = pieces.iter().flat_map(Piece::monotone_parts).collect();
        let bands = Bands::new(&arcs);
        let slabs: Vec<arc::Slab> = arcs.iter().map(arc::Slab::of).collect();
        let cells = cells::Cells::new(&arcs, &slabs, |q| Self::crossings(&bands, &arcs, q));
        let outward = outward::sides(&arcs, cells.lists(), |q| Self::crossings(&bands, &arcs, q));
        let (lines, line_arcs) = sides::Line::all(&arcs);
        Prism {
            frame: frame_for(xf),
            lines,
            line_arcs,
            diamond: (!conic).then(|| diamond::Diamond::new(&arcs, h1, h2)),
            curves: sides::Curve::all(&arcs),
            bands,
            cells,
            outward,
            slabs,
            arcs,
            #[cfg(test)]
            pieces,
            h1,
            h2,
            conic,
            open,
            min: min - pad,
            max: max + pad,
            cull,
        }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// The 2-D point whose sweep holds `q` (object space): (x, z), or (x/y, z/y) for a cone.
    fn section(&self, q: DVec3) -> DVec2 {
        if self.conic {
            DVec2::new(q.x / q.y, q.z / q.y)
        } else {
            DVec2::new(q.x, q.z)
        }
    }

    /// Whether the section point `q` lies inside: its cell's answer, or even-odd over the arcs.
    #[inline]
    fn inside_2d(&self, q: DVec2) -> bool {
        match self.cells.inside(q) {
            Some(inside) => inside,
            None => Self::crossings(&self.bands, &self.arcs, q),
        }
    }

    /// Even-odd over the arcs `bands` lists for `q`.
    fn crossings(bands: &Bands, arcs: &[Piece], q: DVec2) -> bool {
        let mut inside = false;
        for &i in bands.candidates(q) {
            inside ^= arc::crosses_right(&arcs[i as usize], q);
        }
        inside
    }

    fn inside_point(&self, q: DVec3) -> bool {
        if !(q.y >= self.h1 && q.y <= self.h2) || (self.conic && q.y == 0.0) {
            return false;
        }
        self.inside_2d(self.section(q))
    }

    /// The nearest `s` in `(s_min, s_max)` where `o + s·d` (object space) meets the prism.
    #[cfg(test)]
    fn solve(&self, o: DVec3, d: DVec3, s_min: f64, s_max: f64) -> Option<f64> {
        self.solve_face(o, d, s_min, s_max).map(|(s, _)| s)
    }

    /// `solve`, and the face that `s` lies on: the arc's index in `arcs` for a side,
    /// `FACE_H1` or `FACE_H2` for a cap.
    fn solve_face(&self, o: DVec3, d: DVec3, s_min: f64, s_max: f64) -> Option<(f64, u32)> {
        // An empty interval (a lane `hit` dropped) has nothing in it.
        if s_min.is_nan() || s_max.is_nan() || s_min >= s_max {
            return None;
        }
        // The span of s inside the height slab.
        let (mut lo, mut hi) = (s_min, s_max);
        // The caps where the ray enters and leaves the slab: (s, height).
        let (mut near, mut far) = (None, None);
        if d.y != 0.0 {
            let (a, b) = ((self.h1 - o.y) / d.y, (self.h2 - o.y) / d.y);
            (near, far) = if a <= b {
                (Some((a, self.h1)), Some((b, self.h2)))
            } else {
                (Some((b, self.h2)), Some((a, self.h1)))
            };
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        } else if !(o.y >= self.h1 && o.y <= self.h2) {
            return None;
        }
        // A cap is the inside at its height. The entering one, when hit, is nearer than any side
        // (those lie past it in the slab); the leaving one only counts when no side is nearer.
        let cap = |(s, h): (f64, f64)| {
            let hit = !self.open && s > s_min && s < s_max && !(self.conic && h == 0.0) && {
                let q = o + s * d;
                self.inside_2d(self.section(DVec3::new(q.x, h, q.z)))
            };
            hit.then_some((s, if h == self.h1 { FACE_H1 } else { FACE_H2 }))
        };
        if let Some(s) = near.and_then(cap) {
            return Some(s);
        }
        let far_cap = || far.and_then(cap);
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return far_cap();
        }
        // The side: (a, b, k) with a·u + b·v + k = 0 on the ray's plane through the sweep axis
        // direction (linear: the vertical plane of the ray; conic: the plane of ray and apex).
        let (a, b, k) = if self.conic {
            (o.z * d.y - o.y * d.z, o.y * d.x - o.x * d.y, o.x * d.z - o.z * d.x)
        } else {
            (d.z, -d.x, o.z * d.x - o.x * d.z)
        };
        if a == 0.0 && b == 0.0 {
            return far_cap();
        }
        // A linear sweep's ray covers only this box of the section over the height slab: a piece
        // whose control points' box it misses has no crossing there (infinite or NaN spans, a
        // level ray's, compare false and skip nothing). (Clipping it to the section's box too
        // cost prism_linear 4 % more instructions than it saved.)
        let (f_lo, f_hi) = if self.conic {
            (DVec2::NEG_INFINITY, DVec2::INFINITY)
        } else {
            let (x0, x1, z0, z1) = (o.x + lo * d.x, o.x + hi * d.x, o.z + lo * d.z, o.z + hi * d.z);
            let pad = 1e-9 * (x0.abs() + x1.abs() + z0.abs() + z1.abs());
            (DVec2::new(x0.min(x1) - pad, z0.min(z1) - pad), DVec2::new(x0.max(x1) + pad, z0.max(z1) + pad))
        };
        // Lines first, then the curves nearest first: the nearest crossing is the least whatever
        // the order, so the bits are the same as in one pass.
        let ray = sides::SideRay { o, d, plane: (a, b, k), f_lo, f_hi, dd: d.x * d.x + d.z * d.z, lo };
        let mut near = sides::Nearest { s: hi, arc: 0 };
        self.cross_lines(&ray, &mut near);
        if !self.curves.is_empty() {
            self.cross_curves(&ray, &mut near);
        }
        if near.s < hi {
            Some((near.s, near.arc))
        } else {
            far_cap()
        }
    }

    /// `Shape::hit` and each lane's face (`solve_face`; `u32::MAX` where it missed), which
    /// `normal_on` takes instead of searching the arcs for the nearest again.
    #[inline(always)]
    pub fn hit_faces<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, [u32; 8]) {
        let mut faces = [u32::MAX; 8];
        // Most lanes of a packet that reaches a prism miss its box: all lanes at once first.
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        let Some(t_max) = self.cull.live(o, d, t_min, t_max) else { return (L::splat(MISS), faces) };
        let t_max = match &self.diamond {
            Some(diamond) => match diamond.live(o, d, t_min, t_max) {
                Some(t_max) => t_max,
                None => return (L::splat(MISS), faces),
            },
            None => t_max,
        };
        // The object-space ray as `hit_lanes_f64` would transform it again.
        let solve = |_, o, d, lo, hi| self.solve_face(o, d, lo, hi);
        let t = L::from_fn_f64(|i| {
            let (t, face) = super::solve_lane_tagged_f64(i, o, d, t_min, t_max, &solve);
            faces[i] = face.unwrap_or(u32::MAX);
            t
        });
        (t, faces)
    }

    /// `Shape::normal` at points on face `face` (`hit_faces`): that arc's normal or that cap's,
    /// with no search for the nearest (a fifth of a prism frame went to it); the search where
    /// the face is not known (`u32::MAX`).
    pub fn normal_on<L: Lane>(&self, face: u32, p: V3<L>) -> V3<L> {
        super::normal_lanes_f64(&self.frame, p, |q| self.normal_face(face, q))
    }
}

impl Shape for Prism {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.hit_faces(ray, t_min, t_max).0
    }

    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        super::normal_lanes_f64(&self.frame, p, |q| self.normal_object(q))
    }

    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        super::inside_lanes_f64(&self.frame, p, |q| self.inside_point(q))
    }
}

#[cfg(test)]
mod tests;
