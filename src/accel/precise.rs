//! The BVH for the f64 render path: the f32 BVH's tree (same nodes, same primitive order) with
//! every box refitted in f64 from the f64 primitives' bounds, padded by their rounding.
//!
//! Reusing the tree keeps the SAH build in one place and costs one bottom-up pass. The boxes
//! cannot be the f32 ones: those bound the f32 primitives, which were rounded from f64 and may
//! lie a few f32 ulps inside the f64 shapes, so an f64 ray grazing a shape could miss its box.
//! Like every accelerator here it takes a closure for the primitive test and knows no shapes.

use glam::DVec3;

use super::bvh::Bvh;
use crate::geometry::precise::{node_slabs, RayD};

/// A node of `BvhD`: 56 bytes (f64 boxes), children and leaves as in `BvhNode`.
#[derive(Clone, Copy, Debug)]
pub struct BvhNodeD {
    pub min: DVec3,
    pub max: DVec3,
    pub first: u32,
    pub count: u32,
}

const _: () = assert!(std::mem::size_of::<BvhNodeD>() == 56);

/// Bounds are padded by this many f64 ulps of their largest coordinate: the bounds of a sphere
/// (`center ± r`) and of a transformed box round, and so do the hit points tested against them.
const PAD_ULPS: f64 = 64.0 * f64::EPSILON;

#[derive(Clone, Debug, Default)]
pub struct BvhD {
    pub nodes: Vec<BvhNodeD>,
    pub prim_order: Vec<u32>,
}

impl BvhD {
    /// Refits `tree`'s nodes to `bounds` (index `i` is primitive `i`, as for `Bvh::build`).
    pub fn refit(tree: &Bvh, bounds: &[(DVec3, DVec3)]) -> BvhD {
        let padded: Vec<(DVec3, DVec3)> = bounds
            .iter()
            .map(|&(lo, hi)| {
                let pad = lo.abs().max(hi.abs()).max_element() * PAD_ULPS + f64::MIN_POSITIVE;
                (lo - pad, hi + pad)
            })
            .collect();
        let mut nodes: Vec<BvhNodeD> = tree
            .nodes
            .iter()
            .map(|n| BvhNodeD { min: DVec3::INFINITY, max: DVec3::NEG_INFINITY, first: n.first, count: n.count })
            .collect();
        // Children always come after their parent (`Bvh::build` pushes them later), so a pass
        // from the back sees every child before its parent.
        for i in (0..nodes.len()).rev() {
            let n = nodes[i];
            let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
            if n.count > 0 {
                for &p in &tree.prim_order[n.first as usize..(n.first + n.count) as usize] {
                    let (a, b) = padded[p as usize];
                    lo = lo.min(a);
                    hi = hi.max(b);
                }
            } else {
                for c in [&nodes[n.first as usize], &nodes[n.first as usize + 1]] {
                    lo = lo.min(c.min);
                    hi = hi.max(c.max);
                }
            }
            nodes[i].min = lo;
            nodes[i].max = hi;
        }
        BvhD { nodes, prim_order: tree.prim_order.clone() }
    }

    /// Nearest-hit traversal, as `Bvh::traverse`: `test(prim, t_max)` returns a hit nearer than
    /// `t_max`, which then shrinks the search. Returns the number of nodes visited.
    pub fn traverse<F: FnMut(u32, f64) -> Option<f64>>(&self, ray: &RayD, mut t_max: f64, mut test: F) -> u32 {
        if self.nodes.is_empty() {
            return 0;
        }
        let enters = |n: &BvhNodeD, t_max: f64| {
            let (near, far) = node_slabs(n.min, n.max, ray.origin, ray.inv_dir);
            (near <= far && far >= 0.0 && near <= t_max).then_some(near)
        };
        let mut visited = 1;
        if enters(&self.nodes[0], t_max).is_none() {
            return visited;
        }
        let mut stack = [0u32; 64];
        let mut sp = 0usize;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.count > 0 {
                for &p in &self.prim_order[n.first as usize..(n.first + n.count) as usize] {
                    if let Some(t) = test(p, t_max) {
                        t_max = t_max.min(t);
                    }
                }
            } else {
                let (a, b) = (n.first as usize, n.first as usize + 1);
                visited += 2;
                match (enters(&self.nodes[a], t_max), enters(&self.nodes[b], t_max)) {
                    (Some(an), Some(bn)) => {
                        let (near, far) = if an <= bn { (a, b) } else { (b, a) };
                        // The tree is at most `bvh::MAX_DEPTH` (60) deep, so 64 entries suffice.
                        stack[sp] = far as u32;
                        sp += 1;
                        node = near;
                        continue;
                    }
                    (Some(_), None) => {
                        node = a;
                        continue;
                    }
                    (None, Some(_)) => {
                        node = b;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            if sp == 0 {
                return visited;
            }
            sp -= 1;
            node = stack[sp] as usize;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accel::aabb::Aabb;

    #[test]
    fn refitted_boxes_contain_the_f64_bounds_and_their_children() {
        let f64_bounds: Vec<(DVec3, DVec3)> = (0..300)
            .map(|i| {
                let c = DVec3::new((i % 7) as f64 * 1.1, (i / 7 % 7) as f64 * 0.9, (i / 49) as f64 * 1.3) + 1e5;
                (c - 0.3, c + 0.3 + 1e-9)
            })
            .collect();
        let f32_bounds: Vec<Aabb> = f64_bounds.iter().map(|(a, b)| Aabb::new(a.as_vec3(), b.as_vec3())).collect();
        let tree = Bvh::build(&f32_bounds);
        let bvh = BvhD::refit(&tree, &f64_bounds);
        for n in &bvh.nodes {
            if n.count > 0 {
                for &p in &bvh.prim_order[n.first as usize..(n.first + n.count) as usize] {
                    let (lo, hi) = f64_bounds[p as usize];
                    assert!(n.min.cmplt(lo).all() && n.max.cmpgt(hi).all());
                }
            } else {
                for c in [&bvh.nodes[n.first as usize], &bvh.nodes[n.first as usize + 1]] {
                    assert!(n.min.cmple(c.min).all() && n.max.cmpge(c.max).all());
                }
            }
        }
    }
}
