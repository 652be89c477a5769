//! Scene data: `desc` (as written, f64) and `build` (render-ready, f32, relative to a render
//! origin), with the fixtures, generators and printer that work on descriptions.

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
