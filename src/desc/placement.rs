//! An object's transform held as what it is: nothing, a move, a uniform scale and a move, or a
//! general affine map. A million generated objects mostly have no transform or a move; as two
//! f64 4×4 matrices each they cost 256 bytes an object, and an `ObjectDesc` several times
//! what the render scene needs.
//!
//! The lowering composes transforms as full matrices (`Transform`) and only the result is
//! compacted, losslessly: a compact form is chosen only when it rebuilds both matrices bit for
//! bit, so every image stays as it was.

use glam::{DMat4, DVec3, DVec4};

use super::Transform;

#[derive(Clone, Debug, Default)]
pub enum Placement {
    /// No transform.
    #[default]
    Identity,
    /// A move by `offset`, whose inverse is the move by `-offset`; `zeros` holds the signs of
    /// both matrices' zero entries (`ZeroSigns`).
    Translate { offset: DVec3, zeros: ZeroSigns },
    /// A uniform scale then a move (boxed: the enum stays the size of a move).
    Scale(Box<ScaleMove>),
    /// Anything else.
    Affine(Box<Transform>),
}

/// Which zero entries of a matrix (bits 0–15, column-major) and of its inverse (bits 16–31)
/// are `-0.0`. A general inverse writes `-0.0` in places (`DMat4::inverse` of a move has
/// seven), and a product may; they are kept so that the matrices rebuild bit for bit.
pub type ZeroSigns = u32;

/// A uniform scale by `scale` then a move by `offset` (the matrix), and the inverse's own
/// numbers (the general inverse rounds as it does; they are kept rather than recomputed).
#[derive(Clone, Debug, PartialEq)]
pub struct ScaleMove {
    pub scale: f64,
    pub offset: DVec3,
    pub inverse_scale: f64,
    pub inverse_offset: DVec3,
    pub zeros: ZeroSigns,
}

/// `diag(s, s, s, 1)` moved by `t`, its zero entries signed as bits `zeros` say.
fn scale_move(s: f64, t: DVec3, zeros: u32) -> DMat4 {
    let m = DMat4::from_cols(
        DVec4::new(s, 0.0, 0.0, 0.0),
        DVec4::new(0.0, s, 0.0, 0.0),
        DVec4::new(0.0, 0.0, s, 0.0),
        t.extend(1.0),
    );
    let mut a = m.to_cols_array();
    for (i, x) in a.iter_mut().enumerate() {
        if *x == 0.0 {
            *x = if zeros >> i & 1 == 1 { -0.0 } else { 0.0 };
        }
    }
    DMat4::from_cols_array(&a)
}

/// The bits of `m`'s `-0.0` entries (column-major).
fn negative_zeros(m: &DMat4) -> u32 {
    m.to_cols_array()
        .iter()
        .enumerate()
        .fold(0, |bits, (i, x)| bits | u32::from(*x == 0.0 && x.is_sign_negative()) << i)
}

/// Whether `a` and `b` are the same bits (so `-0.0` and `0.0` differ: a rebuilt matrix must
/// be the one the lowering composed).
fn same_bits(a: &DMat4, b: &DMat4) -> bool {
    a.to_cols_array().iter().zip(b.to_cols_array().iter()).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// `m`'s uniform scale and move, when it is one.
fn as_scale_move(m: &DMat4) -> Option<(f64, DVec3)> {
    let (s, t) = (m.x_axis.x, m.w_axis.truncate());
    same_bits(m, &scale_move(s, t, negative_zeros(m))).then_some((s, t))
}

impl Placement {
    /// The most compact form that rebuilds `t` exactly.
    pub fn of(t: &Transform) -> Placement {
        let affine = || Placement::Affine(Box::new(*t));
        let Some((scale, offset)) = as_scale_move(&t.matrix) else { return affine() };
        let Some((inverse_scale, inverse_offset)) = as_scale_move(&t.inverse) else { return affine() };
        let zeros = negative_zeros(&t.matrix) | negative_zeros(&t.inverse) << 16;
        let one = 1f64.to_bits();
        if scale.to_bits() == one && inverse_scale.to_bits() == one {
            if zeros == 0 && offset == DVec3::ZERO && inverse_offset == DVec3::ZERO {
                return Placement::Identity;
            }
            if same_bits(&t.inverse, &scale_move(1.0, -offset, zeros >> 16)) {
                return Placement::Translate { offset, zeros };
            }
        }
        Placement::Scale(Box::new(ScaleMove { scale, offset, inverse_scale, inverse_offset, zeros }))
    }

    /// Both matrices.
    pub fn transform(&self) -> Transform {
        match self {
            Placement::Identity => Transform::default(),
            Placement::Translate { offset, zeros } => {
                Transform { matrix: scale_move(1.0, *offset, *zeros), inverse: scale_move(1.0, -*offset, *zeros >> 16) }
            }
            Placement::Scale(s) => Transform {
                matrix: scale_move(s.scale, s.offset, s.zeros),
                inverse: scale_move(s.inverse_scale, s.inverse_offset, s.zeros >> 16),
            },
            Placement::Affine(t) => **t,
        }
    }

    /// Object space → the space above it.
    pub fn matrix(&self) -> DMat4 {
        self.transform().matrix
    }

    /// The inverse of `matrix`.
    pub fn inverse(&self) -> DMat4 {
        self.transform().inverse
    }

    /// `then` applied after this one (composed as `Transform::then` does).
    pub fn then(&self, then: &Transform) -> Placement {
        Placement::of(&self.transform().then(then))
    }

    pub fn is_identity(&self) -> bool {
        matches!(self, Placement::Identity) || self.transform().is_identity()
    }
}

impl PartialEq for Placement {
    /// Equal when the matrices are, as `Transform`s compare (`-0.0 == 0.0`): the same move
    /// composed in two ways is the same placement, whatever form holds it.
    fn eq(&self, other: &Placement) -> bool {
        self.transform() == other.transform()
    }
}

impl From<Transform> for Placement {
    fn from(t: Transform) -> Placement {
        Placement::of(&t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip(t: Transform) -> Placement {
        let p = Placement::of(&t);
        let back = p.transform();
        assert!(same_bits(&back.matrix, &t.matrix) && same_bits(&back.inverse, &t.inverse), "{p:?}");
        p
    }

    fn of_matrix(m: DMat4) -> Transform {
        Transform { matrix: m, inverse: m.inverse() }
    }

    #[test]
    fn compact_forms_rebuild_both_matrices_exactly() {
        assert_eq!(round_trip(Transform::default()), Placement::Identity);
        let moved = of_matrix(DMat4::from_translation(DVec3::new(1.5, 0.0, 1e6)));
        assert!(matches!(round_trip(moved), Placement::Translate { .. }));
        let scaled = of_matrix(DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(3.0)));
        assert!(matches!(round_trip(scaled), Placement::Scale(_)));
        let composed = moved.then(&scaled).then(&moved);
        round_trip(composed);
        let rotated = of_matrix(DMat4::from_rotation_y(0.3) * DMat4::from_translation(DVec3::Y));
        assert!(matches!(round_trip(rotated), Placement::Affine(_)));
        let stretched = of_matrix(DMat4::from_scale(DVec3::new(1.0, 2.0, 1.0)));
        assert!(matches!(round_trip(stretched), Placement::Affine(_)));
    }

    #[test]
    fn placements_compare_as_their_matrices() {
        // The lowering's move has a general inverse (with -0.0s); a generator's the exact one.
        let m = DMat4::from_translation(DVec3::new(1.0, 2.0, 3.0));
        let general = Placement::of(&of_matrix(m));
        let exact =
            Placement::of(&Transform { matrix: m, inverse: DMat4::from_translation(DVec3::new(-1.0, -2.0, -3.0)) });
        assert_eq!(general, exact);
        assert_ne!(general, Placement::Identity);
    }

    #[test]
    fn a_negative_zero_is_not_rounded_away() {
        // A general inverse may hold -0.0 where the compact form would rebuild 0.0.
        let mut t = of_matrix(DMat4::from_translation(DVec3::new(1.0, 0.0, 0.0)));
        t.inverse.w_axis.y = -0.0;
        round_trip(t);
    }

    #[test]
    fn composing_keeps_the_matrices_of_transform_then() {
        let a = of_matrix(DMat4::from_translation(DVec3::new(0.1, 0.2, 0.3)));
        let b = of_matrix(DMat4::from_scale(DVec3::splat(0.7)));
        let p = Placement::of(&a).then(&b);
        let t = a.then(&b);
        assert!(same_bits(&p.matrix(), &t.matrix) && same_bits(&p.inverse(), &t.inverse));
    }
}
