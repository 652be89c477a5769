//! `camera { ... }` with POV-Ray 3.7's semantics. Vectors are gathered first (the last of each
//! wins), then `angle`, then `look_at`, then transforms: POV-Ray 3.7 renders `look_at` before
//! `location` the same as after it, and `angle` before or after `look_at` the same (checked
//! with renders), so the written order of these items does not matter.

use super::Lowerer;
use crate::desc::CameraDesc;
use crate::desc::{FocalBlur, Projection};
use crate::pov::ast::{CameraItem, CameraProjection};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::{CameraState, Value};

impl Lowerer<'_> {
    pub(super) fn camera(&mut self, items: &[CameraItem], span: Span) -> PResult<CameraDesc> {
        let state = self.camera_state(items)?;
        self.scene.camera_mesh = state.mesh.clone();
        self.scene.camera_normal = state.normal.clone();
        self.resolve_camera(state, span)
    }

    /// Applies `items` in order, starting from a declared camera when the first item names one.
    pub(super) fn camera_state(&mut self, items: &[CameraItem]) -> PResult<CameraState> {
        let mut state = CameraState::default();
        // What the items say about the lens, applied to `state.cam.lens` after the loop (the
        // projection keyword should stand first, but `angle` may come before it).
        let mut projection: Option<(CameraProjection, Span)> = None;
        let mut angle_span = None;
        let mut angle_v = None;
        let mut blur = None::<FocalBlur>;
        let mut blur_span = None;
        for item in items {
            let CameraState { cam, angle, look_at, transforms, mesh, normal } = &mut state;
            match item {
                CameraItem::Declared(e) => match self.eval(e)? {
                    Value::Camera(declared) => state = *declared,
                    other => return Err(other.wrong_kind(e.span, "a camera")),
                },
                CameraItem::Location(e) => cam.location = self.vec3(e)?,
                CameraItem::Direction(e) => cam.direction = self.vec3(e)?,
                CameraItem::Right(e) => {
                    cam.right = self.vec3(e)?;
                    cam.up_or_right_given = true;
                }
                CameraItem::Up(e) => {
                    cam.up = self.vec3(e)?;
                    cam.up_or_right_given = true;
                }
                CameraItem::Sky(e) => cam.sky = self.vec3(e)?,
                CameraItem::Angle(e) => {
                    let a = self.float(e)?;
                    if !(a > 0.0 && a.is_finite()) {
                        return Err(Diag::new(e.span, "camera angle must be greater than 0 degrees"));
                    }
                    *angle = Some(a);
                    angle_span = Some(e.span);
                }
                CameraItem::AngleV(e) => {
                    let a = self.float(e)?;
                    if !(a > 0.0 && a.is_finite()) {
                        return Err(Diag::new(e.span, "camera vertical angle must be greater than 0 degrees"));
                    }
                    angle_v = Some(a);
                }
                CameraItem::LookAt(e) => *look_at = Some((self.vec3(e)?, e.span)),
                CameraItem::Transform(t) => transforms.push(self.transform(t)?),
                CameraItem::Projection(p, span) => projection = Some((p.clone(), *span)),
                CameraItem::Aperture(e) => {
                    let b = blur.get_or_insert(cam.lens.blur.unwrap_or_default());
                    b.aperture = self.float(e)?;
                    blur_span.get_or_insert(e.span);
                }
                CameraItem::BlurSamples(min, max) => {
                    let b = blur.get_or_insert(cam.lens.blur.unwrap_or_default());
                    let count = |l: &mut Self, e: &crate::pov::ast::Expr| -> PResult<u32> {
                        let n = l.float(e)?;
                        if !(0.0..=1e6).contains(&n) {
                            return Err(Diag::new(e.span, "blur_samples must be between 0 and 1000000"));
                        }
                        Ok(n as u32)
                    };
                    b.max_samples = count(self, max)?;
                    b.min_samples = match min {
                        Some(m) => count(self, m)?,
                        // POV-Ray's default minimum: 4 below 7 samples, else 7.
                        None if b.max_samples < 7 => 4,
                        None => 7,
                    };
                    blur_span.get_or_insert(max.span);
                }
                CameraItem::FocalPoint(e) => {
                    blur.get_or_insert(cam.lens.blur.unwrap_or_default()).focal_point = self.vec3(e)?;
                }
                CameraItem::Confidence(e) => {
                    blur.get_or_insert(cam.lens.blur.unwrap_or_default()).confidence = self.float(e)?;
                }
                CameraItem::Variance(e) => {
                    blur.get_or_insert(cam.lens.blur.unwrap_or_default()).variance = self.float(e)?;
                }
                // A later `normal` replaces an earlier one (POV-Ray reads it as a new normal).
                CameraItem::Normal(n) => *normal = Some(std::sync::Arc::new(self.normal(n)?)),
                CameraItem::Unmodelled(what, span) => {
                    self.warn(Diag::new(*span, format!("{what} is not modelled; the camera ignores it")));
                }
                CameraItem::MeshCamera(desc, _) => {
                    let smooth = mesh.as_ref().is_some_and(|m| m.smooth) || desc.smooth;
                    let mut desc = desc.clone();
                    std::sync::Arc::make_mut(&mut desc).smooth = smooth;
                    cam.lens.projection = Projection::Mesh {
                        rays_per_pixel: desc.rays_per_pixel,
                        offset: 0.0,
                        reverse: false,
                        max_distance: desc.max_distance,
                    };
                    *mesh = Some(desc);
                    projection = None;
                }
                CameraItem::Smooth(span) => match mesh {
                    Some(m) => std::sync::Arc::make_mut(m).smooth = true,
                    None => {
                        return Err(Diag::new(*span, "camera `smooth` belongs to a mesh_camera (none given before it)"))
                    }
                },
            }
        }
        if projection.is_some() {
            // A projection keyword after a mesh_camera replaces it.
            state.mesh = None;
        }
        let cam = &mut state.cam;
        if let Some((p, span)) = projection {
            cam.lens.projection = match p {
                CameraProjection::Perspective => Projection::Perspective,
                CameraProjection::Orthographic => Projection::Orthographic,
                // Angles are filled in by `resolve_camera`, once `angle` is known.
                CameraProjection::Fisheye => Projection::Fisheye { angle: 0.0 },
                CameraProjection::UltraWideAngle => Projection::UltraWideAngle { angle: 0.0 },
                CameraProjection::Omnimax => Projection::Omnimax,
                CameraProjection::Panoramic => Projection::Panoramic,
                CameraProjection::Cylinder(e) => {
                    let k = self.float(&e)?;
                    if !matches!(k, 1.0 | 2.0 | 3.0 | 4.0) {
                        return Err(Diag::new(e.span, format!("cylinder camera type must be 1, 2, 3 or 4, not {k}")));
                    }
                    Projection::Cylinder { kind: k as u8, angle: 0.0 }
                }
                CameraProjection::Spherical => Projection::Spherical { h: 0.0, v: 0.0 },
            };
            let _ = span;
        }
        if let Some(v) = angle_v {
            if let Projection::Spherical { v: sv, .. } = &mut cam.lens.projection {
                *sv = v;
            }
        }
        if let (Some(a), Some(span)) = (state.angle, angle_span) {
            let limited = matches!(state.cam.lens.projection, Projection::Perspective | Projection::Orthographic);
            if limited && a >= 180.0 {
                return Err(Diag::new(
                    span,
                    format!(
                        "camera angle must be between 0 and 180 degrees for a {} camera",
                        state.cam.lens.projection.keyword()
                    ),
                ));
            }
        }
        if let Some(b) = blur {
            let cam = &mut state.cam;
            cam.lens.blur = (b.aperture > 0.0 && b.max_samples > 0).then_some(b);
            if b.aperture > 0.0 && b.max_samples == 0 {
                self.warn(Diag::new(
                    blur_span.expect("blur items have spans"),
                    "focal blur needs `blur_samples` as well as `aperture`; no blur",
                ));
            }
            if cam.lens.blur.is_some() && !(b.confidence > 0.0 && b.confidence < 1.0 && b.variance > 0.0) {
                self.warn(Diag::new(
                    blur_span.expect("blur items have spans"),
                    "focal blur `confidence` must be in (0, 1) and `variance` positive (both parsed, not \
                     modelled: strahl always traces blur_samples rays)",
                ));
            }
        }
        Ok(state)
    }

    /// The camera `state` describes: `angle`, then `look_at`, then the transforms.
    fn resolve_camera(&mut self, state: CameraState, span: Span) -> PResult<CameraDesc> {
        let CameraState { mut cam, angle, look_at, transforms, .. } = state;
        if let Projection::Mesh { offset, reverse, .. } = &mut cam.lens.projection {
            // POV-Ray 3.4.2.2.3.5–6: only location's z (along each face normal) and the sign
            // of direction's z mean anything to a mesh camera.
            *offset = cam.location.z;
            *reverse = cam.direction.z < -1e-10;
        }
        for (v, name) in [(cam.direction, "direction"), (cam.right, "right"), (cam.up, "up")] {
            if v.length() == 0.0 {
                return Err(Diag::new(span, format!("camera {name} vector has zero length")));
            }
        }
        // The angle the projection reads: the scene's, else the perspective field of view
        // the vectors give (POV-Ray's rule, checked by rendering).
        let fov =
            angle.unwrap_or_else(|| 2.0 * (0.5 * cam.right.length() / cam.direction.length()).atan().to_degrees());
        match &mut cam.lens.projection {
            Projection::Fisheye { angle }
            | Projection::UltraWideAngle { angle }
            | Projection::Cylinder { angle, .. } => *angle = fov,
            Projection::Spherical { h, v } => {
                *h = fov;
                if *v == 0.0 {
                    *v = fov / 2.0;
                }
            }
            _ => {}
        }
        let perspective = cam.lens.projection == Projection::Perspective;
        if let (Some(a), true) = (angle, perspective) {
            // Horizontal field of view: the image plane spans |right| at distance |direction|.
            let len = 0.5 * cam.right.length() / (a.to_radians() / 2.0).tan();
            cam.direction = cam.direction.normalize() * len;
        }
        if angle.is_some() {
            cam.angle = angle;
        }
        if cam.lens.projection == Projection::Orthographic && (angle.is_some() || !cam.up_or_right_given) {
            // POV-Ray's second orthographic mode: the view the perspective camera it replaces
            // has at the distance to `look_at` (or one direction length ahead without one).
            let distance = look_at.map_or(cam.direction.length(), |(p, _)| (p - cam.location).length());
            let width = match angle {
                Some(a) => 2.0 * distance * (a.to_radians() / 2.0).tan(),
                None => cam.right.length() * distance / cam.direction.length(),
            };
            let k = width / cam.right.length();
            if k.is_finite() && k > 0.0 {
                cam.right *= k;
                cam.up *= k;
            }
        }
        if let Some((target, target_span)) = look_at {
            let to = target - cam.location;
            if to.length() == 0.0 {
                return Err(Diag::new(target_span, "camera look_at is the same point as its location"));
            }
            // A right-handed camera (`right -x*4/3`, as modellers export) stays right-handed:
            // POV-Ray keeps the handedness of the vectors it was given (checked by rendering),
            // and reads vectors of no handedness (`up z` along the default `direction z`, as
            // objects/prism3.inc has) as right-handed: those scenes render mirrored.
            let right_handed = cam.right.cross(cam.up).dot(cam.direction) <= 0.0;
            let direction = to.normalize() * cam.direction.length();
            let mut right = cam.sky.cross(direction);
            let parallel = |r: glam::DVec3, other: glam::DVec3| {
                r.length() <= 1e-12 * direction.length() * other.length().max(1e-300)
            };
            if parallel(right, cam.sky) {
                // POV-Ray 3.7 warns and keeps the given `right` (checked by rendering: looking
                // straight down with the default sky, +x is right and +z is up).
                self.warn(Diag::new(
                    target_span,
                    "Camera location to look_at direction and sky direction should be \
                     different. Using default/supplied right vector instead.",
                ));
                right = cam.right;
                if parallel(right.cross(direction), right) {
                    return Err(Diag::new(
                        target_span,
                        "camera look_at direction is parallel to sky and to right (give a \
                         different `sky` vector)",
                    ));
                }
                // Keep only the part of `right` across the view direction.
                let d = direction.normalize();
                right -= d * right.dot(d);
            }
            // POV-Ray's left-handed frame: cross(sky, direction) points to the image's right.
            let right = right.normalize() * cam.right.length();
            let up = direction.cross(right).normalize() * cam.up.length();
            let right = if right_handed { -right } else { right };
            cam.direction = direction;
            cam.right = right;
            cam.up = up;
            cam.look_at = Some(target);
        }
        for t in transforms {
            cam.location = t.matrix.transform_point3(cam.location);
            cam.direction = t.matrix.transform_vector3(cam.direction);
            cam.right = t.matrix.transform_vector3(cam.right);
            cam.up = t.matrix.transform_vector3(cam.up);
            cam.sky = t.matrix.transform_vector3(cam.sky);
            cam.look_at = cam.look_at.map(|p| t.matrix.transform_point3(p));
        }
        Ok(cam)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    #[test]
    fn default_frame_is_left_handed() {
        // Looking down +z with +y up, the image's right is +x.
        assert_eq!(DVec3::Y.cross(DVec3::Z), DVec3::X);
    }
}
