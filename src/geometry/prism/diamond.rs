//! A second cull for a linear sweep's lanes, after its box's (`CullBox`): the slab of heights
//! and the section's bounds along the diagonals `u + v` and `u − v`, a box turned 45° about the
//! sweep axis. A star or a glyph's diagonal strokes leave much of the upright box empty, and a
//! lane dropped here costs no f64 solve.
//!
//! The turned coordinates of a lane's origin are rounded once more in f32, so the bounds are
//! widened per lane by that rounding's bound, besides the 10⁻⁴ of the size and the 10⁻⁵ of the
//! distances that `CullBox` allows: a lane the solve would find a hit for is never dropped, and
//! packets and single rays keep the same bits.

use glam::{DVec2, Vec3};

use crate::accel::aabb::node_slabs;
use crate::geometry::live_between;
use crate::geometry::spline::Piece;
use crate::lanes::{Lane, V3};

#[derive(Clone, Copy, Debug)]
pub struct Diamond {
    /// `(u + v, y, u − v)` bounds, widened.
    lo: Vec3,
    hi: Vec3,
}

impl Diamond {
    /// The bounds of the sweep of `arcs` between heights `h1 < h2` (object space).
    pub fn new(arcs: &[Piece], h1: f64, h2: f64) -> Diamond {
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for p in arcs {
            for i in 0..=p.degree {
                let q = DVec2::new(p.cu[i] + p.cv[i], p.cu[i] - p.cv[i]);
                (lo, hi) = (lo.min(q), hi.max(q));
            }
        }
        let widen = 1e-4
            * (hi - lo)
                .max_element()
                .max(h2 - h1)
                .max(lo.abs().max(hi.abs()).max_element())
                .max(h1.abs().max(h2.abs()));
        Diamond {
            lo: Vec3::new((lo.x - widen) as f32, (h1 - widen) as f32, (lo.y - widen) as f32),
            hi: Vec3::new((hi.x + widen) as f32, (h2 + widen) as f32, (hi.y + widen) as f32),
        }
    }

    /// `t_max`, or −inf for the lanes whose object-space ray `o + t·d` certainly misses the
    /// turned box within `(t_min, t_max)`; `None` when every lane does (`CullBox::live`).
    #[inline(always)]
    pub fn live<L: Lane>(&self, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> Option<L> {
        let turn = |v: V3<L>| V3 { x: v.x + v.z, y: v.y, z: v.x - v.z };
        // The rounding of `o.x ± o.z`: at most an ulp of the sum of magnitudes.
        let slack = (o.x.abs() + o.z.abs()) * L::splat(2.0 * f32::EPSILON);
        let (lo, hi) = (V3::splat(self.lo), V3::splat(self.hi));
        let lo = V3 { x: lo.x - slack, y: lo.y, z: lo.z - slack };
        let hi = V3 { x: hi.x + slack, y: hi.y, z: hi.z + slack };
        let (near, far) = node_slabs(lo, hi, turn(o), turn(d).recip());
        live_between(near, far, t_min, t_max)
    }
}
