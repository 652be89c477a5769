//! A packet block's working rows (`render::packet::trace_block`): the surfaces of its hits, its
//! shadow rays towards one light, and per light the directions and lit lanes, eight rows of
//! eight lanes each.
//!
//! They live in the tracer (`Tracer::block`), one set per tile, and are reused from block to
//! block instead of being built zeroed for each: about 7 KB of stores for every 8×8 block, 3 %
//! of a floor-only frame. A block writes every row and lane it reads, or masks it out
//! (`SurfaceRows::valid`, `ShadowRows::active`), so what an earlier block left behind never
//! reaches a colour.

use glam::Vec3;

use crate::accel::packet::Ray8;
use crate::lanes::{Lane, F8, M8, V3};
use crate::shading::pattern::{Rgbft, RgbftLanes};

/// Three coordinates of eight lanes, stored as rows are (`V3<F8>` by value).
#[derive(Clone, Copy, Default)]
pub(crate) struct Soa3 {
    pub x: F8,
    pub y: F8,
    pub z: F8,
}

impl From<V3<F8>> for Soa3 {
    #[inline(always)]
    fn from(v: V3<F8>) -> Soa3 {
        Soa3 { x: v.x, y: v.y, z: v.z }
    }
}

impl Soa3 {
    #[inline(always)]
    pub fn v(self) -> V3<F8> {
        V3 { x: self.x, y: self.y, z: self.z }
    }

    #[inline(always)]
    pub fn set(&mut self, i: usize, v: Vec3) {
        (self.x.0[i], self.y.0[i], self.z.0[i]) = (v.x, v.y, v.z);
    }
}

/// The shading points of a block's hits: position, the normal facing the ray, the shading
/// normal. Only the lanes of `valid` hold this block's values.
#[derive(Default)]
pub(crate) struct SurfaceRows {
    pub p: [Soa3; 8],
    pub facing: [Soa3; 8],
    pub normal: [Soa3; 8],
    pub valid: [M8; 8],
}

/// Shadow rays towards one light for a block, and where they stop. `shadow_setup` writes every
/// row below the block's row count for each light.
pub(crate) struct ShadowRows {
    pub rays: [Ray8; 8],
    pub t_max: [F8; 8],
    /// Lanes with a shadow ray to trace.
    pub active: [M8; 8],
    /// Lanes the light reaches unless something blocks it (direction in `rays[r].d`).
    pub lit: [M8; 8],
}

/// Per row of a block: the direction to one light and the lanes it reaches.
pub(crate) type LightRows = ([V3<F8>; 8], [M8; 8]);

/// Everything a block works in, kept from block to block.
pub(crate) struct BlockRows {
    pub surfaces: SurfaceRows,
    /// The pigment colours of the lanes shaded eight wide.
    pub pigments: [RgbftLanes<F8>; 8],
    pub shadow: ShadowRows,
    /// Per light of the scene (resized on first use).
    pub lights: Vec<LightRows>,
}

impl BlockRows {
    pub fn new() -> Box<BlockRows> {
        Box::new(BlockRows {
            surfaces: SurfaceRows::default(),
            pigments: [RgbftLanes::splat(Rgbft::default()); 8],
            shadow: ShadowRows {
                rays: [Ray8::ZERO; 8],
                t_max: [F8::splat(f32::NEG_INFINITY); 8],
                active: [M8::default(); 8],
                lit: [M8::default(); 8],
            },
            lights: Vec::new(),
        })
    }
}
