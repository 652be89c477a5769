//! Render-ready normal perturbation (`bumps`), evaluated per hit in render space.
//!
//! POV-Ray's `bumps AMOUNT` adds `AMOUNT · DNoise(p)` to the normal in pattern space and
//! renormalises. Measured on POV-Ray 3.7 (plane lit by parallel lights at ±45° in x and in z,
//! `bumps 0.4`): the slope n_x/n_y has std 0.1028 (n_z/n_y: 0.0989) — exactly 0.4 × the DNoise
//! component std of 0.251 — and the same figures with `scale 1` and `scale 0.2`, so the
//! perturbation is not scaled by the transform: it lives in pattern space and is carried back
//! with the normal. Its autocorrelation (0.57 at 0.5 pattern units) equals DNoise's, so the
//! bump vector is DNoise itself, not a derivative of Noise.

use glam::{DMat4, Mat3A, Vec3};

use super::pattern_space::{pattern_from_render, Period};
use super::patterns::{Kind32, Pattern32};
use super::pigment::PatternQuality;
use crate::desc::{NormalDesc, NormalPattern, SlopeEntry};
use crate::lanes::{Lane, V3};
use crate::noise::{dnoise_lanes, warp_lanes, TurbulenceF32, LATTICE_PERIOD};

#[derive(Clone, Debug, PartialEq)]
pub enum NormalPattern32 {
    Bumps(f32),
    /// Any pattern of the kernel layer as a height: the normal tilts down its gradient by
    /// `amount` (the gradient by forward differences of `NORMAL_DELTA` in pattern space),
    /// the value first turned into a height by the `slope_map` if there is one.
    Pattern(Box<Pattern32>, f32, Option<Box<SlopeMap32>>),
    /// `normal_map`: entries sorted by value, each a whole normal of its own.
    Map(Box<Pattern32>, Vec<(f32, NormalF32)>),
}

/// A `slope_map` ready to evaluate: one cubic per interval of positive width, in powers of the
/// interval's parameter t (the Hermite curve with the entries' slopes per unit of t).
#[derive(Clone, Debug, PartialEq)]
pub struct SlopeMap32 {
    /// `(v0, v1, 1 / (v1 − v0), [c0, c1, c2, c3])`: height = c0 + c1·t + c2·t² + c3·t³.
    intervals: Vec<(f32, f32, f32, [f32; 4])>,
    /// The first entry's value and height (the height below it), and the last's (above it).
    first: (f32, f32),
    last: (f32, f32),
}

impl SlopeMap32 {
    /// `None` for an empty map. `entries` are sorted by value (`lower::textures`).
    pub fn new(entries: &[SlopeEntry]) -> Option<SlopeMap32> {
        let (first, last) = (entries.first()?, entries.last()?);
        let intervals = entries
            .windows(2)
            .filter(|w| w[1].value > w[0].value)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                // Hermite from (h0, s0) at t = 0 to (h1, s1) at t = 1, collected by powers of t.
                let c = [
                    a.height,
                    a.slope,
                    -3.0 * a.height - 2.0 * a.slope + 3.0 * b.height - b.slope,
                    2.0 * a.height + a.slope - 2.0 * b.height + b.slope,
                ];
                (a.value as f32, b.value as f32, (1.0 / (b.value - a.value)) as f32, c.map(|x| x as f32))
            })
            .collect();
        Some(SlopeMap32 {
            intervals,
            first: (first.value as f32, first.height as f32),
            last: (last.value as f32, last.height as f32),
        })
    }

    /// The height at pattern value `v`: the first entry's below it, the last's above it, the
    /// lowest interval holding `v` between (so at a value written twice the later entry starts
    /// the next interval).
    #[inline(always)]
    pub fn height<L: Lane>(&self, v: L) -> L {
        let mut out = L::splat(self.last.1);
        for &(v0, v1, inv, [c0, c1, c2, c3]) in self.intervals.iter().rev() {
            let t = (v - L::splat(v0)) * L::splat(inv);
            let h = L::splat(c0) + t * (L::splat(c1) + t * (L::splat(c2) + t * L::splat(c3)));
            out = L::select(v.le(L::splat(v1)), h, out);
        }
        L::select(v.le(L::splat(self.first.0)), L::splat(self.first.1), out)
    }
}

/// The finite-difference step for pattern normals, in pattern units.
const NORMAL_DELTA: f32 = 0.02;

/// POV-Ray 3.7 tilts a pattern normal far less than the pattern's slope: measured on a plane
/// lit at 45° by a parallel light, `normal { gradient x A }` tilts by atan(0.133·A) (A = 0.5,
/// 1, 2: 3.8°, 7.6°, 14.9°), the same under `scale 0.25`, and `marble 1` (slope 2) by twice
/// that. So the gradient is scaled by this before it tilts the normal (images excepted: a
/// `bump_map` steps one texel, `shading::image_map`).
const PATTERN_NORMAL_GAIN: f32 = 0.133;

/// `wrinkles` and `dents` have normals of their own in POV-Ray, steeper than the general
/// rule: on tests/reference/scenes/noise_normals.pov their texture strength (local std-dev)
/// came to 0.36× and 0.70× POV-Ray's with `PATTERN_NORMAL_GAIN`, so they tilt by these.
const WRINKLES_NORMAL_GAIN: f32 = PATTERN_NORMAL_GAIN * 2.0;
const DENTS_NORMAL_GAIN: f32 = PATTERN_NORMAL_GAIN * 1.4;
/// `ripples` and `waves` too: POV-Ray 3.7's textures/patterns/ripples.pov and waves.pov
/// measured 0.47–0.48× and 0.51× POV-Ray's texture strength (tests/suite/samples.rs regions).
const WAVE_NORMAL_GAIN: f32 = PATTERN_NORMAL_GAIN * 2.0;

/// POV-Ray's `wrinkles` normal leans one way: on a plane facing −z with `wrinkles 1`, parallel
/// lights at 45° from +x, −x, +y, −y and head-on give mean diffuse 0.821, 0.193, 0.825, 0.193
/// and 0.699, a mean normal near (0.45, 0.45, −0.70): the perturbation has a mean of about this
/// times the amount on every pattern axis, added to the slope.
const WRINKLES_BIAS: f32 = 0.4;

#[derive(Clone, Debug, PartialEq)]
pub struct NormalF32 {
    pub pattern: NormalPattern32,
    pub turbulence: Option<TurbulenceF32>,
    /// Render space → pattern space (points).
    pub pattern_from_render: glam::Affine3A,
    /// Carries a render-space normal into pattern space: the inverse transpose of the linear part.
    pub normal_to_pattern: Mat3A,
    /// Carries a pattern-space normal back: the transpose of the linear part.
    pub normal_from_pattern: Mat3A,
    /// `accuracy`: the tetrahedron's radius for the general pattern kinds.
    pub accuracy: f32,
}

/// Our dnoise is a little rougher than POV-Ray's: on a bumpy plane (`bumps 0.4`, scale 1 and
/// 0.2 alike) the slope n_x/n_y has a standard deviation of 0.1084 against POV-Ray's 0.1009, so
/// amounts are scaled by their ratio to give the same bump strength.
const BUMPS_GAIN: f64 = 0.1009 / 0.1084;

impl NormalF32 {
    pub fn from_desc(d: &NormalDesc, world_from_render: &DMat4) -> NormalF32 {
        let periods = match d.pattern {
            NormalPattern::Bumps(_) => [Period::Every(LATTICE_PERIOD); 3],
            NormalPattern::Pattern(..) | NormalPattern::Map(..) => [Period::Never; 3],
        };
        let pattern_from_render =
            pattern_from_render(&d.transform.inverse, world_from_render, periods, d.turbulence.as_ref());
        let linear = pattern_from_render.matrix3;
        let mut pattern = match &d.pattern {
            NormalPattern::Bumps(a) => NormalPattern32::Bumps((a * BUMPS_GAIN) as f32),
            NormalPattern::Pattern(p, a) => NormalPattern32::Pattern(
                Box::new(Pattern32::from_desc(p)),
                *a as f32,
                SlopeMap32::new(&d.slope_map).map(Box::new),
            ),
            NormalPattern::Map(p, entries) => NormalPattern32::Map(
                Box::new(Pattern32::from_desc(p)),
                entries.iter().map(|(v, n)| (*v as f32, NormalF32::from_desc(n, world_from_render))).collect(),
            ),
        };
        // Marble and wood build their turbulence in, so their slope follows it
        // (`Pattern32::build_in_turbulence`); other patterns are warped once before the
        // differences, as POV-Ray does.
        let turbulence = d.turbulence.as_ref().map(TurbulenceF32::from);
        let turbulence = match &mut pattern {
            NormalPattern32::Pattern(pat, ..) | NormalPattern32::Map(pat, _) => pat.build_in_turbulence(turbulence),
            NormalPattern32::Bumps(_) => turbulence,
        };
        NormalF32 {
            pattern,
            turbulence,
            pattern_from_render,
            normal_to_pattern: linear.inverse().transpose(),
            normal_from_pattern: linear.transpose(),
            accuracy: d.accuracy as f32,
        }
    }
}

/// The perturbed unit normal at a render-space point; `n` is the unit geometric normal.
#[inline]
pub fn perturb_normal(nrm: &NormalF32, p_render: Vec3, n: Vec3, q: PatternQuality) -> Vec3 {
    perturb_normal_lanes(nrm, V3::from_vec3(p_render), V3::from_vec3(n), q).vec3()
}

/// `perturb_normal` for one or eight points.
#[inline(always)]
pub fn perturb_normal_lanes<L: Lane>(nrm: &NormalF32, p_render: V3<L>, n: V3<L>, q: PatternQuality) -> V3<L> {
    let mut p = p_render.transform_point(&nrm.pattern_from_render);
    if let Some(t) = &nrm.turbulence {
        p = warp_lanes(p, t, q.max_octaves);
    }
    match &nrm.pattern {
        NormalPattern32::Bumps(amount) => {
            let np = n.mat3_mul(&nrm.normal_to_pattern).normalize_or(n);
            let bumped = np.add(dnoise_lanes(p).scale(L::splat(*amount)));
            bumped.mat3_mul(&nrm.normal_from_pattern).normalize_or(n)
        }
        NormalPattern32::Pattern(pat, amount, slope) => pattern_normal(nrm, pat, *amount, slope.as_deref(), p, n, q),
        NormalPattern32::Map(pat, entries) => normal_map(pat, entries, p, p_render, n, q),
    }
}

/// `normal_map`: the entries' perturbed normals blended by the pattern's value as a colour
/// map blends colours (clamped to the first and last entries), then renormalised.
#[inline(never)]
fn normal_map<L: Lane>(
    pat: &Pattern32,
    entries: &[(f32, NormalF32)],
    p: V3<L>,
    p_render: V3<L>,
    n: V3<L>,
    q: PatternQuality,
) -> V3<L> {
    // The entries' normals through one call each, not inlined four times over: each holds every
    // pattern, and the copies made this one of the largest functions LLVM had to optimise.
    #[inline(never)]
    fn perturb_normal_lanes<L: Lane>(nrm: &NormalF32, p_render: V3<L>, n: V3<L>, q: PatternQuality) -> V3<L> {
        super::normal::perturb_normal_lanes(nrm, p_render, n, q)
    }
    let v = pat.value_lanes(p, q.max_octaves);
    let (Some(first), Some(last)) = (entries.first(), entries.last()) else { return n };
    let mut out = perturb_normal_lanes(&last.1, p_render, n, q);
    for w in entries.windows(2).rev() {
        let ((v0, a), (v1, b)) = (&w[0], &w[1]);
        let nb = perturb_normal_lanes(b, p_render, n, q);
        let c = if v1 > v0 {
            let t = (v - L::splat(*v0)) / L::splat(v1 - v0);
            let na = perturb_normal_lanes(a, p_render, n, q);
            na.scale(L::splat(1.0) - t).add(nb.scale(t))
        } else {
            nb
        };
        out = V3::select(v.le(L::splat(*v1)), c, out);
    }
    let lo = perturb_normal_lanes(&first.1, p_render, n, q);
    V3::select(v.le(L::splat(first.0)), lo, out).normalize_or(n)
}

#[inline(never)]
fn pattern_normal<L: Lane>(
    nrm: &NormalF32,
    pat: &Pattern32,
    amount: f32,
    slope: Option<&SlopeMap32>,
    p: V3<L>,
    n: V3<L>,
    q: PatternQuality,
) -> V3<L> {
    // The warps move the point once and the unwarped pattern is differentiated around where
    // they put it, as POV-Ray 3.7 does (and as it does with the classic `turbulence`). Measured
    // on a plane lit from ±x and ±y, slope spread (n_x/n_z, n_y/n_z): `marble 0.6 warp {
    // turbulence 0.8 } scale 0.15` 0.157, 0.011 (differentiated through the warp: 0.242,
    // 0.195); `gradient x 1 triangle_wave` 0.259, 0.017 under `warp { turbulence 0.8 }` and
    // 0.261, 0.007 under a `black_hole` (0.419, 0.346 and 0.264, 0.023 through the warp), the
    // same as unwarped; `bozo 1 warp { turbulence 0.5 }` 0.039 as plain bozo (0.066 through it);
    // and under `warp { repeat x*0.3 flip x }` a constant slope of −0.264, the rising edge of
    // the triangle wave inside the first cell, flipped or not (through it: ±0.26).
    let pw = pat.warped(p, q.max_octaves);
    // quilted has a normal of its own, not its pigment's gradient (3.4.7.1.21: "similar ...
    // but not identical"); POV-Ray takes no slope_map or wave with it.
    if let Kind32::Quilted(c0, c1) = pat.kind {
        let w = super::patterns::simple::quilted_normal(pw, c0, c1);
        let np = n.mat3_mul(&nrm.normal_to_pattern).normalize_or(n);
        return np.add(w.scale(L::splat(amount))).mat3_mul(&nrm.normal_from_pattern).normalize_or(n);
    }
    // With a slope_map the gradient is the height's, by the same differences: POV-Ray 3.7
    // differentiates across the map too (a step in height shows as a ridge as wide as the
    // differences reach, measured on `[0.5 <0,0>] [0.5 <1,0>]`).
    let at = |d: Vec3| {
        let v = pat.value_at_warped_lanes(pw.add(V3::splat(d)), q.max_octaves);
        match slope {
            Some(m) => m.height(v),
            None => v,
        }
    };
    let grad = match &pat.kind {
        Kind32::Image(_) | Kind32::Wrinkles | Kind32::Dents | Kind32::Ripples | Kind32::Waves => {
            forward_gradient(pat, at)
        }
        _ => tetrahedron_gradient(at, nrm.accuracy),
    };
    let np = n.mat3_mul(&nrm.normal_to_pattern).normalize_or(n);
    let mut bumped = np.sub(grad.scale(L::splat(amount)));
    if matches!(pat.kind, Kind32::Wrinkles) {
        bumped = bumped.add(V3::splat(Vec3::splat(WRINKLES_BIAS * amount)));
    }
    bumped.mat3_mul(&nrm.normal_from_pattern).normalize_or(n)
}

/// The gradient by forward differences along the pattern axes, scaled by the kind's gain:
/// the images' own texel step, and the calibrated noise and wave kinds.
#[inline(always)]
fn forward_gradient<L: Lane>(pat: &Pattern32, at: impl Fn(Vec3) -> L) -> V3<L> {
    let v0 = at(Vec3::ZERO);
    // Images (`bump_map`) step one texel and tilt by the height difference itself
    // (`shading::image_map::ImageLookup::normal_step`); other patterns take the gradient.
    let (delta, inv) = match &pat.kind {
        Kind32::Image(im) => im.normal_step(),
        Kind32::Wrinkles => (NORMAL_DELTA, WRINKLES_NORMAL_GAIN / NORMAL_DELTA),
        Kind32::Dents => (NORMAL_DELTA, DENTS_NORMAL_GAIN / NORMAL_DELTA),
        Kind32::Ripples | Kind32::Waves => (NORMAL_DELTA, WAVE_NORMAL_GAIN / NORMAL_DELTA),
        _ => (NORMAL_DELTA, PATTERN_NORMAL_GAIN / NORMAL_DELTA),
    };
    let image = matches!(pat.kind, Kind32::Image(_));
    let dy = if image { -delta } else { delta };
    let (inv, inv_y) = (L::splat(inv), L::splat(inv * dy.signum()));
    // POV-Ray 3.7 differentiates a bump_map over a triangle: the point's texel and the two
    // texels either side of it on the next row down. Their difference (halved) is the x slope,
    // their mean less the point's height the y slope. Measured on a 16-texel disc (heights 30
    // and 230, `bump_size 1`): across a horizontal edge the tilt is 0.784 in y over one texel;
    // across a vertical edge 0.392 in x over two texels, and 0.392 in y as well, + outside the
    // edge and − inside it (a texel's mean neighbour below is 130, between its heights), which
    // a difference straight down the column (0 there) missed: 27.3 → 38.3 dB on bump_maps.pov,
    // the slope maps now equal POV-Ray's to 0.001 on bump16 and test16, plain and
    // `interpolate 2`. A 16-texel ramp tilts by its step a texel.
    if image {
        let (right, left) = (at(Vec3::new(delta, dy, 0.0)), at(Vec3::new(-delta, dy, 0.0)));
        let half = L::splat(0.5);
        let y = (right + left) * half - v0;
        return V3 { x: (right - left) * half * inv, y: y * inv_y, z: (at(Vec3::Z * delta) - v0) * inv };
    }
    V3 { x: (at(Vec3::X * delta) - v0) * inv, y: (at(Vec3::Y * dy) - v0) * inv_y, z: (at(Vec3::Z * delta) - v0) * inv }
}

/// The unit vertices of the tetrahedron POV-Ray 3.7 samples a pattern on for its normal, in
/// pattern space: one along +y, three below it at y = −1/3. Measured by where a step in height
/// (`slope_map { [0.5 <0,0>] [0.5 <1,0>] }`) shows as a ridge: the samples reach 0.0192 and
/// −0.0096 along x, 0.02 and −0.0064 along y, ±0.016 along z, at `NORMAL_DELTA` = 0.02.
/// Their offset also explains the lean of a smooth map's measured slope (0.0230 at value
/// 0.025 of `[0 <0,0>] [1 <1,0>]` against 0.0196 for the exact gradient).
const TETRAHEDRON: [Vec3; 4] = [
    Vec3::new(0.0, 1.0, 0.0),
    Vec3::new(0.942_809, -1.0 / 3.0, 0.0),
    Vec3::new(-0.471_405, -1.0 / 3.0, 0.816_497),
    Vec3::new(-0.471_405, -1.0 / 3.0, -0.816_497),
];

/// The gradient (times `PATTERN_NORMAL_GAIN`) from the tetrahedron's four samples at distance
/// `delta` (`accuracy`; POV-Ray's default `NORMAL_DELTA`): for unit
/// vertices summing to zero, Σ dᵢ dᵢᵀ = 4/3 I, so Σ h(p + δ dᵢ) dᵢ · 3 / (4δ) is exact for a
/// linear height. Four pattern lookups, as forward differences take.
#[inline(always)]
fn tetrahedron_gradient<L: Lane>(at: impl Fn(Vec3) -> L, delta: f32) -> V3<L> {
    let k = L::splat(PATTERN_NORMAL_GAIN * 3.0 / (4.0 * delta));
    let mut g = V3 { x: L::splat(0.0), y: L::splat(0.0), z: L::splat(0.0) };
    for d in TETRAHEDRON {
        g = g.add(V3::splat(d).scale(at(d * delta)));
    }
    g.scale(k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::Transform;
    use glam::DVec3;

    fn bumps(amount: f64, scale: DVec3) -> NormalF32 {
        let m = DMat4::from_scale(scale);
        let d = NormalDesc {
            pattern: NormalPattern::Bumps(amount),
            turbulence: None,
            transform: Transform { matrix: m, inverse: m.inverse() },
            slope_map: Vec::new(),
            accuracy: 0.02,
        };
        NormalF32::from_desc(&d, &DMat4::from_translation(DVec3::new(3.0, 1.0, -4.0)))
    }

    /// POV-Ray 3.7's `normal { quilted 1 }` on a plane facing −z, measured by parallel lights
    /// straight on and 30° off in ±x and ±y: the slopes n_x/(−n_z) and n_y/(−n_z) at points
    /// (x, y, z) of cells whose centre is (½, ½, ½).
    #[test]
    fn quilted_normal_matches_povray() {
        use crate::desc::{PatternDesc, PatternKind};
        let d = NormalDesc {
            pattern: NormalPattern::Pattern(PatternDesc::new(PatternKind::Quilted { c0: 1.0, c1: 1.0 }), 1.0),
            turbulence: None,
            transform: Transform { matrix: DMat4::IDENTITY, inverse: DMat4::IDENTITY },
            slope_map: Vec::new(),
            accuracy: 0.02,
        };
        let nrm = NormalF32::from_desc(&d, &DMat4::IDENTITY);
        for (p, sx, sy) in [
            ([0.0625, 0.9375, 0.5], -0.47718, 0.47718),
            ([0.1875, 0.6875, 0.5], -0.26820, 0.16092),
            ([0.9375, 0.8125, 0.3], 0.38418, 0.27443),
            ([0.0625, 0.9375, 0.3], -0.39603, 0.39603),
            ([0.4375, 0.5625, 0.05], -0.04225, 0.04225),
            ([0.3125, 0.1875, 0.05], -0.13530, -0.22550),
        ] {
            let n = perturb_normal(&nrm, Vec3::from(p), Vec3::NEG_Z, PatternQuality::default());
            let (gx, gy) = (n.x / -n.z, n.y / -n.z);
            assert!((gx - sx).abs() < 2e-3 && (gy - sy).abs() < 2e-3, "at {p:?}: ({gx}, {gy}), POV-Ray ({sx}, {sy})");
        }
    }

    fn entry(value: f64, height: f64, slope: f64) -> SlopeEntry {
        SlopeEntry { value, height, slope }
    }

    #[test]
    fn slope_map_heights_follow_hermite_curves_with_slopes_per_interval() {
        // The identity map is the value itself; `[0 <0,1>] [0.5 <1,1>]` is twice the value
        // (slopes per unit of the interval, POV-Ray 3.7 measured); outside the map the ends hold.
        let identity = SlopeMap32::new(&[entry(0.0, 0.0, 1.0), entry(1.0, 1.0, 1.0)]).unwrap();
        let half = SlopeMap32::new(&[entry(0.0, 0.0, 1.0), entry(0.5, 1.0, 1.0), entry(1.0, 0.0, -1.0)]).unwrap();
        let inner = SlopeMap32::new(&[entry(0.2, 0.3, 0.0), entry(0.8, 0.9, 0.0)]).unwrap();
        for i in 0..=100 {
            let v = i as f32 / 100.0;
            assert!((identity.height(v) - v).abs() < 1e-6);
            if v <= 0.5 {
                assert!((half.height(v) - 2.0 * v).abs() < 1e-5, "{v}");
            }
            let t = ((v - 0.2) / 0.6).clamp(0.0, 1.0);
            let smooth = 0.3 + 0.6 * t * t * (3.0 - 2.0 * t);
            assert!((inner.height(v) - smooth).abs() < 1e-5, "{v}: {}", inner.height(v));
        }
        // A value written twice: the later entry starts the next interval.
        let step =
            SlopeMap32::new(&[entry(0.0, 0.0, 0.0), entry(0.5, 0.0, 0.0), entry(0.5, 1.0, 0.0), entry(1.0, 1.0, 0.0)])
                .unwrap();
        assert_eq!((step.height(0.5f32), step.height(0.5001f32)), (0.0, 1.0));
        assert!(SlopeMap32::new(&[]).is_none());
    }

    #[test]
    fn tetrahedron_gradient_is_exact_for_linear_heights() {
        let g = Vec3::new(0.3, -1.2, 2.5);
        let got = tetrahedron_gradient::<f32>(|d| 7.0 + g.dot(d), 0.02).vec3() / PATTERN_NORMAL_GAIN;
        assert!((got - g).length() < 1e-3, "{got}");
    }

    #[test]
    fn bumps_leave_the_normal_unit_length() {
        let q = PatternQuality::default();
        for nrm in [bumps(0.4, DVec3::splat(0.2)), bumps(3.0, DVec3::new(1.0, 0.1, 5.0))] {
            for i in 0..500 {
                let p = Vec3::new(i as f32 * 0.37, (i % 7) as f32 * 1.3, (i % 11) as f32 * -0.9);
                let n = Vec3::new(0.3, 1.0, -0.2).normalize();
                let b = perturb_normal(&nrm, p, n, q);
                assert!((b.length() - 1.0).abs() < 1e-5);
            }
        }
    }

    #[test]
    fn bump_strength_is_independent_of_uniform_scale() {
        // POV-Ray: identical slope statistics for `scale 1` and `scale 0.2` (module doc).
        let q = PatternQuality::default();
        let slope_std = |s: f64| {
            let nrm = bumps(0.4, DVec3::splat(s));
            let mut v = Vec::new();
            for j in 0..200 {
                for i in 0..200 {
                    let p = Vec3::new(i as f32 * 0.13, 0.0, j as f32 * 0.13) * s as f32;
                    let b = perturb_normal(&nrm, p, Vec3::Y, q);
                    v.push(b.x / b.y);
                }
            }
            (v.iter().map(|x| x * x).sum::<f32>() / v.len() as f32).sqrt()
        };
        let (a, b) = (slope_std(1.0), slope_std(0.2));
        assert!((a - b).abs() / a < 0.1, "{a} vs {b}");
        assert!((a - 0.1028).abs() / 0.1028 < 0.15, "{a}");
    }

    #[test]
    fn far_bumps_reduce_by_the_noise_lattice() {
        // Bumps evaluated 256·3907 units from their origin (the camera there, the texture not
        // moved) become the numbers of the camera 3 units from it.
        let d = NormalDesc {
            pattern: NormalPattern::Bumps(0.4),
            turbulence: None,
            transform: Transform::default(),
            slope_map: Vec::new(),
            accuracy: 0.02,
        };
        let at = |x: f64| NormalF32::from_desc(&d, &DMat4::from_translation(DVec3::new(x, 1.0, -4.0)));
        assert_eq!(at(256.0 * 3907.0 + 3.0).pattern_from_render, at(3.0).pattern_from_render);
    }

    #[test]
    fn eight_lanes_match_one_lane_bit_for_bit() {
        use crate::lanes::F8;
        let q = PatternQuality::default();
        for nrm in [bumps(0.4, DVec3::splat(0.2)), bumps(3.0, DVec3::new(1.0, 0.1, 5.0))] {
            for k in 0..500 {
                let j = |i: usize| (k * 8 + i) as f32;
                let p = |i: usize| Vec3::new((j(i) * 0.7).sin() * 4.0, j(i) * 0.01, (j(i) * 0.3).cos() * 4.0);
                let n = |i: usize| Vec3::new((j(i) * 0.2).sin(), 1.0, (j(i) * 0.45).cos()).normalize();
                let wide = perturb_normal_lanes(&nrm, V3::<F8>::from_lanes(p), V3::<F8>::from_lanes(n), q);
                for i in 0..8 {
                    let one = perturb_normal(&nrm, p(i), n(i), q);
                    assert_eq!(wide.lane(i).to_array().map(f32::to_bits), one.to_array().map(f32::to_bits));
                }
            }
        }
    }
}
