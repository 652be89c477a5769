//! Mapping warps, `warp { cylindrical | spherical | toroidal | planar | cubic }`: a pattern-space
//! point becomes (u, v, depth) the way image maps wrap a point, then is turned by the warp's
//! `orientation` (for `planar`, the plane's normal), and the pattern is read there.
//!
//! Everything here was measured with POV-Ray 3.7's `function { pattern { gradient x|y|z
//! scale 100 translate -50*x|y|z warp { ... } } }`, which prints each coordinate of the warped
//! point, at ten points per warp and for twelve orientations (the tests below hold them).

use glam::{DVec3, Mat3, Vec3};

use crate::desc::WarpMap;
use crate::geometry::uv::box_uv;

/// A render-ready mapping warp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MappingWarp {
    map: Map32,
    /// The turn for `orientation`, applied to (u, v, depth).
    turn: Mat3,
    dist_exp: f32,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Map32 {
    Cylindrical,
    Spherical,
    Toroidal { major_radius: f32 },
    Planar { distance: f32 },
    Cubic,
}

impl MappingWarp {
    /// `orientation` is of unit length (z by default, which turns nothing).
    pub fn new(map: WarpMap, orientation: DVec3, dist_exp: f64) -> MappingWarp {
        let map = match map {
            WarpMap::Cylindrical => Map32::Cylindrical,
            WarpMap::Spherical => Map32::Spherical,
            WarpMap::Toroidal { major_radius } => Map32::Toroidal { major_radius: major_radius as f32 },
            WarpMap::Planar { distance } => Map32::Planar { distance: distance as f32 },
            WarpMap::Cubic => Map32::Cubic,
        };
        MappingWarp { map, turn: turn(orientation.as_vec3()), dist_exp: dist_exp as f32 }
    }

    /// The warped point. Points where a mapping has no direction (on a cylinder's or torus's
    /// axis, at a sphere's centre or on a torus's core circle) stay where they are, as POV-Ray's
    /// do on the axis.
    pub fn apply(&self, p: Vec3) -> Vec3 {
        let around = |p: Vec3| {
            let u = p.z.atan2(p.x) * (0.5 / std::f32::consts::PI);
            u - u.floor()
        };
        let spread = |d: f32| if self.dist_exp == 0.0 { 1.0 } else { d.powf(self.dist_exp) };
        let mapped = match self.map {
            // Only u is spread by the distance: v is the height along the axis.
            Map32::Cylindrical => {
                let rho = (p.x * p.x + p.z * p.z).sqrt();
                Vec3::new(around(p) * spread(rho), p.y, rho)
            }
            Map32::Spherical => {
                let r = p.length();
                if r == 0.0 {
                    return p;
                }
                let v = 0.5 + (p.y / r).clamp(-1.0, 1.0).asin() / std::f32::consts::PI;
                Vec3::new(around(p) * spread(r), v * spread(r), r)
            }
            Map32::Toroidal { major_radius } => {
                let rho = (p.x * p.x + p.z * p.z).sqrt();
                let d = ((rho - major_radius).powi(2) + p.y * p.y).sqrt();
                if rho == 0.0 || d == 0.0 {
                    return p;
                }
                let v = p.y.atan2(rho - major_radius) * (0.5 / std::f32::consts::PI) + 0.5;
                Vec3::new(around(p) * spread(d), v * spread(d), d)
            }
            Map32::Planar { distance } => Vec3::new(p.x, p.y, distance),
            Map32::Cubic => {
                let m = p.abs().max_element();
                if m == 0.0 {
                    return p;
                }
                let uv = box_uv((p / m).as_dvec3(), DVec3::NEG_ONE, DVec3::ONE);
                Vec3::new(uv.x as f32, uv.y as f32, m)
            }
        };
        self.turn * mapped
    }
}

/// POV-Ray 3.7's turn for a unit orientation n, measured column by column with `planar` warps
/// of twelve normals (±x, ±y, ±z, <0,±1,1>, <1,1,0>, <±1,0,1>, <1,2,3>): depth goes along
/// (nx, −ny, nz), u along (ny + nz, 0, −nx) and v along (0, nx + nz, ny). A rotation for the
/// axes; for other orientations it also stretches (u by √2 for <0,1,1>), as POV-Ray does.
fn turn(n: Vec3) -> Mat3 {
    Mat3::from_cols(Vec3::new(n.y + n.z, 0.0, -n.x), Vec3::new(0.0, n.x + n.z, n.y), Vec3::new(n.x, -n.y, n.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn warp(map: WarpMap, orientation: DVec3, dist_exp: f64, p: [f32; 3]) -> Vec3 {
        MappingWarp::new(map, orientation.normalize(), dist_exp).apply(Vec3::from(p))
    }

    fn close(a: Vec3, b: [f32; 3]) {
        assert!((a - Vec3::from(b)).abs().max_element() < 2e-5, "{a} != {b:?}");
    }

    /// POV-Ray 3.7's printed values.
    #[test]
    fn spherical_and_cylindrical_as_povray() {
        let s = |p, e| warp(WarpMap::Spherical, DVec3::Z, e, p);
        close(s([1.0, 0.0, 0.0], 0.0), [0.0, 0.5, 1.0]);
        close(s([0.0, 0.0, -1.0], 0.0), [0.75, 0.5, 1.0]);
        close(s([0.0, -1.0, 0.0], 0.0), [0.0, 0.0, 1.0]);
        close(s([0.5, 0.5, 0.5], 0.0), [0.125, 0.69591, 0.86603]);
        close(s([2.0, 0.3, 0.7], 0.0), [0.05358, 0.54477, 2.14009]);
        close(s([2.0, 0.3, 0.7], 1.0), [0.11467, 1.16586, 2.14009]);
        close(s([-0.2, 0.1, 3.0], 1.0), [0.78395, 1.53600, 3.00832]);
        close(warp(WarpMap::Spherical, DVec3::Y, 0.0, [0.5, 0.5, 0.5]), [0.125, -0.86603, 0.69591]);
        close(warp(WarpMap::Spherical, DVec3::new(1.0, 2.0, 3.0), 0.0, [1.0, 2.0, 3.0]), [1.26565, -1.27357, 3.31008]);
        close(warp(WarpMap::Spherical, DVec3::NEG_Z, 0.0, [1.0, 2.0, 3.0]), [-0.19879, -0.67951, -3.74166]);
        let c = |p, e| warp(WarpMap::Cylindrical, DVec3::Z, e, p);
        close(c([0.5, 0.5, 0.5], 0.0), [0.125, 0.5, 0.70711]);
        close(c([0.3, -2.0, 0.4], 0.0), [0.14758, -2.0, 0.5]);
        close(c([0.3, -2.0, 0.4], 1.0), [0.07379, -2.0, 0.5]);
        close(c([0.0, 1.0, 0.0], 0.0), [0.0, 1.0, 0.0]);
        close(warp(WarpMap::Cylindrical, DVec3::X, 0.0, [1.0, 2.0, 3.0]), [3.16228, 2.0, -0.19879]);
        close(
            warp(WarpMap::Cylindrical, DVec3::new(1.0, 1.0, 0.0), 0.0, [1.0, 2.0, 3.0]),
            [2.37664, -0.82185, 1.27365],
        );
    }

    #[test]
    fn toroidal_planar_and_cubic_as_povray() {
        let t = |p, r, e| warp(WarpMap::Toroidal { major_radius: r }, DVec3::Z, e, p);
        close(t([0.5, 0.5, 0.5], 1.0, 0.0), [0.125, 0.83434, 0.57947]);
        close(t([0.3, -2.0, 0.4], 1.0, 0.0), [0.14758, 0.21101, 2.06155]);
        close(t([0.0, 1.0, 0.0], 1.0, 0.0), [0.0, 1.0, 0.0]);
        close(t([1.0, 0.0, 0.0], 0.5, 1.0), [0.0, 0.25, 0.5]);
        close(t([-0.2, 0.1, 3.0], 0.5, 1.0), [0.65374, 1.27025, 2.50865]);
        let pl = |n: DVec3, d, p| warp(WarpMap::Planar { distance: d }, n, 0.0, p);
        close(pl(DVec3::Z, 0.0, [2.0, 0.3, 0.7]), [2.0, 0.3, 0.0]);
        close(pl(DVec3::Y, 0.5, [0.3, -2.0, 0.4]), [0.3, -0.5, -2.0]);
        close(pl(DVec3::X, 0.2, [0.5, 0.5, 0.5]), [0.2, 0.5, -0.5]);
        close(pl(DVec3::new(0.0, 1.0, 1.0), 0.0, [1.0, 2.0, 3.0]), [1.41421, 1.41421, 1.41421]);
        close(pl(DVec3::new(1.0, 2.0, 3.0), 0.5, [1.0, 2.0, 3.0]), [1.46994, 1.87083, 1.20268]);
        close(pl(DVec3::NEG_Y, 0.0, [1.0, 2.0, 3.0]), [-1.0, 0.0, -2.0]);
        let cu = |p| warp(WarpMap::Cubic, DVec3::Z, 0.0, p);
        close(cu([1.0, 0.0, 0.0]), [0.625, 0.5, 1.0]);
        close(cu([0.0, 1.0, 0.0]), [0.375, 0.83333, 1.0]);
        close(cu([0.0, 0.0, -1.0]), [0.875, 0.5, 1.0]);
        close(cu([2.0, 0.3, 0.7]), [0.58125, 0.525, 2.0]);
        close(cu([0.3, -2.0, 0.4]), [0.39375, 0.2, 2.0]);
        close(cu([-0.2, 0.1, 3.0]), [0.36667, 0.50556, 3.0]);
    }
}
