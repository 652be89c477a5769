//! Pattern space: where a pattern's points come from, as one f32 affine map from render space
//! that keeps precision far from the origin by dropping whole periods of the pattern.

use glam::{Affine3A, DMat4};

use crate::desc::Turbulence;
use crate::noise::TurbulenceF32;
use crate::noise::LATTICE_PERIOD;

/// How a pattern (turbulence included) repeats along one axis of its own space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Period {
    /// It does not depend on this coordinate at all (wood along its axis).
    Any,
    /// Moving the point by this many units leaves it unchanged; always a power of two here
    /// (checker 2, noise `LATTICE_PERIOD`), so of two periods the longer is a multiple of both.
    Every(f64),
    /// It does not repeat (wood's rings across its axis, turbulence with a fractional
    /// `lambda`).
    Never,
}

impl Period {
    /// The period of a pattern made of two parts with these periods.
    fn with(self, other: Period) -> Period {
        match (self, other) {
            (Period::Never, _) | (_, Period::Never) => Period::Never,
            (Period::Any, p) | (p, Period::Any) => p,
            (Period::Every(a), Period::Every(b)) => Period::Every(a.max(b)),
        }
    }
}

/// The period turbulence gives a pattern: octave i samples the noise at λ^i·p, which repeats
/// every `LATTICE_PERIOD` when λ is an integer (POV-Ray's default is 2); any other λ makes it
/// aperiodic. No turbulence (or no octaves) imposes nothing.
fn turbulence_period(t: Option<&Turbulence>) -> Period {
    match t {
        None => Period::Any,
        Some(t) if t.octaves == 0 => Period::Any,
        Some(t) if t.lambda.is_finite() && t.lambda.fract() == 0.0 => Period::Every(LATTICE_PERIOD),
        Some(_) => Period::Never,
    }
}

/// How far from the render origin (the camera), in render units (the camera's unit), a
/// pattern's origin must lie along an axis before `pattern_from_render` reduces that axis.
///
/// Reducing moves every pattern point by whole steps, so the points the camera sees get small
/// coordinates only if they are near the camera. A checker floor seen through a telephoto
/// lens from 8.3e4 units away, looking at the pattern origin (`tests/suite/extremes.rs`), had its
/// visible points moved from near 0 to about 2e4, where the checker's tolerance, relative to
/// the coordinate, shifted edges by a third of a check: 3 995 wrong pixels. Its origin lies
/// one camera unit away (the unit is the distance to `look_at`), a scene written 1e6 away from
/// its floor's origin 2e5. Beyond 16 units, the points within a few units of the camera, where
/// it looks, come nearer the pattern origin (to within half a step plus their distance), and
/// an origin nearer than that, like the telephoto's, keeps its numbers.
const FAR_PATTERN_ORIGIN: f64 = 16.0;

/// The shortest lattice step `pattern_from_render` reduces by, in pattern units.
///
/// A scene near the pattern origin is not reduced (`FAR_PATTERN_ORIGIN`), so the same scene
/// written at an offset renders the same numbers only if its reduced translation comes back to
/// the unreduced one: the offset must be a multiple of the step, and the near translation
/// under half a step. Reducing a checker by its own period 2 would bring the seed scene's
/// floor (translation 3) at 1e6 to −1, the same pattern in other roundings (reduced to −1
/// itself, the seed render changed on 14 of its 1280×720 pixels). With steps of at least 32,
/// near translations under 16 units come back (the seed's, and the reference scenes' at most
/// 10) for offsets that are multiples of 32 (1e5 = 2^5·3125 and every larger power of ten),
/// at the cost of at most an f32 ulp of 16 units (2e-6).
const MIN_REDUCTION_STEP: f64 = 32.0;

/// The lattice step for a pattern of period `period` (a power of two): the smallest multiple of
/// it by a power of two that is at least `MIN_REDUCTION_STEP`.
fn reduction_step(period: f64) -> f64 {
    debug_assert!(period > 0.0, "a period must be positive: {period}");
    let mut step = period;
    while step < MIN_REDUCTION_STEP {
        step *= 2.0;
    }
    step
}

/// `pattern_from_world ∘ world_from_render`, composed in f64 then cast: its translation is
/// where the render origin sits in pattern space, so f32 keeps precision near the camera.
///
/// Where the pattern itself lies far from the render origin (a checker floor under a scene
/// written at x = 1e6, whose texture is not moved with it), that translation is large and its
/// f32 ulp (0.06 at 1e6) moves every check edge. So along each axis where the pattern has a
/// period (its own `periods` with `turbulence`'s), the translation t is reduced in f64 by a
/// whole number of lattice steps L, a multiple of the period (`reduction_step`):
/// t − floor(t/L + ½)·L. No colour changes, since the pattern repeats, and |t| < L/2 keeps
/// its old numbers. floor(x + ½) rather than round(), whose ties go away from zero, so that a
/// scene moved by whole steps reduces to the same number on either side of zero; L is a power
/// of two, so the reduction is exact. An axis without a period keeps its translation: wood's
/// rings far from their own axis stay limited by f32 (a known limit; POV-Ray evaluates
/// patterns in double).
pub fn pattern_from_render(
    world_from_pattern_inverse: &DMat4,
    world_from_render: &DMat4,
    periods: [Period; 3],
    turbulence: Option<&Turbulence>,
) -> Affine3A {
    let mut m = *world_from_pattern_inverse * *world_from_render;
    let turbulence = turbulence_period(turbulence);
    for (axis, period) in periods.into_iter().enumerate() {
        let Period::Every(p) = period.with(turbulence) else { continue };
        let t = m.w_axis[axis];
        // Pattern units per render unit along this axis: the row's absolute sum.
        let per_render = m.row(axis).truncate().abs().element_sum();
        if t.abs() > FAR_PATTERN_ORIGIN * per_render {
            let step = reduction_step(p);
            m.w_axis[axis] = t - (t / step + 0.5).floor() * step;
        }
    }
    Affine3A::from_mat4(m.as_mat4())
}

impl From<&Turbulence> for TurbulenceF32 {
    fn from(t: &Turbulence) -> TurbulenceF32 {
        TurbulenceF32 { amount: t.amount.as_vec3(), octaves: t.octaves, omega: t.omega as f32, lambda: t.lambda as f32 }
    }
}
