//! SceneDesc (f64, world space) → `PreciseScene`: the geometry of a `Scene` in f64, for the
//! precise render path (`render::precise`), relative to the same render origin.
//!
//! It is built from the scene description, not widened from the f32 `Scene`, whose coordinates
//! have already been rounded to f32. Only geometry, lights and the index of refraction are kept
//! here; materials, which shapes cast shadows and the primitive list stay in the `Scene`, whose
//! arrays this one mirrors index for index (primitive `i` of `Scene::prims` is entry
//! `prims[i].index` of the f64 array of its kind). A `Scene` builds it only when asked
//! (`Scene::prepare_precise`), so f32 renders pay nothing for it.

use glam::{DAffine3, DVec3};

use crate::accel::bvh::Bvh;
use crate::accel::precise::BvhD;
use crate::accel::Accel;
use crate::geometry::precise::{CuboidD, EllipsoidD, FrameD, PlaneD, PolygonD, SphereD, TriangleD};
use crate::scene::build::{RenderFrame, RenderShape, Scene, ShapeKind};
use crate::scene::desc::{SceneDesc, ShapeDesc, Transform};

/// How the f64 path finds candidates among the bounded primitives.
pub enum PreciseAccel {
    /// The f32 tree refitted in f64 (for `--accel bvh` and `grid`: the grid has no f64 twin,
    /// so a BVH is built for it from the f32 bounds).
    Bvh(BvhD),
    /// Brute force over `count` primitives (`--accel none`).
    None { count: u32 },
}

pub struct PreciseScene {
    pub spheres: Vec<SphereD>,
    pub ellipsoids: Vec<EllipsoidD>,
    pub boxes: Vec<CuboidD>,
    pub triangles: Vec<TriangleD>,
    pub polygons: Vec<PolygonD>,
    pub planes: Vec<PlaneD>,
    /// Light positions in render space, in the order of `Scene::lights`.
    pub lights: Vec<DVec3>,
    /// `interior { ior }` per material, in the order of `Scene::materials`.
    pub iors: Vec<f64>,
    pub accel: PreciseAccel,
}

impl PreciseScene {
    /// The f64 geometry of `scene`, which must have been built from `desc`.
    ///
    /// # Panics
    /// When `scene` holds a different number of shapes than `desc` describes (a programming
    /// error: the two were built from different descriptions).
    pub fn build(desc: &SceneDesc, scene: &Scene) -> PreciseScene {
        let frame = scene.frame;
        let mut p = PreciseScene {
            spheres: Vec::new(),
            ellipsoids: Vec::new(),
            boxes: Vec::new(),
            triangles: Vec::new(),
            polygons: Vec::new(),
            planes: Vec::new(),
            lights: desc.lights.iter().map(|l| frame.point(l.position)).collect(),
            iors: desc.objects.iter().map(|o| o.interior.ior).collect(),
            accel: PreciseAccel::None { count: 0 },
        };
        for object in &desc.objects {
            p.add_shape(&object.shape, &object.transform, &frame);
        }
        let counts = |s: &Scene| {
            [s.spheres.len(), s.ellipsoids.len(), s.boxes.len(), s.triangles.len(), s.polygons.len(), s.planes.len()]
        };
        let mine =
            [p.spheres.len(), p.ellipsoids.len(), p.boxes.len(), p.triangles.len(), p.polygons.len(), p.planes.len()];
        assert_eq!(mine, counts(scene), "PreciseScene::build: the scene was not built from this description");
        let bounds = p.prim_bounds(scene);
        p.accel = match &scene.accel {
            Accel::Bvh(tree) => PreciseAccel::Bvh(BvhD::refit(tree, &bounds)),
            Accel::Grid(_) => PreciseAccel::Bvh(BvhD::refit(&Bvh::build(&scene.prim_bounds()), &bounds)),
            Accel::None { count } => PreciseAccel::None { count: *count },
        };
        p
    }

    /// `Scene::add_shape`'s placement kept in f64, so the arrays line up with the f32 ones.
    fn add_shape(&mut self, shape: &ShapeDesc, t: &Transform, frame: &RenderFrame) {
        match frame.place(shape, t) {
            RenderShape::Sphere { center, radius } => self.spheres.push(SphereD { center, radius }),
            RenderShape::Ellipsoid { render_from_object, center, radius } => {
                let xf = render_from_object
                    * DAffine3::from_translation(center)
                    * DAffine3::from_scale(DVec3::splat(radius));
                self.ellipsoids.push(EllipsoidD { frame: FrameD::new(xf) });
            }
            RenderShape::Box { min, max, frame } => {
                self.boxes.push(CuboidD { min, max, frame: frame.map(FrameD::new) })
            }
            RenderShape::Triangle([a, b, c]) => self.triangles.push(TriangleD::new(a, b, c)),
            RenderShape::Polygon(points) => self.polygons.push(PolygonD::new(&points)),
            RenderShape::Plane { normal, distance } => self.planes.push(PlaneD { normal, distance }),
        }
    }

    /// f64 bounds of each of `scene.prims`.
    fn prim_bounds(&self, scene: &Scene) -> Vec<(DVec3, DVec3)> {
        scene
            .prims
            .iter()
            .map(|r| {
                let i = r.index as usize;
                match r.kind {
                    ShapeKind::Sphere => self.spheres[i].bounds(),
                    ShapeKind::Ellipsoid => self.ellipsoids[i].bounds(),
                    ShapeKind::Box => self.boxes[i].bounds(),
                    ShapeKind::Triangle => self.triangles[i].bounds(),
                    ShapeKind::Polygon => (self.polygons[i].min, self.polygons[i].max),
                    ShapeKind::Plane => unreachable!("planes are never bounded primitives"),
                }
            })
            .collect()
    }
}
