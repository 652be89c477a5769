//! `camera { }`: its projection, vectors, modifiers and focal blur.

use super::{is_pov_keyword, Parser};
use crate::pov::ast::{CameraItem, CameraProjection, Stmt};
use crate::pov::source::{Diag, PResult, Span};

const CAMERA: &[&str] = &[
    "location",
    "look_at",
    "angle",
    "right",
    "up",
    "direction",
    "sky",
    "perspective",
    "orthographic",
    "fisheye",
    "ultra_wide_angle",
    "omnimax",
    "panoramic",
    "cylinder",
    "spherical",
    "aperture",
    "blur_samples",
    "focal_point",
    "confidence",
    "variance",
    "normal",
    "bokeh",
    "rotate",
    "scale",
    "translate",
    "matrix",
    "transform",
];
/// Camera items that only the first statement of a camera may give (not after a declared one).
const CAMERA_TYPES: &[&str] =
    &["perspective", "orthographic", "fisheye", "ultra_wide_angle", "omnimax", "panoramic", "cylinder", "spherical"];

impl Parser<'_, '_> {
    pub(super) fn camera(&mut self) -> PResult<Stmt> {
        let (items, span) = self.camera_items()?;
        Ok(Stmt::Camera { items, span })
    }

    /// `camera { [Declared] items }`, for a camera statement or a declaration; returns the items
    /// and the keyword's span.
    pub(super) fn camera_items(&mut self) -> PResult<(Vec<CameraItem>, Span)> {
        let kw = self.bump().span;
        self.open_block("camera", kw)?;
        let mut items = Vec::new();
        // POV-Ray lets a declared camera's name stand first, to start from a copy of it. A word
        // followed by a value (`locaton <0, 2, -5>`) is a misspelt item instead, reported below.
        if let Some(name) =
            self.peek_ident().filter(|w| !CAMERA.contains(&&**w) && !is_pov_keyword(w) && !super::is_reserved(w))
        {
            let span = self.peek().span;
            match self.low.lookup(&name) {
                Some(crate::pov::value::Value::Camera(_)) => {
                    items.push(CameraItem::Declared(self.declared_name(&name, span)?));
                }
                Some(crate::pov::value::Value::Unmodelled(u)) => return Err(u.used_at(span)),
                Some(other) => {
                    return Err(Diag::new(span, format!("`{name}` is {}, not a camera", other.kind_name())));
                }
                None => {}
            }
        }
        let declared = !items.is_empty();
        while !self.at_block_end() {
            let item = match self.peek_ident().as_deref() {
                // POV-Ray 3.7 accepts only transforms after a declared camera (checked by parsing).
                Some(word)
                    if declared
                        && CAMERA.contains(&word)
                        && !matches!(word, "rotate" | "scale" | "translate" | "matrix" | "transform") =>
                {
                    return Err(Diag::new(
                        self.peek().span,
                        format!(
                            "`{word}` cannot follow a declared camera: only rotate, scale and translate may (as in POV-Ray)"
                        ),
                    ));
                }
                Some(word) if CAMERA_TYPES.contains(&word) => {
                    let span = self.bump().span;
                    let projection = match word {
                        "perspective" => CameraProjection::Perspective,
                        "orthographic" => CameraProjection::Orthographic,
                        "fisheye" => CameraProjection::Fisheye,
                        "ultra_wide_angle" => CameraProjection::UltraWideAngle,
                        "omnimax" => CameraProjection::Omnimax,
                        "panoramic" => CameraProjection::Panoramic,
                        "cylinder" => CameraProjection::Cylinder(self.expr()?),
                        _ => CameraProjection::Spherical,
                    };
                    CameraItem::Projection(projection, span)
                }
                Some("mesh_camera") => {
                    return Err(Diag::unmodelled(
                        self.peek().span,
                        "`mesh_camera` is not supported (strahl's cameras: perspective, orthographic, fisheye, \
                         ultra_wide_angle, omnimax, panoramic, cylinder 1-4, spherical)",
                    ));
                }
                Some(word @ ("normal" | "bokeh")) => {
                    let span = self.peek().span;
                    if word == "normal" {
                        self.normal()?;
                        CameraItem::Unmodelled("camera `normal` (perturbed eye rays)", span)
                    } else {
                        let kw = self.bump().span;
                        self.open_block("bokeh", kw)?;
                        if self.peek_ident().as_deref() == Some("pigment") {
                            self.pigment()?;
                        }
                        self.close_block("bokeh", kw)?;
                        CameraItem::Unmodelled("focal blur `bokeh` (the lens samples a uniform disc)", span)
                    }
                }
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    CameraItem::Transform(self.transform_item()?)
                }
                Some("blur_samples") => {
                    self.bump();
                    let first = self.expr()?;
                    if self.eat_punct(',') {
                        CameraItem::BlurSamples(Some(first), self.expr()?)
                    } else {
                        CameraItem::BlurSamples(None, first)
                    }
                }
                Some("angle") => {
                    self.bump();
                    let h = self.expr()?;
                    items.push(CameraItem::Angle(h));
                    // `angle H V` (spherical): the vertical angle, after a comma or a space.
                    let comma = self.eat_punct(',');
                    if comma || self.starts_expr(CAMERA) {
                        items.push(CameraItem::AngleV(self.expr()?));
                    }
                    continue;
                }
                Some(
                    word @ ("location" | "look_at" | "right" | "up" | "direction" | "sky" | "aperture" | "focal_point"
                    | "confidence" | "variance"),
                ) => {
                    self.bump();
                    let e = self.expr()?;
                    match word {
                        "location" => CameraItem::Location(e),
                        "look_at" => CameraItem::LookAt(e),
                        "right" => CameraItem::Right(e),
                        "up" => CameraItem::Up(e),
                        "direction" => CameraItem::Direction(e),
                        "aperture" => CameraItem::Aperture(e),
                        "focal_point" => CameraItem::FocalPoint(e),
                        "confidence" => CameraItem::Confidence(e),
                        "variance" => CameraItem::Variance(e),
                        _ => CameraItem::Sky(e),
                    }
                }
                _ => return Err(self.unknown_in("camera", &CAMERA[..7])),
            };
            items.push(item);
        }
        self.close_block("camera", kw)?;
        Ok((items, kw))
    }
}
