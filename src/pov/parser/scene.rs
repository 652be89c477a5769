//! Top-level items and objects with their modifiers; the camera, lights and global settings
//! have files of their own.

use std::rc::Rc;

use super::blob::BLOB_ITEMS;
use super::julia::JULIA_ITEMS;
use super::{Parser, UNSUPPORTED_SHAPES};
use glam::{DMat4, DVec4};

use crate::desc::Transform;
use crate::pov::ast::{
    AtmosphereKind, Clip, CsgOp, Expr, ExprKind, Modifier, Object, ObjectKind, ShapeKind, Stmt, TransformItem,
    TransformKind,
};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

const TOP_LEVEL: &[&str] = &[
    "camera",
    "light_source",
    "background",
    "global_settings",
    "object",
    "union",
    "merge",
    "intersection",
    "difference",
    "sphere",
    "plane",
    "box",
    "triangle",
    "polygon",
    "cylinder",
    "cone",
    "disc",
    "torus",
    "quadric",
    "cubic",
    "quartic",
    "poly",
    "superellipsoid",
    "prism",
    "text",
    "lathe",
    "sor",
    "blob",
    "julia_fractal",
    "smooth_triangle",
    "mesh",
    "mesh2",
    "height_field",
    "bicubic_patch",
    "light_group",
    "isosurface",
    "parametric",
    "sky_sphere",
    "fog",
    "rainbow",
    "media",
];
const SHAPES: &str =
    "sphere, plane, box, triangle, polygon, cylinder, cone, disc, torus, quadric, cubic, quartic, poly, \
     superellipsoid, prism, text, lathe, sor, blob, julia_fractal, smooth_triangle, mesh, mesh2, height_field, bicubic_patch, \
     isosurface, parametric, light_group, union, merge, intersection, difference, object";
/// Shapes whose bodies the parser reads and evaluates itself (`parser::mesh`).
const BUILT: &[&str] = &["mesh", "mesh2", "height_field", "smooth_triangle", "bicubic_patch"];
/// Keywords that may precede a prism's numbers (POV-Ray 3.4.6.x Prism), in any order.
pub const PRISM_ITEMS: &[&str] =
    &["linear_spline", "quadratic_spline", "cubic_spline", "bezier_spline", "linear_sweep", "conic_sweep"];
/// What a `transform { }` block holds, besides declared transforms.
const TRANSFORM: &[&str] = &["rotate", "scale", "translate", "matrix", "transform", "inverse"];

/// A composed transform as a transform item.
fn transform_value(tr: Transform, span: Span) -> TransformItem {
    let value = Expr { kind: ExprKind::Value(Rc::new(Value::Transform(tr))), span };
    TransformItem { kind: TransformKind::Transform, value, span }
}

/// What may follow an object's arguments.
pub const MODIFIERS: &[&str] = &[
    "pigment",
    "normal",
    "finish",
    "texture",
    "interior",
    "material",
    "rotate",
    "scale",
    "translate",
    "matrix",
    "transform",
    "no_shadow",
    "hollow",
    "open",
    "sturm",
    "inverse",
    "clipped_by",
    "bounded_by",
    "inside_vector",
    "hierarchy",
    "no_image",
    "uv_mapping",
    "no_reflection",
    "double_illuminate",
    "no_radiosity",
    "photons",
    "radiosity",
    "interior_texture",
];

pub fn is_object_keyword(word: &str) -> bool {
    shape_kind(word).is_some()
        || matches!(word, "object" | "blob" | "julia_fractal" | "light_group")
        || csg_op(word).is_some()
        || BUILT.contains(&word)
}

/// The items a shape parsed by a file of its own takes, which may stand among its modifiers.
fn own_items(kind: &ObjectKind) -> &'static [&'static str] {
    match kind {
        ObjectKind::Blob(_) => BLOB_ITEMS,
        ObjectKind::Julia(_) => JULIA_ITEMS,
        _ => &[],
    }
}

fn csg_op(word: &str) -> Option<CsgOp> {
    Some(match word {
        "union" => CsgOp::Union,
        "merge" => CsgOp::Merge,
        "intersection" => CsgOp::Intersection,
        "difference" => CsgOp::Difference,
        _ => return None,
    })
}

fn shape_kind(word: &str) -> Option<ShapeKind> {
    Some(match word {
        "sphere" => ShapeKind::Sphere,
        "plane" => ShapeKind::Plane,
        "box" => ShapeKind::Box,
        "triangle" => ShapeKind::Triangle,
        "polygon" => ShapeKind::Polygon,
        "cylinder" => ShapeKind::Cylinder,
        "cone" => ShapeKind::Cone,
        "disc" => ShapeKind::Disc,
        "torus" => ShapeKind::Torus,
        "quadric" => ShapeKind::Quadric,
        "cubic" => ShapeKind::Cubic,
        "quartic" => ShapeKind::Quartic,
        "poly" => ShapeKind::Poly,
        "superellipsoid" => ShapeKind::Superellipsoid,
        "prism" => ShapeKind::Prism,
        "text" => ShapeKind::Text,
        "lathe" => ShapeKind::Lathe,
        "sor" => ShapeKind::Sor,
        "isosurface" => ShapeKind::Isosurface,
        "parametric" => ShapeKind::Parametric,
        _ => return None,
    })
}

/// Arguments each shape takes, as named in messages.
fn shape_args(kind: ShapeKind) -> &'static [&'static str] {
    match kind {
        ShapeKind::Sphere => &["center", "radius"],
        ShapeKind::Plane => &["normal", "distance"],
        ShapeKind::Box => &["corner1", "corner2"],
        ShapeKind::Triangle => &["a", "b", "c"],
        ShapeKind::Polygon => &["number of points", "points"],
        ShapeKind::Cylinder => &["base", "cap", "radius"],
        ShapeKind::Cone => &["base", "base radius", "cap", "cap radius"],
        ShapeKind::Disc => &["center", "normal", "radius"],
        ShapeKind::Torus => &["major radius", "minor radius"],
        ShapeKind::Quadric => &["<A, B, C>", "<D, E, F>", "<G, H, I>", "J"],
        ShapeKind::Cubic => &["<20 coefficients>"],
        ShapeKind::Quartic => &["<35 coefficients>"],
        ShapeKind::Poly => &["order", "<coefficients>"],
        ShapeKind::Superellipsoid => &["<e, n>"],
        ShapeKind::Prism => &["height 1", "height 2", "number of points", "points"],
        ShapeKind::Text => &["ttf", "font", "string", "thickness", "offset"],
        ShapeKind::Lathe | ShapeKind::Sor => &["number of points", "points"],
        ShapeKind::Isosurface => &["function"],
        ShapeKind::Parametric => &["function x", "function y", "function z", "<u1, v1>", "<u2, v2>"],
    }
}

impl Parser<'_, '_> {
    /// One top-level item (not a directive).
    pub(super) fn item(&mut self) -> PResult<Stmt> {
        match self.peek_ident().as_deref() {
            Some("camera") => self.camera(),
            Some("light_source") => self.light().map(Stmt::Light),
            Some("background") => {
                let kw = self.bump().span;
                self.open_block("background", kw)?;
                let color = self.color()?;
                self.close_block("background", kw)?;
                Ok(Stmt::Background { color, span: kw })
            }
            Some("global_settings") => self.global_settings(),
            Some("sky_sphere") => self.atmosphere(AtmosphereKind::SkySphere),
            Some("fog") => self.atmosphere(AtmosphereKind::Fog),
            Some("rainbow") => self.atmosphere(AtmosphereKind::Rainbow),
            Some("media") => self.skip_media(),
            Some(w) if is_object_keyword(w) => self.object().map(Stmt::Object),
            Some(w) if UNSUPPORTED_SHAPES.contains(&w) => {
                Err(Diag::unmodelled(self.peek().span, format!("`{w}` is not supported (supported: {SHAPES})")))
            }
            _ => Err(self.unknown_in("the scene", TOP_LEVEL)),
        }
    }

    /// when none follows, else whether it is on (a value that cannot be read yet counts on).
    fn flag_value(&mut self) -> PResult<Option<bool>> {
        if !self.starts_bool() {
            return Ok(None);
        }
        let e = self.expr()?;
        Ok(Some(!self.low.float(&e).is_ok_and(|v| v == 0.0)))
    }

    /// `rotate V`, `scale V`, `translate V`, `matrix <..>`, `transform { ... }` or
    /// `transform T`.
    pub(super) fn transform_item(&mut self) -> PResult<TransformItem> {
        let t = self.bump();
        let kind = match &t.kind {
            TokenKind::Ident(w) if &**w == "rotate" => TransformKind::Rotate,
            TokenKind::Ident(w) if &**w == "scale" => TransformKind::Scale,
            TokenKind::Ident(w) if &**w == "matrix" => {
                let (tr, span) = self.matrix_after(t.span)?;
                return Ok(transform_value(tr, t.span.to(span)));
            }
            TokenKind::Ident(w) if &**w == "transform" => {
                let (tr, span) = self.transform_after(t.span)?;
                return Ok(transform_value(tr, span));
            }
            _ => TransformKind::Translate,
        };
        let value = self.expr()?;
        Ok(TransformItem { kind, span: t.span.to(value.span), value })
    }

    /// `matrix <m00, m01, m02, m10, ..., m32>` after its keyword (3.3.1.12.4): the rows are
    /// where x, y and z go and the last is the translation.
    fn matrix_after(&mut self, kw: Span) -> PResult<(Transform, Span)> {
        let open = self.expect_punct('<', "after `matrix`")?;
        self.enter(open)?;
        let mut m = [0.0; 12];
        for (i, slot) in m.iter_mut().enumerate() {
            if i > 0 {
                self.expect_punct(',', "between the 12 values of `matrix`")?;
            }
            let e = self.expr()?;
            *slot = self.low.float(&e)?;
        }
        self.eat_punct(',');
        let close = self.expect_punct('>', "to close the 12 values of `matrix`")?;
        self.leave();
        let matrix = DMat4::from_cols(
            DVec4::new(m[0], m[1], m[2], 0.0),
            DVec4::new(m[3], m[4], m[5], 0.0),
            DVec4::new(m[6], m[7], m[8], 0.0),
            DVec4::new(m[9], m[10], m[11], 1.0),
        );
        let det = matrix.determinant();
        if !det.is_finite() || det.abs() < 1e-12 {
            return Err(Diag::new(kw.to(close), "`matrix` is singular (it flattens space), so it has no inverse"));
        }
        Ok((Transform { matrix, inverse: matrix.inverse() }, close))
    }

    /// `transform { items [inverse] }` or `transform T` after its keyword (3.3.1.12.5): the
    /// items compose left to right; `inverse` anywhere inverts the whole.
    pub(super) fn transform_after(&mut self, kw: Span) -> PResult<(Transform, Span)> {
        if !self.is_punct('{') {
            let e = self.expr()?;
            return match self.low.eval(&e)? {
                Value::Transform(t) => Ok((t, kw.to(e.span))),
                other => Err(Diag::new(
                    e.span,
                    format!("`transform` needs a declared transform, found {}", other.kind_name()),
                )),
            };
        }
        self.open_block("transform", kw)?;
        let mut tr = Transform::default();
        let mut inverse = false;
        while !self.at_block_end() {
            match self.peek_ident().as_deref() {
                Some("inverse") => {
                    self.bump();
                    inverse = true;
                }
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    let item = self.transform_item()?;
                    tr = tr.then(&self.low.transform(&item)?);
                }
                Some(_) if self.starts_expr(&[]) => {
                    // A declared transform named alone (`transform { T }`).
                    let e = self.expr()?;
                    match self.low.eval(&e)? {
                        Value::Transform(t) => tr = tr.then(&t),
                        other => {
                            return Err(Diag::new(
                                e.span,
                                format!("expected a transform in `transform {{ }}`, found {}", other.kind_name()),
                            ))
                        }
                    }
                }
                _ => return Err(self.unknown_in("transform", TRANSFORM)),
            }
        }
        let close = self.peek().span;
        self.close_block("transform", kw)?;
        if inverse {
            tr = Transform { matrix: tr.inverse, inverse: tr.matrix };
        }
        Ok((tr, kw.to(close)))
    }

    /// A shape or `object { ... }` with its modifiers.
    pub(super) fn object(&mut self) -> PResult<Object> {
        let word = self.peek_ident().unwrap_or_else(|| Rc::from(""));
        let word: &str = &word;
        let kw = self.peek().span;
        if UNSUPPORTED_SHAPES.contains(&word) {
            return Err(Diag::unmodelled(kw, format!("`{word}` is not supported (supported: {SHAPES})")));
        }
        let word = word.to_string();
        self.bump();
        self.open_block(&word, kw)?;
        let mut kind = match shape_kind(&word) {
            None if word == "blob" => ObjectKind::Blob(self.blob_items()?),
            None if word == "julia_fractal" => ObjectKind::Julia(self.julia_items()?),
            Some(shape) => ObjectKind::Shape(shape, self.shape_args(shape, &word)?),
            None if word == "mesh" => ObjectKind::Built(self.mesh_body(kw)?),
            None if word == "mesh2" => ObjectKind::Built(self.mesh2_body(kw)?),
            None if word == "smooth_triangle" => ObjectKind::Built(self.smooth_triangle_body()?),
            None if word == "height_field" => ObjectKind::Built(self.height_field_body(kw)?),
            None if word == "bicubic_patch" => ObjectKind::Built(self.bicubic_body(kw)?),
            None if word == "light_group" => {
                let outer = std::mem::replace(&mut self.in_csg, true);
                let body = self.light_group_body();
                self.in_csg = outer;
                let (children, global_lights) = body?;
                ObjectKind::LightGroup { children, global_lights }
            }
            None if csg_op(&word).is_some() => {
                let outer = std::mem::replace(&mut self.in_csg, true);
                let children = self.children();
                self.in_csg = outer;
                ObjectKind::Csg { op: csg_op(&word).unwrap_or(CsgOp::Union), children: children? }
            }
            None if self.peek_ident().is_some_and(|w| is_object_keyword(&w) || UNSUPPORTED_SHAPES.contains(&&*w)) => {
                // `object { sphere { ... } modifiers }`, as a macro that makes an object is used.
                ObjectKind::Inner(Box::new(self.object()?))
            }
            None => {
                if !self.starts_expr(MODIFIERS) {
                    return Err(Diag::new(
                        self.peek().span,
                        format!("expected the name of a declared object in `object`, found {}", self.peek().describe()),
                    ));
                }
                ObjectKind::Ref(self.expr()?)
            }
        };
        let mut modifiers = Vec::new();
        while !self.at_block_end() {
            let m = match self.peek_ident().as_deref() {
                // A shape's own items may stand among its modifiers.
                Some(w) if own_items(&kind).contains(&w) => {
                    match &mut kind {
                        ObjectKind::Blob(blob) => self.blob_item(blob)?,
                        ObjectKind::Julia(julia) => self.julia_item(julia)?,
                        _ => {}
                    }
                    continue;
                }
                // `global_lights` may follow the group's modifiers too (POV-Ray's abyss.pov).
                Some("global_lights") if matches!(kind, ObjectKind::LightGroup { .. }) => {
                    self.bump();
                    let on = if self.starts_bool() { Some(self.expr()?) } else { None };
                    if let ObjectKind::LightGroup { global_lights, .. } = &mut kind {
                        *global_lights = Some(on);
                    }
                    continue;
                }
                Some("pigment") => Modifier::Pigment(self.pigment()?),
                Some("normal") => Modifier::Normal(self.normal()?),
                Some("finish") => Modifier::Finish(self.finish()?),
                Some("texture") => Modifier::Texture(self.texture()?),
                Some("interior") => Modifier::Interior(self.interior()?),
                Some("material") => Modifier::Material(self.material()?),
                Some("rotate" | "scale" | "translate" | "matrix" | "transform") => {
                    Modifier::Transform(self.transform_item()?)
                }
                Some("no_shadow") => {
                    self.bump();
                    Modifier::NoShadow
                }
                Some("open") => Modifier::Open(self.bump().span),
                Some("inverse") => {
                    self.bump();
                    Modifier::Inverse
                }
                Some("clipped_by") => Modifier::ClippedBy(self.clip("clipped_by", "bounded_by")?),
                Some("bounded_by") => Modifier::BoundedBy(self.clip("bounded_by", "clipped_by")?),
                Some("sturm") => Modifier::Sturm(self.bump().span),
                Some("inside_vector") if matches!(&*word, "mesh" | "mesh2" | "object") => {
                    self.bump();
                    Modifier::InsideVector(self.expr()?)
                }
                // A hint for POV-Ray's own mesh bounding; strahl always builds a BVH.
                Some("hierarchy") if BUILT.contains(&&*word) || word == "object" => {
                    self.bump();
                    self.flag_value()?;
                    continue;
                }
                // Flags of features strahl does not model: read with their optional boolean,
                // noted once. `no_radiosity` needs no note: radiosity itself is noted.
                Some(w @ ("no_image" | "no_reflection" | "double_illuminate" | "no_radiosity")) => {
                    let w = w.to_string();
                    let at = self.bump().span;
                    if self.flag_value()?.is_none_or(|on| on) && w != "no_radiosity" {
                        self.low.not_modelled(&w, at);
                    }
                    continue;
                }
                // POV-Ray 3.7 lets `uv_mapping` stand on the object for all its textures.
                Some("uv_mapping") => Modifier::UvMapping(self.bump().span),
                Some(w @ ("photons" | "radiosity")) => {
                    let w = w.to_string();
                    self.skip_unmodelled(&w)?;
                    continue;
                }
                Some("interior_texture") => Modifier::InteriorTexture(self.texture()?),
                Some("hollow") => {
                    self.bump();
                    // `hollow` alone means on; a boolean may follow (`hollow off`, `hollow 0`).
                    Modifier::Hollow(if self.starts_bool() { Some(self.expr()?) } else { None })
                }
                Some(w) if matches!(kind, ObjectKind::Csg { .. }) && is_object_keyword(w) => {
                    return Err(Diag::new(
                        self.peek().span,
                        format!(
                            "`{w}` after the modifiers of `{word}`: its objects must come first \
                             (as in POV-Ray)"
                        ),
                    ));
                }
                None if self.is_punct(',') => {
                    let message = match shape_kind(&word) {
                        Some(s)
                            if !matches!(
                                s,
                                ShapeKind::Polygon
                                    | ShapeKind::Prism
                                    | ShapeKind::Text
                                    | ShapeKind::Lathe
                                    | ShapeKind::Sor
                            ) =>
                        {
                            let names = shape_args(s);
                            format!("{word} takes {} arguments ({}); found an extra `,`", names.len(), names.join(", "))
                        }
                        _ => format!("unexpected `,` in {word}"),
                    };
                    return Err(Diag::new(self.peek().span, message));
                }
                _ => {
                    // Name only the flags this shape takes.
                    let takes = |m: &&str| match *m {
                        "open" => {
                            matches!(
                                shape_kind(&word),
                                Some(
                                    ShapeKind::Cylinder
                                        | ShapeKind::Cone
                                        | ShapeKind::Prism
                                        | ShapeKind::Sor
                                        | ShapeKind::Isosurface
                                )
                            )
                        }
                        "sturm" => {
                            word == "blob"
                                || matches!(
                                    shape_kind(&word),
                                    Some(
                                        ShapeKind::Torus
                                            | ShapeKind::Cubic
                                            | ShapeKind::Quartic
                                            | ShapeKind::Poly
                                            | ShapeKind::Prism
                                            | ShapeKind::Lathe
                                            | ShapeKind::Sor
                                    )
                                )
                        }
                        "inside_vector" => matches!(&*word, "mesh" | "mesh2"),
                        "hierarchy" => BUILT.contains(&&*word),
                        _ => true,
                    };
                    let allowed: Vec<&str> = own_items(&kind).iter().chain(MODIFIERS).copied().filter(takes).collect();
                    return Err(self.unknown_in(&word, &allowed));
                }
            };
            modifiers.push(m);
        }
        self.close_block(&word, kw)?;
        Ok(Object { kind, modifiers, span: kw })
    }

    /// `clipped_by { objects }` / `bounded_by { objects }`, or the one naming the other
    /// (`clipped_by { bounded_by }`).
    fn clip(&mut self, word: &str, other: &str) -> PResult<Clip> {
        let kw = self.bump().span;
        self.open_block(word, kw)?;
        let clip = if self.peek_ident().as_deref() == Some(other) {
            Clip::Other(self.bump().span)
        } else {
            let outer = std::mem::replace(&mut self.in_csg, true);
            let children = self.children();
            self.in_csg = outer;
            Clip::Objects(children?, kw)
        };
        self.close_block(word, kw)?;
        Ok(clip)
    }

    /// The comma-separated arguments of a shape; commas are optional, as in POV-Ray.
    fn shape_args(&mut self, shape: ShapeKind, word: &str) -> PResult<Vec<crate::pov::ast::Expr>> {
        if shape == ShapeKind::Isosurface {
            return self.isosurface_args();
        }
        if shape == ShapeKind::Parametric {
            return self.parametric_args();
        }
        let names = shape_args(shape);
        let mut args = Vec::new();
        let leading = match shape {
            ShapeKind::Prism => PRISM_ITEMS,
            ShapeKind::Text => &["ttf", "internal"],
            ShapeKind::Lathe => &PRISM_ITEMS[..4],
            _ => &[],
        };
        if !leading.is_empty() {
            // Keywords first, kept as words for lowering; a misspelt one is named here.
            while let Some(w) = self.peek_ident() {
                let span = self.peek().span;
                if leading.contains(&&*w) {
                    self.bump();
                    args.push(crate::pov::ast::Expr { kind: crate::pov::ast::ExprKind::Ident(w.to_string()), span });
                } else if (w.ends_with("_spline") || w.ends_with("_sweep")) && self.low.lookup(&w).is_none() {
                    return Err(Diag::new(
                        span,
                        format!("unknown keyword `{w}` in {word} (expected one of: {})", leading.join(", ")),
                    ));
                } else {
                    break;
                }
            }
        }
        if matches!(shape, ShapeKind::Polygon | ShapeKind::Prism | ShapeKind::Text | ShapeKind::Lathe | ShapeKind::Sor)
        {
            if !self.starts_expr(MODIFIERS) {
                let what = match shape {
                    ShapeKind::Polygon => "polygon needs the number of points, then the points",
                    ShapeKind::Prism => "prism needs two heights, the number of points, then the points",
                    ShapeKind::Lathe => "lathe needs the number of points, then the points",
                    ShapeKind::Sor => "sor needs the number of points, then the points",
                    _ => "text needs: ttf \"font.ttf\" \"string\" thickness, offset",
                };
                return Err(Diag::new(self.peek().span, what));
            }
            args.push(self.expr()?);
            loop {
                // A comma before a modifier is taken too (POV-Ray's parser reads one token
                // ahead, not two).
                self.eat_punct(',');
                if !self.starts_expr(MODIFIERS) {
                    break;
                }
                args.push(self.expr()?);
            }
            return Ok(args);
        }
        if matches!(shape, ShapeKind::Cubic | ShapeKind::Quartic | ShapeKind::Poly) {
            return self.poly_args(shape, word);
        }
        for i in 0..names.len() {
            if i > 0 {
                self.eat_punct(',');
            }
            if !self.starts_expr(MODIFIERS) {
                return Err(Diag::new(
                    self.peek().span,
                    format!("{word} needs {} arguments ({}), found {i}", names.len(), names.join(", ")),
                ));
            }
            args.push(self.expr()?);
        }
        // disc's hole radius is optional.
        if shape == ShapeKind::Disc {
            let mark = self.is_punct(',');
            if mark {
                self.eat_punct(',');
            }
            if self.starts_expr(MODIFIERS) {
                args.push(self.expr()?);
            } else if mark {
                return Err(Diag::new(self.peek().span, "disc: expected the hole radius after `,`"));
            }
        }
        Ok(args)
    }

    /// `cubic { <20 coefficients> }`, `quartic { <35> }` or `poly { order, <coefficients> }`:
    /// the order (poly only), then every coefficient as one argument. A list has more
    /// components than a vector may, so it is read here; its count is checked here for cubic
    /// and quartic, and when lowering (once the order is known) for poly.
    fn poly_args(&mut self, shape: ShapeKind, word: &str) -> PResult<Vec<crate::pov::ast::Expr>> {
        let mut args = Vec::new();
        if shape == ShapeKind::Poly {
            if !self.starts_expr(MODIFIERS) {
                return Err(Diag::new(self.peek().span, "poly needs its order, then <coefficients>"));
            }
            args.push(self.expr()?);
            self.eat_punct(',');
        }
        let open = self.peek().span;
        if !self.is_punct('<') {
            return Err(Diag::new(
                open,
                format!("{word} needs its coefficients as <c1, c2, ...>, found {}", self.peek().describe()),
            ));
        }
        self.bump();
        // Commas may be left out, as in a vector (`0    1.5,` in POV-Ray's objects/primitiv.pov).
        loop {
            args.push(self.expr()?);
            let comma = self.eat_punct(',');
            if self.is_punct('>') || !(comma || self.starts_expr(&[])) {
                break;
            }
        }
        let close = self.expect_punct('>', "to close the coefficients")?;
        let found = args.len() - usize::from(shape == ShapeKind::Poly);
        let wanted = match shape {
            ShapeKind::Cubic => 20,
            ShapeKind::Quartic => 35,
            _ => found,
        };
        if found != wanted {
            return Err(Diag::new(open.to(close), format!("{word} takes {wanted} coefficients, found {found}")));
        }
        Ok(args)
    }
}
