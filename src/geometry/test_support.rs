//! What the shape tests share: a seeded random source, polynomials of chosen roots and a prism
//! outline with many pieces.

use glam::DVec2;

use super::spline::{closed_pieces, Piece};
use crate::desc::SplineKind;

/// Uniform numbers in [0, 1) from an xorshift of `seed`: the same sequence on every run.
pub fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Coefficients of `scale·∏ (x − r)`, highest power first.
pub fn from_roots(roots: &[f64], scale: f64) -> Vec<f64> {
    let mut c = vec![scale];
    for &r in roots {
        let mut next = vec![0.0; c.len() + 1];
        for (i, &k) in c.iter().enumerate() {
            next[i] += k;
            next[i + 1] -= k * r;
        }
        c = next;
    }
    c
}

/// A linear star with a cubic hole in it: many pieces, some level, of two kinds.
pub fn star_with_hole() -> Vec<Piece> {
    let q = |x: f64, z: f64| DVec2::new(x, z);
    let star = [q(0.45, 0.0), q(0.12, 0.12), q(0.0, 0.45), q(-0.12, 0.12), q(-0.45, 0.0), q(-0.12, -0.12)];
    let mut pts: Vec<DVec2> = star.into();
    pts.extend([q(0.0, -0.45), q(0.12, -0.12), q(0.45, 0.0)]);
    let mut pieces = closed_pieces(SplineKind::Linear, &pts).expect("star").0;
    let hole = [q(0.1, 0.0), q(0.0, 0.05), q(-0.1, 0.0), q(0.0, -0.05), q(0.1, 0.0), q(0.0, 0.05), q(-0.1, 0.0)];
    pieces.extend(closed_pieces(SplineKind::Cubic, &hole).expect("hole").0);
    pieces
}

/// Checks `Shape::blocks` against `Shape::hit` on `rays` (render space: origin, direction,
/// `t_min`, `t_max`), one f32 ray at a time and eight to a packet: `MISS` exactly where `hit`
/// misses, and elsewhere a `t` in `(t_min, t_max]`. Answers how many rays hit, so that a caller
/// can check its rays tested something.
pub fn check_blocks<S: crate::geometry::Shape>(shape: &S, rays: &[(glam::Vec3, glam::Vec3, f32, f32)]) -> usize {
    use crate::lanes::{Lane, F8, V3};
    use crate::ray::{Ray, RayLanes, MISS};
    let mut hits = 0;
    for (k, &(o, d, lo, hi)) in rays.iter().enumerate() {
        let ray = Ray::new(o, d).lanes();
        let (hit, blocks) = (shape.hit(&ray, lo, hi), shape.blocks(&ray, lo, hi));
        assert_eq!(hit == MISS, blocks == MISS, "ray {k}: hit {hit}, blocks {blocks}, from {o} along {d}");
        assert!(blocks == MISS || (blocks > lo && blocks <= hi), "ray {k}: blocks {blocks} outside ({lo}, {hi}]");
        hits += (hit != MISS) as usize;
    }
    for chunk in rays.chunks_exact(8) {
        let packet = RayLanes::<F8>::new(V3::from_lanes(|i| chunk[i].0), V3::from_lanes(|i| chunk[i].1));
        let (lo, hi) = (F8::from_fn(|i| chunk[i].2), F8::from_fn(|i| chunk[i].3));
        let (hit, blocks) = (shape.hit(&packet, lo, hi), shape.blocks(&packet, lo, hi));
        for i in 0..8 {
            let one = shape.blocks(&Ray::new(chunk[i].0, chunk[i].1).lanes(), chunk[i].2, chunk[i].3);
            assert_eq!(hit.get(i) == MISS, blocks.get(i) == MISS, "packet lane {i}: {:?}", chunk[i]);
            assert_eq!(blocks.get(i).to_bits(), one.to_bits(), "packet lane {i} against one ray: {:?}", chunk[i]);
        }
    }
    hits
}

/// Rays for `check_blocks` at a shape with bounds `lo`, `hi` (render space): `count` seeded rays
/// from around the box towards a point in it, every third ending somewhere inside its reach
/// (`t_max` in (0, 1)), and from each of those rays' hits (`shape.intersect`) a shadow ray leaving
/// every way.
pub fn blocks_rays<S: crate::geometry::Shape>(
    shape: &S,
    lo: glam::Vec3,
    hi: glam::Vec3,
    count: usize,
    seed: u64,
) -> Vec<(glam::Vec3, glam::Vec3, f32, f32)> {
    use glam::Vec3;
    let mut rnd = uniform(seed);
    let mut r = move || rnd() as f32;
    let mut rays = Vec::new();
    for k in 0..count {
        let at = |t: Vec3| lo + (hi - lo) * t;
        let o = at(Vec3::new(r(), r(), r()) * 3.0 - Vec3::splat(1.0));
        let d = at(Vec3::new(r(), r(), r())) - o;
        let t_max = if k % 3 == 0 { r() } else { 100.0 };
        rays.push((o, d, 0.0, t_max));
        if let Some(t) = shape.intersect(&crate::ray::Ray::new(o, d), 0.0, 100.0) {
            rays.push((o + t * d, Vec3::new(r(), r(), r()) * 2.0 - Vec3::ONE, 1e-4, 100.0));
        }
    }
    rays
}
