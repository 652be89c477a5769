//! POV-Ray's `superellipsoid { <e, n> }` (reference 3.4.6.11): the points of object space where
//! `(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1`, inside where the left side is below 1, all
//! within the unit box. `e` shapes the cross-sections in xy, `n` the profile along z.
//!
//! Solved per lane in f64 (this shape has no 8-wide arithmetic: packets run it lane by lane, as
//! the torus, with the same scalar code, so a packet's lanes equal single rays bit for bit), on
//! the ray clipped to the unit box.
//!
//! For e, n ≤ 2 (almost every scene's shapes) the surface is the unit sphere of the norm
//! `N(q) = ((|x|^a + |y|^a)^(b/a) + |z|^b)^(1/b)`, a = 2/e ≥ 1, b = 2/n ≥ 1: convex along the
//! whole ray and of degree 1, so Newton's method on `N − 1` from the box entry rises
//! monotonically to the first root in a few steps, and stops exactly for a grazing miss (where
//! the slope turns non-negative above the surface). One `log2` per coordinate serves the powers;
//! exponents 1 and 2 are multiplications. Issue 38: the kernel scene (<0.3, 0.3>) went from
//! ~1180 ns per ray-shape test (46 % of the frame in `pow`) to about a tenth.
//!
//! Otherwise (e or n > 2, non-convex), and where Newton gives up, the ray is cut where it
//! crosses the planes x = 0, y = 0, z = 0 and x = ±y (between them the function is smooth), and
//! each piece is sampled for the first sign change, which bisection then narrows to f64
//! precision. A piece that does not change sign at its samples but whose smallest sample comes
//! close to the surface is searched for its minimum (golden section), so rays that graze the
//! surface between two samples still hit it.

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::{transformed_bounds, CullBox, Shape};
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
    /// The convex solver's powers of `e` and `n`, worked out once, not per ray.
    powers: Powers,
    /// The object-space box, for culling lanes before the f64 solve.
    cull: CullBox,
}

impl Superellipsoid {
    pub fn new(render_from_object: Affine3A, e: f64, n: f64) -> Superellipsoid {
        let (min, max) = transformed_bounds(&render_from_object, Vec3::splat(-1.0), Vec3::ONE);
        let cull = CullBox::new(glam::DVec3::splat(-1.0), glam::DVec3::ONE);
        Superellipsoid { frame: frame_for(render_from_object), e, n, min, max, powers: Powers::new(e, n), cull }
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
        if self.e <= 2.0 && self.n <= 2.0 {
            if let Some(hit) = self.solve_convex(o, d, lo, hi) {
                return hit.filter(|&t| t > t_min && t < t_max);
            }
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

    /// The norm `N(q) = ((|x|^a + |y|^a)^(b/a) + |z|^b)^(1/b)` (a = 2/e, b = 2/n) whose unit
    /// sphere is the surface, and its one-sided derivative at `q` along `v`. For e, n ≤ 2 both
    /// exponents are at least 1, so `N` is a norm (a b-norm of an a-norm and |z|): convex along
    /// every line, and of degree 1, so that Newton's method on `N − 1` meets no steep powers.
    #[inline(always)]
    fn norm_slope(&self, p: &Powers, q: [f64; 3], v: [f64; 3]) -> (f64, f64) {
        let (x, y, z) = (q[0].abs(), q[1].abs(), q[2].abs());
        let (px, py, pz) = (p.a.of(x), p.a.of(y), p.b.of(z));
        let g = px + py;
        let big_g = p.e_over_n.of(g);
        let s = big_g + pz;
        let norm = p.inv_b.of(s);
        if s == 0.0 {
            // At the centre: the norm of v.
            let (x, y, z) = (v[0].abs(), v[1].abs(), v[2].abs());
            let g = p.a.of(x) + p.a.of(y);
            return (0.0, p.inv_b.of(p.e_over_n.of(g) + p.b.of(z)));
        }
        // d/dv of S = G + Z, over b: G/g · (X/x·vx + Y/y·vy) + Z/z·vz, where a term whose
        // coordinate is 0 is its one-sided limit (|v| for an exponent of 1, else 0).
        let axis = |pw: f64, c: f64, vc: f64, one: bool| {
            if c != 0.0 {
                pw / c * vc
            } else if one {
                vc.abs()
            } else {
                0.0
            }
        };
        let txy = if g > 0.0 {
            let t = axis(px, x, v[0] * q[0].signum(), p.a_one) + axis(py, y, v[1] * q[1].signum(), p.a_one);
            if p.e_over_n.is_one() {
                t
            } else {
                big_g / g * t
            }
        } else if p.b_one {
            p.inv_a.of(p.a.of(v[0].abs()) + p.a.of(v[1].abs()))
        } else {
            0.0
        };
        let tz = axis(pz, z, v[2] * q[2].signum(), p.b_one);
        (norm, norm / s * (txy + tz))
    }

    /// The convex solver (e, n ≤ 2) on the clipped segment `[lo, hi]`: `Some(None)` a miss,
    /// `Some(Some(t))` the first root, `None` gave up (the sampling path then decides).
    ///
    /// From outside (`N(lo) > 1`) Newton steps forward: each tangent lies below the convex
    /// `N`, so the steps rise monotonically to the first root, and a point where `N > 1` and
    /// the slope is not negative proves a miss (a grazing ray, decided exactly). From inside,
    /// the same from `hi` backwards finds the exit.
    fn solve_convex(&self, o: [f64; 3], d: [f64; 3], lo: f64, hi: f64) -> Option<Option<f64>> {
        let p = &self.powers;
        let at = |t: f64| [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
        let tol = NEWTON_TOL * (hi - lo);
        let (n_lo, s_lo) = self.norm_slope(p, at(lo), d);
        let (mut t, mut n, mut s, sign, v, end) = if n_lo > 1.0 {
            (lo, n_lo, s_lo, 1.0, d, hi)
        } else {
            let back = [-d[0], -d[1], -d[2]];
            let (n_hi, s_hi) = self.norm_slope(p, at(hi), back);
            if !(n_hi > 1.0) {
                return Some(None);
            }
            (hi, n_hi, s_hi, -1.0, back, lo)
        };
        for _ in 0..NEWTON_STEPS {
            if n.is_nan() || s.is_nan() {
                return None;
            }
            if s >= 0.0 {
                // Rising (or flat) away from the surface: no root ahead.
                return if sign > 0.0 { Some(None) } else { None };
            }
            let step = (n - 1.0) / -s;
            t += sign * step;
            if (t - end) * sign >= 0.0 {
                return if sign > 0.0 { Some(None) } else { None };
            }
            if step <= tol {
                return Some(Some(t));
            }
            (n, s) = self.norm_slope(p, at(t), v);
            if n <= 1.0 {
                return Some(Some(t));
            }
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

/// Newton steps of the convex solver before it gives the ray to the sampling path.
const NEWTON_STEPS: usize = 100;
/// The convex solver stops when a step is below this fraction of the clipped segment: the error
/// left is at most the next step (far smaller once the convergence is quadratic), below f32.
const NEWTON_TOL: f64 = 1e-9;

/// `v^k` for `v ≥ 0` and a constant `k`, with the exponents 1 and 2 as multiplications.
#[derive(Clone, Copy, Debug)]
struct Pow {
    k: f64,
    kind: u8,
}

impl Pow {
    fn new(k: f64) -> Pow {
        Pow {
            k,
            kind: if k == 1.0 {
                1
            } else if k == 2.0 {
                2
            } else if k == 0.5 {
                3
            } else {
                0
            },
        }
    }

    fn is_one(&self) -> bool {
        self.kind == 1
    }

    #[inline(always)]
    fn of(&self, v: f64) -> f64 {
        match self.kind {
            1 => v,
            2 => v * v,
            3 => v.sqrt(),
            _ => {
                if v == 0.0 {
                    0.0
                } else {
                    (v.log2() * self.k).exp2()
                }
            }
        }
    }
}

/// The powers of the convex solver.
#[derive(Clone, Copy, Debug)]
struct Powers {
    a: Pow,
    b: Pow,
    e_over_n: Pow,
    inv_a: Pow,
    inv_b: Pow,
    a_one: bool,
    b_one: bool,
}

impl Powers {
    fn new(e: f64, n: f64) -> Powers {
        let (a, b) = (2.0 / e, 2.0 / n);
        Powers {
            a: Pow::new(a),
            b: Pow::new(b),
            e_over_n: Pow::new(e / n),
            inv_a: Pow::new(e / 2.0),
            inv_b: Pow::new(n / 2.0),
            a_one: a == 1.0,
            b_one: b == 1.0,
        }
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
        // Lanes that miss the box, or trace nothing (a blocked shadow ray), are not solved.
        let Some(t_max) = self.cull.live(o, d, t_min, t_max) else { return L::splat(MISS) };
        L::from_fn_f64(|i| {
            let v = |v: V3<L>| [v.x.get_f64(i), v.y.get_f64(i), v.z.get_f64(i)];
            let (lo, hi) = (t_min.get_f64(i), t_max.get_f64(i));
            if !(lo < hi) {
                return MISS as f64;
            }
            self.solve(v(o), v(d), lo, hi).unwrap_or(MISS as f64)
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

    /// A small seeded generator for the randomized tests.
    struct Lcg(u64);

    impl Lcg {
        fn f(&mut self, lo: f64, hi: f64) -> f64 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
        }
    }

    const SHAPES: [(f64, f64); 12] = [
        (1.0, 1.0),
        (0.3, 0.3),
        (0.2, 0.2),
        (0.05, 0.05),
        (1.0, 0.15),
        (0.3, 1.5),
        (2.0, 0.5),
        (2.0, 2.0),
        (0.5, 2.0),
        (1.7, 0.8),
        (2.5, 2.5),
        (3.0, 0.6),
    ];

    fn shape(e: f64, n: f64) -> Superellipsoid {
        Superellipsoid::new(Affine3A::IDENTITY, e, n)
    }

    /// A random point of the surface: a direction scaled onto it (bisection on the ray from the
    /// centre, where the implicit function rises monotonically).
    fn surface_point(s: &Superellipsoid, r: &mut Lcg) -> [f64; 3] {
        let u = [r.f(-1.0, 1.0), r.f(-1.0, 1.0), r.f(-1.0, 1.0)];
        let (mut l, mut h) = (0.0, 10.0);
        for _ in 0..200 {
            let m = 0.5 * (l + h);
            if s.eval([u[0] * m, u[1] * m, u[2] * m]) > 0.0 {
                h = m;
            } else {
                l = m;
            }
        }
        [u[0] * l, u[1] * l, u[2] * l]
    }

    /// Random rays: from a sphere of radius 3 towards the unit box's neighbourhood, and grazing
    /// rays tangent to the surface at a random point, shifted slightly out or in along the
    /// normal (for convex shapes the former must miss, the latter hit).
    fn rays(s: &Superellipsoid, r: &mut Lcg, count: usize) -> Vec<([f64; 3], [f64; 3], i8)> {
        let mut out = Vec::new();
        for k in 0..count {
            if k % 3 != 2 {
                let u = [r.f(-1.0, 1.0), r.f(-1.0, 1.0), r.f(-1.0, 1.0)];
                let l = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt().max(1e-3);
                let o = [3.0 * u[0] / l, 3.0 * u[1] / l, 3.0 * u[2] / l];
                let target = [r.f(-1.2, 1.2), r.f(-1.2, 1.2), r.f(-1.2, 1.2)];
                let scale = r.f(0.2, 3.0);
                out.push((o, [(target[0] - o[0]) * scale, (target[1] - o[1]) * scale, (target[2] - o[2]) * scale], 0));
            } else {
                let q = surface_point(s, r);
                let g = s.gradient(q);
                let gl = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
                if !(gl > 1e-6) {
                    continue;
                }
                let nrm = [g[0] / gl, g[1] / gl, g[2] / gl];
                // A tangent direction: a random vector minus its normal part.
                let w = [r.f(-1.0, 1.0), r.f(-1.0, 1.0), r.f(-1.0, 1.0)];
                let wn = w[0] * nrm[0] + w[1] * nrm[1] + w[2] * nrm[2];
                let d = [w[0] - wn * nrm[0], w[1] - wn * nrm[1], w[2] - wn * nrm[2]];
                let dl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                if !(dl > 1e-6) {
                    continue;
                }
                let d = [d[0] / dl, d[1] / dl, d[2] / dl];
                let shift = [1e-4, -1e-4, 1e-7, -1e-7, 0.0][k % 5];
                let o = [
                    q[0] - 3.0 * d[0] + shift * nrm[0],
                    q[1] - 3.0 * d[1] + shift * nrm[1],
                    q[2] - 3.0 * d[2] + shift * nrm[2],
                ];
                out.push((
                    o,
                    d,
                    if shift > 0.0 {
                        1
                    } else if shift < 0.0 {
                        -1
                    } else {
                        0
                    },
                ));
            }
        }
        out
    }

    /// Dense sampling (40 000 samples over the unit box's chord): the first sample clearly
    /// inside (f ≤ −1e-9, where rounding cannot decide: a ray along a face of a nearly cubic
    /// shape has f within 1e-13 of 0 for long stretches) and the length of that inside stretch.
    fn brute(s: &Superellipsoid, o: [f64; 3], d: [f64; 3]) -> Option<(f64, f64)> {
        let (lo, hi) = chord(o, d)?;
        let f = |t: f64| s.eval([o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]]);
        let m = 40_000;
        let step = (hi - lo) / m as f64;
        for k in 1..=m {
            let t = lo + step * k as f64;
            if f(t) <= -1e-9 {
                let mut end = t;
                while end < hi && f(end) <= -1e-9 {
                    end += step;
                }
                return Some((t, end - t));
            }
        }
        None
    }

    /// The ray's `t` range in the unit box, padded as the solver pads it.
    fn chord(o: [f64; 3], d: [f64; 3]) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = (0.0f64, f64::INFINITY);
        for a in 0..3 {
            let (t0, t1) = ((-1.0 - 1e-9 - o[a]) / d[a], (1.0 + 1e-9 - o[a]) / d[a]);
            lo = lo.max(t0.min(t1));
            hi = hi.min(t0.max(t1));
        }
        (lo < hi).then_some((lo, hi))
    }

    #[test]
    fn solver_matches_dense_sampling_on_random_and_grazing_rays() {
        let mut r = Lcg(0x5eed_0038);
        for &(e, n) in &SHAPES {
            let s = shape(e, n);
            let convex = e <= 2.0 && n <= 2.0;
            for (o, d, graze) in rays(&s, &mut r, 150) {
                let got = s.solve(o, d, 0.0, f64::INFINITY);
                let want = brute(&s, o, d);
                let f = |t: f64| s.eval([o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]]);
                if let Some(t) = got {
                    // A point of the surface (f changes by about |∇f·d| ~ 1 per unit of t, so
                    // this is t within ~1e-7), with no sample clearly inside before it.
                    assert!(f(t).abs() < 1e-7, "<{e}, {n}> o {o:?} d {d:?}: {t}, f = {}", f(t));
                    let (lo, _) = chord(o, d).expect("a hit is in the box");
                    let m = 4_000;
                    for k in 0..m {
                        let u = lo + (t - lo) * k as f64 / m as f64;
                        assert!(f(u) > -1e-9, "<{e}, {n}> o {o:?} d {d:?}: {t} but inside at {u}");
                    }
                }
                if let Some((w, len)) = want {
                    // Where sampling finds the ray clearly inside, the solver hits no later;
                    // only the sampling path of a non-convex shape may step over a sliver.
                    let dl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                    match got {
                        Some(t) => assert!(t <= w, "<{e}, {n}> o {o:?} d {d:?}: {t} after {w}"),
                        None => assert!(
                            !convex && len * dl < 1e-3,
                            "<{e}, {n}> o {o:?} d {d:?}: missed the inside at {w} (for {len})"
                        ),
                    }
                }
                if convex && graze != 0 {
                    // The tangent line moved out misses a convex shape; moved in, it hits.
                    assert!(got.is_some() == (graze < 0), "<{e}, {n}> o {o:?} d {d:?}: grazing {graze} gave {got:?}");
                }
            }
        }
    }

    #[test]
    fn convex_solver_from_inside_finds_the_exit() {
        let mut r = Lcg(7);
        for &(e, n) in SHAPES.iter().filter(|(e, n)| *e <= 2.0 && *n <= 2.0) {
            let s = shape(e, n);
            for _ in 0..200 {
                let q = surface_point(&s, &mut r);
                let k = r.f(0.0, 0.99);
                let o = [q[0] * k, q[1] * k, q[2] * k];
                let d = [r.f(-1.0, 1.0), r.f(-1.0, 1.0), r.f(-1.0, 1.0)];
                let t = s.solve(o, d, 0.0, f64::INFINITY).expect("a ray from inside meets the surface");
                let p = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
                assert!(s.eval(p).abs() < 1e-6, "<{e}, {n}>: f = {}", s.eval(p));
                assert!(t > 0.0);
            }
        }
    }

    #[test]
    fn packets_match_single_rays_bit_for_bit() {
        let mut r = Lcg(99);
        for &(e, n) in &SHAPES {
            let s = Superellipsoid::new(
                Affine3A::from_scale_rotation_translation(
                    Vec3::new(0.7, 1.2, 0.9),
                    glam::Quat::from_euler(glam::EulerRot::XYZ, 0.3, -0.5, 0.2),
                    Vec3::new(0.2, -0.1, 6.0),
                ),
                e,
                n,
            );
            for _ in 0..40 {
                let rays: [Ray; 8] = std::array::from_fn(|_| {
                    let o = Vec3::new(r.f(-2.0, 2.0) as f32, r.f(-2.0, 2.0) as f32, r.f(-1.0, 1.0) as f32);
                    let target = Vec3::new(r.f(-1.5, 1.5) as f32, r.f(-1.5, 1.5) as f32, r.f(5.0, 7.0) as f32);
                    Ray::new(o, (target - o).normalize())
                });
                let packet = RayLanes::<F8> {
                    o: V3::from_lanes(|i| rays[i].origin),
                    d: V3::from_lanes(|i| rays[i].dir),
                    inv: V3::from_lanes(|i| rays[i].inv_dir),
                };
                let wide = s.hit(&packet, F8::splat(0.0), F8::splat(MISS));
                for (i, ray) in rays.iter().enumerate() {
                    assert_eq!(wide.get(i).to_bits(), s.hit(&ray.lanes(), 0.0, MISS).to_bits(), "<{e}, {n}> lane {i}");
                }
            }
        }
    }
}
