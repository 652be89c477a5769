//! `bicubic_patch` bodies (POV-Ray 3.4.5.2.1): the patch items (`type`, `flatness`, `u_steps`,
//! `v_steps`, in any order, `type` required), the 16 control points, and an optional
//! `uv_vectors`. Evaluated as they are read, as meshes are, and tessellated by
//! `lower::bicubic` into a mesh: the patch is traced by the mesh machinery, not a kernel of its
//! own.

use std::sync::Arc;

use glam::DVec3;

use super::Parser;
use crate::desc::ShapeDesc;
use crate::pov::lower::bicubic::{tessellate, MAX_STEPS};
use crate::pov::source::{Diag, PResult, Span};

/// The items that may precede the control points.
const PATCH_ITEMS: &[&str] = &["type", "flatness", "u_steps", "v_steps", "accuracy"];

impl Parser<'_, '_> {
    /// `bicubic_patch { type T [flatness F] [u_steps N] [v_steps M] P1, ..., P16 [uv_vectors ..] }`,
    /// up to the modifiers.
    pub(super) fn bicubic_body(&mut self, kw: Span) -> PResult<ShapeDesc> {
        let mut patch_type = None;
        let (mut u_steps, mut v_steps) = (0u32, 0u32);
        loop {
            // `uv_vectors` may also stand among the items, before the control points.
            if self.peek_ident().as_deref() == Some("uv_vectors") {
                self.patch_uv_vectors()?;
                continue;
            }
            let Some(word) = self.peek_ident().filter(|w| PATCH_ITEMS.contains(&&**w)) else { break };
            let span = self.bump().span;
            let e = self.expr()?;
            let value = self.low.float(&e)?;
            match &*word {
                "type" => {
                    if value != 0.0 && value != 1.0 {
                        return Err(Diag::new(e.span, format!("bicubic_patch: type must be 0 or 1, found {value}")));
                    }
                    patch_type = Some(value);
                }
                "u_steps" | "v_steps" => {
                    if value.is_nan() || value < 0.0 {
                        return Err(Diag::new(e.span, format!("bicubic_patch: {word} must be ≥ 0, found {value}")));
                    }
                    let steps = value as u32;
                    if steps > MAX_STEPS {
                        self.low.warn(Diag::new(
                            e.span,
                            format!(
                                "bicubic_patch: {word} {steps} is tessellated as {MAX_STEPS} ({} rows of quads)",
                                1 << MAX_STEPS
                            ),
                        ));
                    }
                    let steps = steps.min(MAX_STEPS);
                    if &*word == "u_steps" {
                        u_steps = steps;
                    } else {
                        v_steps = steps;
                    }
                }
                // `flatness` lets POV-Ray stop subdividing early; strahl always subdivides to
                // `u_steps` × `v_steps`, which is the finer (the exact surface's) answer.
                "flatness" => {
                    if value.is_nan() || value < 0.0 {
                        return Err(Diag::new(e.span, format!("bicubic_patch: flatness must be ≥ 0, found {value}")));
                    }
                }
                // `accuracy` tunes POV-Ray's patch/ray test, which strahl does not use.
                _ => {
                    let _ = span;
                }
            }
        }
        if patch_type.is_none() {
            return Err(Diag::new(
                self.peek().span,
                format!(
                    "bicubic_patch needs `type 0` or `type 1` before its control points, found {}",
                    self.peek().describe()
                ),
            ));
        }
        let mut points = [DVec3::ZERO; 16];
        for (i, slot) in points.iter_mut().enumerate() {
            // Commas are optional, also after the items (`v_steps 4, <0, 0, 0>, ...`).
            self.eat_punct(',');
            if !self.starts_expr(super::scene::MODIFIERS) || self.peek_ident().as_deref() == Some("uv_vectors") {
                return Err(Diag::new(
                    self.peek().span,
                    format!("bicubic_patch needs 16 control points (4 rows of 4): found {i}"),
                ));
            }
            let e = self.expr()?;
            *slot = self.low.vec3(&e)?;
        }
        if self.peek_ident().as_deref() == Some("uv_vectors") {
            self.patch_uv_vectors()?;
        }
        let _ = kw;
        Ok(ShapeDesc::Mesh { mesh: Arc::new(tessellate(&points, u_steps, v_steps)), inside_vector: None })
    }

    /// `uv_vectors <u,v>, <u,v>, <u,v>, <u,v>`: the patch corners' uv, read and warned about.
    fn patch_uv_vectors(&mut self) -> PResult<()> {
        let span = self.bump().span;
        for i in 0..4 {
            if i > 0 {
                self.eat_punct(',');
            }
            self.expr()?;
        }
        self.low.warn(Diag::new(span, "bicubic_patch: uv coordinates are not modelled (no uv_mapping)"));
        Ok(())
    }
}
