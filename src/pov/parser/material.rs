//! `material { [M] texture {..} interior {..} transforms }` (POV-Ray 3.4.5.5.3 Material): a
//! wrapper that carries a texture and an interior to an object. Lowered in `lower::material`.

use super::Parser;
use crate::pov::ast::{Material, MaterialItem};
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
