//! Ray/box intersection: the slab test, in the box's own space when it is rotated.
//!
//! (Named `cuboid` because `box` is a Rust keyword.)

use glam::{Affine3A, Mat3A, Vec3, Vec3A};

use super::ray::Ray;

/// An axis-aligned box in its own space, plus the map into it when that is not render space.
#[derive(Clone, Copy, Debug)]
pub struct Cuboid {
    pub min: Vec3,
    pub max: Vec3,
    pub frame: Option<BoxFrame>,
}

/// The affine frame of a rotated or sheared box.
#[derive(Clone, Copy, Debug)]
pub struct BoxFrame {
    pub object_from_render: Affine3A,
    /// Inverse transpose of the render-from-object linear part: maps object normals out.
    pub normal_to_render: Mat3A,
}

/// Slab test against an axis-aligned box; returns the entry and exit distances.
///
/// With IEEE infinities from `inv_dir` this needs no branch for axis-parallel rays. A ray lying
/// exactly in a face plane gives 0·inf = NaN there; `max`/`min` of glam drop NaN operands
/// consistently, so such a ray counts as inside that slab.
#[inline]
pub fn slabs(min: Vec3, max: Vec3, origin: Vec3, inv_dir: Vec3) -> (f32, f32) {
    let t0 = (min - origin) * inv_dir;
    let t1 = (max - origin) * inv_dir;
    let near = t0.min(t1);
    let far = t0.max(t1);
    (near.max_element(), far.min_element())
}

impl Cuboid {
    #[inline]
    fn local_ray(&self, ray: &Ray) -> (Vec3, Vec3) {
        match &self.frame {
            None => (ray.origin, ray.inv_dir),
            Some(f) => {
                let o = f.object_from_render.transform_point3(ray.origin);
                let d = f.object_from_render.transform_vector3(ray.dir);
                (o, d.recip())
            }
        }
    }

    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        let (o, inv) = self.local_ray(ray);
        let (near, far) = slabs(self.min, self.max, o, inv);
        if near > far {
            return None;
        }
        if near > t_min && near < t_max {
            Some(near)
        } else if far > t_min && far < t_max {
            Some(far)
        } else {
            None
        }
    }

    /// Outward normal of the face nearest to `p` (a point on the surface, render space).
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        let local = match &self.frame {
            None => p,
            Some(f) => f.object_from_render.transform_point3(p),
        };
        let size = (self.max - self.min).max(Vec3::splat(f32::MIN_POSITIVE));
        // Distance to each face, relative to the box's extent on that axis.
        let d_min = ((local - self.min) / size).abs();
        let d_max = ((self.max - local) / size).abs();
        let mut best = (d_min.x, -Vec3::X);
        for (d, n) in [
            (d_max.x, Vec3::X),
            (d_min.y, -Vec3::Y),
            (d_max.y, Vec3::Y),
            (d_min.z, -Vec3::Z),
            (d_max.z, Vec3::Z),
        ] {
            if d < best.0 {
                best = (d, n);
            }
        }
        match &self.frame {
            None => best.1,
            Some(f) => Vec3::from(f.normal_to_render * Vec3A::from(best.1)).normalize_or(best.1),
        }
    }

    /// Render-space bounds (of the transformed corners, for a rotated box).
    pub fn bounds(&self) -> (Vec3, Vec3) {
        match &self.frame {
            None => (self.min, self.max),
            Some(f) => {
                let render_from_object = f.object_from_render.inverse();
                let mut lo = Vec3::splat(f32::INFINITY);
                let mut hi = Vec3::splat(f32::NEG_INFINITY);
                for i in 0..8 {
                    let c = Vec3::new(
                        if i & 1 == 0 { self.min.x } else { self.max.x },
                        if i & 2 == 0 { self.min.y } else { self.max.y },
                        if i & 4 == 0 { self.min.z } else { self.max.z },
                    );
                    let w = render_from_object.transform_point3(c);
                    lo = lo.min(w);
                    hi = hi.max(w);
                }
                (lo, hi)
            }
        }
    }
}

/// Builds the frame for a box whose object→render map is `render_from_object`.
pub fn frame_for(render_from_object: Affine3A) -> BoxFrame {
    BoxFrame {
        object_from_render: render_from_object.inverse(),
        normal_to_render: render_from_object.matrix3.inverse().transpose(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> Cuboid {
        Cuboid { min: Vec3::splat(-1.0), max: Vec3::splat(1.0), frame: None }
    }

    #[test]
    fn hit_miss_inside_behind() {
        let b = unit_box();
        let hit = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        assert_eq!(b.intersect(&hit, 0.0, f32::INFINITY), Some(4.0));
        assert_eq!(b.normal_at(hit.at(4.0)), -Vec3::Z);
        let miss = Ray::new(Vec3::new(0.0, 2.0, -5.0), Vec3::Z);
        assert_eq!(b.intersect(&miss, 0.0, f32::INFINITY), None);
        let inside = Ray::new(Vec3::ZERO, Vec3::X);
        assert_eq!(b.intersect(&inside, 0.0, f32::INFINITY), Some(1.0));
        let behind = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z);
        assert_eq!(b.intersect(&behind, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn ray_along_an_edge_plane_does_not_produce_nan() {
        // Parallel to the x faces, lying exactly in the plane x = 1.
        let r = Ray::new(Vec3::new(1.0, 0.0, -5.0), Vec3::Z);
        let t = unit_box().intersect(&r, 0.0, f32::INFINITY);
        assert!(t.is_none_or(|t| t.is_finite()));
        // Parallel and outside: a clean miss.
        let r = Ray::new(Vec3::new(1.5, 0.0, -5.0), Vec3::Z);
        assert_eq!(unit_box().intersect(&r, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn rotated_box_matches_its_corners() {
        let xf = Affine3A::from_rotation_y(0.3) * Affine3A::from_translation(Vec3::new(0.0, 0.0, 3.0));
        let b = Cuboid { min: Vec3::splat(-1.0), max: Vec3::splat(1.0), frame: Some(frame_for(xf)) };
        let center = xf.transform_point3(Vec3::ZERO);
        let r = Ray::new(Vec3::ZERO, center.normalize());
        let t = b.intersect(&r, 0.0, f32::INFINITY).expect("hit");
        let n = b.normal_at(r.at(t));
        assert!((n.length() - 1.0).abs() < 1e-5);
        assert!(n.dot(r.dir) < 0.0);
        let (lo, hi) = b.bounds();
        assert!(lo.cmple(center).all() && hi.cmpge(center).all());
    }
}
