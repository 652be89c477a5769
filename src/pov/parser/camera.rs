//! `camera { }`: its projection, vectors, modifiers and focal blur.

use super::{is_pov_keyword, Parser};
use crate::desc::{MeshCameraDesc, MeshCameraMesh, ShapeDesc};
use crate::pov::ast::{CameraItem, CameraProjection, Stmt};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

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
    "mesh_camera",
    "smooth",
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
                Some("mesh_camera") => self.mesh_camera()?,
                Some("smooth") => CameraItem::Smooth(self.bump().span),
                Some("normal") => CameraItem::Normal(self.normal()?),
                Some("bokeh") => {
                    let kw = self.bump().span;
                    self.open_block("bokeh", kw)?;
                    if self.peek_ident().as_deref() == Some("pigment") {
                        self.pigment()?;
                    }
                    self.close_block("bokeh", kw)?;
                    CameraItem::Unmodelled("focal blur `bokeh` (the lens samples a uniform disc)", kw)
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

impl Parser<'_, '_> {
    /// `mesh_camera { rays_per_pixel distribution_type [max_distance] mesh { M transforms }...
    /// [smooth] }` (POV-Ray 3.4.2.2.3), evaluated as it is read: the meshes are declared
    /// `mesh`/`mesh2` objects.
    fn mesh_camera(&mut self) -> PResult<CameraItem> {
        let kw = self.bump().span;
        self.open_block("mesh_camera", kw)?;
        const STOP: &[&str] = &["mesh", "smooth"];
        let number = |p: &mut Self, what: &str| -> PResult<(f64, Span)> {
            if !p.starts_expr(STOP) {
                return Err(Diag::new(p.peek().span, format!("mesh_camera needs {what} first")));
            }
            let e = p.expr()?;
            Ok((p.low.float(&e)?, e.span))
        };
        let (rays, rays_span) = number(self, "its rays per pixel")?;
        if !(1.0..=1e6).contains(&rays) {
            return Err(Diag::new(rays_span, format!("mesh_camera: rays per pixel must be at least 1, not {rays}")));
        }
        let (distribution, dist_span) = number(self, "its rays per pixel and distribution type")?;
        if !matches!(distribution, 0.0 | 1.0 | 2.0 | 3.0) {
            return Err(Diag::new(
                dist_span,
                format!("mesh_camera: distribution type must be 0, 1, 2 or 3, not {distribution}"),
            ));
        }
        let max_distance = if self.starts_expr(STOP) { number(self, "")?.0 } else { 0.0 };
        let mut desc = MeshCameraDesc {
            rays_per_pixel: rays as u32,
            distribution: distribution as u8,
            max_distance: max_distance.max(0.0),
            smooth: false,
            meshes: Vec::new(),
        };
        while !self.at_block_end() {
            match self.peek_ident().as_deref() {
                Some("mesh") => desc.meshes.push(self.mesh_camera_mesh()?),
                Some("smooth") => {
                    self.bump();
                    desc.smooth = true;
                }
                _ => return Err(self.unknown_in("mesh_camera", STOP)),
            }
        }
        let meshes = desc.meshes.len();
        let problem = match desc.distribution {
            _ if meshes == 0 => Some("needs at least one `mesh { M }`".to_string()),
            0 if meshes < desc.rays_per_pixel as usize => Some(format!(
                "distribution 0 needs a mesh for each of its {} rays per pixel, found {meshes}",
                desc.rays_per_pixel
            )),
            2 | 3 if desc.rays_per_pixel != 1 => Some(format!(
                "distribution {} shoots one ray per pixel, not {}",
                desc.distribution, desc.rays_per_pixel
            )),
            3 if desc.meshes.iter().all(|m| m.mesh.uv_faces.is_empty()) => {
                Some("distribution 3 needs a mesh with uv_vectors".to_string())
            }
            _ => None,
        };
        if let Some(p) = problem {
            return Err(Diag::new(kw, format!("mesh_camera: {p}")));
        }
        self.close_block("mesh_camera", kw)?;
        Ok(CameraItem::MeshCamera(std::sync::Arc::new(desc), kw))
    }

    /// `mesh { M [transforms] }` inside a mesh_camera: a declared mesh or mesh2 placed.
    fn mesh_camera_mesh(&mut self) -> PResult<MeshCameraMesh> {
        let kw = self.bump().span;
        self.open_block("mesh", kw)?;
        let e = self.expr()?;
        let not_mesh = |what: &str| {
            Diag::new(e.span, format!("mesh_camera's `mesh {{ }}` names a declared mesh or mesh2, not {what}"))
        };
        let (mesh, mut transform) = match self.low.eval(&e)? {
            Value::Object(group) => match group.parts.as_slice() {
                [part] => match &part.desc.shape {
                    ShapeDesc::Mesh { mesh, .. } => (mesh.clone(), part.desc.transform.transform()),
                    other => return Err(not_mesh(&format!("a {}", other.keyword()))),
                },
                _ => return Err(not_mesh("a union")),
            },
            other => return Err(not_mesh(other.kind_name())),
        };
        while let Some("rotate" | "scale" | "translate" | "matrix" | "transform") = self.peek_ident().as_deref() {
            let t = self.transform_item()?;
            transform = transform.then(&self.low.transform(&t)?);
        }
        self.close_block("mesh", kw)?;
        Ok(MeshCameraMesh { mesh, transform })
    }
}
