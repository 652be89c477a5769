//! User-defined functions (POV-Ray 3.7's `function { ... }`, reference 3.3.1.8): the expression
//! tree the parser builds (`Node`), the compiler that turns it into register code once
//! (`Program`: constants folded, calls to other functions inlined), and the internal functions
//! `functions.inc` names (`internal`), and the splines a body may read (`spline`).
//!
//! The parser (`pov`) produces `Node`s and knows nothing of `Program`; shapes (`geometry`) only
//! run `Program`s. This module depends on neither, nor on `shading`.
//!
//! Layer 1 of docs/design/architecture.md: uses only `noise`; a pigment function reaches `shading` through the `Shade` trait.

mod compile;
pub mod internal;
mod lanes;
mod ops;
pub mod shade;
pub mod spline;
mod trig;

use std::rc::Rc;
use std::sync::Arc;

pub use compile::Program;
pub use internal::Internal;
pub use ops::{Binary, Unary};
pub use shade::{Channel, Shade};
pub use spline::SplineRead;

/// Most parameters a function may take, as in POV-Ray 3.7.
pub const MAX_PARAMS: usize = 56;

/// Deepest nesting of inlined function calls (POV-Ray's limit is 1024; inlining copies
/// nothing, but compiling recurses).
pub const MAX_CALL_DEPTH: usize = 64;

/// A float expression over a function's parameters, as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    Const(f64),
    /// The function's parameter number `i` (`x`, `y`, `z` are 0, 1, 2 by default).
    Param(u16),
    Unary(Unary, Box<Node>),
    Binary(Binary, Box<Node>, Box<Node>),
    /// `c ? a : b`, and `select`: `a` where `c` is not zero, else `b`; only one side runs.
    Cond(Box<Node>, Box<Node>, Box<Node>),
    /// An internal function (`f_sphere`) with its arguments (the count checked when parsed).
    Internal(Internal, Vec<Node>),
    /// A call of another user function, inlined when compiled: the arguments are computed
    /// once and stand for the callee's parameters.
    Call(Rc<Function>, Vec<Node>),
    /// One channel of a pattern or pigment function at the point of its three arguments.
    Shade(Arc<dyn Shade>, Channel, Vec<Node>),
    /// One component of a declared spline at the parameter computed by the node
    /// (`Spl(x).y`).
    Spline(Arc<SplineRead>, Box<Node>),
}

/// A declared function: its parameter names (for messages) and body.
#[derive(Clone, Debug, PartialEq)]
pub struct Function {
    pub params: Vec<String>,
    pub body: Node,
    /// How deeply calls nest inside `body` (0 without calls).
    pub depth: usize,
    /// A pigment function's pigment: a call gives its colour, and a body must pick a
    /// channel of it (`body` reads its gray).
    pub color: Option<Arc<dyn Shade>>,
}

impl Function {
    /// `function { body }` over `params`; `None` when its calls nest deeper than
    /// `MAX_CALL_DEPTH`.
    pub fn new(params: Vec<String>, body: Node) -> Option<Function> {
        let depth = body.call_depth();
        (depth <= MAX_CALL_DEPTH).then(|| Function { params, body: body.folded(), depth, color: None })
    }

    /// The function's value, walking the tree (for parse-time calls and as the compiler's
    /// slow twin in tests). Missing arguments read as 0.
    pub fn eval(&self, args: &[f64]) -> f64 {
        self.body.eval(args)
    }

    /// `function { pattern { ... } }` (`color` false) or `function { pigment { ... } }` of
    /// x, y, z.
    pub fn shade(shade: Arc<dyn Shade>, color: bool) -> Function {
        let channel = if color { Channel::Gray } else { Channel::Pattern };
        let body = Node::Shade(shade.clone(), channel, (0..3).map(Node::Param).collect());
        let params = ["x", "y", "z"].iter().map(|s| s.to_string()).collect();
        Function { params, body, depth: 0, color: color.then_some(shade) }
    }

    pub fn compile(&self) -> Program {
        Program::compile(&self.body, self.params.len())
    }
}

impl Node {
    pub fn unary(op: Unary, a: Node) -> Node {
        Node::Unary(op, Box::new(a))
    }

    pub fn binary(op: Binary, a: Node, b: Node) -> Node {
        Node::Binary(op, Box::new(a), Box::new(b))
    }

    pub fn cond(c: Node, a: Node, b: Node) -> Node {
        Node::Cond(Box::new(c), Box::new(a), Box::new(b))
    }

    /// POV-Ray's `select(A, B, C)` (B where A < 0, else C) and `select(A, B, C, D)` (B where
    /// A < 0, C where A = 0, D where A > 0), as conditions.
    pub fn select(mut args: Vec<Node>) -> Node {
        let a = args.remove(0);
        let less = Node::binary(Binary::Lt, a.clone(), Node::Const(0.0));
        if args.len() == 2 {
            let c = args.pop().unwrap_or(Node::Const(0.0));
            let b = args.pop().unwrap_or(Node::Const(0.0));
            return Node::cond(less, b, c);
        }
        let d = args.pop().unwrap_or(Node::Const(0.0));
        let c = args.pop().unwrap_or(Node::Const(0.0));
        let b = args.pop().unwrap_or(Node::Const(0.0));
        Node::cond(less, b, Node::cond(Node::binary(Binary::Eq, a, Node::Const(0.0)), c, d))
    }

    /// The tree's value for parameters `p`, walking it.
    pub fn eval(&self, p: &[f64]) -> f64 {
        match self {
            Node::Const(v) => *v,
            Node::Param(i) => p.get(*i as usize).copied().unwrap_or(0.0),
            Node::Unary(op, a) => op.apply(a.eval(p)),
            Node::Binary(op, a, b) => op.apply(a.eval(p), b.eval(p)),
            Node::Cond(c, a, b) => {
                if c.eval(p) != 0.0 {
                    a.eval(p)
                } else {
                    b.eval(p)
                }
            }
            Node::Internal(f, args) => {
                let v: Vec<f64> = args.iter().map(|a| a.eval(p)).collect();
                f.eval(&v)
            }
            Node::Call(f, args) => {
                let v: Vec<f64> = args.iter().map(|a| a.eval(p)).collect();
                f.eval(&v)
            }
            Node::Shade(s, ch, args) => {
                let v: Vec<f64> = args.iter().map(|a| a.eval(p)).collect();
                s.value(*ch, &v)
            }
            Node::Spline(s, t) => s.value(t.eval(p)),
        }
    }

    fn call_depth(&self) -> usize {
        match self {
            Node::Const(_) | Node::Param(_) => 0,
            Node::Unary(_, a) | Node::Spline(_, a) => a.call_depth(),
            Node::Binary(_, a, b) => a.call_depth().max(b.call_depth()),
            Node::Cond(c, a, b) => c.call_depth().max(a.call_depth()).max(b.call_depth()),
            Node::Internal(_, args) | Node::Shade(_, _, args) => args.iter().map(Node::call_depth).max().unwrap_or(0),
            Node::Call(f, args) => (f.depth + 1).max(args.iter().map(Node::call_depth).max().unwrap_or(0)),
        }
    }

    /// The tree with every constant part computed: an operator or call whose operands are all
    /// constants becomes its value, a condition with a constant test becomes the side it picks.
    pub fn folded(&self) -> Node {
        match self {
            Node::Const(_) | Node::Param(_) => self.clone(),
            Node::Unary(op, a) => match a.folded() {
                Node::Const(v) => Node::Const(op.apply(v)),
                a => Node::unary(*op, a),
            },
            Node::Binary(op, a, b) => match (a.folded(), b.folded()) {
                (Node::Const(a), Node::Const(b)) => Node::Const(op.apply(a, b)),
                (a, b) => Node::binary(*op, a, b),
            },
            Node::Cond(c, a, b) => match c.folded() {
                Node::Const(v) if v != 0.0 => a.folded(),
                Node::Const(_) => b.folded(),
                c => Node::cond(c, a.folded(), b.folded()),
            },
            Node::Internal(f, args) => {
                let args: Vec<Node> = args.iter().map(Node::folded).collect();
                match constants(&args) {
                    Some(v) => Node::Const(f.eval(&v)),
                    None => Node::Internal(*f, args),
                }
            }
            Node::Call(f, args) => {
                let args: Vec<Node> = args.iter().map(Node::folded).collect();
                match constants(&args) {
                    Some(v) => Node::Const(f.eval(&v)),
                    // A body that does not read its parameters is a constant too.
                    None => match &f.body {
                        Node::Const(v) => Node::Const(*v),
                        _ => Node::Call(f.clone(), args),
                    },
                }
            }
            Node::Shade(s, ch, args) => {
                let args: Vec<Node> = args.iter().map(Node::folded).collect();
                match constants(&args) {
                    Some(v) => Node::Const(s.value(*ch, &v)),
                    None => Node::Shade(s.clone(), *ch, args),
                }
            }
            Node::Spline(s, t) => match t.folded() {
                Node::Const(v) => Node::Const(s.value(v)),
                t => Node::Spline(s.clone(), Box::new(t)),
            },
        }
    }
}

/// The values of `args` when all are constants.
fn constants(args: &[Node]) -> Option<Vec<f64>> {
    args.iter().map(|a| if let Node::Const(v) = a { Some(*v) } else { None }).collect()
}

#[cfg(test)]
mod tests;
