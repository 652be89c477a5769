//! Pattern functions in pattern space (checker, wood) and colour-map lookup.
//!
//! Pure functions of a point; transforms and turbulence are applied by `pigment` and `normal`.

use glam::Vec3;

/// A colour with POV-Ray's filter and transmit channels, in linear light.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Rgbft {
    pub rgb: Vec3,
    pub filter: f32,
    pub transmit: f32,
}

impl Rgbft {
    pub fn from_desc(c: &crate::scene::desc::Color) -> Rgbft {
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

/// How far past an integer a coordinate may fall short and still count as on it.
///
/// POV-Ray 3.7 floors each coordinate plus a tiny tolerance: rendering `plane { y, -d }` with
/// `checker` flips colour between d = 9.5e-11 and 1e-10 (and the same on x), so a plane at y = 0
/// shows the cell [0, 1): (0.5, 0, 0.5) gets the *first* colour. In f32 a hit on y = 0 lands
/// up to a few ulps either side of 0, so we widen the tolerance to 1e-4 (plus 2^-16 relative, for
/// large coordinates); this moves edges by at most that much, which no pixel can see.
#[inline]
fn floor_tolerant(v: f32) -> f32 {
    (v + 1e-4 + v.abs() * (1.0 / 65536.0)).floor()
}

/// POV-Ray's `checker`: 0 for the first colour, 1 for the second, alternating in unit cubes.
#[inline]
pub fn checker(p: Vec3) -> u32 {
    let s = floor_tolerant(p.x) + floor_tolerant(p.y) + floor_tolerant(p.z);
    // `rem_euclid` keeps negative sums in {0, 1}.
    (s.rem_euclid(2.0)) as u32
}

/// POV-Ray's `wood`: concentric rings around the z axis with a triangle wave, 0 on the axis,
/// 1 at radius 0.5, back to 0 at radius 1.
///
/// Verified by rendering `plane { z, 0 pigment { wood color_map {[0 rgb 0][1 rgb 1]} } }`: the
/// sRGB-decoded profile along x is 2r for r < 0.5 and 2 − 2r above (e.g. r = 0.2563 → 0.5126,
/// r = 0.1064 → 0.2128), i.e. a triangle wave, not a sawtooth.
#[inline]
pub fn wood(p: Vec3) -> f32 {
    let r = (p.x * p.x + p.y * p.y).sqrt();
    let f = r - r.floor();
    1.0 - (2.0 * f - 1.0).abs()
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

    pub fn from_desc(entries: &[crate::scene::desc::ColorMapEntry]) -> ColorMap {
        ColorMap::new(entries.iter().map(|e| (e.value as f32, Rgbft::from_desc(&e.color))).collect())
    }

    /// Linear interpolation between the two entries around `v`, in linear colour (POV-Ray 3.7
    /// blends map entries in the working colour space, linear under `assumed_gamma 1`); clamped
    /// to the first entry below it and the last above it. Maps are a handful of entries, so a
    /// linear scan beats a binary search.
    #[inline]
    pub fn lookup(&self, v: f32) -> Rgbft {
        let e = &self.entries;
        let Some(first) = e.first() else { return Rgbft::default() };
        if v <= first.0 {
            return first.1;
        }
        for w in e.windows(2) {
            let ((v0, c0), (v1, c1)) = (w[0], w[1]);
            if v <= v1 {
                let span = v1 - v0;
                // Equal values make a hard step: take the upper colour.
                return if span > 0.0 { c0.lerp(c1, (v - v0) / span) } else { c1 };
            }
        }
        e[e.len() - 1].1
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
