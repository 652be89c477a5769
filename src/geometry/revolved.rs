//! What the surfaces of revolution (`lathe`, `sor`) share: which of their pieces each lane of a
//! ray may meet, decided for all lanes at once in lane arithmetic, before any lane is solved in
//! f64 (`hit_lanes`).
//!
//! Every piece lies in a slab of heights `y_lo ..= y_hi` and a band of squared radii
//! `r2_min ..= r2_max` about the y axis (`Band`). A ray can meet it only at a `t` inside the slab
//! where its squared distance from the axis, a parabola in `t`, is inside the band: the test
//! `RadialRay::misses` makes per lane in f64, here made once for eight lanes. Most lanes the
//! shape's box lets through meet none of its pieces (two in three in the lathe kernel scene):
//! they now cost a few vector operations per piece, where each went through the f64 setup and
//! every piece's test one lane at a time.
//!
//! The test only ever keeps too much: it is padded by a part in 10⁴ of the magnitudes it
//! rounds (f32 rounds them by a few parts in 10⁷), every comparison that culls is false for NaN,
//! and a band's bounds are rounded outwards. The per-lane f64 solve that follows still decides
//! every hit, so the answers are the bits the solve gives without the cull.

use glam::DVec3;

use super::cuboid::BoxFrame;
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

/// A piece's slab of heights and band of radii about the y axis, in object space, rounded
/// outwards to f32.
#[derive(Clone, Copy, Debug)]
pub struct Band {
    y_lo: f32,
    y_hi: f32,
    r_min: f32,
    r_max: f32,
}

/// `v` rounded to f32 and moved a part in 10⁶ (of `|v|` plus the unit scale the shapes are
/// solved in) in the direction `dir`.
fn outward(v: f64, dir: f64) -> f32 {
    (v + dir * 1e-6 * (v.abs() + 1.0)) as f32
}

impl Band {
    /// The piece within heights `y_lo ..= y_hi` whose squared radius keeps to
    /// `r2_min ..= r2_max` (a negative `r2_min` as zero; a negative `r2_max`, a piece with no
    /// real points, as radius zero).
    pub fn new(y_lo: f64, y_hi: f64, r2_min: f64, r2_max: f64) -> Band {
        Band {
            y_lo: outward(y_lo, -1.0),
            y_hi: outward(y_hi, 1.0),
            r_min: outward(r2_min.max(0.0).sqrt(), -1.0).max(0.0),
            r_max: outward(r2_max.max(0.0).sqrt(), 1.0),
        }
    }

    /// The band holding all of `bands`.
    pub fn around(bands: &[Band]) -> Band {
        bands.iter().fold(
            Band { y_lo: f32::INFINITY, y_hi: f32::NEG_INFINITY, r_min: f32::INFINITY, r_max: 0.0 },
            |a, b| Band {
                y_lo: a.y_lo.min(b.y_lo),
                y_hi: a.y_hi.max(b.y_hi),
                r_min: a.r_min.min(b.r_min),
                r_max: a.r_max.max(b.r_max),
            },
        )
    }
}

/// Which pieces each lane of a ray may meet (`candidates`): per piece a byte with bit `i` for
/// lane `i`, the last entry for every piece from 63 on.
#[derive(Clone, Copy, Debug)]
pub struct Candidates {
    by_piece: [u8; 64],
}

/// One lane's view of `Candidates`: what its f64 solve is told.
#[derive(Clone, Copy, Debug)]
pub struct LaneCandidates<'a> {
    of: &'a Candidates,
    lane: usize,
}

impl Candidates {
    /// The lanes (bit `i` for lane `i`) that may meet piece `k`.
    #[inline(always)]
    pub fn lanes(&self, k: usize) -> u8 {
        self.by_piece[k.min(63)]
    }
}

impl LaneCandidates<'_> {
    /// Whether the lane may meet piece `k`.
    #[inline(always)]
    pub fn may_meet(&self, k: usize) -> bool {
        self.of.by_piece[k.min(63)] >> self.lane & 1 != 0
    }
}

/// The order a ray whose direction climbs by `d_y` meets `n` pieces listed from the bottom up
/// (a sor's segments; a lathe's usually): downwards from the top for a falling ray, so the
/// first hit found sets the bound that lets the later pieces be passed over unsolved. Either
/// order finds the same nearest root.
#[inline(always)]
pub fn along(n: usize, d_y: f64) -> impl Iterator<Item = usize> {
    let down = d_y < 0.0;
    (0..n).map(move |i| if down { n - 1 - i } else { i })
}

/// Per lane, the pieces (`bands`) the ray `o + t·d` (object space) may meet for `t` in
/// `(t_min, t_max)`, and the lanes that may meet any (`None` if none may): `whole` first, the
/// band of all of them, then each piece's for the lanes `whole` keeps.
///
/// The distance from the axis at `t` is that of the point `o_h + t·d_h` (the horizontal parts),
/// whose f32 coordinates are good to a few ulps of `|o_h| + |t|·|d_h|`, not of the squares a
/// polynomial in `t` would cancel (a primary ray's origin is tens of radii away); the test
/// widens each band by a part in 10⁵ of that.
#[inline(always)]
pub fn candidates<L: Lane>(
    whole: &Band,
    bands: &[Band],
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
) -> Option<(Candidates, u8)> {
    let ray = BandRay::new(o, d, t_min, t_max);
    let any = ray.keeps(whole);
    if any == 0 {
        return None;
    }
    let mut c = Candidates { by_piece: [0; 64] };
    for (k, b) in bands.iter().enumerate() {
        c.by_piece[k.min(63)] |= ray.keeps(b) & any;
    }
    Some((c, any))
}

/// A ray's lanes as `candidates` tests them against each band: what does not depend on the
/// band, formed once.
struct BandRay<L: Lane> {
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
    inv_dy: L,
    /// Where the distance from the axis is least (NaN or infinite for a ray along the axis),
    /// the squared distance there and its rounding (`err`).
    near: L,
    q_near: L,
    err_near: L,
    /// `|o_h|` and `|d_h|`, for `err`.
    o_len: L,
    d_len: L,
    /// The rounding of `y − o.y` in f32, over `d.y`: a slab end's error in `t`.
    y_err: L,
}

/// The padding, relative to the magnitudes rounded.
const PAD: f32 = 1e-5;

impl<L: Lane> BandRay<L> {
    #[inline(always)]
    fn new(o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> Self {
        let dh2 = d.x * d.x + d.z * d.z;
        let inv_dy = L::splat(1.0) / d.y;
        let near = -(o.x * d.x + o.z * d.z) / dh2;
        let mut r = BandRay {
            o,
            d,
            t_min,
            t_max,
            inv_dy,
            near,
            q_near: L::splat(0.0),
            err_near: L::splat(0.0),
            o_len: (o.x * o.x + o.z * o.z).sqrt(),
            d_len: dh2.sqrt(),
            y_err: (o.y.abs() + L::splat(1.0)) * inv_dy.abs(),
        };
        (r.q_near, r.err_near) = (r.q(near), r.err(near));
        r
    }

    /// The squared distance from the axis at `t`.
    #[inline(always)]
    fn q(&self, t: L) -> L {
        let (x, z) = (self.o.x + t * self.d.x, self.o.z + t * self.d.z);
        x * x + z * z
    }

    /// A bound on the rounding of the distance from the axis at `t`, widened `PAD` times.
    #[inline(always)]
    fn err(&self, t: L) -> L {
        L::splat(PAD) * (self.o_len + t.abs() * self.d_len)
    }

    /// The lanes (bit `i` for lane `i`) that may meet band `b`.
    #[inline(always)]
    fn keeps(&self, b: &Band) -> u8 {
        let (o, inf, pad) = (self.o, L::splat(f32::INFINITY), L::splat(PAD));
        // The slab's span of t, widened, then clipped to (t_min, t_max). A NaN end (a level
        // ray at the slab's height, or a ray not a number) keeps the whole line.
        let (a0, a1) = ((L::splat(b.y_lo) - o.y) * self.inv_dy, (L::splat(b.y_hi) - o.y) * self.inv_dy);
        let widen = pad * (a0.abs() + a1.abs() + self.y_err);
        let (lo, hi) = (a0.min(a1) - widen, a0.max(a1) + widen);
        let known = L::and(lo.le(lo), hi.le(hi));
        let lo = L::select(known, lo, -inf).max(self.t_min);
        let hi = L::select(known, hi, inf).min(self.t_max);
        // The band over [lo, hi]: all of it beyond r_max (both ends, and the nearest point
        // where that lies inside), or all of it within r_min (the ends: the squared distance is
        // convex in t). Every comparison that culls is false for NaN.
        let beyond_at = |q: L, e: L| {
            let r = L::splat(b.r_max) + e;
            (r * r).lt(q)
        };
        let (q_lo, q_hi, e_lo, e_hi) = (self.q(lo), self.q(hi), self.err(lo), self.err(hi));
        let near = self.near;
        let near_outside = L::or(L::or(near.le(lo), hi.le(near)), beyond_at(self.q_near, self.err_near));
        let beyond = L::and(L::and(beyond_at(q_lo, e_lo), beyond_at(q_hi, e_hi)), near_outside);
        let mut cull = L::or(hi.lt(lo), beyond);
        if b.r_min > 0.0 {
            let within_at = |q: L, e: L| {
                let r = L::splat(b.r_min) - e;
                L::and(q.lt(r * r), L::splat(0.0).lt(r))
            };
            cull = L::or(cull, L::and(within_at(q_lo, e_lo), within_at(q_hi, e_hi)));
        }
        let keep = L::not(cull);
        let mut byte = 0u8;
        for i in 0..L::WIDTH {
            byte |= (L::mask_lane(keep, i) as u8) << i;
        }
        byte
    }
}

/// The hit of a surface of revolution made of `bands`' pieces, as `hit_lanes_f64` answers it
/// (the same retries past a root that rounds onto `t_min`), but with each lane's f64 `solve`
/// told which pieces it may meet (`candidates`, its first argument), and
/// not called at all for a lane that meets none, nor for any lane when none does. `whole` is
/// the band of all of `bands` together.
#[inline(always)]
pub fn hit_lanes<L: Lane>(
    frame: &BoxFrame,
    ray: &RayLanes<L>,
    t_min: L,
    t_max: L,
    whole: &Band,
    bands: &[Band],
    solve: impl Fn(LaneCandidates, DVec3, DVec3, f64, f64) -> Option<f64>,
) -> L {
    let (o, d) = object_ray(frame, ray);
    let Some((c, any)) = candidates(whole, bands, o, d, t_min, t_max) else {
        return L::splat(MISS);
    };
    solve_left(&c, any, L::splat(MISS), o, d, t_min, t_max, solve)
}

/// The ray in object space.
#[inline(always)]
pub fn object_ray<L: Lane>(frame: &BoxFrame, ray: &RayLanes<L>) -> (V3<L>, V3<L>) {
    (ray.o.transform_point(&frame.object_from_render), ray.d.transform_vector(&frame.object_from_render))
}

/// `answers`, but for the lanes `left` (bit `i` for lane `i`), which `solve` answers one by one
/// in f64 (as `hit_lanes`): for a shape that answers its other lanes all at once.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn solve_left<L: Lane>(
    c: &Candidates,
    left: u8,
    answers: L,
    o: V3<L>,
    d: V3<L>,
    t_min: L,
    t_max: L,
    solve: impl Fn(LaneCandidates, DVec3, DVec3, f64, f64) -> Option<f64>,
) -> L {
    if left == 0 {
        return answers;
    }
    // A lane no piece can hold misses at once (no solve: `None` is a miss).
    let solved = super::solve_lanes_f64(o, d, t_min, t_max, |i, o, d, lo, hi| {
        (left >> i & 1 != 0).then(|| solve(LaneCandidates { of: c, lane: i }, o, d, lo, hi)).flatten()
    });
    L::select(L::mask_from_fn(|i| left >> i & 1 != 0), solved, answers)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_support::uniform;
    use crate::lanes::F8;
    use glam::Vec3;

    /// Seeded random bands and rays aimed at points on a band's edges (its top or bottom rim,
    /// its outer or inner wall), with origins near and far (10⁻³ to 10⁴ away), level and
    /// vertical: every lane whose ray reaches such a point inside `(t_min, t_max)` keeps the
    /// band, in eight lanes and in one; and most lanes that keep nothing are culled.
    #[test]
    fn keeps_every_band_a_ray_reaches() {
        let mut rand = uniform(0x2545_f491_4f6c_dd1d);
        let (mut checked, mut culled) = (0, 0);
        for case in 0..4000 {
            let y_lo = rand() * 2.0 - 1.0;
            let y_hi = y_lo + [0.0, 1e-6, rand()][case % 3];
            let r_min = if case % 4 == 0 { 0.0 } else { rand() * 0.5 };
            let r_max = r_min + [0.0, 1e-6, rand()][case / 3 % 3];
            let band = Band::new(y_lo, y_hi, r_min * r_min, r_max * r_max);
            let whole = Band::around(&[band]);
            let mut rays = [(Vec3::ZERO, Vec3::ZERO, 0.0f32, 0.0f32, true); 8];
            for ray in &mut rays {
                // A point on the band's boundary, or (one lane in four) anywhere.
                let a = rand() * std::f64::consts::TAU;
                let on_edge = rand() < 0.75;
                let (r, y) = match (rand() * 4.0) as u32 {
                    0 => (r_min + (r_max - r_min) * rand(), y_lo),
                    1 => (r_min + (r_max - r_min) * rand(), y_hi),
                    2 => (r_max, y_lo + (y_hi - y_lo) * rand()),
                    _ => (r_min, y_lo + (y_hi - y_lo) * rand()),
                };
                let (r, y) = if on_edge { (r, y) } else { (rand() * 2.0, rand() * 4.0 - 2.0) };
                let p = glam::DVec3::new(r * a.cos(), y, r * a.sin());
                let mut d = glam::DVec3::new(rand() - 0.5, rand() - 0.5, rand() - 0.5).normalize();
                match case % 5 {
                    0 => d.y = 0.0,
                    1 => d = glam::DVec3::Y,
                    _ => {}
                }
                let d = d.normalize();
                let dist = 10f64.powf(rand() * 7.0 - 3.0);
                let o = p - dist * d;
                let (o, d) = (o.as_vec3(), d.as_vec3());
                // The f32 ray's distance to the point, and whether the f32 ray passes within
                // rounding of the band at all: the f64 test below decides on the f32 ray.
                let t = (p - o.as_dvec3()).dot(d.as_dvec3()) / d.as_dvec3().length_squared();
                let at = o.as_dvec3() + t * d.as_dvec3();
                let w2 = at.x * at.x + at.z * at.z;
                let inside = at.y >= y_lo && at.y <= y_hi && w2 <= r_max * r_max && w2 >= r_min * r_min;
                let (lo, hi) = if rand() < 0.5 { (0.0, f32::INFINITY) } else { (t as f32 * 0.999, t as f32 * 1.001) };
                *ray = (o, d, lo, hi, inside && t > lo as f64 && t < hi as f64);
            }
            let o = V3::<F8>::from_lanes(|i| rays[i].0);
            let d = V3::<F8>::from_lanes(|i| rays[i].1);
            let (lo, hi) = (F8::from_fn(|i| rays[i].2), F8::from_fn(|i| rays[i].3));
            let wide = candidates(&whole, &[band], o, d, lo, hi);
            for (i, ray) in rays.iter().enumerate() {
                let one = candidates(&whole, &[band], V3::<f32>::from_vec3(ray.0), V3::from_vec3(ray.1), ray.2, ray.3);
                let kept_one = one.is_some_and(|(c, _)| c.by_piece[0] & 1 != 0);
                let kept = wide.is_some_and(|(c, _)| c.by_piece[0] >> i & 1 != 0);
                assert_eq!(kept, kept_one, "case {case} lane {i}");
                if ray.4 {
                    assert!(kept, "case {case} lane {i}: {ray:?} {band:?}");
                    checked += 1;
                } else if !kept {
                    culled += 1;
                }
            }
        }
        assert!(checked > 4_000 && culled > 4_000, "{checked} {culled}");
    }
}
