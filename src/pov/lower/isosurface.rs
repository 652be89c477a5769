//! `isosurface` as the parser hands it over (the function, then keyword items with their
//! values): checked, with POV-Ray's defaults, into `ShapeDesc::Isosurface`.

use glam::DVec3;

use super::Lowerer;
use crate::pov::ast::{Expr, ExprKind};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;
use crate::scene::desc::{Container, IsoParams, ShapeDesc};

impl Lowerer<'_> {
    pub(super) fn isosurface(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let Some(ExprKind::Value(v)) = args.first().map(|a| &a.kind) else {
            return Err(Diag::new(span, "isosurface needs a `function { ... }`"));
        };
        let Value::Function(f) = &**v else {
            return Err(Diag::new(span, "isosurface needs a `function { ... }`"));
        };
        let function = f.compile();
        // POV-Ray's default container is the box from <-1, -1, -1> to <1, 1, 1>.
        let mut container = Container::Box { min: DVec3::splat(-1.0), max: DVec3::splat(1.0) };
        let mut params = IsoParams::default();
        let mut i = 1;
        let value = |i: usize| args.get(i).ok_or_else(|| Diag::new(span, "isosurface: a value is missing"));
        while i < args.len() {
            let ExprKind::Ident(word) = &args[i].kind else {
                return Err(Diag::new(args[i].span, "isosurface: expected an item keyword"));
            };
            let at = args[i].span;
            i += 1;
            match word.as_str() {
                "contained_by" => {
                    let ExprKind::Ident(shape) = &value(i)?.kind else {
                        return Err(Diag::new(at, "contained_by needs a box or sphere"));
                    };
                    let (a, b) = (value(i + 1)?, value(i + 2)?);
                    container = if shape == "box" {
                        let (p, q) = (self.vec3(a)?, self.vec3(b)?);
                        Container::Box { min: p.min(q), max: p.max(q) }
                    } else {
                        let radius = self.float(b)?;
                        if radius <= 0.0 {
                            return Err(Diag::new(b.span, "contained_by sphere: the radius must be positive"));
                        }
                        Container::Sphere { center: self.vec3(a)?, radius }
                    };
                    i += 3;
                }
                "threshold" => {
                    params.threshold = self.float(value(i)?)?;
                    i += 1;
                }
                "accuracy" => {
                    let e = value(i)?;
                    params.accuracy = self.float(e)?;
                    if !(params.accuracy > 0.0) {
                        return Err(Diag::new(e.span, "isosurface accuracy must be positive"));
                    }
                    i += 1;
                }
                "max_gradient" => {
                    let e = value(i)?;
                    params.max_gradient = self.float(e)?;
                    if !(params.max_gradient > 0.0) {
                        return Err(Diag::new(e.span, "isosurface max_gradient must be positive"));
                    }
                    i += 1;
                }
                "evaluate" => {
                    for k in 0..3 {
                        self.float(value(i + k)?)?;
                    }
                    self.warn(Diag::new(
                        at,
                        "isosurface `evaluate` (an adaptive max_gradient) is not modelled; max_gradient is used",
                    ));
                    i += 3;
                }
                "open" => params.open = true,
                // strahl always finds every crossing a query asks for, as all_intersections.
                "max_trace" => {
                    self.float(value(i)?)?;
                    i += 1;
                }
                "all_intersections" => {}
                "polarity" => {
                    self.float(value(i)?)?;
                    self.warn(Diag::new(at, "isosurface `polarity` is not modelled"));
                    i += 1;
                }
                other => return Err(Diag::new(at, format!("isosurface: unknown item `{other}`"))),
            }
        }
        if let Container::Box { min, max } = container {
            if (max - min).min_element() <= 0.0 {
                return Err(Diag::new(span, "contained_by box is flat"));
            }
        }
        Ok(ShapeDesc::Isosurface { function, container, params })
    }
}
