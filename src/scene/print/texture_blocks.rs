//! `texture { }` blocks: a plain texture, layered textures (one block per layer), patterns
//! of whole textures (`texture_map`, list patterns of textures, `material_map` as the image
//! pattern it becomes) and the `#declare`s that layered entries of such patterns need.

use std::fmt::Write;

use glam::DMat4;

use super::num;
use super::textures::{finish, list_head, normal, pattern_text, pigment};
use super::transform::modifiers;
use crate::desc::{PigmentDesc, PigmentPattern, TextureDesc, TexturePatternDesc};

/// Layered textures that a pattern of textures holds: the scene language reads them there only
/// by name (`texture { Name }`), so they are declared before the object that uses them.
#[derive(Default)]
pub(super) struct Declarations {
    /// `#declare` lines not yet written out, inner ones first.
    pub(super) text: String,
    count: usize,
}

impl Declarations {
    /// Declares `t` (layered), written relative to `object_inverse`; returns its name.
    fn layered(&mut self, t: &TextureDesc, object_inverse: &DMat4) -> String {
        let mut body = String::new();
        texture_blocks(&mut body, t, object_inverse, self);
        self.count += 1;
        let name = format!("strahl_layered_{}", self.count);
        let _ = writeln!(self.text, "#declare {name} ={body}");
        name
    }
}

/// The layers' pigments of a composited layered pigment, bottom first (nested ones flattened);
/// one pigment for any other.
fn layer_pigments(p: &PigmentDesc) -> Vec<&PigmentDesc> {
    match &p.pattern {
        PigmentPattern::Layered(list) => list.iter().flat_map(layer_pigments).collect(),
        _ => vec![p],
    }
}

/// Whether a pattern of pigments picks a layered one (from a pattern of layered textures).
fn holds_layers(p: &PigmentDesc) -> bool {
    let layered = |p: &PigmentDesc| matches!(p.pattern, PigmentPattern::Layered(_));
    match &p.pattern {
        PigmentPattern::PigmentMap(_, e) => e.iter().any(|(_, p)| layered(p)),
        PigmentPattern::List(_, l) => l.iter().any(layered),
        _ => false,
    }
}

/// Whether `t` is more than one layer, so that it takes more than one `texture { }` block.
fn is_layered(t: &TextureDesc) -> bool {
    match &t.pattern {
        Some(p) => p.layered,
        None => matches!(t.pigment.pattern, PigmentPattern::Layered(_)),
    }
}

/// `t` as `texture { }` blocks, each on its own line: one per layer (shaded one by one or
/// composited: each layer with its own normal and finish, as the loader reads them back).
pub(super) fn texture_blocks(s: &mut String, t: &TextureDesc, object_inverse: &DMat4, d: &mut Declarations) {
    match &t.pattern {
        Some(p) if p.layered => p.entries.iter().for_each(|e| texture_blocks(s, e, object_inverse, d)),
        Some(p) => {
            let _ = write!(s, "\n  texture {{\n    ");
            texture_pattern(s, p, object_inverse, d);
            let _ = write!(s, "\n  }}");
        }
        None if holds_layers(&t.pigment) => {
            // A pattern of textures that differ only in pigment became one pigment; layered
            // pigments have no pigment syntax, so it is written as the textures again.
            let entries = match &t.pigment.pattern {
                PigmentPattern::PigmentMap(_, e) => e.iter().map(|(_, p)| p).collect(),
                PigmentPattern::List(_, l) => l.iter().collect(),
                _ => Vec::new(),
            };
            let entry = |p: &PigmentDesc| TextureDesc { pigment: p.clone(), pattern: None, ..t.clone() };
            let entries = entries.into_iter().map(entry).collect();
            let p = TexturePatternDesc { selector: t.pigment.clone(), entries, layered: false };
            let _ = write!(s, "\n  texture {{\n    ");
            texture_pattern(s, &p, object_inverse, d);
            let _ = write!(s, "\n  }}");
        }
        None => {
            for layer in layer_pigments(&t.pigment) {
                let _ = write!(s, "\n  texture {{\n    ");
                plain_body(s, layer, t, object_inverse);
                let _ = write!(s, "\n  }}");
            }
        }
    }
}

/// A plain texture's items: `uv_mapping` where it has it, `pigment`, its normal, its finish.
fn plain_body(s: &mut String, pigment_desc: &PigmentDesc, t: &TextureDesc, object_inverse: &DMat4) {
    // A uv-mapped texture's transforms are in uv space: its object's do not move it.
    let object_inverse = if t.uv_mapping {
        let _ = write!(s, "uv_mapping\n    ");
        &DMat4::IDENTITY
    } else {
        object_inverse
    };
    pigment(s, pigment_desc, object_inverse);
    if let Some(n) = &t.normal {
        let _ = write!(s, "\n    ");
        normal(s, n, object_inverse);
    }
    let _ = write!(s, "\n    ");
    finish(s, &t.finish);
}

/// A pattern of textures: the pattern, its entries (`texture_map` or a list), its transform.
/// The entries are read inside the pattern's transform, so they are written relative to it.
fn texture_pattern(s: &mut String, p: &TexturePatternDesc, object_inverse: &DMat4, d: &mut Declarations) {
    let sel = &p.selector;
    let inner = sel.transform.inverse;
    let mut entry = |s: &mut String, t: &TextureDesc| {
        if is_layered(t) {
            let name = d.layered(t, &inner);
            let _ = write!(s, "texture {{ {name} }}");
        } else {
            let mut block = String::new();
            texture_blocks(&mut block, t, &inner, d);
            let _ = write!(s, "{}", block.trim_start());
        }
    };
    match &sel.pattern {
        PigmentPattern::PigmentMap(pd, values) => {
            let _ = write!(s, "{} texture_map {{", pattern_text(pd));
            for ((v, _), t) in values.iter().zip(&p.entries) {
                let _ = write!(s, "\n      [{} ", num(*v));
                entry(s, t);
                let _ = write!(s, "]");
            }
            let _ = write!(s, "\n    }}");
        }
        PigmentPattern::List(pd, _) => {
            let (head, tail) = list_head(pd);
            let _ = write!(s, "{head}");
            for t in &p.entries {
                let _ = write!(s, "\n      ");
                entry(s, t);
            }
            let _ = write!(s, "\n    {tail}");
        }
        // The lowering makes only maps and lists.
        _ => {}
    }
    let _ = write!(s, "{}", modifiers(&(*object_inverse * sel.transform.matrix)));
}
