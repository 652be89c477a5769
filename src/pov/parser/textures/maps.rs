//! Maps: `color_map` (both entry forms), `slope_map`, and the block maps (`pigment_map`,
//! `normal_map`, `texture_map`) whose entries are blocks or declared names.

use super::patterns::PATTERNS;
use super::Parser;

use crate::pov::ast::{ColorMap, ColorMapBody, Expr, MapEntry, Normal, Pigment, SlopeMapBody, Texture};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult};

/// What a map entry holds when it names a declared item instead of writing a block.
pub(in crate::pov::parser) trait FromName: Sized {
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

impl Parser<'_, '_> {
    /// `color_map { [v C] ... }`, `color_map { [a, b color C1 color C2] ... }` (POV-Ray's older
    /// band form, which may be mixed with the first) or `color_map { Name }`.
    pub(in crate::pov::parser) fn color_map(&mut self) -> PResult<ColorMap> {
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

    /// `slope_map { [v, <height, slope>] .. }` or `slope_map { NAME }`.
    pub(in crate::pov::parser) fn slope_map(&mut self) -> PResult<(SlopeMapBody, crate::pov::source::Span)> {
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

    /// `NAME_map { [v X] ... }` where X is read by `item` (a block) or is a declared name.
    pub(super) fn block_map<T>(
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
