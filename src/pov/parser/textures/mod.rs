//! Surface blocks: pigment, normal and texture, with their patterns and maps; finish and
//! interior are in `finish.rs`.
//!
//! Split by what is read: the blocks here, `patterns` (pattern keywords, their modifiers and
//! warps), `maps` (colour, slope and block maps).

mod maps;
mod patterns;

use super::expr::color_key;
use super::Parser;
use patterns::{PATTERNS, PATTERN_MODS};

use crate::pov::ast::{Normal, NormalItem, PatternAst, Pigment, PigmentItem, Texture, TextureItem, Turb, TurbKind};
use crate::pov::lexer::TokenKind;
use crate::pov::source::PResult;

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
                            slope: None,
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
}
