//! Evaluating expressions, colours and transform modifiers.

use glam::{DMat4, DVec3};

use super::Lowerer;
use crate::desc::{Color, Transform};
use crate::pov::ast::{Builtin, ColorItem, ColorKey, Expr, ExprKind, TransformItem, TransformKind};
use crate::pov::source::{Diag, PResult};
use crate::pov::value::{binary, color_from, negate, truthy, Value};

impl Lowerer<'_> {
    pub(crate) fn eval(&self, e: &Expr) -> PResult<Value> {
        match &e.kind {
            ExprKind::Number(v) => Ok(Value::Float(*v)),
            ExprKind::Vector3(v) => Ok(Value::Vector(v.to_vec())),
            ExprKind::Version => Ok(Value::Float(self.version)),
            ExprKind::Ident(name) => Err(Diag::new(e.span, format!("undefined identifier `{name}`"))),
            ExprKind::Value(v) => Ok((**v).clone()),
            ExprKind::Vector(parts) => {
                let mut out = Vec::with_capacity(parts.len());
                for p in parts {
                    out.push(self.float(p)?);
                }
                Ok(Value::Vector(out))
            }
            ExprKind::Neg(inner) => negate(&self.eval(inner)?, e.span),
            ExprKind::Not(inner) => {
                let v = self.float(inner)?;
                Ok(Value::Float(if truthy(v) { 0.0 } else { 1.0 }))
            }
            ExprKind::Ternary(cond, a, b) => {
                if truthy(self.float(cond)?) {
                    self.eval(a)
                } else {
                    self.eval(b)
                }
            }
            ExprKind::Member(inner, index) => self.member(inner, *index),
            ExprKind::Builtin(b) => Ok(Value::Float(self.builtin(*b))),
            ExprKind::Binary(op, a, b) => binary(*op, &self.eval(a)?, &self.eval(b)?, a.span, b.span),
            ExprKind::Call(name, args) => self.call(name, args, e),
            ExprKind::Color(items) => Ok(Value::Color(self.color_items(Color::BLACK, items)?)),
        }
    }

    /// `v.x` and friends; `index` counts (x, y, z, filter, transmit).
    fn member(&self, inner: &Expr, index: usize) -> PResult<Value> {
        let names = ["x", "y", "z", "t", "transmit", "gray"];
        let comps = match self.eval(inner)? {
            // `.gray`: 0.297 red + 0.589 green + 0.114 blue, as `shading::pigment::gray`.
            Value::Color(c) if index == 5 => {
                return Ok(Value::Float(0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z))
            }
            Value::Vector(c) if index == 5 && c.len() >= 3 => {
                return Ok(Value::Float(0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]))
            }
            Value::Vector(c) => c,
            Value::Color(c) => vec![c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit],
            other => {
                return Err(Diag::new(
                    inner.span,
                    format!("`.{}` needs a vector or color, found {}", names[index.min(5)], other.kind_name()),
                ))
            }
        };
        comps.get(index).map(|v| Value::Float(*v)).ok_or_else(|| {
            Diag::new(
                inner.span,
                format!(
                    "`.{}` needs a vector of at least {} components, found {}",
                    names[index.min(5)],
                    index + 1,
                    comps.len()
                ),
            )
        })
    }

    /// Values POV-Ray's renderer provides (`ParseOptions::clock`; a still image is frame 0 at
    /// clock 0).
    fn builtin(&self, b: Builtin) -> f64 {
        match b {
            Builtin::ImageWidth => f64::from(self.options.image_width),
            Builtin::ImageHeight => f64::from(self.options.image_height),
            Builtin::Clock => self.options.clock.clock,
            Builtin::ClockDelta => self.options.clock.clock_delta,
            Builtin::FrameNumber => f64::from(self.options.clock.frame_number),
            Builtin::InitialClock => self.options.clock.initial_clock,
            Builtin::FinalClock => self.options.clock.final_clock,
            Builtin::InitialFrame => f64::from(self.options.clock.initial_frame),
            Builtin::FinalFrame => f64::from(self.options.clock.final_frame),
            Builtin::ClockOn => f64::from(u8::from(self.options.clock.on)),
        }
    }

    fn call(&self, name: &str, args: &[Expr], e: &Expr) -> PResult<Value> {
        let f = |i: usize| self.float(&args[i]);
        let v = |i: usize| self.vec3(&args[i]);
        let out = match name {
            "sqrt" => {
                let a = f(0)?;
                if a < 0.0 {
                    return Err(Diag::new(args[0].span, "sqrt of a negative number"));
                }
                Value::Float(a.sqrt())
            }
            "sin" => Value::Float(f(0)?.sin()),
            "cos" => Value::Float(f(0)?.cos()),
            "tan" => Value::Float(f(0)?.tan()),
            "asin" => Value::Float(f(0)?.asin()),
            "acos" => Value::Float(f(0)?.acos()),
            "atan2" => Value::Float(f(0)?.atan2(f(1)?)),
            "abs" => Value::Float(f(0)?.abs()),
            "exp" => Value::Float(f(0)?.exp()),
            // POV-Ray's `log` is base 10; `ln` is the natural logarithm.
            "log" => Value::Float(f(0)?.log10()),
            "ln" => Value::Float(f(0)?.ln()),
            "atan" => Value::Float(f(0)?.atan()),
            "sinh" => Value::Float(f(0)?.sinh()),
            "cosh" => Value::Float(f(0)?.cosh()),
            "tanh" => Value::Float(f(0)?.tanh()),
            "asinh" => Value::Float(f(0)?.asinh()),
            "acosh" => Value::Float(f(0)?.acosh()),
            "atanh" => Value::Float(f(0)?.atanh()),
            "floor" => Value::Float(f(0)?.floor()),
            "ceil" => Value::Float(f(0)?.ceil()),
            "int" => Value::Float(f(0)?.trunc()),
            "div" => {
                let d = f(1)?;
                if d == 0.0 {
                    return Err(Diag::new(args[1].span, "division by zero"));
                }
                Value::Float((f(0)? / d).trunc())
            }
            "mod" => {
                let d = f(1)?;
                if d == 0.0 {
                    return Err(Diag::new(args[1].span, "division by zero"));
                }
                Value::Float(f(0)? % d)
            }
            "radians" => Value::Float(f(0)?.to_radians()),
            "degrees" => Value::Float(f(0)?.to_degrees()),
            "pow" => Value::Float(f(0)?.powf(f(1)?)),
            "min" | "max" => {
                let mut acc = f(0)?;
                for i in 1..args.len() {
                    let x = f(i)?;
                    acc = if name == "min" { acc.min(x) } else { acc.max(x) };
                }
                Value::Float(acc)
            }
            // select(A, B, C[, D]): B where A < 0, C where A = 0 (or A ≥ 0 with three), D where A > 0.
            "select" => {
                let a = f(0)?;
                let pick = match args.len() {
                    3 if a < 0.0 => 1,
                    3 => 2,
                    _ if a < 0.0 => 1,
                    _ if a == 0.0 => 2,
                    _ => 3,
                };
                self.eval(&args[pick])?
            }
            "vlength" => Value::Float(v(0)?.length()),
            "vdot" => Value::Float(v(0)?.dot(v(1)?)),
            "vcross" => {
                let c = v(0)?.cross(v(1)?);
                Value::Vector(c.to_array().to_vec())
            }
            "vnormalize" => {
                let a = v(0)?;
                if a.length() == 0.0 {
                    return Err(Diag::new(args[0].span, "vnormalize of a zero-length vector"));
                }
                Value::Vector(a.normalize().to_array().to_vec())
            }
            _ => match self.other_function(name, args, e) {
                Some(result) => result?,
                None => return Err(Diag::new(e.span, format!("unknown function `{name}`"))),
            },
        };
        let finite = match &out {
            Value::Float(x) => x.is_finite(),
            Value::Vector(c) => c.iter().all(|x| x.is_finite()),
            _ => true,
        };
        if !finite {
            return Err(Diag::new(e.span, format!("`{name}` gives no finite result here")));
        }
        Ok(out)
    }

    pub(crate) fn float(&self, e: &Expr) -> PResult<f64> {
        self.eval(e)?.as_float(e.span)
    }

    pub(crate) fn vec3(&self, e: &Expr) -> PResult<DVec3> {
        self.eval(e)?.as_vec3(e.span)
    }

    /// A colour's keyword items applied in order to `start` (black for a colour written alone;
    /// a pigment's colour when `filter .7` follows it, as in `pigment { White filter .7 }`).
    pub(super) fn color_items(&self, start: Color, items: &[ColorItem]) -> PResult<Color> {
        let mut c = start;
        for item in items {
            let v = self.eval(&item.value)?;
            let span = item.value.span;
            // Components an `rgb`-style keyword reads: a float promotes to all of them.
            let comps = |n: usize| -> PResult<Vec<f64>> {
                match &v {
                    Value::Float(f) => Ok(vec![*f; n]),
                    Value::Vector(c) => Ok((0..n).map(|i| c.get(i).copied().unwrap_or(0.0)).collect()),
                    Value::Color(c) => Ok([c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit][..n].to_vec()),
                    other => Err(Diag::new(span, format!("expected a color, found {}", other.kind_name()))),
                }
            };
            match item.key {
                ColorKey::Base => c = v.as_color(span)?,
                ColorKey::Rgb => c.rgb = color_from(&comps(3)?).rgb,
                ColorKey::Rgbf => c = Color { transmit: c.transmit, ..color_from(&comps(4)?) },
                ColorKey::Rgbt => {
                    let k = comps(4)?;
                    c = Color { rgb: DVec3::new(k[0], k[1], k[2]), filter: c.filter, transmit: k[3] };
                }
                ColorKey::Rgbft => c = color_from(&comps(5)?),
                ColorKey::Red => c.rgb.x = v.as_float(span)?,
                ColorKey::Green => c.rgb.y = v.as_float(span)?,
                ColorKey::Blue => c.rgb.z = v.as_float(span)?,
                ColorKey::Filter => c.filter = v.as_float(span)?,
                ColorKey::Transmit => c.transmit = v.as_float(span)?,
            }
        }
        Ok(c)
    }

    pub(super) fn color(&self, e: &Expr) -> PResult<Color> {
        self.eval(e)?.as_color(e.span)
    }

    /// `rotate` (degrees; about x, then y, then z), `scale` or `translate`.
    pub(crate) fn transform(&mut self, t: &TransformItem) -> PResult<Transform> {
        if t.kind == TransformKind::Transform {
            return match self.eval(&t.value)? {
                Value::Transform(tr) => Ok(tr),
                other => Err(Diag::new(t.span, format!("expected a transform, found {}", other.kind_name()))),
            };
        }
        let v = self.vec3(&t.value)?;
        let matrix = match t.kind {
            // glam's rotation matrices turn the same way as POV-Ray's: `rotate y*90` takes +x
            // to -z (checked with a POV-Ray 3.7 render; see tests/suite/pov_parse.rs).
            TransformKind::Rotate => rotation(v),
            TransformKind::Scale => {
                // POV-Ray's behaviour: keep each axis scaled by 0 unscaled, and warn, once for
                // the whole `scale` (not once per axis: `scale 0` is one mistake).
                let mut s = v;
                let mut zero_axes = Vec::new();
                for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
                    if s[i] == 0.0 {
                        s[i] = 1.0;
                        zero_axes.push(axis);
                    }
                }
                if !zero_axes.is_empty() {
                    let axes = zero_axes.join(", ");
                    self.warn(Diag::new(t.span, format!("Illegal Value: Scale by 0.0 ({axes}). Changed to 1.0.")));
                }
                DMat4::from_scale(s)
            }
            TransformKind::Translate => DMat4::from_translation(v),
            TransformKind::Transform => unreachable!("returned above"),
        };
        Ok(Transform { matrix, inverse: matrix.inverse() })
    }
}

/// `rotate v`: degrees about x, then y, then z.
pub(super) fn rotation(v: DVec3) -> DMat4 {
    rotation_x(v.x).then(rotation_y(v.y)).then(rotation_z(v.z)).into()
}

/// Sine and cosine of an angle in degrees, exact for multiples of 90° (so `rotate y*90` maps a
/// box onto exactly the corners written rotated by hand, with no 6e-17 residue).
fn sin_cos_degrees(deg: f64) -> (f64, f64) {
    let quarter = deg / 90.0;
    if quarter.fract() == 0.0 && quarter.abs() < 1e15 {
        match (quarter as i64).rem_euclid(4) {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        }
    } else {
        deg.to_radians().sin_cos()
    }
}

/// Rotation matrices with glam's orientation (the same as POV-Ray's: `rotate y*90` takes +x to
/// -z, checked with a POV-Ray 3.7 render; see tests/suite/pov_parse.rs), built from exact sin/cos.
fn rotation_x(deg: f64) -> Rotation {
    let (s, c) = sin_cos_degrees(deg);
    Rotation(DMat4::from_cols_array(&[1.0, 0.0, 0.0, 0.0, 0.0, c, s, 0.0, 0.0, -s, c, 0.0, 0.0, 0.0, 0.0, 1.0]))
}

fn rotation_y(deg: f64) -> Rotation {
    let (s, c) = sin_cos_degrees(deg);
    Rotation(DMat4::from_cols_array(&[c, 0.0, -s, 0.0, 0.0, 1.0, 0.0, 0.0, s, 0.0, c, 0.0, 0.0, 0.0, 0.0, 1.0]))
}

fn rotation_z(deg: f64) -> Rotation {
    let (s, c) = sin_cos_degrees(deg);
    Rotation(DMat4::from_cols_array(&[c, s, 0.0, 0.0, -s, c, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]))
}

/// A rotation about one axis, composed in POV-Ray's order (x, then y, then z).
struct Rotation(DMat4);

impl Rotation {
    fn then(self, next: Rotation) -> Rotation {
        Rotation(next.0 * self.0)
    }
}

impl From<Rotation> for DMat4 {
    fn from(r: Rotation) -> DMat4 {
        r.0
    }
}
