//! POV-Ray's `disc`: a flat disc, optionally with a hole, in the plane z = 0 of its own space.

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::{transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Copy, Debug)]
pub struct Disc {
    /// Render space → the disc's space, where it is `x² + y² ∈ [hole², 1]`, z = 0.
    pub frame: BoxFrame,
    /// Hole radius relative to the disc's (0 for none).
    pub hole: f32,
    pub min: Vec3,
    pub max: Vec3,
}

impl Disc {
    pub fn new(render_from_object: Affine3A, hole: f32) -> Disc {
        let (lo, hi) = transformed_bounds(&render_from_object, Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, 1.0, 0.0));
        Disc { frame: frame_for(render_from_object), hole, min: lo, max: hi }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }
}

impl Shape for Disc {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        let t = -o.z / d.z;
        let (x, y) = (o.x + t * d.x, o.y + t * d.y);
        let r2 = x * x + y * y;
        let h = L::splat(self.hole);
        let inside = L::and(L::le(r2, L::splat(1.0)), L::le(h * h, r2));
        let ok = L::and(inside, L::and(t_min.lt(t), t.lt(t_max)));
        L::select(ok, t, L::splat(MISS))
    }

    #[inline(always)]
    fn normal<L: Lane>(&self, _: V3<L>) -> V3<L> {
        V3::splat(Vec3::Z).mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
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

    #[test]
    fn disc_with_a_hole() {
        let d = Disc::new(
            Affine3A::from_translation(Vec3::new(0.0, 0.0, 3.0)) * Affine3A::from_scale(Vec3::splat(2.0)),
            0.25,
        );
        let at = |x: f32| Ray::new(Vec3::new(x, 0.0, 0.0), Vec3::Z);
        assert_eq!(d.intersect(&at(1.0), 0.0, f32::INFINITY), Some(3.0));
        assert_eq!(d.intersect(&at(0.2), 0.0, f32::INFINITY), None, "hole");
        assert_eq!(d.intersect(&at(2.5), 0.0, f32::INFINITY), None, "outside");
        assert_eq!(d.intersect(&Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::X), 0.0, f32::INFINITY), None, "parallel");
        assert!((d.normal_at(Vec3::new(1.0, 0.0, 3.0)) - Vec3::Z).length() < 1e-6);
    }
}
