//! `W<N>`: `N` f64 lanes, for the polynomial shapes whose closed forms need f64 (a quadric seen
//! from far away, a torus) but should not pay for one lane at a time: `N = 8` for a packet,
//! which LLVM packs into 256-bit f64 instructions inside the AVX2 packet kernels, `N = 1` for a
//! single ray. Every operation works lane by lane in index order with plain IEEE arithmetic (no
//! contraction), so a lane of `W<8>` and a `W<1>` of the same inputs give the same bits: packets
//! and single rays agree by construction, as with `crate::lanes`.
//!
//! `lanes_f64` carries a ray's object-space origin and direction from any `Lane` into `W`,
//! and `to_lane` the answers back.
//!
//! The operations are plain loops, not `std::array::from_fn`: once enough kernels used `W`,
//! LLVM stopped inlining `from_fn`'s machinery into some of them and called it out of line,
//! without AVX2 (scenes/kernels/quartic.pov: 10 → 33 M instructions in `try_from_fn`, 22 %
//! more CPU time).

// Lane loops index several per-lane arrays at once; iterators would hide which lane is meant.
#![allow(clippy::needless_range_loop)]

use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::lanes::{Lane, V3};

/// `N` f64 lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct W<const N: usize>(pub [f64; N]);

/// Lane masks (one bool per lane).
pub type Mask<const N: usize> = [bool; N];

macro_rules! w_binop {
    ($tr:ident, $f:ident, $op:tt) => {
        impl<const N: usize> $tr for W<N> {
            type Output = W<N>;
            #[inline(always)]
            fn $f(self, o: W<N>) -> W<N> {
                let mut out = self.0;
                for i in 0..N {
                    out[i] = self.0[i] $op o.0[i];
                }
                W(out)
            }
        }
    };
}
w_binop!(Add, add, +);
w_binop!(Sub, sub, -);
w_binop!(Mul, mul, *);
w_binop!(Div, div, /);

impl<const N: usize> Neg for W<N> {
    type Output = W<N>;
    #[inline(always)]
    fn neg(self) -> W<N> {
        self.map(|v| -v)
    }
}

impl<const N: usize> W<N> {
    #[inline(always)]
    pub fn splat(v: f64) -> W<N> {
        W([v; N])
    }
    #[inline(always)]
    pub fn map(self, f: impl Fn(f64) -> f64) -> W<N> {
        let mut out = self.0;
        for i in 0..N {
            out[i] = f(self.0[i]);
        }
        W(out)
    }
    #[inline(always)]
    pub fn zip(self, o: W<N>, f: impl Fn(f64, f64) -> f64) -> W<N> {
        let mut out = self.0;
        for i in 0..N {
            out[i] = f(self.0[i], o.0[i]);
        }
        W(out)
    }
    #[inline(always)]
    pub fn sqrt(self) -> W<N> {
        self.map(f64::sqrt)
    }
    #[inline(always)]
    pub fn abs(self) -> W<N> {
        self.map(f64::abs)
    }
    /// `|self|` with `sign`'s sign bit.
    #[inline(always)]
    pub fn copysign(self, sign: W<N>) -> W<N> {
        self.zip(sign, f64::copysign)
    }
    /// The larger of each pair; `o` where either is NaN (as `maxpd` answers).
    #[inline(always)]
    pub fn max(self, o: W<N>) -> W<N> {
        self.zip(o, |a, b| if a > b { a } else { b })
    }
    /// The smaller of each pair; `o` where either is NaN (as `minpd` answers).
    #[inline(always)]
    pub fn min(self, o: W<N>) -> W<N> {
        self.zip(o, |a, b| if a < b { a } else { b })
    }
    #[inline(always)]
    pub fn lt(self, o: W<N>) -> Mask<N> {
        let mut out = [false; N];
        for i in 0..N {
            out[i] = self.0[i] < o.0[i];
        }
        out
    }
    #[inline(always)]
    pub fn le(self, o: W<N>) -> Mask<N> {
        let mut out = [false; N];
        for i in 0..N {
            out[i] = self.0[i] <= o.0[i];
        }
        out
    }
    /// `a` where `m`, else `b`.
    #[inline(always)]
    pub fn select(m: Mask<N>, a: W<N>, b: W<N>) -> W<N> {
        let mut out = b.0;
        for i in 0..N {
            if m[i] {
                out[i] = a.0[i];
            }
        }
        W(out)
    }
}

/// Lane-wise `a && b`.
#[inline(always)]
pub fn and<const N: usize>(a: Mask<N>, b: Mask<N>) -> Mask<N> {
    let mut out = a;
    for i in 0..N {
        out[i] = a[i] & b[i];
    }
    out
}

/// Lane-wise `a || b`.
#[inline(always)]
pub fn or<const N: usize>(a: Mask<N>, b: Mask<N>) -> Mask<N> {
    let mut out = a;
    for i in 0..N {
        out[i] = a[i] | b[i];
    }
    out
}

/// Lane-wise `!m`.
#[inline(always)]
pub fn not<const N: usize>(m: Mask<N>) -> Mask<N> {
    let mut out = m;
    for i in 0..N {
        out[i] = !m[i];
    }
    out
}

/// A shape solved in f64 lanes in its object space: `solve` answers each lane's nearest hit of
/// `o + t·d` in `(t_min, t_max)`, `+inf` for none, as the lane type will hold it (`round`).
pub trait WideSolve {
    fn solve<const N: usize>(
        &self,
        o: WV<N>,
        d: WV<N>,
        t_min: W<N>,
        t_max: W<N>,
        round: impl Fn(f64) -> f64 + Copy,
    ) -> W<N>;
}

/// `Shape::hit` of a `WideSolve` shape in `frame`: the ray moved to object space in the lane
/// type (as every framed shape does), then solved eight lanes at once for a packet, one for a
/// single ray.
#[inline(always)]
pub fn hit_wide<L: Lane, S: WideSolve>(
    shape: &S,
    frame: &super::cuboid::BoxFrame,
    ray: &crate::ray::RayLanes<L>,
    t_min: L,
    t_max: L,
) -> L {
    let o = ray.o.transform_point(&frame.object_from_render);
    let d = ray.d.transform_vector(&frame.object_from_render);
    if L::WIDTH == 8 {
        let t = shape.solve::<8>(lanes_f64(o), lanes_f64(d), lane_f64(t_min), lane_f64(t_max), L::round_f64);
        to_lane(t)
    } else {
        let t = shape.solve::<1>(lanes_f64(o), lanes_f64(d), lane_f64(t_min), lane_f64(t_max), L::round_f64);
        to_lane(t)
    }
}

/// A vector of f64 lanes.
#[derive(Clone, Copy, Debug)]
pub struct WV<const N: usize> {
    pub x: W<N>,
    pub y: W<N>,
    pub z: W<N>,
}

impl<const N: usize> WV<N> {
    #[inline(always)]
    pub fn dot(self, o: WV<N>) -> W<N> {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    #[inline(always)]
    pub fn scale(self, s: W<N>) -> WV<N> {
        WV { x: self.x * s, y: self.y * s, z: self.z * s }
    }
    #[inline(always)]
    pub fn add(self, o: WV<N>) -> WV<N> {
        WV { x: self.x + o.x, y: self.y + o.y, z: self.z + o.z }
    }
}

/// The first `N` lanes of `v` (`N ≤ L::WIDTH`), widened exactly to f64.
#[inline(always)]
pub fn lanes_f64<L: Lane, const N: usize>(v: V3<L>) -> WV<N> {
    let w = |l: L| W(std::array::from_fn(|i| l.get_f64(i)));
    WV { x: w(v.x), y: w(v.y), z: w(v.z) }
}

/// The first `N` lanes of a scalar lane value, widened to f64.
#[inline(always)]
pub fn lane_f64<L: Lane, const N: usize>(v: L) -> W<N> {
    W(std::array::from_fn(|i| v.get_f64(i)))
}

/// `v` as lanes of `L` (`N == L::WIDTH`), each lane rounded as `L` holds it.
#[inline(always)]
pub fn to_lanes<L: Lane, const N: usize>(v: WV<N>) -> V3<L> {
    V3 { x: to_lane(v.x), y: to_lane(v.y), z: to_lane(v.z) }
}

/// `w` as the lane type `L` (`N == L::WIDTH`), each lane rounded as `L` holds it.
#[inline(always)]
pub fn to_lane<L: Lane, const N: usize>(w: W<N>) -> L {
    L::from_fn_f64(|i| w.0[i.min(N - 1)])
}

/// The ray `o + t·d` about its point `p` nearest the object origin with unit direction `u`, for
/// `N` lanes: a distance `s` along `u` from `p` is at `t = t_c + s / len`. The arithmetic of
/// `geometry::centred_ray` lane by lane; `valid` is false where that answers `None` (a zero,
/// infinite or NaN direction).
#[derive(Clone, Copy, Debug)]
pub struct CentredLanes<const N: usize> {
    pub p: [W<N>; 3],
    pub u: [W<N>; 3],
    pub t_c: W<N>,
    pub len: W<N>,
    pub valid: [bool; N],
}

impl<const N: usize> CentredLanes<N> {
    #[inline(always)]
    pub fn new(o: WV<N>, d: WV<N>) -> CentredLanes<N> {
        let len2 = d.x * d.x + d.y * d.y + d.z * d.z;
        let valid = std::array::from_fn(|i| {
            let l = len2.0[i];
            !(l.is_nan() || l <= 0.0 || !l.is_finite())
        });
        let len = len2.sqrt();
        let u = [d.x / len, d.y / len, d.z / len];
        let t_c = -(o.x * d.x + o.y * d.y + o.z * d.z) / len2;
        let p = [o.x + t_c * d.x, o.y + t_c * d.y, o.z + t_c * d.z];
        CentredLanes { p, u, t_c, len, valid }
    }
}
