//! The pattern kernel layer: one enum of POV-Ray's patterns, each a pure function of a
//! pattern-space point giving a value in [0, 1], with the shared modifiers (`warp`s,
//! `frequency`, `phase`, wave types) applied generically. Pigments look the value up in a
//! colour or pigment map, list patterns pick a pigment per cell, normals take its gradient.
//!
//! Every function works on one or eight lanes with the same bits per lane (kernels that have
//! no lane arithmetic run the scalar kernel lane by lane).

pub mod cells;
pub mod density;
pub mod fractal;
pub mod mapping;
pub mod simple;
pub mod slope;
pub mod turbulent;

use glam::{Affine3A, Vec3};

use crate::desc::{PatternDesc, PatternKind, Warp, Wave};
use crate::lanes::{Lane, V3};
use crate::noise::{warp_lanes, TurbulenceF32};
use cells::Crackle;

#[derive(Clone, Debug, PartialEq)]
pub enum Kind32 {
    Gradient(Vec3),
    Bozo,
    Granite,
    /// With the classic `turbulence` it builds in (`Pattern32::build_in_turbulence`).
    Marble(Option<TurbulenceF32>),
    Agate(f32),
    Crackle(Crackle),
    Cells,
    Wrinkles,
    Dents,
    Leopard,
    Ripples,
    Waves,
    Radial,
    Onion,
    Spiral1(f32),
    Spiral2(f32),
    Brick(Vec3, f32),
    Hexagon,
    Checker,
    Boxed,
    Cylindrical,
    Spherical,
    Planar,
    Quilted(f32, f32),
    Fractal(fractal::Fractal32),
    /// `density_file`: voxels looked up lane by lane.
    Density(std::sync::Arc<crate::density_file::DensityGrid>, u32),
    /// `pigment_pattern`: the pigment's grey, in this pattern's space.
    PigmentPattern(Box<crate::shading::pigment::Pigment>),
    /// With the classic `turbulence` it builds in (`Pattern32::build_in_turbulence`).
    Wood(Option<TurbulenceF32>),
    /// `average` has no value of its own (the pigment averages its map).
    Average,
    /// A user function, run in f64 lane by lane (the compiled register code has no lane
    /// arithmetic), its value wrapped into [0, 1).
    Function(std::sync::Arc<crate::function::Program>),
    /// `image_pattern` / `bump_map`: looked up lane by lane (`shading::image_map`).
    Image(std::sync::Arc<crate::shading::image_map::ImageLookup>),
    /// The `object` pattern: asked lane by lane.
    Object(crate::desc::SolidRef),
    /// `slope`: needs the surface's normal (`Pattern32::surface_value_lanes`).
    Slope(slope::Slope32),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Wave32 {
    Ramp,
    Triangle,
    Sine,
    Scallop,
    Cubic,
    Poly(f32),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warp32 {
    Turbulence(TurbulenceF32),
    Repeat { axis: usize, width: f32, offset: Vec3, flip: Vec3 },
    BlackHole { center: Vec3, radius: f32, strength: f32, falloff: f32, inverse: bool, repeat: Vec3 },
    Mapping(mapping::MappingWarp),
}

/// A warp in pattern space: where it was written among the pattern's transforms, `to` moves
/// the point into the space it works in and `back` returns it (`None`: written before any).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlacedWarp32 {
    pub warp: Warp32,
    pub space: Option<(Affine3A, Affine3A)>,
}

/// A render-ready pattern: kind, warps, frequency, phase and wave.
#[derive(Clone, Debug, PartialEq)]
pub struct Pattern32 {
    pub kind: Kind32,
    pub wave: Wave32,
    pub frequency: f32,
    pub phase: f32,
    /// In written order; applied last first, as POV-Ray does.
    pub warps: Vec<PlacedWarp32>,
}

impl Pattern32 {
    pub fn from_desc(d: &PatternDesc) -> Pattern32 {
        let kind = match &d.kind {
            &PatternKind::Gradient(v) => Kind32::Gradient(v.normalize_or_zero().as_vec3()),
            PatternKind::Bozo => Kind32::Bozo,
            PatternKind::Granite => Kind32::Granite,
            PatternKind::Marble => Kind32::Marble(None),
            &PatternKind::Agate { turb } => Kind32::Agate(turb as f32),
            &PatternKind::Crackle { form, metric, offset, solid } => {
                Kind32::Crackle(Crackle { form: form.as_vec3(), metric: metric as f32, offset: offset as f32, solid })
            }
            PatternKind::Cells => Kind32::Cells,
            PatternKind::Wrinkles => Kind32::Wrinkles,
            PatternKind::Dents => Kind32::Dents,
            PatternKind::Leopard => Kind32::Leopard,
            PatternKind::Ripples => Kind32::Ripples,
            PatternKind::Waves => Kind32::Waves,
            PatternKind::Radial => Kind32::Radial,
            PatternKind::Onion => Kind32::Onion,
            &PatternKind::Spiral1(n) => Kind32::Spiral1(n as f32),
            &PatternKind::Spiral2(n) => Kind32::Spiral2(n as f32),
            &PatternKind::Brick { size, mortar } => Kind32::Brick(size.as_vec3(), mortar as f32),
            PatternKind::Hexagon => Kind32::Hexagon,
            PatternKind::Checker => Kind32::Checker,
            PatternKind::Boxed => Kind32::Boxed,
            PatternKind::Cylindrical => Kind32::Cylindrical,
            PatternKind::Spherical => Kind32::Spherical,
            PatternKind::Planar => Kind32::Planar,
            &PatternKind::Quilted { c0, c1 } => Kind32::Quilted(c0 as f32, c1 as f32),
            PatternKind::Fractal(f) => Kind32::Fractal(fractal::Fractal32::from_desc(f)),
            PatternKind::Density { grid, interpolate, .. } => Kind32::Density(grid.clone(), *interpolate),
            PatternKind::PigmentPattern(p) => {
                Kind32::PigmentPattern(Box::new(crate::shading::pigment::Pigment::from_desc(p, &glam::DMat4::IDENTITY)))
            }
            PatternKind::Wood => Kind32::Wood(None),
            PatternKind::Average => Kind32::Average,
            PatternKind::Function(f) => Kind32::Function(f.clone()),
            PatternKind::Object(s) => Kind32::Object(s.clone()),
            PatternKind::Slope(s) => Kind32::Slope(slope::Slope32::from_desc(s)),
            PatternKind::Image(im) => {
                Kind32::Image(std::sync::Arc::new(crate::shading::image_map::ImageLookup::from_desc(im)))
            }
        };
        let wave = match d.wave {
            Wave::Ramp => Wave32::Ramp,
            Wave::Triangle => Wave32::Triangle,
            Wave::Sine => Wave32::Sine,
            Wave::Scallop => Wave32::Scallop,
            Wave::Cubic => Wave32::Cubic,
            Wave::Poly(e) => Wave32::Poly(e as f32),
        };
        let warps = d
            .warps
            .iter()
            .filter_map(|placed| {
                let space = (!placed.space.is_identity()).then(|| {
                    let f = |m: &glam::DMat4| Affine3A::from_mat4(m.as_mat4());
                    (f(&placed.space.matrix), f(&placed.space.inverse))
                });
                let warp = match placed.warp {
                    Warp::Turbulence(t) => Warp32::Turbulence(TurbulenceF32::from(&t)),
                    Warp::Repeat { dir, offset, flip } => {
                        let axis = (0..3).find(|&a| dir[a] != 0.0)?;
                        Warp32::Repeat {
                            axis,
                            width: dir[axis].abs() as f32,
                            offset: offset.as_vec3(),
                            flip: flip.as_vec3(),
                        }
                    }
                    Warp::BlackHole { center, radius, strength, falloff, inverse, repeat } => Warp32::BlackHole {
                        center: center.as_vec3(),
                        radius: radius as f32,
                        strength: strength as f32,
                        falloff: falloff as f32,
                        inverse,
                        repeat: repeat.as_vec3(),
                    },
                    Warp::Mapping { map, orientation, dist_exp } => {
                        Warp32::Mapping(mapping::MappingWarp::new(map, orientation, dist_exp))
                    }
                };
                Some(PlacedWarp32 { warp, space })
            })
            .collect();
        Pattern32 { kind, wave, frequency: d.frequency as f32, phase: d.phase as f32, warps }
    }

    /// Takes a pigment's or normal's classic `turbulence`: `marble` and `wood` build it into
    /// their value, so it is kept in the kind and `None` returned; any other pattern returns it,
    /// to be applied as a warp to the point before the pattern is looked up.
    ///
    /// It matters most for normals. POV-Ray 3.7 warps the point once and then differentiates
    /// the pattern around it, so `gradient x triangle_wave turbulence 0.8` and `marble warp {
    /// turbulence 0.8 }` tilt only as the unwarped stripes do (slope n_x/n_z std 0.070, n_y/n_z
    /// 0.005 on a lit plane, `0.6 … scale 0.15`); `marble turbulence 0.8` tilts along the
    /// turbulence too (0.104 and 0.071), and `wood 0.6 turbulence 0.3 scale 0.3` four times as
    /// much as without (0.20 against 0.05): their turbulence is differentiated with them.
    pub fn build_in_turbulence(&mut self, t: Option<TurbulenceF32>) -> Option<TurbulenceF32> {
        match &mut self.kind {
            Kind32::Marble(built_in) | Kind32::Wood(built_in) => {
                *built_in = t;
                None
            }
            _ => t,
        }
    }

    /// Whether the value is a cell index (list patterns) rather than a continuous value.
    pub fn is_list(&self) -> bool {
        matches!(self.kind, Kind32::Checker | Kind32::Brick(..) | Kind32::Hexagon | Kind32::Object(_))
    }

    /// A pattern-space point moved by the pattern's warps, the last written first.
    #[inline(always)]
    pub fn warped<L: Lane>(&self, p: V3<L>, max_octaves: Option<u32>) -> V3<L> {
        let mut p = p;
        for w in self.warps.iter().rev() {
            p = match w.space {
                None => apply_warp(&w.warp, p, max_octaves),
                Some((to, back)) => apply_warp(&w.warp, p.transform_point(&to), max_octaves).transform_point(&back),
            };
        }
        p
    }

    /// The value at a pattern-space point (transform and classic turbulence already applied):
    /// warps, the kernel, then frequency, phase and the wave.
    #[inline(always)]
    pub fn value_lanes<L: Lane>(&self, p: V3<L>, max_octaves: Option<u32>) -> L {
        self.value_at_warped_lanes(self.warped(p, max_octaves), max_octaves)
    }

    /// The value at a point the warps have already moved (`warped`): the kernel, then
    /// frequency, phase and the wave. Normals differentiate this around the warped point.
    #[inline(always)]
    pub fn value_at_warped_lanes<L: Lane>(&self, p: V3<L>, max_octaves: Option<u32>) -> L {
        let v = kernel(&self.kind, p, max_octaves);
        if self.is_list() {
            return v;
        }
        self.shaped(v)
    }

    /// Whether the value depends on the surface's normal (`slope`).
    #[inline(always)]
    pub fn reads_normal(&self) -> bool {
        matches!(self.kind, Kind32::Slope(_))
    }

    /// `value_lanes` on a surface whose unit outward normal is `n` (world axes): what `slope`
    /// needs; every other pattern ignores `n`.
    #[inline(always)]
    pub fn surface_value_lanes<L: Lane>(&self, p: V3<L>, n: V3<L>, max_octaves: Option<u32>) -> L {
        match &self.kind {
            Kind32::Slope(s) => self.shaped(s.value_lanes(self.warped(p, max_octaves), n)),
            _ => self.value_lanes(p, max_octaves),
        }
    }

    /// Frequency, phase and the wave, on a kernel's value.
    #[inline(always)]
    fn shaped<L: Lane>(&self, v: L) -> L {
        let v = if self.frequency != 1.0 || self.phase != 0.0 {
            simple::frac(v * L::splat(self.frequency) + L::splat(self.phase))
        } else {
            v
        };
        shape(self.wave, v)
    }
}

/// The kernel of each pattern.
#[inline(always)]
fn kernel<L: Lane>(k: &Kind32, p: V3<L>, max_octaves: Option<u32>) -> L {
    match *k {
        Kind32::Gradient(d) => simple::gradient(p, d),
        Kind32::Bozo => turbulent::bozo(p),
        Kind32::Granite => turbulent::granite(p),
        Kind32::Marble(None) => simple::frac(p.x),
        Kind32::Marble(Some(ref t)) => simple::frac(turbulent::marble_turbulent(p, t, max_octaves)),
        Kind32::Agate(t) => turbulent::agate(p, t),
        Kind32::Crackle(ref c) => cells::crackle(p, c),
        Kind32::Cells => cells::cells(p),
        Kind32::Wrinkles => turbulent::wrinkles(p),
        Kind32::Dents => turbulent::dents(p),
        Kind32::Leopard => simple::leopard(p),
        Kind32::Ripples => turbulent::ripples(p),
        Kind32::Waves => turbulent::waves(p),
        Kind32::Radial => simple::radial(p),
        Kind32::Onion => simple::onion(p),
        Kind32::Spiral1(n) => simple::spiral1(p, n),
        Kind32::Spiral2(n) => simple::spiral2(p, n),
        Kind32::Brick(size, mortar) => simple::brick(p, size, mortar),
        Kind32::Hexagon => simple::hexagon(p),
        Kind32::Checker => simple::checker(p),
        Kind32::Boxed => simple::boxed(p),
        Kind32::Cylindrical => simple::cylindrical(p),
        Kind32::Spherical => simple::spherical(p),
        Kind32::Planar => simple::planar(p),
        Kind32::Quilted(a, b) => simple::quilted(p, a, b),
        Kind32::Fractal(ref f) => fractal::fractal(p, f),
        Kind32::Density(ref g, interpolate) => density::density(p, g, interpolate),
        Kind32::PigmentPattern(ref pig) => pigment_grey(pig, p),
        Kind32::Wood(None) => simple::wood_rings(p),
        Kind32::Wood(Some(ref t)) => simple::wood_rings(turbulent::wood_cycloidal(p, t, max_octaves)),
        Kind32::Average => L::splat(0.0),
        Kind32::Function(ref f) => {
            simple::frac(L::from_fn_f64(|i| f.eval(&[p.x.get_f64(i), p.y.get_f64(i), p.z.get_f64(i)])))
        }
        Kind32::Image(ref im) => im.value_lanes(p),
        // No surface here (`surface_value_lanes` has one).
        Kind32::Slope(_) => L::splat(0.0),
        Kind32::Object(ref s) => L::from_fn_f64(|i| {
            let q = glam::DVec3::new(p.x.get_f64(i), p.y.get_f64(i), p.z.get_f64(i));
            if s.0.contains(q) {
                1.0
            } else {
                0.0
            }
        }),
    }
}

/// POV-Ray's grey of a colour, as `pigment_pattern` reads it (3.4.7.1.19), clamped to [0, 1].
/// The weights are the luminance POV-Ray 3.7 uses for grey values (0.297 R + 0.589 G +
/// 0.114 B), checked by rendering `pigment_pattern { rgb C }` with `ambient 1`.
pub const GREY: [f32; 3] = [0.297, 0.589, 0.114];

#[inline(always)]
fn pigment_grey<L: Lane>(pig: &crate::shading::pigment::Pigment, p: V3<L>) -> L {
    let c = crate::shading::pigment::eval_pigment_lanes(pig, p, Default::default());
    let g = c.rgb.x * L::splat(GREY[0]) + c.rgb.y * L::splat(GREY[1]) + c.rgb.z * L::splat(GREY[2]);
    g.max(L::splat(0.0)).min(L::splat(1.0))
}

/// POV-Ray's wave types on a value in [0, 1] (measured on `gradient x`: `sine_wave` is
/// 0.5 + 0.5·sin 2πv, `scallop_wave` |sin πv|, `cubic_wave` 3v² − 2v³, `poly_wave E` v^E).
#[inline(always)]
pub fn shape<L: Lane>(w: Wave32, v: L) -> L {
    let one = L::splat(1.0);
    match w {
        Wave32::Ramp => v,
        Wave32::Triangle => {
            let f = simple::frac(v);
            one - (L::splat(2.0) * f - one).abs()
        }
        Wave32::Sine => L::splat(0.5) + L::splat(0.5) * v.map(|x| (x * std::f32::consts::TAU).sin()),
        Wave32::Scallop => v.map(|x| (x * std::f32::consts::PI).sin().abs()),
        Wave32::Cubic => v * v * (L::splat(3.0) - L::splat(2.0) * v),
        Wave32::Poly(e) => v.map(|x| x.max(0.0).powf(e)),
    }
}

#[inline(always)]
fn apply_warp<L: Lane>(w: &Warp32, p: V3<L>, max_octaves: Option<u32>) -> V3<L> {
    match *w {
        Warp32::Turbulence(ref t) => warp_lanes(p, t, max_octaves),
        Warp32::Repeat { axis, width, offset, flip } => V3::from_lanes(|i| {
            let mut q = p.lane(i);
            let cell = (q[axis] / width).floor();
            q[axis] -= cell * width;
            if flip[axis] != 0.0 && cell.rem_euclid(2.0) != 0.0 {
                q[axis] = width - q[axis];
            }
            q + offset * cell
        }),
        Warp32::BlackHole { center, radius, strength, falloff, inverse, repeat } => V3::from_lanes(|i| {
            let q = p.lane(i);
            // With `repeat`, the hole of the cell the point is in (centre offset into it).
            let cell = Vec3::select(repeat.cmpgt(Vec3::ZERO), (q / repeat).floor() * repeat, Vec3::ZERO);
            let d = q - (cell + center);
            let r = d.length();
            if r >= radius || r == 0.0 {
                return q;
            }
            // A point moves at most its distance from the centre (POV-Ray's reference). The
            // hole pulls the pattern in: a point reads the pattern from further out (POV-Ray
            // 3.7 renders a star of small checks); `inverse` pushes it out.
            let amount = ((1.0 - r / radius).powf(falloff) * strength).min(1.0);
            if inverse {
                q - d * amount
            } else {
                q + d * amount
            }
        }),
        Warp32::Mapping(ref m) => V3::from_lanes(|i| m.apply(p.lane(i))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::{PlacedWarp, Transform, Turbulence, WarpMap};
    use crate::function::{Binary, Node, Program};
    use crate::lanes::F8;
    use glam::DVec3;

    fn all_kinds() -> Vec<PatternKind> {
        vec![
            PatternKind::Gradient(DVec3::new(1.0, 1.0, 0.0)),
            PatternKind::Bozo,
            PatternKind::Granite,
            PatternKind::Marble,
            PatternKind::Agate { turb: 1.0 },
            PatternKind::Crackle { form: DVec3::new(-1.0, 1.0, 0.0), metric: 2.0, offset: 0.0, solid: false },
            PatternKind::Crackle { form: DVec3::new(1.0, 0.0, 0.0), metric: 1.5, offset: 0.1, solid: true },
            PatternKind::Cells,
            PatternKind::Wrinkles,
            PatternKind::Dents,
            PatternKind::Leopard,
            PatternKind::Ripples,
            PatternKind::Waves,
            PatternKind::Radial,
            PatternKind::Onion,
            PatternKind::Spiral1(3.0),
            PatternKind::Spiral2(2.0),
            PatternKind::Brick { size: DVec3::new(8.0, 3.0, 4.5), mortar: 0.5 },
            PatternKind::Hexagon,
            PatternKind::Checker,
            PatternKind::Boxed,
            PatternKind::Cylindrical,
            PatternKind::Spherical,
            PatternKind::Planar,
            PatternKind::Quilted { c0: 1.0, c1: 1.0 },
            PatternKind::Fractal(crate::desc::Fractal::new(crate::desc::FractalKind::Mandel { exponent: 2 }, 25)),
            PatternKind::Fractal(crate::desc::Fractal::new(
                crate::desc::FractalKind::MagnetJulia { magnet: 2, c: [0.4, 0.2] },
                25,
            )),
            PatternKind::PigmentPattern(Box::new(crate::desc::PigmentDesc {
                pattern: crate::desc::PigmentPattern::Checker(
                    crate::desc::Color::WHITE,
                    crate::desc::Color::rgb(0.2, 0.5, 0.1),
                ),
                ..Default::default()
            })),
            PatternKind::Wood,
            // `function { x * 1.5 - y }`: wrapped into [0, 1).
            PatternKind::Function(std::sync::Arc::new(Program::compile(
                &Node::binary(Binary::Sub, Node::binary(Binary::Mul, Node::Param(0), Node::Const(1.5)), Node::Param(1)),
                3,
            ))),
        ]
    }

    fn point(k: usize) -> Vec3 {
        let j = k as f32;
        Vec3::new((j * 0.731).sin() * 3.0, (j * 0.377).cos() * 2.0, j * 0.0013 - 1.0)
    }

    #[test]
    fn every_pattern_is_in_range_and_lanes_match_one_lane() {
        for kind in all_kinds() {
            for (wave, warps) in [
                (Wave::Ramp, vec![]),
                (Wave::Sine, vec![Warp::Turbulence(Turbulence { amount: DVec3::splat(0.3), ..Default::default() })]),
                (Wave::Poly(2.0), vec![Warp::Repeat { dir: DVec3::X, offset: DVec3::Y, flip: DVec3::X }]),
                (
                    Wave::Ramp,
                    vec![Warp::Mapping {
                        map: WarpMap::Toroidal { major_radius: 0.7 },
                        orientation: DVec3::Y,
                        dist_exp: 1.0,
                    }],
                ),
            ] {
                let mut d = PatternDesc::new(kind.clone());
                d.wave = wave;
                d.warps = warps
                    .into_iter()
                    .map(|warp| PlacedWarp { warp, space: Transform::default(), inherited: false })
                    .collect();
                d.frequency = 2.0;
                let pat = Pattern32::from_desc(&d);
                for k in 0..100 {
                    let p = |i: usize| point(k * 8 + i);
                    let wide = pat.value_lanes(V3::<F8>::from_lanes(p), None);
                    for i in 0..8 {
                        let one = pat.value_lanes(V3::<f32>::from_vec3(p(i)), None);
                        assert_eq!(wide.get(i).to_bits(), one.to_bits(), "{kind:?}");
                        assert!((0.0..=1.0).contains(&one) || pat.is_list() && one <= 2.0, "{kind:?}: {one}");
                    }
                }
            }
        }
    }

    #[test]
    fn noise_patterns_mean_and_spread() {
        // POV-Ray 3.7 over a 8×6 plane: bozo 0.525 ± 0.131, wrinkles 0.528 ± 0.142,
        // dents 0.172 ± 0.120.
        for (kind, mean, std) in [
            (PatternKind::Bozo, 0.525, 0.131),
            (PatternKind::Wrinkles, 0.528, 0.142),
            (PatternKind::Dents, 0.172, 0.12),
        ] {
            let pat = Pattern32::from_desc(&PatternDesc::new(kind.clone()));
            let v: Vec<f32> = (0..20_000)
                .map(|k| {
                    pat.value_lanes(
                        V3::<f32>::from_vec3(Vec3::new(k as f32 * 0.173, 0.37, (k / 100) as f32 * 0.291)),
                        None,
                    )
                })
                .collect();
            let m = v.iter().sum::<f32>() / v.len() as f32;
            let s = (v.iter().map(|x| (x - m) * (x - m)).sum::<f32>() / v.len() as f32).sqrt();
            assert!((m - mean).abs() < 0.06, "{kind:?} mean {m}");
            assert!((s - std).abs() < 0.05, "{kind:?} std {s}");
            // Deterministic and continuous.
            let at = |x: f32| pat.value_lanes(V3::<f32>::from_vec3(Vec3::new(x, 0.2, 0.7)), None);
            assert_eq!(at(1.3), at(1.3));
            assert!((at(1.3) - at(1.3001)).abs() < 0.01, "{kind:?}");
        }
    }

    #[test]
    fn waves_match_povray_profiles() {
        let v = |w, x: f32| shape::<f32>(w, x);
        assert!((v(Wave32::Triangle, 0.25) - 0.5).abs() < 1e-6);
        assert!((v(Wave32::Sine, 0.25) - 1.0).abs() < 1e-6);
        assert!((v(Wave32::Scallop, 0.5) - 1.0).abs() < 1e-6);
        assert!((v(Wave32::Cubic, 0.5) - 0.5).abs() < 1e-6);
        assert!((v(Wave32::Poly(2.0), 0.5) - 0.25).abs() < 1e-6);
        // frequency 2 phase 0.25 on gradient x: frac(2x + 0.25).
        let mut d = PatternDesc::new(PatternKind::Gradient(DVec3::X));
        d.frequency = 2.0;
        d.phase = 0.25;
        let pat = Pattern32::from_desc(&d);
        assert!((pat.value_lanes(V3::<f32>::from_vec3(Vec3::new(0.3, 0.0, 0.0)), None) - 0.85).abs() < 1e-5);
    }
}
