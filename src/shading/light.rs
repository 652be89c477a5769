//! Light models past the plain point light: spotlight and cylinder falloff, `fade_distance`,
//! and the sample positions of area lights (POV-Ray 3.7 semantics, checked by rendering
//! `tests/reference/scenes/lights_*.pov`). The light loop and shadow rays that use them are in
//! `render::trace`; point lights without fading keep the 8-lane shadow packets of
//! `render::packet`, every other light is shaded with single rays (area lights shoot one shadow
//! ray per sample, and spot/cylinder/parallel/fading lights take the single-ray path too so
//! that both paths stay bit-identical without a second lane copy of this file).

use glam::Vec3;

/// How a light's intensity varies with the direction it sends light in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Beam {
    /// Uniform in all directions.
    Point,
    /// `spotlight`: cosines of `radius` and `falloff` (`cos_radius >= cos_falloff`).
    Spot { cos_radius: f32, cos_falloff: f32 },
    /// `cylinder`: `radius` and `falloff` as distances from the axis.
    Cylinder { radius: f32, falloff: f32 },
}

/// POV-Ray's smooth step from `low` (0) to `high` (1): `t²(3 − 2t)`.
#[inline]
pub fn smooth_step(low: f32, high: f32, x: f32) -> f32 {
    if x <= low {
        0.0
    } else if x >= high {
        1.0
    } else {
        let t = (x - low) / (high - low);
        t * t * (3.0 - 2.0 * t)
    }
}

/// The intensity multiplier of a spotlight or cylinder at `from_light` (the vector from the
/// light to the lit point); `axis` is the unit direction the light points in, `tightness` the
/// exponent on the cosine (or on the fraction of the falloff distance, for a cylinder).
pub fn beam_factor(beam: Beam, axis: Vec3, tightness: f32, from_light: Vec3) -> f32 {
    match beam {
        Beam::Point => 1.0,
        Beam::Spot { cos_radius, cos_falloff } => {
            let dist = from_light.length();
            if dist == 0.0 {
                return 1.0;
            }
            let cos = from_light.dot(axis) / dist;
            if cos <= cos_falloff {
                return 0.0;
            }
            let mut f = if tightness == 0.0 { 1.0 } else { cos.powf(tightness) };
            if cos < cos_radius {
                f *= smooth_step(cos_falloff, cos_radius, cos);
            }
            f
        }
        Beam::Cylinder { radius, falloff } => {
            let along = from_light.dot(axis);
            if along <= 0.0 {
                return 0.0;
            }
            let off_axis = (from_light - along * axis).length();
            if off_axis >= falloff {
                return 0.0;
            }
            let rest = 1.0 - off_axis / falloff;
            let mut f = if tightness == 0.0 { 1.0 } else { rest.powf(tightness) };
            if off_axis > radius {
                f *= smooth_step(0.0, 1.0 - radius / falloff, rest);
            }
            f
        }
    }
}

/// `fade_distance D fade_power P`: `2 / (1 + (d/D)^P)`, 1 at distance `D` (POV-Ray's light
/// fading formula). `D <= 0` means no fading.
#[inline]
pub fn fade(distance: f32, fade_distance: f32, fade_power: f32) -> f32 {
    if fade_distance <= 0.0 {
        return 1.0;
    }
    2.0 / (1.0 + (distance / fade_distance).powf(fade_power))
}

/// The grid of an `area_light`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaGrid {
    pub axis1: Vec3,
    pub axis2: Vec3,
    pub size1: u32,
    pub size2: u32,
    /// `adaptive N`: `Some(N)`; every grid point otherwise.
    pub adaptive: Option<u32>,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
}

/// Corner-first subdivision stops when the four corners of a cell differ by less than this
/// in every channel: they are then all lit or all blocked.
pub const ADAPTIVE_TOLERANCE: f32 = 0.1;

impl AreaGrid {
    /// The grid with at most `cap` points: both sizes scaled down by the same factor
    /// (`Quality::max_area_samples`).
    pub fn capped(mut self, cap: Option<u32>) -> AreaGrid {
        if let Some(cap) = cap {
            let cap = cap.max(1);
            let n = self.size1 * self.size2;
            if n > cap {
                let k = (cap as f32 / n as f32).sqrt();
                self.size1 = ((self.size1 as f32 * k).floor() as u32).max(1);
                self.size2 = ((self.size2 as f32 * k).floor() as u32).max(1);
            }
        }
        self
    }

    /// The axes for a point lit from `to_point` (light → point): as written, or turned to face
    /// it (`orient`), keeping their lengths.
    pub fn axes(&self, to_point: Vec3) -> (Vec3, Vec3) {
        if !self.orient {
            return (self.axis1, self.axis2);
        }
        let d = to_point.normalize_or_zero();
        if d == Vec3::ZERO {
            return (self.axis1, self.axis2);
        }
        let helper = if d.x.abs() < 0.9 { Vec3::X } else { Vec3::Y };
        let a = d.cross(helper).normalize();
        let b = d.cross(a);
        (a * self.axis1.length(), b * self.axis2.length())
    }

    /// The offset from the light's centre of grid point (i, j) with axes `(a1, a2)`; `jitter`
    /// is a pair in [0, 1)² (used when the light says `jitter`): the point moves by up to half
    /// a cell either way.
    pub fn offset(&self, a1: Vec3, a2: Vec3, i: u32, j: u32, jitter: (f32, f32)) -> Vec3 {
        let coord = |k: u32, n: u32, r: f32| -> f32 {
            if n <= 1 {
                return 0.0;
            }
            let mut u = k as f32 / (n - 1) as f32 - 0.5;
            if self.jitter {
                u += (r - 0.5) / (n - 1) as f32;
            }
            u
        };
        let (mut u, mut v) = (coord(i, self.size1, jitter.0), coord(j, self.size2, jitter.1));
        if self.circular {
            (u, v) = square_to_disc(u, v);
        }
        a1 * u + a2 * v
    }
}

/// Shirley's concentric map of the square [-½, ½]² onto the disc of radius ½: squares of the
/// grid become rings, so a circular light's points stay evenly spread.
pub fn square_to_disc(u: f32, v: f32) -> (f32, f32) {
    let (a, b) = (2.0 * u, 2.0 * v);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) = if a.abs() > b.abs() {
        (a, std::f32::consts::FRAC_PI_4 * (b / a))
    } else {
        (b, std::f32::consts::FRAC_PI_2 - std::f32::consts::FRAC_PI_4 * (a / b))
    };
    (0.5 * r * phi.cos(), 0.5 * r * phi.sin())
}

/// A hash of `seed` words to two numbers in [0, 1): jitter without a shared generator, so a
/// pixel's value never depends on the thread or tile that traced it.
pub fn hash2(words: &[u32]) -> (f32, f32) {
    let mut h: u64 = 0x9e37_79b9_7f4a_7c15;
    for &w in words {
        h ^= w as u64;
        h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
        h ^= h >> 31;
    }
    h = h.wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 29;
    let a = (h >> 40) as u32 as f32 / (1u32 << 24) as f32;
    let b = ((h >> 8) & 0xff_ffff) as u32 as f32 / (1u32 << 24) as f32;
    (a, b)
}

/// Area-light visibility by POV-Ray's adaptive scheme: the four corners of a cell of grid
/// points first; when they agree (after at least `min_depth` splits) their mean stands for the
/// cell, else the cell is split in four. `sample(i, j)` is the light passed from grid point
/// (i, j); each point is traced at most once (`cache`, `size1 × size2` entries).
pub fn adaptive_visibility(
    size1: u32,
    size2: u32,
    min_depth: u32,
    cache: &mut Vec<Option<Vec3>>,
    sample: &mut dyn FnMut(u32, u32) -> Vec3,
) -> Vec3 {
    cache.clear();
    cache.resize((size1 * size2) as usize, None);
    region(0, size1 - 1, 0, size2 - 1, 0, min_depth, size1, cache, sample)
}

#[allow(clippy::too_many_arguments)]
fn region(
    i0: u32,
    i1: u32,
    j0: u32,
    j1: u32,
    depth: u32,
    min_depth: u32,
    size1: u32,
    cache: &mut [Option<Vec3>],
    sample: &mut dyn FnMut(u32, u32) -> Vec3,
) -> Vec3 {
    let mut at = |i: u32, j: u32, cache: &mut [Option<Vec3>]| -> Vec3 {
        let k = (j * size1 + i) as usize;
        *cache[k].get_or_insert_with(|| sample(i, j))
    };
    let c = [at(i0, j0, cache), at(i1, j0, cache), at(i0, j1, cache), at(i1, j1, cache)];
    let mean = (c[0] + c[1] + c[2] + c[3]) * 0.25;
    let smallest = i1 - i0 <= 1 && j1 - j0 <= 1;
    let agree = c.iter().all(|v| (*v - mean).abs().max_element() < ADAPTIVE_TOLERANCE);
    if smallest || (depth >= min_depth && agree) {
        return mean;
    }
    let is = if i1 - i0 > 1 { vec![(i0, (i0 + i1) / 2), ((i0 + i1) / 2, i1)] } else { vec![(i0, i1)] };
    let js = if j1 - j0 > 1 { vec![(j0, (j0 + j1) / 2), ((j0 + j1) / 2, j1)] } else { vec![(j0, j1)] };
    let mut sum = Vec3::ZERO;
    for &(a, b) in &is {
        for &(c0, c1) in &js {
            sum += region(a, b, c0, c1, depth + 1, min_depth, size1, cache, sample);
        }
    }
    sum / (is.len() * js.len()) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spotlight_falloff_curve() {
        let cos = |deg: f32| deg.to_radians().cos();
        let spot = Beam::Spot { cos_radius: cos(10.0), cos_falloff: cos(20.0) };
        let at = |deg: f32| {
            let r = deg.to_radians();
            beam_factor(spot, Vec3::Z, 0.0, Vec3::new(r.sin(), 0.0, r.cos()) * 3.0)
        };
        // Full inside the radius, nothing past the falloff, a smooth step between.
        assert_eq!(at(0.0), 1.0);
        assert_eq!(at(9.0), 1.0);
        assert_eq!(at(21.0), 0.0);
        assert!(at(12.0) > at(15.0) && at(15.0) > at(18.0) && at(18.0) > 0.0);
        let mid = smooth_step(cos(20.0), cos(10.0), cos(15.0));
        assert!((at(15.0) - mid).abs() < 1e-4, "{} {mid}", at(15.0));
        // Tightness multiplies by cos^tightness everywhere, the centre included.
        let tight = beam_factor(spot, Vec3::Z, 10.0, Vec3::new(cos(85.0), 0.0, cos(5.0)));
        assert!((tight - cos(5.0).powf(10.0)).abs() < 1e-3, "{tight}");
        // Behind the light: dark.
        assert_eq!(beam_factor(spot, Vec3::Z, 0.0, -Vec3::Z), 0.0);
    }

    #[test]
    fn cylinder_falloff_is_by_distance_from_the_axis() {
        let cyl = Beam::Cylinder { radius: 1.0, falloff: 2.0 };
        let at = |off: f32, along: f32| beam_factor(cyl, Vec3::Y, 0.0, Vec3::new(off, along, 0.0));
        assert_eq!(at(0.5, 10.0), 1.0);
        assert_eq!(at(0.5, 1000.0), 1.0);
        assert_eq!(at(2.5, 10.0), 0.0);
        assert_eq!(at(0.5, -1.0), 0.0);
        assert!(at(1.2, 5.0) > at(1.8, 5.0) && at(1.8, 5.0) > 0.0);
    }

    #[test]
    fn fade_formula() {
        // Full intensity at the fade distance, 2 at the light, 2/(1+2^p) at twice the distance.
        assert_eq!(fade(5.0, 5.0, 2.0), 1.0);
        assert_eq!(fade(0.0, 5.0, 2.0), 2.0);
        assert!((fade(10.0, 5.0, 2.0) - 0.4).abs() < 1e-6);
        assert!((fade(10.0, 5.0, 1.0) - 2.0 / 3.0).abs() < 1e-6);
        assert_eq!(fade(123.0, 0.0, 2.0), 1.0);
    }

    fn grid(jitter: bool, circular: bool) -> AreaGrid {
        AreaGrid {
            axis1: Vec3::X * 2.0,
            axis2: Vec3::Z * 2.0,
            size1: 3,
            size2: 3,
            adaptive: None,
            jitter,
            circular,
            orient: false,
        }
    }

    #[test]
    fn area_light_sample_positions() {
        let g = grid(false, false);
        // Corners at ± half an axis, the centre in the middle.
        assert_eq!(g.offset(g.axis1, g.axis2, 0, 0, (0.0, 0.0)), Vec3::new(-1.0, 0.0, -1.0));
        assert_eq!(g.offset(g.axis1, g.axis2, 2, 2, (0.0, 0.0)), Vec3::new(1.0, 0.0, 1.0));
        assert_eq!(g.offset(g.axis1, g.axis2, 1, 1, (0.9, 0.1)), Vec3::ZERO);
        // Circular: every point within the ellipse of the axes.
        let c = grid(false, true);
        for i in 0..3 {
            for j in 0..3 {
                assert!(c.offset(c.axis1, c.axis2, i, j, (0.0, 0.0)).length() <= 1.0 + 1e-6);
            }
        }
    }

    #[test]
    fn area_light_jitter_is_deterministic_and_within_its_cell() {
        let g = grid(true, false);
        let a = hash2(&[3, 7, 1, 4]);
        assert_eq!(a, hash2(&[3, 7, 1, 4]));
        assert_ne!(a, hash2(&[3, 7, 1, 5]));
        for s in 0..100u32 {
            let r = hash2(&[s, 11]);
            assert!((0.0..1.0).contains(&r.0) && (0.0..1.0).contains(&r.1));
            let p = g.offset(g.axis1, g.axis2, 1, 1, r);
            assert!(p.x.abs() <= 0.5 && p.z.abs() <= 0.5, "{p}");
        }
    }

    #[test]
    fn orient_turns_the_grid_to_face_the_point() {
        let g = AreaGrid { orient: true, circular: true, ..grid(false, true) };
        let (a, b) = g.axes(Vec3::new(1.0, -2.0, 0.5));
        let d = Vec3::new(1.0, -2.0, 0.5).normalize();
        assert!(a.dot(d).abs() < 1e-5 && b.dot(d).abs() < 1e-5);
        assert!((a.length() - 2.0).abs() < 1e-5 && (b.length() - 2.0).abs() < 1e-5);
    }

    #[test]
    fn adaptive_traces_corners_first_and_matches_the_full_grid_when_uniform() {
        let mut cache = Vec::new();
        let mut count = 0;
        let lit = adaptive_visibility(9, 9, 0, &mut cache, &mut |_, _| {
            count += 1;
            Vec3::ONE
        });
        assert_eq!((lit, count), (Vec3::ONE, 4));
        // adaptive 1: at least 9 rays (3×3 points).
        let mut count = 0;
        adaptive_visibility(9, 9, 1, &mut cache, &mut |_, _| {
            count += 1;
            Vec3::ZERO
        });
        assert_eq!(count, 9);
        // A half-blocked light: subdivision finds the edge, the result lies between.
        let v = adaptive_visibility(9, 9, 0, &mut cache, &mut |i, _| if i < 4 { Vec3::ZERO } else { Vec3::ONE });
        assert!(v.x > 0.3 && v.x < 0.7, "{v}");
    }

    #[test]
    fn capping_keeps_the_grid_shape() {
        let g = AreaGrid { size1: 16, size2: 8, ..grid(false, false) };
        let c = g.capped(Some(32));
        assert!(c.size1 * c.size2 <= 32 && c.size1 == 2 * c.size2, "{c:?}");
        assert_eq!(g.capped(None), g);
        assert_eq!(g.capped(Some(1000)), g);
    }
}
