//! strahl: a real-time CPU ray tracer for scenes written in POV-Ray's scene language.
//!
//! Data flows one way: `pov` parses text into `desc`; `scene::build` turns that into
//! render-ready data; `render` traces it with `geometry`, `accel` and `shading`; `headless` and
//! `app` drive `render`. Underneath everything, `lanes` is the arithmetic (one f32, eight f32s
//! or one f64) that shapes, bounds and shading formulas are written in once; `function` compiles
//! the scene language's user-defined functions, which `pov` builds and `geometry` runs. The
//! layers and the rule that keeps them from looping: docs/design/architecture.md.

pub mod accel;
pub mod app;
pub mod camera;
pub mod density_file;
pub mod desc;
pub mod error;
pub mod fly;
pub mod function;
pub mod geometry;
pub mod headless;
pub mod image_file;
pub mod lanes;
pub mod noise;
pub mod pov;
pub mod ray;
pub mod render;
pub mod scene;
pub mod shading;
pub mod text;
