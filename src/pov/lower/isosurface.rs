//! `isosurface` and `parametric` as the parser hands them over (the functions, then keyword
//! items with their values): checked, with POV-Ray's defaults, into `ShapeDesc::Isosurface`
//! and `ShapeDesc::Parametric`.

use glam::DVec3;

use super::Lowerer;
use crate::desc::{Container, IsoParams, ParametricParams, ShapeDesc};
use crate::pov::ast::{Expr, ExprKind};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

/// POV-Ray's default container, the box from <-1, -1, -1> to <1, 1, 1>.
const DEFAULT_CONTAINER: Container = Container::Box { min: DVec3::splat(-1.0), max: DVec3::splat(1.0) };

impl Lowerer<'_> {
    /// `contained_by { box {a, b} | sphere {c, r} }` from `args[i..]` (after the keyword).
    fn container(&mut self, args: &[Expr], i: usize, at: Span) -> PResult<Container> {
        let value = |i: usize| args.get(i).ok_or_else(|| Diag::new(at, "contained_by: a value is missing"));
        let ExprKind::Ident(shape) = &value(i)?.kind else {
            return Err(Diag::new(at, "contained_by needs a box or sphere"));
        };
        let (a, b) = (value(i + 1)?, value(i + 2)?);
        if shape == "box" {
            let (p, q) = (self.vec3(a)?, self.vec3(b)?);
            if (p - q).abs().min_element() <= 0.0 {
                return Err(Diag::new(at, "contained_by box is flat"));
            }
            return Ok(Container::Box { min: p.min(q), max: p.max(q) });
        }
        let radius = self.float(b)?;
        if radius <= 0.0 {
            return Err(Diag::new(b.span, "contained_by sphere: the radius must be positive"));
        }
        Ok(Container::Sphere { center: self.vec3(a)?, radius })
    }

    pub(super) fn parametric(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let function = |i: usize| match args.get(i).map(|a| &a.kind) {
            Some(ExprKind::Value(v)) => match &**v {
                Value::Function(f) => Ok(f.compile()),
                _ => Err(Diag::new(span, "parametric needs three functions")),
            },
            _ => Err(Diag::new(span, "parametric needs three functions")),
        };
        let functions = [function(0)?, function(1)?, function(2)?];
        let corner = |i: usize| args.get(i).ok_or_else(|| Diag::new(span, "parametric needs <u1, v1>, <u2, v2>"));
        let (a, b) = (self.vec3(corner(3)?)?, self.vec3(corner(4)?)?);
        let mut params = ParametricParams { lo: a.truncate(), hi: b.truncate(), accuracy: 0.001, max_gradient: 1.0 };
        if params.lo.x == params.hi.x || params.lo.y == params.hi.y {
            return Err(Diag::new(corner(3)?.span.to(corner(4)?.span), "parametric: the (u, v) rectangle is empty"));
        }
        let mut container = DEFAULT_CONTAINER;
        let mut i = 5;
        let value = |i: usize| args.get(i).ok_or_else(|| Diag::new(span, "parametric: a value is missing"));
        while i < args.len() {
            let ExprKind::Ident(word) = &args[i].kind else {
                return Err(Diag::new(args[i].span, "parametric: expected an item keyword"));
            };
            let at = args[i].span;
            i += 1;
            match word.as_str() {
                "contained_by" => {
                    container = self.container(args, i, at)?;
                    i += 3;
                }
                "accuracy" | "max_gradient" => {
                    let e = value(i)?;
                    let v = self.float(e)?;
                    if v.is_nan() || v <= 0.0 {
                        return Err(Diag::new(e.span, format!("parametric {word} must be positive")));
                    }
                    if word == "accuracy" {
                        params.accuracy = v;
                    } else {
                        params.max_gradient = v;
                    }
                    i += 1;
                }
                "precompute" => {
                    self.float(value(i)?)?;
                    i += 1;
                }
                other => return Err(Diag::new(at, format!("parametric: unknown item `{other}`"))),
            }
        }
        Ok(ShapeDesc::Parametric { functions: Box::new(functions), container, params: Box::new(params) })
    }

    pub(super) fn isosurface(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let Some(ExprKind::Value(v)) = args.first().map(|a| &a.kind) else {
            return Err(Diag::new(span, "isosurface needs a `function { ... }`"));
        };
        let Value::Function(f) = &**v else {
            return Err(Diag::new(span, "isosurface needs a `function { ... }`"));
        };
        let function = f.compile();
        let mut container = DEFAULT_CONTAINER;
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
                    container = self.container(args, i, at)?;
                    i += 3;
                }
                "threshold" => {
                    params.threshold = self.float(value(i)?)?;
                    i += 1;
                }
                "accuracy" => {
                    let e = value(i)?;
                    params.accuracy = self.float(e)?;
                    if params.accuracy.is_nan() || params.accuracy <= 0.0 {
                        return Err(Diag::new(e.span, "isosurface accuracy must be positive"));
                    }
                    i += 1;
                }
                "max_gradient" => {
                    let e = value(i)?;
                    params.max_gradient = self.float(e)?;
                    if params.max_gradient.is_nan() || params.max_gradient <= 0.0 {
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
        Ok(ShapeDesc::Isosurface { function: Box::new(function), container, params: Box::new(params) })
    }
}
