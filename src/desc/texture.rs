//! Textures as written: patterns, pigments, normals, finishes and interiors.

use super::{Color, Transform};
use glam::DVec3;
use std::sync::Arc;

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
    /// `image_map { }`: the image's colours wrapped onto pattern space.
    ImageMap(Arc<ImageMapDesc>),
}

/// How `image_map`, `bump_map` and `image_pattern` wrap an image onto pattern space
/// (`map_type`): the unit square of the x-y plane, a sphere, a cylinder or a torus around y.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageMapping {
    Planar,
    Spherical,
    Cylindrical,
    /// `map_type 5`: a torus of major radius 1 around y.
    Torus,
}

/// An image with the modifiers `image_map`, `bump_map` and `image_pattern` share.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageMapDesc {
    /// The file as found (for messages and the printer).
    pub file: String,
    /// The type keyword written (`png`, `gif`, ..., `sys`).
    pub format: String,
    pub image: Arc<crate::image_file::Image>,
    pub mapping: ImageMapping,
    /// `interpolate`: 0 none, 2 bilinear, 4 normalized distance.
    pub interpolate: u32,
    /// `once`: no repetition; outside the image is clear (transmit 1).
    pub once: bool,
    /// `use_index`: a palette image's value is its index over 255 rather than its colour's
    /// intensity (`bump_map`, `image_pattern`).
    pub use_index: bool,
    /// `use_alpha` (`image_pattern`): the value is the alpha channel.
    pub use_alpha: bool,
    /// `filter N F` / `filter all F`, in written order (`None`: all entries).
    pub filter: Vec<(Option<usize>, f64)>,
    pub transmit: Vec<(Option<usize>, f64)>,
    /// How stored values become working colours: `Some(g)`: sRGB-decoded then raised to
    /// 1 / g (the scene's `assumed_gamma`, so that an image shows its own values on an
    /// `ambient 1` surface, as POV-Ray 3.7 renders it); `None`: as stored (legacy scenes).
    pub decode_gamma: Option<f64>,
    /// `gamma G` in the block: the file's values are raised to G instead of sRGB-decoded.
    pub file_gamma: Option<f64>,
}

/// The pattern functions (`shading::patterns`), with their own parameters.
#[derive(Clone, Debug, PartialEq)]
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
    /// `mandel`, `julia` and `magnet 1|2` (3.4.7.1.11): one fractal family.
    Fractal(Fractal),
    /// `pigment_pattern { PIGMENT }` (3.4.7.1.19): the pigment's grey value, evaluated in
    /// this pattern's space (the inner pigment keeps its own transform).
    PigmentPattern(Box<PigmentDesc>),
    /// `density_file df3 "FILE" [interpolate N]`: the file's voxels over the unit cube.
    Density {
        /// The file as found (for the printer).
        file: String,
        grid: Arc<crate::density_file::DensityGrid>,
        interpolate: u32,
    },
    /// Raw ring value `frac(r)` (its default wave is the triangle).
    Wood,
    /// `average`: a `pigment_map`'s pigments averaged, weighted by their entry values.
    Average,
    /// `function { ... }` (3.4.7.1.12): the user function of (x, y, z), wrapped into [0, 1)
    /// as POV-Ray wraps it (`function { x }` repeats every unit, checked by rendering).
    Function(std::sync::Arc<crate::function::Program>),
    /// `image_pattern { }` (and `bump_map`'s heights): the image's intensity (or alpha).
    Image(Arc<ImageMapDesc>),
    /// `object { OBJECT A, B }` (3.4.7.2.5): 1 inside the object, 0 outside.
    Object(SolidRef),
    /// `slope { .. }` (3.4.7.3.2): read from the surface's normal (`shading::patterns::slope`).
    Slope(Slope),
}

/// The `slope` pattern as written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slope {
    /// The direction (world axes), or with `point_at` the point the surface is aimed at.
    pub direction: DVec3,
    pub point_at: bool,
    /// `Lo_slope, Hi_slope`: the slope values that become 0 and 1 (0, 1 unless written).
    pub range: [f64; 2],
    /// `altitude A, Lo_alt, Hi_alt`: a gradient along A in pattern space, from Lo to Hi.
    pub altitude: Option<(DVec3, [f64; 2])>,
}

/// What the `object` pattern asks of its object: whether a point (in the pattern's space,
/// which is the object's world) lies inside. `render::probe` answers it with the renderer's
/// own kernels; the shading layer only asks.
pub trait Solid: Send + Sync + std::fmt::Debug {
    fn contains(&self, p: glam::DVec3) -> bool;
    /// The objects it was made of, as written (for `scene::print`).
    fn objects(&self) -> &[super::ObjectDesc];
}

/// A shared `Solid`; two are equal when they are the same one.
#[derive(Clone, Debug)]
pub struct SolidRef(pub Arc<dyn Solid>);

impl PartialEq for SolidRef {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::addr_eq(Arc::as_ptr(&self.0), Arc::as_ptr(&other.0))
    }
}

impl PatternKind {
    /// How many pigments a list pattern picks from; `None` for a continuous pattern.
    pub fn list_len(&self) -> Option<usize> {
        match self {
            PatternKind::Checker | PatternKind::Brick { .. } | PatternKind::Object(_) => Some(2),
            PatternKind::Hexagon => Some(3),
            _ => None,
        }
    }
}

/// The iteration of a fractal pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FractalKind {
    /// z ← z^exponent + c from z = 0, c the point.
    Mandel { exponent: u32 },
    /// z ← z^exponent + c from z the point.
    Julia { c: [f64; 2], exponent: u32 },
    /// `magnet 1|2 mandel`: the magnet map with c the point, from z = 0.
    MagnetMandel { magnet: u32 },
    /// `magnet 1|2 julia C`: the magnet map with c given, from z the point.
    MagnetJulia { magnet: u32, c: [f64; 2] },
}

/// `mandel`, `julia` and `magnet` with their `interior` and `exterior` colouring types
/// (0–6; exterior also 7, 8) and factors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    pub kind: FractalKind,
    pub iterations: u32,
    pub interior: (u32, f64),
    pub exterior: (u32, f64),
}

impl Fractal {
    /// POV-Ray's defaults: interior type 0 (value 1), exterior type 1 (iterations until
    /// bailout over the iteration count), factors 1.
    pub fn new(kind: FractalKind, iterations: u32) -> Fractal {
        Fractal { kind, iterations, interior: (0, 1.0), exterior: (1, 1.0) }
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
    /// `warp { black_hole C, R ... }`; `repeat` (zero components: no repeat) places one in
    /// every cell of that size, C being the offset into each.
    BlackHole {
        center: DVec3,
        radius: f64,
        strength: f64,
        falloff: f64,
        inverse: bool,
        repeat: DVec3,
    },
    /// `warp { cylindrical | spherical | toroidal | planar | cubic }`: the point mapped onto
    /// (u, v, depth) as image maps wrap, then turned by `orientation` (for `planar`, the
    /// plane's normal).
    Mapping {
        map: WarpMap,
        orientation: DVec3,
        dist_exp: f64,
    },
}

/// A warp and where it was written among the pattern's transforms: `space` maps pattern space
/// to the space the warp works in (the transforms written before it; identity for none).
/// POV-Ray applies warps and transforms in one list, so `warp { black_hole 0, 1 } scale 2`
/// and `scale 2 warp { black_hole 0, 1 }` differ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlacedWarp {
    pub warp: Warp,
    pub space: super::Transform,
    /// Written in an enclosing pigment (`inherit_warps`), not in this pattern's own block:
    /// the scene printer leaves it to the enclosing one.
    pub inherited: bool,
}

/// The surface a mapping warp wraps the pattern around.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WarpMap {
    Cylindrical,
    Spherical,
    Toroidal {
        major_radius: f64,
    },
    /// The pattern on the plane `distance` along the normal, extruded along z.
    Planar {
        distance: f64,
    },
    Cubic,
}

/// A pattern with its value modifiers; the transform and classic turbulence live with the
/// pigment or normal that uses it.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternDesc {
    pub kind: PatternKind,
    pub wave: Wave,
    pub frequency: f64,
    pub phase: f64,
    /// In written order; POV-Ray applies the last written first.
    pub warps: Vec<PlacedWarp>,
}

impl PatternDesc {
    pub fn new(kind: PatternKind) -> PatternDesc {
        // POV-Ray 3.4.7: ramp_wave unless a pattern's section says otherwise (marble, wood,
        // spiral1, spiral2: triangle_wave).
        let wave = match kind {
            PatternKind::Marble | PatternKind::Wood | PatternKind::Spiral1(_) | PatternKind::Spiral2(_) => {
                Wave::Triangle
            }
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

    /// Warps written in an enclosing pigment after this one (in its `pigment_map` or list):
    /// POV-Ray warps the point for the pigments a pattern is made of too. Each `(warp,
    /// before)` works in the space of the enclosing block's transforms written before it, so
    /// here in that of this pigment's transform so far followed by them. Wood and solid
    /// colours take none (a warped wood is lowered as a general pattern); images ignore them.
    pub fn inherit_warps(&mut self, warps: &[(Warp, super::Transform)]) {
        if warps.is_empty() {
            return;
        }
        let own = self.transform;
        let placed =
            || warps.iter().map(|(warp, before)| PlacedWarp { warp: *warp, space: own.then(before), inherited: true });
        if let PigmentPattern::Checker(a, b) = self.pattern {
            let (pd, list) = PigmentDesc::checker_list(a, b);
            self.pattern = PigmentPattern::List(pd, list);
        }
        match &mut self.pattern {
            PigmentPattern::Mapped(pd, _) => pd.warps.extend(placed()),
            PigmentPattern::PigmentMap(pd, entries) => {
                pd.warps.extend(placed());
                entries.iter_mut().for_each(|(_, p)| p.inherit_warps(warps));
            }
            PigmentPattern::List(pd, list) => {
                pd.warps.extend(placed());
                list.iter_mut().for_each(|p| p.inherit_warps(warps));
            }
            PigmentPattern::Layered(list) => list.iter_mut().for_each(|p| p.inherit_warps(warps)),
            PigmentPattern::Solid(_) | PigmentPattern::Checker(..) | PigmentPattern::Wood(_) => {}
            PigmentPattern::ImageMap(_) => {}
        }
    }

    /// `checker a b` as the general pattern over a list of two solid pigments: what a warped
    /// checker needs (the plain one keeps its fast path, `PigmentPattern::Checker`).
    pub fn checker_list(a: Color, b: Color) -> (PatternDesc, Vec<PigmentDesc>) {
        let solid = |c: Color| PigmentDesc { pattern: PigmentPattern::Solid(c), ..Default::default() };
        (PatternDesc::new(PatternKind::Checker), vec![solid(a), solid(b)])
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
    /// `normal_map`: the pattern's value blends the perturbed normals of the two entries
    /// around it (sorted by value); each entry keeps its own pattern and transform.
    Map(PatternDesc, Vec<(f64, NormalDesc)>),
}

impl NormalDesc {
    /// Moves the normal, and every normal it is made of, by `tr` (applied after its own).
    pub fn transform_by(&mut self, tr: &Transform) {
        self.transform = self.transform.then(tr);
        if let NormalPattern::Map(_, entries) = &mut self.pattern {
            entries.iter_mut().for_each(|(_, n)| n.transform_by(tr));
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct NormalDesc {
    pub pattern: NormalPattern,
    pub turbulence: Option<Turbulence>,
    /// Pattern space → world space.
    pub transform: Transform,
    /// `slope_map`: the pattern's value turned into a height before the normal tilts down its
    /// gradient; empty for none (the value is the height). Sorted by value.
    pub slope_map: Vec<SlopeEntry>,
    /// `accuracy`: how far from the point (pattern units) the pattern is sampled for its
    /// gradient; POV-Ray's default is 0.02.
    pub accuracy: f64,
}

/// POV-Ray 3.7's `accuracy` when none is written.
pub const DEFAULT_NORMAL_ACCURACY: f64 = 0.02;

/// One `[value, <height, slope>]` entry of a `slope_map`. Between two entries the height is the
/// cubic Hermite curve from one to the other whose slopes are per unit of the interval, not of
/// the pattern's value (POV-Ray 3.7, measured: `[0 <0,1>] [0.5 <1,1>]` is the straight line
/// height = 2·value, tilting twice as far as `gradient x` alone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlopeEntry {
    pub value: f64,
    pub height: f64,
    pub slope: f64,
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
    /// `uv_mapping` (POV-Ray 3.4.6.7): the pigment is evaluated at the hit's surface
    /// coordinates (u, v, 0) through its own transforms only; the object's transforms do not
    /// move it. Shapes with uv: `geometry::uv`.
    pub uv_mapping: bool,
    /// A pattern of whole textures whose entries differ in more than their pigments; `None`
    /// for a plain texture (and for patterns of textures that differ only in pigment, which
    /// `pigment` renders alone). Boxed: most textures have none.
    pub pattern: Option<Box<TexturePatternDesc>>,
}

/// A pattern of textures (`texture_map`, a list pattern of textures such as `checker texture
/// {..} texture {..}`, `material_map`) whose entries differ in their normals or finishes.
/// POV-Ray shades each entry a point shows and blends the results by the pattern's weights, so
/// these are kept whole; the texture's own `pigment` is the same pattern over the entries'
/// pigments, for everything that needs only a colour (shadow rays through it).
#[derive(Clone, Debug, PartialEq)]
pub struct TexturePatternDesc {
    /// Picks the entries: a `PigmentMap` (values, or `average` weights) or a `List` (cells)
    /// over the entries' pigments, with the pattern's modifiers and transforms.
    pub selector: PigmentDesc,
    pub entries: Vec<TextureDesc>,
    /// Layered textures (`texture { A } texture { B }`) whose layers differ in finish or
    /// reflect or shine: `entries` are the layers, bottom first, and `selector` is their
    /// composited pigment; the renderer shades each layer with its own finish.
    pub layered: bool,
}

impl TextureDesc {
    /// Moves the pigment, the normal and every entry of a pattern of textures by `tr`.
    pub fn transform_by(&mut self, tr: &Transform) {
        self.pigment.transform_by(tr);
        if let Some(n) = &mut self.normal {
            n.transform_by(tr);
        }
        if let Some(p) = &mut self.pattern {
            p.selector.transform_by(tr);
            p.entries.iter_mut().for_each(|t| t.transform_by(tr));
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct InteriorDesc {
    pub ior: f64,
    /// `fade_distance`, `fade_power`, `fade_color`: `None` unless a distance and a power are
    /// given (boxed: most objects have none, and every object carries an interior).
    pub fade: Option<Box<FadeDesc>>,
}

impl Default for InteriorDesc {
    fn default() -> Self {
        InteriorDesc { ior: 1.0, fade: None }
    }
}

/// Light fading as it travels through an object (POV-Ray 3.4.8.1.6 Attenuation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FadeDesc {
    pub distance: f64,
    pub power: f64,
    /// The colour light fades to; white does not fade.
    pub color: DVec3,
}
