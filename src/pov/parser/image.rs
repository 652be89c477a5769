//! `image_map { }`, `bump_map { }` and `image_pattern { }` blocks (POV-Ray 3.4.6.6, 3.4.7.5.2):
//! `[TYPE] "file"` and the bitmap modifiers. The file is decoded as the block is read, as a
//! `height_field`'s is (`pov::lower::images`).

use std::sync::Arc;

use super::Parser;
use crate::desc::{ImageMapDesc, ImageMapping};
use crate::pov::ast::{Expr, TextureItem};
use crate::pov::lower::ImageOptions;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

/// The image type keywords POV-Ray knows (`crate::image_file::read_image` says which it reads).
const IMAGE_TYPES: &[&str] = &["png", "gif", "tga", "iff", "ppm", "pgm", "jpeg", "tiff", "sys", "exr", "hdr", "bmp"];
const IMAGE_ITEMS: &[&str] = &[
    "map_type",
    "interpolate",
    "once",
    "use_color",
    "use_colour",
    "use_index",
    "use_alpha",
    "filter",
    "transmit",
    "gamma",
    "premultiplied",
    "bump_size",
];
const MATERIAL_MAP_ITEMS: &[&str] =
    &["texture", "map_type", "interpolate", "once", "rotate", "scale", "translate", "matrix", "transform"];

impl Parser<'_, '_> {
    /// `uv_mapping` in a normal: read; the normal stays in 3-D pattern space (uv-mapped
    /// pigments are modelled, uv-mapped normals are not), noted once.
    pub(super) fn uv_mapping(&mut self) {
        let span = self.bump().span;
        self.low.not_modelled("uv_mapping in a normal", span);
    }

    /// One image block after its keyword `word`: the decoded image with its modifiers, the
    /// `bump_size` written inside (bump_map), and the block's span.
    pub(super) fn image_block(&mut self, word: &str) -> PResult<(Arc<ImageMapDesc>, Option<Expr>, Span)> {
        let (kw, format, name, name_span) = self.image_file(word)?;
        let mut opts = ImageOptions::default();
        let mut bump_size = None;
        while !self.at_block_end() {
            if !self.image_modifier(word, &mut opts, &mut bump_size)? {
                return Err(self.unknown_in(word, IMAGE_ITEMS));
            }
        }
        let end = self.close_block(word, kw)?;
        let desc = self.low.image_map_desc(word, format.as_deref(), &name, name_span, opts)?;
        Ok((desc, bump_size, kw.to(end)))
    }

    /// `material_map { TYPE "file" [BITMAP_MODS] TEXTURE... [TRANSFORMATIONS] }` (POV-Ray
    /// 3.4.6.5) after its keyword.
    pub(super) fn material_map(&mut self) -> PResult<TextureItem> {
        let word = "material_map";
        let (kw, format, name, name_span) = self.image_file(word)?;
        let mut opts = ImageOptions::default();
        let (mut textures, mut transforms) = (Vec::new(), Vec::new());
        while !self.at_block_end() {
            match self.peek_ident().as_deref() {
                Some("texture") => textures.push(self.texture_one()?),
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    transforms.push(self.transform_item()?)
                }
                _ if self.image_modifier(word, &mut opts, &mut None)? => {}
                _ => return Err(self.unknown_in(word, MATERIAL_MAP_ITEMS)),
            }
        }
        let end = self.close_block(word, kw)?;
        if textures.is_empty() {
            return Err(Diag::new(kw.to(end), "material_map needs at least one texture"));
        }
        // The palette index picks the texture, whatever `use_color` says.
        opts.use_index_set = Some(true);
        let desc = self.low.image_map_desc(word, format.as_deref(), &name, name_span, opts)?;
        Ok(TextureItem::MaterialMap(desc, textures, transforms, kw.to(end)))
    }

    /// An image block's keyword, `{`, type and file name: (keyword span, type, name, name span).
    fn image_file(&mut self, word: &str) -> PResult<(Span, Option<String>, String, Span)> {
        let kw = self.bump().span;
        self.open_block(word, kw)?;
        let format = match self.peek_ident() {
            Some(w) if IMAGE_TYPES.contains(&&*w) => {
                self.bump();
                Some(w.to_string())
            }
            _ => None,
        };
        let name_expr = self.expr()?;
        let name = match self.low.eval(&name_expr)? {
            Value::Str(s) => s.to_string(),
            other => return Err(other.wrong_kind(name_expr.span, &format!("{word}'s image file name"))),
        };
        Ok((kw, format, name, name_expr.span))
    }

    /// One bitmap modifier of a `word` block into `opts` (`bump_size` for a bump_map); false
    /// when the next word is none.
    fn image_modifier(&mut self, word: &str, opts: &mut ImageOptions, bump_size: &mut Option<Expr>) -> PResult<bool> {
        let at = self.peek().span;
        match self.peek_ident().as_deref() {
            Some("map_type") => {
                self.bump();
                let e = self.expr()?;
                opts.mapping = match self.low.float(&e)? as i64 {
                    0 => ImageMapping::Planar,
                    1 => ImageMapping::Spherical,
                    2 => ImageMapping::Cylindrical,
                    5 => ImageMapping::Torus,
                    n => {
                        return Err(Diag::new(
                            e.span,
                            format!("map_type {n} is not supported (0 planar, 1 spherical, 2 cylindrical, 5 torus)"),
                        ))
                    }
                };
            }
            Some("interpolate") => {
                self.bump();
                let e = self.expr()?;
                opts.interpolate = match self.low.float(&e)? as i64 {
                    n @ (0 | 2 | 4) => n as u32,
                    n => {
                        self.low.warn(Diag::new(
                            e.span,
                            format!(
                                "interpolate {n} is not modelled (0, 2 bilinear, 4 normalized distance); none used"
                            ),
                        ));
                        0
                    }
                };
            }
            Some("once") => {
                self.bump();
                opts.once = true;
            }
            Some("use_color" | "use_colour") => {
                self.bump();
                opts.use_index_set = Some(false);
            }
            Some("use_index") => {
                self.bump();
                opts.use_index_set = Some(true);
            }
            Some("use_alpha") => {
                self.bump();
                opts.use_alpha = true;
            }
            Some(w @ ("filter" | "transmit")) => {
                let is_filter = w == "filter";
                self.bump();
                let which = if self.peek_ident().as_deref() == Some("all") {
                    self.bump();
                    None
                } else {
                    let e = self.expr()?;
                    let n = self.low.float(&e)?;
                    if !(0.0..=65535.0).contains(&n) {
                        return Err(Diag::new(e.span, "a palette index must lie in 0..65535"));
                    }
                    Some(n as usize)
                };
                self.eat_punct(',');
                let e = self.expr()?;
                let v = self.low.float(&e)?;
                if is_filter {
                    opts.filter.push((which, v));
                } else {
                    opts.transmit.push((which, v));
                }
            }
            Some("gamma") => {
                self.bump();
                if self.peek_ident().as_deref() == Some("srgb") {
                    self.bump();
                } else {
                    let e = self.expr()?;
                    opts.file_gamma = Some(self.low.float(&e)?);
                }
            }
            Some("premultiplied") => {
                self.bump();
                let e = self.expr()?;
                self.low.float(&e)?;
                self.low.not_modelled("image premultiplied", at);
            }
            Some("bump_size") if word == "bump_map" => {
                self.bump();
                *bump_size = Some(self.expr()?);
            }
            _ => return Ok(false),
        }
        Ok(true)
    }
}
