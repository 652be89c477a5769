//! `bicubic_patch` → triangles (POV-Ray 3.4.5.2.1). A Bézier patch over 16 control points,
//! written as 4 rows of 4: `u` runs along a row, `v` from row to row. It is cut into
//! 2^u_steps × 2^v_steps quads of two triangles each, every vertex carrying the surface normal
//! from the Bézier derivatives (∂P/∂u × ∂P/∂v), so the patch shades as the smooth surface, and
//! the result is an ordinary mesh: the mesh machinery (its BVH, its triangle kernel, packets)
//! traces it. A patch is not solid: it gets no `inside_vector`, so nothing is inside it, as in
//! POV-Ray.
//!
//! POV-Ray subdivides adaptively when `flatness` > 0 and stops once a piece is flat enough;
//! strahl always subdivides to the steps given, the finer of the two.

use glam::DVec3;

use crate::desc::{MeshDesc, MeshFace};

/// Most subdivision steps per direction: 2^8 = 256 rows of quads, 131 072 triangles a patch.
pub const MAX_STEPS: u32 = 8;

/// The four cubic Bernstein polynomials at `t`, and their derivatives.
fn bernstein(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    let b = [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t];
    let d = [-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t];
    (b, d)
}

/// The patch's point, ∂P/∂u and ∂P/∂v at (u, v).
pub fn eval(points: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    let (mut p, mut pu, mut pv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for row in 0..4 {
        for col in 0..4 {
            let c = points[row * 4 + col];
            p += c * (bu[col] * bv[row]);
            pu += c * (du[col] * bv[row]);
            pv += c * (bu[col] * dv[row]);
        }
    }
    (p, pu, pv)
}

/// The surface normal at (u, v), not normalised. Where a row or column of control points
/// collapses to a point (the apex of the teapot's lid) the derivatives' cross product
/// vanishes; the normal is then taken a little way towards the patch's centre, where it is
/// the limit of the normals around the apex.
pub fn normal(points: &[DVec3; 16], u: f64, v: f64) -> DVec3 {
    let scale = points.iter().fold(0.0f64, |m, p| m.max(p.abs().max_element())).max(f64::MIN_POSITIVE);
    let (mut u, mut v) = (u, v);
    let mut step = 1e-6;
    for _ in 0..6 {
        let (_, pu, pv) = eval(points, u, v);
        let n = pu.cross(pv);
        if n.length() > 1e-12 * scale * scale {
            return n;
        }
        u += (0.5 - u) * step;
        v += (0.5 - v) * step;
        step *= 10.0;
    }
    DVec3::ZERO
}

/// The patch cut into 2^u_steps × 2^v_steps quads, two smooth triangles each. Triangles of
/// zero area (along a collapsed edge) are left out: no ray can hit them.
pub fn tessellate(points: &[DVec3; 16], u_steps: u32, v_steps: u32) -> MeshDesc {
    let (nu, nv) = (1usize << u_steps.min(MAX_STEPS), 1usize << v_steps.min(MAX_STEPS));
    let mut mesh = MeshDesc::default();
    mesh.vertices.reserve((nu + 1) * (nv + 1));
    mesh.normals.reserve((nu + 1) * (nv + 1));
    for j in 0..=nv {
        let v = j as f64 / nv as f64;
        for i in 0..=nu {
            let u = i as f64 / nu as f64;
            mesh.vertices.push(eval(points, u, v).0);
            mesh.normals.push(normal(points, u, v));
        }
    }
    let at = |i: usize, j: usize| (j * (nu + 1) + i) as u32;
    for j in 0..nv {
        for i in 0..nu {
            let quad = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            for tri in [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]] {
                let [a, b, c] = tri.map(|k| mesh.vertices[k as usize]);
                if (b - a).cross(c - a) != DVec3::ZERO {
                    mesh.faces.push(MeshFace { vertices: tri, normals: Some(tri) });
                }
            }
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat patch: the control points of the unit square in z = 0, evenly spaced.
    fn flat() -> [DVec3; 16] {
        std::array::from_fn(|k| DVec3::new((k % 4) as f64 / 3.0, (k / 4) as f64 / 3.0, 0.0))
    }

    #[test]
    fn corners_are_interpolated_and_the_grid_has_the_steps() {
        let mut p = flat();
        p[5].z = 1.0;
        let m = tessellate(&p, 2, 1);
        assert_eq!(m.vertices.len(), 5 * 3);
        assert_eq!(m.faces.len(), 4 * 2 * 2);
        assert_eq!(m.vertices[0], p[0]);
        assert!((m.vertices[4] - p[3]).length() < 1e-12);
        assert!((m.vertices[14] - p[15]).length() < 1e-12);
    }

    #[test]
    fn a_flat_patch_has_the_plane_normal_and_linear_points() {
        let m = tessellate(&flat(), 3, 3);
        for (v, n) in m.vertices.iter().zip(&m.normals) {
            assert!(v.z.abs() < 1e-12);
            assert!((n.normalize() - DVec3::Z).length() < 1e-9, "{n}");
        }
        // 9 vertices a row: the second vertex of the second row.
        assert!((m.vertices[10] - DVec3::new(1.0 / 8.0, 1.0 / 8.0, 0.0)).length() < 1e-12);
    }

    #[test]
    fn derivatives_match_differences() {
        let p: [DVec3; 16] =
            std::array::from_fn(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, ((k * 7) % 5) as f64 * 0.3));
        let (u, v, h) = (0.3, 0.6, 1e-6);
        let (_, pu, pv) = eval(&p, u, v);
        let du = (eval(&p, u + h, v).0 - eval(&p, u - h, v).0) / (2.0 * h);
        let dv = (eval(&p, u, v + h).0 - eval(&p, u, v - h).0) / (2.0 * h);
        assert!((pu - du).length() < 1e-6 && (pv - dv).length() < 1e-6);
    }

    #[test]
    fn a_collapsed_row_gets_the_limit_normal_and_no_empty_triangles() {
        // The first row collapses to the apex (0, 0, 1) of a cone-like cap.
        let mut p = flat();
        for q in p.iter_mut().take(4) {
            *q = DVec3::new(0.5, 0.0, 1.0);
        }
        let m = tessellate(&p, 2, 2);
        assert!(m.normals.iter().all(|n| n.length() > 0.0));
        assert_eq!(m.faces.len(), 4 * 4 * 2 - 4);
    }
}
