//! The prism's tests: sides, caps, conic sweeps and packets against brute force.

use super::*;
use crate::desc::SplineKind;
use crate::geometry::spline::closed_pieces;
use crate::geometry::test_support::*;
use crate::lanes::F8;
use crate::ray::Ray;

fn square(kind: SplineKind) -> Vec<Piece> {
    let p = |x: f64, z: f64| DVec2::new(x, z);
    let pts: Vec<DVec2> = match kind {
        SplineKind::Linear => vec![p(-1.0, -1.0), p(1.0, -1.0), p(1.0, 1.0), p(-1.0, 1.0), p(-1.0, -1.0)],
        _ => unreachable!(),
    };
    closed_pieces(kind, &pts).expect("square").0
}

fn prism(xf: DAffine3, conic: bool, open: bool) -> Prism {
    Prism::new(xf, &square(SplineKind::Linear), if conic { 1.0 } else { 0.0 }, 2.0, conic, open)
}

fn inside(p: &Prism, q: Vec3) -> bool {
    p.inside(V3::from_vec3(q))
}

fn hit(p: &Prism, o: Vec3, d: Vec3) -> Option<f32> {
    p.intersect(&Ray::new(o, d.normalize()), 0.0, f32::INFINITY)
}

#[test]
fn sides_caps_open_and_conic() {
    let p = prism(DAffine3::IDENTITY, false, false);
    assert!((hit(&p, Vec3::new(0.0, 1.0, -5.0), Vec3::Z).expect("side") - 4.0).abs() < 1e-5);
    assert!((p.normal_at(Vec3::new(0.0, 1.0, -1.0)) - -Vec3::Z).length() < 1e-5);
    assert!((hit(&p, Vec3::new(0.2, 5.0, 0.1), -Vec3::Y).expect("cap") - 3.0).abs() < 1e-5);
    assert!((p.normal_at(Vec3::new(0.2, 2.0, 0.1)) - Vec3::Y).length() < 1e-5);
    // Along the sweep axis outside the outline: a miss.
    assert_eq!(hit(&p, Vec3::new(1.5, 5.0, 0.0), -Vec3::Y), None);
    let open = prism(DAffine3::IDENTITY, false, true);
    // Open: down through the top hits the bottom... no: no caps at all, the inside of a wall.
    assert_eq!(hit(&open, Vec3::new(0.2, 5.0, 0.1), -Vec3::Y), None);
    assert!((hit(&open, Vec3::new(0.0, 1.0, 0.0), Vec3::Z).expect("wall from inside") - 1.0).abs() < 1e-5);
    // Conic: the square scaled by y, from y = 1 to 2; at y = 1.5 the half-width is 1.5.
    let c = prism(DAffine3::IDENTITY, true, false);
    assert!((hit(&c, Vec3::new(0.0, 1.5, -5.0), Vec3::Z).expect("conic side") - 3.5).abs() < 1e-5);
    let n = c.normal_at(Vec3::new(0.0, 1.5, -1.5));
    assert!((n - Vec3::new(0.0, -1.0, -1.0).normalize()).length() < 1e-5, "{n}");
    assert!((hit(&c, Vec3::new(1.8, 5.0, 0.0), -Vec3::Y).expect("top cap reaches 2") - 3.0).abs() < 1e-5);
    assert!(inside(&c, Vec3::new(1.4, 1.5, 0.0)) && !inside(&c, Vec3::new(1.6, 1.5, 0.0)));
}

/// Seeded random rays (some starting inside, some level) at a star with a curved hole, closed
/// and conic: the nearest hit is the least of the caps (each by even-odd over all pieces) and
/// the sides (the open prism's), as the entering-cap-first order must keep; eight-lane
/// packets give the single rays' bits.
#[test]
fn caps_and_sides_against_brute_force_and_packets() {
    use crate::geometry::spline::even_odd;
    let mut rand = uniform(0x2545_f491_4f6c_dd1du64);
    let pieces = star_with_hole();
    let mut caps_hit = 0;
    for conic in [false, true] {
        let (h1, h2) = if conic { (0.5, 1.5) } else { (0.0, 0.6) };
        let closed = Prism::new(DAffine3::IDENTITY, &pieces, h1, h2, conic, false);
        let open = Prism::new(DAffine3::IDENTITY, &pieces, h1, h2, conic, true);
        let mut rays = Vec::new();
        for i in 0..4000 {
            // Render space is the prism as written.
            let y = h1 + (h2 - h1) * rand();
            let reach = if conic { 0.5 * y } else { 0.5 };
            let target = DVec3::new((rand() * 2.0 - 1.0) * reach, y, (rand() * 2.0 - 1.0) * reach);
            let o = DVec3::new(rand() * 4.0 - 2.0, rand() * 4.0 - 1.0, rand() * 4.0 - 2.0);
            let o = if i % 5 == 0 { target } else { o };
            let mut d = (target - o + 0.1 * DVec3::new(rand(), rand(), rand())).normalize();
            if i % 17 == 0 {
                d.y = 0.0;
            }
            let ray = Ray::new(o.as_vec3(), d.as_vec3());
            rays.push(ray);
            let f = &closed.frame.object_from_render;
            let (o, d) = (f.transform_point3(ray.origin).as_dvec3(), f.transform_vector3(ray.dir).as_dvec3());
            let s_min = if i % 3 == 0 { 1e-4 } else { 0.0 };
            let mut want = open.solve(o, d, s_min, f64::INFINITY).unwrap_or(f64::INFINITY);
            for h in [closed.h1, closed.h2] {
                let s = (h - o.y) / d.y;
                let w = o + s * d;
                if s > s_min && s < want && even_odd(&closed.pieces, closed.section(DVec3::new(w.x, h, w.z))) {
                    want = s;
                    caps_hit += 1;
                }
            }
            let want = want.is_finite().then_some(want).map(f64::to_bits);
            assert_eq!(closed.solve(o, d, s_min, f64::INFINITY).map(f64::to_bits), want, "{o} {d}");
        }
        for chunk in rays.chunks_exact(8) {
            let packet = RayLanes::<F8> {
                o: V3::from_lanes(|i| chunk[i].origin),
                d: V3::from_lanes(|i| chunk[i].dir),
                inv: V3::from_lanes(|i| chunk[i].inv_dir),
            };
            let wide = closed.hit(&packet, F8::splat(0.0), F8::splat(MISS));
            for (i, r) in chunk.iter().enumerate() {
                assert_eq!(wide.get(i).to_bits(), closed.hit(&r.lanes(), 0.0, MISS).to_bits());
            }
        }
    }
    assert!(caps_hit > 500, "the rays reach the caps: {caps_hit}");
}

#[test]
fn grazing_scaled_moved_and_packets() {
    // Grazing the wall z = -1 along it: either no hit or one on the wall's line.
    let p = prism(DAffine3::IDENTITY, false, false);
    let g = hit(&p, Vec3::new(-5.0, 1.0, -1.0), Vec3::X);
    assert!(g.is_none_or(|t| (3.9..=6.1).contains(&t)), "{g:?}");
    // Scaled 1e-4 and 1e5, moved 1e6: the same hit in proportion.
    for (s, at) in [(1e-4, 0.0), (1e5, 0.0), (1.0, 1e6)] {
        let xf = DAffine3::from_translation(DVec3::splat(at)) * DAffine3::from_scale(DVec3::splat(s));
        let p = prism(xf, false, false);
        // Render space puts the camera near the shape: rays start close to it.
        let o = Vec3::new(0.0, 1.0, -5.0) * s as f32 + Vec3::splat(at as f32);
        let t = hit(&p, o, Vec3::Z).expect("hit");
        let want = 4.0 * s as f32;
        assert!((t - want).abs() <= want * 1e-4 + at as f32 * 1e-6, "{s} {at}: {t}");
    }
    let rays: [Ray; 8] = std::array::from_fn(|i| {
        let o = Vec3::new(i as f32 * 0.3 - 1.2, 3.0, -4.0);
        Ray::new(o, (Vec3::new(0.1 * i as f32, 1.0, 0.0) - o).normalize())
    });
    let packet = RayLanes::<F8> {
        o: V3::from_lanes(|i| rays[i].origin),
        d: V3::from_lanes(|i| rays[i].dir),
        inv: V3::from_lanes(|i| rays[i].inv_dir),
    };
    let wide = p.hit(&packet, F8::splat(0.0), F8::splat(MISS));
    for (i, r) in rays.iter().enumerate() {
        assert_eq!(wide.get(i).to_bits(), p.hit(&r.lanes(), 0.0, MISS).to_bits());
    }
}

#[test]
fn curved_sides_holes_and_the_nearest_point() {
    // A circle-ish cubic outline with a square hole (even-odd).
    let q = |x: f64, z: f64| DVec2::new(x, z);
    let mut pts = vec![q(0.0, -2.0), q(2.0, 0.0), q(0.0, 2.0), q(-2.0, 0.0), q(0.0, -2.0), q(2.0, 0.0), q(0.0, 2.0)];
    pts.extend([q(-0.5, -0.5), q(0.5, -0.5), q(0.5, 0.5), q(-0.5, 0.5), q(-0.5, -0.5)].map(|p| p * 1.0));
    let cubic = closed_pieces(SplineKind::Cubic, &pts[..7]).expect("cubic").0;
    let hole = closed_pieces(SplineKind::Linear, &pts[7..]).expect("hole").0;
    let all: Vec<Piece> = cubic.into_iter().chain(hole).collect();
    let p = Prism::new(DAffine3::IDENTITY, &all, 0.0, 1.0, false, false);
    assert!(inside(&p, Vec3::new(1.0, 0.5, 0.0)));
    assert!(!inside(&p, Vec3::new(0.0, 0.5, 0.0)), "the hole");
    assert!(!inside(&p, Vec3::new(2.5, 0.5, 0.0)));
    // From the hole's middle along x: the hole's wall at 0.5.
    let t = hit(&p, Vec3::new(0.0, 0.5, 0.0), Vec3::X).expect("hole wall");
    assert!((t - 0.5).abs() < 1e-5, "{t}");
    assert!((p.normal_at(Vec3::new(0.5, 0.5, 0.0)) - -Vec3::X).length() < 1e-4);
    // The outer wall at x = 2 (a point of the spline), normal +x.
    let t = hit(&p, Vec3::new(5.0, 0.5, 0.0), -Vec3::X).expect("outer");
    assert!((t - 3.0).abs() < 1e-4, "{t}");
    assert!((p.normal_at(Vec3::new(2.0, 0.5, 0.0)) - Vec3::X).length() < 1e-3);
}

/// Seeded random rays at a star with a curved hole, closed and conic: the face each hit names
/// is the surface it lies on (the cap's height to rounding, or within 10⁻⁹ of that arc); away from the
/// edges its normal is the search's (`normal_object`), to the bit; and eight-lane packets name
/// the single rays' faces.
#[test]
fn hit_faces_name_the_surface_and_its_normal() {
    let mut rand = uniform(0x9e37_79b9_7f4a_7c15u64);
    let pieces = star_with_hole();
    for conic in [false, true] {
        let (h1, h2) = if conic { (0.5, 1.5) } else { (0.0, 0.6) };
        let p = Prism::new(DAffine3::IDENTITY, &pieces, h1, h2, conic, false);
        let (mut sides, mut caps, mut same) = (0, 0, 0);
        let mut rays = Vec::new();
        for _ in 0..4000 {
            let y = h1 + (h2 - h1) * rand();
            let reach = if conic { 0.5 * y } else { 0.5 };
            let target = DVec3::new((rand() * 2.0 - 1.0) * reach, y, (rand() * 2.0 - 1.0) * reach);
            let o = DVec3::new(rand() * 4.0 - 2.0, rand() * 4.0 - 1.0, rand() * 4.0 - 2.0);
            let ray = Ray::new(o.as_vec3(), (target - o).normalize().as_vec3());
            rays.push(ray);
            let f = &p.frame.object_from_render;
            let (o, d) = (f.transform_point3(ray.origin).as_dvec3(), f.transform_vector3(ray.dir).as_dvec3());
            let Some((s, face)) = p.solve_face(o, d, 0.0, f64::INFINITY) else { continue };
            let q = o + s * d;
            match face {
                FACE_H1 => assert!((q.y - p.h1).abs() < 1e-12, "{o} {d}: {}", q.y),
                FACE_H2 => assert!((q.y - p.h2).abs() < 1e-12, "{o} {d}: {}", q.y),
                i => {
                    let (arc, w) = (&p.arcs[i as usize], p.section(q));
                    let gap = (arc.at(arc::nearest_t(arc, w)) - w).length();
                    assert!(gap < 1e-9, "{o} {d}: {gap}");
                }
            }
            (sides, caps) = if face < FACE_H1 { (sides + 1, caps) } else { (sides, caps + 1) };
            let (got, want) = (p.normal_face(face, q), p.normal_object(q));
            same += (got == want) as usize;
        }
        assert!(sides > 200 && caps > 200, "{sides} sides, {caps} caps");
        assert!(same * 100 >= (sides + caps) * 95, "{same} of {} the search's", sides + caps);
        for chunk in rays.chunks_exact(8) {
            let packet = RayLanes::<F8> {
                o: V3::from_lanes(|i| chunk[i].origin),
                d: V3::from_lanes(|i| chunk[i].dir),
                inv: V3::from_lanes(|i| chunk[i].inv_dir),
            };
            let (wide, faces) = p.hit_faces(&packet, F8::splat(0.0), F8::splat(MISS));
            for (i, r) in chunk.iter().enumerate() {
                let (t, face) = p.hit_faces(&r.lanes(), 0.0, MISS);
                assert_eq!((wide.get(i).to_bits(), faces[i]), (t.to_bits(), face[0]));
            }
        }
    }
}
