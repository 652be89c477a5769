//! The `mesh2` kind: one rippled sheet of exactly N triangles, a height field written as a
//! mesh, as modeller exports are (issue #42's ten-million-triangle scenes).
//!
//! Every vertex, normal and face is a function of its index, so the writer streams them
//! (`write`) and the same sheet held as a `MeshDesc` (`shape`, for `generate`) is the text read
//! back, number for number.

use std::fmt;

use glam::DVec3;

use super::{extent, object_texture, qv, PALETTE};
use crate::desc::{FinishDesc, MeshDesc, MeshFace, PigmentPattern, ShapeDesc, TextureDesc};

/// The grid of an `n`-triangle sheet: `cols` × `rows` squares of two triangles each, the last
/// row cut short so that there are exactly `n` faces.
#[derive(Clone, Copy, Debug)]
struct Grid {
    cols: usize,
    rows: usize,
    /// The sheet spans [-size/2, size/2] in x and z, as the other kinds' cube does.
    size: f64,
}

impl Grid {
    fn new(n: usize) -> Grid {
        let cols = ((n as f64 / 2.0).sqrt().ceil() as usize).max(1);
        let rows = n.div_ceil(2 * cols).max(1);
        Grid { cols, rows, size: extent(n) }
    }

    fn vertex_count(&self) -> usize {
        (self.rows + 1) * (self.cols + 1)
    }

    /// Grid point (r, c) on the ground plane, and the rippled height's gradient there.
    fn point(&self, index: usize) -> (f64, f64, f64, DVec3) {
        let (r, c) = (index / (self.cols + 1), index % (self.cols + 1));
        let (x, z) = ((c as f64 / self.cols as f64 - 0.5) * self.size, (r as f64 / self.rows as f64 - 0.5) * self.size);
        // Two crossing waves of a few wavelengths across the sheet, a tenth of it high.
        let (kx, kz) = (6.0 * std::f64::consts::PI / self.size, 4.0 * std::f64::consts::PI / self.size);
        let amp = 0.05 * self.size;
        let y = 0.8 + 0.3 * self.size + amp * (kx * x).sin() * (kz * z).cos();
        let gradient =
            DVec3::new(amp * kx * (kx * x).cos() * (kz * z).cos(), 0.0, -amp * kz * (kx * x).sin() * (kz * z).sin());
        (x, y, z, gradient)
    }

    fn vertex(&self, index: usize) -> DVec3 {
        let (x, y, z, _) = self.point(index);
        qv(DVec3::new(x, y, z))
    }

    /// The surface normal at the vertex (not unit-long: POV-Ray normalises them).
    fn normal(&self, index: usize) -> DVec3 {
        let (_, _, _, g) = self.point(index);
        qv(DVec3::new(-g.x, 1.0, -g.z))
    }

    /// Face `k`: square k / 2's lower-left or upper-right triangle, both wound the same way.
    fn face(&self, k: usize) -> [u32; 3] {
        let (square, upper) = (k / 2, k % 2 == 1);
        let (r, c) = (square / self.cols, square % self.cols);
        let at = |r: usize, c: usize| (r * (self.cols + 1) + c) as u32;
        if upper {
            [at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)]
        } else {
            [at(r, c), at(r, c + 1), at(r + 1, c)]
        }
    }
}

/// The sheet's look: the `mesh` kind's blue with a highlight.
pub fn texture() -> TextureDesc {
    let [r, g, b] = PALETTE[1];
    object_texture(
        PigmentPattern::Solid(crate::desc::Color::rgb(r, g, b)),
        FinishDesc { phong: 0.5, ..FinishDesc::default() },
    )
}

/// The `n`-triangle sheet, without normals (what `write` writes without `normal_vectors`).
pub fn shape(n: usize) -> ShapeDesc {
    let grid = Grid::new(n);
    let mesh = MeshDesc {
        vertices: (0..grid.vertex_count()).map(|i| grid.vertex(i)).collect(),
        faces: (0..n).map(|k| MeshFace { vertices: grid.face(k), normals: None }).collect(),
        ..MeshDesc::default()
    };
    ShapeDesc::Mesh { mesh: std::sync::Arc::new(mesh), inside_vector: None }
}

/// Writes the sheet's `mesh2 {` … up to its texture, one number at a time; with `normals`,
/// one normal per vertex, which the face indices index too.
pub fn write(o: &mut impl fmt::Write, n: usize, normals: bool) -> fmt::Result {
    let grid = Grid::new(n);
    let count = grid.vertex_count();
    super::write::write_mesh2(
        o,
        (count, (0..count).map(|i| grid.vertex(i))),
        normals.then(|| (count, (0..count).map(|i| grid.normal(i)))),
        (n, (0..n).map(|k| grid.face(k))),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exactly_n_faces_on_existing_vertices() {
        for n in [1, 2, 3, 7, 8, 100, 1001] {
            let ShapeDesc::Mesh { mesh, .. } = shape(n) else { panic!() };
            assert_eq!(mesh.faces.len(), n);
            assert!(mesh.faces.iter().all(|f| f.vertices.iter().all(|&v| (v as usize) < mesh.vertices.len())));
            // No degenerate faces: three distinct corners.
            assert!(mesh.faces.iter().all(|f| { f.vertices[0] != f.vertices[1] && f.vertices[1] != f.vertices[2] }));
        }
    }

    #[test]
    fn normals_point_up_and_across_the_slope() {
        let grid = Grid::new(5000);
        for i in (0..grid.vertex_count()).step_by(37) {
            let n = grid.normal(i);
            assert!(n.y == 1.0);
            // Perpendicular to the two grid directions' differences, to the rounding of the text.
            let (_, _, _, g) = grid.point(i);
            assert!((n.x + g.x).abs() < 1e-4 && (n.z + g.z).abs() < 1e-4);
        }
    }

    #[test]
    fn streamed_text_is_the_shape_written() {
        let n = 333;
        let mut streamed = String::new();
        write(&mut streamed, n, false).unwrap();
        let ShapeDesc::Mesh { mesh, .. } = shape(n) else { panic!() };
        let vertex_lines = streamed.matches(",\n    <").count();
        assert_eq!(vertex_lines, mesh.vertices.len() + n);
        let mut with_normals = String::new();
        write(&mut with_normals, n, true).unwrap();
        // The normals go between the vertices and the faces; the rest is the same text.
        let split = streamed.find("\n  face_indices").unwrap();
        assert!(with_normals.starts_with(&streamed[..split]));
        assert!(with_normals.ends_with(&streamed[split..]));
        assert!(with_normals[split..].starts_with(&format!("\n  normal_vectors {{ {}", mesh.vertices.len())));
    }
}
