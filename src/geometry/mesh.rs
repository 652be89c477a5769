//! Triangle meshes (`mesh`, `mesh2`, and the grid of a `height_field`): the triangles in object
//! space with their own BVH, stored once (`MeshData` behind an `Arc`) and placed by a frame per
//! object (`Mesh`), so a declared mesh used N times holds one copy.
//!
//! The per-triangle test is `triangle::Triangle`'s (Möller–Trumbore); the hierarchy is
//! `accel::bvh::Bvh`, built over the triangles' boxes and traversed with a closure, as the
//! scene's own is. A ray is carried into object space once per lane and traced there; the hit
//! reports which face (`Mesh::hit_face`), and the face's normal is computed afterwards, only for
//! the winning hit (`Mesh::normal`): interpolated for a smooth triangle, flipped to the side of
//! the geometric normal as POV-Ray does.

use std::sync::Arc;

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::height_field::HeightGrid;
use super::triangle::{Triangle, TriangleLanes};
use super::{transformed_bounds, Shape};
use crate::accel::aabb::node_slabs;
use crate::accel::aabb::Aabb;
use crate::accel::bvh::{Bvh, BvhNode};
use crate::lanes::{next_up, Lane, F8, M8, V3};
use crate::ray::{Ray, RayLanes, MISS};

mod lanes;
mod placed;
#[cfg(test)]
mod tests;
use lanes::LaneNode;
pub use placed::Mesh;

/// Meshes of fewer faces are walked row by row (`Mesh::walks_rows`).
const ROWS_MIN_FACES: usize = 32;

/// How far beyond the best distance so far (relative) the walks still enter boxes
/// (`cull_limit`).
const CULL_SLACK: f32 = 1.0 / 4096.0;

/// The box-culling limit of a walk that accepts hits up to `bound`: a little beyond it. A face
/// hit at exactly `bound` (coincident faces, a shared edge) lies in a box whose entry distance,
/// rounded, may come out a few ulps beyond its `t`; culling at `bound` itself would test that
/// face or not depending on whether the other was found first, and single rays and packets,
/// walking in different orders, would name different faces (objects/chesmsh.pov's knight).
#[inline(always)]
fn cull_limit<L: Lane>(bound: L) -> L {
    bound + bound.abs() * L::splat(CULL_SLACK)
}

/// The greatest float below `x` (lane by lane: `-next_up(-x)`).
#[inline(always)]
fn next_down(x: f32) -> f32 {
    -next_up(-x)
}

/// `MeshData::smooth_of` for a flat face.
const FLAT: u32 = u32::MAX;

/// A mesh's triangles in object space, in the BVH's leaf order (so a leaf's faces are
/// contiguous and `Bvh::prim_order` is the identity), with their vertex normals.
#[derive(Debug)]
pub struct MeshData {
    pub triangles: Vec<Triangle>,
    /// Per face: its entry in `smooth`, or `FLAT`.
    smooth_of: Vec<u32>,
    /// Unit vertex normals of the smooth faces.
    smooth: Vec<[Vec3; 3]>,
    bvh: Bvh,
    /// The same hierarchy for the packet walk (`walk_lanes`): boxes indexed by direction sign.
    lane_nodes: Vec<LaneNode>,
    pub min: Vec3,
    pub max: Vec3,
    /// Each stored face's index in the faces `new` was given (for `uv_mapping`'s uv_vectors).
    pub source_face: Vec<u32>,
    /// Hits below this object-space height are not hits (`height_field`'s `water_level`);
    /// -inf for meshes.
    floor: f32,
    /// A height field's grid: its inside test, in place of counting crossings.
    grid: Option<HeightGrid>,
}

impl MeshData {
    /// Builds the hierarchy over `faces` (three vertices and, for a smooth face, three
    /// normals, each in object space) and stores them in its order.
    pub fn new(faces: impl IntoIterator<Item = ([Vec3; 3], Option<[Vec3; 3]>)>) -> MeshData {
        let faces: Vec<([Vec3; 3], Option<[Vec3; 3]>)> = faces.into_iter().collect();
        MeshData::from_faces(faces.len(), |i| faces[i])
    }

    /// `count` faces, face `i` read as `face(i)` (twice: for its box, then in the tree's
    /// order), so that a mesh description is not copied first: ten million faces as one list
    /// of `(corners, Option<normals>)` held 76 bytes a face, more than the finished mesh.
    pub fn from_faces(count: usize, face: impl Fn(usize) -> ([Vec3; 3], Option<[Vec3; 3]>)) -> MeshData {
        let bounds: Vec<Aabb> = (0..count)
            .map(|i| {
                let v = face(i).0;
                Aabb::new(v[0].min(v[1]).min(v[2]), v[0].max(v[1]).max(v[2]))
            })
            .collect();
        let mut bvh = Bvh::build(&bounds);
        let mut triangles = Vec::with_capacity(count);
        let mut smooth_of = Vec::with_capacity(count);
        let mut smooth = Vec::new();
        let mut all = Aabb::EMPTY;
        for &f in &bvh.prim_order {
            let (v, n) = face(f as usize);
            triangles.push(Triangle::new(v[0], v[1], v[2]));
            all.grow(&bounds[f as usize]);
            match n {
                Some(n) => {
                    smooth_of.push(smooth.len() as u32);
                    smooth.push(n.map(|n| n.normalize_or_zero()));
                }
                None => smooth_of.push(FLAT),
            }
        }
        drop(bounds);
        // Faces are stored in leaf order: leaf ranges now index `triangles` directly.
        let source_face = std::mem::replace(&mut bvh.prim_order, (0..triangles.len() as u32).collect());
        let (min, max) = if triangles.is_empty() { (Vec3::ZERO, Vec3::ZERO) } else { (all.min, all.max) };
        let lane_nodes = bvh.nodes.iter().map(|n| LaneNode::new(&bvh, n)).collect();
        MeshData {
            triangles,
            smooth_of,
            smooth,
            bvh,
            lane_nodes,
            min,
            max,
            source_face,
            floor: f32::NEG_INFINITY,
            grid: None,
        }
    }

    /// Hits below object-space height `floor` are left out (`water_level`).
    pub fn with_floor(mut self, floor: f32) -> MeshData {
        self.floor = floor;
        self
    }

    /// The mesh of a height field: `grid` answers which points lie inside (below the surface),
    /// and finds the faces a ray hits by walking its cells instead of the BVH.
    pub fn with_grid(mut self, grid: HeightGrid) -> MeshData {
        self.grid = Some(grid.linked(&self.triangles));
        self
    }

    /// Whether the hit at `t` on `ray` lies above the floor.
    #[inline(always)]
    fn above_floor(&self, ray: &Ray, t: f32) -> bool {
        self.floor == f32::NEG_INFINITY || ray.origin.y + t * ray.dir.y >= self.floor
    }

    /// The nearest face hit by the object-space `ray` in `(t_min, t_max)`: its distance and
    /// index. Of faces hit at exactly the same distance (a ray through a shared edge) the lowest
    /// index wins, whatever order the walk finds them in, so a packet's walk
    /// (`nearest_faces_lanes`) names the same face.
    #[inline]
    pub fn nearest(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<(f32, u32)> {
        // Idle lanes of a packet (a point at infinity, an empty interval): the slab test reads
        // NaN as "could be anywhere" and would visit every node.
        if !(t_min < t_max && ray.origin.is_finite() && ray.dir.is_finite()) {
            return None;
        }
        if let Some(cells) = self.grid.as_ref().and_then(HeightGrid::cells) {
            return cells.nearest(&self.triangles, ray, t_min, t_max);
        }
        let lanes = ray.lanes();
        // The greatest distance still accepted (the best so far, else just below `t_max`) and
        // its face (`u32::MAX` before a hit): a face at exactly `bound` wins with a lower index.
        let (mut bound, mut face) = (next_down(t_max), u32::MAX);
        // Boxes are culled a little beyond `bound` (`cull_limit`), so that every face at the
        // final distance is tested whatever order the walk meets them in.
        self.bvh.traverse(ray, cull_limit(bound), |f, _| {
            let t = self.triangles[f as usize].hit(&lanes, t_min, next_up(bound));
            let wins = t != MISS && (t < bound || f < face);
            (wins && self.above_floor(ray, t)).then(|| {
                (bound, face) = (t, f);
                cull_limit(t)
            })
        });
        (face != u32::MAX).then_some((bound, face))
    }

    /// A face hit by the object-space `ray` in `(t_min, t_max)`, the first found: `nearest`
    /// for shadow rays, which need only whether there is one.
    #[inline]
    pub fn first(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        if !(t_min < t_max && ray.origin.is_finite() && ray.dir.is_finite()) {
            return None;
        }
        if let Some(cells) = self.grid.as_ref().and_then(HeightGrid::cells) {
            return cells.first(&self.triangles, ray, t_min, t_max);
        }
        let lanes = ray.lanes();
        let mut found = None;
        self.bvh.traverse(ray, t_max, |f, t_max| {
            if found.is_some() {
                return None;
            }
            let t = self.triangles[f as usize].hit(&lanes, t_min, t_max);
            (t != MISS && self.above_floor(ray, t)).then(|| {
                found = Some(t);
                // No node accepts a limit of -inf: the walk ends.
                f32::NEG_INFINITY
            })
        });
        found
    }

    /// How many faces the object-space `ray` crosses at `t > 0` (the inside test's parity).
    pub fn crossings(&self, ray: &Ray) -> u32 {
        if !(ray.origin.is_finite() && ray.dir.is_finite()) {
            return 0;
        }
        let lanes = ray.lanes();
        let mut n = 0;
        self.bvh.traverse(ray, f32::INFINITY, |f, _| {
            let t = self.triangles[f as usize].hit(&lanes, 0.0, f32::INFINITY);
            n += (t != MISS && self.above_floor(ray, t)) as u32;
            None
        });
        n
    }

    /// Whether `face` has vertex normals.
    pub fn is_smooth(&self, face: u32) -> bool {
        self.smooth_of[face as usize] != FLAT
    }

    /// Bytes held, for the statistics and docs/perf/meshes.md.
    pub fn bytes(&self) -> usize {
        self.triangles.len() * std::mem::size_of::<Triangle>()
            + self.smooth_of.len() * 4
            + self.smooth.len() * 36
            + self.bvh.nodes.len() * std::mem::size_of::<crate::accel::bvh::BvhNode>()
            + self.lane_nodes.len() * std::mem::size_of::<LaneNode>()
            + self.bvh.prim_order.len() * 4
            + self.source_face.len() * 4
    }
}
