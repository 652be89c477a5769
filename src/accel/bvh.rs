//! Bounding volume hierarchy (chapter 24.4, "Hierarchien"): binned SAH build, flat nodes.
//!
//! The BVH never knows what a primitive is: it is built from bounds and traversed with a closure
//! that tests one primitive (the obvhs pattern), so shapes stay in `geometry`.

use glam::Vec3;

mod build;

use super::aabb::slabs;
use super::aabb::Aabb;
use crate::ray::Ray;

/// A flat node: 32 bytes, two per 64-byte cache line.
///
/// Interior nodes have `count == 0` and their children at `first` and `first + 1` (siblings are
/// adjacent, so one index suffices). Leaves hold `count` primitives starting at `first` in
/// `Bvh::prim_order`.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub struct BvhNode {
    pub min: [f32; 3],
    pub first: u32,
    pub max: [f32; 3],
    pub count: u32,
}

const _: () = assert!(std::mem::size_of::<BvhNode>() == 32);

impl BvhNode {
    #[inline]
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }

    #[inline]
    pub fn bounds(&self) -> (Vec3, Vec3) {
        (Vec3::from_array(self.min), Vec3::from_array(self.max))
    }
}

#[derive(Clone, Debug, Default)]
pub struct Bvh {
    pub nodes: Vec<BvhNode>,
    /// Leaf ranges index this; it maps to the caller's primitive indices.
    pub prim_order: Vec<u32>,
}

/// Deepest tree built. Traversal stacks hold 64 entries, one per level at most, so no subtree
/// is ever dropped; SAH trees over a million primitives are about 30 deep.
pub const MAX_DEPTH: usize = 60;

impl Bvh {
    /// Interior node `n`'s children, nearer first for a packet travelling along `dir` (one
    /// lane's direction stands for the packet's): ordered along the axis that separates the
    /// children's centres most. The order only speeds the walk; no result depends on it.
    #[inline(always)]
    pub fn near_far(&self, n: &BvhNode, dir: Vec3) -> (u32, u32) {
        let (a, b) = (&self.nodes[n.first as usize], &self.nodes[n.first as usize + 1]);
        let ca = Vec3::from_array(a.min) + Vec3::from_array(a.max);
        let cb = Vec3::from_array(b.min) + Vec3::from_array(b.max);
        let sep = (cb - ca).abs();
        let axis = if sep.x >= sep.y && sep.x >= sep.z {
            0
        } else if sep.y >= sep.z {
            1
        } else {
            2
        };
        if (cb[axis] - ca[axis]) * dir[axis] >= 0.0 {
            (n.first, n.first + 1)
        } else {
            (n.first + 1, n.first)
        }
    }

    /// Builds over primitives with the given bounds; index `i` of `bounds` is primitive `i`.
    /// Runs on the current rayon pool and gives the same nodes as `build_serial`. On a pool of
    /// one thread it is `build_serial`: the parallel build holds its subtrees' nodes twice for
    /// a moment (once in pieces, once laid end to end), which buys nothing there.
    pub fn build(bounds: &[Aabb]) -> Bvh {
        Bvh::build_weighted(bounds, None)
    }

    /// `build` with each primitive's test weighed at `weights[i]` node visits (all 1 where
    /// None: the tree `build` makes): costly primitives are split into smaller leaves.
    pub fn build_weighted(bounds: &[Aabb], weights: Option<&[u32]>) -> Bvh {
        let grain = if rayon::current_num_threads() > 1 { build::Grain::PARALLEL } else { build::Grain::SERIAL };
        build::build(bounds, weights, grain)
    }

    /// `build` on the calling thread alone.
    pub fn build_serial(bounds: &[Aabb]) -> Bvh {
        build::build(bounds, None, build::Grain::SERIAL)
    }

    /// Whether `other` has the same nodes, bit for bit, in the same order, over the same
    /// primitive order.
    pub fn same_as(&self, other: &Bvh) -> bool {
        let bits = |n: &BvhNode| (n.min.map(f32::to_bits), n.first, n.max.map(f32::to_bits), n.count);
        self.prim_order == other.prim_order
            && self.nodes.len() == other.nodes.len()
            && self.nodes.iter().zip(&other.nodes).all(|(x, y)| bits(x) == bits(y))
    }

    pub fn depth(&self) -> usize {
        fn walk(b: &Bvh, i: usize) -> usize {
            let n = &b.nodes[i];
            if n.is_leaf() {
                1
            } else {
                1 + walk(b, n.first as usize).max(walk(b, n.first as usize + 1))
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            walk(self, 0)
        }
    }

    /// Nearest-hit traversal. `test(prim, t_max)` tests one primitive and returns its hit
    /// distance if it is nearer than `t_max`; traversal shrinks `t_max` as hits are found.
    /// Returns the number of nodes visited, for statistics.
    #[inline]
    pub fn traverse<F: FnMut(u32, f32) -> Option<f32>>(&self, ray: &Ray, mut t_max: f32, mut test: F) -> u32 {
        if self.nodes.is_empty() {
            return 0;
        }
        let mut stack = [0u32; 64];
        let mut sp = 0usize;
        let mut node = &self.nodes[0];
        let mut visited = 1;
        let (root_near, root_far) =
            slabs(Vec3::from_array(node.min), Vec3::from_array(node.max), ray.origin, ray.inv_dir);
        if root_near > root_far || root_far < 0.0 || root_near > t_max {
            return visited;
        }
        loop {
            if node.is_leaf() {
                for &p in &self.prim_order[node.first as usize..(node.first + node.count) as usize] {
                    if let Some(t) = test(p, t_max) {
                        t_max = t_max.min(t);
                    }
                }
            } else {
                // Visit the nearer child first so later boxes are culled by the shrunk t_max.
                let a = &self.nodes[node.first as usize];
                let b = &self.nodes[node.first as usize + 1];
                visited += 2;
                let (an, af) = slabs(Vec3::from_array(a.min), Vec3::from_array(a.max), ray.origin, ray.inv_dir);
                let (bn, bf) = slabs(Vec3::from_array(b.min), Vec3::from_array(b.max), ray.origin, ray.inv_dir);
                let hit_a = an <= af && af >= 0.0 && an <= t_max;
                let hit_b = bn <= bf && bf >= 0.0 && bn <= t_max;
                match (hit_a, hit_b) {
                    (true, true) => {
                        let (near, far) = if an <= bn { (a, node.first + 1) } else { (b, node.first) };
                        if sp < stack.len() {
                            stack[sp] = far;
                            sp += 1;
                        }
                        node = near;
                        continue;
                    }
                    (true, false) => {
                        node = a;
                        continue;
                    }
                    (false, true) => {
                        node = b;
                        continue;
                    }
                    (false, false) => {}
                }
            }
            // Pop, skipping nodes that the current t_max has since culled is left to the box test.
            if sp == 0 {
                return visited;
            }
            sp -= 1;
            node = &self.nodes[stack[sp] as usize];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boxes(n: usize) -> Vec<Aabb> {
        (0..n)
            .map(|i| {
                let c = Vec3::new((i % 10) as f32 * 3.0, ((i / 10) % 10) as f32 * 3.0, (i / 100) as f32 * 3.0);
                Aabb::new(c - 0.5, c + 0.5)
            })
            .collect()
    }

    #[test]
    fn empty_and_single() {
        let empty = Bvh::build(&[]);
        assert_eq!(empty.traverse(&Ray::new(Vec3::ZERO, Vec3::Z), f32::INFINITY, |_, _| Some(1.0)), 0);
        let one = Bvh::build(&[Aabb::new(Vec3::splat(-1.0), Vec3::ONE)]);
        assert_eq!(one.nodes.len(), 1);
        assert!(one.nodes[0].is_leaf());
    }

    #[test]
    fn every_primitive_is_in_exactly_one_leaf() {
        let bvh = Bvh::build(&boxes(1000));
        let mut seen = vec![0; 1000];
        for n in bvh.nodes.iter().filter(|n| n.is_leaf()) {
            for &p in &bvh.prim_order[n.first as usize..(n.first + n.count) as usize] {
                seen[p as usize] += 1;
            }
        }
        assert!(seen.iter().all(|&c| c == 1));
        assert!(bvh.depth() < 40);
    }

    #[test]
    fn depth_is_capped_on_degenerate_input() {
        // Exponentially spaced centres make every SAH split peel off one primitive.
        let b: Vec<Aabb> = (0..200)
            .map(|i| {
                let c = Vec3::splat(1.5f32.powi(i));
                Aabb::new(c, c + Vec3::splat(1e-3))
            })
            .collect();
        let bvh = Bvh::build(&b);
        assert!(bvh.depth() <= MAX_DEPTH);
        let mut seen = vec![false; b.len()];
        for n in bvh.nodes.iter().filter(|n| n.is_leaf()) {
            for &p in &bvh.prim_order[n.first as usize..(n.first + n.count) as usize] {
                seen[p as usize] = true;
            }
        }
        assert!(seen.iter().all(|s| *s));
    }

    #[test]
    fn identical_centres_still_terminate() {
        let b = vec![Aabb::new(Vec3::ZERO, Vec3::ONE); 100];
        let bvh = Bvh::build(&b);
        assert!(bvh.depth() <= 10);
    }

    #[test]
    fn degenerate_flat_bounds() {
        // Zero-thickness boxes (e.g. axis-aligned triangles) must still be found.
        let b: Vec<Aabb> =
            (0..50).map(|i| Aabb::new(Vec3::new(i as f32, 0.0, 0.0), Vec3::new(i as f32 + 0.5, 1.0, 0.0))).collect();
        let bvh = Bvh::build(&b);
        let ray = Ray::new(Vec3::new(10.25, 0.5, -1.0), Vec3::Z);
        let mut found = vec![];
        bvh.traverse(&ray, f32::INFINITY, |p, _| {
            found.push(p);
            None
        });
        assert!(found.contains(&10));
    }
}
