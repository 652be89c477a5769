//! Packet traversal of the BVH: rows of eight rays (`Ray8`) walk the tree together.
//!
//! Modelled on the classic interactive-ray-tracing packet walk (Wald et al. 2001; tinybvh's
//! `Intersect256Rays`): a node is entered by the whole packet if any ray wants it, and the
//! packet keeps a range `first..=last` of rows still active, shrunk at every node, so rows that
//! missed stop paying. A frustum interval test culls nodes that no ray of a shared-origin packet
//! can reach before a single row is tested.

// Lane loops index several per-lane arrays at once; iterators would hide which lane is meant.
#![allow(clippy::needless_range_loop)]
use glam::Vec3;

use super::aabb::node_slabs;
use super::bvh::{Bvh, BvhNode};
use crate::lanes::{Lane, F8, M8, V3};
use crate::ray::{Ray, RayLanes};

/// Eight rays in structure-of-arrays form.
pub type Ray8 = RayLanes<F8>;

impl Ray8 {
    pub const ZERO: Ray8 = Ray8 {
        o: V3 { x: F8([0.0; 8]), y: F8([0.0; 8]), z: F8([0.0; 8]) },
        d: V3 { x: F8([0.0; 8]), y: F8([0.0; 8]), z: F8([0.0; 8]) },
        inv: V3 { x: F8([0.0; 8]), y: F8([0.0; 8]), z: F8([0.0; 8]) },
    };

    /// Eight single rays as one packet, lane `i` ray `i`, bit for bit.
    #[inline]
    pub fn from_rays(rays: &[Ray; 8]) -> Ray8 {
        let mut packet = Ray8::ZERO;
        for (i, r) in rays.iter().enumerate() {
            packet.set_lane(i, r.origin, r.dir, r.inv_dir);
        }
        packet
    }

    #[inline]
    pub fn set_lane(&mut self, i: usize, o: Vec3, d: Vec3, inv: Vec3) {
        (self.o.x.0[i], self.o.y.0[i], self.o.z.0[i]) = (o.x, o.y, o.z);
        (self.d.x.0[i], self.d.y.0[i], self.d.z.0[i]) = (d.x, d.y, d.z);
        (self.inv.x.0[i], self.inv.y.0[i], self.inv.z.0[i]) = (inv.x, inv.y, inv.z);
    }

    pub fn from_fn(f: impl Fn(usize) -> (Vec3, Vec3, Vec3)) -> Ray8 {
        let mut r = Ray8 { o: V3::splat(Vec3::ZERO), d: V3::splat(Vec3::ZERO), inv: V3::splat(Vec3::ZERO) };
        for i in 0..8 {
            let (o, d, inv) = f(i);
            (r.o.x.0[i], r.o.y.0[i], r.o.z.0[i]) = (o.x, o.y, o.z);
            (r.d.x.0[i], r.d.y.0[i], r.d.z.0[i]) = (d.x, d.y, d.z);
            (r.inv.x.0[i], r.inv.y.0[i], r.inv.z.0[i]) = (inv.x, inv.y, inv.z);
        }
        r
    }
}

/// Bounds on the directions of a packet whose rays share one origin: for each axis the range
/// of `1/d`, valid when every ray's component has the same sign.
#[derive(Clone, Copy, Debug)]
pub struct Frustum {
    pub origin: Vec3,
    pub inv_min: Vec3,
    pub inv_max: Vec3,
    /// Per axis: all components of one sign, so the interval bounds the slab distances.
    pub coherent: [bool; 3],
}

impl Frustum {
    /// Inlined, so that it runs in its caller's 256-bit instructions.
    #[inline(always)]
    pub fn new(origin: Vec3, rows: &[Ray8]) -> Frustum {
        // Lane-wise extremes first (vector min/max), then across the eight lanes.
        let (mut lo, mut hi) = (rows[0].inv, rows[0].inv);
        for r in &rows[1..] {
            lo = lo.min(r.inv);
            hi = hi.max(r.inv);
        }
        let across = |v: F8, f: fn(f32, f32) -> f32| v.0[1..].iter().fold(v.0[0], |a, &b| f(a, b));
        let inv_min = Vec3::new(across(lo.x, f32::min), across(lo.y, f32::min), across(lo.z, f32::min));
        let inv_max = Vec3::new(across(hi.x, f32::max), across(hi.y, f32::max), across(hi.z, f32::max));
        // One sign per axis (and finite), or the interval says nothing on that axis.
        let coherent = std::array::from_fn(|a| {
            let (l, h) = (inv_min[a], inv_max[a]);
            l.is_finite() && h.is_finite() && ((l > 0.0 && h > 0.0) || (l < 0.0 && h < 0.0))
        });
        Frustum { origin, inv_min, inv_max, coherent }
    }

    /// True when no ray of the packet can meet the box within `(0, t_max)`. Conservative: a
    /// product `x·inv` is monotonic in `inv` under IEEE rounding, so every ray's own slab
    /// distances lie inside the bounds computed from the interval ends.
    #[inline(always)]
    pub fn culls(&self, lo: Vec3, hi: Vec3, t_max: f32) -> bool {
        let mut entry = f32::NEG_INFINITY;
        let mut exit = f32::INFINITY;
        for a in 0..3 {
            if !self.coherent[a] {
                continue;
            }
            let (near, far) = if self.inv_min[a] > 0.0 { (lo[a], hi[a]) } else { (hi[a], lo[a]) };
            let n = near - self.origin[a];
            let f = far - self.origin[a];
            entry = entry.max((n * self.inv_min[a]).min(n * self.inv_max[a]));
            exit = exit.min((f * self.inv_min[a]).max(f * self.inv_max[a]));
        }
        entry > exit || exit < 0.0 || entry > t_max
    }
}

#[inline(always)]
fn node_box(n: &BvhNode) -> (V3<F8>, V3<F8>) {
    (V3::splat(Vec3::from_array(n.min)), V3::splat(Vec3::from_array(n.max)))
}

/// Whether any active ray of the row enters the node before its current `t`.
#[inline(always)]
fn row_enters(n: &BvhNode, r: &Ray8, t: F8, active: M8) -> bool {
    let (lo, hi) = node_box(n);
    let (near, far) = node_slabs(lo, hi, r.o, r.inv);
    let zero = F8::splat(0.0);
    let hit = F8::and(F8::and(near.le(far), zero.le(far)), near.le(t));
    F8::and(hit, active).any()
}

/// Tests one primitive against one row of rays, lowering `t` for the lanes it hits.
///
/// A trait rather than a closure: its `#[inline(always)]` method is inlined into the walk and
/// from there into the caller's `#[target_feature(enable = "avx2")]` function, where the 8-wide
/// kernels compile to 256-bit instructions. (A closure was compiled out of line, without AVX2.)
pub trait RowTest {
    fn test(&mut self, prim: u32, row: usize, t: &mut F8);

    /// `test` for rows `first..=last` (`t` holds every row's limit): a shape that walks
    /// several rows at once (a mesh's own hierarchy) takes them together.
    #[inline(always)]
    fn test_rows(&mut self, prim: u32, first: usize, last: usize, t: &mut [F8]) {
        for r in first..=last {
            self.test(prim, r, &mut t[r]);
        }
    }
}

impl Bvh {
    /// Walks the tree with `rows` (up to 64 rays). `t[r]` holds each ray's current limit;
    /// `test` tests one primitive against one row and lowers the lanes it hits. `active[r]` masks lanes that take part (e.g. shadow rays already blocked).
    /// Returns the nodes visited.
    #[inline(always)]
    pub fn traverse_packet<T: RowTest>(
        &self,
        rows: &[Ray8],
        t: &mut [F8],
        active: &[M8],
        frustum: Option<&Frustum>,
        test: &mut T,
    ) -> u32 {
        if self.nodes.is_empty() || rows.is_empty() {
            return 0;
        }
        let mut stack = [(0u32, 0u8, 0u8); 64];
        let mut sp = 0usize;
        let (mut node, mut first, mut last) = (0u32, 0usize, rows.len() - 1);
        let mut visited = 0;
        loop {
            let n = &self.nodes[node as usize];
            visited += 1;
            let culled = match frustum {
                Some(f) => {
                    let mut far = t[first];
                    for row in &t[first + 1..=last] {
                        far = far.max(*row);
                    }
                    f.culls(
                        Vec3::from_array(n.min),
                        Vec3::from_array(n.max),
                        far.0.iter().fold(0.0f32, |m, &v| m.max(v)),
                    )
                }
                None => false,
            };
            if !culled {
                // Early hit: the first row that enters the node; then the last one.
                while first <= last && !row_enters(n, &rows[first], t[first], active[first]) {
                    first += 1;
                }
                while last > first && !row_enters(n, &rows[last], t[last], active[last]) {
                    last -= 1;
                }
            }
            if !culled && first <= last {
                if n.is_leaf() {
                    for &p in &self.prim_order[n.first as usize..(n.first + n.count) as usize] {
                        test.test_rows(p, first, last, t);
                    }
                } else {
                    // Nearer child first, judged by the first active ray.
                    let d = Vec3::new(rows[first].d.x.0[0], rows[first].d.y.0[0], rows[first].d.z.0[0]);
                    let (near, far) = self.near_far(n, d);
                    if sp < stack.len() {
                        stack[sp] = (far, first as u8, last as u8);
                        sp += 1;
                    }
                    node = near;
                    continue;
                }
            }
            if sp == 0 {
                return visited;
            }
            sp -= 1;
            (node, first, last) = (stack[sp].0, stack[sp].1 as usize, stack[sp].2 as usize);
        }
    }
}
