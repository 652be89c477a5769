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
    /// The projection and focal blur (`crate::camera::lens`).
    pub lens: crate::camera::Lens,
    /// Whether the camera statement gave `up` or `right` (an orthographic camera without
    /// either takes its view size from the perspective camera it replaces).
    pub up_or_right_given: bool,
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
            lens: Default::default(),
            up_or_right_given: false,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightDesc {
    pub position: DVec3,
    pub color: DVec3,
    /// `shadowless`: the light illuminates but casts no shadows (no shadow rays are traced).
    pub shadowless: bool,
    /// Point (the default), `spotlight` or `cylinder`.
    pub kind: LightKind,
    /// `point_at`: where a spotlight, cylinder or parallel light points (default the origin).
    pub point_at: DVec3,
    /// `radius`, `falloff`, `tightness` as written: degrees for a spotlight, units from the axis
    /// for a cylinder. `None`: the kind's default (`LightDesc::spot_params`).
    pub radius: Option<f64>,
    pub falloff: Option<f64>,
    pub tightness: Option<f64>,
    /// `parallel`: every ray of the light travels along `point_at - position`.
    pub parallel: bool,
    /// `fade_distance` (0: no fading) and `fade_power`.
    pub fade_distance: f64,
    pub fade_power: f64,
    /// `area_light`: soft shadows from a grid of point lights.
    pub area: Option<AreaLightDesc>,
    /// `media_interaction`, `media_attenuation`: kept as written; strahl models no media.
    pub media_interaction: bool,
    pub media_attenuation: bool,
}

impl Default for LightDesc {
    /// A white point light at the origin, as POV-Ray's defaults.
    fn default() -> Self {
        LightDesc {
            position: DVec3::ZERO,
            color: DVec3::ONE,
            shadowless: false,
            kind: LightKind::Point,
            point_at: DVec3::ZERO,
            radius: None,
            falloff: None,
            tightness: None,
            parallel: false,
            fade_distance: 0.0,
            fade_power: 0.0,
            area: None,
            media_interaction: true,
            media_attenuation: false,
        }
    }
}

impl LightDesc {
    /// `(radius, falloff, tightness)` with the kind's defaults (POV-Ray 3.7: spotlight 30, 45, 0
    /// degrees; cylinder 0.75, 1, 0 units).
    pub fn spot_params(&self) -> (f64, f64, f64) {
        let (r, f) = match self.kind {
            LightKind::Cylinder => (0.75, 1.0),
            _ => (30.0, 45.0),
        };
        (self.radius.unwrap_or(r), self.falloff.unwrap_or(f), self.tightness.unwrap_or(0.0))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    Point,
    Spot,
    Cylinder,
}

/// `area_light <axis1>, <axis2>, size1, size2 [adaptive N] [jitter] [circular] [orient]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLightDesc {
    pub axis1: DVec3,
    pub axis2: DVec3,
    /// Rows and columns of point lights (at least 1 each).
    pub size1: u32,
    pub size2: u32,
    /// `adaptive N`: corner-first subdivision with at least N levels; `None`: every point.
    pub adaptive: Option<u32>,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalSettings {
    /// `None` when the scene did not say; the effective value then depends on `#version`.
    pub assumed_gamma: Option<f64>,
    pub max_trace_level: u32,
    pub ambient_light: DVec3,
    /// `noise_generator` 1, 2 or 3 (POV-Ray 3.7's default is 2): which noise patterns use.
    pub noise_generator: u32,
    /// `number_of_waves`: how many centres `waves` and `ripples` sum (POV-Ray's default 10).
    pub number_of_waves: u32,
    /// `irid_wavelength`: the wavelengths (as a colour) `irid` interferes at.
    pub irid_wavelength: DVec3,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            assumed_gamma: None,
            max_trace_level: 5,
            ambient_light: DVec3::ONE,
            noise_generator: 2,
            number_of_waves: 10,
            irid_wavelength: DVec3::new(0.25, 0.18, 0.14),
        }
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
    /// Any other pattern's value looked up in a colour map.
    Mapped(PatternDesc, Vec<ColorMapEntry>),
    /// `pigment_map`: the pattern's value blends the pigments of the two entries around it
    /// (sorted by value).
    PigmentMap(PatternDesc, Vec<(f64, PigmentDesc)>),
    /// A list pattern (`checker`, `hexagon`, `brick`) picking one pigment per cell.
    List(PatternDesc, Vec<PigmentDesc>),
    /// Layered textures' pigments, bottom first: each upper layer shows what is below it
    /// through its filter and transmit.
    Layered(Vec<PigmentDesc>),
}

/// The pattern functions (`shading::patterns`), with their own parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PatternKind {
    /// `gradient V`: V is normalised.
    Gradient(DVec3),
    /// `bozo`, `spotted` and `bumps` as a pigment: noise.
    Bozo,
    Granite,
    Marble,
    Agate {
        turb: f64,
    },
    Crackle {
        form: DVec3,
        metric: f64,
        offset: f64,
        solid: bool,
    },
    Cells,
    Wrinkles,
    Dents,
    Leopard,
    Ripples,
    Waves,
    Radial,
    Onion,
    Spiral1(f64),
    Spiral2(f64),
    /// Values 0 (mortar) and 1 (brick).
    Brick {
        size: DVec3,
        mortar: f64,
    },
    /// Values 0, 1, 2.
    Hexagon,
    /// Values 0, 1.
    Checker,
    Boxed,
    Cylindrical,
    Spherical,
    Planar,
    Quilted {
        c0: f64,
        c1: f64,
    },
    Mandel(u32),
    /// Raw ring value `frac(r)` (its default wave is the triangle).
    Wood,
    /// `average`: a `pigment_map`'s pigments averaged, weighted by their entry values.
    Average,
}

impl PatternKind {
    /// How many pigments a list pattern picks from; `None` for a continuous pattern.
    pub fn list_len(&self) -> Option<usize> {
        match self {
            PatternKind::Checker | PatternKind::Brick { .. } => Some(2),
            PatternKind::Hexagon => Some(3),
            _ => None,
        }
    }
}

/// How a pattern's value in [0, 1) is shaped after `frequency` and `phase`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Wave {
    Ramp,
    Triangle,
    Sine,
    Scallop,
    Cubic,
    Poly(f64),
}

/// One `warp { }` of a pattern, applied in pattern space in written order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warp {
    Turbulence(Turbulence),
    /// `warp { repeat V offset O flip F }`: V has one non-zero component, the period.
    Repeat {
        dir: DVec3,
        offset: DVec3,
        flip: DVec3,
    },
    BlackHole {
        center: DVec3,
        radius: f64,
        strength: f64,
        falloff: f64,
        inverse: bool,
    },
}

/// A pattern with its value modifiers; the transform and classic turbulence live with the
/// pigment or normal that uses it.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternDesc {
    pub kind: PatternKind,
    pub wave: Wave,
    pub frequency: f64,
    pub phase: f64,
    pub warps: Vec<Warp>,
}

impl PatternDesc {
    pub fn new(kind: PatternKind) -> PatternDesc {
        let wave = match kind {
            PatternKind::Marble | PatternKind::Wood => Wave::Triangle,
            _ => Wave::Ramp,
        };
        PatternDesc { kind, wave, frequency: 1.0, phase: 0.0, warps: Vec::new() }
    }
}

impl PigmentDesc {
    /// Moves the pigment, and every pigment it is made of, by `tr` (applied after its own).
    pub fn transform_by(&mut self, tr: &Transform) {
        self.transform = self.transform.then(tr);
        match &mut self.pattern {
            PigmentPattern::PigmentMap(_, entries) => entries.iter_mut().for_each(|(_, p)| p.transform_by(tr)),
            PigmentPattern::List(_, list) | PigmentPattern::Layered(list) => {
                list.iter_mut().for_each(|p| p.transform_by(tr))
            }
            _ => {}
        }
    }

    /// Whether the pigment is a single colour that needs no pattern work.
    pub fn is_solid(&self) -> bool {
        matches!(self.pattern, PigmentPattern::Solid(_))
    }
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
    /// Any other pattern: the normal tilts by `amount` times the pattern's gradient.
    Pattern(PatternDesc, f64),
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
    /// The reflection seen along the normal's direction... or everywhere when `reflection_min`
    /// is `None`; with a minimum, this is the maximum, seen at grazing angles.
    pub reflection: DVec3,
    /// `metallic`: how far highlights take the pigment's colour (0 to 1).
    pub metallic: f64,
    /// `emission`: light the surface gives off, like `ambient` but not scaled by
    /// `ambient_light`.
    pub emission: DVec3,
    /// `reflection { MIN, MAX .. }`: the reflection along the normal; `None` for constant.
    pub reflection_min: Option<DVec3>,
    /// `falloff`: the exponent of (1 − cos θ) from the minimum to the maximum.
    pub reflection_falloff: f64,
    /// `fresnel`: the Fresnel reflectance (from the interior's ior) blends minimum to maximum.
    pub reflection_fresnel: bool,
    /// `exponent` (`reflection_exponent`): reflected light is raised to 1 / this power.
    pub reflection_exponent: f64,
    /// `metallic` in `reflection { }`: how far reflections take the pigment's colour.
    pub reflection_metallic: f64,
    /// `conserve_energy`: filter and transmit are scaled by what reflection leaves.
    pub conserve_energy: bool,
    /// `diffuse albedo`, `phong albedo`, `specular albedo`: those amounts are total
    /// reflectances, turned into peak values by `scene::material::Finish`.
    pub albedo: Albedo,
}

/// Which of `diffuse`, `phong` and `specular` were given with `albedo`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Albedo {
    pub diffuse: bool,
    pub phong: bool,
    pub specular: bool,
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
            metallic: 0.0,
            emission: DVec3::ZERO,
            reflection_min: None,
            reflection_falloff: 1.0,
            reflection_fresnel: false,
            reflection_exponent: 1.0,
            reflection_metallic: 0.0,
            conserve_energy: false,
            albedo: Albedo::default(),
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

/// `sky_sphere { pigment.. [transform] [emission C] }`: pigments evaluated on the unit ray
/// direction, layered (the first written is the bottom layer).
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphereDesc {
    /// Bottom layer first; each pigment's transform includes the sky sphere's own.
    pub pigments: Vec<PigmentDesc>,
    pub emission: DVec3,
}

/// `fog { fog_type distance color fog_offset fog_alt up turbulence .. }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogDesc {
    /// 1: constant, 2: ground fog.
    pub fog_type: u32,
    pub distance: f64,
    pub color: Color,
    pub offset: f64,
    pub alt: f64,
    /// Unit up direction of ground fog (rotated by the fog's transforms).
    pub up: DVec3,
    /// `turbulence`: parsed; strahl's fog is smooth (warned once).
    pub turbulence: DVec3,
}

impl Default for FogDesc {
    fn default() -> Self {
        FogDesc {
            fog_type: 1,
            distance: 0.0,
            color: Color::BLACK,
            offset: 0.0,
            alt: 0.0,
            up: DVec3::Y,
            turbulence: DVec3::ZERO,
        }
    }
}

/// `rainbow { direction angle width distance jitter up arc_angle falloff_angle color_map }`.
#[derive(Clone, Debug, PartialEq)]
pub struct RainbowDesc {
    pub direction: DVec3,
    /// Degrees.
    pub angle: f64,
    pub width: f64,
    pub distance: f64,
    pub jitter: f64,
    pub up: DVec3,
    pub arc_angle: f64,
    pub falloff_angle: f64,
    pub color_map: Vec<ColorMapEntry>,
}

impl Default for RainbowDesc {
    fn default() -> Self {
        RainbowDesc {
            direction: DVec3::Z,
            angle: 0.0,
            width: 0.0,
            distance: 1e7,
            jitter: 0.0,
            up: DVec3::Y,
            arc_angle: 180.0,
            falloff_angle: 180.0,
            color_map: Vec::new(),
        }
    }
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
    /// `sky_sphere { pigment.. }`: seen where rays miss (`scene::atmosphere`).
    pub sky_sphere: Option<SkySphereDesc>,
    /// `fog { .. }` layers, in scene order.
    pub fogs: Vec<FogDesc>,
    /// `rainbow { .. }`s, in scene order.
    pub rainbows: Vec<RainbowDesc>,
    pub global: GlobalSettings,
    pub objects: Vec<ObjectDesc>,
    /// The scene's `light_group`s; empty when it has none (every light lights everything).
    pub light_groups: Vec<LightGroupDesc>,
    /// Every file `#include` read, in order, with the directive that read it (for the
    /// statistics: which `colors.inc` a scene got).
    pub included: Vec<IncludedFile>,
    /// Rendering features the scene asks for that strahl does not model (`radiosity`, `media`,
    /// `photons`...), each named once, where it first appears: for the statistics and the HUD.
    pub unmodelled: Vec<UnmodelledFeature>,
}

/// A feature the scene uses that strahl renders without (the rest of the scene renders).
#[derive(Clone, Debug, PartialEq)]
pub struct UnmodelledFeature {
    /// The feature as the scene writes it (`radiosity`, `media`, `photons`).
    pub name: String,
    pub at: SourceRef,
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
            sky_sphere: None,
            fogs: Vec::new(),
            rainbows: Vec::new(),
            global: GlobalSettings::default(),
            objects: Vec::new(),
            light_groups: Vec::new(),
            included: Vec::new(),
            unmodelled: Vec::new(),
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
