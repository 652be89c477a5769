//! `blob` items → `ShapeDesc::Blob`: each component's numbers checked, its transforms composed
//! in its own space. Per-component textures are parsed and named in a warning (strahl gives
//! the whole blob the blob's texture; POV-Ray blends them by field strength).

use super::Lowerer;
use crate::desc::{self, BlobComponent, ShapeDesc, Transform};
use crate::pov::ast::{Blob, BlobShape, Modifier};
use crate::pov::source::{Diag, PResult, Span};

impl Lowerer<'_> {
    pub(super) fn blob(&mut self, blob: &Blob, span: Span) -> PResult<ShapeDesc> {
        let threshold = match &blob.threshold {
            Some(e) => {
                let t = self.float(e)?;
                if t.is_nan() || t <= 0.0 {
                    return Err(Diag::new(e.span, format!("blob threshold must be positive, found {t}")));
                }
                t
            }
            // POV-Ray's default.
            None => 1.0,
        };
        if blob.components.is_empty() {
            return Err(Diag::new(span, "blob needs at least one component (sphere, cylinder or component)"));
        }
        let mut components = Vec::with_capacity(blob.components.len());
        let mut textured = None;
        for c in &blob.components {
            let radius = self.float(&c.radius)?;
            if radius.is_nan() || radius <= 0.0 {
                return Err(Diag::new(
                    c.radius.span,
                    format!("blob component radius must be positive, found {radius}"),
                ));
            }
            let strength = self.float(&c.strength)?;
            let shape = match &c.shape {
                BlobShape::Sphere { center } => desc::BlobShape::Sphere { center: self.vec3(center)? },
                BlobShape::Cylinder { base, cap } => {
                    let (b, t) = (self.vec3(base)?, self.vec3(cap)?);
                    if b == t {
                        return Err(Diag::new(c.span, "blob cylinder component has the same point at both ends"));
                    }
                    desc::BlobShape::Cylinder { base: b, cap: t }
                }
            };
            let mut transform = Transform::default();
            for m in &c.modifiers {
                match m {
                    Modifier::Transform(t) => transform = transform.then(&self.transform(t)?),
                    _ => textured = textured.or(Some(c.span)),
                }
            }
            components.push(BlobComponent { shape, radius, strength, transform });
        }
        if let Some(at) = textured {
            self.warn(Diag::new(
                at,
                "textures on blob components are not blended by strahl; the blob's own texture is used",
            ));
        }
        if !components.iter().any(|c| c.strength > 0.0) {
            self.warn(Diag::new(span, "blob has no component of positive strength: it is empty"));
        }
        Ok(ShapeDesc::Blob { components, threshold })
    }
}
