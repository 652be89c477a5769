//! A pigment or pattern as a user function's callee (`function { pigment { ... } }`,
//! `function { pattern { ... } }`): the lowered pigment, evaluated through the pattern layer
//! (`shading::pigment`) and handed to the function layer as its `function::Shade`, so there is
//! never a second copy of a pattern kernel.

use std::any::Any;

use glam::{DMat4, Vec3};

use crate::desc::PigmentDesc;
use crate::function::{Channel, Shade};
use crate::shading::pigment::{eval_pigment, gray, pattern_value, PatternQuality, Pigment};

/// A lowered pigment evaluated as a function of (x, y, z), in the pigment's own space.
#[derive(Debug, PartialEq)]
pub struct PigmentFn {
    pigment: Pigment,
}

impl PigmentFn {
    /// The pigment `d` as a function: its point is the one the pigment would be evaluated at
    /// (its own transforms apply, no object's).
    pub fn new(d: &PigmentDesc) -> PigmentFn {
        PigmentFn { pigment: Pigment::from_desc(d, &DMat4::IDENTITY) }
    }

    fn point(a: &[f64]) -> Vec3 {
        let p = |i: usize| a.get(i).copied().unwrap_or(0.0) as f32;
        Vec3::new(p(0), p(1), p(2))
    }
}

impl Shade for PigmentFn {
    fn color(&self, a: &[f64]) -> [f64; 5] {
        let c = eval_pigment(&self.pigment, Self::point(a), PatternQuality::default());
        [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit].map(f64::from)
    }

    #[inline]
    fn value(&self, ch: Channel, a: &[f64]) -> f64 {
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

    fn as_any(&self) -> &dyn Any {
        self
    }

    fn same(&self, other: &dyn Shade) -> bool {
        other.as_any().downcast_ref::<PigmentFn>().is_some_and(|o| o == self)
    }
}
