//! Pattern keywords with what they take, their value modifiers and `warp { }`.

use super::Parser;
use super::{turb_kind, PIGMENT};
use std::rc::Rc;

use crate::pov::ast::{Expr, ExprKind, PatternAst, PatternMod, Pigment, SlopeAst, Turb, TurbKind, WarpAst};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

/// Pattern keywords of the kernel layer (`shading::patterns`); `checker` and `wood` have their
/// own items in a pigment.
pub(crate) const PATTERNS: &[&str] = &[
    "gradient",
    "bozo",
    "spotted",
    "bumps",
    "granite",
    "marble",
    "agate",
    "crackle",
    "cells",
    "wrinkles",
    "dents",
    "leopard",
    "ripples",
    "waves",
    "radial",
    "onion",
    "spiral1",
    "spiral2",
    "brick",
    "hexagon",
    "boxed",
    "cylindrical",
    "spherical",
    "planar",
    "quilted",
    "mandel",
    "julia",
    "magnet",
    "pigment_pattern",
    "density_file",
    "average",
    "checker",
    "wood",
    "function",
    "object",
    "slope",
];

/// Modifiers of a pattern's value, in any block that has a pattern.
pub(super) const PATTERN_MODS: &[&str] = &[
    "ramp_wave",
    "triangle_wave",
    "sine_wave",
    "scallop_wave",
    "cubic_wave",
    "poly_wave",
    "frequency",
    "phase",
    "warp",
    "brick_size",
    "mortar",
    "agate_turb",
    "form",
    "metric",
    "offset",
    "solid",
    "control0",
    "control1",
    "noise_generator",
    "exponent",
    "interior",
    "exterior",
    "interpolate",
];

impl Parser<'_, '_> {
    /// A pattern keyword and what it takes. `stop`: the keywords of the enclosing block.
    pub(super) fn pattern(&mut self, stop: &[&str], context: &str) -> PResult<PatternAst> {
        let tok = self.bump();
        let span = tok.span;
        let name = match &tok.kind {
            TokenKind::Ident(w) => w.to_string(),
            _ => unreachable!("pattern() is called on a pattern keyword"),
        };
        let mut pat = PatternAst {
            name,
            arg: None,
            params: Vec::new(),
            colors: Vec::new(),
            pigments: Vec::new(),
            textures: Vec::new(),
            object: None,
            slope: None,
            span,
        };
        match pat.name.as_str() {
            "gradient" => pat.arg = Some(self.expr()?),
            "function" => {
                // The body is read as a declared function is; the argument carries it.
                let f = self.function_after(span)?;
                let value = Rc::new(Value::Function(Rc::new(f)));
                pat.arg = Some(Expr { kind: ExprKind::Value(value), span });
            }
            "spiral1" | "spiral2" | "mandel" if self.starts_expr(stop) && !self.starts_mod() => {
                pat.arg = Some(self.expr()?)
            }
            "julia" => {
                pat.params.push(self.expr()?);
                self.eat_punct(',');
                pat.arg = Some(self.expr()?);
            }
            "magnet" => {
                pat.params.push(self.expr()?);
                match self.peek_ident().as_deref() {
                    Some("mandel") => {
                        self.bump();
                    }
                    Some("julia") => {
                        self.bump();
                        pat.params.push(self.expr()?);
                        self.eat_punct(',');
                    }
                    _ => {
                        let t = self.peek();
                        return Err(Diag::new(
                            t.span,
                            format!("expected `mandel` or `julia` after `magnet N`, found {}", t.describe()),
                        ));
                    }
                }
                pat.arg = Some(self.expr()?);
            }
            "density_file" => {
                if self.peek_ident().as_deref() != Some("df3") {
                    let t = self.peek();
                    return Err(Diag::new(
                        t.span,
                        format!("expected `df3` after `density_file`, found {}", t.describe()),
                    ));
                }
                self.bump();
                pat.arg = Some(self.expr()?);
            }
            "pigment_pattern" => {
                self.open_block("pigment_pattern", span)?;
                let items = self.pigment_items(false)?;
                let end = self.close_block("pigment_pattern", span)?;
                pat.pigments.push(Pigment { items, span: span.to(end) });
            }
            "quilted" if self.starts_expr(stop) && !self.starts_mod() => {}
            "slope" => self.slope(&mut pat)?,
            "checker" | "brick" | "hexagon" => {
                let max = if pat.name == "hexagon" { 3 } else { 2 };
                self.list_items(&mut pat, max, context)?;
            }
            "object" => {
                // `object { OBJECT_ID | OBJECT {..}  ITEM_A, ITEM_B }`: the list is inside.
                self.open_block("object", span)?;
                if self.peek_ident().is_some_and(|w| super::super::scene::is_object_keyword(&w)) {
                    pat.object = Some(Box::new(self.object()?));
                } else {
                    pat.arg = Some(self.expr()?);
                }
                self.eat_punct(',');
                self.list_items(&mut pat, 2, context)?;
                self.close_block("object", span)?;
            }
            _ => {}
        }
        Ok(pat)
    }

    /// `slope`'s arguments: a block, or POV-Ray 3.5's bare direction (`slope -z`).
    fn slope(&mut self, pat: &mut PatternAst) -> PResult<()> {
        let span = pat.span;
        if !self.is_punct('{') {
            pat.arg = Some(self.expr()?);
            pat.slope = Some(Box::new(SlopeAst { point_at: false, range: None, altitude: None }));
            return Ok(());
        }
        self.open_block("slope", span)?;
        let point_at = self.peek_ident().as_deref() == Some("point_at");
        if point_at {
            self.bump();
        }
        pat.arg = Some(self.expr()?);
        let range = |p: &mut Self| -> PResult<Option<(Expr, Expr)>> {
            if !p.eat_punct(',') {
                return Ok(None);
            }
            let lo = p.expr()?;
            p.expect_punct(',', "between a slope range's low and high values")?;
            Ok(Some((lo, p.expr()?)))
        };
        let range_of_slope = range(self)?;
        let altitude = if !point_at && self.peek_ident().as_deref() == Some("altitude") {
            self.bump();
            let a = self.expr()?;
            Some((a, range(self)?))
        } else {
            None
        };
        self.close_block("slope", span)?;
        pat.slope = Some(Box::new(SlopeAst { point_at, range: range_of_slope, altitude }));
        Ok(())
    }

    /// Up to `max` entries of a list pattern (`checker A, B`) in a `context` block.
    fn list_items(&mut self, pat: &mut PatternAst, max: usize, context: &str) -> PResult<()> {
        for _ in 0..max {
            match self.peek_ident().as_deref() {
                Some("pigment") if context == "pigment" => pat.pigments.push(self.pigment()?),
                Some("texture") if context == "texture" => pat.textures.push(self.texture_one()?),
                Some("normal") => {
                    // A list of normals: read, the pattern's own gradient is used.
                    self.normal()?;
                }
                // `PIGMENT[6..]`: the pigment keywords less the colour words.
                _ if context == "pigment" && self.starts_expr(&PIGMENT[6..]) && !self.starts_mod() => {
                    pat.colors.push(self.color()?)
                }
                _ => break,
            }
            self.eat_punct(',');
        }
        Ok(())
    }

    /// Whether the next word is a pattern modifier (so not an amount or colour).
    pub(super) fn starts_mod(&mut self) -> bool {
        matches!(self.peek_ident().as_deref(), Some(w) if PATTERN_MODS.contains(&w) || turb_kind(w).is_some())
    }

    /// One pattern modifier.
    pub(super) fn pattern_mod(&mut self) -> PResult<PatternMod> {
        let tok = self.bump();
        let word = match &tok.kind {
            TokenKind::Ident(w) => w.to_string(),
            _ => unreachable!("pattern_mod() is called on a modifier keyword"),
        };
        Ok(match word.as_str() {
            "ramp_wave" | "triangle_wave" | "sine_wave" | "scallop_wave" | "cubic_wave" => PatternMod::Wave(word, None),
            "poly_wave" => {
                let e = if self.starts_expr(PIGMENT) { Some(self.expr()?) } else { None };
                PatternMod::Wave(word, e)
            }
            "solid" => PatternMod::Flag(word, tok.span),
            "interior" | "exterior" => {
                // `interior TYPE, FACTOR`: carried as the vector <TYPE, FACTOR>.
                let t = self.expr()?;
                let factor =
                    if self.eat_punct(',') { self.expr()? } else { Expr { kind: ExprKind::Number(1.0), span: t.span } };
                let span = tok.span.to(factor.span);
                PatternMod::Set(word, Expr { kind: ExprKind::Vector(vec![t, factor]), span })
            }
            "warp" => PatternMod::Warp(self.warp(tok.span)?),
            "turbulence" | "octaves" | "omega" | "lambda" => {
                // In a texture: the turbulence of its pattern.
                let kind = turb_kind(&word).unwrap_or(TurbKind::Turbulence);
                PatternMod::Warp(WarpAst::Turbulence(vec![Turb { kind, value: self.expr()? }]))
            }
            _ => PatternMod::Set(word, self.expr()?),
        })
    }

    /// `warp { ... }` after its keyword.
    pub(super) fn warp(&mut self, kw: crate::pov::source::Span) -> PResult<WarpAst> {
        self.open_block("warp", kw)?;
        let w = match self.peek_ident().as_deref() {
            Some("turbulence") => {
                let mut t = Vec::new();
                while let Some(k) = self.peek_ident().as_deref().and_then(turb_kind) {
                    t.push(self.turb(k)?);
                }
                WarpAst::Turbulence(t)
            }
            Some("repeat") => {
                self.bump();
                let dir = self.expr()?;
                let (mut offset, mut flip) = (None, None);
                loop {
                    match self.peek_ident().as_deref() {
                        Some("offset") => {
                            self.bump();
                            offset = Some(self.expr()?);
                        }
                        Some("flip") => {
                            self.bump();
                            flip = Some(self.expr()?);
                        }
                        _ => break,
                    }
                }
                WarpAst::Repeat { dir, offset, flip }
            }
            Some("black_hole") => {
                self.bump();
                let center = self.expr()?;
                self.eat_punct(',');
                let radius = self.expr()?;
                let (mut strength, mut falloff, mut inverse) = (None, None, false);
                let (mut repeat, mut turbulence) = (None, None);
                loop {
                    match self.peek_ident().as_deref() {
                        Some("strength") => {
                            self.bump();
                            strength = Some(self.expr()?);
                        }
                        Some("falloff") => {
                            self.bump();
                            falloff = Some(self.expr()?);
                        }
                        Some("inverse") => {
                            self.bump();
                            inverse = true;
                        }
                        Some("repeat") => {
                            self.bump();
                            repeat = Some(self.expr()?);
                        }
                        Some("turbulence") => {
                            turbulence = Some(self.bump().span);
                            self.expr()?;
                        }
                        _ => break,
                    }
                }
                WarpAst::BlackHole { center, radius, strength, falloff, inverse, repeat, turbulence }
            }
            Some(map @ ("cylindrical" | "spherical" | "toroidal" | "planar" | "cubic")) => {
                self.bump();
                let plane = if map == "planar" && self.starts_expr(&[]) {
                    let normal = self.expr()?;
                    self.expect_punct(',', "after the planar warp's normal")?;
                    Some((normal, self.expr()?))
                } else {
                    None
                };
                let (mut orientation, mut dist_exp, mut major_radius) = (None, None, None);
                loop {
                    match self.peek_ident().as_deref() {
                        Some("orientation") if map != "planar" && map != "cubic" => {
                            self.bump();
                            orientation = Some(self.expr()?);
                        }
                        Some("dist_exp") if map != "planar" && map != "cubic" => {
                            self.bump();
                            dist_exp = Some(self.expr()?);
                        }
                        Some("major_radius") if map == "toroidal" => {
                            self.bump();
                            major_radius = Some(self.expr()?);
                        }
                        _ => break,
                    }
                }
                WarpAst::Mapping { map: map.to_string(), plane, orientation, dist_exp, major_radius }
            }
            _ => {
                let span = self.peek().span;
                let word = self.peek_ident().map_or_else(|| "warp".to_string(), |w| w.to_string());
                self.skip_to_close("warp", kw)?;
                return Ok(WarpAst::Other(word, span));
            }
        };
        if !self.at_block_end() {
            let span = self.peek().span;
            self.skip_to_close("warp", kw)?;
            return Ok(WarpAst::Other("warp".into(), span));
        }
        self.close_block("warp", kw)?;
        Ok(w)
    }
}
