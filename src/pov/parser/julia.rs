//! The items of a `julia_fractal` (POV-Ray 3.4.5.1.7): the 4-D parameter first, then the
//! algebra, the function, `max_iteration`, `precision` and `slice`, in any order among the
//! object's modifiers.

use super::Parser;
use crate::pov::ast::{JuliaFractal, JuliaItem};
use crate::pov::source::{Diag, PResult};

/// The words that start a julia_fractal item.
pub const JULIA_ITEMS: &[&str] = &[
    "quaternion",
    "hypercomplex",
    "max_iteration",
    "precision",
    "slice",
    "sqr",
    "cube",
    "exp",
    "reciprocal",
    "sin",
    "asin",
    "sinh",
    "asinh",
    "cos",
    "acos",
    "cosh",
    "acosh",
    "tan",
    "atan",
    "tanh",
    "atanh",
    "ln",
    "pwr",
];

impl Parser<'_, '_> {
    /// The parameter and the items up to the first modifier (more may follow among them).
    pub(super) fn julia_items(&mut self) -> PResult<JuliaFractal> {
        if !self.starts_expr(JULIA_ITEMS) {
            let t = self.peek();
            return Err(Diag::new(
                t.span,
                format!("julia_fractal needs its 4-D parameter <a, b, c, d> first, found {}", t.describe()),
            ));
        }
        let mut julia = JuliaFractal { param: self.expr()?, items: Vec::new() };
        while self.peek_ident().is_some_and(|w| JULIA_ITEMS.contains(&&*w)) {
            self.julia_item(&mut julia)?;
        }
        Ok(julia)
    }

    /// One item; the cursor is on its keyword.
    pub(super) fn julia_item(&mut self, julia: &mut JuliaFractal) -> PResult<()> {
        let word = self.peek_ident().unwrap_or_default();
        let span = self.bump().span;
        let item = match &*word {
            "quaternion" | "hypercomplex" => JuliaItem::Algebra(word, span),
            "max_iteration" => JuliaItem::MaxIteration(self.expr()?),
            "precision" => JuliaItem::Precision(self.expr()?),
            "slice" => {
                let normal = self.expr()?;
                self.eat_punct(',');
                JuliaItem::Slice(normal, self.expr()?)
            }
            "pwr" => {
                self.expect_punct('(', "after `pwr`")?;
                let x = self.expr()?;
                self.expect_punct(',', "between pwr's two values")?;
                let y = self.expr()?;
                let close = self.expect_punct(')', "to close `pwr(`")?;
                JuliaItem::Pwr(x, y, span.to(close))
            }
            _ => JuliaItem::Function(word, span),
        };
        julia.items.push(item);
        Ok(())
    }
}
