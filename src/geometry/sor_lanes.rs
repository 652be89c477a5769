//! The sor's segments and caps solved eight lanes at once in f64 (`wide::W`): a ray meets a
//! segment where `x² + z² = f(y)` with `y` linear along it, a cubic, whose roots come in closed
//! form (`cubic::roots_lanes_conditioned`) with two Newton steps each. The per-lane Bernstein
//! isolation and polish of `Sor::solve` took three fifths of scenes/kernels/sor.pov's frame.
//!
//! The cubic is written about the ray's point nearest the object's centre, in the distance `s`
//! along the unit direction (`wide::CentredLanes`): the sor is scaled to unit size there, so its
//! roots lie within a few units of `s = 0` and the coefficients have the size of the shape,
//! however far the ray starts. Where the closed form is ill-conditioned (a double root: a
//! grazing ray; a vanishing `s³` term: a ray near level, whose third root flies off) or a polish
//! does not settle, the lane is reported `ill` and the caller solves it whole with
//! `Sor::solve`, so those rays keep that solve's answers.
//!
//! Each lane does the arithmetic of a single ray (`N = 1`), lane by lane in order, so packets
//! and single rays agree bit for bit.

use super::cubic::{finite, roots_lanes_conditioned};
use super::revolved::Candidates;
use super::sor::Segment;
use super::wide::{and, lane_f64, lanes_f64, not, or, to_lane, CentredLanes, Mask, W, WV};
use crate::lanes::{Lane, V3};
use crate::ray::MISS;

/// How near a double root the closed form gives up (`roots_lanes_conditioned`).
const ILL: f64 = 1e-6;

/// The size of the region, about the object's centre, that holds every root a lane can use:
/// the unit-scaled sor lies within √2 of it.
const REACH: f64 = 2.0;

/// The largest last Newton step, relative to `REACH`, of a root that has settled: a simple
/// root's second step is at the rounding (10⁻¹⁶); one that moves more is near a double root
/// the threshold let through.
const SETTLED: f64 = 1e-9;

/// How far past its ends a segment keeps a root (in the unit-scaled heights): neighbours meet
/// with equal value and slope, so a root there is on both, and none falls between them.
const JOINT: f64 = 1e-9;

/// The sor's closed caps: heights and squared radii, bottom then top.
pub(super) type Caps = Option<[(f64, f64); 2]>;

/// Per lane of `live`, the nearest hit of `o + t·d` (object space) in `(t_min, t_max)` with the
/// `segments` (then `caps`, pieces `n` and `n + 1`) that `candidates` lets the lane meet (bit
/// `i` of `candidates(k)` for lane `i` and piece `k`), as
/// `hit_lanes_f64` answers it: the first root the lane's rounding (`round`) puts above `t_min`,
/// rounded, at most `t_max`; `MISS` for none. Also the lanes the closed form declines (`ill`),
/// whose answer the caller must find otherwise.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(super) fn hit<const N: usize>(
    segments: &[Segment],
    caps: Caps,
    candidates: impl Fn(usize) -> u8,
    live: Mask<N>,
    o: WV<N>,
    d: WV<N>,
    t_min: W<N>,
    t_max: W<N>,
    round: impl Fn(f64) -> f64 + Copy,
) -> (W<N>, Mask<N>) {
    let k = W::<N>::splat;
    let CentredLanes { p, u, t_c, len, valid } = CentredLanes::new(o, d);
    let mut ill = [false; N];
    let live = and(live, valid);
    let mut best = t_max;
    // Along the ray: the squared distance from the axis, ph2 + 2·puh·s + uh2·s², and the height
    // p.y + v·s.
    let (v, py) = (u[1], p[1]);
    let (uh2, puh, ph2) = (u[0] * u[0] + u[2] * u[2], p[0] * u[0] + p[2] * u[2], p[0] * p[0] + p[2] * p[2]);
    let (v2, inv_v) = (v * v, k(1.0) / v);
    let v3 = v2 * v;
    let s_min = (t_min - t_c) * len;
    // The first live lane's direction sets the order (either order gives the same answers): a
    // packet's lanes mostly share it, and a hit found early passes the later segments over.
    let n = segments.len();
    let down = (0..N).find(|&i| live[i]).is_some_and(|i| d.y.0[i] < 0.0);
    for step in 0..n {
        let at = if down { n - 1 - step } else { step };
        let seg = &segments[at];
        let lanes = candidates(at);
        // The segment's slab in s, padded; a lane whose slab lies outside (t_min, best) is not
        // solved. NaN (a level ray at a slab's height) is solved (and declined below).
        let (a0, a1) = ((k(seg.lo) - py) * inv_v, (k(seg.hi) - py) * inv_v);
        let (near, far) = (a0.min(a1), a0.max(a1));
        let s_best = (best - t_c) * len;
        let pad = k(1e-6) * (near.abs() + far.abs() + k(REACH));
        let mut go = [false; N];
        for i in 0..N {
            go[i] = live[i]
                && !ill[i]
                && lanes >> i & 1 != 0
                && !(far.0[i] + pad.0[i] < s_min.0[i])
                && !(s_best.0[i] < near.0[i] - pad.0[i]);
        }
        if !go.contains(&true) {
            continue;
        }
        // f(py + v·s) − (ph2 + 2·puh·s + uh2·s²), highest power first: f's Taylor expansion
        // about py.
        let [a, b, c, dd] = seg.k.map(k);
        let f0 = ((a * py + b) * py + c) * py + dd;
        let f1 = (k(3.0) * a * py + k(2.0) * b) * py + c;
        let f2 = k(3.0) * a * py + b;
        let cubic = [a * v3, f2 * v2 - uh2, f1 * v - k(2.0) * puh, f0 - ph2];
        let inv_lead = k(1.0) / cubic[0];
        let (ma, mb, mc) = (cubic[1] * inv_lead, cubic[2] * inv_lead, cubic[3] * inv_lead);
        let (roots, declined) = roots_lanes_conditioned(ma, mb, mc, ILL);
        let unusable = or(declined, not(and(finite(ma), and(finite(mb), finite(mc)))));
        ill = or(ill, and(go, unusable));
        let go = and(go, not(unusable));
        let eval = |s: W<N>| ((cubic[0] * s + cubic[1]) * s + cubic[2]) * s + cubic[3];
        let slope = |s: W<N>| (k(3.0) * cubic[0] * s + k(2.0) * cubic[1]) * s + cubic[2];
        for r in roots {
            // A root far outside the slab, or far outside (t_min, best), stays out (a polish
            // moves one by far less).
            let (from, to) = (near.max(s_min), far.min(s_best));
            let todo = and(go, and(finite(r), and((from - pad).le(r), r.le(to + pad))));
            if !todo.contains(&true) {
                continue;
            }
            let (mut s, mut last) = (r, k(0.0));
            for _ in 0..2 {
                last = eval(s) / slope(s);
                s = W::select(finite(last), s - last, s);
            }
            let settled = last.abs().le(k(SETTLED * REACH));
            ill = or(ill, and(todo, not(settled)));
            let y = py + v * s;
            let t = t_c + s / len;
            let mut keep = [false; N];
            for i in 0..N {
                let (t, y, lo) = (t.0[i], y.0[i], t_min.0[i]);
                keep[i] = todo[i]
                    && settled[i]
                    && y >= seg.lo - JOINT
                    && y <= seg.hi + JOINT
                    && t > lo
                    && t < best.0[i]
                    && round(t) > lo;
            }
            best = W::select(keep, t, best);
        }
    }
    if let Some(caps) = caps {
        for (j, (h, r2)) in caps.into_iter().enumerate() {
            let lanes = candidates(n + j);
            // As `Sor::solve` meets a cap: where the ray crosses its height, within its radius.
            let t = (k(h) - o.y) / d.y;
            let (x, z) = (o.x + t * d.x, o.z + t * d.z);
            let w2 = x * x + z * z;
            let mut keep = [false; N];
            for i in 0..N {
                let (t, lo) = (t.0[i], t_min.0[i]);
                keep[i] = live[i]
                    && lanes >> i & 1 != 0
                    && d.y.0[i] != 0.0
                    && t > lo
                    && t < best.0[i]
                    && round(t) > lo
                    && w2.0[i] <= r2;
            }
            best = W::select(keep, t, best);
        }
    }
    let mut out = [MISS as f64; N];
    for i in 0..N {
        if best.0[i] < t_max.0[i] {
            out[i] = round(best.0[i]).min(t_max.0[i]);
        }
    }
    (W(out), ill)
}

/// `sor_lanes::hit` for the lanes `lanes`, and the lanes it declines (bit `i` for lane `i`).
/// Out of line, so that its code stays out of the renderer's loops (a wide sor solve
/// inlined there once slowed the lathe kernels, whose code was unchanged), with AVX2 where
/// the CPU has it (the same operations, so the same bits).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(super) fn closed_form<L: Lane>(
    segments: &[Segment],
    caps: Caps,
    c: &Candidates,
    lanes: u8,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
) -> (L, u8) {
    #[cfg(target_arch = "x86_64")]
    if L::WIDTH == 8 && std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { closed_form_avx2(segments, caps, c, lanes, o, d, t_min, t_max) };
    }
    closed_form_in(segments, caps, c, lanes, o, d, t_min, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
unsafe fn closed_form_avx2<L: Lane>(
    segments: &[Segment],
    caps: Caps,
    c: &Candidates,
    lanes: u8,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
) -> (L, u8) {
    closed_form_in(segments, caps, c, lanes, o, d, t_min, t_max)
}

/// Most calls have few lanes the cull keeps (three or four of eight on the kernel scene):
/// those are gathered into two or four lanes (the same arithmetic per lane, so the same
/// bits) and solved in one or half the vector operations.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn closed_form_in<L: Lane>(
    segments: &[Segment],
    caps: Caps,
    c: &Candidates,
    lanes: u8,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
) -> (L, u8) {
    if L::WIDTH == 1 {
        let (o, d, lo, hi) = (lanes_f64::<L, 1>(o), lanes_f64(d), lane_f64(t_min), lane_f64(t_max));
        let may = |k: usize| c.lanes(k) & 1;
        let (t, ill) = hit::<1>(segments, caps, may, [lanes & 1 != 0], o, d, lo, hi, L::round_f64);
        return (to_lane(t), ill[0] as u8);
    }
    match lanes.count_ones() {
        0..=2 => closed_form_few::<L, 2>(segments, caps, c, lanes, o, d, t_min, t_max),
        3..=4 => closed_form_few::<L, 4>(segments, caps, c, lanes, o, d, t_min, t_max),
        _ => closed_form_few::<L, 8>(segments, caps, c, lanes, o, d, t_min, t_max),
    }
}

/// `closed_form_in` for at most `M` lanes of eight, gathered into `M`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn closed_form_few<L: Lane, const M: usize>(
    segments: &[Segment],
    caps: Caps,
    c: &Candidates,
    lanes: u8,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
) -> (L, u8) {
    let (mut at, mut n) = ([0usize; M], 0);
    for i in 0..L::WIDTH {
        if lanes >> i & 1 != 0 && n < M {
            at[n] = i;
            n += 1;
        }
    }
    let (o, d, lo, hi) = (lanes_f64::<L, 8>(o), lanes_f64::<L, 8>(d), lane_f64::<L, 8>(t_min), lane_f64::<L, 8>(t_max));
    let g = |w: W<8>| W(at.map(|i| w.0[i]));
    let gv = |v: WV<8>| WV { x: g(v.x), y: g(v.y), z: g(v.z) };
    let may = |k: usize| {
        let all = c.lanes(k);
        let mut m = 0u8;
        for (slot, &i) in at.iter().enumerate() {
            m |= (all >> i & 1) << slot;
        }
        m
    };
    let live = std::array::from_fn(|slot| slot < n);
    let (t, ill) = hit::<M>(segments, caps, may, live, gv(o), gv(d), g(lo), g(hi), L::round_f64);
    let (mut out, mut bad) = ([MISS as f64; 8], 0u8);
    for slot in 0..n {
        out[at[slot]] = t.0[slot];
        bad |= (ill[slot] as u8) << at[slot];
    }
    (to_lane(W(out)), bad)
}

#[cfg(test)]
mod tests {
    use crate::geometry::sor::Sor;
    use crate::geometry::test_support::uniform;
    use crate::geometry::Shape;
    use crate::lanes::{Lane, F8, V3};
    use crate::ray::{Ray, RayLanes, MISS};
    use glam::{DAffine3, DVec2, DVec3};

    /// The kernel scene's sor, and a random one seeded `seed` (heights rising by 0.1 to 0.6,
    /// radii 0.05 to 0.6).
    fn sors(seed: u64) -> Vec<Vec<DVec2>> {
        let p = DVec2::new;
        let kernel = vec![p(0.0, -0.1), p(0.4, 0.0), p(0.25, 0.35), p(0.45, 0.7), p(0.3, 0.95), p(0.3, 1.05)];
        let mut r = uniform(seed);
        let mut y = 0.0;
        let random = (0..7)
            .map(|_| {
                y += 0.1 + 0.5 * r();
                p(0.05 + 0.55 * r(), y)
            })
            .collect();
        vec![kernel, random]
    }

    /// The first crossing of the surface past `t0` along `o + t·d` by sampling its inside test
    /// finely and bisecting the first change: slow, and blind to a ray that only touches.
    fn brute_force(s: &Sor, o: DVec3, d: DVec3, t0: f64, t1: f64) -> Option<f64> {
        let inside = |t: f64| s.inside_at(o + t * d);
        let steps = 20_000;
        let mut prev = (t0, inside(t0));
        for i in 1..=steps {
            let t = t0 + (t1 - t0) * i as f64 / steps as f64;
            let now = inside(t);
            if now != prev.1 {
                let (mut a, mut b) = (prev.0, t);
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    if inside(m) == prev.1 {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                return Some(0.5 * (a + b));
            }
            prev = (t, now);
        }
        None
    }

    /// Seeded random rays at the kernel scene's sor and a random one, open and closed, from
    /// afar and from inside, some steep, some near level (`d.y` down to 10⁻⁹ of the run), some
    /// grazing the side (aimed along the tangent plane at a point of it): eight lanes give one
    /// lane's bits; every hit lies on the surface; a lane that meets a closed sor finds the
    /// brute-force crossing (or an earlier point on the surface, where the sampling stepped
    /// over a touch); and a hit agrees with
    /// the Bernstein solve the closed form replaced (`Sor::scalar_hit`) to f32's rounding,
    /// grazing rays included, where either may miss a touch the other finds, but no more.
    #[test]
    fn closed_form_matches_scalar_and_brute_force() {
        let mut r = uniform(0x5eed_50f3);
        let (mut hits, mut compared, mut touches) = (0, 0, 0);
        for (case, pts) in sors(11).into_iter().enumerate() {
            for open in [false, true] {
                let s = Sor::new(DAffine3::IDENTITY, &pts, open);
                let (lo, hi) = s.bounds();
                let (lo, hi) = (lo.as_dvec3(), hi.as_dvec3());
                let mut rays = Vec::new();
                for k in 0..1600 {
                    let at = lo + (hi - lo) * DVec3::new(r(), r(), r());
                    let mut d = DVec3::new(r() - 0.5, r() - 0.5, r() - 0.5).normalize();
                    match k % 4 {
                        // Near level.
                        1 => d.y = (r() - 0.5) * 10f64.powf(-9.0 * r()),
                        // Grazing: along the side's tangent plane at a point of it.
                        2 => {
                            rays.push(s.grazing_ray(r(), r(), d));
                            continue;
                        }
                        _ => {}
                    }
                    let d = d.normalize();
                    let o = if k % 8 == 3 { at } else { at - (2.0 + 50.0 * r()) * d };
                    rays.push((o.as_vec3(), d.as_vec3()));
                }
                for (k, chunk) in rays.chunks_exact(8).enumerate() {
                    let packet = RayLanes::<F8>::new(V3::from_lanes(|i| chunk[i].0), V3::from_lanes(|i| chunk[i].1));
                    let wide = s.hit(&packet, F8::splat(0.0), F8::splat(MISS));
                    for (i, &(o, d)) in chunk.iter().enumerate() {
                        let id = (case, open, 8 * k + i);
                        let ray = Ray::new(o, d);
                        let one = s.hit(&ray.lanes(), 0.0, MISS);
                        assert_eq!(wide.get(i).to_bits(), one.to_bits(), "{id:?}");
                        let old = s.scalar_hit(&ray.lanes(), 0.0, MISS);
                        let grazing = (8 * k + i) % 4 == 2;
                        let (o64, d64) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
                        if one != MISS && old != MISS {
                            compared += 1;
                            let near = (one - old).abs() <= 1e-4 * (1.0 + old.abs());
                            assert!(near || grazing, "{id:?}: {one} vs {old}, {o} {d}");
                            touches += usize::from(!near);
                        } else if one != old {
                            assert!(grazing, "{id:?}: {one} vs {old}, {o} {d}");
                            touches += 1;
                        }
                        if one != MISS {
                            hits += 1;
                            let q = o64 + one as f64 * d64;
                            assert!(s.on_surface(q, 1e-4), "{id:?}: {one} at {q} is on no part");
                        }
                        // The inside test has caps an open sor lacks: only closed ones are sampled.
                        if let Some(t) = brute_force(&s, o64, d64, 1e-4, 200.0).filter(|_| !open) {
                            if !grazing {
                                assert!(
                                    one != MISS && one as f64 <= t + 1e-4 * (1.0 + t),
                                    "{id:?}: {one} past the crossing {t}, {o} {d}"
                                );
                            }
                        }
                    }
                }
            }
        }
        assert!(hits > 500 && compared > 500 && touches * 20 < compared, "{hits} {compared} {touches}");
    }
}
