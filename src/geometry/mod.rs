//! Shapes and their ray tests, one file per kind, each written once for every path.
//!
//! A shape implements `Shape`: `hit` answers the nearest `t` in an open interval
//! `(t_min, t_max)` (or `MISS`) for one ray in f32, eight rays in f32 (`F8`, packets) or one ray
//! in f64 (`--precision f64` re-solving a hit), from the same formula; `normal` gives the
//! geometric normal, computed afterwards, only for the winning hit. The lane arithmetic is
//! `crate::lanes`; what every test shares (rays, `MISS`, root picking, offsets) is `ray`.
//!
//! Layer 4 of docs/design/architecture.md: uses `accel`, `desc`, `function`, `ray`; `shading`, `scene` and `render` use it.

/// `Shape` for a shape solved lane by lane in f64 in its object space (`self.frame`), written
/// once for julia_fractal, isosurface, sor, blob and parametric: `hit` is `self.solve(o, d,
/// t_min, t_max)` through `hit_lanes_f64`, `normal` the named object-space normal through
/// `normal_lanes_f64`, and `inside` the named object-space test through `inside_lanes_f64`
/// (`inside: none` for a shell with no inside). With `solve: rounded`, `solve` takes a fifth
/// argument, the lane's rounding (`Lane::round_f64`), so that a search may stop once its answer
/// is decided to the lane's precision; with `blocks: bracket` also a sixth, `any`, and `blocks`
/// is the solve with `any` set: it may answer any point of a bracket that certainly holds the
/// nearest root (see `Shape::blocks`). `hit` is not inlined into `Scene::hit_prim`:
/// the dispatch every shape shares stays small, so scenes without these kinds do not pay for
/// their code.
macro_rules! shape_solved_in_f64 {
    ($ty:ty, normal: $normal:ident, inside: none) => {
        shape_solved_in_f64!(@impl $ty, $normal, |_this: &$ty, _q: glam::DVec3| false,
            |this: &$ty, o: glam::DVec3, d: glam::DVec3, lo: f64, hi: f64, _round: fn(f64) -> f64| this.solve(o, d, lo, hi));
    };
    ($ty:ty, normal: $normal:ident, inside: $inside:ident) => {
        shape_solved_in_f64!(@impl $ty, $normal, |this: &$ty, q: glam::DVec3| this.$inside(q),
            |this: &$ty, o: glam::DVec3, d: glam::DVec3, lo: f64, hi: f64, _round: fn(f64) -> f64| this.solve(o, d, lo, hi));
    };
    ($ty:ty, normal: $normal:ident, inside: $inside:ident, solve: rounded, blocks: bracket) => {
        shape_solved_in_f64!(@impl $ty, $normal, |this: &$ty, q: glam::DVec3| this.$inside(q),
            |this: &$ty, o: glam::DVec3, d: glam::DVec3, lo: f64, hi: f64, round: fn(f64) -> f64| this.solve(o, d, lo, hi, round, false),
            fn blocks<L: $crate::lanes::Lane>(
                &self,
                ray: &$crate::ray::RayLanes<L>,
                t_min: L,
                t_max: L,
            ) -> L {
                $crate::geometry::hit_lanes_f64(&self.frame, ray, t_min, t_max, |o, d, lo, hi| {
                    self.solve(o, d, lo, hi, L::round_f64, true)
                })
            }
        );
    };
    (@impl $ty:ty, $normal:ident, $inside:expr, $solve:expr $(, $blocks:item)?) => {
        impl $crate::geometry::Shape for $ty {
            $(#[inline(never)] $blocks)?

            #[inline(never)]
            fn hit<L: $crate::lanes::Lane>(
                &self,
                ray: &$crate::ray::RayLanes<L>,
                t_min: L,
                t_max: L,
            ) -> L {
                let solve = $solve;
                $crate::geometry::hit_lanes_f64(&self.frame, ray, t_min, t_max, |o, d, lo, hi| {
                    solve(self, o, d, lo, hi, L::round_f64)
                })
            }

            fn normal<L: $crate::lanes::Lane>(&self, p: $crate::lanes::V3<L>) -> $crate::lanes::V3<L> {
                $crate::geometry::normal_lanes_f64(&self.frame, p, |q| self.$normal(q))
            }

            fn inside<L: $crate::lanes::Lane>(&self, p: $crate::lanes::V3<L>) -> L::Mask {
                let inside = $inside;
                $crate::geometry::inside_lanes_f64(&self.frame, p, |q| inside(self, q))
            }
        }
    };
}

pub mod bands;
pub mod bernstein;
pub mod blob;
pub mod cone;
mod cubic;
pub mod cuboid;
pub mod disc;
mod halley;
pub mod height_field;
mod height_walk;
pub mod isosurface;
mod isosurface_search;
pub mod julia;
mod julia_cells;
pub mod lathe;
pub mod lathe_linear;
pub mod lathe_quartic;
pub mod mesh;
pub mod parametric;
pub mod plane;
pub mod poly;
pub mod polygon;
pub mod prism;
mod quadric;
mod quartic;
pub mod revolved;
pub mod roots;
pub mod sor;
mod sor_lanes;
pub mod sphere;
pub mod spline;
mod sturm;
pub mod superellipsoid;
pub mod torus;
pub mod triangle;
pub mod uv;
mod wide;

#[cfg(test)]
pub(crate) mod test_support;

use glam::Vec3;

use crate::lanes::{Lane, V3};
use crate::ray::{Ray, RayLanes, MISS};

/// Render-space bounds of the object-space box `[lo, hi]` under `render_from_object`: the box
/// of its eight transformed corners.
pub fn transformed_bounds(render_from_object: &glam::Affine3A, lo: Vec3, hi: Vec3) -> (Vec3, Vec3) {
    let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for i in 0..8 {
        let c = Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        let w = render_from_object.transform_point3(c);
        min = min.min(w);
        max = max.max(w);
    }
    (min, max)
}

/// An object-space box that eight lanes are tested against before a shape solves them one by
/// one in f64: `new` widens the shape's box by 10⁻⁴ of its size (its corners are rounded to
/// f32), and `live` drops the lanes whose ray certainly misses it.
#[derive(Clone, Copy, Debug)]
pub struct CullBox {
    lo: Vec3,
    hi: Vec3,
}

impl CullBox {
    /// The box `[lo, hi]` (object space, f64), widened.
    pub fn new(lo: glam::DVec3, hi: glam::DVec3) -> CullBox {
        let widen = 1e-4 * (hi - lo).max_element().max(lo.abs().max(hi.abs()).max_element());
        CullBox { lo: (lo - widen).as_vec3(), hi: (hi + widen).as_vec3() }
    }

    /// `t_max`, or −inf (an empty interval, which a solve answers at once) for the lanes whose
    /// object-space ray `o + t·d` misses the box within `(t_min, t_max)`; `None` when every lane
    /// does. In the lanes' own arithmetic, with a margin of 10⁻⁵ of the distances (far above
    /// the slab test's rounding), so a lane the f64 solve would find a hit for is never dropped,
    /// and packets and single rays keep the same bits. Most lanes of a packet that reaches a
    /// prism or a torus miss its box (three in five on the kernel scenes).
    #[inline(always)]
    pub fn live<L: Lane>(&self, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> Option<L> {
        let (near, far) = crate::accel::aabb::node_slabs(V3::splat(self.lo), V3::splat(self.hi), o, d.recip());
        live_between(near, far, t_min, t_max)
    }
}

/// `t_max`, or −inf for the lanes whose slab entry `near` and exit `far`, widened by 10⁻⁵ of
/// the distances, leave nothing of `(t_min, t_max)`; `None` when every lane does. What
/// `CullBox::live` answers, for culls with other slabs (the prism's turned box).
#[inline(always)]
pub fn live_between<L: Lane>(near: L, far: L, t_min: L, t_max: L) -> Option<L> {
    let margin = (near.abs() + far.abs()) * L::splat(1e-5);
    let (near, far) = (near - margin, far + margin);
    let live = L::and(near.le(far), L::and(near.le(t_max), t_min.le(far)));
    if !L::any(live) {
        return None;
    }
    Some(L::select(live, t_max, L::splat(f32::NEG_INFINITY)))
}

/// The hit of a shape solved lane by lane in f64 in its object space (`frame`): `solve(o, d,
/// t_min, t_max)` answers the nearest root in the open interval. Each root is compared with
/// `t_min` as the lane will hold it (`Lane::round_f64`), and one that rounds onto `t_min` is
/// stepped past, so CSG searching on from a crossing finds the next one, not that one again.
#[inline(always)]
pub fn hit_lanes_f64<L: Lane>(
    frame: &cuboid::BoxFrame,
    ray: &RayLanes<L>,
    t_min: L,
    t_max: L,
    solve: impl Fn(glam::DVec3, glam::DVec3, f64, f64) -> Option<f64>,
) -> L {
    let o = ray.o.transform_point(&frame.object_from_render);
    let d = ray.d.transform_vector(&frame.object_from_render);
    solve_lanes_f64(o, d, t_min, t_max, |_, o, d, lo, hi| solve(o, d, lo, hi))
}

/// `hit_lanes_f64` for a ray already in object space (`o + t·d`), where `solve` also learns
/// which lane it answers (`solve(lane, o, d, t_min, t_max)`): for shapes that first rule lanes
/// out eight at a time (`revolved`).
#[inline(always)]
pub fn solve_lanes_f64<L: Lane>(
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
    solve: impl Fn(usize, glam::DVec3, glam::DVec3, f64, f64) -> Option<f64>,
) -> L {
    L::from_fn_f64(|i| solve_lane_f64(i, o, d, t_min, t_max, &solve))
}

/// Lane `i` of `solve_lanes_f64`, as f64.
#[inline(always)]
pub fn solve_lane_f64<L: Lane>(
    i: usize,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
    solve: &impl Fn(usize, glam::DVec3, glam::DVec3, f64, f64) -> Option<f64>,
) -> f64 {
    solve_lane_tagged_f64(i, o, d, t_min, t_max, &|i, o, d, lo, hi| solve(i, o, d, lo, hi).map(|t| (t, ()))).0
}

/// `solve_lane_f64` where `solve` also names what its root lies on (a prism's side or cap):
/// the lane's hit and the tag of the root taken, `None` where it missed.
#[inline(always)]
pub fn solve_lane_tagged_f64<L: Lane, T>(
    i: usize,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
    solve: &impl Fn(usize, glam::DVec3, glam::DVec3, f64, f64) -> Option<(f64, T)>,
) -> (f64, Option<T>) {
    let v = |v: V3<L>| glam::DVec3::new(v.x.get_f64(i), v.y.get_f64(i), v.z.get_f64(i));
    let (lo, hi) = (t_min.get_f64(i), t_max.get_f64(i));
    // An empty interval holds no root: lanes a packet does not trace (a blocked shadow
    // ray, a lane culled by its box) cost no solve.
    if !(lo < hi) {
        return (MISS as f64, None);
    }
    let mut from = lo;
    for _ in 0..4 {
        let Some((t, tag)) = solve(i, v(o), v(d), from, hi) else { break };
        if L::round_f64(t) > lo {
            return (L::round_f64(t).min(hi), Some(tag));
        }
        from = t;
    }
    (MISS as f64, None)
}

/// `normal` of a shape that computes its object-space normal per point in f64.
#[inline(always)]
pub fn normal_lanes_f64<L: Lane>(
    frame: &cuboid::BoxFrame,
    p: V3<L>,
    normal: impl Fn(glam::DVec3) -> glam::DVec3,
) -> V3<L> {
    let q = p.transform_point(&frame.object_from_render);
    let n: [glam::DVec3; 8] = std::array::from_fn(|i| {
        if i < L::WIDTH {
            normal(glam::DVec3::new(q.x.get_f64(i), q.y.get_f64(i), q.z.get_f64(i)))
        } else {
            glam::DVec3::Y
        }
    });
    let n = V3 { x: L::from_fn_f64(|i| n[i].x), y: L::from_fn_f64(|i| n[i].y), z: L::from_fn_f64(|i| n[i].z) };
    n.mat3_mul(&frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
}

/// `inside` of a shape that answers per point in f64 in its object space (`frame`).
#[inline(always)]
pub fn inside_lanes_f64<L: Lane>(frame: &cuboid::BoxFrame, p: V3<L>, inside: impl Fn(glam::DVec3) -> bool) -> L::Mask {
    let q = p.transform_point(&frame.object_from_render);
    L::mask_from_fn(|i| inside(glam::DVec3::new(q.x.get_f64(i), q.y.get_f64(i), q.z.get_f64(i))))
}

/// An f64 affine map as f32: the cast every shape's frame goes through once, after composing
/// in f64.
/// A ray `o + t·d` (object space) taken about its point nearest the object origin, so that
/// polynomial surfaces are solved in well-scaled numbers: `p` is that point, `u` the unit
/// direction, and a distance `s` along `u` from `p` is at `t = t_c + s / len`.
#[derive(Clone, Copy, Debug)]
pub struct CentredRay {
    pub p: [f64; 3],
    pub u: [f64; 3],
    pub t_c: f64,
    pub len: f64,
}

/// `o + t·d` as a `CentredRay`; `None` for a zero, infinite or NaN direction.
#[inline]
pub fn centred_ray(o: [f64; 3], d: [f64; 3]) -> Option<CentredRay> {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let len2 = dot(d, d);
    // NaN compares false everywhere: each test also rejects it.
    if len2.is_nan() || len2 <= 0.0 || !len2.is_finite() {
        return None;
    }
    let len = len2.sqrt();
    let u = [d[0] / len, d[1] / len, d[2] / len];
    let t_c = -dot(o, d) / len2;
    let p = [o[0] + t_c * d[0], o[1] + t_c * d[1], o[2] + t_c * d[2]];
    Some(CentredRay { p, u, t_c, len })
}

/// A ray's squared distance from the y axis, `dh2·t² + 2·odh·t + oh2` (`dh2 = d.x² + d.z²`,
/// `odh = o.x·d.x + o.z·d.z`, `oh2 = o.x² + o.z²`), formed once per ray for the bands of a
/// surface of revolution's pieces.
#[derive(Clone, Copy, Debug)]
pub struct RadialRay {
    pub dh2: f64,
    pub odh: f64,
    pub oh2: f64,
    /// Where the distance is least, `−odh / dh2` (NaN for a ray along the axis).
    near: f64,
}

impl RadialRay {
    #[inline]
    pub fn new(o: glam::DVec3, d: glam::DVec3) -> RadialRay {
        let (dh2, odh) = (d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z);
        RadialRay { dh2, odh, oh2: o.x * o.x + o.z * o.z, near: -odh / dh2 }
    }

    /// The span of `t` where the ray's squared distance from the axis is at most `r2`,
    /// both widened by a part in 10⁹ (so a root on its edge stays inside, as `misses` keeps
    /// it); `None` if the ray keeps farther away or runs along the axis.
    #[inline]
    pub fn within(&self, r2: f64) -> Option<(f64, f64)> {
        let r2 = r2 + 1e-9 * (r2.abs() + self.oh2);
        let disc = self.odh * self.odh - self.dh2 * (self.oh2 - r2);
        if !(disc >= 0.0 && self.dh2 > 0.0) {
            return None;
        }
        let q = -(self.odh + disc.sqrt().copysign(self.odh));
        let (a, b) = if q == 0.0 { (0.0, 0.0) } else { (q / self.dh2, (self.oh2 - r2) / q) };
        let pad = 1e-9 * (a.abs() + b.abs()) + 1e-9 * (r2.abs() / self.dh2).sqrt();
        Some((a.min(b) - pad, a.max(b) + pad))
    }

    /// Whether the ray keeps clear of the band `r2_min ..= r2_max` for `t` in `[lo, hi]`: its
    /// squared distance stays above `r2_max` or below `r2_min` there. The radius of every point
    /// of a lathe piece or sor segment lies in its band, so such a ray cannot meet it and its
    /// polynomial need not be solved: POV-Ray's per-segment bounding cylinders, as an exact
    /// test. Padded by a part in 10⁹, so rounding never skips a crossing.
    #[inline]
    pub fn misses(&self, lo: f64, hi: f64, r2_min: f64, r2_max: f64) -> bool {
        let q = |t: f64| (self.dh2 * t + 2.0 * self.odh) * t + self.oh2;
        let (q_lo, q_hi) = (q(lo), q(hi));
        let q_max = q_lo.max(q_hi);
        // The parabola's lowest point, where it falls inside the span.
        let q_min = if self.dh2 > 0.0 && self.near > lo && self.near < hi { q(self.near) } else { q_lo.min(q_hi) };
        let pad = 1e-9 * (q_max.abs() + r2_max.abs()) + 1e-300;
        // NaN or infinite spans compare false: never skipped.
        q_min > r2_max + pad || q_max < r2_min - pad
    }
}

pub fn affine_f32(a: &glam::DAffine3) -> glam::Affine3A {
    glam::Affine3A::from_mat3_translation(a.matrix3.as_mat3(), a.translation.as_vec3())
}

/// A surface rays can hit.
pub trait Shape {
    /// The nearest hit in `(t_min, t_max)` for each lane, `MISS` where there is none.
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L;

    /// The outward geometric normal at points on the surface (render space), unit length.
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L>;

    /// Which points lie inside the solid (render space), as CSG asks: POV-Ray's `Inside`.
    /// Flat shapes (triangles, polygons, discs) have no inside and answer false everywhere;
    /// points on the surface may answer either way.
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask;

    /// For shadow rays: `MISS` exactly where `hit` answers `MISS`, and elsewhere a `t` in
    /// `(t_min, t_max)` that need not be the nearest hit's. A shape whose nearest root costs a
    /// refinement (a bisection, a polish) answers as soon as a bracket lying inside the interval
    /// certainly holds the root `hit` would answer, so the decision, blocked or not, is `hit`'s
    /// bit for bit and only its cost differs.
    #[inline(always)]
    fn blocks<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.hit(ray, t_min, t_max)
    }

    /// `hit` for one f32 ray, `None` for a miss.
    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        let t = self.hit(&ray.lanes(), t_min, t_max);
        (t != MISS).then_some(t)
    }

    /// `normal` at one point.
    #[inline]
    fn normal_at(&self, p: Vec3) -> Vec3 {
        self.normal(V3::from_vec3(p)).vec3()
    }
}
