//! POV-Ray 3.7's string, array, random-number and vector-rotation functions (the float
//! functions are in `eval`).

use std::cell::RefCell;

use glam::{DMat4, DVec3};

use super::Lowerer;
use crate::pov::ast::Expr;
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

/// Longest string a scene may build (`concat` in a loop): 16 MiB.
pub const MAX_STRING_LEN: usize = 16 << 20;

/// Most random streams (`seed(...)` calls) a scene may open.
pub const MAX_RANDOM_STREAMS: usize = 1 << 20;

/// The random streams `seed()` opened, each the 32-bit state of its generator, so the numbers
/// depend only on the scene, never on the run or the thread count.
///
/// The generator is POV-Ray 3.7's, measured from its output (`#debug str(rand(S), 0, 17)`):
/// a linear congruential generator `state = state · 1812433253 + 12345 (mod 2³²)` whose value is
/// the new state divided by 2³² − 1; `seed(v)` starts it at `v` truncated to a 32-bit integer
/// (out of range: −2³¹, as C's conversion gives). So `seed(0)` yields 2.87e-6, 0.46656, 0.24907,
/// ... as POV-Ray does, and scenes that scatter objects with `rand` place them where POV-Ray does.
#[derive(Debug, Default)]
pub struct RandomStreams {
    streams: RefCell<Vec<u32>>,
}

const LCG_MULTIPLIER: u32 = 1_812_433_253;
const LCG_INCREMENT: u32 = 12_345;

/// The state `seed(v)` starts a stream at.
fn seed_state(v: f64) -> u32 {
    let t = v.trunc();
    if (-2_147_483_648.0..2_147_483_648.0).contains(&t) {
        t as i32 as u32
    } else {
        i32::MIN as u32
    }
}

/// Advances `state` and returns the next number, in [0, 1].
fn next_rand(state: &mut u32) -> f64 {
    *state = state.wrapping_mul(LCG_MULTIPLIER).wrapping_add(LCG_INCREMENT);
    *state as f64 / u32::MAX as f64
}

impl Lowerer<'_> {
    /// The functions of this module; `None` for a name that is not one of them.
    pub(super) fn other_function(&self, name: &str, args: &[Expr], e: &Expr) -> Option<PResult<Value>> {
        let f = |i: usize| self.float(&args[i]);
        let s = |i: usize| self.string(&args[i]);
        let v = |i: usize| self.vec3(&args[i]);
        let text = |t: String| -> PResult<Value> {
            if t.len() > MAX_STRING_LEN {
                return Err(Diag::new(e.span, format!("string longer than {MAX_STRING_LEN} bytes")));
            }
            Ok(Value::Str(t.into()))
        };
        let result = match name {
            "concat" => (|| {
                let mut out = String::new();
                for i in 0..args.len() {
                    out.push_str(&s(i)?);
                    if out.len() > MAX_STRING_LEN {
                        break;
                    }
                }
                text(out)
            })(),
            "str" => (|| text(format_float(f(0)?, f(1)?, f(2)?)))(),
            "vstr" => (|| {
                let n = f(0)?;
                let comps = self.components(&args[1])?;
                if !(1.0..=5.0).contains(&n) {
                    return Err(Diag::new(args[0].span, "vstr takes 1 to 5 components"));
                }
                let sep = s(2)?;
                let (w, p) = (f(3)?, f(4)?);
                let parts: Vec<String> =
                    (0..n as usize).map(|i| format_float(comps.get(i).copied().unwrap_or(0.0), w, p)).collect();
                text(parts.join(&sep))
            })(),
            "chr" => (|| {
                let c = f(0)?;
                match char::from_u32(c as u32).filter(|_| c >= 0.0 && c.fract() == 0.0) {
                    Some(ch) => text(ch.to_string()),
                    None => Err(Diag::new(args[0].span, format!("chr({c}) is not a character"))),
                }
            })(),
            "substr" => (|| {
                let t: Vec<char> = s(0)?.chars().collect();
                let (start, len) = (f(1)?, f(2)?);
                // POV-Ray counts from 1 and refuses a range past the end.
                if start < 1.0 || len < 0.0 || start - 1.0 + len > t.len() as f64 {
                    return Err(Diag::new(
                        e.span,
                        format!("substr({start}, {len}) is outside the string of length {}", t.len()),
                    ));
                }
                let from = start as usize - 1;
                text(t[from..from + len as usize].iter().collect())
            })(),
            "strupr" => (|| text(s(0)?.to_uppercase()))(),
            "strlwr" => (|| text(s(0)?.to_lowercase()))(),
            "strlen" => (|| Ok(Value::Float(s(0)?.chars().count() as f64)))(),
            "strcmp" => (|| {
                let (a, b) = (s(0)?, s(1)?);
                Ok(Value::Float(match a.cmp(&b) {
                    std::cmp::Ordering::Less => -1.0,
                    std::cmp::Ordering::Equal => 0.0,
                    std::cmp::Ordering::Greater => 1.0,
                }))
            })(),
            "val" => (|| Ok(Value::Float(leading_number(&s(0)?))))(),
            "asc" => (|| Ok(Value::Float(s(0)?.chars().next().map_or(0.0, |c| f64::from(u32::from(c))))))(),
            "file_exists" => (|| {
                let name = s(0)?;
                Ok(Value::Float(if self.files.file_exists(&name) { 1.0 } else { 0.0 }))
            })(),
            "dimensions" | "dimension_size" => (|| {
                let Value::Array(a) = self.eval(&args[0])? else {
                    return Err(Diag::new(args[0].span, format!("`{name}` needs an array")));
                };
                if name == "dimensions" {
                    return Ok(Value::Float(a.dims.len() as f64));
                }
                let d = f(1)?;
                if d < 1.0 || d as usize > a.dims.len() {
                    return Err(Diag::new(args[1].span, format!("the array has {} dimension(s)", a.dims.len())));
                }
                Ok(Value::Float(a.dims[d as usize - 1] as f64))
            })(),
            "seed" => (|| {
                let mut streams = self.random.streams.borrow_mut();
                if streams.len() >= MAX_RANDOM_STREAMS {
                    return Err(Diag::new(e.span, format!("more than {MAX_RANDOM_STREAMS} random streams")));
                }
                streams.push(seed_state(f(0)?));
                Ok(Value::Float((streams.len() - 1) as f64))
            })(),
            "rand" => (|| {
                let id = f(0)?;
                let mut streams = self.random.streams.borrow_mut();
                let Some(stream) = streams.get_mut(id as usize).filter(|_| id >= 0.0 && id.fract() == 0.0) else {
                    return Err(Diag::new(args[0].span, "rand() needs a stream made by seed()"));
                };
                Ok(Value::Float(next_rand(stream)))
            })(),
            "bitwise_and" | "bitwise_or" | "bitwise_xor" => (|| {
                let mut acc = f(0)? as i64;
                for i in 1..args.len() {
                    let x = f(i)? as i64;
                    acc = match name {
                        "bitwise_and" => acc & x,
                        "bitwise_or" => acc | x,
                        _ => acc ^ x,
                    };
                }
                Ok(Value::Float(acc as f64))
            })(),
            // A fixed time: a scene must render the same bytes on every run.
            "now" => Ok(Value::Float(0.0)),
            "datetime" => (|| text(format!("{}", f(0)?)))(),
            "vrotate" => (|| {
                let r = v(1)?;
                let m = super::eval::rotation(r);
                Ok(vector(m.transform_vector3(v(0)?)))
            })(),
            "vaxis_rotate" => (|| {
                let axis = v(1)?;
                if axis.length() == 0.0 {
                    return Err(Diag::new(args[1].span, "vaxis_rotate about a zero-length axis"));
                }
                // POV-Ray turns the same way as its `rotate`: left-handed, as glam's matrices
                // are used here for `rotate` (see `eval::rotation`).
                let m = DMat4::from_axis_angle(axis.normalize(), f(2)?.to_radians());
                Ok(vector(m.transform_vector3(v(0)?)))
            })(),
            // `vturbulence(Lambda, Omega, Octaves, A)`: the turbulence displacement at A, as
            // the `turbulence` warp computes it (one shared noise, `shading::noise`).
            "vturbulence" => (|| {
                let octaves = f(2)?;
                if !(0.0..=64.0).contains(&octaves) {
                    return Err(Diag::new(args[2].span, "vturbulence takes 0 to 64 octaves"));
                }
                let t = crate::noise::TurbulenceF32 {
                    amount: glam::Vec3::ONE,
                    octaves: octaves as u32,
                    omega: f(1)? as f32,
                    lambda: f(0)? as f32,
                };
                let d = crate::noise::turbulence(v(3)?.as_vec3(), &t, None);
                Ok(vector(d.as_dvec3()))
            })(),
            _ => return None,
        };
        Some(result)
    }

    /// A string argument.
    pub(super) fn string(&self, e: &Expr) -> PResult<String> {
        match self.eval(e)? {
            Value::Str(s) => Ok(s.to_string()),
            other => Err(other.wrong_kind(e.span, "a string")),
        }
    }

    /// The components of a float, vector or colour.
    fn components(&self, e: &Expr) -> PResult<Vec<f64>> {
        Ok(match self.eval(e)? {
            Value::Float(x) => vec![x],
            Value::Vector(c) => c,
            Value::Color(c) => vec![c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit],
            other => return Err(other.wrong_kind(e.span, "a vector")),
        })
    }
}

fn vector(v: DVec3) -> Value {
    Value::Vector(v.to_array().to_vec())
}

/// `str(value, width, precision)` as POV-Ray writes it: at least `width` characters (padded
/// with zeros when `width` is negative), `precision` decimals (6 when negative).
pub fn format_float(v: f64, width: f64, precision: f64) -> String {
    let p = if precision < 0.0 { 6 } else { precision.min(16.0) as usize };
    let w = width.abs().min(64.0) as usize;
    if width < 0.0 {
        format!("{v:0w$.p$}")
    } else {
        format!("{v:w$.p$}")
    }
}

/// `val("12.5abc")` = 12.5: the number at the start of the text (0 when there is none), as C's
/// `atof` reads it.
fn leading_number(s: &str) -> f64 {
    let t = s.trim_start();
    let mut end = 0;
    let bytes = t.as_bytes();
    let mut seen_digit = false;
    let mut seen_dot = false;
    let mut seen_exp = false;
    while end < bytes.len() {
        let c = bytes[end];
        let ok = match c {
            b'0'..=b'9' => {
                seen_digit = true;
                true
            }
            b'+' | b'-' => end == 0 || matches!(bytes[end - 1], b'e' | b'E'),
            b'.' if !seen_dot && !seen_exp => {
                seen_dot = true;
                true
            }
            b'e' | b'E' if seen_digit && !seen_exp => {
                seen_exp = true;
                true
            }
            _ => false,
        };
        if !ok {
            break;
        }
        end += 1;
    }
    // Back off a dangling exponent or sign ("1e", "3-").
    while end > 0 && t[..end].parse::<f64>().is_err() {
        end -= 1;
    }
    t[..end].parse().unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn val_reads_the_leading_number() {
        assert_eq!(leading_number("12.5abc"), 12.5);
        assert_eq!(leading_number(" -3e2x"), -300.0);
        assert_eq!(leading_number("1e"), 1.0);
        assert_eq!(leading_number("abc"), 0.0);
    }

    #[test]
    fn str_pads_and_rounds_as_pov_ray() {
        assert_eq!(format_float(1.5, 0.0, 2.0), "1.50");
        assert_eq!(format_float(7.0, -3.0, 0.0), "007");
        assert_eq!(format_float(2.0, 4.0, 0.0), "   2");
        assert_eq!(format_float(0.25, 0.0, -1.0), "0.250000");
    }
}
