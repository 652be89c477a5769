//! Surface blocks: pigment, normal, finish, texture and interior.

use super::expr::color_key;
use super::{is_pov_keyword, Parser};
use crate::pov::ast::{
    ColorMap, ColorMapBody, Expr, ExprKind, Finish, FinishItem, FinishKey, Interior, InteriorItem, MapEntry, Normal,
    NormalItem, Pigment, PigmentItem, ReflectionBlock, Texture, TextureItem, Turb, TurbKind,
};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult, Span};

const PIGMENT: &[&str] = &[
    "color",
    "colour",
    "rgb",
    "rgbf",
    "rgbt",
    "rgbft",
    "checker",
    "wood",
    "color_map",
    "colour_map",
    "turbulence",
    "octaves",
    "omega",
    "lambda",
    "rotate",
    "scale",
    "translate",
];
const NORMAL: &[&str] = &["bumps", "turbulence", "octaves", "omega", "lambda", "rotate", "scale", "translate"];
const FINISH: &[&str] = &[
    "ambient",
    "diffuse",
    "brilliance",
    "phong",
    "phong_size",
    "specular",
    "roughness",
    "reflection",
    "metallic",
    "emission",
    "reflection_exponent",
    "conserve_energy",
    "crand",
    "irid",
    "subsurface",
];
const REFLECTION: &[&str] = &["fresnel", "falloff", "exponent", "metallic"];
const TEXTURE: &[&str] = &["pigment", "normal", "finish", "rotate", "scale", "translate"];
const INTERIOR: &[&str] =
    &["ior", "media", "caustics", "dispersion", "dispersion_samples", "fade_distance", "fade_power", "fade_color"];

fn turb_kind(word: &str) -> Option<TurbKind> {
    Some(match word {
        "turbulence" => TurbKind::Turbulence,
        "octaves" => TurbKind::Octaves,
        "omega" => TurbKind::Omega,
        "lambda" => TurbKind::Lambda,
        _ => return None,
    })
}

impl Parser<'_, '_> {
    /// A leading declared name (`pigment { DMFWood4 scale 2 }`), if the block starts with one.
    fn base(&mut self, keywords: &[&str]) -> PResult<Option<crate::pov::ast::Expr>> {
        match &self.peek().kind {
            TokenKind::Ident(w) if !keywords.contains(&&**w) && color_key(w).is_none() => {
                let w = w.clone();
                if super::is_pov_keyword(&w) || super::is_reserved(&w) {
                    return Ok(None);
                }
                Ok(Some(self.maybe_bare_name(Self::expr)?))
            }
            _ => Ok(None),
        }
    }

    fn turb(&mut self, kind: TurbKind) -> PResult<Turb> {
        self.bump();
        Ok(Turb { kind, value: self.expr()? })
    }

    pub(super) fn pigment(&mut self) -> PResult<Pigment> {
        let kw = self.bump().span;
        self.open_block("pigment", kw)?;
        let mut items = Vec::new();
        if let Some(b) = self.base(PIGMENT)? {
            items.push(PigmentItem::Base(b));
        }
        while !self.at_block_end() {
            let item = match self.peek_ident().as_deref() {
                Some(w) if matches!(w, "color" | "colour") || color_key(w).is_some() => {
                    PigmentItem::Color(self.color()?)
                }
                Some("checker") => {
                    let span = self.bump().span;
                    let mut colors = Vec::new();
                    while colors.len() < 2 {
                        if !colors.is_empty() {
                            self.eat_punct(',');
                        }
                        if self.peek_ident().as_deref() == Some("pigment") {
                            return Err(Diag::unmodelled(
                                self.peek().span,
                                "a pattern of pigments (`checker pigment {..} pigment {..}`) is not supported yet",
                            ));
                        }
                        if !self.starts_expr(&PIGMENT[6..]) {
                            break;
                        }
                        colors.push(self.color()?);
                    }
                    PigmentItem::Checker(colors, span)
                }
                Some("wood") => PigmentItem::Wood(self.bump().span),
                Some("color_map" | "colour_map") => PigmentItem::ColorMap(self.color_map()?),
                Some(w) if turb_kind(w).is_some() => {
                    PigmentItem::Turb(self.turb(turb_kind(w).unwrap_or(TurbKind::Turbulence))?)
                }
                Some("rotate" | "scale" | "translate") => PigmentItem::Transform(self.transform_item()?),
                _ => return Err(self.unknown_in("pigment", PIGMENT)),
            };
            items.push(item);
        }
        let end = self.close_block("pigment", kw)?;
        Ok(Pigment { items, span: kw.to(end) })
    }

    /// `color_map { [v C] ... }`, `color_map { [a, b color C1 color C2] ... }` (POV-Ray's older
    /// band form, which may be mixed with the first) or `color_map { Name }`.
    pub(super) fn color_map(&mut self) -> PResult<ColorMap> {
        let kw = self.bump().span;
        self.open_block("color_map", kw)?;
        if matches!(self.peek().kind, TokenKind::Ident(_)) {
            let name = self.expr()?;
            self.close_block("color_map", kw)?;
            return Ok(ColorMap { body: ColorMapBody::Named(name), span: kw });
        }
        let mut entries = Vec::new();
        while !self.at_block_end() {
            let open = self.expect_punct('[', "to start a color_map entry")?;
            let value = self.expr()?;
            self.eat_punct(',');
            let explicit = matches!(self.peek_ident().as_deref(), Some("color" | "colour"));
            let first = self.color()?;
            if explicit || !matches!(self.peek_ident().as_deref(), Some("color" | "colour")) {
                let close = self.expect_punct(']', "to close the color_map entry")?;
                entries.push(MapEntry { value, color: first, span: open.to(close) });
                continue;
            }
            // `[a, b color C1 color C2]`: `first` was the band's end, `b`.
            let from = self.color()?;
            let to = self.band_color()?;
            let close = self.expect_punct(']', "to close the color_map entry")?;
            let span = open.to(close);
            entries.push(MapEntry { value, color: from, span });
            entries.push(MapEntry { value: first, color: to, span });
        }
        self.close_block("color_map", kw)?;
        if entries.is_empty() {
            return Err(Diag::new(kw, "color_map needs at least one entry"));
        }
        Ok(ColorMap { body: ColorMapBody::Entries(entries), span: kw })
    }

    /// The second colour of a band, which POV-Ray requires to start with `color`/`colour`.
    fn band_color(&mut self) -> PResult<crate::pov::ast::Expr> {
        if !matches!(self.peek_ident().as_deref(), Some("color" | "colour")) {
            let t = self.peek();
            return Err(Diag::new(
                t.span,
                format!("expected `color` and the second colour of `[a, b color C1 color C2]`, found {}", t.describe()),
            ));
        }
        self.color()
    }

    pub(super) fn normal(&mut self) -> PResult<Normal> {
        let kw = self.bump().span;
        self.open_block("normal", kw)?;
        let mut items = Vec::new();
        if let Some(b) = self.base(NORMAL)? {
            items.push(NormalItem::Base(b));
        }
        while !self.at_block_end() {
            let item = match self.peek_ident().as_deref() {
                Some("bumps") => {
                    let span = self.bump().span;
                    let amount = if self.starts_expr(NORMAL) { Some(self.expr()?) } else { None };
                    NormalItem::Bumps(amount, span)
                }
                Some(w) if turb_kind(w).is_some() => {
                    NormalItem::Turb(self.turb(turb_kind(w).unwrap_or(TurbKind::Turbulence))?)
                }
                Some("rotate" | "scale" | "translate") => NormalItem::Transform(self.transform_item()?),
                _ => return Err(self.unknown_in("normal", NORMAL)),
            };
            items.push(item);
        }
        let end = self.close_block("normal", kw)?;
        Ok(Normal { items, span: kw.to(end) })
    }

    pub(super) fn finish(&mut self) -> PResult<Finish> {
        let kw = self.bump().span;
        self.open_block("finish", kw)?;
        let mut items = Vec::new();
        if let Some(b) = self.base(FINISH)? {
            items.push(FinishItem::Base(b));
        }
        while !self.at_block_end() {
            let word = self.peek_ident();
            let key = match word.as_deref() {
                Some("ambient") => FinishKey::Ambient,
                Some("diffuse") => FinishKey::Diffuse,
                Some("brilliance") => FinishKey::Brilliance,
                Some("phong") => FinishKey::Phong,
                Some("phong_size") => FinishKey::PhongSize,
                Some("specular") => FinishKey::Specular,
                Some("roughness") => FinishKey::Roughness,
                Some("reflection") => FinishKey::Reflection,
                Some("metallic") => FinishKey::Metallic,
                Some("emission") => FinishKey::Emission,
                Some("reflection_exponent") => FinishKey::ReflectionExponent,
                Some("conserve_energy") => FinishKey::ConserveEnergy,
                Some("subsurface") => {
                    self.skip_unmodelled("subsurface")?;
                    continue;
                }
                Some("irid") => {
                    self.skip_unmodelled("irid")?;
                    continue;
                }
                // A random darkening per pixel, "not for animations" (POV-Ray's docs): noted.
                Some("crand") => {
                    self.skip_unmodelled("crand")?;
                    self.expr()?;
                    continue;
                }
                _ => return Err(self.unknown_in("finish", FINISH)),
            };
            let kw_span = self.bump().span;
            let key = match key {
                FinishKey::Diffuse | FinishKey::Phong | FinishKey::Specular
                    if self.peek_ident().as_deref() == Some("albedo") =>
                {
                    self.bump();
                    match key {
                        FinishKey::Diffuse => FinishKey::DiffuseAlbedo,
                        FinishKey::Phong => FinishKey::PhongAlbedo,
                        _ => FinishKey::SpecularAlbedo,
                    }
                }
                k => k,
            };
            let value = match key {
                FinishKey::Reflection if self.is_punct('{') => {
                    items.push(FinishItem::Reflection(Box::new(self.reflection_block(kw_span)?)));
                    continue;
                }
                FinishKey::Ambient | FinishKey::Reflection | FinishKey::Emission => self.color()?,
                // `metallic` and `conserve_energy` alone mean on.
                FinishKey::Metallic | FinishKey::ConserveEnergy if !self.starts_value() => {
                    Expr { kind: ExprKind::Number(1.0), span: kw_span }
                }
                _ => self.expr()?,
            };
            items.push(FinishItem::Set(key, value));
            if matches!(key, FinishKey::Diffuse | FinishKey::DiffuseAlbedo) && self.eat_punct(',') {
                // `diffuse A, B`: B lights the back of thin objects (paper, leaves).
                let back = self.expr()?;
                self.low.not_modelled("diffuse backside illumination", back.span);
            }
        }
        let end = self.close_block("finish", kw)?;
        Ok(Finish { items, span: kw.to(end) })
    }

    /// `reflection { [MIN,] MAX fresnel B falloff F exponent E metallic M }`, at its `{`.
    fn reflection_block(&mut self, kw: Span) -> PResult<ReflectionBlock> {
        self.open_block("reflection", kw)?;
        let first = self.color()?;
        let (min, max) = if self.eat_punct(',') { (Some(first), self.color()?) } else { (None, first) };
        let mut block = ReflectionBlock { min, max, fresnel: None, falloff: None, exponent: None, metallic: None };
        while !self.at_block_end() {
            let word = self.peek_ident();
            if !matches!(word.as_deref(), Some(w) if REFLECTION.contains(&w)) {
                return Err(self.unknown_in("reflection", REFLECTION));
            }
            let at = self.bump().span;
            // `fresnel` and `metallic` alone mean on (1).
            let value = if self.starts_value() { self.expr()? } else { Expr { kind: ExprKind::Number(1.0), span: at } };
            let slot = match word.as_deref() {
                Some("fresnel") => &mut block.fresnel,
                Some("falloff") => &mut block.falloff,
                Some("exponent") => &mut block.exponent,
                _ => &mut block.metallic,
            };
            *slot = Some(value);
        }
        self.close_block("reflection", kw)?;
        Ok(block)
    }

    /// Whether a value (a number, a parenthesis, a sign, a boolean word or a declared name)
    /// follows, for items whose value is optional (`metallic`, `fresnel`).
    fn starts_value(&mut self) -> bool {
        match self.peek().kind {
            TokenKind::Number(_) => true,
            TokenKind::Punct(c) => matches!(c, '(' | '-' | '+' | '<'),
            TokenKind::Ident(w) => {
                matches!(&*w, "on" | "off" | "true" | "false" | "yes" | "no")
                    || (!is_pov_keyword(&w) && self.low.lookup(&w).is_some())
            }
            _ => false,
        }
    }

    pub(super) fn texture(&mut self) -> PResult<Texture> {
        let kw = self.bump().span;
        self.open_block("texture", kw)?;
        let mut items = Vec::new();
        if let Some(b) = self.base(TEXTURE)? {
            items.push(TextureItem::Base(b));
        }
        while !self.at_block_end() {
            let item = match self.peek_ident().as_deref() {
                Some("pigment") => TextureItem::Pigment(self.pigment()?),
                Some("normal") => TextureItem::Normal(self.normal()?),
                Some("finish") => TextureItem::Finish(self.finish()?),
                Some("rotate" | "scale" | "translate") => TextureItem::Transform(self.transform_item()?),
                _ => return Err(self.unknown_in("texture", TEXTURE)),
            };
            items.push(item);
        }
        let end = self.close_block("texture", kw)?;
        Ok(Texture { items, span: kw.to(end) })
    }

    pub(super) fn interior(&mut self) -> PResult<Interior> {
        let kw = self.bump().span;
        self.open_block("interior", kw)?;
        let mut items = Vec::new();
        if let Some(b) = self.base(INTERIOR)? {
            items.push(InteriorItem::Base(b));
        }
        while !self.at_block_end() {
            match self.peek_ident().as_deref() {
                Some("ior") => {
                    self.bump();
                    items.push(InteriorItem::Ior(self.expr()?));
                }
                Some("media") => self.skip_unmodelled("media")?,
                // Light bent by wavelength and focused light: not modelled, noted.
                Some(w @ ("caustics" | "dispersion")) => {
                    let w = w.to_string();
                    let at = self.bump().span;
                    self.low.not_modelled(&w, at);
                    self.expr()?;
                }
                Some("dispersion_samples") => {
                    self.bump();
                    self.expr()?;
                }
                // Light fading with the distance it travels inside: not modelled yet, noted.
                Some(w @ ("fade_distance" | "fade_power")) => {
                    let at = self.bump().span;
                    let w = w.to_string();
                    self.low.not_modelled(&format!("interior {w}"), at);
                    self.expr()?;
                }
                Some("fade_color" | "fade_colour") => {
                    self.bump();
                    self.color()?;
                }
                _ => return Err(self.unknown_in("interior", INTERIOR)),
            }
        }
        let end = self.close_block("interior", kw)?;
        Ok(Interior { items, span: kw.to(end) })
    }
}
