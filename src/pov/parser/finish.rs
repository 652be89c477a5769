//! `finish { }` (with `reflection { }`) and `interior { }`.

use super::{is_pov_keyword, Parser};
use crate::pov::ast::{Expr, ExprKind, Finish, FinishItem, FinishKey, Interior, InteriorItem, ReflectionBlock};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{PResult, Span};

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
const INTERIOR: &[&str] =
    &["ior", "media", "caustics", "dispersion", "dispersion_samples", "fade_distance", "fade_power", "fade_color"];

impl Parser<'_, '_> {
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
        // The comma between MIN and MAX may be left out (`reflection { 0.0 1.0 fresnel on }` in
        // POV-Ray's gamma_showcase.pov): a second colour is whatever is not an item or the end.
        let second = self.eat_punct(',')
            || match self.peek().kind {
                TokenKind::Number(_) => true,
                TokenKind::Punct(c) => matches!(c, '(' | '-' | '+' | '<'),
                TokenKind::Ident(w) => !REFLECTION.contains(&&*w),
                _ => false,
            };
        let (min, max) = if second { (Some(first), self.color()?) } else { (None, first) };
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
                Some("fade_distance") => {
                    self.bump();
                    items.push(InteriorItem::FadeDistance(self.expr()?));
                }
                Some("fade_power") => {
                    self.bump();
                    items.push(InteriorItem::FadePower(self.expr()?));
                }
                Some("fade_color" | "fade_colour") => {
                    self.bump();
                    items.push(InteriorItem::FadeColor(self.color()?));
                }
                _ => return Err(self.unknown_in("interior", INTERIOR)),
            }
        }
        let end = self.close_block("interior", kw)?;
        Ok(Interior { items, span: kw.to(end) })
    }
}
