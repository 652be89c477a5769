//! A quadric's ray test (`Poly` of order 2): its terms as a symmetric matrix, so that the
//! quadratic along a ray takes a few products, solved in closed form for all lanes at once in
//! f64 (`wide::W`): a quadric costs about what a sphere costs, where the general polynomial
//! path (expansion, trimming, the closed form's polish, one lane at a time) cost it 3.5x a
//! sphere's frame on scenes/kernels/quadric.pov.
//!
//! The ray is first moved to its point nearest the object origin and its direction made unit,
//! as for every polynomial surface (`super::centred_ray`), so that a quadric seen from far away
//! keeps its digits.

use super::wide::{and, not, Mask, WideSolve, W, WV};

/// A quadric's terms as `f(q) = q·A·q + g·q + k`, `A` symmetric.
#[derive(Clone, Copy, Debug)]
pub(super) struct QuadricForm {
    a: [[f64; 3]; 3],
    g: [f64; 3],
    k: f64,
}

/// A leading coefficient below this part of the largest is rounding noise (a ray along the axis
/// of a paraboloid makes the s² term cancel to ~1e-17 of the others): the quadratic is then a
/// line, or nothing.
const NOISE: f64 = 1e-14;

impl QuadricForm {
    /// The form of order-2 `terms` (coefficient and exponents of x, y, z).
    pub(super) fn of(terms: &[(f64, [u8; 3])]) -> QuadricForm {
        let mut q = QuadricForm { a: [[0.0; 3]; 3], g: [0.0; 3], k: 0.0 };
        for &(c, e) in terms {
            let axes: Vec<usize> = (0..3).flat_map(|axis| std::iter::repeat_n(axis, e[axis] as usize)).collect();
            match axes[..] {
                [] => q.k += c,
                [i] => q.g[i] += c,
                [i, j] if i == j => q.a[i][i] += c,
                [i, j] => {
                    q.a[i][j] += 0.5 * c;
                    q.a[j][i] += 0.5 * c;
                }
                _ => unreachable!("a quadric's terms are of order 2 at most"),
            }
        }
        q
    }

    /// `A·v` lane by lane.
    #[inline(always)]
    fn times<const N: usize>(&self, v: WV<N>) -> WV<N> {
        let row = |r: [f64; 3]| v.x * W::splat(r[0]) + v.y * W::splat(r[1]) + v.z * W::splat(r[2]);
        WV { x: row(self.a[0]), y: row(self.a[1]), z: row(self.a[2]) }
    }

    #[inline(always)]
    fn linear<const N: usize>(&self, v: WV<N>) -> W<N> {
        v.x * W::splat(self.g[0]) + v.y * W::splat(self.g[1]) + v.z * W::splat(self.g[2])
    }

    /// The nearest hit of `o + t·d` (object space) in `(t_min, t_max)` per lane, `+inf` where
    /// there is none: the first root `t` that `round` (the lane's rounding, `Lane::round_f64`)
    /// puts above `t_min`, so that a CSG search from a crossing is not handed it again, as
    /// `super::hit_lanes_f64` answers; the answer is `round(t)`, at most `t_max`.
    #[inline(always)]
    pub(super) fn hit<const N: usize>(
        &self,
        o: WV<N>,
        d: WV<N>,
        t_min: W<N>,
        t_max: W<N>,
        round: impl Fn(f64) -> f64 + Copy,
    ) -> W<N> {
        let (zero, one) = (W::splat(0.0), W::splat(1.0));
        // The ray about its point `p` nearest the origin, with unit direction `u`: distance `s`
        // along it is at `t = t_c + s / len`.
        let len2 = d.dot(d);
        let t_c = -o.dot(d) / len2;
        let p = o.add(d.scale(t_c));
        let len = len2.sqrt();
        let inv_len = one / len;
        let u = d.scale(inv_len);
        let (au, ap) = (self.times(u), self.times(p));
        let c2 = u.dot(au);
        let c1 = W::splat(2.0) * p.dot(au) + self.linear(u);
        let c0 = p.dot(ap) + self.linear(p) + W::splat(self.k);
        let scale = c0.abs().max(c1.abs()).max(c2.abs());
        let floor = W::splat(NOISE) * scale;
        let quadratic = floor.lt(c2.abs());
        let line = and(floor.lt(c1.abs()), not(quadratic));
        // The stable roots q/c2 and c0/q (no cancellation between −c1 and the square root);
        // q = 0 only for a double root at s = 0.
        let disc = c1 * c1 - W::splat(4.0) * c2 * c0;
        let q = W::splat(-0.5) * (c1 + disc.max(zero).sqrt().copysign(c1));
        let q_zero = and(q.le(zero), zero.le(q));
        let safe_q = W::select(q_zero, one, q);
        let r0 = W::select(q_zero, zero, q / c2);
        let r1 = W::select(q_zero, zero, c0 / safe_q);
        let flat = -c0 / c1;
        let near = W::select(line, flat, r0.min(r1));
        let far = W::select(line, flat, r0.max(r1));
        let mut real: Mask<N> = [false; N];
        for i in 0..N {
            real[i] = line[i] | (quadratic[i] & (disc.0[i] >= 0.0));
        }
        let (near_ok, near_t) = pick(real, t_c + near * inv_len, t_min, t_max, round);
        let (far_ok, far_t) = pick(real, t_c + far * inv_len, t_min, t_max, round);
        W::select(near_ok, near_t, W::select(far_ok, far_t, W::splat(f64::INFINITY)))
    }

    /// The polynomial at `q`.
    #[inline(always)]
    pub(super) fn eval(&self, q: [f64; 3]) -> f64 {
        let v = WV { x: W([q[0]]), y: W([q[1]]), z: W([q[2]]) };
        (v.dot(self.times(v)) + self.linear(v)).0[0] + self.k
    }

    /// The polynomial's gradient at `q`, lane by lane: `2·A·q + g`. The same operations on one
    /// lane or eight, so a packet's normals are a single ray's bit for bit.
    #[inline(always)]
    pub(super) fn gradient<const N: usize>(&self, q: WV<N>) -> WV<N> {
        let a = self.times(q);
        let two = W::splat(2.0);
        WV {
            x: two * a.x + W::splat(self.g[0]),
            y: two * a.y + W::splat(self.g[1]),
            z: two * a.z + W::splat(self.g[2]),
        }
    }
}

/// Root `t` of `real` lanes, rounded by `round`, where it lies in `(t_min, t_max)`: which lanes,
/// and `round(t)` capped at `t_max`. A function, not a closure: called twice, the closure was
/// compiled out of line, without AVX2 (3 % of the quadric scene's frame).
#[inline(always)]
fn pick<const N: usize>(
    real: Mask<N>,
    t: W<N>,
    t_min: W<N>,
    t_max: W<N>,
    round: impl Fn(f64) -> f64 + Copy,
) -> (Mask<N>, W<N>) {
    let mut r = t;
    let mut ok = real;
    for i in 0..N {
        r.0[i] = round(t.0[i]);
        ok[i] &= (r.0[i] > t_min.0[i]) & (t.0[i] < t_max.0[i]);
    }
    (ok, r.min(t_max))
}

impl WideSolve for QuadricForm {
    #[inline(always)]
    fn solve<const N: usize>(
        &self,
        o: WV<N>,
        d: WV<N>,
        t_min: W<N>,
        t_max: W<N>,
        round: impl Fn(f64) -> f64 + Copy,
    ) -> W<N> {
        self.hit(o, d, t_min, t_max, round)
    }
}

#[cfg(test)]
mod tests {
    use glam::{Affine3A, Vec3};

    use super::*;
    use crate::geometry::poly::Poly;
    use crate::geometry::roots::Solver;
    use crate::geometry::test_support::uniform;
    use crate::geometry::Shape;
    use crate::lanes::{Lane, F8, V3};
    use crate::ray::{Ray, RayLanes, MISS};

    /// POV-Ray's order-2 coefficients (x², xy, xz, x, y², yz, y, z², z, 1) of quadrics of every
    /// kind, at `s` times their unit size: a tilted ellipsoid, a cylinder, a cone, a paraboloid,
    /// hyperboloids of one and two sheets, two crossing planes, a plane.
    fn quadrics(s: f64) -> Vec<[f64; 10]> {
        let (i1, i2) = (1.0 / s, 1.0 / (s * s));
        vec![
            [i2, i2, 0.0, 0.0, 2.5 * i2, 0.0, 0.0, i2, 0.0, -0.16],
            [i2, 0.0, 0.0, 0.0, i2, 0.0, 0.0, 0.0, 0.0, -1.0],
            [i2, 0.0, 0.0, 0.0, i2, 0.0, 0.0, -i2, 0.0, 0.0],
            [i2, 0.0, 0.0, 0.0, i2, 0.0, 0.0, 0.0, -i1, 0.0],
            [i2, 0.0, 0.0, 0.0, -i2, 0.0, 0.0, i2, 0.0, -1.0],
            [-i2, 0.0, 0.0, 0.0, -i2, 0.0, 0.0, i2, 0.0, -1.0],
            [0.0, i2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, i1, 0.0, 0.0, 0.5 * i1, 0.0, 0.0, -0.2],
        ]
    }

    /// Seeded rays at scale `s`: from near and far, aimed at points about the origin, some along
    /// the axes (a paraboloid's or cylinder's axis), some starting on a surface point's tangent.
    fn rays(seed: u64, s: f64, count: usize) -> Vec<([f64; 3], [f64; 3])> {
        let mut r = uniform(seed);
        let mut unit = move || loop {
            let v = [2.0 * r() - 1.0, 2.0 * r() - 1.0, 2.0 * r() - 1.0];
            let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if l > 0.1 && l <= 1.0 {
                return [v[0] / l, v[1] / l, v[2] / l];
            }
        };
        (0..count)
            .map(|k| {
                let dist = [3.0, 50.0, 1e4][k % 3] * s;
                let (v, w) = (unit(), unit());
                let target = [w[0] * 1.5 * s, w[1] * 1.5 * s, w[2] * 1.5 * s];
                let o = [target[0] + dist * v[0], target[1] + dist * v[1], target[2] + dist * v[2]];
                let d = if k % 7 == 0 { [0.0, 0.0, -1.0] } else { [-v[0], -v[1], -v[2]] };
                (o, d)
            })
            .collect()
    }

    fn wv(v: [f64; 3]) -> WV<1> {
        WV { x: W([v[0]]), y: W([v[1]]), z: W([v[2]]) }
    }

    /// Against the general path (expansion along the ray, trimming, the closed form with its
    /// Newton polish, `roots::smallest_root_by`) on seeded random rays at every scale: the
    /// same hits to 1e-9 of the distance, except where a ray grazes the surface (the two
    /// roots then within 1e-4 of each other, relative), where either may call it a touch.
    #[test]
    fn agrees_with_the_general_expansion() {
        let mut compared = 0;
        for (k, &s) in [1.0, 1e-4, 1e6].iter().enumerate() {
            for (j, c) in quadrics(s).iter().enumerate() {
                let poly = Poly::new(Affine3A::IDENTITY, 2, c, Solver::Fast);
                let form = QuadricForm::of(&poly.terms);
                for (i, &(o, d)) in rays(0x9e37_79b9 + (k * 16 + j) as u64, s, 3000).iter().enumerate() {
                    let t_min = [0.0, 1e-3 * s][i % 2];
                    let new = form.hit(wv(o), wv(d), W([t_min]), W([f64::INFINITY]), |v| v).0[0];
                    let old = poly.solve_reference(o, d, t_min, f64::INFINITY).unwrap_or(f64::INFINITY);
                    if new == old || (new - old).abs() <= 1e-9 * (new.abs() + s) {
                        compared += (new.is_finite()) as usize;
                        continue;
                    }
                    // A graze: the hit (whichever found it) is where the ray is nearly tangent.
                    let t = if new.is_finite() { new } else { old };
                    let x = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
                    let g = form.gradient(wv(x));
                    let g = [g.x.0[0], g.y.0[0], g.z.0[0]];
                    let dl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                    let gl = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
                    let cos = (g[0] * d[0] + g[1] * d[1] + g[2] * d[2]).abs() / (gl * dl);
                    assert!(cos < 1e-4, "quadric {j} scale {s} ray {i} {o:?} {d:?}: new {new} old {old} cos {cos}");
                }
            }
        }
        assert!(compared > 20_000, "{compared}");
    }

    /// Exactly tangent rays and rays along a paraboloid's axis: the touch is found where the
    /// general path finds it, and no root comes from the rounding noise of the s² term.
    #[test]
    fn tangents_and_axes() {
        let sphere = QuadricForm::of(&[(1.0, [2, 0, 0]), (1.0, [0, 2, 0]), (1.0, [0, 0, 2]), (-1.0, [0, 0, 0])]);
        let inf = W([f64::INFINITY]);
        // Tangent at (1, 0, 0): a double root at t = 5.
        let t = sphere.hit(wv([1.0, 0.0, -5.0]), wv([0.0, 0.0, 1.0]), W([0.0]), inf, |v| v).0[0];
        assert!((t - 5.0).abs() < 1e-6, "{t}");
        // Just outside: a miss.
        let t = sphere.hit(wv([1.0 + 1e-9, 0.0, -5.0]), wv([0.0, 0.0, 1.0]), W([0.0]), inf, |v| v).0[0];
        assert_eq!(t, f64::INFINITY);
        // z = x² + y², down the axis from above: the vertex only, at any scale.
        for s in [1e-4, 1.0, 1e6] {
            let bowl =
                QuadricForm::of(&[(1.0 / (s * s), [2, 0, 0]), (1.0 / (s * s), [0, 2, 0]), (-1.0 / s, [0, 0, 1])]);
            let t = bowl.hit(wv([0.0, 0.0, 3.0 * s]), wv([0.0, 0.0, -1.0]), W([0.0]), inf, |v| v).0[0];
            assert!((t / s - 3.0).abs() < 1e-9, "{s}: {t}");
            // From below, upwards: the same vertex, then nothing.
            let up = bowl.hit(wv([0.0, 0.0, -3.0 * s]), wv([0.0, 0.0, 1.0]), W([0.0]), inf, |v| v).0[0];
            assert!((up / s - 3.0).abs() < 1e-9, "{s}: {up}");
            let past = bowl.hit(wv([0.0, 0.0, -3.0 * s]), wv([0.0, 0.0, 1.0]), W([up * (1.0 + 1e-6)]), inf, |v| v).0[0];
            assert_eq!(past, f64::INFINITY, "{s}");
        }
        // A root the lane rounds onto t_min is passed over for the next one.
        let t = sphere.hit(wv([0.0, 0.0, -5.0]), wv([0.0, 0.0, 1.0]), W([4.0]), inf, |v| v as f32 as f64).0[0];
        assert_eq!(t, 6.0);
    }

    /// Eight-lane packets give the single-lane answers bit for bit.
    #[test]
    fn packets_match_single_rays_bit_for_bit() {
        let frame = Affine3A::from_translation(Vec3::new(0.3, -0.2, 8.0)) * Affine3A::from_rotation_y(0.4);
        let mut hits = 0;
        for c in quadrics(1.0) {
            let poly = Poly::new(frame, 2, &c, Solver::Fast);
            let all = rays(0x5eed, 1.0, 800);
            for chunk in all.chunks(8) {
                let rays: [Ray; 8] = std::array::from_fn(|i| {
                    let (o, d) = chunk[i];
                    let f = |v: [f64; 3]| Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32);
                    Ray::new(frame.transform_point3(f(o)), frame.transform_vector3(f(d)).normalize())
                });
                let packet = RayLanes::<F8> {
                    o: V3::from_lanes(|i| rays[i].origin),
                    d: V3::from_lanes(|i| rays[i].dir),
                    inv: V3::from_lanes(|i| rays[i].inv_dir),
                };
                let t_min = F8::from_fn_f64(|i| [0.0, 0.5][i % 2]);
                let wide = poly.hit(&packet, t_min, F8::splat(MISS));
                for (i, r) in rays.iter().enumerate() {
                    let one = poly.hit(&r.lanes(), t_min.get(i), MISS);
                    assert_eq!(wide.get(i).to_bits(), one.to_bits(), "lane {i}");
                    hits += (one != MISS) as usize;
                }
            }
        }
        assert!(hits > 1000, "{hits}");
    }
}
