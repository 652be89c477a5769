//! Procedural textures, render-ready: pigments (solid, checker, wood with a
//! colour map) and normal perturbation (bumps).
//!
//! Everything here is f32 and evaluated per hit in render space (world minus the render origin);
//! conversion from `desc` happens once, in f64, in the `from_desc` constructors. Lighting
//! and finishes are left to the renderer.
//!
//! Layer 5 of docs/design/architecture.md: uses `geometry`, `desc`, `function`, `noise`; `scene` and `render` use it.

pub mod image_map;
pub mod light;
pub mod normal;
pub mod pattern;
pub mod pattern_space;
pub mod patterns;
pub mod pigment;
pub mod pigment_fn;
