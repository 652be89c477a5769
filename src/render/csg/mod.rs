//! CSG queries: a node's nearest surface and its inside test, for one ray (f32 or f64) or eight,
//! from one generic formula (as `geometry::Shape`).
//!
//! A node's surface is found child by child: each surface child's hits are taken in order
//! along the ray (`hit_prim_in` from the last one rejected), and the first whose point the
//! other children accept is that child's candidate; the nearest candidate wins. An
//! `intersection` accepts a point inside every other child, a `merge` one inside none, a
//! `union` any. Rejected hits cost one more root search each, so a ray pays for the crossings
//! it passes, not for the node's size. Nodes whose children all have a line span (boxes,
//! spheres, ellipsoids, planes) answer from the spans instead (`spans`).

mod spans;

use glam::Vec3;

use crate::accel::aabb::{node_slabs, Aabb};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};
use crate::scene::build::Scene;
use crate::scene::csg::{CsgChild, CsgNode, CsgRule, CsgTarget};
use spans::SPANS;

/// The most surface crossings followed along one ray through one child; beyond, the child is
/// missed. A child of closed shapes has a few; this bounds a pathological nesting.
const MAX_CROSSINGS: usize = 256;

impl Scene {
    /// The nearest surface of node `node` in `(t_min, t_max)` for each lane (`MISS` where
    /// none), and the leaf it belongs to (an index into `prims`, as a float: exact below 2^24).
    pub fn hit_csg<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        // Packets reach here through a call that is not inlined (nodes nest), so the 8-wide
        // code would run in the caller's SSE; the copies below run it in 256-bit instructions.
        // AVX2 without FMA computes the same bits (as `render::packet`).
        #[cfg(target_arch = "x86_64")]
        if L::WIDTH == 8 && crate::lanes::has_avx2() {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.hit_csg_avx2(node, ray, t_min, t_max) };
        }
        if L::WIDTH == 8 {
            // Out of line, so that this dispatch stays small for the AVX2 packets (an inlined
            // search made every call reserve and probe its stack frame).
            return self.hit_node_outlined(node, ray, t_min, t_max);
        }
        self.hit_node(node, ray, t_min, t_max, true)
    }

    #[inline(never)]
    fn hit_node_outlined<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        self.hit_node(node, ray, t_min, t_max, true)
    }

    /// `hit_csg` for AVX2 packets: a node of a few children with spans (the common small
    /// `intersection`, `difference`, `clipped_by`) in its own function, apart from the general
    /// search, which inlines every shape's kernel: its stack frame (tens of KiB, probed page by
    /// page on every call) and code were paid by each small node too.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn hit_csg_avx2<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        let n = &self.csg[node as usize];
        match way(n) {
            FEW => self.hit_few_avx2(node, ray, t_min, t_max),
            MANY => self.hit_many_avx2(node, ray, t_min, t_max),
            _ => self.hit_any_avx2(node, ray, t_min, t_max),
        }
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn hit_few_avx2<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        let n = &self.csg[node as usize];
        self.hit_all::<L, FEW>(n, &self.csg_children[n.children()], ray, t_min, t_max, true)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn hit_many_avx2<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        let n = &self.csg[node as usize];
        self.hit_all::<L, MANY>(n, &self.csg_children[n.children()], ray, t_min, t_max, true)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn hit_any_avx2<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        self.hit_node(node, ray, t_min, t_max, true)
    }

    /// `hit_csg`; `direct`: whether a node of kept children with spans may take its answer
    /// from their latest entry and earliest exit (`hit_kept`) instead of the search (which
    /// finds the same: the unit tests compare the two).
    #[inline(always)]
    fn hit_node<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L, direct: bool) -> (L, L) {
        let n = &self.csg[node as usize];
        let kids = &self.csg_children[n.children()];
        if n.rule == CsgRule::All {
            return self.hit_all::<L, ANY>(n, kids, ray, t_min, t_max, direct);
        }
        // A union keeps every crossing; a merge one inside no other child.
        let window = Window { t_min, t_max, crossed: Flags::all(), asked: Flags::all() };
        self.search_all(n, ray, &window, &mut AnyChildren { scene: self, rule: n.rule, kids, ray })
    }

    /// `hit_csg` for a node under `CsgRule::All`: the same search, cut short by the children's
    /// boxes (exactly: a box the ray misses holds no crossing and no point of the ray).
    ///
    /// Before any shape is tried, each child's box is met with the ray's window: a child whose
    /// surface box is missed has no crossing to search; a subtracted (inverted) child whose
    /// solid box is missed contains every point of the window, so no inside test asks it; a
    /// kept child whose box is missed contains none, so the node is missed.
    ///
    /// `WAY` (`way`): which answer this copy compiles, `ANY` choosing by the node.
    #[inline(always)]
    fn hit_all<L: Lane, const WAY: u8>(
        &self,
        n: &CsgNode,
        kids: &[CsgChild],
        ray: &RayLanes<L>,
        t_min: L,
        t_max: L,
        direct: bool,
    ) -> (L, L) {
        let miss = L::splat(MISS);
        let (t_min, t_max) = within_box(n.min, n.max, ray, t_min, t_max);
        // An empty window in every lane (a packet that meets the node's box in the BVH, not
        // in this window): nothing to find.
        if !L::any(L::not(t_max.le(t_min))) {
            return (miss, L::splat(0.0));
        }
        // A node with spans meets its kept children's boxes only as a group's: the window lies
        // within the node's box, which lies within each kept child's, so their own boxes would
        // cut nothing, and a kept child whose box a lane's window misses shows in its span
        // (every point of the window clearly outside it, or outside its box by the pad).
        let spans = way(n) != ANY;
        let mut crossed = Flags::all();
        let mut asked = Flags::all();
        if WAY != FEW && n.groups > 0 && kids.len() <= Flags::CAPACITY {
            // A group whose box the window misses: each member's boxes are missed too.
            for g in &self.csg_groups[n.first_group as usize..(n.first_group + n.groups) as usize] {
                let members = &self.csg_group_members[g.first as usize..(g.first + g.count) as usize];
                if spans && members.iter().all(|&j| !kids[j as usize].inverse) {
                    continue;
                }
                let met = meets(&g.bounds, ray, t_min, t_max);
                for &j in members {
                    let j = j as usize;
                    let cut = if met {
                        !(spans && !kids[j].inverse)
                            && cull_child(&kids[j], j, ray, t_min, t_max, &mut crossed, &mut asked)
                    } else {
                        missed_child(&kids[j], j, &mut crossed, &mut asked)
                    };
                    if cut {
                        return (miss, L::splat(0.0));
                    }
                }
            }
        } else {
            for (j, c) in kids.iter().enumerate().take(Flags::CAPACITY) {
                if !(spans && !c.inverse) && cull_child(c, j, ray, t_min, t_max, &mut crossed, &mut asked) {
                    return (miss, L::splat(0.0));
                }
            }
        }
        let window = Window { t_min, t_max, crossed, asked };
        if WAY == FEW || (WAY == ANY && way(n) == FEW) {
            self.hit_spans::<L, 8>(n, kids, ray, &window, direct)
        } else if WAY == MANY || (WAY == ANY && way(n) == MANY) {
            self.hit_spans::<L, SPANS>(n, kids, ray, &window, direct)
        } else {
            let mut all = AllChildren { scene: self, kids, ray, asked: &window.asked, rejecters: Rejecters::default() };
            self.search_all(n, ray, &window, &mut all)
        }
    }

    /// The search of `hit_csg` over a node's surface children (`Children`): each child's
    /// crossings in order, the first that the other children accept is its candidate, the
    /// nearest candidate wins (the first child's on a tie).
    #[inline(always)]
    fn search_all<L: Lane>(
        &self,
        n: &CsgNode,
        ray: &RayLanes<L>,
        window: &Window<L>,
        children: &mut impl Children<L>,
    ) -> (L, L) {
        let miss = L::splat(MISS);
        let mut best = window.t_max;
        let mut leaf = L::splat(0.0);
        let mut found = L::mask_from_fn(|_| false);
        for i in window.crossed.ones(n.surfaces as usize) {
            let mut from = window.t_min;
            for _ in 0..MAX_CROSSINGS {
                let (t, l) = children.search(i, from, best);
                let hit = t.lt(miss);
                if !L::any(hit) {
                    break;
                }
                let p = ray.o.add(ray.d.scale(t));
                let keep = L::and(hit, children.inside(i, t, p, hit));
                best = L::select(keep, t, best);
                leaf = L::select(keep, l, leaf);
                found = L::or(found, keep);
                let again = L::and(hit, L::not(keep));
                if !L::any(again) {
                    break;
                }
                // Lanes done search the empty interval (best, best).
                from = L::select(again, t, best);
            }
        }
        (L::select(found, best, miss), leaf)
    }

    /// Which points lie inside node `node`.
    pub fn inside_node<L: Lane>(&self, node: u32, p: V3<L>) -> L::Mask {
        let n = &self.csg[node as usize];
        let kids = &self.csg_children[n.children()];
        match n.rule {
            CsgRule::All => self.inside_others(kids, usize::MAX, p, true),
            CsgRule::Union | CsgRule::Merge => self.inside_others(kids, usize::MAX, p, false),
        }
    }

    /// `all`: whether `p` is inside every child but `skip`; else whether inside any of them.
    fn inside_others<L: Lane>(&self, kids: &[CsgChild], skip: usize, p: V3<L>, all: bool) -> L::Mask {
        let mut m = L::mask_from_fn(|_| all);
        for (j, c) in kids.iter().enumerate() {
            if j == skip {
                continue;
            }
            let inside = self.inside_child(c, p);
            m = if all { L::and(m, inside) } else { L::or(m, inside) };
            // Outside for every lane: nothing more can change it.
            if all && !L::any(m) {
                break;
            }
        }
        m
    }

    #[inline(always)]
    fn inside_child<L: Lane>(&self, c: &CsgChild, p: V3<L>) -> L::Mask {
        let inside = match c.target {
            CsgTarget::Leaf(i) => self.inside_prim(&self.prims[i as usize], p),
            CsgTarget::Node(k) => self.inside_node(k, p),
        };
        L::xor(inside, L::mask_from_fn(|_| c.inverse))
    }

    #[inline(always)]
    fn hit_child<L: Lane>(&self, c: &CsgChild, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        match c.target {
            CsgTarget::Leaf(i) => (self.hit_prim_in(&self.prims[i as usize], ray, t_min, t_max), L::splat(i as f32)),
            CsgTarget::Node(k) => self.hit_csg(k, ray, t_min, t_max),
        }
    }
}

/// `hit_all`'s answers: from the spans of at most 8 children (`FEW`) or of at most `SPANS`
/// (`MANY`), or by the search (`ANY`, which also stands for "choose by the node").
const ANY: u8 = 0;
const FEW: u8 = 1;
const MANY: u8 = 2;

/// Which of `hit_all`'s answers node `n` takes (`ANY`: the search, or not under `CsgRule::All`).
#[inline(always)]
fn way(n: &CsgNode) -> u8 {
    if n.rule != CsgRule::All || !n.spans {
        ANY
    } else if n.count <= 8 {
        FEW
    } else if n.count as usize <= SPANS {
        MANY
    } else {
        ANY
    }
}

/// What `Scene::search_all` asks of a node's children. A trait, not closures: its
/// `#[inline(always)]` methods are inlined into the search, and from there into `hit_csg_avx2`,
/// where the eight-lane code compiles to 256-bit instructions (closures were compiled out of
/// line, without AVX2, as `accel::packet::RowTest` notes).
trait Children<L: Lane> {
    /// Child `i`'s nearest crossing in `(from, best)` and its leaf (as a float).
    fn search(&mut self, i: usize, from: L, best: L) -> (L, L);
    /// Whether the point `p` at `t` on child `i`'s surface is accepted by the other children,
    /// for the lanes of `hit` (the others do not matter).
    fn inside(&mut self, i: usize, t: L, p: V3<L>, hit: L::Mask) -> L::Mask;
}

/// A union's or a merge's children: a union keeps every crossing, a merge one inside no other
/// child.
struct AnyChildren<'a, L: Lane> {
    scene: &'a Scene,
    rule: CsgRule,
    kids: &'a [CsgChild],
    ray: &'a RayLanes<L>,
}

impl<L: Lane> Children<L> for AnyChildren<'_, L> {
    #[inline(always)]
    fn search(&mut self, i: usize, from: L, best: L) -> (L, L) {
        self.scene.hit_child(&self.kids[i], self.ray, from, best)
    }

    #[inline(always)]
    fn inside(&mut self, i: usize, _: L, p: V3<L>, hit: L::Mask) -> L::Mask {
        match self.rule {
            CsgRule::Union => hit,
            _ => L::not(self.scene.inside_others(self.kids, i, p, false)),
        }
    }
}

/// An intersection's (or difference's) children, searched shape by shape: a crossing is kept
/// where every other child asked contains it.
struct AllChildren<'a, L: Lane> {
    scene: &'a Scene,
    kids: &'a [CsgChild],
    ray: &'a RayLanes<L>,
    asked: &'a Flags,
    rejecters: Rejecters,
}

impl<L: Lane> Children<L> for AllChildren<'_, L> {
    #[inline(always)]
    fn search(&mut self, i: usize, from: L, best: L) -> (L, L) {
        self.scene.hit_child(&self.kids[i], self.ray, from, best)
    }

    #[inline(always)]
    fn inside(&mut self, i: usize, _: L, p: V3<L>, _: L::Mask) -> L::Mask {
        let (scene, kids) = (self.scene, self.kids);
        let test = |j: usize| scene.inside_child(&kids[j], p);
        inside_all_but::<L>(kids.len(), i, test, self.asked, &mut self.rejecters)
    }
}

/// Whether a point is inside every child `asked` of `count` but `skip` (`inside(j)`; the
/// children not asked contain it): the conjunction, in an order that ends it early where one
/// child rejects every lane: the two children that last did (`rejecters`), then the rest.
fn inside_all_but<L: Lane>(
    count: usize,
    skip: usize,
    inside: impl Fn(usize) -> L::Mask,
    asked: &Flags,
    rejecters: &mut Rejecters,
) -> L::Mask {
    let mut m = L::mask_from_fn(|_| true);
    let mut left = *asked;
    let first = rejecters.0;
    for (k, &j) in first.iter().enumerate() {
        if j == skip || !left.get(j) || j >= count {
            continue;
        }
        left.clear(j);
        m = L::and(m, inside(j));
        if !L::any(m) {
            rejecters.0.swap(0, k);
            return m;
        }
    }
    let mut ask = |j: usize, m: &mut L::Mask, left: &mut Flags| {
        if j == skip || !left.get(j) {
            return false;
        }
        left.clear(j);
        *m = L::and(*m, inside(j));
        let rejected = !L::any(*m);
        if rejected {
            rejecters.0 = [j, first[0]];
        }
        rejected
    };
    for w in 0..count.min(Flags::CAPACITY).div_ceil(64) {
        let mut bits = left.word(w, count);
        while bits != 0 {
            if ask(w * 64 + bits.trailing_zeros() as usize, &mut m, &mut left) {
                return m;
            }
            bits &= bits - 1;
        }
    }
    for j in Flags::CAPACITY..count {
        if ask(j, &mut m, &mut left) {
            return m;
        }
    }
    m
}

/// Child `j`'s part of `hit_all`'s culling: a child whose surface box the window misses has no
/// crossing to search (`crossed`); a subtracted child whose solid box it misses contains every
/// point of it (`asked`). True where a kept closed child is missed, so the node is.
#[inline(always)]
fn cull_child<L: Lane>(
    c: &CsgChild,
    j: usize,
    ray: &RayLanes<L>,
    t_min: L,
    t_max: L,
    crossed: &mut Flags,
    asked: &mut Flags,
) -> bool {
    let meets_surface = meets(&c.surface, ray, t_min, t_max);
    if !meets_surface {
        crossed.clear(j);
        if !c.inverse && c.solid == c.surface {
            return true;
        }
    }
    if c.inverse && !(if c.solid == c.surface { meets_surface } else { meets(&c.solid, ray, t_min, t_max) }) {
        asked.clear(j);
    }
    false
}

/// `cull_child` for a child of a group whose box the window misses: both its boxes are missed.
#[inline(always)]
fn missed_child(c: &CsgChild, j: usize, crossed: &mut Flags, asked: &mut Flags) -> bool {
    crossed.clear(j);
    if c.inverse {
        asked.clear(j);
    }
    !c.inverse && c.solid == c.surface
}

/// Whether any lane's window `(t_min, t_max)` meets the box `b` (padded in `t` as
/// `within_box`, so a crossing the box holds is never lost to rounding).
#[inline(always)]
fn meets<L: Lane>(b: &Aabb, ray: &RayLanes<L>, t_min: L, t_max: L) -> bool {
    let (near, far) = within_box(b.min, b.max, ray, t_min, t_max);
    L::any(near.le(far))
}

/// The ray's window through a node and which children it needs: `crossed`, those whose
/// crossings are searched; `asked`, those whose inside tests can reject a point.
struct Window<L: Lane> {
    t_min: L,
    t_max: L,
    crossed: Flags,
    asked: Flags,
}

/// One flag per child of a node (the first `CAPACITY`; those beyond are always set).
#[derive(Clone, Copy)]
struct Flags([u64; Flags::WORDS]);

impl Flags {
    const WORDS: usize = 8;
    const CAPACITY: usize = Flags::WORDS * 64;

    fn all() -> Flags {
        Flags([u64::MAX; Flags::WORDS])
    }

    fn clear(&mut self, j: usize) {
        if j < Flags::CAPACITY {
            self.0[j / 64] &= !(1 << (j % 64));
        }
    }

    fn get(&self, j: usize) -> bool {
        j >= Flags::CAPACITY || self.0[j / 64] & (1 << (j % 64)) != 0
    }

    /// The children among the first `count` whose flag is set, in order: a node's loops skip
    /// the culled ones a word at a time instead of asking each.
    #[inline(always)]
    fn ones(&self, count: usize) -> Ones<'_> {
        let bits = if count > 0 { self.word(0, count) } else { 0 };
        Ones { flags: self, count, w: 0, bits, beyond: Flags::CAPACITY }
    }

    /// Word `w` of the flags of `count` children (bits past `count` cleared).
    #[inline(always)]
    pub(super) fn word(&self, w: usize, count: usize) -> u64 {
        let bits = self.0[w];
        if (w + 1) * 64 > count {
            bits & (u64::MAX >> ((w + 1) * 64 - count))
        } else {
            bits
        }
    }
}

/// `Flags::ones`: the set flags' children below `count`, then those past `CAPACITY`.
struct Ones<'a> {
    flags: &'a Flags,
    count: usize,
    /// The word `bits` came from, and its flags not yet given.
    w: usize,
    bits: u64,
    /// The next child past `CAPACITY`.
    beyond: usize,
}

impl Iterator for Ones<'_> {
    type Item = usize;

    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        loop {
            if self.bits != 0 {
                let j = self.w * 64 + self.bits.trailing_zeros() as usize;
                self.bits &= self.bits - 1;
                return Some(j);
            }
            if (self.w + 1) * 64 < self.count.min(Flags::CAPACITY) {
                self.w += 1;
                self.bits = self.flags.word(self.w, self.count);
                continue;
            }
            if self.beyond < self.count {
                self.beyond += 1;
                return Some(self.beyond - 1);
            }
            return None;
        }
    }
}

/// The two children that last rejected a point, asked first (`usize::MAX`: none yet).
struct Rejecters([usize; 2]);

impl Default for Rejecters {
    fn default() -> Rejecters {
        Rejecters([usize::MAX; 2])
    }
}

/// `(t_min, t_max)` narrowed to where the ray is inside the box `min`..`max`, widened by a part
/// in 10⁵ of the distance so that no crossing on the box's faces is lost to rounding. A point
/// that every non-subtracted child of an `intersection` accepts lies in all their boxes, so the
/// node's own box bounds the search, however often an unbounded child (a cubic, a plane)
/// crosses the ray outside it.
#[inline(always)]
fn within_box<L: Lane>(min: Vec3, max: Vec3, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
    let (near, far) = node_slabs(V3::splat(min), V3::splat(max), ray.o, ray.inv);
    let pad = |t: L| t.abs() * L::splat(1e-5) + L::splat(1e-6);
    (t_min.max(near - pad(near)), t_max.min(far + pad(far)))
}
