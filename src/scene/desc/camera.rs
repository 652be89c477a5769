//! The camera as written.

use glam::DVec3;

/// `camera { ... }` after all its modifiers; vectors as POV-Ray holds them before `look_at`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraDesc {
    pub location: DVec3,
    /// Final viewing direction; its length sets the field of view unless `angle` is given.
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    pub sky: DVec3,
    /// `look_at`, if given (already applied to direction/right/up by `lower`).
    pub look_at: Option<DVec3>,
    /// Horizontal field of view in degrees, if given.
    pub angle: Option<f64>,
    /// The projection and focal blur (`crate::camera::lens`).
    pub lens: crate::camera::Lens,
    /// Whether the camera statement gave `up` or `right` (an orthographic camera without
    /// either takes its view size from the perspective camera it replaces).
    pub up_or_right_given: bool,
}

impl Default for CameraDesc {
    fn default() -> Self {
        CameraDesc {
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            sky: DVec3::Y,
            look_at: None,
            angle: None,
            lens: Default::default(),
            up_or_right_given: false,
        }
    }
}
