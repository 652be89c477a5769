//! Shapes as written, each in its own object space.

use super::{ObjectDesc, Transform};
use glam::{DVec2, DVec3, DVec4};
use std::sync::Arc;

/// A shape in its own object space, as written.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeDesc {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// Points `p` with `normal · p = distance` (normal as written, not normalised).
    Plane {
        normal: DVec3,
        distance: f64,
    },
    Box {
        corner1: DVec3,
        corner2: DVec3,
    },
    Triangle {
        a: DVec3,
        b: DVec3,
        c: DVec3,
    },
    /// A closed, planar outline (first point repeated at the end is allowed and removed).
    Polygon {
        points: Vec<DVec3>,
    },
    /// `cylinder` (`base_radius == cap_radius`) or `cone`: the axis from `base` to `cap`.
    Cone {
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        /// No end caps.
        open: bool,
        /// Written as `cylinder` (for messages and printing).
        cylinder: bool,
    },
    /// A flat disc around `center` facing `normal`, with an optional hole (0: none).
    Disc {
        center: DVec3,
        normal: DVec3,
        radius: f64,
        hole: f64,
    },
    /// The ring of radius `major` in the xz-plane, swept by a circle of radius `minor`.
    Torus {
        major: f64,
        minor: f64,
    },
    /// `quadric`, `cubic`, `quartic` or `poly`: the zeros of a polynomial of `order` whose
    /// coefficients are in POV-Ray's `poly` order (x's power falling, then y's, then z's; see
    /// `geometry::poly::term_exponents`). A quadric is kept as its order-2 poly.
    Poly {
        order: usize,
        coefficients: Vec<f64>,
        sturm: bool,
        /// The keyword it was written with, for messages and printing.
        written: PolyForm,
    },
    /// `superellipsoid { <e, n> }` in the unit box.
    Superellipsoid {
        e: f64,
        n: f64,
    },
    /// Constructive solid geometry over `children` (each with its own transform, texture and
    /// `inverse`; the node's own transforms are already applied to them).
    Csg {
        op: CsgOp,
        children: Vec<ObjectDesc>,
    },
    /// Closed curves through `points` (x, z) swept along y from `h1` to `h2`, or towards the
    /// origin (`conic`); checked to close when lowered.
    Prism {
        spline: SplineKind,
        conic: bool,
        h1: f64,
        h2: f64,
        points: Vec<DVec2>,
        /// No caps.
        open: bool,
    },
    /// The spline through (r, y) `points` revolved around the y axis; checked when lowered.
    Lathe {
        spline: SplineKind,
        points: Vec<DVec2>,
    },
    /// `sor`: `r² = f(y)` through (r, y) `points` (checked when lowered), revolved around the
    /// y axis; `open` drops the end caps.
    Sor {
        points: Vec<DVec2>,
        open: bool,
    },
    /// `blob`: the surface where the components' fields sum to `threshold`.
    Blob {
        components: Vec<BlobComponent>,
        threshold: f64,
    },
    /// `julia_fractal`: the slice `slice.0 · h = slice.1` of the 4-D set whose orbits under
    /// `function` plus `param` stay bounded for `max_iteration` steps.
    ///
    /// The rare shapes' larger parts are boxed, here and below: an enum is as large as its
    /// largest variant, and every sphere of a million-sphere scene pays for it.
    Julia {
        param: Box<DVec4>,
        function: JuliaFunction,
        max_iteration: u32,
        precision: f64,
        slice: Box<(DVec4, f64)>,
    },
    /// `isosurface { function {..} contained_by {..} ... }`: where `function` (of x, y, z,
    /// compiled) equals the threshold, inside the container.
    Isosurface {
        function: Box<crate::function::Program>,
        container: Container,
        params: Box<IsoParams>,
    },
    /// `parametric { function {x(u, v)} function {y} function {z} <u1, v1>, <u2, v2> ... }`,
    /// the functions compiled; clipped to the container.
    Parametric {
        functions: Box<[crate::function::Program; 3]>,
        container: Container,
        params: Box<ParametricParams>,
    },
    /// `text { ttf "font" "string" thickness, offset }`: the glyph outlines, read from the font
    /// when lowered and placed along x (em = 1 unit, baseline y = 0), extruded from z = 0 to
    /// `thickness`.
    Text {
        /// The font file as found (for printing and messages).
        font: std::sync::Arc<str>,
        string: String,
        thickness: f64,
        offset: Box<DVec3>,
        glyphs: Box<[TextGlyph]>,
    },
    /// `mesh` or `mesh2` (POV-Ray 3.4.5.2.2–3): triangles in object space, shared (`Arc`) by
    /// every object made from one declaration, so N instances hold one copy. Without an
    /// `inside_vector` a mesh is not solid (nothing is inside it), as in POV-Ray.
    Mesh {
        mesh: Arc<MeshDesc>,
        inside_vector: Option<DVec3>,
    },
    /// `height_field { png "f.png" smooth water_level w }` (POV-Ray 3.4.5.1.6): the unit
    /// square x, z in [0, 1] with y the image's value in [0, 1]; parts below `water_level` are
    /// left out.
    HeightField {
        field: Arc<HeightFieldDesc>,
        smooth: bool,
        water_level: f64,
    },
}

/// A triangle mesh's vertices, normals and faces, as written (f64).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct MeshDesc {
    pub vertices: Vec<DVec3>,
    /// Vertex normals of smooth faces (not normalised; POV-Ray normalises them).
    pub normals: Vec<DVec3>,
    pub faces: Vec<MeshFace>,
    /// `uv_vectors`: texture coordinates, empty when the mesh gives none.
    pub uvs: Vec<glam::DVec2>,
    /// Each face's three indices into `uvs`, parallel to `faces` (empty without uvs).
    pub uv_faces: Vec<[u32; 3]>,
}

/// One triangle of a mesh: vertex indices, and normal indices for a smooth one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshFace {
    pub vertices: [u32; 3],
    pub normals: Option<[u32; 3]>,
}

/// A height field's image as heights in [0, 1], row 0 the image's top row.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct HeightFieldDesc {
    /// The file as found, and the type keyword it was read as (`png`, `pgm`, `ppm`, `tga`).
    pub file: String,
    pub format: String,
    pub width: u32,
    pub height: u32,
    /// `width * height` values, row by row.
    pub heights: Vec<f32>,
}

/// An isosurface's `contained_by` shape (object space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    Box { min: DVec3, max: DVec3 },
    Sphere { center: DVec3, radius: f64 },
}

/// The search parameters of an `isosurface` (POV-Ray's defaults).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IsoParams {
    pub threshold: f64,
    pub accuracy: f64,
    pub max_gradient: f64,
    /// No container walls where it cuts the solid.
    pub open: bool,
}

impl Default for IsoParams {
    fn default() -> Self {
        IsoParams { threshold: 0.0, accuracy: 0.001, max_gradient: 1.1, open: false }
    }
}

/// The (u, v) rectangle and search parameters of a `parametric`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParametricParams {
    pub lo: DVec2,
    pub hi: DVec2,
    pub accuracy: f64,
    pub max_gradient: f64,
}

/// How a polynomial surface was written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PolyForm {
    Quadric,
    Cubic,
    Quartic,
    Poly,
}

impl PolyForm {
    pub fn keyword(self) -> &'static str {
        match self {
            PolyForm::Quadric => "quadric",
            PolyForm::Cubic => "cubic",
            PolyForm::Quartic => "quartic",
            PolyForm::Poly => "poly",
        }
    }
}

/// How a CSG node combines its children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgOp {
    /// Every child's surface.
    Union,
    /// The union's surfaces that lie inside no other child.
    Merge,
    /// The surfaces of each child that lie inside all the others.
    Intersection,
    /// The first child's surface outside all the others, and theirs inside it.
    Difference,
    /// `clipped_by`: the first child's surface inside all the others (whose surfaces are not
    /// added).
    Clip,
}

impl CsgOp {
    pub fn keyword(self) -> &'static str {
        match self {
            CsgOp::Union => "union",
            CsgOp::Merge => "merge",
            CsgOp::Intersection => "intersection",
            CsgOp::Difference => "difference",
            CsgOp::Clip => "clipped_by",
        }
    }
}

/// One glyph's closed outlines in text space (x, y): quadratic Bézier pieces `[start, control,
/// end]`; a straight piece has its control point exactly halfway.
#[derive(Clone, Debug, PartialEq)]
pub struct TextGlyph {
    pub quads: Vec<[DVec2; 3]>,
}

/// One component of a `blob`: `strength · (1 − d²/radius²)²` within `radius` of a point or a
/// segment, in its own space under `transform` (within the blob's space).
#[derive(Clone, Debug, PartialEq)]
pub struct BlobComponent {
    pub shape: BlobShape,
    pub radius: f64,
    pub strength: f64,
    pub transform: Transform,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BlobShape {
    Sphere {
        center: DVec3,
    },
    /// Hemispheres close both ends.
    Cylinder {
        base: DVec3,
        cap: DVec3,
    },
}

impl ShapeDesc {
    /// The keyword POV-Ray uses for this shape, for statistics and messages.
    pub fn keyword(&self) -> &'static str {
        match self {
            ShapeDesc::Sphere { .. } => "sphere",
            ShapeDesc::Plane { .. } => "plane",
            ShapeDesc::Box { .. } => "box",
            ShapeDesc::Triangle { .. } => "triangle",
            ShapeDesc::Polygon { .. } => "polygon",
            ShapeDesc::Cone { cylinder: true, .. } => "cylinder",
            ShapeDesc::Cone { .. } => "cone",
            ShapeDesc::Disc { .. } => "disc",
            ShapeDesc::Torus { .. } => "torus",
            ShapeDesc::Csg { op, .. } => op.keyword(),
            ShapeDesc::Poly { written, .. } => written.keyword(),
            ShapeDesc::Superellipsoid { .. } => "superellipsoid",
            ShapeDesc::Prism { .. } => "prism",
            ShapeDesc::Text { .. } => "text",
            ShapeDesc::Lathe { .. } => "lathe",
            ShapeDesc::Sor { .. } => "sor",
            ShapeDesc::Blob { .. } => "blob",
            ShapeDesc::Julia { .. } => "julia_fractal",
            ShapeDesc::Mesh { .. } => "mesh",
            ShapeDesc::HeightField { .. } => "height_field",
            ShapeDesc::Isosurface { .. } => "isosurface",
            ShapeDesc::Parametric { .. } => "parametric",
        }
    }
}

/// Which algebra and function the iteration uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JuliaFunction {
    QuaternionSqr,
    QuaternionCube,
    Hypercomplex(ComplexFn),
}

/// The functions of hypercomplex numbers, each a complex function applied to both halves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ComplexFn {
    Sqr,
    Cube,
    Exp,
    Reciprocal,
    Sin,
    Asin,
    Sinh,
    Asinh,
    Cos,
    Acos,
    Cosh,
    Acosh,
    Tan,
    Atan,
    Tanh,
    Atanh,
    Ln,
    /// `h` to the complex power `x + y·i`.
    Pwr(f64, f64),
}

/// The functions with a keyword of their own, and the keywords.
const NAMED: [(ComplexFn, &str); 17] = [
    (ComplexFn::Sqr, "sqr"),
    (ComplexFn::Cube, "cube"),
    (ComplexFn::Exp, "exp"),
    (ComplexFn::Reciprocal, "reciprocal"),
    (ComplexFn::Sin, "sin"),
    (ComplexFn::Asin, "asin"),
    (ComplexFn::Sinh, "sinh"),
    (ComplexFn::Asinh, "asinh"),
    (ComplexFn::Cos, "cos"),
    (ComplexFn::Acos, "acos"),
    (ComplexFn::Cosh, "cosh"),
    (ComplexFn::Acosh, "acosh"),
    (ComplexFn::Tan, "tan"),
    (ComplexFn::Atan, "atan"),
    (ComplexFn::Tanh, "tanh"),
    (ComplexFn::Atanh, "atanh"),
    (ComplexFn::Ln, "ln"),
];

impl ComplexFn {
    /// The function named by POV-Ray's keyword (`pwr` takes its exponent separately).
    pub fn from_keyword(word: &str) -> Option<ComplexFn> {
        NAMED.iter().find(|n| n.1 == word).map(|n| n.0)
    }

    /// The keyword `from_keyword` reads, `None` for `pwr` (written with its exponent).
    pub fn keyword(self) -> Option<&'static str> {
        NAMED.iter().find(|n| n.0 == self).map(|n| n.1)
    }
}

/// How points connect, as POV-Ray's spline keywords name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    Linear,
    Quadratic,
    Cubic,
    Bezier,
}

impl SplineKind {
    pub fn keyword(self) -> &'static str {
        match self {
            SplineKind::Linear => "linear_spline",
            SplineKind::Quadratic => "quadratic_spline",
            SplineKind::Cubic => "cubic_spline",
            SplineKind::Bezier => "bezier_spline",
        }
    }

    pub fn from_keyword(word: &str) -> Option<SplineKind> {
        Some(match word {
            "linear_spline" => SplineKind::Linear,
            "quadratic_spline" => SplineKind::Quadratic,
            "cubic_spline" => SplineKind::Cubic,
            "bezier_spline" => SplineKind::Bezier,
            _ => return None,
        })
    }
}
