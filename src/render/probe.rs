//! Parse-time questions about declared objects (POV-Ray 3.3.1.4 `min_extent`, `max_extent`,
//! `trace`, `inside`): answered by the renderer's own storage and kernels, built for just
//! those objects with no accelerator (`AccelKind::None`), so there is no second copy of any
//! bounds or intersection routine and no BVH is built while parsing.

use glam::DVec3;

use crate::accel::AccelKind;
use crate::desc::{ObjectDesc, SceneDesc, Solid, SolidRef};
use crate::geometry::Shape;
use crate::lanes::Lane;
use crate::render::stats::RenderStats;
use crate::scene::build::Scene;
use std::sync::Arc;

fn scene_of(objects: &[ObjectDesc]) -> Scene {
    let desc = SceneDesc { objects: objects.to_vec(), ..SceneDesc::default() };
    Scene::build(&desc, DVec3::ZERO, AccelKind::None)
}

/// The objects' bounding box in world space (what `min_extent`/`max_extent` report); `None`
/// when nothing is bounded (an infinite plane alone).
pub fn bounds(objects: &[ObjectDesc]) -> Option<(DVec3, DVec3)> {
    scene_of(objects).world_bounds()
}

/// `trace(OBJ, start, dir)`: the nearest hit point along the ray and the outward surface
/// normal there (outward even from inside, as POV-Ray 3.7 returns it); `None` on a miss or a
/// zero direction.
pub fn trace(objects: &[ObjectDesc], start: DVec3, dir: DVec3) -> Option<(DVec3, DVec3)> {
    if dir.length_squared() == 0.0 || !dir.is_finite() || !start.is_finite() {
        return None;
    }
    let scene = scene_of(objects);
    let frame = &scene.frame;
    let ray = crate::ray::Ray::new(frame.point(start).as_vec3(), frame.vector(dir).normalize().as_vec3());
    let hit = scene.intersect(&ray, f32::INFINITY, &mut RenderStats::default())?;
    let hit = scene.refine(&ray, hit);
    let p = ray.at(hit.t);
    let n = scene.normal_at(hit.shape, p);
    let world = frame.world_from_render();
    let n = world.transform_vector3(n.as_dvec3()).normalize_or_zero();
    Some((world.transform_point3(p.as_dvec3()), n))
}

/// `inside(OBJ, P)`: whether `p` is inside any of the objects' primitives.
pub fn inside(objects: &[ObjectDesc], p: DVec3) -> bool {
    scene_contains(&scene_of(objects), p)
}

/// The objects as a `Solid` for the `object` pattern: built once, asked per point.
pub fn solid(objects: &[ObjectDesc]) -> SolidRef {
    SolidRef(Arc::new(ProbeSolid { scene: scene_of(objects), objects: objects.to_vec() }))
}

struct ProbeSolid {
    scene: Scene,
    objects: Vec<ObjectDesc>,
}

impl std::fmt::Debug for ProbeSolid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ProbeSolid({} primitives)", self.scene.prims.len())
    }
}

impl Solid for ProbeSolid {
    fn contains(&self, p: DVec3) -> bool {
        scene_contains(&self.scene, p)
    }

    fn objects(&self) -> &[ObjectDesc] {
        &self.objects
    }
}

fn scene_contains(scene: &Scene, p: DVec3) -> bool {
    let q = crate::lanes::V3::<f32>::from_vec3(scene.frame.point(p).as_vec3());
    // The prims from `first_leaf` on are CSG leaves, inside only as their nodes say.
    scene.prims[..scene.first_leaf as usize].iter().any(|prim| f32::mask_lane(scene.inside_prim(prim, q), 0))
        || scene.planes.iter().any(|pl| f32::mask_lane(pl.inside(q), 0))
}
