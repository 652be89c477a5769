//! `function [(params)] { body }`: the body read straight into a `function::Node` tree, names
//! resolved as they are read (parameters, declared floats and functions, internal functions,
//! POV-Ray's float functions), with a located error for an unknown name or a wrong number of
//! arguments. `pattern { }` and `pigment { }` bodies are lowered at once into the function's
//! `Shade`; a declared spline is read per point (`S(t).y`). `function { transform { } }` and
//! `function { spline { } }` are values of their own (`parser::spline`).

use std::rc::Rc;
use std::sync::Arc;

use super::Parser;
use crate::function::spline::Spline;
use crate::function::{Binary, Channel, Function, Internal, Node, SplineRead, Unary, MAX_PARAMS};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
use crate::shading::pigment_fn::PigmentFn;

/// Float functions a body may call beyond those of one or two arguments.
const SPECIAL: &[&str] = &["min", "max", "select", "internal"];

impl Parser<'_, '_> {
    /// `function [(a, b, ...)] { ... }` at the cursor.
    pub(super) fn function(&mut self) -> PResult<Function> {
        let kw = self.bump().span;
        self.function_after(kw)
    }

    /// The rest of `function [(a, b, ...)] { ... }` after its keyword at `kw`.
    pub(super) fn function_after(&mut self, kw: Span) -> PResult<Function> {
        let mut params: Vec<String> = Vec::new();
        let named = self.eat_punct('(');
        if named {
            loop {
                let t = self.bump();
                let TokenKind::Ident(name) = &t.kind else {
                    return Err(Diag::new(t.span, format!("expected a parameter name, found {}", t.describe())));
                };
                if params.iter().any(|p| p == &**name || p == alias(name)) {
                    return Err(Diag::new(t.span, format!("parameter `{name}` is named twice")));
                }
                params.push(name.to_string());
                if params.len() > MAX_PARAMS {
                    return Err(Diag::new(t.span, format!("a function takes at most {MAX_PARAMS} parameters")));
                }
                if !self.eat_punct(',') {
                    break;
                }
            }
            self.expect_punct(')', "to close the parameter list")?;
        } else {
            params = vec!["x".into(), "y".into(), "z".into()];
        }
        self.open_block("function", kw)?;
        if let Some(word) = self.peek_ident() {
            if matches!(&*word, "pattern" | "pigment") {
                return self.shade_function(&word, kw);
            }
            if matches!(&*word, "transform" | "spline") {
                return Err(Diag::unmodelled(
                    self.peek().span,
                    format!("`function {{ {word} {{ ... }} }}` is not supported yet (float, pattern and pigment functions are)"),
                ));
            }
            if &*word == "internal" && !named {
                return self.internal(kw);
            }
        }
        let body = self.fn_expr(&params)?;
        self.close_block("function", kw)?;
        Function::new(params, body).ok_or_else(|| {
            Diag::new(kw, format!("function calls nest deeper than {}", crate::function::MAX_CALL_DEPTH))
        })
    }

    /// `internal(N) }` of `functions.inc`: the function of x, y, z and its extra parameters.
    fn internal(&mut self, kw: Span) -> PResult<Function> {
        let at = self.bump().span;
        self.expect_punct('(', "after `internal`")?;
        let e = self.full_expr()?;
        let n = self.low.float(&e)?;
        self.expect_punct(')', "to close `internal(`")?;
        self.close_block("function", kw)?;
        let Some(f) = Internal::from_number(n as u32).filter(|_| n >= 0.0 && n.fract() == 0.0) else {
            return Err(Diag::unmodelled(
                at.to(e.span),
                format!("internal function {n} is not supported yet (supported: {})", Internal::NUMBERS),
            ));
        };
        let params: Vec<String> =
            ["x", "y", "z"].iter().map(|s| s.to_string()).chain((0..f.arity() - 3).map(|i| format!("P{i}"))).collect();
        let body = Node::Internal(f, (0..f.arity() as u16).map(Node::Param).collect());
        Ok(Function { params, body, depth: 0, color: None })
    }

    /// `pattern { ... } }` or `pigment { ... } }` of a function at `kw`: the pigment lowered
    /// now, once, into the function's one `Shade`. A pattern block is read as a pigment's items
    /// (the pattern and its modifiers); its value is the pattern's, not a colour.
    fn shade_function(&mut self, word: &str, kw: Span) -> PResult<Function> {
        let ast = if word == "pigment" {
            self.pigment()?
        } else {
            let at = self.bump().span;
            self.open_block("pattern", at)?;
            let items = self.pigment_items(false)?;
            let end = self.close_block("pattern", at)?;
            crate::pov::ast::Pigment { items, span: at.to(end) }
        };
        let desc = self.low.pigment(&ast)?;
        self.close_block("function", kw)?;
        Ok(Function::shade(Arc::new(PigmentFn::new(&desc)), word == "pigment"))
    }

    /// A body expression: `?:` lowest, then `|`, `&`, comparisons, `+ -`, `* /`, `^`, signs.
    fn fn_expr(&mut self, params: &[String]) -> PResult<Node> {
        let cond = self.fn_binary(params, 0)?;
        if !self.is_punct('?') {
            return Ok(cond);
        }
        let q = self.bump().span;
        self.enter(q)?;
        let a = self.fn_expr(params)?;
        self.expect_punct(':', "in `? :`")?;
        let b = self.fn_expr(params)?;
        self.leave();
        Ok(Node::cond(Node::binary(Binary::Ne, cond, Node::Const(0.0)), a, b))
    }

    /// The left-to-right operators of precedence `level` and above.
    fn fn_binary(&mut self, params: &[String], level: usize) -> PResult<Node> {
        const LEVELS: usize = 5;
        if level == LEVELS {
            return self.fn_power(params);
        }
        let mut lhs = self.fn_binary(params, level + 1)?;
        let mut chained = 0;
        loop {
            let kind = self.peek().kind;
            let op = match (level, &kind) {
                (0, TokenKind::Punct('|')) => Binary::Or,
                (1, TokenKind::Punct('&')) => Binary::And,
                (2, TokenKind::Punct('<')) => Binary::Lt,
                (2, TokenKind::Punct('>')) => Binary::Gt,
                (2, TokenKind::Punct('=')) => Binary::Eq,
                (2, TokenKind::Op2("<=")) => Binary::Le,
                (2, TokenKind::Op2(">=")) => Binary::Ge,
                (2, TokenKind::Op2("!=")) => Binary::Ne,
                (3, TokenKind::Punct('+')) => Binary::Add,
                (3, TokenKind::Punct('-')) => Binary::Sub,
                (4, TokenKind::Punct('*')) => Binary::Mul,
                (4, TokenKind::Punct('/')) => Binary::Div,
                _ => break,
            };
            let span = self.bump().span;
            if let Err(e) = self.enter(span) {
                self.depth -= chained;
                return Err(e);
            }
            chained += 1;
            let rhs = self.fn_binary(params, level + 1)?;
            lhs = Node::binary(op, lhs, rhs);
        }
        self.depth -= chained;
        Ok(lhs)
    }

    /// `a ^ b` (right to left, tighter than `*`; a sign applies to the whole power: `-x^2`
    /// is `-(x^2)`). POV-Ray 3.7 itself has no `^` in functions; it is `pow`.
    fn fn_power(&mut self, params: &[String]) -> PResult<Node> {
        let t = self.peek();
        if let TokenKind::Punct(c @ ('-' | '+' | '!')) = t.kind {
            self.bump();
            self.enter(t.span)?;
            let inner = self.fn_power(params);
            self.leave();
            let inner = inner?;
            return Ok(match c {
                '-' => Node::unary(Unary::Neg, inner),
                '!' => Node::unary(Unary::Not, inner),
                _ => inner,
            });
        }
        let base = self.fn_primary(params)?;
        if !self.is_punct('^') {
            return Ok(base);
        }
        let at = self.bump().span;
        self.enter(at)?;
        let exponent = self.fn_power(params);
        self.leave();
        Ok(Node::binary(Binary::Pow, base, exponent?))
    }

    fn fn_primary(&mut self, params: &[String]) -> PResult<Node> {
        let t = self.peek();
        match &t.kind {
            TokenKind::Number(v) => {
                self.bump();
                Ok(Node::Const(*v))
            }
            TokenKind::Punct('(') => {
                self.bump();
                self.enter(t.span)?;
                let inner = self.fn_expr(params)?;
                self.expect_punct(')', "to close `(`")?;
                self.leave();
                Ok(inner)
            }
            TokenKind::Ident(word) => self.fn_word(word, t.span, params),
            TokenKind::Eof if self.pending.is_some() => Err(Diag::new(t.span, "")),
            _ => Err(Diag::new(t.span, format!("expected an expression in the function, found {}", t.describe()))),
        }
    }

    fn fn_word(&mut self, word: &str, span: Span, params: &[String]) -> PResult<Node> {
        if let Some(i) = params.iter().position(|p| p == word || p == alias(word)) {
            self.bump();
            return Ok(Node::Param(i as u16));
        }
        let constant = match word {
            "pi" => Some(std::f64::consts::PI),
            "true" | "yes" | "on" => Some(1.0),
            "false" | "no" | "off" => Some(0.0),
            _ => None,
        };
        if let Some(v) = constant {
            self.bump();
            return Ok(Node::Const(v));
        }
        if let Some(b) = super::expr::builtin(word) {
            self.bump();
            let e = crate::pov::ast::Expr { kind: crate::pov::ast::ExprKind::Builtin(b), span };
            return Ok(Node::Const(self.low.float(&e)?));
        }
        let unary = Unary::named(word);
        let binary = Binary::named(word).filter(|_| !matches!(word, "min" | "max"));
        if unary.is_some() || binary.is_some() || SPECIAL.contains(&word) {
            self.bump();
            let args = self.fn_arguments(word, params)?;
            let count = |want: &str, ok: bool| -> PResult<()> {
                if ok {
                    Ok(())
                } else {
                    Err(Diag::new(span, format!("`{word}` takes {want} argument(s), found {}", args.len())))
                }
            };
            if let Some(op) = unary {
                count("1", args.len() == 1)?;
                return Ok(Node::unary(op, args.into_iter().next().unwrap_or(Node::Const(0.0))));
            }
            if let Some(op) = binary {
                count("2", args.len() == 2)?;
                let mut it = args.into_iter();
                let (a, b) = (it.next().unwrap_or(Node::Const(0.0)), it.next().unwrap_or(Node::Const(0.0)));
                return Ok(Node::binary(op, a, b));
            }
            return match word {
                "min" | "max" => {
                    count("2 or more", args.len() >= 2)?;
                    let op = if word == "min" { Binary::Min } else { Binary::Max };
                    let mut it = args.into_iter();
                    let first = it.next().unwrap_or(Node::Const(0.0));
                    Ok(it.fold(first, |acc, a| Node::binary(op, acc, a)))
                }
                "select" => {
                    count("3 or 4", (3..=4).contains(&args.len()))?;
                    Ok(Node::select(args))
                }
                _ => Err(Diag::new(span, "`internal(N)` may only stand alone in `function { internal(N) }`")),
            };
        }
        if matches!(word, "sum" | "prod") {
            return Err(Diag::unmodelled(span, format!("`{word}` in functions is not supported yet")));
        }
        let Some(value) = self.low.lookup(word).cloned() else {
            let list = params.join(", ");
            return Err(if self.peek_after_is('(') {
                Diag::new(span, format!("unknown function `{word}`"))
            } else {
                Diag::new(span, format!("unknown identifier `{word}` in a function (its parameters: {list})"))
            });
        };
        self.bump();
        match value {
            Value::Float(v) => Ok(Node::Const(v)),
            Value::Function(f) => {
                let args = self.fn_arguments(word, params)?;
                if args.len() != f.params.len() {
                    return Err(Diag::new(
                        span,
                        format!(
                            "`{word}` takes {} argument(s) ({}), found {}",
                            f.params.len(),
                            f.params.join(", "),
                            args.len()
                        ),
                    ));
                }
                if f.depth + 1 > crate::function::MAX_CALL_DEPTH {
                    return Err(Diag::new(span, "function calls nest too deeply"));
                }
                let Some(shade) = &f.color else {
                    return Ok(Node::Call(f, args));
                };
                // A pigment function's call is a colour: the body reads one channel of it.
                if !self.is_punct('.') {
                    return Err(Diag::new(
                        span,
                        format!(
                            "`{word}` is a pigment function, its value a colour: pick a channel ({})",
                            Channel::NAMES
                        ),
                    ));
                }
                self.bump();
                let t = self.bump();
                let channel = match &t.kind {
                    TokenKind::Ident(w) => Channel::named(w),
                    _ => None,
                };
                match channel {
                    Some(ch) => Ok(Node::Shade(shade.clone(), ch, args)),
                    None => Err(Diag::new(
                        t.span,
                        format!(
                            "expected a colour channel ({}) after `{word}(...).`, found {}",
                            Channel::NAMES,
                            t.describe()
                        ),
                    )),
                }
            }
            Value::Vector(c) if self.is_punct('.') => {
                self.bump();
                let t = self.bump();
                let index = match &t.kind {
                    TokenKind::Ident(w) => component_index(w),
                    _ => None,
                };
                match index.and_then(|i| c.get(i)) {
                    Some(v) => Ok(Node::Const(*v)),
                    None => Err(Diag::new(t.span, format!("`{word}` has no component {}", t.describe()))),
                }
            }
            Value::Spline(s) => self.fn_spline(&s, word, span, params),
            Value::Unmodelled(u) => Err(u.used_at(span)),
            other => Err(Diag::new(span, format!("`{word}` is {}, which a function cannot use", other.kind_name()))),
        }
    }

    /// `S(t [, kind]).c` in a body after the name `word` (at `span`) of a declared spline:
    /// component `c` of its point at `t`, read per point (POV-Ray lets a function body
    /// call a spline; language/splinefunction.pov draws a gradient with `Spl_Pat(x).y`).
    fn fn_spline(&mut self, s: &Spline, word: &str, span: Span, params: &[String]) -> PResult<Node> {
        let open = self.expect_punct('(', &format!("after `{word}`"))?;
        self.enter(open)?;
        let t = self.fn_expr(params)?;
        let kind = if self.eat_punct(',') { self.spline_kind_arg()? } else { s.kind };
        let close = self.expect_punct(')', &format!("to close `{word}(`"))?;
        self.leave();
        if s.is_empty() {
            return Err(Diag::new(span.to(close), format!("spline `{word}` has no points")));
        }
        if !self.eat_punct('.') {
            return Err(Diag::new(
                span.to(close),
                format!("`{word}(...)` is a point, a function's value a float: pick a component (`.x`, `.y`, ...)"),
            ));
        }
        let c = self.bump();
        let index = match &c.kind {
            TokenKind::Ident(w) => component_index(w),
            _ => None,
        };
        let Some(index) = index else {
            return Err(Diag::new(
                c.span,
                format!("expected a component (x, y, z, t, transmit) after `{word}(...).`, found {}", c.describe()),
            ));
        };
        Ok(Node::Spline(Arc::new(SplineRead { spline: s.clone(), kind, index }), Box::new(t)))
    }

    /// Whether the token after the cursor is `c` (the cursor is a word not yet taken).
    fn peek_after_is(&mut self, c: char) -> bool {
        self.bump();
        self.is_punct(c)
    }

    /// `(a, b, ...)` after a function's name, in a function body.
    fn fn_arguments(&mut self, word: &str, params: &[String]) -> PResult<Vec<Node>> {
        let open = self.expect_punct('(', &format!("after `{word}`"))?;
        self.enter(open)?;
        let mut args = Vec::new();
        if !self.is_punct(')') {
            args.push(self.fn_expr(params)?);
            while self.eat_punct(',') {
                args.push(self.fn_expr(params)?);
            }
        }
        self.expect_punct(')', &format!("to close `{word}(`"))?;
        self.leave();
        Ok(args)
    }

    /// `(a, b, ...)` after a function's name `word`: the arguments as floats (none for `()`)
    /// and the span of the closing parenthesis.
    pub(super) fn float_args(&mut self, word: &str) -> PResult<(Vec<f64>, Span)> {
        let open = self.expect_punct('(', &format!("after `{word}`"))?;
        self.enter(open)?;
        let mut args = Vec::new();
        if !self.is_punct(')') {
            loop {
                let e = self.full_expr()?;
                args.push(self.low.float(&e)?);
                if !self.eat_punct(',') {
                    break;
                }
            }
        }
        let close = self.expect_punct(')', &format!("to close `{word}(`"))?;
        self.leave();
        Ok((args, close))
    }

    /// `F(a, b, c)` in an ordinary expression, `F` a declared function: its value now.
    /// A pigment function's value is its colour.
    pub(super) fn call_function(&mut self, f: Rc<Function>, word: &str, span: Span) -> PResult<Value> {
        let (args, close) = self.float_args(word)?;
        if args.len() != f.params.len() {
            return Err(Diag::new(
                span.to(close),
                format!(
                    "`{word}` takes {} argument(s) ({}), found {}",
                    f.params.len(),
                    f.params.join(", "),
                    args.len()
                ),
            ));
        }
        Ok(match &f.color {
            Some(shade) => Value::Color(crate::pov::value::color_from(&shade.color(&args))),
            None => Value::Float(f.eval(&args)),
        })
    }
}

/// The component a member name reads of a vector or colour (`.y` is 1, `.t` 3), as in
/// ordinary expressions.
fn component_index(word: &str) -> Option<usize> {
    Some(match word {
        "x" | "u" | "red" => 0,
        "y" | "v" | "green" => 1,
        "z" | "blue" => 2,
        "t" | "filter" => 3,
        "transmit" => 4,
        _ => return None,
    })
}

/// The other name of a parameter: `x` is `u` and `y` is `v` (POV-Ray 3.3.1.8.3).
fn alias(name: &str) -> &str {
    match name {
        "x" => "u",
        "y" => "v",
        "u" => "x",
        "v" => "y",
        other => other,
    }
}
