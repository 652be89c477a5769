//! Rays in render space (world space minus the render origin), and robust secondary-ray origins.

use glam::Vec3;

use crate::lanes::{Lane, V3};

#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub origin: Vec3,
    /// Unit length, so `t` is a distance.
    pub dir: Vec3,
    /// `1 / dir`, with ±0 components giving ±inf so slab tests stay branch-free.
    pub inv_dir: Vec3,
}

impl Ray {
    #[inline]
    pub fn new(origin: Vec3, dir: Vec3) -> Ray {
        Ray { origin, dir, inv_dir: dir.recip() }
    }

    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + self.dir * t
    }
}

/// One ray (`f32`, `f64`) or eight (`F8`), as the shape tests take them.
#[derive(Clone, Copy, Debug)]
pub struct RayLanes<L> {
    pub o: V3<L>,
    /// Unit length, so `t` is a distance.
    pub d: V3<L>,
    /// `1 / d`, with ±0 components giving ±inf.
    pub inv: V3<L>,
}

impl<L: Lane> RayLanes<L> {
    #[inline(always)]
    pub fn new(o: V3<L>, d: V3<L>) -> RayLanes<L> {
        RayLanes { o, d, inv: d.recip() }
    }

    #[inline(always)]
    pub fn at(&self, t: L) -> V3<L> {
        self.o.add(self.d.scale(t))
    }
}

impl Ray {
    /// This ray as the shape tests take it.
    #[inline(always)]
    pub fn lanes(&self) -> RayLanes<f32> {
        RayLanes { o: V3::from_vec3(self.origin), d: V3::from_vec3(self.dir), inv: V3::from_vec3(self.inv_dir) }
    }

    /// This ray widened to f64, exactly.
    #[inline(always)]
    pub fn lanes_f64(&self) -> RayLanes<f64> {
        let w = |v: Vec3| V3::from_dvec3(v.as_dvec3());
        RayLanes { o: w(self.origin), d: w(self.dir), inv: w(self.dir).recip() }
    }
}

/// "No hit" distance.
pub const MISS: f32 = f32::INFINITY;

/// Picks the near root if it lies in `(t_min, t_max)`, else the far one, else `MISS`.
#[inline(always)]
pub fn pick_root<L: Lane>(valid: L::Mask, near: L, far: L, t_min: L, t_max: L) -> L {
    let near_ok = L::and(valid, L::and(t_min.lt(near), near.lt(t_max)));
    let far_ok = L::and(valid, L::and(t_min.lt(far), far.lt(t_max)));
    L::select(near_ok, near, L::select(far_ok, far, L::splat(MISS)))
}

/// Relative error bound of a computed hit point, in units of its largest coordinate.
///
/// The intersection routines compute hit points with a handful of f32 operations on values of
/// the point's magnitude, so the error is a small multiple of f32's epsilon times that magnitude.
/// 32 ulps covers the worst routine (the oriented box: two affine transforms) with room to spare,
/// while staying invisible: at |p| = 10 the offset is 2e-5.
pub(crate) const HIT_ERROR_ULPS: f32 = 32.0 * f32::EPSILON;
/// Shadow rays stop this fraction of their length short of the light (see `shadow_t_max`).
pub(crate) const SHADOW_SHRINK: f32 = 1.0 - 4.0 * f32::EPSILON;

/// The largest absolute coordinate. Plain comparisons: `f32::max` handles NaN with extra
/// compare-and-blend instructions, which made this 4% of the seed scene's frame.
#[inline]
fn max_abs(v: Vec3) -> f32 {
    let (x, y, z) = (v.x.abs(), v.y.abs(), v.z.abs());
    let m = if x > y { x } else { y };
    if m > z {
        m
    } else {
        z
    }
}

/// Moves a hit point off its surface to the side `dir` leaves towards, by an amount that scales
/// with the point's magnitude, so a secondary ray never re-hits the surface it starts on
/// (chapter 24.5, last paragraph) at any scene scale.
#[inline]
pub fn offset_origin(p: Vec3, n: Vec3, dir: Vec3) -> Vec3 {
    let magnitude = max_abs(p);
    // The tiny floor keeps points at the render origin movable.
    let d = magnitude * HIT_ERROR_ULPS + f32::MIN_POSITIVE * 16.0;
    let offset = if n.dot(dir) >= 0.0 { n * d } else { -n * d };
    p + offset
}

/// How far a shadow ray from `origin` may look for blockers before `light`: short of the light by
/// the error bound of a hit point at these magnitudes, so a surface the light lies on (whose
/// computed hit lands a few ulps of the coordinates either side of the light) never blocks it.
/// A relative shrink of the distance alone is not enough: for a shallow ray the plane's `t`
/// carries the rounding of coordinates much larger than the distance to the light.
#[inline]
pub fn shadow_t_max(origin: Vec3, light: Vec3) -> f32 {
    let (a, b) = (max_abs(origin), max_abs(light));
    let magnitude = if a > b { a } else { b };
    let dist = (light - origin).length();
    let t = dist * SHADOW_SHRINK - magnitude * HIT_ERROR_ULPS;
    if t > 0.0 {
        t
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_moves_to_the_leaving_side_at_every_scale() {
        for scale in [1e-4f32, 1.0, 1e5, 1e6] {
            let p = Vec3::new(scale, 0.5 * scale, 0.0);
            let n = Vec3::Y;
            let up = offset_origin(p, n, Vec3::new(0.3, 1.0, 0.0).normalize());
            let down = offset_origin(p, n, Vec3::new(0.3, -1.0, 0.0).normalize());
            assert!(up.y > p.y && down.y < p.y, "scale {scale}");
        }
    }

    #[test]
    fn zero_direction_components_give_signed_infinities() {
        let r = Ray::new(Vec3::ZERO, Vec3::new(0.0, -0.0, 1.0));
        assert_eq!(r.inv_dir.x, f32::INFINITY);
        assert_eq!(r.inv_dir.y, f32::NEG_INFINITY);
    }
}
