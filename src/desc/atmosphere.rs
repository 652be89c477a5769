//! The atmosphere as written: sky sphere, fog and rainbow.

use super::{Color, ColorMapEntry, PigmentDesc};
use glam::DVec3;

/// `sky_sphere { pigment.. [transform] [emission C] }`: pigments evaluated on the unit ray
/// direction, layered (the first written is the bottom layer).
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphereDesc {
    /// Bottom layer first; each pigment's transform includes the sky sphere's own.
    pub pigments: Vec<PigmentDesc>,
    pub emission: DVec3,
}

/// `fog { fog_type distance color fog_offset fog_alt up turbulence .. }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogDesc {
    /// 1: constant, 2: ground fog.
    pub fog_type: u32,
    pub distance: f64,
    pub color: Color,
    pub offset: f64,
    pub alt: f64,
    /// Unit up direction of ground fog (rotated by the fog's transforms).
    pub up: DVec3,
    /// `turbulence`: parsed; strahl's fog is smooth (warned once).
    pub turbulence: DVec3,
}

impl Default for FogDesc {
    fn default() -> Self {
        FogDesc {
            fog_type: 1,
            distance: 0.0,
            color: Color::BLACK,
            offset: 0.0,
            alt: 0.0,
            up: DVec3::Y,
            turbulence: DVec3::ZERO,
        }
    }
}

/// `rainbow { direction angle width distance jitter up arc_angle falloff_angle color_map }`.
#[derive(Clone, Debug, PartialEq)]
pub struct RainbowDesc {
    pub direction: DVec3,
    /// Degrees.
    pub angle: f64,
    pub width: f64,
    pub distance: f64,
    pub jitter: f64,
    pub up: DVec3,
    pub arc_angle: f64,
    pub falloff_angle: f64,
    pub color_map: Vec<ColorMapEntry>,
}

impl Default for RainbowDesc {
    fn default() -> Self {
        RainbowDesc {
            direction: DVec3::Z,
            angle: 0.0,
            width: 0.0,
            distance: 1e7,
            jitter: 0.0,
            up: DVec3::Y,
            arc_angle: 180.0,
            falloff_angle: 180.0,
            color_map: Vec::new(),
        }
    }
}
