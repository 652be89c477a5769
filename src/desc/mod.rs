//! The scene as written: plain f64 data produced by `pov::lower`, consumed by `scene::build`.
//!
//! Nothing here knows about tokens, BVHs or rays. Every value is in POV-Ray's units and
//! left-handed world space exactly as the scene file states it; transforms are kept as matrices so
//! that `build` can fold them into render-ready f32 data relative to the camera.
//!
//! Layer 2 of docs/design/architecture.md: uses only `function`, `image_file` and `density_file`; every layer above reads it.

use glam::{DMat4, DVec3};

mod atmosphere;
mod camera;
mod light;
mod placement;
mod shape;
mod texture;

pub use atmosphere::*;
pub use camera::*;
pub use light::*;
pub use placement::Placement;
pub use shape::*;
pub use texture::*;

/// A POV-Ray colour: red, green, blue, filter, transmit.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Color {
    pub rgb: DVec3,
    /// Fraction of light that passes through, tinted by `rgb`.
    pub filter: f64,
    /// Fraction of light that passes through untinted.
    pub transmit: f64,
}

impl Color {
    pub const BLACK: Color = Color { rgb: DVec3::ZERO, filter: 0.0, transmit: 0.0 };
    pub const WHITE: Color = Color { rgb: DVec3::ONE, filter: 0.0, transmit: 0.0 };

    pub fn rgb(r: f64, g: f64, b: f64) -> Color {
        Color { rgb: DVec3::new(r, g, b), filter: 0.0, transmit: 0.0 }
    }
}

/// An affine transform, stored both ways so nobody inverts on the per-ray path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Maps points from the local (object or pattern) space into the space above it.
    pub matrix: DMat4,
    /// The inverse of `matrix`.
    pub inverse: DMat4,
}

impl Default for Transform {
    fn default() -> Self {
        Transform { matrix: DMat4::IDENTITY, inverse: DMat4::IDENTITY }
    }
}

impl Transform {
    /// `then` is applied after `self` (POV-Ray's order: modifiers compose left to right).
    pub fn then(&self, then: &Transform) -> Transform {
        Transform { matrix: then.matrix * self.matrix, inverse: self.inverse * then.inverse }
    }

    pub fn is_identity(&self) -> bool {
        self.matrix == DMat4::IDENTITY
    }
}

/// The box holding the box `[lo, hi]` mapped by `m` (its eight corners'), `[min, max]`.
pub fn box_through(m: &DMat4, lo: DVec3, hi: DVec3) -> [DVec3; 2] {
    let (mut a, mut b) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for i in 0..8 {
        let corner = DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        let c = m.transform_point3(corner);
        (a, b) = (a.min(c), b.max(c));
    }
    [a, b]
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalSettings {
    /// `None` when the scene did not say; the effective value then depends on `#version`.
    pub assumed_gamma: Option<f64>,
    pub max_trace_level: u32,
    pub ambient_light: DVec3,
    /// `noise_generator` 1, 2 or 3 (POV-Ray 3.7's default is 2): which noise patterns use.
    pub noise_generator: u32,
    /// `number_of_waves`: how many centres `waves` and `ripples` sum (POV-Ray's default 10).
    pub number_of_waves: u32,
    /// `irid_wavelength`: the wavelengths (as a colour) `irid` interferes at.
    pub irid_wavelength: DVec3,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            assumed_gamma: None,
            max_trace_level: 5,
            ambient_light: DVec3::ONE,
            noise_generator: 2,
            number_of_waves: 10,
            irid_wavelength: DVec3::new(0.25, 0.18, 0.14),
        }
    }
}

/// Where in the scene files something was written, for messages after parsing.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct SourceRef {
    /// Shared by every object of one file (a million objects, one name).
    pub file: std::sync::Arc<str>,
    pub line: u32,
    pub col: u32,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ObjectDesc {
    pub shape: ShapeDesc,
    /// Object space → world space, as compactly as it is held exactly.
    pub transform: Placement,
    /// Shared by the objects that look alike (the lowering hands out one copy of each look it
    /// met recently: a million generated spheres in 16 colours hold 16 textures).
    pub texture: std::sync::Arc<TextureDesc>,
    /// `interior_texture`: the texture a ray sees where it meets the surface from inside
    /// (against the outward normal); `None`: `texture` on both sides.
    pub interior_texture: Option<Box<TextureDesc>>,
    pub interior: InteriorDesc,
    /// `no_shadow`: the object is visible but casts no shadow (shadow rays ignore it).
    pub no_shadow: bool,
    /// `inverse`: inside and outside swap, for an enclosing CSG (and its normal points in).
    pub inverse: bool,
    /// `hollow`: the inside may hold media. Kept as written; nothing that strahl renders yet
    /// depends on it (in POV-Ray only media and fog inside objects do).
    pub hollow: bool,
    /// The innermost `light_group` the object belongs to (an index into
    /// `SceneDesc::light_groups`), or `None`: lit by the scene's global lights only.
    pub light_group: Option<u32>,
    /// `bounded_by { .. }`: the box of the bounding objects in this object's own space (so the
    /// transforms written after it move it along), `[min, max]`. A hint for the renderer, which
    /// skips the shape for rays that miss it; only unbounded shapes (polynomials) need it.
    pub bounded_by: Option<Box<[DVec3; 2]>>,
    pub source: SourceRef,
}
impl ObjectDesc {
    /// The texture to change, copied first if other objects share it.
    pub fn texture_mut(&mut self) -> &mut TextureDesc {
        std::sync::Arc::make_mut(&mut self.texture)
    }
}

/// A `light_group` (POV-Ray 3.4.4.2): its lights (indices into `SceneDesc::lights`) light only
/// the objects of the group and of the groups inside it; the scene's global lights (those in no
/// group) light them too when `global_lights` is on.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct LightGroupDesc {
    pub lights: Vec<u32>,
    pub global_lights: bool,
    /// The group this one is written in: its lights light this group's objects too.
    pub parent: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SceneDesc {
    /// The language version in effect at the end of parsing (`#version`, or 3.7 when none).
    pub version: f64,
    /// Whether any `#version` directive ran (an included `colors.inc` runs one). POV-Ray 3.7
    /// treats a scene without one as legacy for gamma: no `assumed_gamma`, linear output.
    pub version_directive: bool,
    pub camera: CameraDesc,
    /// The meshes of a `mesh_camera` (`camera.lens.projection` is `Projection::Mesh`).
    pub camera_mesh: Option<std::sync::Arc<MeshCameraDesc>>,
    /// The camera's `normal { .. }`, read at screen points (x, y, 0) and tilting the eye rays
    /// (`render::RayGen`).
    pub camera_normal: Option<std::sync::Arc<NormalDesc>>,
    pub lights: Vec<LightDesc>,
    /// `background { color C }`; black by default.
    pub background: Color,
    /// `sky_sphere { pigment.. }`: seen where rays miss (`scene::atmosphere`).
    pub sky_sphere: Option<SkySphereDesc>,
    /// `fog { .. }` layers, in scene order.
    pub fogs: Vec<FogDesc>,
    /// `rainbow { .. }`s, in scene order.
    pub rainbows: Vec<RainbowDesc>,
    pub global: GlobalSettings,
    pub objects: Vec<ObjectDesc>,
    /// The scene's `light_group`s; empty when it has none (every light lights everything).
    pub light_groups: Vec<LightGroupDesc>,
    /// Every file `#include` read, in order, with the directive that read it (for the
    /// statistics: which `colors.inc` a scene got).
    pub included: Vec<IncludedFile>,
    /// Rendering features the scene asks for that strahl does not model (`radiosity`, `media`,
    /// `photons`...), each named once, where it first appears: for the statistics and the HUD.
    pub unmodelled: Vec<UnmodelledFeature>,
}

/// A feature the scene uses that strahl renders without (the rest of the scene renders).
#[derive(Clone, Debug, PartialEq)]
pub struct UnmodelledFeature {
    /// The feature as the scene writes it (`radiosity`, `media`, `photons`).
    pub name: String,
    pub at: SourceRef,
}

/// A file an `#include` read: where it was found, and where the directive stands.
#[derive(Clone, Debug, PartialEq)]
pub struct IncludedFile {
    pub path: String,
    pub from: SourceRef,
}

impl Default for SceneDesc {
    fn default() -> Self {
        SceneDesc {
            version: 3.7,
            version_directive: false,
            camera: CameraDesc::default(),
            camera_mesh: None,
            camera_normal: None,
            lights: Vec::new(),
            background: Color::BLACK,
            sky_sphere: None,
            fogs: Vec::new(),
            rainbows: Vec::new(),
            global: GlobalSettings::default(),
            objects: Vec::new(),
            light_groups: Vec::new(),
            included: Vec::new(),
            unmodelled: Vec::new(),
        }
    }
}

impl SceneDesc {
    /// How computed colours become output values, as POV-Ray 3.7 does it (checked by rendering):
    /// `Some(g)`: raised to the power `g` (`assumed_gamma`), then sRGB-encoded; `None`: written
    /// as they are (a legacy scene without `assumed_gamma`). A scene whose `#version` directive
    /// says 3.7 or later and gives no `assumed_gamma` gets 1.0; one with no directive at all
    /// is legacy.
    pub fn output_gamma(&self) -> Option<f64> {
        match self.global.assumed_gamma {
            Some(g) => Some(g),
            None if self.version_directive && self.version >= 3.7 - 1e-9 => Some(1.0),
            None => None,
        }
    }

    /// Which of `lights` light the objects of `group` (`None`: objects in no group), or `None`
    /// when the scene has no light groups and every light lights everything.
    pub fn light_mask(&self, group: Option<u32>) -> Option<Vec<bool>> {
        if self.light_groups.is_empty() {
            return None;
        }
        let mut grouped = vec![false; self.lights.len()];
        for g in &self.light_groups {
            for &l in &g.lights {
                grouped[l as usize] = true;
            }
        }
        let global = group.is_none_or(|g| self.light_groups[g as usize].global_lights);
        let mut mask: Vec<bool> = grouped.iter().map(|&in_group| global && !in_group).collect();
        // The group's own lights and those of the groups around it (bounded: a chain of
        // parents cannot be longer than the number of groups).
        let mut at = group;
        for _ in 0..self.light_groups.len() {
            let Some(g) = at else { break };
            let g = &self.light_groups[g as usize];
            for &l in &g.lights {
                mask[l as usize] = true;
            }
            at = g.parent;
        }
        Some(mask)
    }

    /// Whether output pixels are sRGB-encoded.
    pub fn writes_srgb(&self) -> bool {
        self.output_gamma().is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene of a million objects holds a million of these until it is built: they were
    /// 1856 bytes each (a texture of 1224 bytes inline, two 4×4 matrices, the largest shape's
    /// numbers in every sphere), more than POV-Ray's whole object.
    #[test]
    fn an_object_description_stays_small() {
        assert!(std::mem::size_of::<Placement>() <= 32, "{}", std::mem::size_of::<Placement>());
        assert!(std::mem::size_of::<ShapeDesc>() <= 80, "{}", std::mem::size_of::<ShapeDesc>());
        assert!(std::mem::size_of::<ObjectDesc>() <= 192, "{}", std::mem::size_of::<ObjectDesc>());
    }
}
