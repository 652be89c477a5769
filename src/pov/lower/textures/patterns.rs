//! Pattern keywords → `PatternKind`, and the modifiers of a pattern's value (wave type,
//! frequency, phase, warps, ...), for pigments, normals and textures alike.

use glam::DVec3;

use super::TurbState;
use crate::desc::{Fractal, FractalKind, PatternDesc, PatternKind, PlacedWarp, Transform, Warp, WarpMap, Wave};
use crate::pov::ast::{Expr, PatternAst, PatternMod, Stmt, WarpAst};
use crate::pov::lower::Lowerer;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

impl Lowerer<'_> {
    /// The pattern a keyword names, with its argument.
    pub(in crate::pov::lower) fn pattern_kind(&mut self, pa: &PatternAst) -> PResult<PatternKind> {
        let arg = |l: &Self, default: f64| match &pa.arg {
            Some(e) => l.float(e),
            None => Ok(default),
        };
        Ok(match pa.name.as_str() {
            "gradient" => {
                let v = match &pa.arg {
                    Some(e) => self.vec3(e)?,
                    None => DVec3::X,
                };
                if v == DVec3::ZERO {
                    return Err(Diag::new(pa.span, "gradient needs a non-zero vector"));
                }
                PatternKind::Gradient(v)
            }
            "bozo" | "spotted" | "bumps" => PatternKind::Bozo,
            "granite" => PatternKind::Granite,
            "marble" => PatternKind::Marble,
            "agate" => PatternKind::Agate { turb: 1.0 },
            "crackle" => {
                PatternKind::Crackle { form: DVec3::new(-1.0, 1.0, 0.0), metric: 2.0, offset: 0.0, solid: false }
            }
            "cells" => PatternKind::Cells,
            "wrinkles" => PatternKind::Wrinkles,
            "dents" => PatternKind::Dents,
            "leopard" => PatternKind::Leopard,
            "ripples" => PatternKind::Ripples,
            "waves" => PatternKind::Waves,
            "radial" => PatternKind::Radial,
            "onion" => PatternKind::Onion,
            "spiral1" => PatternKind::Spiral1(arg(self, 1.0)?),
            "spiral2" => PatternKind::Spiral2(arg(self, 1.0)?),
            "brick" => PatternKind::Brick { size: DVec3::new(8.0, 3.0, 4.5), mortar: 0.5 },
            "hexagon" => PatternKind::Hexagon,
            "checker" => PatternKind::Checker,
            "boxed" => PatternKind::Boxed,
            "cylindrical" => PatternKind::Cylindrical,
            "spherical" => PatternKind::Spherical,
            "planar" => PatternKind::Planar,
            "quilted" => PatternKind::Quilted { c0: 1.0, c1: 1.0 },
            "mandel" | "julia" | "magnet" => PatternKind::Fractal(self.fractal(pa)?),
            "density_file" => {
                let Some(e) = &pa.arg else { return Err(Diag::new(pa.span, "density_file needs a file name")) };
                let file = match self.eval(e)? {
                    Value::Str(s) => s.to_string(),
                    other => return Err(other.wrong_kind(e.span, "density_file's file name")),
                };
                let path = self
                    .files
                    .data_path(&file, false)
                    .ok()
                    .filter(|p| p.is_file())
                    .ok_or_else(|| Diag::new(e.span, format!("density_file \"{file}\" not found")))?;
                let bytes = std::fs::read(&path)
                    .map_err(|err| Diag::new(e.span, format!("cannot read density_file \"{file}\": {err}")))?;
                let grid = crate::density_file::DensityGrid::from_df3(&bytes)
                    .map_err(|m| Diag::new(e.span, format!("density_file \"{file}\" {m}")))?;
                // The file as found, so that a printed scene reads it from anywhere.
                let file = path.to_string_lossy().into_owned();
                PatternKind::Density { file, grid: std::sync::Arc::new(grid), interpolate: 0 }
            }
            "pigment_pattern" => match pa.pigments.first() {
                Some(p) => PatternKind::PigmentPattern(Box::new(self.pigment(p)?)),
                None => return Err(Diag::new(pa.span, "pigment_pattern needs a pigment body")),
            },
            "wood" => PatternKind::Wood,
            "average" => PatternKind::Average,
            "function" => match pa.arg.as_ref().map(|e| self.eval(e)).transpose()? {
                Some(Value::Function(f)) => PatternKind::Function(std::sync::Arc::new(f.compile())),
                _ => return Err(Diag::new(pa.span, "function pattern needs a function body")),
            },
            "object" => PatternKind::Object(self.pattern_object(pa)?),
            "slope" => PatternKind::Slope(self.slope(pa)?),
            other => return Err(Diag::new(pa.span, format!("unknown pattern `{other}`"))),
        })
    }

    /// `slope`'s vectors and ranges; a zero direction or altitude, or an empty range, is an
    /// error at the vector or range.
    fn slope(&mut self, pa: &PatternAst) -> PResult<crate::desc::Slope> {
        let (Some(d), Some(sa)) = (&pa.arg, &pa.slope) else {
            return Err(Diag::new(pa.span, "slope needs a direction"));
        };
        let direction = self.vec3(d)?;
        if direction == DVec3::ZERO && !sa.point_at {
            return Err(Diag::new(d.span, "slope needs a non-zero direction"));
        }
        let range = |l: &mut Self, r: &Option<(Expr, Expr)>| -> PResult<[f64; 2]> {
            let Some((lo, hi)) = r else { return Ok([0.0, 1.0]) };
            let v = [l.float(lo)?, l.float(hi)?];
            if v[0] == v[1] {
                return Err(Diag::new(lo.span, format!("slope range {} to {} is empty", v[0], v[1])));
            }
            Ok(v)
        };
        let altitude = match &sa.altitude {
            Some((a, r)) => {
                let v = self.vec3(a)?;
                if v == DVec3::ZERO {
                    return Err(Diag::new(a.span, "slope altitude needs a non-zero vector"));
                }
                Some((v, range(self, r)?))
            }
            None => None,
        };
        Ok(crate::desc::Slope { direction, point_at: sa.point_at, range: range(self, &sa.range)?, altitude })
    }

    /// The solid of an `object` pattern: its object written out or declared, asked by
    /// `render::probe`.
    fn pattern_object(&mut self, pa: &PatternAst) -> PResult<crate::desc::SolidRef> {
        let parts = match (&pa.object, &pa.arg) {
            (Some(o), _) => self.children(&[Stmt::Object((**o).clone())], "object", pa.span)?,
            (None, Some(e)) => match self.eval(e)? {
                Value::Object(g) => g.parts.clone(),
                other => return Err(other.wrong_kind(e.span, "the object of an `object` pattern")),
            },
            (None, None) => return Err(Diag::new(pa.span, "the `object` pattern needs an object")),
        };
        let objects: Vec<_> = parts.into_iter().map(|p| p.into_desc(&Default::default())).collect();
        Ok(crate::render::probe::solid(&objects))
    }

    /// `mandel N`, `julia C, N`, `magnet 1|2 mandel N`, `magnet 1|2 julia C, N`.
    fn fractal(&mut self, pa: &PatternAst) -> PResult<Fractal> {
        let iterations = match &pa.arg {
            Some(e) => {
                let n = self.float(e)?;
                if !(1.0..=1e6).contains(&n) {
                    return Err(Diag::new(e.span, format!("{} needs between 1 and 1e6 iterations", pa.name)));
                }
                n as u32
            }
            None => 25,
        };
        let complex = |l: &Self, e: &Expr| -> PResult<[f64; 2]> {
            let v = l.vec3(e)?;
            Ok([v.x, v.y])
        };
        let kind = match (pa.name.as_str(), pa.params.as_slice()) {
            ("julia", [c]) => FractalKind::Julia { c: complex(self, c)?, exponent: 2 },
            ("magnet", [m, rest @ ..]) => {
                let t = self.float(m)?;
                if t != 1.0 && t != 2.0 {
                    return Err(Diag::new(m.span, "magnet type must be 1 or 2"));
                }
                let magnet = t as u32;
                match rest {
                    [c] => FractalKind::MagnetJulia { magnet, c: complex(self, c)? },
                    _ => FractalKind::MagnetMandel { magnet },
                }
            }
            _ => FractalKind::Mandel { exponent: 2 },
        };
        Ok(Fractal::new(kind, iterations))
    }

    /// `exponent`, `interior` and `exterior` of a fractal pattern.
    fn fractal_mod(&self, word: &str, e: &Expr, f: &mut Fractal) -> PResult<()> {
        if word == "exponent" {
            let n = self.float(e)?;
            if !(2.0..=33.0).contains(&n) || n.fract() != 0.0 {
                return Err(Diag::new(e.span, "exponent must be a whole number from 2 to 33"));
            }
            match &mut f.kind {
                FractalKind::Mandel { exponent } | FractalKind::Julia { exponent, .. } => *exponent = n as u32,
                _ => return Err(Diag::new(e.span, "magnet patterns take no exponent")),
            }
            return Ok(());
        }
        let v = self.vec3(e)?;
        let max = if word == "exterior" { 8.0 } else { 6.0 };
        if !(0.0..=max).contains(&v.x) || v.x.fract() != 0.0 {
            return Err(Diag::new(e.span, format!("{word} type must be a whole number from 0 to {max}")));
        }
        let slot = if word == "exterior" { &mut f.exterior } else { &mut f.interior };
        *slot = (v.x as u32, v.y);
        Ok(())
    }

    /// Applies one modifier to a pattern.
    /// `placed`: the pattern's transforms written so far (where a warp sits among them).
    pub(in crate::pov::lower) fn pattern_mod(
        &mut self,
        m: &PatternMod,
        pd: &mut PatternDesc,
        placed: &Transform,
    ) -> PResult<()> {
        let place = |warp| PlacedWarp { warp, space: *placed, inherited: false };
        match m {
            PatternMod::Wave(w, e) => {
                pd.wave = match w.as_str() {
                    "ramp_wave" => Wave::Ramp,
                    "triangle_wave" => Wave::Triangle,
                    "sine_wave" => Wave::Sine,
                    "scallop_wave" => Wave::Scallop,
                    "cubic_wave" => Wave::Cubic,
                    _ => Wave::Poly(match e {
                        Some(e) => self.float(e)?,
                        None => 1.0,
                    }),
                }
            }
            PatternMod::Flag(_, _) => {
                if let PatternKind::Crackle { solid, .. } = &mut pd.kind {
                    *solid = true;
                }
            }
            PatternMod::Set(word, e) => match (word.as_str(), &mut pd.kind) {
                ("frequency", _) => pd.frequency = self.float(e)?,
                ("phase", _) => pd.phase = self.float(e)?,
                ("brick_size", PatternKind::Brick { size, .. }) => {
                    let v = self.vec3(e)?;
                    if v.min_element() <= 0.0 {
                        return Err(Diag::new(e.span, "brick_size must be positive"));
                    }
                    *size = v;
                }
                ("mortar", PatternKind::Brick { mortar, .. }) => *mortar = self.float(e)?,
                ("agate_turb", PatternKind::Agate { turb }) => *turb = self.float(e)?,
                ("form", PatternKind::Crackle { form, .. }) => *form = self.vec3(e)?,
                ("metric", PatternKind::Crackle { metric, .. }) => {
                    let v = self.float(e)?;
                    if v <= 0.0 {
                        return Err(Diag::new(e.span, "metric must be positive"));
                    }
                    *metric = v;
                }
                ("offset", PatternKind::Crackle { offset, .. }) => *offset = self.float(e)?,
                ("control0", PatternKind::Quilted { c0, .. }) => *c0 = self.float(e)?,
                ("control1", PatternKind::Quilted { c1, .. }) => *c1 = self.float(e)?,
                ("exponent" | "interior" | "exterior", PatternKind::Fractal(f)) => self.fractal_mod(word, e, f)?,
                ("interpolate", PatternKind::Density { interpolate, .. }) => {
                    let n = self.float(e)?;
                    *interpolate = match n as i64 {
                        0 => 0,
                        1 => 1,
                        2 => {
                            self.not_modelled("density_file interpolate 2 (tricubic; trilinear used)", e.span);
                            1
                        }
                        _ => return Err(Diag::new(e.span, "density_file interpolate must be 0, 1 or 2")),
                    };
                }
                ("interpolate", _) => return Err(Diag::new(e.span, "`interpolate` needs density_file here")),
                ("exponent" | "interior" | "exterior", _) => {
                    return Err(Diag::new(e.span, format!("`{word}` needs a fractal pattern (mandel, julia, magnet)")))
                }
                // noise_generator 1|2|3: read; strahl has one noise.
                _ => {
                    self.float(e)?;
                }
            },
            PatternMod::Warp(w) => match w {
                WarpAst::Turbulence(items) => {
                    let mut state = TurbState::from(None);
                    for t in items {
                        self.turb(t, &mut state)?;
                    }
                    // `octaves` etc. after a `turbulence` warp of a texture extend it.
                    if let (false, Some(Warp::Turbulence(last))) =
                        (state.given, pd.warps.last_mut().map(|w| &mut w.warp))
                    {
                        for t in items {
                            let mut s = TurbState { value: *last, given: true };
                            self.turb(t, &mut s)?;
                            *last = s.value;
                        }
                    } else if let Some(t) = state.finish() {
                        pd.warps.push(place(Warp::Turbulence(t)));
                    }
                }
                WarpAst::Repeat { dir, offset, flip } => {
                    let dir = self.vec3(dir)?;
                    let offset = match offset {
                        Some(e) => self.vec3(e)?,
                        None => DVec3::ZERO,
                    };
                    let flip = match flip {
                        Some(e) => self.vec3(e)?,
                        None => DVec3::ZERO,
                    };
                    pd.warps.push(place(Warp::Repeat { dir, offset, flip }));
                }
                WarpAst::BlackHole { center, radius, strength, falloff, inverse, repeat, turbulence } => {
                    let opt = |l: &Self, e: &Option<Expr>, d: f64| match e {
                        Some(e) => l.float(e),
                        None => Ok(d),
                    };
                    if let Some(span) = turbulence {
                        self.warn(Diag::new(
                            *span,
                            "black_hole `turbulence` (jittered repeats) is not modelled; the holes repeat exactly",
                        ));
                    }
                    let repeat = match repeat {
                        Some(e) => self.vec3(e)?.max(DVec3::ZERO),
                        None => DVec3::ZERO,
                    };
                    // Repeated holes must lie inside their cells: along a repeated axis the
                    // centre is at least the radius into the cell and the cell at least the
                    // centre plus the radius wide (POV-Ray moves them the same way, measured:
                    // `black_hole 0, 0.3 repeat <0.8, 0.8, 0>` centres its holes at 0.3).
                    let (mut center, radius) = (self.vec3(center)?, self.float(radius)?);
                    let mut repeat = repeat;
                    for a in 0..3 {
                        if repeat[a] > 0.0 {
                            center[a] = center[a].max(radius);
                            repeat[a] = repeat[a].max(center[a] + radius);
                        }
                    }
                    pd.warps.push(place(Warp::BlackHole {
                        center,
                        radius,
                        strength: opt(self, strength, 1.0)?,
                        falloff: opt(self, falloff, 2.0)?,
                        inverse: *inverse,
                        repeat,
                    }));
                }
                WarpAst::Mapping { map, plane, orientation, dist_exp, major_radius } => {
                    let opt = |l: &Self, e: &Option<Expr>, d: f64| match e {
                        Some(e) => l.float(e),
                        None => Ok(d),
                    };
                    let (map, orientation) = match (map.as_str(), plane) {
                        ("cylindrical", _) => (WarpMap::Cylindrical, orientation.as_ref()),
                        ("spherical", _) => (WarpMap::Spherical, orientation.as_ref()),
                        ("toroidal", _) => {
                            (WarpMap::Toroidal { major_radius: opt(self, major_radius, 1.0)? }, orientation.as_ref())
                        }
                        ("planar", Some((normal, distance))) => {
                            (WarpMap::Planar { distance: self.float(distance)? }, Some(normal))
                        }
                        ("planar", None) => (WarpMap::Planar { distance: 0.0 }, None),
                        _ => (WarpMap::Cubic, None),
                    };
                    let orientation = match orientation {
                        Some(e) => self.vec3(e)?.try_normalize().unwrap_or(DVec3::Z),
                        None => DVec3::Z,
                    };
                    let dist_exp = opt(self, dist_exp, 0.0)?;
                    pd.warps.push(place(Warp::Mapping { map, orientation, dist_exp }));
                }
                WarpAst::Other(word, span) => {
                    self.warn(Diag::new(*span, format!("warp `{word}` is not modelled; ignored")));
                }
            },
        }
        Ok(())
    }
}
