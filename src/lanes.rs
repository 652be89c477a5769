//! The arithmetic every ray test, pattern and shading formula is written in: `Lane`, a number
//! that is one `f32`, eight `f32`s (`F8`) or one `f64`, and `V3`, a vector of lanes.
//!
//! Formulas are written once, generic over `Lane`, so the packet path computes exactly the
//! same IEEE operations in the same order as the single-ray path: packets and single rays give
//! bit-identical results by construction, not by tolerance. `F8` is eight `f32`s operated on with
//! plain loops; inside a function compiled with AVX2 enabled (see `render::packet`) LLVM turns
//! each loop into one 256-bit instruction, and elsewhere into two SSE instructions. Neither
//! contracts `a*b + c` into FMA, so both give the same bits on every x86-64 CPU.
//!
//! `f64` is the same formula in double precision: `--precision f64` re-solves a ray's nearest
//! hit with it, and a shape whose formula needs more than f32 holds (a quartic) may compute in
//! it internally. Constants and shape data enter as `f32` (`splat`), which widens exactly.
//!
//! This module is at the bottom of the house: it depends on nothing but glam.

// Eight-lane operations are written out lane by lane (`each8!`), which LLVM's SLP vectoriser
// turns into one vector instruction. `V3::add`/`sub`/`mul` are lane-generic helpers, not the
// operator traits (which would need more bounds on `L` for no gain).
#![allow(clippy::needless_range_loop, clippy::should_implement_trait)]

use std::ops::{Add, Div, Mul, Neg, Sub};

use glam::Vec3;

/// Whether this CPU has AVX2, for the functions that keep a `#[target_feature(enable = "avx2")]`
/// copy of their eight-lane code (`render::packet` and the kernels it calls out of line). The
/// same IEEE operations give the same bits either way; AVX2 only does eight of them at once.
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn has_avx2() -> bool {
    std::arch::is_x86_feature_detected!("avx2")
}

#[cfg(not(target_arch = "x86_64"))]
#[inline]
pub fn has_avx2() -> bool {
    false
}

/// `f32::next_up` without branches, so that eight lanes of it vectorise (`Lane::map`): the same
/// value for every input (NaN and +∞ stay, ±0 steps to the least subnormal, a positive number's
/// bits go up by one, a negative number's down by one; a test compares it with `f32::next_up`).
#[inline(always)]
pub fn next_up(x: f32) -> f32 {
    let b = x.to_bits();
    let abs = b & 0x7fff_ffff;
    let stays = abs >= 0x7f80_0000 && b != 0xff80_0000;
    let step = if (b as i32) < 0 { b.wrapping_sub(1) } else { b.wrapping_add(1) };
    let next = if abs == 0 { 1 } else { step };
    f32::from_bits(if stays { b } else { next })
}

pub trait Lane:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self>
{
    type Mask: Copy;
    fn splat(v: f32) -> Self;
    fn sqrt(self) -> Self;
    /// `if self < o { self } else { o }`: the minps/maxps rule, so NaN picks `o` in both widths.
    fn min(self, o: Self) -> Self;
    fn max(self, o: Self) -> Self;
    fn lt(self, o: Self) -> Self::Mask;
    fn le(self, o: Self) -> Self::Mask;
    fn and(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    fn or(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    fn not(a: Self::Mask) -> Self::Mask;
    fn xor(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// 1 for `self >= 0` (including -0), else -1: the sign the stable quadratic needs, never 0.
    fn sign_or_one(self) -> Self;
    fn abs(self) -> Self;
    fn recip(self) -> Self {
        Self::splat(1.0) / self
    }
    /// Lanes in one value: 1 for `f32` and `f64`, 8 for `F8`.
    const WIDTH: usize;
    /// Lane `i` (rounded to f32 for `f64`).
    fn get(self, i: usize) -> f32;
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self;
    /// Lane `i` widened to f64 (exact), for formulas that solve each lane in f64.
    fn get_f64(self, i: usize) -> f64;
    /// Lanes from f64 values, rounded once to the lane's precision.
    fn from_fn_f64(f: impl FnMut(usize) -> f64) -> Self;
    /// `v` rounded to the lane's precision (and widened back): what a lane would hold. An f64
    /// solve must compare its roots with `t_min` after this, or a root that rounds down onto
    /// `t_min` is found again and again (CSG looking past a crossing).
    fn round_f64(v: f64) -> f64;
    /// Whether lane `i` of a mask is set.
    fn mask_lane(m: Self::Mask, i: usize) -> bool;
    /// Whether any lane of `m` is set.
    fn any(m: Self::Mask) -> bool;
    fn mask_from_fn(f: impl FnMut(usize) -> bool) -> Self::Mask;
    fn floor(self) -> Self;
    /// `f` applied lane by lane, for what has no vector instruction (`powf`, `round`).
    fn map(self, f: impl Fn(f32) -> f32) -> Self;
    /// `self · g` per lane for a g ∈ {−1, 0, 1} packed in `bits[lane]`: bit `k` set means g ≠ 0,
    /// bit `k + 16` set means g < 0. Bit for bit the product for finite `self` (a zero product
    /// keeps `self`'s sign), by integer operations where selects would build g first.
    fn times_unit(self, bits: &[u32; 8], k: u32) -> Self;
}

/// `times_unit` on one lane's bits.
#[inline(always)]
fn times_unit_bits(v: u32, bits: u32, k: u32) -> u32 {
    const SIGN: u32 = 1 << 31;
    let nonzero = ((bits >> k) & 1).wrapping_neg();
    let flip = ((bits >> (16 + k)) & 1) << 31;
    ((v ^ flip) & nonzero) | (v & SIGN & !nonzero)
}

impl Lane for f32 {
    type Mask = bool;
    #[inline(always)]
    fn splat(v: f32) -> f32 {
        v
    }
    #[inline(always)]
    fn sqrt(self) -> f32 {
        f32::sqrt(self)
    }
    #[inline(always)]
    fn min(self, o: f32) -> f32 {
        if self < o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn max(self, o: f32) -> f32 {
        if self > o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn lt(self, o: f32) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: f32) -> bool {
        self <= o
    }
    #[inline(always)]
    fn and(a: bool, b: bool) -> bool {
        a & b
    }
    #[inline(always)]
    fn or(a: bool, b: bool) -> bool {
        a | b
    }
    #[inline(always)]
    fn not(a: bool) -> bool {
        !a
    }
    #[inline(always)]
    fn xor(a: bool, b: bool) -> bool {
        a ^ b
    }
    #[inline(always)]
    fn select(m: bool, a: f32, b: f32) -> f32 {
        if m {
            a
        } else {
            b
        }
    }
    #[inline(always)]
    fn abs(self) -> f32 {
        f32::abs(self)
    }
    #[inline(always)]
    fn sign_or_one(self) -> f32 {
        if self >= 0.0 {
            1.0
        } else {
            -1.0
        }
    }
    const WIDTH: usize = 1;
    #[inline(always)]
    fn get(self, _: usize) -> f32 {
        self
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> f32 {
        f(0)
    }
    #[inline(always)]
    fn get_f64(self, _: usize) -> f64 {
        self as f64
    }
    #[inline(always)]
    fn round_f64(v: f64) -> f64 {
        v as f32 as f64
    }
    #[inline(always)]
    fn from_fn_f64(mut f: impl FnMut(usize) -> f64) -> f32 {
        f(0) as f32
    }
    #[inline(always)]
    fn mask_lane(m: bool, _: usize) -> bool {
        m
    }
    #[inline(always)]
    fn any(m: bool) -> bool {
        m
    }
    #[inline(always)]
    fn mask_from_fn(mut f: impl FnMut(usize) -> bool) -> bool {
        f(0)
    }
    #[inline(always)]
    fn floor(self) -> f32 {
        f32::floor(self)
    }
    #[inline(always)]
    fn map(self, f: impl Fn(f32) -> f32) -> f32 {
        f(self)
    }
    #[inline(always)]
    fn times_unit(self, bits: &[u32; 8], k: u32) -> f32 {
        f32::from_bits(times_unit_bits(self.to_bits(), bits[0], k))
    }
}

/// One lane in double precision: the `f32` rules (minps/maxps on NaN, the sign never 0) in f64.
impl Lane for f64 {
    type Mask = bool;
    #[inline(always)]
    fn splat(v: f32) -> f64 {
        v as f64
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn min(self, o: f64) -> f64 {
        if self < o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn max(self, o: f64) -> f64 {
        if self > o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn lt(self, o: f64) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: f64) -> bool {
        self <= o
    }
    #[inline(always)]
    fn and(a: bool, b: bool) -> bool {
        a & b
    }
    #[inline(always)]
    fn or(a: bool, b: bool) -> bool {
        a | b
    }
    #[inline(always)]
    fn not(a: bool) -> bool {
        !a
    }
    #[inline(always)]
    fn xor(a: bool, b: bool) -> bool {
        a ^ b
    }
    #[inline(always)]
    fn select(m: bool, a: f64, b: f64) -> f64 {
        if m {
            a
        } else {
            b
        }
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn sign_or_one(self) -> f64 {
        if self >= 0.0 {
            1.0
        } else {
            -1.0
        }
    }
    const WIDTH: usize = 1;
    #[inline(always)]
    fn get(self, _: usize) -> f32 {
        self as f32
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> f64 {
        f(0) as f64
    }
    #[inline(always)]
    fn get_f64(self, _: usize) -> f64 {
        self
    }
    #[inline(always)]
    fn round_f64(v: f64) -> f64 {
        v
    }
    #[inline(always)]
    fn from_fn_f64(mut f: impl FnMut(usize) -> f64) -> f64 {
        f(0)
    }
    #[inline(always)]
    fn mask_lane(m: bool, _: usize) -> bool {
        m
    }
    #[inline(always)]
    fn any(m: bool) -> bool {
        m
    }
    #[inline(always)]
    fn mask_from_fn(mut f: impl FnMut(usize) -> bool) -> bool {
        f(0)
    }
    #[inline(always)]
    fn floor(self) -> f64 {
        f64::floor(self)
    }
    #[inline(always)]
    fn map(self, f: impl Fn(f32) -> f32) -> f64 {
        f(self as f32) as f64
    }
    #[inline(always)]
    fn times_unit(self, bits: &[u32; 8], k: u32) -> f64 {
        let g = if (bits[0] >> k) & 1 == 0 {
            0.0
        } else if (bits[0] >> (16 + k)) & 1 == 0 {
            1.0
        } else {
            -1.0
        };
        if g == 0.0 {
            0.0f64.copysign(self)
        } else {
            self * g
        }
    }
}

/// `[e(0), e(1), …, e(7)]` with `$i` bound to each index, written out: straight-line code. Every
/// eight-lane operation is built from it, so that no loop is left for LLVM to rotate, unroll and
/// vectorise in each of the thousands of places an operation is inlined (as loops, those passes
/// took more than half of the library's optimisation time); the SLP vectoriser packs the eight
/// lines into one instruction, as it did the unrolled loops. The elements run in index order.
macro_rules! each8 {
    (|$i:ident| $e:expr) => {
        [
            { let $i: usize = 0; $e },
            { let $i: usize = 1; $e },
            { let $i: usize = 2; $e },
            { let $i: usize = 3; $e },
            { let $i: usize = 4; $e },
            { let $i: usize = 5; $e },
            { let $i: usize = 6; $e },
            { let $i: usize = 7; $e },
        ]
    };
}

/// Eight f32 lanes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(32))]
pub struct F8(pub [f32; 8]);

/// Eight lane masks, all-ones or zero, as i32 so selects vectorise to blends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C, align(32))]
pub struct M8(pub [i32; 8]);

impl M8 {
    #[inline(always)]
    pub fn any(self) -> bool {
        let a = self.0;
        (a[0] | a[1] | a[2] | a[3] | a[4] | a[5] | a[6] | a[7]) != 0
    }
    #[inline(always)]
    pub fn lane(self, i: usize) -> bool {
        self.0[i] != 0
    }
    #[inline(always)]
    pub fn from_fn(f: impl Fn(usize) -> bool) -> M8 {
        M8(each8!(|i| -(f(i) as i32)))
    }
    /// How many lanes are set (a vector sum: set lanes are −1).
    #[inline(always)]
    pub fn count(self) -> u32 {
        let a = self.0;
        (-(a[0] + a[1] + a[2] + a[3] + a[4] + a[5] + a[6] + a[7])) as u32
    }
    /// The lanes of `values` equal to `v`, without a branch per lane.
    #[inline(always)]
    pub fn equal(values: &[u32; 8], v: u32) -> M8 {
        M8(each8!(|i| -((values[i] == v) as i32)))
    }
}

macro_rules! f8_binop {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for F8 {
            type Output = F8;
            #[inline(always)]
            fn $f(self, o: F8) -> F8 {
                F8(each8!(|i| self.0[i] $op o.0[i]))
            }
        }
    };
}
f8_binop!(Add, add, +);
f8_binop!(Sub, sub, -);
f8_binop!(Mul, mul, *);
f8_binop!(Div, div, /);

impl Neg for F8 {
    type Output = F8;
    #[inline(always)]
    fn neg(self) -> F8 {
        F8(each8!(|i| -self.0[i]))
    }
}

impl F8 {
    #[inline(always)]
    fn zip(self, o: F8, f: impl Fn(f32, f32) -> f32) -> F8 {
        F8(each8!(|i| f(self.0[i], o.0[i])))
    }
    #[inline(always)]
    fn cmp(self, o: F8, f: impl Fn(f32, f32) -> bool) -> M8 {
        M8(each8!(|i| -(f(self.0[i], o.0[i]) as i32)))
    }
}

impl Lane for F8 {
    type Mask = M8;
    #[inline(always)]
    fn splat(v: f32) -> F8 {
        F8([v; 8])
    }
    #[inline(always)]
    fn sqrt(self) -> F8 {
        F8(each8!(|i| self.0[i].sqrt()))
    }
    #[inline(always)]
    fn min(self, o: F8) -> F8 {
        self.zip(o, <f32 as Lane>::min)
    }
    #[inline(always)]
    fn max(self, o: F8) -> F8 {
        self.zip(o, <f32 as Lane>::max)
    }
    #[inline(always)]
    fn lt(self, o: F8) -> M8 {
        self.cmp(o, |a, b| a < b)
    }
    #[inline(always)]
    fn le(self, o: F8) -> M8 {
        self.cmp(o, |a, b| a <= b)
    }
    #[inline(always)]
    fn and(a: M8, b: M8) -> M8 {
        M8(each8!(|i| a.0[i] & b.0[i]))
    }
    #[inline(always)]
    fn or(a: M8, b: M8) -> M8 {
        M8(each8!(|i| a.0[i] | b.0[i]))
    }
    #[inline(always)]
    fn not(a: M8) -> M8 {
        M8(each8!(|i| !a.0[i]))
    }
    #[inline(always)]
    fn xor(a: M8, b: M8) -> M8 {
        M8(each8!(|i| a.0[i] ^ b.0[i]))
    }
    #[inline(always)]
    fn select(m: M8, a: F8, b: F8) -> F8 {
        F8(each8!(|i| f32::from_bits((a.0[i].to_bits() & m.0[i] as u32) | (b.0[i].to_bits() & !m.0[i] as u32))))
    }
    #[inline(always)]
    fn abs(self) -> F8 {
        F8(each8!(|i| self.0[i].abs()))
    }
    #[inline(always)]
    fn sign_or_one(self) -> F8 {
        F8(each8!(|i| <f32 as Lane>::sign_or_one(self.0[i])))
    }
    const WIDTH: usize = 8;
    #[inline(always)]
    fn get(self, i: usize) -> f32 {
        self.0[i]
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> F8 {
        F8(each8!(|i| f(i)))
    }
    #[inline(always)]
    fn get_f64(self, i: usize) -> f64 {
        self.0[i] as f64
    }
    #[inline(always)]
    fn round_f64(v: f64) -> f64 {
        v as f32 as f64
    }
    #[inline(always)]
    fn from_fn_f64(mut f: impl FnMut(usize) -> f64) -> F8 {
        F8(each8!(|i| f(i) as f32))
    }
    #[inline(always)]
    fn mask_lane(m: M8, i: usize) -> bool {
        m.0[i] != 0
    }
    #[inline(always)]
    fn any(m: M8) -> bool {
        m.any()
    }
    #[inline(always)]
    fn mask_from_fn(mut f: impl FnMut(usize) -> bool) -> M8 {
        M8(each8!(|i| -(f(i) as i32)))
    }
    #[inline(always)]
    fn floor(self) -> F8 {
        F8(each8!(|i| self.0[i].floor()))
    }
    #[inline(always)]
    fn map(self, f: impl Fn(f32) -> f32) -> F8 {
        F8(each8!(|i| f(self.0[i])))
    }
    #[inline(always)]
    fn times_unit(self, bits: &[u32; 8], k: u32) -> F8 {
        F8(each8!(|i| f32::from_bits(times_unit_bits(self.0[i].to_bits(), bits[i], k))))
    }
}

/// A vector of lanes.
#[derive(Clone, Copy, Debug)]
pub struct V3<L> {
    pub x: L,
    pub y: L,
    pub z: L,
}

impl<L: Lane> V3<L> {
    #[inline(always)]
    pub fn splat(v: Vec3) -> V3<L> {
        V3 { x: L::splat(v.x), y: L::splat(v.y), z: L::splat(v.z) }
    }
    #[inline(always)]
    pub fn add(self, o: V3<L>) -> V3<L> {
        V3 { x: self.x + o.x, y: self.y + o.y, z: self.z + o.z }
    }
    #[inline(always)]
    pub fn sub(self, o: V3<L>) -> V3<L> {
        V3 { x: self.x - o.x, y: self.y - o.y, z: self.z - o.z }
    }
    #[inline(always)]
    pub fn scale(self, s: L) -> V3<L> {
        V3 { x: self.x * s, y: self.y * s, z: self.z * s }
    }
    #[inline(always)]
    pub fn mul(self, o: V3<L>) -> V3<L> {
        V3 { x: self.x * o.x, y: self.y * o.y, z: self.z * o.z }
    }
    #[inline(always)]
    pub fn dot(self, o: V3<L>) -> L {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    #[inline(always)]
    pub fn cross(self, o: V3<L>) -> V3<L> {
        V3 { x: self.y * o.z - self.z * o.y, y: self.z * o.x - self.x * o.z, z: self.x * o.y - self.y * o.x }
    }
    #[inline(always)]
    pub fn min(self, o: V3<L>) -> V3<L> {
        V3 { x: self.x.min(o.x), y: self.y.min(o.y), z: self.z.min(o.z) }
    }
    #[inline(always)]
    pub fn max(self, o: V3<L>) -> V3<L> {
        V3 { x: self.x.max(o.x), y: self.y.max(o.y), z: self.z.max(o.z) }
    }
    #[inline(always)]
    pub fn recip(self) -> V3<L> {
        V3 { x: self.x.recip(), y: self.y.recip(), z: self.z.recip() }
    }
    /// The largest absolute component, with `Lane::max`'s rule (as `ray::max_abs`).
    #[inline(always)]
    pub fn max_abs(self) -> L {
        self.x.abs().max(self.y.abs()).max(self.z.abs())
    }
    #[inline(always)]
    pub fn select(m: L::Mask, a: V3<L>, b: V3<L>) -> V3<L> {
        V3 { x: L::select(m, a.x, b.x), y: L::select(m, a.y, b.y), z: L::select(m, a.z, b.z) }
    }
    #[inline(always)]
    pub fn neg(self) -> V3<L> {
        V3 { x: -self.x, y: -self.y, z: -self.z }
    }
    /// `1 / |v|`, as glam's `length_recip`.
    #[inline(always)]
    pub fn length_recip(self) -> L {
        self.dot(self).sqrt().recip()
    }
    /// `v / |v|`, computed as glam's `Vec3::normalize` does (`v * (1 / sqrt(v·v))`).
    #[inline(always)]
    pub fn normalize(self) -> V3<L> {
        self.scale(self.length_recip())
    }
    /// `v / |v|`, or `fallback` where that is not finite (glam's `normalize_or`).
    #[inline(always)]
    pub fn normalize_or(self, fallback: V3<L>) -> V3<L> {
        let rcp = self.length_recip();
        let ok = L::and(rcp.lt(L::splat(f32::INFINITY)), L::splat(0.0).lt(rcp));
        V3::select(ok, self.scale(rcp), fallback)
    }
    /// Component `axis` (0 = x, 1 = y, 2 = z).
    #[inline(always)]
    pub fn axis(self, axis: usize) -> L {
        match axis {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }
    /// Lane `i` as a `Vec3`.
    #[inline(always)]
    pub fn lane(self, i: usize) -> Vec3 {
        Vec3::new(self.x.get(i), self.y.get(i), self.z.get(i))
    }
    /// Lanes built from one `Vec3` per lane.
    #[inline(always)]
    pub fn from_lanes(mut f: impl FnMut(usize) -> Vec3) -> V3<L> {
        let mut v = [Vec3::ZERO; 8];
        for (i, v) in v.iter_mut().enumerate().take(L::WIDTH) {
            *v = f(i);
        }
        V3 { x: L::from_fn(|i| v[i].x), y: L::from_fn(|i| v[i].y), z: L::from_fn(|i| v[i].z) }
    }
    /// A 3×3 matrix times each lane's vector, in glam's `Mat3A * Vec3A` order (columns).
    #[inline(always)]
    pub fn mat3_mul(self, m: &glam::Mat3A) -> V3<L> {
        let c = |a: glam::Vec3A| V3::<L>::splat(Vec3::from(a));
        c(m.x_axis).scale(self.x).add(c(m.y_axis).scale(self.y)).add(c(m.z_axis).scale(self.z))
    }
    /// An affine map (column-major 3×3 plus translation) applied to a point.
    #[inline(always)]
    pub fn transform_point(self, a: &glam::Affine3A) -> V3<L> {
        let m = &a.matrix3;
        V3 {
            x: self.x * L::splat(m.x_axis.x)
                + self.y * L::splat(m.y_axis.x)
                + self.z * L::splat(m.z_axis.x)
                + L::splat(a.translation.x),
            y: self.x * L::splat(m.x_axis.y)
                + self.y * L::splat(m.y_axis.y)
                + self.z * L::splat(m.z_axis.y)
                + L::splat(a.translation.y),
            z: self.x * L::splat(m.x_axis.z)
                + self.y * L::splat(m.y_axis.z)
                + self.z * L::splat(m.z_axis.z)
                + L::splat(a.translation.z),
        }
    }
    #[inline(always)]
    pub fn transform_vector(self, a: &glam::Affine3A) -> V3<L> {
        let m = &a.matrix3;
        V3 {
            x: self.x * L::splat(m.x_axis.x) + self.y * L::splat(m.y_axis.x) + self.z * L::splat(m.z_axis.x),
            y: self.x * L::splat(m.x_axis.y) + self.y * L::splat(m.y_axis.y) + self.z * L::splat(m.z_axis.y),
            z: self.x * L::splat(m.x_axis.z) + self.y * L::splat(m.y_axis.z) + self.z * L::splat(m.z_axis.z),
        }
    }
}

impl V3<f32> {
    #[inline(always)]
    pub fn from_vec3(v: Vec3) -> V3<f32> {
        V3 { x: v.x, y: v.y, z: v.z }
    }
    #[inline(always)]
    pub fn vec3(self) -> Vec3 {
        Vec3::new(self.x, self.y, self.z)
    }
}

impl V3<F8> {
    /// Sets lane `i` to `v`.
    #[inline(always)]
    pub fn set_lane(&mut self, i: usize, v: Vec3) {
        (self.x.0[i], self.y.0[i], self.z.0[i]) = (v.x, v.y, v.z);
    }
}

impl V3<f64> {
    #[inline(always)]
    pub fn from_dvec3(v: glam::DVec3) -> V3<f64> {
        V3 { x: v.x, y: v.y, z: v.z }
    }
    #[inline(always)]
    pub fn dvec3(self) -> glam::DVec3 {
        glam::DVec3::new(self.x, self.y, self.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn next_up_is_f32_next_up() {
        let specials = [0.0, -0.0, f32::MIN_POSITIVE, -f32::MIN_POSITIVE, f32::MAX, f32::MIN, 1.0, -1.0];
        let more = [f32::INFINITY, f32::NEG_INFINITY, f32::NAN, -f32::NAN, f32::from_bits(1), -f32::from_bits(1)];
        let strided = (0..=u32::MAX).step_by(4099).map(f32::from_bits);
        for x in specials.into_iter().chain(more).chain(strided) {
            assert_eq!(next_up(x).to_bits(), x.next_up().to_bits(), "{x:e} ({:#x})", x.to_bits());
        }
    }

    #[test]
    fn select_and_masks() {
        let a = F8::splat(1.0);
        let b = F8::splat(2.0);
        let m = M8::from_fn(|i| i % 2 == 0);
        let s = F8::select(m, a, b);
        assert_eq!(s.0, [1.0, 2.0, 1.0, 2.0, 1.0, 2.0, 1.0, 2.0]);
        assert!(m.any() && !M8::default().any());
        let x = F8::xor(m, M8::from_fn(|i| i < 4));
        assert_eq!(x.0.map(|v| v != 0), [false, true, false, true, true, false, true, false]);
    }

    #[test]
    fn times_unit_is_the_product_in_every_width() {
        // bits: lane gets g = 1 (k = 0), g = -1 (k = 1), g = 0 (k = 2).
        let bits = [(1 << 0) | (1 << 1) | (1 << 17); 8];
        for v in [2.5f32, -0.0, 0.0, -3.0] {
            for (k, g) in [(0u32, 1.0f32), (1, -1.0), (2, 0.0)] {
                let want = if g == 0.0 { 0.0f32.copysign(v) } else { v * g };
                assert_eq!(v.times_unit(&bits, k).to_bits(), want.to_bits());
                assert_eq!(F8::splat(v).times_unit(&bits, k).0[3].to_bits(), want.to_bits());
                assert_eq!((v as f64).times_unit(&bits, k).to_bits(), (want as f64).to_bits());
            }
        }
    }
}
