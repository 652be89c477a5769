//! `texture { }` blocks → `TextureDesc`: a texture's pigment, normal and finish, its layers
//! (`texture {A} texture {B}`), patterns of whole textures (list patterns, `texture_map`,
//! `material_map`) and where it says `uv_mapping`.

use super::Lowerer;
use crate::desc::{
    FinishDesc, PatternDesc, PatternKind, PigmentDesc, PigmentPattern, TextureDesc, TexturePatternDesc, Transform,
};
use crate::pov::ast::{PigmentItem, Texture, TextureItem};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
use glam::DVec3;

impl Lowerer<'_> {
    pub(super) fn texture(&mut self, t: &Texture) -> PResult<TextureDesc> {
        let mut out = (*self.default_texture).clone();
        let mut pattern: Option<PatternDesc> = None;
        // The textures of a list pattern (`checker texture {..} texture {..}`), or of a map.
        let mut list: Vec<TextureDesc> = Vec::new();
        let mut texture_map: Option<Vec<(f64, TextureDesc)>> = None;
        let mut pattern_transform = Transform::default();
        for item in &t.items {
            match item {
                TextureItem::Base(e) => match self.declared(e)? {
                    Some(Value::Texture(base)) => out = (**base).clone(),
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared texture")),
                    None => return Err(Diag::new(e.span, "expected a declared texture")),
                },
                TextureItem::Pigment(p) => {
                    out.pigment = self.pigment(p)?;
                    out.uv_mapping |= uv_span(p).is_some();
                }
                TextureItem::UvMapping(_) => out.uv_mapping = true,
                TextureItem::Normal(n) => out.normal = Some(self.normal(n)?),
                TextureItem::Finish(f) => out.finish = self.finish_block(f)?,
                TextureItem::Transform(tr) => {
                    let tr = self.transform(tr)?;
                    // The texture's own transforms move a uv-mapped pigment in uv space.
                    out.transform_by(&tr);
                    if pattern.is_some() {
                        // The pattern that picks the textures moves with them.
                        pattern_transform = pattern_transform.then(&tr);
                    }
                    list.iter_mut().for_each(|t| transform_texture(t, &tr));
                    if let Some(m) = &mut texture_map {
                        m.iter_mut().for_each(|(_, t)| transform_texture(t, &tr));
                    }
                }
                TextureItem::Pattern(pa) => {
                    let kind = self.pattern_kind(pa)?;
                    list.clear();
                    for t in &pa.textures {
                        list.push(self.texture(t)?);
                    }
                    pattern = Some(PatternDesc::new(kind));
                }
                TextureItem::ImagePattern(im, _) => pattern = Some(PatternDesc::new(PatternKind::Image(im.clone()))),
                TextureItem::MaterialMap(im, textures, transforms, _) => {
                    // Palette index k picks texture k: a map with a hard step at each index.
                    let mut m = Vec::with_capacity(textures.len());
                    for (k, t) in textures.iter().enumerate() {
                        m.push((k as f64 / 255.0, self.texture(t)?));
                    }
                    let mut local = Transform::default();
                    for tr in transforms {
                        let tr = self.transform(tr)?;
                        m.iter_mut().for_each(|(_, t)| transform_texture(t, &tr));
                        local = local.then(&tr);
                    }
                    texture_map = Some(m);
                    pattern = Some(PatternDesc::new(PatternKind::Image(im.clone())));
                    pattern_transform = local;
                }
                TextureItem::Mod(m) => {
                    if let Some(pd) = &mut pattern {
                        self.pattern_mod(m, pd, &pattern_transform)?;
                    }
                }
                TextureItem::TextureMap(entries, _) => {
                    let mut m = Vec::with_capacity(entries.len());
                    for (v, t) in entries {
                        m.push((self.float(v)?, self.texture(t)?));
                    }
                    m.sort_by(|a, b| a.0.total_cmp(&b.0));
                    // The pattern's transforms written before the map move its textures too
                    // (POV-Ray 3.7: `gradient y scale 3 texture_map {..}` renders as `gradient
                    // y texture_map {..} scale 3`, both for a `slope` texture in the map).
                    m.iter_mut().for_each(|(_, t)| transform_texture(t, &pattern_transform));
                    texture_map = Some(m);
                }
                TextureItem::Layer(t) => {
                    let upper = self.texture(t)?;
                    layer_over(&mut out, upper);
                }
            }
        }
        if let Some(pd) = pattern {
            texture_pattern(&mut out, pd, list, texture_map, pattern_transform);
        }
        Ok(out)
    }
}

/// Puts `upper` over `out` as a texture layer: the pigments stack; each layer keeps its own
/// normal (see below).
pub(super) fn layer_over(out: &mut TextureDesc, upper: TextureDesc) {
    // The layers so far, whole, in case they must be shaded one by one (below).
    let mut layers = match out.pattern.take() {
        Some(p) if p.layered => p.entries,
        mut pattern => {
            // Over a pattern of textures, the layer lies over each of them.
            if let Some(p) = &mut pattern {
                p.entries.iter_mut().for_each(|t| layer_over(t, upper.clone()));
            }
            let bottom = TextureDesc { pattern: None, ..out.clone() };
            out.pattern = pattern;
            if out.pattern.is_some() {
                Vec::new()
            } else {
                vec![bottom]
            }
        }
    };
    let below = std::mem::take(&mut out.pigment);
    let mut pigments = match below.pattern {
        PigmentPattern::Layered(l) if below.transform.is_identity() => l,
        _ => vec![below],
    };
    pigments.push(upper.pigment.clone());
    out.pigment = PigmentDesc { pattern: PigmentPattern::Layered(pigments), ..Default::default() };
    if layers.is_empty() {
        if upper.normal.is_some() {
            out.normal = upper.normal.clone();
        }
        return;
    }
    // POV-Ray 3.7 lights each layer with its own normal, the surface's own where the layer
    // has none, and refracts what passes through them all by the top layer's (measured on a
    // flat plate lit from the side, a tilting normal on the bottom or the top layer of two:
    // only that layer's diffuse changes; through glass, only the top one's shifts the view).
    out.normal = upper.normal.clone();
    // POV-Ray shades each layer with its own finish; one finish over the composited pigment
    // gives the same only while no layer differs in finish or normal and none shines or
    // reflects (every layer's highlights and reflection add up). Those keep the cheaper
    // composite.
    layers.push(TextureDesc { pattern: None, ..upper });
    let bottom = &layers[0];
    let plain = |f: &FinishDesc| f.phong == 0.0 && f.specular == 0.0 && f.reflection == DVec3::ZERO;
    if layers.iter().all(|t| t.finish == bottom.finish && plain(&t.finish) && t.normal == bottom.normal) {
        return;
    }
    out.pattern = Some(Box::new(TexturePatternDesc { selector: out.pigment.clone(), entries: layers, layered: true }));
}

/// Moves `t` with its object by `tr`; a uv-mapped texture stays on the surface's (u, v).
pub(super) fn transform_texture(t: &mut TextureDesc, tr: &Transform) {
    if !t.uv_mapping {
        t.transform_by(tr);
    }
}

/// Where a pigment block says `uv_mapping`, if it does.
pub(super) fn uv_span(p: &crate::pov::ast::Pigment) -> Option<Span> {
    p.items.iter().find_map(|i| match i {
        PigmentItem::UvMapping(span) => Some(*span),
        _ => None,
    })
}

/// Where a texture block says `uv_mapping` (itself or in its pigment), if it does.
pub(super) fn texture_uv_span(t: &Texture) -> Option<Span> {
    t.items.iter().find_map(|i| match i {
        TextureItem::UvMapping(span) => Some(*span),
        TextureItem::Pigment(p) => uv_span(p),
        _ => None,
    })
}

/// A pattern of textures (`pd` over a list's textures or a map's entries) as `out`: the
/// pigments follow the pattern; where the textures differ in normal or finish too, they are
/// kept whole (`TexturePatternDesc`) and the first one's normal and finish stand for the
/// pattern only where a colour is all that is needed.
fn texture_pattern(
    out: &mut TextureDesc,
    pd: PatternDesc,
    list: Vec<TextureDesc>,
    map: Option<Vec<(f64, TextureDesc)>>,
    transform: Transform,
) {
    let is_map = map.is_some();
    let (values, entries): (Vec<f64>, Vec<TextureDesc>) = match map {
        Some(m) => m.into_iter().unzip(),
        None => (Vec::new(), list),
    };
    let pigment = if is_map {
        PigmentPattern::PigmentMap(pd, values.iter().copied().zip(entries.iter().map(|t| t.pigment.clone())).collect())
    } else {
        PigmentPattern::List(pd, entries.iter().map(|t| t.pigment.clone()).collect())
    };
    let selector = PigmentDesc { pattern: pigment, transform, ..Default::default() };
    let Some(first) = entries.first() else {
        out.pigment = selector;
        return;
    };
    out.normal = first.normal.clone();
    out.finish = first.finish;
    let uniform = entries.iter().all(|t| t.normal == first.normal && t.finish == first.finish && t.pattern.is_none());
    out.pattern =
        (!uniform).then(|| Box::new(TexturePatternDesc { selector: selector.clone(), entries, layered: false }));
    out.pigment = selector;
}
