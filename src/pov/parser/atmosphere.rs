//! Atmosphere items: `sky_sphere`, `fog`, `rainbow`, and atmospheric `media` (skipped with a
//! warning by `lower`). `background` stays in `parser::scene`. Their values are lowered by
//! `lower::atmosphere`.

use super::Parser;
use crate::pov::ast::{AtmoItem, Atmosphere, AtmosphereKind, Stmt};
use crate::pov::source::PResult;
use crate::pov::value::Value;

const SKY_SPHERE: &[&str] = &["pigment", "emission", "rotate", "scale", "translate"];
const FOG: &[&str] = &[
    "fog_type",
    "distance",
    "color",
    "colour",
    "rgb",
    "rgbf",
    "rgbt",
    "rgbft",
    "fog_offset",
    "fog_alt",
    "up",
    "turbulence",
    "turb_depth",
    "omega",
    "lambda",
    "octaves",
    "rotate",
    "scale",
    "translate",
];
const RAINBOW: &[&str] = &[
    "direction",
    "angle",
    "width",
    "distance",
    "jitter",
    "up",
    "arc_angle",
    "falloff_angle",
    "color_map",
    "colour_map",
    "rotate",
    "scale",
    "translate",
];
/// Items that take one expression, per kind.
const FOG_VALUES: &[&str] =
    &["fog_type", "distance", "fog_offset", "fog_alt", "up", "turbulence", "turb_depth", "omega", "lambda", "octaves"];
const RAINBOW_VALUES: &[&str] =
    &["direction", "angle", "width", "distance", "jitter", "up", "arc_angle", "falloff_angle"];

impl Parser<'_, '_> {
    /// `sky_sphere { .. }`, `fog { .. }`, `rainbow { .. }`: items in written order.
    pub(super) fn atmosphere(&mut self, kind: AtmosphereKind) -> PResult<Stmt> {
        let keyword = kind.keyword();
        let kw = self.bump().span;
        self.open_block(keyword, kw)?;
        let (expected, values) = match kind {
            AtmosphereKind::SkySphere => (SKY_SPHERE, &[][..]),
            AtmosphereKind::Fog => (FOG, FOG_VALUES),
            AtmosphereKind::Rainbow => (RAINBOW, RAINBOW_VALUES),
        };
        let mut items = Vec::new();
        // A declared block of the same kind first (`sky_sphere { S_Cloud1 rotate .. }`): its
        // items, then these.
        let base = match self.peek_ident().as_deref().and_then(|n| self.low.lookup(n)) {
            Some(Value::Atmosphere(base)) if base.kind == kind => Some(base.clone()),
            _ => None,
        };
        if let Some(base) = base {
            items.extend(base.items.iter().cloned());
            self.bump();
        }
        while !self.at_block_end() {
            let word = self.peek_ident();
            let item = match word.as_deref() {
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    AtmoItem::Transform(self.transform_item()?)
                }
                Some("pigment") if kind == AtmosphereKind::SkySphere => AtmoItem::Pigment(self.pigment()?),
                Some("emission") if kind == AtmosphereKind::SkySphere => {
                    let span = self.bump().span;
                    AtmoItem::Value("emission", self.color()?, span)
                }
                Some("color_map" | "colour_map") if kind == AtmosphereKind::Rainbow => {
                    AtmoItem::ColorMap(self.color_map()?)
                }
                Some(w) if kind == AtmosphereKind::Fog && FOG[2..8].contains(&w) => AtmoItem::Color(self.color()?),
                Some(w) if values.contains(&w) => {
                    let name = values.iter().copied().find(|v| *v == w).unwrap_or("distance");
                    let span = self.bump().span;
                    AtmoItem::Value(name, self.expr()?, span)
                }
                // A bare colour in a fog (`fog { distance 10 Gray50 }`), as POV-Ray accepts.
                _ if kind == AtmosphereKind::Fog
                    && self.starts_expr(FOG)
                    && !self.peek_ident().is_some_and(|w| super::is_pov_keyword(&w)) =>
                {
                    AtmoItem::Color(self.maybe_bare_name(Self::color)?)
                }
                _ => return Err(self.unknown_in(keyword, expected)),
            };
            items.push(item);
        }
        let end = self.close_block(keyword, kw)?;
        Ok(Stmt::Atmosphere(Atmosphere { kind, items, span: kw.to(end) }))
    }

    /// `media { .. }` at the top level (atmospheric media): the block is skipped, braces
    /// balanced; `lower` warns that media is not modelled.
    pub(super) fn skip_media(&mut self) -> PResult<Stmt> {
        let kw = self.bump().span;
        self.skip_braced("media", kw)?;
        Ok(Stmt::Media(kw))
    }
}
