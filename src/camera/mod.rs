//! POV-Ray's perspective camera as the renderer uses it, and the free-flying camera state.
//!
//! `Camera` holds POV-Ray's four vectors (location, direction, right, up) in f64 world space; a
//! primary ray through image coordinates (u, v) in [0,1]² points along
//! `direction + (u - 0.5)·right + (0.5 - v)·up`, exactly as POV-Ray builds it. Rays are made
//! relative to the scene's render origin (see `scene::build`) before they become f32.
//!
//! Camera paths (keyframed flights for capture and bench) live in `path`; their file format in
//! `path_file`; orbits around a scene's `look_at` are generated in `orbit`.
//!
//! Layer 3 of docs/design/architecture.md: uses `desc`; `scene`, `render`, `fly` and the front ends use it.

pub mod frame;
pub mod lens;
pub mod mesh;
pub mod orbit;
pub mod path;
mod path_file;

use glam::DVec3;

use crate::desc::{CameraDesc, Lens, Projection};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// The projection and focal blur (`lens`); flying keeps it.
    pub lens: Lens,
}

impl Camera {
    pub fn from_desc(desc: &CameraDesc) -> Camera {
        Camera { location: desc.location, direction: desc.direction, right: desc.right, up: desc.up, lens: desc.lens }
    }

    /// A camera at `location` looking at `look_at`, with POV-Ray's `look_at` rules: the vector
    /// lengths of `like` (which set the field of view and aspect) are kept, the sky is +y.
    /// `angle`, when given, is the horizontal field of view in degrees.
    pub fn looking_at(location: DVec3, look_at: DVec3, angle: Option<f64>, like: &Camera) -> Camera {
        let right_len = like.right.length();
        let up_len = like.up.length();
        let mut dir_len = like.direction.length();
        if let Some(a) = angle {
            dir_len = 0.5 * right_len / (a.to_radians() * 0.5).tan();
        }
        let forward = (look_at - location).try_normalize().unwrap_or(DVec3::Z);
        let basis = Basis::from_forward(forward, DVec3::Y);
        Camera {
            location,
            direction: basis.forward * dir_len,
            right: basis.right * right_len,
            up: basis.up * up_len,
            lens: like.lens,
        }
    }

    /// Horizontal field of view in degrees.
    pub fn angle_deg(&self) -> f64 {
        2.0 * (0.5 * self.right.length() / self.direction.length()).atan().to_degrees()
    }

    /// The point the camera looks at, one direction length ahead.
    pub fn look_at(&self) -> DVec3 {
        self.location + self.direction
    }

    /// The camera as a POV-Ray `camera { }` block that reproduces this view.
    pub fn to_pov(&self) -> String {
        let v = |v: DVec3| format!("<{:.6}, {:.6}, {:.6}>", v.x, v.y, v.z);
        let projection = match self.lens.projection {
            Projection::Perspective => String::new(),
            Projection::Fisheye { angle } | Projection::UltraWideAngle { angle } => {
                format!("  {}\n  angle {angle:.6}\n", self.lens.projection.keyword())
            }
            Projection::Cylinder { angle, .. } => format!("  {}\n  angle {angle:.6}\n", self.lens.projection.keyword()),
            Projection::Spherical { h, v } => format!("  spherical\n  angle {h:.6}, {v:.6}\n"),
            // The meshes are the scene's; a perspective view of the same vectors stands in.
            Projection::Mesh { .. } => "  // mesh_camera: its meshes are not written\n".into(),
            p => format!("  {}\n", p.keyword()),
        };
        let blur = match self.lens.blur {
            Some(b) => format!(
                "  aperture {:.6}\n  blur_samples {}, {}\n  focal_point {}\n  confidence {:.6}\n  variance {:.9}\n",
                b.aperture,
                b.min_samples,
                b.max_samples,
                v(b.focal_point),
                b.confidence,
                b.variance
            ),
            None => String::new(),
        };
        format!(
            "camera {{\n{projection}  location {}\n  direction {}\n  right {}\n  up {}\n{blur}}}",
            v(self.location),
            v(self.direction),
            v(self.right),
            v(self.up)
        )
    }
}

/// An orthonormal, left-handed viewing frame: right × up = forward as POV-Ray's axes are.
#[derive(Clone, Copy, Debug)]
pub struct Basis {
    pub forward: DVec3,
    pub right: DVec3,
    pub up: DVec3,
}

impl Basis {
    pub fn from_forward(forward: DVec3, sky: DVec3) -> Basis {
        let mut right = sky.cross(forward);
        if right.length_squared() < 1e-24 {
            // Looking straight along the sky: any perpendicular will do, keep it stable.
            right = DVec3::X.cross(forward).cross(forward).normalize().cross(forward);
            if right.length_squared() < 1e-24 {
                right = DVec3::X;
            }
        }
        let right = right.normalize();
        let up = forward.cross(right).normalize();
        Basis { forward, right, up }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn look_at_keeps_pov_default_lengths() {
        let base = Camera::from_desc(&CameraDesc::default());
        let c = Camera::looking_at(DVec3::new(0.0, 0.0, -5.0), DVec3::ZERO, None, &base);
        assert!((c.direction - DVec3::Z).length() < 1e-12);
        assert!((c.right - DVec3::new(1.33, 0.0, 0.0)).length() < 1e-12);
        assert!((c.up - DVec3::Y).length() < 1e-12);
    }

    #[test]
    fn angle_sets_direction_length() {
        let base = Camera::from_desc(&CameraDesc::default());
        let c = Camera::looking_at(DVec3::ZERO, DVec3::Z, Some(90.0), &base);
        assert!((c.angle_deg() - 90.0).abs() < 1e-9);
    }

    #[test]
    fn looking_straight_down_is_finite() {
        let base = Camera::from_desc(&CameraDesc::default());
        let c = Camera::looking_at(DVec3::Y, DVec3::ZERO, None, &base);
        assert!(c.right.is_finite() && c.up.is_finite());
        assert!(c.right.dot(c.direction).abs() < 1e-9);
    }
}
