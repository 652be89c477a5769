//! Surface coordinates for `uv_mapping` (POV-Ray 3.4.6.7): (u, v) of a point on a shape, from
//! the object-space point (and, for meshes, the face and its `uv_vectors`).
//!
//! Formulas measured on POV-Ray 3.7 (an orthographic view of each shape with `uv_mapping
//! gradient x` and `gradient y` pigments reading u and v back):
//!
//! | shape | u | v |
//! |---|---|---|
//! | sphere | `0.75 + atan2(x, -z) / 2π` (mod 1), from the centre | `acos(-y) / π` |
//! | torus | `0.5 - atan2(z, x) / 2π` (mod 1) around the major circle | `0.5 + atan2(y, ρ - R) / 2π` (mod 1) around the minor one, ρ = √(x² + z²) |
//! | mesh, mesh2 | the face's `uv_vectors` interpolated barycentrically | |
//! | box | the faces unfolded into a cross (`box_uv`) | |
//!
//! Only uv-mapped materials compute these (`render::trace`); everything else pays nothing.

use std::sync::Arc;

use glam::{DMat4, DVec2, DVec3};

use crate::desc::{MeshDesc, ShapeDesc};

/// Whether `shape` has surface coordinates here (others keep 3-D pattern space, warned).
pub fn has_uv(shape: &ShapeDesc) -> bool {
    match shape {
        ShapeDesc::Sphere { .. } | ShapeDesc::Torus { .. } | ShapeDesc::Box { .. } => true,
        ShapeDesc::Mesh { mesh, .. } => !mesh.uv_faces.is_empty(),
        _ => false,
    }
}

/// A shape's uv map, in its object space.
#[derive(Clone, Debug, PartialEq)]
pub enum UvShape {
    Sphere {
        center: DVec3,
    },
    Torus {
        major: f64,
    },
    Box {
        min: DVec3,
        max: DVec3,
    },
    /// The description's faces and uvs; hits name faces in `MeshData` order, which
    /// `MeshData::source_face` maps back.
    Mesh(Arc<MeshDesc>),
}

/// How a uv-mapped material finds (u, v) at a render-space hit.
#[derive(Clone, Debug, PartialEq)]
pub struct UvMap {
    pub object_from_render: DMat4,
    pub shape: UvShape,
}

impl UvMap {
    /// The uv map of `shape` placed by `object_from_render`, if it has one.
    pub fn new(shape: &ShapeDesc, object_from_render: DMat4) -> Option<UvMap> {
        let shape = match shape {
            ShapeDesc::Sphere { center, .. } => UvShape::Sphere { center: *center },
            ShapeDesc::Torus { major, .. } => UvShape::Torus { major: *major },
            ShapeDesc::Box { corner1, corner2 } => {
                UvShape::Box { min: corner1.min(*corner2), max: corner1.max(*corner2) }
            }
            ShapeDesc::Mesh { mesh, .. } if !mesh.uv_faces.is_empty() => UvShape::Mesh(mesh.clone()),
            _ => return None,
        };
        Some(UvMap { object_from_render, shape })
    }

    /// (u, v) at render-space point `p`; `face` is the hit's face as the description numbers
    /// it, with that face's three object-space corners (meshes only).
    pub fn uv(&self, p: DVec3, face: Option<(usize, [DVec3; 3])>) -> DVec2 {
        let q = self.object_from_render.transform_point3(p);
        let turn = std::f64::consts::TAU;
        match &self.shape {
            UvShape::Sphere { center } => {
                let d = (q - *center).normalize_or_zero();
                DVec2::new(
                    (0.75 + d.x.atan2(0.0 - d.z) / turn).rem_euclid(1.0),
                    (-d.y).clamp(-1.0, 1.0).acos() / std::f64::consts::PI,
                )
            }
            UvShape::Torus { major } => {
                let rho = q.x.hypot(q.z);
                DVec2::new(
                    (0.5 - q.z.atan2(q.x) / turn).rem_euclid(1.0),
                    (0.5 + q.y.atan2(rho - major) / turn).rem_euclid(1.0),
                )
            }
            UvShape::Box { min, max } => box_uv(q, *min, *max),
            UvShape::Mesh(mesh) => {
                let Some((f, [a, b, c])) = face else { return DVec2::ZERO };
                let Some(uv) = mesh.uv_faces.get(f) else { return DVec2::ZERO };
                let w = barycentric(a, b, c, q);
                let t = uv.map(|k| mesh.uvs[k as usize]);
                t[0] * w[0] + t[1] * w[1] + t[2] * w[2]
            }
        }
    }
}

/// POV-Ray 3.7's box map (the reference's "UV Boxmap" figure), measured with `uv_mapping`
/// gradients on each face of a cube and of a box of sides 4, 4, 4 offset from the origin:
/// the faces unfold into a cross four faces wide and three high, each face scaled to its
/// cell. The middle row (v from 1/3 to 2/3, up the box) runs -x, +z, +x, -z in u, each seen
/// from outside with u growing to the right; +y is the cell above +z (its -z edge at the
/// top), -y the cell below (its +z edge at the top). A point takes the face it is nearest.
pub(crate) fn box_uv(q: DVec3, min: DVec3, max: DVec3) -> DVec2 {
    let a = ((q - min) / (max - min).max(DVec3::splat(f64::MIN_POSITIVE))).clamp(DVec3::ZERO, DVec3::ONE);
    let (below, above) = ((q - min).abs(), (max - q).abs());
    let gap = below.min(above);
    let (u, v) = if gap.x <= gap.y && gap.x <= gap.z {
        let u = if below.x <= above.x { a.z } else { 2.0 + (1.0 - a.z) };
        (u, 1.0 + a.y)
    } else if gap.y <= gap.z {
        let v = if below.y <= above.y { a.z } else { 2.0 + (1.0 - a.z) };
        (1.0 + a.x, v)
    } else {
        let u = if below.z <= above.z { 3.0 + (1.0 - a.x) } else { 1.0 + a.x };
        (u, 1.0 + a.y)
    };
    DVec2::new(u / 4.0, v / 3.0)
}

/// Barycentric weights of `p` (on or near the triangle's plane) in triangle a, b, c.
fn barycentric(a: DVec3, b: DVec3, c: DVec3, p: DVec3) -> [f64; 3] {
    let (e1, e2, d) = (b - a, c - a, p - a);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (dp1, dp2) = (d.dot(e1), d.dot(e2));
    let det = d11 * d22 - d12 * d12;
    if det.abs() < 1e-300 {
        return [1.0, 0.0, 0.0];
    }
    let w1 = (d22 * dp1 - d12 * dp2) / det;
    let w2 = (d11 * dp2 - d12 * dp1) / det;
    [1.0 - w1 - w2, w1, w2]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec2, b: DVec2) {
        assert!((a - b).length() < 1e-9, "{a} != {b}");
    }

    #[test]
    fn sphere_and_torus_coordinates() {
        let s = UvMap::new(&ShapeDesc::Sphere { center: DVec3::ZERO, radius: 2.0 }, DMat4::IDENTITY).unwrap();
        // The point facing the default camera (-z) has u = 0.75; the equator v = 0.5.
        close(s.uv(DVec3::new(0.0, 0.0, -2.0), None), DVec2::new(0.75, 0.5));
        close(s.uv(DVec3::new(2.0, 0.0, 0.0), None), DVec2::new(0.0, 0.5));
        close(s.uv(DVec3::new(0.0, 2.0, 0.0), None), DVec2::new(0.75, 1.0));
        let t = UvMap::new(&ShapeDesc::Torus { major: 1.0, minor: 0.25 }, DMat4::IDENTITY).unwrap();
        close(t.uv(DVec3::new(0.0, 0.0, 1.25), None), DVec2::new(0.25, 0.5));
        close(t.uv(DVec3::new(1.0, 0.25, 0.0), None), DVec2::new(0.5, 0.75));
        close(t.uv(DVec3::new(-1.0, -0.25, 0.0), None), DVec2::new(0.0, 0.25));
    }

    #[test]
    fn box_faces_unfold_into_a_cross() {
        // Figures read back from POV-Ray 3.7 (16-bit PPM) on a box of sides 4, 4, 4.
        let shape = ShapeDesc::Box { corner1: DVec3::new(3.0, 2.0, 1.0), corner2: DVec3::new(-1.0, -2.0, -3.0) };
        let b = UvMap::new(&shape, DMat4::IDENTITY).unwrap();
        let near = |p: DVec3, u: f64, v: f64| {
            let got = b.uv(p, None);
            assert!((got - DVec2::new(u, v)).length() < 1e-4, "{p}: {got} vs ({u}, {v})");
        };
        near(DVec3::new(0.108, 0.892, -3.0), 0.9307, 0.5743);
        near(DVec3::new(1.692, -0.692, -3.0), 0.8318, 0.4424);
        near(DVec3::new(0.108, 2.0, 0.892), 0.3193, 0.6757);
        near(DVec3::new(1.692, 2.0, -0.692), 0.4182, 0.8076);
        near(DVec3::new(3.0, 0.892, -0.692), 0.6057, 0.5743);
        near(DVec3::new(3.0, -0.692, 0.892), 0.5068, 0.4424);
        // The unit cube's -x, +z and -y faces, and a point just inside a face takes that face.
        let c = UvMap::new(&ShapeDesc::Box { corner1: -DVec3::ONE, corner2: DVec3::ONE }, DMat4::IDENTITY).unwrap();
        close(c.uv(DVec3::new(-1.0, 0.0, 0.0), None), DVec2::new(0.125, 0.5));
        close(c.uv(DVec3::new(0.0, 0.0, 1.0), None), DVec2::new(0.375, 0.5));
        close(c.uv(DVec3::new(0.0, -1.0, 0.0), None), DVec2::new(0.375, 1.0 / 6.0));
        close(c.uv(DVec3::new(0.5, 0.999_999_999, 0.2), None), DVec2::new(0.4375, 0.8));
    }

    #[test]
    fn mesh_coordinates_interpolate() {
        let mesh = MeshDesc {
            vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            faces: vec![crate::desc::MeshFace { vertices: [0, 1, 2], normals: None }],
            uvs: vec![DVec2::new(0.5, 0.5), DVec2::new(1.0, 0.5), DVec2::new(0.5, 1.0)],
            uv_faces: vec![[0, 1, 2]],
            ..MeshDesc::default()
        };
        let shape = ShapeDesc::Mesh { mesh: Arc::new(mesh), inside_vector: None };
        let m = UvMap::new(&shape, DMat4::IDENTITY).unwrap();
        let face = Some((0, [DVec3::ZERO, DVec3::X, DVec3::Y]));
        close(m.uv(DVec3::new(0.5, 0.25, 0.0), face), DVec2::new(0.75, 0.625));
    }
}
