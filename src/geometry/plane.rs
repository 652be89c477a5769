//! Ray/plane intersection. Planes are unbounded, so they live outside every bounding hierarchy.

use glam::Vec3;

use super::Shape;
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

/// Points `p` with `normal · p = distance`, `normal` of unit length.
#[derive(Clone, Copy, Debug)]
pub struct Plane {
    pub normal: Vec3,
    pub distance: f32,
}

impl Plane {
    /// Whether `a` and `b` lie strictly on opposite sides (a point on the plane is on neither).
    #[inline]
    pub fn separates(&self, a: Vec3, b: Vec3) -> bool {
        let (sa, sb) = (self.normal.dot(a) - self.distance, self.normal.dot(b) - self.distance);
        (sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)
    }
}

impl Shape for Plane {
    /// A ray parallel to the plane never hits it, even when it lies in it.
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let (n, dist) = (V3::splat(self.normal), L::splat(self.distance));
        let (o, d) = (ray.o, ray.d);
        let denom = n.dot(d);
        let t = (dist - n.dot(o)) / denom;
        let parallel = L::and(L::le(denom, L::splat(0.0)), L::le(L::splat(0.0), denom));
        let ok = L::and(L::not(parallel), L::and(t_min.lt(t), t.lt(t_max)));
        L::select(ok, t, L::splat(MISS))
    }

    #[inline(always)]
    fn normal<L: Lane>(&self, _: V3<L>) -> V3<L> {
        V3::splat(self.normal)
    }

    /// The half-space the normal points away from (POV-Ray's solid plane).
    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        V3::splat(self.normal).dot(p).lt(L::splat(self.distance))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ray::Ray;

    const FLOOR: Plane = Plane { normal: Vec3::Y, distance: 0.0 };

    #[test]
    fn hit_from_above() {
        let r = Ray::new(Vec3::new(0.0, 2.0, 0.0), -Vec3::Y);
        assert_eq!(FLOOR.intersect(&r, 0.0, f32::INFINITY), Some(2.0));
    }

    #[test]
    fn hit_from_below() {
        let r = Ray::new(Vec3::new(0.0, -2.0, 0.0), Vec3::Y);
        assert_eq!(FLOOR.intersect(&r, 0.0, f32::INFINITY), Some(2.0));
    }

    #[test]
    fn separates_only_strictly_opposite_points() {
        assert!(FLOOR.separates(Vec3::new(0.0, 1.0, 0.0), Vec3::new(5.0, -1.0, 0.0)));
        assert!(!FLOOR.separates(Vec3::new(0.0, 1.0, 0.0), Vec3::new(5.0, 2.0, 0.0)));
        // A light lying on the plane is on neither side.
        assert!(!FLOOR.separates(Vec3::new(0.0, 1.0, 0.0), Vec3::new(5.0, 0.0, 0.0)));
    }

    #[test]
    fn parallel_misses() {
        let r = Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::X);
        assert_eq!(FLOOR.intersect(&r, 0.0, f32::INFINITY), None);
        let in_plane = Ray::new(Vec3::ZERO, Vec3::X);
        assert_eq!(FLOOR.intersect(&in_plane, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn behind_origin_is_no_hit() {
        let r = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y);
        assert_eq!(FLOOR.intersect(&r, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn tangent_grazing_ray_hits_far_away() {
        let r = Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::new(1.0, -1e-6, 0.0).normalize());
        let t = FLOOR.intersect(&r, 0.0, f32::INFINITY).expect("grazing hit");
        assert!((t - 1e6).abs() / 1e6 < 1e-3);
    }
}
