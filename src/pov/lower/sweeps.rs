//! The swept and revolved shapes' arguments → `ShapeDesc`: `prism` (spline and sweep keywords,
//! heights, the point count and the points; the splines are checked to close here, so a bad
//! outline is a located error and never reaches the renderer).

use glam::DVec2;

use super::Lowerer;
use crate::desc::ShapeDesc;
use crate::desc::SplineKind;
use crate::geometry::sor::check_points;
use crate::geometry::spline::{closed_pieces, open_pieces};
use crate::pov::ast::{Expr, ExprKind};
use crate::pov::source::{Diag, PResult, Span};

/// The leading keywords (`Ident`s the parser kept) and the rest of a shape's arguments.
fn split_words(args: &[Expr]) -> (Vec<(&str, Span)>, &[Expr]) {
    let n = args.iter().take_while(|e| matches!(e.kind, ExprKind::Ident(_))).count();
    let words = args[..n]
        .iter()
        .filter_map(|e| match &e.kind {
            ExprKind::Ident(w) => Some((w.as_str(), e.span)),
            _ => None,
        })
        .collect();
    (words, &args[n..])
}

impl Lowerer<'_> {
    /// `N, <p1>, ..., <pN>` of a prism, lathe or sor: the count checked against the points.
    fn counted_points(&mut self, word: &str, args: &[Expr], span: Span) -> PResult<Vec<(DVec2, Span)>> {
        let count_expr = args.first().ok_or_else(|| Diag::new(span, format!("{word} needs the number of points")))?;
        let count = self.float(count_expr)?;
        let given = args.len() - 1;
        if count != given as f64 {
            return Err(Diag::new(
                count_expr.span,
                format!("{word} says it has {count} points, but {given} are given"),
            ));
        }
        args[1..].iter().map(|e| self.vec3(e).map(|v| (DVec2::new(v.x, v.y), e.span))).collect()
    }

    /// `prism { [spline] [sweep] h1, h2, N, points }` (POV-Ray 3.4.6.x Prism).
    pub(super) fn prism(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let (words, rest) = split_words(args);
        let mut spline = SplineKind::Linear;
        let mut conic = false;
        for (w, _) in words {
            match w {
                "linear_sweep" => conic = false,
                "conic_sweep" => conic = true,
                _ => spline = SplineKind::from_keyword(w).unwrap_or(spline),
            }
        }
        if rest.len() < 3 {
            return Err(Diag::new(span, "prism needs two heights, the number of points, then the points"));
        }
        let (h1, h2) = (self.float(&rest[0])?, self.float(&rest[1])?);
        if h1 == h2 {
            return Err(Diag::new(rest[1].span, "prism heights must differ"));
        }
        let points: Vec<DVec2> = self.counted_points("prism", &rest[2..], span)?.into_iter().map(|p| p.0).collect();
        let (_, auto_closed) =
            closed_pieces(spline, &points).map_err(|m| Diag::new(rest[2].span, format!("prism: {m}")))?;
        if auto_closed {
            self.warn(Diag::new(span, "prism: linear outline not closed; closed with a line (as POV-Ray does)"));
        }
        Ok(ShapeDesc::Prism { spline, conic, h1, h2, points, open: false })
    }

    /// `lathe { [spline] N, points }` (POV-Ray 3.4.6.x Lathe): (r, y) points around the y axis.
    pub(super) fn lathe(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let (words, rest) = split_words(args);
        let spline = words.last().and_then(|(w, _)| SplineKind::from_keyword(w)).unwrap_or(SplineKind::Linear);
        if rest.is_empty() {
            return Err(Diag::new(span, "lathe needs the number of points, then the points"));
        }
        let points: Vec<DVec2> = self.counted_points("lathe", rest, span)?.into_iter().map(|p| p.0).collect();
        open_pieces(spline, &points).map_err(|m| Diag::new(rest[0].span, format!("lathe: {m}")))?;
        Ok(ShapeDesc::Lathe { spline, points })
    }

    /// `sor { N, points }` (POV-Ray 3.4.5.1.15): (r, y) points, heights increasing.
    pub(super) fn sor(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        if args.is_empty() {
            return Err(Diag::new(span, "sor needs the number of points, then the points"));
        }
        let points: Vec<DVec2> = self.counted_points("sor", args, span)?.into_iter().map(|p| p.0).collect();
        check_points(&points).map_err(|m| Diag::new(args[0].span, format!("sor: {m}")))?;
        Ok(ShapeDesc::Sor { points, open: false })
    }
}
