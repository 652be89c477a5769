//! Scene queries: the nearest hit (`intersect`) and yes/no occlusion (`occluded`), over the
//! accelerator for bounded shapes plus loops over the unbounded planes and the unbounded
//! primitives (`Scene::unbounded`, see `scene::build`).

use glam::Vec3;

use crate::geometry::Shape;
use crate::lanes::{Lane, F8, M8, V3};
use crate::ray::{Ray, RayLanes, MISS};
use crate::render::stats::RenderStats;
use crate::scene::build::{PrimRef, Scene, ShapeKind};

/// How far (relative to `t`) an f64 root may lie from the f32 one and still be the same hit:
/// f32's formulas are good to a few ulps (1e-7), so 1e-4 only rejects a different root.
const REFINE_WINDOW: f64 = 1e-4;

/// What a ray hit: a bounded primitive (index into `Scene::prims`) or a plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HitShape {
    Prim(u32),
    Plane(u32),
    /// A hit on a mesh or height field (`prim`) resolved to its face (`Scene::resolve`), whose
    /// normal shades it; or on a prism, with the side or cap it crossed (`Prism::hit_faces`),
    /// whose normal needs no search then.
    Face {
        prim: u32,
        face: u32,
    },
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub t: f32,
    pub shape: HitShape,
}

impl Scene {
    /// Primitive `p`'s nearest hit in `(0, t_max)` for one ray (f32 or f64) or eight: the one
    /// dispatch every path shares, so each shape's formula is written once (`geometry::Shape`).
    #[inline(always)]
    pub fn hit_prim<L: Lane>(&self, p: &PrimRef, ray: &RayLanes<L>, t_max: L) -> L {
        self.hit_prim_in(p, ray, L::splat(0.0), t_max)
    }

    /// `hit_prim`, with what `resolve` would make of each lane's hit, found in the same search:
    /// per lane the CSG leaf where `p` is a CSG node, and the face where it is a mesh, height
    /// field or prism (`u32::MAX` elsewhere). A leaf that is itself a mesh still needs `resolve`
    /// for its face; a leaf that is a prism is shaded without one (`Prism::normal_on`).
    #[inline(always)]
    pub fn hit_prim_resolved<L: Lane>(&self, p: &PrimRef, ray: &RayLanes<L>, t_max: L) -> (L, [u32; 8], [u32; 8]) {
        let none = [u32::MAX; 8];
        match p.kind {
            ShapeKind::Mesh | ShapeKind::HeightField => {
                let (t, faces) = self.meshes[p.index as usize].hit_faces(ray, L::splat(0.0), t_max);
                (t, none, faces)
            }
            ShapeKind::Prism => {
                let (t, faces) = self.prisms[p.index as usize].hit_faces(ray, L::splat(0.0), t_max);
                (t, none, faces)
            }
            ShapeKind::Csg => {
                let (t, leaf) = self.hit_csg(p.index, ray, L::splat(0.0), t_max);
                let leaves =
                    std::array::from_fn(
                        |i| if i < L::WIDTH && t.get(i) != MISS { leaf.get(i) as u32 } else { u32::MAX },
                    );
                (t, leaves, none)
            }
            _ => (self.hit_prim(p, ray, t_max), none, none),
        }
    }

    /// For shadow rays: a hit on `p` below `t_max` where there is one, `MISS` elsewhere, not
    /// necessarily the nearest. Meshes stop at the first face found, the kinds with a
    /// `Shape::blocks` of their own answer that; every other kind answers `hit_prim`.
    #[inline(always)]
    pub fn blocks_prim<L: Lane>(&self, p: &PrimRef, ray: &RayLanes<L>, t_max: L) -> L {
        match p.kind {
            ShapeKind::Mesh | ShapeKind::HeightField => {
                self.meshes[p.index as usize].first_hit(ray, L::splat(0.0), t_max)
            }
            ShapeKind::Julia => self.julias[p.index as usize].blocks(ray, L::splat(0.0), t_max),
            ShapeKind::Isosurface => self.isosurfaces[p.index as usize].blocks(ray, L::splat(0.0), t_max),
            ShapeKind::Lathe => self.lathes[p.index as usize].blocks(ray, L::splat(0.0), t_max),
            ShapeKind::Sor => self.sors[p.index as usize].blocks(ray, L::splat(0.0), t_max),
            ShapeKind::Blob => self.blobs[p.index as usize].blocks(ray, L::splat(0.0), t_max),
            _ => self.hit_prim(p, ray, t_max),
        }
    }

    /// `hit_prim` in `(t_min, t_max)`. A CSG node answers its nearest surface; which leaf
    /// that is, `resolve` finds afterwards.
    #[inline(always)]
    pub fn hit_prim_in<L: Lane>(&self, p: &PrimRef, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let i = p.index as usize;
        match p.kind {
            ShapeKind::Sphere => self.spheres[i].hit(ray, t_min, t_max),
            ShapeKind::Ellipsoid => self.ellipsoids[i].hit(ray, t_min, t_max),
            ShapeKind::Box => self.boxes[i].hit(ray, t_min, t_max),
            ShapeKind::Triangle => self.triangles[i].hit(ray, t_min, t_max),
            ShapeKind::SmoothTriangle => self.smooth_triangles[i].hit(ray, t_min, t_max),
            ShapeKind::Polygon => self.polygons[i].hit(ray, t_min, t_max),
            ShapeKind::Cone => self.cones[i].hit(ray, t_min, t_max),
            ShapeKind::Disc => self.discs[i].hit(ray, t_min, t_max),
            ShapeKind::Torus => self.tori[i].hit(ray, t_min, t_max),
            ShapeKind::Poly => self.polys[i].hit(ray, t_min, t_max),
            ShapeKind::Superellipsoid => self.superellipsoids[i].hit(ray, t_min, t_max),
            ShapeKind::Prism => self.prisms[i].hit(ray, t_min, t_max),
            ShapeKind::Lathe => self.lathes[i].hit(ray, t_min, t_max),
            ShapeKind::Sor => self.sors[i].hit(ray, t_min, t_max),
            ShapeKind::Blob => self.blobs[i].hit(ray, t_min, t_max),
            ShapeKind::Julia => self.julias[i].hit(ray, t_min, t_max),
            ShapeKind::Mesh | ShapeKind::HeightField => self.meshes[i].hit(ray, t_min, t_max),
            ShapeKind::Isosurface => self.isosurfaces[i].hit(ray, t_min, t_max),
            ShapeKind::Parametric => self.parametrics[i].hit(ray, t_min, t_max),
            // Only CSG leaves are planes among the primitives.
            ShapeKind::Plane => self.half_spaces[i].hit(ray, t_min, t_max),
            ShapeKind::Csg => self.hit_csg(p.index, ray, t_min, t_max).0,
        }
    }

    /// Which points lie inside primitive `p`'s solid (not counting its `flip`).
    #[inline(always)]
    pub fn inside_prim<L: Lane>(&self, p: &PrimRef, q: V3<L>) -> L::Mask {
        let i = p.index as usize;
        match p.kind {
            ShapeKind::Sphere => self.spheres[i].inside(q),
            ShapeKind::Ellipsoid => self.ellipsoids[i].inside(q),
            ShapeKind::Box => self.boxes[i].inside(q),
            ShapeKind::Triangle => self.triangles[i].inside(q),
            ShapeKind::SmoothTriangle => self.smooth_triangles[i].inside(q),
            ShapeKind::Polygon => self.polygons[i].inside(q),
            ShapeKind::Cone => self.cones[i].inside(q),
            ShapeKind::Disc => self.discs[i].inside(q),
            ShapeKind::Torus => self.tori[i].inside(q),
            ShapeKind::Poly => self.polys[i].inside(q),
            ShapeKind::Superellipsoid => self.superellipsoids[i].inside(q),
            ShapeKind::Prism => self.prisms[i].inside(q),
            ShapeKind::Lathe => self.lathes[i].inside(q),
            ShapeKind::Sor => self.sors[i].inside(q),
            ShapeKind::Blob => self.blobs[i].inside(q),
            ShapeKind::Julia => self.julias[i].inside(q),
            ShapeKind::Mesh | ShapeKind::HeightField => self.meshes[i].inside(q),
            ShapeKind::Isosurface => self.isosurfaces[i].inside(q),
            ShapeKind::Parametric => self.parametrics[i].inside(q),
            ShapeKind::Plane => self.half_spaces[i].inside(q),
            ShapeKind::Csg => self.inside_node(p.index, q),
        }
    }

    /// One primitive test, counted for the statistics.
    #[inline]
    pub fn test_prim(&self, p: &PrimRef, ray: &Ray, t_max: f32, stats: &mut RenderStats) -> Option<f32> {
        let t = self.hit_prim(p, &ray.lanes(), t_max);
        let t = (t != MISS).then_some(t);
        stats.count_test(p.kind, t.is_some());
        t
    }

    /// `test_prim`, with the face of a hit on a prism as packets learn it (`hit_prim_resolved`;
    /// `u32::MAX` for other kinds, whose faces `resolve` finds).
    #[inline]
    fn test_prim_face(&self, p: &PrimRef, ray: &Ray, t_max: f32, stats: &mut RenderStats) -> Option<(f32, u32)> {
        if p.kind != ShapeKind::Prism {
            return self.test_prim(p, ray, t_max, stats).map(|t| (t, u32::MAX));
        }
        let (t, faces) = self.prisms[p.index as usize].hit_faces(&ray.lanes(), 0.0, t_max);
        stats.count_test(p.kind, t != MISS);
        (t != MISS).then_some((t, faces[0]))
    }

    /// `blocks_prim` for one ray, counted in `stats`.
    fn test_blocks(&self, p: &PrimRef, ray: &Ray, t_max: f32, stats: &mut RenderStats) -> bool {
        let hit = self.blocks_prim(p, &ray.lanes(), t_max) != MISS;
        stats.count_test(p.kind, hit);
        hit
    }

    /// The nearest hit with `0 < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_max: f32, stats: &mut RenderStats) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        // The face of a hit on a prism (`test_prim_face`), kept apart so that ties still
        // compare primitives.
        let mut face = u32::MAX;
        let mut t_best = t_max;
        for (i, plane) in self.planes.iter().enumerate() {
            let t = plane.intersect(ray, 0.0, t_best);
            stats.count_test(ShapeKind::Plane, t.is_some());
            if let Some(t) = t {
                t_best = t;
                best = Some(Hit { t, shape: HitShape::Plane(i as u32) });
            }
        }
        // Unbounded primitives, nearest strictly first (open interval), so ties keep the plane.
        for prim in self.unbounded.clone() {
            if let Some((t, f)) = self.test_prim_face(&self.prims[prim as usize], ray, t_best, stats) {
                t_best = t;
                best = Some(Hit { t, shape: HitShape::Prim(prim) });
                face = f;
            }
        }
        stats.nodes_visited += self.accel.traverse(ray, t_best, |prim, t_max| {
            let (t, f) = self.test_prim_face(&self.prims[prim as usize], ray, t_max, stats)?;
            // Ties go to the lower index so every accelerator picks the same primitive.
            if best.is_none_or(|b| t < b.t || (t == b.t && b.shape > HitShape::Prim(prim))) {
                best = Some(Hit { t, shape: HitShape::Prim(prim) });
                face = f;
            }
            Some(t)
        }) as u64;
        best.map(|hit| match hit.shape {
            HitShape::Prim(prim) if face != u32::MAX => Hit { t: hit.t, shape: HitShape::Face { prim, face } },
            _ => self.resolve(ray, hit),
        })
    }

    /// Whether `resolve` can change a hit on primitive `prim`: a CSG node or a mesh (a hit on a
    /// mesh names its face).
    #[inline(always)]
    pub fn resolves(&self, prim: u32) -> bool {
        matches!(self.prims[prim as usize].kind, ShapeKind::Csg | ShapeKind::Mesh | ShapeKind::HeightField)
    }

    /// A hit on a CSG node as the hit on its leaf (whose normal and material shade it), and a
    /// hit on a mesh as the hit on its face.
    #[inline]
    pub fn resolve(&self, ray: &Ray, hit: Hit) -> Hit {
        let hit = match hit.shape {
            HitShape::Prim(i) if self.prims[i as usize].kind == ShapeKind::Csg => {
                let (t, leaf) = self.hit_csg(self.prims[i as usize].index, &ray.lanes(), 0.0, f32::INFINITY);
                debug_assert_eq!(t, hit.t, "the node's nearest surface, found again");
                Hit { t: hit.t, shape: HitShape::Prim(leaf as u32) }
            }
            _ => hit,
        };
        match hit.shape {
            HitShape::Prim(i) if matches!(self.prims[i as usize].kind, ShapeKind::Mesh | ShapeKind::HeightField) => {
                // The face at exactly this `t`: the mesh searched again in (t⁻, t⁺), which its
                // BVH culls to the few boxes around the hit.
                let mesh = &self.meshes[self.prims[i as usize].index as usize];
                let found = mesh.hit_face(&ray.lanes(), hit.t.next_down(), hit.t.next_up());
                debug_assert!(found.is_some_and(|(t, _)| t == hit.t), "the mesh's hit, found again");
                Hit { t: hit.t, shape: HitShape::Face { prim: i, face: found.map_or(0, |(_, f)| f) } }
            }
            _ => hit,
        }
    }

    /// `hit` re-solved in f64 (`Precision::F64`): the same shape's formula on `ray` widened
    /// exactly, so `t` carries one rounding (to f32) instead of the formula's. The f32 `t` stays
    /// where f64 finds no root near it (a ray grazing an edge, which f32 rounded onto the shape).
    pub fn refine(&self, ray: &Ray, hit: Hit) -> Hit {
        let r = ray.lanes_f64();
        let t32 = hit.t as f64;
        let t = match hit.shape {
            HitShape::Plane(i) => self.planes[i as usize].hit(&r, 0.0, f64::INFINITY),
            HitShape::Face { prim, face } => {
                let p = &self.prims[prim as usize];
                match p.kind {
                    // A prism's face names no part of its solve: the whole prism again.
                    ShapeKind::Prism => self.hit_prim(p, &r, f64::INFINITY),
                    _ => self.meshes[p.index as usize].refine_face(face, &r),
                }
            }
            // A CSG leaf's nearest root may lie outside the node: look only near the hit.
            HitShape::Prim(i) if i >= self.first_leaf => {
                self.hit_prim_in(&self.prims[i as usize], &r, t32 * (1.0 - REFINE_WINDOW), f64::INFINITY)
            }
            HitShape::Prim(i) => self.hit_prim(&self.prims[i as usize], &r, f64::INFINITY),
        };
        if (t - t32).abs() <= REFINE_WINDOW * t32 {
            Hit { t: t as f32, ..hit }
        } else {
            hit
        }
    }

    /// Whether anything lies on `ray` with `0 < t < t_max` (pbrt's `IntersectP`): stops at the
    /// first hit found, in any order.
    pub fn occluded(&self, ray: &Ray, t_max: f32, stats: &mut RenderStats) -> bool {
        for (plane, &casts) in self.planes.iter().zip(&self.plane_casts_shadow) {
            if !casts {
                continue;
            }
            let hit = plane.intersect(ray, 0.0, t_max).is_some();
            stats.count_test(ShapeKind::Plane, hit);
            if hit {
                return true;
            }
        }
        self.bounded_occluded(ray, t_max, stats)
    }

    /// Whether the shadow ray from `ray.origin` towards the point light at `light` is blocked.
    ///
    /// Planes are tested by side, not by intersection: a plane blocks the segment exactly when
    /// its two ends lie strictly on opposite sides. A plane through the light (a light lying on
    /// the floor) then never shadows it, however shallow the ray, where an intersection `t`
    /// near `t_max` carries an error growing as 1/(n·d) that no fixed slack covers.
    pub fn occluded_towards(&self, ray: &Ray, t_max: f32, light: Vec3, stats: &mut RenderStats) -> bool {
        for (plane, &casts) in self.planes.iter().zip(&self.plane_casts_shadow) {
            if !casts {
                continue;
            }
            let hit = plane.separates(ray.origin, light);
            stats.count_test(ShapeKind::Plane, hit);
            if hit {
                return true;
            }
        }
        self.bounded_occluded(ray, t_max, stats)
    }

    /// The unbounded primitives, then the accelerator's.
    fn bounded_occluded(&self, ray: &Ray, t_max: f32, stats: &mut RenderStats) -> bool {
        for prim in self.unbounded.clone() {
            let p = &self.prims[prim as usize];
            if p.casts_shadow && self.test_blocks(p, ray, t_max, stats) {
                return true;
            }
        }
        let mut blocked = false;
        stats.nodes_visited += self.accel.traverse(ray, t_max, |prim, t_max| {
            let p = &self.prims[prim as usize];
            if blocked || !p.casts_shadow || !self.test_blocks(p, ray, t_max, stats) {
                return None;
            }
            blocked = true;
            // No node or cell accepts a limit of -inf: the walk ends.
            Some(f32::NEG_INFINITY)
        }) as u64;
        blocked
    }

    /// Geometric outward normal at a hit point.
    pub fn normal_at(&self, shape: HitShape, p: Vec3) -> Vec3 {
        self.normal_lanes(shape, V3::from_vec3(p)).vec3()
    }

    /// Whether `shape`'s normals are worked out point by point (`ShapeKind::normal_per_lane`),
    /// so that a packet should ask `normal_at` for its own lanes rather than `normal_lanes` for
    /// all eight. The bits are the same either way.
    #[inline]
    pub fn normal_per_lane(&self, shape: HitShape) -> bool {
        match shape {
            HitShape::Prim(i) => {
                let p = &self.prims[i as usize];
                p.kind.normal_per_lane()
                    && (p.kind != ShapeKind::Poly || self.polys[p.index as usize].normal_per_lane())
            }
            HitShape::Face { prim, .. } => self.prims[prim as usize].kind == ShapeKind::Prism,
            HitShape::Plane(_) => false,
        }
    }

    /// Whether `normal_faces` takes hits on primitive `prim` (a mesh or height field; a prism's
    /// faces, its sides and caps, are asked one by one).
    #[inline(always)]
    pub fn gathers_face_normals(&self, prim: u32) -> bool {
        matches!(self.prims[prim as usize].kind, ShapeKind::Mesh | ShapeKind::HeightField)
    }

    /// `normal_lanes` for eight points on mesh primitive `prim`, each on its own face
    /// (`faces[i]`, for the lanes of `lanes`; `lead` is one of those lanes): the same bits as
    /// asking face by face.
    #[inline(always)]
    pub fn normal_faces(&self, prim: u32, faces: &[u32; 8], lanes: M8, lead: usize, p: V3<F8>) -> V3<F8> {
        let r = &self.prims[prim as usize];
        as_placed(r, self.meshes[r.index as usize].normal_faces(faces, lanes, faces[lead], p))
    }

    /// `normal_at` for one or eight points on the same shape.
    #[inline(always)]
    pub fn normal_lanes<L: Lane>(&self, shape: HitShape, p: V3<L>) -> V3<L> {
        match shape {
            HitShape::Plane(i) => V3::splat(self.planes[i as usize].normal),
            HitShape::Face { prim, face } => {
                let r = &self.prims[prim as usize];
                let n = match r.kind {
                    ShapeKind::Prism => self.prisms[r.index as usize].normal_on(face, p),
                    _ => self.meshes[r.index as usize].normal(face, p),
                };
                as_placed(r, n)
            }
            HitShape::Prim(i) => {
                let r = &self.prims[i as usize];
                let k = r.index as usize;
                let n = match r.kind {
                    ShapeKind::Sphere => self.spheres[k].normal(p),
                    ShapeKind::Ellipsoid => self.ellipsoids[k].normal(p),
                    ShapeKind::Box => self.boxes[k].normal(p),
                    ShapeKind::Triangle => self.triangles[k].normal(p),
                    ShapeKind::SmoothTriangle => self.smooth_triangles[k].normal(p),
                    ShapeKind::Polygon => self.polygons[k].normal(p),
                    ShapeKind::Cone => self.cones[k].normal(p),
                    ShapeKind::Disc => self.discs[k].normal(p),
                    ShapeKind::Torus => self.tori[k].normal(p),
                    ShapeKind::Poly => self.polys[k].normal(p),
                    ShapeKind::Superellipsoid => self.superellipsoids[k].normal(p),
                    ShapeKind::Prism => self.prisms[k].normal(p),
                    ShapeKind::Lathe => self.lathes[k].normal(p),
                    ShapeKind::Sor => self.sors[k].normal(p),
                    ShapeKind::Blob => self.blobs[k].normal(p),
                    ShapeKind::Julia => self.julias[k].normal(p),
                    ShapeKind::Isosurface => self.isosurfaces[k].normal(p),
                    ShapeKind::Parametric => self.parametrics[k].normal(p),
                    ShapeKind::Plane => self.half_spaces[k].normal(p),
                    // Hits are resolved to faces before anything asks for a normal.
                    ShapeKind::Mesh | ShapeKind::HeightField => self.meshes[k].normal(0, p),
                    // Hits are resolved to leaves before anything asks for a normal.
                    ShapeKind::Csg => V3::splat(Vec3::Y),
                };
                as_placed(r, n)
            }
        }
    }

    pub fn casts_shadow(&self, shape: HitShape) -> bool {
        match shape {
            HitShape::Plane(i) => self.plane_casts_shadow[i as usize],
            HitShape::Prim(i) | HitShape::Face { prim: i, .. } => self.prims[i as usize].casts_shadow,
        }
    }

    pub fn material_of(&self, shape: HitShape) -> u32 {
        match shape {
            HitShape::Plane(i) => self.plane_materials[i as usize],
            HitShape::Prim(i) | HitShape::Face { prim: i, .. } => self.prims[i as usize].material,
        }
    }
}

impl PartialOrd for HitShape {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        let key = |s: &HitShape| match s {
            HitShape::Plane(i) => (0, *i, 0),
            HitShape::Prim(i) => (1, *i, 0),
            HitShape::Face { prim, face } => (2, *prim, *face),
        };
        key(self).partial_cmp(&key(other))
    }
}

/// A shape's own normal `n` as primitive `r` shows it: turned in where `r` is flipped.
#[inline(always)]
fn as_placed<L: Lane>(r: &PrimRef, n: V3<L>) -> V3<L> {
    if r.flip {
        n.neg()
    } else {
        n
    }
}
