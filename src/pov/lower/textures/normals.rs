//! Normal blocks → `NormalDesc`: bumps, patterns as normals, `normal_map` and `slope_map`.

use super::TurbState;
use crate::desc::{
    NormalDesc, NormalPattern, PatternDesc, PatternKind, SlopeEntry, Transform, DEFAULT_NORMAL_ACCURACY,
};
use crate::pov::ast::{Normal, NormalItem, SlopeMapBody};
use crate::pov::lower::Lowerer;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

/// POV-Ray's `bumps` amount when none is written.
const DEFAULT_BUMPS: f64 = 0.5;

/// `bump_map`'s `bump_size` when none is written. The documentation names none; measured on
/// POV-Ray 3.7 (bump16.png and test16.png, plain, `interpolate 2` and `use_color`), a bump_map
/// without one lights exactly as with `bump_size 0.5`, and tilts half as far as with 1.
const DEFAULT_BUMP_MAP: f64 = 0.5;

impl Lowerer<'_> {
    /// `#default { normal { .. } }`: POV-Ray 3.7 takes one without a pattern
    /// (`normal { bump_size 1.5 }`, textures/normals/normmap.pov) as no default normal; its
    /// amount would only matter to patterns written later, which bring their own.
    pub(in crate::pov::lower) fn default_normal(&mut self, n: &Normal) -> PResult<Option<NormalDesc>> {
        let has_pattern = self.default_texture.normal.is_some()
            || n.items
                .iter()
                .any(|i| !matches!(i, NormalItem::BumpSize(_) | NormalItem::Transform(_) | NormalItem::Turb(_)));
        if !has_pattern {
            return Ok(None);
        }
        self.normal(n).map(Some)
    }

    pub(in crate::pov::lower) fn normal(&mut self, n: &Normal) -> PResult<NormalDesc> {
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
                        self.pattern_mod(m, pd, &transform)?;
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
    pub(in crate::pov::lower) fn slope_map(&mut self, body: &SlopeMapBody) -> PResult<Vec<SlopeEntry>> {
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
