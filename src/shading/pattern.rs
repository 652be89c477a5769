//! Pattern functions in pattern space (checker, wood) and colour-map lookup.
//!
//! Pure functions of a point; transforms and turbulence are applied by `pigment` and `normal`.

use glam::Vec3;

use crate::lanes::{Lane, V3};

/// A colour with POV-Ray's filter and transmit channels, in linear light.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgbft {
    pub rgb: Vec3,
    pub filter: f32,
    pub transmit: f32,
}

impl Rgbft {
    pub fn from_desc(c: &crate::desc::Color) -> Rgbft {
        Rgbft { rgb: c.rgb.as_vec3(), filter: c.filter as f32, transmit: c.transmit as f32 }
    }

    #[inline]
    pub fn lerp(self, other: Rgbft, t: f32) -> Rgbft {
        Rgbft {
            rgb: self.rgb.lerp(other.rgb, t),
            filter: self.filter + (other.filter - self.filter) * t,
            transmit: self.transmit + (other.transmit - self.transmit) * t,
        }
    }
}

/// `Rgbft` for one or eight points.
#[derive(Clone, Copy)]
pub struct RgbftLanes<L: Lane> {
    pub rgb: V3<L>,
    pub filter: L,
    pub transmit: L,
}

impl<L: Lane> RgbftLanes<L> {
    #[inline(always)]
    pub fn splat(c: Rgbft) -> Self {
        RgbftLanes { rgb: V3::splat(c.rgb), filter: L::splat(c.filter), transmit: L::splat(c.transmit) }
    }

    #[inline(always)]
    pub fn select(m: L::Mask, a: Self, b: Self) -> Self {
        RgbftLanes {
            rgb: V3::select(m, a.rgb, b.rgb),
            filter: L::select(m, a.filter, b.filter),
            transmit: L::select(m, a.transmit, b.transmit),
        }
    }

    /// As `Rgbft::lerp`.
    #[inline(always)]
    pub fn lerp(self, other: Self, t: L) -> Self {
        let one_minus = L::splat(1.0) - t;
        RgbftLanes {
            rgb: self.rgb.scale(one_minus).add(other.rgb.scale(t)),
            filter: self.filter + (other.filter - self.filter) * t,
            transmit: self.transmit + (other.transmit - self.transmit) * t,
        }
    }

    #[inline(always)]
    pub fn lane(self, i: usize) -> Rgbft {
        Rgbft { rgb: self.rgb.lane(i), filter: self.filter.get(i), transmit: self.transmit.get(i) }
    }

    #[inline(always)]
    pub fn from_lanes(mut f: impl FnMut(usize) -> Rgbft) -> Self {
        let mut c = [Rgbft::default(); 8];
        for (i, c) in c.iter_mut().enumerate().take(L::WIDTH) {
            *c = f(i);
        }
        RgbftLanes {
            rgb: V3::from_lanes(|i| c[i].rgb),
            filter: L::from_fn(|i| c[i].filter),
            transmit: L::from_fn(|i| c[i].transmit),
        }
    }
}

/// How far past an integer a coordinate may fall short and still count as on it.
///
/// POV-Ray 3.7 floors each coordinate plus a tiny tolerance: rendering `plane { y, -d }` with
/// `checker` flips colour between d = 9.5e-11 and 1e-10 (and the same on x), so a plane at y = 0
/// shows the cell [0, 1): (0.5, 0, 0.5) gets the *first* colour. In f32 a hit on y = 0 lands
/// up to a few ulps either side of 0, so we widen the tolerance to 1e-4 (plus 2^-16 relative, for
/// large coordinates); this moves edges by at most that much, which no pixel can see. `slack`
/// widens it further by how far the point itself may be off (see `checker_lanes`).
#[inline(always)]
fn floor_tolerant<L: Lane>(v: L, tolerance: f32, slack: L) -> L {
    (v + L::splat(tolerance) + v.abs() * L::splat(1.0 / 65536.0) + slack).floor()
}

/// The fixed part of `floor_tolerant`'s tolerance, in pattern units.
pub const CHECKER_TOLERANCE: f32 = 1e-4;

/// POV-Ray's `checker`: 0 for the first colour, 1 for the second, alternating in unit cubes.
#[inline]
pub fn checker(p: Vec3) -> u32 {
    checker_lanes(V3::from_vec3(p), 0.0) as u32
}

/// `checker` for one or eight points: set where the second colour shows. `slack` is the error
/// the point may carry in pattern units: an f32 hit point far from the camera is off the surface
/// by a relative 1e-7 of that distance, more than the fixed tolerance once the camera is some
/// thousand units away, and a floor at y = 0 would then show the other colour wherever it
/// lands below 0 (measured: 6.4e-4 units at 8.3e4, where the tolerance is 1e-4).
#[inline(always)]
pub fn checker_lanes<L: Lane>(p: V3<L>, slack: L) -> L::Mask {
    checker_lanes_within(p, [CHECKER_TOLERANCE; 3], slack)
}

/// `checker_lanes` with the fixed tolerance of each axis given (`CHECKER_TOLERANCE` or less):
/// a checker scaled up along an axis (`scale <1, 1, 10000>`, the samples' stripes) needs it
/// that much smaller there, or its edges move by the tolerance times the scale.
#[inline(always)]
pub fn checker_lanes_within<L: Lane>(p: V3<L>, tolerance: [f32; 3], slack: L) -> L::Mask {
    // An integer sum is odd where half of it has a fraction; that holds for negative sums too,
    // and sums beyond 2^25 (whose halves are whole) count as even, as `rem_euclid(2.0)` does.
    let [tx, ty, tz] = tolerance;
    let half = (floor_tolerant(p.x, tx, slack) + floor_tolerant(p.y, ty, slack) + floor_tolerant(p.z, tz, slack))
        * L::splat(0.5);
    half.floor().lt(half)
}

/// POV-Ray's `wood`: concentric rings around the z axis with a triangle wave, 0 on the axis,
/// 1 at radius 0.5, back to 0 at radius 1.
///
/// Verified by rendering `plane { z, 0 pigment { wood color_map {[0 rgb 0][1 rgb 1]} } }`: the
/// sRGB-decoded profile along x is 2r for r < 0.5 and 2 − 2r above (e.g. r = 0.2563 → 0.5126,
/// r = 0.1064 → 0.2128), i.e. a triangle wave, not a sawtooth.
#[inline]
pub fn wood(p: Vec3) -> f32 {
    wood_lanes(V3::from_vec3(p))
}

/// `wood` for one or eight points.
#[inline(always)]
pub fn wood_lanes<L: Lane>(p: V3<L>) -> L {
    let r = (p.x * p.x + p.y * p.y).sqrt();
    let f = r - r.floor();
    L::splat(1.0) - (L::splat(2.0) * f - L::splat(1.0)).abs()
}

/// A `color_map`: entries sorted by value.
#[derive(Clone, Debug, PartialEq)]
pub struct ColorMap {
    entries: Vec<(f32, Rgbft)>,
}

impl ColorMap {
    /// Entries must be sorted by value (the parser guarantees it); an empty map reads black.
    pub fn new(entries: Vec<(f32, Rgbft)>) -> ColorMap {
        ColorMap { entries }
    }

    pub fn entries(&self) -> &[(f32, Rgbft)] {
        &self.entries
    }

    pub fn from_desc(entries: &[crate::desc::ColorMapEntry]) -> ColorMap {
        ColorMap::new(entries.iter().map(|e| (e.value as f32, Rgbft::from_desc(&e.color))).collect())
    }

    /// Linear interpolation between the two entries around `v`, in linear colour (POV-Ray 3.7
    /// blends map entries in the working colour space, linear under `assumed_gamma 1`); clamped
    /// to the first entry below it and the last above it.
    #[inline]
    pub fn lookup(&self, v: f32) -> Rgbft {
        self.lookup_lanes(v).lane(0)
    }

    /// `lookup` for one or eight values: every entry pair is blended and the first pair that
    /// holds `v` selected, so one and eight lanes give the same bits.
    #[inline(always)]
    pub fn lookup_lanes<L: Lane>(&self, v: L) -> RgbftLanes<L> {
        let e = &self.entries;
        let (Some(first), Some(last)) = (e.first(), e.last()) else { return RgbftLanes::splat(Rgbft::default()) };
        let mut out = RgbftLanes::splat(last.1);
        for w in e.windows(2).rev() {
            let ((v0, c0), (v1, c1)) = (w[0], w[1]);
            let span = v1 - v0;
            // Equal values make a hard step: take the upper colour.
            let c = if span > 0.0 {
                RgbftLanes::splat(c0).lerp(RgbftLanes::splat(c1), (v - L::splat(v0)) / L::splat(span))
            } else {
                RgbftLanes::splat(c1)
            };
            out = RgbftLanes::select(v.le(L::splat(v1)), c, out);
        }
        RgbftLanes::select(v.le(L::splat(first.0)), RgbftLanes::splat(first.1), out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checker_on_integer_boundaries() {
        // POV-Ray: plane y = 0 shows cell [0,1) — first colour at (0.5, 0, 0.5).
        assert_eq!(checker(Vec3::new(0.5, 0.0, 0.5)), 0);
        assert_eq!(checker(Vec3::new(0.5, -1e-6, 0.5)), 0, "f32 noise below y = 0");
        assert_eq!(checker(Vec3::new(0.5, 1e-6, 0.5)), 0);
        assert_eq!(checker(Vec3::new(-0.5, 0.0, 0.5)), 1);
        assert_eq!(checker(Vec3::new(1.0, 0.0, 0.5)), 1);
        assert_eq!(checker(Vec3::new(1.5, 0.0, 1.5)), 0);
        assert_eq!(checker(Vec3::new(-0.5, -0.5, -0.5)), 1);
        assert_eq!(checker(Vec3::new(-1.5, 0.0, -1.5)), 0);
        assert_eq!(checker(Vec3::new(0.5, -0.01, 0.5)), 1);
    }

    #[test]
    fn wood_rings_are_radial_triangle_waves() {
        for k in 0..16 {
            let a = k as f32 * 0.4;
            let dir = Vec3::new(a.cos(), a.sin(), 0.0);
            for (r, v) in [(0.0, 0.0), (0.25, 0.5), (0.5, 1.0), (0.75, 0.5), (1.25, 0.5), (3.5, 1.0)] {
                let p = dir * r + Vec3::Z * (k as f32 - 5.0);
                assert!((wood(p) - v).abs() < 1e-5, "r {r}: {}", wood(p));
            }
        }
    }

    #[test]
    fn color_map_interpolates_and_clamps() {
        let c = |r: f32| Rgbft { rgb: Vec3::splat(r), filter: 0.0, transmit: r };
        let m = ColorMap::new(vec![(0.1, c(0.2)), (0.5, c(0.6)), (0.5, c(0.0)), (0.9, c(1.0))]);
        assert_eq!(m.lookup(-1.0), c(0.2));
        assert_eq!(m.lookup(0.1), c(0.2));
        assert!((m.lookup(0.3).rgb.x - 0.4).abs() < 1e-6);
        assert!((m.lookup(0.3).transmit - 0.4).abs() < 1e-6);
        assert!((m.lookup(0.7).rgb.x - 0.5).abs() < 1e-6);
        assert_eq!(m.lookup(0.95), c(1.0));
        assert_eq!(m.lookup(2.0), c(1.0));
        assert_eq!(ColorMap::new(vec![]).lookup(0.5), Rgbft::default());
    }
}
