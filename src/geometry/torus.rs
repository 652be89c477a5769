//! POV-Ray's `torus { major, minor }`: the ring of radius `major` in the xz-plane around the
//! y axis, swept by a circle of radius `minor`. A quartic surface, solved in f64 eight lanes at
//! once for a packet (`wide::W`; one lane for a single ray, the same arithmetic, so packets and
//! single rays agree bit for bit): cheap rejections, then Ferrari's closed form with Newton polish, and
//! `roots`' critical-point isolation only where the closed form is ill-conditioned (issue 38:
//! the isolation alone made this 2.4x slower on scenes/kernels/torus.pov).
//!
//! In object space the major radius is 1 (the frame's scale carries it), so the quartic's
//! coefficients have the size of the torus. The ray is first moved to its point nearest the
//! centre and its direction made unit, which keeps them so for a torus seen from far away.

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::quartic::first_root_lanes;
use super::roots::{roots_in, MAX_DEGREE};
use super::wide::{and, lane_f64, lanes_f64, not, to_lane, CentredLanes, Mask, W, WV};
use super::{transformed_bounds, CullBox, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Copy, Debug)]
pub struct Torus {
    pub frame: BoxFrame,
    /// Minor radius relative to the major one.
    pub minor: f32,
    pub min: Vec3,
    pub max: Vec3,
    /// The object-space box, for culling lanes before the f64 solve.
    cull: CullBox,
}

impl Torus {
    /// A torus of major radius 1 and minor radius `minor` under `render_from_object`.
    pub fn new(render_from_object: Affine3A, minor: f32) -> Torus {
        let extent = Vec3::new(1.0 + minor, minor, 1.0 + minor);
        let (lo, hi) = transformed_bounds(&render_from_object, -extent, extent);
        let cull = CullBox::new(-extent.as_dvec3(), extent.as_dvec3());
        Torus { frame: frame_for(render_from_object), minor, min: lo, max: hi, cull }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }
}

/// The nearest `t` in `(t_min, t_max)` where `o + t·d` (object space) meets the torus, or
/// `None`: one lane of [`solve_lanes`].
#[cfg(test)]
fn solve(
    o: [f64; 3],
    d: [f64; 3],
    minor: f64,
    t_min: f64,
    t_max: f64,
    round: impl Fn(f64) -> f64 + Copy,
) -> Option<f64> {
    let v = |v: [f64; 3]| WV { x: W([v[0]]), y: W([v[1]]), z: W([v[2]]) };
    let t = solve_lanes::<1>(v(o), v(d), minor, W([t_min]), W([t_max]), round).0[0];
    (t != MISS as f64).then_some(t)
}

/// Per lane, the nearest `t` in `(t_min, t_max)` where `o + t·d` (object space) meets the
/// torus, `MISS` for none. `round` is the lane type's rounding (`Lane::round_f64`): roots are
/// compared with the interval as the lane will hold them.
///
/// Cheap rejections first (the sphere through the outer equator, the slab `|y| ≤ minor`, a
/// span wholly inside the hole's cylinder), then the quartic in closed form
/// (`quartic::first_root_lanes`), each root polished by Newton steps, all `N` lanes at once;
/// where the closed form is ill-conditioned (a double root: a grazing ray) it declines, and the
/// critical-point isolation `roots_in` decides for that lane alone. Each lane does the
/// arithmetic of a single ray (`N = 1`), so packets and single rays agree bit for bit.
#[inline(always)]
fn solve_lanes<const N: usize>(
    o: WV<N>,
    d: WV<N>,
    minor: f64,
    t_min: W<N>,
    t_max: W<N>,
    round: impl Fn(f64) -> f64 + Copy,
) -> W<N> {
    let k = W::<N>::splat;
    let miss = k(MISS as f64);
    let dot = |a: [W<N>; 3], b: [W<N>; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let CentredLanes { p, u, t_c, len, valid } = CentredLanes::new(o, d);
    let mut live = and(valid, t_min.lt(t_max));
    let outer = 1.0 + minor;
    let reach2 = k(outer * outer) - dot(p, p);
    live = and(live, k(0.0).le(reach2));
    // Padded: the outer equator lies on this sphere, and a root there must not be cut off.
    let reach = reach2.sqrt() * k(1.0 + 1e-9) + k(1e-12);
    let mut lo = (-reach).zip((t_min - t_c) * len, f64::max);
    let mut hi = reach.zip((t_max - t_c) * len, f64::min);
    // The slab |y| ≤ minor, padded alike (the tube's top and bottom circles lie on it).
    let slab = minor * (1.0 + 1e-9) + 1e-12;
    let level = u[1].0.map(|v| v == 0.0);
    let inv = k(1.0) / u[1];
    let (a, b) = ((k(-slab) - p[1]) * inv, (k(slab) - p[1]) * inv);
    lo = W::select(level, lo, lo.zip(a.zip(b, f64::min), f64::max));
    hi = W::select(level, hi, hi.zip(a.zip(b, f64::max), f64::min));
    live = and(live, not(and(level, not(p[1].abs().le(k(slab))))));
    live = and(live, lo.lt(hi));
    let a2 = u[0] * u[0] + u[2] * u[2];
    let b2 = p[0] * u[0] + p[2] * u[2];
    let c2 = p[0] * p[0] + p[2] * p[2];
    // The squared distance from the axis is convex in s: a span whose ends both lie inside the
    // hole's cylinder (radius 1 − minor, padded) lies inside it throughout, and misses.
    let hole = 1.0 - minor;
    if hole > 0.0 {
        let hole2 = k(hole * hole * (1.0 - 1e-9));
        let rho2 = |s: W<N>| (a2 * s + k(2.0) * b2) * s + c2;
        live = and(live, not(and(rho2(lo).lt(hole2), rho2(hi).lt(hole2))));
    }
    if !live.iter().any(|&l| l) {
        return miss;
    }
    let e = dot(p, p) + k(1.0) - k(minor * minor);
    let f = dot(p, u);
    let c = [
        k(1.0),
        k(4.0) * f,
        k(4.0) * f * f + k(2.0) * e - k(4.0) * a2,
        k(4.0) * f * e - k(8.0) * b2,
        e * e - k(4.0) * c2,
    ];
    let quartic = Quartic { c, lo, hi, t_c, len, t_min, t_max };
    // Most packets reach the closed form with a few lanes: up to four are gathered into one
    // 256-bit register's worth (the same arithmetic per lane, so the same bits).
    match live.iter().filter(|&&l| l).count() {
        n if N > 2 && n <= 2 => quartic.solve_few::<2>(live, round),
        n if N > 4 && n <= 4 => quartic.solve_few::<4>(live, round),
        _ => quartic.solve(live, round),
    }
}

/// The torus's quartic along `N` rays, in `s` (`t = t_c + s / len`), and each lane's span.
struct Quartic<const N: usize> {
    c: [W<N>; 5],
    lo: W<N>,
    hi: W<N>,
    t_c: W<N>,
    len: W<N>,
    t_min: W<N>,
    t_max: W<N>,
}

impl<const N: usize> Quartic<N> {
    /// Lanes `at` of these, as `M` lanes.
    #[inline(always)]
    fn gather<const M: usize>(&self, at: [usize; M]) -> Quartic<M> {
        let g = |w: W<N>| W(at.map(|i| w.0[i]));
        Quartic {
            c: self.c.map(g),
            lo: g(self.lo),
            hi: g(self.hi),
            t_c: g(self.t_c),
            len: g(self.len),
            t_min: g(self.t_min),
            t_max: g(self.t_max),
        }
    }

    /// `solve` for at most `M` live lanes, gathered into `M` lanes and scattered back.
    #[inline(always)]
    fn solve_few<const M: usize>(&self, live: Mask<N>, round: impl Fn(f64) -> f64 + Copy) -> W<N> {
        let (mut at, mut n) = ([0usize; M], 0);
        for i in (0..N).filter(|&i| live[i]) {
            at[n] = i;
            n += 1;
        }
        for slot in n..M {
            at[slot] = at[0];
        }
        let few = self.gather(at).solve(std::array::from_fn(|slot| slot < n), round);
        let mut t = W::splat(MISS as f64);
        for slot in 0..n {
            t.0[at[slot]] = few.0[slot];
        }
        t
    }

    /// Each `live` lane's first root whose `t` lies in `(t_min, t_max)`, `MISS` for none: the
    /// closed form, and the isolation for a lane where that declines.
    #[inline(always)]
    fn solve(&self, live: Mask<N>, round: impl Fn(f64) -> f64 + Copy) -> W<N> {
        let Quartic { c, lo, hi, t_c, len, t_min, t_max } = *self;
        let accept = |s: W<N>| {
            let t = (t_c + s / len).map(round);
            (and(t_min.lt(t), t.lt(t_max)), t)
        };
        let (t, found, ill) = first_root_lanes(&c, lo, hi, live, accept);
        let mut t = W::select(found, t, W::splat(MISS as f64));
        for i in (0..N).filter(|&i| ill[i]) {
            let c = c.map(|c| c.0[i]);
            t.0[i] =
                isolate(&c, lo.0[i], hi.0[i], t_c.0[i], len.0[i], t_min.0[i], t_max.0[i], round).unwrap_or(MISS as f64);
        }
        t
    }
}

/// The first root of `c` in `[lo, hi]` whose `t` lies in `(t_min, t_max)`, by the critical-point
/// isolation: slow, and robust at double roots.
#[allow(clippy::too_many_arguments)]
fn isolate(
    c: &[f64; 5],
    lo: f64,
    hi: f64,
    t_c: f64,
    len: f64,
    t_min: f64,
    t_max: f64,
    round: impl Fn(f64) -> f64,
) -> Option<f64> {
    // The first root whose `t` lies in the interval: a root at `t_min` itself (CSG looking
    // past a rejected crossing, with `t_min` that crossing rounded) may land on either side.
    let mut roots = [0.0; MAX_DEGREE];
    let n = roots_in(c, lo, hi, &mut roots);
    roots[..n].iter().map(|s| round(t_c + s / len)).find(|&t| t > t_min && t < t_max)
}

impl Shape for Torus {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        // Lanes that miss the box, or trace nothing (a blocked shadow ray), are not solved: on
        // the kernel scene a solve was asked of half again as many lanes as could hit.
        let Some(t_max) = self.cull.live(o, d, t_min, t_max) else { return L::splat(MISS) };
        let minor = self.minor as f64;
        if L::WIDTH == 8 {
            to_lane(solve_lanes::<8>(lanes_f64(o), lanes_f64(d), minor, lane_f64(t_min), lane_f64(t_max), L::round_f64))
        } else {
            to_lane(solve_lanes::<1>(lanes_f64(o), lanes_f64(d), minor, lane_f64(t_min), lane_f64(t_max), L::round_f64))
        }
    }

    /// Away from the nearest point of the ring.
    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let q = p.transform_point(&self.frame.object_from_render);
        let rho = (q.x * q.x + q.z * q.z).sqrt();
        let ring = V3 { x: q.x / rho, y: L::splat(0.0), z: q.z / rho };
        q.sub(ring).mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }

    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = p.transform_point(&self.frame.object_from_render);
        let rho = (q.x * q.x + q.z * q.z).sqrt() - L::splat(1.0);
        (rho * rho + q.y * q.y).lt(L::splat(self.minor * self.minor))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lanes::F8;
    use crate::ray::Ray;

    fn torus() -> Torus {
        // Major 2, minor 0.5, centred at z = 10.
        Torus::new(Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)) * Affine3A::from_scale(Vec3::splat(2.0)), 0.25)
    }

    #[test]
    fn hits_outer_and_inner_walls_and_misses_the_hole() {
        let t = torus();
        // Along z over the ring's x = 2: the tube's outer surface, 1.5 before the centre plane.
        let r = Ray::new(Vec3::new(2.0, 0.0, 0.0), Vec3::Z);
        let hit = t.intersect(&r, 0.0, f32::INFINITY).expect("tube");
        assert!((hit - 8.5).abs() < 1e-5, "{hit}");
        // Along z through the hole: nothing... the ring lies across it at z = 10 ± 2 though.
        let hole = Ray::new(Vec3::new(0.0, 0.0, 0.0), Vec3::Z);
        let hit = t.intersect(&hole, 0.0, f32::INFINITY).expect("ring across the axis");
        assert!((hit - 7.5).abs() < 1e-5, "{hit}");
        // Straight down the y axis through the hole: a miss.
        let down = Ray::new(Vec3::new(0.0, 5.0, 10.0), -Vec3::Y);
        assert_eq!(t.intersect(&down, 0.0, f32::INFINITY), None);
        // Down through the tube.
        let tube = Ray::new(Vec3::new(2.0, 5.0, 10.0), -Vec3::Y);
        let hit = t.intersect(&tube, 0.0, f32::INFINITY).expect("top of tube");
        assert!((hit - 4.5).abs() < 1e-5);
        assert!((t.normal_at(tube.at(hit)) - Vec3::Y).length() < 1e-5);
        // From inside the tube, the far wall.
        let inside = Ray::new(Vec3::new(2.0, 0.0, 10.0), Vec3::X);
        let hit = t.intersect(&inside, 0.0, f32::INFINITY).expect("wall");
        assert!((hit - 0.5).abs() < 1e-5);
    }

    #[test]
    fn grazing_and_far_rays_and_packets() {
        let t = torus();
        // Tangent to the top of the tube: y = 0.5 exactly.
        let graze = Ray::new(Vec3::new(-10.0, 0.5, 10.0), Vec3::X);
        let hit = t.intersect(&graze, 0.0, f32::INFINITY);
        assert!(hit.is_none_or(|h| (h - 8.0).abs() < 1e-2 || (h - 12.0).abs() < 1e-2), "{hit:?}");
        // From 1e5 away the tube is still where it is.
        let far = Ray::new(Vec3::new(2.0, 0.0, -1e5), Vec3::Z);
        let hit = t.intersect(&far, 0.0, f32::INFINITY).expect("far");
        assert!((hit - (1e5 + 8.5)).abs() < 2e-2, "{hit}");
        let rays: [Ray; 8] = std::array::from_fn(|i| {
            let o = Vec3::new(i as f32 * 0.6 - 2.0, 0.1 * i as f32, 0.0);
            Ray::new(o, (Vec3::new(1.5, 0.2, 10.0) - o).normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let wide = t.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, r) in rays.iter().enumerate() {
            assert_eq!(wide.get(i).to_bits(), t.hit(&r.lanes(), 0.0, MISS).to_bits());
        }
    }

    /// The solver before the closed form (issue 38): critical-point isolation over the sphere's
    /// span, no other rejection. The reference the new one is held to.
    fn old_solve(o: [f64; 3], d: [f64; 3], minor: f64, t_min: f64, t_max: f64) -> Option<f64> {
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let crate::geometry::CentredRay { p, u, t_c, len } = crate::geometry::centred_ray(o, d)?;
        let outer = 1.0 + minor;
        let reach2 = outer * outer - dot(p, p);
        if reach2.is_nan() || reach2 < 0.0 {
            return None;
        }
        let reach = reach2.sqrt() * (1.0 + 1e-9) + 1e-12;
        let lo = (-reach).max((t_min - t_c) * len);
        let hi = reach.min((t_max - t_c) * len);
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return None;
        }
        let e = dot(p, p) + 1.0 - minor * minor;
        let f = dot(p, u);
        let a2 = u[0] * u[0] + u[2] * u[2];
        let b2 = p[0] * u[0] + p[2] * u[2];
        let c2 = p[0] * p[0] + p[2] * p[2];
        let c = [1.0, 4.0 * f, 4.0 * f * f + 2.0 * e - 4.0 * a2, 4.0 * f * e - 8.0 * b2, e * e - 4.0 * c2];
        let mut roots = [0.0; MAX_DEGREE];
        let n = roots_in(&c, lo, hi, &mut roots);
        roots[..n].iter().map(|s| t_c + s / len).find(|&t| t > t_min && t < t_max)
    }

    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn range(&mut self, a: f64, b: f64) -> f64 {
            a + (b - a) * self.next()
        }
        fn unit(&mut self) -> [f64; 3] {
            loop {
                let v = [self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0)];
                let l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
                if l2 > 1e-4 && l2 <= 1.0 {
                    let l = l2.sqrt();
                    return [v[0] / l, v[1] / l, v[2] / l];
                }
            }
        }
    }

    /// The signed distance from the torus's surface (object space, major radius 1).
    fn distance(x: [f64; 3], minor: f64) -> f64 {
        let rho = (x[0] * x[0] + x[2] * x[2]).sqrt() - 1.0;
        (rho * rho + x[1] * x[1]).sqrt() - minor
    }

    /// Seeded random rays of every kind the renderer sends: from far and near, from inside the
    /// tube, aimed at points on and about the torus, along the axis, through the hole, grazing
    /// the tube (aimed at a surface point along a tangent), horizontal ones (a biquadratic).
    fn rays(seed: u64, count: usize) -> Vec<([f64; 3], [f64; 3], f64)> {
        let mut rng = Rng(seed);
        let mut out = Vec::new();
        for case in 0..count {
            let minor = [0.35, 0.1, 0.5, 0.01, 0.9][case % 5];
            let dist = [3.0, 30.0, 1e3, 1.5][(case / 5) % 4];
            let kind = (case / 20) % 6;
            // A point on the surface.
            let (phi, theta) = (rng.range(0.0, 6.3), rng.range(0.0, 6.3));
            let n = [theta.cos() * phi.cos(), theta.sin(), theta.cos() * phi.sin()];
            let on = [phi.cos() + minor * n[0], minor * n[1], phi.sin() + minor * n[2]];
            let (o, d) = match kind {
                0 => {
                    // At a random point near the torus from a random place.
                    let target = [rng.range(-1.5, 1.5), rng.range(-0.6, 0.6), rng.range(-1.5, 1.5)];
                    let v = rng.unit();
                    let o = [target[0] + dist * v[0], target[1] + dist * v[1], target[2] + dist * v[2]];
                    (o, [target[0] - o[0], target[1] - o[1], target[2] - o[2]])
                }
                1 => {
                    // Grazing: along a tangent at a surface point, nudged in or out a little.
                    let v = rng.unit();
                    let dot = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
                    let t = [v[0] - dot * n[0], v[1] - dot * n[1], v[2] - dot * n[2]];
                    let nudge = minor * [0.0, 1e-3, -1e-3, 1e-7, -1e-7, 1e-12][case % 6];
                    let at = [on[0] + nudge * n[0], on[1] + nudge * n[1], on[2] + nudge * n[2]];
                    let o = [at[0] - dist * t[0], at[1] - dist * t[1], at[2] - dist * t[2]];
                    (o, t)
                }
                2 => {
                    // Along (or near) the axis, from above or below: through the hole.
                    let x = [0.0, 1e-3, rng.range(-0.5, 0.5)][case % 3];
                    let up = if case % 2 == 0 { 1.0 } else { -1.0 };
                    ([x, up * dist, rng.range(-0.2, 0.2)], [rng.range(-1e-3, 1e-3), -up, 0.0])
                }
                3 => {
                    // Horizontal rays across the ring, some through the hole.
                    let y = rng.range(-1.2, 1.2) * minor;
                    let a = rng.range(0.0, 6.3);
                    let off = rng.range(-1.6, 1.6);
                    let d = [a.cos(), 0.0, a.sin()];
                    let o = [-dist * d[0] - off * d[2], y, -dist * d[2] + off * d[0]];
                    (o, d)
                }
                4 => {
                    // From inside the tube or the hole, any way.
                    let k = rng.range(0.0, 0.99);
                    let o = if case % 2 == 0 {
                        [phi.cos() + k * minor * n[0], k * minor * n[1], phi.sin() + k * minor * n[2]]
                    } else {
                        [rng.range(-0.3, 0.3), rng.range(-0.5, 0.5), rng.range(-0.3, 0.3)]
                    };
                    (o, rng.unit())
                }
                _ => {
                    // Straight at a surface point, direction not unit.
                    let v = rng.unit();
                    let o = [on[0] + dist * v[0], on[1] + dist * v[1], on[2] + dist * v[2]];
                    let k = rng.range(0.1, 10.0);
                    (o, [-v[0] * k, -v[1] * k, -v[2] * k])
                }
            };
            out.push((o, d, minor));
        }
        out
    }

    /// The closed form finds what the isolation finds, on every kind of ray: the same hit or miss
    /// and the same `t` to about 1e-9 of the ray's reach, except where the ray is tangent to the
    /// surface (the hit point within 1e-6 of the tube's size of grazing it) and either answer
    /// is right. Every hit found lies on the surface.
    #[test]
    fn closed_form_matches_isolation_on_random_rays() {
        let (mut hits, mut grazing_disagree) = (0, 0);
        for (i, &(o, d, minor)) in rays(0x9e37_79b9_7f4a_7c15, 60_000).iter().enumerate() {
            let t_min = if i % 7 == 0 { 0.5 } else { 0.0 };
            let new = solve(o, d, minor, t_min, f64::INFINITY, |v| v);
            let old = old_solve(o, d, minor, t_min, f64::INFINITY);
            let at = |t: f64| [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
            let scale = (o[0] * o[0] + o[1] * o[1] + o[2] * o[2]).sqrt() + 2.0;
            let dl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if let Some(t) = new {
                assert!(
                    distance(at(t), minor).abs() < 1e-9 * scale + 1e-12,
                    "ray {i} {o:?} {d:?} {minor} t_min {t_min}: {t} off the surface (old {old:?}, d {})",
                    distance(at(t), minor)
                );
            }
            match (new, old) {
                (Some(a), Some(b)) => {
                    hits += 1;
                    if (a - b).abs() * dl > 1e-9 * scale {
                        // Two different roots: only where the ray grazes the tube near the
                        // first (a near-double root, either one right).
                        let graze = |t: f64| {
                            let x = at(t);
                            let rho = (x[0] * x[0] + x[2] * x[2]).sqrt();
                            let g = [x[0] - x[0] / rho, x[1], x[2] - x[2] / rho];
                            let gl = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
                            ((g[0] * d[0] + g[1] * d[1] + g[2] * d[2]) / (gl * dl)).abs()
                        };
                        assert!(graze(a.min(b)) < 1e-3, "ray {i} {o:?} {d:?} {minor}: new {a} old {b}");
                        grazing_disagree += 1;
                    }
                }
                (None, None) => {}
                (a, b) => {
                    // A hit only one finds: a tangent touch.
                    let t = a.or(b).unwrap();
                    let x = at(t);
                    let rho = (x[0] * x[0] + x[2] * x[2]).sqrt();
                    let g = [x[0] - x[0] / rho, x[1], x[2] - x[2] / rho];
                    let gl = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
                    let cos = ((g[0] * d[0] + g[1] * d[1] + g[2] * d[2]) / (gl * dl)).abs();
                    assert!(cos < 1e-3, "ray {i} {o:?} {d:?} {minor}: new {a:?} old {b:?} cos {cos}");
                    grazing_disagree += 1;
                }
            }
        }
        assert!(hits > 20_000, "{hits}");
        assert!(grazing_disagree < 200, "{grazing_disagree} grazing rays disagree");
    }

    /// Against dense sampling of the signed distance along the ray: the first sign change
    /// (a sure crossing) is where the solver's first hit is, or the solver's hit comes earlier
    /// (a touch the sampling stepped over).
    #[test]
    fn first_hit_matches_dense_sampling() {
        for (i, &(o, d, minor)) in rays(0x1234_5678_9abc_def1, 6_000).iter().enumerate() {
            let dl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            let u = [d[0] / dl, d[1] / dl, d[2] / dl];
            let start = (o[0] * o[0] + o[1] * o[1] + o[2] * o[2]).sqrt() - 1.0 - minor;
            let start = start.max(0.0);
            let at = |s: f64| [o[0] + s * u[0], o[1] + s * u[1], o[2] + s * u[2]];
            let hit = solve(o, u, minor, 0.0, f64::INFINITY, |v| v);
            let steps = 20_000;
            let span = 2.0 * (2.0 + 2.0 * minor);
            let h = span / steps as f64;
            let mut prev = distance(at(start.max(1e-9)), minor);
            let mut crossing = None;
            for k in 1..=steps {
                let s = start + k as f64 * h;
                let v = distance(at(s), minor);
                if (v < 0.0) != (prev < 0.0) {
                    crossing = Some(s);
                    break;
                }
                prev = v;
            }
            match (hit, crossing) {
                (Some(t), Some(s)) => assert!(t <= s + 1e-9 * start.max(1.0), "ray {i}: hit {t} after crossing {s}"),
                (None, Some(s)) => panic!("ray {i} {o:?} {d:?} {minor}: missed a crossing at {s}"),
                (Some(t), None) => {
                    // Only a touch between two samples, or past the sampled span.
                    assert!(distance(at(t), minor).abs() < 1e-7, "ray {i}: {t}")
                }
                (None, None) => {}
            }
        }
    }

    /// Exactly tangent rays (double roots): along the top of the tube, around the outer
    /// equator, around the inner equator; the hit, where there is one, is at the touch.
    #[test]
    fn tangent_rays_touch_where_they_should() {
        for &minor in &[0.35, 0.1, 0.5] {
            // Over the top at y = minor, across the ring at x = 1: touches at z = 0.
            let t = solve([1.0, minor, -5.0], [0.0, 0.0, 1.0], minor, 0.0, f64::INFINITY, |v| v);
            assert!(t.is_none_or(|t| (t - 5.0).abs() < 1e-3), "{minor} {t:?}");
            // Tangent to the outer equator: x = 1 + minor, in the plane y = 0.
            let t = solve([1.0 + minor, 0.0, -5.0], [0.0, 0.0, 1.0], minor, 0.0, f64::INFINITY, |v| v);
            assert!(t.is_none_or(|t| (t - 5.0).abs() < 1e-3), "{minor} {t:?}");
            // Tangent to the inner equator from outside the ring: enters the tube first.
            let t = solve([1.0 - minor, 0.0, -5.0], [0.0, 0.0, 1.0], minor, 0.0, f64::INFINITY, |v| v);
            let first = 5.0 - ((1.0f64 + minor).powi(2) - (1.0 - minor) * (1.0 - minor)).sqrt();
            assert!((t.unwrap() - first).abs() < 1e-9, "{minor} {t:?}");
            // Just above the top: a miss; just below: a hit near the touch.
            let above = solve([1.0, minor * (1.0 + 1e-6), -5.0], [0.0, 0.0, 1.0], minor, 0.0, f64::INFINITY, |v| v);
            assert_eq!(above, None);
            let below = solve([1.0, minor * (1.0 - 1e-6), -5.0], [0.0, 0.0, 1.0], minor, 0.0, f64::INFINITY, |v| v);
            assert!(below.is_some_and(|t| (t - 5.0).abs() < 0.05), "{minor} {below:?}");
        }
    }

    /// Eight-lane packets give the single-lane answers bit for bit, on random rays of every kind.
    #[test]
    fn packets_match_single_rays_bit_for_bit() {
        let t = torus();
        let all = rays(0x5151_2727_abcd_0001, 4_000);
        let to_render = |v: [f64; 3]| Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32);
        let frame = Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)) * Affine3A::from_scale(Vec3::splat(2.0));
        let mut hits = 0;
        for chunk in all.chunks(8).filter(|c| c.len() == 8) {
            let rays: [Ray; 8] = std::array::from_fn(|i| {
                let (o, d, _) = chunk[i];
                Ray::new(frame.transform_point3(to_render(o)), frame.transform_vector3(to_render(d)).normalize())
            });
            let packet = RayLanes::<F8> {
                o: V3::from_lanes(|i| rays[i].origin),
                d: V3::from_lanes(|i| rays[i].dir),
                inv: V3::from_lanes(|i| rays[i].inv_dir),
            };
            let t_min = F8::from_fn_f64(|i| [0.0, 0.3][i % 2]);
            let wide = t.hit(&packet, t_min, F8::splat(MISS));
            for (i, r) in rays.iter().enumerate() {
                let one = t.hit(&r.lanes(), t_min.get(i), MISS);
                assert_eq!(wide.get(i).to_bits(), one.to_bits(), "lane {i}");
                hits += (one != MISS) as usize;
            }
        }
        assert!(hits > 1000, "{hits}");
    }
}
