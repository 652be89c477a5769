//! Unit tests of the julia fractal (`super`).

use super::*;
use crate::geometry::Shape;
use crate::ray::Ray;

fn q(a: f64, b: f64, c: f64, d: f64) -> DVec4 {
    DVec4::new(a, b, c, d)
}

/// Hamilton's product, written out from ij = k, jk = i, ki = j.
fn hamilton(p: DVec4, r: DVec4) -> DVec4 {
    q(
        p.x * r.x - p.y * r.y - p.z * r.z - p.w * r.w,
        p.x * r.y + p.y * r.x + p.z * r.w - p.w * r.z,
        p.x * r.z - p.y * r.w + p.z * r.x + p.w * r.y,
        p.x * r.w + p.y * r.z - p.z * r.y + p.w * r.x,
    )
}

/// The hypercomplex product from its basis rules: ij = k, jk = −i, ki = −j, k² = 1.
fn hyper(p: DVec4, r: DVec4) -> DVec4 {
    q(
        p.x * r.x - p.y * r.y - p.z * r.z + p.w * r.w,
        p.x * r.y + p.y * r.x - p.z * r.w - p.w * r.z,
        p.x * r.z + p.z * r.x - p.y * r.w - p.w * r.y,
        p.x * r.w + p.w * r.x + p.y * r.z + p.z * r.y,
    )
}

#[test]
fn steps_are_the_algebras_products() {
    let h = q(0.3, -0.7, 0.2, 0.5);
    let close = |a: DVec4, b: DVec4| (a - b).length() < 1e-12;
    assert!(close(step(JuliaFunction::QuaternionSqr, h), hamilton(h, h)));
    assert!(close(step(JuliaFunction::QuaternionCube, h), hamilton(hamilton(h, h), h)));
    assert!(close(step(JuliaFunction::Hypercomplex(ComplexFn::Sqr), h), hyper(h, h)));
    assert!(close(step(JuliaFunction::Hypercomplex(ComplexFn::Cube), h), hyper(hyper(h, h), h)));
    // reciprocal(h)·h = 1, and pwr(2, 0) is sqr.
    let r = step(JuliaFunction::Hypercomplex(ComplexFn::Reciprocal), h);
    assert!(close(hyper(r, h), q(1.0, 0.0, 0.0, 0.0)));
    assert!(close(step(JuliaFunction::Hypercomplex(ComplexFn::Pwr(2.0, 0.0)), h), hyper(h, h)));
    // The inverse functions undo their functions near 0.
    let small = q(0.1, 0.05, -0.02, 0.03);
    for (f, g) in [
        (ComplexFn::Sin, ComplexFn::Asin),
        (ComplexFn::Cos, ComplexFn::Acos),
        (ComplexFn::Tan, ComplexFn::Atan),
        (ComplexFn::Sinh, ComplexFn::Asinh),
        (ComplexFn::Tanh, ComplexFn::Atanh),
        (ComplexFn::Exp, ComplexFn::Ln),
    ] {
        let back = step(JuliaFunction::Hypercomplex(g), step(JuliaFunction::Hypercomplex(f), small));
        assert!(close(back, small), "{f:?} then {g:?}: {back}");
    }
    let z = C(1.5, 0.4);
    let w = z.apply(ComplexFn::Acosh).apply(ComplexFn::Cosh);
    assert!((w.0 - z.0).abs() < 1e-12 && (w.1 - z.1).abs() < 1e-12);
}

/// The march with every sample iterated and the crossing bisected to f64 rounding: what
/// `solve` did before it skipped empty cells and stopped at the lane's rounding, the
/// reference it must agree with.
fn bisected(j: &Julia, o: DVec3, d: DVec3) -> Option<f64> {
    let (a, b, c) = (d.dot(d), o.dot(d), o.dot(o) - j.radius * j.radius);
    let disc = b * b - a * c;
    // From t = 0, as `solve` is asked below.
    let (lo, hi) = (((-b - disc.sqrt()) / a).max(0.0), (-b + disc.sqrt()) / a);
    if !(disc > 0.0) {
        return None;
    }
    let (dt, start) = (j.step / a.sqrt(), j.inside_object(o + lo * d));
    let mut t0 = lo;
    loop {
        let t1 = (t0 + dt).min(hi);
        if j.inside_object(o + t1 * d) != start {
            let (mut a, mut b) = (t0, t1);
            loop {
                let m = 0.5 * (a + b);
                if m <= a || m >= b {
                    return Some(b);
                }
                if j.inside_object(o + m * d) == start {
                    a = m;
                } else {
                    b = m;
                }
            }
        }
        if t1 >= hi {
            return None;
        }
        t0 = t1;
    }
}

/// Seeded random rays through julias of both algebras: the march over empty cells, bisected
/// to the lane's rounding, rounds to the f32 that bisecting to f64 rounding does, and for
/// f64 lanes gives its answer.
#[test]
fn crossings_round_as_bisection_does() {
    let param = q(-0.083, 0.0, -0.83, -0.025);
    let mut seed = 11u64;
    let mut rnd = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let to_f32: fn(f64) -> f64 = |v| v as f32 as f64;
    let exact: fn(f64) -> f64 = |v| v;
    for f in [JuliaFunction::QuaternionSqr, JuliaFunction::QuaternionCube, JuliaFunction::Hypercomplex(ComplexFn::Sqr)]
    {
        let j = Julia::new(DAffine3::IDENTITY, param, f, 8, 15.0, (DVec4::W, 0.0));
        let mut hits = 0;
        for _ in 0..300 {
            let o = DVec3::new(rnd(), rnd(), rnd()).normalize() * 3.0;
            let d = DVec3::new(rnd(), rnd(), rnd()) * 0.8 - o;
            let want = bisected(&j, o, d);
            let got = j.solve(o, d, 0.0, 100.0, to_f32, false);
            assert_eq!(got.map(to_f32), want.map(to_f32), "{f:?} from {o} along {d}");
            assert_eq!(j.solve(o, d, 0.0, 100.0, exact, false), want, "{f:?} from {o} along {d}");
            hits += want.is_some() as usize;
        }
        assert!(hits > 50, "{f:?}: {hits}");
    }
}

/// Seeded random points in the cells marked empty are outside, for both quaternion
/// functions (hypercomplex ones get no cells), and the cells mark some space empty.
#[test]
fn empty_cells_hold_no_inside_point() {
    let mut seed = 5u64;
    let mut rnd = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for f in [JuliaFunction::QuaternionSqr, JuliaFunction::QuaternionCube] {
        let j = Julia::new(DAffine3::IDENTITY, q(-0.083, 0.0, -0.83, -0.025), f, 8, 15.0, (DVec4::W, 0.0));
        let cells = j.cells.clone().expect("quaternions get cells");
        let mut empty = 0;
        for _ in 0..100_000 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * j.radius;
            if cells.empty(p) {
                empty += 1;
                assert!(!j.inside_object(p), "{f:?}: {p} is inside an empty cell");
            }
        }
        assert!(empty > 20_000, "{f:?}: {empty}");
    }
    let h = Julia::new(
        DAffine3::IDENTITY,
        q(0.2, 0.1, 0.59, -0.2),
        JuliaFunction::Hypercomplex(ComplexFn::Sqr),
        7,
        15.0,
        (DVec4::W, 0.0),
    );
    assert!(h.cells.is_none());
}

#[test]
fn with_no_parameter_the_sqr_set_is_the_unit_ball() {
    // h → h² stays bounded exactly for |h| ≤ 1 (a slow escape just outside needs many
    // iterations, so the edge is at 1 to within max_iteration's reach).
    let j = Julia::new(DAffine3::IDENTITY, DVec4::ZERO, JuliaFunction::QuaternionSqr, 40, 50.0, (DVec4::W, 0.0));
    let t = j.intersect(&Ray::new(Vec3::new(0.0, 0.0, -3.0), Vec3::Z), 1e-4, 100.0).unwrap();
    assert!((t - 2.0).abs() < 2e-3, "{t}");
    let n = j.normal_at(Vec3::new(0.0, 0.0, -(3.0 - t)));
    assert!((n - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-3, "{n}");
    assert!(j.inside_object(DVec3::new(0.5, 0.2, 0.1)) && !j.inside_object(DVec3::new(0.9, 0.5, 0.0)));
    // Leaving it from inside.
    let t = j.intersect(&Ray::new(Vec3::ZERO, Vec3::Y), 1e-4, 100.0).unwrap();
    assert!((t - 1.0).abs() < 2e-3, "{t}");
    // The slice moves through the fourth dimension: at w = 0.6 the ball's radius is 0.8.
    let s = Julia::new(DAffine3::IDENTITY, DVec4::ZERO, JuliaFunction::QuaternionSqr, 40, 50.0, (DVec4::W, 0.6));
    let t = s.intersect(&Ray::new(Vec3::ZERO, Vec3::X), 1e-4, 100.0).unwrap();
    assert!((t - 0.8).abs() < 2e-3, "{t}");
}

/// `blocks` (shadow rays: stop at the first march step that holds a crossing) misses exactly
/// where `hit` does, for seeded random rays through julias of both algebras, with limits that
/// cut some crossings off, and for rays leaving the surface as shadow rays do.
#[test]
fn blocks_as_hit_does() {
    use crate::geometry::test_support::{check_blocks, uniform};
    let mut rnd = uniform(23);
    let mut r = move || rnd() as f32 * 2.0 - 1.0;
    let param = q(-0.083, 0.0, -0.83, -0.025);
    for f in [JuliaFunction::QuaternionSqr, JuliaFunction::Hypercomplex(ComplexFn::Sqr)] {
        let placed = DAffine3::from_scale_rotation_translation(DVec3::splat(0.35), Default::default(), DVec3::Y * 0.5);
        let j = Julia::new(placed, param, f, 8, 15.0, (DVec4::W, 0.0));
        let mut rays = Vec::new();
        for k in 0..240 {
            let o = Vec3::new(r(), r(), r()).normalize() * 2.0 + Vec3::Y * 0.5;
            let d = Vec3::new(r(), r(), r()) * 0.3 + Vec3::Y * 0.5 - o;
            // A third of the rays end near the julia (t = 1 is about its middle).
            let t_max = if k % 3 == 0 { 0.8 + 0.4 * r().abs() } else { 100.0 };
            rays.push((o, d, 0.0, t_max));
            if let Some(t) = j.intersect(&Ray::new(o, d), 0.0, 100.0) {
                // A shadow ray from the hit, every way.
                let p = o + t * d;
                rays.push((p, Vec3::new(r(), r(), r()), 1e-4, 100.0));
            }
        }
        let hits = check_blocks(&j, &rays);
        assert!(hits > 40 && hits < rays.len() - 40, "{f:?}: {hits} of {}", rays.len());
    }
}
