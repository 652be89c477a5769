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
    /// Where the ray's line is inside the half-space (`inside`), as a pair of roots like
    /// `Sphere::span`'s: from the crossing on where the ray enters, up to it where the ray
    /// leaves, the whole line or none of it where the ray runs parallel. `hit` takes the same
    /// crossing (CSG keeps spans and picks from them with `ray::pick_root`, the same bits).
    #[inline(always)]
    pub fn span<L: Lane>(&self, ray: &RayLanes<L>) -> (L::Mask, L, L) {
        let (denom, t, parallel) = self.crossing(ray);
        let (ninf, inf) = (L::splat(f32::NEG_INFINITY), L::splat(f32::INFINITY));
        let entering = denom.lt(L::splat(0.0));
        let valid = L::or(L::not(parallel), self.inside(ray.o));
        let near = L::select(L::and(L::not(parallel), entering), t, ninf);
        let far = L::select(L::or(parallel, entering), inf, t);
        (valid, near, far)
    }

    /// `n·d`, the distance along the ray to the plane, and whether the ray runs parallel.
    #[inline(always)]
    fn crossing<L: Lane>(&self, ray: &RayLanes<L>) -> (L, L, L::Mask) {
        let (n, dist) = (V3::splat(self.normal), L::splat(self.distance));
        let denom = n.dot(ray.d);
        let t = (dist - n.dot(ray.o)) / denom;
        let parallel = L::and(L::le(denom, L::splat(0.0)), L::le(L::splat(0.0), denom));
        (denom, t, parallel)
    }

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
        let (_, t, parallel) = self.crossing(ray);
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

    /// `pick_root` on the span gives `hit`'s bits, and the span holds exactly the points
    /// `inside` calls inside, away from the crossing, on seeded random rays (some parallel).
    #[test]
    fn span_agrees_with_hit_and_inside() {
        let mut seed = 0x853c_49e6_748f_ea9bu64;
        let mut rand = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 40) as f32 / (1u64 << 23) as f32 - 1.0
        };
        let plane = Plane { normal: Vec3::new(0.6, 0.0, 0.8), distance: 0.3 };
        for k in 0..5000 {
            let o = Vec3::new(rand(), rand(), rand()) * 4.0;
            let mut d = Vec3::new(rand(), rand(), rand());
            if k % 10 == 0 {
                d -= plane.normal * plane.normal.dot(d);
            }
            let ray = Ray::new(o, d).lanes();
            let (valid, near, far) = plane.span(&ray);
            let (t_min, t_max) = (rand().abs(), 2.0 + rand().abs() * 8.0);
            assert_eq!(
                crate::ray::pick_root(valid, near, far, t_min, t_max).to_bits(),
                plane.hit(&ray, t_min, t_max).to_bits()
            );
            for s in [-3.0f32, -0.7, 0.2, 1.3, 5.0] {
                let p = ray.o.add(ray.d.scale(s));
                let clear = (near - s).abs() > 1e-3 && (far - s).abs() > 1e-3;
                if clear {
                    assert_eq!(valid && near < s && s < far, plane.inside(p), "{o} {d} at {s}: {near}..{far}");
                }
            }
        }
    }

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
