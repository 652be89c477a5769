//! `Node` → register code, once per function: the interpreter loop runs one flat instruction
//! per operator with no allocation and no name lookup, the cost an isosurface pays for every
//! sample along every ray.
//!
//! Registers `0..params` hold the arguments; temporaries are allocated as a stack (an
//! operator's operands are freed before its result is taken), so a function needs as many
//! registers as its tree is deep, not as it is large. A parameter is read from its register
//! in place, never copied. A call of another function is inlined: its arguments are computed
//! into registers once and its body is compiled with its parameters mapped onto them.

use std::sync::Arc;

use super::internal::Internal;
use super::ops::{Binary, Unary};
use super::shade::{Channel, Shade};
use super::spline::SplineRead;
use super::Node;

/// Registers kept on the stack while running; a deeper function uses a heap buffer.
const STACK_REGISTERS: usize = 48;

pub(super) type Reg = u16;

#[derive(Clone, Debug, PartialEq)]
pub(super) enum Instr {
    Const {
        d: Reg,
        v: f64,
    },
    Copy {
        d: Reg,
        a: Reg,
    },
    Unary {
        op: Unary,
        d: Reg,
        a: Reg,
    },
    Binary {
        op: Binary,
        d: Reg,
        a: Reg,
        b: Reg,
    },
    /// Jump to instruction `to` when register `c` is 0.
    JumpIfZero {
        c: Reg,
        to: u32,
    },
    Jump {
        to: u32,
    },
    /// `d = f(registers a .. a + n)`.
    Internal {
        f: Internal,
        d: Reg,
        a: Reg,
        n: u16,
    },
    /// `d = s(registers a, a + 1, a + 2)`'s channel `ch`.
    Shade {
        s: Arc<dyn Shade>,
        ch: Channel,
        d: Reg,
        a: Reg,
    },
    /// `d = s(register a)`.
    Spline {
        s: Arc<SplineRead>,
        d: Reg,
        a: Reg,
    },
}

/// A compiled function.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub(super) code: Vec<Instr>,
    /// Registers needed, parameters included.
    pub(super) registers: usize,
    pub(super) params: usize,
    /// Where the result is left.
    pub(super) result: Reg,
    /// Whether the code branches (a condition): then lanes cannot share one pass.
    pub(super) branches: bool,
}

struct Compiler {
    code: Vec<Instr>,
    next: usize,
    most: usize,
}

impl Compiler {
    fn alloc(&mut self) -> Reg {
        let r = self.next as Reg;
        self.next += 1;
        self.most = self.most.max(self.next);
        r
    }

    /// Compiles `node` with parameter `i` in register `env[i]`: the register holding its value
    /// (a parameter's own register, or a new one).
    fn node(&mut self, node: &Node, env: &[Reg]) -> Reg {
        if let Node::Param(i) = node {
            if let Some(&r) = env.get(*i as usize) {
                return r;
            }
        }
        let d = self.alloc();
        self.into(node, env, d);
        d
    }

    /// Compiles `node` to leave its value in register `d`, which nothing below it reads;
    /// temporaries are allocated above the registers in use and freed again.
    fn into(&mut self, node: &Node, env: &[Reg], d: Reg) {
        let mark = self.next;
        match node {
            Node::Param(i) => match env.get(*i as usize) {
                Some(&a) => self.code.push(Instr::Copy { d, a }),
                // A parameter the caller did not pass reads as 0.
                None => self.code.push(Instr::Const { d, v: 0.0 }),
            },
            Node::Const(v) => self.code.push(Instr::Const { d, v: *v }),
            Node::Unary(op, a) => {
                let a = self.node(a, env);
                self.code.push(Instr::Unary { op: *op, d, a });
            }
            Node::Binary(op, a, b) => {
                let a = self.node(a, env);
                let b = self.node(b, env);
                self.code.push(Instr::Binary { op: *op, d, a, b });
            }
            Node::Cond(c, a, b) => {
                let c = self.node(c, env);
                let jump = self.code.len();
                self.code.push(Instr::JumpIfZero { c, to: 0 });
                self.next = mark;
                self.into(a, env, d);
                let skip = self.code.len();
                self.code.push(Instr::Jump { to: 0 });
                self.code[jump] = Instr::JumpIfZero { c, to: self.code.len() as u32 };
                self.into(b, env, d);
                self.code[skip] = Instr::Jump { to: self.code.len() as u32 };
            }
            Node::Internal(f, args) => {
                let a = self.arguments(args, env);
                self.code.push(Instr::Internal { f: *f, d, a, n: args.len() as u16 });
            }
            Node::Shade(s, ch, args) => {
                let a = self.arguments(args, env);
                self.code.push(Instr::Shade { s: s.clone(), ch: *ch, d, a });
            }
            Node::Spline(s, t) => {
                let a = self.node(t, env);
                self.code.push(Instr::Spline { s: s.clone(), d, a });
            }
            Node::Call(f, args) => {
                // The arguments stay in their registers while the inlined body runs; one
                // that is a parameter as it is (`F(x, y, z)`) is read where it stands.
                let inner: Vec<Reg> = args.iter().map(|a| self.node(a, env)).collect();
                self.into(&f.body, &inner, d);
            }
        }
        self.next = mark;
    }

    /// Computes `args` into consecutive new registers (an internal function reads them as
    /// one slice): the first of them.
    fn arguments(&mut self, args: &[Node], env: &[Reg]) -> Reg {
        let first = self.next as Reg;
        for _ in args {
            self.alloc();
        }
        for (i, arg) in args.iter().enumerate() {
            self.into(arg, env, first + i as Reg);
        }
        first
    }
}

impl Program {
    /// Compiles `body`, a function of `params` parameters, with its constants folded.
    pub fn compile(body: &Node, params: usize) -> Program {
        let body = body.folded();
        let mut c = Compiler { code: Vec::new(), next: params, most: params };
        let env: Vec<Reg> = (0..params as Reg).collect();
        let result = c.node(&body, &env);
        let branches = c.code.iter().any(|i| matches!(i, Instr::Jump { .. } | Instr::JumpIfZero { .. }));
        Program { code: c.code, registers: c.most.max(1), params, result, branches }
    }

    /// Instructions in the compiled code (for tests and statistics).
    pub fn len(&self) -> usize {
        self.code.len()
    }

    pub fn is_empty(&self) -> bool {
        self.code.is_empty()
    }

    /// The value for `args` (missing ones read as 0, extra ones are ignored).
    #[inline]
    pub fn eval(&self, args: &[f64]) -> f64 {
        // The register file is zeroed on every call: sized to the program, so a short function
        // (a parametric's `cos(u) * cos(v)`) does not pay for clearing 48 registers (a memset
        // that was 15 % of the parametric kernel's frame).
        if self.registers <= 8 {
            let mut r = [0.0; 8];
            self.run(args, &mut r)
        } else if self.registers <= 16 {
            let mut r = [0.0; 16];
            self.run(args, &mut r)
        } else if self.registers <= STACK_REGISTERS {
            let mut r = [0.0; STACK_REGISTERS];
            self.run(args, &mut r)
        } else {
            let mut r = vec![0.0; self.registers];
            self.run(args, &mut r)
        }
    }

    fn run(&self, args: &[f64], r: &mut [f64]) -> f64 {
        let n = self.params.min(args.len());
        r[..n].copy_from_slice(&args[..n]);
        let mut pc = 0;
        while let Some(instr) = self.code.get(pc) {
            pc += 1;
            match instr {
                &Instr::Const { d, v } => r[d as usize] = v,
                &Instr::Copy { d, a } => r[d as usize] = r[a as usize],
                &Instr::Unary { op, d, a } => r[d as usize] = op.apply(r[a as usize]),
                &Instr::Binary { op, d, a, b } => r[d as usize] = op.apply(r[a as usize], r[b as usize]),
                &Instr::JumpIfZero { c, to } => {
                    if r[c as usize] == 0.0 {
                        pc = to as usize;
                    }
                }
                &Instr::Jump { to } => pc = to as usize,
                &Instr::Internal { f, d, a, n } => {
                    let a = a as usize;
                    r[d as usize] = f.eval(&r[a..a + n as usize]);
                }
                Instr::Shade { s, ch, d, a } => {
                    let a = *a as usize;
                    r[*d as usize] = s.value(*ch, &r[a..a + 3]);
                }
                Instr::Spline { s, d, a } => r[*d as usize] = s.value(r[*a as usize]),
            }
        }
        r[self.result as usize]
    }
}
