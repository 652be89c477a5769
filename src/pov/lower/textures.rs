//! Surface blocks → `PigmentDesc`, `NormalDesc`, `FinishDesc`, `TextureDesc`, `InteriorDesc`.
//! A block that starts with a declared name copies it, then applies the rest in written order.

use glam::DVec3;

use super::Lowerer;
use crate::pov::ast::{
    ColorMap, ColorMapBody, Expr, ExprKind, Finish, FinishItem, FinishKey, Interior, InteriorItem, Normal, NormalItem,
    Pigment, PigmentItem, Texture, TextureItem, Turb, TurbKind,
};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
use crate::scene::desc::{
    Color, ColorMapEntry, FinishDesc, InteriorDesc, NormalDesc, NormalPattern, PigmentDesc, PigmentPattern,
    TextureDesc, Transform, Turbulence,
};

/// POV-Ray's `bumps` amount when none is written.
const DEFAULT_BUMPS: f64 = 0.5;

/// The pattern while a pigment block is read; the map is checked against it at the end.
enum Pattern {
    Solid(Color),
    Checker(Color, Color),
    Wood,
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
    fn declared<'v>(&'v self, e: &'v Expr) -> PResult<Option<&'v Value>> {
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
    pub(super) fn pigment(&mut self, p: &Pigment) -> PResult<PigmentDesc> {
        let (mut pattern, mut map, mut turb, mut transform) = pigment_state(self.default_texture.pigment.clone());
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
                PigmentItem::Color(e) => pattern = Pattern::Solid(self.color(e)?),
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
                PigmentItem::Transform(t) => transform = transform.then(&self.transform(t)?),
            }
        }
        let pattern = match (pattern, map) {
            (Pattern::Wood, Some((m, _))) => PigmentPattern::Wood(m),
            (Pattern::Wood, None) => PigmentPattern::Wood(default_wood_map()),
            (_, Some((_, Some(span)))) => {
                return Err(Diag::new(span, "color_map needs a pattern that uses it (supported: wood)"))
            }
            (Pattern::Solid(c), _) => PigmentPattern::Solid(c),
            (Pattern::Checker(a, b), _) => PigmentPattern::Checker(a, b),
        };
        Ok(PigmentDesc { pattern, turbulence: turb.finish(), transform })
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

    pub(super) fn normal(&mut self, n: &Normal) -> PResult<NormalDesc> {
        let start = self.default_texture.normal.clone();
        let mut pattern = start.as_ref().map(|n| n.pattern.clone());
        let mut turb = TurbState::from(start.as_ref().and_then(|n| n.turbulence));
        let mut transform = start.map_or_else(Transform::default, |n| n.transform);
        for item in &n.items {
            match item {
                NormalItem::Base(e) => match self.declared(e)? {
                    Some(Value::Normal(base)) => {
                        let base = (**base).clone();
                        pattern = Some(base.pattern);
                        turb = TurbState::from(base.turbulence);
                        transform = base.transform;
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
                NormalItem::Transform(t) => transform = transform.then(&self.transform(t)?),
            }
        }
        let pattern = pattern.ok_or_else(|| Diag::new(n.span, "normal needs a pattern (supported: bumps)"))?;
        Ok(NormalDesc { pattern, turbulence: turb.finish(), transform })
    }

    pub(super) fn finish_block(&mut self, f: &Finish) -> PResult<FinishDesc> {
        let mut out = self.default_texture.finish;
        for item in &f.items {
            match item {
                FinishItem::Base(e) => match self.declared(e)? {
                    Some(Value::Finish(base)) => out = *base,
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared finish")),
                    None => return Err(Diag::new(e.span, "expected a declared finish")),
                },
                FinishItem::Set(key, e) => match key {
                    FinishKey::Ambient => out.ambient = self.color(e)?.rgb,
                    FinishKey::Reflection => out.reflection = self.color(e)?.rgb,
                    FinishKey::Diffuse => out.diffuse = self.float(e)?,
                    FinishKey::Brilliance => out.brilliance = self.float(e)?,
                    FinishKey::Phong => out.phong = self.float(e)?,
                    FinishKey::PhongSize => out.phong_size = self.float(e)?,
                    FinishKey::Specular => out.specular = self.float(e)?,
                    FinishKey::Roughness => {
                        let r = self.float(e)?;
                        if r <= 0.0 {
                            return Err(Diag::new(e.span, "roughness must be positive"));
                        }
                        out.roughness = r;
                    }
                    FinishKey::Metallic => out.metallic = self.float(e)?,
                    FinishKey::Emission => out.emission = self.color(e)?.rgb,
                    FinishKey::ReflectionExponent => out.reflection_exponent = self.float(e)?,
                    FinishKey::ConserveEnergy => out.conserve_energy = self.float(e)? != 0.0,
                    FinishKey::DiffuseAlbedo => {
                        out.diffuse = self.float(e)?;
                        out.albedo.diffuse = true;
                    }
                    FinishKey::PhongAlbedo => {
                        out.phong = self.float(e)?;
                        out.albedo.phong = true;
                    }
                    FinishKey::SpecularAlbedo => {
                        out.specular = self.float(e)?;
                        out.albedo.specular = true;
                    }
                },
                FinishItem::Reflection(r) => {
                    out.reflection = self.color(&r.max)?.rgb;
                    out.reflection_fresnel = match &r.fresnel {
                        Some(e) => self.float(e)? != 0.0,
                        None => false,
                    };
                    // One colour is a constant reflection, but a Fresnel one rises from zero.
                    out.reflection_min = match &r.min {
                        Some(e) => Some(self.color(e)?.rgb),
                        None if out.reflection_fresnel => Some(DVec3::ZERO),
                        None => None,
                    };
                    if let Some(e) = &r.falloff {
                        out.reflection_falloff = self.float(e)?;
                    }
                    if let Some(e) = &r.exponent {
                        out.reflection_exponent = self.float(e)?;
                    }
                    if let Some(e) = &r.metallic {
                        out.reflection_metallic = self.float(e)?;
                    }
                }
            }
        }
        Ok(out)
    }

    pub(super) fn texture(&mut self, t: &Texture) -> PResult<TextureDesc> {
        let mut out = self.default_texture.clone();
        for item in &t.items {
            match item {
                TextureItem::Base(e) => match self.declared(e)? {
                    Some(Value::Texture(base)) => out = (**base).clone(),
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared texture")),
                    None => return Err(Diag::new(e.span, "expected a declared texture")),
                },
                TextureItem::Pigment(p) => out.pigment = self.pigment(p)?,
                TextureItem::Normal(n) => out.normal = Some(self.normal(n)?),
                TextureItem::Finish(f) => out.finish = self.finish_block(f)?,
                TextureItem::Transform(tr) => {
                    let tr = self.transform(tr)?;
                    transform_texture(&mut out, &tr);
                }
            }
        }
        Ok(out)
    }

    pub(super) fn interior(&mut self, i: &Interior) -> PResult<InteriorDesc> {
        let mut out = InteriorDesc::default();
        for item in &i.items {
            match item {
                InteriorItem::Base(e) => match self.declared(e)? {
                    Some(Value::Interior(base)) => out = *base,
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared interior")),
                    None => return Err(Diag::new(e.span, "expected a declared interior")),
                },
                InteriorItem::Ior(e) => {
                    let ior = self.float(e)?;
                    if ior <= 0.0 {
                        return Err(Diag::new(e.span, "ior must be positive"));
                    }
                    out.ior = ior;
                }
            }
        }
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

/// Carries a texture's patterns along with a transform applied after them.
pub(super) fn transform_texture(t: &mut TextureDesc, tr: &Transform) {
    t.pigment.transform = t.pigment.transform.then(tr);
    if let Some(n) = &mut t.normal {
        n.transform = n.transform.then(tr);
    }
}
