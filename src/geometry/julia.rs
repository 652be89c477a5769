//! POV-Ray's `julia_fractal` (3.4.5.1.7 Julia Fractal): the points `h(0)` of a 3-D slice of
//! 4-D space whose orbit `h(n+1) = f(h(n)) + p` stays within radius 4 for `max_iteration`
//! steps, `f` a function of quaternions (`sqr`, `cube`) or of hypercomplex numbers (those and
//! the complex functions POV-Ray lists). A point `(x, y, z)` of the object lies on the slice
//! `N·h = D`: `h = (x, y, z, (D − N.xyz·(x, y, z)) / N.w)`.
//!
//! Hypercomplex numbers multiply commutatively with `k² = 1` (as Fractint's, whose algebra
//! POV-Ray follows), so `a + b·i + c·j + d·k` splits into the two complex numbers
//! `(a − d) + (b + c)·i` and `(a + d) + (b − c)·i`, on which every function acts one by one.
//!
//! A ray is marched through the bounding ball in steps of `1 / precision` (object units), each
//! sample iterated (but for those in cells proven empty, `julia_cells`), and the step where
//! inside and outside swap is bisected until the lane's rounding of the crossing is decided.
//! Thin parts shorter than a step can be missed, which is what POV-Ray's `precision` trades.
//! The normal is the gradient of `|h(k)|²` at the iteration `k` where the point just outside
//! escapes, by central differences. Lanes are solved one by one in f64.

use glam::{DAffine3, DVec3, DVec4, Vec3};

use std::sync::Arc;

use super::cuboid::{frame_for, BoxFrame};
use super::julia_cells::EmptyCells;
use super::{affine_f32, transformed_bounds};
use crate::desc::{ComplexFn, JuliaFunction};

/// The escape radius POV-Ray documents, squared.
const BAILOUT2: f64 = 16.0;

/// Most orbit steps `Julia::probe` follows; a longer orbit gets no reach.
const ORBIT: usize = 64;

/// A complex number, just what the hypercomplex functions need.
#[derive(Clone, Copy, Debug, PartialEq)]
struct C(f64, f64);

impl C {
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn div(self, o: C) -> C {
        let n = o.0 * o.0 + o.1 * o.1;
        C((self.0 * o.0 + self.1 * o.1) / n, (self.1 * o.0 - self.0 * o.1) / n)
    }
    fn exp(self) -> C {
        let m = self.0.exp();
        C(m * self.1.cos(), m * self.1.sin())
    }
    fn ln(self) -> C {
        C(self.0.hypot(self.1).ln(), self.1.atan2(self.0))
    }
    fn sqrt(self) -> C {
        let r = self.0.hypot(self.1);
        let re = (0.5 * (r + self.0)).max(0.0).sqrt();
        let im = (0.5 * (r - self.0)).max(0.0).sqrt();
        C(re, if self.1 < 0.0 { -im } else { im })
    }
    fn times_i(self) -> C {
        C(-self.1, self.0)
    }

    fn apply(self, f: ComplexFn) -> C {
        const ONE: C = C(1.0, 0.0);
        let z = self;
        match f {
            ComplexFn::Sqr => z.mul(z),
            ComplexFn::Cube => z.mul(z).mul(z),
            ComplexFn::Exp => z.exp(),
            ComplexFn::Reciprocal => ONE.div(z),
            ComplexFn::Sin => C(z.0.sin() * z.1.cosh(), z.0.cos() * z.1.sinh()),
            ComplexFn::Cos => C(z.0.cos() * z.1.cosh(), -z.0.sin() * z.1.sinh()),
            ComplexFn::Sinh => C(z.0.sinh() * z.1.cos(), z.0.cosh() * z.1.sin()),
            ComplexFn::Cosh => C(z.0.cosh() * z.1.cos(), z.0.sinh() * z.1.sin()),
            ComplexFn::Tan => z.apply(ComplexFn::Sin).div(z.apply(ComplexFn::Cos)),
            ComplexFn::Tanh => z.apply(ComplexFn::Sinh).div(z.apply(ComplexFn::Cosh)),
            ComplexFn::Ln => z.ln(),
            // asin z = −i·ln(i·z + sqrt(1 − z²)), acos z = −i·ln(z + i·sqrt(1 − z²)).
            ComplexFn::Asin => {
                let w = z.times_i().add(ONE.sub(z.mul(z)).sqrt()).ln();
                C(w.1, -w.0)
            }
            ComplexFn::Acos => {
                let w = z.add(ONE.sub(z.mul(z)).sqrt().times_i()).ln();
                C(w.1, -w.0)
            }
            // atan z = (i/2)·ln((i + z)/(i − z)).
            ComplexFn::Atan => {
                let i = C(0.0, 1.0);
                let w = i.add(z).div(i.sub(z)).ln();
                C(-0.5 * w.1, 0.5 * w.0)
            }
            ComplexFn::Asinh => z.add(z.mul(z).add(ONE).sqrt()).ln(),
            ComplexFn::Acosh => z.add(z.add(ONE).sqrt().mul(z.sub(ONE).sqrt())).ln(),
            ComplexFn::Atanh => {
                let w = ONE.add(z).div(ONE.sub(z)).ln();
                C(0.5 * w.0, 0.5 * w.1)
            }
            ComplexFn::Pwr(x, y) => {
                if z == C(0.0, 0.0) {
                    z
                } else {
                    z.ln().mul(C(x, y)).exp()
                }
            }
        }
    }
}

/// `f(h)` for one step of the iteration.
fn step(f: JuliaFunction, h: DVec4) -> DVec4 {
    let (a, b, c, d) = (h.x, h.y, h.z, h.w);
    match f {
        JuliaFunction::QuaternionSqr => {
            DVec4::new(a * a - b * b - c * c - d * d, 2.0 * a * b, 2.0 * a * c, 2.0 * a * d)
        }
        JuliaFunction::QuaternionCube => {
            let v2 = b * b + c * c + d * d;
            let s = 3.0 * a * a - v2;
            DVec4::new(a * a * a - 3.0 * a * v2, s * b, s * c, s * d)
        }
        JuliaFunction::Hypercomplex(g) => {
            let z1 = C(a - d, b + c).apply(g);
            let z2 = C(a + d, b - c).apply(g);
            DVec4::new(0.5 * (z1.0 + z2.0), 0.5 * (z1.1 + z2.1), 0.5 * (z1.1 - z2.1), 0.5 * (z2.0 - z1.0))
        }
    }
}

#[derive(Clone, Debug)]
pub struct Julia {
    pub frame: BoxFrame,
    param: DVec4,
    function: JuliaFunction,
    max_iteration: u32,
    /// March step, object units.
    step: f64,
    /// Of the bounding ball.
    radius: f64,
    /// The slice: `w = slice_w.w − slice_w.xyz·(x, y, z)`.
    slice_w: DVec4,
    /// How far `lift` moves `h` per unit `p` moves, at most: `|(1, −slice_w.xyz)|`.
    lift_gain: f64,
    /// Where the march need not iterate (quaternions only: `probe` has no bound otherwise).
    cells: Option<Arc<EmptyCells>>,
    pub min: Vec3,
    pub max: Vec3,
}

/// Radius of a ball the object lies in. Beyond the escape radius nothing stays; quaternions
/// are a normed algebra, so `|f(h) + p| ≥ |h|^k − |p|` (k = 2 for sqr, 3 for cube) and the
/// smallest radius from which that bound passes the escape radius within `max_iteration`
/// steps bounds the object tighter (hypercomplex numbers have no such norm).
fn radius(function: JuliaFunction, param: DVec4, max_iteration: u32) -> f64 {
    let power = match function {
        JuliaFunction::QuaternionSqr => 2,
        JuliaFunction::QuaternionCube => 3,
        JuliaFunction::Hypercomplex(_) => return BAILOUT2.sqrt(),
    };
    let (c, escape) = (param.length(), BAILOUT2.sqrt());
    let escapes = |mut r: f64| {
        for _ in 0..max_iteration {
            r = (r.powi(power) - c).max(0.0);
            if r > escape {
                return true;
            }
        }
        false
    };
    let (mut lo, mut hi) = (0.0, escape);
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if escapes(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
    // A sliver of margin over the bisection's last step.
    (hi * (1.0 + 1e-9)).min(escape)
}

impl Julia {
    /// `slice` is the 4-D normal and distance; its normal's w is not zero (checked when lowered).
    pub fn new(
        render_from_object: DAffine3,
        param: DVec4,
        function: JuliaFunction,
        max_iteration: u32,
        precision: f64,
        slice: (DVec4, f64),
    ) -> Julia {
        let (n, dist) = slice;
        let slice_w = DVec4::new(n.x / n.w, n.y / n.w, n.z / n.w, dist / n.w);
        let xf = affine_f32(&render_from_object);
        let radius = radius(function, param, max_iteration.max(1));
        let r = radius as f32;
        let (min, max) = transformed_bounds(&xf, Vec3::splat(-r), Vec3::splat(r));
        let pad = (max - min).max(min.abs().max(max.abs())) * 4.0 * f32::EPSILON;
        let mut julia = Julia {
            frame: frame_for(xf),
            param,
            function,
            max_iteration: max_iteration.max(1),
            step: 1.0 / precision.max(1.0),
            slice_w,
            lift_gain: (1.0 + slice_w.truncate().length_squared()).sqrt(),
            cells: None,
            radius,
            min: min - pad,
            max: max + pad,
        };
        let tag = match function {
            JuliaFunction::QuaternionSqr => Some(1),
            JuliaFunction::QuaternionCube => Some(2),
            JuliaFunction::Hypercomplex(_) => None,
        };
        if let Some(tag) = tag {
            let (p, s) = (param.to_array().map(f64::to_bits), slice_w.to_array().map(f64::to_bits));
            let key = [tag, p[0], p[1], p[2], p[3], julia.max_iteration as u64, s[0], s[1], s[2], s[3]];
            julia.cells = Some(EmptyCells::shared(key, radius, |q| julia.probe(q)));
        }
        julia
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    fn lift(&self, p: DVec3) -> DVec4 {
        let s = self.slice_w;
        DVec4::new(p.x, p.y, p.z, s.w - s.x * p.x - s.y * p.y - s.z * p.z)
    }

    /// How many steps of the iteration decide inside: `max_iteration` for quaternions, one
    /// fewer for hypercomplex numbers, which is what matches POV-Ray 3.7's renders (silhouettes
    /// of both algebras compared pixel by pixel against its orthographic renders).
    fn steps(&self) -> u32 {
        match self.function {
            JuliaFunction::Hypercomplex(_) => (self.max_iteration - 1).max(1),
            _ => self.max_iteration,
        }
    }

    /// The iteration at which the orbit of `p` escapes, `None` if it stays (inside).
    fn escape(&self, p: DVec3) -> Option<u32> {
        self.escape_all([p])[0]
    }

    /// `escape` of several points, their orbits iterated side by side: one orbit is a chain
    /// of dependent multiplications that leaves most of the processor idle, so two or three
    /// take little longer than one (julia_fractal.pov's frame took half as long when the
    /// march and the bisection went two and three samples at a time).
    fn escape_all<const N: usize>(&self, ps: [DVec3; N]) -> [Option<u32>; N] {
        match self.function {
            JuliaFunction::QuaternionSqr => self.escape_quaternion_in::<N, false>(ps),
            JuliaFunction::QuaternionCube => self.escape_quaternion_in::<N, true>(ps),
            JuliaFunction::Hypercomplex(_) => self.escape_hypercomplex(ps),
        }
    }

    /// `escape_quaternion` in the widest vectors the CPU has. The function is a constant of
    /// the kernel, so its loop holds no branch on it.
    #[inline(always)]
    fn escape_quaternion_in<const N: usize, const CUBE: bool>(&self, ps: [DVec3; N]) -> [Option<u32>; N] {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.escape_quaternion_avx2::<N, CUBE>(ps) };
        }
        self.escape_quaternion::<N, CUBE>(ps)
    }

    /// `escape_quaternion` with 256-bit vectors: the same operations (no FMA), so the same bits.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn escape_quaternion_avx2<const N: usize, const CUBE: bool>(&self, ps: [DVec3; N]) -> [Option<u32>; N] {
        self.escape_quaternion::<N, CUBE>(ps)
    }

    /// The quaternion orbits with each component of the points in an array of its own, so that
    /// one vector instruction steps several orbits: `step`'s arithmetic, operation for
    /// operation, and `length_squared`'s sum in its order, so every lane's bits are `step`'s.
    #[inline(always)]
    fn escape_quaternion<const N: usize, const CUBE: bool>(&self, ps: [DVec3; N]) -> [Option<u32>; N] {
        const STAYS: u32 = u32::MAX;
        let h = ps.map(|p| self.lift(p));
        let (mut x, mut y, mut z, mut w) = (h.map(|h| h.x), h.map(|h| h.y), h.map(|h| h.z), h.map(|h| h.w));
        let mut at = h.map(|h| if h.length_squared() > BAILOUT2 { 0 } else { STAYS });
        let q = self.param;
        for k in 1..=self.steps() {
            if at.iter().all(|&a| a != STAYS) {
                break;
            }
            for i in 0..N {
                let (a, b, c, d) = (x[i], y[i], z[i], w[i]);
                let (na, nb, nc, nd) = if CUBE {
                    let v2 = b * b + c * c + d * d;
                    let s = 3.0 * a * a - v2;
                    (a * a * a - 3.0 * a * v2, s * b, s * c, s * d)
                } else {
                    (a * a - b * b - c * c - d * d, 2.0 * a * b, 2.0 * a * c, 2.0 * a * d)
                };
                (x[i], y[i], z[i], w[i]) = (na + q.x, nb + q.y, nc + q.z, nd + q.w);
                let n2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i] + w[i] * w[i];
                // NaN (a function's pole) counts as escaped.
                let escaped = n2.is_nan() || n2 > BAILOUT2;
                at[i] = if at[i] == STAYS && escaped { k } else { at[i] };
            }
        }
        at.map(|a| (a != STAYS).then_some(a))
    }

    /// `escape_all` for hypercomplex functions, one `step` per orbit.
    fn escape_hypercomplex<const N: usize>(&self, ps: [DVec3; N]) -> [Option<u32>; N] {
        let mut h = ps.map(|p| self.lift(p));
        let mut at = h.map(|h| (h.length_squared() > BAILOUT2).then_some(0));
        for k in 1..=self.steps() {
            if at.iter().all(Option::is_some) {
                break;
            }
            for (h, at) in h.iter_mut().zip(at.iter_mut()) {
                *h = step(self.function, *h) + self.param;
                let n2 = h.length_squared();
                // NaN (a function's pole) counts as escaped.
                if at.is_none() && (n2.is_nan() || n2 > BAILOUT2) {
                    *at = Some(k);
                }
            }
        }
        at
    }

    fn inside_object(&self, p: DVec3) -> bool {
        self.escape(p).is_none()
    }

    /// A distance (object units) within which every point around `p` is outside, 0 where none
    /// is known (`p` inside, hypercomplex numbers, or an orbit longer than `ORBIT` steps).
    ///
    /// Quaternions are a normed algebra, so for `f(h) = hⁿ` (n = 2, 3) orbits `a(j)` and
    /// `b(j)` that are `e(j)` apart part by at most `e(j+1) ≤ (|a(j)| + e(j))ⁿ − |a(j)|ⁿ`
    /// (`a² − b² = a·(a − b) + (a − b)·b`, and likewise for cubes). A point whose orbit stays
    /// within `|a(j)| − 4` of `p`'s at a step `j ≤ steps` where `p`'s is past the escape
    /// radius has escaped too. That bound run backwards from every such `j` (the orbit is
    /// followed past its escape: far from the object the later, larger radii reach further)
    /// says how far `h(0)`, and so the point, may move: a guarantee, not an estimate.
    fn probe(&self, p: DVec3) -> f64 {
        let power = match self.function {
            JuliaFunction::QuaternionSqr => 2,
            JuliaFunction::QuaternionCube => 3,
            JuliaFunction::Hypercomplex(_) => return 0.0,
        };
        let steps = self.steps() as usize;
        let mut r = [0.0f64; ORBIT];
        let mut h = self.lift(p);
        let (mut escaped, mut last) = (None, 0);
        for (j, rj) in r.iter_mut().enumerate() {
            if j > 0 {
                h = step(self.function, h) + self.param;
            }
            let n2 = h.length_squared();
            if escaped.is_none() && n2 > BAILOUT2 {
                escaped = Some(j);
            }
            *rj = n2.sqrt();
            last = j;
            // Past a radius of 1e30 each further step only halves the reach (and cubes
            // would overflow).
            if j == steps || (escaped.is_some() && n2 > 1e60) {
                break;
            }
        }
        let Some(k) = escaped else { return 0.0 };
        // How far the orbit at step j may move: the most over every escaped step from j on.
        let mut m = 0.0f64;
        for j in (0..=last).rev() {
            let rj = r[j];
            if m > 0.0 {
                // The inverse of e ↦ (r + e)ⁿ − rⁿ, in a form that does not cancel.
                m = if power == 2 {
                    m / ((rj * rj + m).sqrt() + rj)
                } else {
                    let a = (rj * rj * rj + m).cbrt();
                    m / (a * a + a * rj + rj * rj)
                };
            }
            if j >= k {
                m = m.max(rj - BAILOUT2.sqrt());
            }
        }
        // A tenth off, for the rounding of the orbits compared.
        let reach = 0.9 * m / self.lift_gain;
        if reach.is_finite() {
            reach
        } else {
            0.0
        }
    }

    /// The nearest crossing in `(t_min, t_max)`; with `any` (a shadow ray), the far end of the
    /// first march step that holds one, where that step lies inside the interval and rounds
    /// above `t_min` (the bisection's answer could only lie in it, and be taken).
    fn solve(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64, round: fn(f64) -> f64, any: bool) -> Option<f64> {
        // The span of t within the bounding ball.
        let (a, b, c) = (d.dot(d), o.dot(d), o.dot(o) - self.radius * self.radius);
        let disc = b * b - a * c;
        if !(disc > 0.0 && a > 0.0) {
            return None;
        }
        let root = disc.sqrt();
        let (lo, hi) = (((-b - root) / a).max(t_min), ((-b + root) / a).min(t_max));
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return None;
        }
        let dt = self.step / a.sqrt();
        let p = o + lo * d;
        // A start in an empty cell is outside; most rays enter the ball so.
        let start = !self.cells.as_ref().is_some_and(|c| c.empty(p)) && self.inside_object(p);
        // Marching through the outside, a sample in an empty cell is known outside.
        let cells = self.cells.as_deref().filter(|_| !start);
        // Quaternion orbits are iterated up to eight at a time, in two vectors, which take
        // little longer than one: julia_fractal.pov's frame (1 thread, minima, a `quick` build)
        // went from 246 to 214 ms when the march's batches grew from four to eight. Hypercomplex
        // orbits are iterated one by one, so they keep batches of four.
        let fill = if cells.is_some() { 5 } else { 1 };
        let mut t0 = lo;
        loop {
            // The next samples whose side is not known, `fill` to eight of them (fewer at the
            // end), and the ones before them, taken four at a time.
            let (mut pending, mut n, mut end) = ([(0.0, 0.0); 8], 0, false);
            while n < fill && !end {
                let (mut next, mut m) = ([(t0, t0); 4], 0);
                while m < 4 && !end {
                    let t1 = (t0 + dt).min(hi);
                    next[m] = (t0, t1);
                    (t0, end, m) = (t1, t1 >= hi, m + 1);
                }
                let known = next.map(|(_, t)| cells.is_some_and(|c| c.empty(o + t * d)));
                for (&sample, &known) in next[..m].iter().zip(&known) {
                    // Stored either way, kept only where unknown: no branch per sample.
                    pending[n] = sample;
                    n += !known as usize;
                }
            }
            let sides: [bool; 8] = match n {
                0 => [start; 8],
                1 => std::array::from_fn(|i| if i == 0 { self.inside_object(o + pending[0].1 * d) } else { start }),
                2..=4 => {
                    let four = self.inside_all::<4>(std::array::from_fn(|i| o + pending[i.min(n - 1)].1 * d));
                    std::array::from_fn(|i| if i < 4 { four[i] } else { start })
                }
                _ => self.inside_all::<8>(std::array::from_fn(|i| o + pending[i.min(n - 1)].1 * d)),
            };
            if let Some(i) = sides[..n.max(1)].iter().position(|&s| s != start) {
                let (a, b) = pending[i];
                if any && round(a) > t_min && b < t_max {
                    return Some(b);
                }
                let b = self.crossing(o, d, start, a, b, round);
                return (b > t_min && b < t_max).then_some(b);
            }
            if end {
                return None;
            }
        }
    }

    /// `inside_object` of several points at once (`escape_all`).
    fn inside_all<const N: usize>(&self, ps: [DVec3; N]) -> [bool; N] {
        self.escape_all(ps).map(|e| e.is_none())
    }

    /// The crossing in `[a, b]`, where `o + a·d` is inside as `start` says and `o + b·d` is
    /// not, bisected until the lane's rounding of the bracket's ends agrees (to adjacent f64
    /// numbers for f64 lanes): every answer inside it rounds alike, so stopping there gives
    /// the f32 lanes the answer of bisecting on to f64 rounding, some 29 halvings sooner (f32
    /// carries 29 bits fewer). Secant steps on the size of the last orbit step took fewer
    /// still (julia_fractal.pov's frame a quarter shorter), but where a march step holds
    /// several crossings they may land on another than bisection does: the image changed.
    ///
    /// Three halvings are taken per round: every middle the next three could need (seven
    /// points, a heap: node `n`'s halves have the middles `2n` and `2n + 1`) is iterated side
    /// by side (`inside_all`, eight lanes), and the halvings then walk down the heap, so the
    /// steps and the answer are the plain bisection's.
    fn crossing(&self, o: DVec3, d: DVec3, start: bool, mut a: f64, mut b: f64, round: fn(f64) -> f64) -> f64 {
        loop {
            // Node n's bracket is lo..hi; its middle is 0.5 · (lo + hi), as the loop takes it.
            let mut mid = [0.0f64; 8];
            let mut ends = [(a, b); 8];
            for n in 1..8 {
                let (lo, hi) = ends[n];
                mid[n] = 0.5 * (lo + hi);
                if n < 4 {
                    (ends[2 * n], ends[2 * n + 1]) = ((lo, mid[n]), (mid[n], hi));
                }
            }
            let m = mid[1];
            if round(a) == round(b) || m <= a || m >= b {
                return b;
            }
            // Lane 0 repeats the first middle: eight lanes fill two vectors.
            mid[0] = m;
            let side = self.inside_all(mid.map(|t| o + t * d));
            let mut n = 1;
            while n < 8 {
                let m = mid[n];
                if n > 1 && (round(a) == round(b) || m <= a || m >= b) {
                    return b;
                }
                if side[n] == start {
                    a = m;
                    n = 2 * n + 1;
                } else {
                    b = m;
                    n *= 2;
                }
            }
        }
    }

    fn normal_object(&self, p: DVec3) -> DVec3 {
        // The surface near p is |h(k)|² = bailout for the k where the outside escapes; step
        // out along the rough gradient until a point escapes, then take |h(k)|²'s gradient.
        let e = 1e-6 * (1.0 + p.length());
        let k = self
            .escape_all([p, p + DVec3::splat(e), p - DVec3::splat(e)])
            .into_iter()
            .flatten()
            .max()
            .unwrap_or(self.steps())
            .max(1);
        // |h(k)|² at p ± e along each axis, the six orbits side by side.
        let mut h = [DVec3::X, -DVec3::X, DVec3::Y, -DVec3::Y, DVec3::Z, -DVec3::Z].map(|a| self.lift(p + a * e));
        for _ in 0..k {
            for h in h.iter_mut() {
                *h = step(self.function, *h) + self.param;
            }
        }
        let f = h.map(|h| h.length_squared());
        let g = DVec3::new(f[0] - f[1], f[2] - f[3], f[4] - f[5]);
        if g.is_finite() && g != DVec3::ZERO {
            g
        } else {
            p
        }
    }
}

shape_solved_in_f64!(Julia, normal: normal_object, inside: inside_object, solve: rounded, blocks: bracket);

#[cfg(test)]
mod tests;
