//! Cones and cylinders (POV-Ray's `cone` and `cylinder`), capped or `open`: one formula, the
//! cylinder being the cone whose two radii are equal.
//!
//! In object space the axis runs along z from 0 (radius `r0`) to 1 (radius `r1`); `frame` maps
//! render space there, so any transform (a non-uniform scale makes an elliptic cone) costs the
//! same. The side is `x² + y² = (r0 + (r1 − r0)·z)²`, solved from the point of the ray nearest the
//! axis rather than from its origin: there the quadratic's terms have the size of the cone, not of
//! the distance to it, so a thin cylinder seen from far away keeps f32's precision.

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::{transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Copy, Debug)]
pub struct Cone {
    pub frame: BoxFrame,
    /// Radius at z = 0 and at z = 1, object space; both ≥ 0.
    pub r0: f32,
    pub r1: f32,
    /// No end caps: the side alone, seen from inside through the ends.
    pub open: bool,
    /// Render-space bounds.
    pub min: Vec3,
    pub max: Vec3,
}

impl Cone {
    /// A cone (or, with `r0 == r1`, a cylinder) under `render_from_object`.
    pub fn new(render_from_object: Affine3A, r0: f32, r1: f32, open: bool) -> Cone {
        let r = r0.max(r1);
        let (lo, hi) = transformed_bounds(&render_from_object, Vec3::new(-r, -r, 0.0), Vec3::new(r, r, 1.0));
        Cone { frame: frame_for(render_from_object), r0, r1, open, min: lo, max: hi }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }
}

impl Shape for Cone {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        let (zero, one) = (L::splat(0.0), L::splat(1.0));
        let (r0, r1) = (L::splat(self.r0), L::splat(self.r1));
        let k = r1 - r0;
        // Shift to the ray's point nearest the axis (t_c); a ray along the axis keeps its origin.
        let dd = d.x * d.x + d.y * d.y;
        let along_axis = L::le(dd, zero);
        let t_c = L::select(along_axis, zero, -(o.x * d.x + o.y * d.y) / L::select(along_axis, one, dd));
        let p = o.add(d.scale(t_c));
        // a·s² + 2b·s + c = 0 for s = t − t_c.
        let (rp, kd) = (r0 + k * p.z, k * d.z);
        let a = dd - kd * kd;
        let b = p.x * d.x + p.y * d.y - rp * kd;
        let c = p.x * p.x + p.y * p.y - rp * rp;
        let disc = b * b - a * c;
        let solvable = L::and(L::le(zero, disc), L::not(L::and(L::le(a, zero), L::le(zero, a))));
        let mut best = L::splat(MISS);
        // Where no lane meets the side, its roots would all be dropped: their square root and
        // two divisions are skipped (the result is the same, lane by lane).
        if L::any(solvable) {
            let q = -(b + b.sign_or_one() * disc.max(zero).sqrt());
            let q_zero = L::and(L::le(q, zero), L::le(zero, q));
            let s0 = q / L::select(solvable, a, one);
            let s1 = L::select(q_zero, s0, c / L::select(q_zero, one, q));
            for s in [s0, s1] {
                let t = t_c + s;
                let z = o.z + t * d.z;
                take(&mut best, t, L::and(solvable, L::and(L::le(zero, z), L::le(z, one))), t_min, t_max);
            }
        }
        if !self.open {
            for (plane, r) in [(zero, r0), (one, r1)] {
                let t = (plane - o.z) / d.z;
                let (x, y) = (o.x + t * d.x, o.y + t * d.y);
                take(&mut best, t, L::le(x * x + y * y, r * r), t_min, t_max);
            }
        }
        best
    }

    /// The side's normal, or a cap's where the point is nearer that cap than the side (distances
    /// relative to the axis length and the larger radius).
    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let q = p.transform_point(&self.frame.object_from_render);
        let (r0, k) = (L::splat(self.r0), L::splat(self.r1 - self.r0));
        let r = r0 + k * q.z;
        let side = V3 { x: q.x, y: q.y, z: -(r * k) };
        let mut n = side;
        if !self.open {
            let rho = (q.x * q.x + q.y * q.y).sqrt();
            let d_side = (rho - r).abs() / L::splat(self.r0.max(self.r1).max(f32::MIN_POSITIVE));
            let d0 = q.z.abs();
            let d1 = (L::splat(1.0) - q.z).abs();
            let cap0 = L::and(d0.lt(d_side), L::le(d0, d1));
            let cap1 = L::and(d1.lt(d_side), d1.lt(d0));
            n = V3::select(cap0, V3::splat(-Vec3::Z), V3::select(cap1, V3::splat(Vec3::Z), n));
        }
        n.mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }

    /// Inside the side and between the caps; an `open` cone is a solid too, as in POV-Ray.
    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = p.transform_point(&self.frame.object_from_render);
        let r = L::splat(self.r0) + L::splat(self.r1 - self.r0) * q.z;
        let between = L::and(L::splat(0.0).lt(q.z), q.z.lt(L::splat(1.0)));
        L::and(between, (q.x * q.x + q.y * q.y).lt(r * r))
    }
}

/// Keeps `t` in `best` where `ok` and it lies in `(t_min, t_max)` nearer than `best`. A function,
/// not a closure: a closure is compiled out of line, without the caller's AVX2 (it was 2 % of the
/// cylinder kernel's frame, called by pointer, its lanes spilled).
#[inline(always)]
fn take<L: Lane>(best: &mut L, t: L, ok: L::Mask, t_min: L, t_max: L) {
    let nearer = L::and(ok, L::and(t_min.lt(t), L::and(t.lt(t_max), t.lt(*best))));
    *best = L::select(nearer, t, *best);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lanes::F8;
    use crate::ray::Ray;

    /// The unit-radius cylinder from z = 0 to z = 2, or a cone narrowing to `r1`.
    fn cone(r1: f32, open: bool) -> Cone {
        Cone::new(Affine3A::from_scale(Vec3::new(1.0, 1.0, 2.0)), 1.0, r1, open)
    }

    #[test]
    fn cylinder_side_caps_and_open_ends() {
        let c = cone(1.0, false);
        let side = Ray::new(Vec3::new(-5.0, 0.0, 1.0), Vec3::X);
        assert_eq!(c.intersect(&side, 0.0, f32::INFINITY), Some(4.0));
        assert!((c.normal_at(side.at(4.0)) + Vec3::X).length() < 1e-6);
        let down = Ray::new(Vec3::new(0.3, 0.2, 5.0), -Vec3::Z);
        assert_eq!(c.intersect(&down, 0.0, f32::INFINITY), Some(3.0));
        assert!((c.normal_at(down.at(3.0)) - Vec3::Z).length() < 1e-6);
        // Open: the ray passes the missing cap and meets nothing (it runs inside, along the axis).
        assert_eq!(cone(1.0, true).intersect(&down, 0.0, f32::INFINITY), None);
        // From inside an open cylinder a slanted ray meets the inner side.
        let slant = Ray::new(Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 0.0, 0.2).normalize());
        let t = cone(1.0, true).intersect(&slant, 0.0, f32::INFINITY).expect("inner side");
        assert!((slant.at(t).x - 1.0).abs() < 1e-5);
        assert_eq!(c.intersect(&Ray::new(Vec3::new(-5.0, 1.5, 1.0), Vec3::X), 0.0, f32::INFINITY), None);
    }

    #[test]
    fn cone_narrows_to_its_apex() {
        let c = cone(0.0, false);
        // At z = 1 (half-way up a 2-long cone) the radius is 0.5.
        let t = c.intersect(&Ray::new(Vec3::new(-5.0, 0.0, 1.0), Vec3::X), 0.0, f32::INFINITY).expect("hit");
        assert!((t - 4.5).abs() < 1e-5, "{t}");
        let n = c.normal_at(Vec3::new(-0.5, 0.0, 1.0));
        assert!(n.x < 0.0 && n.z > 0.0 && (n.length() - 1.0).abs() < 1e-6);
        // Past the apex nothing.
        assert_eq!(c.intersect(&Ray::new(Vec3::new(-5.0, 0.0, 2.5), Vec3::X), 0.0, f32::INFINITY), None);
    }

    #[test]
    fn a_thin_cylinder_far_away_keeps_its_radius() {
        let c = Cone::new(Affine3A::from_translation(Vec3::new(0.0, 0.0, 1e4)), 1e-3, 1e-3, false);
        let t = c.intersect(&Ray::new(Vec3::new(0.0, 0.0, 0.0), Vec3::Z), 0.0, f32::INFINITY).expect("cap");
        assert!((t - 1e4).abs() < 2e-3);
        let r = Ray::new(Vec3::new(-1e4, 5e-4, 1e4 + 0.5), Vec3::X);
        let t = c.intersect(&r, 0.0, f32::INFINITY).expect("side");
        let want = 1e4 - (1e-6f32 - 2.5e-7).sqrt();
        assert!((t - want).abs() < 2e-3, "{t} {want}");
    }

    #[test]
    fn packets_and_f64_agree_with_single_rays() {
        let shapes = [cone(1.0, false), cone(0.3, true), cone(0.0, false)];
        for s in &shapes {
            for k in 0..200u32 {
                let ray = |i: usize| {
                    let j = (k * 8 + i as u32) as f32;
                    let o = Vec3::new((j * 0.37).sin() * 4.0, (j * 0.71).cos() * 4.0, (j * 0.13).sin() * 3.0 + 1.0);
                    let target = Vec3::new((j * 0.53).cos() * 0.8, (j * 0.29).sin() * 0.8, (j * 0.41).cos() + 1.0);
                    Ray::new(o, (target - o).normalize())
                };
                let rays: [Ray; 8] = std::array::from_fn(ray);
                let packet = RayLanes::<F8> {
                    o: V3::from_lanes(|i| rays[i].origin),
                    d: V3::from_lanes(|i| rays[i].dir),
                    inv: V3::from_lanes(|i| rays[i].inv_dir),
                };
                let wide = s.hit(&packet, F8::splat(0.0), F8::splat(MISS));
                for (i, r) in rays.iter().enumerate() {
                    let one = s.hit(&r.lanes(), 0.0, MISS);
                    assert_eq!(wide.get(i).to_bits(), one.to_bits());
                    let precise = s.hit(&r.lanes_f64(), 0.0, f64::INFINITY);
                    assert_eq!(one == MISS, precise == f64::INFINITY, "ray {k}/{i}: {one} {precise}");
                    if one != MISS {
                        assert!((one as f64 - precise).abs() < 1e-5 * precise.max(1.0));
                    }
                }
            }
        }
    }
}
