//! Empty space for the julia_fractal march (`julia::Julia::solve`): the cube around the
//! object's bounding ball cut into cells, each marked where a bound proves every point of it
//! outside, so that the march's samples there are known without iterating their orbits. The
//! bound is a guarantee (`Julia::probe`), so the march finds what it found without the cells.
//!
//! The cells depend only on what shapes the fractal (function, parameter, iterations, slice),
//! not on its transform, so they are built once per distinct fractal and shared: a process-wide
//! cache, which the 64 copies of one julia in scenes/kernels/julia_fractal.pov all hit.

use std::sync::{Arc, Mutex};

use glam::DVec3;
use rayon::prelude::*;

/// Cells along each axis of the cube.
const FINE: usize = 64;

/// Fine cells along each axis of a coarse one: a coarse cell proven empty marks its
/// `RATIO³` fine cells without asking for each.
const RATIO: usize = 4;

/// Bits of one slab of coarse cells (`RATIO` fine rows): whole words, so slabs are built apart.
const SLAB: usize = RATIO * FINE * FINE;
const _: () = assert!(SLAB % 64 == 0 && FINE % RATIO == 0);

/// Distinct fractals whose cells are kept; the oldest goes first.
const KEPT: usize = 64;

/// What decides a fractal's cells: its function, parameter, iterations and slice, as bits.
pub type Key = [u64; 10];

#[derive(Debug)]
pub struct EmptyCells {
    radius: f64,
    /// Cells per object unit.
    scale: f64,
    /// One bit per cell, `(i·FINE + j)·FINE + k`: set where every point is outside.
    bits: Vec<u64>,
}

impl EmptyCells {
    /// The cells of `[-radius, radius]³`; `reach(p)` is a distance within which every point
    /// around `p` is outside, 0 where none is known. Slabs of coarse cells are built on all
    /// cores (tests/reference/scenes/julias.pov, four quaternion fractals: build 0.51 s on one
    /// core, 0.39 s on two busy ones).
    fn build(radius: f64, reach: impl Fn(DVec3) -> f64 + Sync) -> EmptyCells {
        let size = 2.0 * radius / FINE as f64;
        let half_diagonal = |size: f64| 0.5 * 3f64.sqrt() * size;
        let center = |i: usize, j: usize, k: usize, size: f64| {
            DVec3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * size - DVec3::splat(radius)
        };
        let mut bits = vec![0u64; FINE * FINE * FINE / 64];
        let coarse = FINE / RATIO;
        bits.par_chunks_mut(SLAB / 64).enumerate().for_each(|(ci, slab)| {
            for (cj, ck) in (0..coarse).flat_map(|j| (0..coarse).map(move |k| (j, k))) {
                let all = reach(center(ci, cj, ck, size * RATIO as f64)) >= half_diagonal(size * RATIO as f64);
                for (fi, fj, fk) in cube(RATIO) {
                    let (i, j, k) = (ci * RATIO + fi, cj * RATIO + fj, ck * RATIO + fk);
                    if all || reach(center(i, j, k, size)) >= half_diagonal(size) {
                        // Within the slab: its first row is ci·RATIO.
                        let at = (fi * FINE + j) * FINE + k;
                        slab[at / 64] |= 1 << (at % 64);
                    }
                }
            }
        });
        EmptyCells { radius, scale: 1.0 / size, bits }
    }

    /// Whether `p` lies in a cell proven empty (false off the cube).
    #[inline]
    pub fn empty(&self, p: DVec3) -> bool {
        let c = (p + DVec3::splat(self.radius)) * self.scale;
        // NaN fails too.
        if !(c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0) {
            return false;
        }
        let (i, j, k) = (c.x as usize, c.y as usize, c.z as usize);
        if i >= FINE || j >= FINE || k >= FINE {
            return false;
        }
        let at = (i * FINE + j) * FINE + k;
        (self.bits[at / 64] >> (at % 64)) & 1 == 1
    }

    /// The cells of the fractal `key`, built by `build`'s `reach` the first time they are asked
    /// for.
    pub fn shared(key: Key, radius: f64, reach: impl Fn(DVec3) -> f64 + Sync) -> Arc<EmptyCells> {
        static CACHE: Mutex<Vec<(Key, f64, Arc<EmptyCells>)>> = Mutex::new(Vec::new());
        // A poisoned lock only means another build panicked: the entries are whole.
        let lock = || CACHE.lock().unwrap_or_else(|e| e.into_inner());
        let find = |cache: &[(Key, f64, Arc<EmptyCells>)]| {
            cache.iter().find(|(k, r, _)| *k == key && *r == radius).map(|(_, _, c)| c.clone())
        };
        if let Some(cells) = find(&lock()) {
            return cells;
        }
        // Built without the lock: a rayon worker waiting on the build may take up another
        // fractal's construction, which would then wait on a lock its own thread holds.
        let cells = Arc::new(EmptyCells::build(radius, reach));
        let mut cache = lock();
        if let Some(built) = find(&cache) {
            return built;
        }
        if cache.len() >= KEPT {
            cache.remove(0);
        }
        cache.push((key, radius, cells.clone()));
        cells
    }
}

/// Every `(i, j, k)` of an `n³` grid.
fn cube(n: usize) -> impl Iterator<Item = (usize, usize, usize)> {
    (0..n).flat_map(move |i| (0..n).flat_map(move |j| (0..n).map(move |k| (i, j, k))))
}
