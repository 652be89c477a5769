//! `julia_fractal` items → `ShapeDesc::Julia`, with POV-Ray's defaults (quaternion, sqr,
//! max_iteration 20, precision 20, slice <0, 0, 0, 1>, 0) and its rules: quaternions take only
//! `sqr` and `cube`, and the slice's normal needs a non-zero fourth component.

use glam::DVec4;

use super::Lowerer;
use crate::desc::{ComplexFn, JuliaFunction, ShapeDesc};
use crate::pov::ast::{JuliaFractal, JuliaItem};
use crate::pov::source::{Diag, PResult, Span};

/// More iterations than this are refused before rendering starts (POV-Ray's own samples use
/// at most 20; each costs every sample of every ray).
const MAX_ITERATIONS: f64 = 10_000.0;

impl Lowerer<'_> {
    pub(super) fn julia(&mut self, julia: &JuliaFractal, _span: Span) -> PResult<ShapeDesc> {
        let param = self.eval(&julia.param)?.as_vec4(julia.param.span)?;
        let (mut hypercomplex, mut function, mut max_iteration, mut precision) = (false, None, 20, 20.0);
        let mut slice = (DVec4::W, 0.0);
        for item in &julia.items {
            match item {
                JuliaItem::Algebra(word, _) => hypercomplex = &**word == "hypercomplex",
                JuliaItem::Function(word, span) => {
                    let f = ComplexFn::from_keyword(word)
                        .ok_or_else(|| Diag::new(*span, format!("`{word}` is not a julia_fractal function")))?;
                    function = Some((f, *span));
                }
                JuliaItem::Pwr(x, y, span) => function = Some((ComplexFn::Pwr(self.float(x)?, self.float(y)?), *span)),
                JuliaItem::MaxIteration(e) => {
                    let n = self.float(e)?;
                    if !(1.0..=MAX_ITERATIONS).contains(&n) {
                        return Err(Diag::new(
                            e.span,
                            format!("julia_fractal max_iteration must be from 1 to {MAX_ITERATIONS}, found {n}"),
                        ));
                    }
                    max_iteration = n as u32;
                }
                // Values below 1 are raised to 1, as POV-Ray documents.
                JuliaItem::Precision(e) => precision = self.float(e)?.clamp(1.0, 1e6),
                JuliaItem::Slice(normal, distance) => {
                    let n = self.eval(normal)?.as_vec4(normal.span)?;
                    if n.w == 0.0 {
                        return Err(Diag::new(
                            normal.span,
                            "julia_fractal slice: the normal's fourth component must not be 0",
                        ));
                    }
                    slice = (n, self.float(distance)?);
                }
            }
        }
        let function = match (hypercomplex, function) {
            (true, f) => JuliaFunction::Hypercomplex(f.map_or(ComplexFn::Sqr, |f| f.0)),
            (false, None | Some((ComplexFn::Sqr, _))) => JuliaFunction::QuaternionSqr,
            (false, Some((ComplexFn::Cube, _))) => JuliaFunction::QuaternionCube,
            (false, Some((_, span))) => {
                return Err(Diag::new(
                    span,
                    "julia_fractal: quaternions take only sqr and cube; add `hypercomplex` for this function",
                ))
            }
        };
        Ok(ShapeDesc::Julia { param: Box::new(param), function, max_iteration, precision, slice: Box::new(slice) })
    }
}
