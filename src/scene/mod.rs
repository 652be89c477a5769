//! The render-ready scene: `build` turns a `desc::SceneDesc` (as written, f64) into a `Scene`
//! (f32, relative to a render origin), with the fixtures, generators and printer that work on
//! descriptions.
//!
//! Layer 6 of docs/design/architecture.md: uses `accel`, `camera`, `desc`, `function`, `geometry`, `shading`; `render` and above use it.

pub mod atmosphere;
pub mod build;
pub mod csg;
pub mod fixtures;
pub mod generate;
pub mod light;
pub mod material;
pub mod place;
pub mod print;
pub mod shape_kind;
mod store;
mod test_cost;
