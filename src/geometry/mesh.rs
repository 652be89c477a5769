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
use super::triangle::Triangle;
use super::{transformed_bounds, Shape};
use crate::accel::aabb::node_slabs;
use crate::accel::aabb::Aabb;
use crate::accel::bvh::{Bvh, BvhNode};
use crate::lanes::{next_up, Lane, F8, V3};
use crate::ray::{Ray, RayLanes, MISS};

/// Meshes of fewer faces are walked row by row (`Mesh::walks_rows`).
const ROWS_MIN_FACES: usize = 32;

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
        let bounds: Vec<Aabb> =
            faces.iter().map(|(v, _)| Aabb::new(v[0].min(v[1]).min(v[2]), v[0].max(v[1]).max(v[2]))).collect();
        let mut bvh = Bvh::build(&bounds);
        let mut triangles = Vec::with_capacity(faces.len());
        let mut smooth_of = Vec::with_capacity(faces.len());
        let mut smooth = Vec::new();
        let mut all = Aabb::EMPTY;
        for &f in &bvh.prim_order {
            let (v, n) = faces[f as usize];
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
        let mut best: Option<(f32, u32)> = None;
        self.bvh.traverse(ray, t_max, |f, limit| {
            // Up to the best distance itself, for a tie with a lower index.
            let reach = if best.is_some() { limit.next_up() } else { limit };
            let t = self.triangles[f as usize].hit(&lanes, t_min, reach);
            let wins = t != MISS && best.is_none_or(|(b, g)| t < b || f < g);
            (wins && self.above_floor(ray, t)).then(|| {
                best = Some((t, f));
                t
            })
        });
        best
    }

    /// `nearest` for a packet of object-space rays: each lane's distance and face (`u32::MAX`
    /// where it missed), walking the BVH once with all lanes: a node is entered when any active
    /// lane's slab test (the same `node_slabs` the single-ray walk uses) wants it, and each
    /// leaf's triangles are tested eight lanes at a time with the single-ray kernel
    /// (`Triangle::hit` over `L`). Every lane's result is the least `t` over the faces it hits
    /// in `(t_min, t_max)`, ties to the lowest index, whatever the visiting order, so it is the
    /// single-ray walk's `t` and face bit for bit (tests/suite/properties.rs checks it on random
    /// meshes).
    #[inline(always)]
    pub fn nearest_faces_lanes<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, [u32; 8]) {
        self.walk_lanes::<L, false>(ray, t_min, t_max)
    }

    /// For shadow rays: a hit in `(t_min, t_max)` for each lane that has one, not necessarily
    /// the nearest (pbrt's `IntersectP`). A lane stops at its first hit and the walk ends when
    /// every active lane has stopped, so a blocked ray does not search on for a nearer face.
    #[inline(always)]
    pub fn first_lanes<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.walk_lanes::<L, true>(ray, t_min, t_max).0
    }

    /// The walk behind `nearest_faces_lanes` (`FIRST` false) and `first_lanes` (`FIRST` true), with
    /// each lane's face (for `FIRST` none: shadow rays ask only whether they are blocked).
    ///
    /// Rows whose active lanes agree in the sign of each direction component, with finite
    /// `1/d` (nearly every row of primary and shadow rays), take the cheaper box test
    /// (`SignedSlabs`); the others the general one (`Slabs`). Both answer exactly what
    /// `node_slabs` answers, so every lane sees the same faces either way.
    #[inline(always)]
    fn walk_lanes<L: Lane, const FIRST: bool>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, [u32; 8]) {
        if let Some(cells) = self.grid.as_ref().and_then(HeightGrid::cells) {
            return cells.lanes::<L, FIRST>(&self.triangles, ray, t_min, t_max);
        }
        // Idle lanes (a point at infinity, an empty interval) take no part, as in `nearest`.
        let active = L::and(t_min.lt(t_max), L::and(finite(&ray.o), finite(&ray.d)));
        if self.lane_nodes.is_empty() || !L::any(active) {
            return (L::splat(MISS), [u32::MAX; 8]);
        }
        if self.lane_nodes.len() == 1 {
            // One leaf (a `smooth_triangle` is a mesh of one face): nothing to order or share,
            // and the signs below would cost more than the one box test they save.
            return self.walk_with::<L, FIRST, _>(
                ray,
                t_min,
                t_max,
                active,
                &Slabs { ray, active, down: [false; 3] },
                false,
            );
        }
        // Per axis: do all active lanes point up it (1), down it (-1), or neither (0)?
        let signs = [axis_sign(ray.inv.x, active), axis_sign(ray.inv.y, active), axis_sign(ray.inv.z, active)];
        if signs[0] != 0 && signs[1] != 0 && signs[2] != 0 {
            let down = [signs[0] < 0, signs[1] < 0, signs[2] < 0];
            let test = SignedSlabs::new(ray, active, down);
            return self.walk_with::<L, FIRST, _>(ray, t_min, t_max, active, &test, true);
        }
        // Nearer child first, judged by the first active lane's direction.
        let first_active = (0..L::WIDTH).find(|&i| L::mask_lane(active, i)).unwrap_or(0);
        let down = [ray.d.x.get(first_active) < 0.0, ray.d.y.get(first_active) < 0.0, ray.d.z.get(first_active) < 0.0];
        self.walk_with::<L, FIRST, _>(ray, t_min, t_max, active, &Slabs { ray, active, down }, false)
    }

    /// `walk_lanes` with one box test. `skip_root`: the caller's box test is exact enough that
    /// a lane entering a child would have entered the root (see `SignedSlabs`), so the root's
    /// own test, which the scene's walk has just made on the placed mesh's box, is left out.
    #[inline(always)]
    fn walk_with<L: Lane, const FIRST: bool, T: NodeTest<L>>(
        &self,
        ray: &RayLanes<L>,
        t_min: L,
        t_max: L,
        active: L::Mask,
        test: &T,
        skip_root: bool,
    ) -> (L, [u32; 8]) {
        let mut row = RowState::new(active, t_max);
        let down = test.down();
        let mut stack = [0u32; 64];
        let mut sp = 0usize;
        let mut node = 0u32;
        let root = &self.lane_nodes[0];
        if skip_root && !root.is_leaf() {
            let (near, far) = root.near_far(down);
            stack[0] = far;
            sp = 1;
            node = near;
        }
        loop {
            let n = &self.lane_nodes[node as usize];
            if test.enters(n, row.limit) {
                if n.is_leaf() {
                    if !self.leaf_row::<L, FIRST>(n, ray, t_min, &mut row) {
                        return (row.best, row.faces);
                    }
                } else {
                    let (near, far) = n.near_far(down);
                    if sp < stack.len() {
                        stack[sp] = far;
                        sp += 1;
                    }
                    node = near;
                    continue;
                }
            }
            if sp == 0 {
                return (row.best, row.faces);
            }
            sp -= 1;
            node = stack[sp];
        }
    }

    /// Tests leaf `n`'s faces against one row, lowering its lanes' limits; false once every
    /// lane of a shadow row (`FIRST`) has hit, when the row is done.
    #[inline(always)]
    fn leaf_row<L: Lane, const FIRST: bool>(
        &self,
        n: &LaneNode,
        ray: &RayLanes<L>,
        t_min: L,
        row: &mut RowState<L>,
    ) -> bool {
        let first = n.first();
        for f in first..first + n.count() {
            if FIRST {
                let t = self.triangles[f as usize].hit(ray, t_min, row.limit);
                let mut hit = t.lt(row.limit);
                if self.floor != f32::NEG_INFINITY {
                    let y = ray.o.y + t * ray.d.y;
                    hit = L::and(hit, L::splat(self.floor).le(y));
                }
                row.best = L::select(hit, t, row.best);
                // A lane that has hit is done: no node or face accepts -inf.
                row.limit = L::select(hit, L::splat(f32::NEG_INFINITY), row.limit);
                if !L::any(L::lt(L::splat(f32::NEG_INFINITY), row.limit)) {
                    return false;
                }
                continue;
            }
            // As `nearest`: up to a lane's best distance itself, where a face of lower index
            // wins a tie.
            let found = row.best.lt(L::splat(MISS));
            let reach = L::select(found, row.limit.map(next_up), row.limit);
            let t = self.triangles[f as usize].hit(ray, t_min, reach);
            let lower = L::mask_from_fn(|i| f < row.faces[i]);
            let mut hit = L::and(t.lt(reach), L::or(t.lt(row.limit), lower));
            if self.floor != f32::NEG_INFINITY {
                let y = ray.o.y + t * ray.d.y;
                hit = L::and(hit, L::splat(self.floor).le(y));
            }
            row.best = L::select(hit, t, row.best);
            // A select per lane, not a branch.
            for (i, face) in row.faces.iter_mut().enumerate().take(L::WIDTH) {
                *face = if L::mask_lane(hit, i) { f } else { *face };
            }
            row.limit = L::select(hit, t, row.limit);
        }
        true
    }

    /// `walk_lanes` for up to eight rows of one packet at once (`rays`, in object space, with
    /// their limits `t_max`): the rows share one walk of the tree, as the scene's packet walk
    /// (`Bvh::traverse_packet`) shares its own, keeping the range of rows still wanting the
    /// current node, so the nodes near the root are tested once for the block rather than once
    /// per row. A row tests a leaf's faces only where its own box test admits it, so each row
    /// meets the faces its own walk would (the results do not depend on the order, as
    /// `nearest_faces_lanes` says). Writes each row's distances and faces to `out`.
    ///
    /// Only for rows with one direction sign per axis among them all (`SignedSlabs`, whose
    /// child-implies-parent property the shared range relies on); other blocks walk row by row.
    #[inline(always)]
    fn walk_rows<L: Lane, const FIRST: bool>(&self, rays: &[RayLanes<L>], t_max: &[L], out: &mut [(L, [u32; 8])]) {
        let rows = rays.len().min(8);
        if self.grid.is_some() || self.lane_nodes.is_empty() {
            for r in 0..rows {
                out[r] = self.walk_lanes::<L, FIRST>(&rays[r], L::splat(0.0), t_max[r]);
            }
            return;
        }
        let t_min = L::splat(0.0);
        let none = L::lt(L::splat(0.0), L::splat(0.0));
        let mut active = [none; 8];
        // Each axis's sign over all rows with an active lane: 0 where they disagree.
        let mut signs = [0i8; 3];
        let mut any_row = false;
        let mut agree = true;
        for r in 0..rows {
            let ray = &rays[r];
            active[r] = L::and(t_min.lt(t_max[r]), L::and(finite(&ray.o), finite(&ray.d)));
            if !L::any(active[r]) {
                continue;
            }
            let row =
                [axis_sign(ray.inv.x, active[r]), axis_sign(ray.inv.y, active[r]), axis_sign(ray.inv.z, active[r])];
            if !any_row {
                signs = row;
                any_row = true;
            }
            agree &= row[0] != 0 && row[1] != 0 && row[2] != 0 && row == signs;
        }
        if !any_row {
            for o in out.iter_mut().take(rows) {
                *o = (L::splat(MISS), [u32::MAX; 8]);
            }
            return;
        }
        if !agree {
            for r in 0..rows {
                out[r] = self.walk_lanes::<L, FIRST>(&rays[r], t_min, t_max[r]);
            }
            return;
        }
        let down = [signs[0] < 0, signs[1] < 0, signs[2] < 0];
        // Loops, not `array::from_fn`: closures are compiled out of line, without AVX2.
        let mut tests = [SignedSlabs::new(&rays[0], active[0], down); 8];
        let mut state = [RowState::new(active[0], t_max[0]); 8];
        // Rows with lanes still to find a hit (bit per row), for shadow rows' early end.
        let mut left = 0u32;
        for r in 1..rows {
            tests[r] = SignedSlabs::new(&rays[r], active[r], down);
            state[r] = RowState::new(active[r], t_max[r]);
        }
        for r in 0..rows {
            if L::any(active[r]) {
                left |= 1 << r;
            }
        }
        let mut stack = [(0u32, 0u8, 0u8); 64];
        let mut sp = 0usize;
        let (mut node, mut lo, mut hi) = (0u32, 0usize, rows - 1);
        let root = &self.lane_nodes[0];
        if !root.is_leaf() {
            let (near, far) = root.near_far(down);
            stack[0] = (far, 0, hi as u8);
            sp = 1;
            node = near;
        }
        loop {
            let n = &self.lane_nodes[node as usize];
            while lo <= hi && !tests[lo].enters(n, state[lo].limit) {
                lo += 1;
            }
            while hi > lo && !tests[hi].enters(n, state[hi].limit) {
                hi -= 1;
            }
            if lo <= hi {
                if n.is_leaf() {
                    for r in lo..=hi {
                        // The range's ends entered just above; rows between them ask their own.
                        if r != lo && r != hi && !tests[r].enters(n, state[r].limit) {
                            continue;
                        }
                        if !self.leaf_row::<L, FIRST>(n, &rays[r], t_min, &mut state[r]) {
                            left &= !(1 << r);
                        }
                    }
                    if FIRST && left == 0 {
                        break;
                    }
                } else {
                    let (near, far) = n.near_far(down);
                    if sp < stack.len() {
                        stack[sp] = (far, lo as u8, hi as u8);
                        sp += 1;
                    }
                    node = near;
                    continue;
                }
            }
            if sp == 0 {
                break;
            }
            sp -= 1;
            (node, lo, hi) = (stack[sp].0, stack[sp].1 as usize, stack[sp].2 as usize);
        }
        for r in 0..rows {
            out[r] = (state[r].best, state[r].faces);
        }
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

/// The lanes where every component of `v` is finite (`f32::is_finite` lane by lane, as compares
/// that vectorise: `|x| < ∞` fails for ±∞ and NaN alike).
#[inline(always)]
fn finite<L: Lane>(v: &V3<L>) -> L::Mask {
    let inf = L::splat(f32::INFINITY);
    L::and(L::and(v.x.abs().lt(inf), v.y.abs().lt(inf)), v.z.abs().lt(inf))
}

/// 1 where every active lane's `inv` is positive and finite, -1 where every one is negative
/// and finite, 0 otherwise (mixed signs, a zero direction component, an idle row).
#[inline(always)]
fn axis_sign<L: Lane>(inv: L, active: L::Mask) -> i8 {
    let (zero, inf) = (L::splat(0.0), L::splat(f32::INFINITY));
    let up = L::and(zero.lt(inv), inv.lt(inf));
    let down = L::and(L::splat(f32::NEG_INFINITY).lt(inv), inv.lt(zero));
    if !L::any(L::and(active, L::not(up))) {
        1
    } else if !L::any(L::and(active, L::not(down))) {
        -1
    } else {
        0
    }
}

/// One row's progress in a walk: each lane's limit (-inf for idle lanes and, in shadow walks,
/// for lanes that have hit: no node or face accepts it), best distance and face.
#[derive(Clone, Copy)]
struct RowState<L: Lane> {
    limit: L,
    best: L,
    faces: [u32; 8],
}

impl<L: Lane> RowState<L> {
    #[inline(always)]
    fn new(active: L::Mask, t_max: L) -> RowState<L> {
        RowState {
            limit: L::select(active, t_max, L::splat(f32::NEG_INFINITY)),
            best: L::splat(MISS),
            faces: [u32::MAX; 8],
        }
    }
}

/// A node of `MeshData::lane_nodes`: `BvhNode`'s box and children as eight floats, so that a
/// box corner is picked by index (`b[axis + 4]` is the far side of an axis the ray goes up),
/// and, for an interior node, the axis that orders its children (`Bvh::near_far`'s choice,
/// made once here instead of at every visit).
///
/// `b`: min x, y, z, then `first` (bits), max x, y, z, then `meta` (bits): for a leaf its face
/// count; for an interior node `INTERIOR | axis | (second child lower along the axis) << 2`.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
struct LaneNode {
    b: [f32; 8],
}

/// `LaneNode`'s `meta` bit for an interior node (a leaf's count is below it).
const INTERIOR: u32 = 1 << 31;

impl LaneNode {
    fn new(bvh: &Bvh, n: &BvhNode) -> LaneNode {
        let meta = if n.is_leaf() {
            assert!(n.count < INTERIOR);
            n.count
        } else {
            let (a, c) = (&bvh.nodes[n.first as usize], &bvh.nodes[n.first as usize + 1]);
            let ca = Vec3::from_array(a.min) + Vec3::from_array(a.max);
            let cb = Vec3::from_array(c.min) + Vec3::from_array(c.max);
            let sep = (cb - ca).abs();
            let axis = if sep.x >= sep.y && sep.x >= sep.z {
                0
            } else if sep.y >= sep.z {
                1
            } else {
                2
            };
            INTERIOR | axis | (((cb[axis as usize] - ca[axis as usize]) < 0.0) as u32) << 2
        };
        let [x0, y0, z0] = n.min;
        let [x1, y1, z1] = n.max;
        LaneNode { b: [x0, y0, z0, f32::from_bits(n.first), x1, y1, z1, f32::from_bits(meta)] }
    }

    #[inline(always)]
    fn meta(&self) -> u32 {
        self.b[7].to_bits()
    }

    #[inline(always)]
    fn is_leaf(&self) -> bool {
        self.meta() & INTERIOR == 0
    }

    #[inline(always)]
    fn first(&self) -> u32 {
        self.b[3].to_bits()
    }

    #[inline(always)]
    fn count(&self) -> u32 {
        self.meta()
    }

    /// An interior node's children, nearer first for rays going `down` (per axis) the
    /// node's ordering axis. The order only speeds the walk; no result depends on it.
    #[inline(always)]
    fn near_far(&self, down: [bool; 3]) -> (u32, u32) {
        let meta = self.meta();
        let flip = (meta >> 2) & 1 != down[(meta & 3) as usize] as u32;
        let first = self.first();
        if flip {
            (first + 1, first)
        } else {
            (first, first + 1)
        }
    }
}

/// Whether a row of lanes enters a node: a trait, not a closure, so it inlines into the walk
/// and into its caller's AVX2 code.
trait NodeTest<L: Lane> {
    /// Whether any active lane meets the node's box within `(0, limit)`.
    fn enters(&self, n: &LaneNode, limit: L) -> bool;
    /// The direction, per axis, that orders children.
    fn down(&self) -> [bool; 3];
}

/// Any row: `node_slabs`, as the single-ray walk tests.
struct Slabs<'a, L: Lane> {
    ray: &'a RayLanes<L>,
    active: L::Mask,
    down: [bool; 3],
}

impl<L: Lane> NodeTest<L> for Slabs<'_, L> {
    #[inline(always)]
    fn enters(&self, n: &LaneNode, limit: L) -> bool {
        let lo = V3::splat(Vec3::new(n.b[0], n.b[1], n.b[2]));
        let hi = V3::splat(Vec3::new(n.b[4], n.b[5], n.b[6]));
        let (near, far) = node_slabs(lo, hi, self.ray.o, self.ray.inv);
        L::any(L::and(L::and(near.le(far), L::splat(0.0).le(far)), L::and(near.le(limit), self.active)))
    }

    #[inline(always)]
    fn down(&self) -> [bool; 3] {
        self.down
    }
}

/// Rows whose active lanes all go the same way along each axis, with finite `1/d`: the box's
/// near side per axis is known for the whole row, so each axis costs one subtraction and one
/// product per side and no min, max or NaN repair. The same numbers as `node_slabs`: no
/// product is NaN (finite times finite), and with `inv > 0` the slab `lo` side's distance is
/// the smaller, as rounding keeps order (and the other way for `inv < 0`). For the same reason
/// a lane that enters a child box enters its parent, which lets the walk skip the root.
#[derive(Clone, Copy)]
struct SignedSlabs<L: Lane> {
    o: V3<L>,
    inv: V3<L>,
    active: L::Mask,
    down: [bool; 3],
    /// Per axis, the index in `LaneNode::b` of the box side met first (`lo`, 0..3, going up;
    /// `hi`, 4..7, going down) and of the side met last.
    near: [usize; 3],
    far: [usize; 3],
}

impl<L: Lane> SignedSlabs<L> {
    #[inline(always)]
    fn new(ray: &RayLanes<L>, active: L::Mask, down: [bool; 3]) -> SignedSlabs<L> {
        let near = [4 * down[0] as usize, 1 + 4 * down[1] as usize, 2 + 4 * down[2] as usize];
        let far = [4 * !down[0] as usize, 1 + 4 * !down[1] as usize, 2 + 4 * !down[2] as usize];
        SignedSlabs { o: ray.o, inv: ray.inv, active, down, near, far }
    }
}

/// The distance along one axis to the box side `b[ix]`.
#[inline(always)]
fn side<L: Lane>(n: &LaneNode, ix: usize, o: L, inv: L) -> L {
    (L::splat(n.b[ix & 7]) - o) * inv
}

impl<L: Lane> NodeTest<L> for SignedSlabs<L> {
    #[inline(always)]
    fn enters(&self, n: &LaneNode, limit: L) -> bool {
        let (near, far) = (&self.near, &self.far);
        let nx = side(n, near[0], self.o.x, self.inv.x);
        let ny = side(n, near[1], self.o.y, self.inv.y);
        let nz = side(n, near[2], self.o.z, self.inv.z);
        let fx = side(n, far[0], self.o.x, self.inv.x);
        let fy = side(n, far[1], self.o.y, self.inv.y);
        let fz = side(n, far[2], self.o.z, self.inv.z);
        let (near, far) = (nx.max(ny).max(nz), fx.min(fy).min(fz));
        L::any(L::and(L::and(near.le(far), L::splat(0.0).le(far)), L::and(near.le(limit), self.active)))
    }

    #[inline(always)]
    fn down(&self) -> [bool; 3] {
        self.down
    }
}

/// One placed mesh: shared triangles under an object transform.
#[derive(Clone, Debug)]
pub struct Mesh {
    pub data: Arc<MeshData>,
    frame: BoxFrame,
    /// `inside_vector` in object space: points are inside when a ray from them along it crosses
    /// the surface an odd number of times. `None`: not solid.
    inside_vector: Option<Vec3>,
    min: Vec3,
    max: Vec3,
}

impl Mesh {
    pub fn new(data: Arc<MeshData>, render_from_object: Affine3A, inside_vector: Option<Vec3>) -> Mesh {
        let (min, max) = transformed_bounds(&render_from_object, data.min, data.max);
        let inside_vector = inside_vector.filter(|v| v.length_squared() > 0.0 && v.is_finite());
        Mesh { data, frame: frame_for(render_from_object), inside_vector, min, max }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// Lane `i` of a render-space ray as an object-space `Ray` (not normalised: `t` is the
    /// same along both). Every path (packets, single rays, the face lookup) goes through here,
    /// so they trace the same numbers.
    #[inline(always)]
    fn object_ray<L: Lane>(&self, o: &V3<L>, d: &V3<L>, i: usize) -> Ray {
        let origin = Vec3::new(o.x.get(i), o.y.get(i), o.z.get(i));
        let dir = Vec3::new(d.x.get(i), d.y.get(i), d.z.get(i));
        Ray { origin, dir, inv_dir: dir.recip() }
    }

    /// The nearest hit of one ray and which face it is on.
    #[inline]
    pub fn hit_face(&self, ray: &RayLanes<f32>, t_min: f32, t_max: f32) -> Option<(f32, u32)> {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        self.data.nearest(&self.object_ray(&o, &d, 0), t_min, t_max)
    }

    /// `Shape::hit` and each lane's face (`u32::MAX` where it missed): the face `hit_face`
    /// finds again at that distance, so packets of primary rays need not search again.
    #[inline(always)]
    pub fn hit_faces<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, [u32; 8]) {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        if L::WIDTH > 1 {
            return self.data.nearest_faces_lanes(&RayLanes { o, d, inv: d.recip() }, t_min, t_max);
        }
        let mut faces = [u32::MAX; 8];
        let t = L::from_fn(|i| {
            let r = self.object_ray(&o, &d, i);
            let (t, face) = self.data.nearest(&r, t_min.get(i), t_max.get(i)).unwrap_or((MISS, u32::MAX));
            faces[i] = face;
            t
        });
        (t, faces)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn hit_faces_avx2<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, [u32; 8]) {
        self.hit_faces(ray, t_min, t_max)
    }

    /// For shadow rays: `Shape::hit`, but each lane's first hit found rather than its nearest.
    #[inline(never)]
    pub fn first_hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        // Not inlined into the packet walk (see `Shape::hit` below), so the eight-lane code
        // would run in the caller's SSE; this copy runs it in 256-bit instructions. AVX2
        // without FMA computes the same bits (as `render::packet`).
        #[cfg(target_arch = "x86_64")]
        if L::WIDTH == 8 && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.first_hit_avx2(ray, t_min, t_max) };
        }
        self.first_hit_here(ray, t_min, t_max)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn first_hit_avx2<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.first_hit_here(ray, t_min, t_max)
    }

    #[inline(always)]
    fn first_hit_here<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        if L::WIDTH > 1 {
            return self.data.first_lanes(&RayLanes { o, d, inv: d.recip() }, t_min, t_max);
        }
        L::from_fn(|i| {
            let r = self.object_ray(&o, &d, i);
            self.data.first(&r, t_min.get(i), t_max.get(i)).unwrap_or(MISS)
        })
    }

    /// Whether `rows` pays: a mesh of a few faces (a `smooth_triangle` is a mesh of one) has
    /// little tree to share and would pay `rows`' setup for eight rows (smooth_triangle.pov 1.5x
    /// slower); a height field walks its grid row by row.
    #[inline(always)]
    pub fn walks_rows(&self) -> bool {
        self.data.grid.is_none() && self.data.triangles.len() >= ROWS_MIN_FACES
    }

    /// `hit_faces` (`FIRST` false) or `first_hit` (`FIRST` true) for up to eight rows of one
    /// packet at once, row `r` with limit `t_max[r]`: each row's answer as those give it for
    /// the row alone, from one shared walk (`MeshData::walk_rows`).
    #[inline(never)]
    pub fn rows<const FIRST: bool>(&self, rays: &[RayLanes<F8>], t_max: &[F8]) -> [(F8, [u32; 8]); 8] {
        // In 256-bit instructions where the CPU has them, as `first_hit`.
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.rows_avx2::<FIRST>(rays, t_max) };
        }
        self.rows_here::<FIRST>(rays, t_max)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn rows_avx2<const FIRST: bool>(&self, rays: &[RayLanes<F8>], t_max: &[F8]) -> [(F8, [u32; 8]); 8] {
        self.rows_here::<FIRST>(rays, t_max)
    }

    #[inline(always)]
    fn rows_here<const FIRST: bool>(&self, rays: &[RayLanes<F8>], t_max: &[F8]) -> [(F8, [u32; 8]); 8] {
        let mut object =
            [RayLanes::<F8> { o: V3::splat(Vec3::ZERO), d: V3::splat(Vec3::ZERO), inv: V3::splat(Vec3::ZERO) }; 8];
        let rows = rays.len().min(8);
        for r in 0..rows {
            // As `hit_faces` and `first_hit_here` carry one row.
            let o = rays[r].o.transform_point(&self.frame.object_from_render);
            let d = rays[r].d.transform_vector(&self.frame.object_from_render);
            object[r] = RayLanes { o, d, inv: d.recip() };
        }
        let mut out = [(F8::splat(MISS), [u32::MAX; 8]); 8];
        self.data.walk_rows::<F8, FIRST>(&object[..rows], t_max, &mut out);
        out
    }

    /// `face`'s hit re-solved in f64 (`--precision f64`): the triangle kernel on the ray
    /// carried into object space in f64.
    pub fn refine_face(&self, face: u32, ray: &RayLanes<f64>) -> f64 {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        self.data.triangles[face as usize].hit(&RayLanes::new(o, d), 0.0, f64::INFINITY)
    }

    /// The normal of `face` at render-space points on it: the geometric one, or for a smooth
    /// face the vertex normals interpolated by the point's barycentric coordinates, flipped to
    /// the geometric normal's side (POV-Ray 3.4.5.2.1: `smooth_triangle`).
    #[inline(always)]
    pub fn normal<L: Lane>(&self, face: u32, p: V3<L>) -> V3<L> {
        let tri = &self.data.triangles[face as usize];
        let geometric = V3::splat(tri.normal);
        let n = match self.data.smooth_of[face as usize] {
            FLAT => geometric,
            k => {
                let [n0, n1, n2] = self.data.smooth[k as usize];
                let q = p.transform_point(&self.frame.object_from_render).sub(V3::splat(tri.v0));
                let (e1, e2) = (V3::splat(tri.e1), V3::splat(tri.e2));
                let (d00, d01, d11) = (tri.e1.dot(tri.e1), tri.e1.dot(tri.e2), tri.e2.dot(tri.e2));
                let inv = 1.0 / (d00 * d11 - d01 * d01);
                let (d20, d21) = (q.dot(e1), q.dot(e2));
                let u = (L::splat(d11) * d20 - L::splat(d01) * d21) * L::splat(inv);
                let v = (L::splat(d00) * d21 - L::splat(d01) * d20) * L::splat(inv);
                let w = L::splat(1.0) - u - v;
                let n = V3::splat(n0).scale(w).add(V3::splat(n1).scale(u)).add(V3::splat(n2).scale(v));
                let n = V3::select(n.dot(geometric).lt(L::splat(0.0)), n.neg(), n);
                // A zero interpolated normal (opposite vertex normals) falls back to the face's.
                V3::select(L::lt(L::splat(0.0), n.dot(n)), n, geometric)
            }
        };
        n.mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }
}

impl Shape for Mesh {
    /// Packets (`F8`) walk the mesh's BVH together, carried into object space as a packet
    /// (`MeshData::nearest_faces_lanes`); single rays (f32, and f64, whose lanes are traced in f32)
    /// walk it alone (`MeshData::nearest`). Both give the same `t`.
    // Not inlined into `Scene::hit_prim`: the dispatch every shape shares stays small, so
    // scenes without this kind do not pay for its code.
    #[inline(never)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        // In 256-bit instructions where the CPU has them, as `first_hit`.
        #[cfg(target_arch = "x86_64")]
        if L::WIDTH == 8 && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.hit_faces_avx2(ray, t_min, t_max).0 };
        }
        self.hit_faces(ray, t_min, t_max).0
    }

    /// Without a face the normal is unknown: hits on meshes are resolved to faces
    /// (`HitShape::Face`) before anything asks, and `Mesh::normal` answers then.
    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        self.normal(0, p)
    }

    /// POV-Ray's `inside_vector` test: odd crossings along it are inside; no vector, not solid.
    /// A height field asks its grid (below the surface), the same answer without the walk.
    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = p.transform_point(&self.frame.object_from_render);
        if let Some(grid) = &self.data.grid {
            return L::mask_from_fn(|i| grid.below_surface(Vec3::new(q.x.get(i), q.y.get(i), q.z.get(i))));
        }
        let Some(v) = self.inside_vector else { return L::mask_from_fn(|_| false) };
        L::mask_from_fn(|i| {
            let origin = Vec3::new(q.x.get(i), q.y.get(i), q.z.get(i));
            self.data.crossings(&Ray { origin, dir: v, inv_dir: v.recip() }) % 2 == 1
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lanes::F8;

    /// The unit cube as 12 triangles.
    fn cube() -> Vec<([Vec3; 3], Option<[Vec3; 3]>)> {
        let c = |i: u32| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32);
        let quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]];
        quads.iter().flat_map(|q| [([c(q[0]), c(q[1]), c(q[2])], None), ([c(q[0]), c(q[2]), c(q[3])], None)]).collect()
    }

    fn placed(inside: bool) -> Mesh {
        let xf = Affine3A::from_translation(Vec3::new(0.0, 0.0, 3.0)) * Affine3A::from_rotation_y(0.3);
        Mesh::new(Arc::new(MeshData::new(cube())), xf, inside.then_some(Vec3::new(0.1, 0.2, 1.0)))
    }

    #[test]
    fn hits_report_their_face() {
        let m = placed(false);
        let ray = Ray::new(Vec3::new(0.3, 0.5, -1.0), Vec3::Z);
        let (t, face) = m.hit_face(&ray.lanes(), 0.0, f32::INFINITY).expect("hit");
        assert_eq!(m.intersect(&ray, 0.0, f32::INFINITY), Some(t));
        let n = m.normal(face, V3::from_vec3(ray.at(t))).vec3();
        // The front face (z = 0 before the turn); its winding, not the mesh, sets the sign.
        assert!(n.dot(Vec3::Z).abs() > 0.9, "{n}");
    }

    #[test]
    fn inside_by_parity_only_with_an_inside_vector() {
        let p = Affine3A::from_translation(Vec3::new(0.0, 0.0, 3.0)).transform_point3(Vec3::splat(0.5));
        assert!(placed(true).inside(V3::from_vec3(p)));
        assert!(!placed(false).inside(V3::from_vec3(p)));
        assert!(!placed(true).inside(V3::from_vec3(Vec3::new(5.0, 0.0, 0.0))));
    }

    /// objects/csg/hfclip.pov took 90 s at 64×48: CSG asks `inside` for idle packet lanes at
    /// infinity, whose NaN slabs entered every node of the mesh's BVH.
    #[test]
    fn points_at_infinity_are_outside_without_a_walk() {
        let m = placed(true);
        assert!(!m.inside(V3::from_vec3(Vec3::INFINITY)));
        assert!(!m.inside(V3::from_vec3(Vec3::NAN)));
        let idle = Ray::new(Vec3::INFINITY, Vec3::Z);
        assert_eq!(m.hit(&idle.lanes(), 0.0, f32::INFINITY), MISS);
    }

    #[test]
    fn eight_lanes_match_one() {
        let m = placed(true);
        let dirs: [Vec3; 8] =
            std::array::from_fn(|i| Vec3::new(0.05 * i as f32 - 0.2, 0.1 - 0.03 * i as f32, 1.0).normalize());
        let o = Vec3::new(0.4, 0.4, -1.0);
        let wide = RayLanes::<F8>::new(V3::splat(o), V3::from_lanes(|i| dirs[i]));
        let t8 = m.hit(&wide, F8::splat(0.0), F8::splat(f32::INFINITY));
        for (i, d) in dirs.iter().enumerate() {
            let one = m.hit(&Ray::new(o, *d).lanes(), 0.0, f32::INFINITY);
            assert_eq!(t8.0[i].to_bits(), one.to_bits());
        }
    }

    /// Shadow rays' first hits: a hit exactly where the nearest search finds one (inside the
    /// same interval), on one lane and eight, from outside the cube and from inside it.
    #[test]
    fn first_hits_are_hits_where_nearest_ones_are() {
        let m = placed(true);
        for o in [Vec3::new(0.4, 0.4, -1.0), Vec3::new(0.5, 0.5, 3.5)] {
            let dirs: [Vec3; 8] =
                std::array::from_fn(|i| Vec3::new(0.3 * i as f32 - 1.0, 0.7 - 0.2 * i as f32, 1.0).normalize());
            let wide = RayLanes::<F8>::new(V3::splat(o), V3::from_lanes(|i| dirs[i]));
            for t_max in [0.5, 2.0, 4.0, f32::INFINITY] {
                let near8 = m.hit(&wide, F8::splat(0.0), F8::splat(t_max));
                let first8 = m.first_hit(&wide, F8::splat(0.0), F8::splat(t_max));
                for (i, d) in dirs.iter().enumerate() {
                    let lanes = Ray::new(o, *d).lanes();
                    let (near, first) = (m.hit(&lanes, 0.0, t_max), m.first_hit(&lanes, 0.0, t_max));
                    assert_eq!(near == MISS, first == MISS, "{o} {d} {t_max}");
                    assert_eq!(near8.0[i] == MISS, first8.0[i] == MISS, "{o} {d} {t_max}");
                    assert_eq!(near == MISS, near8.0[i] == MISS);
                    assert!(first == MISS || (first >= near && first < t_max), "{first} {near}");
                }
            }
        }
    }

    #[test]
    fn smooth_normals_interpolate_and_keep_the_geometric_side() {
        let v = [Vec3::ZERO, Vec3::X, Vec3::Y];
        // Normals written pointing away from the geometric normal (+z): flipped back.
        let n = [-Vec3::Z + Vec3::X, -Vec3::Z, -Vec3::Z];
        let m = Mesh::new(Arc::new(MeshData::new([(v, Some(n))])), Affine3A::IDENTITY, None);
        let at0 = m.normal(0, V3::from_vec3(Vec3::new(0.0, 0.0, 0.0))).vec3();
        assert!((at0 - Vec3::new(-1.0, 0.0, 1.0).normalize()).length() < 1e-5, "{at0}");
        let at1 = m.normal(0, V3::from_vec3(Vec3::new(1.0, 0.0, 0.0))).vec3();
        assert!((at1 - Vec3::Z).length() < 1e-5, "{at1}");
    }

    /// A small deterministic generator (SplitMix64) of floats in `[lo, hi)`.
    struct Rng(u64);

    impl Rng {
        fn f(&mut self, lo: f32, hi: f32) -> f32 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            lo + (hi - lo) * ((z >> 40) as f32 / (1u64 << 24) as f32)
        }

        fn v(&mut self, lo: f32, hi: f32) -> Vec3 {
            Vec3::new(self.f(lo, hi), self.f(lo, hi), self.f(lo, hi))
        }
    }

    /// The nearest face of `m` for one render-space ray by testing every triangle (the ray
    /// carried into object space as `Mesh::hit_face` carries it): least `t`, ties to the lowest
    /// face.
    fn brute_force(m: &Mesh, o: Vec3, d: Vec3, t_max: f32) -> Option<(f32, u32)> {
        let ray = RayLanes::<f32>::new(V3::from_vec3(o), V3::from_vec3(d));
        let o = ray.o.transform_point(&m.frame.object_from_render);
        let d = ray.d.transform_vector(&m.frame.object_from_render);
        let object = RayLanes { o, d, inv: d.recip() };
        let mut best: Option<(f32, u32)> = None;
        for (f, tri) in m.data.triangles.iter().enumerate() {
            let t = tri.hit(&object, 0.0, t_max);
            if t != MISS && best.is_none_or(|(b, _)| t < b) {
                best = Some((t, f as u32));
            }
        }
        best
    }

    /// Rows walked together (`Mesh::rows`) answer what each row's own walk (`hit_faces`,
    /// `first_hit`), each lane's single ray and brute force answer: the same distance and face
    /// bit for bit, the same shadow verdicts. Blocks of one origin (primary rays); of many
    /// origins aimed at one point, with limits of their own and idle lanes (shadow rays); with
    /// mixed direction signs (walked row by row); with lanes aimed exactly at vertices (grazing).
    #[test]
    fn rows_together_match_rows_alone_single_rays_and_brute_force() {
        let r = &mut Rng(0x5EED);
        let (mut hits, mut lanes, mut disagree) = (0, 0, 0);
        for case in 0..12 {
            let faces: Vec<([Vec3; 3], Option<[Vec3; 3]>)> = (0..20 + (case * 37) % 200)
                .map(|_| {
                    let c = r.v(-1.0, 1.0);
                    ([c + r.v(-0.3, 0.3), c + r.v(-0.3, 0.3), c + r.v(-0.3, 0.3)], None)
                })
                .collect();
            let vertices: Vec<Vec3> = faces.iter().flat_map(|(v, _)| *v).collect();
            let xf = if case % 2 == 0 {
                Affine3A::from_translation(r.v(-2.0, 2.0))
            } else {
                Affine3A::from_rotation_y(r.f(0.0, 3.0)) * Affine3A::from_scale(Vec3::splat(1.5))
            };
            let m = Mesh::new(Arc::new(MeshData::new(faces)), xf, None);
            for block in 0..30 {
                let kind = block % 3;
                let n = 1 + block % 8;
                let eye = r.v(-6.0, 6.0);
                let light = r.v(-8.0, 8.0);
                let mut rows = [RayLanes::<F8>::new(V3::splat(Vec3::ZERO), V3::splat(Vec3::X)); 8];
                let mut t_max = [F8::splat(MISS); 8];
                let mut single = [[(Vec3::ZERO, Vec3::X, MISS); 8]; 8];
                for (k, row) in single.iter_mut().enumerate().take(n) {
                    for (i, lane) in row.iter_mut().enumerate() {
                        let target = if (k + i) % 5 == 0 {
                            xf.transform_point3(vertices[(k * 8 + i + block) % vertices.len()])
                        } else {
                            xf.transform_point3(r.v(-1.2, 1.2))
                        };
                        *lane = match kind {
                            0 => (eye, target - eye, MISS),
                            // From points near the mesh towards the light, to just before it; lane 1 idle.
                            1 => (target, light - target, [0.999, 0.0, 0.999, 0.5][i % 4]),
                            _ => (target + r.v(-0.5, 0.5), r.v(-1.0, 1.0), [MISS, 2.0][i % 2]),
                        };
                    }
                    rows[k] = RayLanes::new(V3::from_lanes(|i| row[i].0), V3::from_lanes(|i| row[i].1));
                    t_max[k] = F8::from_fn(|i| row[i].2);
                }
                let near = m.rows::<false>(&rows[..n], &t_max[..n]);
                let first = m.rows::<true>(&rows[..n], &t_max[..n]);
                for k in 0..n {
                    let (t_row, faces_row) = m.hit_faces(&rows[k], F8::splat(0.0), t_max[k]);
                    let first_row = m.first_hit(&rows[k], F8::splat(0.0), t_max[k]);
                    for i in 0..8 {
                        let (o, d, limit) = single[k][i];
                        let what = format!("case {case} block {block} row {k} lane {i}");
                        assert_eq!(near[k].0 .0[i].to_bits(), t_row.0[i].to_bits(), "{what}");
                        assert_eq!(near[k].1[i], faces_row[i], "{what}");
                        let blocked = first[k].0 .0[i] < MISS;
                        assert_eq!(blocked, first_row.0[i] < MISS, "{what}");
                        // A lane aimed exactly at a vertex can meet it where its own box test
                        // fails but its row's walk tests the face for another lane: packets and
                        // single rays may part there (as before rows were walked together).
                        if (k + i) % 5 != 0 {
                            let lane = RayLanes::<f32>::new(V3::from_vec3(o), V3::from_vec3(d));
                            let one = m.hit_face(&lane, 0.0, limit);
                            let (t, face) = one.unwrap_or((MISS, u32::MAX));
                            assert_eq!((near[k].0 .0[i].to_bits(), near[k].1[i]), (t.to_bits(), face), "{what}");
                            assert_eq!(blocked, one.is_some(), "{what}");
                            // The walks cull by boxes, brute force does not: a hit the kernel
                            // rounds a hair outside its face's box may differ (rarely).
                            disagree += u32::from(one != brute_force(&m, o, d, limit));
                        }
                        hits += u32::from(blocked);
                        lanes += 1;
                    }
                }
            }
        }
        // Not a vacuous pass: a fair share of the lanes hit.
        assert!(hits > lanes / 10 && hits < lanes, "{hits} of {lanes}");
        assert!(disagree * 1000 < lanes, "{disagree} of {lanes} lanes disagree with brute force");
    }
}
