//! CSG queries: a node's nearest surface and its inside test, for one ray (f32 or f64) or eight,
//! from one generic formula (as `geometry::Shape`).
//!
//! A node's surface is found child by child: each surface child's hits are taken in order
//! along the ray (`hit_prim_in` from the last one rejected), and the first whose point the
//! other children accept is that child's candidate; the nearest candidate wins. An
//! `intersection` accepts a point inside every other child, a `merge` one inside none, a
//! `union` any. Rejected hits cost one more root search each, so a ray pays for the crossings
//! it passes, not for the node's size.

use glam::Vec3;

use crate::accel::aabb::{node_slabs, Aabb};
use crate::lanes::{Lane, V3};
use crate::ray::{pick_root, RayLanes, MISS};
use crate::scene::build::{PrimRef, Scene, ShapeKind};
use crate::scene::csg::{CsgChild, CsgNode, CsgRule, CsgTarget};

/// The most surface crossings followed along one ray through one child; beyond, the child is
/// missed. A child of closed shapes has a few; this bounds a pathological nesting.
const MAX_CROSSINGS: usize = 256;

/// The most children whose spans `hit_spans` keeps (on the stack); a larger node searches each
/// child's shape instead.
const SPANS: usize = 64;

/// How near (relative to `t` and the ray's origin) a point may lie to an end of a child's span
/// before the child's own inside test decides: far above the few ulps the span and the test
/// each round by, so both agree wherever the span decides.
const SPAN_MARGIN: f32 = 1e-4;

impl Scene {
    /// The nearest surface of node `node` in `(t_min, t_max)` for each lane (`MISS` where
    /// none), and the leaf it belongs to (an index into `prims`, as a float: exact below 2^24).
    pub fn hit_csg<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        let n = &self.csg[node as usize];
        let kids = &self.csg_children[n.children()];
        if n.rule == CsgRule::All {
            return self.hit_all(n, kids, ray, t_min, t_max);
        }
        let miss = L::splat(MISS);
        let mut best = t_max;
        let mut leaf = L::splat(0.0);
        let mut found = L::mask_from_fn(|_| false);
        for (i, child) in kids[..n.surfaces as usize].iter().enumerate() {
            let mut from = t_min;
            for _ in 0..MAX_CROSSINGS {
                let (t, l) = self.hit_child(child, ray, from, best);
                let hit = t.lt(miss);
                if !L::any(hit) {
                    break;
                }
                let p = ray.o.add(ray.d.scale(t));
                let keep = match n.rule {
                    CsgRule::Union => hit,
                    _ => L::and(hit, L::not(self.inside_others(kids, i, p, false))),
                };
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

    /// `hit_csg` for a node under `CsgRule::All`: the same search, cut short by the children's
    /// boxes (exactly: a box the ray misses holds no crossing and no point of the ray).
    ///
    /// Before any shape is tried, each child's box is met with the ray's window: a child whose
    /// surface box is missed has no crossing to search; a subtracted (inverted) child whose
    /// solid box is missed contains every point of the window, so no inside test asks it; a
    /// kept child whose box is missed contains none, so the node is missed.
    fn hit_all<L: Lane>(&self, n: &CsgNode, kids: &[CsgChild], ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
        let miss = L::splat(MISS);
        let (t_min, t_max) = within_box(n.min, n.max, ray, t_min, t_max);
        let mut crossed = Flags::all();
        let mut asked = Flags::all();
        for (j, c) in kids.iter().enumerate().take(Flags::CAPACITY) {
            let meets_surface = meets(&c.surface, ray, t_min, t_max);
            if !meets_surface {
                crossed.clear(j);
                if !c.inverse && c.solid == c.surface {
                    return (miss, L::splat(0.0));
                }
            }
            if c.inverse && !(if c.solid == c.surface { meets_surface } else { meets(&c.solid, ray, t_min, t_max) }) {
                asked.clear(j);
            }
        }
        let window = Window { t_min, t_max, crossed, asked };
        if n.spans && kids.len() <= 8 {
            self.hit_spans::<L, 8>(n, kids, ray, &window)
        } else if n.spans && kids.len() <= SPANS {
            self.hit_spans::<L, SPANS>(n, kids, ray, &window)
        } else {
            let search = |i: usize, from: L, best: L| self.hit_child(&kids[i], ray, from, best);
            let mut rejecters = Rejecters::default();
            let inside = |i: usize, _: L, p: V3<L>, _: L::Mask| {
                let test = |j: usize| self.inside_child(&kids[j], p);
                inside_all_but::<L>(kids.len(), i, test, &window.asked, &mut rejecters)
            };
            self.search_all(n, ray, &window, search, inside)
        }
    }

    /// `hit_all` for a node whose children all have a `span` (boxes, spheres, ellipsoids):
    /// each child's line crossings are found once, and every search of the node's loop picks
    /// from them as the child's `hit` would (`pick_root`, the same bits).
    ///
    /// The spans also answer the inside tests: a point of the ray well within a child's span
    /// is inside it, one well outside is outside; only one within `SPAN_MARGIN` of an end (an
    /// edge, coincident faces) asks the child's own test, whose rounding decides there. For
    /// the kept (not inverted) children that is one comparison with the latest entry and the
    /// earliest exit among them (leaving out the point's own child), however many they are.
    fn hit_spans<L: Lane, const CAP: usize>(
        &self,
        n: &CsgNode,
        kids: &[CsgChild],
        ray: &RayLanes<L>,
        window: &Window<L>,
    ) -> (L, L) {
        let (miss, none) = (L::splat(MISS), L::mask_from_fn(|_| false));
        let mut spans = [(none, miss, miss); CAP];
        let mut entries = Extreme::new(f32::NEG_INFINITY);
        let mut exits = Extreme::new(f32::INFINITY);
        let mut missed = none;
        let mut subtracted = [0usize; CAP];
        let mut count = 0;
        for (j, c) in kids.iter().enumerate() {
            if !(window.crossed.get(j) || window.asked.get(j)) {
                continue;
            }
            let CsgTarget::Leaf(l) = c.target else { unreachable!("a node with spans has leaves only") };
            let (valid, near, far) = self.span_prim(&self.prims[l as usize], ray);
            spans[j] = (valid, near, far);
            if c.inverse {
                if window.asked.get(j) {
                    subtracted[count] = j;
                    count += 1;
                }
            } else {
                missed = L::or(missed, L::not(valid));
                entries.add(j, valid, near, |a, b| a.lt(b));
                exits.add(j, valid, far, |a, b| b.lt(a));
            }
        }
        let search = |i: usize, from: L, best: L| {
            let (valid, near, far) = spans[i];
            let CsgTarget::Leaf(l) = kids[i].target else { unreachable!() };
            (pick_root(valid, near, far, from, best), L::splat(l as f32))
        };
        let scale = ray.o.x.abs().max(ray.o.y.abs()).max(ray.o.z.abs());
        // Child `j`'s verdict on the point at `t`: its span's where that is clear, else its test.
        let ask = |j: usize, t: L, p: V3<L>, m: L| {
            let (valid, near, far) = spans[j];
            let within = L::and(valid, L::and((near + m).lt(t), t.lt(far - m)));
            let beyond = L::or(L::not(valid), L::or(t.lt(near - m), (far + m).lt(t)));
            let inverse = L::mask_from_fn(|_| kids[j].inverse);
            let near_end = L::not(L::or(within, beyond));
            if L::any(near_end) {
                let tested = self.inside_child(&kids[j], p);
                L::or(L::and(near_end, tested), L::and(L::not(near_end), L::xor(within, inverse)))
            } else {
                L::xor(within, inverse)
            }
        };
        let inside = |i: usize, t: L, p: V3<L>, hit: L::Mask| {
            let m = (t.abs() + scale) * L::splat(SPAN_MARGIN);
            let (last_in, first_out) = (entries.without(i), exits.without(i));
            let within = L::and(L::not(missed), L::and((last_in + m).lt(t), t.lt(first_out - m)));
            let beyond = L::or(missed, L::or(t.lt(last_in - m), (first_out + m).lt(t)));
            let mut all = if L::any(L::and(hit, L::not(L::or(within, beyond)))) {
                // Near an end of some kept child's span: each kept child answers on its own.
                let mut all = hit;
                for (j, c) in kids.iter().enumerate() {
                    if j != i && !c.inverse && L::any(all) {
                        all = L::and(all, ask(j, t, p, m));
                    }
                }
                all
            } else {
                L::and(hit, within)
            };
            for &j in &subtracted[..count] {
                if !L::any(all) {
                    break;
                }
                if j != i {
                    all = L::and(all, ask(j, t, p, m));
                }
            }
            all
        };
        self.search_all(n, ray, window, search, inside)
    }

    /// The search of `hit_csg` over an `All` node's surface children (`search(i, from, to)`:
    /// child `i`'s nearest crossing in `(from, to)` and its leaf; `inside(i, t, p, lanes)`:
    /// whether the point `p` at `t` on child `i`'s surface is inside every other child, for
    /// the `lanes` that ask): each child's crossings in order, the first that every other child
    /// contains is its candidate, the nearest candidate wins (the first child's on a tie).
    fn search_all<L: Lane>(
        &self,
        n: &CsgNode,
        ray: &RayLanes<L>,
        window: &Window<L>,
        search: impl Fn(usize, L, L) -> (L, L),
        mut inside: impl FnMut(usize, L, V3<L>, L::Mask) -> L::Mask,
    ) -> (L, L) {
        let miss = L::splat(MISS);
        let mut best = window.t_max;
        let mut leaf = L::splat(0.0);
        let mut found = L::mask_from_fn(|_| false);
        for i in 0..n.surfaces as usize {
            if !window.crossed.get(i) {
                continue;
            }
            let mut from = window.t_min;
            for _ in 0..MAX_CROSSINGS {
                let (t, l) = search(i, from, best);
                let hit = t.lt(miss);
                if !L::any(hit) {
                    break;
                }
                let p = ray.o.add(ray.d.scale(t));
                let keep = L::and(hit, inside(i, t, p, hit));
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

    /// A leaf's `span` (for the kinds `csg::has_span` names).
    #[inline(always)]
    fn span_prim<L: Lane>(&self, p: &PrimRef, ray: &RayLanes<L>) -> (L::Mask, L, L) {
        let i = p.index as usize;
        match p.kind {
            ShapeKind::Box => self.boxes[i].span(ray),
            ShapeKind::Sphere => self.spheres[i].span(ray),
            ShapeKind::Ellipsoid => self.ellipsoids[i].span(ray),
            _ => unreachable!("{:?} has no span", p.kind),
        }
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

/// Whether any lane's window `(t_min, t_max)` meets the box `b` (padded in `t` as
/// `within_box`, so a crossing the box holds is never lost to rounding).
#[inline(always)]
fn meets<L: Lane>(b: &Aabb, ray: &RayLanes<L>, t_min: L, t_max: L) -> bool {
    let (near, far) = within_box(b.min, b.max, ray, t_min, t_max);
    L::any(near.le(far))
}

/// The ray's window through an `All` node and which children it needs: `crossed`, those whose
/// crossings are searched; `asked`, those whose inside tests can reject a point.
struct Window<L: Lane> {
    t_min: L,
    t_max: L,
    crossed: Flags,
    asked: Flags,
}

/// Per lane, the largest (or smallest, by `better`) of some children's values and which child
/// holds it, and the runner-up: the extreme over all of them but any one child.
struct Extreme<L: Lane> {
    best: L,
    holder: L,
    second: L,
}

impl<L: Lane> Extreme<L> {
    fn new(start: f32) -> Extreme<L> {
        Extreme { best: L::splat(start), holder: L::splat(-1.0), second: L::splat(start) }
    }

    /// Child `j`'s value `v` in the lanes `valid`; `better(a, b)`: `b` beats `a`.
    #[inline(always)]
    fn add(&mut self, j: usize, valid: L::Mask, v: L, better: impl Fn(L, L) -> L::Mask) {
        let first = L::and(valid, better(self.best, v));
        let second = L::and(valid, better(self.second, v));
        self.second = L::select(first, self.best, L::select(second, v, self.second));
        self.best = L::select(first, v, self.best);
        self.holder = L::select(first, L::splat(j as f32), self.holder);
    }

    /// The extreme over every child added but `i`.
    #[inline(always)]
    fn without(&self, i: usize) -> L {
        L::select(
            self.holder.lt(L::splat(i as f32)),
            self.best,
            L::select(L::splat(i as f32).lt(self.holder), self.best, self.second),
        )
    }
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

    /// Word `w` of the flags of `count` children (bits past `count` cleared).
    #[inline(always)]
    fn word(&self, w: usize, count: usize) -> u64 {
        let bits = self.0[w];
        if (w + 1) * 64 > count {
            bits & (u64::MAX >> ((w + 1) * 64 - count))
        } else {
            bits
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
#[inline]
fn within_box<L: Lane>(min: Vec3, max: Vec3, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
    let (near, far) = node_slabs(V3::splat(min), V3::splat(max), ray.o, ray.inv);
    let pad = |t: L| t.abs() * L::splat(1e-5) + L::splat(1e-6);
    (t_min.max(near - pad(near)), t_max.min(far + pad(far)))
}
