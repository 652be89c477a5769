//! Ray/sphere intersection (chapter 24.3), in the numerically stable form.

use glam::Vec3;

use super::lanes::{self, Lane, V3};
use super::ray::Ray;

#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    pub center: Vec3,
    pub radius: f32,
}

impl Sphere {
    /// Nearest root in `(t_min, t_max)`: the near one from outside, the far one from inside.
    /// The formula (stable against cancellation for small or far spheres) is in `lanes::sphere`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        let t = lanes::sphere(
            V3::from_vec3(self.center),
            self.radius,
            V3::from_vec3(ray.origin),
            V3::from_vec3(ray.dir),
            t_min,
            t_max,
        );
        (t != lanes::MISS).then_some(t)
    }

    #[inline]
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        self.normal_lanes(V3::from_vec3(p)).vec3()
    }

    /// `normal_at` for one or eight points.
    #[inline(always)]
    pub fn normal_lanes<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let r = L::splat(self.radius);
        let v = p.sub(V3::splat(self.center));
        V3 { x: v.x / r, y: v.y / r, z: v.z / r }.normalize_or(V3::splat(Vec3::Y))
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.center - Vec3::splat(self.radius), self.center + Vec3::splat(self.radius))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Sphere {
        Sphere { center: Vec3::new(0.0, 0.0, 5.0), radius: 1.0 }
    }

    #[test]
    fn hit_from_outside_gives_near_root() {
        let t = unit().intersect(&Ray::new(Vec3::ZERO, Vec3::Z), 0.0, f32::INFINITY);
        assert_eq!(t, Some(4.0));
    }

    #[test]
    fn miss() {
        let r = Ray::new(Vec3::ZERO, Vec3::new(0.0, 1.0, 1.0).normalize());
        assert_eq!(unit().intersect(&r, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn tangent_ray_touches() {
        let r = Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::Z);
        let t = unit().intersect(&r, 0.0, f32::INFINITY).expect("tangent hit");
        assert!((t - 5.0).abs() < 1e-3);
    }

    #[test]
    fn from_inside_gives_far_root() {
        let r = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z);
        assert_eq!(unit().intersect(&r, 0.0, f32::INFINITY), Some(1.0));
    }

    #[test]
    fn behind_origin_is_no_hit() {
        let r = Ray::new(Vec3::new(0.0, 0.0, 10.0), Vec3::Z);
        assert_eq!(unit().intersect(&r, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn tiny_far_sphere_is_hit_precisely() {
        let s = Sphere { center: Vec3::new(0.0, 0.0, 1e5), radius: 1e-2 };
        let t = s.intersect(&Ray::new(Vec3::ZERO, Vec3::Z), 0.0, f32::INFINITY).expect("hit");
        assert!((t - (1e5 - 1e-2)).abs() < 0.02);
    }
}

/// A sphere under a non-uniform scale or shear: the unit sphere in its own space.
#[derive(Clone, Copy, Debug)]
pub struct Ellipsoid {
    pub frame: super::cuboid::BoxFrame,
    pub min: Vec3,
    pub max: Vec3,
}

impl Ellipsoid {
    pub fn new(render_from_object: glam::Affine3A) -> Ellipsoid {
        // Bounds: the extent along each render axis is the length of that row of the linear part.
        let m = render_from_object.matrix3;
        let rows = Vec3::new(
            Vec3::new(m.x_axis.x, m.y_axis.x, m.z_axis.x).length(),
            Vec3::new(m.x_axis.y, m.y_axis.y, m.z_axis.y).length(),
            Vec3::new(m.x_axis.z, m.y_axis.z, m.z_axis.z).length(),
        );
        let c: Vec3 = render_from_object.translation.into();
        Ellipsoid { frame: super::cuboid::frame_for(render_from_object), min: c - rows, max: c + rows }
    }

    /// The unit sphere hit in object space; `t` stays a render-space distance because the
    /// object-space direction is not renormalised.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        let o = self.frame.object_from_render.transform_point3(ray.origin);
        let d = self.frame.object_from_render.transform_vector3(ray.dir);
        let a = d.length_squared();
        let b = o.dot(d) / a;
        let perp = o - b * d;
        let disc = 1.0 - perp.length_squared();
        if disc < 0.0 {
            return None;
        }
        let c = (o.length_squared() - 1.0) / a;
        let q = -b - b.signum() * (disc / a).sqrt();
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q) };
        let (near, far) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
        if near > t_min && near < t_max {
            Some(near)
        } else if far > t_min && far < t_max {
            Some(far)
        } else {
            None
        }
    }

    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        self.normal_lanes(V3::from_vec3(p)).vec3()
    }

    /// `normal_at` for one or eight points.
    #[inline(always)]
    pub fn normal_lanes<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let local = p.transform_point(&self.frame.object_from_render);
        local.mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }
}

#[cfg(test)]
mod ellipsoid_tests {
    use super::*;
    use glam::Affine3A;

    #[test]
    fn stretched_sphere_hits_at_its_semi_axes() {
        let e = Ellipsoid::new(
            Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)) * Affine3A::from_scale(Vec3::new(1.0, 1.0, 3.0)),
        );
        let t = e.intersect(&Ray::new(Vec3::ZERO, Vec3::Z), 0.0, f32::INFINITY).expect("hit");
        assert!((t - 7.0).abs() < 1e-4);
        let side = Ray::new(Vec3::new(-5.0, 0.0, 10.0), Vec3::X);
        let t = e.intersect(&side, 0.0, f32::INFINITY).expect("hit");
        assert!((t - 4.0).abs() < 1e-4);
        assert!((e.normal_at(side.at(t)) + Vec3::X).length() < 1e-4);
        assert!(e.intersect(&Ray::new(Vec3::new(2.0, 0.0, 0.0), Vec3::Z), 0.0, f32::INFINITY).is_none());
    }
}
