//! A mesh's packet walks: eight lanes of one row down its BVH (`MeshData::nearest_faces_lanes`,
//! `first_lanes`), and the rows of a whole packet down it together (`walk_rows`), on a copy of
//! the tree laid out for lanes (`LaneNode`: box sides picked by each axis's direction sign,
//! child order precomputed). Every lane gets the single-ray walk's distance and face bit for bit.

use glam::Vec3;

use super::*;

impl MeshData {
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
        let mut row = RowState::new::<FIRST>(active, t_max);
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
            // As `nearest`: up to a lane's bound itself, where a face of lower index wins a tie.
            let reach = row.bound.map(next_up);
            let t = self.triangles[f as usize].hit(ray, t_min, reach);
            let lower = L::mask_from_fn(|i| f < row.faces[i]);
            let mut hit = L::and(t.lt(reach), L::or(t.lt(row.bound), lower));
            if self.floor != f32::NEG_INFINITY {
                let y = ray.o.y + t * ray.d.y;
                hit = L::and(hit, L::splat(self.floor).le(y));
            }
            row.best = L::select(hit, t, row.best);
            // A select per lane, not a branch.
            for (i, face) in row.faces.iter_mut().enumerate().take(L::WIDTH) {
                *face = if L::mask_lane(hit, i) { f } else { *face };
            }
            row.bound = L::select(hit, t, row.bound);
            row.limit = L::select(hit, cull_limit(t), row.limit);
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
    pub(super) fn walk_rows<L: Lane, const FIRST: bool>(
        &self,
        rays: &[RayLanes<L>],
        t_max: &[L],
        out: &mut [(L, [u32; 8])],
    ) {
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
        let mut state = [RowState::new::<FIRST>(active[0], t_max[0]); 8];
        // Rows with lanes still to find a hit (bit per row), for shadow rows' early end.
        let mut left = 0u32;
        for r in 1..rows {
            tests[r] = SignedSlabs::new(&rays[r], active[r], down);
            state[r] = RowState::new::<FIRST>(active[r], t_max[r]);
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

/// One row's progress in a walk: each lane's limit for boxes (-inf for idle lanes and, in
/// shadow walks, for lanes that have hit: no node or face accepts it), best distance and face,
/// and (nearest walks) the greatest distance still accepted, as in `nearest`: the best so far,
/// else just below `t_max`; boxes are culled at `cull_limit` of it.
#[derive(Clone, Copy)]
struct RowState<L: Lane> {
    limit: L,
    best: L,
    faces: [u32; 8],
    bound: L,
}

impl<L: Lane> RowState<L> {
    #[inline(always)]
    fn new<const FIRST: bool>(active: L::Mask, t_max: L) -> RowState<L> {
        let idle = L::splat(f32::NEG_INFINITY);
        let bound = L::select(active, t_max.map(|t| -next_up(-t)), idle);
        let limit = if FIRST { t_max } else { cull_limit(bound) };
        RowState { limit: L::select(active, limit, idle), best: L::splat(MISS), faces: [u32::MAX; 8], bound }
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
pub(super) struct LaneNode {
    b: [f32; 8],
}

/// `LaneNode`'s `meta` bit for an interior node (a leaf's count is below it).
const INTERIOR: u32 = 1 << 31;

impl LaneNode {
    pub(super) fn new(bvh: &Bvh, n: &BvhNode) -> LaneNode {
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
