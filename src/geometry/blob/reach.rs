//! Which rays of a packet can meet a blob at all, eight lanes at a time in f32, before any lane
//! is solved one by one in f64 (`blob::Blob::solve`).
//!
//! A positive component adds at most `strength · (1 − d²/r²)²` to the field at a point `d` away
//! from its centre or axis segment, so along a ray it adds at most that for the ray's least
//! distance `d` from it. Where these maxima summed over the positive components stay below the
//! threshold, the field cannot reach it anywhere along the ray (negative components only take
//! away), and the ray misses. The least distance between the ray's stretch `[t_min, t_max]`
//! and a component's segment (a point for a sphere component) is the closest points of two
//! segments (Ericson, Real-Time Collision Detection, 5.1.9), in the component's own space,
//! where its distance is Euclidean.
//!
//! On the kernel scenes nine rays in ten that reach the blob's box miss it this way: each
//! costs a few vector instructions here instead of its pieces, their sort and their bounds
//! in f64. The test only ever keeps lanes it is unsure of: every distance is lowered by far
//! more than its f32 rounding (the f64 solve works on the same f32 object-space ray, and its
//! own bound keeps a part in 10⁹), and a NaN anywhere keeps the lane.

use glam::{Affine3A, Vec3};

use crate::lanes::{Lane, V3};

/// One positive component as the test sees it: its segment in its own space (`mid + h·axis`,
/// `h` in `[−half, half]`; `half` 0 for a sphere), `1/r²` and its strength.
#[derive(Clone, Copy, Debug)]
pub struct Component {
    pub mid: Vec3,
    pub axis: Vec3,
    pub half: f32,
    pub inv_r2: f32,
    pub strength: f32,
}

/// A blob's positive components for the test, grouped by the map into their space from the
/// blob's unit space (one group where no component has its own transform), so that the ray is
/// carried into each space once.
#[derive(Clone, Debug, Default)]
pub struct Reach {
    groups: Vec<(Affine3A, Vec<Component>)>,
}

impl Reach {
    /// `components` as `(component_from_unit, component)`.
    pub fn new(components: impl IntoIterator<Item = (Affine3A, Component)>) -> Reach {
        let mut reach = Reach::default();
        for (m, c) in components {
            match reach.groups.iter_mut().find(|(k, _)| *k == m) {
                Some((_, group)) => group.push(c),
                None => reach.groups.push((m, vec![c])),
            }
        }
        reach
    }
}

/// Relative error the distances are lowered by: over a thousand ulps of the sizes they are
/// computed from, far above the rounding of the few operations behind them (a part in 10⁴ of
/// a distance moves the field's bound by less than a part in 10³).
const SLACK: f32 = 1e-4;

/// Below this `sin²` of the angle between a ray and a cylinder's axis the closest points are
/// ill-conditioned: such lanes are kept.
const PARALLEL: f32 = 1e-3;

/// The lanes whose unit-space ray `o + t·d`, `t` in `[t_min, t_max]`, comes near enough to the
/// positive components in `reach` for their summed field to reach `threshold`: a lane left out
/// certainly misses the blob. NaN anywhere keeps the lane, except in the interval and the
/// origin, where it is a miss. Eight lanes are computed with AVX2 where the CPU has it (the
/// same operations, so the same bits: no FMA).
#[inline(always)]
pub fn may_reach<L: Lane>(reach: &Reach, threshold: f32, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> L::Mask {
    #[cfg(target_arch = "x86_64")]
    if L::WIDTH == 8 && std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { may_reach_avx2(reach, threshold, o, d, t_min, t_max) };
    }
    may_reach_in::<L, false>(reach, threshold, o, d, t_min, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn may_reach_avx2<L: Lane>(reach: &Reach, threshold: f32, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> L::Mask {
    may_reach_in::<L, true>(reach, threshold, o, d, t_min, t_max)
}

/// A group's ray as each component's test reads it: in the group's space, the ray's point
/// nearest the origin `c0`, its direction `v` and `1/(v·v)`, the ray's stretch about `c0`
/// `[lo, hi]`, `v`'s largest component and the slack for what `c0` was computed from. What
/// follows then works with numbers of the blob's size, not the ray origin's distance.
struct GroupRay<L> {
    c0: V3<L>,
    v: V3<L>,
    inv_vv: L,
    lo: L,
    hi: L,
    v_size: L,
    pad0: L,
}

/// The summed bound on the positive fields, and the lanes kept as unsure whatever it is.
struct Sum<L: Lane> {
    most: L,
    unsure: L::Mask,
}

impl<L: Lane> GroupRay<L> {
    #[inline(always)]
    fn new(m: &Affine3A, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> GroupRay<L> {
        let oc = o.transform_point(m);
        let v = d.transform_vector(m);
        let inv_vv = v.dot(v).recip();
        let t_c = -oc.dot(v) * inv_vv;
        let c0 = oc.add(v.scale(t_c));
        let v_size = v.max_abs();
        let pad0 = L::splat(SLACK) * (oc.max_abs() + t_c.abs() * v_size);
        GroupRay { c0, v, inv_vv, lo: t_min - t_c, hi: t_max - t_c, v_size, pad0 }
    }

    #[inline(always)]
    fn clamp(&self, t: L) -> L {
        t.max(self.lo).min(self.hi)
    }

    /// Adds component `c`'s most along the ray to `sum`, given the vector `w` from its middle to
    /// `c0`, and `p`, the ray's point nearest its segment less that nearest point, at `t`.
    #[inline(always)]
    fn add(&self, c: &Component, w: V3<L>, p: V3<L>, t: L, sum: &mut Sum<L>) {
        let zero = L::splat(0.0);
        // Lowered in proportion to what `p` was computed from.
        let sizes = L::splat(c.half + c.mid.abs().max_element());
        let pad = self.pad0 + L::splat(SLACK) * (w.max_abs() + t.abs() * self.v_size + sizes);
        let near = p.dot(p).sqrt() - pad;
        let near = L::select(near.lt(zero), zero, near);
        let g = L::splat(1.0) - near * near * L::splat(c.inv_r2);
        // A NaN `g` stays NaN (`lt` is false for it), and keeps the lane below.
        let g = L::select(g.lt(zero), zero, g);
        sum.most = sum.most + L::splat(c.strength) * g * g;
    }

    /// A sphere component (`half` 0): the ray's point nearest its centre.
    #[inline(always)]
    fn sphere(&self, c: &Component, sum: &mut Sum<L>) {
        let w = self.c0.sub(V3::splat(c.mid));
        let t = self.clamp(-w.dot(self.v) * self.inv_vv);
        self.add(c, w, w.add(self.v.scale(t)), t, sum);
    }

    /// A cylinder component: the closest points of two segments (the ray's point nearest the
    /// middle where they are near parallel), then the segment's parameter clamped and the ray's
    /// found again from it.
    #[inline(always)]
    fn cylinder(&self, c: &Component, sum: &mut Sum<L>) {
        let (v, inv_vv) = (self.v, self.inv_vv);
        let w = self.c0.sub(V3::splat(c.mid));
        let wv = w.dot(v);
        let a = V3::splat(c.axis);
        let (va, wa) = (v.dot(a), w.dot(a));
        let sin2 = L::splat(1.0) - va * va * inv_vv;
        let skew = L::splat(PARALLEL).lt(sin2);
        sum.unsure = L::or(sum.unsure, L::not(skew));
        let t = L::select(skew, (va * wa * inv_vv - wv * inv_vv) / sin2, -wv * inv_vv);
        let h = wa + self.clamp(t) * va;
        let half = L::splat(c.half);
        let (below, above) = (h.lt(-half), half.lt(h));
        let end = L::select(below, -half, half);
        let t = self.clamp(L::select(L::or(below, above), (end * va - wv) * inv_vv, t));
        let h = L::select(below, -half, L::select(above, half, h));
        self.add(c, w, w.add(v.scale(t)).sub(a.scale(h)), t, sum);
    }
}

// Out of line with AVX2, each reading its inputs from memory and writing its sum back: inlined
// into `may_reach_avx2`'s loops, the eight lanes of every value carried from one component to
// the next were kept as eight scalars and gathered back into a vector at each use (230
// `vinsertps` in a 940-instruction function; 9.0 of scenes/kernels/blob_sphere.pov's 61 M
// instructions at 160×120, 1 333 a call). Out of line, 3.0 M (447 a call), the same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline(never)]
unsafe fn group_avx2<L: Lane>(m: &Affine3A, o: &V3<L>, d: &V3<L>, t_min: &L, t_max: &L, out: &mut GroupRay<L>) {
    *out = GroupRay::new(m, *o, *d, *t_min, *t_max);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline(never)]
unsafe fn sphere_avx2<L: Lane>(g: &GroupRay<L>, c: &Component, sum: &mut Sum<L>) {
    g.sphere(c, sum)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline(never)]
unsafe fn cylinder_avx2<L: Lane>(g: &GroupRay<L>, c: &Component, sum: &mut Sum<L>) {
    g.cylinder(c, sum)
}

/// `AVX2`: the group and component steps are called out of line with AVX2 (only from
/// `may_reach_avx2`).
#[inline(always)]
fn may_reach_in<L: Lane, const AVX2: bool>(
    reach: &Reach,
    threshold: f32,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
) -> L::Mask {
    let zero = L::splat(0.0);
    let mut sum = Sum { most: zero, unsure: zero.lt(zero) };
    for (m, group) in &reach.groups {
        #[cfg(target_arch = "x86_64")]
        if AVX2 {
            let mut g = GroupRay { c0: o, v: d, inv_vv: zero, lo: zero, hi: zero, v_size: zero, pad0: zero };
            // SAFETY: `AVX2` is set only by `may_reach_avx2`, which runs where the CPU has it.
            unsafe { group_avx2(m, &o, &d, &t_min, &t_max, &mut g) };
            for c in group {
                // SAFETY: as above.
                unsafe {
                    if c.half == 0.0 {
                        sphere_avx2(&g, c, &mut sum);
                    } else {
                        cylinder_avx2(&g, c, &mut sum);
                    }
                }
            }
            continue;
        }
        let g = GroupRay::new(m, o, d, t_min, t_max);
        for c in group {
            if c.half == 0.0 {
                g.sphere(c, &mut sum);
            } else {
                g.cylinder(c, &mut sum);
            }
        }
    }
    let reaches = L::or(sum.unsure, L::not(sum.most.lt(L::splat(threshold * (1.0 - SLACK)))));
    // Lanes with an empty interval (a packet's idle lanes, `t_max` −inf) hold no root, nor does
    // a ray from a point at infinity or NaN: the f64 solve finds no piece of any component on
    // it. Each is a miss, not kept as unsure for its NaNs.
    // x - x is zero exactly where x is finite (NaN for ±inf and NaN).
    #[allow(clippy::eq_op)]
    let finite = ((o.x - o.x) + (o.y - o.y) + (o.z - o.z)).le(zero);
    L::and(L::and(t_min.lt(t_max), finite), reaches)
}

/// `may_reach`'s test never changes an answer: each lane's hit, in packets and alone, is the
/// f64 solve's over the whole interval, on random blobs at scales 1e-4 to 1e6 under sheared
/// component transforms, for rays aimed anywhere in the box, rays grazing the surface by a part
/// in 10⁴ to 10⁸ of the scale, and rays leaving the surface (shadow rays).
#[cfg(test)]
mod tests {
    use super::super::*;
    use crate::geometry::hit_lanes_f64;
    use crate::geometry::test_support::uniform;
    use crate::lanes::F8;
    use glam::DMat3;

    /// Random components, a third of them cylinders, some negative, each under a random
    /// non-uniform scale and shear.
    fn random_blob(rnd: &mut impl FnMut() -> f64, scale: f64) -> Blob {
        let mut v = || DVec3::new(rnd(), rnd(), rnd()) * 2.0 - 1.0;
        let comps: Vec<Component> = (0..2 + (v().x.abs() * 4.0) as usize)
            .map(|i| {
                let (c, r) = (v() * 0.6, 0.3 + 0.5 * v().x.abs());
                let shape = if i % 3 == 2 {
                    ComponentShape::Cylinder { base: c, cap: c + v() * 0.7, radius: r }
                } else {
                    ComponentShape::Sphere { center: c, radius: r }
                };
                let strength = if i % 4 == 3 { -0.5 } else { 0.6 + v().x.abs() };
                let m = DMat3::from_cols(v() * 0.3 + DVec3::X, v() * 0.3 + DVec3::Y, v() * 0.3 + DVec3::Z);
                Component { shape, strength, blob_from_component: DAffine3::from_mat3_translation(m, v() * 0.1) }
            })
            .collect();
        let place = DAffine3::from_scale(DVec3::splat(scale)) * DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1));
        Blob::new(place, &comps, 0.3 + 0.4 * rnd())
    }

    #[test]
    fn left_out_lanes_are_misses() {
        let mut rnd = uniform(41);
        let (mut kept, mut left, mut hits, mut grazes) = (0, 0, 0, 0);
        for scale in [1e-4, 1.0, 1e6] {
            for _ in 0..40 {
                let b = random_blob(&mut rnd, scale);
                let (lo, hi) = (b.min.as_dvec3(), b.max.as_dvec3());
                let centre = 0.5 * (lo + hi);
                let size = (hi - lo).max_element();
                let point = |rnd: &mut dyn FnMut() -> f64| lo + (hi - lo) * DVec3::new(rnd(), rnd(), rnd());
                let mut rays: Vec<(Vec3, Vec3, f32)> = Vec::new();
                for _ in 0..64 {
                    let from = centre + (point(&mut rnd) - centre).normalize() * 3.0 * size;
                    let d = (point(&mut rnd) - from).normalize();
                    rays.push((from.as_vec3(), d.as_vec3(), 0.0));
                    let ray = crate::ray::Ray::new(from.as_vec3(), d.as_vec3());
                    let Some(t) = b.intersect(&ray, 0.0, f32::INFINITY) else { continue };
                    // Along the tangent plane at the hit, a little outside and inside it; and
                    // back out from the hit towards a random point.
                    let p = ray.origin + t * ray.dir;
                    let n = b.normal_at(p);
                    let tangent = n.cross(d.as_vec3()).normalize_or_zero().cross(n);
                    for e in [1e-4f32, -1e-6, 1e-8, 0.0] {
                        let at = p + n * e * size as f32;
                        rays.push((at - tangent * 2.0 * size as f32, tangent, 0.0));
                    }
                    rays.push((p, (point(&mut rnd) - p.as_dvec3()).normalize().as_vec3(), 1e-4 * size as f32));
                }
                for chunk in rays.chunks(8) {
                    let lane =
                        |f: &dyn Fn(&(Vec3, Vec3, f32)) -> Vec3| V3::<F8>::from_lanes(|i| f(&chunk[i % chunk.len()]));
                    let packet = RayLanes::<F8>::new(lane(&|r| r.0), lane(&|r| r.1));
                    let t_min = F8::from_fn(|i| chunk[i % chunk.len()].2);
                    let wide = b.hit(&packet, t_min, F8::splat(MISS));
                    // Every lane solved, over its whole interval.
                    let all =
                        hit_lanes_f64(&b.frame, &packet, t_min, F8::splat(MISS), |o, d, lo, hi| b.solve(o, d, lo, hi));
                    let o = packet.o.transform_point(&b.frame.object_from_render);
                    let d = packet.d.transform_vector(&b.frame.object_from_render);
                    let near = may_reach(&b.reach, b.threshold as f32, o, d, t_min, F8::splat(MISS));
                    for (i, r) in chunk.iter().enumerate() {
                        assert_eq!(wide.0[i].to_bits(), all.0[i].to_bits(), "lane {i} of {r:?} at scale {scale}");
                        let one = b.hit(&crate::ray::Ray::new(r.0, r.1).lanes(), r.2, MISS);
                        assert_eq!(one.to_bits(), all.0[i].to_bits(), "{r:?} alone at scale {scale}");
                        let left_out = !near.lane(i);
                        (kept, left) = (kept + !left_out as u32, left + left_out as u32);
                        hits += (all.0[i] != MISS) as u32;
                        grazes += (all.0[i] != MISS && r.2 == 0.0 && i % 6 != 0) as u32;
                    }
                    // Idle lanes (t_max −inf, as shadow packets mark them) and a ray from a point
                    // at infinity: misses both ways.
                    let t_max = F8::from_fn(|i| if i % 2 == 1 { f32::NEG_INFINITY } else { MISS });
                    let far = V3::<F8>::from_lanes(|i| {
                        if i == 4 {
                            Vec3::splat(f32::INFINITY)
                        } else {
                            chunk[i % chunk.len()].0
                        }
                    });
                    let idle = RayLanes::<F8>::new(far, packet.d);
                    let wide = b.hit(&idle, t_min, t_max);
                    let all = hit_lanes_f64(&b.frame, &idle, t_min, t_max, |o, d, lo, hi| b.solve(o, d, lo, hi));
                    assert_eq!(wide.0.map(f32::to_bits), all.0.map(f32::to_bits), "idle lanes at scale {scale}");
                }
            }
        }
        // The test does leave out lanes, and the rays do hit, graze and miss.
        assert!(
            left > 2_000 && kept > 2_000 && hits > 1_000 && grazes > 100,
            "{left} left, {kept} kept, {hits} hits, {grazes}"
        );
    }
}
