//! The fractal patterns (`mandel`, `julia`, `magnet 1|2 mandel|julia`): one escape-time
//! kernel over the pattern-space x-y plane, with POV-Ray's interior and exterior colouring
//! types (3.4.7.1.11). Each lane iterates in f64 (deep zooms such as fractals2.pov's
//! `scale 10000` need more than f32 keeps of the point), with no lane arithmetic: the orbits
//! of neighbouring lanes stop at different iterations.

use crate::desc::{Fractal, FractalKind};
use crate::lanes::{Lane, V3};

/// |z|² beyond which an orbit has escaped (radius 2, as the Mandelbrot set is drawn).
const BAILOUT_SQ: f64 = 4.0;

/// The magnet maps' bailouts, fitted to POV-Ray 3.7 renders of `magnet 1|2 mandel 60` with
/// exterior type 1 over [−2, 2] × [−1.5, 1.5] (mean iteration error 0.04 for type 1, 0.34
/// for type 2): an orbit ends when |z|² > 400 or when it has reached the fixed point 1,
/// |z − 1|² < 0.006 (the basin of 1 counts as exterior: POV-Ray shows it in iterations).
const MAGNET_BAILOUT_SQ: f64 = 400.0;
const MAGNET_CONVERGED_SQ: f64 = 0.006;

/// The render-ready form: as `desc::Fractal` with the kind's constants in f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal32 {
    pub kind: FractalKind,
    pub iterations: u32,
    pub interior: (u32, f64),
    pub exterior: (u32, f64),
}

impl Fractal32 {
    pub fn from_desc(d: &Fractal) -> Fractal32 {
        Fractal32 { kind: d.kind, iterations: d.iterations.max(1), interior: d.interior, exterior: d.exterior }
    }
}

/// Complex multiplication and division on (re, im) pairs.
#[inline(always)]
fn mul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}

#[inline(always)]
fn div(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let d = b.0 * b.0 + b.1 * b.1;
    if d == 0.0 {
        return (f64::INFINITY, f64::INFINITY);
    }
    ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
}

#[inline(always)]
fn powi(z: (f64, f64), n: u32) -> (f64, f64) {
    let mut out = z;
    for _ in 1..n {
        out = mul(out, z);
    }
    out
}

/// One step of the map with parameter `c`.
#[inline(always)]
fn step(kind: &FractalKind, z: (f64, f64), c: (f64, f64)) -> (f64, f64) {
    let add = |a: (f64, f64), b: (f64, f64)| (a.0 + b.0, a.1 + b.1);
    let scale = |a: (f64, f64), k: f64| (a.0 * k, a.1 * k);
    match *kind {
        FractalKind::Mandel { exponent } | FractalKind::Julia { exponent, .. } => add(powi(z, exponent), c),
        FractalKind::MagnetMandel { magnet: 1 } | FractalKind::MagnetJulia { magnet: 1, .. } => {
            // ((z² + c − 1) / (2z + c − 2))²
            let num = add(mul(z, z), (c.0 - 1.0, c.1));
            let den = add(scale(z, 2.0), (c.0 - 2.0, c.1));
            let q = div(num, den);
            mul(q, q)
        }
        _ => {
            // ((z³ + 3(c − 1)z + (c − 1)(c − 2)) / (3z² + 3(c − 2)z + (c − 1)(c − 2) + 1))²
            let c1 = (c.0 - 1.0, c.1);
            let c2 = (c.0 - 2.0, c.1);
            let c12 = mul(c1, c2);
            let num = add(add(powi(z, 3), scale(mul(c1, z), 3.0)), c12);
            let den = add(add(scale(mul(z, z), 3.0), scale(mul(c2, z), 3.0)), (c12.0 + 1.0, c12.1));
            let q = div(num, den);
            mul(q, q)
        }
    }
}

/// The value at one point of the x-y plane.
pub fn fractal_at(f: &Fractal32, x: f64, y: f64) -> f64 {
    // Mandel orbits start at their first point, c (0 maps to it): checked against POV-Ray 3.7,
    // which shows every point beyond radius 2 at exterior value 0 (mandel and julia count
    // the iterations before the one that escapes; the magnets count that one too).
    let (mut z, c) = match f.kind {
        FractalKind::Mandel { .. } => ((x, y), (x, y)),
        FractalKind::MagnetMandel { .. } => ((0.0, 0.0), (x, y)),
        FractalKind::Julia { c, .. } | FractalKind::MagnetJulia { c, .. } => ((x, y), (c[0], c[1])),
    };
    let magnet = matches!(f.kind, FractalKind::MagnetMandel { .. } | FractalKind::MagnetJulia { .. });
    let counted = u32::from(magnet);
    let bailout = if magnet { MAGNET_BAILOUT_SQ } else { BAILOUT_SQ };
    // The orbit's smallest |z|² after the start (a mandel orbit starts at 0, which POV-Ray's
    // interior type 1 does not show).
    let mut min_sq = f64::INFINITY;
    for n in 0..f.iterations {
        z = step(&f.kind, z, c);
        let r = z.0 * z.0 + z.1 * z.1;
        let converged = magnet && (z.0 - 1.0) * (z.0 - 1.0) + z.1 * z.1 < MAGNET_CONVERGED_SQ;
        // A NaN orbit (a magnet's division by zero) has escaped too.
        if r > bailout || r.is_nan() || converged {
            return wrap(exterior(f, n + counted, z));
        }
        min_sq = min_sq.min(r);
    }
    let (t, k) = f.interior;
    wrap(match t {
        1 => min_sq.sqrt() * k,
        _ => last_point(t, z, k),
    })
}

/// Values outside [0, 1] repeat (POV-Ray 3.7: `interior 6, 0.5` on a mandel shows bands
/// where |z|/2 passes each whole number); 1 itself stays 1 (the default interior).
#[inline(always)]
fn wrap(v: f64) -> f64 {
    if (0.0..=1.0).contains(&v) {
        v
    } else {
        v - v.floor()
    }
}

/// Exterior colouring of an orbit that escaped after `n` iterations at `z`.
fn exterior(f: &Fractal32, n: u32, z: (f64, f64)) -> f64 {
    let (t, k) = f.exterior;
    match t {
        1 => n as f64 / f.iterations as f64,
        7 if k >= 1.0 => (n as f64 % k.floor()) / k.floor(),
        8 if k >= 0.0 => (n as f64 % (k.floor() + 1.0)) / k.floor().max(1.0),
        _ => last_point(t, z, k),
    }
}

/// Types 0 and 2–6, shared by interior and exterior: from the orbit's last point.
fn last_point(t: u32, z: (f64, f64), k: f64) -> f64 {
    let v = match t {
        2 => z.0,
        3 => z.1,
        4 => z.0 * z.0,
        5 => z.1 * z.1,
        6 => (z.0 * z.0 + z.1 * z.1).sqrt(),
        _ => return 1.0,
    };
    if v.is_finite() {
        v * k
    } else {
        1.0
    }
}

/// The fractal for one or eight points, lane by lane.
#[inline(always)]
pub fn fractal<L: Lane>(p: V3<L>, f: &Fractal32) -> L {
    L::from_fn_f64(|i| fractal_at(f, p.x.get_f64(i), p.y.get_f64(i)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f(kind: FractalKind) -> Fractal32 {
        Fractal32::from_desc(&Fractal::new(kind, 30))
    }

    #[test]
    fn mandel_inside_is_one_and_outside_escapes() {
        let m = f(FractalKind::Mandel { exponent: 2 });
        assert_eq!(fractal_at(&m, -0.1, 0.1), 1.0);
        assert!(fractal_at(&m, 1.5, 1.5) < 0.1);
        // Exterior type 1: beyond radius 2 the first step escapes, value 0; 0.5 escapes in
        // 3 steps from its first point (0.5, 0.75, 1.0625, 1.6289, 3.15).
        assert_eq!(fractal_at(&m, 3.0, 0.0), 0.0);
        assert!((fractal_at(&m, 0.5, 0.0) - 3.0 / 30.0).abs() < 1e-12);
    }

    #[test]
    fn julia_starts_from_the_point() {
        let j = f(FractalKind::Julia { c: [0.0, 0.0], exponent: 2 });
        // z ← z²: inside the unit circle it never escapes; interior 1 is the orbit's
        // smallest |z|.
        let mut j1 = j;
        j1.interior = (1, 1.0);
        assert!(fractal_at(&j1, 0.5, 0.0) < 1e-6);
        assert_eq!(fractal_at(&j, 0.5, 0.0), 1.0);
        assert!(fractal_at(&j, 1.5, 0.0) < 0.1);
        assert_eq!(fractal_at(&j, 2.5, 0.0), 0.0);
    }

    #[test]
    fn magnet_orbits_end_at_the_fixed_point_one() {
        // z = 1 is a fixed point of magnet type 1 for every c (num = c, den = c).
        for magnet in [1, 2] {
            let m = f(FractalKind::MagnetJulia { magnet, c: [0.3, 0.2] });
            // It is reached at once: exterior after one iteration.
            assert!((fractal_at(&m, 1.0, 0.0) - 1.0 / 30.0).abs() < 1e-12, "magnet {magnet}");
        }
        let m = f(FractalKind::MagnetMandel { magnet: 1 });
        assert!(fractal_at(&m, 5.0, 5.0) < 0.5);
    }
}
