//! The precision knob (`--precision f32|f64`).
//!
//! Rays are traced in f32 in a render space centred on the camera (`scene::build`), which holds
//! a hit to a relative 6e-8 of its distance from the camera, three orders of magnitude below a
//! pixel's footprint. `f64` re-solves each ray's nearest hit in f64 with the same formula
//! (`geometry::Shape` is generic over precision), so `t` carries one rounding instead of the
//! formula's; `docs/precision.md` has what that buys and costs, measured.

use std::fmt;
use std::str::FromStr;

/// The arithmetic rays are traced in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Precision {
    /// Single precision: every ray test, hit point and offset in f32 (with packets).
    #[default]
    F32,
    /// As `F32`, and each ray's nearest hit re-solved in f64 (`Scene::refine`): the same
    /// shape's formula on the ray widened exactly, `t` rounded once. The `reference` preset.
    F64,
}

impl Precision {
    pub const ALL: [Precision; 2] = [Precision::F32, Precision::F64];

    pub fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Precision {
    type Err = String;

    fn from_str(s: &str) -> Result<Precision, String> {
        Precision::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| format!("unknown precision `{s}` (precisions: f32, f64)"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_bad_names_say_what_is_allowed() {
        for p in Precision::ALL {
            assert_eq!(p.name().parse::<Precision>(), Ok(p));
            assert_eq!(p.to_string(), p.name());
        }
        assert_eq!(Precision::default(), Precision::F32);
        let e = "f16".parse::<Precision>().unwrap_err();
        assert!(e.contains("`f16`") && e.contains("f32, f64"), "{e}");
    }
}
