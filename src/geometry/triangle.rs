//! Ray/triangle intersection (Möller–Trumbore).

use glam::Vec3;

use super::ray::Ray;

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

    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        let p = ray.dir.cross(self.e2);
        let det = self.e1.dot(p);
        if det == 0.0 {
            return None;
        }
        let inv = 1.0 / det;
        let s = ray.origin - self.v0;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(self.e1);
        let v = ray.dir.dot(q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return None;
        }
        let t = self.e2.dot(q) * inv;
        (t > t_min && t < t_max).then_some(t)
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        let b = self.v0 + self.e1;
        let c = self.v0 + self.e2;
        (self.v0.min(b).min(c), self.v0.max(b).max(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
