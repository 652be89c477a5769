//! Placement: a shape of the description (world space, f64) under its object transform,
//! carried into render space (`RenderFrame`) and composed in f64, as `RenderShape`, before
//! `Scene::build` rounds it into the per-kind f32 arrays.

use std::sync::Arc;

use glam::{DAffine3, DMat4, DVec3};

use crate::camera::frame::RenderFrame;
use crate::desc::{BlobComponent, BlobShape, HeightFieldDesc, MeshDesc, MeshFace, Placement, ShapeDesc, TextGlyph};
use crate::geometry::blob;
use crate::geometry::spline::{closed_pieces, open_pieces, Piece};

/// One shape of the description placed in render space, in f64: everything subtracted and
/// composed before `Scene::add_shape` rounds it to the f32 arrays.
pub(crate) enum RenderShape {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// A sphere under a non-uniform transform: the sphere (`center`, `radius`, object space)
    /// under `render_from_object`.
    Ellipsoid {
        render_from_object: DAffine3,
        center: DVec3,
        radius: f64,
    },
    /// Axis-aligned in render space (`frame: None`), or corners in object space under `frame`.
    Box {
        min: DVec3,
        max: DVec3,
        frame: Option<DAffine3>,
    },
    Triangle([DVec3; 3]),
    /// A `smooth_triangle` outside a mesh: corners and vertex normals in render space (the
    /// normals carried by the inverse transpose, not normalised again).
    SmoothTriangle {
        corners: [DVec3; 3],
        normals: [DVec3; 3],
    },
    Polygon(Vec<DVec3>),
    /// The canonical cone (axis z from 0 to 1, radii `r0` and `r1`) under `render_from_object`.
    Cone {
        render_from_object: DAffine3,
        r0: f64,
        r1: f64,
        open: bool,
    },
    /// The unit disc in z = 0 with a hole of radius `hole`.
    Disc {
        render_from_object: DAffine3,
        hole: f64,
    },
    /// The torus of major radius 1 and minor radius `minor`.
    Torus {
        render_from_object: DAffine3,
        minor: f64,
    },
    /// A polynomial of `order` with POV-Ray's coefficients (object space).
    Poly {
        render_from_object: DAffine3,
        order: usize,
        coefficients: Vec<f64>,
        sturm: bool,
    },
    /// The superellipsoid `<e, n>` in the unit box.
    Superellipsoid {
        render_from_object: DAffine3,
        e: f64,
        n: f64,
    },
    /// Closed curves in the xz-plane of object space, swept along y from `h1` to `h2` (or
    /// towards the origin: `conic`).
    Prism {
        render_from_object: DAffine3,
        pieces: Vec<Piece>,
        h1: f64,
        h2: f64,
        conic: bool,
        open: bool,
    },
    /// (r, y) pieces revolved around the object's y axis.
    Lathe {
        render_from_object: DAffine3,
        pieces: Vec<Piece>,
    },
    Sor {
        render_from_object: DAffine3,
        points: Vec<glam::DVec2>,
        open: bool,
    },
    Julia {
        render_from_object: DAffine3,
        param: glam::DVec4,
        function: crate::desc::JuliaFunction,
        max_iteration: u32,
        precision: f64,
        slice: (glam::DVec4, f64),
    },
    /// Components in the blob's object space.
    Blob {
        render_from_object: DAffine3,
        components: Vec<blob::Component>,
        threshold: f64,
    },
    Isosurface {
        render_from_object: DAffine3,
        function: crate::function::Program,
        container: crate::desc::Container,
        params: crate::desc::IsoParams,
    },
    Parametric {
        render_from_object: DAffine3,
        functions: [crate::function::Program; 3],
        container: crate::desc::Container,
        params: crate::desc::ParametricParams,
    },
    /// `text`: one linear prism per glyph (its own tight box in the BVH), sharing the frame.
    Glyphs {
        render_from_object: DAffine3,
        glyphs: Vec<Vec<Piece>>,
        thickness: f64,
    },
    /// A mesh (shared, object space) under `render_from_object`.
    Mesh {
        render_from_object: DAffine3,
        mesh: Arc<MeshDesc>,
        inside_vector: Option<DVec3>,
    },
    /// A height field's grid (shared, the unit square) under `render_from_object`.
    HeightField {
        render_from_object: DAffine3,
        field: Arc<HeightFieldDesc>,
        smooth: bool,
        water_level: f64,
    },
    /// `normal · p = distance`, `normal` of unit length.
    Plane {
        normal: DVec3,
        distance: f64,
    },
}

/// A mesh of one smooth face and nothing else (what `smooth_triangle` outside a mesh is
/// parsed as): its corners and vertex normals in object space.
fn lone_smooth_face(mesh: &MeshDesc) -> Option<([DVec3; 3], [DVec3; 3])> {
    match mesh.faces[..] {
        [MeshFace { vertices, normals: Some(normals) }] if mesh.uv_faces.is_empty() => {
            Some((vertices.map(|i| mesh.vertices[i as usize]), normals.map(|i| mesh.normals[i as usize])))
        }
        _ => None,
    }
}

/// Placing shapes: the frame of `camera::frame` carries a description's shape into render space.
impl RenderFrame {
    /// `shape` under the object transform `t`, in render space.
    pub(crate) fn place(&self, shape: &ShapeDesc, t: &Placement) -> RenderShape {
        let t = &t.transform();
        let point = |p: DVec3| self.point(t.matrix.transform_point3(p));
        let render_from_object = || DAffine3::from_mat4(self.render_from_world() * t.matrix);
        match shape {
            ShapeDesc::Sphere { center, radius } => match uniform_scale(&t.matrix) {
                Some(s) => RenderShape::Sphere { center: point(*center), radius: radius * s * self.per_unit },
                None => RenderShape::Ellipsoid {
                    render_from_object: render_from_object(),
                    center: *center,
                    radius: *radius,
                },
            },
            ShapeDesc::Box { corner1, corner2 } => {
                let (lo, hi) = (corner1.min(*corner2), corner1.max(*corner2));
                if is_axis_aligned(&t.matrix) {
                    let (a, b) = (point(lo), point(hi));
                    RenderShape::Box { min: a.min(b), max: a.max(b), frame: None }
                } else {
                    // Object space re-centred on `c` before anything becomes f32: the corners
                    // of a box written far from its object origin would be cast as written.
                    let c = box_object_origin(lo, hi);
                    let frame = if c == DVec3::ZERO {
                        render_from_object()
                    } else {
                        render_from_object() * DAffine3::from_translation(c)
                    };
                    RenderShape::Box { min: lo - c, max: hi - c, frame: Some(frame) }
                }
            }
            ShapeDesc::Triangle { a, b, c } => RenderShape::Triangle([point(*a), point(*b), point(*c)]),
            ShapeDesc::Cone { base, base_radius, cap, cap_radius, open, .. } => {
                // Canonical space: the axis along z, base at 0, cap at 1, scaled uniformly.
                let axis = *cap - *base;
                let len = axis.length();
                let (u, v) = perpendiculars(axis / len);
                let local = DAffine3::from_cols(u * len, v * len, axis, *base);
                RenderShape::Cone {
                    render_from_object: render_from_object() * local,
                    r0: base_radius / len,
                    r1: cap_radius / len,
                    open: *open,
                }
            }
            ShapeDesc::Disc { center, normal, radius, hole } => {
                let n = normal.normalize();
                let (u, v) = perpendiculars(n);
                let local = DAffine3::from_cols(u * *radius, v * *radius, n * *radius, *center);
                RenderShape::Disc { render_from_object: render_from_object() * local, hole: hole / radius }
            }
            ShapeDesc::Torus { major, minor } => RenderShape::Torus {
                render_from_object: render_from_object() * DAffine3::from_scale(DVec3::splat(*major)),
                minor: minor / major,
            },
            ShapeDesc::Poly { order, coefficients, sturm, .. } => RenderShape::Poly {
                render_from_object: render_from_object(),
                order: *order,
                coefficients: coefficients.clone(),
                sturm: *sturm,
            },
            ShapeDesc::Superellipsoid { e, n } => {
                RenderShape::Superellipsoid { render_from_object: render_from_object(), e: *e, n: *n }
            }
            ShapeDesc::Prism { spline, conic, h1, h2, points, open } => RenderShape::Prism {
                render_from_object: render_from_object(),
                // Checked when lowered: a bad outline never gets here.
                pieces: closed_pieces(*spline, points).map(|p| p.0).unwrap_or_default(),
                h1: *h1,
                h2: *h2,
                conic: *conic,
                open: *open,
            },
            ShapeDesc::Lathe { spline, points } => RenderShape::Lathe {
                render_from_object: render_from_object(),
                pieces: open_pieces(*spline, points).unwrap_or_default(),
            },
            ShapeDesc::Sor { points, open } => {
                RenderShape::Sor { render_from_object: render_from_object(), points: points.clone(), open: *open }
            }
            ShapeDesc::Julia { param, function, max_iteration, precision, slice } => RenderShape::Julia {
                render_from_object: render_from_object(),
                param: **param,
                function: *function,
                max_iteration: *max_iteration,
                precision: *precision,
                slice: **slice,
            },
            ShapeDesc::Blob { components, threshold } => RenderShape::Blob {
                render_from_object: render_from_object(),
                components: components.iter().map(blob_component).collect(),
                threshold: *threshold,
            },
            ShapeDesc::Isosurface { function, container, params } => RenderShape::Isosurface {
                render_from_object: render_from_object(),
                function: (**function).clone(),
                container: *container,
                params: **params,
            },
            ShapeDesc::Parametric { functions, container, params } => RenderShape::Parametric {
                render_from_object: render_from_object(),
                functions: (**functions).clone(),
                container: *container,
                params: **params,
            },
            ShapeDesc::Text { thickness, glyphs, .. } => {
                // A prism sweeps its (x, z) outline along y; a glyph's (x, y) outline is swept
                // along z: swap y and z.
                let swap = DAffine3::from_cols(DVec3::X, DVec3::Z, DVec3::Y, DVec3::ZERO);
                let pieces = |g: &TextGlyph| {
                    g.quads
                        .iter()
                        .map(
                            |&[a, c, b]| {
                                if c == 0.5 * (a + b) {
                                    Piece::line(a, b)
                                } else {
                                    Piece::quadratic_bezier(a, c, b)
                                }
                            },
                        )
                        .collect()
                };
                RenderShape::Glyphs {
                    render_from_object: render_from_object() * swap,
                    glyphs: glyphs.iter().map(pieces).collect(),
                    thickness: *thickness,
                }
            }
            ShapeDesc::Mesh { mesh, inside_vector: None } if lone_smooth_face(mesh).is_some() => {
                let (corners, normals) = lone_smooth_face(mesh).expect("checked by the guard");
                let to_render = render_from_object().matrix3.inverse().transpose();
                RenderShape::SmoothTriangle {
                    corners: corners.map(point),
                    normals: normals.map(|n| to_render * n.normalize_or_zero()),
                }
            }
            ShapeDesc::Mesh { mesh, inside_vector } => RenderShape::Mesh {
                render_from_object: render_from_object(),
                mesh: mesh.clone(),
                inside_vector: *inside_vector,
            },
            ShapeDesc::HeightField { field, smooth, water_level } => RenderShape::HeightField {
                render_from_object: render_from_object(),
                field: field.clone(),
                smooth: *smooth,
                water_level: *water_level,
            },
            ShapeDesc::Polygon { points } => RenderShape::Polygon(points.iter().map(|p| point(*p)).collect()),
            ShapeDesc::Csg { .. } => unreachable!("CSG nodes are built by `Scene::add_object`"),
            ShapeDesc::Plane { normal, distance } => {
                // n·p = d in object space; a point on it maps through the transform and the normal
                // through the inverse transpose.
                let n_obj = normal.normalize();
                let d_obj = distance / normal.length();
                let p_render = point(n_obj * d_obj);
                let n = t.inverse.transpose().transform_vector3(n_obj).normalize();
                RenderShape::Plane { normal: n, distance: n.dot(p_render) }
            }
        }
    }
}

/// The snap grid of `box_object_origin`, in a rotated box's largest extents: the grid is the
/// smallest power of two at least this many extents.
///
/// Measured on the in-place twins of `tests/suite/far.rs` (boxes 1.2 to 2.2 units across, offsets
/// 1e5 = 2^5·3125, 1e6 = 2^6·15625, 1e7 = 2^7·78125): with 64 extents (grids of 128 and 256)
/// the wood and refraction twins at 1e5 and 1e6 differed from the original on 1 to 33 pixels,
/// since those offsets are not multiples of the grid; with 16, the refraction twins at 1e5 and
/// <1e6, −3e5, 7e5> on 1 each; with 4 (grids of 8 and 16) all are identical. Fewer extents also leave the corners nearer
/// zero, so more precise; the cost is that fewer boxes keep their old numbers (those within 2
/// to 4 extents of their object origin do, the seed scene's among them).
const BOX_SNAP_EXTENTS: f64 = 4.0;

/// The point a rotated box's object space is re-centred on: its centre snapped to a multiple
/// of a power of two at least `BOX_SNAP_EXTENTS` × its largest extent (zero for a degenerate
/// or unbounded box).
///
/// A rotated box keeps its corners in object space, which the f32 slab test works in, so a box
/// written in place 1e6 from the origin (`box { <1e6, 0, 0>, .. } translate -P rotate ..
/// translate P`) kept corners at 1e6, an f32 ulp of 0.06: bent boxes. Snapping instead of
/// using the centre itself keeps three things exact: a box near its object origin (the seed
/// scene's) snaps to zero and keeps exactly its old numbers; the corners minus a multiple of a
/// power of two no finer than their own spacing subtract exactly in f64; and a box moved by a
/// multiple of the grid moves its origin by exactly as much, so it becomes the same f32
/// numbers. What is left is at most half a grid cell plus half the box: the corners stay
/// within 4.5 extents of zero, with f32 precision relative to the box's size.
fn box_object_origin(lo: DVec3, hi: DVec3) -> DVec3 {
    let extent = (hi - lo).max_element();
    if !(extent > 0.0 && lo.is_finite() && hi.is_finite()) {
        return DVec3::ZERO;
    }
    let mut grid = (BOX_SNAP_EXTENTS * extent).log2().ceil().exp2();
    if grid < BOX_SNAP_EXTENTS * extent {
        grid *= 2.0;
    }
    // floor(x + 0.5) rather than round(), whose ties go away from zero: moving a box by a
    // whole number of cells moves this by exactly that many, on either side of zero.
    ((lo + hi) * 0.5 / grid + 0.5).floor() * grid
}

/// Two unit vectors completing unit `w` to a right-handed orthonormal basis (u × v = w).
fn perpendiculars(w: DVec3) -> (DVec3, DVec3) {
    let helper = if w.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u = helper.cross(w).normalize();
    (u, w.cross(u))
}

/// Whether `m`'s linear part is a rotation times a uniform scale (a sphere stays a sphere).
fn uniform_scale(m: &DMat4) -> Option<f64> {
    let c = [m.x_axis.truncate(), m.y_axis.truncate(), m.z_axis.truncate()];
    let s = c[0].length();
    let ok = c.iter().all(|v| (v.length() - s).abs() <= 1e-9 * s)
        && c[0].dot(c[1]).abs() <= 1e-9 * s * s
        && c[1].dot(c[2]).abs() <= 1e-9 * s * s
        && c[0].dot(c[2]).abs() <= 1e-9 * s * s;
    ok.then_some(s)
}

/// Whether `m`'s linear part is diagonal (an axis-aligned box stays axis-aligned).
fn is_axis_aligned(m: &DMat4) -> bool {
    m.x_axis.y == 0.0
        && m.x_axis.z == 0.0
        && m.y_axis.x == 0.0
        && m.y_axis.z == 0.0
        && m.z_axis.x == 0.0
        && m.z_axis.y == 0.0
}

/// A blob component for the geometry: its form and strength, and its own transform as an
/// affine map into the blob's space.
fn blob_component(c: &BlobComponent) -> blob::Component {
    let shape = match c.shape {
        BlobShape::Sphere { center } => blob::ComponentShape::Sphere { center, radius: c.radius },
        BlobShape::Cylinder { base, cap } => blob::ComponentShape::Cylinder { base, cap, radius: c.radius },
    };
    blob::Component { shape, strength: c.strength, blob_from_component: DAffine3::from_mat4(c.transform.matrix) }
}
