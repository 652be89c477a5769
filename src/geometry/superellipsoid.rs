//! POV-Ray's `superellipsoid { <e, n> }` (reference 3.4.6.11): the points of object space where
//! `(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1`, inside where the left side is below 1, all
//! within the unit box. `e` shapes the cross-sections in xy, `n` the profile along z.
//!
//! Solved per lane in f64 (this shape has no 8-wide arithmetic: packets run it lane by lane, as
//! the torus): the ray is clipped to the unit box, cut where it crosses the planes x = 0, y = 0,
//! z = 0 and x = ±y (between them the function is smooth and, for e, n ≤ 2, convex along the
//! ray), and each piece is sampled for the first sign change, which bisection then narrows to
//! f64 precision. A piece that does not change sign at its samples but whose smallest sample
//! comes close to the surface is searched for its minimum (golden section), so rays that graze
//! the surface between two samples still hit it.

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::{transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

/// Samples per piece of the ray.
const SAMPLES: usize = 12;
/// Golden-section steps of the grazing search: 0.618⁴⁰ ≈ 4e-9 of the two steps searched.
const GOLDEN_STEPS: usize = 40;

#[derive(Clone, Copy, Debug)]
pub struct Superellipsoid {
    pub frame: BoxFrame,
    /// POV-Ray's east-west exponent `e` and north-south exponent `n`.
    pub e: f64,
    pub n: f64,
    pub min: Vec3,
    pub max: Vec3,
}

impl Superellipsoid {
    pub fn new(render_from_object: Affine3A, e: f64, n: f64) -> Superellipsoid {
        let (min, max) = transformed_bounds(&render_from_object, Vec3::splat(-1.0), Vec3::ONE);
        Superellipsoid { frame: frame_for(render_from_object), e, n, min, max }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// The implicit function minus 1: negative inside.
    pub fn eval(&self, q: [f64; 3]) -> f64 {
        let g = q[0].abs().powf(2.0 / self.e) + q[1].abs().powf(2.0 / self.e);
        g.powf(self.e / self.n) + q[2].abs().powf(2.0 / self.n) - 1.0
    }

    /// Its gradient.
    pub fn gradient(&self, q: [f64; 3]) -> [f64; 3] {
        let a = 2.0 / self.e;
        let g = q[0].abs().powf(a) + q[1].abs().powf(a);
        let outer = if g > 0.0 { (2.0 / self.n) * g.powf(self.e / self.n - 1.0) } else { 0.0 };
        let axis = |v: f64, p: f64| if v == 0.0 { 0.0 } else { v.signum() * v.abs().powf(p - 1.0) };
        [outer * axis(q[0], a), outer * axis(q[1], a), (2.0 / self.n) * axis(q[2], 2.0 / self.n)]
    }

    /// The nearest `t` in `(t_min, t_max)` where `o + t·d` (object space) meets the surface.
    fn solve(&self, o: [f64; 3], d: [f64; 3], t_min: f64, t_max: f64) -> Option<f64> {
        if t_max.is_nan() || t_min.is_nan() || t_max <= t_min {
            return None;
        }
        // The unit box, slightly padded.
        let (mut lo, mut hi) = (t_min, t_max);
        for a in 0..3 {
            let inv = 1.0 / d[a];
            let (t0, t1) = ((-1.0 - 1e-9 - o[a]) * inv, (1.0 + 1e-9 - o[a]) * inv);
            let (t0, t1) = if t0 < t1 { (t0, t1) } else { (t1, t0) };
            if t0.is_nan() {
                // d[a] = 0: inside the slab or not.
                if o[a].abs() > 1.0 + 1e-9 {
                    return None;
                }
                continue;
            }
            lo = lo.max(t0);
            hi = hi.min(t1);
        }
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return None;
        }
        // Cuts where the ray crosses x = 0, y = 0, z = 0, x = y and x = −y.
        let mut cuts = [0.0; 7];
        let mut count = 0;
        for t in
            [-o[0] / d[0], -o[1] / d[1], -o[2] / d[2], (o[1] - o[0]) / (d[0] - d[1]), -(o[0] + o[1]) / (d[0] + d[1])]
        {
            if t > lo && t < hi {
                cuts[count] = t;
                count += 1;
            }
        }
        cuts[count] = hi;
        count += 1;
        cuts[..count].sort_unstable_by(f64::total_cmp);
        let f = |t: f64| self.eval([o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]]);
        let mut a = lo;
        let mut fa = f(a);
        for &b in &cuts[..count] {
            if let Some(t) = self.piece(&f, a, fa, b) {
                return (t > t_min && t < t_max).then_some(t);
            }
            a = b;
            fa = f(a);
        }
        None
    }

    /// The first root of `f` in `(a, b]`, `fa = f(a)`.
    fn piece(&self, f: &impl Fn(f64) -> f64, a: f64, fa: f64, b: f64) -> Option<f64> {
        let step = (b - a) / SAMPLES as f64;
        let (mut t0, mut f0) = (a, fa);
        let (mut best, mut f_best) = (a, fa);
        for k in 1..=SAMPLES {
            let t1 = if k == SAMPLES { b } else { a + step * k as f64 };
            let f1 = f(t1);
            if (f0 > 0.0) != (f1 > 0.0) {
                return Some(bisect(f, t0, t1, f0 > 0.0));
            }
            if f1 < f_best {
                (best, f_best) = (t1, f1);
            }
            (t0, f0) = (t1, f1);
        }
        // No sign change seen from outside: a grazing ray may dip inside between samples, near
        // the smallest sample. Search the two steps around it for the minimum.
        if fa > 0.0 && f_best < 0.25 {
            let (mut l, mut h) = ((best - step).max(a), (best + step).min(b));
            // Golden section, each step reusing the inner point it keeps: one evaluation per
            // step, not two. 40 steps narrow two sample steps to 1e-8 of them. The search
            // (60 steps of two evaluations, each three `powf`s) was most of
            // objects/superel1.pov's time: rays passing near the surface all take it.
            let g = 0.618_033_988_749_895;
            let (mut m1, mut m2) = (h - g * (h - l), l + g * (h - l));
            let (mut f1, mut f2) = (f(m1), f(m2));
            for _ in 0..GOLDEN_STEPS {
                if f1 < f2 {
                    (h, m2, f2) = (m2, m1, f1);
                    m1 = h - g * (h - l);
                    f1 = f(m1);
                } else {
                    (l, m1, f1) = (m1, m2, f2);
                    m2 = l + g * (h - l);
                    f2 = f(m2);
                }
            }
            let m = 0.5 * (l + h);
            if f(m) <= 0.0 {
                return Some(bisect(f, (best - step).max(a).min(m), m, true));
            }
        }
        None
    }
}

/// A root of `f` in `[a, b]` where `f(a) > 0` is `outside_at_a` and `f(b) > 0` is not, by
/// bisection.
fn bisect(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64, outside_at_a: bool) -> f64 {
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        // 1e-10 of the box: far below f32's resolution of the result, in 35 steps, not 60.
        if m <= a || m >= b || b - a <= 1e-10 {
            break;
        }
        if (f(m) > 0.0) == outside_at_a {
            a = m;
        } else {
            b = m;
        }
    }
    b
}

impl Shape for Superellipsoid {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        L::from_fn_f64(|i| {
            let v = |v: V3<L>| [v.x.get_f64(i), v.y.get_f64(i), v.z.get_f64(i)];
            self.solve(v(o), v(d), t_min.get_f64(i), t_max.get_f64(i)).unwrap_or(MISS as f64)
        })
    }

    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let q = p.transform_point(&self.frame.object_from_render);
        let mut g = [[0.0; 3]; 8];
        for (i, slot) in g.iter_mut().enumerate().take(L::WIDTH) {
            *slot = self.gradient([q.x.get_f64(i), q.y.get_f64(i), q.z.get_f64(i)]);
        }
        let n = V3 { x: L::from_fn_f64(|i| g[i][0]), y: L::from_fn_f64(|i| g[i][1]), z: L::from_fn_f64(|i| g[i][2]) };
        n.mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }

    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = p.transform_point(&self.frame.object_from_render);
        L::mask_from_fn(|i| self.eval([q.x.get_f64(i), q.y.get_f64(i), q.z.get_f64(i)]) < 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lanes::F8;
    use crate::ray::Ray;

    fn at(e: f64, n: f64) -> Superellipsoid {
        Superellipsoid::new(Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)), e, n)
    }

    #[test]
    fn sphere_box_and_cylinder_limits() {
        // e = n = 1: the unit sphere.
        let s = at(1.0, 1.0);
        let r = Ray::new(Vec3::new(0.3, 0.2, 0.0), Vec3::Z);
        let t = s.intersect(&r, 0.0, MISS).expect("sphere");
        let want = 10.0 - (1.0f32 - 0.09 - 0.04).sqrt();
        assert!((t - want).abs() < 1e-5, "{t} vs {want}");
        let n = s.normal_at(r.at(t));
        assert!((n - (r.at(t) - Vec3::new(0.0, 0.0, 10.0)).normalize()).length() < 1e-4, "{n}");
        // Small exponents: nearly the unit box, so a ray near a corner still hits at z ≈ 9.
        let b = at(0.05, 0.05);
        let t = b.intersect(&Ray::new(Vec3::new(0.9, 0.9, 0.0), Vec3::Z), 0.0, MISS).expect("box");
        assert!((t - 9.0).abs() < 0.05, "{t}");
        // e = 1, n small: a cylinder along z with flat ends.
        let c = at(1.0, 0.05);
        let t = c.intersect(&Ray::new(Vec3::new(-5.0, 0.0, 10.5), Vec3::X), 0.0, MISS).expect("wall");
        assert!((t - 4.0).abs() < 1e-3, "{t}");
        assert!(c.intersect(&Ray::new(Vec3::new(-5.0, 0.9, 10.0 + 0.95), Vec3::X), 0.0, MISS).is_some_and(|t| t < 5.0));
        // Inside, and a ray from inside meets the far wall.
        assert!(
            s.inside(V3::from_vec3(Vec3::new(0.0, 0.0, 10.0))) && !s.inside(V3::from_vec3(Vec3::new(0.0, 0.0, 11.1)))
        );
        let t = s.intersect(&Ray::new(Vec3::new(0.0, 0.0, 10.0), Vec3::X), 0.0, MISS).expect("from inside");
        assert!((t - 1.0).abs() < 1e-5);
    }

    #[test]
    fn grazing_rays_along_axes_and_packets() {
        let s = at(0.5, 2.0);
        // Straight down the z axis and along x through the centre.
        assert!(s
            .intersect(&Ray::new(Vec3::new(0.0, 0.0, 0.0), Vec3::Z), 0.0, MISS)
            .is_some_and(|t| (t - 9.0).abs() < 1e-5));
        assert!(s
            .intersect(&Ray::new(Vec3::new(-3.0, 0.0, 10.0), Vec3::X), 0.0, MISS)
            .is_some_and(|t| (t - 2.0).abs() < 1e-5));
        // A ray just outside the bounding box misses.
        assert_eq!(s.intersect(&Ray::new(Vec3::new(-3.0, 1.01, 10.0), Vec3::X), 0.0, MISS), None);
        let rays: [Ray; 8] = std::array::from_fn(|i| {
            let o = Vec3::new(i as f32 * 0.3 - 1.0, 0.1 * i as f32, 0.0);
            Ray::new(o, (Vec3::new(0.2, 0.3, 10.0) - o).normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let wide = s.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, r) in rays.iter().enumerate() {
            assert_eq!(wide.get(i).to_bits(), s.hit(&r.lanes(), 0.0, MISS).to_bits());
            assert!(wide.get(i) != MISS);
        }
    }
}
