//! The scene as written: plain f64 data produced by `pov::lower`, consumed by `scene::build`.
//!
//! Nothing here knows about tokens, BVHs or rays. Every value is in POV-Ray's units and
//! left-handed world space exactly as the scene file states it; transforms are kept as matrices so
//! that `build` can fold them into render-ready f32 data relative to the camera.

use std::sync::Arc;

use glam::{DMat4, DVec2, DVec3, DVec4};

pub use crate::geometry::julia::{ComplexFn, JuliaFunction};
pub use crate::geometry::spline::SplineKind;

/// A POV-Ray colour: red, green, blue, filter, transmit.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Color {
    pub rgb: DVec3,
    /// Fraction of light that passes through, tinted by `rgb`.
    pub filter: f64,
    /// Fraction of light that passes through untinted.
    pub transmit: f64,
}

impl Color {
    pub const BLACK: Color = Color { rgb: DVec3::ZERO, filter: 0.0, transmit: 0.0 };
    pub const WHITE: Color = Color { rgb: DVec3::ONE, filter: 0.0, transmit: 0.0 };

    pub fn rgb(r: f64, g: f64, b: f64) -> Color {
        Color { rgb: DVec3::new(r, g, b), filter: 0.0, transmit: 0.0 }
    }
}

/// An affine transform, stored both ways so nobody inverts on the per-ray path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Maps points from the local (object or pattern) space into the space above it.
    pub matrix: DMat4,
    /// The inverse of `matrix`.
    pub inverse: DMat4,
}

impl Default for Transform {
    fn default() -> Self {
        Transform { matrix: DMat4::IDENTITY, inverse: DMat4::IDENTITY }
    }
}

impl Transform {
    /// `then` is applied after `self` (POV-Ray's order: modifiers compose left to right).
    pub fn then(&self, then: &Transform) -> Transform {
        Transform { matrix: then.matrix * self.matrix, inverse: self.inverse * then.inverse }
    }

    pub fn is_identity(&self) -> bool {
        self.matrix == DMat4::IDENTITY
    }
}

/// `camera { ... }` after all its modifiers; vectors as POV-Ray holds them before `look_at`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraDesc {
    pub location: DVec3,
    /// Final viewing direction; its length sets the field of view unless `angle` is given.
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    pub sky: DVec3,
    /// `look_at`, if given (already applied to direction/right/up by `lower`).
    pub look_at: Option<DVec3>,
    /// Horizontal field of view in degrees, if given.
    pub angle: Option<f64>,
}

impl Default for CameraDesc {
    fn default() -> Self {
        CameraDesc {
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            sky: DVec3::Y,
            look_at: None,
            angle: None,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightDesc {
    pub position: DVec3,
    pub color: DVec3,
    /// `shadowless`: the light illuminates but casts no shadows (no shadow rays are traced).
    pub shadowless: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalSettings {
    /// `None` when the scene did not say; the effective value then depends on `#version`.
    pub assumed_gamma: Option<f64>,
    pub max_trace_level: u32,
    pub ambient_light: DVec3,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings { assumed_gamma: None, max_trace_level: 5, ambient_light: DVec3::ONE }
    }
}

/// Turbulence (`turbulence`, `octaves`, `omega`, `lambda`) of a pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turbulence {
    pub amount: DVec3,
    pub octaves: u32,
    pub omega: f64,
    pub lambda: f64,
}

impl Default for Turbulence {
    /// POV-Ray's defaults once `turbulence` is given: octaves 6, omega 0.5, lambda 2.
    fn default() -> Self {
        Turbulence { amount: DVec3::ZERO, octaves: 6, omega: 0.5, lambda: 2.0 }
    }
}

/// One `[value color]` entry of a `color_map`; entries are sorted by value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColorMapEntry {
    pub value: f64,
    pub color: Color,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PigmentPattern {
    Solid(Color),
    Checker(Color, Color),
    /// Rings around the pattern-space z axis, looked up in the map.
    Wood(Vec<ColorMapEntry>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct PigmentDesc {
    pub pattern: PigmentPattern,
    /// `None` when the pattern has no turbulence.
    pub turbulence: Option<Turbulence>,
    /// Pattern space → world space (accumulates the pigment's own and its object's transforms).
    pub transform: Transform,
}

impl Default for PigmentDesc {
    /// POV-Ray's default pigment is black.
    fn default() -> Self {
        PigmentDesc { pattern: PigmentPattern::Solid(Color::BLACK), turbulence: None, transform: Transform::default() }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum NormalPattern {
    /// `bumps AMOUNT`.
    Bumps(f64),
}

#[derive(Clone, Debug, PartialEq)]
pub struct NormalDesc {
    pub pattern: NormalPattern,
    pub turbulence: Option<Turbulence>,
    /// Pattern space → world space.
    pub transform: Transform,
}

/// `finish { ... }` with POV-Ray 3.7's defaults.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FinishDesc {
    pub ambient: DVec3,
    pub diffuse: f64,
    pub brilliance: f64,
    pub phong: f64,
    pub phong_size: f64,
    pub specular: f64,
    pub roughness: f64,
    pub reflection: DVec3,
}

impl Default for FinishDesc {
    fn default() -> Self {
        FinishDesc {
            ambient: DVec3::splat(0.1),
            diffuse: 0.6,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            reflection: DVec3::ZERO,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Default)]
pub struct TextureDesc {
    pub pigment: PigmentDesc,
    pub normal: Option<NormalDesc>,
    pub finish: FinishDesc,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InteriorDesc {
    pub ior: f64,
}

impl Default for InteriorDesc {
    fn default() -> Self {
        InteriorDesc { ior: 1.0 }
    }
}

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
    Julia {
        param: DVec4,
        function: JuliaFunction,
        max_iteration: u32,
        precision: f64,
        slice: (DVec4, f64),
    },
    /// `isosurface { function {..} contained_by {..} ... }`: where `function` (of x, y, z,
    /// compiled) equals the threshold, inside the container.
    Isosurface {
        function: crate::function::Program,
        container: Container,
        params: IsoParams,
    },
    /// `parametric { function {x(u, v)} function {y} function {z} <u1, v1>, <u2, v2> ... }`,
    /// the functions compiled; clipped to the container.
    Parametric {
        functions: [crate::function::Program; 3],
        container: Container,
        params: ParametricParams,
    },
    /// `text { ttf "font" "string" thickness, offset }`: the glyph outlines, read from the font
    /// when lowered and placed along x (em = 1 unit, baseline y = 0), extruded from z = 0 to
    /// `thickness`.
    Text {
        /// The font file as found (for printing and messages).
        font: String,
        string: String,
        thickness: f64,
        offset: DVec3,
        glyphs: Vec<TextGlyph>,
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

/// Where in the scene files something was written, for messages after parsing.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct SourceRef {
    pub file: String,
    pub line: u32,
    pub col: u32,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ObjectDesc {
    pub shape: ShapeDesc,
    /// Object space → world space.
    pub transform: Transform,
    pub texture: TextureDesc,
    pub interior: InteriorDesc,
    /// `no_shadow`: the object is visible but casts no shadow (shadow rays ignore it).
    pub no_shadow: bool,
    /// `inverse`: inside and outside swap, for an enclosing CSG (and its normal points in).
    pub inverse: bool,
    /// `hollow`: the inside may hold media. Kept as written; nothing that strahl renders yet
    /// depends on it (in POV-Ray only media and fog inside objects do).
    pub hollow: bool,
    /// The innermost `light_group` the object belongs to (an index into
    /// `SceneDesc::light_groups`), or `None`: lit by the scene's global lights only.
    pub light_group: Option<u32>,
    pub source: SourceRef,
}

/// A `light_group` (POV-Ray 3.4.4.2): its lights (indices into `SceneDesc::lights`) light only
/// the objects of the group and of the groups inside it; the scene's global lights (those in no
/// group) light them too when `global_lights` is on.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct LightGroupDesc {
    pub lights: Vec<u32>,
    pub global_lights: bool,
    /// The group this one is written in: its lights light this group's objects too.
    pub parent: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SceneDesc {
    /// The language version in effect at the end of parsing (`#version`, or 3.7 when none).
    pub version: f64,
    /// Whether any `#version` directive ran (an included `colors.inc` runs one). POV-Ray 3.7
    /// treats a scene without one as legacy for gamma: no `assumed_gamma`, linear output.
    pub version_directive: bool,
    pub camera: CameraDesc,
    pub lights: Vec<LightDesc>,
    /// `background { color C }`; black by default.
    pub background: Color,
    pub global: GlobalSettings,
    pub objects: Vec<ObjectDesc>,
    /// The scene's `light_group`s; empty when it has none (every light lights everything).
    pub light_groups: Vec<LightGroupDesc>,
    /// Every file `#include` read, in order, with the directive that read it (for the
    /// statistics: which `colors.inc` a scene got).
    pub included: Vec<IncludedFile>,
}

/// A file an `#include` read: where it was found, and where the directive stands.
#[derive(Clone, Debug, PartialEq)]
pub struct IncludedFile {
    pub path: String,
    pub from: SourceRef,
}

impl Default for SceneDesc {
    fn default() -> Self {
        SceneDesc {
            version: 3.7,
            version_directive: false,
            camera: CameraDesc::default(),
            lights: Vec::new(),
            background: Color::BLACK,
            global: GlobalSettings::default(),
            objects: Vec::new(),
            light_groups: Vec::new(),
            included: Vec::new(),
        }
    }
}

impl SceneDesc {
    /// How computed colours become output values, as POV-Ray 3.7 does it (checked by rendering):
    /// `Some(g)`: raised to the power `g` (`assumed_gamma`), then sRGB-encoded; `None`: written
    /// as they are (a legacy scene without `assumed_gamma`). A scene whose `#version` directive
    /// says 3.7 or later and gives no `assumed_gamma` gets 1.0; one with no directive at all
    /// is legacy.
    pub fn output_gamma(&self) -> Option<f64> {
        match self.global.assumed_gamma {
            Some(g) => Some(g),
            None if self.version_directive && self.version >= 3.7 - 1e-9 => Some(1.0),
            None => None,
        }
    }

    /// Which of `lights` light the objects of `group` (`None`: objects in no group), or `None`
    /// when the scene has no light groups and every light lights everything.
    pub fn light_mask(&self, group: Option<u32>) -> Option<Vec<bool>> {
        if self.light_groups.is_empty() {
            return None;
        }
        let mut grouped = vec![false; self.lights.len()];
        for g in &self.light_groups {
            for &l in &g.lights {
                grouped[l as usize] = true;
            }
        }
        let global = group.is_none_or(|g| self.light_groups[g as usize].global_lights);
        let mut mask: Vec<bool> = grouped.iter().map(|&in_group| global && !in_group).collect();
        // The group's own lights and those of the groups around it (bounded: a chain of
        // parents cannot be longer than the number of groups).
        let mut at = group;
        for _ in 0..self.light_groups.len() {
            let Some(g) = at else { break };
            let g = &self.light_groups[g as usize];
            for &l in &g.lights {
                mask[l as usize] = true;
            }
            at = g.parent;
        }
        Some(mask)
    }

    /// Whether output pixels are sRGB-encoded.
    pub fn writes_srgb(&self) -> bool {
        self.output_gamma().is_some()
    }
}
