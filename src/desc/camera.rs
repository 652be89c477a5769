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
    /// The projection and focal blur (rays from them: `crate::camera::lens`).
    pub lens: Lens,
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

/// `mesh_camera { rays_per_pixel distribution_type [max_distance] mesh { M transforms }... }`
/// (POV-Ray 3.4.2.2.3): the meshes as declared, each with its transform into the world. The
/// renderer (`camera::mesh`) turns them into rays; the parser never builds a BVH for them.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCameraDesc {
    /// Rays shot per pixel (≥ 1): the ray number picks the mesh (distribution 0) or the block
    /// of faces (distribution 1).
    pub rays_per_pixel: u32,
    /// 0: one mesh per ray number; 1: the meshes' faces summed; 2: the meshes side by side
    /// across the image; 3: each image point found in the first mesh's uv map.
    pub distribution: u8,
    /// Rays end this far from their origin (world units); 0 for no limit.
    pub max_distance: f64,
    /// `smooth`: distribution 3 interpolates the vertex normals.
    pub smooth: bool,
    pub meshes: Vec<MeshCameraMesh>,
}

/// One `mesh { M transforms }` of a mesh camera.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCameraMesh {
    pub mesh: std::sync::Arc<super::MeshDesc>,
    /// Mesh space → world space (the declared mesh's own transform, then the camera's).
    pub transform: super::Transform,
}

/// A camera's projection type, with the parameters it reads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Projection {
    #[default]
    Perspective,
    Orthographic,
    /// `angle` in degrees; without one, the perspective field of view the vectors give (`lower`).
    Fisheye {
        angle: f64,
    },
    UltraWideAngle {
        angle: f64,
    },
    Omnimax,
    Panoramic,
    /// `cylinder 1|2|3|4` with its angle in degrees.
    Cylinder {
        kind: u8,
        angle: f64,
    },
    /// `spherical`, `angle h [v]` in degrees.
    Spherical {
        h: f64,
        v: f64,
    },
    /// `mesh_camera { .. }` (`camera::mesh`): the meshes are the scene's `camera_mesh`; the
    /// camera's vectors are not used. `offset` (world units, from `location.z`) moves each
    /// origin along its face normal; `reverse` (`direction.z < 0`) turns the rays around;
    /// `max_distance` (world units, 0 for none) ends them.
    Mesh {
        rays_per_pixel: u32,
        offset: f64,
        reverse: bool,
        max_distance: f64,
    },
}

impl Projection {
    /// The POV-Ray keyword(s) that select this projection.
    pub fn keyword(&self) -> String {
        match self {
            Projection::Perspective => "perspective".into(),
            Projection::Orthographic => "orthographic".into(),
            Projection::Fisheye { .. } => "fisheye".into(),
            Projection::UltraWideAngle { .. } => "ultra_wide_angle".into(),
            Projection::Omnimax => "omnimax".into(),
            Projection::Panoramic => "panoramic".into(),
            Projection::Cylinder { kind, .. } => format!("cylinder {kind}"),
            Projection::Spherical { .. } => "spherical".into(),
            Projection::Mesh { .. } => "mesh_camera".into(),
        }
    }
}

/// `aperture`, `blur_samples [min,] max`, `focal_point`, `confidence`, `variance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FocalBlur {
    pub aperture: f64,
    /// The rays every pixel takes before the adaptive stop (`render::blur`) may end it.
    pub min_samples: u32,
    pub max_samples: u32,
    pub focal_point: DVec3,
    /// The adaptive stop's probability and colour tolerance (`render::blur`).
    pub confidence: f64,
    pub variance: f64,
}

impl Default for FocalBlur {
    fn default() -> Self {
        FocalBlur {
            aperture: 0.0,
            min_samples: 4,
            max_samples: 0,
            focal_point: DVec3::ZERO,
            confidence: 0.9,
            variance: 1.0 / 128.0,
        }
    }
}

/// What a camera looks through: its projection and, when `aperture` and `blur_samples` are
/// both positive, focal blur.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lens {
    pub projection: Projection,
    pub blur: Option<FocalBlur>,
}

impl Lens {
    /// The blur samples traced per (sub-)sample under a cap; 1 without blur.
    pub fn blur_samples(&self, cap: Option<u32>) -> u32 {
        // A mesh camera's rays each belong to a mesh (or block of faces): never capped.
        if let Projection::Mesh { rays_per_pixel, .. } = self.projection {
            return rays_per_pixel.max(1);
        }
        match self.blur {
            Some(b) => b.max_samples.min(cap.unwrap_or(u32::MAX)).max(1),
            None => 1,
        }
    }
}
