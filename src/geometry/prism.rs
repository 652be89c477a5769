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

use super::bands::Bands;
use super::bernstein::{roots_between, roots_unit};
use super::cuboid::{frame_for, BoxFrame};
use super::halley::{cubic_roots_by_halves, single_change, single_root};
use super::roots::MAX_DEGREE;
use super::spline::Piece;
use super::{affine_f32, transformed_bounds, CullBox, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Debug)]
pub struct Prism {
    pub frame: BoxFrame,
    /// The pieces cut where they turn in u or v (`Piece::monotone_parts`), each with the box of
    /// its ends: what the sides are solved on, as fewer rays reach those boxes and hulls.
    arcs: Vec<Piece>,
    /// Each arc's slab along its chord (`arc::Slab`): with its box, how near a point it can be.
    slabs: Vec<arc::Slab>,
    /// The arcs by height, for the even-odd test of caps and `inside` (`arc::crosses_right`).
    bands: Bands,
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
        Prism {
            frame: frame_for(xf),
            bands: Bands::new(&arcs),
            slabs: arcs.iter().map(arc::Slab::of).collect(),
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

    fn inside_2d(&self, q: DVec2) -> bool {
        let mut inside = false;
        for &i in self.bands.candidates(q) {
            inside ^= arc::crosses_right(&self.arcs[i as usize], q);
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
    fn solve(&self, o: DVec3, d: DVec3, s_min: f64, s_max: f64) -> Option<f64> {
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
            hit.then_some(s)
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
        // level ray's, compare false and skip nothing).
        let footprint = (!self.conic).then(|| {
            let (x0, x1, z0, z1) = (o.x + lo * d.x, o.x + hi * d.x, o.z + lo * d.z, o.z + hi * d.z);
            let pad = 1e-9 * (x0.abs() + x1.abs() + z0.abs() + z1.abs());
            (DVec2::new(x0.min(x1) - pad, z0.min(z1) - pad), DVec2::new(x0.max(x1) + pad, z0.max(z1) + pad))
        });
        // A linear sweep's crossing with a piece lies between its control points' projections
        // on the ray's direction in the section (convex hull), scaled by `dd`: a piece wholly
        // before `lo` needs no solve, and the pieces are solved nearest first, until the next
        // starts past the nearest crossing found.
        let dd = d.x * d.x + d.z * d.z;
        let slab_hi = hi;
        let mut queue = [(0.0, 0u32); 16];
        let mut queued = 0;
        for (i, p) in self.arcs.iter().enumerate() {
            if let Some((f_lo, f_hi)) = footprint {
                if f_lo.x > p.hi.x || f_hi.x < p.lo.x || f_lo.y > p.hi.y || f_hi.y < p.lo.y {
                    continue;
                }
            }
            // The line misses the piece's control points (all on one side): it misses the piece
            // (convex hull). These are the Bernstein coefficients of the piece's polynomial.
            let hull = p.combine_bernstein(a, b, k);
            let hull = &hull[..=p.degree];
            if hull.iter().all(|&c| c > 0.0) || hull.iter().all(|&c| c < 0.0) {
                continue;
            }
            // A line's crossing costs less than bounding it along the ray and queueing it; the
            // nearest crossing is the least whatever the order, so the bits are the same.
            if self.conic || p.degree == 1 {
                self.cross(p, o, d, (a, b, k), dd, lo, &mut hi);
                continue;
            }
            let (mut q_lo, mut q_hi, mut size) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64);
            for i in 0..=p.degree {
                let (du, dv) = (p.cu[i] - o.x, p.cv[i] - o.z);
                let q = du * d.x + dv * d.z;
                (q_lo, q_hi) = (q_lo.min(q), q_hi.max(q));
                size = size.max(du.abs() * d.x.abs() + dv.abs() * d.z.abs());
            }
            // Padded far above the rounding of `q` and of the root's point.
            let pad = 1e-9 * size;
            if q_hi + pad < lo * dd || q_lo - pad > hi * dd {
                continue;
            }
            if queued == queue.len() {
                self.cross(p, o, d, (a, b, k), dd, lo, &mut hi);
            } else {
                queue[queued] = (q_lo - pad, i as u32);
                queued += 1;
            }
        }
        let queue = &mut queue[..queued];
        queue.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        for &(start, i) in queue.iter() {
            if start > hi * dd {
                break;
            }
            self.cross(&self.arcs[i as usize], o, d, (a, b, k), dd, lo, &mut hi);
        }
        if hi < slab_hi {
            Some(hi)
        } else {
            far_cap()
        }
    }

    /// Lowers `hi` to the nearest crossing in `(lo, hi)` of the side over piece `p` by the ray
    /// `o + s·d`, whose plane through the sweep axis is `a·u + b·v + k = 0` in the section
    /// (`dd = d.x² + d.z²`, for a linear sweep).
    #[allow(clippy::too_many_arguments)]
    fn cross(&self, p: &Piece, o: DVec3, d: DVec3, (a, b, k): (f64, f64, f64), dd: f64, lo: f64, hi: &mut f64) {
        let hull = p.combine_bernstein(a, b, k);
        let mut roots = [0.0; MAX_DEGREE];
        let m = match p.degree {
            // A line: where its end values' interpolation is zero (no root for a piece on the
            // line itself, 0/0).
            1 => {
                let t = hull[0] / (hull[0] - hull[1]);
                roots[0] = t;
                (0.0..=1.0).contains(&t) as usize
            }
            2 => {
                let (c, n) = p.combine(a, b, k);
                roots_between(&c[..n], 0.0, 1.0, &mut roots)
            }
            // A cubic whose hull crosses the line once: its one root, by Halley's steps; else on
            // each half where that holds there.
            _ => {
                let (c, n) = p.combine(a, b, k);
                match single_change(&hull[..n]) {
                    Some(i) => {
                        roots[0] = single_root(&c[..n], &hull[..n], i);
                        1
                    }
                    None => {
                        let bz = [hull[0], hull[1], hull[2], hull[3]];
                        match cubic_roots_by_halves(&bz, &mut roots) {
                            Some(m) => m,
                            None => roots_unit(&c[..n], hull, &mut roots),
                        }
                    }
                }
            }
        };
        for &t in &roots[..m] {
            let w = p.at(t);
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
                ((w.x - o.x) * d.x + (w.y - o.z) * d.z) / dd
            };
            if s > lo && s < *hi {
                let y = o.y + s * d.y;
                if y >= self.h1 && y <= self.h2 {
                    *hi = s;
                }
            }
        }
    }

    /// Takes arc `p`'s nearest point to `w` as `side` where it is nearer than `best`.
    fn nearer<'a>(&self, p: &'a Piece, w: DVec2, scale: f64, best: &mut f64, side: &mut Option<(&'a Piece, f64)>) {
        let t = arc::nearest_t(p, w);
        let dist = (p.at(t) - w).length() * scale;
        if dist < *best {
            *best = dist;
            *side = Some((p, t));
        }
    }

    /// The outward object-space normal at `q` on the surface: the nearest of the sides and caps.
    fn normal_object(&self, q: DVec3) -> DVec3 {
        let w = self.section(q);
        // Cap distance in object units.
        let mut best = f64::INFINITY;
        let mut normal = DVec3::Y;
        if !self.open {
            for (h, n) in [(self.h1, -DVec3::Y), (self.h2, DVec3::Y)] {
                let dist = (q.y - h).abs();
                if dist < best {
                    best = dist;
                    normal = n;
                }
            }
        }
        // Side distances are measured in the section, scaled back to object units for a cone.
        let scale = if self.conic { q.y.abs() } else { 1.0 };
        let mut side: Option<(&Piece, f64)> = None;
        // The arcs whose boxes and slabs lie nearer than the caps (none for most points on a
        // cap), the nearest first: the point lies on that arc or a neighbour, and the distance
        // to it then rules out the arcs that lie farther.
        let mut near = [(0.0, 0u32); 32];
        let mut count = 0;
        for (i, (p, slab)) in self.arcs.iter().zip(&self.slabs).enumerate() {
            let g = (p.lo - w).max(w - p.hi).max(DVec2::ZERO).length().max(slab.gap(w)) * scale;
            if g < best {
                if count == near.len() {
                    self.nearer(p, w, scale, &mut best, &mut side);
                } else {
                    near[count] = (g, i as u32);
                    count += 1;
                }
            }
        }
        let near = &mut near[..count];
        if let Some(first) = (0..count).min_by(|&i, &j| near[i].0.total_cmp(&near[j].0)) {
            near.swap(0, first);
        }
        for &(g, i) in near.iter() {
            if g < best {
                self.nearer(&self.arcs[i as usize], w, scale, &mut best, &mut side);
            }
        }
        if let Some((p, t)) = side {
            let tan = p.tangent(t);
            let mut n2 = DVec2::new(tan.y, -tan.x).normalize_or_zero();
            if n2 == DVec2::ZERO {
                return normal;
            }
            // Outward: the side of the curve where the section is not inside.
            let at = p.at(t);
            let eps = 1e-6 * (1.0 + at.abs().max_element());
            if self.inside_2d(at + eps * n2) {
                n2 = -n2;
            }
            normal = if self.conic {
                DVec3::new(n2.x, -n2.dot(at), n2.y) * q.y.signum()
            } else {
                DVec3::new(n2.x, 0.0, n2.y)
            };
        }
        normal
    }
}

impl Shape for Prism {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        // Most lanes of a packet that reaches a prism miss its box: all lanes at once first.
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        let Some(t_max) = self.cull.live(o, d, t_min, t_max) else { return L::splat(MISS) };
        super::hit_lanes_f64(&self.frame, ray, t_min, t_max, |o, d, lo, hi| self.solve(o, d, lo, hi))
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
