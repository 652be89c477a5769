//! The bodies of `isosurface { function {..} contained_by {..} threshold T ... }` and
//! `parametric { function {..} x3 <u1, v1>, <u2, v2> ... }`: the functions as
//! `Value::Function`s, the corners, then each item as its keyword (an `Ident`) and its values,
//! for `lower` to check and apply.

use std::rc::Rc;

use super::Parser;
use crate::pov::ast::{Expr, ExprKind};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

/// What may follow the function, in any order, with how many values each takes.
pub const ISOSURFACE_ITEMS: &[(&str, usize)] = &[
    ("contained_by", 0),
    ("threshold", 1),
    ("accuracy", 1),
    ("max_gradient", 1),
    ("evaluate", 3),
    ("open", 0),
    ("max_trace", 1),
    ("all_intersections", 0),
    ("polarity", 1),
];

/// What may follow a parametric's corners.
pub const PARAMETRIC_ITEMS: &[(&str, usize)] =
    &[("contained_by", 0), ("max_gradient", 1), ("accuracy", 1), ("precompute", 0)];

impl Parser<'_, '_> {
    pub(super) fn parametric_args(&mut self) -> PResult<Vec<Expr>> {
        let mut args = Vec::new();
        for _ in 0..3 {
            self.eat_punct(',');
            let span = self.peek().span;
            if self.peek_ident().as_deref() != Some("function") {
                return Err(Diag::new(
                    span,
                    format!("parametric needs three functions, found {}", self.peek().describe()),
                ));
            }
            let f = self.function()?;
            if f.params.len() > 3 {
                return Err(Diag::new(span, "a parametric's functions take u, v"));
            }
            args.push(Expr { kind: ExprKind::Value(Rc::new(Value::Function(Rc::new(f)))), span });
        }
        self.eat_punct(',');
        args.push(self.expr()?);
        self.eat_punct(',');
        args.push(self.expr()?);
        self.items(&mut args, PARAMETRIC_ITEMS)?;
        Ok(args)
    }

    pub(super) fn isosurface_args(&mut self) -> PResult<Vec<Expr>> {
        let mut args = Vec::new();
        let mut function = None;
        while let Some(word) = self.peek_ident() {
            let span = self.peek().span;
            if &*word == "function" {
                if function.is_some() {
                    return Err(Diag::new(span, "isosurface has one function"));
                }
                let f = self.function()?;
                if f.params.len() != 3 {
                    return Err(Diag::new(span, "an isosurface's function takes x, y, z"));
                }
                function = Some(Expr { kind: ExprKind::Value(Rc::new(Value::Function(Rc::new(f)))), span });
                continue;
            }
            if !self.shape_item(&mut args, ISOSURFACE_ITEMS)? {
                break;
            }
        }
        let Some(function) = function else {
            return Err(Diag::new(self.peek().span, "isosurface needs a `function { ... }`"));
        };
        args.insert(0, function);
        Ok(args)
    }

    /// Items of `items` while they come.
    fn items(&mut self, args: &mut Vec<Expr>, items: &[(&str, usize)]) -> PResult<()> {
        while self.shape_item(args, items)? {}
        Ok(())
    }

    /// One item of `items` at the cursor into `args`; false when none stands there.
    fn shape_item(&mut self, args: &mut Vec<Expr>, items: &[(&str, usize)]) -> PResult<bool> {
        {
            let Some(word) = self.peek_ident() else { return Ok(false) };
            let span = self.peek().span;
            let Some(&(_, values)) = items.iter().find(|(w, _)| *w == &*word) else { return Ok(false) };
            self.bump();
            args.push(Expr { kind: ExprKind::Ident(word.to_string()), span });
            if &*word == "precompute" {
                // `precompute DEPTH, x, y, z`: a speed hint for POV-Ray, read and dropped.
                args.push(self.expr()?);
                while self.eat_punct(',') || matches!(self.peek_ident().as_deref(), Some("x" | "y" | "z")) {
                    if let Some("x" | "y" | "z") = self.peek_ident().as_deref() {
                        self.bump();
                    }
                }
                return Ok(true);
            }
            if &*word == "contained_by" {
                self.open_block("contained_by", span)?;
                let t = self.bump();
                let (shape, n) = match &t.kind {
                    TokenKind::Ident(w) if &**w == "box" || &**w == "sphere" => (w.to_string(), 2),
                    _ => {
                        return Err(Diag::new(
                            t.span,
                            format!("expected `box` or `sphere` in contained_by, found {}", t.describe()),
                        ))
                    }
                };
                self.open_block(&shape, t.span)?;
                args.push(Expr { kind: ExprKind::Ident(shape.clone()), span: t.span });
                for i in 0..n {
                    if i > 0 {
                        self.eat_punct(',');
                    }
                    args.push(self.expr()?);
                }
                self.close_block(&shape, t.span)?;
                self.close_block("contained_by", span)?;
                return Ok(true);
            }
            for i in 0..values {
                if i > 0 {
                    self.eat_punct(',');
                }
                args.push(self.expr()?);
            }
            Ok(true)
        }
    }
}
