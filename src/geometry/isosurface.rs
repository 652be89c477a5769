//! POV-Ray's `isosurface` (3.4.6.2): the surface where a user function equals `threshold`,
//! inside a `contained_by` box or sphere; inside is where the function is below the
//! threshold. Unless `open`, the container's own surface closes the solid where it cuts it.
//!
//! The ray is searched inside the container, in f64 per lane: an interval whose ends have the
//! same sign cannot hold a root when `|g(a)| + |g(b)| > max_gradient · length` (the function
//! cannot change faster than `max_gradient` per unit of distance, the promise the scene
//! makes), and is skipped; any other is halved, nearer half first, down to `accuracy`. A
//! crossing found is then narrowed by secant steps until the lane's rounding of it is decided,
//! so shading and shadow rays start on the surface. The eight lanes of a packet search side by
//! side (`isosurface_search`), each step's samples evaluated in one pass of the function's code
//! (`Program::eval_lanes`). The normal is the function's gradient by central differences.

use glam::{DAffine3, DVec3, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::isosurface_search::{Search, STACK};
use super::{affine_f32, transformed_bounds, Shape};
use crate::desc::{Container, IsoParams};
use crate::function::Program;
use crate::lanes::{Lane, V3};
use crate::ray::RayLanes;

#[derive(Clone, Debug)]
pub struct Isosurface {
    pub frame: BoxFrame,
    function: Program,
    container: Container,
    params: IsoParams,
    pub min: Vec3,
    pub max: Vec3,
}

impl Container {
    /// The span of `t` where `o + t·d` lies inside, if the line meets it.
    pub(crate) fn span(&self, o: DVec3, d: DVec3) -> Option<(f64, f64)> {
        match *self {
            Container::Box { min, max } => {
                let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
                for i in 0..3 {
                    if d[i] == 0.0 {
                        if o[i] < min[i] || o[i] > max[i] {
                            return None;
                        }
                        continue;
                    }
                    let (a, b) = ((min[i] - o[i]) / d[i], (max[i] - o[i]) / d[i]);
                    lo = lo.max(a.min(b));
                    hi = hi.min(a.max(b));
                }
                (lo <= hi).then_some((lo, hi))
            }
            Container::Sphere { center, radius } => {
                let oc = o - center;
                let (a, b, c) = (d.dot(d), oc.dot(d), oc.dot(oc) - radius * radius);
                let disc = b * b - a * c;
                if disc < 0.0 || a == 0.0 {
                    return None;
                }
                let s = disc.sqrt();
                Some(((-b - s) / a, (-b + s) / a))
            }
        }
    }

    pub fn contains(&self, q: DVec3) -> bool {
        match *self {
            Container::Box { min, max } => q.cmpge(min).all() && q.cmple(max).all(),
            Container::Sphere { center, radius } => (q - center).length_squared() <= radius * radius,
        }
    }

    /// How far `q` is from the container's surface, and the outward normal there.
    fn surface(&self, q: DVec3) -> (f64, DVec3) {
        match *self {
            Container::Box { min, max } => {
                let mut best = (f64::INFINITY, DVec3::Y);
                for i in 0..3 {
                    let mut n = DVec3::ZERO;
                    for (face, sign) in [(min[i], -1.0), (max[i], 1.0)] {
                        let dist = (q[i] - face).abs();
                        if dist < best.0 {
                            n[i] = sign;
                            best = (dist, n);
                            n = DVec3::ZERO;
                        }
                    }
                }
                best
            }
            Container::Sphere { center, radius } => {
                let r = q - center;
                ((r.length() - radius).abs(), r.normalize_or(DVec3::Y))
            }
        }
    }

    /// The object-space box it fills.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        match *self {
            Container::Box { min, max } => (min, max),
            Container::Sphere { center, radius } => (center - radius, center + radius),
        }
    }
}

impl Isosurface {
    pub fn new(render_from_object: DAffine3, function: Program, container: Container, params: IsoParams) -> Isosurface {
        let xf = affine_f32(&render_from_object);
        let (lo, hi) = container.bounds();
        let (min, max) = transformed_bounds(&xf, lo.as_vec3(), hi.as_vec3());
        let pad = (max - min).max(min.abs().max(max.abs())) * 4.0 * f32::EPSILON;
        Isosurface { frame: frame_for(xf), function, container, params, min: min - pad, max: max + pad }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// The function less the threshold: negative inside.
    #[inline]
    fn g(&self, q: DVec3) -> f64 {
        self.function.eval(&[q.x, q.y, q.z]) - self.params.threshold
    }

    /// The nearest hit of each lane: the lanes' searches (`Search`) advanced side by side,
    /// the function evaluated for all of them in one pass per step.
    #[inline(always)]
    fn hit_n<L: Lane, const N: usize>(&self, ray: &RayLanes<L>, t_min: L, t_max: L, any: bool) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        let v = |v: V3<L>, i: usize| DVec3::new(v.x.get_f64(i), v.y.get_f64(i), v.z.get_f64(i));
        let mut stacks = [[(0.0, 0.0); STACK]; N];
        let mut stack = stacks.iter_mut();
        let mut lanes: [Search; N] = std::array::from_fn(|i| {
            let (lo, hi) = if i < L::WIDTH { (t_min.get_f64(i), t_max.get_f64(i)) } else { (0.0, f64::NAN) };
            let stack = stack.next().expect("one stack per lane");
            Search::new(&self.container, &self.params, L::round_f64, v(o, i), v(d, i), lo, hi, any, stack)
        });
        loop {
            let mut args = [[0.0; N]; 3];
            let mut any = false;
            for (i, s) in lanes.iter().enumerate() {
                if let Some(t) = s.want() {
                    let q = s.o + t * s.d;
                    (args[0][i], args[1][i], args[2][i]) = (q.x, q.y, q.z);
                    any = true;
                }
            }
            if !any {
                break;
            }
            let g = self.function.eval_lanes(&args);
            for (s, g) in lanes.iter_mut().zip(g) {
                if s.want().is_some() {
                    s.tell(g - self.params.threshold);
                }
            }
        }
        L::from_fn_f64(|i| lanes[i].answer())
    }

    /// `hit_n` with as many searches as the lanes.
    #[inline(always)]
    fn hit_lanes<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L, any: bool) -> L {
        if L::WIDTH == 1 {
            self.hit_n::<L, 1>(ray, t_min, t_max, any)
        } else {
            self.hit_n::<L, 8>(ray, t_min, t_max, any)
        }
    }

    fn normal_object(&self, q: DVec3) -> DVec3 {
        if !self.params.open {
            let (dist, n) = self.container.surface(q);
            if dist < self.params.accuracy && self.g(q) < 0.0 {
                return n;
            }
        }
        let h = (self.params.accuracy * 0.1).max(1e-7);
        let diff = |e: DVec3| self.g(q + e) - self.g(q - e);
        DVec3::new(diff(DVec3::X * h), diff(DVec3::Y * h), diff(DVec3::Z * h))
    }

    fn inside_object(&self, q: DVec3) -> bool {
        self.container.contains(q) && self.g(q) < 0.0
    }
}

impl Shape for Isosurface {
    #[inline(never)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.hit_lanes(ray, t_min, t_max, false)
    }

    /// The search with `any`: a crossing bracketed inside the interval is not narrowed.
    #[inline(never)]
    fn blocks<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.hit_lanes(ray, t_min, t_max, true)
    }

    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        super::normal_lanes_f64(&self.frame, p, |q| self.normal_object(q))
    }

    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        super::inside_lanes_f64(&self.frame, p, |q| self.inside_object(q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::function::{Internal, Node};
    use crate::geometry::Shape;
    use crate::lanes::V3;
    use crate::ray::Ray;
    use crate::ray::RayLanes;

    fn sphere_fn(r: f64) -> Program {
        let body =
            Node::Internal(Internal::Sphere, vec![Node::Param(0), Node::Param(1), Node::Param(2), Node::Const(r)]);
        Program::compile(&body, 3)
    }

    fn unit_box() -> Container {
        Container::Box { min: DVec3::splat(-2.0), max: DVec3::splat(2.0) }
    }

    #[test]
    fn a_sphere_function_hits_where_the_sphere_does() {
        let iso = Isosurface::new(DAffine3::IDENTITY, sphere_fn(1.0), unit_box(), IsoParams::default());
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        let t = iso.intersect(&ray, 0.0, f32::INFINITY).expect("hit");
        assert!((t - 4.0).abs() < 1e-5, "{t}");
        assert!((iso.normal_at(Vec3::new(0.0, 0.0, -1.0)) - -Vec3::Z).length() < 1e-4);
        // From inside: the far side; CSG asking past the first crossing finds the second.
        assert!((iso.intersect(&ray, 4.001, f32::INFINITY).expect("second") - 6.0).abs() < 1e-5);
        let off = Ray::new(Vec3::new(0.0, 1.5, -5.0), Vec3::Z);
        assert_eq!(iso.intersect(&off, 0.0, f32::INFINITY), None);
        assert!(iso.inside(V3::from_vec3(Vec3::new(0.5, 0.0, 0.0))));
        assert!(!iso.inside(V3::from_vec3(Vec3::new(1.5, 0.0, 0.0))));
        // Scaled and moved: the transform applies.
        let xf = DAffine3::from_translation(DVec3::new(0.0, 0.0, 10.0)) * DAffine3::from_scale(DVec3::splat(2.0));
        let iso = Isosurface::new(xf, sphere_fn(1.0), unit_box(), IsoParams::default());
        let t = iso.intersect(&ray, 0.0, f32::INFINITY).expect("scaled");
        assert!((t - 13.0).abs() < 1e-4, "{t}");
    }

    /// `blocks` misses exactly where `hit` does: seeded random rays through a rippled sphere
    /// (the kernel scene's function) cut by its box, some ending near it, and shadow rays leaving
    /// its hits every way.
    #[test]
    fn blocks_as_hit_does() {
        use crate::function::{Binary, Unary};
        use crate::geometry::test_support::{check_blocks, uniform};
        let (x, y, z) = (Node::Param(0), Node::Param(1), Node::Param(2));
        let wave = |p: Node| Node::unary(Unary::Sin, Node::binary(Binary::Mul, Node::Const(20.0), p));
        let ripple = Node::binary(
            Binary::Mul,
            Node::Const(0.03),
            Node::binary(Binary::Mul, wave(x), Node::binary(Binary::Mul, wave(y), wave(z))),
        );
        let body = Node::binary(
            Binary::Add,
            Node::Internal(Internal::Sphere, vec![Node::Param(0), Node::Param(1), Node::Param(2), Node::Const(0.38)]),
            ripple,
        );
        let container = Container::Box { min: DVec3::splat(-0.45), max: DVec3::splat(0.45) };
        let params = IsoParams { max_gradient: 2.2, ..IsoParams::default() };
        let iso = Isosurface::new(DAffine3::IDENTITY, Program::compile(&body, 3), container, params);
        let mut rnd = uniform(5);
        let mut r = move || rnd() as f32 * 2.0 - 1.0;
        let mut rays = Vec::new();
        for k in 0..240 {
            let o = Vec3::new(r(), r(), r()).normalize() * 2.0;
            let d = Vec3::new(r(), r(), r()) * 0.5 - o;
            let t_max = if k % 3 == 0 { 0.7 + 0.2 * r().abs() } else { 100.0 };
            rays.push((o, d, 0.0, t_max));
            if let Some(t) = iso.intersect(&Ray::new(o, d), 0.0, 100.0) {
                rays.push((o + t * d, Vec3::new(r(), r(), r()), 1e-4, 100.0));
            }
        }
        let hits = check_blocks(&iso, &rays);
        assert!(hits > 60 && hits < rays.len() - 60, "{hits} of {}", rays.len());
    }

    #[test]
    fn the_container_closes_a_cut_solid_unless_open() {
        // A sphere of radius 3 cut by the box ±2: the box's faces show.
        let iso = Isosurface::new(DAffine3::IDENTITY, sphere_fn(3.0), unit_box(), IsoParams::default());
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        let t = iso.intersect(&ray, 0.0, f32::INFINITY).expect("face");
        assert!((t - 3.0).abs() < 1e-5, "{t}");
        assert!((iso.normal_at(Vec3::new(0.0, 0.0, -2.0)) - -Vec3::Z).length() < 1e-5);
        let open = IsoParams { open: true, ..IsoParams::default() };
        let iso = Isosurface::new(DAffine3::IDENTITY, sphere_fn(3.0), unit_box(), open);
        assert_eq!(iso.intersect(&ray, 0.0, f32::INFINITY), None);
        // A sphere container and a threshold: f_sphere(r = 0) = 1 is the unit sphere.
        let ball = Container::Sphere { center: DVec3::ZERO, radius: 1.5 };
        let iso = Isosurface::new(DAffine3::IDENTITY, sphere_fn(0.0), ball, IsoParams { threshold: 1.0, ..open });
        let t = iso.intersect(&ray, 0.0, f32::INFINITY).expect("threshold");
        assert!((t - 4.0).abs() < 1e-5, "{t}");
    }

    /// Seeded random rays: the isosurface of `f_sphere` hits where the analytic sphere does
    /// (to its accuracy), eight-ray packets give the single rays' answers, and inside agrees
    /// with the sphere's inside away from the surface.
    #[test]
    fn random_rays_agree_with_the_analytic_sphere() {
        use crate::geometry::sphere::Sphere;
        use crate::lanes::Lane as _;
        use crate::lanes::F8;
        let iso = Isosurface::new(DAffine3::IDENTITY, sphere_fn(1.0), unit_box(), IsoParams::default());
        let ball = Sphere { center: Vec3::ZERO, radius: 1.0 };
        let mut state = 12345u64;
        let mut next = || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 33) as f32 / (1u64 << 31) as f32) * 2.0 - 1.0
        };
        for _ in 0..500 {
            let rays: [Ray; 8] = std::array::from_fn(|_| {
                let o = Vec3::new(next(), next(), next()).normalize() * 4.0;
                let target = Vec3::new(next(), next(), next()) * 1.2;
                Ray::new(o, (target - o).normalize())
            });
            let single: Vec<Option<f32>> = rays.iter().map(|r| iso.intersect(r, 0.0, f32::INFINITY)).collect();
            for (ray, t) in rays.iter().zip(&single) {
                let want = ball.intersect(ray, 0.0, f32::INFINITY);
                match (*t, want) {
                    (Some(t), Some(w)) => assert!((t - w).abs() < 2e-3, "{ray:?}: {t} vs {w}"),
                    // A grazing ray may meet one and miss the other within the accuracy.
                    (Some(t), None) | (None, Some(t)) => {
                        let p = ray.at(t);
                        assert!((p.length() - 1.0).abs() < 2e-3, "{ray:?}: {t}");
                    }
                    (None, None) => {}
                }
            }
            let lane = |f: &dyn Fn(&Ray) -> Vec3| {
                let v: [Vec3; 8] = std::array::from_fn(|i| f(&rays[i]));
                V3 { x: F8::from_fn(|i| v[i].x), y: F8::from_fn(|i| v[i].y), z: F8::from_fn(|i| v[i].z) }
            };
            let packet = RayLanes::<F8>::new(lane(&|r| r.origin), lane(&|r| r.dir));
            let t8 = iso.hit(&packet, F8::splat(0.0), F8::splat(f32::INFINITY));
            for (i, t) in single.iter().enumerate() {
                let got = t8.get_f64(i) as f32;
                assert_eq!(got, t.unwrap_or(crate::ray::MISS), "lane {i}");
            }
            let q = Vec3::new(next(), next(), next()) * 1.5;
            if (q.length() - 1.0).abs() > 1e-3 {
                assert_eq!(iso.inside(V3::from_vec3(q)), q.length() < 1.0, "{q}");
            }
        }
    }
}
