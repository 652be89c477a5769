//! `material { }` (POV-Ray 3.4.5.5.3): lowered to the texture and interior it carries. A
//! transform inside moves only what the material holds when it is written.

use super::texture_block::{layer_over, transform_texture};
use super::Lowerer;
use crate::pov::ast::{Material, MaterialItem};
use crate::pov::source::{Diag, PResult};
use crate::pov::value::{MaterialValue, Value};

impl Lowerer<'_> {
    pub(super) fn material(&mut self, m: &Material) -> PResult<MaterialValue> {
        let mut out = MaterialValue::default();
        for item in &m.items {
            match item {
                MaterialItem::Base(e) => match self.declared(e)? {
                    Some(Value::Material(base)) => out = (**base).clone(),
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared material")),
                    None => return Err(Diag::new(e.span, "expected a declared material")),
                },
                // A texture over one already carried (from the declared base) is a layer.
                MaterialItem::Texture(t) => {
                    let upper = self.texture(t)?;
                    match &mut out.texture {
                        Some(below) => layer_over(below, upper),
                        None => out.texture = Some(upper),
                    }
                }
                MaterialItem::Interior(i) => out.interior = Some(self.interior(i)?),
                MaterialItem::Transform(t) => {
                    let t = self.transform(t)?;
                    if let Some(tex) = &mut out.texture {
                        transform_texture(tex, &t);
                    }
                }
            }
        }
        Ok(out)
    }
}
