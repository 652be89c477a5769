//! The body of `isosurface { function {..} contained_by {..} threshold T ... }`: the function
//! as a `Value::Function`, then each item as its keyword (an `Ident`) and its values, for
//! `lower` to check and apply.

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

impl Parser<'_, '_> {
    pub(super) fn isosurface_args(&mut self) -> PResult<Vec<Expr>> {
        let mut args = Vec::new();
        let mut function = None;
        loop {
            let Some(word) = self.peek_ident() else { break };
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
            let Some(&(_, values)) = ISOSURFACE_ITEMS.iter().find(|(w, _)| *w == &*word) else { break };
            self.bump();
            args.push(Expr { kind: ExprKind::Ident(word.to_string()), span });
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
                continue;
            }
            for i in 0..values {
                if i > 0 {
                    self.eat_punct(',');
                }
                args.push(self.expr()?);
            }
        }
        let Some(function) = function else {
            return Err(Diag::new(self.peek().span, "isosurface needs a `function { ... }`"));
        };
        args.insert(0, function);
        Ok(args)
    }
}
