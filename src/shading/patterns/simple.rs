//! Geometric patterns: pure functions of a pattern-space point, exact (no noise).

use glam::Vec3;

use crate::lanes::{Lane, V3};
use crate::shading::pattern::checker_lanes;

/// `x − floor(x)`.
#[inline(always)]
pub fn frac<L: Lane>(x: L) -> L {
    x - x.floor()
}

/// `max(0, 1 − x)`.
#[inline(always)]
fn fall<L: Lane>(x: L) -> L {
    (L::splat(1.0) - x).max(L::splat(0.0))
}

/// `gradient V` (V unit length): the fraction of the distance along V.
#[inline(always)]
pub fn gradient<L: Lane>(p: V3<L>, dir: Vec3) -> L {
    frac(p.dot(V3::splat(dir)))
}

/// `onion`: concentric spheres of unit spacing.
#[inline(always)]
pub fn onion<L: Lane>(p: V3<L>) -> L {
    frac(p.dot(p).sqrt())
}

/// `radial`: the angle around y, 0 on +x, falling through +z (POV-Ray 3.7 measured: 0.75 on +z,
/// 0.25 on −z).
#[inline(always)]
pub fn radial<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| {
        let a = (-p.z.get(i)).atan2(p.x.get(i)) * (0.5 / std::f32::consts::PI);
        a - a.floor()
    })
}

#[inline(always)]
pub fn spherical<L: Lane>(p: V3<L>) -> L {
    fall(p.dot(p).sqrt())
}

#[inline(always)]
pub fn cylindrical<L: Lane>(p: V3<L>) -> L {
    fall((p.x * p.x + p.z * p.z).sqrt())
}

#[inline(always)]
pub fn planar<L: Lane>(p: V3<L>) -> L {
    fall(p.y.abs())
}

#[inline(always)]
pub fn boxed<L: Lane>(p: V3<L>) -> L {
    fall(p.x.abs().max(p.y.abs()).max(p.z.abs()))
}

/// `leopard`: `((sin x + sin y + sin z) / 3)²`.
#[inline(always)]
pub fn leopard<L: Lane>(p: V3<L>) -> L {
    let s = (p.x.map(f32::sin) + p.y.map(f32::sin) + p.z.map(f32::sin)) * L::splat(1.0 / 3.0);
    s * s
}

/// `spiral1 N`: N arms winding around z, one turn per unit along z. The angle counts from
/// the −y axis: on z = 0 POV-Ray 3.7's value is `frac(r + N·(θ/2π + 1/4))` with θ from +x,
/// to 3e-5 over a 64×64 render of each of `spiral1 1` and `spiral1 3`.
#[inline(always)]
pub fn spiral1<L: Lane>(p: V3<L>, arms: f32) -> L {
    L::from_fn(|i| {
        let (x, y, z) = (p.x.get(i), p.y.get(i), p.z.get(i));
        let turn = y.atan2(x) * (0.5 / std::f32::consts::PI) + 0.25;
        let v = z + (x * x + y * y).sqrt() + arms * turn;
        v - v.floor()
    })
}

/// `spiral2 N` (3.4.7.1.26), before its wave: `frac(tri(z + r + N·(θ/2π + 1/4)) + tri(r))` with
/// `tri(u) = 1 − |2·frac(u) − 1|` and θ from +x, as for `spiral1`. Fitted to POV-Ray 3.7's own
/// values (`function { pattern { spiral2 N ramp_wave } }` at 60 random points in [−2, 2]³ for
/// N = 1, 2, 3: within 1e-5, which is POV-Ray wrapping at 1.00001 instead of 1) and checked on
/// 48×48 16-bit renders of planes at z = 0 and 0.37 for N = 1, 2, 3, 5 with the default
/// triangle wave, ramp and sine (the 16-bit steps, 3e-5). The second term depends on r alone:
/// on a line along z the value is a triangle wave of z lifted by `tri(r)` and wrapped.
/// POV-Ray gives 0 on the z axis itself; this gives the limit of the arms there.
#[inline(always)]
pub fn spiral2<L: Lane>(p: V3<L>, arms: f32) -> L {
    let tri = |u: f32| 1.0 - (2.0 * (u - u.floor()) - 1.0).abs();
    L::from_fn(|i| {
        let (x, y, z) = (p.x.get(i), p.y.get(i), p.z.get(i));
        let turn = y.atan2(x) * (0.5 / std::f32::consts::PI) + 0.25;
        let r = (x * x + y * y).sqrt();
        let v = tri(z + r + arms * turn) + tri(r);
        v - v.floor()
    })
}

/// `checker` as a value: 0 or 1.
#[inline(always)]
pub fn checker<L: Lane>(p: V3<L>) -> L {
    L::select(checker_lanes(p, L::splat(0.0)), L::splat(1.0), L::splat(0.0))
}

/// `brick`: 0 in the mortar, 1 in a brick. Courses of `size.y` along y; the joints across x
/// are shifted by half a brick in odd courses and those across z in even ones, so the joints
/// of neighbouring courses never line up on either face; the mortar (`mortar` wide) runs along
/// the upper faces of every brick, from `size − mortar` up. Measured with POV-Ray 3.7's
/// `function { pattern { brick } }` in courses −2 to 1, to 0.02 units and at the boundaries.
#[inline(always)]
pub fn brick<L: Lane>(p: V3<L>, size: Vec3, mortar: f32) -> L {
    L::from_fn(|i| {
        let q = p.lane(i);
        // Every coordinate is nudged by 1e-4 of the brick along it: a face lying on a joint's
        // plane (a wall box from z = 0) is hit within f32 rounding of it, on either side, where
        // POV-Ray's double hits land on the plane and show the brick, not speckles of mortar.
        let q = q + size * 1e-4;
        let course = (q.y / size.y).floor();
        let odd = course.rem_euclid(2.0) != 0.0;
        let (mut x, y, mut z) = (q.x, q.y - course * size.y, q.z);
        if odd {
            x += size.x * 0.5;
        } else {
            z += size.z * 0.5;
        }
        let fx = x.rem_euclid(size.x);
        let fz = z.rem_euclid(size.z);
        let m = mortar;
        let in_mortar = y >= size.y - m || fx >= size.x - m || fz >= size.z - m;
        if in_mortar {
            0.0
        } else {
            1.0
        }
    })
}

/// `hexagon`: a tiling of the x-z plane by hexagons of unit side (√3 across the flats), coloured
/// 0, 1, 2 so that no two neighbours match; a hexagon is centred on the origin with colour 0,
/// the one across its +z flat has colour 1 and the one beyond its +x, +z side colour 2 (POV-Ray
/// 3.7's `function { pattern { hexagon } }`, measured on a 65×33 grid over [−2, 2]²).
#[inline(always)]
pub fn hexagon<L: Lane>(p: V3<L>) -> L {
    L::from_fn(|i| hexagon_one(p.x.get(i), p.z.get(i)))
}

fn hexagon_one(x: f32, z: f32) -> f32 {
    // Axial coordinates of the nearest hexagon centre (pointy sides on ±x).
    let size = 1.0; // centre to corner (POV-Ray 3.7: about √3 between rows of centres)
    let q = (2.0 / 3.0 * x) / size;
    let r = (-1.0 / 3.0 * x + 3f32.sqrt() / 3.0 * z) / size;
    let s = -q - r;
    let (mut rq, mut rr, rs) = (q.round(), r.round(), s.round());
    let (dq, dr, ds) = ((rq - q).abs(), (rr - r).abs(), (rs - s).abs());
    if dq > dr && dq > ds {
        rq = -rr - rs;
    } else if dr > ds {
        rr = -rq - rs;
    }
    (rr - rq).rem_euclid(3.0)
}

/// `quilted` (3.4.7.1.21) as a pigment pattern: unit cubes between integer planes, 0 at each
/// cube's centre and rising towards its faces. With `v = frac(p) − ½` and `t = |v|`, the value
/// is `(|vx| + |vy| + |vz|) · |q(t)| / (1.5·√3)` where `q` is the cubic the documentation
/// draws (and `scenes/animations/quilted/plotqlt.pov` plots) through 0, c0, c1, 1:
/// `q(t) = t³ + 3t(1 − t)²·c0 + 3t²(1 − t)·c1`. Fitted to POV-Ray 3.7's own values
/// (`function { pattern { quilted ... } }` at 40 random points in [−3, 3]³ for controls
/// (1, 1), (0, 0), (0.5, 0.5), (0.3, 0.8), (−1, 2), (5, 5), (3, −4): within 4e-9) and checked
/// on 32×32 16-bit renders of planes at z = 0 and 0.3 (the 16-bit steps, 8e-6). Not clamped:
/// controls above about 3 give values over 1 at the corners (1.38 for 5, 5), which POV-Ray's
/// colour map clamps as strahl's does.
#[inline(always)]
pub fn quilted<L: Lane>(p: V3<L>, c0: f32, c1: f32) -> L {
    L::from_fn(|i| {
        let w = quilt_vector(p.lane(i), c0, c1);
        // The mean of |w| over the axes: (2/√3)/3 = 1/(1.5·√3), the scale measured on the
        // pigment (2/(3·√3) to the 8 digits POV-Ray printed).
        (w.x.abs() + w.y.abs() + w.z.abs()) * (1.0 / 3.0)
    })
}

/// `quilted` as a normal (3.4.7.1.21): POV-Ray 3.7 adds `amount · w` to the normal facing the
/// ray, `w = (2/√3)·q(t)·v` in pattern space (v, t and q as for the pigment, whose value is the
/// mean of |w| over the axes). Measured on planes facing −z at z = 0.05, 0.3 and 0.5 with
/// `quilted 0.05`, `0.5` and `1`, lit by parallel lights straight on and 30° off in ±x and
/// ±y: the slopes n_x/n_z and n_y/n_z are those of `n + amount·w` to 1e-3 (v_z = 0 shows
/// the 2/√3: 1.155 × v·q(t), whatever the amount; v_z ≠ 0 shows w_z in the denominator).
#[inline(always)]
pub fn quilted_normal<L: Lane>(p: V3<L>, c0: f32, c1: f32) -> V3<L> {
    V3::from_lanes(|i| quilt_vector(p.lane(i), c0, c1))
}

/// `(2/√3)·q(|v|)·v`, v the offset from the unit cube's centre: see `quilted`.
#[inline(always)]
fn quilt_vector(p: Vec3, c0: f32, c1: f32) -> Vec3 {
    let v = p - p.floor() - Vec3::splat(0.5);
    let t = v.length();
    let s = 1.0 - t;
    let cubic = t * t * t + 3.0 * t * s * s * c0 + 3.0 * t * t * s * c1;
    v * (cubic * 1.154_701) // 2/√3
}

/// Raw wood rings: `frac(r)` around z (the triangle wave makes POV-Ray's `wood`).
#[inline(always)]
pub fn wood_rings<L: Lane>(p: V3<L>) -> L {
    frac((p.x * p.x + p.y * p.y).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(f: impl Fn(V3<f32>) -> f32, p: [f32; 3]) -> f32 {
        f(V3::from_vec3(Vec3::from(p)))
    }

    #[test]
    fn exact_values() {
        let g = |p| one(|q| gradient(q, Vec3::X), p);
        assert!((g([0.25, 7.0, 1.0]) - 0.25).abs() < 1e-6);
        assert!((g([-0.25, 0.0, 0.0]) - 0.75).abs() < 1e-6);
        assert!((one(onion, [0.0, 1.3, 0.0]) - 0.3).abs() < 1e-6);
        assert!((one(radial, [0.0, 0.0, 1.0]) - 0.75).abs() < 1e-6);
        assert!((one(radial, [0.0, 0.0, -1.0]) - 0.25).abs() < 1e-6);
        assert!((one(radial, [-1.0, 0.0, 0.0]) - 0.5).abs() < 1e-6);
        assert!((one(spherical, [0.0, 0.5, 0.0]) - 0.5).abs() < 1e-6);
        assert_eq!(one(boxed, [0.0, 2.0, 0.0]), 0.0);
        assert!((one(boxed, [0.25, -0.5, 0.1]) - 0.5).abs() < 1e-6);
        assert!((one(planar, [3.0, 0.25, 3.0]) - 0.75).abs() < 1e-6);
        assert!((one(cylindrical, [0.6, 9.0, 0.0]) - 0.4).abs() < 1e-6);
        assert!((one(leopard, [-std::f32::consts::FRAC_PI_2, 0.0, 0.0]) - 1.0 / 9.0).abs() < 1e-6);
    }

    /// POV-Ray 3.7's values (to 6 digits), printed by `#debug` from `function { pattern {
    /// quilted control0 C0 control1 C1 } }`: offsets of 0.095, 0.238, 0.4 and 0.476 along x
    /// from a cube's centre (½, ½, ½), a corner, a point two cells off and one below zero.
    #[test]
    fn quilted_matches_povray() {
        let pts = [
            [0.595, 0.5, 0.5],
            [0.738, 0.5, 0.5],
            [0.1, 0.5, 0.5],
            [0.024, 0.5, 0.5],
            [0.0, 0.0, 0.0],
            [0.3, 0.8, 0.5],
            [-1.3, 2.15, 0.7],
            [0.05, -0.2, 3.1],
        ];
        let cases: [((f32, f32), [f32; 8]); 6] = [
            ((1.0, 1.0), [0.00946251, 0.051075, 0.120705, 0.156852, 0.575962, 0.142132, 0.240647, 0.427113]),
            ((0.0, 0.0), [3.135e-05, 0.00123497, 0.00985345, 0.0197595, 0.375, 0.00902055, 0.0263055, 0.134733]),
            ((0.5, 0.5), [0.00474693, 0.026155, 0.0652791, 0.0883059, 0.475481, 0.0755761, 0.133476, 0.280923]),
            ((-1.0, 2.0), [0.00671193, 0.0130193, 0.0320237, 0.0784352, 0.696152, 0.0198911, 0.101325, 0.432388]),
            ((0.0, 1.0), [0.000927311, 0.0130969, 0.0541939, 0.0850157, 0.549038, 0.0570144, 0.122759, 0.331411]),
            ((5.0, 5.0), [0.0471872, 0.250435, 0.56411, 0.705223, 1.37981, 0.674576, 1.09801, 1.59663]),
        ];
        for ((c0, c1), want) in cases {
            for (p, w) in pts.iter().zip(want) {
                let got = one(|q| quilted(q, c0, c1), *p);
                assert!((got - w).abs() < 1e-4, "quilted {c0} {c1} at {p:?}: {got}, POV-Ray {w}");
            }
        }
        assert_eq!(one(|q| quilted(q, 1.0, 1.0), [3.5, -0.5, 0.5]), 0.0, "0 at every cube's centre");
    }

    /// POV-Ray 3.7's values (to 6 digits) of `function { pattern { spiral2 N ramp_wave } }`,
    /// printed by `#debug`, on the plane z = 0 and off it.
    #[test]
    fn spiral2_matches_povray() {
        let pts = [[0.3, 0.4, 0.0], [-0.7, 0.2, 0.1], [1.2, -0.9, 0.45], [-0.3, -1.6, -0.8], [0.05, 1.9, 1.3]];
        let cases: [(f32, [f32; 5]); 3] = [
            (1.0, [0.204823, 0.476532, 0.195157, 0.14746, 0.805744]),
            (2.0, [0.590324, 0.0228189, 0.490324, 0.206458, 0.583251]),
            (3.0, [0.614488, 0.653713, 0.785492, 0.265456, 0.822493]),
        ];
        for (n, want) in cases {
            for (p, w) in pts.iter().zip(want) {
                let got = one(|q| spiral2(q, n), *p);
                // POV-Ray wraps at 1.00001, not 1: 1e-5 apart where the sum passed 1.
                assert!((got - w).abs() < 1e-4, "spiral2 {n} at {p:?}: {got}, POV-Ray {w}");
            }
        }
    }

    #[test]
    fn brick_mortar_and_courses() {
        // POV-Ray 3.7's values, read with `function { pattern { brick brick_size <1, 0.5, 1>
        // mortar 0.1 } }`.
        let b = |p| one(|q| brick(q, Vec3::new(1.0, 0.5, 1.0), 0.1), p);
        assert_eq!(b([0.2, 0.25, 0.2]), 1.0);
        assert_eq!(b([0.9, 0.25, 0.2]), 0.0, "the vertical joint starts at size − mortar");
        assert_eq!(b([0.99, 0.25, 0.2]), 0.0);
        assert_eq!(b([1.0, 0.25, 0.2]), 1.0, "and ends at the next brick");
        assert_eq!(b([0.2, 0.45, 0.2]), 0.0, "bed joint");
        assert_eq!(b([0.2, 0.5, 0.2]), 1.0);
        // Even courses shift the joints across z by half a brick, odd ones those across x.
        assert_eq!(b([0.2, 0.25, 0.45]), 0.0);
        assert_eq!(b([0.2, 0.25, 0.95]), 1.0);
        assert_eq!(b([0.45, 0.75, 0.2]), 0.0);
        assert_eq!(b([0.95, 0.75, 0.2]), 1.0);
        assert_eq!(b([0.2, 0.75, 0.95]), 0.0);
        // A face on a joint's plane, hit a rounding error short of it, shows the brick.
        assert_eq!(b([0.2, 0.75, -1e-6]), 1.0);
        assert_eq!(b([1.0 - 1e-6, 0.25, 0.2]), 1.0);
        // The price: the mortar starts 1e-4 of a brick early (POV-Ray: brick at 0.9 − 1e-6).
        assert_eq!(b([0.9 - 1e-6, 0.25, 0.2]), 0.0);
        assert_eq!(b([0.9 - 2e-4, 0.25, 0.2]), 1.0);
        // Negative courses alternate the same way: −1 is odd, −2 even.
        assert_eq!(b([0.45, -0.25, 0.2]), 0.0);
        assert_eq!(b([0.2, -0.25, 0.95]), 0.0);
        assert_eq!(b([0.95, -0.75, 0.2]), 0.0);
        assert_eq!(b([0.2, -0.75, 0.45]), 0.0);
        assert_eq!(b([0.2, -0.75, 0.95]), 1.0);
    }

    #[test]
    fn hexagon_neighbours_differ() {
        let h = |x, z| hexagon_one(x, z);
        assert_eq!(h(0.0, 0.0), 0.0);
        // POV-Ray 3.7's colours around the origin's hexagon.
        assert_eq!(h(0.0, 1.75), 1.0);
        assert_eq!(h(0.0, -1.75), 2.0);
        assert_eq!(h(1.5, 0.87), 2.0);
        assert_eq!(h(-1.5, 0.87), 2.0);
        assert_eq!(h(1.5, -0.87), 1.0);
        assert_eq!(h(-1.5, -0.87), 1.0);
        assert_eq!(h(0.9, 0.0), 0.0);
        assert_eq!(h(1.1, 0.05), 2.0);
        let c = h(0.0, 0.0);
        // The six neighbours √3 away (across the flats) all differ from the centre.
        for k in 0..6 {
            let a = (k as f32 * 60.0 + 30.0).to_radians();
            assert_ne!(h(a.cos() * 3f32.sqrt(), a.sin() * 3f32.sqrt()), c, "neighbour {k}");
        }
        for x in -20..20 {
            for z in -20..20 {
                let v = h(x as f32 * 0.37, z as f32 * 0.41);
                assert!(v == 0.0 || v == 1.0 || v == 2.0);
            }
        }
    }
}
