//! Expressions (`+ - * /`, unary signs, vectors, built-in functions and constants) and colours
//! written with keywords (`color rgb <..> filter F`).

use std::rc::Rc;

use super::Parser;
use crate::pov::ast::{BinOp, Builtin, ColorItem, ColorKey, Expr, ExprKind};
use crate::pov::lexer::{Token, TokenKind};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

/// Built-in functions and how many arguments each takes (least, most), as in POV-Ray 3.7's
/// reference: `min` and `max` take two or more, `select` three or four.
pub const FUNCTIONS: &[(&str, (usize, usize))] = &[
    ("sqrt", (1, 1)),
    ("sin", (1, 1)),
    ("cos", (1, 1)),
    ("tan", (1, 1)),
    ("asin", (1, 1)),
    ("acos", (1, 1)),
    ("atan", (1, 1)),
    ("atan2", (2, 2)),
    ("sinh", (1, 1)),
    ("cosh", (1, 1)),
    ("tanh", (1, 1)),
    ("asinh", (1, 1)),
    ("acosh", (1, 1)),
    ("atanh", (1, 1)),
    ("abs", (1, 1)),
    ("exp", (1, 1)),
    ("log", (1, 1)),
    ("ln", (1, 1)),
    ("floor", (1, 1)),
    ("ceil", (1, 1)),
    ("int", (1, 1)),
    ("div", (2, 2)),
    ("mod", (2, 2)),
    ("radians", (1, 1)),
    ("degrees", (1, 1)),
    ("pow", (2, 2)),
    ("min", (2, usize::MAX)),
    ("max", (2, usize::MAX)),
    ("select", (3, 4)),
    ("vlength", (1, 1)),
    ("vnormalize", (1, 1)),
    ("vcross", (2, 2)),
    ("vdot", (2, 2)),
    ("vrotate", (2, 2)),
    ("vaxis_rotate", (3, 3)),
    ("vturbulence", (4, 4)),
    ("rand", (1, 1)),
    ("seed", (1, 1)),
    ("strcmp", (2, 2)),
    ("strlen", (1, 1)),
    ("val", (1, 1)),
    ("asc", (1, 1)),
    ("concat", (1, usize::MAX)),
    ("str", (3, 3)),
    ("vstr", (5, 5)),
    ("chr", (1, 1)),
    ("substr", (3, 3)),
    ("strupr", (1, 1)),
    ("strlwr", (1, 1)),
    ("file_exists", (1, 1)),
    ("dimensions", (1, 1)),
    ("dimension_size", (2, 2)),
    ("bitwise_and", (2, usize::MAX)),
    ("bitwise_or", (2, usize::MAX)),
    ("bitwise_xor", (2, usize::MAX)),
    ("datetime", (1, 2)),
    ("now", (0, 0)),
];

/// Functions whose argument is an identifier that is read as written, not evaluated.
const NAME_ARGUMENT: &[&str] = &["dimensions", "dimension_size"];

/// Values the renderer provides (`image_width`, `clock`, ...).
pub fn builtin(word: &str) -> Option<Builtin> {
    Some(match word {
        "image_width" => Builtin::ImageWidth,
        "image_height" => Builtin::ImageHeight,
        "clock" => Builtin::Clock,
        "clock_delta" => Builtin::ClockDelta,
        "frame_number" => Builtin::FrameNumber,
        "initial_clock" => Builtin::InitialClock,
        "final_clock" => Builtin::FinalClock,
        "initial_frame" => Builtin::InitialFrame,
        "final_frame" => Builtin::FinalFrame,
        "clock_on" => Builtin::ClockOn,
        _ => return None,
    })
}

/// Component names after `.`, as indices into (x, y, z, filter, transmit).
fn member_index(word: &str) -> Option<usize> {
    Some(match word {
        "x" | "u" | "red" => 0,
        "y" | "v" | "green" => 1,
        "z" | "blue" => 2,
        "t" | "filter" => 3,
        "transmit" => 4,
        "gray" | "grey" => 5,
        _ => return None,
    })
}

pub fn color_key(word: &str) -> Option<ColorKey> {
    Some(match word {
        "rgb" => ColorKey::Rgb,
        "rgbf" => ColorKey::Rgbf,
        "rgbt" => ColorKey::Rgbt,
        "rgbft" => ColorKey::Rgbft,
        "red" => ColorKey::Red,
        "green" => ColorKey::Green,
        "blue" => ColorKey::Blue,
        "filter" => ColorKey::Filter,
        "transmit" => ColorKey::Transmit,
        _ => return None,
    })
}

impl Parser<'_, '_> {
    /// A colour in any form (`color` keyword optional), or any other expression.
    pub(super) fn color(&mut self) -> PResult<Expr> {
        self.color_with(Self::expr)
    }

    /// A colour with keywords, or an expression where comparisons are allowed (a macro's
    /// argument).
    pub(super) fn full_color(&mut self) -> PResult<Expr> {
        self.color_with(Self::full_expr)
    }

    fn color_with(&mut self, base: fn(&mut Self) -> PResult<Expr>) -> PResult<Expr> {
        let start = self.peek().span;
        let explicit = matches!(self.peek_ident().as_deref(), Some("color" | "colour"));
        if explicit {
            self.bump();
        }
        let mut items = Vec::new();
        if self.peek_ident().as_deref().and_then(color_key).is_none() {
            let value = base(self)?;
            items.push(ColorItem { key: ColorKey::Base, span: value.span, value });
        }
        let whole = |k: ColorKey| {
            matches!(k, ColorKey::Base | ColorKey::Rgb | ColorKey::Rgbf | ColorKey::Rgbt | ColorKey::Rgbft)
        };
        while let Some(key) = self.more_ident().as_deref().and_then(color_key) {
            // A second whole colour starts the next colour (`checker rgb A rgb B`: two
            // colours, as POV-Ray 3.7 renders it), not a change to this one.
            if whole(key) && items.iter().any(|i| whole(i.key)) {
                break;
            }
            let key_span = self.bump().span;
            let value = self.expr()?;
            items.push(ColorItem { key, span: key_span.to(value.span), value });
        }
        if !explicit && items.len() == 1 && items[0].key == ColorKey::Base {
            return Ok(items.remove(0).value);
        }
        let span = start.to(items.last().map_or(start, |i| i.span));
        Ok(Expr { kind: ExprKind::Color(items), span })
    }

    /// True when the next token can start an expression or colour; identifiers in `stop` (the
    /// keywords of the enclosing block) cannot.
    pub(super) fn starts_expr(&mut self, stop: &[&str]) -> bool {
        match &self.peek().kind {
            TokenKind::Number(_) | TokenKind::Str(_) => true,
            TokenKind::Punct(c) => matches!(c, '<' | '(' | '-' | '+' | '!'),
            TokenKind::Ident(w) => !stop.contains(&&**w),
            _ => false,
        }
    }

    /// The next token where it may continue what was just read (an operator, a component):
    /// a directive or macro call there ends the expression instead of running first, so that
    /// `#declare A = 1` stores `A` before a following `#if (A)` or `M(A)` reads it, even without
    /// the `;`. The end of a running `#if` branch reads nothing, so it runs and the expression
    /// goes on after it.
    fn peek_more(&mut self) -> Token {
        loop {
            match self.cur.kind {
                TokenKind::Directive(d) if self.ends_running_branch(d) => {
                    if let Err(e) = self.directive(d) {
                        self.fail(e);
                    }
                }
                TokenKind::Directive(_) => return Token { kind: TokenKind::Eof, span: self.cur.span },
                // A word cannot continue an expression (only start one): a macro call there
                // waits too (`#declare C = "a"` before `M(C)` on the next line).
                TokenKind::Ident(_) => return self.cur.clone(),
                // The expression may go on after the macro that wrote its start; a directive
                // there still waits.
                TokenKind::FrameEnd => self.close_frame(),
                _ => return self.peek(),
            }
        }
    }

    pub(super) fn more_ident(&mut self) -> Option<Rc<str>> {
        match self.peek_more().kind {
            TokenKind::Ident(w) => Some(w),
            _ => None,
        }
    }

    /// An expression where comparisons, `&`, `|` and `? :` are allowed: inside parentheses and
    /// in directive conditions. POV-Ray reads `<` and `>` anywhere else as vector brackets
    /// (`#declare A = 1 < 2;` is an error there too), so `expr` does not parse them.
    pub(super) fn full_expr(&mut self) -> PResult<Expr> {
        let cond = self.logical()?;
        if self.peek_more().kind != TokenKind::Punct('?') {
            return Ok(cond);
        }
        let q = self.bump().span;
        self.enter(q)?;
        let a = self.full_expr()?;
        self.expect_punct(':', "in `? :`")?;
        let b = self.full_expr()?;
        self.leave();
        Ok(Expr { span: cond.span.to(b.span), kind: ExprKind::Ternary(Box::new(cond), Box::new(a), Box::new(b)) })
    }

    /// `&` and `|`: one precedence level, left to right (POV-Ray 3.7 gives `(1 | 0 & 0)` = 0).
    fn logical(&mut self) -> PResult<Expr> {
        self.chain(Self::relational, |k| match k {
            TokenKind::Punct('&') => Some(BinOp::And),
            TokenKind::Punct('|') => Some(BinOp::Or),
            _ => None,
        })
    }

    /// Comparisons, left to right (`(3 < 2 < 1)` is `(0 < 1)` = 1 in POV-Ray).
    fn relational(&mut self) -> PResult<Expr> {
        self.chain(Self::expr, |k| match k {
            TokenKind::Punct('<') => Some(BinOp::Lt),
            TokenKind::Punct('>') => Some(BinOp::Gt),
            TokenKind::Punct('=') => Some(BinOp::Eq),
            TokenKind::Op2("<=") => Some(BinOp::Le),
            TokenKind::Op2(">=") => Some(BinOp::Ge),
            TokenKind::Op2("!=") => Some(BinOp::Ne),
            _ => None,
        })
    }

    /// A left-leaning chain `operand (op operand)*`; each operator counts as a nesting level,
    /// because `lower` walks the tree recursively.
    fn chain(
        &mut self,
        operand: fn(&mut Self) -> PResult<Expr>,
        op_of: fn(&TokenKind) -> Option<BinOp>,
    ) -> PResult<Expr> {
        let mut lhs = operand(self)?;
        let mut chained = 0;
        while let Some(op) = op_of(&self.peek_more().kind) {
            let op_span = self.bump().span;
            if let Err(e) = self.enter(op_span) {
                self.depth -= chained;
                return Err(e);
            }
            chained += 1;
            let rhs = operand(self)?;
            lhs = Expr { span: lhs.span.to(rhs.span), kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)) };
        }
        self.depth -= chained;
        Ok(lhs)
    }

    pub(super) fn expr(&mut self) -> PResult<Expr> {
        let mut lhs = self.term()?;
        // Each operator in a chain deepens the (left-leaning) tree that `lower` walks
        // recursively, so it counts as a level of nesting too.
        let mut chained = 0;
        loop {
            let op = match self.peek_more().kind {
                TokenKind::Punct('+') => BinOp::Add,
                TokenKind::Punct('-') => BinOp::Sub,
                _ => {
                    self.depth -= chained;
                    return Ok(lhs);
                }
            };
            let op_span = self.bump().span;
            self.enter(op_span)?;
            chained += 1;
            let rhs = self.term()?;
            lhs = Expr { span: lhs.span.to(rhs.span), kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)) };
        }
    }

    fn term(&mut self) -> PResult<Expr> {
        let mut lhs = self.unary()?;
        let mut chained = 0;
        loop {
            let op = match self.peek_more().kind {
                TokenKind::Punct('*') => BinOp::Mul,
                TokenKind::Punct('/') => BinOp::Div,
                _ => {
                    self.depth -= chained;
                    return Ok(lhs);
                }
            };
            let op_span = self.bump().span;
            self.enter(op_span)?;
            chained += 1;
            let rhs = self.unary()?;
            lhs = Expr { span: lhs.span.to(rhs.span), kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)) };
        }
    }

    fn unary(&mut self) -> PResult<Expr> {
        let t = self.peek();
        match t.kind {
            TokenKind::Punct(c @ ('-' | '+')) => {
                self.bump();
                self.enter(t.span)?;
                let inner = self.unary()?;
                self.leave();
                let span = t.span.to(inner.span);
                Ok(if c == '-' { Expr { kind: ExprKind::Neg(Box::new(inner)), span } } else { inner })
            }
            TokenKind::Punct('!') => {
                self.bump();
                self.enter(t.span)?;
                let inner = self.unary()?;
                self.leave();
                Ok(Expr { span: t.span.to(inner.span), kind: ExprKind::Not(Box::new(inner)) })
            }
            _ => {
                let mut e = self.primary()?;
                // `V.x`: component access binds tighter than any operator.
                let mut chained = 0;
                while self.peek_more().kind == TokenKind::Punct('.') {
                    let dot = self.bump().span;
                    if let Err(err) = self.enter(dot) {
                        self.depth -= chained;
                        return Err(err);
                    }
                    chained += 1;
                    let t = self.bump();
                    let index = match &t.kind {
                        TokenKind::Ident(w) => member_index(w),
                        _ => None,
                    };
                    let Some(index) = index else {
                        self.depth -= chained;
                        return Err(Diag::new(
                            t.span,
                            format!(
                                "expected a component (x, y, z, t, red, green, blue, filter, \
                                 transmit) after `.`, found {}",
                                t.describe()
                            ),
                        ));
                    };
                    e = Expr { span: e.span.to(t.span), kind: ExprKind::Member(Box::new(e), index) };
                }
                self.depth -= chained;
                Ok(e)
            }
        }
    }

    fn primary(&mut self) -> PResult<Expr> {
        let t = self.peek();
        match &t.kind {
            TokenKind::Number(v) => {
                self.bump();
                Ok(Expr { kind: ExprKind::Number(*v), span: t.span })
            }
            TokenKind::Str(text) => {
                self.bump();
                Ok(Expr { kind: ExprKind::Value(Rc::new(Value::Str(text.clone()))), span: t.span })
            }
            TokenKind::Punct('(') => {
                self.bump();
                self.enter(t.span)?;
                let inner = self.full_expr()?;
                let close = self.expect_punct(')', "to close `(`")?;
                self.leave();
                Ok(Expr { kind: inner.kind, span: t.span.to(close) })
            }
            TokenKind::Punct('<') => {
                self.bump();
                self.enter(t.span)?;
                let mut parts = vec![self.expr()?];
                // Commas between components may be left out, as POV-Ray allows
                // (`translate < -1 0 0 >` in its woods.inc).
                while self.eat_punct(',') || (parts.len() < 5 && self.starts_expr(&[])) {
                    if self.is_punct('>') {
                        // A trailing comma (`rgb <0.2, 0.1, 0.5,>`), which POV-Ray accepts.
                        break;
                    }
                    parts.push(self.expr()?);
                }
                let close = self.expect_punct('>', "to close the vector")?;
                self.leave();
                let span = t.span.to(close);
                if !(2..=5).contains(&parts.len()) {
                    return Err(Diag::new(span, format!("a vector has 2 to 5 components, found {}", parts.len())));
                }
                Ok(Expr { kind: ExprKind::Vector(parts), span })
            }
            TokenKind::Ident(word) => self.word(word, t.span),
            TokenKind::Eof if self.pending.is_some() => Err(Diag::new(t.span, "")),
            _ => Err(Diag::new(t.span, format!("expected an expression, found {}", t.describe()))),
        }
    }

    fn word(&mut self, word: &str, span: Span) -> PResult<Expr> {
        let constant = match word {
            "x" => Some(ExprKind::Vector3([1.0, 0.0, 0.0])),
            "y" => Some(ExprKind::Vector3([0.0, 1.0, 0.0])),
            "z" => Some(ExprKind::Vector3([0.0, 0.0, 1.0])),
            // POV-Ray's 2-D unit vectors `u` = <1, 0> and `v` = <0, 1> (3.3.1.4.2).
            "u" => Some(ExprKind::Value(Rc::new(Value::Vector(vec![1.0, 0.0])))),
            "v" => Some(ExprKind::Value(Rc::new(Value::Vector(vec![0.0, 1.0])))),
            "pi" => Some(ExprKind::Number(std::f64::consts::PI)),
            "true" | "yes" | "on" => Some(ExprKind::Number(1.0)),
            "false" | "no" | "off" => Some(ExprKind::Number(0.0)),
            "version" => Some(ExprKind::Version),
            _ => None,
        };
        let constant = constant.or_else(|| builtin(word).map(ExprKind::Builtin));
        if let Some(kind) = constant {
            self.bump();
            return Ok(Expr { kind, span });
        }
        if word == "defined" {
            self.bump();
            self.expect_punct('(', "after `defined`")?;
            let defined = self.defined_name("defined")?;
            let close = self.expect_punct(')', "to close `defined(`")?;
            return Ok(Expr { kind: ExprKind::Number(if defined { 1.0 } else { 0.0 }), span: span.to(close) });
        }
        if matches!(word, "color" | "colour") || color_key(word).is_some() {
            self.enter(span)?;
            let c = self.color();
            self.leave();
            return c;
        }
        if super::probe::PROBES.contains(&word) {
            return self.probe(word, span);
        }
        if let Some(&(_, (least, most))) = FUNCTIONS.iter().find(|(name, _)| *name == word) {
            self.bump();
            self.expect_punct('(', &format!("after `{word}`"))?;
            self.enter(span)?;
            let mut args = Vec::new();
            if !self.is_punct(')') {
                args.push(self.function_argument(word, args.len())?);
                while self.eat_punct(',') {
                    args.push(self.function_argument(word, args.len())?);
                }
            }
            let close = self.expect_punct(')', &format!("to close `{word}(`"))?;
            self.leave();
            if !(least..=most).contains(&args.len()) {
                let takes = match (least, most) {
                    (l, m) if l == m => format!("{l}"),
                    (l, usize::MAX) => format!("{l} or more"),
                    (l, m) => format!("{l} to {m}"),
                };
                return Err(Diag::new(span, format!("`{word}` takes {takes} argument(s), found {}", args.len())));
            }
            return Ok(Expr { kind: ExprKind::Call(word.to_string(), args), span: span.to(close) });
        }
        if super::is_reserved(word) {
            return Err(Diag::new(span, format!("expected an expression, found `{word}`")));
        }
        if super::is_pov_keyword(word) {
            return Err(Diag::unmodelled(span, format!("`{word}` is not supported in an expression")));
        }
        self.declared_name(word, span)
    }

    /// A declared name's value, read now (an array element with its `[i]...`); an undeclared
    /// name stays a name, an error only if it is evaluated.
    pub(super) fn declared_name(&mut self, word: &str, span: Span) -> PResult<Expr> {
        let Some(value) = self.low.lookup(word).cloned() else {
            self.bump();
            return Ok(Expr { kind: ExprKind::Ident(word.to_string()), span });
        };
        self.bump();
        if let Value::Function(f) = &value {
            if self.peek_more().kind == TokenKind::Punct('(') {
                return Ok(match self.call_function(f.clone(), word, span)? {
                    Value::Float(v) => Expr { kind: ExprKind::Number(v), span },
                    v => Expr { kind: ExprKind::Value(Rc::new(v)), span },
                });
            }
        }
        if let Value::Spline(s) = &value {
            if self.peek_more().kind == TokenKind::Punct('(') {
                let v = self.call_spline(s.clone(), word, span)?;
                return Ok(Expr { kind: ExprKind::Value(Rc::new(v)), span });
            }
        }
        if let Value::TransformFunction(t) = &value {
            if self.peek_more().kind == TokenKind::Punct('(') {
                let v = self.call_transform_function(t.matrix, word, span)?;
                return Ok(Expr { kind: ExprKind::Value(Rc::new(v)), span });
            }
        }
        if let Value::Unmodelled(u) = &value {
            if self.peek_more().kind == TokenKind::Punct('(') {
                // A user function (`#declare f = function {...}`) called.
                return Err(u.used_at(span));
            }
        }
        let Value::Array(array) = &value else {
            return Ok(Expr { kind: ExprKind::Value(Rc::new(value)), span });
        };
        if self.peek_more().kind != TokenKind::Punct('[') {
            return Ok(Expr { kind: ExprKind::Value(Rc::new(value)), span });
        }
        let index = self.indices()?;
        let at = array.offset(&index).map_err(|m| Diag::new(span, format!("`{word}`: {m}")))?;
        match &array.items[at] {
            Some(v) => Ok(Expr { kind: ExprKind::Value(Rc::new(v.clone())), span }),
            None => Err(Diag::new(span, format!("element {index:?} of array `{word}` has no value yet"))),
        }
    }

    /// One argument of a built-in function: an expression, or for `dimension_size(A, n)` the
    /// array itself, and for `defined`-style checks the name as written.
    fn function_argument(&mut self, function: &str, index: usize) -> PResult<Expr> {
        if index == 0 && NAME_ARGUMENT.contains(&function) {
            return self.expr();
        }
        self.full_expr()
    }
}
