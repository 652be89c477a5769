//! `light_source { }`: its kind, colour, area and modifiers.

use super::Parser;
use crate::pov::ast::{Light, LightItem};
use crate::pov::source::{Diag, PResult};

const LIGHT: &[&str] = &[
    "color",
    "colour",
    "rgb",
    "rgbf",
    "rgbt",
    "rgbft",
    "rotate",
    "scale",
    "translate",
    "matrix",
    "transform",
    "shadowless",
    "spotlight",
    "cylinder",
    "parallel",
    "point_at",
    "radius",
    "falloff",
    "tightness",
    "fade_distance",
    "fade_power",
    "area_light",
    "adaptive",
    "jitter",
    "circular",
    "orient",
    "area_illumination",
    "looks_like",
    "projected_through",
    "media_interaction",
    "media_attenuation",
];
/// Light items followed by one value.
const LIGHT_VALUES: &[&str] =
    &["point_at", "radius", "falloff", "tightness", "fade_distance", "fade_power", "adaptive"];
/// Light items with an optional boolean after them.
const LIGHT_FLAGS: &[&str] =
    &["jitter", "circular", "orient", "area_illumination", "media_interaction", "media_attenuation"];

impl Parser<'_, '_> {
    pub(super) fn light(&mut self) -> PResult<Light> {
        let kw = self.bump().span;
        self.open_block("light_source", kw)?;
        if self.at_block_end() {
            return Err(Diag::new(self.peek().span, "light_source needs a position, found none"));
        }
        let position = self.expr()?;
        self.eat_punct(',');
        let mut color = None;
        let mut items = Vec::new();
        let mut shadowless = false;
        while !self.at_block_end() {
            let word = self.peek_ident();
            match word.as_deref() {
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    items.push(LightItem::Transform(self.transform_item()?))
                }
                Some("shadowless") => {
                    self.bump();
                    shadowless = true;
                }
                Some(w @ ("spotlight" | "cylinder" | "parallel")) => {
                    let name = LIGHT.iter().copied().find(|k| *k == w).unwrap_or("spotlight");
                    items.push(LightItem::Kind(name, self.bump().span));
                }
                Some(w) if LIGHT_VALUES.contains(&w) => {
                    let name = LIGHT_VALUES.iter().copied().find(|k| *k == w).unwrap_or("radius");
                    let span = self.bump().span;
                    items.push(LightItem::Value(name, self.expr()?, span));
                }
                Some(w) if LIGHT_FLAGS.contains(&w) => {
                    let name = LIGHT_FLAGS.iter().copied().find(|k| *k == w).unwrap_or("jitter");
                    let span = self.bump().span;
                    let value = if self.starts_bool() { Some(self.expr()?) } else { None };
                    items.push(LightItem::Flag(name, value, span));
                }
                Some("area_light") => {
                    let span = self.bump().span;
                    let axis1 = self.expr()?;
                    self.eat_punct(',');
                    let axis2 = self.expr()?;
                    self.eat_punct(',');
                    let size1 = self.expr()?;
                    self.eat_punct(',');
                    let size2 = self.expr()?;
                    items.push(LightItem::AreaLight { axis1, axis2, size1, size2, span });
                }
                Some("looks_like") => {
                    let span = self.bump().span;
                    self.open_block("looks_like", span)?;
                    let object = self.object()?;
                    self.close_block("looks_like", span)?;
                    items.push(LightItem::LooksLike(Box::new(object), span));
                }
                // Photon mapping is not modelled: the light lights without it.
                Some("photons") => self.skip_unmodelled("photons")?,
                Some("projected_through") => {
                    let span = self.bump().span;
                    self.skip_braced("projected_through", span)?;
                    items.push(LightItem::ProjectedThrough(span));
                }
                Some(w) if LIGHT[..6].contains(&w) => color = Some(self.color()?),
                // A bare colour (`light_source { <0,4,-3>, White }`), as POV-Ray accepts.
                _ if color.is_none()
                    && self.starts_expr(&LIGHT[6..])
                    && !self.peek_ident().is_some_and(|w| super::is_pov_keyword(&w)) =>
                {
                    color = Some(self.maybe_bare_name(Self::color)?)
                }
                _ => return Err(self.unknown_in("light_source", LIGHT)),
            }
        }
        self.close_block("light_source", kw)?;
        Ok(Light { position, color, shadowless, items, span: kw })
    }
}
