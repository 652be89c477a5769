//! Pigment and normal blocks → `PigmentDesc`, `NormalDesc`: patterns, their modifiers, colour,
//! pigment and normal maps. A block that starts with a declared name copies it, then applies the
//! rest in written order. (Textures: `texture_block`; finishes and interiors: `finish`.)
//!
//! Split by what is read: the pigment block here, `patterns` (pattern keywords and their
//! modifiers), `color_maps` (colour maps and the patterns' default maps), `normals`.

mod color_maps;
mod normals;
mod patterns;

use super::Lowerer;
use crate::desc::{
    Color, ColorMapEntry, PatternDesc, PatternKind, PigmentDesc, PigmentPattern, Transform, Turbulence, Warp,
};
use crate::pov::ast::{ColorItem, ColorKey, Expr, ExprKind, PatternMod, Pigment, PigmentItem, Turb, TurbKind};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
pub(super) use color_maps::sorted_map;
use color_maps::{default_list_colors, default_pattern_map, default_wood_map};

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
        // Warps written in this block, each with the block's transforms before it: they also
        // move the pigments the pattern is made of.
        let mut own_warps: Vec<(Warp, Transform)> = Vec::new();
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
                    // A warped checker goes through the general list pattern; an unwarped one
                    // keeps its own fast path (wave modifiers do nothing to it).
                    if let (Pattern::Checker(a, b), PatternMod::Warp(_)) = (&pattern, m) {
                        let (pd, list) = PigmentDesc::checker_list(*a, *b);
                        pattern = Pattern::Generic(pd, list);
                    }
                    if let Pattern::Generic(pd, _) = &mut pattern {
                        let before = pd.warps.len();
                        self.pattern_mod(m, pd, &transform)?;
                        own_warps.extend(pd.warps[before..].iter().map(|w| (w.warp, own_transform)));
                    } else if let (
                        Pattern::Done(PigmentPattern::PigmentMap(pd, _) | PigmentPattern::List(pd, _)),
                        PatternMod::Warp(_),
                    ) = (&mut pattern, m)
                    {
                        // A declared pigment_map or list pigment, warped where it is used.
                        let before = pd.warps.len();
                        self.pattern_mod(m, pd, &transform)?;
                        own_warps.extend(pd.warps[before..].iter().map(|w| (w.warp, own_transform)));
                    } else if let (Pattern::Done(PigmentPattern::ImageMap(_)), PatternMod::Warp(_)) = (&pattern, m) {
                        self.warn(Diag::new(
                            p.span,
                            "a warp on an `image_map` is not modelled; the image is not warped",
                        ));
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
            list.iter_mut().for_each(|p| {
                p.inherit_warps(&own_warps);
                p.transform_by(&own_transform)
            });
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
                    entries.iter_mut().for_each(|(_, p)| {
                        p.inherit_warps(&own_warps);
                        p.transform_by(&own_transform)
                    });
                    entries.sort_by(|a, b| a.0.total_cmp(&b.0));
                    PigmentPattern::PigmentMap(pd, entries)
                }
                (None, Some((m, _))) => PigmentPattern::Mapped(pd, m),
                (None, None) => PigmentPattern::Mapped(pd, default_map),
            },
            (Pattern::Done(mut p), _) => {
                match &mut p {
                    PigmentPattern::PigmentMap(_, entries) => {
                        entries.iter_mut().for_each(|(_, e)| e.inherit_warps(&own_warps))
                    }
                    PigmentPattern::List(_, list) => list.iter_mut().for_each(|e| e.inherit_warps(&own_warps)),
                    _ => {}
                }
                p
            }
            (_, Some((_, Some(span)))) => return Err(Diag::new(span, "color_map needs a pattern that uses it")),
            (Pattern::Solid(c), _) => PigmentPattern::Solid(c),
            (Pattern::Checker(a, b), _) => PigmentPattern::Checker(a, b),
        };
        Ok(PigmentDesc { pattern, turbulence: turb.finish(), transform })
    }
}
