//! What each primitive's ray test costs, in BVH node visits: the weights the scene's tree is
//! built with (`Accel::build`), so that its surface-area heuristic splits costly shapes into
//! leaves of their own where cheap ones share a leaf.
//!
//! The figures are rough classes, not timings: a box-like test (a sphere, a box, a triangle, a
//! quadric's closed form) costs about one node visit; a shape that walks its own tree (a mesh, a
//! height field) costs its depth; a shape solved by root finding (a torus, a lathe, a prism, a
//! blob) about eight; one found by marching or subdivision (an isosurface, a julia fractal, a
//! parametric) about thirty-two. A CSG node costs its children.

use super::build::{PrimRef, Scene, ShapeKind};
use super::csg::CsgTarget;

/// Heaviest weight given: a deep CSG tree's cost is summed over its children, and the sum need
/// not grow past what already makes its leaf a leaf of its own.
const MOST: u32 = 64;

impl Scene {
    /// The bounded primitives' weights, in the order of `prim_bounds`.
    pub fn prim_weights(&self) -> Vec<u32> {
        self.prims[..self.unbounded.start as usize].iter().map(|p| self.weight_of(p)).collect()
    }

    /// One primitive's test cost in node visits (at least 1, at most `MOST`).
    fn weight_of(&self, p: &PrimRef) -> u32 {
        let i = p.index as usize;
        let weight = match p.kind {
            ShapeKind::Sphere
            | ShapeKind::Ellipsoid
            | ShapeKind::Box
            | ShapeKind::Triangle
            | ShapeKind::SmoothTriangle
            | ShapeKind::Polygon
            | ShapeKind::Cone
            | ShapeKind::Disc
            | ShapeKind::Plane => 1,
            // A quadric is a closed form; higher orders search for roots.
            ShapeKind::Poly if self.polys[i].order <= 2 => 1,
            ShapeKind::Poly
            | ShapeKind::Torus
            | ShapeKind::Superellipsoid
            | ShapeKind::Prism
            | ShapeKind::Lathe
            | ShapeKind::Sor
            | ShapeKind::Blob => 8,
            ShapeKind::Julia | ShapeKind::Isosurface | ShapeKind::Parametric => 32,
            // Its own tree's depth, and a few triangles at the bottom.
            ShapeKind::Mesh | ShapeKind::HeightField => {
                let faces = self.meshes[i].data.triangles.len().max(1) as u32;
                2 + (u32::BITS - faces.leading_zeros())
            }
            ShapeKind::Csg => self.node_weight(i),
        };
        weight.clamp(1, MOST)
    }

    /// A CSG node's cost: one visit, and its children's.
    fn node_weight(&self, node: usize) -> u32 {
        self.csg_children[self.csg[node].children()].iter().fold(1u32, |sum, child| {
            let w = match child.target {
                CsgTarget::Leaf(leaf) => self.weight_of(&self.prims[leaf as usize]),
                CsgTarget::Node(n) => self.node_weight(n as usize),
            };
            sum.saturating_add(w).min(MOST)
        })
    }
}
