//! A shape's arguments lowered into its `ShapeDesc` (the parser has checked their count; here
//! they are evaluated and checked for sense: radii, polynomial orders, polygon planarity).
//! The object around the shape (modifiers, CSG) is `objects`.

use glam::DVec3;

use super::Lowerer;
use crate::desc::{PolyForm, ShapeDesc};
use crate::geometry::poly::{term_count, MAX_ORDER};
use crate::pov::ast::{Expr, ShapeKind};
use crate::pov::source::{Diag, PResult, Span};

impl Lowerer<'_> {
    pub(super) fn shape(&mut self, kind: ShapeKind, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        // The parser guarantees the argument count for all shapes but polygon.
        let arg = |i: usize| args.get(i).ok_or_else(|| Diag::new(span, "missing argument"));
        Ok(match kind {
            ShapeKind::Sphere => {
                let center = self.vec3(arg(0)?)?;
                let radius = self.float(arg(1)?)?;
                if radius <= 0.0 {
                    return Err(Diag::new(arg(1)?.span, "sphere radius must be positive"));
                }
                ShapeDesc::Sphere { center, radius }
            }
            ShapeKind::Plane => {
                let normal = self.vec3(arg(0)?)?;
                if normal.length() == 0.0 {
                    return Err(Diag::new(arg(0)?.span, "plane normal must not be zero"));
                }
                ShapeDesc::Plane { normal, distance: self.float(arg(1)?)? }
            }
            ShapeKind::Box => ShapeDesc::Box { corner1: self.vec3(arg(0)?)?, corner2: self.vec3(arg(1)?)? },
            ShapeKind::Triangle => {
                let (a, b, c) = (self.vec3(arg(0)?)?, self.vec3(arg(1)?)?, self.vec3(arg(2)?)?);
                if collinear(&[a, b, c]) {
                    return Err(Diag::new(span, "triangle is degenerate: its corners are collinear"));
                }
                ShapeDesc::Triangle { a, b, c }
            }
            ShapeKind::Polygon => self.polygon(args, span)?,
            ShapeKind::Cylinder | ShapeKind::Cone => {
                let cylinder = kind == ShapeKind::Cylinder;
                let base = self.vec3(arg(0)?)?;
                let (base_radius, cap, cap_radius, radii) = if cylinder {
                    let r = self.float(arg(2)?)?;
                    (r, self.vec3(arg(1)?)?, r, [(r, arg(2)?.span)])
                } else {
                    let (r0, r1) = (self.float(arg(1)?)?, self.float(arg(3)?)?);
                    (r0, self.vec3(arg(2)?)?, r1, [(r0.min(r1), if r0 <= r1 { arg(1)? } else { arg(3)? }.span)])
                };
                let word = if cylinder { "cylinder" } else { "cone" };
                if (cap - base).length() == 0.0 {
                    return Err(Diag::new(span, format!("{word}: base and cap are the same point")));
                }
                for (r, at) in radii {
                    if r < 0.0 || (cylinder && r == 0.0) {
                        return Err(Diag::new(at, format!("{word} radius must be positive")));
                    }
                }
                if !cylinder && base_radius == 0.0 && cap_radius == 0.0 {
                    return Err(Diag::new(span, "cone: both radii are 0"));
                }
                ShapeDesc::Cone { base, base_radius, cap, cap_radius, open: false, cylinder }
            }
            ShapeKind::Disc => {
                let (center, normal, radius) = (self.vec3(arg(0)?)?, self.vec3(arg(1)?)?, self.float(arg(2)?)?);
                let hole = match args.get(3) {
                    Some(e) => self.float(e)?,
                    None => 0.0,
                };
                if normal.length() == 0.0 {
                    return Err(Diag::new(arg(1)?.span, "disc normal must not be zero"));
                }
                if radius <= 0.0 {
                    return Err(Diag::new(arg(2)?.span, "disc radius must be positive"));
                }
                if !(0.0..radius).contains(&hole) {
                    return Err(Diag::new(args[3].span, "disc hole radius must lie in [0, radius)"));
                }
                ShapeDesc::Disc { center, normal, radius, hole }
            }
            ShapeKind::Torus => {
                let (major, minor) = (self.float(arg(0)?)?, self.float(arg(1)?)?);
                if major <= 0.0 || minor <= 0.0 {
                    let at = if major <= 0.0 { arg(0)? } else { arg(1)? };
                    return Err(Diag::new(at.span, "torus radii must be positive"));
                }
                ShapeDesc::Torus { major, minor }
            }
            ShapeKind::Quadric => {
                // A·x² + B·y² + C·z² + D·xy + E·xz + F·yz + G·x + H·y + I·z + J, as the order-2
                // poly x², xy, xz, x, y², yz, y, z², z, 1.
                let (abc, def, ghi) = (self.vec3(arg(0)?)?, self.vec3(arg(1)?)?, self.vec3(arg(2)?)?);
                let j = self.float(arg(3)?)?;
                let coefficients = vec![abc.x, def.x, def.y, ghi.x, abc.y, def.z, ghi.y, abc.z, ghi.z, j];
                if coefficients[..9].iter().all(|&c| c == 0.0) {
                    return Err(Diag::new(span, "quadric: every coefficient but J is 0, so it has no surface"));
                }
                ShapeDesc::Poly { order: 2, coefficients, sturm: false, written: PolyForm::Quadric }
            }
            ShapeKind::Cubic | ShapeKind::Quartic | ShapeKind::Poly => self.poly(kind, args, span)?,
            ShapeKind::Superellipsoid => {
                let v = self.vec3(arg(0)?)?;
                if !(v.x > 0.0 && v.y > 0.0) {
                    return Err(Diag::new(arg(0)?.span, "superellipsoid exponents <e, n> must be positive"));
                }
                ShapeDesc::Superellipsoid { e: v.x, n: v.y }
            }
            ShapeKind::Prism => self.prism(args, span)?,
            ShapeKind::Text => self.text(args, span)?,
            ShapeKind::Lathe => self.lathe(args, span)?,
            ShapeKind::Sor => self.sor(args, span)?,
            ShapeKind::Isosurface => self.isosurface(args, span)?,
            ShapeKind::Parametric => self.parametric(args, span)?,
        })
    }

    /// `cubic`, `quartic` or `poly`: the order (3, 4, or as written), then its coefficients.
    fn poly(&mut self, kind: ShapeKind, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let (order, written, coefficients) = match kind {
            ShapeKind::Cubic => (3, PolyForm::Cubic, args),
            ShapeKind::Quartic => (4, PolyForm::Quartic, args),
            _ => {
                let order_expr = args.first().ok_or_else(|| Diag::new(span, "poly needs its order"))?;
                let order = self.float(order_expr)?;
                if order.fract() != 0.0 || !(2.0..=MAX_ORDER as f64).contains(&order) {
                    return Err(Diag::new(
                        order_expr.span,
                        format!("poly order must be a whole number from 2 to {MAX_ORDER}, found {order}"),
                    ));
                }
                let order = order as usize;
                let found = args.len() - 1;
                if found != term_count(order) {
                    let at = args.get(1).map_or(order_expr.span, |first| first.span.to(args[args.len() - 1].span));
                    return Err(Diag::new(
                        at,
                        format!("poly of order {order} takes {} coefficients, found {found}", term_count(order)),
                    ));
                }
                (order, PolyForm::Poly, &args[1..])
            }
        };
        let coefficients = coefficients.iter().map(|e| self.float(e)).collect::<PResult<Vec<f64>>>()?;
        if coefficients.iter().all(|&c| c == 0.0) {
            return Err(Diag::new(span, format!("{}: every coefficient is 0", written.keyword())));
        }
        Ok(ShapeDesc::Poly { order, coefficients, sturm: false, written })
    }

    fn polygon(&mut self, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
        let count_expr = args.first().ok_or_else(|| Diag::new(span, "polygon needs the number of points"))?;
        let count = self.float(count_expr)?;
        let given = args.len() - 1;
        if count != given as f64 {
            return Err(Diag::new(
                count_expr.span,
                format!("polygon says it has {count} points, but {given} are given"),
            ));
        }
        let mut points = Vec::with_capacity(given);
        for e in &args[1..] {
            points.push(self.vec3(e)?);
        }
        if points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
        let mut distinct: Vec<DVec3> = Vec::new();
        for p in &points {
            if !distinct.contains(p) {
                distinct.push(*p);
            }
        }
        if distinct.len() < 3 {
            return Err(Diag::new(span, format!("polygon needs at least 3 distinct points, found {}", distinct.len())));
        }
        if collinear(&distinct) {
            return Err(Diag::new(span, "polygon is degenerate: all its points are collinear"));
        }
        if let Some(i) = off_plane(&points) {
            // POV-Ray 3.7 silently accepts this (checked with povray 3.7.0.10); strahl's polygon
            // needs one plane, so it is an error here rather than a different picture.
            return Err(Diag::new(
                args[i + 1].span,
                format!("polygon points must lie in one plane; point {} does not", i + 1),
            ));
        }
        Ok(ShapeDesc::Polygon { points })
    }
}

/// The index of the first point farther than a millionth of the polygon's size from the plane
/// of the first three points that span one (`points` are not all collinear), if any.
fn off_plane(points: &[DVec3]) -> Option<usize> {
    let a = points[0];
    let scale = points.iter().map(|p| (*p - a).length()).fold(0.0, f64::max);
    let b = points.iter().copied().find(|p| (*p - a).length() > 1e-9 * scale)?;
    let ab = (b - a).normalize();
    let c = points.iter().copied().find(|p| ab.cross(*p - a).length() > 1e-9 * scale)?;
    let normal = ab.cross(c - a).normalize();
    points.iter().position(|p| normal.dot(*p - a).abs() > 1e-6 * scale)
}

/// True when every point lies on one line (relative tolerance, so tiny and huge shapes agree).
fn collinear(points: &[DVec3]) -> bool {
    let a = points[0];
    let scale = points.iter().map(|p| (*p - a).length()).fold(0.0, f64::max);
    if scale == 0.0 {
        return true;
    }
    let far = points.iter().copied().max_by(|p, q| (*p - a).length().total_cmp(&(*q - a).length())).unwrap_or(a);
    let dir = (far - a) / scale;
    points.iter().all(|p| dir.cross(*p - a).length() <= 1e-9 * scale)
}
