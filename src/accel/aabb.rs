//! Axis-aligned bounding boxes for the accelerators.

use glam::Vec3;

use crate::lanes::{Lane, V3};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb { min: Vec3::splat(f32::INFINITY), max: Vec3::splat(f32::NEG_INFINITY) };

    pub fn new(min: Vec3, max: Vec3) -> Aabb {
        Aabb { min, max }
    }

    #[inline]
    pub fn grow(&mut self, other: &Aabb) {
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
    }

    #[inline]
    pub fn grow_point(&mut self, p: Vec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    pub fn center(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// Half the surface area (the SAH only compares areas, so the factor 2 is dropped).
    #[inline]
    pub fn half_area(&self) -> f32 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.max - self.min;
        d.x * d.y + d.y * d.z + d.z * d.x
    }
}

/// Slab test for bounding volumes (BVH nodes, the grid): conservative where `slabs` is not.
///
/// A ray lying exactly in a face plane gives `0·∞ = NaN` on that axis; here that axis then
/// bounds nothing (−∞, +∞), so the node is entered whenever anything inside it could be hit.
/// (Found by the property test comparing the BVH with brute force on axis-aligned rays.)
#[inline(always)]
pub fn node_slabs<L: Lane>(min: V3<L>, max: V3<L>, o: V3<L>, inv: V3<L>) -> (L, L) {
    let t0 = min.sub(o).mul(inv);
    let t1 = max.sub(o).mul(inv);
    let axis = |a: L, b: L| {
        let nan = L::or(L::not(a.le(a)), L::not(b.le(b)));
        (L::select(nan, L::splat(f32::NEG_INFINITY), a.min(b)), L::select(nan, L::splat(f32::INFINITY), a.max(b)))
    };
    let (nx, fx) = axis(t0.x, t1.x);
    let (ny, fy) = axis(t0.y, t1.y);
    let (nz, fz) = axis(t0.z, t1.z);
    (nx.max(ny).max(nz), fx.min(fy).min(fz))
}

/// `node_slabs` for one ray: entry and exit distances against a bounding box.
#[inline]
pub fn slabs(min: Vec3, max: Vec3, origin: Vec3, inv_dir: Vec3) -> (f32, f32) {
    node_slabs(V3::from_vec3(min), V3::from_vec3(max), V3::from_vec3(origin), V3::from_vec3(inv_dir))
}
