//! A height field's own walk: its mesh's triangles found by the grid they were made from instead
//! of by the mesh's BVH. The ray is clipped to the field's box and stepped column by column
//! along whichever of x and z it crosses more cells of; in each column only the rows its z (or
//! x) interval can reach are looked at, and of those only the cells whose height interval (the
//! lowest and highest of the four corners) meets the ray's height over the column. Those cells'
//! two triangles are tested with the same kernel (`Triangle::hit`) on the same triangles as the
//! BVH walk, with the same tie rule (lowest stored face wins an equal `t`), so the walk finds the
//! mesh's nearest hit and face bit for bit, in a few cells instead of a descent through a
//! hierarchy of about 2 · W · H boxes.
//!
//! Every interval (the box, each column, the rows, the heights) is widened by `PAD` times the
//! ray origin's size: the triangle kernel's rounding can place a hit a hair outside its triangle,
//! and the walk must still visit that cell.

use glam::Vec3;

use super::triangle::Triangle;
use super::Shape;
use crate::lanes::Lane;
use crate::ray::{Ray, RayLanes, MISS};

/// Widening of every interval, relative to the size of the ray's origin (object units): some
/// hundred times f32's rounding, a thousandth of a cell of a 64-wide field seen from 20 units.
const PAD: f32 = 1e-5;

/// No face (a triangle left out under the water level).
const NONE: u32 = u32::MAX;

/// One square of the grid: the range of its corners' heights and its two triangles' indices in
/// the mesh's (BVH-ordered) triangle list.
#[derive(Clone, Copy, Debug)]
struct Cell {
    lo: f32,
    hi: f32,
    faces: [u32; 2],
}

/// The cells of a `width` × `height` field, row `k` (z = k / (height − 1)) after row `k − 1`.
#[derive(Clone, Debug)]
pub struct HeightCells {
    nx: usize,
    nz: usize,
    cells: Vec<Cell>,
    /// The lowest and highest sample: the box's y extent.
    lo: f32,
    hi: f32,
    /// Hits below this height are not hits (`water_level`), as the mesh's floor.
    floor: f32,
}

impl HeightCells {
    /// The cells of a field of `heights` (row by row, row 0 the image's top, as
    /// `height_field::faces` reads them), pointing at the mesh's `triangles` made from it. Each
    /// triangle is placed by its first vertex and first edge: `cell` winds a square's first
    /// triangle from its corner (i, k) with an edge along +z, its second from (i + 1, k) with an
    /// edge towards −x.
    pub fn new(width: usize, height: usize, heights: &[f32], floor: f32, triangles: &[Triangle]) -> HeightCells {
        let (nx, nz) = (width - 1, height - 1);
        let y = |i: usize, k: usize| heights[(height - 1 - k) * width + i];
        let mut cells = Vec::with_capacity(nx * nz);
        for k in 0..nz {
            for i in 0..nx {
                let c = [y(i, k), y(i + 1, k), y(i, k + 1), y(i + 1, k + 1)];
                let lo = c.iter().copied().fold(f32::INFINITY, f32::min);
                let hi = c.iter().copied().fold(f32::NEG_INFINITY, f32::max);
                cells.push(Cell { lo, hi, faces: [NONE; 2] });
            }
        }
        for (f, t) in triangles.iter().enumerate() {
            let second = t.e1.x < 0.0;
            let i = (t.v0.x * nx as f32).round() as usize - second as usize;
            let k = (t.v0.z * nz as f32).round() as usize;
            cells[k * nx + i].faces[second as usize] = f as u32;
        }
        let lo = heights.iter().copied().fold(f32::INFINITY, f32::min);
        let hi = heights.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        HeightCells { nx, nz, cells, lo, hi, floor }
    }

    /// The nearest face hit by the object-space `ray` in `(t_min, t_max)`: its distance and
    /// index, as `MeshData::nearest` finds them.
    #[inline]
    pub fn nearest(&self, triangles: &[Triangle], ray: &Ray, t_min: f32, t_max: f32) -> Option<(f32, u32)> {
        self.walk::<false>(triangles, ray, t_min, t_max)
    }

    /// A face hit by `ray` in `(t_min, t_max)`, the first found (for shadow rays).
    #[inline]
    pub fn first(&self, triangles: &[Triangle], ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        self.walk::<true>(triangles, ray, t_min, t_max).map(|(t, _)| t)
    }

    /// `nearest` (`FIRST` false) or `first` for each lane of a packet of object-space rays, and
    /// each lane's face (`u32::MAX` where it missed). Eight lanes walk together (`walk_packet`)
    /// where their columns run the same way; otherwise, and for one lane, each walks alone.
    #[inline(always)]
    pub fn lanes<L: Lane, const FIRST: bool>(
        &self,
        triangles: &[Triangle],
        ray: &RayLanes<L>,
        t_min: L,
        t_max: L,
    ) -> (L, [u32; 8]) {
        if L::WIDTH > 1 {
            if let Some(found) = self.walk_packet::<L, FIRST>(triangles, ray, t_min, t_max) {
                return found;
            }
        }
        let mut faces = [u32::MAX; 8];
        let t = L::from_fn(|i| {
            let origin = Vec3::new(ray.o.x.get(i), ray.o.y.get(i), ray.o.z.get(i));
            let dir = Vec3::new(ray.d.x.get(i), ray.d.y.get(i), ray.d.z.get(i));
            let r = Ray { origin, dir, inv_dir: dir.recip() };
            match self.walk::<FIRST>(triangles, &r, t_min.get(i), t_max.get(i)) {
                Some((t, f)) => {
                    faces[i] = f;
                    t
                }
                None => MISS,
            }
        });
        (t, faces)
    }

    /// The walk of `walk` for all lanes at once: the columns of every lane in turn, in each the
    /// rows any lane reaches, and each cell's triangles tested in all lanes whose own walk would
    /// test it (`Triangle::hit` over `L`, the single-ray kernel). A lane tests at least the cells
    /// its own walk does and takes the least `t`, ties to the lowest face, so its `t` and face
    /// are the single ray's. `None` where the lanes' columns do not all run the same way.
    #[inline(always)]
    fn walk_packet<L: Lane, const FIRST: bool>(
        &self,
        triangles: &[Triangle],
        ray: &RayLanes<L>,
        t_min: L,
        t_max: L,
    ) -> Option<(L, [u32; 8])> {
        let (o, d) = (ray.o, ray.d);
        let (zero, inf, ninf) = (L::splat(0.0), L::splat(f32::INFINITY), L::splat(f32::NEG_INFINITY));
        let finite = |i: usize| {
            let (o, d) = (o.lane(i), d.lane(i));
            o.is_finite() && d.is_finite() && d != Vec3::ZERO
        };
        let mut active = L::and(t_min.lt(t_max), L::mask_from_fn(finite));
        let size = o.x.abs().max(o.y.abs()).max(o.z.abs());
        let pad = L::splat(PAD) * (L::splat(1.0) + size);
        // The part of each ray inside the (widened) box, as `walk`.
        let (mut t0, mut t1) = (t_min, t_max);
        for (o, d, inv, lo, hi) in [
            (o.x, d.x, ray.inv.x, zero - pad, L::splat(1.0) + pad),
            (o.y, d.y, ray.inv.y, L::splat(self.lo) - pad, L::splat(self.hi) + pad),
            (o.z, d.z, ray.inv.z, zero - pad, L::splat(1.0) + pad),
        ] {
            let (ta, tb) = ((lo - o) * inv, (hi - o) * inv);
            let parallel = L::and(d.le(zero), zero.le(d));
            let within = L::and(lo.le(o), o.le(hi));
            let near = L::select(parallel, L::select(within, ninf, inf), ta.min(tb));
            let far = L::select(parallel, L::select(within, inf, ninf), ta.max(tb));
            t0 = t0.max(near);
            t1 = t1.min(far);
        }
        active = L::and(active, t0.le(t1));
        let first = (0..L::WIDTH).find(|&i| L::mask_lane(active, i));
        let Some(first) = first else { return Some((L::splat(MISS), [u32::MAX; 8])) };
        let (nx, nz) = (self.nx as f32, self.nz as f32);
        let x_major = (d.x.get(first) * nx).abs() >= (d.z.get(first) * nz).abs();
        let (ou, du, iu, nu, cu, ov, dv, nv, cv) = if x_major {
            (o.x, d.x, ray.inv.x, nx, self.nx, o.z, d.z, nz, self.nz)
        } else {
            (o.z, d.z, ray.inv.z, nz, self.nz, o.x, d.x, nx, self.nx)
        };
        // All lanes' columns must come in the same order, for a lane's search to end.
        let up = L::and(active, zero.lt(du));
        let down = L::and(active, du.lt(zero));
        if L::any(up) && L::any(down) {
            return None;
        }
        let forward = L::any(up);
        let still = L::and(du.le(zero), zero.le(du));
        // The columns any lane crosses.
        let (ua, ub) = ((ou + t0 * du) * L::splat(nu), (ou + t1 * du) * L::splat(nu));
        let (ulo, uhi) = (ua.min(ub) - pad * L::splat(nu), ua.max(ub) + pad * L::splat(nu));
        let (mut lo_col, mut hi_col) = (f32::INFINITY, f32::NEG_INFINITY);
        for i in 0..L::WIDTH {
            if L::mask_lane(active, i) {
                lo_col = lo_col.min(ulo.get(i));
                hi_col = hi_col.max(uhi.get(i));
            }
        }
        let index = |v: f32, n: usize| (v.max(0.0) as usize).min(n - 1);
        let (first_col, last_col) = (index(lo_col, cu), index(hi_col, cu));
        let (inv_nu, nv_l, top_row) = (1.0 / nu, L::splat(nv), L::splat((cv - 1) as f32));
        let mut faces = [u32::MAX; 8];
        let mut best = L::splat(MISS);
        // Each lane's current limit: its best distance, or -inf once done (and for idle lanes).
        let mut limit = L::select(active, t_max, ninf);
        for n in 0..=last_col - first_col {
            let c = if forward { first_col + n } else { last_col - n };
            let (edge_lo, edge_hi) = (L::splat(c as f32 * inv_nu) - pad, L::splat((c + 1) as f32 * inv_nu) + pad);
            let (ea, eb) = ((edge_lo - ou) * iu, (edge_hi - ou) * iu);
            let in_col = L::and(edge_lo.le(ou), ou.le(edge_hi));
            let ta = L::select(still, L::select(in_col, t0, inf), t0.max(ea.min(eb)));
            let tb = L::select(still, t1, t1.min(ea.max(eb)));
            // A lane is done once its best lies before this column (columns come in order), or
            // for a shadow ray once it has a hit.
            let found = best.lt(L::splat(MISS));
            let done = if FIRST { found } else { L::and(found, best.lt(ta)) };
            // Lanes past their last column are done too: one that does not move along the
            // columns once the walk has passed its own (which may be two, at a boundary).
            let passed = if forward { ou.lt(edge_lo) } else { edge_hi.lt(ou) };
            let ahead = L::or(L::and(still, L::not(passed)), L::and(L::not(still), ta.le(t1)));
            let pending = L::and(L::and(L::lt(ninf, limit), L::not(done)), ahead);
            if !L::any(pending) {
                break;
            }
            let live = L::and(pending, ta.le(tb));
            if !L::any(live) {
                continue;
            }
            let (va, vb) = (ov + ta * dv, ov + tb * dv);
            let vlo = ((va.min(vb) - pad) * nv_l).max(zero).min(top_row);
            let vhi = ((va.max(vb) + pad) * nv_l).max(zero).min(top_row);
            let (ya, yb) = (o.y + ta * d.y, o.y + tb * d.y);
            let (y_lo, y_hi) = (ya.min(yb) - pad, ya.max(yb) + pad);
            // The rows and heights any live lane reaches: cells outside them are passed over
            // before any lane-wise test.
            let lo_row = least(L::select(live, vlo, inf));
            let hi_row = -least(-L::select(live, vhi, ninf));
            let lowest = least(L::select(live, y_lo, inf));
            let highest = -least(-L::select(live, y_hi, ninf));
            for r in index(lo_row, cv)..=index(hi_row, cv) {
                let (i, k) = if x_major { (c, r) } else { (r, c) };
                let cell = &self.cells[k * self.nx + i];
                if cell.hi < lowest || cell.lo > highest {
                    continue;
                }
                let rf = r as f32;
                let rows = L::and(vlo.lt(L::splat(rf + 1.0)), L::splat(rf).le(vhi));
                let heights = L::and(y_lo.le(L::splat(cell.hi)), L::splat(cell.lo).le(y_hi));
                let take = L::and(live, L::and(rows, heights));
                if !L::any(take) {
                    continue;
                }
                for f in cell.faces {
                    if f == NONE {
                        continue;
                    }
                    // As `MeshData::walk_lanes`: up to a lane's best distance itself, where a
                    // face of lower index wins a tie.
                    let found = best.lt(L::splat(MISS));
                    let reach = if FIRST { limit } else { L::select(found, limit.map(f32::next_up), limit) };
                    let reach = L::select(take, reach, ninf);
                    let t = triangles[f as usize].hit(ray, t_min, reach);
                    let lower = L::mask_from_fn(|i| f < faces[i]);
                    let mut hit = L::and(t.lt(reach), L::or(t.lt(limit), lower));
                    if self.floor != f32::NEG_INFINITY {
                        hit = L::and(hit, L::splat(self.floor).le(o.y + t * d.y));
                    }
                    if !L::any(hit) {
                        continue;
                    }
                    best = L::select(hit, t, best);
                    for (i, face) in faces.iter_mut().enumerate().take(L::WIDTH) {
                        if L::mask_lane(hit, i) {
                            *face = f;
                        }
                    }
                    limit = L::select(hit, if FIRST { ninf } else { t }, limit);
                }
            }
        }
        Some((best, faces))
    }

    /// The walk behind `nearest` and `first`.
    #[inline(never)]
    fn walk<const FIRST: bool>(&self, triangles: &[Triangle], ray: &Ray, t_min: f32, t_max: f32) -> Option<(f32, u32)> {
        let (o, d) = (ray.origin, ray.dir);
        if !(t_min < t_max && o.is_finite() && d.is_finite()) || d == Vec3::ZERO {
            return None;
        }
        let pad = PAD * (1.0 + o.abs().max_element());
        // The part of the ray inside the (widened) box.
        let lo = Vec3::new(-pad, self.lo - pad, -pad);
        let hi = Vec3::new(1.0 + pad, self.hi + pad, 1.0 + pad);
        let (mut t0, mut t1) = (t_min, t_max);
        for a in 0..3 {
            if d[a] == 0.0 {
                if !(o[a] >= lo[a] && o[a] <= hi[a]) {
                    return None;
                }
                continue;
            }
            let (ta, tb) = ((lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]);
            t0 = t0.max(ta.min(tb));
            t1 = t1.min(ta.max(tb));
        }
        if !(t0 <= t1) {
            return None;
        }
        // Columns along the axis the ray crosses more cells of (u), rows across it (v).
        let (nx, nz) = (self.nx as f32, self.nz as f32);
        let x_major = (d.x * nx).abs() >= (d.z * nz).abs();
        let (ou, du, nu, cu, ov, dv, nv, cv) = if x_major {
            (o.x, d.x, nx, self.nx, o.z, d.z, nz, self.nz)
        } else {
            (o.z, d.z, nz, self.nz, o.x, d.x, nx, self.nx)
        };
        let index = |v: f32, n: usize| (v.max(0.0) as usize).min(n - 1);
        let (ua, ub) = ((ou + t0 * du) * nu, (ou + t1 * du) * nu);
        let (first_col, last_col) = (index(ua.min(ub) - pad * nu, cu), index(ua.max(ub) + pad * nu, cu));
        let columns = last_col - first_col + 1;
        let lanes = ray.lanes();
        let mut best: Option<(f32, u32)> = None;
        for n in 0..columns {
            let c = if du >= 0.0 { first_col + n } else { last_col - n };
            // The ray's stretch over the widened column.
            let (ta, tb) = if du == 0.0 {
                (t0, t1)
            } else {
                let (ea, eb) = ((c as f32 / nu - pad - ou) / du, ((c + 1) as f32 / nu + pad - ou) / du);
                (t0.max(ea.min(eb)), t1.min(ea.max(eb)))
            };
            if let Some((b, _)) = best {
                // Columns come in order along the ray: none further on holds a nearer hit (or
                // an equal one, which a lower face could win).
                if ta > b {
                    break;
                }
            }
            if !(ta <= tb) {
                continue;
            }
            let (va, vb) = (ov + ta * dv, ov + tb * dv);
            let (first_row, last_row) = (index((va.min(vb) - pad) * nv, cv), index((va.max(vb) + pad) * nv, cv));
            let (ya, yb) = (o.y + ta * d.y, o.y + tb * d.y);
            let (y_lo, y_hi) = (ya.min(yb) - pad, ya.max(yb) + pad);
            for r in first_row..=last_row {
                let (i, k) = if x_major { (c, r) } else { (r, c) };
                let cell = &self.cells[k * self.nx + i];
                if cell.hi < y_lo || cell.lo > y_hi {
                    continue;
                }
                for f in cell.faces {
                    if f == NONE {
                        continue;
                    }
                    if FIRST {
                        let t = triangles[f as usize].hit(&lanes, t_min, t_max);
                        if t != MISS && self.above_floor(ray, t) {
                            return Some((t, f));
                        }
                        continue;
                    }
                    // As `MeshData::nearest`: up to the best distance itself, where a face of
                    // lower index wins a tie.
                    let reach = best.map_or(t_max, |(b, _)| b.next_up());
                    let t = triangles[f as usize].hit(&lanes, t_min, reach);
                    let wins = t != MISS && best.is_none_or(|(b, g)| t < b || f < g);
                    if wins && self.above_floor(ray, t) {
                        best = Some((t, f));
                    }
                }
            }
        }
        best
    }

    /// Whether the hit at `t` on `ray` lies above the floor.

    #[inline(always)]
    fn above_floor(&self, ray: &Ray, t: f32) -> bool {
        self.floor == f32::NEG_INFINITY || ray.origin.y + t * ray.dir.y >= self.floor
    }
}

/// The least lane of `v` (none NaN), without branches: halves compared pairwise, so eight
/// lanes take three dependent steps, not seven (a walk asks four of these per column; as a
/// chain they were a twelfth of scenes/kernels/height_field.pov's frame). The least is the
/// least in any order (an equal −0 and +0 give the same cell and compare alike).
#[inline(always)]
fn least<L: Lane>(v: L) -> f32 {
    let pick = |x: f32, y: f32| if y < x { y } else { x };
    let mut a = [f32::INFINITY; 8];
    for (i, slot) in a.iter_mut().enumerate().take(L::WIDTH) {
        *slot = v.get(i);
    }
    let b = [pick(a[0], a[4]), pick(a[1], a[5]), pick(a[2], a[6]), pick(a[3], a[7])];
    pick(pick(b[0], b[2]), pick(b[1], b[3]))
}

#[cfg(test)]
mod tests {
    use crate::geometry::height_field::{faces, HeightGrid};
    use crate::geometry::mesh::MeshData;
    use crate::geometry::Shape;
    use crate::lanes::{Lane, F8, V3};
    use crate::ray::{Ray, RayLanes, MISS};
    use glam::Vec3;

    /// A seeded xorshift in [0, 1).
    fn rng(mut seed: u64) -> impl FnMut() -> f32 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    /// The same random field as a plain mesh (its BVH) and as a height field (the cell walk).
    fn meshes(w: usize, h: usize, water: f32, rand: &mut impl FnMut() -> f32) -> (MeshData, MeshData) {
        // Some heights repeated exactly, for flat cells and rays along them.
        let heights: Vec<f32> = (0..w * h).map(|_| if rand() < 0.2 { 0.5 } else { rand() }).collect();
        let floor = if water > 0.0 { water } else { f32::NEG_INFINITY };
        let mesh = |grid: bool| {
            let m = MeshData::new(faces(w, h, &heights, false, water));
            let m = if grid { m.with_grid(HeightGrid::new(w, h, &heights, floor)) } else { m };
            if water > 0.0 {
                m.with_floor(water)
            } else {
                m
            }
        };
        (mesh(false), mesh(true))
    }

    /// Rays of every kind: from all around the field towards points on or near it, along the
    /// grid's lines and diagonals (grazing edges), level at a sample's height, straight down.
    fn ray(rand: &mut impl FnMut() -> f32, w: usize, h: usize) -> Ray {
        let target = Vec3::new(rand() * 1.2 - 0.1, rand() * 1.1 - 0.05, rand() * 1.2 - 0.1);
        let snap = |v: f32, n: usize| (v * (n - 1) as f32).round() / (n - 1) as f32;
        let origin = Vec3::new(rand() * 6.0 - 3.0, rand() * 6.0 - 3.0, rand() * 6.0 - 3.0);
        match (rand() * 6.0) as u32 {
            0 => Ray::new(origin, target - origin),
            // Along a grid line in x or z, through its vertices' plane.
            1 => {
                let z = snap(target.z, h);
                Ray::new(Vec3::new(-2.0, target.y + 0.3, z), Vec3::new(1.0, -0.15 * rand(), 0.0))
            }
            2 => {
                let x = snap(target.x, w);
                Ray::new(Vec3::new(x, target.y + 0.3, 2.0), Vec3::new(0.0, -0.15 * rand(), -1.0))
            }
            // Along a cell diagonal (x + z constant), the split every square shares.
            3 => {
                let (x, z) = (snap(target.x, w), snap(target.z, h));
                let d = Vec3::new(1.0 / (w - 1) as f32, -0.01, -1.0 / (h - 1) as f32);
                Ray::new(Vec3::new(x, target.y, z) - d * 20.0, d)
            }
            // Level, and straight down onto a vertex.
            4 => Ray::new(Vec3::new(-1.0, 0.5, target.z), Vec3::new(1.0, 0.0, rand() - 0.5)),
            _ => Ray::new(Vec3::new(snap(target.x, w), 3.0, snap(target.z, h)), Vec3::new(0.0, -1.0, 0.0)),
        }
    }

    /// The walk's hit `got` is the BVH's `want`: the same `t` to the bit and the same face, but
    /// where the BVH passed over a face that its slabs rounded away (a level ray along a flat
    /// cell, a vertex two faces meet at the same `t`): then the walk's face, tested alone, hits
    /// at its `t`, no further than the BVH's, and wins a tie by its lower index. Returns
    /// whether they differ.
    fn same(grid: &MeshData, r: &Ray, t_max: f32, want: Option<(f32, u32)>, got: Option<(f32, u32)>) -> bool {
        if want == got {
            return false;
        }
        let (t, g) = got.unwrap_or_else(|| panic!("{r:?}: the BVH's {want:?}, the walk none"));
        assert_eq!(grid.triangles[g as usize].hit(&r.lanes(), 0.0, t_max), t, "{r:?}: {want:?} {got:?}");
        if let Some((tw, w)) = want {
            assert!(t < tw || (t == tw && g < w), "{r:?}: {want:?} {got:?}");
        }
        true
    }

    /// The walk finds the BVH's nearest hit and face bit for bit, one lane and eight; shadow
    /// walks find a hit exactly where there is one, and one within the interval.
    #[test]
    fn walk_finds_the_bvh_hit_packet_and_single() {
        let mut rand = rng(0x9e37_79b9_7f4a_7c15);
        let (mut hits, mut differ) = (0, 0);
        for (w, h, water) in [(9, 7, 0.0), (17, 23, 0.0), (12, 5, 0.4), (2, 2, 0.0)] {
            let (bvh, grid) = meshes(w, h, water, &mut rand);
            for _ in 0..400 {
                let rays: [Ray; 8] = std::array::from_fn(|_| ray(&mut rand, w, h));
                let t_max = if rand() < 0.3 { rand() * 5.0 } else { f32::INFINITY };
                for r in &rays {
                    let want = bvh.nearest(r, 0.0, t_max);
                    let got = grid.nearest(r, 0.0, t_max);
                    differ += same(&grid, r, t_max, want, got) as u32;
                    assert_eq!(grid.first(r, 0.0, t_max).is_some(), got.is_some(), "{r:?}");
                    hits += want.is_some() as u32;
                }
                let packet = RayLanes::<F8>::new(V3::from_lanes(|i| rays[i].origin), V3::from_lanes(|i| rays[i].dir));
                let (t8, f8) = grid.nearest_faces_lanes(&packet, F8::splat(0.0), F8::splat(t_max));
                let first8 = grid.first_lanes(&packet, F8::splat(0.0), F8::splat(t_max));
                for (i, r) in rays.iter().enumerate() {
                    let one = grid.nearest(r, 0.0, t_max);
                    let got = (t8.get(i) != MISS).then(|| (t8.get(i), f8[i]));
                    assert_eq!(
                        got.map(|(t, f)| (t.to_bits(), f)),
                        one.map(|(t, f)| (t.to_bits(), f)),
                        "lane {i}: {r:?}"
                    );
                    let first = first8.get(i);
                    assert_eq!(first != MISS, one.is_some(), "lane {i}: {r:?}");
                    assert!(first == MISS || (first > 0.0 && first < t_max));
                }
            }
        }
        assert!(hits > 2000 && differ * 100 < hits, "{hits} hits, {differ} not the BVH's");
    }
}
