#![allow(clippy::needless_range_loop)]

//! `Program::eval_lanes`: one pass of the code for `N` points at once, each instruction
//! applied to every lane before the next is decoded. The interpreter's decoding and the
//! library's one-argument `sin` were most of an isosurface's cost per sample; here the
//! decoding is shared by the lanes and the arithmetic packs into vector instructions.
//!
//! Every lane is computed on its own with the same operations in the same order, so a lane
//! gives the same bits alone (`N = 1`, a single ray) as among eight (a packet). `sin` and
//! `cos` are `trig`'s, not the library's: `eval_lanes` and `eval` may differ in the last bits
//! there. Code with branches (a condition) runs lane by lane through `eval`.

use super::compile::{Instr, Program};
use super::ops::{Binary, Unary};
use super::trig::{cos_lanes, sin_lanes};

impl Program {
    /// The values at `N` points: `args[k][i]` is parameter `k` of lane `i` (missing
    /// parameters read as 0, extra ones are ignored).
    #[inline]
    pub fn eval_lanes<const N: usize>(&self, args: &[[f64; N]]) -> [f64; N] {
        if self.branches {
            return std::array::from_fn(|i| {
                let mut one = [0.0; super::MAX_PARAMS];
                let n = args.len().min(super::MAX_PARAMS);
                for k in 0..n {
                    one[k] = args[k][i];
                }
                self.eval(&one[..n])
            });
        }
        #[cfg(target_arch = "x86_64")]
        if N >= 4 && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.eval_lanes_avx2(args) };
        }
        self.eval_lanes_in(args)
    }

    /// `eval_lanes` with 256-bit vectors: the same operations (no FMA), so the same bits.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn eval_lanes_avx2<const N: usize>(&self, args: &[[f64; N]]) -> [f64; N] {
        self.eval_lanes_in(args)
    }

    /// Loops, not closures, below: a closure is compiled out of line, without AVX2.
    #[inline(always)]
    fn eval_lanes_in<const N: usize>(&self, args: &[[f64; N]]) -> [f64; N] {
        if self.registers <= 8 {
            self.run_lanes(args, &mut [[0.0; N]; 8])
        } else if self.registers <= 16 {
            self.run_lanes(args, &mut [[0.0; N]; 16])
        } else {
            self.run_lanes(args, &mut vec![[0.0; N]; self.registers])
        }
    }

    #[inline(always)]
    fn run_lanes<const N: usize>(&self, args: &[[f64; N]], r: &mut [[f64; N]]) -> [f64; N] {
        let n = self.params.min(args.len());
        r[..n].copy_from_slice(&args[..n]);
        for instr in &self.code {
            match instr {
                &Instr::Const { d, v } => r[d as usize] = [v; N],
                &Instr::Copy { d, a } => r[d as usize] = r[a as usize],
                &Instr::Unary { op, d, a } => {
                    let a = r[a as usize];
                    let mut v = [0.0; N];
                    match op {
                        Unary::Neg => {
                            for i in 0..N {
                                v[i] = -a[i];
                            }
                        }
                        Unary::Abs => {
                            for i in 0..N {
                                v[i] = a[i].abs();
                            }
                        }
                        Unary::Sqrt => {
                            for i in 0..N {
                                v[i] = a[i].sqrt();
                            }
                        }
                        Unary::Sin => v = sin_lanes(&a),
                        Unary::Cos => v = cos_lanes(&a),
                        _ => {
                            for i in 0..N {
                                v[i] = op.apply(a[i]);
                            }
                        }
                    }
                    r[d as usize] = v;
                }
                &Instr::Binary { op, d, a, b } => {
                    let (a, b) = (r[a as usize], r[b as usize]);
                    let mut v = [0.0; N];
                    match op {
                        Binary::Add => {
                            for i in 0..N {
                                v[i] = a[i] + b[i];
                            }
                        }
                        Binary::Sub => {
                            for i in 0..N {
                                v[i] = a[i] - b[i];
                            }
                        }
                        Binary::Mul => {
                            for i in 0..N {
                                v[i] = a[i] * b[i];
                            }
                        }
                        Binary::Div => {
                            for i in 0..N {
                                v[i] = a[i] / b[i];
                            }
                        }
                        _ => {
                            for i in 0..N {
                                v[i] = op.apply(a[i], b[i]);
                            }
                        }
                    }
                    r[d as usize] = v;
                }
                Instr::Internal { f, d, a, n } => {
                    let (a, n) = (*a as usize, *n as usize);
                    let v: [f64; N] = std::array::from_fn(|i| {
                        let mut one = [0.0; 16];
                        for k in 0..n.min(16) {
                            one[k] = r[a + k][i];
                        }
                        f.eval(&one[..n.min(16)])
                    });
                    r[*d as usize] = v;
                }
                Instr::Shade { s, ch, d, a } => {
                    let a = *a as usize;
                    let v: [f64; N] = std::array::from_fn(|i| s.value(*ch, &[r[a][i], r[a + 1][i], r[a + 2][i]]));
                    r[*d as usize] = v;
                }
                Instr::Spline { s, d, a } => {
                    let v = r[*a as usize].map(|t| s.value(t));
                    r[*d as usize] = v;
                }
                // Not reached: code with branches runs through `eval`.
                Instr::Jump { .. } | Instr::JumpIfZero { .. } => unreachable!("branches run lane by lane"),
            }
        }
        r[self.result as usize]
    }
}
