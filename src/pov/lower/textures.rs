//! Pigment and normal blocks → `PigmentDesc`, `NormalDesc`: patterns, their modifiers, colour,
//! pigment and normal maps. A block that starts with a declared name copies it, then applies the
//! rest in written order. (Textures: `texture_block`; finishes and interiors: `finish`.)

use glam::DVec3;

use super::Lowerer;
use crate::pov::ast::{
    ColorItem, ColorKey, ColorMap, ColorMapBody, Expr, ExprKind, Normal, NormalItem, PatternAst, PatternMod, Pigment,
    PigmentItem, SlopeMapBody, Stmt, Turb, TurbKind, WarpAst,
};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
use crate::scene::desc::{
    Color, ColorMapEntry, Fractal, FractalKind, NormalDesc, NormalPattern, PatternDesc, PatternKind, PigmentDesc,
    PigmentPattern, SlopeEntry, Transform, Turbulence, Warp, Wave, DEFAULT_NORMAL_ACCURACY,
};

/// POV-Ray's `bumps` amount when none is written.
const DEFAULT_BUMPS: f64 = 0.5;
/// `bump_map`'s `bump_size` when none is written.
const DEFAULT_BUMP_MAP: f64 = 1.0;

/// The pattern while a pigment block is read; the map is checked against it at the end.
enum Pattern {
    Solid(Color),
    Checker(Color, Color),
    Wood,
    /// A pattern of the kernel layer, with the pigments of a list pattern.
    Generic(PatternDesc, Vec<PigmentDesc>),
    /// A `pigment_map` or list pigment this pigment started from.
    Done(PigmentPattern),
}

/// A pigment's colour map while its block is read, with the `color_map` written in the block
/// (none for a map that came with the pigment it started from).
type MapState = Option<(Vec<ColorMapEntry>, Option<Span>)>;

/// Turbulence being built: `octaves` etc. may come before `turbulence`.
struct TurbState {
    value: Turbulence,
    given: bool,
}

impl TurbState {
    fn from(t: Option<Turbulence>) -> Self {
        TurbState { given: t.is_some(), value: t.unwrap_or_default() }
    }

    fn finish(self) -> Option<Turbulence> {
        self.given.then_some(self.value)
    }
}

impl Lowerer<'_> {
    /// A leading name in a block: the declared value, or an error naming what it is.
    pub(super) fn declared<'v>(&'v self, e: &'v Expr) -> PResult<Option<&'v Value>> {
        match &e.kind {
            ExprKind::Value(v) => match &**v {
                Value::Unmodelled(u) => Err(u.used_at(e.span)),
                v => Ok(Some(v)),
            },
            ExprKind::Ident(name) => Err(Diag::new(e.span, format!("undefined identifier `{name}`"))),
            _ => Ok(None),
        }
    }

    fn turb(&self, t: &Turb, state: &mut TurbState) -> PResult<()> {
        match t.kind {
            TurbKind::Turbulence => {
                state.value.amount = self.vec3(&t.value)?;
                state.given = true;
            }
            TurbKind::Octaves => {
                let n = self.float(&t.value)?;
                if !(1.0..=10.0).contains(&n) {
                    return Err(Diag::new(t.value.span, "octaves must be between 1 and 10"));
                }
                state.value.octaves = n as u32;
            }
            TurbKind::Omega => state.value.omega = self.float(&t.value)?,
            TurbKind::Lambda => state.value.lambda = self.float(&t.value)?,
        }
        Ok(())
    }

    /// A pigment block: it starts from the default pigment (POV-Ray: `pigment { scale 2 }`
    /// after `#default { pigment { Red } }` is red), or from the declared pigment it names.
    pub(crate) fn pigment(&mut self, p: &Pigment) -> PResult<PigmentDesc> {
        let (mut pattern, mut map, mut turb, mut transform) = pigment_state(self.default_texture.pigment.clone());
        let mut own_transform = Transform::default();
        let mut default_map = default_pattern_map("");
        let mut pigment_map: Option<(Vec<(f64, PigmentDesc)>, Span)> = None;
        for item in &p.items {
            match item {
                PigmentItem::Base(e) => {
                    if let Some(Value::Pigment(base)) = self.declared(e)? {
                        (pattern, map, turb, transform) = pigment_state((**base).clone());
                    } else {
                        pattern = Pattern::Solid(self.eval(e)?.as_color(e.span).map_err(|_| {
                            Diag::new(e.span, "expected a declared pigment or a color at the start of `pigment`")
                        })?);
                    }
                }
                PigmentItem::Color(e) => {
                    // Components alone after a colour change it: `pigment { White filter .7 }`.
                    let components = |items: &[ColorItem]| {
                        items.iter().all(|i| {
                            matches!(
                                i.key,
                                ColorKey::Red
                                    | ColorKey::Green
                                    | ColorKey::Blue
                                    | ColorKey::Filter
                                    | ColorKey::Transmit
                            )
                        })
                    };
                    pattern = Pattern::Solid(match (&pattern, &e.kind) {
                        (Pattern::Solid(base), ExprKind::Color(items)) if components(items) => {
                            self.color_items(*base, items)?
                        }
                        _ => self.color(e)?,
                    });
                }
                PigmentItem::Checker(colors, _) => {
                    // POV-Ray's checker colours when none are given: blue and green.
                    let a = match colors.first() {
                        Some(e) => self.color(e)?,
                        None => Color::rgb(0.0, 0.0, 1.0),
                    };
                    let b = match colors.get(1) {
                        Some(e) => self.color(e)?,
                        None => Color::rgb(0.0, 1.0, 0.0),
                    };
                    pattern = Pattern::Checker(a, b);
                }
                PigmentItem::Wood(_) => pattern = Pattern::Wood,
                PigmentItem::ColorMap(m) => map = Some((self.color_map(m)?, Some(m.span))),
                PigmentItem::Turb(t) => self.turb(t, &mut turb)?,
                PigmentItem::Transform(t) => {
                    let t = self.transform(t)?;
                    transform = transform.then(&t);
                    own_transform = own_transform.then(&t);
                }
                PigmentItem::Pattern(pa) => {
                    let kind = self.pattern_kind(pa)?;
                    let mut list = Vec::new();
                    for c in &pa.colors {
                        list.push(PigmentDesc { pattern: PigmentPattern::Solid(self.color(c)?), ..Default::default() });
                    }
                    for p in &pa.pigments {
                        list.push(self.pigment(p)?);
                    }
                    if let Some(n) = kind.list_len() {
                        if list.len() > n {
                            return Err(Diag::new(
                                pa.span,
                                format!("{} takes at most {n} colours or pigments", pa.name),
                            ));
                        }
                        let defaults = default_list_colors(&kind);
                        while list.len() < n {
                            let c = defaults[list.len()];
                            list.push(PigmentDesc { pattern: PigmentPattern::Solid(c), ..Default::default() });
                        }
                    }
                    pattern = Pattern::Generic(PatternDesc::new(kind), list);
                    default_map = default_pattern_map(&pa.name);
                }
                PigmentItem::Mod(m) => {
                    if let Pattern::Wood = pattern {
                        pattern = Pattern::Generic(PatternDesc::new(PatternKind::Wood), Vec::new());
                    }
                    if let Pattern::Generic(pd, _) = &mut pattern {
                        self.pattern_mod(m, pd)?;
                    }
                }
                PigmentItem::ImageMap(im, _) => pattern = Pattern::Done(PigmentPattern::ImageMap(im.clone())),
                PigmentItem::UvMapping(_) => {}
                PigmentItem::ImagePattern(im, _) => {
                    pattern = Pattern::Generic(PatternDesc::new(PatternKind::Image(im.clone())), Vec::new())
                }
                PigmentItem::PigmentMap(entries, span) => {
                    let mut out = Vec::with_capacity(entries.len());
                    for (v, p) in entries {
                        out.push((self.float(v)?, self.pigment(p)?));
                    }
                    pigment_map = Some((out, *span));
                }
            }
        }
        // Transforms written in this block also move the pigments it is made of.
        let children = |mut list: Vec<PigmentDesc>| {
            list.iter_mut().for_each(|p| p.transform_by(&own_transform));
            list
        };
        let pattern = match (pattern, map) {
            (Pattern::Wood, Some((m, _))) => PigmentPattern::Wood(m),
            (Pattern::Wood, None) => PigmentPattern::Wood(default_wood_map()),
            (Pattern::Generic(pd, list), map) if pd.kind.list_len().is_some() => {
                if let Some((_, Some(span))) = map {
                    return Err(Diag::new(span, "a list pattern (checker, brick, hexagon) takes no color_map"));
                }
                PigmentPattern::List(pd, children(list))
            }
            (Pattern::Generic(pd, _), map) => match (pigment_map, map) {
                (Some((entries, _)), _) => {
                    let mut entries = entries;
                    entries.iter_mut().for_each(|(_, p)| p.transform_by(&own_transform));
                    entries.sort_by(|a, b| a.0.total_cmp(&b.0));
                    PigmentPattern::PigmentMap(pd, entries)
                }
                (None, Some((m, _))) => PigmentPattern::Mapped(pd, m),
                (None, None) => PigmentPattern::Mapped(pd, default_map),
            },
            (Pattern::Done(p), _) => p,
            (_, Some((_, Some(span)))) => return Err(Diag::new(span, "color_map needs a pattern that uses it")),
            (Pattern::Solid(c), _) => PigmentPattern::Solid(c),
            (Pattern::Checker(a, b), _) => PigmentPattern::Checker(a, b),
        };
        Ok(PigmentDesc { pattern, turbulence: turb.finish(), transform })
    }

    /// The pattern a keyword names, with its argument.
    pub(super) fn pattern_kind(&mut self, pa: &PatternAst) -> PResult<PatternKind> {
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
                let grid = crate::shading::patterns::density::DensityGrid::from_df3(&bytes)
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
            other => return Err(Diag::new(pa.span, format!("unknown pattern `{other}`"))),
        })
    }

    /// The solid of an `object` pattern: its object written out or declared, asked by
    /// `scene::probe`.
    fn pattern_object(&mut self, pa: &PatternAst) -> PResult<crate::scene::desc::SolidRef> {
        let parts = match (&pa.object, &pa.arg) {
            (Some(o), _) => self.children(&[Stmt::Object((**o).clone())], "object", pa.span)?,
            (None, Some(e)) => match self.eval(e)? {
                Value::Object(g) => g.parts.clone(),
                other => return Err(other.wrong_kind(e.span, "the object of an `object` pattern")),
            },
            (None, None) => return Err(Diag::new(pa.span, "the `object` pattern needs an object")),
        };
        let objects: Vec<_> = parts.into_iter().map(|p| p.into_desc(&Default::default())).collect();
        Ok(crate::scene::probe::solid(&objects))
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
    pub(super) fn pattern_mod(&mut self, m: &PatternMod, pd: &mut PatternDesc) -> PResult<()> {
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
                    if let (false, Some(Warp::Turbulence(last))) = (state.given, pd.warps.last_mut()) {
                        for t in items {
                            let mut s = TurbState { value: *last, given: true };
                            self.turb(t, &mut s)?;
                            *last = s.value;
                        }
                    } else if let Some(t) = state.finish() {
                        pd.warps.push(Warp::Turbulence(t));
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
                    pd.warps.push(Warp::Repeat { dir, offset, flip });
                }
                WarpAst::BlackHole { center, radius, strength, falloff, inverse } => {
                    let opt = |l: &Self, e: &Option<Expr>, d: f64| match e {
                        Some(e) => l.float(e),
                        None => Ok(d),
                    };
                    pd.warps.push(Warp::BlackHole {
                        center: self.vec3(center)?,
                        radius: self.float(radius)?,
                        strength: opt(self, strength, 1.0)?,
                        falloff: opt(self, falloff, 2.0)?,
                        inverse: *inverse,
                    });
                }
                WarpAst::Other(word, span) => {
                    self.warn(Diag::new(*span, format!("warp `{word}` is not modelled; ignored")));
                }
            },
        }
        Ok(())
    }

    /// A colour map's entries in the sorted form the renderer reads (see `sorted_map`), or a
    /// copy of the declared map it names.
    pub(super) fn color_map(&mut self, m: &ColorMap) -> PResult<Vec<ColorMapEntry>> {
        let entries = match &m.body {
            ColorMapBody::Named(e) => {
                return match self.declared(e)? {
                    Some(Value::ColorMap(map)) => Ok(map.clone()),
                    Some(other) => Err(other.wrong_kind(e.span, "a declared color_map")),
                    None => Err(Diag::new(e.span, "expected the name of a declared color_map or `[` entries")),
                };
            }
            ColorMapBody::Entries(entries) => entries,
        };
        let mut out = Vec::with_capacity(entries.len());
        for entry in entries {
            out.push(ColorMapEntry { value: self.float(&entry.value)?, color: self.color(&entry.color)? });
        }
        Ok(sorted_map(&out))
    }

    /// `#default { normal { .. } }`: POV-Ray 3.7 takes one without a pattern
    /// (`normal { bump_size 1.5 }`, textures/normals/normmap.pov) as no default normal; its
    /// amount would only matter to patterns written later, which bring their own.
    pub(super) fn default_normal(&mut self, n: &Normal) -> PResult<Option<NormalDesc>> {
        let has_pattern = self.default_texture.normal.is_some()
            || n.items
                .iter()
                .any(|i| !matches!(i, NormalItem::BumpSize(_) | NormalItem::Transform(_) | NormalItem::Turb(_)));
        if !has_pattern {
            return Ok(None);
        }
        self.normal(n).map(Some)
    }

    pub(super) fn normal(&mut self, n: &Normal) -> PResult<NormalDesc> {
        let start = self.default_texture.normal.clone();
        let mut pattern = start.as_ref().map(|n| n.pattern.clone());
        let mut turb = TurbState::from(start.as_ref().and_then(|n| n.turbulence));
        let mut slope_map = start.as_ref().map(|n| n.slope_map.clone()).unwrap_or_default();
        let mut slope_span = None;
        let mut accuracy = start.as_ref().map_or(DEFAULT_NORMAL_ACCURACY, |n| n.accuracy);
        let mut transform = start.map_or_else(Transform::default, |n| n.transform);
        // Transforms written in this block: they also move a normal_map's normals.
        let mut own = Transform::default();
        for item in &n.items {
            match item {
                NormalItem::Base(e) => match self.declared(e)? {
                    Some(Value::Normal(base)) => {
                        let base = (**base).clone();
                        pattern = Some(base.pattern);
                        turb = TurbState::from(base.turbulence);
                        transform = base.transform;
                        slope_map = base.slope_map;
                        accuracy = base.accuracy;
                    }
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared normal")),
                    None => return Err(Diag::new(e.span, "expected a declared normal or a normal pattern")),
                },
                NormalItem::Bumps(amount, _) => {
                    let a = match amount {
                        Some(e) => self.float(e)?,
                        None => DEFAULT_BUMPS,
                    };
                    pattern = Some(NormalPattern::Bumps(a));
                }
                NormalItem::Turb(t) => self.turb(t, &mut turb)?,
                NormalItem::Transform(t) => {
                    let t = self.transform(t)?;
                    transform = transform.then(&t);
                    own = own.then(&t);
                }
                NormalItem::Pattern(pa, amount) => {
                    let a = match amount {
                        Some(e) => self.float(e)?,
                        None => DEFAULT_BUMPS,
                    };
                    let kind = self.pattern_kind(pa)?;
                    pattern = Some(NormalPattern::Pattern(PatternDesc::new(kind), a));
                }
                NormalItem::Mod(m) => {
                    if let Some(NormalPattern::Pattern(pd, _) | NormalPattern::Map(pd, _)) = &mut pattern {
                        self.pattern_mod(m, pd)?;
                    }
                }
                NormalItem::BumpSize(e) => {
                    let v = self.float(e)?;
                    match &mut pattern {
                        Some(NormalPattern::Pattern(_, a)) | Some(NormalPattern::Bumps(a)) => *a = v,
                        // A normal_map's entries carry their own amounts.
                        Some(NormalPattern::Map(..)) | None => {}
                    }
                }
                NormalItem::BumpMap(im, size) => {
                    let a = match size {
                        Some(e) => self.float(e)?,
                        None => DEFAULT_BUMP_MAP,
                    };
                    pattern = Some(NormalPattern::Pattern(PatternDesc::new(PatternKind::Image(im.clone())), a));
                }
                NormalItem::ImagePattern(im, amount) => {
                    let a = match amount {
                        Some(e) => self.float(e)?,
                        None => DEFAULT_BUMPS,
                    };
                    pattern = Some(NormalPattern::Pattern(PatternDesc::new(PatternKind::Image(im.clone())), a));
                }
                NormalItem::NormalMap(entries, span) => {
                    let Some(NormalPattern::Pattern(pd, _)) = &pattern else {
                        return Err(Diag::new(*span, "normal_map needs a pattern before it (e.g. gradient x)"));
                    };
                    let pd = pd.clone();
                    let mut list = Vec::with_capacity(entries.len());
                    for (v, n) in entries {
                        list.push((self.float(v)?, self.normal(n)?));
                    }
                    list.sort_by(|a, b| a.0.total_cmp(&b.0));
                    pattern = Some(NormalPattern::Map(pd, list));
                }
                NormalItem::Accuracy(e) => {
                    accuracy = self.float(e)?;
                    if !(accuracy > 0.0 && accuracy.is_finite()) {
                        return Err(Diag::new(e.span, format!("`accuracy` must be above 0, found {accuracy}")));
                    }
                }
                NormalItem::SlopeMap(body, span) => {
                    slope_map = self.slope_map(body)?;
                    slope_span = Some(*span);
                }
            }
        }
        let mut pattern =
            pattern.ok_or_else(|| Diag::new(n.span, "normal needs a pattern (e.g. bumps, dents, gradient)"))?;
        // POV-Ray 3.7 ignores a slope_map on the normals that have their own shape (measured:
        // `waves 1` and `dents 1` render the same with a flat map), and on normal maps.
        let own_shape = match &pattern {
            NormalPattern::Bumps(_) => Some("bumps"),
            NormalPattern::Map(..) => Some("normal_map"),
            NormalPattern::Pattern(pd, _) => match pd.kind {
                PatternKind::Wrinkles => Some("wrinkles"),
                PatternKind::Dents => Some("dents"),
                PatternKind::Ripples => Some("ripples"),
                PatternKind::Waves => Some("waves"),
                PatternKind::Image(_) => Some("bump_map"),
                _ => None,
            },
        };
        if let (Some(name), false) = (own_shape, slope_map.is_empty()) {
            if let Some(span) = slope_span {
                self.warn(Diag::new(span, format!("`slope_map` has no effect on `{name}` (as in POV-Ray); ignored")));
            }
            slope_map.clear();
        }
        // Transforms written in this block also move the map's normals, as a pigment's move
        // its pigment_map's.
        if let NormalPattern::Map(_, entries) = &mut pattern {
            entries.iter_mut().for_each(|(_, e)| e.transform_by(&own));
        }
        Ok(NormalDesc { pattern, turbulence: turb.finish(), transform, slope_map, accuracy })
    }

    /// A `slope_map`'s entries, sorted by value (entries of one value keep their order: the
    /// later one starts the next interval, as in a colour map's sharp edge).
    pub(super) fn slope_map(&mut self, body: &SlopeMapBody) -> PResult<Vec<SlopeEntry>> {
        let entries = match body {
            SlopeMapBody::Named(e) => {
                return match self.declared(e)? {
                    Some(Value::SlopeMap(map)) => Ok(map.clone()),
                    Some(other) => Err(other.wrong_kind(e.span, "a declared slope_map")),
                    None => {
                        Err(Diag::new(e.span, "expected a declared slope_map or `[value, <height, slope>]` entries"))
                    }
                };
            }
            SlopeMapBody::Entries(entries) => entries,
        };
        let mut out = Vec::with_capacity(entries.len());
        for (value, point, span) in entries {
            let value = self.float(value)?;
            let hs = match self.eval(point)? {
                Value::Vector(c) if c.len() >= 2 => [c[0], c[1]],
                Value::Float(f) => [f, f],
                other => {
                    return Err(Diag::new(
                        *span,
                        format!("a slope_map entry needs `<height, slope>`, found {}", other.kind_name()),
                    ))
                }
            };
            if !(value.is_finite() && hs[0].is_finite() && hs[1].is_finite()) {
                return Err(Diag::new(*span, "a slope_map entry's value, height and slope must be finite"));
            }
            out.push(SlopeEntry { value, height: hs[0], slope: hs[1] });
        }
        out.sort_by(|a, b| a.value.total_cmp(&b.value));
        Ok(out)
    }
}

/// POV-Ray 3.7's map for `wood` without a `color_map`: light tan up to 0.6, then dark brown,
/// with a hard edge. Measured by rendering `plane { z, 0 pigment { wood } }` with `ambient 1
/// diffuse 0` and `File_Gamma=1.0`: rings switch colour at radius 0.3 and 0.7, i.e. at 0.6 of
/// the triangle wave, and the colours read back as (170, 80, 51) and (102, 34, 17) / 255.
fn default_wood_map() -> Vec<ColorMapEntry> {
    let tan = Color::rgb(0.666, 0.312, 0.2);
    let brown = Color::rgb(0.4, 0.133, 0.066);
    [(0.0, tan), (0.6, tan), (0.6, brown), (1.0, brown)]
        .into_iter()
        .map(|(value, color)| ColorMapEntry { value, color })
        .collect()
}

/// POV-Ray's colours of a list pattern written without them.
fn default_list_colors(kind: &PatternKind) -> [Color; 3] {
    match kind {
        // brick: mortar grey, brick red.
        PatternKind::Brick { .. } => [Color::rgb(0.5, 0.5, 0.5), Color::rgb(0.6, 0.15, 0.15), Color::BLACK],
        PatternKind::Hexagon => [Color::rgb(0.0, 0.0, 1.0), Color::rgb(0.0, 1.0, 0.0), Color::rgb(1.0, 0.0, 0.0)],
        _ => [Color::rgb(0.0, 0.0, 1.0), Color::rgb(0.0, 1.0, 0.0), Color::BLACK],
    }
}

/// The map of pattern `name` written without one: black to white, but `bozo`, `marble`,
/// `agate`, `radial` and `mandel` have maps of their own (`spotted` and `bumps`, bozo's noise,
/// do not). Measured with `#debug` on `function { pigment { P } }` beside `function {
/// pattern { P } }` at 3000 points each (mandel at 100000 iterations for its low values):
/// bozo steps white, green, blue, red at 0.4, 0.6, 0.8; marble runs from (0.9, 0.8, 0.8) down
/// by 0.8 per unit in green and blue to 0.9, then black; the others as below (to 1e-3).
fn default_pattern_map(name: &str) -> Vec<ColorMapEntry> {
    let entries: &[(f64, [f64; 3])] = match name {
        "bozo" => &[
            (0.0, [1.0, 1.0, 1.0]),
            (0.4, [1.0, 1.0, 1.0]),
            (0.4, [0.0, 1.0, 0.0]),
            (0.6, [0.0, 1.0, 0.0]),
            (0.6, [0.0, 0.0, 1.0]),
            (0.8, [0.0, 0.0, 1.0]),
            (0.8, [1.0, 0.0, 0.0]),
            (1.0, [1.0, 0.0, 0.0]),
        ],
        "marble" => &[(0.0, [0.9, 0.8, 0.8]), (0.9, [0.9, 0.08, 0.08]), (0.9, [0.0; 3]), (1.0, [0.0; 3])],
        "agate" => &[
            (0.0, [1.0, 1.0, 1.0]),
            (0.5, [0.95, 0.75, 0.5]),
            (0.5, [0.9, 0.7, 0.5]),
            (0.6, [0.9, 0.7, 0.4]),
            (0.6, [1.0, 0.7, 0.4]),
            (1.0, [0.6, 0.3, 0.0]),
        ],
        "radial" => &[
            (0.0, [0.0, 1.0, 1.0]),
            (1.0 / 3.0, [1.0, 1.0, 0.0]),
            (2.0 / 3.0, [1.0, 0.0, 1.0]),
            (1.0, [0.0, 1.0, 1.0]),
        ],
        "mandel" => &[
            (0.0, [0.0; 3]),
            (0.001, [0.0; 3]),
            (0.001, [0.0, 1.0, 1.0]),
            (0.012, [1.0, 1.0, 0.0]),
            (0.015, [1.0, 0.0, 1.0]),
            (0.1, [0.0, 1.0, 1.0]),
            (1.0, [0.0, 1.0, 1.0]),
        ],
        _ => &[(0.0, [0.0; 3]), (1.0, [1.0; 3])],
    };
    entries.iter().map(|&(value, [r, g, b])| ColorMapEntry { value, color: Color::rgb(r, g, b) }).collect()
}

/// The state `pigment` edits, from a pigment it starts from: pattern, map (with no span: a
/// map that came with it is not an error when the pattern changes), turbulence, transform.
fn pigment_state(p: PigmentDesc) -> (Pattern, MapState, TurbState, Transform) {
    let mut map = None;
    let pattern = match p.pattern {
        PigmentPattern::Solid(c) => Pattern::Solid(c),
        PigmentPattern::Checker(a, b) => Pattern::Checker(a, b),
        PigmentPattern::Wood(m) => {
            map = Some((m, None));
            Pattern::Wood
        }
        PigmentPattern::Mapped(pd, m) => {
            map = Some((m, None));
            Pattern::Generic(pd, Vec::new())
        }
        other => Pattern::Done(other),
    };
    (pattern, map, TurbState::from(p.turbulence), p.transform)
}

/// POV-Ray reads a colour map in written order, not sorted: a value at or above the last
/// entry's gets the last colour; any other value blends the pair that ends at the first entry
/// at or above it (so an entry below an earlier one only starts the next pair, and values
/// outside 0–1 are fine). Measured by rendering `gradient x` maps with `ambient 1 diffuse 0`:
/// `[0 R][0.8 B][0.3 G]` is R→B up to 0.3, then G. This returns sorted entries that give the
/// same colours under the renderer's lookup (which assumes sorted entries); entries already in
/// order come back unchanged.
pub(super) fn sorted_map(entries: &[ColorMapEntry]) -> Vec<ColorMapEntry> {
    let Some((&first, &last)) = entries.first().zip(entries.last()) else { return Vec::new() };
    let mut out = vec![first];
    let mut top = first.value;
    for pair in entries.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        if b.value <= top {
            continue;
        }
        // This pair is what values in (top, b] read.
        let start = ColorMapEntry { value: top, color: blend(a, b, top) };
        if out.last() != Some(&start) {
            out.push(start);
        }
        out.push(b);
        top = b.value;
    }
    if last.value < top {
        let below = ColorMapEntry { value: last.value, color: sorted_lookup(&out, last.value) };
        out.retain(|e| e.value < last.value);
        out.extend([below, last]);
    } else if out.last() != Some(&last) {
        // Ends at the top value with another colour: a hard step there.
        out.push(last);
    }
    out
}

/// The colour `a`→`b` gives at `v`.
fn blend(a: ColorMapEntry, b: ColorMapEntry, v: f64) -> Color {
    if v <= a.value {
        return a.color;
    }
    let t = (v - a.value) / (b.value - a.value);
    let mix = |x: f64, y: f64| x + (y - x) * t;
    Color {
        rgb: a.color.rgb + (b.color.rgb - a.color.rgb) * t,
        filter: mix(a.color.filter, b.color.filter),
        transmit: mix(a.color.transmit, b.color.transmit),
    }
}

/// The colour of sorted entries at `v`, as the renderer reads them.
fn sorted_lookup(entries: &[ColorMapEntry], v: f64) -> Color {
    match entries.iter().position(|e| v <= e.value) {
        Some(0) => entries[0].color,
        Some(i) => blend(entries[i - 1], entries[i], v),
        None => entries[entries.len() - 1].color,
    }
}
