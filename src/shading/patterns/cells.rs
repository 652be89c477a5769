//! Cellular patterns: `cells` (a random value per unit cube) and `crackle` (Voronoi cells of
//! one jittered point per unit cube).

use glam::Vec3;

use crate::lanes::{Lane, V3};

/// An integer hash of a lattice cell (the `mix32` rounds of `shading::noise`).
fn hash3(x: i32, y: i32, z: i32, salt: u32) -> u32 {
    let mut h = (x as u32).wrapping_mul(0x8da6_b343)
        ^ (y as u32).wrapping_mul(0xd816_3841)
        ^ (z as u32).wrapping_mul(0xcb1a_b31f)
        ^ salt;
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^= h >> 16;
    h
}

fn unit(h: u32) -> f32 {
    (h >> 8) as f32 * (1.0 / 16_777_216.0)
}

fn cell_of(p: Vec3) -> (i32, i32, i32) {
    let f = p.floor();
    (f.x as i32, f.y as i32, f.z as i32)
}

/// `cells`: one value in [0, 1) per unit cube.
#[inline(always)]
pub fn cells<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| {
        let (x, y, z) = cell_of(p.lane(i));
        unit(hash3(x, y, z, 0x0ce1_1500))
    })
}

/// The feature point of a cell.
fn feature(x: i32, y: i32, z: i32) -> Vec3 {
    let h = |k: u32| unit(hash3(x, y, z, 0xc7ac_0000 + k));
    Vec3::new(x as f32 + h(0), y as f32 + h(1), z as f32 + h(2))
}

/// Crackle's parameters, render-ready.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crackle {
    pub form: Vec3,
    pub metric: f32,
    pub offset: f32,
    pub solid: bool,
}

/// `crackle`: `form · (d1, d2, d3)` of the three nearest feature points (default form
/// <-1, 1, 0>: the distance to the cell wall), plus `offset`; `solid` gives each cell one value.
#[inline(always)]
pub fn crackle<L: Lane>(p: V3<L>, c: &Crackle) -> L {
    L::from_fn(|i| crackle_one(p.lane(i), c))
}

fn crackle_one(p: Vec3, c: &Crackle) -> f32 {
    let (cx, cy, cz) = cell_of(p);
    let mut d = [f32::INFINITY; 3];
    let mut nearest = (cx, cy, cz);
    for dz in -1..=1 {
        for dy in -1..=1 {
            for dx in -1..=1 {
                let (x, y, z) = (cx + dx, cy + dy, cz + dz);
                let v = (feature(x, y, z) - p).abs();
                let dist = if c.metric == 2.0 {
                    v.length()
                } else if c.metric == 1.0 {
                    v.x + v.y + v.z
                } else {
                    (v.x.powf(c.metric) + v.y.powf(c.metric) + v.z.powf(c.metric)).powf(1.0 / c.metric)
                };
                if dist < d[0] {
                    d = [dist, d[0], d[1]];
                    nearest = (x, y, z);
                } else if dist < d[1] {
                    d = [d[0], dist, d[1]];
                } else if dist < d[2] {
                    d[2] = dist;
                }
            }
        }
    }
    if c.solid {
        return unit(hash3(nearest.0, nearest.1, nearest.2, 0x5011_d000));
    }
    (c.form.x * d[0] + c.form.y * d[1] + c.form.z * d[2] + c.offset).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_are_constant_per_cube() {
        let v = |p: [f32; 3]| cells::<f32>(V3::from_vec3(Vec3::from(p)));
        assert_eq!(v([0.1, 0.2, 0.3]), v([0.9, 0.8, 0.7]));
        assert_ne!(v([0.1, 0.2, 0.3]), v([1.1, 0.2, 0.3]));
    }

    #[test]
    fn crackle_is_zero_on_walls_and_in_range() {
        let c = Crackle { form: Vec3::new(-1.0, 1.0, 0.0), metric: 2.0, offset: 0.0, solid: false };
        for i in 0..2000 {
            let p = Vec3::new((i as f32 * 0.37).sin() * 9.0, (i as f32 * 0.11).cos() * 5.0, i as f32 * 0.01);
            let v = crackle_one(p, &c);
            assert!((0.0..=1.0).contains(&v));
        }
    }
}
