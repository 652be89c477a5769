//! `height_field` (POV-Ray 3.4.5.1.6) as a mesh: each square of four neighbouring pixels is two
//! triangles of `geometry::mesh`, so a height field shares the mesh's BVH and the triangle
//! kernel. Pixel column `i` of a `W`-wide image lies at x = i / (W − 1) and row `j` of an
//! `H`-high one at z = 1 − j / (H − 1) (the image's top row at z = 1), y its value in [0, 1];
//! each square is split along the diagonal from (x1, z0) to (x0, z1). Both were measured with
//! POV-Ray 3.7's `trace` on a 3×2 image.

use glam::Vec3;

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
