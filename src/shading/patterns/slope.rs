//! The `slope` pattern (POV-Ray 3.4.7.3.2): a value read from the surface's normal, so only a
//! hit can give it (`Pattern32::surface_value_lanes`); where no surface is (a sky sphere, a
//! normal's own pattern) it is 0, as POV-Ray says it "does not work" there.
//!
//! Measured on POV-Ray 3.7 (a unit sphere under `slope { .. } texture_map { [0 black] [1
//! white] }`, ambient only, 16-bit): the value is 1 − θ/π for the angle θ between the normal
//! and the direction, linear in the angle, not in its cosine (0.9449 where the normal is 10.0°
//! from the direction); the direction is in *world* axes (the texture's `rotate z*90` changes
//! nothing, an object's `scale` changes only its normals); `Lo, Hi` stretch the value and it
//! then wraps as patterns do (1.39 shows as 0.39); `altitude A, Lo, Hi` is a gradient along A
//! in *pattern* space (the texture's translation moves it), averaged with the slope weighted
//! by the two vectors' lengths (`slope { y*3 altitude x, -1, 1 }`: 0.4042 at x = −0.766 where
//! the slope is ½); `point_at P` aims from the hit at P.

use glam::Vec3;

use super::simple::frac;
use crate::desc::Slope;
use crate::lanes::{Lane, V3};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slope32 {
    /// Unit direction, or with `point_at` the point (pattern space).
    direction: Vec3,
    point_at: bool,
    /// `(lo, 1 / (hi − lo))` of the slope.
    range: (f32, f32),
    /// Unit altitude axis and `(lo, 1 / (hi − lo))`, with the weights of slope and altitude.
    altitude: Option<(Vec3, (f32, f32), [f32; 2])>,
}

impl Slope32 {
    pub fn from_desc(s: &Slope) -> Slope32 {
        let range = |r: [f64; 2]| (r[0] as f32, (1.0 / (r[1] - r[0])) as f32);
        let direction = if s.point_at { s.direction } else { s.direction.normalize() };
        let altitude = s.altitude.map(|(a, r)| {
            let (ld, la) = (s.direction.length(), a.length());
            let w = [(ld / (ld + la)) as f32, (la / (ld + la)) as f32];
            (a.normalize().as_vec3(), range(r), w)
        });
        Slope32 { direction: direction.as_vec3(), point_at: s.point_at, range: range(s.range), altitude }
    }

    /// The value at pattern-space point `p` of a surface whose unit outward normal (world
    /// axes) is `n`, before the pattern's frequency and wave.
    #[inline(always)]
    pub fn value_lanes<L: Lane>(&self, p: V3<L>, n: V3<L>) -> L {
        let d = if self.point_at { V3::splat(self.direction).sub(p).normalize() } else { V3::splat(self.direction) };
        let cos = n.dot(d).max(L::splat(-1.0)).min(L::splat(1.0));
        let slope = L::splat(1.0) - cos.map(f32::acos) * L::splat(std::f32::consts::FRAC_1_PI);
        let stretch = |v: L, (lo, inv): (f32, f32)| (v - L::splat(lo)) * L::splat(inv);
        let v = match self.altitude {
            None => stretch(slope, self.range),
            Some((axis, r, [ws, wa])) => {
                let alt = stretch(p.dot(V3::splat(axis)), r);
                stretch(slope, self.range) * L::splat(ws) + alt * L::splat(wa)
            }
        };
        // Wrapped as other patterns are, keeping exactly 1 (a normal along the direction).
        L::select(L::and(v.le(L::splat(1.0)), L::splat(0.0).le(v)), v, frac(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn at(s: &Slope, p: Vec3, n: Vec3) -> f32 {
        Slope32::from_desc(s).value_lanes(V3::from_vec3(p), V3::from_vec3(n.normalize()))
    }

    /// POV-Ray 3.7's values on the unit sphere (orthographic, 201×201, 16-bit; see the module
    /// comment), at the sphere points of pixel centres.
    #[test]
    fn values_match_povray_on_a_sphere() {
        let y = Slope { direction: DVec3::Y, point_at: false, range: [0.0, 1.0], altitude: None };
        let px = |i: f32, j: f32| {
            let (x, y) = ((i + 0.5) / 201.0 * 2.2 - 1.1, 1.1 - (j + 0.5) / 201.0 * 2.2);
            Vec3::new(x, y, -(1.0 - x * x - y * y).sqrt())
        };
        let cases: [(&Slope, (f32, f32), f32); 6] = [
            (&y, (100.0, 10.0), 0.9449),
            (&y, (100.0, 50.0), 0.6843),
            (&y, (100.0, 190.0), 0.0551),
            (&y, (60.0, 60.0), 0.6443),
            (&Slope { range: [0.25, 0.75], ..y }, (100.0, 10.0), 0.3899),
            (&Slope { range: [0.25, 0.75], ..y }, (100.0, 190.0), 0.6101),
        ];
        for (s, (i, j), want) in cases {
            let p = px(i, j);
            let got = at(s, p, p);
            assert!((got - want).abs() < 2e-3, "{s:?} at ({i}, {j}): {got} against POV-Ray's {want}");
        }
        let alt = Slope { direction: DVec3::Y * 3.0, altitude: Some((DVec3::X, [-1.0, 1.0])), ..y };
        let p = px(30.0, 100.0);
        assert!((at(&alt, p, p) - 0.4042).abs() < 2e-3, "{}", at(&alt, p, p));
        // point_at <0, 10, -10> from the sphere's front point.
        let aim = Slope { direction: DVec3::new(0.0, 10.0, -10.0), point_at: true, ..y };
        let p = px(100.0, 100.0);
        assert!((at(&aim, p, p) - 0.7333).abs() < 2e-3, "{}", at(&aim, p, p));
    }
}
