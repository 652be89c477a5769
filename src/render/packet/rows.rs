//! The packet walks of the scene: nearest hits of up to eight rows of primary rays
//! (`intersect_rows`) and which lanes of shadow rows are blocked (`occluded_rows`): planes and
//! unbounded primitives first, then the BVH, each primitive tested against a row at a time
//! (or, for a mesh, against the packet's rows together).

use super::*;

/// Nearest hits of up to eight rows of rays: planes, the unbounded primitives, then the BVH.
pub(super) fn intersect_rows(
    scene: &Scene,
    rows: &[Ray8],
    t: &mut [F8],
    ids: &mut [[u32; 8]],
    faces: &mut [[u32; 8]],
    frustum: Option<&Frustum>,
    stats: &mut RenderStats,
) {
    #[cfg(target_arch = "x86_64")]
    if has_avx2() {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { intersect_rows_avx2(scene, rows, t, ids, faces, frustum, stats) };
    }
    intersect_rows_generic(scene, rows, t, ids, faces, frustum, stats)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn intersect_rows_avx2(
    scene: &Scene,
    rows: &[Ray8],
    t: &mut [F8],
    ids: &mut [[u32; 8]],
    faces: &mut [[u32; 8]],
    frustum: Option<&Frustum>,
    stats: &mut RenderStats,
) {
    intersect_rows_generic(scene, rows, t, ids, faces, frustum, stats)
}

/// Records the lanes where `t_new` beats `t` as hits on `id`, or on CSG leaf `leaf[i]` where
/// that is not `NO_HIT`, on face `face[i]` of a mesh (`NO_HIT` for other shapes).
#[inline(always)]
fn take_nearer(
    t: &mut F8,
    ids: &mut [u32; 8],
    faces: &mut [u32; 8],
    t_new: F8,
    id: u32,
    leaf: &[u32; 8],
    face: &[u32; 8],
) -> u32 {
    let nearer = t_new.lt(*t);
    *t = F8::select(nearer, t_new, *t);
    if !nearer.any() {
        return 0;
    }
    // Branch-free per lane, so it vectorises.
    for i in 0..8 {
        let new_id = if leaf[i] != NO_HIT { leaf[i] } else { id };
        let keep = (nearer.0[i] as u32) ^ u32::MAX;
        ids[i] = (ids[i] & keep) | (new_id & !keep);
        faces[i] = (faces[i] & keep) | (face[i] & !keep);
    }
    nearer.count()
}

#[inline(always)]
fn intersect_rows_generic(
    scene: &Scene,
    rows: &[Ray8],
    t: &mut [F8],
    ids: &mut [[u32; 8]],
    faces: &mut [[u32; 8]],
    frustum: Option<&Frustum>,
    stats: &mut RenderStats,
) {
    for (p, plane) in scene.planes.iter().enumerate() {
        for (r, ray) in rows.iter().enumerate() {
            let tp = plane.hit(ray, F8::splat(0.0), t[r]);
            let none = [NO_HIT; 8];
            let hits = take_nearer(&mut t[r], &mut ids[r], &mut faces[r], tp, PLANE_ID + p as u32, &none, &none);
            stats.tests[ShapeKind::Plane as usize] += 8;
            stats.hits[ShapeKind::Plane as usize] += hits as u64;
        }
    }
    // Counted straight into the caller's statistics: a local `RenderStats` (about 0.8 KB) was
    // zeroed and added field by field three times per block, 5 % of a floor-only frame.
    let mut test = NearestRows { scene, rows, ids, faces, stats };
    // Unbounded primitives (`Scene::unbounded`), for every row, as planes.
    for prim in scene.unbounded.clone() {
        for r in 0..rows.len() {
            test.test(prim, r, &mut t[r]);
        }
    }
    if let Accel::Bvh(bvh) = &scene.accel {
        let all = [M8([-1; 8]); 8];
        let visited = bvh.traverse_packet(rows, t, &all[..rows.len()], frustum, &mut test);
        test.stats.nodes_visited += visited as u64;
    }
}

/// The nearest-hit primitive test for packets: records which primitive each lane hit, and
/// on a mesh which face.
struct NearestRows<'a, 'r> {
    scene: &'a Scene,
    rows: &'r [Ray8],
    ids: &'r mut [[u32; 8]],
    faces: &'r mut [[u32; 8]],
    stats: &'r mut RenderStats,
}

impl RowTest for NearestRows<'_, '_> {
    #[inline(always)]
    fn test(&mut self, prim: u32, r: usize, t: &mut F8) {
        let p = &self.scene.prims[prim as usize];
        let (t_new, leaf, face) = self.scene.hit_prim_resolved(p, &self.rows[r], *t);
        let kind = p.kind;
        let hits = take_nearer(t, &mut self.ids[r], &mut self.faces[r], t_new, prim, &leaf, &face);
        self.stats.tests[kind as usize] += 8;
        self.stats.hits[kind as usize] += hits as u64;
    }

    /// A mesh walks its own tree once for all the rows (`Mesh::rows`).
    #[inline(always)]
    fn test_rows(&mut self, prim: u32, first: usize, last: usize, t: &mut [F8]) {
        let p = &self.scene.prims[prim as usize];
        if p.kind != ShapeKind::Mesh || !self.scene.meshes[p.index as usize].walks_rows() {
            for r in first..=last {
                self.test(prim, r, &mut t[r]);
            }
            return;
        }
        let found = self.scene.meshes[p.index as usize].rows::<false>(&self.rows[first..=last], &t[first..=last]);
        for r in first..=last {
            let (t_new, face) = &found[r - first];
            let hits = take_nearer(&mut t[r], &mut self.ids[r], &mut self.faces[r], *t_new, prim, &[NO_HIT; 8], face);
            self.stats.tests[p.kind as usize] += 8;
            self.stats.hits[p.kind as usize] += hits as u64;
        }
    }
}

/// The any-hit primitive test for shadow packets: a blocked lane's limit drops to -inf, which
/// every later node and primitive test rejects.
struct BlockedRows<'a, 'r> {
    scene: &'a Scene,
    rows: &'r [Ray8],
    active: &'r [M8],
    blocked: [M8; 8],
    stats: &'r mut RenderStats,
}

impl BlockedRows<'_, '_> {
    #[inline(always)]
    fn block(&mut self, r: usize, t: &mut F8, hit: M8) {
        self.blocked[r] = F8::or(self.blocked[r], hit);
        *t = F8::select(hit, F8::splat(f32::NEG_INFINITY), *t);
    }

    /// Blocks row `r`'s active lanes where a shape of `kind` answered a hit (`t_new`).
    #[inline(always)]
    fn blocked_by(&mut self, kind: ShapeKind, r: usize, t: &mut F8, t_new: F8) {
        let hit = F8::and(t_new.lt(F8::splat(MISS)), self.active[r]);
        self.stats.tests[kind as usize] += 8;
        self.stats.hits[kind as usize] += hit.count() as u64;
        self.block(r, t, hit);
    }
}

impl RowTest for BlockedRows<'_, '_> {
    #[inline(always)]
    fn test(&mut self, prim: u32, r: usize, t: &mut F8) {
        let p = &self.scene.prims[prim as usize];
        if !p.casts_shadow {
            return;
        }
        let t_new = self.scene.blocks_prim(p, &self.rows[r], *t);
        self.blocked_by(p.kind, r, t, t_new);
    }

    /// A mesh walks its own tree once for all the rows (`Mesh::rows`).
    #[inline(always)]
    fn test_rows(&mut self, prim: u32, first: usize, last: usize, t: &mut [F8]) {
        let p = &self.scene.prims[prim as usize];
        if p.kind != ShapeKind::Mesh || !p.casts_shadow || !self.scene.meshes[p.index as usize].walks_rows() {
            for r in first..=last {
                self.test(prim, r, &mut t[r]);
            }
            return;
        }
        let found = self.scene.meshes[p.index as usize].rows::<true>(&self.rows[first..=last], &t[first..=last]);
        for r in first..=last {
            self.blocked_by(p.kind, r, &mut t[r], found[r - first].0);
        }
    }
}

/// Which lanes of each row are blocked before their `t_max` (`IntersectP` for packets).
pub(super) fn occluded_rows(
    scene: &Scene,
    rows: &[Ray8],
    t_max: &mut [F8],
    active: &[M8],
    light: Vec3,
    stats: &mut RenderStats,
) -> [M8; 8] {
    #[cfg(target_arch = "x86_64")]
    if has_avx2() {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { occluded_rows_avx2(scene, rows, t_max, active, light, stats) };
    }
    occluded_rows_generic(scene, rows, t_max, active, light, stats)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn occluded_rows_avx2(
    scene: &Scene,
    rows: &[Ray8],
    t_max: &mut [F8],
    active: &[M8],
    light: Vec3,
    stats: &mut RenderStats,
) -> [M8; 8] {
    occluded_rows_generic(scene, rows, t_max, active, light, stats)
}

#[inline(always)]
fn occluded_rows_generic(
    scene: &Scene,
    rows: &[Ray8],
    t_max: &mut [F8],
    active: &[M8],
    light: Vec3,
    stats: &mut RenderStats,
) -> [M8; 8] {
    let mut test = BlockedRows { scene, rows, active, blocked: [M8::default(); 8], stats };
    // Planes by side, as `Scene::occluded_towards`: blocked when the ray's origin and the light
    // lie strictly on opposite sides.
    for (plane, _) in scene.planes.iter().zip(&scene.plane_casts_shadow).filter(|(_, &casts)| casts) {
        let light_side = plane.normal.dot(light) - plane.distance;
        for (r, ray) in rows.iter().enumerate() {
            let side = V3::splat(plane.normal).dot(ray.o) - F8::splat(plane.distance);
            let zero = F8::splat(0.0);
            let opposite = if light_side > 0.0 {
                side.lt(zero)
            } else if light_side < 0.0 {
                zero.lt(side)
            } else {
                M8::default()
            };
            let hit = F8::and(opposite, active[r]);
            test.stats.tests[ShapeKind::Plane as usize] += 8;
            test.stats.hits[ShapeKind::Plane as usize] += hit.count() as u64;
            test.block(r, &mut t_max[r], hit);
        }
    }
    for prim in scene.unbounded.clone() {
        for r in 0..rows.len() {
            test.test(prim, r, &mut t_max[r]);
        }
    }
    if let Accel::Bvh(bvh) = &scene.accel {
        test.stats.nodes_visited += bvh.traverse_packet(rows, t_max, active, None, &mut test) as u64;
    }
    test.blocked
}
