//! The items of a `blob` (POV-Ray 3.4.5.1.2): `threshold`, its components and `hierarchy`, in
//! any order among the object's modifiers.

use super::Parser;
use crate::pov::ast::{Blob, BlobComponent, BlobShape, Expr, Modifier};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult};

/// The words that start a blob item.
pub const BLOB_ITEMS: &[&str] = &["threshold", "sphere", "cylinder", "component", "hierarchy"];
/// What a component may hold after its numbers.
const COMPONENT_MODIFIERS: &[&str] = &["rotate", "scale", "translate", "pigment", "normal", "finish", "texture"];

impl Parser<'_, '_> {
    /// The blob's items up to its first modifier (more may follow among the modifiers).
    pub(super) fn blob_items(&mut self) -> PResult<Blob> {
        let mut blob = Blob::default();
        while self.peek_ident().is_some_and(|w| BLOB_ITEMS.contains(&&*w)) {
            self.blob_item(&mut blob)?;
        }
        Ok(blob)
    }

    /// One item; the cursor is on its keyword.
    pub(super) fn blob_item(&mut self, blob: &mut Blob) -> PResult<()> {
        let word = self.peek_ident().unwrap_or_default();
        let kw = self.bump().span;
        match &*word {
            "threshold" => blob.threshold = Some(self.blob_number("threshold")?),
            "hierarchy" => {
                // A hint for POV-Ray's own bounding of components; it changes no picture.
                if matches!(&self.peek().kind, TokenKind::Ident(w) if matches!(&**w, "on" | "off" | "true" | "false"))
                    || matches!(self.peek().kind, TokenKind::Number(_))
                {
                    self.bump();
                }
            }
            "component" => {
                // The old form: strength, radius, centre.
                let strength = self.blob_number("component")?;
                self.eat_punct(',');
                let radius = self.blob_number("component")?;
                self.eat_punct(',');
                let center = self.blob_number("component")?;
                blob.components.push(BlobComponent {
                    shape: BlobShape::Sphere { center },
                    radius,
                    strength,
                    modifiers: Vec::new(),
                    span: kw,
                });
            }
            _ => {
                let cylinder = &*word == "cylinder";
                self.open_block(&word, kw)?;
                let first = self.blob_number(&word)?;
                self.eat_punct(',');
                let shape = if cylinder {
                    let cap = self.blob_number(&word)?;
                    self.eat_punct(',');
                    BlobShape::Cylinder { base: first, cap }
                } else {
                    BlobShape::Sphere { center: first }
                };
                let radius = self.blob_number(&word)?;
                self.eat_punct(',');
                if self.peek_ident().as_deref() == Some("strength") {
                    self.bump();
                }
                let strength = self.blob_number(&word)?;
                let mut modifiers = Vec::new();
                while !self.at_block_end() {
                    modifiers.push(match self.peek_ident().as_deref() {
                        Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                            Modifier::Transform(self.transform_item()?)
                        }
                        Some("pigment") => Modifier::Pigment(self.pigment()?),
                        Some("normal") => Modifier::Normal(self.normal()?),
                        Some("finish") => Modifier::Finish(self.finish()?),
                        Some("texture") => Modifier::Texture(self.texture()?),
                        _ => return Err(self.unknown_in(&format!("a blob's {word} component"), COMPONENT_MODIFIERS)),
                    });
                }
                self.close_block(&word, kw)?;
                blob.components.push(BlobComponent { shape, radius, strength, modifiers, span: kw });
            }
        }
        Ok(())
    }

    /// A value a blob item needs next, or a located error naming the item.
    fn blob_number(&mut self, word: &str) -> PResult<Expr> {
        if !self.starts_expr(COMPONENT_MODIFIERS) || self.peek_ident().as_deref() == Some("strength") {
            let t = self.peek();
            let what = match word {
                "threshold" => "threshold needs a value".to_string(),
                "component" => "component needs strength, radius and centre".to_string(),
                "sphere" => "a blob's sphere needs centre, radius and strength".to_string(),
                _ => "a blob's cylinder needs two end points, radius and strength".to_string(),
            };
            return Err(Diag::new(t.span, format!("{what}, found {}", t.describe())));
        }
        self.expr()
    }
}
