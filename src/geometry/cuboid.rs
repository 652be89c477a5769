//! Ray/box intersection: the slab test, in the box's own space when it is rotated.
//!
//! (Named `cuboid` because `box` is a Rust keyword.)

use glam::{Affine3A, Mat3A, Vec3};

use super::{transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{pick_root, RayLanes};

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

/// Slab test: (entry, exit) distances of the ray against an axis-aligned box.
#[inline(always)]
fn slabs<L: Lane>(min: V3<L>, max: V3<L>, o: V3<L>, inv: V3<L>) -> (L, L) {
    let t0 = min.sub(o).mul(inv);
    let t1 = max.sub(o).mul(inv);
    let near = t0.min(t1);
    let far = t0.max(t1);
    (near.x.max(near.y).max(near.z), far.x.min(far.y).min(far.z))
}

impl Cuboid {
    /// Where the ray's line crosses the box: whether it does, and its entry and exit distances
    /// (the slab test). `hit` picks from these, so a caller that keeps them (CSG) gets `hit`'s
    /// bits for any interval without solving again.
    #[inline(always)]
    pub fn span<L: Lane>(&self, ray: &RayLanes<L>) -> (L::Mask, L, L) {
        let (lo, hi) = (V3::splat(self.min), V3::splat(self.max));
        let (near, far) = match &self.frame {
            None => slabs(lo, hi, ray.o, ray.inv),
            Some(f) => {
                let o = ray.o.transform_point(&f.object_from_render);
                let d = ray.d.transform_vector(&f.object_from_render);
                slabs(lo, hi, o, d.recip())
            }
        };
        (near.le(far), near, far)
    }
}

impl Shape for Cuboid {
    /// The slab test; the far side counts when the origin is inside.
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let (valid, near, far) = self.span(ray);
        pick_root(valid, near, far, t_min, t_max)
    }

    /// Outward normal of the face nearest to `p` (a point on the surface, render space).
    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let local = match &self.frame {
            None => p,
            Some(f) => p.transform_point(&f.object_from_render),
        };
        let size = (self.max - self.min).max(Vec3::splat(f32::MIN_POSITIVE));
        let (lo, hi, size) = (V3::splat(self.min), V3::splat(self.max), V3::splat(size));
        // Distance to each face, relative to the box's extent on that axis.
        let rel = |a: L, b: L, s: L| ((a - b) / s).abs();
        let d_min = V3 { x: rel(local.x, lo.x, size.x), y: rel(local.y, lo.y, size.y), z: rel(local.z, lo.z, size.z) };
        let d_max = V3 { x: rel(hi.x, local.x, size.x), y: rel(hi.y, local.y, size.y), z: rel(hi.z, local.z, size.z) };
        let (mut best_d, mut best_n) = (d_min.x, V3::splat(-Vec3::X));
        for (d, n) in
            [(d_max.x, Vec3::X), (d_min.y, -Vec3::Y), (d_max.y, Vec3::Y), (d_min.z, -Vec3::Z), (d_max.z, Vec3::Z)]
        {
            let nearer = d.lt(best_d);
            best_d = L::select(nearer, d, best_d);
            best_n = V3::select(nearer, V3::splat(n), best_n);
        }
        match &self.frame {
            None => best_n,
            Some(f) => best_n.mat3_mul(&f.normal_to_render).normalize_or(best_n),
        }
    }

    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = match &self.frame {
            None => p,
            Some(f) => p.transform_point(&f.object_from_render),
        };
        let (lo, hi) = (V3::<L>::splat(self.min), V3::<L>::splat(self.max));
        let x = L::and(lo.x.lt(q.x), q.x.lt(hi.x));
        let y = L::and(lo.y.lt(q.y), q.y.lt(hi.y));
        let z = L::and(lo.z.lt(q.z), q.z.lt(hi.z));
        L::and(x, L::and(y, z))
    }
}

impl Cuboid {
    /// Render-space bounds (of the transformed corners, for a rotated box).
    pub fn bounds(&self) -> (Vec3, Vec3) {
        match &self.frame {
            None => (self.min, self.max),
            Some(f) => transformed_bounds(&f.object_from_render.inverse(), self.min, self.max),
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
    use crate::ray::Ray;

    #[test]
    fn eight_lanes_of_normals_match_one_lane_bit_for_bit() {
        use crate::lanes::F8;
        let rotated = Affine3A::from_rotation_y(0.35) * Affine3A::from_scale(Vec3::new(1.0, 2.0, 0.5));
        for b in [unit_box(), Cuboid { min: Vec3::splat(-1.0), max: Vec3::ONE, frame: Some(frame_for(rotated)) }] {
            for k in 0..400 {
                // Points on and near the surface, some on edges and corners.
                let p = |i: usize| {
                    let j = (k * 8 + i) as f32;
                    let v = Vec3::new((j * 0.91).sin(), (j * 0.53).cos(), (j * 0.27).sin()) * 1.2;
                    let v = if i.is_multiple_of(3) { v / v.abs().max_element() } else { v };
                    rotated.transform_point3(v)
                };
                let wide = b.normal(V3::<F8>::from_lanes(p));
                for i in 0..8 {
                    assert_eq!(
                        wide.lane(i).to_array().map(f32::to_bits),
                        b.normal_at(p(i)).to_array().map(f32::to_bits)
                    );
                }
            }
        }
    }

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
