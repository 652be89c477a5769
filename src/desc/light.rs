//! Light sources as written.

use glam::DVec3;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightDesc {
    pub position: DVec3,
    pub color: DVec3,
    /// `shadowless`: the light illuminates but casts no shadows (no shadow rays are traced).
    pub shadowless: bool,
    /// Point (the default), `spotlight` or `cylinder`.
    pub kind: LightKind,
    /// `point_at`: where a spotlight, cylinder or parallel light points (default the origin).
    pub point_at: DVec3,
    /// `radius`, `falloff`, `tightness` as written: degrees for a spotlight, units from the axis
    /// for a cylinder. `None`: the kind's default (`LightDesc::spot_params`).
    pub radius: Option<f64>,
    pub falloff: Option<f64>,
    pub tightness: Option<f64>,
    /// `parallel`: every ray of the light travels along `point_at - position`.
    pub parallel: bool,
    /// `fade_distance` (0: no fading) and `fade_power`.
    pub fade_distance: f64,
    pub fade_power: f64,
    /// `area_light`: soft shadows from a grid of point lights.
    pub area: Option<AreaLightDesc>,
    /// `media_interaction`, `media_attenuation`: kept as written; strahl models no media.
    pub media_interaction: bool,
    pub media_attenuation: bool,
    /// The innermost `light_group` the light is written in (an index into
    /// `SceneDesc::light_groups`, whose `lights` list it), or `None`: a global light.
    pub light_group: Option<u32>,
}

impl Default for LightDesc {
    /// A white point light at the origin, as POV-Ray's defaults.
    fn default() -> Self {
        LightDesc {
            position: DVec3::ZERO,
            color: DVec3::ONE,
            shadowless: false,
            kind: LightKind::Point,
            point_at: DVec3::ZERO,
            radius: None,
            falloff: None,
            tightness: None,
            parallel: false,
            fade_distance: 0.0,
            fade_power: 0.0,
            area: None,
            media_interaction: true,
            media_attenuation: false,
            light_group: None,
        }
    }
}

impl LightDesc {
    /// `(radius, falloff, tightness)` with the kind's defaults (POV-Ray 3.7: spotlight 30, 45, 0
    /// degrees; cylinder 0.75, 1, 0 units).
    pub fn spot_params(&self) -> (f64, f64, f64) {
        let (r, f) = match self.kind {
            LightKind::Cylinder => (0.75, 1.0),
            _ => (30.0, 45.0),
        };
        (self.radius.unwrap_or(r), self.falloff.unwrap_or(f), self.tightness.unwrap_or(0.0))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    Point,
    Spot,
    Cylinder,
}

/// `area_light <axis1>, <axis2>, size1, size2 [adaptive N] [jitter] [circular] [orient]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLightDesc {
    pub axis1: DVec3,
    pub axis2: DVec3,
    /// Rows and columns of point lights (at least 1 each).
    pub size1: u32,
    pub size2: u32,
    /// `adaptive N`: corner-first subdivision with at least N levels; `None`: every point.
    pub adaptive: Option<u32>,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
}
