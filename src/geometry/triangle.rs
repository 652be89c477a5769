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

    /// The vertex normals `normals` interpolated at points `p` of the triangle (in its own
    /// space) by their barycentric coordinates, flipped to the geometric normal's side, as
    /// POV-Ray shades a `smooth_triangle` (3.4.5.2.1); the geometric normal where they cancel.
    /// Not normalised: the caller carries it into render space first, if it must.
    #[inline(always)]
    pub fn interpolate<L: Lane>(&self, normals: &[Vec3; 3], p: V3<L>) -> V3<L> {
        let corners = TriangleLanes { v0: V3::splat(self.v0), e1: V3::splat(self.e1), e2: V3::splat(self.e2) };
        let [n0, n1, n2] = *normals;
        corners.interpolate(V3::splat(self.normal), &[V3::splat(n0), V3::splat(n1), V3::splat(n2)], p)
    }
}

/// A triangle per lane (`Triangle`'s corner and edges), for the lanes of a packet that hit
/// different faces of one mesh: `interpolate` over them is each lane's own triangle's, bit for
/// bit, so a packet's normals need not be asked one lane at a time.
#[derive(Clone, Copy, Debug)]
pub struct TriangleLanes<L: Lane> {
    pub v0: V3<L>,
    pub e1: V3<L>,
    pub e2: V3<L>,
}

impl<L: Lane> TriangleLanes<L> {
    /// `Triangle::interpolate` of each lane's triangle, with its geometric normal `geometric`
    /// and vertex normals `normals`.
    #[inline(always)]
    pub fn interpolate(&self, geometric: V3<L>, normals: &[V3<L>; 3], p: V3<L>) -> V3<L> {
        let [n0, n1, n2] = *normals;
        let (e1, e2) = (self.e1, self.e2);
        let q = p.sub(self.v0);
        let (d00, d01, d11) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
        let inv = L::splat(1.0) / (d00 * d11 - d01 * d01);
        let (d20, d21) = (q.dot(e1), q.dot(e2));
        let u = (d11 * d20 - d01 * d21) * inv;
        let v = (d00 * d21 - d01 * d20) * inv;
        let w = L::splat(1.0) - u - v;
        let n = n0.scale(w).add(n1.scale(u)).add(n2.scale(v));
        let n = V3::select(n.dot(geometric).lt(L::splat(0.0)), n.neg(), n);
        // A zero interpolated normal (opposite vertex normals) falls back to the face's.
        V3::select(L::lt(L::splat(0.0), n.dot(n)), n, geometric)
    }
}

/// A `smooth_triangle` outside a mesh, placed in render space: the triangle kernel, with its
/// vertex normals carried there by the inverse transpose (interpolation commutes with a linear
/// map, so interpolating them is interpolating in object space and carrying the result). As a
/// mesh of one face it walked a tree of one leaf through its own frame for every ray, half as
/// fast again as a flat `triangle`.
#[derive(Clone, Copy, Debug)]
pub struct SmoothTriangle {
    pub tri: Triangle,
    pub normals: [Vec3; 3],
}

impl Shape for SmoothTriangle {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.tri.hit(ray, t_min, t_max)
    }

    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        self.tri.interpolate(&self.normals, p).normalize_or(V3::splat(Vec3::Y))
    }

    /// Flat: no inside.
    #[inline(always)]
    fn inside<L: Lane>(&self, _: V3<L>) -> L::Mask {
        L::mask_from_fn(|_| false)
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

    /// A lone smooth triangle placed in render space (corners by the transform, normals by
    /// its inverse transpose) shades as the same face in a mesh under that transform: rotated,
    /// unevenly scaled and mirrored, at points spread over the face, and where the vertex
    /// normals cancel (the face's own normal).
    #[test]
    fn placed_smooth_triangle_shades_as_the_mesh_face() {
        use crate::geometry::mesh::{Mesh, MeshData};
        use glam::{Affine3A, Mat3, Quat};
        use std::sync::Arc;
        let corners = [Vec3::new(-0.4, 0.0, 0.1), Vec3::new(0.5, 0.1, -0.2), Vec3::new(0.0, 0.9, 0.3)];
        let normal_sets = [
            [Vec3::new(-0.5, 0.2, -1.0), Vec3::new(0.6, 0.1, -0.9), Vec3::new(0.0, 0.7, -0.6)],
            [Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.0, 0.0, 1.0)],
        ];
        let transforms = [
            Affine3A::IDENTITY,
            Affine3A::from_scale_rotation_translation(
                Vec3::new(2.0, 0.5, 1.5),
                Quat::from_euler(glam::EulerRot::XYZ, 0.3, 0.9, -0.4),
                Vec3::new(3.0, -1.0, 7.0),
            ),
            Affine3A::from_scale(Vec3::new(-1.0, 1.0, 1.0)),
        ];
        for normals in normal_sets {
            for m in transforms {
                let mesh = Mesh::new(Arc::new(MeshData::new([(corners, Some(normals))])), m, None);
                let to_render = Mat3::from(m.matrix3).inverse().transpose();
                let placed = SmoothTriangle {
                    tri: Triangle::new(
                        m.transform_point3(corners[0]),
                        m.transform_point3(corners[1]),
                        m.transform_point3(corners[2]),
                    ),
                    normals: normals.map(|n| to_render * n.normalize()),
                };
                for (a, b) in [(0.2, 0.3), (0.6, 0.1), (0.0, 0.0), (0.45, 0.45), (0.1, 0.85)] {
                    let p = corners[0] + (corners[1] - corners[0]) * a + (corners[2] - corners[0]) * b;
                    let q = m.transform_point3(p);
                    let want = mesh.normal::<f32>(0, V3::from_vec3(q)).vec3();
                    let got = Shape::normal::<f32>(&placed, V3::from_vec3(q)).vec3();
                    // The mesh orients to its object-space face; under a mirror the placed
                    // face's winding turns, so compare up to sign there.
                    let d = if m.matrix3.determinant() < 0.0 { got.dot(want).abs() } else { got.dot(want) };
                    assert!(d > 1.0 - 1e-5, "{m:?} at {a},{b}: {got} vs {want}");
                }
            }
        }
    }
}
