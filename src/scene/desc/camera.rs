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
