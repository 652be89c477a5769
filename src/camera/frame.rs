//! Render space: the camera-centred, camera-scaled frame every render-ready number lives in.

use glam::{DMat4, DVec3};

use crate::desc::SceneDesc;

/// Where render space sits in world space: `render = (world − origin) / unit`.
///
/// The unit is a length the scene's own camera defines, the distance to `look_at` (else the
/// length of `direction`), so it scales with the scene: scale a whole scene, camera included,
/// by any factor and its render-space numbers stay the same, up to f64 rounding far below f32's.
/// A power-of-two unit would only be exact for power-of-two scales. Ray tracing has no
/// absolute lengths left after this (offsets and epsilons are relative; patterns live in their
/// own space), so the unit changes no picture, only which f32 numbers represent it.
///
/// Every conversion multiplies by the one rounded `1 / unit` (`per_unit`), never divides, so a
/// point reached through an object's composed matrix and the same point converted directly get
/// the same f64 bits wherever the world numbers are exact: faces that coincide in the scene
/// (a box standing on the floor plane) still coincide in render space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderFrame {
    pub origin: DVec3,
    pub unit: f64,
    /// `1 / unit`, rounded once.
    pub per_unit: f64,
}

impl RenderFrame {
    /// Centred on `origin`, in the unit `desc`'s camera sets (1 where it sets none usable).
    pub fn for_scene(desc: &SceneDesc, origin: DVec3) -> RenderFrame {
        let c = &desc.camera;
        let look = c.look_at.map_or(0.0, |p| (p - c.location).length());
        let unit = [look, c.direction.length()]
            .into_iter()
            .find(|u| u.is_finite() && (1e-30..=1e30).contains(u))
            .unwrap_or(1.0);
        RenderFrame { origin, unit, per_unit: 1.0 / unit }
    }

    /// A world point in render space.
    #[inline]
    pub fn point(&self, p: DVec3) -> DVec3 {
        (p - self.origin) * self.per_unit
    }

    /// A world vector (an offset, not a position) in render space.
    #[inline]
    pub fn vector(&self, v: DVec3) -> DVec3 {
        v * self.per_unit
    }

    pub fn render_from_world(&self) -> DMat4 {
        DMat4::from_scale(DVec3::splat(self.per_unit)) * DMat4::from_translation(-self.origin)
    }

    pub fn world_from_render(&self) -> DMat4 {
        DMat4::from_translation(self.origin) * DMat4::from_scale(DVec3::splat(self.unit))
    }
}
