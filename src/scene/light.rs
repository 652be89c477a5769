//! The renderer's lights: a scene's `light_source`s in render space, with what shading needs
//! of each kind (beam, fading, area grid) resolved once when the scene is built.

use glam::{DVec3, Vec3};

use crate::camera::frame::RenderFrame;
use crate::desc::{LightDesc, LightKind};
use crate::shading::light::{AreaGrid, Beam};

#[derive(Clone, Copy, Debug)]
pub struct Light {
    /// Render space.
    pub position: Vec3,
    pub color: Vec3,
    /// `shadowless`: lights every point that faces it, no shadow rays.
    pub shadowless: bool,
    /// Spotlight or cylinder falloff (`shading::light::Beam`).
    pub beam: Beam,
    /// Unit direction from the light towards `point_at` (spot, cylinder, parallel).
    pub axis: Vec3,
    pub tightness: f32,
    /// `parallel`: light arrives along `axis` everywhere; shadows end at the plane through
    /// the light's position across `axis`.
    pub parallel: bool,
    /// `fade_distance` in render units (0: no fading) and `fade_power`.
    pub fade_distance: f32,
    pub fade_power: f32,
    /// `area_light`, axes in render units.
    pub area: Option<AreaGrid>,
}

impl Light {
    /// A plain point light, shaded exactly as before the other kinds existed (and the only
    /// kind traced in shadow packets).
    #[inline]
    pub fn is_point(&self) -> bool {
        self.beam == Beam::Point && !self.parallel && self.fade_distance <= 0.0 && self.area.is_none()
    }

    pub(super) fn from_desc(l: &LightDesc, frame: &RenderFrame) -> Light {
        let to = l.point_at - l.position;
        let axis = if to.length() > 0.0 { to.normalize() } else { DVec3::NEG_Y };
        let (radius, falloff, tightness) = l.spot_params();
        let beam = match l.kind {
            LightKind::Point => Beam::Point,
            LightKind::Spot => {
                // POV-Ray reads the angles as half-openings below 90°, by their cosines, so
                // a negative angle opens as its positive one (`radius 90 falloff -90`, the
                // mesh_camera samples' lights, lights the half-space as `falloff 90` does); a
                // falloff inside the radius makes a hard edge at the radius.
                let falloff = falloff.abs().min(90.0);
                let radius = radius.abs().min(falloff);
                Beam::Spot {
                    cos_radius: radius.to_radians().cos() as f32,
                    cos_falloff: falloff.to_radians().cos() as f32,
                }
            }
            LightKind::Cylinder => {
                let falloff = (falloff * frame.per_unit).max(1e-12);
                Beam::Cylinder { radius: (radius * frame.per_unit).min(falloff) as f32, falloff: falloff as f32 }
            }
        };
        Light {
            position: frame.point(l.position).as_vec3(),
            color: l.color.as_vec3(),
            shadowless: l.shadowless,
            beam,
            axis: axis.as_vec3(),
            tightness: tightness as f32,
            parallel: l.parallel,
            fade_distance: (l.fade_distance * frame.per_unit) as f32,
            fade_power: l.fade_power as f32,
            area: l.area.map(|a| AreaGrid {
                axis1: frame.vector(a.axis1).as_vec3(),
                axis2: frame.vector(a.axis2).as_vec3(),
                size1: a.size1.max(1),
                size2: a.size2.max(1),
                adaptive: a.adaptive,
                jitter: a.jitter,
                circular: a.circular,
                orient: a.orient,
            }),
        }
    }
}
