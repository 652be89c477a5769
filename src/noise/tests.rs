use super::*;

/// Deterministic pseudo-random points in a box of side `size`, from the module's own hash.
fn points(n: u32, size: f32) -> impl Iterator<Item = Vec3> {
    (0..n).map(move |i| {
        let u = |k: u32| (mix32(i.wrapping_mul(3).wrapping_add(k) ^ 0xabcd_1234) as f32) / 4294967296.0;
        Vec3::new(u(0), u(1), u(2)) * size - Vec3::splat(size * 0.5)
    })
}

fn mean_std(v: &[f32]) -> (f32, f32) {
    let n = v.len() as f64;
    let m = v.iter().map(|&x| x as f64).sum::<f64>() / n;
    let var = v.iter().map(|&x| (x as f64 - m).powi(2)).sum::<f64>() / n;
    (m as f32, var.sqrt() as f32)
}

#[test]
fn perm_is_a_permutation() {
    let mut seen = [false; 256];
    for &p in &PERM[..256] {
        seen[p as usize] = true;
    }
    assert!(seen.iter().all(|&s| s));
    assert_eq!(PERM[..256], PERM[256..]);
}

#[test]
fn raw_noise_spread() {
    // The figure NOISE_SCALE and DNOISE_SCALE divide by.
    let v: Vec<f32> = points(200_000, 200.0).map(raw_noise).collect();
    let (m, s) = mean_std(&v);
    eprintln!("raw noise mean {m:.4} std {s:.4}");
    assert!(m.abs() < 0.01);
    assert!((s - 0.2547).abs() < 0.006, "std {s}");
}

#[test]
fn noise_in_range_centred_and_matching_povray_spread() {
    let v: Vec<f32> = points(100_000, 300.0).map(noise).collect();
    assert!(v.iter().all(|&x| (0.0..=1.0).contains(&x)));
    let (m, s) = mean_std(&v);
    assert!((m - 0.5).abs() < 0.01, "mean {m}");
    assert!((s - 0.122).abs() < 0.006, "std {s}");
    // Not pinned to 0.5 on integer points (POV-Ray's std there: 0.141): the lattice is offset.
    let on_grid: Vec<f32> =
        (1..15).flat_map(|i| (1..15).map(move |j| noise(Vec3::new(i as f32, j as f32, 0.0)))).collect();
    let (_, grid_std) = mean_std(&on_grid);
    assert!(grid_std > 0.08, "std on integer points {grid_std}");
}

#[test]
fn dnoise_components_match_povray_spread_and_are_independent() {
    let v: Vec<Vec3> = points(100_000, 300.0).map(dnoise).collect();
    for axis in 0..3 {
        let c: Vec<f32> = v.iter().map(|d| d[axis]).collect();
        let (m, s) = mean_std(&c);
        assert!(m.abs() < 0.01 && (s - 0.251).abs() < 0.012, "axis {axis}: mean {m} std {s}");
    }
    let (_, sx) = mean_std(&v.iter().map(|d| d.x).collect::<Vec<_>>());
    let corr = v.iter().map(|d| d.x * d.y).sum::<f32>() / v.len() as f32 / (sx * sx);
    assert!(corr.abs() < 0.05, "x/y correlation {corr}");
}

#[test]
fn noise_is_continuous() {
    // Largest step between points 1e-3 apart: the gradient is bounded (≈ 2.2/unit after scaling),
    // including across lattice planes.
    for p in points(20_000, 50.0) {
        for d in [Vec3::X, Vec3::Y, Vec3::Z] {
            let a = noise(p);
            let b = noise(p + d * 1e-3);
            assert!((a - b).abs() < 4e-3, "jump {a} -> {b} at {p}");
        }
    }
    let e = 1e-4;
    let (a, b) = (dnoise(Vec3::new(1.0 - e, 0.3, 0.7)), dnoise(Vec3::new(1.0 + e, 0.3, 0.7)));
    assert!((a - b).length() < 1e-2);
}

#[test]
fn dnoise_is_deterministic() {
    let p = Vec3::new(12.345, -6.5, 0.25);
    assert_eq!(dnoise(p), dnoise(p));
    assert_ne!(dnoise(p), dnoise(p + Vec3::splat(0.5)));
}

/// Autocorrelation of `noise` along x at a lag, over a 40×30 grid like the POV-Ray calibration.
fn autocorrelation(lag: f32) -> f32 {
    let mut a = Vec::new();
    let mut b = Vec::new();
    for j in 0..240 {
        for i in 0..320 {
            let p = Vec3::new(i as f32 * 0.125 - 20.0, j as f32 * 0.125 - 15.0, -0.37);
            a.push(noise(p));
            b.push(noise(p + Vec3::X * lag));
        }
    }
    let (ma, sa) = mean_std(&a);
    let (mb, sb) = mean_std(&b);
    a.iter().zip(&b).map(|(x, y)| (x - ma) * (y - mb)).sum::<f32>() / a.len() as f32 / (sa * sb)
}

#[test]
fn feature_size_matches_povray() {
    // POV-Ray's Noise: 0.56 at 0.5 units, 0.06 at 1 unit (measured, see the module doc).
    let (h, one) = (autocorrelation(0.5), autocorrelation(1.0));
    eprintln!("autocorrelation 0.5: {h:.3}, 1.0: {one:.3}");
    assert!((h - 0.56).abs() < 0.08, "{h}");
    assert!((one - 0.06).abs() < 0.08, "{one}");
}

#[test]
fn octave_cap_changes_output_only_past_the_cap() {
    let t = TurbulenceF32 { amount: Vec3::ONE, octaves: 3, omega: 0.5, lambda: 2.0 };
    for p in points(100, 20.0) {
        let full = turbulence(p, &t, None);
        assert_eq!(turbulence(p, &t, Some(3)), full);
        assert_eq!(turbulence(p, &t, Some(10)), full);
        assert_ne!(turbulence(p, &t, Some(2)), full);
        assert_eq!(turbulence(p, &t, Some(0)), Vec3::ZERO);
    }
}

#[test]
fn turbulence_first_octave_is_dnoise() {
    let t = TurbulenceF32 { amount: Vec3::splat(0.1), octaves: 1, omega: 0.5, lambda: 2.0 };
    let p = Vec3::new(0.3, 4.1, -2.2);
    assert_eq!(turbulence(p, &t, None), dnoise(p));
    assert_eq!(warp(p, &t, None), p + 0.1 * dnoise(p));
}

/// `dnoise` as it was computed before the lane-generic version: each corner's three gradient
/// dot products as one `Mat3A * Vec3A` from `GRAD3`. The bit table must give the same noise.
fn dnoise_from_grad3(p: Vec3) -> Vec3 {
    let c = cell(p);
    let mut v = [Vec3A::ZERO; 8];
    for (i, v) in v.iter_mut().enumerate() {
        *v = GRAD3[c.hash[i] as usize] * Vec3A::from(corner_offset(c.frac, i));
    }
    Vec3::from(blend(v, c.weight)) * DNOISE_SCALE
}

#[test]
fn eight_lanes_match_one_lane_and_the_gradient_table_bit_for_bit() {
    use crate::lanes::F8;
    let pts: Vec<Vec3> = points(8000, 600.0).collect();
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    for chunk in pts.chunks_exact(8) {
        let wide = dnoise_lanes(V3::<F8>::from_lanes(|i| chunk[i]));
        let t = TurbulenceF32 { amount: Vec3::new(0.3, 0.2, 0.1), octaves: 3, omega: 0.5, lambda: 2.0 };
        let wide_turb = turbulence_lanes(V3::<F8>::from_lanes(|i| chunk[i]), &t, None);
        for (i, &p) in chunk.iter().enumerate() {
            assert_eq!(bits(wide.lane(i)), bits(dnoise(p)), "{p}");
            assert_eq!(bits(dnoise(p)), bits(dnoise_from_grad3(p)), "{p}");
            assert_eq!(bits(wide_turb.lane(i)), bits(turbulence(p, &t, None)), "{p}");
        }
    }
}
