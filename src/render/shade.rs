//! The local lighting model, written once for one hit (`f32`) and for eight (`F8`).
//!
//! `Tracer::shade_surface` lights single hits with it and `render::packet` lights whole rows of a
//! packet with it, so both compute the same IEEE operations in the same order and give the same
//! bits (as the shapes' `geometry::Shape::hit` does).
//!
//! `I = ambient·C·ambient_light·opacity + Σ_lights L·(diffuse·C·(N·L)^brilliance·opacity
//!      + phong·(R·L)^phong_size + specular·(N·H)^(1/roughness))`

use glam::Vec3;

use crate::lanes::{Lane, V3};
use crate::scene::material::Finish;

/// Light arriving at a hit from one light source.
#[derive(Clone, Copy)]
pub struct LightSample<L: Lane> {
    /// Unit direction towards the light.
    pub dir: V3<L>,
    /// The light's colour times what the shadow ray let through.
    pub color: V3<L>,
    /// Lanes the light reaches.
    pub on: L::Mask,
}

/// What the local model needs of a hit.
#[derive(Clone, Copy)]
pub struct LocalHit<L: Lane> {
    /// Pigment colour.
    pub color: V3<L>,
    /// `1 − filter − transmit`, as POV-Ray weighs the surface's own colour: not clamped, so
    /// `filter + transmit > 1` subtracts it, the contrast filter of POV-Ray's samples
    /// (textures/pigments/transmitfx.pov, advanced/bwstripe.pov).
    pub opacity: L,
    /// Shading normal (after bumps), facing the viewer.
    pub normal: V3<L>,
    pub ray_dir: V3<L>,
}

/// `1 − filter − transmit`, negative where they add up past 1 (measured against POV-Ray 3.7:
/// `rgb <0.5, 0.25, 1> filter 1 transmit 0.5` over a background B shows `B·(C + 0.5) − 0.5·C`).
#[inline(always)]
pub fn opacity<L: Lane>(filter: L, transmit: L) -> L {
    L::splat(1.0) - filter - transmit
}

/// The mirror direction of `ray_dir` about `normal`.
#[inline(always)]
pub fn reflect<L: Lane>(ray_dir: V3<L>, normal: V3<L>) -> V3<L> {
    ray_dir.sub(normal.scale(L::splat(2.0) * ray_dir.dot(normal)))
}

/// The ambient term, where lighting starts.
#[inline(always)]
pub fn ambient<L: Lane>(finish: &Finish, ambient_light: Vec3, hit: &LocalHit<L>) -> V3<L> {
    let a = V3::splat(finish.ambient).mul(hit.color).mul(V3::splat(ambient_light)).scale(hit.opacity);
    if finish.emission == Vec3::ZERO {
        return a;
    }
    // `emission`: as ambient, without `ambient_light`.
    a.add(V3::splat(finish.emission).mul(hit.color).scale(hit.opacity))
}

/// The colour of a highlight of light `light`: the light's own, or towards the pigment's with
/// `metallic`.
#[inline(always)]
fn highlight<L: Lane>(finish: &Finish, light: V3<L>, color: V3<L>) -> V3<L> {
    if finish.metallic == 0.0 {
        return light;
    }
    let m = L::splat(finish.metallic);
    let one = V3::splat(Vec3::ONE);
    light.mul(one.add(color.sub(one).scale(m)))
}

/// `color` plus one light's diffuse, phong and specular terms; `reflected` is
/// `reflect(hit.ray_dir, hit.normal)`.
#[inline(always)]
pub fn add_light<L: Lane>(
    finish: &Finish,
    hit: &LocalHit<L>,
    reflected: V3<L>,
    mut color: V3<L>,
    light: &LightSample<L>,
) -> V3<L> {
    let LocalHit { color: c, opacity, normal, ray_dir } = *hit;
    let zero = L::splat(0.0);
    let (l, on) = (light.dir, light.on);
    // Each term is computed only where some lane takes it: a lane's bits are the same either
    // way (the select keeps `color` where it does not), and shadowed rows skip the powers.
    if !L::any(on) {
        return color;
    }
    if finish.diffuse > 0.0 {
        let d = finish.brilliance.pow_lanes(normal.dot(l));
        let term = light.color.mul(c).scale(L::splat(finish.diffuse) * d * opacity);
        color = V3::select(on, color.add(term), color);
    }
    if finish.phong > 0.0 {
        let r_dot_l = reflected.dot(l);
        let lit = L::and(on, zero.lt(r_dot_l));
        if L::any(lit) {
            let term =
                highlight(finish, light.color, c).scale(L::splat(finish.phong) * finish.phong_size.pow_lanes(r_dot_l));
            color = V3::select(lit, color.add(term), color);
        }
    }
    if finish.specular > 0.0 {
        let h = l.sub(ray_dir).normalize_or(V3::splat(Vec3::ZERO));
        let n_dot_h = normal.dot(h);
        let lit = L::and(on, zero.lt(n_dot_h));
        if L::any(lit) {
            let term = highlight(finish, light.color, c)
                .scale(L::splat(finish.specular) * finish.specular_exponent.pow_lanes(n_dot_h));
            color = V3::select(lit, color.add(term), color);
        }
    }
    color
}
