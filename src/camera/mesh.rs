//! POV-Ray 3.7's `mesh_camera` (3.4.2.2.3): every pixel's rays come from faces of meshes.
//!
//! Distributions 0–2 give pixel (x, y) of a w×h image the face numbered `w·y + x` (y from the
//! top row; POV-Ray 3.7 shows face row y - 1 in image row y ≥ 1, measured) and shoot from the
//! face's centroid along its normal:
//!
//! | distribution | ray number r of a pixel |
//! |---|---|
//! | 0 | face `w·y + x` of mesh r |
//! | 1 | face `w·h·r + w·y + x` of all meshes' faces in order |
//! | 2 | the image cut into one column block per mesh, left to right; face `bw·y + (x - i·bw)` of mesh i (bw = w / meshes) |
//! | 3 | the image point (u, 1 - v) looked up in the faces' uv map: the first face containing it, and the point of the face with the same barycentric coordinates; `smooth` interpolates the vertex normals there |
//!
//! A ray with no face is not shot (it leaves the pixel's average). The face normal points the
//! way the meshes of POV-Ray's `meshcam_macros.inc` look into the scene: `(c - a) × (b - a)`
//! for corners a, b, c. The camera's `location.z` moves each origin along the normal, and a
//! `direction` with z < 0 reverses the rays (for baking: rays from just outside a surface back
//! onto it).
//!
//! `CameraMesh` is built once per scene, in render space, from the description; it holds the
//! faces flat and, for distribution 3, a grid over uv space so a lookup tests a few faces.

use glam::{DVec2, DVec3};

use crate::camera::frame::RenderFrame;
use crate::desc::MeshCameraDesc;

/// One camera face in render space.
#[derive(Clone, Debug)]
struct Face {
    corners: [DVec3; 3],
    /// Unit face normal.
    normal: DVec3,
    /// Unit vertex normals, when the mesh gives them.
    normals: Option<[DVec3; 3]>,
    uv: Option<[DVec2; 3]>,
}

/// A mesh camera ready to make rays (render space, f64).
#[derive(Clone, Debug)]
pub struct CameraMesh {
    faces: Vec<Face>,
    /// Where each mesh's faces start in `faces`, and one past the last.
    starts: Vec<usize>,
    rays_per_pixel: u32,
    distribution: u8,
    smooth: bool,
    /// Distribution 3's lookup, over all faces with uvs.
    grid: UvGrid,
}

impl CameraMesh {
    pub fn build(desc: &MeshCameraDesc, frame: &RenderFrame) -> CameraMesh {
        let mut faces = Vec::new();
        let mut starts = vec![0];
        for m in &desc.meshes {
            let to_world = m.transform.matrix;
            // Normals go through the inverse transpose (what a transformed triangle's is).
            let normal_matrix = m.transform.inverse.transpose();
            let normal = |n: DVec3| frame.vector(normal_matrix.transform_vector3(n)).try_normalize();
            let mesh = &m.mesh;
            for (i, f) in mesh.faces.iter().enumerate() {
                let [a, b, c] = f.vertices.map(|v| mesh.vertices[v as usize]);
                let Some(n) = normal((c - a).cross(b - a)) else {
                    // A degenerate face keeps its number (the pixel mapping counts it) but
                    // shoots nothing.
                    faces.push(Face { corners: [DVec3::ZERO; 3], normal: DVec3::ZERO, normals: None, uv: None });
                    continue;
                };
                let normals = f.normals.and_then(|ix| {
                    let [na, nb, nc] = ix.map(|k| normal(mesh.normals[k as usize]));
                    Some([na?, nb?, nc?])
                });
                let uv = mesh.uv_faces.get(i).map(|ix| ix.map(|k| mesh.uvs[k as usize]));
                let corners = [a, b, c].map(|p| frame.point(to_world.transform_point3(p)));
                faces.push(Face { corners, normal: n, normals, uv });
            }
            starts.push(faces.len());
        }
        let grid = if desc.distribution == 3 { UvGrid::build(&faces) } else { UvGrid::default() };
        CameraMesh {
            faces,
            starts,
            rays_per_pixel: desc.rays_per_pixel.max(1),
            distribution: desc.distribution,
            smooth: desc.smooth,
            grid,
        }
    }

    /// Rays per pixel, averaged over those that have a face.
    pub fn rays_per_pixel(&self) -> u32 {
        self.rays_per_pixel
    }

    /// Ray number `ray` of pixel (x, y) of a w×h image, with (u, v) the sample's image point
    /// in [0, 1]² (v down; only distribution 3 reads it; POV-Ray 3.7 looks up a pixel's top
    /// left corner, measured): origin on the face and unit
    /// direction along its normal, before `location`'s offset and `direction`'s reversal.
    /// `None` where no face belongs to the pixel.
    pub fn ray(&self, (x, y, w, h): (u32, u32, u32, u32), (u, v): (f64, f64), ray: u32) -> Option<(DVec3, DVec3)> {
        // Measured on POV-Ray 3.7 (a mesh of one face per pixel over a gradient): image row
        // y ≥ 1 shows face row y - 1, and rows 0 and 1 both show face row 0.
        let y = y.saturating_sub(1);
        let pixel = w as usize * y as usize + x as usize;
        let meshes = self.starts.len() - 1;
        let face = match self.distribution {
            0 => {
                let m = ray as usize;
                (m < meshes).then(|| self.starts[m] + pixel).filter(|&f| f < self.starts[m + 1])?
            }
            1 => w as usize * h as usize * ray as usize + pixel,
            2 => {
                let bw = w as usize / meshes.max(1);
                let m = (x as usize).checked_div(bw)?;
                if m >= meshes {
                    return None;
                }
                let f = self.starts[m] + bw * y as usize + (x as usize - m * bw);
                (f < self.starts[m + 1]).then_some(f)?
            }
            _ => return self.uv_ray(DVec2::new(u, 1.0 - v)),
        };
        let f = self.faces.get(face)?;
        if f.normal == DVec3::ZERO {
            return None;
        }
        let centroid = (f.corners[0] + f.corners[1] + f.corners[2]) / 3.0;
        Some((centroid, f.normal))
    }

    /// Distribution 3: the first face whose uv triangle holds `p`.
    fn uv_ray(&self, p: DVec2) -> Option<(DVec3, DVec3)> {
        for &i in self.grid.cell(p) {
            let f = &self.faces[i as usize];
            let Some(uv) = f.uv else { continue };
            let Some(b) = barycentric(uv, p) else { continue };
            let origin = f.corners[0] * b[0] + f.corners[1] * b[1] + f.corners[2] * b[2];
            let normal = match (self.smooth, f.normals) {
                (true, Some(n)) => (n[0] * b[0] + n[1] * b[1] + n[2] * b[2]).try_normalize().unwrap_or(f.normal),
                _ => f.normal,
            };
            return Some((origin, normal));
        }
        None
    }
}

/// The barycentric coordinates of `p` in triangle `t`, if it lies inside (edges included,
/// with a little slack so points on a shared edge find one of the faces).
fn barycentric(t: [DVec2; 3], p: DVec2) -> Option<[f64; 3]> {
    let (e1, e2, d) = (t[1] - t[0], t[2] - t[0], p - t[0]);
    let det = e1.perp_dot(e2);
    if det.abs() < 1e-300 {
        return None;
    }
    let b1 = d.perp_dot(e2) / det;
    let b2 = e1.perp_dot(d) / det;
    let b0 = 1.0 - b1 - b2;
    const SLACK: f64 = -1e-9;
    (b0 >= SLACK && b1 >= SLACK && b2 >= SLACK).then_some([b0, b1, b2])
}

/// A uniform grid over the faces' uv bounds: each cell lists, in face order, the faces whose
/// uv bounds touch it, so "the first face that holds the point" stays the first.
#[derive(Clone, Debug, Default)]
struct UvGrid {
    min: DVec2,
    /// Cells per uv unit along u and v.
    scale: DVec2,
    n: usize,
    /// `cells[k]..cells[k + 1]` index `items` for cell k.
    cells: Vec<u32>,
    items: Vec<u32>,
}

impl UvGrid {
    fn build(faces: &[Face]) -> UvGrid {
        let uvs: Vec<(usize, [DVec2; 3])> =
            faces.iter().enumerate().filter_map(|(i, f)| f.uv.map(|u| (i, u))).collect();
        if uvs.is_empty() {
            return UvGrid::default();
        }
        let (mut min, mut max) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for (_, t) in &uvs {
            for p in t {
                min = min.min(*p);
                max = max.max(*p);
            }
        }
        // About one face per cell.
        let n = ((uvs.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let scale = DVec2::splat(n as f64) / (max - min).max(DVec2::splat(1e-12));
        let grid = UvGrid { min, scale, n, cells: Vec::new(), items: Vec::new() };
        let mut lists = vec![Vec::new(); n * n];
        for (i, t) in &uvs {
            let lo = grid.coords(t[0].min(t[1]).min(t[2]));
            let hi = grid.coords(t[0].max(t[1]).max(t[2]));
            for cy in lo.1..=hi.1 {
                for cx in lo.0..=hi.0 {
                    lists[cy * n + cx].push(*i as u32);
                }
            }
        }
        let mut cells = Vec::with_capacity(n * n + 1);
        let mut items = Vec::new();
        cells.push(0);
        for l in lists {
            items.extend(l);
            cells.push(items.len() as u32);
        }
        UvGrid { cells, items, ..grid }
    }

    /// The cell holding `p`, clamped to the grid.
    fn coords(&self, p: DVec2) -> (usize, usize) {
        let c = ((p - self.min) * self.scale).floor();
        let clamp = |x: f64| (x.max(0.0) as usize).min(self.n - 1);
        (clamp(c.x), clamp(c.y))
    }

    /// The faces to test for `p` (none outside the grid's bounds).
    fn cell(&self, p: DVec2) -> &[u32] {
        if self.n == 0 {
            return &[];
        }
        let c = (p - self.min) * self.scale;
        let slack = 1e-6;
        if !(c.x >= -slack && c.y >= -slack && c.x <= self.n as f64 + slack && c.y <= self.n as f64 + slack) {
            return &[];
        }
        let (cx, cy) = self.coords(p);
        let k = cy * self.n + cx;
        &self.items[self.cells[k] as usize..self.cells[k + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::desc::{MeshCameraMesh, MeshDesc, MeshFace, Transform};

    /// Two triangles side by side in the z = 0 plane, facing +z, with a uv map.
    fn quad_mesh() -> MeshDesc {
        let v = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        MeshDesc {
            // Two faces: the first at x ∈ [0, 1], the second at x ∈ [1, 2].
            vertices: vec![v(0.0, 1.0), v(1.0, 0.0), v(0.0, 0.0), v(1.0, 1.0), v(2.0, 0.0), v(1.0, 0.0)],
            faces: vec![
                MeshFace { vertices: [0, 1, 2], normals: None },
                MeshFace { vertices: [3, 4, 5], normals: None },
            ],
            uvs: vec![DVec2::new(0.0, 1.0), DVec2::new(0.5, 0.0), DVec2::new(0.0, 0.0), DVec2::new(1.0, 1.0)],
            uv_faces: vec![[0, 1, 2], [3, 1, 0]],
            ..MeshDesc::default()
        }
    }

    fn camera(distribution: u8, meshes: usize) -> CameraMesh {
        let mesh = Arc::new(quad_mesh());
        let desc = MeshCameraDesc {
            rays_per_pixel: 1,
            distribution,
            max_distance: 0.0,
            smooth: false,
            meshes: (0..meshes)
                .map(|_| MeshCameraMesh { mesh: mesh.clone(), transform: Transform::default() })
                .collect(),
        };
        let frame = RenderFrame { origin: DVec3::ZERO, unit: 1.0, per_unit: 1.0 };
        CameraMesh::build(&desc, &frame)
    }

    #[test]
    fn pixels_map_to_faces_in_order() {
        let c = camera(0, 1);
        let (o, d) = c.ray((0, 0, 2, 1), (0.25, 0.5), 0).unwrap();
        assert!((o - DVec3::new(1.0 / 3.0, 1.0 / 3.0, 0.0)).length() < 1e-12);
        // Corners top, bottom right, bottom left: the normal looks along +z.
        assert!((d - DVec3::Z).length() < 1e-12, "{d}");
        let (o, _) = c.ray((1, 0, 2, 1), (0.75, 0.5), 0).unwrap();
        assert!(o.x > 1.0);
        // Image row 1 shows face row 0 as row 0 does; row 2 (face row 1) has no faces.
        assert_eq!(c.ray((0, 1, 2, 3), (0.0, 0.0), 0), c.ray((0, 0, 2, 3), (0.0, 0.0), 0));
        assert!(c.ray((0, 2, 2, 3), (0.0, 0.0), 0).is_none(), "no third face");
        assert!(c.ray((0, 0, 2, 1), (0.0, 0.0), 1).is_none(), "no second mesh");
    }

    #[test]
    fn summed_and_side_by_side() {
        let c = camera(1, 2);
        // Ray 1 of pixel 0 of a 1×1 image: face 1 of the summed faces.
        assert!(c.ray((0, 0, 1, 1), (0.5, 0.5), 1).unwrap().0.x > 1.0);
        assert!(c.ray((0, 0, 2, 1), (0.5, 0.5), 2).is_none());
        let c = camera(2, 2);
        // 4×1 image, two blocks of width 2: pixel 2 is face 0 of the second mesh.
        assert!(c.ray((2, 0, 4, 1), (0.6, 0.5), 0).unwrap().0.x < 1.0);
        assert!(c.ray((3, 0, 4, 1), (0.9, 0.5), 0).unwrap().0.x > 1.0);
    }

    #[test]
    fn uv_lookup_finds_the_barycentric_point() {
        let c = camera(3, 1);
        // uv (0.1, 0.5) lies in face 0's uv triangle (0,1), (0.5,0), (0,0): barycentrics
        // b1 = 0.2, b0 = 0.5, b2 = 0.3 → the point 0.5·(0,1) + 0.2·(1,0) + 0.3·(0,0).
        let (o, _) = c.ray((0, 0, 1, 1), (0.1, 0.5), 0).unwrap();
        assert!((o - DVec3::new(0.2, 0.5, 0.0)).length() < 1e-12, "{o}");
        // uv (0.9, 0.9) is in face 1's.
        assert!(c.ray((0, 0, 1, 1), (0.9, 0.1), 0).unwrap().0.x > 1.0);
        // Outside every uv triangle.
        assert!(c.ray((0, 0, 1, 1), (0.9, 0.9), 0).is_none());
    }
}
