//! POV-Ray's polynomial surfaces, `quadric`, `cubic`, `quartic` and `poly`: the points where a
//! polynomial in x, y, z (object space) is zero, inside where it is negative (POV-Ray 3.7
//! reference, 3.4.6.5 "Poly, Cubic and Quartic" and 3.4.6.6 "Quadric"). One shape for all four:
//! a quadric is a `poly` of order 2.
//!
//! A quadric is solved in closed form for all lanes at once in f64 (`quadric`). The others are
//! solved per lane in f64 (packets run the f64 solve lane by lane): the ray, moved to its point nearest the object origin and made
//! unit, is substituted into the polynomial, which gives one polynomial in the distance along
//! the ray, solved by `roots::smallest_root_by` with POV-Ray's solver (`Solver::Fast`) or
//! `sturm` (`Solver::Sturm`; a quartic tries the closed form of `quartic` first, and Sturm
//! sequences settle what it declines). The polynomial along the ray comes from the general
//! expansion.
//!
//! Such surfaces are in general unbounded: their bounds are infinite and `Scene` keeps them out
//! of the accelerator, testing them for every ray as planes (see `scene::build`). A quadric
//! whose quadratic part is definite (an ellipsoid written as a quadric) gets its finite box.

use glam::{Affine3A, DVec3, Vec3};

mod bounds;
mod expand;
mod first_root;

use super::cubic::smallest_root_lanes;
use super::cuboid::{frame_for, BoxFrame};
use super::quadric::QuadricForm;
use super::quartic::{first_root, first_root_lanes, Ill};
use super::roots::{root_bound, smallest_root_by, Solver, MAX_DEGREE};
use super::wide::{and, hit_wide, lane_f64, lanes_f64, to_lanes, CentredLanes, Mask, W, WV};
use super::{transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};
use bounds::quadric_box;
use expand::along_ray;
use first_root::first_root_within_bound;

/// The exponents (of x, y, z) of POV-Ray's coefficients for a polynomial of `order`, in the
/// order it reads them: x's power falling, then y's, then z's (`cubic`: x³, x²y, x²z, x², xy²,
/// xyz, xy, xz², xz, x, y³, ..., z, 1).
pub fn term_exponents(order: usize) -> Vec<[u8; 3]> {
    let mut out = Vec::new();
    for i in (0..=order).rev() {
        for j in (0..=order - i).rev() {
            for k in (0..=order - i - j).rev() {
                out.push([i as u8, j as u8, k as u8]);
            }
        }
    }
    out
}

/// How many coefficients a polynomial of `order` has: (order + 1)(order + 2)(order + 3) / 6.
pub fn term_count(order: usize) -> usize {
    (order + 1) * (order + 2) * (order + 3) / 6
}

/// `q[axis].powi(e)` for every axis and `e` below `K` (`K > order`), each by the repeated
/// squaring of the runtime's `powi` (so the same bits), computed once per point instead of by a
/// call per factor: the calls were 6 % of scenes/kernels/cubic.pov's time (normals and inside
/// tests). Sized for the order (as `hit_lanes`' tables are): a table for degree 16, filled and
/// then copied out by `memmove` on every inside test, was another 8 % of that scene's time.
struct Powers<const K: usize>([[f64; K]; 3]);

impl<const K: usize> Powers<K> {
    #[inline(always)]
    fn of(q: [f64; 3]) -> Powers<K> {
        Powers(q.map(|x| std::array::from_fn(|e| powi(x, e as u32))))
    }

    #[inline(always)]
    fn get(&self, axis: usize, e: u8) -> f64 {
        self.0[axis][e as usize]
    }
}

/// `x^e` by repeated squaring in the order of the runtime's `__powidf2`, the routine
/// `f64::powi` calls for an exponent not known at compile time.
#[inline]
fn powi(mut x: f64, mut e: u32) -> f64 {
    let mut r = 1.0;
    loop {
        if e & 1 != 0 {
            r *= x;
        }
        e /= 2;
        if e == 0 {
            return r;
        }
        x *= x;
    }
}

/// `powi` lane by lane: the same multiplications in the same order.
#[inline(always)]
fn powi_lanes<const N: usize>(mut x: W<N>, mut e: u32) -> W<N> {
    let mut r = W::splat(1.0);
    loop {
        if e & 1 != 0 {
            r = r * x;
        }
        e /= 2;
        if e == 0 {
            return r;
        }
        x = x * x;
    }
}

/// Highest order accepted (the root finder's limit).
pub const MAX_ORDER: usize = MAX_DEGREE - 1;

#[derive(Clone, Debug)]
pub struct Poly {
    pub frame: BoxFrame,
    pub order: usize,
    pub solver: Solver,
    /// The non-zero terms: coefficient (scaled so the largest is ±1; the surface is the same)
    /// and exponents of x, y, z.
    pub terms: Vec<(f64, [u8; 3])>,
    /// Render-space bounds, infinite for an unbounded surface.
    pub min: Vec3,
    pub max: Vec3,
    /// For a quadric, its terms as a matrix, solved in closed form eight lanes at once
    /// (`quadric`) instead of by the general expansion (`along_ray`) lane by lane.
    quadric: Option<QuadricForm>,
}

impl Poly {
    /// The polynomial with `coefficients` in POV-Ray's order for `order` (`term_exponents`)
    /// under `render_from_object`.
    pub fn new(render_from_object: Affine3A, order: usize, coefficients: &[f64], solver: Solver) -> Poly {
        let scale = coefficients.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let scale = if scale > 0.0 && scale.is_finite() { scale } else { 1.0 };
        let terms: Vec<(f64, [u8; 3])> = coefficients
            .iter()
            .zip(term_exponents(order))
            .filter(|(c, _)| **c != 0.0)
            .map(|(c, e)| (c / scale, e))
            .collect();
        let (min, max) = match (order == 2).then(|| quadric_box(&terms)).flatten() {
            Some((lo, hi)) => transformed_bounds(&render_from_object, lo.as_vec3(), hi.as_vec3()),
            None => (Vec3::splat(f32::NEG_INFINITY), Vec3::splat(f32::INFINITY)),
        };
        let quadric = (order == 2).then(|| QuadricForm::of(&terms));
        Poly { frame: frame_for(render_from_object), order, solver, terms, min, max, quadric }
    }

    /// Whether the packet path must ask for normals one lane at a time (`Shape::normal` works
    /// them out point by point): all but a quadric, whose gradient is computed eight lanes wide.
    pub fn normal_per_lane(&self) -> bool {
        self.quadric.is_none()
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// The polynomial at object-space `q`.
    pub fn eval(&self, q: [f64; 3]) -> f64 {
        match self.order {
            0..=4 => self.eval_with(&Powers::<5>::of(q)),
            5..=8 => self.eval_with(&Powers::<9>::of(q)),
            _ => self.eval_with(&Powers::<{ MAX_DEGREE + 1 }>::of(q)),
        }
    }

    #[inline(always)]
    fn eval_with<const K: usize>(&self, pw: &Powers<K>) -> f64 {
        self.terms.iter().map(|&(c, [i, j, k])| c * pw.get(0, i) * pw.get(1, j) * pw.get(2, k)).sum()
    }

    /// Whether the polynomial is negative at each of `N` object-space points: `eval`'s powers
    /// and products in its order, lane by lane in `W` (`eval` < 0 to the bit: the sums differ
    /// at most in the sign of a zero, which compares alike). A CSG node's inside tests ask
    /// this for every crossing of its other children (scenes/kernels/cubic.pov: `eval` lane
    /// by lane was a twentieth of the frame).
    #[inline(always)]
    fn below_lanes<const N: usize>(&self, q: WV<N>) -> Mask<N> {
        match self.order {
            0..=4 => self.below_lanes_with::<N, 5>(q),
            5..=8 => self.below_lanes_with::<N, 9>(q),
            _ => self.below_lanes_with::<N, { MAX_DEGREE + 1 }>(q),
        }
    }

    #[inline(always)]
    fn below_lanes_with<const N: usize, const K: usize>(&self, q: WV<N>) -> Mask<N> {
        let axes = [q.x, q.y, q.z];
        let mut pw = [[W::splat(1.0); K]; 3];
        for axis in 0..3 {
            for e in 1..K {
                pw[axis][e] = powi_lanes(axes[axis], e as u32);
            }
        }
        let mut sum = W::splat(-0.0);
        for &(c, [i, j, k]) in &self.terms {
            sum = sum + W::splat(c) * pw[0][i as usize] * pw[1][j as usize] * pw[2][k as usize];
        }
        sum.lt(W::splat(0.0))
    }

    /// The polynomial's gradient at object-space `q`.
    pub fn gradient(&self, q: [f64; 3]) -> [f64; 3] {
        match self.order {
            0..=4 => self.gradient_with(&Powers::<5>::of(q)),
            5..=8 => self.gradient_with(&Powers::<9>::of(q)),
            _ => self.gradient_with(&Powers::<{ MAX_DEGREE + 1 }>::of(q)),
        }
    }

    #[inline(always)]
    fn gradient_with<const K: usize>(&self, pw: &Powers<K>) -> [f64; 3] {
        let mut g = [0.0; 3];
        for &(c, e) in &self.terms {
            for (axis, slot) in g.iter_mut().enumerate() {
                if e[axis] == 0 {
                    continue;
                }
                let mut v = c * e[axis] as f64;
                for (a, &p) in e.iter().enumerate() {
                    let p = if a == axis { p - 1 } else { p };
                    v *= pw.get(a, p);
                }
                *slot += v;
            }
        }
        g
    }

    /// `solve` for the tests: a quadric's general path, the reference its closed form is held to.
    #[cfg(test)]
    pub(crate) fn solve_reference(&self, o: [f64; 3], d: [f64; 3], t_min: f64, t_max: f64) -> Option<f64> {
        self.solve(o, d, t_min, t_max)
    }

    /// The nearest `t` in `(t_min, t_max)` where `o + t·d` (object space) meets the surface:
    /// one lane of the packet path (`hit`), for the tests.
    #[cfg(test)]
    fn solve(&self, o: [f64; 3], d: [f64; 3], t_min: f64, t_max: f64) -> Option<f64> {
        use super::wide::{W, WV};
        let v = |a: [f64; 3]| WV { x: W([a[0]]), y: W([a[1]]), z: W([a[2]]) };
        let ray = CentredLanes::<1>::new(v(o), v(d));
        if !ray.valid[0] {
            return None;
        }
        let along = along_ray::<1, { MAX_DEGREE + 1 }, 153>(&self.terms, self.order, ray.p, ray.u);
        let c: [f64; MAX_DEGREE + 1] = std::array::from_fn(|k| along[k].0[0]);
        self.solve_along(&c[..=self.order], ray.t_c.0[0], ray.len.0[0], t_min, t_max)
    }

    /// The nearest `t` in `(t_min, t_max)` where the polynomial `poly` along the centred ray
    /// (lowest degree first; `t = t_c + s / len`) is zero.
    fn solve_along(&self, poly: &[f64], t_c: f64, len: f64, t_min: f64, t_max: f64) -> Option<f64> {
        // A blocked shadow lane (t_max = −inf) costs nothing.
        if t_max.is_nan() || t_min.is_nan() || t_max <= t_min {
            return None;
        }
        let n = self.order;
        // Highest degree first, without leading terms that are rounding noise (a ray along
        // the axis of a paraboloid makes the s² term cancel to ~1e-17 of the others).
        let scale = poly[..=n].iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if scale.is_nan() || scale == 0.0 {
            return None;
        }
        let mut c = [0.0; MAX_DEGREE + 1];
        for (slot, &v) in c.iter_mut().zip(poly[..=n].iter().rev()) {
            *slot = v;
        }
        let first = c[..=n].iter().position(|v| v.abs() > 1e-14 * scale).unwrap_or(n);
        let mut lo = (t_min - t_c) * len;
        let hi = (t_max - t_c) * len;
        let c = &c[first..=n];
        // A root at `t_min` itself (CSG searching on from a crossing) may come back from the
        // change to `s` and back just past it: then the next root is the one wanted.
        for _ in 0..4 {
            // `sturm` asks for a solver that does not lose roots: the closed form serves where
            // it is well-conditioned, and Sturm sequences decide near a double root, where it
            // declines.
            let closed = match (self.solver, c.len()) {
                (Solver::Sturm, 5) => {
                    let monic = [1.0, c[1] / c[0], c[2] / c[0], c[3] / c[0], c[4] / c[0]];
                    first_root(&monic, lo, hi, |s| (s > lo && s < hi).then_some(s))
                }
                _ => Err(Ill),
            };
            let s = match (self.solver, c.len() - 1) {
                (Solver::Fast, 5..) => first_root_within_bound(c, lo, hi),
                // The closed forms' work does not depend on the span.
                (Solver::Fast, _) => smallest_root_by(Solver::Fast, c, lo, hi),
                _ => closed.unwrap_or_else(|Ill| {
                    // The isolation's work grows with its span: only where roots can be.
                    let bound = root_bound(c);
                    smallest_root_by(self.solver, c, lo.max(-bound), hi.min(bound))
                }),
            }?;
            let t = t_c + s / len;
            if t > t_min {
                return (t < t_max).then_some(t);
            }
            lo = s;
        }
        None
    }
}

impl Poly {
    /// `hit` of the object-space ray `o + t·d`: the polynomials along the `N` lanes' rays
    /// expanded together, then each lane solved on its own (`solve_along`).
    #[inline(always)]
    fn hit_lanes<L: Lane, const N: usize>(&self, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> L {
        // A packet whose every lane is blocked (shadow rays) or empty costs nothing.
        if (0..L::WIDTH).all(|i| !(t_min.get_f64(i) < t_max.get_f64(i))) {
            return L::from_fn_f64(|_| MISS as f64);
        }
        let ray = CentredLanes::<N>::new(lanes_f64(o), lanes_f64(d));
        // The tables sized for the order: zeroing one for degree 16 on every ray cost a fifth
        // of objects/csg/hfclip.pov's time (a quadric then). The arithmetic is the same.
        match self.order {
            0..=4 => self.solve_expanded::<L, N, 5, 15>(&ray, o, d, t_min, t_max),
            5..=6 => self.solve_expanded::<L, N, 7, 28>(&ray, o, d, t_min, t_max),
            7..=8 => self.solve_expanded::<L, N, 9, 45>(&ray, o, d, t_min, t_max),
            _ => self.solve_expanded::<L, N, { MAX_DEGREE + 1 }, 153>(&ray, o, d, t_min, t_max),
        }
    }

    /// `hit_lanes` once the table sizes are chosen (`K > order`, `T = K (K + 1) / 2`).
    #[inline(always)]
    fn solve_expanded<L: Lane, const N: usize, const K: usize, const T: usize>(
        &self,
        ray: &CentredLanes<N>,
        o: V3<L>,
        d: V3<L>,
        t_min: L,
        t_max: L,
    ) -> L {
        let along = along_ray::<N, K, T>(&self.terms, self.order, ray.p, ray.u);
        let lane = |i: usize, _: DVec3, _: DVec3, lo: f64, hi: f64| {
            if !ray.valid[i] {
                return None;
            }
            let c: [f64; K] = std::array::from_fn(|k| along[k].0[i]);
            self.solve_along(&c[..=self.order], ray.t_c.0[i], ray.len.0[i], lo, hi)
        };
        // The closed forms that take all lanes at once.
        if N > 1
            && ((self.order == 4 && self.solver == Solver::Sturm) || (self.order == 3 && self.solver == Solver::Fast))
        {
            return self.closed_lanes(ray, &along, o, d, t_min, t_max, lane);
        }
        super::solve_lanes_f64(o, d, t_min, t_max, lane)
    }

    /// `solve_expanded` for a quartic under `sturm` or a cubic without it, all lanes at once:
    /// the closed form as `solve_along` takes it (`quartic::first_root_lanes`,
    /// `cubic::smallest_root_lanes`), for every lane whose polynomial has its leading term and
    /// whose root, if any, is the answer at once. A lane where the closed form declines, or
    /// that must search on past `t_min` (CSG), is solved by `lane` alone, from the start: the
    /// same arithmetic, so the same bits either way.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn closed_lanes<L: Lane, const N: usize, const K: usize>(
        &self,
        ray: &CentredLanes<N>,
        along: &[W<N>; K],
        o: V3<L>,
        d: V3<L>,
        t_min: L,
        t_max: L,
        lane: impl Fn(usize, DVec3, DVec3, f64, f64) -> Option<f64>,
    ) -> L {
        let k = W::<N>::splat;
        let n = self.order;
        let (lo, hi): (W<N>, W<N>) = (lane_f64(t_min), lane_f64(t_max));
        // As `solve_along`: the coefficients' size, and the leading term above its noise.
        let scale = along[..=n].iter().fold(k(0.0), |m, c| m.zip(c.abs(), f64::max));
        let lead = along[n];
        let mut fast = and(ray.valid, lo.lt(hi));
        fast = and(fast, and(scale.0.map(|v| !v.is_nan() && v != 0.0), (k(1e-14) * scale).lt(lead.abs())));
        let (s_lo, s_hi) = ((lo - ray.t_c) * ray.len, (hi - ray.t_c) * ray.len);
        let c = along;
        let (s, found, ill) = if n == 4 {
            let monic = [k(1.0), c[3] / c[4], c[2] / c[4], c[1] / c[4], c[0] / c[4]];
            let accept = |s: W<N>| (and(s_lo.lt(s), s.lt(s_hi)), s);
            first_root_lanes(&monic, s_lo, s_hi, fast, accept)
        } else {
            let s = smallest_root_lanes(&[c[3], c[2], c[1], c[0]], s_lo, s_hi);
            (s, s.0.map(|v| !v.is_nan()), [false; N])
        };
        let t = ray.t_c + s / ray.len;
        L::from_fn_f64(|i| {
            if !fast[i] || ill[i] {
                return super::solve_lane_f64(i, o, d, t_min, t_max, &lane);
            }
            if !found[i] {
                return MISS as f64;
            }
            let (t, lo, hi) = (t.0[i], lo.0[i], hi.0[i]);
            if !(t > lo) {
                // Before `t_min` (CSG searching on from a crossing): searched past, alone.
                return super::solve_lane_f64(i, o, d, t_min, t_max, &lane);
            }
            if !(t < hi) {
                return MISS as f64;
            }
            if !(L::round_f64(t) > lo) {
                // Rounded back onto `t_min`: searched past, alone.
                return super::solve_lane_f64(i, o, d, t_min, t_max, &lane);
            }
            L::round_f64(t).min(hi)
        })
    }
}

impl Poly {
    /// The lanes whose stretch `(t_min, t_max)` may meet the render-space box (finite), a
    /// part in 10⁴ of its size wider than the accelerator's: every lane the accelerator would
    /// pass to `hit` alone is kept, and one that is unsure (a NaN) too. On
    /// scenes/kernels/quartic.pov (a `bounded_by` box) the lanes of packets that straddle a
    /// box's edge, shadow packets from the floor most, were solved in closed form for nothing.
    /// All lanes at once, as one lane at a time gave it (a fourteenth of
    /// scenes/kernels/cubic.pov's CSG search went to that).
    #[inline(always)]
    fn box_meets<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L::Mask {
        let pad = (self.max - self.min) * 1e-4 + self.min.abs().max(self.max.abs()) * 1e-6;
        let (lo, hi) = (self.min - pad, self.max + pad);
        let (a, b) = (V3::splat(lo).sub(ray.o).mul(ray.inv), V3::splat(hi).sub(ray.o).mul(ray.inv));
        let (mut t0, mut t1, mut unsure) = (t_min, t_max, L::lt(t_min, t_min));
        for (a, b) in [(a.x, b.x), (a.y, b.y), (a.z, b.z)] {
            unsure = L::or(unsure, L::or(L::not(a.le(a)), L::not(b.le(b))));
            t0 = t0.max(a.min(b));
            t1 = t1.min(a.max(b));
        }
        L::or(unsure, L::not(t1.lt(t0)))
    }
}

impl Shape for Poly {
    /// Through `hit_lanes_f64`, which steps past a root that rounds onto `t_min`: a CSG node
    /// searching on from a crossing would otherwise be handed that crossing again, up to
    /// `MAX_CROSSINGS` times (objects/csg/hfclip.pov's clipped `Cylinder_Y` did).
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        if let Some(q) = &self.quadric {
            return hit_wide(q, &self.frame, ray, t_min, t_max);
        }
        // A packet's lanes that miss a bounded surface's box are not solved: a ray alone
        // would not reach the surface past the accelerator's test of that box.
        let t_max = if L::WIDTH > 1 && self.min.is_finite() && self.max.is_finite() {
            L::select(self.box_meets(ray, t_min, t_max), t_max, t_min)
        } else {
            t_max
        };
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        if L::WIDTH == 8 {
            self.hit_lanes::<L, 8>(o, d, t_min, t_max)
        } else {
            self.hit_lanes::<L, 1>(o, d, t_min, t_max)
        }
    }

    /// The gradient, which points to where the polynomial grows: out of the inside.
    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let q = p.transform_point(&self.frame.object_from_render);
        let n = if let Some(f) = &self.quadric {
            // All lanes at once (`Poly::normal_per_lane` is false for a quadric).
            if L::WIDTH == 8 {
                to_lanes(f.gradient::<8>(lanes_f64(q)))
            } else {
                to_lanes(f.gradient::<1>(lanes_f64(q)))
            }
        } else {
            let mut g = [[0.0; 3]; 8];
            for (i, slot) in g.iter_mut().enumerate().take(L::WIDTH) {
                *slot = self.gradient([q.x.get_f64(i), q.y.get_f64(i), q.z.get_f64(i)]);
            }
            V3 { x: L::from_fn_f64(|i| g[i][0]), y: L::from_fn_f64(|i| g[i][1]), z: L::from_fn_f64(|i| g[i][2]) }
        };
        n.mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }

    /// Where the polynomial is negative.
    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = p.transform_point(&self.frame.object_from_render);
        if let Some(f) = &self.quadric {
            return L::mask_from_fn(|i| f.eval([q.x.get_f64(i), q.y.get_f64(i), q.z.get_f64(i)]) < 0.0);
        }
        if L::WIDTH == 8 {
            let below = self.below_lanes::<8>(lanes_f64(q));
            L::mask_from_fn(|i| below[i])
        } else {
            let below = self.below_lanes::<1>(lanes_f64(q));
            L::mask_from_fn(|_| below[0])
        }
    }
}

#[cfg(test)]
mod tests;
