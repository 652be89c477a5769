//! Pattern and pigment functions (`function { pattern { ... } }`, `function { pigment { ... } }`,
//! POV-Ray 3.3.1.8.5): the lowered pigment held once (an `Arc` shared by every call and compiled
//! copy) and evaluated through the pattern layer (`shading::pigment`), never a second copy of a
//! pattern kernel. A pigment function's call is a colour; a function body reads one channel of
//! it (`F(x, y, z).red`, `.gray`, ...), a pattern function's call is its pattern value.

use glam::{DMat4, Vec3};

use crate::scene::desc::PigmentDesc;
use crate::shading::pigment::{eval_pigment, gray, pattern_value, PatternQuality, Pigment};

/// What a call of a pattern or pigment function reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    Red,
    Green,
    Blue,
    Filter,
    Transmit,
    /// 0.297 red + 0.589 green + 0.114 blue (`shading::pigment::gray`).
    Gray,
    /// The pattern's own value (a pattern function).
    Pattern,
}

impl Channel {
    /// The channel a member name selects (`.x` is red, `.t` filter, as for colours).
    pub fn named(word: &str) -> Option<Channel> {
        Some(match word {
            "x" | "u" | "red" => Channel::Red,
            "y" | "v" | "green" => Channel::Green,
            "z" | "blue" => Channel::Blue,
            "t" | "filter" => Channel::Filter,
            "transmit" => Channel::Transmit,
            "gray" | "grey" => Channel::Gray,
            _ => return None,
        })
    }

    /// The member names, for messages.
    pub const NAMES: &'static str = "red, green, blue, filter, transmit, gray (or x, y, z, t)";
}

/// A lowered pigment evaluated as a function of (x, y, z), in the pigment's own space.
#[derive(Debug, PartialEq)]
pub struct Shade {
    pigment: Pigment,
}

impl Shade {
    /// The pigment `d` as a function: its point is the one the pigment would be evaluated at
    /// (its own transforms apply, no object's).
    pub fn new(d: &PigmentDesc) -> Shade {
        Shade { pigment: Pigment::from_desc(d, &DMat4::IDENTITY) }
    }

    fn point(a: &[f64]) -> Vec3 {
        let p = |i: usize| a.get(i).copied().unwrap_or(0.0) as f32;
        Vec3::new(p(0), p(1), p(2))
    }

    /// The colour at (a[0], a[1], a[2]): red, green, blue, filter, transmit.
    pub fn color(&self, a: &[f64]) -> [f64; 5] {
        let c = eval_pigment(&self.pigment, Self::point(a), PatternQuality::default());
        [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit].map(f64::from)
    }

    /// One channel at (a[0], a[1], a[2]).
    #[inline]
    pub fn value(&self, ch: Channel, a: &[f64]) -> f64 {
        let q = PatternQuality::default();
        if ch == Channel::Pattern {
            return f64::from(pattern_value(&self.pigment, Self::point(a), q));
        }
        let c = eval_pigment(&self.pigment, Self::point(a), q);
        f64::from(match ch {
            Channel::Red => c.rgb.x,
            Channel::Green => c.rgb.y,
            Channel::Blue => c.rgb.z,
            Channel::Filter => c.filter,
            Channel::Transmit => c.transmit,
            _ => gray(&c),
        })
    }
}
