//! CSG in render data: the nodes of `intersection`, `difference`, `merge`, `clipped_by` (and a
//! `union` inside them) over leaf primitives, with the bounds that let them sit in the BVH.
//!
//! A node is one bounded primitive of the scene (`ShapeKind::Csg`); its leaves are ordinary
//! primitives stored after the scene's own (`Scene::prims[first_leaf..]`), outside the
//! accelerator, with their own materials. The queries (which surface a ray meets first, which
//! points are inside) are in `render::csg`.

use glam::Vec3;

use crate::accel::aabb::Aabb;
use crate::desc::CsgOp;
use crate::scene::build::ShapeKind;

/// How a node's children combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgRule {
    /// Every child's surface; inside any child.
    Union,
    /// A child's surface where it is inside no other child; inside any child.
    Merge,
    /// A child's surface where it is inside every other child; inside all of them
    /// (`intersection`, `difference` with its subtracted children inverted, `clipped_by`).
    All,
}

/// One node: `children` index `Scene::csg_children`.
#[derive(Clone, Copy, Debug)]
pub struct CsgNode {
    pub rule: CsgRule,
    pub first: u32,
    pub count: u32,
    /// Only the first `surfaces` children are surfaces (`clipped_by`: only the clipped object);
    /// the rest only decide what is inside.
    pub surfaces: u32,
    /// Render-space bounds of the node's surface (infinite where unbounded).
    pub min: Vec3,
    pub max: Vec3,
    /// Every child is a leaf of a kind with a `span` (`has_span`): the queries may keep each
    /// child's crossings instead of searching it again.
    pub spans: bool,
    /// The node's groups of children (`CsgGroup`, `Scene::csg_groups[first_group..][..groups]`);
    /// none for a node of few children, whose boxes are met one by one.
    pub first_group: u32,
    pub groups: u32,
}

/// Children of one node whose boxes lie near each other, and a box around all their boxes
/// (surface and solid): a ray that misses it misses each of theirs, so the query culls them
/// together before it meets any one (the node's children in a two-level tree).
#[derive(Clone, Copy, Debug)]
pub struct CsgGroup {
    pub bounds: Aabb,
    /// `Scene::csg_group_members[first..first + count]`: child indices within the node.
    pub first: u32,
    pub count: u32,
}

/// Nodes of more children than this are grouped (`group_children`).
pub const GROUPED_FROM: usize = 16;
/// Children per group at most.
const GROUP_SIZE: usize = 8;

/// `kids` split into groups of at most `GROUP_SIZE` by their boxes' centres, each time halved at
/// the median along the axis where the centres spread most, so a group's box stays small. Each
/// group with its box (the union of its members' surface and solid boxes), members in index
/// order.
pub fn group_children(kids: &[CsgChild]) -> Vec<(Aabb, Vec<u32>)> {
    fn split(kids: &[CsgChild], members: &mut [u32], out: &mut Vec<(Aabb, Vec<u32>)>) {
        let centre = |j: u32| {
            let b = &kids[j as usize].surface;
            (b.min + b.max) * 0.5
        };
        if members.len() <= GROUP_SIZE {
            let mut bounds = Aabb::EMPTY;
            for &j in members.iter() {
                bounds.grow(&kids[j as usize].surface);
                bounds.grow(&kids[j as usize].solid);
            }
            let mut members = members.to_vec();
            members.sort_unstable();
            out.push((bounds, members));
            return;
        }
        let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for &j in members.iter() {
            let c = centre(j);
            // Unbounded children (an infinite centre) sort last on every axis.
            if c.is_finite() {
                (lo, hi) = (lo.min(c), hi.max(c));
            }
        }
        let spread = hi - lo;
        let axis = if spread.x >= spread.y && spread.x >= spread.z {
            0
        } else if spread.y >= spread.z {
            1
        } else {
            2
        };
        let key = |j: &u32| {
            let c = centre(*j)[axis];
            if c.is_nan() {
                f32::INFINITY
            } else {
                c
            }
        };
        members.sort_by(|a, b| key(a).total_cmp(&key(b)).then(a.cmp(b)));
        let (left, right) = members.split_at_mut(members.len() / 2);
        split(kids, left, out);
        split(kids, right, out);
    }
    let mut members: Vec<u32> = (0..kids.len() as u32).collect();
    let mut out = Vec::new();
    split(kids, &mut members, &mut out);
    out
}

impl CsgNode {
    pub fn children(&self) -> std::ops::Range<usize> {
        self.first as usize..(self.first + self.count) as usize
    }
}

/// Whether leaves of `kind` tell where the ray's line crosses them as one pair of roots
/// (`span`), from which their `hit` picks: convex solids solved in closed form, and half-spaces
/// (a plane's span is a half-line, or all or none of the line).
pub fn has_span(kind: ShapeKind) -> bool {
    matches!(kind, ShapeKind::Box | ShapeKind::Sphere | ShapeKind::Ellipsoid | ShapeKind::Plane)
}

/// What a child is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgTarget {
    /// A primitive, `Scene::prims[i]`.
    Leaf(u32),
    /// A nested node, `Scene::csg[i]`.
    Node(u32),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CsgChild {
    pub target: CsgTarget,
    /// Inside and outside swap (`inverse`, or a subtracted child of `difference`).
    pub inverse: bool,
    /// Where the child's surface can be, padded for rounding (`padded`): a ray that misses it
    /// crosses no surface of the child.
    pub surface: Aabb,
    /// Where the child's solid (before `inverse`) can be, padded: a point outside it is
    /// outside the solid, so inside the child exactly when the child is inverted.
    pub solid: Aabb,
}

impl CsgChild {
    pub fn new(target: CsgTarget, inverse: bool, bounds: &ChildBounds) -> CsgChild {
        CsgChild { target, inverse, surface: padded(&bounds.surface), solid: padded(&bounds.solid) }
    }
}

/// `b` widened by a part in 10⁵ of its size and of its distance from the origin (and 10⁻⁶),
/// so that a point the shape's own test may round onto its surface is never outside it.
pub fn padded(b: &Aabb) -> Aabb {
    if b.is_empty() {
        return *b;
    }
    let scale = b.min.abs().max(b.max.abs()).max(b.max - b.min);
    let pad = scale * 1e-5 + Vec3::splat(1e-6);
    // Infinite sides stay infinite (∞ + ∞); a finite side moves out by its pad.
    let pad = Vec3::select(pad.is_finite_mask(), pad, Vec3::ZERO);
    Aabb { min: b.min - pad, max: b.max + pad }
}

impl CsgOp {
    /// The rule a node of this operation follows, and whether its children after the first
    /// are inverted (`difference`) and surfaces (all but `clipped_by`'s).
    pub fn rule(self) -> (CsgRule, bool, bool) {
        match self {
            CsgOp::Union => (CsgRule::Union, false, true),
            CsgOp::Merge => (CsgRule::Merge, false, true),
            CsgOp::Intersection => (CsgRule::All, false, true),
            CsgOp::Difference => (CsgRule::All, true, true),
            CsgOp::Clip => (CsgRule::All, false, false),
        }
    }
}

/// The everywhere box: where a child's inside or surface is unbounded.
pub const EVERYWHERE: Aabb = Aabb { min: Vec3::splat(f32::NEG_INFINITY), max: Vec3::splat(f32::INFINITY) };

/// Bounds of a child as CSG sees them: where its surface can be, and where its inside can be.
#[derive(Clone, Copy, Debug)]
pub struct ChildBounds {
    pub surface: Aabb,
    pub inside: Aabb,
    /// `inside` before the child's own inversion: where its solid can be.
    pub solid: Aabb,
}

impl ChildBounds {
    /// A solid primitive's (its inside is within its surface's box); an inverted child's inside
    /// is everywhere.
    pub fn of_leaf(surface: Aabb, inverse: bool) -> ChildBounds {
        ChildBounds { surface, inside: if inverse { EVERYWHERE } else { surface }, solid: surface }
    }

    /// A plane's: its surface is unbounded, and so is its inside unless the plane is
    /// axis-aligned, when the inside is a half-space box (`plane { y, 10 }`: y ≤ 10) that
    /// bounds an intersection with it.
    pub fn of_plane(plane: &crate::geometry::plane::Plane, inverse: bool) -> ChildBounds {
        let (n, d) = (plane.normal, plane.distance);
        let mut solid = EVERYWHERE;
        let axes: Vec<usize> = (0..3).filter(|&k| n[k] != 0.0).collect();
        if let &[k] = axes.as_slice() {
            // n_k · p_k < d, padded for rounding.
            let edge = d / n[k];
            let edge = edge + edge.abs().max(1.0) * 1e-5 * n[k].signum();
            if n[k] > 0.0 {
                solid.max[k] = edge;
            } else {
                solid.min[k] = edge;
            }
        }
        ChildBounds { surface: EVERYWHERE, inside: if inverse { EVERYWHERE } else { solid }, solid }
    }

    /// A node over children with these bounds (`surfaces` of them surfaces), under `rule`.
    pub fn of_node(rule: CsgRule, children: &[ChildBounds], surfaces: usize, inverse: bool) -> ChildBounds {
        let mut surface = Aabb::EMPTY;
        for c in &children[..surfaces] {
            surface.grow(&c.surface);
        }
        // `inside` bounds where the node's surface may show; `solid` where its inside test
        // may hold, from each child's box as its own test sees it (`held`).
        let held = |c: &ChildBounds| {
            let mut b = c.inside;
            b.grow(&c.solid);
            b
        };
        let (inside, solid) = match rule {
            CsgRule::Union | CsgRule::Merge => {
                let (mut b, mut s) = (Aabb::EMPTY, Aabb::EMPTY);
                children.iter().for_each(|c| {
                    b.grow(&c.inside);
                    s.grow(&held(c));
                });
                (b, s)
            }
            CsgRule::All => {
                let b = children.iter().fold(EVERYWHERE, |b, c| intersect(&b, &c.inside));
                surface = intersect(&surface, &b);
                (b, children.iter().fold(EVERYWHERE, |s, c| intersect(&s, &held(c))))
            }
        };
        ChildBounds { surface, inside: if inverse { EVERYWHERE } else { inside }, solid }
    }
}

fn intersect(a: &Aabb, b: &Aabb) -> Aabb {
    Aabb { min: a.min.max(b.min), max: a.max.min(b.max) }
}

/// Whether a box reaches infinity on some axis (such a node lives outside the BVH).
pub fn is_unbounded(b: &Aabb) -> bool {
    !(b.min.is_finite() && b.max.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(lo: f32, hi: f32) -> Aabb {
        Aabb::new(Vec3::splat(lo), Vec3::splat(hi))
    }

    #[test]
    fn intersection_bounds_shrink_to_the_common_box() {
        let kids = [ChildBounds::of_leaf(cube(0.0, 2.0), false), ChildBounds::of_leaf(cube(1.0, 3.0), false)];
        let b = ChildBounds::of_node(CsgRule::All, &kids, 2, false);
        assert_eq!((b.surface.min, b.surface.max), (Vec3::splat(1.0), Vec3::splat(2.0)));
    }

    #[test]
    fn difference_keeps_the_first_box_and_a_half_space_stays_unbounded() {
        let kids = [ChildBounds::of_leaf(cube(0.0, 2.0), false), ChildBounds::of_leaf(cube(1.0, 3.0), true)];
        let b = ChildBounds::of_node(CsgRule::All, &kids, 2, false);
        assert_eq!((b.surface.min, b.surface.max), (Vec3::splat(0.0), Vec3::splat(2.0)));
        let plane = [ChildBounds::of_leaf(EVERYWHERE, false)];
        assert!(is_unbounded(&ChildBounds::of_node(CsgRule::All, &plane, 1, false).surface));
    }

    #[test]
    fn groups_hold_each_child_once_in_a_box_around_theirs() {
        let kids: Vec<CsgChild> = (0..37)
            .map(|k| {
                let c = Vec3::new((k * 7 % 11) as f32, (k * 3 % 5) as f32, k as f32 * 0.5);
                let b = Aabb::new(c - 0.4, c + 0.4);
                let bounds = ChildBounds::of_leaf(b, k % 4 == 0);
                CsgChild::new(CsgTarget::Leaf(k), k % 2 == 0, &bounds)
            })
            .collect();
        let groups = group_children(&kids);
        let mut seen = vec![0; kids.len()];
        for (bounds, members) in &groups {
            assert!(!members.is_empty() && members.len() <= GROUP_SIZE);
            assert!(members.windows(2).all(|w| w[0] < w[1]), "in index order");
            for &j in members {
                seen[j as usize] += 1;
                for b in [&kids[j as usize].surface, &kids[j as usize].solid] {
                    assert!(bounds.min.cmple(b.min).all() && bounds.max.cmpge(b.max).all());
                }
            }
        }
        assert!(seen.iter().all(|&n| n == 1), "{seen:?}");
        assert_eq!(groups.len(), 8, "37 children halved down to groups of 8 or fewer");
    }
}
