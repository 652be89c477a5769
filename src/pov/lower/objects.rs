//! Objects: shape arguments → `ShapeDesc` (with the zero-size checks), then modifiers in written
//! order. A transform moves the object and the patterns already attached to it; a pigment given
//! after the transform is not moved, exactly as in POV-Ray. `union` and `merge` are flattened
//! into their children, each carrying the union's transforms.

use glam::DVec3;

use super::textures::transform_texture;
use super::Lowerer;
use crate::pov::ast::{Expr, ExprKind, Modifier, Object, ObjectKind, ShapeKind, Stmt};
use crate::pov::parser::LAYERED;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::{Group, Part, Value};
use crate::scene::desc::{InteriorDesc, ObjectDesc, ShapeDesc, TextureDesc, Transform};

impl Lowerer<'_> {
    pub(super) fn object(&mut self, o: &Object) -> PResult<Group> {
        let mut group = match &o.kind {
            ObjectKind::Shape(kind, args) => Group {
                parts: vec![Part {
                    desc: ObjectDesc {
                        shape: self.shape(*kind, args, o.span)?,
                        transform: Transform::default(),
                        texture: TextureDesc::default(),
                        interior: InteriorDesc::default(),
                        no_shadow: false,
                        hollow: false,
                        source: self.files.source_ref(o.span),
                    },
                    textured: false,
                    has_interior: false,
                }],
                csg: false,
            },
            ObjectKind::Inner(inner) => self.object(inner)?,
            ObjectKind::Ref(e) => match (&e.kind, self.eval(e)?) {
                (ExprKind::Value(_), Value::Object(group)) => *group,
                (_, other) => return Err(other.wrong_kind(e.span, "a declared object")),
            },
            ObjectKind::Csg { children, merge } => self.csg(children, *merge, o.span)?,
        };
        if group.csg {
            self.csg_modifiers(&mut group, &o.modifiers)?;
        } else {
            for part in &mut group.parts {
                self.modifiers(part, &o.modifiers)?;
            }
        }
        Ok(group)
    }

    /// A single shape's modifiers, in written order. A transform moves the object and the
    /// patterns already attached to it.
    fn modifiers(&mut self, part: &mut Part, modifiers: &[Modifier]) -> PResult<()> {
        for m in modifiers {
            let surface = matches!(m, Modifier::Pigment(_) | Modifier::Normal(_) | Modifier::Finish(_));
            if surface && !part.textured {
                // The first of these starts the object's texture from the default in effect.
                part.desc.texture = self.default_texture.clone();
            }
            let obj = &mut part.desc;
            match m {
                Modifier::Pigment(p) => obj.texture.pigment = self.pigment(p)?,
                Modifier::Normal(n) => obj.texture.normal = Some(self.normal(n)?),
                Modifier::Finish(f) => obj.texture.finish = self.finish_block(f)?,
                Modifier::Texture(t) if part.textured => return Err(Diag::new(t.span, LAYERED)),
                Modifier::Texture(t) => obj.texture = self.texture(t)?,
                Modifier::Interior(i) => {
                    obj.interior = self.interior(i)?;
                    part.has_interior = true;
                }
                Modifier::Transform(t) => {
                    let t = self.transform(t)?;
                    obj.transform = obj.transform.then(&t);
                    transform_texture(&mut obj.texture, &t);
                }
                Modifier::NoShadow => obj.no_shadow = true,
                Modifier::Hollow(on) => obj.hollow = self.hollow(on.as_ref())?,
                Modifier::Open(span) => match &mut obj.shape {
                    ShapeDesc::Cone { open, .. } | ShapeDesc::Prism { open, .. } => *open = true,
                    other => return Err(flag_not_taken(*span, "open", other.keyword(), OPEN_TAKERS)),
                },
                Modifier::Sturm(span) => {
                    if !matches!(obj.shape, ShapeDesc::Torus { .. } | ShapeDesc::Prism { .. } | ShapeDesc::Lathe { .. })
                    {
                        return Err(flag_not_taken(*span, "sturm", obj.shape.keyword(), STURM_TAKERS));
                    }
                }
            }
            if surface || matches!(m, Modifier::Texture(_)) {
                part.textured = true;
            }
        }
        Ok(())
    }

    /// `union { ... }` / `merge { ... }`: the children, flattened. strahl's objects are opaque
    /// or refract as separate surfaces, so `merge` (which removes the inner surfaces of
    /// overlapping children, visible only through transparent ones) lowers like `union`.
    fn csg(&mut self, children: &[Stmt], merge: bool, span: Span) -> PResult<Group> {
        self.csg_stack.push(Vec::new());
        let result = children.iter().try_for_each(|c| self.stmt(c));
        let parts = self.csg_stack.pop().unwrap_or_default();
        result?;
        if parts.is_empty() {
            let word = if merge { "merge" } else { "union" };
            self.warn(Diag::new(span, format!("`{word}` has no objects")));
        }
        Ok(Group { parts, csg: true })
    }

    /// A union's modifiers: transforms and `no_shadow` apply to every child; the union's own
    /// texture and interior go, at the end, to the children that have none, as in POV-Ray.
    /// `hollow` alone is on; with a value, on unless it is 0.
    fn hollow(&self, on: Option<&Expr>) -> PResult<bool> {
        on.map_or(Ok(true), |e| Ok(self.float(e)? != 0.0))
    }

    fn csg_modifiers(&mut self, group: &mut Group, modifiers: &[Modifier]) -> PResult<()> {
        let mut texture: Option<TextureDesc> = None;
        let mut interior = None;
        for m in modifiers {
            match m {
                Modifier::Pigment(p) => {
                    let pigment = self.pigment(p)?;
                    texture.get_or_insert_with(|| self.default_texture.clone()).pigment = pigment;
                }
                Modifier::Normal(n) => {
                    let normal = self.normal(n)?;
                    texture.get_or_insert_with(|| self.default_texture.clone()).normal = Some(normal);
                }
                Modifier::Finish(f) => {
                    let finish = self.finish_block(f)?;
                    texture.get_or_insert_with(|| self.default_texture.clone()).finish = finish;
                }
                Modifier::Texture(t) if texture.is_some() => return Err(Diag::new(t.span, LAYERED)),
                Modifier::Texture(t) => texture = Some(self.texture(t)?),
                Modifier::Interior(i) => interior = Some(self.interior(i)?),
                Modifier::Transform(t) => {
                    let t = self.transform(t)?;
                    for part in &mut group.parts {
                        part.desc.transform = part.desc.transform.then(&t);
                        transform_texture(&mut part.desc.texture, &t);
                    }
                    if let Some(tex) = &mut texture {
                        transform_texture(tex, &t);
                    }
                }
                Modifier::NoShadow => {
                    for part in &mut group.parts {
                        part.desc.no_shadow = true;
                    }
                }
                Modifier::Open(span) => return Err(flag_not_taken(*span, "open", "union", OPEN_TAKERS)),
                Modifier::Sturm(span) => return Err(flag_not_taken(*span, "sturm", "union", STURM_TAKERS)),
                // As in POV-Ray, `hollow` on a CSG object applies to all its parts.
                Modifier::Hollow(on) => {
                    let hollow = self.hollow(on.as_ref())?;
                    for part in &mut group.parts {
                        part.desc.hollow = hollow;
                    }
                }
            }
        }
        for part in &mut group.parts {
            if let (false, Some(tex)) = (part.textured, &texture) {
                part.desc.texture = tex.clone();
                part.textured = true;
            }
            if let (false, Some(int)) = (part.has_interior, &interior) {
                part.desc.interior = *int;
                part.has_interior = true;
            }
        }
        Ok(())
    }

    fn shape(&mut self, kind: ShapeKind, args: &[Expr], span: Span) -> PResult<ShapeDesc> {
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
            ShapeKind::Prism => self.prism(args, span)?,
            ShapeKind::Text => self.text(args, span)?,
            ShapeKind::Lathe => self.lathe(args, span)?,
        })
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

/// The shapes that take `open` and `sturm`, for messages.
const OPEN_TAKERS: &str = "cylinder, cone and prism";
const STURM_TAKERS: &str = "torus, prism and lathe";

/// `flag` written on a shape that does not take it.
fn flag_not_taken(span: Span, flag: &str, on: &str, takes: &str) -> Diag {
    Diag::new(span, format!("`{flag}` does not apply to {on} (only to {takes})"))
}
