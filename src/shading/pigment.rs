//! Render-ready pigments: a closed enum evaluated per hit at a render-space point.
//!
//! Solid colours return before any transform or noise work; only turbulent patterns pay for noise.

use glam::{Affine3A, DMat4, Vec3};

use super::pattern::{checker_lanes_within, wood_lanes, ColorMap, Rgbft, RgbftLanes, CHECKER_TOLERANCE};
use super::pattern_space::{pattern_from_render, Period};
use super::patterns::turbulent::wood_cycloidal;
use super::patterns::{Kind32, Pattern32};
use crate::desc::{PigmentDesc, PigmentPattern};
use crate::lanes::{Lane, V3};
use crate::noise::{warp_lanes, TurbulenceF32};

/// Per-frame knobs that trade pattern fidelity for speed.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PatternQuality {
    /// Caps every turbulence's octave count; `None` renders them as written.
    pub max_octaves: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PigmentPattern32 {
    Solid(Rgbft),
    Checker([Rgbft; 2]),
    /// Turbulence displaces wood cycloidally (see `patterns::turbulent::wood_cycloidal`), not by the plain warp.
    Wood(ColorMap),
    /// Any other pattern through a colour map.
    Mapped(Box<Pattern32>, ColorMap),
    /// `pigment_map`: entries sorted by value.
    PigmentMap(Box<Pattern32>, Vec<(f32, Pigment)>),
    /// A list pattern's pigment per cell.
    List(Box<Pattern32>, Vec<Pigment>),
    /// Layered textures' pigments, bottom first.
    Layered(Vec<Pigment>),
    /// `image_map`: texels looked up lane by lane.
    ImageMap(std::sync::Arc<super::image_map::ImageLookup>),
}

impl PigmentPattern32 {
    /// Whether any point of it lets light through (filter or transmit above zero).
    pub fn may_be_transparent(&self) -> bool {
        let see_through = |c: &Rgbft| c.filter > 0.0 || c.transmit > 0.0;
        match self {
            PigmentPattern32::Solid(c) => see_through(c),
            PigmentPattern32::Checker(cs) => cs.iter().any(see_through),
            PigmentPattern32::Wood(map) | PigmentPattern32::Mapped(_, map) => {
                map.entries().iter().any(|(_, c)| see_through(c))
            }
            PigmentPattern32::PigmentMap(_, e) => e.iter().any(|(_, p)| p.pattern.may_be_transparent()),
            PigmentPattern32::List(_, l) => l.iter().any(|p| p.pattern.may_be_transparent()),
            // Each layer passes on only what shows through it: the bottom decides.
            PigmentPattern32::Layered(l) => l.first().is_some_and(|p| p.pattern.may_be_transparent()),
            PigmentPattern32::ImageMap(im) => im.may_be_transparent(),
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    pub pattern: PigmentPattern32,
    /// Whether its pattern, or a pattern of a pigment it is made of, reads the surface's
    /// normal (`slope`): such a pigment is evaluated by `eval_surface_pigment_lanes`.
    pub reads_normal: bool,
    pub turbulence: Option<TurbulenceF32>,
    /// Render space (`camera::frame::RenderFrame`) → pattern space.
    pub pattern_from_render: Affine3A,
    /// Error of a pattern-space point per render-space unit of the hit's distance from the
    /// camera (render space's origin), through `pattern_from_render`'s largest row. Measured on a
    /// floor 8.3e4 units from the camera: 0.07 f32 epsilons of the distance; a quarter epsilon
    /// covers that 4× over and moves checker edges by at most 0.1 pixel there. The checker
    /// widens its tolerance by this times the distance.
    pub slack_per_render: f32,
    /// The checker's fixed edge tolerance along each pattern axis: `CHECKER_TOLERANCE` in
    /// render units, at most that in pattern units, so an axis scaled up (POV-Ray's `scale <1,
    /// 1, 10000>` stripes) keeps its edges where POV-Ray has them rather than the tolerance
    /// times the scale away (1 unit there; 3.2 units under `scale 32000`).
    pub checker_tolerance: [f32; 3],
}

impl Pigment {
    pub fn from_desc(d: &PigmentDesc, world_from_render: &DMat4) -> Pigment {
        let mut pattern = match &d.pattern {
            PigmentPattern::Solid(c) => PigmentPattern32::Solid(Rgbft::from_desc(c)),
            PigmentPattern::Checker(a, b) => PigmentPattern32::Checker([Rgbft::from_desc(a), Rgbft::from_desc(b)]),
            PigmentPattern::Wood(map) => PigmentPattern32::Wood(ColorMap::from_desc(map)),
            PigmentPattern::Mapped(pat, map) => {
                PigmentPattern32::Mapped(Box::new(Pattern32::from_desc(pat)), ColorMap::from_desc(map))
            }
            PigmentPattern::PigmentMap(pat, entries) => PigmentPattern32::PigmentMap(
                Box::new(Pattern32::from_desc(pat)),
                entries.iter().map(|(v, p)| (*v as f32, Pigment::from_desc(p, world_from_render))).collect(),
            ),
            PigmentPattern::List(pat, list) => PigmentPattern32::List(
                Box::new(Pattern32::from_desc(pat)),
                list.iter().map(|p| Pigment::from_desc(p, world_from_render)).collect(),
            ),
            PigmentPattern::Layered(list) => {
                PigmentPattern32::Layered(list.iter().map(|p| Pigment::from_desc(p, world_from_render)).collect())
            }
            PigmentPattern::ImageMap(im) => {
                PigmentPattern32::ImageMap(std::sync::Arc::new(super::image_map::ImageLookup::from_desc(im)))
            }
        };
        let periods = match &d.pattern {
            PigmentPattern::Solid(_) => [Period::Any; 3],
            PigmentPattern::Checker(..) => [Period::Every(2.0); 3],
            PigmentPattern::Wood(_) => [Period::Never, Period::Never, Period::Any],
            // Patterns of the kernel layer keep their translation (no reduction).
            _ => [Period::Never; 3],
        };
        let pattern_from_render =
            pattern_from_render(&d.transform.inverse, world_from_render, periods, d.turbulence.as_ref());
        let m = pattern_from_render.matrix3;
        let row_norm = (0..3).map(|r| m.row(r).abs().element_sum()).fold(0.0, f32::max);
        // Marble and wood (in a pigment_map or list) build their turbulence in; the wood pigment
        // has its own path (`wood_value`) and keeps it here.
        let turbulence = d.turbulence.as_ref().map(TurbulenceF32::from);
        let turbulence = match &mut pattern {
            PigmentPattern32::Mapped(pat, _)
            | PigmentPattern32::PigmentMap(pat, _)
            | PigmentPattern32::List(pat, _) => pat.build_in_turbulence(turbulence),
            _ => turbulence,
        };
        let reads_normal = match &pattern {
            PigmentPattern32::Mapped(pat, _) => pat.reads_normal(),
            PigmentPattern32::PigmentMap(pat, entries) => {
                pat.reads_normal() || entries.iter().any(|(_, p)| p.reads_normal)
            }
            PigmentPattern32::List(pat, list) => pat.reads_normal() || list.iter().any(|p| p.reads_normal),
            PigmentPattern32::Layered(list) => list.iter().any(|p| p.reads_normal),
            _ => false,
        };
        Pigment {
            pattern,
            reads_normal,
            turbulence,
            pattern_from_render,
            slack_per_render: 0.25 * f32::EPSILON * row_norm,
            checker_tolerance: [0, 1, 2].map(|r| CHECKER_TOLERANCE * m.row(r).abs().element_sum().min(1.0)),
        }
    }

    /// Pattern-space point for a render-space hit, turbulence applied.
    #[inline(always)]
    fn pattern_point<L: Lane>(&self, p_render: V3<L>, q: PatternQuality) -> V3<L> {
        let p = p_render.transform_point(&self.pattern_from_render);
        match &self.turbulence {
            Some(t) => warp_lanes(p, t, q.max_octaves),
            None => p,
        }
    }
}

/// The pigment's colour at a render-space point.
#[inline]
pub fn eval_pigment(pig: &Pigment, p_render: Vec3, q: PatternQuality) -> Rgbft {
    eval_pigment_lanes(pig, V3::from_vec3(p_render), q).lane(0)
}

/// `eval_pigment` for one or eight render-space points.
#[inline(always)]
pub fn eval_pigment_lanes<L: Lane>(pig: &Pigment, p_render: V3<L>, q: PatternQuality) -> RgbftLanes<L> {
    match &pig.pattern {
        PigmentPattern32::Solid(c) => RgbftLanes::splat(*c),
        PigmentPattern32::Checker(c) => {
            let p = pig.pattern_point(p_render, q);
            let slack = p_render.max_abs() * L::splat(pig.slack_per_render);
            RgbftLanes::select(
                checker_lanes_within(p, pig.checker_tolerance, slack),
                RgbftLanes::splat(c[1]),
                RgbftLanes::splat(c[0]),
            )
        }
        PigmentPattern32::Wood(map) => map.lookup_lanes(wood_value(pig, p_render, q)),
        _ => eval_composite_lanes(pig, p_render, None, q),
    }
}

/// `eval_pigment_lanes` on a surface whose unit outward normal (world axes) is `n`: a `slope`
/// pigment reads it; every other pigment is `eval_pigment_lanes`.
#[inline(always)]
pub fn eval_surface_pigment_lanes<L: Lane>(
    pig: &Pigment,
    p_render: V3<L>,
    n: V3<L>,
    q: PatternQuality,
) -> RgbftLanes<L> {
    if pig.reads_normal {
        eval_composite_lanes(pig, p_render, Some(n), q)
    } else {
        eval_pigment_lanes(pig, p_render, q)
    }
}

/// Wood's ring value at a render-space point (its turbulence is cycloidal, not a warp).
#[inline(always)]
fn wood_value<L: Lane>(pig: &Pigment, p_render: V3<L>, q: PatternQuality) -> L {
    let p = p_render.transform_point(&pig.pattern_from_render);
    let p = match &pig.turbulence {
        Some(t) => wood_cycloidal(p, t, q.max_octaves),
        None => p,
    };
    wood_lanes(p)
}

/// POV-Ray's `.gray` of a colour: 0.297 red + 0.589 green + 0.114 blue (measured with
/// `#debug` on `function { pigment { rgb <0.2, 0.5, 0.9> } }(0, 0, 0).gray` = 0.4565).
pub fn gray(c: &Rgbft) -> f32 {
    0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
}

/// The pattern value a pigment looks its colour up by, at a render-space point: what
/// `function { pattern { ... } }` gives (checker 0 or 1, a list pattern its cell index, any
/// other pattern its shaped value in [0, 1]); a pigment without a pattern gives its gray.
pub fn pattern_value(pig: &Pigment, p_render: Vec3, q: PatternQuality) -> f32 {
    let p = V3::from_vec3(p_render);
    match &pig.pattern {
        PigmentPattern32::Checker(_) => {
            let slack = p.max_abs() * pig.slack_per_render;
            if checker_lanes_within(pig.pattern_point(p, q), pig.checker_tolerance, slack) {
                1.0
            } else {
                0.0
            }
        }
        PigmentPattern32::Wood(_) => wood_value(pig, p, q),
        PigmentPattern32::Mapped(pat, _) | PigmentPattern32::PigmentMap(pat, _) | PigmentPattern32::List(pat, _) => {
            pat.value_lanes(pig.pattern_point(p, q), q.max_octaves)
        }
        _ => gray(&eval_pigment(pig, p_render, q)),
    }
}

/// `pattern_value` on a surface whose unit outward normal (world axes) is `n` (what picks a
/// `slope` texture map's entries).
pub fn surface_pattern_value(pig: &Pigment, p_render: Vec3, n: Vec3, q: PatternQuality) -> f32 {
    match &pig.pattern {
        PigmentPattern32::Mapped(pat, _) | PigmentPattern32::PigmentMap(pat, _) | PigmentPattern32::List(pat, _)
            if pat.reads_normal() =>
        {
            let p = pig.pattern_point(V3::from_vec3(p_render), q);
            pat.surface_value_lanes(p, V3::from_vec3(n), q.max_octaves)
        }
        _ => pattern_value(pig, p_render, q),
    }
}

/// The pigments of the pattern layer (`shading::patterns`), kept out of line so that solid,
/// checker and wood pigments stay as small as they were.
#[inline(never)]
fn eval_composite_lanes<L: Lane>(pig: &Pigment, p_render: V3<L>, n: Option<V3<L>>, q: PatternQuality) -> RgbftLanes<L> {
    // The pigments it is made of, and the pattern's value: on a surface (`n`, the outward
    // normal) as `slope` reads it.
    let eval = |p: &Pigment| match n {
        Some(n) => eval_surface_pigment_lanes(p, p_render, n, q),
        None => eval_pigment_lanes(p, p_render, q),
    };
    let value = |pat: &Pattern32| {
        let p = pig.pattern_point(p_render, q);
        match n {
            Some(n) => pat.surface_value_lanes(p, n, q.max_octaves),
            None => pat.value_lanes(p, q.max_octaves),
        }
    };
    match &pig.pattern {
        PigmentPattern32::Mapped(pat, map) => map.lookup_lanes(value(pat)),
        PigmentPattern32::PigmentMap(pat, entries) if pat.kind == Kind32::Average => {
            let total: f32 = entries.iter().map(|e| e.0).sum();
            let mut out = RgbftLanes::splat(Rgbft::default());
            for (w, p) in entries {
                let c = eval(p);
                let k = L::splat(if total != 0.0 { w / total } else { 0.0 });
                out = RgbftLanes {
                    rgb: out.rgb.add(c.rgb.scale(k)),
                    filter: out.filter + c.filter * k,
                    transmit: out.transmit + c.transmit * k,
                };
            }
            out
        }
        PigmentPattern32::PigmentMap(pat, entries) => {
            let v = value(pat);
            let colors: Vec<(f32, RgbftLanes<L>)> = entries.iter().map(|(value, p)| (*value, eval(p))).collect();
            blend_entries(&colors, v)
        }
        PigmentPattern32::List(pat, list) => {
            let v = value(pat);
            let mut out = match list.first() {
                Some(p) => eval(p),
                None => return RgbftLanes::splat(Rgbft::default()),
            };
            for (k, p) in list.iter().enumerate().skip(1) {
                let c = eval(p);
                out = RgbftLanes::select(L::splat(k as f32 - 0.5).lt(v), c, out);
            }
            out
        }
        PigmentPattern32::ImageMap(im) => im.color_lanes(pig.pattern_point(p_render, q)),
        PigmentPattern32::Layered(list) => {
            let mut out = RgbftLanes::splat(Rgbft::default());
            for (k, p) in list.iter().enumerate() {
                let c = eval(p);
                out = if k == 0 { c } else { layer_over(c, out) };
            }
            out
        }
        PigmentPattern32::Solid(_) | PigmentPattern32::Checker(_) | PigmentPattern32::Wood(_) => {
            eval_pigment_lanes(pig, p_render, q)
        }
    }
}

/// An upper layer over what lies below it: its opaque part shows its colour, its transmitted
/// part the colour below, its filtered part the colour below tinted by its own; filter and
/// transmit of the result are what passes through both.
#[inline(always)]
fn layer_over<L: Lane>(top: RgbftLanes<L>, below: RgbftLanes<L>) -> RgbftLanes<L> {
    let one = L::splat(1.0);
    let pass = top.filter + top.transmit;
    let opaque = (one - pass).max(L::splat(0.0));
    let tint = V3 {
        x: top.transmit + top.filter * top.rgb.x,
        y: top.transmit + top.filter * top.rgb.y,
        z: top.transmit + top.filter * top.rgb.z,
    };
    RgbftLanes {
        rgb: top.rgb.scale(opaque).add(below.rgb.mul(tint)),
        filter: below.filter * pass,
        transmit: below.transmit * pass,
    }
}

/// Linear blending between sorted map entries, clamped at both ends (as `ColorMap`).
#[inline(always)]
fn blend_entries<L: Lane>(e: &[(f32, RgbftLanes<L>)], v: L) -> RgbftLanes<L> {
    let (Some(first), Some(last)) = (e.first(), e.last()) else { return RgbftLanes::splat(Rgbft::default()) };
    let mut out = last.1;
    for w in e.windows(2).rev() {
        let ((v0, c0), (v1, c1)) = (w[0], w[1]);
        let span = v1 - v0;
        let c = if span > 0.0 { c0.lerp(c1, (v - L::splat(v0)) / L::splat(span)) } else { c1 };
        out = RgbftLanes::select(v.le(L::splat(v1)), c, out);
    }
    RgbftLanes::select(v.le(L::splat(first.0)), first.1, out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    use crate::desc::{Color, ColorMapEntry, Transform};
    use crate::shading::pattern::checker;

    fn scaled(s: DVec3) -> Transform {
        let m = DMat4::from_scale(s);
        Transform { matrix: m, inverse: m.inverse() }
    }

    #[test]
    fn render_origin_is_folded_into_the_pattern_transform() {
        let desc = PigmentDesc {
            pattern: PigmentPattern::Checker(Color::WHITE, Color::BLACK),
            turbulence: None,
            transform: scaled(DVec3::splat(2.0)),
        };
        let (origin, unit) = (DVec3::new(1000.25, 3.0, -500.5), 0.3);
        let world_from_render = DMat4::from_translation(origin) * DMat4::from_scale(DVec3::splat(unit));
        let pig = Pigment::from_desc(&desc, &world_from_render);
        for w in [DVec3::new(1001.0, 0.0, -499.0), DVec3::new(998.9, 0.5, -503.7)] {
            let expect = checker((w / 2.0).as_vec3());
            let got = eval_pigment(&pig, ((w - origin) / unit).as_vec3(), PatternQuality::default());
            assert_eq!(got, Rgbft::from_desc(if expect == 0 { &Color::WHITE } else { &Color::BLACK }));
        }
    }

    #[test]
    fn a_checker_scaled_up_keeps_its_edges_where_povray_has_them() {
        // `scale <1, 1, 10000>` stripes (incdemo/metals/golds.pov): the edge at z = 0 stays
        // there, half a unit either side shows either colour (with the tolerance in pattern
        // units it was 1 unit off, the cell [-1, 0) showing the first colour). Not tested: the
        // edges at z = ±10000, as far from the render origin, where `slack_per_render` (by the
        // largest row, not z's) still moves them by some 3 units.
        let desc = PigmentDesc {
            pattern: PigmentPattern::Checker(Color::WHITE, Color::BLACK),
            turbulence: None,
            transform: scaled(DVec3::new(1.0, 1.0, 10000.0)),
        };
        let pig = Pigment::from_desc(&desc, &DMat4::IDENTITY);
        let at = |p: Vec3| eval_pigment(&pig, p, PatternQuality::default());
        let (first, second) = (Rgbft::from_desc(&Color::WHITE), Rgbft::from_desc(&Color::BLACK));
        assert_eq!(at(Vec3::new(0.5, 0.5, 0.5)), first);
        assert_eq!(at(Vec3::new(0.5, 0.5, -0.5)), second);
        assert_eq!(at(Vec3::new(0.5, 0.5, -0.01)), second);
        assert_eq!(at(Vec3::new(0.5, 0.5, 5000.0)), first);
        assert_eq!(at(Vec3::new(0.5, 0.5, -5000.0)), second);
        // Unscaled axes keep the fixed tolerance: a floor at y = 0 shows the cell above it.
        assert_eq!(at(Vec3::new(0.5, -1e-6, 0.5)), first);
    }

    fn checker_desc(turbulence: Option<crate::desc::Turbulence>) -> PigmentDesc {
        PigmentDesc {
            pattern: PigmentPattern::Checker(Color::WHITE, Color::BLACK),
            turbulence,
            transform: scaled(DVec3::ONE),
        }
    }

    /// A render frame centred on `origin` in the seed scene's unit.
    fn frame_at(origin: DVec3) -> DMat4 {
        DMat4::from_translation(origin) * DMat4::from_scale(DVec3::splat(22f64.sqrt()))
    }

    #[test]
    fn a_far_checker_reduces_to_the_numbers_of_the_near_one() {
        // A floor checker under a camera 1e6 (a multiple of the 32-unit step) from its origin
        // becomes the pattern of the camera at the origin, number for number.
        let near = Pigment::from_desc(&checker_desc(None), &frame_at(DVec3::new(3.0, 3.0, -1.0)));
        let far = Pigment::from_desc(&checker_desc(None), &frame_at(DVec3::new(1e6 + 3.0, 3.0, 7e5 - 1.0)));
        assert_eq!(far.pattern_from_render, near.pattern_from_render);
        // Not a multiple: another lattice step, the same colours.
        let odd = Pigment::from_desc(&checker_desc(None), &frame_at(DVec3::new(123458.0, 3.0, -1.0)));
        assert!(odd.pattern_from_render.translation.x.abs() <= 16.0);
        for i in 0..2000 {
            let p = Vec3::new((i as f32 * 0.37).sin() * 9.0, (i as f32 * 0.23).sin(), (i as f32 * 0.11).cos() * 9.0);
            let w = DVec3::new(123458.0, 3.0, -1.0) + p.as_dvec3() * 22f64.sqrt();
            let edge = |v: f64| (v - v.floor()).min(v.ceil() - v) < 1e-3;
            if edge(w.x) || edge(w.y) || edge(w.z) {
                continue; // too near an edge for f32
            }
            let cell = w.floor();
            let want = if (cell.x + cell.y + cell.z).rem_euclid(2.0) == 0.0 { Color::WHITE } else { Color::BLACK };
            assert_eq!(eval_pigment(&odd, p, PatternQuality::default()), Rgbft::from_desc(&want), "at {w}");
        }
    }

    #[test]
    fn only_periodic_axes_far_from_the_camera_are_reduced() {
        use crate::desc::Turbulence;
        let far = frame_at(DVec3::new(1e6 + 3.0, 1e6 + 3.0, 1e6 + 3.0));
        let t = |d: &PigmentDesc, frame: &DMat4| Pigment::from_desc(d, frame).pattern_from_render.translation;
        // A pattern origin within 16 camera units keeps its translation (a telephoto camera
        // 8.3e4 away looking at the origin has it 1 unit away).
        let telephoto = DMat4::from_translation(DVec3::new(1e4, 2e4, -8e4)) * DMat4::from_scale(DVec3::splat(8.3e4));
        assert_eq!(t(&checker_desc(None), &telephoto), Vec3::new(1e4, 2e4, -8e4).into());
        // Turbulence with an integer lambda repeats with the noise lattice; a fractional one
        // does not repeat at all.
        let turb = |lambda| Some(Turbulence { amount: DVec3::splat(0.3), octaves: 3, omega: 0.5, lambda });
        assert!(t(&checker_desc(turb(2.0)), &far).abs().max_element() <= 128.0);
        assert_eq!(t(&checker_desc(turb(2.5)), &far), Vec3::splat(1e6 + 3.0).into());
        // Wood's rings never repeat across the axis; along it, only turbulence's period counts.
        let wood = |turbulence| PigmentDesc {
            pattern: PigmentPattern::Wood(vec![]),
            turbulence,
            transform: Transform::default(),
        };
        assert_eq!(t(&wood(None), &far), Vec3::splat(1e6 + 3.0).into());
        let w = t(&wood(turb(2.0)), &far);
        assert_eq!((w.x, w.y), (1e6 + 3.0, 1e6 + 3.0));
        assert!(w.z.abs() <= 128.0);
    }

    #[test]
    fn wood_without_turbulence_follows_the_map() {
        let desc = PigmentDesc {
            pattern: PigmentPattern::Wood(vec![
                ColorMapEntry { value: 0.0, color: Color::BLACK },
                ColorMapEntry { value: 1.0, color: Color::WHITE },
            ]),
            turbulence: None,
            transform: Transform::default(),
        };
        let pig = Pigment::from_desc(&desc, &DMat4::IDENTITY);
        let c = eval_pigment(&pig, Vec3::new(0.25, 0.0, 3.0), PatternQuality::default());
        assert!((c.rgb - Vec3::splat(0.5)).abs().max_element() < 1e-6);
    }

    #[test]
    fn eight_lanes_match_one_lane_bit_for_bit() {
        use crate::desc::Turbulence;
        use crate::lanes::F8;
        let map = vec![
            ColorMapEntry { value: 0.1, color: Color::WHITE },
            ColorMapEntry { value: 0.5, color: Color::BLACK },
            ColorMapEntry { value: 0.5, color: Color::WHITE },
            ColorMapEntry { value: 0.9, color: Color::BLACK },
        ];
        let turbulence = Some(Turbulence { amount: DVec3::new(0.04, 0.3, 0.1), octaves: 3, omega: 0.5, lambda: 2.0 });
        let pigments = [
            PigmentDesc {
                pattern: PigmentPattern::Wood(map.clone()),
                turbulence,
                transform: scaled(DVec3::new(0.05, 0.05, 1.0)),
            },
            PigmentDesc { pattern: PigmentPattern::Wood(map), turbulence: None, transform: Transform::default() },
            PigmentDesc {
                pattern: PigmentPattern::Checker(Color::WHITE, Color::BLACK),
                turbulence,
                transform: scaled(DVec3::splat(0.7)),
            },
        ];
        for desc in &pigments {
            let pig = Pigment::from_desc(desc, &DMat4::from_translation(DVec3::new(3.0, 1.0, -2.0)));
            for k in 0..500 {
                let p = |i: usize| {
                    let j = (k * 8 + i) as f32;
                    Vec3::new((j * 0.731).sin() * 7.0, (j * 0.377).cos() * 3.0, j * 0.013 - 2.0)
                };
                let wide = eval_pigment_lanes(&pig, V3::<F8>::from_lanes(p), PatternQuality::default());
                for i in 0..8 {
                    let one = eval_pigment(&pig, p(i), PatternQuality::default());
                    let w = wide.lane(i);
                    assert_eq!(w.rgb.to_array().map(f32::to_bits), one.rgb.to_array().map(f32::to_bits));
                    assert_eq!(
                        (w.filter.to_bits(), w.transmit.to_bits()),
                        (one.filter.to_bits(), one.transmit.to_bits())
                    );
                }
            }
        }
    }
}
