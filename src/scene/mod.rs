//! Scene data: `desc` (as written, f64), `build` (render-ready, f32, relative to a render origin)
//! and `precise` (the same geometry in f64, for the precise render path).

pub mod build;
pub mod desc;
pub mod fixtures;
pub mod generate;
pub mod material;
pub mod precise;
pub mod print;
