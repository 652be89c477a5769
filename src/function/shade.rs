//! Pattern and pigment functions (`function { pattern { ... } }`, `function { pigment { ... } }`,
//! POV-Ray 3.3.1.8.5): what a call reads (`Channel`) and the one operation this layer needs of
//! the pigment behind it (`Shade`). The pigment itself is the shading layer's
//! (`shading::pigment_fn`): functions sit below shading, so they see it only through this
//! trait, held once in an `Arc` shared by every call and compiled copy. A pigment function's
//! call is a colour; a function body reads one channel of it (`F(x, y, z).red`, `.gray`, ...),
//! a pattern function's call is its pattern value.

use std::any::Any;
use std::fmt::Debug;

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

/// A pattern or pigment as a function of (x, y, z), in the pigment's own space.
pub trait Shade: Debug + Send + Sync + 'static {
    /// The colour at (a[0], a[1], a[2]): red, green, blue, filter, transmit.
    fn color(&self, a: &[f64]) -> [f64; 5];

    /// One channel at (a[0], a[1], a[2]).
    fn value(&self, ch: Channel, a: &[f64]) -> f64;

    /// For comparing two shades (`same`).
    fn as_any(&self) -> &dyn Any;

    /// Whether `other` is the same pattern or pigment (descriptions compare by value).
    fn same(&self, other: &dyn Shade) -> bool;
}

impl PartialEq for dyn Shade {
    fn eq(&self, other: &dyn Shade) -> bool {
        self.same(other)
    }
}
