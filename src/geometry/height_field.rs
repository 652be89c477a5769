//! `height_field` (POV-Ray 3.4.5.1.6) as a mesh: each square of four neighbouring pixels is two
//! triangles of `geometry::mesh`, so a height field shares the mesh's BVH and the triangle
//! kernel. Pixel column `i` of a `W`-wide image lies at x = i / (W − 1) and row `j` of an
//! `H`-high one at z = 1 − j / (H − 1) (the image's top row at z = 1), y its value in [0, 1];
//! each square is split along the diagonal from (x1, z0) to (x0, z1). Both were measured with
//! POV-Ray 3.7's `trace` on a 3×2 image.

use glam::Vec3;

use super::height_walk::HeightCells;
use super::triangle::Triangle;

/// A height field's grid, kept for its inside test: below the surface, found in the one square
/// under the point instead of by counting the mesh's crossings along a ray.
#[derive(Clone, Debug)]
pub struct HeightGrid {
    width: usize,
    height: usize,
    /// Row by row, row 0 the image's top (as `faces` takes them).
    heights: Vec<f32>,
    /// The mesh's floor (`water_level`, or -inf): surface below it is not there.
    floor: f32,
    /// The walk over the mesh's triangles by cell, once `linked` to them.
    cells: Option<HeightCells>,
}

impl HeightGrid {
    pub fn new(width: usize, height: usize, heights: &[f32], floor: f32) -> HeightGrid {
        HeightGrid { width, height, heights: heights.to_vec(), floor, cells: None }
    }

    /// The grid with its walk over `triangles`, the mesh made of it by `faces` (in any order).
    pub fn linked(self, triangles: &[Triangle]) -> HeightGrid {
        let cells = HeightCells::new(self.width, self.height, &self.heights, self.floor, triangles);
        HeightGrid { cells: Some(cells), ..self }
    }

    /// The walk, once linked: the mesh's own in place of its BVH's.
    #[inline(always)]
    pub fn cells(&self) -> Option<&HeightCells> {
        self.cells.as_ref()
    }

    /// Whether object-space `p` lies below the surface, over the unit square, where the surface
    /// is (not under the water level's floor): where a ray from `p` straight up crosses the
    /// mesh once, as POV-Ray's solid below the surface.
    pub fn below_surface(&self, p: Vec3) -> bool {
        let (w, h) = (self.width, self.height);
        if !(p.x >= 0.0 && p.x <= 1.0 && p.z >= 0.0 && p.z <= 1.0) {
            return false;
        }
        let (gx, gz) = (p.x * (w - 1) as f32, p.z * (h - 1) as f32);
        let (i, k) = ((gx as usize).min(w - 2), (gz as usize).min(h - 2));
        let (fx, fz) = (gx - i as f32, gz - k as f32);
        let y = |i: usize, k: usize| self.heights[(h - 1 - k) * w + i];
        // The square's two triangles (`cell`), split along the diagonal from (x1, z0) to (x0, z1).
        let surface = if fx + fz <= 1.0 {
            y(i, k) + fx * (y(i + 1, k) - y(i, k)) + fz * (y(i, k + 1) - y(i, k))
        } else {
            y(i + 1, k + 1)
                + (1.0 - fx) * (y(i, k + 1) - y(i + 1, k + 1))
                + (1.0 - fz) * (y(i + 1, k) - y(i + 1, k + 1))
        };
        p.y < surface && surface >= self.floor
    }
}

/// The triangles (and, with `smooth`, vertex normals) of a `width` × `height` grid of
/// `heights` (row by row, row 0 the image's top), leaving out triangles wholly below
/// `water_level` (the mesh's floor clips the rest).
pub fn faces(
    width: usize,
    height: usize,
    heights: &[f32],
    smooth: bool,
    water_level: f32,
) -> Vec<([Vec3; 3], Option<[Vec3; 3]>)> {
    let (w, h) = (width, height);
    debug_assert!(w >= 2 && h >= 2 && heights.len() == w * h);
    let vertex = |i: usize, k: usize| {
        let y = heights[(h - 1 - k) * w + i];
        Vec3::new(i as f32 / (w - 1) as f32, y, k as f32 / (h - 1) as f32)
    };
    // Smooth normals: each vertex's adjacent face normals summed, weighted by area (the
    // unnormalised cross products).
    let normals = smooth.then(|| {
        let mut n = vec![Vec3::ZERO; w * h];
        for k in 0..h - 1 {
            for i in 0..w - 1 {
                for [a, b, c] in cell(i, k) {
                    let (pa, pb, pc) = (vertex(a.0, a.1), vertex(b.0, b.1), vertex(c.0, c.1));
                    let f = (pc - pa).cross(pb - pa);
                    for v in [a, b, c] {
                        n[v.1 * w + v.0] += f;
                    }
                }
            }
        }
        n
    });
    let mut out = Vec::with_capacity(2 * (w - 1) * (h - 1));
    for k in 0..h - 1 {
        for i in 0..w - 1 {
            for tri in cell(i, k) {
                let v = tri.map(|(i, k)| vertex(i, k));
                if v.iter().all(|p| p.y < water_level) {
                    continue;
                }
                let n = normals.as_ref().map(|n| tri.map(|(i, k)| n[k * w + i]));
                out.push((v, n));
            }
        }
    }
    out
}

/// The two triangles of the square at grid position (i, k), as (column, z index) corners,
/// wound so that their normals point up, out of the solid below the surface, as POV-Ray's do
/// (the `slope` pattern reads them: flat ground under `slope -y` is 0).
fn cell(i: usize, k: usize) -> [[(usize, usize); 3]; 2] {
    let (a, b, c, d) = ((i, k), (i + 1, k), (i, k + 1), (i + 1, k + 1));
    [[a, c, b], [b, c, d]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::mesh::MeshData;
    use crate::ray::Ray;

    /// The grid's answer is the mesh's crossing parity straight up, off the triangles' edges,
    /// on a random 9×7 field with a water level.
    #[test]
    fn below_surface_is_one_crossing_up() {
        let (w, h) = (9, 7);
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut rand = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 40) as f32 / (1u64 << 24) as f32
        };
        let heights: Vec<f32> = (0..w * h).map(|_| rand()).collect();
        for water in [0.0, 0.4] {
            let mesh = MeshData::new(faces(w, h, &heights, false, water));
            let mesh = if water > 0.0 { mesh.with_floor(water) } else { mesh };
            let grid = HeightGrid::new(w, h, &heights, if water > 0.0 { water } else { f32::NEG_INFINITY });
            let (mut inside, mut checked) = (0, 0);
            for _ in 0..20_000 {
                let p = Vec3::new(rand() * 1.2 - 0.1, rand() * 1.2 - 0.1, rand() * 1.2 - 0.1);
                // Off the grid lines and diagonals, where parity counts an edge twice or not at all.
                let (gx, gz) = (p.x * (w - 1) as f32, p.z * (h - 1) as f32);
                let near = |v: f32| (v - v.round()).abs() < 1e-3;
                if near(gx) || near(gz) || near(gx.fract() + gz.fract()) {
                    continue;
                }
                let up = Ray { origin: p, dir: Vec3::Y, inv_dir: Vec3::Y.recip() };
                let parity = mesh.crossings(&up) % 2 == 1;
                // Points within rounding of the surface may go either way.
                let below = grid.below_surface(p);
                if below != parity && (grid.below_surface(p + Vec3::Y * 1e-4) == grid.below_surface(p - Vec3::Y * 1e-4))
                {
                    panic!("{p:?} (water {water}): grid says {below}, crossings {}", mesh.crossings(&up));
                }
                checked += 1;
                inside += below as u32;
            }
            assert!(checked > 10_000 && inside > 1_000, "{checked} points, {inside} inside");
        }
    }

    /// The 3×2 image POV-Ray was measured on: rows [255 0 0] and [0 0 128].
    #[test]
    fn corners_and_diagonal_as_povray_places_them() {
        let h = [1.0, 0.0, 0.0, 0.0, 0.0, 128.0 / 255.0];
        let f = faces(3, 2, &h, false, 0.0);
        assert_eq!(f.len(), 4);
        assert!(f.iter().any(|(v, _)| v.contains(&Vec3::new(0.0, 1.0, 1.0))));
        assert!(f.iter().any(|(v, _)| v.contains(&Vec3::new(1.0, 128.0 / 255.0, 0.0))));
        // Water at 0.6 leaves out the right square, wholly below it.
        assert_eq!(faces(3, 2, &h, false, 0.6).len(), 2);
        // Every face's normal (by the triangle's winding) points up.
        for (v, _) in faces(3, 2, &h, false, 0.0) {
            assert!((v[1] - v[0]).cross(v[2] - v[0]).y > 0.0, "{v:?}");
        }
    }
}
