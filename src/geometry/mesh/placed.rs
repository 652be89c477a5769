//! A placed mesh (`Mesh`): the shared triangles (`MeshData`) under one object's transform. Rays
//! are carried into object space once per lane (or per row of a packet) and the face found is
//! kept, so its normal is worked out only for the winning hit.

use super::*;

/// One placed mesh: shared triangles under an object transform.
#[derive(Clone, Debug)]
pub struct Mesh {
    pub data: Arc<MeshData>,
    pub(super) frame: BoxFrame,
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
        self.unit_in_render(n)
    }

    /// An object-space normal carried to render space, unit length (`Vec3::Y` if it vanishes).
    #[inline(always)]
    fn unit_in_render<L: Lane>(&self, n: V3<L>) -> V3<L> {
        n.mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }

    /// `normal` at eight render-space points, each on its own face (`faces[i]`; lanes outside
    /// `lanes` take face `fill`, any face of the mesh, the caller's first lane's): the faces' corners and
    /// vertex normals gathered into lanes, then the same operations as `normal` lane by lane,
    /// so the same bits. A row of a packet over a mesh hits a different face in almost every
    /// lane, and asking lane by lane was a fifteenth of a smooth mesh's frame.
    #[inline(always)]
    pub fn normal_faces(&self, faces: &[u32; 8], lanes: M8, fill: u32, p: V3<F8>) -> V3<F8> {
        let zero = V3::splat(Vec3::ZERO);
        let (mut corners, mut geometric) = (TriangleLanes { v0: zero, e1: zero, e2: zero }, zero);
        let mut normals = [zero; 3];
        let mut smooth = M8::default();
        for i in 0..8 {
            let f = if lanes.lane(i) { faces[i] } else { fill } as usize;
            let tri = &self.data.triangles[f];
            corners.v0.set_lane(i, tri.v0);
            corners.e1.set_lane(i, tri.e1);
            corners.e2.set_lane(i, tri.e2);
            geometric.set_lane(i, tri.normal);
            let k = self.data.smooth_of[f];
            let vertex = if k == FLAT { [tri.normal; 3] } else { self.data.smooth[k as usize] };
            for (n, v) in normals.iter_mut().zip(vertex) {
                n.set_lane(i, v);
            }
            smooth.0[i] = -((k != FLAT) as i32);
        }
        let n = if smooth.any() {
            let q = p.transform_point(&self.frame.object_from_render);
            V3::select(smooth, corners.interpolate(geometric, &normals, q), geometric)
        } else {
            geometric
        };
        self.unit_in_render(n)
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
