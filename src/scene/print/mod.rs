//! SceneDesc → POV-Ray source that `pov::load_scene` reads back as the same scene (up to float
//! rounding of the transforms). For round-trip tests and for saving generated scenes.
//!
//! Everything is written explicitly: the camera as location/direction/right/up/sky (no
//! `look_at`), colours with filter and transmit, every finish value. Our parser has no `matrix`
//! keyword, so a transform is written as `rotate`, `scale`, `rotate`, `translate`: any affine
//! map's linear part is U·Σ·Vᵀ (singular value decomposition) with U and V rotations and Σ a
//! diagonal scale (negative for a mirror), which covers shear too. Shapes stay in object space
//! and each pattern's transform is written relative to its object (O⁻¹·P), inside the pattern
//! block, so the loader composes it back to P.
//!
//! Split by what is printed: the scene's frame here, `shapes`, `textures` (pigments, normals,
//! finishes), `world` (lights, atmosphere), `transform` (matrices as modifiers).

mod shapes;
mod texture_blocks;
mod textures;
mod transform;
mod world;

use std::fmt::Write;

use glam::DVec3;

use crate::desc::{Color, SceneDesc};
use shapes::object;
use texture_blocks::Declarations;
pub use transform::{decompose, recomposed, Decomposed};
use world::{atmosphere, light};

/// The scene as POV-Ray source (no `#include`s needed).
pub fn to_pov(desc: &SceneDesc) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "#version {};", num(desc.version));
    let g = &desc.global;
    let _ = write!(s, "global_settings {{");
    if let Some(gamma) = g.assumed_gamma {
        let _ = write!(s, " assumed_gamma {}", num(gamma));
    }
    let _ = writeln!(s, " max_trace_level {} ambient_light rgb {} }}", g.max_trace_level, vec(g.ambient_light));
    let _ = writeln!(s, "background {{ {} }}", color(&desc.background));
    let c = &desc.camera;
    let _ = write!(
        s,
        "camera {{\n  location {}\n  direction {}\n  right {}\n  up {}\n  sky {}\n",
        vec(c.location),
        vec(c.direction),
        vec(c.right),
        vec(c.up),
        vec(c.sky)
    );
    if let Some(n) = &desc.camera_normal {
        s.push_str("  ");
        textures::normal(&mut s, n, &glam::DMat4::IDENTITY);
        s.push('\n');
    }
    s.push_str("}\n");
    for l in &desc.lights {
        light(&mut s, l);
    }
    atmosphere(&mut s, desc);
    let mut declared = Declarations::default();
    for o in &desc.objects {
        let mut text = String::new();
        object(&mut text, o, &mut declared);
        s.push_str(&std::mem::take(&mut declared.text));
        s.push_str(&text);
    }
    s
}

/// Shortest decimal that reads back as the same f64, never in exponent form (the lexer's
/// numbers are plain decimals).
fn num(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        // Not expressible in the scene language; 0 keeps the output parseable.
        "0".to_string()
    }
}

/// 2-D points as `<u, v>, ...`.
fn vec2s(points: &[glam::DVec2]) -> String {
    let pts: Vec<String> = points.iter().map(|p| format!("<{}, {}>", num(p.x), num(p.y))).collect();
    pts.join(", ")
}

fn vec(v: DVec3) -> String {
    format!("<{}, {}, {}>", num(v.x), num(v.y), num(v.z))
}

fn color(c: &Color) -> String {
    format!("color rgb {} filter {} transmit {}", vec(c.rgb), num(c.filter), num(c.transmit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prints_numbers_without_exponents() {
        assert_eq!(num(1e-7), "0.0000001");
        assert_eq!(num(-2.5), "-2.5");
        assert_eq!(num(f64::NAN), "0");
    }
}
