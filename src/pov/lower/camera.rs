//! `camera { ... }` with POV-Ray 3.7's semantics. Vectors are gathered first (the last of each
//! wins), then `angle`, then `look_at`, then transforms: POV-Ray 3.7 renders `look_at` before
//! `location` the same as after it, and `angle` before or after `look_at` the same (checked
//! with renders), so the written order of these items does not matter.

use super::Lowerer;
use crate::pov::ast::CameraItem;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::{CameraState, Value};
use crate::scene::desc::CameraDesc;

impl Lowerer<'_> {
    pub(super) fn camera(&mut self, items: &[CameraItem], span: Span) -> PResult<CameraDesc> {
        let state = self.camera_state(items)?;
        self.resolve_camera(state, span)
    }

    /// Applies `items` in order, starting from a declared camera when the first item names one.
    pub(super) fn camera_state(&mut self, items: &[CameraItem]) -> PResult<CameraState> {
        let mut state = CameraState::default();
        for item in items {
            let CameraState { cam, angle, look_at, transforms } = &mut state;
            match item {
                CameraItem::Declared(e) => match self.eval(e)? {
                    Value::Camera(declared) => state = *declared,
                    other => return Err(other.wrong_kind(e.span, "a camera")),
                },
                CameraItem::Location(e) => cam.location = self.vec3(e)?,
                CameraItem::Direction(e) => cam.direction = self.vec3(e)?,
                CameraItem::Right(e) => cam.right = self.vec3(e)?,
                CameraItem::Up(e) => cam.up = self.vec3(e)?,
                CameraItem::Sky(e) => cam.sky = self.vec3(e)?,
                CameraItem::Angle(e) => {
                    let a = self.float(e)?;
                    if !(a > 0.0 && a < 180.0) {
                        return Err(Diag::new(e.span, "camera angle must be between 0 and 180 degrees"));
                    }
                    *angle = Some(a);
                }
                CameraItem::LookAt(e) => *look_at = Some((self.vec3(e)?, e.span)),
                CameraItem::Transform(t) => transforms.push(self.transform(t)?),
            }
        }
        Ok(state)
    }

    /// The camera `state` describes: `angle`, then `look_at`, then the transforms.
    fn resolve_camera(&mut self, state: CameraState, span: Span) -> PResult<CameraDesc> {
        let CameraState { mut cam, angle, look_at, transforms } = state;
        for (v, name) in [(cam.direction, "direction"), (cam.right, "right"), (cam.up, "up")] {
            if v.length() == 0.0 {
                return Err(Diag::new(span, format!("camera {name} vector has zero length")));
            }
        }
        if let Some(a) = angle {
            // Horizontal field of view: the image plane spans |right| at distance |direction|.
            let len = 0.5 * cam.right.length() / (a.to_radians() / 2.0).tan();
            cam.direction = cam.direction.normalize() * len;
            cam.angle = Some(a);
        }
        if let Some((target, target_span)) = look_at {
            let to = target - cam.location;
            if to.length() == 0.0 {
                return Err(Diag::new(target_span, "camera look_at is the same point as its location"));
            }
            // A right-handed camera (`right -x*4/3`, as modellers export) stays right-handed:
            // POV-Ray keeps the handedness of the vectors it was given (checked by rendering).
            let right_handed = cam.right.cross(cam.up).dot(cam.direction) < 0.0;
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
