//! CSG queries: a node's nearest surface and its inside test, for one ray (f32 or f64) or eight,
//! from one generic formula (as `geometry::Shape`).
//!
//! A node's surface is found child by child: each surface child's hits are taken in order
//! along the ray (`hit_prim_in` from the last one rejected), and the first whose point the
//! other children accept is that child's candidate; the nearest candidate wins. An
//! `intersection` accepts a point inside every other child, a `merge` one inside none, a
//! `union` any. Rejected hits cost one more root search each, so a ray pays for the crossings
//! it passes, not for the node's size.

use glam::Vec3;

use crate::accel::aabb::node_slabs;
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};
use crate::scene::build::Scene;
use crate::scene::csg::{CsgChild, CsgRule, CsgTarget};

/// The most surface crossings followed along one ray through one child; beyond, the child is
/// missed. A child of closed shapes has a few; this bounds a pathological nesting.
const MAX_CROSSINGS: usize = 256;

impl Scene {
    /// The nearest surface of node `node` in `(t_min, t_max)` for each lane (`MISS` where
    /// none), and the leaf it belongs to (an index into `prims`, as a float: exact below 2^24).
    pub fn hit_csg<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        let n = &self.csg[node as usize];
        let kids = &self.csg_children[n.children()];
        let miss = L::splat(MISS);
        let (t_min, t_max) =
            if n.rule == CsgRule::All { within_box(n.min, n.max, ray, t_min, t_max) } else { (t_min, t_max) };
        let mut best = t_max;
        let mut leaf = L::splat(0.0);
        let mut found = L::mask_from_fn(|_| false);
        for (i, child) in kids[..n.surfaces as usize].iter().enumerate() {
            let mut from = t_min;
            for _ in 0..MAX_CROSSINGS {
                let (t, l) = self.hit_child(child, ray, from, best);
                let hit = t.lt(miss);
                if !L::any(hit) {
                    break;
                }
                let p = ray.o.add(ray.d.scale(t));
                let keep = match n.rule {
                    CsgRule::Union => hit,
                    CsgRule::Merge => L::and(hit, L::not(self.inside_others(kids, i, p, false))),
                    CsgRule::All => L::and(hit, self.inside_others(kids, i, p, true)),
                };
                best = L::select(keep, t, best);
                leaf = L::select(keep, l, leaf);
                found = L::or(found, keep);
                let again = L::and(hit, L::not(keep));
                if !L::any(again) {
                    break;
                }
                // Lanes done search the empty interval (best, best).
                from = L::select(again, t, best);
            }
        }
        (L::select(found, best, miss), leaf)
    }

    /// Which points lie inside node `node`.
    pub fn inside_node<L: Lane>(&self, node: u32, p: V3<L>) -> L::Mask {
        let n = &self.csg[node as usize];
        let kids = &self.csg_children[n.children()];
        match n.rule {
            CsgRule::All => self.inside_others(kids, usize::MAX, p, true),
            CsgRule::Union | CsgRule::Merge => self.inside_others(kids, usize::MAX, p, false),
        }
    }

    /// `all`: whether `p` is inside every child but `skip`; else whether inside any of them.
    fn inside_others<L: Lane>(&self, kids: &[CsgChild], skip: usize, p: V3<L>, all: bool) -> L::Mask {
        let mut m = L::mask_from_fn(|_| all);
        for (j, c) in kids.iter().enumerate() {
            if j == skip {
                continue;
            }
            let inside = self.inside_child(c, p);
            m = if all { L::and(m, inside) } else { L::or(m, inside) };
            // Outside for every lane: nothing more can change it.
            if all && !L::any(m) {
                break;
            }
        }
        m
    }

    #[inline(always)]
    fn inside_child<L: Lane>(&self, c: &CsgChild, p: V3<L>) -> L::Mask {
        let inside = match c.target {
            CsgTarget::Leaf(i) => self.inside_prim(&self.prims[i as usize], p),
            CsgTarget::Node(k) => self.inside_node(k, p),
        };
        L::xor(inside, L::mask_from_fn(|_| c.inverse))
    }

    #[inline(always)]
    fn hit_child<L: Lane>(&self, c: &CsgChild, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        match c.target {
            CsgTarget::Leaf(i) => (self.hit_prim_in(&self.prims[i as usize], ray, t_min, t_max), L::splat(i as f32)),
            CsgTarget::Node(k) => self.hit_csg(k, ray, t_min, t_max),
        }
    }
}

/// `(t_min, t_max)` narrowed to where the ray is inside the box `min`..`max`, widened by a part
/// in 10⁵ of the distance so that no crossing on the box's faces is lost to rounding. A point
/// that every non-subtracted child of an `intersection` accepts lies in all their boxes, so the
/// node's own box bounds the search, however often an unbounded child (a cubic, a plane)
/// crosses the ray outside it.
#[inline]
fn within_box<L: Lane>(min: Vec3, max: Vec3, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
    let (near, far) = node_slabs(V3::splat(min), V3::splat(max), ray.o, ray.inv);
    let pad = |t: L| t.abs() * L::splat(1e-5) + L::splat(1e-6);
    (t_min.max(near - pad(near)), t_max.min(far + pad(far)))
}
