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
            if self.conic {
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
mod tests {
    use super::*;
    use crate::desc::SplineKind;
    use crate::geometry::spline::closed_pieces;
    use crate::geometry::test_support::*;
    use crate::lanes::F8;
    use crate::ray::Ray;

    fn square(kind: SplineKind) -> Vec<Piece> {
        let p = |x: f64, z: f64| DVec2::new(x, z);
        let pts: Vec<DVec2> = match kind {
            SplineKind::Linear => vec![p(-1.0, -1.0), p(1.0, -1.0), p(1.0, 1.0), p(-1.0, 1.0), p(-1.0, -1.0)],
            _ => unreachable!(),
        };
        closed_pieces(kind, &pts).expect("square").0
    }

    fn prism(xf: DAffine3, conic: bool, open: bool) -> Prism {
        Prism::new(xf, &square(SplineKind::Linear), if conic { 1.0 } else { 0.0 }, 2.0, conic, open)
    }

    fn inside(p: &Prism, q: Vec3) -> bool {
        p.inside(V3::from_vec3(q))
    }

    fn hit(p: &Prism, o: Vec3, d: Vec3) -> Option<f32> {
        p.intersect(&Ray::new(o, d.normalize()), 0.0, f32::INFINITY)
    }

    #[test]
    fn sides_caps_open_and_conic() {
        let p = prism(DAffine3::IDENTITY, false, false);
        assert!((hit(&p, Vec3::new(0.0, 1.0, -5.0), Vec3::Z).expect("side") - 4.0).abs() < 1e-5);
        assert!((p.normal_at(Vec3::new(0.0, 1.0, -1.0)) - -Vec3::Z).length() < 1e-5);
        assert!((hit(&p, Vec3::new(0.2, 5.0, 0.1), -Vec3::Y).expect("cap") - 3.0).abs() < 1e-5);
        assert!((p.normal_at(Vec3::new(0.2, 2.0, 0.1)) - Vec3::Y).length() < 1e-5);
        // Along the sweep axis outside the outline: a miss.
        assert_eq!(hit(&p, Vec3::new(1.5, 5.0, 0.0), -Vec3::Y), None);
        let open = prism(DAffine3::IDENTITY, false, true);
        // Open: down through the top hits the bottom... no: no caps at all, the inside of a wall.
        assert_eq!(hit(&open, Vec3::new(0.2, 5.0, 0.1), -Vec3::Y), None);
        assert!((hit(&open, Vec3::new(0.0, 1.0, 0.0), Vec3::Z).expect("wall from inside") - 1.0).abs() < 1e-5);
        // Conic: the square scaled by y, from y = 1 to 2; at y = 1.5 the half-width is 1.5.
        let c = prism(DAffine3::IDENTITY, true, false);
        assert!((hit(&c, Vec3::new(0.0, 1.5, -5.0), Vec3::Z).expect("conic side") - 3.5).abs() < 1e-5);
        let n = c.normal_at(Vec3::new(0.0, 1.5, -1.5));
        assert!((n - Vec3::new(0.0, -1.0, -1.0).normalize()).length() < 1e-5, "{n}");
        assert!((hit(&c, Vec3::new(1.8, 5.0, 0.0), -Vec3::Y).expect("top cap reaches 2") - 3.0).abs() < 1e-5);
        assert!(inside(&c, Vec3::new(1.4, 1.5, 0.0)) && !inside(&c, Vec3::new(1.6, 1.5, 0.0)));
    }

    /// Seeded random rays (some starting inside, some level) at a star with a curved hole, closed
    /// and conic: the nearest hit is the least of the caps (each by even-odd over all pieces) and
    /// the sides (the open prism's), as the entering-cap-first order must keep; eight-lane
    /// packets give the single rays' bits.
    #[test]
    fn caps_and_sides_against_brute_force_and_packets() {
        use crate::geometry::spline::even_odd;
        let mut rand = uniform(0x2545_f491_4f6c_dd1du64);
        let pieces = star_with_hole();
        let mut caps_hit = 0;
        for conic in [false, true] {
            let (h1, h2) = if conic { (0.5, 1.5) } else { (0.0, 0.6) };
            let closed = Prism::new(DAffine3::IDENTITY, &pieces, h1, h2, conic, false);
            let open = Prism::new(DAffine3::IDENTITY, &pieces, h1, h2, conic, true);
            let mut rays = Vec::new();
            for i in 0..4000 {
                // Render space is the prism as written.
                let y = h1 + (h2 - h1) * rand();
                let reach = if conic { 0.5 * y } else { 0.5 };
                let target = DVec3::new((rand() * 2.0 - 1.0) * reach, y, (rand() * 2.0 - 1.0) * reach);
                let o = DVec3::new(rand() * 4.0 - 2.0, rand() * 4.0 - 1.0, rand() * 4.0 - 2.0);
                let o = if i % 5 == 0 { target } else { o };
                let mut d = (target - o + 0.1 * DVec3::new(rand(), rand(), rand())).normalize();
                if i % 17 == 0 {
                    d.y = 0.0;
                }
                let ray = Ray::new(o.as_vec3(), d.as_vec3());
                rays.push(ray);
                let f = &closed.frame.object_from_render;
                let (o, d) = (f.transform_point3(ray.origin).as_dvec3(), f.transform_vector3(ray.dir).as_dvec3());
                let s_min = if i % 3 == 0 { 1e-4 } else { 0.0 };
                let mut want = open.solve(o, d, s_min, f64::INFINITY).unwrap_or(f64::INFINITY);
                for h in [closed.h1, closed.h2] {
                    let s = (h - o.y) / d.y;
                    let w = o + s * d;
                    if s > s_min && s < want && even_odd(&closed.pieces, closed.section(DVec3::new(w.x, h, w.z))) {
                        want = s;
                        caps_hit += 1;
                    }
                }
                let want = want.is_finite().then_some(want).map(f64::to_bits);
                assert_eq!(closed.solve(o, d, s_min, f64::INFINITY).map(f64::to_bits), want, "{o} {d}");
            }
            for chunk in rays.chunks_exact(8) {
                let packet = RayLanes::<F8> {
                    o: V3::from_lanes(|i| chunk[i].origin),
                    d: V3::from_lanes(|i| chunk[i].dir),
                    inv: V3::from_lanes(|i| chunk[i].inv_dir),
                };
                let wide = closed.hit(&packet, F8::splat(0.0), F8::splat(MISS));
                for (i, r) in chunk.iter().enumerate() {
                    assert_eq!(wide.get(i).to_bits(), closed.hit(&r.lanes(), 0.0, MISS).to_bits());
                }
            }
        }
        assert!(caps_hit > 500, "the rays reach the caps: {caps_hit}");
    }

    #[test]
    fn grazing_scaled_moved_and_packets() {
        // Grazing the wall z = -1 along it: either no hit or one on the wall's line.
        let p = prism(DAffine3::IDENTITY, false, false);
        let g = hit(&p, Vec3::new(-5.0, 1.0, -1.0), Vec3::X);
        assert!(g.is_none_or(|t| (3.9..=6.1).contains(&t)), "{g:?}");
        // Scaled 1e-4 and 1e5, moved 1e6: the same hit in proportion.
        for (s, at) in [(1e-4, 0.0), (1e5, 0.0), (1.0, 1e6)] {
            let xf = DAffine3::from_translation(DVec3::splat(at)) * DAffine3::from_scale(DVec3::splat(s));
            let p = prism(xf, false, false);
            // Render space puts the camera near the shape: rays start close to it.
            let o = Vec3::new(0.0, 1.0, -5.0) * s as f32 + Vec3::splat(at as f32);
            let t = hit(&p, o, Vec3::Z).expect("hit");
            let want = 4.0 * s as f32;
            assert!((t - want).abs() <= want * 1e-4 + at as f32 * 1e-6, "{s} {at}: {t}");
        }
        let rays: [Ray; 8] = std::array::from_fn(|i| {
            let o = Vec3::new(i as f32 * 0.3 - 1.2, 3.0, -4.0);
            Ray::new(o, (Vec3::new(0.1 * i as f32, 1.0, 0.0) - o).normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let wide = p.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, r) in rays.iter().enumerate() {
            assert_eq!(wide.get(i).to_bits(), p.hit(&r.lanes(), 0.0, MISS).to_bits());
        }
    }

    #[test]
    fn curved_sides_holes_and_the_nearest_point() {
        // A circle-ish cubic outline with a square hole (even-odd).
        let q = |x: f64, z: f64| DVec2::new(x, z);
        let mut pts =
            vec![q(0.0, -2.0), q(2.0, 0.0), q(0.0, 2.0), q(-2.0, 0.0), q(0.0, -2.0), q(2.0, 0.0), q(0.0, 2.0)];
        pts.extend([q(-0.5, -0.5), q(0.5, -0.5), q(0.5, 0.5), q(-0.5, 0.5), q(-0.5, -0.5)].map(|p| p * 1.0));
        let cubic = closed_pieces(SplineKind::Cubic, &pts[..7]).expect("cubic").0;
        let hole = closed_pieces(SplineKind::Linear, &pts[7..]).expect("hole").0;
        let all: Vec<Piece> = cubic.into_iter().chain(hole).collect();
        let p = Prism::new(DAffine3::IDENTITY, &all, 0.0, 1.0, false, false);
        assert!(inside(&p, Vec3::new(1.0, 0.5, 0.0)));
        assert!(!inside(&p, Vec3::new(0.0, 0.5, 0.0)), "the hole");
        assert!(!inside(&p, Vec3::new(2.5, 0.5, 0.0)));
        // From the hole's middle along x: the hole's wall at 0.5.
        let t = hit(&p, Vec3::new(0.0, 0.5, 0.0), Vec3::X).expect("hole wall");
        assert!((t - 0.5).abs() < 1e-5, "{t}");
        assert!((p.normal_at(Vec3::new(0.5, 0.5, 0.0)) - -Vec3::X).length() < 1e-4);
        // The outer wall at x = 2 (a point of the spline), normal +x.
        let t = hit(&p, Vec3::new(5.0, 0.5, 0.0), -Vec3::X).expect("outer");
        assert!((t - 3.0).abs() < 1e-4, "{t}");
        assert!((p.normal_at(Vec3::new(2.0, 0.5, 0.0)) - Vec3::X).length() < 1e-3);
    }
}
