//! Values of evaluated expressions and declarations, with POV-Ray's promotion rules: a float
//! promotes to every component of a vector or colour, a short vector pads with zeros, and
//! arithmetic with a colour works on all five components (red, green, blue, filter, transmit).

use std::ops::Range;
use std::rc::Rc;
use std::sync::Arc;

use glam::DVec3;

use crate::desc::{
    CameraDesc, Color, ColorMapEntry, CsgOp, FinishDesc, InteriorDesc, LightDesc, NormalDesc, ObjectDesc, PigmentDesc,
    Placement, ShapeDesc, SourceRef, TextureDesc, Transform,
};
use crate::pov::ast::BinOp;
use crate::pov::source::{Diag, PResult, Span};

#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Float(f64),
    /// 2 to 5 components.
    Vector(Vec<f64>),
    Color(Color),
    Pigment(Box<PigmentDesc>),
    Normal(Box<NormalDesc>),
    Finish(FinishDesc),
    Texture(Box<TextureDesc>),
    Interior(InteriorDesc),
    /// A declared `material`: what it carries to an object.
    Material(Box<MaterialValue>),
    /// A declared `color_map`, already in the sorted form the renderer reads.
    ColorMap(Vec<ColorMapEntry>),
    /// A declared `slope_map`, sorted by value.
    SlopeMap(Vec<crate::desc::SlopeEntry>),
    Object(Box<Group>),
    /// A declared `camera`, before its `look_at` and transforms are resolved.
    Camera(Box<CameraState>),
    /// A declared `light_source`, with its `looks_like` objects lowered where the light is
    /// (a `light_source { L .. }` or `object { L .. }` moves them with the light).
    Light(Box<LightDesc>, Rc<[Part]>),
    /// A declared `sky_sphere`, `fog` or `rainbow`: its items as read (names resolved), which
    /// a block naming it starts from.
    Atmosphere(Rc<crate::pov::ast::Atmosphere>),
    Str(Rc<str>),
    Array(Rc<Array>),
    Macro(Rc<Macro>),
    /// `function { ... }`: a user-defined float function, parsed into its tree.
    Function(Rc<crate::function::Function>),
    /// `transform { ... }`, composed.
    Transform(Transform),
    /// `spline { ... }` (also `function { spline { ... } }`): evaluated as `S(t)` where it
    /// is read.
    Spline(Rc<crate::function::spline::Spline>),
    /// `function { transform { ... } }`: `F(x, y, z)` is the point moved by the transform.
    TransformFunction(Transform),
    /// A declaration whose syntax was read but which needs a feature strahl does not model
    /// yet: using it is the error, not declaring it (include files declare far more than a
    /// scene uses).
    Unmodelled(Rc<Unmodelled>),
}

/// A `material { }` lowered: the texture and interior it carries (POV-Ray 3.4.5.5.3), each
/// only if written (a material without a texture leaves the object's own).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MaterialValue {
    pub texture: Option<TextureDesc>,
    pub interior: Option<InteriorDesc>,
}

/// A camera as its items leave it, before `look_at`, `angle` and the transforms are resolved:
/// what `#declare C = camera {...}` stores, so `camera { C ... }` continues from it as POV-Ray
/// continues from a copy of the declared camera.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CameraState {
    pub(crate) cam: CameraDesc,
    pub(crate) angle: Option<f64>,
    pub(crate) look_at: Option<(DVec3, Span)>,
    pub(crate) transforms: Vec<Transform>,
    /// A `mesh_camera`'s meshes (the projection is then `Projection::Mesh`).
    pub(crate) mesh: Option<std::sync::Arc<crate::desc::MeshCameraDesc>>,
    /// `normal { .. }`: tilts every eye ray (`render::RayGen`).
    pub(crate) normal: Option<std::sync::Arc<crate::desc::NormalDesc>>,
}

/// `array[d1][d2]...`: up to five dimensions, elements unset until declared.
#[derive(Clone, Debug, PartialEq)]
pub struct Array {
    pub dims: Vec<usize>,
    pub items: Vec<Option<Value>>,
}

/// Most dimensions an array may have, as in POV-Ray 3.7.
pub const MAX_ARRAY_DIMENSIONS: usize = 5;

/// Most elements in one array: 16 M unset elements are 0.5 GiB, beyond any real scene.
pub const MAX_ARRAY_ELEMENTS: usize = 16 << 20;

impl Array {
    /// The flat index of `index`, or why it is out of range.
    pub fn offset(&self, index: &[usize]) -> Result<usize, String> {
        if index.len() != self.dims.len() {
            return Err(format!("array has {} dimension(s), indexed with {}", self.dims.len(), index.len()));
        }
        let mut at = 0;
        for (i, (&k, &n)) in index.iter().zip(&self.dims).enumerate() {
            if k >= n {
                return Err(format!("array index {k} out of range 0..{} in dimension {}", n.saturating_sub(1), i + 1));
            }
            at = at * n + k;
        }
        Ok(at)
    }
}

/// `#macro Name(P1, optional P2) ... #end`: the body stays tokens until a call expands it.
#[derive(Debug, PartialEq)]
pub struct Macro {
    pub name: Rc<str>,
    pub params: Vec<(Rc<str>, bool)>,
    /// The text of the file the macro is written in, and the body's byte range in it (read
    /// again at each call).
    pub source: crate::pov::parser::Text,
    pub body: Range<usize>,
    /// The macro's name in its `#macro` directive.
    pub defined: Span,
}

#[derive(Debug, PartialEq)]
pub struct Unmodelled {
    /// Why strahl cannot model it, as the parser said it ("`granite` is not supported ...").
    pub why: String,
    /// Where the unmodelled feature is written.
    pub at: Span,
}

/// POV-Ray's epsilon for `=`, `!=` and truth (`#if (1e-11)` is false in POV-Ray 3.7).
pub const EPSILON: f64 = 1e-10;

/// One lowered object with what a surrounding `union` needs to know about it.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    pub desc: ObjectDesc,
    /// A pigment, normal, finish or texture was given: a union's texture does not replace it
    /// (POV-Ray: a child with only a `finish` keeps the default pigment, checked by rendering).
    pub textured: bool,
    /// An `interior` was given.
    pub has_interior: bool,
    /// A CSG node's children, kept as parts while lowering so that a texture given later (on
    /// `object { Declared pigment { .. } }`) still reaches the leaves without one. `desc.shape`
    /// is then `ShapeDesc::Csg` with no children until `into_desc` moves them in.
    pub children: Vec<Part>,
}

impl Part {
    /// A plain shape without texture or interior.
    pub fn leaf(desc: ObjectDesc) -> Part {
        Part { desc, textured: false, has_interior: false, children: Vec::new() }
    }

    /// A CSG node over `children`.
    pub fn node(op: CsgOp, children: Vec<Part>, source: SourceRef) -> Part {
        let desc = ObjectDesc {
            shape: ShapeDesc::Csg { op, children: Vec::new() },
            transform: Placement::Identity,
            texture: Arc::default(),
            interior_texture: None,
            interior: InteriorDesc::default(),
            no_shadow: false,
            inverse: false,
            hollow: false,
            light_group: None,
            bounded_by: None,
            source,
        };
        Part { desc, textured: false, has_interior: false, children }
    }

    pub fn is_node(&self) -> bool {
        matches!(self.desc.shape, ShapeDesc::Csg { .. })
    }

    /// Calls `f` on every shape below this part (the part itself when it is one).
    pub fn for_each_leaf(&mut self, f: &mut impl FnMut(&mut Part)) {
        if self.is_node() {
            for c in &mut self.children {
                c.for_each_leaf(f);
            }
        } else {
            f(self)
        }
    }

    /// Shapes below this part.
    pub fn leaf_count(&self) -> usize {
        if self.is_node() {
            self.children.iter().map(Part::leaf_count).sum()
        } else {
            1
        }
    }

    /// The finished object: leaves without a texture get `default` (the one in effect where
    /// the object is placed), and a node's children move into its shape.
    pub fn into_desc(self, default: &Arc<TextureDesc>) -> ObjectDesc {
        let mut desc = self.desc;
        if let ShapeDesc::Csg { children, .. } = &mut desc.shape {
            *children = self.children.into_iter().map(|c| c.into_desc(default)).collect();
        } else if !self.textured {
            desc.texture = default.clone();
        }
        desc
    }
}

/// What an object statement lowers to: one shape (or CSG node), or the flattened children of a
/// union.
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    pub parts: Vec<Part>,
    /// A `union` (modifiers apply to each child) rather than a single object.
    pub csg: bool,
    /// `light_source`s written inside (as in a lamp made of a union): they move with the
    /// object's transforms and light the scene wherever it is placed.
    pub lights: Vec<LightDesc>,
}

impl Value {
    /// The kind of value, for "expected a float, found a pigment".
    pub fn kind_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "a float",
            Value::Vector(_) => "a vector",
            Value::Color(_) => "a color",
            Value::Pigment(_) => "a pigment",
            Value::Normal(_) => "a normal",
            Value::Finish(_) => "a finish",
            Value::Texture(_) => "a texture",
            Value::Interior(_) => "an interior",
            Value::Material(_) => "a material",
            Value::ColorMap(_) => "a color_map",
            Value::SlopeMap(_) => "a slope_map",
            Value::Object(_) => "an object",
            Value::Camera(_) => "a camera",
            Value::Light(..) => "a light_source",
            Value::Atmosphere(a) => match a.kind {
                crate::pov::ast::AtmosphereKind::SkySphere => "a sky_sphere",
                crate::pov::ast::AtmosphereKind::Fog => "a fog",
                crate::pov::ast::AtmosphereKind::Rainbow => "a rainbow",
            },
            Value::Str(_) => "a string",
            Value::Array(_) => "an array",
            Value::Macro(_) => "a macro",
            Value::Function(_) => "a function",
            Value::Transform(_) => "a transform",
            Value::Spline(_) => "a spline",
            Value::TransformFunction(_) => "a transform function",
            Value::Unmodelled(_) => "a declaration strahl does not model yet",
        }
    }

    /// "expected a float, found a pigment"; using an unmodelled declaration says why it is one.
    pub fn wrong_kind(&self, span: Span, expected: &str) -> Diag {
        match self {
            Value::Unmodelled(u) => u.used_at(span),
            other => Diag::new(span, format!("expected {expected}, found {}", other.kind_name())),
        }
    }

    pub fn as_float(&self, span: Span) -> PResult<f64> {
        match self {
            Value::Float(v) => Ok(*v),

            other => Err(other.wrong_kind(span, "a float")),
        }
    }

    /// A 3D vector: floats promote to all three components, 2D vectors get z = 0. Four and
    /// five components are an error, as in POV-Ray 3.7 ("Vector expected but color expression
    /// found" for `sphere { <1,2,3,4>, 1 }`, checked with povray 3.7.0.10).
    pub fn as_vec3(&self, span: Span) -> PResult<DVec3> {
        match self {
            Value::Float(v) => Ok(DVec3::splat(*v)),
            Value::Vector(c) if c.len() <= 3 => {
                Ok(DVec3::new(c[0], c.get(1).copied().unwrap_or(0.0), c.get(2).copied().unwrap_or(0.0)))
            }
            Value::Vector(c) => Err(Diag::new(
                span,
                format!(
                    "expected a 3-component vector, found {} components (POV-Ray 3.7 rejects \
                     this too; use `<V.x, V.y, V.z>`)",
                    c.len()
                ),
            )),
            other => Err(other.wrong_kind(span, "a vector")),
        }
    }

    /// A 4-D vector (julia_fractal's parameter and slice): floats promote to all four
    /// components, shorter vectors are padded with zeros.
    pub fn as_vec4(&self, span: Span) -> PResult<glam::DVec4> {
        match self {
            Value::Float(_) | Value::Vector(_) if self.width().is_some_and(|w| w <= 4) => {
                let c = self.components(4);
                Ok(glam::DVec4::new(c[0], c[1], c[2], c[3]))
            }
            Value::Vector(c) => {
                Err(Diag::new(span, format!("expected a 4-component vector, found {} components", c.len())))
            }
            other => Err(other.wrong_kind(span, "a 4-D vector")),
        }
    }

    /// A colour: a float sets all five components, a vector sets r, g, b[, filter[, transmit]].
    pub fn as_color(&self, span: Span) -> PResult<Color> {
        match self {
            Value::Color(c) => Ok(*c),
            Value::Float(_) | Value::Vector(_) => Ok(color_from(&self.components(5))),
            other => Err(other.wrong_kind(span, "a color")),
        }
    }

    /// The numeric components padded (vectors) or promoted (floats) to `n`.
    fn components(&self, n: usize) -> Vec<f64> {
        match self {
            Value::Float(v) => vec![*v; n],
            Value::Vector(c) => (0..n).map(|i| c.get(i).copied().unwrap_or(0.0)).collect(),
            Value::Color(c) => vec![c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit],
            _ => Vec::new(),
        }
    }

    fn width(&self) -> Option<usize> {
        match self {
            Value::Float(_) => Some(1),
            Value::Vector(c) => Some(c.len()),
            Value::Color(_) => Some(5),
            _ => None,
        }
    }
}

/// How an error about using an unmodelled declaration begins.
const UNUSABLE: &str = "this declaration cannot be used: ";

impl Unmodelled {
    /// The error for using it at `span` (itself unmodelled: a declaration that uses this one
    /// is kept as unmodelled in turn).
    pub fn used_at(&self, span: Span) -> Diag {
        Diag::unmodelled(span, format!("{UNUSABLE}{}", self.why)).with_note(self.at, "declared with it here")
    }

    /// The unmodelled value a declaration becomes when reading it failed with `e`: a use of
    /// another unmodelled declaration passes that one's reason and place on.
    pub fn from_error(e: Diag) -> Unmodelled {
        match (e.message.strip_prefix(UNUSABLE), e.notes.first()) {
            (Some(why), Some(&(at, _))) => Unmodelled { why: why.to_string(), at },
            _ => Unmodelled { why: e.message, at: e.span },
        }
    }
}

pub fn color_from(c: &[f64]) -> Color {
    let at = |i: usize| c.get(i).copied().unwrap_or(0.0);
    Color { rgb: DVec3::new(at(0), at(1), at(2)), filter: at(3), transmit: at(4) }
}

fn finite(v: f64, span: Span) -> PResult<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Diag::new(span, "number overflows to infinity"))
    }
}

/// `a op b` for the comparison and logic operators, giving 1 or 0: floats, or two strings
/// compared by their characters (POV-Ray 3.7's own include files test `#if (c_file != "")`).
fn compare(op: BinOp, a: &Value, b: &Value, a_span: Span, b_span: Span) -> PResult<Value> {
    if let (Value::Str(x), Value::Str(y)) = (a, b) {
        let truth = match op {
            BinOp::Lt => x < y,
            BinOp::Le => x <= y,
            BinOp::Gt => x > y,
            BinOp::Ge => x >= y,
            BinOp::Eq => x == y,
            BinOp::Ne => x != y,
            _ => return Err(Diag::new(a_span.to(b_span), "`&` and `|` need floats, found two strings")),
        };
        return Ok(Value::Float(if truth { 1.0 } else { 0.0 }));
    }
    let x = a.as_float(a_span)?;
    let y = b.as_float(b_span)?;
    let truth = match op {
        BinOp::Lt => x < y,
        BinOp::Le => x <= y,
        BinOp::Gt => x > y,
        BinOp::Ge => x >= y,
        BinOp::Eq => (x - y).abs() < EPSILON,
        BinOp::Ne => (x - y).abs() >= EPSILON,
        BinOp::And => truthy(x) && truthy(y),
        _ => truthy(x) || truthy(y),
    };
    Ok(Value::Float(if truth { 1.0 } else { 0.0 }))
}

/// POV-Ray's truth: anything farther than epsilon from zero.
pub fn truthy(v: f64) -> bool {
    v.abs() > EPSILON
}

/// `a op b` with promotion; `span` covers the whole operation.
pub fn binary(op: BinOp, a: &Value, b: &Value, a_span: Span, b_span: Span) -> PResult<Value> {
    if !matches!(op, BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Div) {
        return compare(op, a, b, a_span, b_span);
    }
    let span = a_span.to(b_span);
    let (wa, wb) = match (a.width(), b.width()) {
        (Some(wa), Some(wb)) => (wa, wb),
        (None, _) if matches!(a, Value::Unmodelled(_)) => return Err(a.wrong_kind(a_span, "")),
        (_, None) if matches!(b, Value::Unmodelled(_)) => return Err(b.wrong_kind(b_span, "")),
        (None, _) => return Err(Diag::new(a_span, format!("cannot do arithmetic on {}", a.kind_name()))),
        (_, None) => return Err(Diag::new(b_span, format!("cannot do arithmetic on {}", b.kind_name()))),
    };
    let n = wa.max(wb);
    let (ca, cb) = (a.components(n), b.components(n));
    let mut out = Vec::with_capacity(n);
    for (x, y) in ca.iter().zip(&cb) {
        let v = match op {
            BinOp::Sub => x - y,
            BinOp::Mul => x * y,
            BinOp::Div => {
                if *y == 0.0 {
                    return Err(Diag::new(b_span, "division by zero"));
                }
                x / y
            }
            // `Add`; comparisons and logic returned through `compare` above.
            _ => x + y,
        };
        out.push(finite(v, span)?);
    }
    Ok(if matches!(a, Value::Color(_)) || matches!(b, Value::Color(_)) {
        Value::Color(color_from(&out))
    } else if n == 1 {
        Value::Float(out[0])
    } else {
        Value::Vector(out)
    })
}

pub fn negate(v: &Value, span: Span) -> PResult<Value> {
    binary(BinOp::Mul, v, &Value::Float(-1.0), span, span)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s() -> Span {
        Span::default()
    }

    #[test]
    fn strings_compare_by_their_characters() {
        let st = |t: &str| Value::Str(Rc::from(t));
        let cmp = |op, a: &str, b: &str| binary(op, &st(a), &st(b), s(), s()).unwrap();
        assert_eq!(cmp(BinOp::Ne, "file", ""), Value::Float(1.0));
        assert_eq!(cmp(BinOp::Eq, "ab", "ab"), Value::Float(1.0));
        assert_eq!(cmp(BinOp::Lt, "ab", "b"), Value::Float(1.0));
        assert!(binary(BinOp::Eq, &st("a"), &Value::Float(1.0), s(), s()).is_err());
        assert!(binary(BinOp::And, &st("a"), &st("b"), s(), s()).is_err());
    }

    #[test]
    fn floats_promote_to_vectors_and_colors() {
        let v = binary(BinOp::Mul, &Value::Float(2.0), &Value::Vector(vec![0.0, 1.0, 0.0]), s(), s());
        assert_eq!(v.unwrap(), Value::Vector(vec![0.0, 2.0, 0.0]));
        let white = Value::Color(Color::WHITE);
        let gray = binary(BinOp::Mul, &white, &Value::Float(0.05), s(), s()).unwrap();
        assert_eq!(gray, Value::Color(Color::rgb(0.05, 0.05, 0.05)));
    }

    #[test]
    fn vectors_multiply_componentwise_and_pad() {
        let v = binary(BinOp::Mul, &Value::Vector(vec![1.0, 2.0, 3.0]), &Value::Vector(vec![2.0, 2.0]), s(), s());
        assert_eq!(v.unwrap(), Value::Vector(vec![2.0, 4.0, 0.0]));
    }

    #[test]
    fn overflow_and_division_by_zero_are_errors() {
        let e = binary(BinOp::Mul, &Value::Float(1e300), &Value::Float(1e300), s(), s()).unwrap_err();
        assert_eq!(e.message, "number overflows to infinity");
        let e = binary(BinOp::Div, &Value::Float(1.0), &Value::Vector(vec![1.0, 0.0]), s(), s()).unwrap_err();
        assert_eq!(e.message, "division by zero");
    }

    #[test]
    fn two_d_vectors_get_z_zero() {
        assert_eq!(Value::Vector(vec![1.0, 2.0]).as_vec3(s()).unwrap(), DVec3::new(1.0, 2.0, 0.0));
    }
}
