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

mod lanes;
use lanes::LaneNode;

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
        let n = match self.data.smooth_of[face as usize] {
            FLAT => V3::splat(tri.normal),
            k => tri.interpolate(&self.data.smooth[k as usize], p.transform_point(&self.frame.object_from_render)),
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

    /// Coincident faces (each face twice, the copy wound the other way, as on
    /// objects/chesmsh.pov's knight): every path names the same face, the lowest index at the
    /// nearest distance, as brute force does: a packet's walk (`hit_faces` on eight lanes), rows
    /// walked together (`rows`), the single-ray walk (`hit_face`) and `Scene::resolve`'s search
    /// again around the hit. The faces lie in planes z = const, so their boxes are flat in z and
    /// a box's entry distance, rounded, falls on either side of the face's `t` by an ulp: with
    /// boxes culled at the best distance itself, whether the second copy was tested depended on
    /// the order the walk met them (the packet and single-ray walks disagreed).
    #[test]
    fn coincident_faces_resolve_alike_on_every_path() {
        let r = &mut Rng(0xC0FFEE);
        let mut faces = Vec::new();
        for _ in 0..40 {
            let z = (r.f(-4.0, 4.0) * 8.0).round() / 8.0;
            let c = Vec3::new(r.f(-1.0, 1.0), r.f(-1.0, 1.0), z);
            let v = [
                c,
                c + Vec3::new(r.f(0.3, 1.0), r.f(-0.2, 0.2), 0.0),
                c + Vec3::new(r.f(-0.2, 0.2), r.f(0.3, 1.0), 0.0),
            ];
            let n = r.f(0.0, 1.0) < 0.5;
            let smooth = n.then_some([Vec3::Z, Vec3::X + Vec3::Z, Vec3::Y + Vec3::Z]);
            faces.push((v, smooth));
            faces.push(([v[0], v[2], v[1]], smooth.map(|n| [n[0], n[2], n[1]])));
        }
        let surface: Vec<[Vec3; 3]> = faces.iter().map(|f| f.0).collect();
        let xf = Affine3A::from_rotation_x(0.2) * Affine3A::from_translation(Vec3::new(0.1, -0.2, 0.3));
        let m = Mesh::new(Arc::new(MeshData::new(faces)), xf, None);
        let (mut hits, mut lanes) = (0, 0);
        for block in 0..400 {
            let eye = Vec3::new(r.f(-3.0, 3.0), r.f(-3.0, 3.0), if block % 2 == 0 { -9.0 } else { 9.0 });
            let mut rows = [RayLanes::<F8>::new(V3::splat(Vec3::ZERO), V3::splat(Vec3::X)); 8];
            let mut dirs = [[Vec3::X; 8]; 8];
            for k in 0..8 {
                for i in 0..8 {
                    let v = surface[(block * 64 + k * 8 + i) * 7 % surface.len()];
                    let (a, b) = (r.f(0.0, 1.0), r.f(0.0, 1.0));
                    let (a, b) = if a + b > 1.0 { (1.0 - a, 1.0 - b) } else { (a, b) };
                    let target = xf.transform_point3(v[0] + a * (v[1] - v[0]) + b * (v[2] - v[0]));
                    dirs[k][i] = target - eye;
                }
                rows[k] = RayLanes::new(V3::splat(eye), V3::from_lanes(|i| dirs[k][i]));
            }
            let t_max = [F8::splat(MISS); 8];
            let together = m.rows::<false>(&rows, &t_max);
            for k in 0..8 {
                let (t8, faces8) = m.hit_faces(&rows[k], F8::splat(0.0), t_max[k]);
                for i in 0..8 {
                    let what = format!("block {block} row {k} lane {i}");
                    let ray = RayLanes::<f32>::new(V3::from_vec3(eye), V3::from_vec3(dirs[k][i]));
                    let single = m.hit_face(&ray, 0.0, MISS);
                    let lane = (t8.0[i] != MISS).then_some((t8.0[i], faces8[i]));
                    assert_eq!(lane, single, "{what}: packet, single ray");
                    let rows_lane = (together[k].0 .0[i] != MISS).then_some((together[k].0 .0[i], together[k].1[i]));
                    assert_eq!(rows_lane, single, "{what}: rows together, single ray");
                    if let Some((t, _)) = single {
                        assert_eq!(m.hit_face(&ray, t.next_down(), t.next_up()), single, "{what}: found again");
                        assert_eq!(brute_force(&m, eye, dirs[k][i], MISS), single, "{what}: brute force");
                        hits += 1;
                    }
                    lanes += 1;
                }
            }
        }
        assert!(hits > lanes / 2, "{hits} of {lanes}");
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
