//! SceneDesc (f64, world space) → Scene (f32, render space, arrays of primitives by kind).
//!
//! Render space is world space shifted so that `origin` (normally the scene's camera) sits at
//! zero, measured in a `unit` the scene's camera sets (`RenderFrame`). Everything is subtracted
//! and divided in f64 before it becomes f32, so a scene translated 1e6 units away renders with
//! the same precision as one at the world origin, and a scene scaled by 1e-4 or 1e5 becomes the
//! same f32 numbers as the original: the same image, not merely a similar one.
//!
//! **Bounded and unbounded primitives.** `Scene::prims` is ordered as
//! `[bounded primitives, in the accelerator][unbounded primitives]`: the accelerator is built
//! over `prims[..unbounded.start]` only (`prim_bounds` covers that range), and the primitives in
//! `Scene::unbounded` (a quadric cylinder, a general `poly`; later, say, an intersection of
//! planes) are tested for every ray, as planes are, by every query (`Scene::intersect`,
//! `occluded`, `occluded_towards` in `render::intersect`; `intersect_rows` and `occluded_rows`
//! in `render::packet`). A primitive is unbounded when its bounds (`prim_box`) are not finite;
//! `Scene::build` moves those behind the bounded ones once all objects are added (their
//! `PrimRef`s point into the per-kind arrays, so the order of `prims` is free). A scene without
//! them has an empty range and pays one empty loop per query. Planes keep their own arrays,
//! since their shadow test is by side, not by intersection.

use std::collections::HashMap;
use std::sync::Arc;

use glam::{DVec3, Vec3};

use crate::accel::aabb::Aabb;
use crate::accel::Accel;
pub use crate::accel::AccelKind;
use crate::camera::frame::RenderFrame;
use crate::desc::{CsgOp, InteriorDesc, ObjectDesc, SceneDesc, ShapeDesc, TextureDesc};
use crate::geometry::blob::Blob;
use crate::geometry::cone::Cone;
use crate::geometry::cuboid::Cuboid;
use crate::geometry::disc::Disc;
use crate::geometry::isosurface::Isosurface;
use crate::geometry::julia::Julia;
use crate::geometry::lathe::Lathe;
use crate::geometry::mesh::{Mesh, MeshData};
use crate::geometry::parametric::Parametric;
use crate::geometry::plane::Plane;
use crate::geometry::poly::Poly;
use crate::geometry::polygon::Polygon;
use crate::geometry::prism::Prism;
use crate::geometry::sor::Sor;
use crate::geometry::sphere::{Ellipsoid, Sphere};
use crate::geometry::superellipsoid::Superellipsoid;
use crate::geometry::torus::Torus;
use crate::geometry::triangle::{SmoothTriangle, Triangle};
use crate::scene::atmosphere::Atmosphere;
use crate::scene::csg::{
    group_children, has_span, is_unbounded, ChildBounds, CsgChild, CsgGroup, CsgNode, CsgRule, CsgTarget, EVERYWHERE,
    GROUPED_FROM,
};
pub use crate::scene::light::Light;
use crate::scene::material::Material;
use crate::scene::place::RenderShape;
use crate::shading::pattern::Rgbft;

/// Distinct looks remembered for sharing materials while a scene is built (`add_material`).
const MATERIAL_CACHE: usize = 64;

pub use crate::scene::shape_kind::ShapeKind;

/// A bounded primitive: which array, which entry, which material.
#[derive(Clone, Copy, Debug)]
pub struct PrimRef {
    pub kind: ShapeKind,
    /// False for `no_shadow` objects: shadow rays pass through them.
    pub casts_shadow: bool,
    pub index: u32,
    pub material: u32,
    /// The normal points in: an `inverse`d shape, or one subtracted by a `difference`.
    pub flip: bool,
}

/// What the scene uses, so shading pays only for that.
#[derive(Clone, Copy, Debug, Default)]
pub struct Features {
    pub transparency: bool,
    pub reflection: bool,
    pub normals: bool,
    /// Some object is `no_shadow`.
    pub no_shadow: bool,
    /// Some light is not a plain point light (`Light::is_point`): shaded with single rays.
    pub complex_lights: bool,
}

pub struct Scene {
    /// Where render space sits in world space.
    pub frame: RenderFrame,
    pub spheres: Vec<Sphere>,
    pub ellipsoids: Vec<Ellipsoid>,
    pub boxes: Vec<Cuboid>,
    pub triangles: Vec<Triangle>,
    pub smooth_triangles: Vec<SmoothTriangle>,
    pub polygons: Vec<Polygon>,
    pub cones: Vec<Cone>,
    pub discs: Vec<Disc>,
    pub tori: Vec<Torus>,
    pub polys: Vec<Poly>,
    pub superellipsoids: Vec<Superellipsoid>,
    pub prisms: Vec<Prism>,
    pub lathes: Vec<Lathe>,
    pub sors: Vec<Sor>,
    pub blobs: Vec<Blob>,
    pub julias: Vec<Julia>,
    /// Meshes and height fields (`ShapeKind::Mesh` and `HeightField` index this), each placing
    /// shared `MeshData`.
    pub meshes: Vec<Mesh>,
    /// The `MeshData` built for each mesh description (by address) or height field (address,
    /// `smooth`, water level bits) during `build`, so instances share one copy.
    pub(super) mesh_cache: HashMap<(usize, bool, u64), Arc<MeshData>>,
    /// While building: the last few distinct (texture, interior, light group)s and their
    /// materials, so objects that look alike share one `Material` (a generated cloud of
    /// 1 000 000 spheres has 16 looks; one material each cost ~0.4 KB per sphere).
    material_cache: Vec<(Arc<TextureDesc>, InteriorDesc, Option<u32>, u32)>,
    /// While building: which lights light the objects of no light group (entry 0) and of
    /// each `light_group` (entry g + 1); empty without light groups.
    light_masks: Vec<Option<Arc<[bool]>>>,
    pub isosurfaces: Vec<Isosurface>,
    pub parametrics: Vec<Parametric>,
    /// Unbounded: tested for every ray, outside the accelerator.
    pub planes: Vec<Plane>,
    pub plane_materials: Vec<u32>,
    /// False for `no_shadow` planes.
    pub plane_casts_shadow: Vec<bool>,
    /// The primitives: `[..unbounded.start]` bounded, in the accelerator; `unbounded`, tested
    /// for every ray (see the module docs); `[first_leaf..]` the leaves of CSG nodes, reached
    /// only through their nodes.
    pub prims: Vec<PrimRef>,
    /// The unbounded primitives' range in `prims` (empty in most scenes): tested for every
    /// ray, outside the accelerator.
    pub unbounded: std::ops::Range<u32>,
    /// Where the CSG leaves start in `prims`.
    pub first_leaf: u32,
    pub csg: Vec<CsgNode>,
    pub csg_children: Vec<CsgChild>,
    /// Groups of the children of nodes with many (`CsgNode::first_group`), and their members.
    pub csg_groups: Vec<CsgGroup>,
    pub csg_group_members: Vec<u32>,
    /// Planes inside CSG nodes, as half-spaces (`ShapeKind::Plane` primitives index this).
    pub half_spaces: Vec<Plane>,
    pub materials: Vec<Material>,
    /// Per material: `Material::is_local`, asked per row of every packet, so answered once.
    pub local: Vec<bool>,
    pub lights: Vec<Light>,
    pub background: Rgbft,
    /// `sky_sphere`, `fog`, `rainbow` (empty in most scenes).
    pub atmosphere: Atmosphere,
    /// A `mesh_camera`'s faces in render space (`camera::mesh`); `None` for other cameras.
    pub camera_mesh: Option<Arc<crate::camera::mesh::CameraMesh>>,
    /// The camera's `normal`, in screen space (`render::RayGen`); `None` in most scenes.
    pub camera_normal: Option<Arc<crate::shading::normal::NormalF32>>,
    pub ambient_light: Vec3,
    pub max_trace_level: u32,
    /// Whether output pixels are sRGB-encoded (3.7 gamma handling) or written linear (legacy).
    pub srgb: bool,
    /// `assumed_gamma`: each sample is raised to this power before encoding (1 for 3.7 scenes).
    pub gamma: f32,
    pub features: Features,
    pub accel: Accel,
}

impl Scene {
    /// Builds render data with render space centred on `origin` (world space).
    pub fn build(desc: &SceneDesc, origin: DVec3, accel: AccelKind) -> Scene {
        let mut scene = Scene::lower(desc, origin);
        scene.accel = Accel::build(accel, &scene.prim_bounds(), &scene.prim_weights());
        scene
    }

    /// `build` for a description the caller no longer needs: its objects are dropped once they
    /// are lowered, before the accelerator is built, so the two are never held at once (at a
    /// million spheres the descriptions are about 190 MB and the tree build about 120 MB). The
    /// scene is the one `build` makes, bit for bit.
    pub fn build_owned(mut desc: SceneDesc, origin: DVec3, accel: AccelKind) -> Scene {
        let mut scene = Scene::lower(&desc, origin);
        desc.objects = Vec::new();
        drop(desc);
        scene.accel = Accel::build(accel, &scene.prim_bounds(), &scene.prim_weights());
        scene
    }

    /// Everything of `build` but the accelerator (left `Accel::None`).
    fn lower(desc: &SceneDesc, origin: DVec3) -> Scene {
        let frame = RenderFrame::for_scene(desc, origin);
        let mut scene = Scene {
            frame,
            spheres: Vec::new(),
            ellipsoids: Vec::new(),
            boxes: Vec::new(),
            triangles: Vec::new(),
            smooth_triangles: Vec::new(),
            polygons: Vec::new(),
            cones: Vec::new(),
            discs: Vec::new(),
            tori: Vec::new(),
            polys: Vec::new(),
            superellipsoids: Vec::new(),
            prisms: Vec::new(),
            lathes: Vec::new(),
            sors: Vec::new(),
            blobs: Vec::new(),
            julias: Vec::new(),
            meshes: Vec::new(),
            mesh_cache: HashMap::new(),
            material_cache: Vec::new(),
            light_masks: (0..desc.light_groups.len() + 1)
                .filter(|_| !desc.light_groups.is_empty())
                .map(|g| desc.light_mask(g.checked_sub(1).map(|g| g as u32)).map(Arc::from))
                .collect(),
            isosurfaces: Vec::new(),
            parametrics: Vec::new(),
            planes: Vec::new(),
            plane_materials: Vec::new(),
            plane_casts_shadow: Vec::new(),
            prims: Vec::new(),
            first_leaf: 0,
            csg: Vec::new(),
            csg_children: Vec::new(),
            csg_groups: Vec::new(),
            csg_group_members: Vec::new(),
            half_spaces: Vec::new(),
            unbounded: 0..0,
            materials: Vec::with_capacity(desc.objects.len()),
            local: Vec::new(),
            lights: desc.lights.iter().map(|l| Light::from_desc(l, &frame)).collect(),
            background: Rgbft::from_desc(&desc.background),
            atmosphere: Atmosphere::build(desc, &frame),
            camera_mesh: desc.camera_mesh.as_ref().map(|m| Arc::new(crate::camera::mesh::CameraMesh::build(m, &frame))),
            // Read at screen points, not in the scene: no render frame between.
            camera_normal: desc
                .camera_normal
                .as_ref()
                .map(|n| Arc::new(crate::shading::normal::NormalF32::from_desc(n, &glam::DMat4::IDENTITY))),
            ambient_light: desc.global.ambient_light.as_vec3(),
            max_trace_level: desc.global.max_trace_level.max(1),
            srgb: desc.writes_srgb(),
            gamma: desc.output_gamma().unwrap_or(1.0) as f32,
            features: Features::default(),
            accel: Accel::None { count: 0 },
        };
        scene.features.complex_lights = !scene.lights.iter().all(Light::is_point);
        let mut leaves = Vec::new();
        for object in &desc.objects {
            scene.add_object(object, &mut leaves);
        }
        scene.order_unbounded_last();
        scene.first_leaf = scene.prims.len() as u32;
        for c in &mut scene.csg_children {
            if let CsgTarget::Leaf(i) = &mut c.target {
                *i += scene.first_leaf;
            }
        }
        scene.prims.extend(leaves);
        scene.mesh_cache.clear();
        scene.material_cache = Vec::new();
        scene.light_masks.clear();
        scene
    }

    /// The material of `object`, noting what it needs in `features`.
    fn add_material(&mut self, object: &ObjectDesc) -> u32 {
        self.features.no_shadow |= object.no_shadow;
        // Shared textures (`pov::lower::looks`) compare by address first.
        let same = |(t, i, g, _): &&(Arc<TextureDesc>, InteriorDesc, Option<u32>, u32)| {
            *g == object.light_group
                && *i == object.interior
                && (Arc::ptr_eq(t, &object.texture) || *t == object.texture)
        };
        let uv = object.texture.uv_mapping.then(|| {
            let object_from_render = object.transform.inverse() * self.frame.world_from_render();
            crate::geometry::uv::UvMap::new(&object.shape, object_from_render)
        });
        let shared = uv.is_none() && object.interior_texture.is_none();
        if let Some(&(.., index)) = self.material_cache.iter().find(same).filter(|_| shared) {
            return index;
        }
        let uv = uv.flatten().map(Box::new);
        let lights = self.light_masks.get(object.light_group.map_or(0, |g| g as usize + 1)).cloned().flatten();
        let world_from_render = self.frame.world_from_render();
        let inside = object.interior_texture.as_ref().map(|inner| {
            let mut m = Material::from_desc(inner, &object.interior, &world_from_render);
            m.place(uv.clone(), lights.clone());
            self.note_material(&m);
            self.local.push(m.is_local());
            self.materials.push(m);
            self.materials.len() as u32 - 1
        });
        let mut m = Material::from_desc(&object.texture, &object.interior, &world_from_render);
        m.place(uv, lights);
        m.inside = inside;
        self.note_material(&m);
        self.local.push(m.is_local());
        self.materials.push(m);
        let index = self.materials.len() as u32 - 1;
        // A bounded list: a scene of a million different looks compares each object with
        // MATERIAL_CACHE entries at most and shares none, as before.
        if self.material_cache.len() < MATERIAL_CACHE && shared {
            self.material_cache.push((object.texture.clone(), object.interior.clone(), object.light_group, index));
        }
        index
    }

    /// Notes in `features` what `m` needs.
    fn note_material(&mut self, m: &Material) {
        self.features.transparency |= m.may_be_transparent();
        self.features.reflection |= m.reflects();
        self.features.normals |= m.has_normal();
    }

    /// One object of the scene: a primitive (or plane), or a CSG node over leaves.
    fn add_object(&mut self, object: &ObjectDesc, leaves: &mut Vec<PrimRef>) {
        let ShapeDesc::Csg { op, children } = &object.shape else {
            let material = self.add_material(object);
            match self.frame.place(&object.shape, &object.transform) {
                RenderShape::Plane { normal, distance } => {
                    self.planes.push(Plane { normal: normal.as_vec3(), distance: distance as f32 });
                    self.plane_materials.push(material);
                    self.plane_casts_shadow.push(!object.no_shadow);
                }
                RenderShape::Glyphs { render_from_object, glyphs, thickness } => {
                    for index in self.store_glyphs(render_from_object, glyphs, thickness) {
                        let (kind, casts_shadow, flip) = (ShapeKind::Prism, !object.no_shadow, object.inverse);
                        self.prims.push(PrimRef { kind, casts_shadow, index, material, flip });
                    }
                }
                placed => {
                    let (kind, index) = self.store(placed);
                    self.bound_by(kind, index, object);
                    let casts_shadow = !object.no_shadow;
                    self.prims.push(PrimRef { kind, casts_shadow, index, material, flip: object.inverse });
                }
            }
            return;
        };
        // A merge of opaque shapes looks like their union: its inner surfaces never show.
        if *op == CsgOp::Merge && !object.inverse && children.iter().all(|c| !may_show_inner_surfaces(c)) {
            for c in children {
                self.add_object(c, leaves);
            }
            return;
        }
        let start = leaves.len();
        let (target, bounds) = self.add_csg_child(object, false, leaves);
        let CsgTarget::Node(index) = target else { unreachable!("a CSG description makes a node") };
        // An unbounded node (an intersection of planes) is moved out of the accelerator with
        // the other unbounded primitives.
        let b = bounds.surface;
        self.csg[index as usize].min = b.min;
        self.csg[index as usize].max = b.max;
        let material = leaves.get(start).map_or(0, |l| l.material);
        let casts_shadow = children.iter().any(casts_any_shadow);
        self.prims.push(PrimRef { kind: ShapeKind::Csg, casts_shadow, index, material, flip: false });
    }

    /// `object` as a CSG child below nodes whose inversions multiply to `flip`: its leaves go
    /// to `leaves`, its nodes to `csg`.
    fn add_csg_child(
        &mut self,
        object: &ObjectDesc,
        flip: bool,
        leaves: &mut Vec<PrimRef>,
    ) -> (CsgTarget, ChildBounds) {
        let flip = flip ^ object.inverse;
        let ShapeDesc::Csg { op, children } = &object.shape else {
            let material = self.add_material(object);
            let (kind, index) = match self.frame.place(&object.shape, &object.transform) {
                RenderShape::Plane { normal, distance } => {
                    self.half_spaces.push(Plane { normal: normal.as_vec3(), distance: distance as f32 });
                    (ShapeKind::Plane, self.half_spaces.len() as u32 - 1)
                }
                // Text in CSG: a union of its glyphs.
                RenderShape::Glyphs { render_from_object, glyphs, thickness } => {
                    let first = self.csg_children.len() as u32;
                    let mut surface = Aabb::EMPTY;
                    for index in self.store_glyphs(render_from_object, glyphs, thickness) {
                        let prim =
                            PrimRef { kind: ShapeKind::Prism, casts_shadow: !object.no_shadow, index, material, flip };
                        let b = self.bounds_of(&prim);
                        surface.grow(&b);
                        leaves.push(prim);
                        let target = CsgTarget::Leaf(leaves.len() as u32 - 1);
                        self.csg_children.push(CsgChild::new(target, false, &ChildBounds::of_leaf(b, false)));
                    }
                    let count = self.csg_children.len() as u32 - first;
                    let (min, max) = (surface.min, surface.max);
                    self.csg.push(CsgNode {
                        rule: CsgRule::Union,
                        first,
                        count,
                        surfaces: count,
                        min,
                        max,
                        spans: false,
                        first_group: 0,
                        groups: 0,
                    });
                    let node = CsgTarget::Node(self.csg.len() as u32 - 1);
                    return (node, ChildBounds::of_leaf(surface, object.inverse));
                }
                placed => self.store(placed),
            };
            self.bound_by(kind, index, object);
            let prim = PrimRef { kind, casts_shadow: !object.no_shadow, index, material, flip };
            let mut bounds = if kind == ShapeKind::Plane {
                ChildBounds::of_plane(&self.half_spaces[index as usize], object.inverse)
            } else {
                ChildBounds::of_leaf(self.bounds_of(&prim), object.inverse)
            };
            // Solids whose inside test may hold outside their box: a polynomial's (`bounded_by`
            // narrows its box, not its inside; an inverted quadric), a blob's (a threshold of
            // zero or less holds far from every component).
            if matches!(kind, ShapeKind::Poly | ShapeKind::Blob) {
                bounds.solid = EVERYWHERE;
            }
            leaves.push(prim);
            return (CsgTarget::Leaf(leaves.len() as u32 - 1), bounds);
        };
        let (rule, subtracts, all_surfaces) = op.rule();
        let mut kids = Vec::with_capacity(children.len());
        let mut bounds = Vec::with_capacity(children.len());
        for (i, c) in children.iter().enumerate() {
            let inverse = subtracts && i > 0;
            let (target, b) = self.add_csg_child(c, flip ^ inverse, leaves);
            let b = if inverse { ChildBounds { inside: EVERYWHERE, ..b } } else { b };
            kids.push((target, inverse ^ c.inverse));
            bounds.push(b);
        }
        let surfaces = if all_surfaces { kids.len() } else { kids.len().min(1) };
        if rule == CsgRule::All {
            // A quadric's inside within what the other children allow (a cylinder cut by two
            // planes): chess2.pov's pieces, unbounded otherwise, are then bounded.
            let node = ChildBounds::of_node(rule, &bounds, surfaces, false);
            for (b, &(target, inverse)) in bounds.iter_mut().zip(&kids) {
                let CsgTarget::Leaf(l) = target else { continue };
                let prim = leaves[l as usize];
                if inverse || prim.kind != ShapeKind::Poly {
                    continue;
                }
                let poly = &self.polys[prim.index as usize];
                if let Some((lo, hi)) = poly.inside_bounds_within(node.inside.min, node.inside.max) {
                    b.inside = Aabb::new(lo, hi);
                }
                // The same within what the other children's inside tests allow (`solid`): a
                // point outside it fails this child's test or another's.
                if let Some((lo, hi)) = poly.inside_bounds_within(node.solid.min, node.solid.max) {
                    b.solid = Aabb::new(lo, hi);
                }
            }
        }
        let b = ChildBounds::of_node(rule, &bounds, surfaces, object.inverse);
        let spans = kids.iter().all(|(t, _)| matches!(t, CsgTarget::Leaf(l) if has_span(leaves[*l as usize].kind)));
        let first = self.csg_children.len() as u32;
        self.csg_children.extend(kids.iter().zip(&bounds).map(|(&(t, inv), b)| CsgChild::new(t, inv, b)));
        let first_group = self.csg_groups.len() as u32;
        if rule == CsgRule::All && kids.len() > GROUPED_FROM {
            for (bounds, members) in group_children(&self.csg_children[first as usize..]) {
                let first = self.csg_group_members.len() as u32;
                self.csg_group_members.extend(&members);
                self.csg_groups.push(CsgGroup { bounds, first, count: members.len() as u32 });
            }
        }
        self.csg.push(CsgNode {
            rule,
            first,
            count: children.len() as u32,
            surfaces: surfaces as u32,
            min: b.surface.min,
            max: b.surface.max,
            spans,
            first_group,
            groups: self.csg_groups.len() as u32 - first_group,
        });
        (CsgTarget::Node(self.csg.len() as u32 - 1), b)
    }

    /// The bounded primitives' box in world space, `None` without any. Render space is in the
    /// camera's unit of length; whatever moves through the scene in world units (the fly
    /// camera) must measure it here.
    pub fn world_bounds(&self) -> Option<(DVec3, DVec3)> {
        let mut b = Aabb::EMPTY;
        for p in self.prim_bounds() {
            b.grow(&p);
        }
        if self.unbounded.start == 0 {
            return None;
        }
        let world = self.frame.world_from_render();
        Some((world.transform_point3(b.min.as_dvec3()), world.transform_point3(b.max.as_dvec3())))
    }

    /// The bounds of what the scene shows seen from `eye` (`camera::orbit::subject_of` of the
    /// bounded primitives' world boxes), in world units.
    pub fn subject_bounds(&self, eye: DVec3) -> Option<(DVec3, DVec3)> {
        let world = self.frame.world_from_render();
        let boxes = self.prim_bounds().into_iter().map(|b| {
            let (a, c) = (world.transform_point3(b.min.as_dvec3()), world.transform_point3(b.max.as_dvec3()));
            (a.min(c), a.max(c))
        });
        crate::camera::orbit::subject_of(boxes, eye)
    }

    /// Moves the unbounded primitives behind the bounded ones and sets `unbounded` (see the
    /// module docs); the bounded ones keep their order, so a scene without unbounded
    /// primitives is unchanged.
    fn order_unbounded_last(&mut self) {
        let (bounded, unbounded): (Vec<PrimRef>, Vec<PrimRef>) =
            self.prims.iter().partition(|p| !is_unbounded(&self.bounds_of(p)));
        self.unbounded = bounded.len() as u32..self.prims.len() as u32;
        if !unbounded.is_empty() {
            self.prims = bounded.into_iter().chain(unbounded).collect();
        }
    }
}

/// Whether any shape of `object` may let light through (so a `merge`'s inner surfaces show).
fn may_show_inner_surfaces(object: &ObjectDesc) -> bool {
    match &object.shape {
        ShapeDesc::Csg { children, .. } => children.iter().any(may_show_inner_surfaces),
        _ => Material::from_desc(&object.texture, &object.interior, &glam::DMat4::IDENTITY).may_be_transparent(),
    }
}

/// Whether any shape of `object` casts a shadow.
fn casts_any_shadow(object: &ObjectDesc) -> bool {
    match &object.shape {
        ShapeDesc::Csg { children, .. } => children.iter().any(casts_any_shadow),
        _ => !object.no_shadow,
    }
}
