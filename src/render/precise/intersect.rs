//! Scene queries in f64: the nearest hit and shadow-ray occlusion over the f64 geometry
//! (`scene::precise`), with the f32 `Scene`'s primitive list, materials and shadow flags.
//! The same rules as `render::intersect`: unbounded planes outside the accelerator, ties to the
//! lower primitive, planes tested by side for shadow rays.

use glam::DVec3;

use crate::geometry::precise::RayD;
use crate::render::intersect::HitShape;
use crate::render::stats::RenderStats;
use crate::scene::build::{PrimRef, Scene, ShapeKind};
use crate::scene::precise::{PreciseAccel, PreciseScene};

/// What an f64 ray hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitD {
    pub t: f64,
    pub shape: HitShape,
}

/// A scene as the f64 path sees it: f64 geometry, f32 materials.
#[derive(Clone, Copy)]
pub struct SceneD<'a> {
    pub scene: &'a Scene,
    pub geo: &'a PreciseScene,
}

impl<'a> SceneD<'a> {
    /// `None` until `Scene::prepare_precise` has built the f64 geometry.
    pub fn new(scene: &'a Scene) -> Option<SceneD<'a>> {
        Some(SceneD { scene, geo: scene.precise()? })
    }

    /// One primitive test, counted for the statistics.
    #[inline]
    pub fn test_prim(&self, p: &PrimRef, ray: &RayD, t_max: f64, stats: &mut RenderStats) -> Option<f64> {
        let (g, i) = (self.geo, p.index as usize);
        let t = match p.kind {
            ShapeKind::Sphere => g.spheres[i].intersect(ray, 0.0, t_max),
            ShapeKind::Ellipsoid => g.ellipsoids[i].intersect(ray, 0.0, t_max),
            ShapeKind::Box => g.boxes[i].intersect(ray, 0.0, t_max),
            ShapeKind::Triangle => g.triangles[i].intersect(ray, 0.0, t_max),
            ShapeKind::Polygon => g.polygons[i].intersect(ray, 0.0, t_max),
            ShapeKind::Plane => None,
        };
        stats.count_test(p.kind, t.is_some());
        t
    }

    fn traverse(&self, ray: &RayD, t_max: f64, test: impl FnMut(u32, f64) -> Option<f64>) -> u64 {
        match &self.geo.accel {
            PreciseAccel::Bvh(b) => b.traverse(ray, t_max, test) as u64,
            PreciseAccel::None { count } => {
                let (mut test, mut t_max) = (test, t_max);
                for p in 0..*count {
                    if let Some(t) = test(p, t_max) {
                        t_max = t_max.min(t);
                    }
                }
                0
            }
        }
    }

    /// The nearest hit with `0 < t < t_max`.
    pub fn intersect(&self, ray: &RayD, t_max: f64, stats: &mut RenderStats) -> Option<HitD> {
        let mut best: Option<HitD> = None;
        let mut t_best = t_max;
        for (i, plane) in self.geo.planes.iter().enumerate() {
            let t = plane.intersect(ray, 0.0, t_best);
            stats.count_test(ShapeKind::Plane, t.is_some());
            if let Some(t) = t {
                t_best = t;
                best = Some(HitD { t, shape: HitShape::Plane(i as u32) });
            }
        }
        stats.nodes_visited += self.traverse(ray, t_best, |prim, t_max| {
            let t = self.test_prim(&self.scene.prims[prim as usize], ray, t_max, stats)?;
            // Ties go to the lower index so every accelerator picks the same primitive.
            if best.is_none_or(|b| t < b.t || (t == b.t && b.shape > HitShape::Prim(prim))) {
                best = Some(HitD { t, shape: HitShape::Prim(prim) });
            }
            Some(t)
        });
        best
    }

    /// Whether the shadow ray towards the light at `light` is blocked before `t_max`; planes
    /// are tested by side, as in `Scene::occluded_towards`.
    pub fn occluded_towards(&self, ray: &RayD, t_max: f64, light: DVec3, stats: &mut RenderStats) -> bool {
        for (plane, &casts) in self.geo.planes.iter().zip(&self.scene.plane_casts_shadow) {
            if !casts {
                continue;
            }
            let hit = plane.separates(ray.origin, light);
            stats.count_test(ShapeKind::Plane, hit);
            if hit {
                return true;
            }
        }
        let mut blocked = false;
        stats.nodes_visited += self.traverse(ray, t_max, |prim, t_max| {
            let p = &self.scene.prims[prim as usize];
            if blocked || !p.casts_shadow {
                return None;
            }
            let t = self.test_prim(p, ray, t_max, stats)?;
            blocked = true;
            // A zero limit culls every remaining node.
            Some(t.min(0.0))
        });
        blocked
    }

    /// Geometric outward normal at a hit point.
    pub fn normal_at(&self, shape: HitShape, p: DVec3) -> DVec3 {
        let g = self.geo;
        match shape {
            HitShape::Plane(i) => g.planes[i as usize].normal,
            HitShape::Prim(i) => {
                let r = &self.scene.prims[i as usize];
                let k = r.index as usize;
                match r.kind {
                    ShapeKind::Sphere => g.spheres[k].normal_at(p),
                    ShapeKind::Ellipsoid => g.ellipsoids[k].normal_at(p),
                    ShapeKind::Box => g.boxes[k].normal_at(p),
                    ShapeKind::Triangle => g.triangles[k].normal,
                    ShapeKind::Polygon => g.polygons[k].normal,
                    ShapeKind::Plane => DVec3::Y,
                }
            }
        }
    }
}
