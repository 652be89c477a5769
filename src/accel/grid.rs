//! The chapter's uniform grid ("Bereichsunterteilung", 24.4): the scene's bounding box split into
//! equal cells, each listing the primitives that overlap it, walked in ray order with a 3D DDA
//! (Amanatides & Woo). A hit inside the current cell ends the walk: no later cell can hold a
//! nearer one. Primitives spanning several cells are tested once per cell, as the chapter notes.

use glam::{IVec3, Vec3};

use super::aabb::slabs;
use super::aabb::Aabb;
use crate::ray::Ray;

pub struct Grid {
    pub bounds: Aabb,
    pub res: IVec3,
    cell_size: Vec3,
    /// `cell_start[c]..cell_start[c + 1]` indexes `items` for cell `c` (x fastest).
    cell_start: Vec<u32>,
    items: Vec<u32>,
}

/// About this many cells per primitive (Cleary & Wyvill's λ ≈ 2-3 cells per object is typical).
const CELLS_PER_PRIM: f32 = 2.0;
const MAX_RES: i32 = 128;

impl Grid {
    pub fn build(prims: &[Aabb]) -> Grid {
        let mut bounds = Aabb::EMPTY;
        for b in prims {
            bounds.grow(b);
        }
        if prims.is_empty() {
            return Grid { bounds, res: IVec3::ZERO, cell_size: Vec3::ONE, cell_start: vec![0], items: vec![] };
        }
        // Pad degenerate (flat) extents so every axis has a positive size.
        let extent =
            (bounds.max - bounds.min).max(Vec3::splat(1e-6 * (bounds.max - bounds.min).max_element().max(1e-6)));
        bounds.max = bounds.min + extent;
        let cells = CELLS_PER_PRIM * prims.len() as f32;
        let k = (cells / (extent.x * extent.y * extent.z)).cbrt();
        let res = (extent * k).ceil().as_ivec3().clamp(IVec3::ONE, IVec3::splat(MAX_RES));
        let cell_size = extent / res.as_vec3();
        let n_cells = (res.x * res.y * res.z) as usize;
        let cell_of = |p: Vec3| (((p - bounds.min) / cell_size).floor().as_ivec3()).clamp(IVec3::ZERO, res - 1);
        // Two passes (count, then fill) keep the cell lists in one flat array.
        let mut counts = vec![0u32; n_cells + 1];
        for b in prims {
            let (lo, hi) = (cell_of(b.min), cell_of(b.max));
            for z in lo.z..=hi.z {
                for y in lo.y..=hi.y {
                    for x in lo.x..=hi.x {
                        counts[(x + res.x * (y + res.y * z)) as usize] += 1;
                    }
                }
            }
        }
        let mut start = vec![0u32; n_cells + 1];
        for c in 0..n_cells {
            start[c + 1] = start[c] + counts[c];
        }
        let mut fill = start.clone();
        let mut items = vec![0u32; start[n_cells] as usize];
        for (i, b) in prims.iter().enumerate() {
            let (lo, hi) = (cell_of(b.min), cell_of(b.max));
            for z in lo.z..=hi.z {
                for y in lo.y..=hi.y {
                    for x in lo.x..=hi.x {
                        let c = (x + res.x * (y + res.y * z)) as usize;
                        items[fill[c] as usize] = i as u32;
                        fill[c] += 1;
                    }
                }
            }
        }
        Grid { bounds, res, cell_size, cell_start: start, items }
    }

    /// Walks the cells the ray passes through, nearest first. Returns cells visited.
    pub fn traverse<F: FnMut(u32, f32) -> Option<f32>>(&self, ray: &Ray, mut t_max: f32, mut test: F) -> u32 {
        if self.items.is_empty() {
            return 0;
        }
        let (near, far) = slabs(self.bounds.min, self.bounds.max, ray.origin, ray.inv_dir);
        if near > far || far < 0.0 || near > t_max {
            return 0;
        }
        let t_enter = near.max(0.0);
        let p = ray.at(t_enter);
        let mut cell = (((p - self.bounds.min) / self.cell_size).floor().as_ivec3()).clamp(IVec3::ZERO, self.res - 1);
        let step = IVec3::new(dir_step(ray.dir.x), dir_step(ray.dir.y), dir_step(ray.dir.z));
        // Distance along the ray to the next cell boundary on each axis, and between boundaries.
        let next_boundary = self.bounds.min + (cell + step.max(IVec3::ZERO)).as_vec3() * self.cell_size;
        let mut t_next =
            Vec3::select(step.cmpeq(IVec3::ZERO), Vec3::INFINITY, (next_boundary - ray.origin) * ray.inv_dir);
        let t_delta = Vec3::select(step.cmpeq(IVec3::ZERO), Vec3::INFINITY, (self.cell_size * ray.inv_dir).abs());
        let mut visited = 0;
        loop {
            visited += 1;
            let c = (cell.x + self.res.x * (cell.y + self.res.y * cell.z)) as usize;
            for &prim in &self.items[self.cell_start[c] as usize..self.cell_start[c + 1] as usize] {
                if let Some(t) = test(prim, t_max) {
                    t_max = t_max.min(t);
                }
            }
            let cell_exit = t_next.min_element();
            // A hit before this cell's exit is final: every later cell lies further along the ray.
            if t_max <= cell_exit {
                return visited;
            }
            let axis = if t_next.x <= t_next.y && t_next.x <= t_next.z {
                0
            } else if t_next.y <= t_next.z {
                1
            } else {
                2
            };
            cell[axis] += step[axis];
            if cell[axis] < 0 || cell[axis] >= self.res[axis] {
                return visited;
            }
            t_next[axis] += t_delta[axis];
        }
    }
}

fn dir_step(d: f32) -> i32 {
    if d > 0.0 {
        1
    } else if d < 0.0 {
        -1
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_box_along_an_axis_parallel_ray() {
        let prims: Vec<Aabb> = (0..10)
            .map(|i| Aabb::new(Vec3::new(i as f32 * 2.0, 0.0, 0.0), Vec3::new(i as f32 * 2.0 + 1.0, 1.0, 1.0)))
            .collect();
        let g = Grid::build(&prims);
        let ray = Ray::new(Vec3::new(-5.0, 0.5, 0.5), Vec3::X);
        let mut order = vec![];
        g.traverse(&ray, f32::INFINITY, |p, _| {
            order.push(p);
            None
        });
        // Cells are visited front to back, so the first candidate is the nearest box.
        assert_eq!(order.first(), Some(&0));
        assert!(order.contains(&9));
    }

    #[test]
    fn empty_grid_visits_nothing() {
        let g = Grid::build(&[]);
        assert_eq!(g.traverse(&Ray::new(Vec3::ZERO, Vec3::Z), f32::INFINITY, |_, _| Some(0.0)), 0);
    }
}
