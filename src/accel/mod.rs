//! Acceleration structures over the bounded primitives (chapter 24.4): a BVH, the chapter's
//! uniform grid, and brute force as the ground truth. Unbounded planes are never in here.
//!
//! Every accelerator takes a closure that tests one primitive, so none of them knows shapes.
//!
//! Layer 3 of docs/design/architecture.md: uses `ray` and `lanes`; `geometry` (a mesh's own BVH), `scene` and `render` use it.

pub mod aabb;
pub mod bvh;
pub mod grid;
pub mod packet;

use crate::ray::Ray;
use aabb::Aabb;
use bvh::Bvh;
use grid::Grid;

/// Which accelerator to build over the bounded primitives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum AccelKind {
    #[default]
    Bvh,
    Grid,
    None,
}

impl AccelKind {
    pub fn name(self) -> &'static str {
        match self {
            AccelKind::Bvh => "bvh",
            AccelKind::Grid => "grid",
            AccelKind::None => "none",
        }
    }
}

pub enum Accel {
    Bvh(Bvh),
    Grid(Grid),
    /// Brute force over `count` primitives: the chapter's first algorithm.
    None {
        count: u32,
    },
}

impl Accel {
    /// The accelerator over primitives with these bounds, each test weighed at `weights[i]`
    /// node visits (the BVH splits costly primitives into smaller leaves; the grid and brute
    /// force ignore weights).
    pub fn build(kind: AccelKind, bounds: &[Aabb], weights: &[u32]) -> Accel {
        match kind {
            AccelKind::Bvh => Accel::Bvh(Bvh::build_weighted(bounds, Some(weights))),
            AccelKind::Grid => Accel::Grid(Grid::build(bounds)),
            AccelKind::None => Accel::None { count: bounds.len() as u32 },
        }
    }

    pub fn kind(&self) -> AccelKind {
        match self {
            Accel::Bvh(_) => AccelKind::Bvh,
            Accel::Grid(_) => AccelKind::Grid,
            Accel::None { .. } => AccelKind::None,
        }
    }

    /// Calls `test(prim, t_max)` on candidates front to back as far as the structure can order
    /// them; `test` returns a hit nearer than `t_max`, which then shrinks the search.
    /// Returns the number of nodes or cells visited.
    #[inline]
    pub fn traverse<F: FnMut(u32, f32) -> Option<f32>>(&self, ray: &Ray, t_max: f32, mut test: F) -> u32 {
        match self {
            Accel::Bvh(b) => b.traverse(ray, t_max, test),
            Accel::Grid(g) => g.traverse(ray, t_max, test),
            Accel::None { count } => {
                let mut t_max = t_max;
                for p in 0..*count {
                    if let Some(t) = test(p, t_max) {
                        t_max = t_max.min(t);
                    }
                }
                0
            }
        }
    }
}
