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
        // Packets reach here through a call that is not inlined (nodes nest), so the 8-wide
        // code would run in the caller's SSE; this copy runs it in 256-bit instructions. AVX2
        // without FMA computes the same bits (as `render::packet`).
        #[cfg(target_arch = "x86_64")]
        if L::WIDTH == 8 && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2, checked just above.
            return unsafe { self.hit_csg_avx2(node, ray, t_min, t_max) };
        }
        self.hit_node(node, ray, t_min, t_max, true)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn hit_csg_avx2<L: Lane>(&self, node: u32, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
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
            return self.hit_all(n, kids, ray, t_min, t_max, direct);
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
    #[inline(always)]
    fn hit_all<L: Lane>(
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
            self.hit_spans::<L, 8>(n, kids, ray, &window, direct)
        } else if n.spans && kids.len() <= SPANS {
            self.hit_spans::<L, SPANS>(n, kids, ray, &window, direct)
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
    #[inline(always)]
    fn hit_spans<L: Lane, const CAP: usize>(
        &self,
        n: &CsgNode,
        kids: &[CsgChild],
        ray: &RayLanes<L>,
        window: &Window<L>,
        direct: bool,
    ) -> (L, L) {
        let (miss, none) = (L::splat(MISS), L::mask_from_fn(|_| false));
        let mut spans = [(none, miss, miss); CAP];
        let mut entries = Extreme::new(f32::NEG_INFINITY);
        let mut exits = Extreme::new(f32::INFINITY);
        let mut missed = none;
        let mut subtracted = [0usize; CAP];
        let mut count = 0;
        let mut inverse_crossed = false;
        for (j, c) in kids.iter().enumerate() {
            if !(window.crossed.get(j) || window.asked.get(j)) {
                continue;
            }
            let CsgTarget::Leaf(l) = c.target else { unreachable!("a node with spans has leaves only") };
            let (valid, near, far) = self.span_prim(&self.prims[l as usize], ray);
            spans[j] = (valid, near, far);
            if c.inverse {
                inverse_crossed |= window.crossed.get(j);
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
        if direct && count == 0 && !inverse_crossed {
            let leaf = |j: usize| match kids[j].target {
                CsgTarget::Leaf(l) => l as f32,
                CsgTarget::Node(_) => unreachable!(),
            };
            if let Some(hit) = hit_kept(&entries, &exits, missed, window, scale, n.surfaces as usize, leaf) {
                #[cfg(test)]
                tests::DIRECT.with(|d| d.set(d.get() + 1));
                return hit;
            }
        }
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
    #[inline(always)]
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
            ShapeKind::Plane => self.half_spaces[i].span(ray),
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

/// `hit_spans`' answer for a node whose every child is kept (no subtracted child meets the
/// window), straight from the latest entry `E` and earliest exit `X` among the children's spans
/// (`second`: the runner-up, `holder`: whose), where every lane's answer is clear; `None` sends
/// the packet to the search.
///
/// The search takes the nearest crossing of a surface child in the window that every other
/// child contains; each verdict depends only on the child and the point, and `hit_spans` gives
/// it from the spans where the point is more than the margin `m(t)` inside or outside them.
/// A lane is clear when that decides its answer and every crossing before it:
/// - some child missed: every crossing is outside it;
/// - entry: `E`, on its holder `h` (a surface), inside the others, is the answer when every
///   other entry lies before `E - m(E)` (outside `h`, as crossings before `E` can only be
///   other children's entries: their exits lie after `E + m`);
/// - exit: every entry at or before the window, `X` on its holder inside the others: no
///   crossing comes before it;
/// - miss: the window is empty; or ends before `E - m(t_max)`; or the spans are disjoint by
///   `m(t_max)` (every point before `E - m` or after `X + m`); or every entry and `X` are
///   behind the window and the next exit is after `X + m(t_max)`.
///
/// `m` grows with `t`, and every crossing in the window lies in `[0, t_max)`, so a bound at
/// `E` or `t_max` holds for every crossing it covers: the same answer as the search, bit for bit.
#[inline(always)]
fn hit_kept<L: Lane>(
    entries: &Extreme<L>,
    exits: &Extreme<L>,
    missed: L::Mask,
    window: &Window<L>,
    scale: L,
    surfaces: usize,
    leaf: impl Fn(usize) -> f32,
) -> Option<(L, L)> {
    let (t_min, t_max) = (window.t_min, window.t_max);
    let margin = |t: L| (t.abs() + scale) * L::splat(SPAN_MARGIN);
    let (e, h, e2) = (entries.best, entries.holder, entries.second);
    let (x, g, x2) = (exits.best, exits.holder, exits.second);
    let same = L::and(g.le(h), h.le(g));
    // The search's verdict on a point at `t` from the latest entry and earliest exit among the
    // other children (`hit_spans`' `inside`, the same expression): clearly inside all of them.
    let inside = |t: L, last_in: L, first_out: L| {
        let m = margin(t);
        L::and(L::not(missed), L::and((last_in + m).lt(t), t.lt(first_out - m)))
    };
    let surface = |holder: L| holder.lt(L::splat(surfaces as f32));
    let in_window = |t: L| L::and(t_min.lt(t), t.lt(t_max));
    let entry =
        L::and(L::and(surface(h), in_window(e)), L::and(inside(e, e2, L::select(same, x2, x)), e2.lt(e - margin(e))));
    let exit = L::and(L::and(L::and(e.le(t_min), surface(g)), in_window(x)), inside(x, L::select(same, e2, e), x2));
    let mw = margin(t_max);
    let miss = L::or(
        L::or(missed, t_max.le(t_min)),
        L::or(L::or(t_max.le(e - mw), (x + mw).lt(e - mw)), L::and(L::and(e.le(t_min), x.le(t_min)), (x + mw).lt(x2))),
    );
    let clear = L::and(L::splat(0.0).le(t_min), L::or(L::or(entry, exit), miss));
    if L::any(L::not(clear)) {
        return None;
    }
    let t = L::select(entry, e, L::select(exit, x, L::splat(MISS)));
    let holder = L::select(entry, h, L::select(exit, g, L::splat(-1.0)));
    let leaf = L::from_fn(|k| {
        let j = holder.get(k);
        if j < 0.0 {
            0.0
        } else {
            leaf(j as usize)
        }
    });
    Some((t, leaf))
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
#[inline(always)]
fn within_box<L: Lane>(min: Vec3, max: Vec3, ray: &RayLanes<L>, t_min: L, t_max: L) -> (L, L) {
    let (near, far) = node_slabs(V3::splat(min), V3::splat(max), ray.o, ray.inv);
    let pad = |t: L| t.abs() * L::splat(1e-5) + L::splat(1e-6);
    (t_min.max(near - pad(near)), t_max.min(far + pad(far)))
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use glam::{DMat4, DVec3, Vec3};

    use crate::accel::packet::Ray8;
    use crate::accel::AccelKind;
    use crate::desc::{CsgOp, InteriorDesc, ObjectDesc, SceneDesc, ShapeDesc, SourceRef, TextureDesc, Transform};
    use crate::lanes::{Lane, F8};
    use crate::ray::{Ray, MISS};
    use crate::scene::build::{Scene, ShapeKind};

    thread_local! {
        /// How many packets or rays `hit_kept` answered on this thread.
        pub static DIRECT: Cell<usize> = const { Cell::new(0) };
    }

    struct Rng(u64);

    impl Rng {
        fn f(&mut self, lo: f32, hi: f32) -> f32 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            lo + (hi - lo) * ((self.0 >> 40) as f32 / (1u64 << 24) as f32)
        }
        fn v(&mut self, lo: f32, hi: f32) -> Vec3 {
            Vec3::new(self.f(lo, hi), self.f(lo, hi), self.f(lo, hi))
        }
    }

    fn object(shape: ShapeDesc, m: DMat4) -> ObjectDesc {
        ObjectDesc {
            shape,
            transform: Transform { matrix: m, inverse: m.inverse() },
            texture: TextureDesc::default(),
            interior_texture: None,
            interior: InteriorDesc::default(),
            no_shadow: false,
            inverse: false,
            hollow: false,
            light_group: None,
            bounded_by: None,
            source: SourceRef::default(),
        }
    }

    /// A CSG of `count` boxes (every other one turned), spheres and ellipsoids around the
    /// origin and a box written twice (coincident faces): `intersection`, `difference` (its
    /// subtracted spheres far away, so no ray near the node meets them) or `clipped_by` (a
    /// sphere clipped by the rest).
    fn scene(r: &mut Rng, op: CsgOp, count: usize) -> Scene {
        let d = |v: Vec3| v.as_dvec3();
        let mut kids: Vec<ObjectDesc> = (0..count)
            .map(|k| match k % 3 {
                0 => {
                    let turn = if k % 2 == 0 { 0.0 } else { r.f(0.0, 1.5) as f64 };
                    let shape = ShapeDesc::Box { corner1: d(r.v(-1.2, -0.6)), corner2: d(r.v(0.6, 1.2)) };
                    object(shape, DMat4::from_rotation_x(turn) * DMat4::from_rotation_y(turn * 0.7))
                }
                1 => {
                    let shape = ShapeDesc::Sphere { center: d(r.v(-0.3, 0.3)), radius: r.f(1.0, 1.5) as f64 };
                    object(shape, DMat4::IDENTITY)
                }
                _ => {
                    let m = DMat4::from_rotation_y(r.f(0.0, 1.5) as f64) * DMat4::from_scale(d(r.v(0.9, 1.6)));
                    object(ShapeDesc::Sphere { center: DVec3::ZERO, radius: 1.0 }, m)
                }
            })
            .collect();
        for _ in 0..2 {
            let shape = ShapeDesc::Box { corner1: DVec3::splat(-0.7), corner2: DVec3::splat(0.7) };
            kids.push(object(shape, DMat4::IDENTITY));
        }
        let far = |c: DVec3| object(ShapeDesc::Sphere { center: c, radius: 1.0 }, DMat4::IDENTITY);
        match op {
            CsgOp::Difference => kids.extend([far(DVec3::X * 30.0), far(DVec3::Y * -30.0)]),
            CsgOp::Clip => {
                kids.insert(0, object(ShapeDesc::Sphere { center: DVec3::ZERO, radius: 1.1 }, DMat4::IDENTITY))
            }
            _ => {}
        }
        let node = object(ShapeDesc::Csg { op, children: kids }, DMat4::IDENTITY);
        let desc = SceneDesc { objects: vec![node], ..SceneDesc::default() };
        Scene::build(&desc, DVec3::ZERO, AccelKind::Bvh)
    }

    /// `hit_kept`'s answers against the search's, bit for bit (distance and leaf), for one f32
    /// ray, eight lanes and f64: rays from afar, rays leaving the surface (shadow rays), rays
    /// through edges and corners, coincident faces, windows that cut the node.
    #[test]
    fn the_direct_answer_is_the_searchs() {
        let r = &mut Rng(0xC59);
        let before = DIRECT.with(Cell::get);
        let (mut rays, mut hits) = (0, 0);
        for case in 0..24 {
            let op = [CsgOp::Intersection, CsgOp::Difference, CsgOp::Clip][case % 3];
            let scene = scene(r, op, [2, 7, 64, 9][case % 3 + (case / 3) % 2]);
            let prim = scene.prims.iter().find(|p| p.kind == ShapeKind::Csg).expect("a node");
            let n = &scene.csg[prim.index as usize];
            assert!(n.spans, "{op:?}: leaves with spans only");
            for k in 0..400 {
                let origin = r.v(-1.0, 1.0).normalize() * r.f(2.0, 9.0);
                let target = match k % 4 {
                    // Corners and edges of the shared box (grazing rays).
                    0 => Vec3::new(0.7, 0.7, r.f(-0.7, 0.7)),
                    1 => Vec3::splat(0.7) * Vec3::new(1.0, -1.0, 1.0),
                    _ => r.v(-1.0, 1.0),
                };
                let mut ray = Ray::new(origin, (target - origin).normalize());
                let (t, _) = scene.hit_node(prim.index, &ray.lanes(), 0.0, f32::INFINITY, false);
                if k % 5 == 0 && t != MISS {
                    // A shadow ray from the surface, out in a random direction.
                    ray = Ray::new(ray.at(t), r.v(-1.0, 1.0).normalize());
                }
                let (lo, hi) = if k % 7 == 0 { (r.f(0.0, 4.0), r.f(2.0, 9.0)) } else { (0.0, f32::INFINITY) };
                let want = scene.hit_node(prim.index, &ray.lanes(), lo, hi, false);
                let got = scene.hit_node(prim.index, &ray.lanes(), lo, hi, true);
                assert_eq!((got.0.to_bits(), got.1.to_bits()), (want.0.to_bits(), want.1.to_bits()), "{op:?} {ray:?}");
                let wide = scene.hit_node(prim.index, &ray.lanes_f64(), lo as f64, hi as f64, true);
                let narrow = scene.hit_node(prim.index, &ray.lanes_f64(), lo as f64, hi as f64, false);
                assert_eq!(
                    (wide.0.to_bits(), wide.1.to_bits()),
                    (narrow.0.to_bits(), narrow.1.to_bits()),
                    "f64 {ray:?}"
                );
                let packet = Ray8::from_fn(|i| {
                    let o = if i == 3 { ray.origin } else { ray.origin + Vec3::splat(i as f32 * 0.01) };
                    (o, ray.dir, ray.inv_dir)
                });
                let (t8, leaf8) = scene.hit_csg(prim.index, &packet, F8::splat(lo), F8::splat(hi));
                assert_eq!((t8.0[3].to_bits(), leaf8.0[3].to_bits()), (want.0.to_bits(), want.1.to_bits()), "lane");
                rays += 1;
                hits += (want.0 != MISS) as usize;
            }
        }
        let direct = DIRECT.with(Cell::get) - before;
        assert!(rays > 9000 && hits > 1000 && direct > 3000, "{rays} rays, {hits} hits, {direct} answered directly");
    }
}
