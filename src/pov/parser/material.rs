//! `material { [M] texture {..} interior {..} transforms }` (POV-Ray 3.4.5.5.3 Material): a
//! wrapper that carries a texture and an interior to an object (lowered in `lower::material`);
//! and the old `tiles` texture (3.4.6.5.2), read as the checker of textures it is.

use super::Parser;
use crate::pov::ast::{Material, MaterialItem, PatternAst};
use crate::pov::source::Diag;
use crate::pov::source::PResult;

/// What a `material` block takes.
const MATERIAL: &[&str] = &["texture", "interior", "interior_texture", "rotate", "scale", "translate"];

impl Parser<'_, '_> {
    pub(super) fn material(&mut self) -> PResult<Material> {
        let kw = self.bump().span;
        self.open_block("material", kw)?;
        let mut items = Vec::new();
        if let Some(b) = self.base(MATERIAL)? {
            items.push(MaterialItem::Base(b));
        }
        while !self.at_block_end() {
            let item = match self.peek_ident().as_deref() {
                Some("texture") => MaterialItem::Texture(self.texture()?),
                Some("interior") => MaterialItem::Interior(self.interior()?),
                Some("interior_texture") => {
                    let at = self.peek().span;
                    self.low.not_modelled("interior_texture", at);
                    self.texture()?;
                    continue;
                }
                Some("rotate" | "scale" | "translate") => MaterialItem::Transform(self.transform_item()?),
                _ => return Err(self.unknown_in("material", MATERIAL)),
            };
            items.push(item);
        }
        let end = self.close_block("material", kw)?;
        Ok(Material { items, span: kw.to(end) })
    }
}

impl Parser<'_, '_> {
    /// `tiles { TEXTURE tile2 TEXTURE }` in a texture (POV-Ray 3.7 wants the braces, which its
    /// reference leaves out): a `checker` of the two textures.
    pub(super) fn tiles(&mut self) -> PResult<PatternAst> {
        let kw = self.bump().span;
        self.open_block("tiles", kw)?;
        let mut textures = Vec::new();
        for (i, what) in ["the first texture after `tiles`", "a texture after `tile2`"].into_iter().enumerate() {
            if i == 1 {
                match self.peek_ident().as_deref() {
                    Some("tile2") => {
                        self.bump();
                    }
                    _ => {
                        return Err(Diag::new(
                            self.peek().span,
                            format!("expected `tile2` in `tiles`, found {}", self.peek().describe()),
                        ))
                    }
                }
            }
            if self.peek_ident().as_deref() != Some("texture") {
                return Err(Diag::new(self.peek().span, format!("expected {what}, found {}", self.peek().describe())));
            }
            textures.push(self.texture()?);
        }
        let end = self.close_block("tiles", kw)?;
        // Rendered by POV-Ray 3.7: the `tiles` texture shows where `checker`'s second entry
        // does, `tile2` where its first does.
        textures.reverse();
        Ok(PatternAst {
            name: "checker".into(),
            arg: None,
            params: Vec::new(),
            colors: Vec::new(),
            pigments: Vec::new(),
            textures,
            object: None,
            slope: None,
            span: kw.to(end),
        })
    }
}
