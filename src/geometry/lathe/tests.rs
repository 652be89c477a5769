//! The lathe's tests: its solves against each other (scalar, eight lanes, packets, single rays,
//! shadow rays) and against its inside test.

use super::*;
use crate::desc::SplineKind;
use crate::geometry::spline::open_pieces;
use crate::ray::Ray;

/// A cylinder of radius 1 from y = 0 to 2 as a closed linear outline.
fn can(xf: DAffine3) -> Lathe {
    let p = |r: f64, y: f64| DVec2::new(r, y);
    let pts = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 2.0), p(0.0, 2.0)];
    Lathe::new(xf, &open_pieces(SplineKind::Linear, &pts).expect("lathe"))
}

#[test]
fn walls_level_rays_axis_rays_and_extremes() {
    let l = can(DAffine3::IDENTITY);
    let hit = |o: Vec3, d: Vec3| l.intersect(&Ray::new(o, d.normalize()), 0.0, f32::INFINITY);
    // Level ray (d.y = 0): the wall at x = -1.
    assert!((hit(Vec3::new(-5.0, 1.0, 0.0), Vec3::X).expect("level") - 4.0).abs() < 1e-5);
    assert!((l.normal_at(Vec3::new(-1.0, 1.0, 0.0)) - -Vec3::X).length() < 1e-5);
    // Slanted: enters the wall at y = 1.5.
    let t = hit(Vec3::new(0.0, 2.5, -2.0), Vec3::new(0.0, -1.0, 1.0)).expect("slant");
    assert!((t - 2f32.sqrt()).abs() < 1e-4, "{t}");
    // Down the axis: the top disc of the outline.
    assert!((hit(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y).expect("axis") - 3.0).abs() < 1e-5);
    assert!((l.normal_at(Vec3::new(0.3, 2.0, 0.0)) - Vec3::Y).length() < 1e-5);
    // Beside it, parallel to the axis: a miss.
    assert_eq!(hit(Vec3::new(1.5, 5.0, 0.0), -Vec3::Y), None);
    // Grazing the wall: a miss or a hit on it.
    let g = hit(Vec3::new(-5.0, 1.0, 1.0), Vec3::X);
    assert!(g.is_none_or(|t| (t - 5.0).abs() < 1e-2), "{g:?}");
    assert!(l.inside(V3::from_vec3(Vec3::new(0.5, 1.0, 0.2))) && !l.inside(V3::from_vec3(Vec3::new(1.5, 1.0, 0.0))));
    for (s, at) in [(1e-4, 0.0), (1e5, 0.0), (1.0, 1e6)] {
        let xf = DAffine3::from_translation(DVec3::splat(at)) * DAffine3::from_scale(DVec3::splat(s));
        let l = can(xf);
        let o = Vec3::new(-5.0, 1.0, 0.0) * s as f32 + Vec3::splat(at as f32);
        let t = l.intersect(&Ray::new(o, Vec3::X), 0.0, f32::INFINITY).expect("far");
        let want = 4.0 * s as f32;
        assert!((t - want).abs() <= want * 1e-4 + at as f32 * 1e-6, "{s} {at}: {t}");
    }
}

/// The straight pieces solved eight lanes at once (`lathe_linear`) give the scalar solve's
/// bits, in packets and single rays, over seeded random rays at the kernel vase (scaled,
/// moved, seen from near and far), some level with the axis (left to the scalar solve),
/// some nearly so, some along it.
#[test]
fn cones_give_the_scalar_solves_bits() {
    use crate::lanes::F8;
    use crate::ray::MISS;
    let p = |r: f64, y: f64| DVec2::new(r, y);
    let vase = [p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
    let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1)) * DAffine3::from_scale(DVec3::splat(2.0));
    let wide = Lathe::new(xf, &open_pieces(SplineKind::Linear, &vase).expect("lathe"));
    assert_eq!(wide.cones.len(), wide.pieces.len());
    let scalar = Lathe { cones: Vec::new(), ..wide.clone() };
    let mut rand = crate::geometry::test_support::uniform(0x94d0_49bb_1331_11ebu64);
    let (lo, hi) = wide.bounds();
    let mut hits = 0;
    for case in 0..2000 {
        let rays: [Ray; 8] = std::array::from_fn(|i| {
            let at = |a: f64, b: f64, c: f64| lo + (hi - lo) * Vec3::new(a as f32, b as f32, c as f32);
            let far = [1.0, 30.0][case % 2];
            let o = at(rand() * 1.4 - 0.2, rand() * 1.4 - 0.2, rand() * 1.4 - 0.2 - far);
            let mut d = (at(rand(), rand(), rand()) - o).normalize();
            match (case + i) % 7 {
                0 => d.y = 0.0,
                1 => d.y *= 1e-9,
                2 => d = Vec3::new(0.0, -1.0, 0.0),
                _ => {}
            }
            Ray::new(o, d.normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let t_min = F8::from_fn(|i| [0.0, 0.5, 2.0][(case + i) % 3]);
        let (a, b) = (wide.hit(&packet, t_min, F8::splat(MISS)), scalar.hit(&packet, t_min, F8::splat(MISS)));
        for (i, r) in rays.iter().enumerate() {
            let one = wide.hit(&r.lanes(), t_min.get(i), MISS);
            assert_eq!(a.get(i).to_bits(), b.get(i).to_bits(), "case {case} lane {i}: {r:?}");
            assert_eq!(one.to_bits(), b.get(i).to_bits(), "case {case} lane {i}: {r:?}");
            hits += usize::from(one != MISS);
        }
    }
    assert!(hits > 2000, "{hits}");
}

/// `blocks` misses exactly where `hit` does for the curved kernel vases: seeded random rays
/// at them, a third ending inside their box, and shadow rays leaving their hits every way.
#[test]
fn blocks_as_hit_does() {
    use crate::geometry::test_support::{blocks_rays, check_blocks};
    let p = |r: f64, y: f64| DVec2::new(r, y);
    let vase = [p(0.0, -0.1), p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
    for (kind, pts) in [(SplineKind::Quadratic, &vase[..6]), (SplineKind::Cubic, &vase[..])] {
        let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1));
        let l = Lathe::new(xf, &open_pieces(kind, pts).expect("lathe"));
        let (lo, hi) = l.bounds();
        let rays = blocks_rays(&l, lo, hi, 400, 77);
        let hits = check_blocks(&l, &rays);
        assert!(hits > 100 && hits < rays.len() - 100, "{kind:?}: {hits} of {}", rays.len());
    }
}

/// Every spline kind of the kernel vase (each outline closed by the axis), seeded random rays from around it: eight-lane
/// packets give the single rays' distances bit for bit, and a ray from a point outside
/// crosses the surface an even number of times, from inside an odd number (grazing rays
/// and starts on the surface decide nothing and are passed over).
#[test]
fn packets_match_single_rays_and_crossings_match_inside() {
    use crate::lanes::F8;
    use crate::ray::MISS;
    let p = |r: f64, y: f64| DVec2::new(r, y);
    let vase = [p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
    let cubic = [&[p(0.0, -0.1)][..], &vase, &[p(0.0, 1.05)]].concat();
    let bezier =
        [p(0.0, 0.0), p(0.6, 0.0), p(0.1, 0.5), p(0.45, 0.75), p(0.45, 0.75), p(0.3, 1.0), p(0.2, 0.9), p(0.0, 0.95)];
    let mut seed = 0x853c_49e6_748f_ea9bu64;
    let mut rand = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 40) as f32 / (1u32 << 24) as f32
    };
    let mut checked = 0;
    for (kind, pts) in [
        (SplineKind::Linear, &vase[..]),
        (SplineKind::Quadratic, &cubic[..cubic.len() - 1]),
        (SplineKind::Cubic, &cubic[..]),
        (SplineKind::Bezier, &bezier[..]),
    ] {
        let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1)) * DAffine3::from_scale(DVec3::splat(2.0));
        let l = Lathe::new(xf, &open_pieces(kind, pts).expect("lathe"));
        let (lo, hi) = l.bounds();
        for _ in 0..300 {
            let at = |t: Vec3| lo + (hi - lo) * t;
            let rays: [Ray; 8] = std::array::from_fn(|_| {
                let o = at(Vec3::new(rand(), rand(), rand()) * 1.4 - Vec3::splat(0.2));
                let target = at(Vec3::new(rand(), rand(), rand()));
                Ray::new(o, (target - o).normalize())
            });
            let packet = RayLanes::<F8> {
                o: V3::from_lanes(|i| rays[i].origin),
                d: V3::from_lanes(|i| rays[i].dir),
                inv: V3::from_lanes(|i| rays[i].inv_dir),
            };
            let wide = l.hit(&packet, F8::splat(0.0), F8::splat(MISS));
            for (i, r) in rays.iter().enumerate() {
                let single = l.hit(&r.lanes(), 0.0, MISS);
                assert_eq!(wide.get(i).to_bits(), single.to_bits(), "{kind:?} lane {i}");
                let mut crossings = Vec::new();
                let mut t = 0.0;
                while crossings.len() < 16 {
                    let Some(next) = l.intersect(r, t, f32::INFINITY) else { break };
                    crossings.push(next);
                    t = next;
                }
                let scale = 1.0 + r.origin.length();
                if crossings.first().is_some_and(|&c| c < 1e-3 * scale)
                    || crossings.windows(2).any(|w| w[1] - w[0] < 1e-3 * scale)
                {
                    continue;
                }
                let inside = l.inside(V3::from_vec3(r.origin));
                assert_eq!(inside, crossings.len() % 2 == 1, "{kind:?} {r:?}: {crossings:?}");
                checked += 1;
            }
        }
    }
    assert!(checked > 8000, "{checked}");
}

/// The quadratic kernel vase (each outline point of `lathe_quadratic.pov`), scaled and moved.
fn quadratic_vase() -> (Lathe, Vec<Piece>) {
    let p = |r: f64, y: f64| DVec2::new(r, y);
    let pts = [p(0.0, -0.1), p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
    let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1)) * DAffine3::from_scale(DVec3::splat(2.0));
    let outline: Vec<Piece> =
        open_pieces(SplineKind::Quadratic, &pts).expect("lathe").iter().map(|q| q.map(|v| 2.0 * v)).collect();
    let l = Lathe::new(xf, &open_pieces(SplineKind::Quadratic, &pts).expect("lathe"));
    assert!(!l.quads.is_empty() && l.cones.is_empty());
    (l, outline)
}

/// The nearest crossing in `(lo, hi)` of the object-space ray `o + s·d` with the lathe's
/// pieces, by brute force: each piece's quartic sampled at 4096 points of its parameter over
/// the part of it at the heights the ray passes within the lathe's (unit) box, each sign change
/// bisected to the end. (Sampled over the whole piece, a ray nearly level with the axis passes
/// it within less than a sample.)
fn brute_force(l: &Lathe, o: DVec3, d: DVec3, lo: f64, hi: f64) -> Option<f64> {
    let r = PieceRay::new(o, d);
    let (mut s0, mut s1) = (lo, hi.min(1e30));
    for (oa, da) in [(o.x, d.x), (o.y, d.y), (o.z, d.z)] {
        if da != 0.0 {
            let (u, v) = ((-1.01 - oa) / da, (1.01 - oa) / da);
            (s0, s1) = (s0.max(u.min(v)), s1.min(u.max(v)));
        } else if oa.abs() > 1.01 {
            return None;
        }
    }
    if s0 >= s1 {
        return None;
    }
    let (ya, yb) = (o.y + s0 * d.y, o.y + s1 * d.y);
    let mut best: Option<f64> = None;
    for (p, sq) in l.pieces.iter().zip(&l.squares) {
        // Where the piece's height (monotone) reaches `y`, clamped to [0, 1].
        let rising = p.at(1.0).y > p.at(0.0).y;
        let t_of = |y: f64| {
            let (mut a, mut b) = (0.0, 1.0);
            for _ in 0..80 {
                let m = 0.5 * (a + b);
                if (p.at(m).y < y) == rising {
                    a = m;
                } else {
                    b = m;
                }
            }
            a
        };
        let (ta, tb) = (t_of(ya), t_of(yb));
        let (ta, tb) = ((ta.min(tb) - 1e-9).max(0.0), (ta.max(tb) + 1e-9).min(1.0));
        let f = |t: f64| {
            let (mut v, mut tk) = (r.k_1, 1.0);
            for j in 0..=4 {
                v += (r.k_y2 * sq.y2[j] + r.k_y * sq.y[j] - r.k_r2 * sq.r2[j]) * tk;
                tk *= t;
            }
            v
        };
        const N: usize = 4096;
        let (mut t0, mut f0) = (ta, f(ta));
        for i in 1..=N {
            let t1 = ta + (tb - ta) * i as f64 / N as f64;
            let f1 = f(t1);
            if (f0 <= 0.0) != (f1 <= 0.0) {
                let (mut a, mut b) = (t0, t1);
                for _ in 0..80 {
                    let m = 0.5 * (a + b);
                    if (f(m) <= 0.0) == (f0 <= 0.0) {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                let s = (p.at(0.5 * (a + b)).y - o.y) / d.y;
                if s > lo && s < hi && best.is_none_or(|b| s < b) {
                    best = Some(s);
                }
            }
            (t0, f0) = (t1, f1);
        }
    }
    best
}

/// The quadratic pieces solved eight lanes at once (`lathe_quartic`, Ferrari) against the
/// scalar solve (Bernstein isolation) and a brute-force search, on seeded random rays at the
/// kernel vase from near and far, some nearly level with the axis, some along it: packets give
/// the single rays' bits, and all three agree to f32 rounding but on a handful of grazing rays.
#[test]
fn quartics_agree_with_scalar_and_brute_force() {
    use crate::lanes::F8;
    let (wide, _) = quadratic_vase();
    let scalar = Lathe { quads: Vec::new(), ..wide.clone() };
    let mut rand = crate::geometry::test_support::uniform(0x2f1a_77c3_9e04_b5d1);
    let (lo, hi) = wide.bounds();
    let (mut hits, mut lanes, mut off_scalar, mut off_brute) = (0, 0, 0, 0);
    for case in 0..1500 {
        let rays: [Ray; 8] = std::array::from_fn(|i| {
            let at = |a: f64, b: f64, c: f64| lo + (hi - lo) * Vec3::new(a as f32, b as f32, c as f32);
            let far = [0.0, 1.0, 30.0][case % 3];
            let o = at(rand() * 1.4 - 0.2, rand() * 1.4 - 0.2, rand() * 1.4 - 0.2 - far);
            let mut d = (at(rand(), rand(), rand()) - o).normalize();
            match (case + i) % 9 {
                0 => d.y *= 1e-3,
                1 => d = Vec3::new(0.0, -1.0, 0.0),
                _ => {}
            }
            Ray::new(o, d.normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let t_min = F8::from_fn(|i| [0.0, 0.5, 2.0][(case + i) % 3]);
        let a = wide.hit(&packet, t_min, F8::splat(MISS));
        let b = scalar.hit(&packet, t_min, F8::splat(MISS));
        for (i, r) in rays.iter().enumerate() {
            let one = wide.hit(&r.lanes(), t_min.get(i), MISS);
            assert_eq!(a.get(i).to_bits(), one.to_bits(), "case {case} lane {i}: {r:?}");
            let (o, d) = object_ray(&wide.frame, &r.lanes());
            let (o, d) = (o.vec3().as_dvec3(), d.vec3().as_dvec3());
            let brute = brute_force(&wide, o, d, t_min.get(i) as f64, MISS as f64).map_or(MISS, |s| s as f32);
            let near = |x: f32, y: f32| (x == MISS && y == MISS) || (x - y).abs() <= 1e-5 * (1.0 + x.abs());
            off_scalar += usize::from(!near(one, b.get(i)));
            off_brute += usize::from(!near(one, brute));
            if !near(one, brute) && off_brute < 6 {
                eprintln!("{r:?} {} one {one} scalar {} brute {brute}", t_min.get(i), b.get(i));
            }
            hits += usize::from(one != MISS);
            lanes += 1;
        }
    }
    assert!(hits > 3000, "{hits} of {lanes}");
    assert!(off_scalar * 1000 <= lanes && off_brute * 1000 <= lanes, "{off_scalar} {off_brute} of {lanes}");
}

/// Rays tangent to the quadratic vase (through a point of its surface along its tangent plane:
/// a double root of the piece's quartic, which the closed form declines to the scalar solve)
/// and rays just beside them: packets give the single rays' bits, `blocks` misses exactly
/// where `hit` does, and every hit lies on the surface.
#[test]
fn grazing_rays_on_quadratic_pieces() {
    use crate::geometry::spline::closest_t;
    use crate::geometry::test_support::check_blocks;
    use crate::lanes::F8;
    let (l, outline) = quadratic_vase();
    let centre = DVec3::new(0.3, -0.2, 0.1);
    let mut rand = crate::geometry::test_support::uniform(0x51ed_2701_a3c4_880f);
    let mut rays = Vec::new();
    for case in 0..800 {
        let p = &outline[case % outline.len()];
        let t = 0.05 + 0.9 * rand();
        let (w, tan) = (p.at(t), p.tangent(t).normalize());
        let phi = rand() * std::f64::consts::TAU;
        let (c, s) = (phi.cos(), phi.sin());
        let at = centre + DVec3::new(w.x * c, w.y, w.x * s);
        let around = DVec3::new(-s, 0.0, c);
        let along = DVec3::new(tan.x * c, tan.y, tan.x * s);
        let theta = 0.2 + 1.2 * rand();
        let dir = (theta.cos() * around + theta.sin() * along).normalize();
        // Beside the tangent point by up to a part in 10⁶ of the vase, outwards or in.
        let normal = DVec3::new(tan.y * c, -tan.x, tan.y * s);
        let off = [0.0, 1e-7, -1e-7, 1e-6][case % 4] * (rand() - 0.5);
        let o = at + off * normal - 3.0 * dir;
        rays.push((o.as_vec3(), dir.as_vec3(), 0.0f32, f32::INFINITY));
    }
    let mut hits = 0;
    for chunk in rays.chunks_exact(8) {
        let packet = RayLanes::<F8>::new(V3::from_lanes(|i| chunk[i].0), V3::from_lanes(|i| chunk[i].1));
        let wide = l.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, &(o, d, _, _)) in chunk.iter().enumerate() {
            let ray = Ray::new(o, d);
            let one = l.hit(&ray.lanes(), 0.0, MISS);
            assert_eq!(wide.get(i).to_bits(), one.to_bits(), "{o} {d}");
            if one == MISS {
                continue;
            }
            hits += 1;
            let q = ray.at(one).as_dvec3() - centre;
            let w = DVec2::new((q.x * q.x + q.z * q.z).sqrt(), q.y);
            let off = outline.iter().map(|p| (p.at(closest_t(p, w)) - w).length()).fold(f64::INFINITY, f64::min);
            assert!(off < 1e-4, "{o} {d}: hit {one} lies {off} off the surface");
        }
    }
    assert!(hits > 400, "{hits}");
    check_blocks(&l, &rays);
}
