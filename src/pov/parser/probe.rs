//! `min_extent(O)`, `max_extent(O)`, `trace(O, start, dir [, N])` and `inside(O, P)`
//! (POV-Ray 3.3.1.4.3): questions about a declared object, answered while parsing by
//! `render::probe` (the renderer's own bounds and kernels), their values in the expression.

use std::rc::Rc;

use super::Parser;
use crate::desc::ObjectDesc;
use crate::pov::ast::{Expr, ExprKind};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
use crate::render::probe;

/// The object questions, by keyword.
pub const PROBES: &[&str] = &["min_extent", "max_extent", "trace", "inside"];

impl Parser<'_, '_> {
    /// One object question at `word` (the cursor), evaluated now.
    pub(super) fn probe(&mut self, word: &str, span: Span) -> PResult<Expr> {
        self.bump();
        let open = self.expect_punct('(', &format!("after `{word}`"))?;
        self.enter(open)?;
        let object = self.expr()?;
        let objects = match self.low.eval(&object)? {
            // A CSG node's children live beside its desc until `into_desc` moves them in.
            Value::Object(g) => {
                g.parts.iter().map(|p| p.clone().into_desc(&Default::default())).collect::<Vec<ObjectDesc>>()
            }
            other => {
                return Err(Diag::new(
                    object.span,
                    format!("`{word}` needs a declared object, found {}", other.kind_name()),
                ))
            }
        };
        let value = match word {
            "min_extent" | "max_extent" => {
                let (lo, hi) = probe::bounds(&objects).unwrap_or((DVEC_MIN, DVEC_MAX));
                vector(if word == "min_extent" { lo } else { hi })
            }
            "inside" => {
                self.expect_punct(',', "after the object in `inside(`")?;
                let p = self.expr()?;
                let p = self.low.vec3(&p)?;
                Value::Float(if probe::inside(&objects, p) { 1.0 } else { 0.0 })
            }
            _ => {
                self.expect_punct(',', "after the object in `trace(`")?;
                let start = self.expr()?;
                let start = self.low.vec3(&start)?;
                self.expect_punct(',', "after the start point in `trace(`")?;
                let dir = self.expr()?;
                let dir = self.low.vec3(&dir)?;
                let hit = probe::trace(&objects, start, dir);
                if self.eat_punct(',') {
                    // The normal goes into a declared variable: <0, 0, 0> on a miss.
                    let t = self.bump();
                    let TokenKind::Ident(name) = &t.kind else {
                        return Err(Diag::new(
                            t.span,
                            format!("expected the name of a variable for the normal, found {}", t.describe()),
                        ));
                    };
                    let normal = hit.map_or(glam::DVec3::ZERO, |h| h.1);
                    if !self.low.reassign(name, vector(normal)) {
                        return Err(Diag::new(
                            t.span,
                            format!("`{name}` must be declared before `trace` writes the normal into it"),
                        ));
                    }
                }
                // A miss gives <0, 0, 0>, as POV-Ray 3.7 returns it (checked by #debug).
                vector(hit.map_or(glam::DVec3::ZERO, |h| h.0))
            }
        };
        let close = self.expect_punct(')', &format!("to close `{word}(`"))?;
        self.leave();
        Ok(Expr { kind: ExprKind::Value(Rc::new(value)), span: span.to(close) })
    }
}

const DVEC_MIN: glam::DVec3 = glam::DVec3::splat(-1e10);
const DVEC_MAX: glam::DVec3 = glam::DVec3::splat(1e10);

fn vector(v: glam::DVec3) -> Value {
    Value::Vector(vec![v.x, v.y, v.z])
}
