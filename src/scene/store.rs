//! The scene's per-kind shape arrays: a placed shape rounded into its kind's array (f64 composed,
//! cast to f32 once), and each primitive's bounds read back from there.

use std::sync::Arc;

use glam::{DAffine3, DVec3, Vec3};

use super::build::{PrimRef, Scene, ShapeKind};
use crate::accel::aabb::Aabb;
use crate::desc::{box_through, MeshDesc, ObjectDesc};
use crate::geometry::affine_f32;
use crate::geometry::blob::Blob;
use crate::geometry::cone::Cone;
use crate::geometry::cuboid::{frame_for, Cuboid};
use crate::geometry::disc::Disc;
use crate::geometry::height_field::{self, HeightGrid};
use crate::geometry::isosurface::Isosurface;
use crate::geometry::julia::Julia;
use crate::geometry::lathe::Lathe;
use crate::geometry::mesh::{Mesh, MeshData};
use crate::geometry::parametric::Parametric;
use crate::geometry::poly::Poly;
use crate::geometry::polygon::Polygon;
use crate::geometry::prism::Prism;
use crate::geometry::roots::Solver;
use crate::geometry::sor::Sor;
use crate::geometry::sphere::{Ellipsoid, Sphere};
use crate::geometry::spline::Piece;
use crate::geometry::superellipsoid::Superellipsoid;
use crate::geometry::torus::Torus;
use crate::geometry::triangle::{SmoothTriangle, Triangle};
use crate::scene::csg::EVERYWHERE;
use crate::scene::place::RenderShape;

impl Scene {
    /// `text`'s glyphs as prisms sharing one frame: their indices in `prisms`.
    pub(super) fn store_glyphs(
        &mut self,
        render_from_object: DAffine3,
        glyphs: Vec<Vec<Piece>>,
        thickness: f64,
    ) -> Vec<u32> {
        glyphs
            .into_iter()
            .map(|pieces| {
                self.prisms.push(Prism::new(render_from_object, &pieces, 0.0, thickness, false, false));
                self.prisms.len() as u32 - 1
            })
            .collect()
    }

    /// Puts a placed (non-plane) shape into its array: its kind and index there.
    pub(super) fn store(&mut self, placed: RenderShape) -> (ShapeKind, u32) {
        let at = |len: usize| len as u32 - 1;
        match placed {
            RenderShape::Sphere { center, radius } => {
                self.spheres.push(Sphere { center: center.as_vec3(), radius: radius as f32 });
                (ShapeKind::Sphere, at(self.spheres.len()))
            }
            RenderShape::Ellipsoid { render_from_object, center, radius } => {
                // Composed in f64 and cast once: the sphere's object-space centre is as written
                // (1e6 for a sphere written in place and scaled about itself), and in f32 it
                // cancelled against the render-space translation with an ulp of 0.06.
                let xf = render_from_object
                    * DAffine3::from_translation(center)
                    * DAffine3::from_scale(DVec3::splat(radius));
                self.ellipsoids.push(Ellipsoid::new(affine_f32(&xf)));
                (ShapeKind::Ellipsoid, at(self.ellipsoids.len()))
            }
            RenderShape::Box { min, max, frame } => {
                let frame = frame.map(|f| frame_for(affine_f32(&f)));
                self.boxes.push(Cuboid { min: min.as_vec3(), max: max.as_vec3(), frame });
                (ShapeKind::Box, at(self.boxes.len()))
            }
            RenderShape::Triangle([a, b, c]) => {
                self.triangles.push(Triangle::new(a.as_vec3(), b.as_vec3(), c.as_vec3()));
                (ShapeKind::Triangle, at(self.triangles.len()))
            }
            RenderShape::SmoothTriangle { corners: [a, b, c], normals } => {
                let tri = Triangle::new(a.as_vec3(), b.as_vec3(), c.as_vec3());
                self.smooth_triangles.push(SmoothTriangle { tri, normals: normals.map(|n| n.as_vec3()) });
                (ShapeKind::SmoothTriangle, at(self.smooth_triangles.len()))
            }
            RenderShape::Polygon(points) => {
                self.polygons.push(Polygon::new(&points));
                (ShapeKind::Polygon, at(self.polygons.len()))
            }
            RenderShape::Cone { render_from_object, r0, r1, open } => {
                self.cones.push(Cone::new(affine_f32(&render_from_object), r0 as f32, r1 as f32, open));
                (ShapeKind::Cone, at(self.cones.len()))
            }
            RenderShape::Disc { render_from_object, hole } => {
                self.discs.push(Disc::new(affine_f32(&render_from_object), hole as f32));
                (ShapeKind::Disc, at(self.discs.len()))
            }
            RenderShape::Torus { render_from_object, minor } => {
                self.tori.push(Torus::new(affine_f32(&render_from_object), minor as f32));
                (ShapeKind::Torus, at(self.tori.len()))
            }
            RenderShape::Poly { render_from_object, order, coefficients, sturm } => {
                let solver = if sturm { Solver::Sturm } else { Solver::Fast };
                self.polys.push(Poly::new(affine_f32(&render_from_object), order, &coefficients, solver));
                (ShapeKind::Poly, at(self.polys.len()))
            }
            RenderShape::Prism { render_from_object, pieces, h1, h2, conic, open } => {
                self.prisms.push(Prism::new(render_from_object, &pieces, h1, h2, conic, open));
                (ShapeKind::Prism, at(self.prisms.len()))
            }
            RenderShape::Lathe { render_from_object, pieces } => {
                self.lathes.push(Lathe::new(render_from_object, &pieces));
                (ShapeKind::Lathe, at(self.lathes.len()))
            }
            RenderShape::Sor { render_from_object, points, open } => {
                self.sors.push(Sor::new(render_from_object, &points, open));
                (ShapeKind::Sor, at(self.sors.len()))
            }
            RenderShape::Blob { render_from_object, components, threshold } => {
                self.blobs.push(Blob::new(render_from_object, &components, threshold));
                (ShapeKind::Blob, at(self.blobs.len()))
            }
            RenderShape::Julia { render_from_object, param, function, max_iteration, precision, slice } => {
                self.julias.push(Julia::new(render_from_object, param, function, max_iteration, precision, slice));
                (ShapeKind::Julia, at(self.julias.len()))
            }
            RenderShape::Isosurface { render_from_object, function, container, params } => {
                self.isosurfaces.push(Isosurface::new(render_from_object, function, container, params));
                (ShapeKind::Isosurface, at(self.isosurfaces.len()))
            }
            RenderShape::Parametric { render_from_object, functions, container, params } => {
                self.parametrics.push(Parametric::new(render_from_object, functions, container, params));
                (ShapeKind::Parametric, at(self.parametrics.len()))
            }
            RenderShape::Superellipsoid { render_from_object, e, n } => {
                self.superellipsoids.push(Superellipsoid::new(affine_f32(&render_from_object), e, n));
                (ShapeKind::Superellipsoid, at(self.superellipsoids.len()))
            }
            RenderShape::Mesh { render_from_object, mesh, inside_vector } => {
                let key = (Arc::as_ptr(&mesh) as usize, false, 0);
                let data = self.mesh_cache.entry(key).or_insert_with(|| Arc::new(mesh_data(&mesh))).clone();
                let inside = inside_vector.map(|v| v.as_vec3());
                self.meshes.push(Mesh::new(data, affine_f32(&render_from_object), inside));
                (ShapeKind::Mesh, at(self.meshes.len()))
            }
            RenderShape::HeightField { render_from_object, field, smooth, water_level } => {
                let key = (Arc::as_ptr(&field) as usize, smooth, water_level.to_bits());
                let data = self.mesh_cache.entry(key).or_insert_with(|| {
                    let water = water_level as f32;
                    let faces =
                        height_field::faces(field.width as usize, field.height as usize, &field.heights, smooth, water);
                    let floor = if water_level > 0.0 { water } else { f32::NEG_INFINITY };
                    let grid = HeightGrid::new(field.width as usize, field.height as usize, &field.heights, floor);
                    let data = MeshData::new(faces).with_grid(grid);
                    Arc::new(if water_level > 0.0 { data.with_floor(water) } else { data })
                });
                // Solid below its surface, as POV-Ray's: odd crossings going up (the grid
                // answers it).
                let data = data.clone();
                self.meshes.push(Mesh::new(data, affine_f32(&render_from_object), Some(Vec3::Y)));
                (ShapeKind::HeightField, at(self.meshes.len()))
            }
            RenderShape::Plane { .. } | RenderShape::Glyphs { .. } => {
                unreachable!("planes and text are stored by the caller")
            }
        }
    }

    /// Narrows a polynomial surface's bounds (infinite in general) to its object's
    /// `bounded_by` box, in render space: the accelerator then skips it for rays that miss
    /// the box, as POV-Ray does. Other kinds' own bounds are tight already.
    pub(super) fn bound_by(&mut self, kind: ShapeKind, index: u32, object: &ObjectDesc) {
        let (Some(&[lo, hi]), ShapeKind::Poly) = (object.bounded_by.as_deref(), kind) else { return };
        let [lo, hi] = box_through(&(self.frame.render_from_world() * object.transform.matrix()), lo, hi);
        let b = Aabb::new(lo.as_vec3(), hi.as_vec3());
        let poly = &mut self.polys[index as usize];
        // Rounded outwards by a part in a million of the box: the f32 corners must not cut
        // the surface where the bound touches it.
        let pad = (b.max - b.min).abs() * 1e-6 + Vec3::splat(f32::MIN_POSITIVE);
        poly.min = poly.min.max(b.min - pad);
        poly.max = poly.max.min(b.max + pad);
    }

    /// The bounded primitives' boxes (`prims[..unbounded.start]`), for the accelerator.
    pub fn prim_bounds(&self) -> Vec<Aabb> {
        self.prims[..self.unbounded.start as usize].iter().map(|p| self.bounds_of(p)).collect()
    }

    /// One primitive's render-space bounds (infinite for unbounded ones).
    pub fn bounds_of(&self, p: &PrimRef) -> Aabb {
        let i = p.index as usize;
        let (lo, hi) = match p.kind {
            ShapeKind::Sphere => self.spheres[i].bounds(),
            ShapeKind::Ellipsoid => (self.ellipsoids[i].min, self.ellipsoids[i].max),
            ShapeKind::Box => self.boxes[i].bounds(),
            ShapeKind::Triangle => self.triangles[i].bounds(),
            ShapeKind::SmoothTriangle => self.smooth_triangles[i].tri.bounds(),
            ShapeKind::Polygon => (self.polygons[i].min, self.polygons[i].max),
            ShapeKind::Cone => self.cones[i].bounds(),
            ShapeKind::Disc => self.discs[i].bounds(),
            ShapeKind::Torus => self.tori[i].bounds(),
            ShapeKind::Poly => self.polys[i].bounds(),
            ShapeKind::Superellipsoid => self.superellipsoids[i].bounds(),
            ShapeKind::Prism => self.prisms[i].bounds(),
            ShapeKind::Lathe => self.lathes[i].bounds(),
            ShapeKind::Sor => self.sors[i].bounds(),
            ShapeKind::Blob => self.blobs[i].bounds(),
            ShapeKind::Julia => self.julias[i].bounds(),
            ShapeKind::Mesh | ShapeKind::HeightField => self.meshes[i].bounds(),
            ShapeKind::Isosurface => self.isosurfaces[i].bounds(),
            ShapeKind::Parametric => self.parametrics[i].bounds(),
            ShapeKind::Csg => (self.csg[i].min, self.csg[i].max),
            ShapeKind::Plane => return EVERYWHERE,
        };
        Aabb::new(lo, hi)
    }
}

/// A mesh description's triangles (object space, f32) with their BVH.
fn mesh_data(mesh: &MeshDesc) -> MeshData {
    let v = |i: u32| mesh.vertices[i as usize].as_vec3();
    let n = |i: u32| mesh.normals[i as usize].as_vec3();
    MeshData::from_faces(mesh.faces.len(), |i| {
        let f = &mesh.faces[i];
        (f.vertices.map(v), f.normals.map(|k| k.map(n)))
    })
}
