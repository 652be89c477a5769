//! Syntax tree of one scene item: what was written, with a span on every node. Declared names
//! are resolved as they are read (`ExprKind::Value`); `lower` evaluates the rest.

use std::rc::Rc;

use super::source::Span;
use super::value::Value;
pub use crate::desc::CsgOp;

/// An item of the scene as the parser hands it to `lower`; directives never get here, the
/// token stream runs them (`parser::directives`).
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    Camera {
        items: Vec<CameraItem>,
        span: Span,
    },
    Light(Light),
    Background {
        color: Expr,
        span: Span,
    },
    GlobalSettings {
        items: Vec<GlobalItem>,
        span: Span,
    },
    Object(Object),
    /// `sky_sphere`, `fog`, `rainbow`.
    Atmosphere(Atmosphere),
    /// Atmospheric `media { }`: skipped, warned about.
    Media(Span),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AtmosphereKind {
    SkySphere,
    Fog,
    Rainbow,
}

impl AtmosphereKind {
    pub fn keyword(self) -> &'static str {
        match self {
            AtmosphereKind::SkySphere => "sky_sphere",
            AtmosphereKind::Fog => "fog",
            AtmosphereKind::Rainbow => "rainbow",
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Atmosphere {
    pub kind: AtmosphereKind,
    pub items: Vec<AtmoItem>,
    pub span: Span,
}

/// One item of an atmosphere block, in written order.
#[derive(Clone, Debug, PartialEq)]
pub enum AtmoItem {
    /// `keyword value` (the keyword as listed in `parser::atmosphere`), with the keyword's span.
    Value(&'static str, Expr, Span),
    Color(Expr),
    Pigment(Pigment),
    ColorMap(ColorMap),
    Transform(TransformItem),
}

/// One block of `#default { ... }`.
#[derive(Clone, Debug, PartialEq)]
pub enum DefaultItem {
    Texture(Texture),
    Pigment(Pigment),
    Normal(Normal),
    Finish(Finish),
}

/// The right-hand side of `#declare Name = ...`.
#[derive(Clone, Debug, PartialEq)]
pub enum DeclValue {
    Expr(Expr),
    Pigment(Pigment),
    Normal(Normal),
    Finish(Finish),
    Texture(Texture),
    Interior(Interior),
    Material(Material),
    ColorMap(ColorMap),
    /// `#declare S = slope_map { .. }`.
    SlopeMap(SlopeMapBody),
    Object(Object),
    Camera(Vec<CameraItem>),
    Light(Light),
    /// `#declare S = sky_sphere { .. }` (or fog, rainbow): its items, for a block that names
    /// it to start from.
    Atmosphere(Atmosphere),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    /// Comparisons and logic give 1 or 0; POV-Ray only parses them inside parentheses.
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
}

/// A value POV-Ray's renderer provides: image size and animation state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    ImageWidth,
    ImageHeight,
    Clock,
    ClockDelta,
    FrameNumber,
    InitialClock,
    FinalClock,
    InitialFrame,
    FinalFrame,
    ClockOn,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Number(f64),
    /// A built-in vector constant (`x`, `y`, `z`).
    Vector3([f64; 3]),
    /// A name that was not declared where it was read: an error if it is evaluated (the
    /// parser may still find that it was a misspelt keyword instead).
    Ident(String),
    /// A declared name, resolved where it was read (as POV-Ray does: a macro's locals are gone
    /// by the time the object it built is lowered).
    Value(Rc<Value>),
    /// `<a, b, ...>` with 2 to 5 components.
    Vector(Vec<Expr>),
    Neg(Box<Expr>),
    /// `!a`: 1 when `a` is (within epsilon) zero, else 0.
    Not(Box<Expr>),
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `c ? a : b` (only inside parentheses).
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `v.x`, `c.red`, ...: one component, by index into (x, y, z, filter, transmit).
    Member(Box<Expr>, usize),
    Builtin(Builtin),
    /// A built-in function such as `sqrt(x)`.
    Call(String, Vec<Expr>),
    /// The `version` keyword: the language version in effect.
    Version,
    /// `color rgb <..> filter F ...`: items applied left to right to black.
    Color(Vec<ColorItem>),
}

/// One part of a colour written with keywords.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorKey {
    /// A colour-valued expression (declared name, vector, arithmetic) that replaces the colour.
    Base,
    Rgb,
    Rgbf,
    Rgbt,
    Rgbft,
    Red,
    Green,
    Blue,
    Filter,
    Transmit,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ColorItem {
    pub key: ColorKey,
    pub value: Expr,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransformKind {
    Rotate,
    Scale,
    Translate,
    /// `matrix <..12..>`, `transform { ... }` or `transform T`: the value is a
    /// `Value::Transform` (composed when read, as the parser reads every block's names).
    Transform,
}

#[derive(Clone, Debug, PartialEq)]
pub struct TransformItem {
    pub kind: TransformKind,
    pub value: Expr,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum CameraItem {
    /// `camera { C ... }`: start from declared camera `C` (only as the first item).
    Declared(Expr),
    Location(Expr),
    LookAt(Expr),
    Angle(Expr),
    Right(Expr),
    Up(Expr),
    Direction(Expr),
    Sky(Expr),
    Transform(TransformItem),
    /// The projection keyword (`orthographic`, `cylinder 2`, ...).
    Projection(CameraProjection, Span),
    /// `angle H V`'s second value (spherical cameras' vertical angle).
    AngleV(Expr),
    Aperture(Expr),
    /// `blur_samples [min,] max`.
    BlurSamples(Option<Expr>, Expr),
    FocalPoint(Expr),
    Confidence(Expr),
    Variance(Expr),
    /// Read in full but not modelled (`bokeh { }`): a warning names it.
    Unmodelled(&'static str, Span),
    /// `normal { .. }`: perturbs the eye rays (`render::RayGen`).
    Normal(Normal),
    /// `mesh_camera { .. }`, its numbers evaluated and its meshes looked up as it was read.
    MeshCamera(std::sync::Arc<crate::desc::MeshCameraDesc>, Span),
    /// `smooth` in the camera's body (POV-Ray's grammar puts it there; the samples write it
    /// inside `mesh_camera`).
    Smooth(Span),
}

#[derive(Clone, Debug, PartialEq)]
pub enum CameraProjection {
    Perspective,
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    /// `cylinder N`, N in 1..=4.
    Cylinder(Expr),
    Spherical,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub position: Expr,
    pub color: Option<Expr>,
    pub shadowless: bool,
    /// Light modifiers and transforms in written order (a transform moves what was given
    /// before it: position, `point_at`, area axes).
    pub items: Vec<LightItem>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum LightItem {
    /// `spotlight`, `cylinder`, `parallel`.
    Kind(&'static str, Span),
    /// `point_at`, `radius`, `falloff`, `tightness`, `fade_distance`, `fade_power`, `adaptive`.
    Value(&'static str, Expr, Span),
    /// `jitter`, `circular`, `orient`, `media_interaction`, `media_attenuation`,
    /// `area_illumination`, each with its optional boolean.
    Flag(&'static str, Option<Expr>, Span),
    AreaLight {
        axis1: Expr,
        axis2: Expr,
        size1: Expr,
        size2: Expr,
        span: Span,
    },
    LooksLike(Box<Object>, Span),
    /// `projected_through { .. }`: skipped, warned about.
    ProjectedThrough(Span),
    Transform(TransformItem),
}

#[derive(Clone, Debug, PartialEq)]
pub enum GlobalItem {
    AssumedGamma(Expr),
    MaxTraceLevel(Expr),
    AmbientLight(Expr),
    NoiseGenerator(Expr),
    NumberOfWaves(Expr),
    IridWavelength(Expr),
    /// `adc_bailout F`: strahl's bailout is fixed at 1/255; a different one is noted.
    AdcBailout(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Turb {
    pub kind: TurbKind,
    pub value: Expr,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TurbKind {
    Turbulence,
    Octaves,
    Omega,
    Lambda,
}

/// One `[value color]` point of a colour map. POV-Ray's older band `[a, b color C1 color C2]`
/// is read as the two points it stands for, `(a, C1)` and `(b, C2)`, both spanning the bracket.
#[derive(Clone, Debug, PartialEq)]
pub struct MapEntry {
    pub value: Expr,
    pub color: Expr,
    pub span: Span,
}

/// What a `color_map { ... }` block holds: its own entries, or the name of a declared map.
#[derive(Clone, Debug, PartialEq)]
pub enum ColorMapBody {
    Entries(Vec<MapEntry>),
    Named(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub struct ColorMap {
    pub body: ColorMapBody,
    /// The `color_map` keyword.
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PigmentItem {
    /// A leading identifier (declared pigment) or colour expression.
    Base(Expr),
    /// `color C` / `rgb ...`.
    Color(Expr),
    /// `checker C1 C2`; colours optional.
    Checker(Vec<Expr>, Span),
    Wood(Span),
    ColorMap(ColorMap),
    Turb(Turb),
    Transform(TransformItem),
    /// Any other pattern (`gradient x`, `brick C1 C2`, `checker pigment {..} pigment {..}`).
    Pattern(PatternAst),
    Mod(PatternMod),
    /// `pigment_map { [v pigment {..}] ... }`.
    PigmentMap(Vec<(Expr, Pigment)>, Span),
    /// `image_map { }`, read (and its file decoded) as it is parsed, as `height_field` is.
    ImageMap(std::sync::Arc<crate::desc::ImageMapDesc>, Span),
    /// `image_pattern { }` as the pigment's pattern.
    ImagePattern(std::sync::Arc<crate::desc::ImageMapDesc>, Span),
    /// `uv_mapping`: the pigment follows the surface's (u, v) (`TextureDesc::uv_mapping`).
    UvMapping(Span),
}

/// A pattern keyword with its argument and, for list patterns, what each cell shows.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternAst {
    pub name: String,
    /// `gradient V`, `spiral1 N`, `mandel N` (a fractal's iterations).
    pub arg: Option<Expr>,
    /// Further arguments: `julia C` → [C]; `magnet N mandel` → [N]; `magnet N julia C` → [N, C].
    pub params: Vec<Expr>,
    pub colors: Vec<Expr>,
    pub pigments: Vec<Pigment>,
    pub textures: Vec<Texture>,
    /// `object { sphere {..} A, B }`: the pattern's object written out (a declared one is
    /// `arg`).
    pub object: Option<Box<Object>>,
    /// `slope { .. }`'s ranges and altitude (its direction or `point_at` point is `arg`).
    pub slope: Option<Box<SlopeAst>>,
    pub span: Span,
}

/// `slope { D [, Lo, Hi] [altitude A [, Lo, Hi]] }` or `slope { point_at P [, Lo, Hi] }`;
/// `slope D` without braces is the direction alone.
#[derive(Clone, Debug, PartialEq)]
pub struct SlopeAst {
    pub point_at: bool,
    pub range: Option<(Expr, Expr)>,
    pub altitude: Option<(Expr, Option<(Expr, Expr)>)>,
}

/// A modifier of a pattern's value.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternMod {
    /// `ramp_wave`, `triangle_wave`, ..., `poly_wave [E]`.
    Wave(String, Option<Expr>),
    /// `frequency`, `phase`, `brick_size`, `mortar`, `agate_turb`, `form`, `metric`, `offset`,
    /// `control0`, `control1`, `noise_generator`.
    Set(String, Expr),
    /// `solid` (crackle).
    Flag(String, Span),
    Warp(WarpAst),
}

#[derive(Clone, Debug, PartialEq)]
pub enum WarpAst {
    Turbulence(Vec<Turb>),
    Repeat {
        dir: Expr,
        offset: Option<Expr>,
        flip: Option<Expr>,
    },
    BlackHole {
        center: Expr,
        radius: Expr,
        strength: Option<Expr>,
        falloff: Option<Expr>,
        inverse: bool,
        repeat: Option<Expr>,
        /// `turbulence` (jitter of repeated holes): read, not modelled.
        turbulence: Option<Span>,
    },
    /// `cylindrical`, `spherical`, `toroidal`, `planar [N, D]` or `cubic` (the word), with
    /// `orientation`, `dist_exp` and `major_radius`.
    Mapping {
        map: String,
        plane: Option<(Expr, Expr)>,
        orientation: Option<Expr>,
        dist_exp: Option<Expr>,
        major_radius: Option<Expr>,
    },
    /// A warp read but not modelled, with its keyword.
    Other(String, Span),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    pub items: Vec<PigmentItem>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum NormalItem {
    /// A leading identifier naming a declared normal.
    Base(Expr),
    /// `bumps [AMOUNT]`.
    Bumps(Option<Expr>, Span),
    Turb(Turb),
    Transform(TransformItem),
    /// Any other pattern with its optional amount.
    Pattern(PatternAst, Option<Expr>),
    Mod(PatternMod),
    BumpSize(Expr),
    /// `accuracy F`: the distance of the samples a pattern's gradient is taken from.
    Accuracy(Expr),
    /// `normal_map { [v normal { .. }] .. }` (entries may also be bare normal bodies).
    NormalMap(Vec<(Expr, Normal)>, Span),
    /// `slope_map { [v, <height, slope>] .. }` (or a declared map's name), with its keyword.
    SlopeMap(SlopeMapBody, Span),
    /// `bump_map { ... [bump_size F] }` with its bump size, if given inside.
    BumpMap(std::sync::Arc<crate::desc::ImageMapDesc>, Option<Expr>),
    /// `image_pattern { }` with its optional amount.
    ImagePattern(std::sync::Arc<crate::desc::ImageMapDesc>, Option<Expr>),
}

/// What a `slope_map { }` holds: `(value, <height, slope>, entry span)` entries, or a name.
#[derive(Clone, Debug, PartialEq)]
pub enum SlopeMapBody {
    Entries(Vec<(Expr, Expr, Span)>),
    Named(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Normal {
    pub items: Vec<NormalItem>,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FinishKey {
    Ambient,
    Diffuse,
    Brilliance,
    Phong,
    PhongSize,
    Specular,
    Roughness,
    Reflection,
    /// `metallic [AMOUNT]` (1 when no amount follows).
    Metallic,
    Emission,
    /// `reflection_exponent` (the old form of `reflection { .. exponent E }`).
    ReflectionExponent,
    /// `conserve_energy [BOOL]`.
    ConserveEnergy,
    /// `diffuse albedo A`, `phong albedo A`, `specular albedo A`: A is the total reflectance.
    DiffuseAlbedo,
    PhongAlbedo,
    SpecularAlbedo,
}

/// `reflection { [MIN,] MAX fresnel B falloff F exponent E metallic M }`.
#[derive(Clone, Debug, PartialEq)]
pub struct ReflectionBlock {
    pub min: Option<Expr>,
    pub max: Expr,
    pub fresnel: Option<Expr>,
    pub falloff: Option<Expr>,
    pub exponent: Option<Expr>,
    pub metallic: Option<Expr>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum FinishItem {
    Base(Expr),
    Set(FinishKey, Expr),
    Reflection(Box<ReflectionBlock>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Finish {
    pub items: Vec<FinishItem>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum TextureItem {
    Base(Expr),
    Pigment(Pigment),
    Normal(Normal),
    Finish(Finish),
    Transform(TransformItem),
    /// `texture { checker texture {..} texture {..} }` or a pattern for `texture_map`.
    Pattern(PatternAst),
    Mod(PatternMod),
    TextureMap(Vec<(Expr, Texture)>, Span),
    /// A further `texture { }` written right after this one: a layer over it.
    Layer(Box<Texture>),
    /// `image_pattern { }` as the pattern of a `texture_map`.
    ImagePattern(std::sync::Arc<crate::desc::ImageMapDesc>, Span),
    /// `material_map { png "f" .. texture {..}.. transforms }`: the image's palette index
    /// picks the texture.
    MaterialMap(std::sync::Arc<crate::desc::ImageMapDesc>, Vec<Texture>, Vec<TransformItem>, Span),
    /// `uv_mapping`: the texture's pigment follows the surface's (u, v).
    UvMapping(Span),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub items: Vec<TextureItem>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum InteriorItem {
    Base(Expr),
    Ior(Expr),
    FadeDistance(Expr),
    FadePower(Expr),
    FadeColor(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Interior {
    pub items: Vec<InteriorItem>,
    pub span: Span,
}

/// One item of `material { }` (POV-Ray 3.5.5 Material).
#[derive(Clone, Debug, PartialEq)]
pub enum MaterialItem {
    /// A declared material to start from.
    Base(Expr),
    Texture(Texture),
    Interior(Interior),
    /// Moves the material's texture (and interior) only.
    Transform(TransformItem),
}

/// `material { [M] texture {..} interior {..} transforms }`: a texture and an interior as one.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub items: Vec<MaterialItem>,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShapeKind {
    Sphere,
    Plane,
    Box,
    Triangle,
    Polygon,
    Cylinder,
    Cone,
    Disc,
    Torus,
    Quadric,
    Cubic,
    Quartic,
    Poly,
    Superellipsoid,
    /// `prism`: leading spline/sweep keywords come first in its arguments, as `Ident`s.
    Prism,
    /// `text`: `ttf` first, as an `Ident`, then font, string, thickness and offset.
    Text,
    /// `lathe`: an optional spline keyword first, as an `Ident`.
    Lathe,
    Sor,
    /// `isosurface`: the function first (a `Value::Function`), then its items, each a keyword
    /// `Ident` followed by its values.
    Isosurface,
    /// `parametric`: its three functions first (`Value::Function`s), the two (u, v) corners,
    /// then keyword items as for `Isosurface`.
    Parametric,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ObjectKind {
    /// A shape and its arguments as written (checked for count by the parser).
    Shape(ShapeKind, Vec<Expr>),
    /// A shape the parser evaluated as it read it (`mesh`, `mesh2`, `height_field`: too
    /// large to hold as expressions).
    Built(crate::desc::ShapeDesc),
    /// `object { Name ... }`.
    Ref(Expr),
    /// `object { sphere { ... } ... }`: an object written inside `object`.
    Inner(Box<Object>),
    /// `union`, `merge`, `intersection` or `difference { ... }`: child objects and the
    /// directives that make them.
    Csg { op: CsgOp, children: Vec<Stmt> },
    /// `blob { threshold T  sphere { .. }  cylinder { .. }  component S, R, C ... }`.
    Blob(Blob),
    /// `julia_fractal { <p> items }`.
    Julia(JuliaFractal),
    /// `light_group { objects lights global_lights B }`: a union whose own lights light only
    /// its objects; `global_lights` is `None` when not written (off), `Some(None)` when
    /// written alone (on).
    LightGroup { children: Vec<Stmt>, global_lights: Option<Option<Expr>> },
}

/// A `julia_fractal`'s parameter and items as written; the object modifiers follow as for any
/// shape.
#[derive(Clone, Debug, PartialEq)]
pub struct JuliaFractal {
    pub param: Expr,
    pub items: Vec<JuliaItem>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum JuliaItem {
    /// `quaternion` or `hypercomplex`.
    Algebra(Rc<str>, Span),
    /// `sqr`, `cube`, `exp`, ... (the keyword).
    Function(Rc<str>, Span),
    /// `pwr(x, y)`.
    Pwr(Expr, Expr, Span),
    MaxIteration(Expr),
    Precision(Expr),
    /// `slice <4-D normal>, distance`.
    Slice(Expr, Expr),
}

/// A blob's own items; the object modifiers follow them as for any shape.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Blob {
    pub threshold: Option<Expr>,
    pub components: Vec<BlobComponent>,
}

/// `sphere { C, R, [strength] S  modifiers }`, `cylinder { A, B, R, [strength] S  modifiers }`
/// or the old `component S, R, C` inside a blob.
#[derive(Clone, Debug, PartialEq)]
pub struct BlobComponent {
    pub shape: BlobShape,
    pub radius: Expr,
    pub strength: Expr,
    /// Transforms, and textures (which strahl does not blend per component).
    pub modifiers: Vec<Modifier>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum BlobShape {
    Sphere { center: Expr },
    Cylinder { base: Expr, cap: Expr },
}

#[derive(Clone, Debug, PartialEq)]
pub enum Modifier {
    Pigment(Pigment),
    Normal(Normal),
    Finish(Finish),
    Texture(Texture),
    Interior(Interior),
    /// `material { }`: a texture and an interior given together.
    Material(Material),
    /// `interior_texture { }`: the texture of the surface's inner side.
    InteriorTexture(Texture),
    Transform(TransformItem),
    NoShadow,
    /// `hollow [on|off]`: kept for media (not modelled yet); changes nothing else in POV-Ray.
    Hollow(Option<Expr>),
    /// `open` on a cylinder or cone: no end caps.
    Open(Span),
    /// `sturm` on a polynomial shape: POV-Ray's robust root finder, which strahl always uses.
    Sturm(Span),
    /// `inverse`: inside and outside swap (for CSG).
    Inverse,
    /// `inside_vector <v>` on a mesh: its inside test casts along `v`.
    InsideVector(Expr),
    /// `clipped_by { objects }`: only the surface inside all of them remains.
    ClippedBy(Clip),
    /// `bounded_by { objects }`: a hint for the renderer, which changes no picture.
    BoundedBy(Clip),
    /// `uv_mapping` on the object: all its textures follow the surface's (u, v).
    UvMapping(Span),
}

/// What `clipped_by` and `bounded_by` hold.
#[derive(Clone, Debug, PartialEq)]
pub enum Clip {
    Objects(Vec<Stmt>, Span),
    /// `clipped_by { bounded_by }` or `bounded_by { clipped_by }`: the other one's objects.
    Other(Span),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub kind: ObjectKind,
    pub modifiers: Vec<Modifier>,
    /// The keyword (`sphere`), where messages about the object point.
    pub span: Span,
}
