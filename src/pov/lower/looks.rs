//! Objects that look alike share one texture. Each object is lowered with its own copy of what
//! it was written with (a generated cloud of a million spheres writes `pigment { color rgb
//! <..> }` a million times, in a few colours); the placed object keeps a reference to a copy
//! met recently instead, so the description holds each look once, as the render scene's
//! `Material`s already do.

use std::sync::Arc;

use super::Lowerer;
use crate::desc::{ObjectDesc, ShapeDesc, TextureDesc};

/// How many distinct looks are remembered: a scene of a million different looks compares each
/// object with this many at most and shares none.
const LOOKS: usize = 64;

impl Lowerer<'_> {
    /// Points `object`'s texture (and those of the shapes in it) at a remembered copy of an
    /// equal texture, remembering it when it is new.
    pub(super) fn share_looks(&mut self, object: &mut ObjectDesc) {
        if let ShapeDesc::Csg { children, .. } = &mut object.shape {
            children.iter_mut().for_each(|c| self.share_looks(c));
        }
        share(&mut self.looks, &mut object.texture);
    }
}

/// `texture` as one of `looks` when one is equal to it; otherwise remembered while there is
/// room.
fn share(looks: &mut Vec<Arc<TextureDesc>>, texture: &mut Arc<TextureDesc>) {
    if let Some(same) = looks.iter().find(|l| Arc::ptr_eq(l, texture) || **l == *texture) {
        *texture = same.clone();
    } else if looks.len() < LOOKS {
        looks.push(texture.clone());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::{Color, PigmentPattern};

    fn solid(r: f64) -> Arc<TextureDesc> {
        let mut t = TextureDesc::default();
        t.pigment.pattern = PigmentPattern::Solid(Color::rgb(r, 0.0, 0.0));
        Arc::new(t)
    }

    #[test]
    fn equal_textures_become_one_and_different_ones_stay_apart() {
        let mut looks = Vec::new();
        let (mut a, mut b, mut c) = (solid(0.5), solid(0.5), solid(0.25));
        share(&mut looks, &mut a);
        share(&mut looks, &mut b);
        share(&mut looks, &mut c);
        assert!(Arc::ptr_eq(&a, &b));
        assert!(!Arc::ptr_eq(&a, &c));
        assert_eq!(looks.len(), 2);
    }

    #[test]
    fn a_placed_cloud_holds_each_look_once() {
        let text: String =
            (0..50).map(|i| format!("sphere {{ <{i}, 0, 0>, 0.5 pigment {{ rgb {} }} }}\n", i % 3)).collect();
        let (scene, _) = crate::pov::lower::tests::lower(&text).unwrap();
        let mut distinct: Vec<*const TextureDesc> = scene.objects.iter().map(|o| Arc::as_ptr(&o.texture)).collect();
        distinct.sort();
        distinct.dedup();
        assert_eq!(distinct.len(), 3);
    }
}
