//! Unit tests of the polynomial surfaces (`super`).

use super::*;
use crate::ray::MISS;

use crate::lanes::F8;
use crate::ray::Ray;

/// A quadric `<A,B,C>, <D,E,F>, <G,H,I>, J` as POV-Ray's order-2 coefficients.
fn quadric(q: [f64; 10]) -> [f64; 10] {
    let [a, b, c, d, e, f, g, h, i, j] = q;
    [a, d, e, g, b, f, h, c, i, j]
}

fn shape(order: usize, c: &[f64], solver: Solver) -> Poly {
    Poly::new(Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)), order, c, solver)
}

/// The bounded search finds the first root in the span, on seeded random
/// polynomials of degree 5 to 7 made from known roots (some of them double or 1e-12 or
/// 1e-6 apart, some with a complex pair, at scales 1e-4 to 1e6, over random spans): that
/// root to 1e-8 of the scale, or, where a near-double root (a graze) comes first, either
/// it or nothing there. (The critical points over Cauchy's bound, which it replaces, fail
/// this: a sextic with roots of size 5e3 gave them a spurious root at −1.3e9.)
#[test]
fn bounded_subdivision_finds_the_first_root() {
    let mut r = crate::geometry::test_support::uniform(0x0005_eed5);
    let mut found = 0;
    for case in 0..20_000 {
        let degree = 5 + case % 3;
        let scale = 10f64.powf(r() * 10.0 - 4.0);
        let mut roots: Vec<f64> = (0..degree).map(|_| (2.0 * r() - 1.0) * scale).collect();
        if case % 4 == 0 {
            roots[1] = roots[0] * (1.0 + [0.0, 1e-12, 1e-6][case % 3]);
        }
        // The odd cases trade two real roots for a complex pair.
        roots.truncate(degree - (case % 2) * 2);
        let mut c = vec![1.0];
        let mut times = |factor: &[f64]| {
            let mut next = vec![0.0; c.len() + factor.len() - 1];
            for (i, &k) in c.iter().enumerate() {
                for (j, &f) in factor.iter().enumerate() {
                    next[i + j] += k * f;
                }
            }
            c = next;
        };
        for &x in &roots {
            times(&[1.0, -x]);
        }
        if case % 2 == 1 {
            let m = scale * (0.1 + r());
            times(&[1.0, 0.3 * m, m * m]);
        }
        let (lo, hi) = match case % 5 {
            0 => (f64::NEG_INFINITY, f64::INFINITY),
            1 => (0.0, f64::INFINITY),
            _ => ((2.0 * r() - 1.0) * scale, (1.0 + 2.0 * r()) * scale),
        };
        let want = roots
            .iter()
            .copied()
            .filter(|&x| x > lo && x < hi)
            .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |m| m.min(x))));
        let got = first_root_within_bound(&c, lo, hi);
        let paired = |x: f64| roots.iter().filter(|&&y| (y - x).abs() <= 1e-5 * scale).count() >= 2;
        match (got, want) {
            (Some(a), Some(b)) if (a - b).abs() <= 1e-8 * scale => found += 1,
            (None, None) => {}
            (Some(a), Some(b)) if paired(b) && (a - b).abs() <= 1e-5 * scale => {}
            (None, Some(b)) | (Some(_), Some(b)) if paired(b) => {
                // Missed the graze: then the next root beyond it, or nothing.
                let next = roots
                    .iter()
                    .copied()
                    .filter(|&x| x > b + 2e-5 * scale && x < hi)
                    .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |m: f64| m.min(x))));
                assert!(
                    got.is_none() && next.is_none()
                        || got.zip(next).is_some_and(|(a, n)| (a - n).abs() <= 1e-8 * scale),
                    "case {case} {roots:?} in ({lo}, {hi}): {got:?}, want {want:?}"
                );
            }
            _ => panic!("case {case} {roots:?} in ({lo}, {hi}): {got:?}, want {want:?}"),
        }
    }
    assert!(found > 5_000, "{found}");
}

/// x⁶ + y⁶ + z⁶ − 1 (scenes/kernels/poly.pov's rounded cube, degree 6 by Bernstein signs
/// and Halley steps, `first_root`): on seeded random rays, many of them grazing its edges
/// and corners, a packet's lanes give a single ray's bits, and each hit is the first sign
/// change of the polynomial on a grid of step 10⁻⁴ along the ray; where the two disagree
/// the ray grazes (the polynomial's least value is within 10⁻³ of zero).
#[test]
fn sextic_packets_match_single_rays_and_brute_force() {
    let terms = term_exponents(6);
    let c: Vec<f64> = terms
        .iter()
        .map(|t| match t {
            [6, 0, 0] | [0, 6, 0] | [0, 0, 6] => 1.0,
            [0, 0, 0] => -1.0,
            _ => 0.0,
        })
        .collect();
    let q = shape(6, &c, Solver::Fast);
    let mut r = crate::geometry::test_support::uniform(0x5e71_c0be);
    let (mut hits, mut grazes) = (0, 0);
    for _ in 0..60 {
        let rays: [Ray; 8] = std::array::from_fn(|_| {
            let o = Vec3::new(r() as f32 * 4.0 - 2.0, r() as f32 * 4.0 - 2.0, 0.0);
            let at = Vec3::new(r() as f32 * 2.4 - 1.2, r() as f32 * 2.4 - 1.2, 10.0 + r() as f32 * 2.0 - 1.0);
            Ray::new(o, (at - o).normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let wide = q.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, ray) in rays.iter().enumerate() {
            let single = q.hit(&ray.lanes(), 0.0, MISS);
            assert_eq!(wide.get(i).to_bits(), single.to_bits());
            let (o, d) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
            let f = |t: f64| {
                let p = o + d * t;
                q.eval([p.x, p.y, p.z - 10.0])
            };
            let (mut want, mut least, mut prev) = (None, f64::INFINITY, f(7.0));
            for k in 1..60_000 {
                let t = 7.0 + k as f64 * 1e-4;
                let v = f(t);
                least = least.min(v);
                if want.is_none() && (v < 0.0) != (prev < 0.0) {
                    want = Some(t);
                }
                prev = v;
            }
            let got = (single < MISS).then_some(single as f64);
            match (got, want) {
                (Some(a), Some(b)) if (a - b).abs() <= 2e-4 => hits += 1,
                (None, None) => {}
                _ => {
                    assert!(least.abs() < 1e-3, "{ray:?}: {got:?}, grid {want:?}, least {least}");
                    grazes += 1;
                }
            }
        }
    }
    assert!(hits > 150 && grazes < 20, "{hits} hits, {grazes} grazes");
}

#[test]
fn coefficient_order_is_povrays() {
    assert_eq!(term_count(3), 20);
    assert_eq!(term_count(4), 35);
    let cubic = term_exponents(3);
    assert_eq!(cubic.len(), 20);
    assert_eq!(&cubic[..6], &[[3, 0, 0], [2, 1, 0], [2, 0, 1], [2, 0, 0], [1, 2, 0], [1, 1, 1]]);
    assert_eq!(cubic[10], [0, 3, 0]);
    assert_eq!(cubic[19], [0, 0, 0]);
    assert_eq!(
        term_exponents(2),
        vec![
            [2, 0, 0],
            [1, 1, 0],
            [1, 0, 1],
            [1, 0, 0],
            [0, 2, 0],
            [0, 1, 1],
            [0, 1, 0],
            [0, 0, 2],
            [0, 0, 1],
            [0, 0, 0]
        ]
    );
}

#[test]
fn quadric_sphere_and_cylinder() {
    for solver in [Solver::Fast, Solver::Sturm] {
        // x² + y² + z² − 4: a sphere of radius 2, bounded.
        let s = shape(2, &quadric([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0]), solver);
        let r = Ray::new(Vec3::ZERO, Vec3::Z);
        let t = s.intersect(&r, 0.0, MISS).expect("sphere");
        assert!((t - 8.0).abs() < 1e-5, "{t}");
        assert!((s.normal_at(r.at(t)) + Vec3::Z).length() < 1e-5);
        let (lo, hi) = s.bounds();
        assert!((lo - Vec3::new(-2.0, -2.0, 8.0)).abs().max_element() < 1e-4, "{lo}");
        assert!((hi - Vec3::new(2.0, 2.0, 12.0)).abs().max_element() < 1e-4, "{hi}");
        assert!(s.inside(V3::from_vec3(Vec3::new(0.0, 1.0, 10.0))));
        assert!(!s.inside(V3::from_vec3(Vec3::new(0.0, 3.0, 10.0))));
        // x² + y² − 1: the cylinder along z, unbounded; a ray along its axis from inside
        // never meets it, one across meets its wall.
        let c = shape(2, &quadric([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]), solver);
        assert!(c.bounds().0.x.is_infinite());
        assert_eq!(c.intersect(&Ray::new(Vec3::new(0.5, 0.0, 0.0), Vec3::Z), 0.0, MISS), None);
        let t = c.intersect(&Ray::new(Vec3::new(-5.0, 0.0, 1e4), Vec3::X), 0.0, MISS).expect("wall");
        assert!((t - 4.0).abs() < 1e-5, "{t}");
        // Grazing: tangent to the wall at y = 1.
        let g = c.intersect(&Ray::new(Vec3::new(-5.0, 1.0 - 1e-4, 0.0), Vec3::X), 0.0, MISS).expect("graze");
        assert!((g - (5.0 - (1.0f32 - (1.0 - 1e-4f32).powi(2)).sqrt())).abs() < 1e-3, "{g}");
    }
}

#[test]
fn paraboloid_along_its_axis_and_hyperboloid_scales() {
    // z = x² + y² (x² + y² − z = 0): a ray down the axis meets the vertex only.
    let c = quadric([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
    for solver in [Solver::Fast, Solver::Sturm] {
        let p = Poly::new(Affine3A::IDENTITY, 2, &c, solver);
        let t = p.intersect(&Ray::new(Vec3::new(0.0, 0.0, -3.0), Vec3::Z), 0.0, MISS).expect("vertex");
        assert!((t - 3.0).abs() < 1e-5, "{solver:?} {t}");
        assert!((p.normal_at(Vec3::ZERO) + Vec3::Z).length() < 1e-5);
        // Scaled by 1e-4 and 1e5 with the ray: the same distances in those units.
        for s in [1e-4f32, 1e5] {
            let q = Poly::new(Affine3A::from_scale(Vec3::splat(s)), 2, &c, solver);
            let t = q.intersect(&Ray::new(Vec3::new(0.5 * s, 0.0, 2.0 * s), -Vec3::Z), 0.0, MISS).expect("bowl");
            assert!((t / s - 1.75).abs() < 1e-5, "{solver:?} {s}: {}", t / s);
        }
    }
}

#[test]
fn quartic_torus_matches_the_torus_and_packets_match_single_rays() {
    // (x² + y² + z² + R² − r²)² − 4R²(x² + z²) with R = 2, r = 0.5, as 35 coefficients.
    let (r2, big) = (0.25, 4.0);
    let e = big - r2;
    let mut c = vec![0.0; 35];
    let terms = term_exponents(4);
    let mut set = |x: u8, y: u8, z: u8, v: f64| {
        let i = terms.iter().position(|t| *t == [x, y, z]).expect("term");
        c[i] += v;
    };
    for (a, b) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)] {
        let mut ex = [0u8; 3];
        ex[a] += 2;
        ex[b] += 2;
        set(ex[0], ex[1], ex[2], if a == b { 1.0 } else { 2.0 });
    }
    set(2, 0, 0, 2.0 * e - 4.0 * big);
    set(0, 2, 0, 2.0 * e);
    set(0, 0, 2, 2.0 * e - 4.0 * big);
    set(0, 0, 0, e * e);
    let torus = crate::geometry::torus::Torus::new(
        Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)) * Affine3A::from_scale(Vec3::splat(2.0)),
        0.25,
    );
    let rays: [Ray; 8] = std::array::from_fn(|i| {
        let o = Vec3::new(i as f32 * 0.6 - 2.0, 0.1 * i as f32, 0.0);
        Ray::new(o, (Vec3::new(1.5, 0.2, 10.0) - o).normalize())
    });
    for solver in [Solver::Fast, Solver::Sturm] {
        let q = shape(4, &c, solver);
        for r in &rays {
            let (a, b) = (q.intersect(r, 0.0, MISS), torus.intersect(r, 0.0, MISS));
            assert_eq!(a.is_some(), b.is_some());
            if let (Some(a), Some(b)) = (a, b) {
                assert!((a - b).abs() < 1e-4, "{solver:?}: {a} vs {b}");
                let (na, nb) = (q.normal_at(r.at(a)), torus.normal_at(r.at(b)));
                assert!((na - nb).length() < 1e-3, "{na} vs {nb}");
            }
        }
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let wide = q.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, r) in rays.iter().enumerate() {
            assert_eq!(wide.get(i).to_bits(), q.hit(&r.lanes(), 0.0, MISS).to_bits());
        }
        assert!(
            q.inside(V3::from_vec3(Vec3::new(2.0, 0.0, 10.0))) && !q.inside(V3::from_vec3(Vec3::new(0.0, 0.0, 10.0)))
        );
    }
}
