//! The internal functions `functions.inc` declares as `function { internal(N) }`, by POV-Ray's
//! numbers. Each takes x, y, z and its extra parameters; the formulas were checked against
//! POV-Ray 3.7 by evaluating them at parse time (`#debug str(f_sphere(...), 0, 8)` at sample
//! points, figures in the tests), not taken from its source.

/// The internal functions strahl models.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Internal {
    /// 17: `sqrt((x·a)² + (y·b)² + (z·c)²)` (no `- 1`: POV-Ray's value at (1, 0, 2) with
    /// (1, 2, 3) is √37).
    Ellipsoid,
    /// 25: `(n, period, minor, major, shape, section, angle)`: `n` tubes wound around y (see
    /// `helix1`).
    Helix1,
    /// 45: `s·(y − x² − z²)`.
    Paraboloid,
    /// 47: the polar angle `acos(y / r)` (0 at the origin).
    Ph,
    /// 57: the distance from the origin.
    R,
    /// 59: `(H, lacunarity, octaves, offset, gain, noise)`: Musgrave's ridged multifractal
    /// ("Texturing and Modeling", 2nd ed., ch. 16) over strahl's lattice noise mapped to
    /// [-1, 1]; octave i weighs λ^(−i·H), each octave's ridge (offset − |n|)² is damped by
    /// the previous one times `gain` (clamped to [0, 1]). The noise generator number is read
    /// and not modelled (one noise).
    RidgedMf,
    /// 60: `(radius, sx, sy, sz)`: the distance outside a box of half-sizes s with its edges
    /// rounded by `radius`; inside, `-radius` (POV-Ray subtracts a further 1e-6 everywhere).
    RoundedBox,
    /// 61: `|p| − radius`.
    Sphere,
    /// 68: `(e, n)`: `1 − ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2)`, negative outside.
    Superellipsoid,
    /// 69: the azimuth `atan2(x, z)`.
    Th,
    /// 70: `(major, minor)`: `√((√(x² + z²) − major)² + y²) − minor`.
    Torus,
    /// 76: lattice noise in [0, 1] (strahl's own, shared with the `bumps`-style patterns).
    Noise3d,
}

impl Internal {
    /// POV-Ray's number for it in `internal(N)`.
    pub fn from_number(n: u32) -> Option<Internal> {
        Some(match n {
            17 => Internal::Ellipsoid,
            25 => Internal::Helix1,
            45 => Internal::Paraboloid,
            47 => Internal::Ph,
            57 => Internal::R,
            59 => Internal::RidgedMf,
            60 => Internal::RoundedBox,
            61 => Internal::Sphere,
            68 => Internal::Superellipsoid,
            69 => Internal::Th,
            70 => Internal::Torus,
            76 => Internal::Noise3d,
            _ => return None,
        })
    }

    /// The numbers `from_number` knows, for messages.
    pub const NUMBERS: &'static str =
        "17 (f_ellipsoid), 25 (f_helix1), 45 (f_paraboloid), 47 (f_ph), 57 (f_r), 59 (f_ridged_mf), 60 (f_rounded_box), \
                                       61 (f_sphere), 68 (f_superellipsoid), 69 (f_th), 70 (f_torus), 76 (f_noise3d)";

    /// How many parameters it takes, x, y and z included.
    pub fn arity(self) -> usize {
        3 + match self {
            Internal::Ph | Internal::R | Internal::Th | Internal::Noise3d => 0,
            Internal::Sphere | Internal::Paraboloid => 1,
            Internal::Torus | Internal::Superellipsoid => 2,
            Internal::Ellipsoid => 3,
            Internal::RoundedBox => 4,
            Internal::RidgedMf => 6,
            Internal::Helix1 => 7,
        }
    }

    /// Its value at `a` (x, y, z, then the extra parameters; `arity` of them).
    #[inline]
    pub fn eval(self, a: &[f64]) -> f64 {
        let p = |i: usize| a.get(i).copied().unwrap_or(0.0);
        let (x, y, z) = (p(0), p(1), p(2));
        match self {
            Internal::Ellipsoid => ((x * p(3)).powi(2) + (y * p(4)).powi(2) + (z * p(5)).powi(2)).sqrt(),
            Internal::Paraboloid => p(3) * (y - x * x - z * z),
            Internal::Ph => {
                let r = (x * x + y * y + z * z).sqrt();
                if r > 0.0 {
                    (y / r).clamp(-1.0, 1.0).acos()
                } else {
                    0.0
                }
            }
            Internal::R => (x * x + y * y + z * z).sqrt(),
            Internal::RoundedBox => {
                let r = p(3);
                let q = |v: f64, s: f64| (v.abs() - s + r).max(0.0);
                let (qx, qy, qz) = (q(x, p(4)), q(y, p(5)), q(z, p(6)));
                (qx * qx + qy * qy + qz * qz).sqrt() - r - 1e-6
            }
            Internal::Helix1 => helix1([x, y, z], [p(3), p(4), p(5), p(6), p(7), p(8), p(9)]),
            Internal::RidgedMf => ridged_mf([x, y, z], p(3), p(4), p(5), p(6), p(7)),
            Internal::Sphere => (x * x + y * y + z * z).sqrt() - p(3),
            Internal::Superellipsoid => {
                let (e, n) = (p(3), p(4));
                let xy = x.abs().powf(2.0 / e) + y.abs().powf(2.0 / e);
                1.0 - (xy.powf(e / n) + z.abs().powf(2.0 / n)).powf(n / 2.0)
            }
            Internal::Th => x.atan2(z),
            Internal::Torus => {
                let w = (x * x + z * z).sqrt() - p(3);
                (w * w + y * y).sqrt() - p(4)
            }
            Internal::Noise3d => f64::from(crate::noise::noise(glam::Vec3::new(x as f32, y as f32, z as f32))),
        }
    }
}

/// `f_helix1` at `p` with `(n, period, minor, major, shape, section, angle)`, as POV-Ray 3.7
/// evaluates it (fitted to its `#debug` values at scattered points over every parameter, all
/// matching to 8 decimals; figures in the tests):
/// - across the tube: `dx = ρ − major`, ρ the distance from the y axis;
/// - along y: the tubes pass the azimuth `θ = atan2(z, x)` where `n·(period·y + θ)` is an odd
///   multiple of π, and `dy` is the height from the nearest, `(t − π) / (n·period·shape)` with
///   `t = n·(period·y + θ)` wrapped into [0, 2π) (so `shape` > 1 fattens the tube along y);
/// - `(dx, dy)` is turned by `angle` degrees and measured with the norm of exponent
///   `2 / section` (1 a circle, 2 a diamond, 0 a square, 3 a concave diamond);
/// - the value is that norm, at most `ρ + major`, less `minor`. With `n·period·shape` = 0 there
///   is no winding and the value is `ρ + major − minor` everywhere.
fn helix1(p: [f64; 3], [n, period, minor, major, shape, section, angle]: [f64; 7]) -> f64 {
    let [x, y, z] = p;
    let rho = x.hypot(z);
    let far = rho + major;
    let pitch = n * period * shape;
    if pitch == 0.0 {
        return far - minor;
    }
    let t = (n * (period * y + z.atan2(x))).rem_euclid(std::f64::consts::TAU);
    let (dx, dy) = (rho - major, (t - std::f64::consts::PI) / pitch);
    let (sin, cos) = angle.to_radians().sin_cos();
    let (u, v) = (dx * cos - dy * sin, dx * sin + dy * cos);
    let norm = if section == 0.0 {
        u.abs().max(v.abs())
    } else {
        let e = 2.0 / section;
        (u.abs().powf(e) + v.abs().powf(e)).powf(1.0 / e)
    };
    norm.min(far) - minor
}

/// Most octaves `f_ridged_mf` sums (each is one noise lookup).
const MAX_OCTAVES: f64 = 32.0;

/// Musgrave's ridged multifractal at `p` (see `Internal::RidgedMf`).
fn ridged_mf(p: [f64; 3], h: f64, lacunarity: f64, octaves: f64, offset: f64, gain: f64) -> f64 {
    let noise = |q: [f64; 3]| {
        let n = crate::noise::noise(glam::Vec3::new(q[0] as f32, q[1] as f32, q[2] as f32));
        2.0 * f64::from(n) - 1.0
    };
    let octaves = if octaves.is_finite() { octaves.clamp(0.0, MAX_OCTAVES) as usize } else { 0 };
    let mut q = p;
    let mut signal = offset - noise(q).abs();
    signal *= signal;
    let mut result = signal;
    for i in 1..octaves {
        q = q.map(|c| c * lacunarity);
        let weight = (signal * gain).clamp(0.0, 1.0);
        signal = offset - noise(q).abs();
        signal = signal * signal * weight;
        result += signal * lacunarity.powf(-(i as f64) * h);
    }
    result
}
