//! Ray/triangle intersection (Möller–Trumbore).

use glam::Vec3;

use super::Shape;
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Copy, Debug)]
pub struct Triangle {
    pub v0: Vec3,
    pub e1: Vec3,
    pub e2: Vec3,
    /// Unit geometric normal, `e1 × e2` normalised.
    pub normal: Vec3,
}

impl Triangle {
    pub fn new(a: Vec3, b: Vec3, c: Vec3) -> Triangle {
        let e1 = b - a;
        let e2 = c - a;
        Triangle { v0: a, e1, e2, normal: e1.cross(e2).normalize_or(Vec3::Y) }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        let b = self.v0 + self.e1;
        let c = self.v0 + self.e2;
        (self.v0.min(b).min(c), self.v0.max(b).max(c))
    }
}

impl Shape for Triangle {
    /// Möller–Trumbore.
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let (v0, e1, e2) = (V3::splat(self.v0), V3::splat(self.e1), V3::splat(self.e2));
        let (o, d) = (ray.o, ray.d);
        let p = d.cross(e2);
        let det = e1.dot(p);
        let inv = L::splat(1.0) / det;
        let s = o.sub(v0);
        let u = s.dot(p) * inv;
        let q = s.cross(e1);
        let v = d.dot(q) * inv;
        let t = e2.dot(q) * inv;
        let zero = L::splat(0.0);
        let one = L::splat(1.0);
        let det_zero = L::and(L::le(det, zero), L::le(zero, det));
        let inside = L::and(L::and(L::le(zero, u), L::le(u, one)), L::and(L::le(zero, v), L::le(u + v, one)));
        let ok = L::and(L::and(L::not(det_zero), inside), L::and(t_min.lt(t), t.lt(t_max)));
        L::select(ok, t, L::splat(MISS))
    }

    #[inline(always)]
    fn normal<L: Lane>(&self, _: V3<L>) -> V3<L> {
        V3::splat(self.normal)
    }

    /// Flat: no inside.
    #[inline(always)]
    fn inside<L: Lane>(&self, _: V3<L>) -> L::Mask {
        L::mask_from_fn(|_| false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ray::Ray;

    fn tri() -> Triangle {
        Triangle::new(Vec3::new(-1.0, -1.0, 2.0), Vec3::new(1.0, -1.0, 2.0), Vec3::new(0.0, 1.0, 2.0))
    }

    #[test]
    fn hit_miss_behind_and_parallel() {
        let t = tri();
        assert_eq!(t.intersect(&Ray::new(Vec3::ZERO, Vec3::Z), 0.0, f32::INFINITY), Some(2.0));
        let miss = Ray::new(Vec3::new(2.0, 0.0, 0.0), Vec3::Z);
        assert_eq!(t.intersect(&miss, 0.0, f32::INFINITY), None);
        let behind = Ray::new(Vec3::new(0.0, 0.0, 3.0), Vec3::Z);
        assert_eq!(t.intersect(&behind, 0.0, f32::INFINITY), None);
        let parallel = Ray::new(Vec3::new(0.0, 0.0, 2.0), Vec3::X);
        assert_eq!(t.intersect(&parallel, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn from_behind_the_face_still_hits() {
        let r = Ray::new(Vec3::new(0.0, 0.0, 4.0), -Vec3::Z);
        assert_eq!(tri().intersect(&r, 0.0, f32::INFINITY), Some(2.0));
    }

    #[test]
    fn edge_is_inside() {
        let r = Ray::new(Vec3::new(0.0, -1.0, 0.0), Vec3::Z);
        assert!(tri().intersect(&r, 0.0, f32::INFINITY).is_some());
    }
}
