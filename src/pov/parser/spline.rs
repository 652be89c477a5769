//! `spline { [S] [kind] key, <point> [,] ... }` (POV-Ray 3.3.1.11) read into a
//! `function::spline::Spline`, and a call `S(t [, kind])` evaluated where it is read; the other
//! vector-valued functions, `function { spline { .. } }` and `function { transform { .. } }`
//! (`transforms.inc`'s `vtransform`), and their calls. The interpolation lives in
//! `function::spline`.

use std::rc::Rc;

use super::Parser;
use crate::function::spline::{Spline, SplineKind, MAX_COMPONENTS};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

/// The most points one spline may hold: far above what a scene writes by hand or by loop.
pub const MAX_SPLINE_POINTS: usize = 1_000_000;

impl Parser<'_, '_> {
    /// `spline { ... }` at its keyword.
    pub(super) fn spline(&mut self) -> PResult<Spline> {
        let kw = self.bump().span;
        self.open_block("spline", kw)?;
        let mut spline = Spline::default();
        let mut first = true;
        while !self.at_block_end() {
            if let Some(word) = self.peek_ident() {
                if let Some(kind) = SplineKind::from_keyword(&word) {
                    self.bump();
                    spline.kind = kind;
                    first = false;
                    continue;
                }
                // `spline { S ... }`: a copy of the declared spline to continue from.
                if first {
                    if let Some(Value::Spline(base)) = self.low.lookup(&word) {
                        spline = (**base).clone();
                        self.bump();
                        first = false;
                        continue;
                    }
                }
            }
            first = false;
            let key = self.expr()?;
            let key_value = self.low.float(&key)?;
            self.eat_punct(',');
            let point = self.expr()?;
            let components = match self.low.eval(&point)? {
                Value::Vector(v) => v,
                other => return Err(other.wrong_kind(point.span, "a vector for the spline point")),
            };
            if components.len() > MAX_COMPONENTS {
                return Err(Diag::new(point.span, "a spline point has at most 5 components"));
            }
            if !key_value.is_finite() || components.iter().any(|c| !c.is_finite()) {
                return Err(Diag::new(key.span.to(point.span), "a spline key and point must be finite"));
            }
            if spline.len() >= MAX_SPLINE_POINTS {
                return Err(Diag::new(key.span, format!("a spline may have at most {MAX_SPLINE_POINTS} points")));
            }
            spline.insert(key_value, &components);
            self.eat_punct(',');
        }
        self.close_block("spline", kw)?;
        Ok(spline)
    }

    /// `function { spline { .. } }` or `function { transform { .. } }` after `function` (at
    /// `kw`), the cursor at `{`.
    pub(super) fn vector_function(&mut self, kw: Span, spline: bool) -> PResult<Value> {
        self.open_block("function", kw)?;
        let value = if spline {
            Value::Spline(Rc::new(self.spline()?))
        } else {
            let at = self.bump().span;
            Value::TransformFunction(self.transform_after(at)?.0)
        };
        self.close_block("function", kw)?;
        Ok(value)
    }

    /// `F(x, y, z)` after the name `word` (at `span`) of a `function { transform { .. } }`.
    pub(super) fn call_transform_function(&mut self, m: glam::DMat4, word: &str, span: Span) -> PResult<Value> {
        let (args, close) = self.float_args(word)?;
        let [x, y, z] = args[..] else {
            return Err(Diag::new(
                span.to(close),
                format!("`{word}` takes 3 arguments (x, y, z), found {}", args.len()),
            ));
        };
        let p = m.transform_point3(glam::DVec3::new(x, y, z));
        Ok(Value::Vector(vec![p.x, p.y, p.z]))
    }

    /// The `kind` of a call `S(t, kind)`, after its comma.
    pub(super) fn spline_kind_arg(&mut self) -> PResult<SplineKind> {
        let k = self.bump();
        match &k.kind {
            TokenKind::Ident(w) => SplineKind::from_keyword(w),
            _ => None,
        }
        .ok_or_else(|| {
            Diag::new(
                k.span,
                format!(
                    "expected a spline kind (linear_spline, quadratic_spline, cubic_spline, natural_spline), found {}",
                    k.describe()
                ),
            )
        })
    }

    /// `S(t)` or `S(t, kind)` after a declared spline's name `word` (at `span`): the point.
    pub(super) fn call_spline(&mut self, s: Rc<Spline>, word: &str, span: Span) -> PResult<Value> {
        let open = self.expect_punct('(', &format!("after `{word}`"))?;
        self.enter(open)?;
        let t = self.full_expr()?;
        let t = self.low.float(&t)?;
        let kind = if self.eat_punct(',') { self.spline_kind_arg()? } else { s.kind };
        let close = self.expect_punct(')', &format!("to close `{word}(`"))?;
        self.leave();
        if s.is_empty() {
            return Err(Diag::new(span.to(close), format!("spline `{word}` has no points")));
        }
        Ok(Value::Vector(s.eval(t, kind)))
    }
}
