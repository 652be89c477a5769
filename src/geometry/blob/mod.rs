//! POV-Ray's `blob` (3.4.5.1.2 Blob): the surface where a sum of fields equals `threshold`.
//! Each component adds `strength · (1 − d²/r²)²` within radius `r` of its centre (a sphere
//! component) or of its axis segment (a cylinder component, with hemispherical ends), and
//! nothing beyond; a negative strength subtracts. Each component may carry its own transform.
//!
//! Along a ray, `d²` is a quadratic in `t` wherever the ray is within one piece of a component
//! (a sphere, a cylinder's middle, one of its ends), so the field is a quartic there. The
//! pieces' spans along the ray are swept in order; between consecutive span ends the active
//! pieces' quartics add up to one, whose first root above the threshold is found in f64 (`span`):
//! spans where the pieces' most cannot reach the threshold are skipped, the others solved in
//! closed form (`quartic::ferrari`, polished) where that is well-conditioned, else by
//! `roots::roots_in` (with a bisection where the ends' signs differ and the critical-point
//! search returns nothing, so a crossing is never lost to rounding). A shadow ray (`blocks`)
//! stops, unsolved, at the first span whose ends the field crosses the threshold between,
//! where the whole span lies inside its interval: the closed form would answer a root there. The field and its
//! derivative are zero at every piece's edge, so the sum is continuous across span ends. Lanes
//! are solved one by one, as the torus and lathe are, but only those that `reach`'s
//! eight-lane f32 test cannot rule out (nine in ten of those reaching the box on the kernel
//! scenes are ruled out).
//!
//! Distances along the ray are measured from the ray's point nearest the blob's centre, in
//! units where the blob has unit size, so the quartics stay well conditioned far away.

use std::cell::RefCell;

use glam::{Affine3A, DAffine3, DVec3, Vec3};

mod reach;
#[cfg(test)]
mod regressions;
mod span;
#[cfg(test)]
mod tests;

use super::cuboid::{frame_for, BoxFrame};
use super::roots::MAX_DEGREE;
use super::{affine_f32, inside_lanes_f64, normal_lanes_f64, solve_lanes_f64, transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};
use reach::{may_reach, Component as ReachComponent, Reach};
use span::{bracket, span_roots};

/// The form of one component, in its own space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ComponentShape {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// From `base` to `cap`, hemispheres at both ends.
    Cylinder {
        base: DVec3,
        cap: DVec3,
        radius: f64,
    },
}

/// One component as written: its form, strength, and where its space sits in the blob's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Component {
    pub shape: ComponentShape,
    pub strength: f64,
    /// The component's own transforms (identity for none): blob space from component space.
    pub blob_from_component: DAffine3,
}

/// A component ready to evaluate: a sphere or a segment (length 0 for a sphere) in component
/// space, and the map into it from the blob's unit space.
#[derive(Clone, Copy, Debug)]
struct Field {
    component_from_unit: DAffine3,
    /// `component_from_unit` is the previous field's (every field's, where no component has
    /// its own transform): the ray is carried into that space once for all of them.
    same_space: bool,
    base: DVec3,
    /// Unit axis (any unit vector for a sphere).
    axis: DVec3,
    length: f64,
    r2: f64,
    strength: f64,
}

/// A span of the ray inside one piece and the piece's quartic there (highest power first).
#[derive(Clone, Copy, Debug)]
struct Piece {
    lo: f64,
    hi: f64,
    k: [f64; 5],
    strength: f64,
    /// The squared distance over `r²` along the ray, `q(u) = q[0]·u² + q[1]·u + q[2]`: the
    /// field is `strength · (1 − q)²`.
    q: [f64; 3],
}

impl Piece {
    /// The most this piece adds to the field for `u` in `[lo, hi]` (within its span): where
    /// `q` is least.
    fn most(&self, lo: f64, hi: f64) -> f64 {
        let q = |u: f64| (self.q[0] * u + self.q[1]) * u + self.q[2];
        let mut least = q(lo).min(q(hi));
        if self.q[0] > 0.0 {
            let vertex = -0.5 * self.q[1] / self.q[0];
            if vertex > lo && vertex < hi {
                least = least.min(q(vertex));
            }
        }
        let g = 1.0 - least.clamp(0.0, 1.0);
        self.strength * g * g
    }
}

#[derive(Clone, Debug)]
pub struct Blob {
    pub frame: BoxFrame,
    fields: Vec<Field>,
    /// The positive fields, for the eight-lane test of which rays can meet the blob at all.
    reach: Reach,
    threshold: f64,
    /// No component subtracts: the field falls along a ray leaving every component (`leaves`).
    none_negative: bool,
    pub min: Vec3,
    pub max: Vec3,
}

/// One ray's pieces, their span ends (`end_key`) and the active set.
type Scratch = (Vec<Piece>, Vec<u128>, Vec<u32>);

thread_local! {
    /// Reused for every ray a thread solves: no allocation per ray.
    static SCRATCH: RefCell<Scratch> = const { RefCell::new((Vec::new(), Vec::new(), Vec::new())) };
}

/// A span end as the sweep sorts it: its position `u` in `f64::total_cmp`'s order, then ends
/// before starts, then `code` (2·piece, + 1 for an end). One integer compare per step of the
/// sort, where a comparator chaining `total_cmp` and the kind took a tenth of the solve.
fn end_key(u: f64, code: u32) -> u128 {
    let bits = u.to_bits() as i64;
    let ordered = (bits ^ ((((bits >> 63) as u64) >> 1) as i64)) as u64 ^ (1 << 63);
    (ordered as u128) << 33 | (((code & 1) ^ 1) as u128) << 32 | code as u128
}

/// The position and code `end_key` was made from.
fn end_of(key: u128) -> (f64, u32) {
    let bits = ((key >> 33) as u64 ^ (1 << 63)) as i64;
    (f64::from_bits((bits ^ ((((bits >> 63) as u64) >> 1) as i64)) as u64), key as u32)
}

/// The box of a component in blob space, if it adds to the field (positive strength), with
/// its radius times `shrink`.
fn component_bounds(c: &Component, shrink: f64) -> Option<(Vec3, Vec3)> {
    // NaN strengths add nothing either.
    if c.strength.is_nan() || c.strength <= 0.0 {
        return None;
    }
    let (lo, hi) = match c.shape {
        ComponentShape::Sphere { center, radius } => (center - radius * shrink, center + radius * shrink),
        ComponentShape::Cylinder { base, cap, radius } => {
            (base.min(cap) - radius * shrink, base.max(cap) + radius * shrink)
        }
    };
    Some(transformed_bounds(&affine_f32(&c.blob_from_component), lo.as_vec3(), hi.as_vec3()))
}

/// The span `(lo, hi)` where `a·u² + b·u + c < 0`, if any.
fn below_zero(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    if a <= 0.0 {
        // Parallel to the axis: the distance does not change along the ray.
        return (c < 0.0).then_some((f64::NEG_INFINITY, f64::INFINITY));
    }
    let disc = b * b - 4.0 * a * c;
    if disc.is_nan() || disc <= 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (r0, r1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    Some((r0.min(r1), r0.max(r1)))
}

/// The fraction of its radius within which some positive component lies from every point
/// where the field reaches `threshold`: with `S` the positive strengths' sum, a point where
/// each component `i` adds less than `threshold · sᵢ / S` has a field below `threshold` (the
/// negative ones only take away), so one adds at least that: `(1 − d²/r²)² ≥ threshold / S`.
/// On scenes/kernels/blob_sphere.pov the box shrinks to 0.8 of the components' radii, to 0.74
/// on blob_cylinder.pov. A part in 10³ over, for rounding.
fn surface_radius(components: &[Component], threshold: f64) -> f64 {
    let total: f64 = components.iter().map(|c| c.strength).filter(|s| *s > 0.0).sum();
    let ratio = threshold / total;
    if !(ratio > 0.0 && total.is_finite()) {
        return 1.0;
    }
    ((1.0 - ratio.min(1.0).sqrt()).sqrt() + 1e-3).min(1.0)
}

impl Field {
    fn of(c: &Component, blob_from_unit: &DAffine3) -> Field {
        let component_from_unit = c.blob_from_component.inverse() * *blob_from_unit;
        let (base, axis, length, radius) = match c.shape {
            ComponentShape::Sphere { center, radius } => (center, DVec3::Y, 0.0, radius),
            ComponentShape::Cylinder { base, cap, radius } => {
                let length = (cap - base).length();
                let axis = if length > 0.0 { (cap - base) / length } else { DVec3::Y };
                (base, axis, length, radius)
            }
        };
        Field { component_from_unit, same_space: false, base, axis, length, r2: radius * radius, strength: c.strength }
    }

    /// This field as `reach` tests it, if it adds to the field (positive strength).
    fn reach(&self) -> Option<(Affine3A, ReachComponent)> {
        (self.strength > 0.0).then(|| {
            let c = ReachComponent {
                mid: (self.base + 0.5 * self.length * self.axis).as_vec3(),
                axis: self.axis.as_vec3(),
                half: (0.5 * self.length) as f32,
                inv_r2: (1.0 / self.r2) as f32,
                strength: self.strength as f32,
            };
            (affine_f32(&self.component_from_unit), c)
        })
    }

    /// The piece over `[lo, hi]` whose squared distance is `a·u² + b·u + c`: its quartic
    /// `strength · (1 − (a·u² + b·u + c) / r²)²`, expanded.
    fn piece(&self, lo: f64, hi: f64, a: f64, b: f64, c: f64) -> Piece {
        let q = [a / self.r2, b / self.r2, c / self.r2];
        let (a, b, c) = (q[0], q[1], 1.0 - q[2]);
        let s = self.strength;
        let k = [s * a * a, s * 2.0 * a * b, s * (b * b - 2.0 * a * c), s * -2.0 * b * c, s * c * c];
        Piece { lo, hi, k, strength: s, q }
    }

    /// The point `p` and direction `dir` of unit space in this component's space.
    fn carry(&self, (p, dir): (DVec3, DVec3)) -> (DVec3, DVec3) {
        (self.component_from_unit.transform_point3(p), self.component_from_unit.transform_vector3(dir))
    }

    /// The pieces of this component along the ray `p0 + u·dir`, given in component space
    /// (`carry`), into `out`.
    fn pieces(&self, (p0, qd): (DVec3, DVec3), out: &mut Vec<Piece>) {
        let q0 = p0 - self.base;
        let mut sphere = |w: DVec3, span: (f64, f64)| {
            let (a, b, c) = (qd.dot(qd), 2.0 * w.dot(qd), w.dot(w));
            if let Some((lo, hi)) = below_zero(a, b, c - self.r2) {
                let (lo, hi) = (lo.max(span.0), hi.min(span.1));
                if lo < hi {
                    out.push(self.piece(lo, hi, a, b, c));
                }
            }
        };
        if self.length == 0.0 {
            sphere(q0, (f64::NEG_INFINITY, f64::INFINITY));
            return;
        }
        // Height along the axis, h0 + u·hd; the spans of u below, along and above the segment.
        let (h0, hd) = (q0.dot(self.axis), qd.dot(self.axis));
        let (below, along, above) = if hd != 0.0 {
            let (u0, u1) = (-h0 / hd, (self.length - h0) / hd);
            let (lo, hi) = (u0.min(u1), u0.max(u1));
            if hd > 0.0 {
                ((f64::NEG_INFINITY, lo), (lo, hi), (hi, f64::INFINITY))
            } else {
                ((hi, f64::INFINITY), (lo, hi), (f64::NEG_INFINITY, lo))
            }
        } else {
            let (all, none) = ((f64::NEG_INFINITY, f64::INFINITY), (0.0, 0.0));
            if h0 < 0.0 {
                (all, none, none)
            } else if h0 > self.length {
                (none, none, all)
            } else {
                (none, all, none)
            }
        };
        sphere(q0, below);
        sphere(q0 - self.length * self.axis, above);
        let (w, v) = (q0 - h0 * self.axis, qd - hd * self.axis);
        let (a, b, c) = (v.dot(v), 2.0 * w.dot(v), w.dot(w));
        if let Some((lo, hi)) = below_zero(a, b, c - self.r2) {
            let (lo, hi) = (lo.max(along.0), hi.min(along.1));
            if lo < hi {
                out.push(self.piece(lo, hi, a, b, c));
            }
        }
    }

    /// The field and its gradient (unit space) at the point `at` of this component's space.
    fn at(&self, at: DVec3) -> (f64, DVec3) {
        let q = at - self.base;
        let h = q.dot(self.axis).clamp(0.0, self.length);
        let w = q - h * self.axis;
        let d2 = w.dot(w) / self.r2;
        if d2 >= 1.0 {
            return (0.0, DVec3::ZERO);
        }
        let g = 1.0 - d2;
        let grad_q = w * (-4.0 * self.strength * g / self.r2);
        (self.strength * g * g, self.component_from_unit.matrix3.transpose() * grad_q)
    }
}

impl Blob {
    /// `components` (blob space) with their sum at `threshold` as the surface, under
    /// `render_from_object`. A blob without a positive component is empty.
    pub fn new(render_from_object: DAffine3, components: &[Component], threshold: f64) -> Blob {
        let boxes = |shrink: f64| {
            let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
            for (a, b) in components.iter().filter_map(|c| component_bounds(c, shrink)) {
                lo = lo.min(a);
                hi = hi.max(b);
            }
            if !(lo.cmple(hi).all()) {
                (lo, hi) = (Vec3::ZERO, Vec3::ZERO);
            }
            (lo, hi)
        };
        // The unit space is made from the components' whole boxes; the bounds from where the
        // surface can be (`surface_radius`).
        let (lo, hi) = boxes(1.0);
        let (tight_lo, tight_hi) = boxes(surface_radius(components, threshold));
        let center = 0.5 * (lo.as_dvec3() + hi.as_dvec3());
        let size = 0.5 * (hi - lo).max_element() as f64;
        let size = if size > 0.0 && size.is_finite() { size } else { 1.0 };
        let blob_from_unit = DAffine3::from_translation(center) * DAffine3::from_scale(DVec3::splat(size));
        let mut fields: Vec<Field> = components.iter().map(|c| Field::of(c, &blob_from_unit)).collect();
        for i in 1..fields.len() {
            fields[i].same_space = fields[i].component_from_unit == fields[i - 1].component_from_unit;
        }
        let reach = Reach::new(fields.iter().filter_map(Field::reach));
        let xf = affine_f32(&(render_from_object * blob_from_unit));
        // In unit space (size 1), widened by far more than the rounding of the f32 blob-space
        // boxes, which is relative to their coordinates' size, not the blob's.
        let (c, inv) = (center.as_vec3(), 1.0 / size as f32);
        let slack = 64.0 * f32::EPSILON * (1.0 + (lo.abs().max(hi.abs()).max_element() * inv));
        let (e_lo, e_hi) = ((tight_lo - c) * inv - slack, (tight_hi - c) * inv + slack);
        let (min, max) = transformed_bounds(&xf, e_lo.min(e_hi), e_hi.max(e_lo));
        let pad = (max - min).max(min.abs().max(max.abs())) * 4.0 * f32::EPSILON;
        let none_negative = fields.iter().all(|f| f.strength >= 0.0);
        Blob { frame: frame_for(xf), fields, reach, threshold, none_negative, min: min - pad, max: max + pad }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// Each field's value and gradient at a point of unit space, in order: the point is
    /// carried into each component's space once for the run of fields sharing it (all of
    /// them on the kernel scenes), as `search` carries the ray: the same bits as a transform
    /// per field, and the normal's instructions on scenes/kernels/blob_sphere.pov 9 % fewer.
    fn each_at(&self, p: DVec3) -> impl Iterator<Item = (f64, DVec3)> + '_ {
        let mut at = p;
        self.fields.iter().map(move |f| {
            if !f.same_space {
                at = f.component_from_unit.transform_point3(p);
            }
            f.at(at)
        })
    }

    /// The field at a point of unit space.
    fn field(&self, p: DVec3) -> f64 {
        self.each_at(p).map(|(v, _)| v).sum()
    }

    /// The first root along `o + t·d` (unit space) in `(t_min, t_max)`, as the tests ask it.
    #[cfg(test)]
    fn solve(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64) -> Option<f64> {
        self.search(o, d, t_min, t_max, None)
    }

    /// `solve`, or with `any` (the lane's rounding, `Lane::round_f64`) a `t` inside a span that
    /// certainly holds a root `solve` would answer, for `Shape::blocks`: the spans before it are
    /// solved as `solve` solves them, so the first root `solve` finds there is answered as it
    /// is, and where none is, `solve` would find one in this span (`bracket`).
    fn search(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64, any: Option<fn(f64) -> f64>) -> Option<f64> {
        // An empty interval (a lane `reach` left out) holds no root.
        if !(t_min < t_max) {
            return None;
        }
        let len = d.length();
        if len.is_nan() || len <= 0.0 {
            return None;
        }
        let dir = d / len;
        // u = t·len − s0: distance from the ray's point nearest the centre.
        let s0 = -o.dot(dir);
        let p0 = o + s0 * dir;
        let (u_min, u_max) = (t_min * len - s0, t_max * len - s0);
        if self.leaves(p0, dir, u_min) {
            return None;
        }
        SCRATCH.with(|scratch| {
            let (pieces, ends, active) = &mut *scratch.borrow_mut();
            pieces.clear();
            ends.clear();
            active.clear();
            let mut ray = (p0, dir);
            for f in &self.fields {
                if !f.same_space {
                    ray = f.carry((p0, dir));
                }
                f.pieces(ray, pieces);
            }
            // Nowhere along the ray can the field reach the threshold if the pieces' most over
            // their spans together cannot (a part in 10⁹ to spare for rounding).
            let most: f64 = pieces
                .iter()
                .filter(|p| p.strength > 0.0 && p.hi > u_min && p.lo < u_max)
                .map(|p| p.most(p.lo.max(u_min), p.hi.min(u_max)))
                .sum();
            if !(most >= self.threshold * (1.0 - 1e-9)) {
                return None;
            }
            for (i, p) in pieces.iter().enumerate() {
                if p.hi > u_min && p.lo < u_max {
                    ends.push(end_key(p.lo.max(u_min), 2 * i as u32));
                    ends.push(end_key(p.hi.min(u_max), 2 * i as u32 + 1));
                }
            }
            // Ends before starts at the same place: a piece is never active across no span.
            ends.sort_unstable();
            for w in 0..ends.len() {
                let (u, e) = end_of(ends[w]);
                let piece = e >> 1;
                if e & 1 == 0 {
                    active.push(piece);
                } else if let Some(at) = active.iter().position(|&p| p == piece) {
                    active.swap_remove(at);
                }
                let Some(next) = ends.get(w + 1).map(|&k| end_of(k).0) else { break };
                // The field cannot reach the threshold where the active pieces' most cannot
                // (with a part in 10⁹ to spare for rounding): on blob_sphere.pov most spans.
                let reach: f64 = active
                    .iter()
                    .map(|&p| &pieces[p as usize])
                    .filter(|p| p.strength > 0.0)
                    .map(|p| p.most(u, next))
                    .sum();
                if next.is_nan() || next <= u || !(reach >= self.threshold * (1.0 - 1e-9)) {
                    continue;
                }
                let mut k = [0.0; 5];
                for &p in active.iter() {
                    for (s, c) in k.iter_mut().zip(pieces[p as usize].k) {
                        *s += c;
                    }
                }
                k[4] -= self.threshold;
                let (lo, hi) = (u.max(u_min), next);
                if let Some(round) = any {
                    let (first, last) =
                        bracket(&k, lo, hi).map_or((f64::NAN, f64::NAN), |(a, b)| ((a + s0) / len, (b + s0) / len));
                    // NaN compares false.
                    if first > t_min && last < t_max && round(first) > t_min {
                        return Some(0.5 * (first + last));
                    }
                }
                // Back in t, a root just above u_min may round onto t_min: take the first
                // that does not, so searching on from a crossing finds the next one.
                let mut roots = [0.0; MAX_DEGREE];
                let n = span_roots(&k, lo, hi, &mut roots);
                if let Some(t) = roots[..n].iter().map(|r| (r + s0) / len).find(|&t| t > t_min && t < t_max) {
                    return Some(t);
                }
            }
            None
        })
    }

    /// Whether the ray `p0 + u·dir` (unit space) certainly does not reach the threshold past
    /// `u_min`: no component subtracts, the ray moves away from every component from `u_min`
    /// on (the distance to a point or segment is convex along a line, so once it grows it
    /// keeps growing, and each component's field keeps falling), and the field at `u_min` is
    /// below the threshold by more than a part in 10⁹. Shadow rays leaving a lit blob are so
    /// (their origin is moved off the surface to the side they leave by): here they cost one
    /// evaluation of the field instead of its pieces, their sort and a closed-form solve per
    /// span, which `reach` cannot spare them (the field reaches the threshold where they start).
    fn leaves(&self, p0: DVec3, dir: DVec3, u_min: f64) -> bool {
        if !self.none_negative || !u_min.is_finite() {
            return false;
        }
        let p = p0 + u_min * dir;
        let mut field = 0.0;
        let mut ray = (p, dir);
        for f in &self.fields {
            if !f.same_space {
                ray = f.carry((p, dir));
            }
            let q = ray.0 - f.base;
            let h = q.dot(f.axis).clamp(0.0, f.length);
            let w = q - h * f.axis;
            // Half the derivative of the squared distance along the ray: NaN fails too.
            if !(w.dot(ray.1) >= 0.0) {
                return false;
            }
            let d2 = w.dot(w) / f.r2;
            if d2 < 1.0 {
                let g = 1.0 - d2;
                field += f.strength * g * g;
            }
        }
        field < self.threshold * (1.0 - 1e-9)
    }

    fn normal_unit(&self, p: DVec3) -> DVec3 {
        let grad: DVec3 = self.each_at(p).map(|(_, g)| g).sum();
        -grad
    }

    fn inside_unit(&self, p: DVec3) -> bool {
        self.field(p) > self.threshold
    }
}

/// As `shape_solved_in_f64!` writes it for the other kinds solved lane by lane in f64, but
/// lanes `reach` shows cannot meet the blob are not solved: they are given an empty
/// interval (no root lies in `(t_min, t_min)`), and a packet none of whose lanes can meet it is
/// a miss at once.
impl Blob {
    /// `hit` (`any` none) or `blocks` (`any` the lanes' rounding): see `search`.
    #[inline(always)]
    fn lanes<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L, any: Option<fn(f64) -> f64>) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        let near = may_reach(&self.reach, self.threshold as f32, o, d, t_min, t_max);
        if !L::any(near) {
            return L::splat(MISS);
        }
        let t_max = L::select(near, t_max, t_min);
        solve_lanes_f64(o, d, t_min, t_max, |_, o, d, lo, hi| self.search(o, d, lo, hi, any))
    }
}

impl Shape for Blob {
    #[inline(never)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.lanes(ray, t_min, t_max, None)
    }

    /// A shadow ray stops at the first span that certainly holds the root `hit` would answer
    /// there (`search`), without the closed form and polish that place it.
    #[inline(never)]
    fn blocks<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.lanes(ray, t_min, t_max, Some(L::round_f64))
    }

    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        normal_lanes_f64(&self.frame, p, |q| self.normal_unit(q))
    }

    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        inside_lanes_f64(&self.frame, p, |q| self.inside_unit(q))
    }
}
