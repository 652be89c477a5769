//! Surface blocks: pigment, normal and texture, with their patterns and maps; finish and
//! interior are in `finish.rs`.

use super::expr::color_key;
use super::Parser;
use std::rc::Rc;

use crate::pov::ast::{
    ColorMap, ColorMapBody, Expr, ExprKind, MapEntry, Normal, NormalItem, PatternAst, PatternMod, Pigment, PigmentItem,
    SlopeMapBody, Texture, TextureItem, Turb, TurbKind, WarpAst,
};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

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
    "pigment_map",
    "turbulence",
    "octaves",
    "omega",
    "lambda",
    "rotate",
    "scale",
    "translate",
    "matrix",
    "transform",
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
    "quick_color",
    "quick_colour",
    "image_map",
    "image_pattern",
    "uv_mapping",
];
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
];
/// Modifiers of a pattern's value, in any block that has a pattern.
const PATTERN_MODS: &[&str] = &[
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
const NORMAL: &[&str] = &[
    "bumps",
    "turbulence",
    "octaves",
    "omega",
    "lambda",
    "rotate",
    "scale",
    "translate",
    "matrix",
    "transform",
    "bump_size",
    "slope_map",
    "normal_map",
    "accuracy",
    "bump_map",
    "image_pattern",
    "uv_mapping",
];
const TEXTURE: &[&str] = &[
    "pigment",
    "normal",
    "finish",
    "rotate",
    "scale",
    "translate",
    "matrix",
    "transform",
    "texture_map",
    "image_pattern",
    "material_map",
    "uv_mapping",
    "tiles",
];
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
    pub(super) fn base(&mut self, keywords: &[&str]) -> PResult<Option<crate::pov::ast::Expr>> {
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
        let items = self.pigment_items(false)?;
        let end = self.close_block("pigment", kw)?;
        Ok(Pigment { items, span: kw.to(end) })
    }

    /// The end of a block body, or of a map entry's body (`]`) when `in_entry`.
    fn at_body_end(&mut self, in_entry: bool) -> bool {
        self.at_block_end() || in_entry && self.is_punct(']')
    }

    /// A pigment's items, up to its `}` (or the `]` of a `pigment_map` entry).
    pub(super) fn pigment_items(&mut self, in_entry: bool) -> PResult<Vec<PigmentItem>> {
        let mut items = Vec::new();
        if let Some(b) = self.base(PIGMENT)? {
            items.push(PigmentItem::Base(b));
        }
        while !self.at_body_end(in_entry) {
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
                        if colors.is_empty() && self.peek_ident().as_deref() == Some("pigment") {
                            break;
                        }
                        if !self.starts_expr(&PIGMENT[6..]) {
                            break;
                        }
                        colors.push(self.color()?);
                    }
                    if colors.is_empty() && self.peek_ident().as_deref() == Some("pigment") {
                        let mut pigments = Vec::new();
                        while self.peek_ident().as_deref() == Some("pigment") {
                            pigments.push(self.pigment()?);
                            self.eat_punct(',');
                        }
                        PigmentItem::Pattern(PatternAst {
                            name: "checker".into(),
                            arg: None,
                            params: Vec::new(),
                            colors: Vec::new(),
                            pigments,
                            textures: Vec::new(),
                            object: None,
                            span,
                        })
                    } else {
                        PigmentItem::Checker(colors, span)
                    }
                }
                Some("wood") => PigmentItem::Wood(self.bump().span),
                Some(w) if PATTERNS.contains(&w) => PigmentItem::Pattern(self.pattern(PIGMENT, "pigment")?),
                Some(w) if PATTERN_MODS.contains(&w) => PigmentItem::Mod(self.pattern_mod()?),
                Some("pigment_map") => {
                    let span = self.bump().span;
                    PigmentItem::PigmentMap(self.block_map("pigment_map", span, |p| p.pigment())?, span)
                }
                Some("quick_color" | "quick_colour") => {
                    self.bump();
                    self.color()?;
                    continue;
                }
                Some("color_map" | "colour_map") => PigmentItem::ColorMap(self.color_map()?),
                Some("image_map") => {
                    let (im, _, span) = self.image_block("image_map")?;
                    PigmentItem::ImageMap(im, span)
                }
                Some("uv_mapping") => PigmentItem::UvMapping(self.bump().span),
                Some("image_pattern") => {
                    let (im, _, span) = self.image_block("image_pattern")?;
                    PigmentItem::ImagePattern(im, span)
                }
                Some(w) if turb_kind(w).is_some() => {
                    PigmentItem::Turb(self.turb(turb_kind(w).unwrap_or(TurbKind::Turbulence))?)
                }
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    PigmentItem::Transform(self.transform_item()?)
                }
                _ => return Err(self.unknown_in("pigment", PIGMENT)),
            };
            items.push(item);
        }
        Ok(items)
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
        let items = self.normal_items(false)?;
        let end = self.close_block("normal", kw)?;
        Ok(Normal { items, span: kw.to(end) })
    }

    /// A normal's items, up to its `}` (or the `]` of a `normal_map` entry).
    fn normal_items(&mut self, in_entry: bool) -> PResult<Vec<NormalItem>> {
        let mut items = Vec::new();
        if let Some(b) = self.base(NORMAL)? {
            items.push(NormalItem::Base(b));
        }
        while !self.at_body_end(in_entry) {
            let item = match self.peek_ident().as_deref() {
                Some("bumps") => {
                    let span = self.bump().span;
                    let amount = if self.starts_expr(NORMAL) { Some(self.expr()?) } else { None };
                    NormalItem::Bumps(amount, span)
                }
                Some(w) if turb_kind(w).is_some() => {
                    NormalItem::Turb(self.turb(turb_kind(w).unwrap_or(TurbKind::Turbulence))?)
                }
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    NormalItem::Transform(self.transform_item()?)
                }
                Some(w) if PATTERNS.contains(&w) => {
                    let pat = self.pattern(NORMAL, "normal")?;
                    // The bump amount may follow a comma (`gradient x, 0.5`), as POV-Ray reads it.
                    let comma = self.eat_punct(',');
                    let amount = if comma || (self.starts_expr(NORMAL) && !self.starts_mod()) {
                        Some(self.expr()?)
                    } else {
                        None
                    };
                    NormalItem::Pattern(pat, amount)
                }
                Some(w) if PATTERN_MODS.contains(&w) => NormalItem::Mod(self.pattern_mod()?),
                Some("bump_size") => {
                    self.bump();
                    NormalItem::BumpSize(self.expr()?)
                }
                Some("bump_map") => {
                    let (im, size, _) = self.image_block("bump_map")?;
                    NormalItem::BumpMap(im, size)
                }
                Some("uv_mapping") => {
                    self.uv_mapping();
                    continue;
                }
                Some("image_pattern") => {
                    let (im, _, _) = self.image_block("image_pattern")?;
                    let comma = self.eat_punct(',');
                    let amount = if comma || (self.starts_expr(NORMAL) && !self.starts_mod()) {
                        Some(self.expr()?)
                    } else {
                        None
                    };
                    NormalItem::ImagePattern(im, amount)
                }
                Some("accuracy") => {
                    self.bump();
                    NormalItem::Accuracy(self.expr()?)
                }
                Some("normal_map") => {
                    let span = self.bump().span;
                    NormalItem::NormalMap(self.block_map("normal_map", span, |p| p.normal())?, span)
                }
                Some("slope_map") => {
                    let (body, span) = self.slope_map()?;
                    NormalItem::SlopeMap(body, span)
                }
                _ => return Err(self.unknown_in("normal", NORMAL)),
            };
            items.push(item);
        }
        Ok(items)
    }

    /// `slope_map { [v, <height, slope>] .. }` or `slope_map { NAME }`.
    pub(super) fn slope_map(&mut self) -> PResult<(SlopeMapBody, crate::pov::source::Span)> {
        let kw = self.bump().span;
        self.open_block("slope_map", kw)?;
        if matches!(self.peek().kind, TokenKind::Ident(_)) {
            let name = self.expr()?;
            self.close_block("slope_map", kw)?;
            return Ok((SlopeMapBody::Named(name), kw));
        }
        let mut entries = Vec::new();
        while !self.at_block_end() {
            let open = self.expect_punct('[', "to start a slope_map entry")?;
            let value = self.expr()?;
            self.eat_punct(',');
            let point = self.expr()?;
            let close = self.expect_punct(']', "to close the slope_map entry (`[value, <height, slope>]`)")?;
            entries.push((value, point, open.to(close)));
        }
        self.close_block("slope_map", kw)?;
        if entries.is_empty() {
            return Err(Diag::new(kw, "slope_map needs at least one entry"));
        }
        Ok((SlopeMapBody::Entries(entries), kw))
    }

    /// One `texture { }` block alone (a `texture_list` entry), without the layers after it.
    pub(super) fn texture_one(&mut self) -> PResult<Texture> {
        let kw = self.bump().span;
        self.open_block("texture", kw)?;
        let items = self.texture_items(false)?;
        let end = self.close_block("texture", kw)?;
        Ok(Texture { items, span: kw.to(end) })
    }

    /// A texture's items, up to its `}` (or the `]` of a `texture_map` entry).
    fn texture_items(&mut self, in_entry: bool) -> PResult<Vec<TextureItem>> {
        let mut items = Vec::new();
        if let Some(b) = self.base(TEXTURE)? {
            items.push(TextureItem::Base(b));
        }
        while !self.at_body_end(in_entry) {
            let item = match self.peek_ident().as_deref() {
                Some("pigment") => TextureItem::Pigment(self.pigment()?),
                Some("normal") => TextureItem::Normal(self.normal()?),
                Some("finish") => TextureItem::Finish(self.finish()?),
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    TextureItem::Transform(self.transform_item()?)
                }
                Some(w) if PATTERNS.contains(&w) => TextureItem::Pattern(self.pattern(TEXTURE, "texture")?),
                Some("tiles") => TextureItem::Pattern(self.tiles()?),
                Some(w) if PATTERN_MODS.contains(&w) || turb_kind(w).is_some() => TextureItem::Mod(self.pattern_mod()?),
                Some("texture_map") => {
                    let span = self.bump().span;
                    TextureItem::TextureMap(self.block_map("texture_map", span, |p| p.texture_one())?, span)
                }
                Some("image_pattern") => {
                    let (im, _, span) = self.image_block("image_pattern")?;
                    TextureItem::ImagePattern(im, span)
                }
                Some("material_map") => self.material_map()?,
                Some("uv_mapping") => TextureItem::UvMapping(self.bump().span),
                _ => return Err(self.unknown_in("texture", TEXTURE)),
            };
            items.push(item);
        }
        Ok(items)
    }

    /// `texture { }` and the layers written right after it (`texture {A} texture {B}`: B over A).
    pub(super) fn texture(&mut self) -> PResult<Texture> {
        let mut t = self.texture_one()?;
        // The next word is not expanded: a macro call after a declared texture runs only once
        // the declaration has stored it (incdemo/screen.pov's `Screen_Plane(T, ..)`).
        while !matches!(self.cur.kind, TokenKind::Directive(_)) && self.more_ident().as_deref() == Some("texture") {
            let layer = self.texture_one()?;
            t.span = t.span.to(layer.span);
            t.items.push(TextureItem::Layer(Box::new(layer)));
        }
        Ok(t)
    }

    /// A pattern keyword and what it takes. `stop`: the keywords of the enclosing block.
    fn pattern(&mut self, stop: &[&str], context: &str) -> PResult<PatternAst> {
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
            "checker" | "brick" | "hexagon" => {
                let max = if pat.name == "hexagon" { 3 } else { 2 };
                self.list_items(&mut pat, max, context)?;
            }
            "object" => {
                // `object { OBJECT_ID | OBJECT {..}  ITEM_A, ITEM_B }`: the list is inside.
                self.open_block("object", span)?;
                if self.peek_ident().is_some_and(|w| super::scene::is_object_keyword(&w)) {
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
    fn starts_mod(&mut self) -> bool {
        matches!(self.peek_ident().as_deref(), Some(w) if PATTERN_MODS.contains(&w) || turb_kind(w).is_some())
    }

    /// One pattern modifier.
    fn pattern_mod(&mut self) -> PResult<PatternMod> {
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
    fn warp(&mut self, kw: crate::pov::source::Span) -> PResult<WarpAst> {
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
                        _ => break,
                    }
                }
                WarpAst::BlackHole { center, radius, strength, falloff, inverse }
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

    /// `NAME_map { [v X] ... }` where X is read by `item` (a block) or is a declared name.
    fn block_map<T>(
        &mut self,
        what: &str,
        kw: crate::pov::source::Span,
        mut item: impl FnMut(&mut Self) -> PResult<T>,
    ) -> PResult<Vec<(crate::pov::ast::Expr, T)>>
    where
        T: FromName,
    {
        self.open_block(what, kw)?;
        let mut out = Vec::new();
        while !self.at_block_end() {
            let open = self.expect_punct('[', "to start a map entry")?;
            // `average`'s entries may leave out their weight (`[function { x } color_map {..}]`,
            // `[pigment { .. }]`), which is then 1: POV-Ray 3.7 renders three such entries as
            // equal thirds.
            let weightless = match self.peek_ident() {
                Some(w) => {
                    PATTERNS.contains(&&*w) || &*w == T::KEYWORD || matches!(&*w, "pigment" | "normal" | "finish")
                }
                None => false,
            };
            let value = if weightless {
                Expr { kind: crate::pov::ast::ExprKind::Number(1.0), span: open }
            } else {
                self.expr()?
            };
            self.eat_punct(',');
            let inner = match self.peek_ident().as_deref() {
                Some(w) if w == T::KEYWORD => item(self)?,
                _ => T::body(self, open)?,
            };
            self.expect_punct(']', "to close the map entry")?;
            out.push((value, inner));
        }
        self.close_block(what, kw)?;
        if out.is_empty() {
            return Err(Diag::new(kw, format!("{what} needs at least one entry")));
        }
        Ok(out)
    }
}

/// What a map entry holds when it names a declared item instead of writing a block.
pub(super) trait FromName: Sized {
    const KEYWORD: &'static str;
    /// The entry's body written without its block (`[0.5 rgb 1]`, `[0 T_Stone1]`).
    fn body(p: &mut Parser<'_, '_>, span: crate::pov::source::Span) -> PResult<Self>;
}

impl FromName for Pigment {
    const KEYWORD: &'static str = "pigment";
    fn body(p: &mut Parser<'_, '_>, span: crate::pov::source::Span) -> PResult<Self> {
        Ok(Pigment { items: p.pigment_items(true)?, span })
    }
}

impl FromName for Normal {
    const KEYWORD: &'static str = "normal";
    fn body(p: &mut Parser<'_, '_>, span: crate::pov::source::Span) -> PResult<Self> {
        Ok(Normal { items: p.normal_items(true)?, span })
    }
}

impl FromName for Texture {
    const KEYWORD: &'static str = "texture";
    fn body(p: &mut Parser<'_, '_>, span: crate::pov::source::Span) -> PResult<Self> {
        Ok(Texture { items: p.texture_items(true)?, span })
    }
}
