//! The compiler against the tree walk, constant folding, inlining and the internal functions
//! against values POV-Ray 3.7 printed.

use super::*;

fn p(i: u16) -> Node {
    Node::Param(i)
}

fn c(v: f64) -> Node {
    Node::Const(v)
}

/// A small deterministic generator (SplitMix64) for random trees and points.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn float(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

const UNARY: [Unary; 24] = [
    Unary::Neg,
    Unary::Not,
    Unary::Abs,
    Unary::Sqrt,
    Unary::Sin,
    Unary::Cos,
    Unary::Tan,
    Unary::Asin,
    Unary::Acos,
    Unary::Atan,
    Unary::Sinh,
    Unary::Cosh,
    Unary::Tanh,
    Unary::Asinh,
    Unary::Acosh,
    Unary::Atanh,
    Unary::Exp,
    Unary::Ln,
    Unary::Log,
    Unary::Floor,
    Unary::Ceil,
    Unary::Int,
    Unary::Radians,
    Unary::Degrees,
];

const BINARY: [Binary; 17] = [
    Binary::Add,
    Binary::Sub,
    Binary::Mul,
    Binary::Div,
    Binary::Pow,
    Binary::Lt,
    Binary::Le,
    Binary::Gt,
    Binary::Ge,
    Binary::Eq,
    Binary::Ne,
    Binary::And,
    Binary::Or,
    Binary::Atan2,
    Binary::Mod,
    Binary::Min,
    Binary::Max,
];

fn random_tree(r: &mut Rng, depth: usize, inner: &Rc<Function>) -> Node {
    if depth == 0 || r.below(4) == 0 {
        return match r.below(3) {
            0 => c((r.float() * 4.0).round() / 4.0),
            _ => p(r.below(3) as u16),
        };
    }
    let sub = |r: &mut Rng| random_tree(r, depth - 1, inner);
    match r.below(6) {
        0 => Node::unary(UNARY[r.below(UNARY.len())], sub(r)),
        1 | 2 => Node::binary(BINARY[r.below(BINARY.len())], sub(r), sub(r)),
        3 => Node::cond(sub(r), sub(r), sub(r)),
        4 => Node::Internal(Internal::Torus, vec![sub(r), sub(r), sub(r), c(1.0), c(0.25)]),
        _ => Node::Call(inner.clone(), vec![sub(r), sub(r)]),
    }
}

fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

#[test]
fn every_operator_compiles_to_what_the_tree_gives() {
    let pts = [[0.5, -1.25, 2.0], [0.0, 0.0, 0.0], [-3.0, 0.75, 1.0], [1.0, 1.0, -0.5]];
    for op in UNARY {
        let f = Node::unary(op, p(0));
        let prog = Program::compile(&f, 3);
        for q in &pts {
            assert!(same(prog.eval(q), op.apply(q[0])), "{op:?} at {q:?}");
        }
    }
    for op in BINARY {
        let f = Node::binary(op, p(0), p(1));
        let prog = Program::compile(&f, 3);
        for q in &pts {
            assert!(same(prog.eval(q), op.apply(q[0], q[1])), "{op:?} at {q:?}");
        }
    }
    // A few the tree walk is not needed for.
    let at = |f: Node, q: [f64; 3]| Program::compile(&f, 3).eval(&q);
    assert_eq!(at(Node::binary(Binary::Pow, p(0), c(3.0)), [2.0, 0.0, 0.0]), 8.0);
    assert_eq!(at(Node::binary(Binary::Mod, c(-7.0), p(0)), [3.0, 0.0, 0.0]), -1.0);
    assert_eq!(at(Node::select(vec![p(0), c(1.0), c(2.0), c(3.0)]), [0.0, 0.0, 0.0]), 2.0);
    assert_eq!(at(Node::select(vec![p(0), c(1.0), c(2.0)]), [-1.0, 0.0, 0.0]), 1.0);
    assert_eq!(at(Node::select(vec![p(0), c(1.0), c(2.0), c(3.0)]), [0.5, 0.0, 0.0]), 3.0);
}

#[test]
fn random_trees_compile_to_what_the_tree_gives() {
    let inner = Rc::new(Function::new(vec!["a".into(), "b".into()], Node::binary(Binary::Sub, p(0), p(1))).unwrap());
    let mut r = Rng(7);
    for case in 0..2000 {
        let f = random_tree(&mut r, 6, &inner);
        let prog = Program::compile(&f, 3);
        for _ in 0..4 {
            let q = [r.float(), r.float(), r.float()];
            let (want, got) = (f.eval(&q), prog.eval(&q));
            assert!(same(want, got), "case {case}: {f:?} at {q:?}: tree {want}, compiled {got}");
            assert!(same(f.folded().eval(&q), want), "case {case}: folding changed {f:?}");
        }
    }
}

#[test]
fn constants_fold_away() {
    // (1 + 2) * x + sqrt(16): one multiply, one add and the constants they read.
    let f = Node::binary(
        Binary::Add,
        Node::binary(Binary::Mul, Node::binary(Binary::Add, c(1.0), c(2.0)), p(0)),
        Node::unary(Unary::Sqrt, c(16.0)),
    );
    assert_eq!(f.folded(), Node::binary(Binary::Add, Node::binary(Binary::Mul, c(3.0), p(0)), c(4.0)));
    let prog = Program::compile(&f, 3);
    assert_eq!(prog.len(), 4);
    assert_eq!(prog.eval(&[2.0, 0.0, 0.0]), 10.0);
    // A constant condition keeps only its side; a call with constant arguments is its value.
    let g = Node::cond(c(0.0), p(0), Node::Internal(Internal::Sphere, vec![c(3.0), c(4.0), c(0.0), c(1.0)]));
    assert_eq!(g.folded(), c(4.0));
    assert_eq!(Program::compile(&g, 3).len(), 1);
}

#[test]
fn calls_are_inlined_with_their_arguments_computed_once() {
    // F(a, b) = a*a + b; G = F(x + y, 2) + F(1, 2).
    let f = Rc::new(
        Function::new(
            vec!["a".into(), "b".into()],
            Node::binary(Binary::Add, Node::binary(Binary::Mul, p(0), p(0)), p(1)),
        )
        .unwrap(),
    );
    let g = Node::binary(
        Binary::Add,
        Node::Call(f.clone(), vec![Node::binary(Binary::Add, p(0), p(1)), c(2.0)]),
        Node::Call(f.clone(), vec![c(1.0), c(2.0)]),
    );
    let prog = Program::compile(&g, 3);
    assert_eq!(prog.eval(&[1.0, 2.0, 0.0]), 9.0 + 2.0 + 3.0);
    // x + y once, the constant 2, a*a, + b, the folded F(1, 2) and the final add.
    assert_eq!(prog.len(), 6, "{prog:?}");
    // Calls nest by depth; too deep is refused.
    let mut h = f.clone();
    for _ in 0..MAX_CALL_DEPTH - 1 {
        h = Rc::new(Function::new(vec!["a".into(), "b".into()], Node::Call(h.clone(), vec![p(0), p(1)])).unwrap());
    }
    assert_eq!(h.depth, MAX_CALL_DEPTH - 1);
    assert!(Function::new(vec!["a".into()], Node::Call(h.clone(), vec![p(0), p(0)])).is_some());
    let deeper = Rc::new(Function::new(vec!["a".into()], Node::Call(h, vec![p(0), p(0)])).unwrap());
    assert!(Function::new(vec!["a".into()], Node::Call(deeper, vec![p(0)])).is_none());
}

#[test]
fn deep_functions_run_on_the_heap() {
    // A right-leaning chain 60 deep needs more registers than the stack buffer holds.
    let mut f = p(0);
    for i in 0..60 {
        f = Node::binary(Binary::Add, p(1), Node::binary(Binary::Mul, c(1.0 + i as f64 * 0.0), f));
    }
    let f = Node::binary(Binary::Add, p(2), f);
    let prog = Program::compile(&f, 3);
    assert_eq!(prog.eval(&[1.0, 2.0, 3.0]), f.eval(&[1.0, 2.0, 3.0]));
}

#[test]
fn internal_functions_give_pov_rays_values() {
    // Printed by POV-Ray 3.7.0.10 with `#debug str(f(...), 0, 8)`.
    let close = |f: Internal, a: &[f64], want: f64| {
        let got = f.eval(a);
        assert!((got - want).abs() < 1e-7, "{f:?}{a:?}: {got}, POV-Ray {want}");
    };
    close(Internal::R, &[1.0, 0.0, 2.0], 2.23606798);
    close(Internal::Th, &[1.0, 0.0, 2.0], 0.46364761);
    close(Internal::Th, &[-1.0, 2.0, 0.5], -1.10714872);
    close(Internal::Ph, &[0.3, -0.7, 0.2], 2.66595494);
    close(Internal::Ph, &[0.0, 0.0, 0.0], 0.0);
    close(Internal::Ellipsoid, &[1.0, 0.0, 2.0, 1.0, 2.0, 3.0], 6.08276253);
    close(Internal::Ellipsoid, &[0.3, -0.7, 0.2, 1.0, 2.0, 3.0], 1.55241747);
    close(Internal::RoundedBox, &[1.0, 0.0, 2.0, 0.3, 1.0, 0.5, 0.8], 1.22970485);
    close(Internal::RoundedBox, &[0.0, 0.0, 0.0, 0.3, 1.0, 0.5, 0.8], -0.30000100);
    close(Internal::RoundedBox, &[1.0, 0.0, 2.0, 0.0, 1.0, 0.5, 0.8], 1.19999900);
    close(Internal::Superellipsoid, &[1.0, 0.0, 2.0, 0.5, 0.3], -1.00294066);
    close(Internal::Superellipsoid, &[0.1, 0.2, -3.0, 0.5, 0.3], -2.00000001);
    close(Internal::Superellipsoid, &[1.0, 0.0, 2.0, 1.0, 1.0], -1.23606798);
    close(Internal::Torus, &[1.0, 0.0, 2.0, 1.0, 0.3], 0.93606798);
    close(Internal::Torus, &[0.3, -0.7, 0.2, 1.0, 0.3], 0.64809796);
    close(Internal::Sphere, &[0.3, -0.7, 0.2, 0.7], 0.08740079);
    close(Internal::Paraboloid, &[0.3, -0.7, 0.2, 2.0], -1.66);
    // f_helix1 over every parameter: round, square, diamond-like and concave sections, turned
    // sections, one to four tubes, negative periods and shapes, and points past the cap.
    let helix = |p: [f64; 3], k: [f64; 7], want: f64| {
        let mut a = p.to_vec();
        a.extend(k);
        close(Internal::Helix1, &a, want);
    };
    let (a, b, c, d) = ([1.2, -3.0, 0.3], [0.7, 0.4, -0.9], [-0.3, 1.7, 0.2], [0.9, -0.2, -0.1]);
    helix(a, [1.0, 1.0, 0.1, 1.0, 1.0, 3.0, 30.0], 0.41462259);
    helix(c, [1.0, 1.0, 0.1, 1.0, 1.0, 3.0, 30.0], 1.26055513);
    helix(b, [2.0, 1.5, 0.2, 0.8, 1.5, 1.0, 20.0], 0.45562093);
    helix(c, [3.0, 2.0, 0.1, 1.0, 0.7, 0.0, -40.0], 0.70368099);
    helix(d, [1.0, 1.0, 0.1, 1.0, 1.0, -1.0, 0.0], -0.00559106);
    helix(d, [4.0, 3.0, 0.2, 0.9, 1.3, 2.5, 75.0], -0.16763180);
    helix(a, [1.0, -2.0, 0.15, 1.2, -0.8, 0.7, 200.0], 1.71491827);
    helix([0.05, 0.3, 0.02], [3.0, 35.0, 0.0105, 0.0165, 2.0, 1.0, 0.0], 0.02794983);
    helix(a, [0.0, 1.0, 0.1, 1.0, 1.0, 1.0, 0.0], 2.13693169);
    for n in 0..100 {
        if let Some(f) = Internal::from_number(n) {
            assert!(Internal::NUMBERS.contains(&format!("{n} (")), "{n}");
            let v = f.eval(&vec![0.25; f.arity()]);
            assert!(v.is_finite(), "{f:?}");
        }
    }
}

/// Eight lanes give each lane's bits alone (`eval_lanes::<1>`), and agree with `eval` but for
/// `sin` and `cos` (trig's, within a few ulp of the library's, which then carry through
/// the rest of the tree): random trees, with and without conditions.
#[test]
fn lanes_give_each_lane_alone_and_the_scalar_value() {
    let inner = Rc::new(Function::new(vec!["a".into(), "b".into()], Node::binary(Binary::Sub, p(0), p(1))).unwrap());
    let mut r = Rng(11);
    for case in 0..2000 {
        let f = random_tree(&mut r, 6, &inner);
        let prog = Program::compile(&f, 3);
        let args: [[f64; 8]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| r.float()));
        let eight = prog.eval_lanes(&args);
        for i in 0..8 {
            let one = prog.eval_lanes(&[[args[0][i]], [args[1][i]], [args[2][i]]])[0];
            assert!(eight[i].to_bits() == one.to_bits() || (eight[i].is_nan() && one.is_nan()), "case {case}");
        }
    }
    // Without trig the lanes are `eval`'s bits; with it, close.
    let trig = Node::binary(
        Binary::Add,
        Node::unary(Unary::Sin, Node::binary(Binary::Mul, c(20.0), p(0))),
        Node::binary(
            Binary::Mul,
            Node::unary(Unary::Cos, p(1)),
            Node::unary(Unary::Sqrt, Node::unary(Unary::Abs, p(2))),
        ),
    );
    let plain = Node::binary(Binary::Div, Node::binary(Binary::Sub, p(0), p(1)), Node::unary(Unary::Abs, p(2)));
    for (f, exact) in [(trig, false), (plain, true)] {
        let prog = Program::compile(&f, 3);
        for _ in 0..1000 {
            let q = [r.float(), r.float(), r.float()];
            let got = prog.eval_lanes(&[[q[0]; 4], [q[1]; 4], [q[2]; 4]])[3];
            let want = prog.eval(&q);
            if exact {
                assert_eq!(got.to_bits(), want.to_bits(), "{q:?}");
            } else {
                assert!((got - want).abs() <= 1e-14, "{q:?}: {got} vs {want}");
            }
        }
    }
}
