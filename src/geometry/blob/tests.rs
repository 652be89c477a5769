use super::*;
use crate::geometry::Shape;
use crate::ray::Ray;

fn sphere(center: DVec3, radius: f64, strength: f64) -> Component {
    Component { shape: ComponentShape::Sphere { center, radius }, strength, blob_from_component: DAffine3::IDENTITY }
}

fn cylinder(base: DVec3, cap: DVec3, radius: f64, strength: f64) -> Component {
    Component {
        shape: ComponentShape::Cylinder { base, cap, radius },
        strength,
        blob_from_component: DAffine3::IDENTITY,
    }
}

/// The first `t` where the field along the ray rises through the threshold, by marching
/// in tiny steps (the reference `solve` must agree with).
fn march(b: &Blob, o: DVec3, d: DVec3, t_max: f64, steps: usize) -> Option<f64> {
    let f = |t: f64| b.field(o + t * d) - b.threshold;
    let mut prev = f(0.0);
    for i in 1..=steps {
        let t = t_max * i as f64 / steps as f64;
        let v = f(t);
        if (v > 0.0) != (prev > 0.0) {
            return Some(t);
        }
        prev = v;
    }
    None
}

#[test]
fn one_sphere_component_is_a_sphere_of_the_threshold_radius() {
    // s·(1 − d²/r²)² = th at d = r·sqrt(1 − sqrt(th/s)).
    let b = Blob::new(DAffine3::IDENTITY, &[sphere(DVec3::ZERO, 2.0, 1.0)], 0.25);
    let expect = 2.0 * (1.0f64 - 0.5).sqrt();
    let t = b.intersect(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), 1e-4, 100.0).unwrap();
    assert!((t as f64 - (5.0 - expect)).abs() < 1e-5, "{t}");
    let n = b.normal_at(Vec3::new(0.0, 0.0, -expect as f32));
    assert!((n - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-5, "{n}");
    assert!(b.inside_unit(DVec3::ZERO));
    // Leaving from inside.
    let t = b.intersect(&Ray::new(Vec3::ZERO, Vec3::X), 1e-4, 100.0).unwrap();
    assert!((t as f64 - expect).abs() < 1e-5, "{t}");
}

#[test]
fn two_spheres_merge_and_a_negative_one_carves() {
    let pair = [sphere(DVec3::new(-0.6, 0.0, 0.0), 1.0, 1.0), sphere(DVec3::new(0.6, 0.0, 0.0), 1.0, 1.0)];
    let b = Blob::new(DAffine3::IDENTITY, &pair, 0.5);
    // Alone neither reaches 0.5 at the origin (0.64·... each 0.4096); together they do.
    let unit_from_blob = b.fields[0].component_from_unit.inverse();
    assert!(b.inside_unit(unit_from_blob.transform_point3(DVec3::ZERO)));
    let t = b.intersect(&Ray::new(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y), 1e-4, 100.0);
    assert!(t.is_some(), "the neck between them is solid");
    let mut carved = pair.to_vec();
    carved.push(sphere(DVec3::ZERO, 0.5, -4.0));
    let c = Blob::new(DAffine3::IDENTITY, &carved, 0.5);
    let down = Ray::new(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y);
    assert!(c.intersect(&down, 1e-4, 100.0).is_none(), "the negative component cuts the neck");
}

#[test]
fn a_cylinder_component_has_round_ends() {
    let b = Blob::new(DAffine3::IDENTITY, &[cylinder(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1.0, 1.0)], 0.25);
    let r = (1.0f64 - 0.5).sqrt();
    let side = b.intersect(&Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X), 1e-4, 100.0).unwrap();
    assert!((side as f64 - (5.0 - r)).abs() < 1e-5, "{side}");
    let top = b.intersect(&Ray::new(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y), 1e-4, 100.0).unwrap();
    assert!((top as f64 - (5.0 - 2.0 - r)).abs() < 1e-5, "{top}");
    let n = b.normal_at(Vec3::new(-r as f32, 1.0, 0.0));
    assert!((n + Vec3::X).length() < 1e-4, "{n}");
}

#[test]
fn first_crossing_matches_a_dense_march_of_the_field() {
    let parts = [
        sphere(DVec3::new(-0.5, 0.0, 0.0), 1.0, 1.0),
        sphere(DVec3::new(0.7, 0.3, 0.0), 0.8, 1.5),
        cylinder(DVec3::new(0.0, -1.0, 0.2), DVec3::new(0.5, 1.0, -0.3), 0.5, 2.0),
        sphere(DVec3::new(0.1, 0.1, 0.4), 0.4, -1.0),
    ];
    let b = Blob::new(DAffine3::IDENTITY, &parts, 0.6);
    // Component transforms are the identity: component space is blob space.
    let unit_from_blob = b.fields[0].component_from_unit.inverse();
    let mut seed = 7u64;
    let mut rnd = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut hits = 0;
    for _ in 0..400 {
        let o = DVec3::new(rnd(), rnd(), rnd()).normalize() * 4.0;
        let target = DVec3::new(rnd(), rnd(), rnd()) * 0.8;
        let d = (target - o).normalize();
        // In unit space: the blob's own solve, against marching its own field.
        let (ou, du) = (unit_from_blob.transform_point3(o), unit_from_blob.transform_vector3(d));
        let got = b.solve(ou, du, 0.0, 20.0);
        let want = march(&b, ou, du, 20.0, 200_000);
        match (got, want) {
            (Some(g), Some(w)) => {
                hits += 1;
                assert!((g - w).abs() < 2e-4, "from {o} along {d}: solve {g}, march {w}");
                // Searching on from a crossing finds the next one, as CSG does.
                let next = b.solve(ou, du, g + 1e-9, 20.0);
                let want_next = {
                    let from = g + 1e-4;
                    march(&b, ou + from * du, du, 20.0 - from, 200_000).map(|t| t + from)
                };
                if let (Some(n), Some(w)) = (next, want_next) {
                    assert!((n - w).abs() < 2e-4, "next crossing from {o}: {n} vs {w}");
                }
            }
            (None, None) => {}
            (g, w) => {
                // A graze too slight for the march's step may be seen by one only.
                let t = g.or(w).unwrap();
                let v = b.field(ou + t * du) - b.threshold;
                assert!(v.abs() < 1e-3, "from {o} along {d}: solve {g:?}, march {w:?}");
            }
        }
    }
    assert!(hits > 100, "{hits}");
}

/// `blocks` answers `MISS` exactly where `hit` does, and elsewhere a `t` in the interval, in
/// packets and alone (`check_blocks`), on the kernel scenes' blobs and one with a negative
/// component: for rays aimed through the box, rays grazing the surface, and shadow rays leaving
/// it towards random points, each with its interval cut short at random.
#[test]
fn blocks_decides_as_hit_does() {
    use crate::geometry::test_support::{check_blocks, uniform};
    let spheres = [
        sphere(DVec3::new(-0.15, 0.4, 0.0), 0.55, 1.0),
        sphere(DVec3::new(0.15, 0.4, 0.0), 0.55, 1.0),
        sphere(DVec3::new(0.0, 0.6, 0.1), 0.5, 1.0),
    ];
    let cross = [
        cylinder(DVec3::new(-0.35, 0.25, 0.0), DVec3::new(0.35, 0.25, 0.0), 0.4, 1.0),
        cylinder(DVec3::new(0.0, 0.25, -0.35), DVec3::new(0.0, 0.25, 0.35), 0.4, 1.0),
    ];
    let mut carved = spheres.to_vec();
    carved.push(sphere(DVec3::new(0.0, 0.5, -0.2), 0.3, -1.5));
    let mut rnd = uniform(0xb10b);
    let (mut hits, mut earlier) = (0, 0);
    for parts in [&spheres[..], &cross[..], &carved[..]] {
        let b = Blob::new(DAffine3::from_translation(DVec3::new(0.3, 0.0, -0.2)), parts, 0.4);
        let (lo, hi) = (b.min.as_dvec3(), b.max.as_dvec3());
        let mut point = || (lo + (hi - lo) * DVec3::new(rnd(), rnd(), rnd())).as_vec3();
        let mut rays = Vec::new();
        for _ in 0..2000 {
            let from = point() + (point() - point()) * 4.0;
            let d = (point() - from).normalize();
            let ray = Ray::new(from, d);
            rays.push((from, d, 0.0, 1e30));
            let Some(t) = b.intersect(&ray, 0.0, f32::INFINITY) else { continue };
            let p = ray.origin + t * d;
            let n = b.normal_at(p);
            let tangent = n.cross(d).normalize_or_zero().cross(n);
            for e in [1e-3f32, 1e-6, -1e-6] {
                rays.push((p + n * e - tangent, tangent, 0.0, 3.0));
            }
            let towards = (point() - p).normalize();
            rays.push((p, towards, 1e-4, 0.2 + 3.0 * point().x.abs()));
            rays.push((p + n * 1e-4, towards, 0.0, 1e30));
        }
        rays.truncate(rays.len() / 8 * 8);
        hits += check_blocks(&b, &rays);
        for &(o, d, t0, t1) in &rays {
            let ray = Ray::new(o, d).lanes();
            earlier += (b.blocks(&ray, t0, t1) < b.hit(&ray, t0, t1)) as u32;
        }
    }
    // The rays do hit, and shadow rays are spared their root's placing.
    assert!(hits > 2000 && earlier > 200, "{hits} hits, {earlier} answered before the root");
}
