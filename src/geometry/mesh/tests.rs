use super::*;
use crate::lanes::F8;

/// The unit cube as 12 triangles.
fn cube() -> Vec<([Vec3; 3], Option<[Vec3; 3]>)> {
    let c = |i: u32| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32);
    let quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]];
    quads.iter().flat_map(|q| [([c(q[0]), c(q[1]), c(q[2])], None), ([c(q[0]), c(q[2]), c(q[3])], None)]).collect()
}

fn placed(inside: bool) -> Mesh {
    let xf = Affine3A::from_translation(Vec3::new(0.0, 0.0, 3.0)) * Affine3A::from_rotation_y(0.3);
    Mesh::new(Arc::new(MeshData::new(cube())), xf, inside.then_some(Vec3::new(0.1, 0.2, 1.0)))
}

#[test]
fn hits_report_their_face() {
    let m = placed(false);
    let ray = Ray::new(Vec3::new(0.3, 0.5, -1.0), Vec3::Z);
    let (t, face) = m.hit_face(&ray.lanes(), 0.0, f32::INFINITY).expect("hit");
    assert_eq!(m.intersect(&ray, 0.0, f32::INFINITY), Some(t));
    let n = m.normal(face, V3::from_vec3(ray.at(t))).vec3();
    // The front face (z = 0 before the turn); its winding, not the mesh, sets the sign.
    assert!(n.dot(Vec3::Z).abs() > 0.9, "{n}");
}

#[test]
fn inside_by_parity_only_with_an_inside_vector() {
    let p = Affine3A::from_translation(Vec3::new(0.0, 0.0, 3.0)).transform_point3(Vec3::splat(0.5));
    assert!(placed(true).inside(V3::from_vec3(p)));
    assert!(!placed(false).inside(V3::from_vec3(p)));
    assert!(!placed(true).inside(V3::from_vec3(Vec3::new(5.0, 0.0, 0.0))));
}

/// objects/csg/hfclip.pov took 90 s at 64×48: CSG asks `inside` for idle packet lanes at
/// infinity, whose NaN slabs entered every node of the mesh's BVH.
#[test]
fn points_at_infinity_are_outside_without_a_walk() {
    let m = placed(true);
    assert!(!m.inside(V3::from_vec3(Vec3::INFINITY)));
    assert!(!m.inside(V3::from_vec3(Vec3::NAN)));
    let idle = Ray::new(Vec3::INFINITY, Vec3::Z);
    assert_eq!(m.hit(&idle.lanes(), 0.0, f32::INFINITY), MISS);
}

#[test]
fn eight_lanes_match_one() {
    let m = placed(true);
    let dirs: [Vec3; 8] =
        std::array::from_fn(|i| Vec3::new(0.05 * i as f32 - 0.2, 0.1 - 0.03 * i as f32, 1.0).normalize());
    let o = Vec3::new(0.4, 0.4, -1.0);
    let wide = RayLanes::<F8>::new(V3::splat(o), V3::from_lanes(|i| dirs[i]));
    let t8 = m.hit(&wide, F8::splat(0.0), F8::splat(f32::INFINITY));
    for (i, d) in dirs.iter().enumerate() {
        let one = m.hit(&Ray::new(o, *d).lanes(), 0.0, f32::INFINITY);
        assert_eq!(t8.0[i].to_bits(), one.to_bits());
    }
}

/// Shadow rays' first hits: a hit exactly where the nearest search finds one (inside the
/// same interval), on one lane and eight, from outside the cube and from inside it.
#[test]
fn first_hits_are_hits_where_nearest_ones_are() {
    let m = placed(true);
    for o in [Vec3::new(0.4, 0.4, -1.0), Vec3::new(0.5, 0.5, 3.5)] {
        let dirs: [Vec3; 8] =
            std::array::from_fn(|i| Vec3::new(0.3 * i as f32 - 1.0, 0.7 - 0.2 * i as f32, 1.0).normalize());
        let wide = RayLanes::<F8>::new(V3::splat(o), V3::from_lanes(|i| dirs[i]));
        for t_max in [0.5, 2.0, 4.0, f32::INFINITY] {
            let near8 = m.hit(&wide, F8::splat(0.0), F8::splat(t_max));
            let first8 = m.first_hit(&wide, F8::splat(0.0), F8::splat(t_max));
            for (i, d) in dirs.iter().enumerate() {
                let lanes = Ray::new(o, *d).lanes();
                let (near, first) = (m.hit(&lanes, 0.0, t_max), m.first_hit(&lanes, 0.0, t_max));
                assert_eq!(near == MISS, first == MISS, "{o} {d} {t_max}");
                assert_eq!(near8.0[i] == MISS, first8.0[i] == MISS, "{o} {d} {t_max}");
                assert_eq!(near == MISS, near8.0[i] == MISS);
                assert!(first == MISS || (first >= near && first < t_max), "{first} {near}");
            }
        }
    }
}

#[test]
fn smooth_normals_interpolate_and_keep_the_geometric_side() {
    let v = [Vec3::ZERO, Vec3::X, Vec3::Y];
    // Normals written pointing away from the geometric normal (+z): flipped back.
    let n = [-Vec3::Z + Vec3::X, -Vec3::Z, -Vec3::Z];
    let m = Mesh::new(Arc::new(MeshData::new([(v, Some(n))])), Affine3A::IDENTITY, None);
    let at0 = m.normal(0, V3::from_vec3(Vec3::new(0.0, 0.0, 0.0))).vec3();
    assert!((at0 - Vec3::new(-1.0, 0.0, 1.0).normalize()).length() < 1e-5, "{at0}");
    let at1 = m.normal(0, V3::from_vec3(Vec3::new(1.0, 0.0, 0.0))).vec3();
    assert!((at1 - Vec3::Z).length() < 1e-5, "{at1}");
}

/// A small deterministic generator (SplitMix64) of floats in `[lo, hi)`.
struct Rng(u64);

impl Rng {
    fn f(&mut self, lo: f32, hi: f32) -> f32 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        lo + (hi - lo) * ((z >> 40) as f32 / (1u64 << 24) as f32)
    }

    fn v(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.f(lo, hi), self.f(lo, hi), self.f(lo, hi))
    }
}

/// The nearest face of `m` for one render-space ray by testing every triangle (the ray
/// carried into object space as `Mesh::hit_face` carries it): least `t`, ties to the lowest
/// face.
fn brute_force(m: &Mesh, o: Vec3, d: Vec3, t_max: f32) -> Option<(f32, u32)> {
    let ray = RayLanes::<f32>::new(V3::from_vec3(o), V3::from_vec3(d));
    let o = ray.o.transform_point(&m.frame.object_from_render);
    let d = ray.d.transform_vector(&m.frame.object_from_render);
    let object = RayLanes { o, d, inv: d.recip() };
    let mut best: Option<(f32, u32)> = None;
    for (f, tri) in m.data.triangles.iter().enumerate() {
        let t = tri.hit(&object, 0.0, t_max);
        if t != MISS && best.is_none_or(|(b, _)| t < b) {
            best = Some((t, f as u32));
        }
    }
    best
}

/// Coincident faces (each face twice, the copy wound the other way, as on
/// objects/chesmsh.pov's knight): every path names the same face, the lowest index at the
/// nearest distance, as brute force does: a packet's walk (`hit_faces` on eight lanes), rows
/// walked together (`rows`), the single-ray walk (`hit_face`) and `Scene::resolve`'s search
/// again around the hit. The faces lie in planes z = const, so their boxes are flat in z and
/// a box's entry distance, rounded, falls on either side of the face's `t` by an ulp: with
/// boxes culled at the best distance itself, whether the second copy was tested depended on
/// the order the walk met them (the packet and single-ray walks disagreed).
#[test]
fn coincident_faces_resolve_alike_on_every_path() {
    let r = &mut Rng(0xC0FFEE);
    let mut faces = Vec::new();
    for _ in 0..40 {
        let z = (r.f(-4.0, 4.0) * 8.0).round() / 8.0;
        let c = Vec3::new(r.f(-1.0, 1.0), r.f(-1.0, 1.0), z);
        let v =
            [c, c + Vec3::new(r.f(0.3, 1.0), r.f(-0.2, 0.2), 0.0), c + Vec3::new(r.f(-0.2, 0.2), r.f(0.3, 1.0), 0.0)];
        let n = r.f(0.0, 1.0) < 0.5;
        let smooth = n.then_some([Vec3::Z, Vec3::X + Vec3::Z, Vec3::Y + Vec3::Z]);
        faces.push((v, smooth));
        faces.push(([v[0], v[2], v[1]], smooth.map(|n| [n[0], n[2], n[1]])));
    }
    let surface: Vec<[Vec3; 3]> = faces.iter().map(|f| f.0).collect();
    let xf = Affine3A::from_rotation_x(0.2) * Affine3A::from_translation(Vec3::new(0.1, -0.2, 0.3));
    let m = Mesh::new(Arc::new(MeshData::new(faces)), xf, None);
    let (mut hits, mut lanes) = (0, 0);
    for block in 0..400 {
        let eye = Vec3::new(r.f(-3.0, 3.0), r.f(-3.0, 3.0), if block % 2 == 0 { -9.0 } else { 9.0 });
        let mut rows = [RayLanes::<F8>::new(V3::splat(Vec3::ZERO), V3::splat(Vec3::X)); 8];
        let mut dirs = [[Vec3::X; 8]; 8];
        for k in 0..8 {
            for i in 0..8 {
                let v = surface[(block * 64 + k * 8 + i) * 7 % surface.len()];
                let (a, b) = (r.f(0.0, 1.0), r.f(0.0, 1.0));
                let (a, b) = if a + b > 1.0 { (1.0 - a, 1.0 - b) } else { (a, b) };
                let target = xf.transform_point3(v[0] + a * (v[1] - v[0]) + b * (v[2] - v[0]));
                dirs[k][i] = target - eye;
            }
            rows[k] = RayLanes::new(V3::splat(eye), V3::from_lanes(|i| dirs[k][i]));
        }
        let t_max = [F8::splat(MISS); 8];
        let together = m.rows::<false>(&rows, &t_max);
        for k in 0..8 {
            let (t8, faces8) = m.hit_faces(&rows[k], F8::splat(0.0), t_max[k]);
            for i in 0..8 {
                let what = format!("block {block} row {k} lane {i}");
                let ray = RayLanes::<f32>::new(V3::from_vec3(eye), V3::from_vec3(dirs[k][i]));
                let single = m.hit_face(&ray, 0.0, MISS);
                let lane = (t8.0[i] != MISS).then_some((t8.0[i], faces8[i]));
                assert_eq!(lane, single, "{what}: packet, single ray");
                let rows_lane = (together[k].0 .0[i] != MISS).then_some((together[k].0 .0[i], together[k].1[i]));
                assert_eq!(rows_lane, single, "{what}: rows together, single ray");
                if let Some((t, _)) = single {
                    assert_eq!(m.hit_face(&ray, t.next_down(), t.next_up()), single, "{what}: found again");
                    assert_eq!(brute_force(&m, eye, dirs[k][i], MISS), single, "{what}: brute force");
                    hits += 1;
                }
                lanes += 1;
            }
        }
    }
    assert!(hits > lanes / 2, "{hits} of {lanes}");
}

/// Rows walked together (`Mesh::rows`) answer what each row's own walk (`hit_faces`,
/// `first_hit`), each lane's single ray and brute force answer: the same distance and face
/// bit for bit, the same shadow verdicts. Blocks of one origin (primary rays); of many
/// origins aimed at one point, with limits of their own and idle lanes (shadow rays); with
/// mixed direction signs (walked row by row); with lanes aimed exactly at vertices (grazing).
#[test]
fn rows_together_match_rows_alone_single_rays_and_brute_force() {
    let r = &mut Rng(0x5EED);
    let (mut hits, mut lanes, mut disagree) = (0, 0, 0);
    for case in 0..12 {
        let faces: Vec<([Vec3; 3], Option<[Vec3; 3]>)> = (0..20 + (case * 37) % 200)
            .map(|_| {
                let c = r.v(-1.0, 1.0);
                ([c + r.v(-0.3, 0.3), c + r.v(-0.3, 0.3), c + r.v(-0.3, 0.3)], None)
            })
            .collect();
        let vertices: Vec<Vec3> = faces.iter().flat_map(|(v, _)| *v).collect();
        let xf = if case % 2 == 0 {
            Affine3A::from_translation(r.v(-2.0, 2.0))
        } else {
            Affine3A::from_rotation_y(r.f(0.0, 3.0)) * Affine3A::from_scale(Vec3::splat(1.5))
        };
        let m = Mesh::new(Arc::new(MeshData::new(faces)), xf, None);
        for block in 0..30 {
            let kind = block % 3;
            let n = 1 + block % 8;
            let eye = r.v(-6.0, 6.0);
            let light = r.v(-8.0, 8.0);
            let mut rows = [RayLanes::<F8>::new(V3::splat(Vec3::ZERO), V3::splat(Vec3::X)); 8];
            let mut t_max = [F8::splat(MISS); 8];
            let mut single = [[(Vec3::ZERO, Vec3::X, MISS); 8]; 8];
            for (k, row) in single.iter_mut().enumerate().take(n) {
                for (i, lane) in row.iter_mut().enumerate() {
                    let target = if (k + i) % 5 == 0 {
                        xf.transform_point3(vertices[(k * 8 + i + block) % vertices.len()])
                    } else {
                        xf.transform_point3(r.v(-1.2, 1.2))
                    };
                    *lane = match kind {
                        0 => (eye, target - eye, MISS),
                        // From points near the mesh towards the light, to just before it; lane 1 idle.
                        1 => (target, light - target, [0.999, 0.0, 0.999, 0.5][i % 4]),
                        _ => (target + r.v(-0.5, 0.5), r.v(-1.0, 1.0), [MISS, 2.0][i % 2]),
                    };
                }
                rows[k] = RayLanes::new(V3::from_lanes(|i| row[i].0), V3::from_lanes(|i| row[i].1));
                t_max[k] = F8::from_fn(|i| row[i].2);
            }
            let near = m.rows::<false>(&rows[..n], &t_max[..n]);
            let first = m.rows::<true>(&rows[..n], &t_max[..n]);
            for k in 0..n {
                let (t_row, faces_row) = m.hit_faces(&rows[k], F8::splat(0.0), t_max[k]);
                let first_row = m.first_hit(&rows[k], F8::splat(0.0), t_max[k]);
                for i in 0..8 {
                    let (o, d, limit) = single[k][i];
                    let what = format!("case {case} block {block} row {k} lane {i}");
                    assert_eq!(near[k].0 .0[i].to_bits(), t_row.0[i].to_bits(), "{what}");
                    assert_eq!(near[k].1[i], faces_row[i], "{what}");
                    let blocked = first[k].0 .0[i] < MISS;
                    assert_eq!(blocked, first_row.0[i] < MISS, "{what}");
                    // A lane aimed exactly at a vertex can meet it where its own box test
                    // fails but its row's walk tests the face for another lane: packets and
                    // single rays may part there (as before rows were walked together).
                    if (k + i) % 5 != 0 {
                        let lane = RayLanes::<f32>::new(V3::from_vec3(o), V3::from_vec3(d));
                        let one = m.hit_face(&lane, 0.0, limit);
                        let (t, face) = one.unwrap_or((MISS, u32::MAX));
                        assert_eq!((near[k].0 .0[i].to_bits(), near[k].1[i]), (t.to_bits(), face), "{what}");
                        assert_eq!(blocked, one.is_some(), "{what}");
                        // The walks cull by boxes, brute force does not: a hit the kernel
                        // rounds a hair outside its face's box may differ (rarely).
                        disagree += u32::from(one != brute_force(&m, o, d, limit));
                    }
                    hits += u32::from(blocked);
                    lanes += 1;
                }
            }
        }
    }
    // Not a vacuous pass: a fair share of the lanes hit.
    assert!(hits > lanes / 10 && hits < lanes, "{hits} of {lanes}");
    assert!(disagree * 1000 < lanes, "{disagree} of {lanes} lanes disagree with brute force");
}
