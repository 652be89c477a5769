//! CSG nodes whose children all have a `span` (boxes, spheres, ellipsoids, planes: one pair of
//! line crossings each): the crossings are found once per ray and answer both the search and
//! the inside tests, and a node of kept children takes its answer from the latest entry and
//! earliest exit (`hit_kept`). The same hits and leaves as the general search (the tests below
//! compare them), in fewer shape tests.

use super::{Children, Window};
use crate::geometry::Shape;
use crate::lanes::{Lane, V3};
use crate::ray::{pick_root, RayLanes, MISS};
use crate::scene::build::{PrimRef, Scene, ShapeKind};
use crate::scene::csg::{CsgChild, CsgNode, CsgTarget};

/// The most children whose spans `hit_spans` keeps (on the stack); a larger node searches each
/// child's shape instead.
pub(super) const SPANS: usize = 64;

/// How near (relative to `t` and the ray's origin) a point may lie to an end of a child's span
/// before the child's own inside test decides: far above the few ulps the span and the test
/// each round by, so both agree wherever the span decides.
const SPAN_MARGIN: f32 = 1e-4;

impl Scene {
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
    pub(super) fn hit_spans<L: Lane, const CAP: usize>(
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
        let scale = ray.o.x.abs().max(ray.o.y.abs()).max(ray.o.z.abs());
        // A node of many kept children whose spans already leave every lane clearly missed
        // (`apart`) stops there: later children only narrow the spans' overlap, and
        // `hit_kept` would answer a miss in every lane (the same expression).
        let stops =
            direct && CAP > 8 && !L::any(L::not(L::splat(0.0).le(window.t_min))) && kids.iter().all(|c| !c.inverse);
        let mw = (window.t_max.abs() + scale) * L::splat(SPAN_MARGIN);
        let mut kept = 0;
        // The children to span: those searched or asked (at most `SPANS`, one word of flags).
        let mut live =
            if kids.is_empty() { 0 } else { window.crossed.word(0, kids.len()) | window.asked.word(0, kids.len()) };
        while live != 0 {
            let j = live.trailing_zeros() as usize;
            live &= live - 1;
            let c = &kids[j];
            let CsgTarget::Leaf(l) = c.target else { unreachable!("a node with spans has leaves only") };
            let (valid, near, far) = self.span_prim(&self.prims[l as usize], ray);
            spans[j] = (valid, near, far);
            if c.inverse {
                inverse_crossed |= window.crossed.get(j);
                // A child no lane's line meets holds none of its points: every lane is outside
                // it, so inside its inverse, and asking it changes nothing (`ask` answers so).
                if window.asked.get(j) && L::any(valid) {
                    subtracted[count] = j;
                    count += 1;
                }
            } else {
                missed = L::or(missed, L::not(valid));
                entries.add(j, valid, near, |a, b| a.lt(b));
                exits.add(j, valid, far, |a, b| b.lt(a));
                kept += 1;
                if stops && kept % 8 == 0 && j + 1 < kids.len() {
                    let apart = apart(entries.best, exits.best, missed, window, mw);
                    if !L::any(L::not(apart)) {
                        #[cfg(test)]
                        tests::STOPPED.with(|d| d.set(d.get() + 1));
                        return (miss, L::splat(0.0));
                    }
                }
            }
        }
        if direct && count == 0 && !inverse_crossed {
            // A node with spans holds leaves only, added one after the other (`Scene::build`):
            // child `j`'s leaf is the first one's plus `j`.
            let first = match kids.first() {
                Some(CsgChild { target: CsgTarget::Leaf(l), .. }) => *l,
                _ => 0,
            };
            debug_assert!(kids.iter().enumerate().all(|(j, c)| c.target == CsgTarget::Leaf(first + j as u32)));
            if let Some(hit) = hit_kept(&entries, &exits, missed, window, scale, n.surfaces as usize, first as f32) {
                #[cfg(test)]
                tests::DIRECT.with(|d| d.set(d.get() + 1));
                return hit;
            }
        }
        let mut children = SpanChildren {
            scene: self,
            kids,
            spans: &spans,
            entries: &entries,
            exits: &exits,
            missed,
            subtracted: &subtracted[..count],
            scale,
        };
        self.search_all(n, ray, window, &mut children)
    }

    /// `inside_prim` for the kinds `csg::has_span` names: the same tests, without the
    /// dispatch over every kind (whose inlined tests bloated the span nodes' code and frame).
    #[inline(always)]
    fn inside_span_prim<L: Lane>(&self, p: &PrimRef, q: V3<L>) -> L::Mask {
        let i = p.index as usize;
        match p.kind {
            ShapeKind::Box => self.boxes[i].inside(q),
            ShapeKind::Sphere => self.spheres[i].inside(q),
            ShapeKind::Ellipsoid => self.ellipsoids[i].inside(q),
            ShapeKind::Plane => self.half_spaces[i].inside(q),
            _ => unreachable!("{:?} has no span", p.kind),
        }
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
}

/// The children of a node with spans, as `Scene::search_all` asks them: crossings picked from
/// the spans (`pick_root`, the bits of the child's own `hit`), and inside tests answered by the
/// spans wherever they are clear.
///
/// The spans answer the inside tests: a point of the ray well within a child's span is inside
/// it, one well outside is outside; only one within `SPAN_MARGIN` of an end (an edge,
/// coincident faces) asks the child's own test, whose rounding decides there. For the kept
/// (not inverted) children that is one comparison with the latest entry and the earliest exit
/// among them (leaving out the point's own child), however many they are.
struct SpanChildren<'a, L: Lane> {
    scene: &'a Scene,
    kids: &'a [CsgChild],
    /// Per child: the lanes whose line meets it, and where it enters and leaves.
    spans: &'a [(L::Mask, L, L)],
    entries: &'a Extreme<L>,
    exits: &'a Extreme<L>,
    /// Lanes that miss some kept child's span.
    missed: L::Mask,
    /// The subtracted children some lane's line meets.
    subtracted: &'a [usize],
    /// The ray origin's largest coordinate, for the margin.
    scale: L,
}

impl<L: Lane> SpanChildren<'_, L> {
    /// Child `j`'s verdict on the point `p` at `t`: its span's where that is clear (`m` from
    /// either end), else its own test.
    #[inline(always)]
    fn ask(&self, j: usize, t: L, p: V3<L>, m: L) -> L::Mask {
        let (valid, near, far) = self.spans[j];
        let within = L::and(valid, L::and((near + m).lt(t), t.lt(far - m)));
        let beyond = L::or(L::not(valid), L::or(t.lt(near - m), (far + m).lt(t)));
        let inverse = L::mask_from_fn(|_| self.kids[j].inverse);
        let near_end = L::not(L::or(within, beyond));
        if L::any(near_end) {
            let c = &self.kids[j];
            let CsgTarget::Leaf(l) = c.target else { unreachable!("a node with spans has leaves only") };
            let tested = L::xor(self.scene.inside_span_prim(&self.scene.prims[l as usize], p), inverse);
            L::or(L::and(near_end, tested), L::and(L::not(near_end), L::xor(within, inverse)))
        } else {
            L::xor(within, inverse)
        }
    }
}

impl<L: Lane> Children<L> for SpanChildren<'_, L> {
    #[inline(always)]
    fn search(&mut self, i: usize, from: L, best: L) -> (L, L) {
        let (valid, near, far) = self.spans[i];
        let CsgTarget::Leaf(l) = self.kids[i].target else { unreachable!("a node with spans has leaves only") };
        (pick_root(valid, near, far, from, best), L::splat(l as f32))
    }

    #[inline(always)]
    fn inside(&mut self, i: usize, t: L, p: V3<L>, hit: L::Mask) -> L::Mask {
        let m = (t.abs() + self.scale) * L::splat(SPAN_MARGIN);
        let (last_in, first_out) = (self.entries.without(i), self.exits.without(i));
        let within = L::and(L::not(self.missed), L::and((last_in + m).lt(t), t.lt(first_out - m)));
        let beyond = L::or(self.missed, L::or(t.lt(last_in - m), (first_out + m).lt(t)));
        let mut all = if L::any(L::and(hit, L::not(L::or(within, beyond)))) {
            // Near an end of some kept child's span: each kept child answers on its own.
            let mut all = hit;
            for (j, c) in self.kids.iter().enumerate() {
                if j != i && !c.inverse && L::any(all) {
                    all = L::and(all, self.ask(j, t, p, m));
                }
            }
            all
        } else {
            L::and(hit, within)
        };
        for &j in self.subtracted {
            if !L::any(all) {
                break;
            }
            if j != i {
                all = L::and(all, self.ask(j, t, p, m));
            }
        }
        all
    }
}

/// `hit_spans`' answer for a node whose every child is kept (no subtracted child meets the
/// window), straight from the latest entry `E` and earliest exit `X` among the children's spans
/// (`second`: the runner-up, `holder`: whose), where every lane's answer is clear; `None` sends
/// the packet to the search. Child `j`'s leaf is `first_leaf + j`.
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
    first_leaf: f32,
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
    let miss = L::or(apart(e, x, missed, window, mw), L::and(L::and(e.le(t_min), x.le(t_min)), (x + mw).lt(x2)));
    let clear = L::and(L::splat(0.0).le(t_min), L::or(L::or(entry, exit), miss));
    if L::any(L::not(clear)) {
        return None;
    }
    let t = L::select(entry, e, L::select(exit, x, L::splat(MISS)));
    let holder = L::select(entry, h, L::select(exit, g, L::splat(-1.0)));
    // Child `j`'s leaf is `first_leaf + j` (exact: both below 2^24); none (-1) answers 0.
    // Lane arithmetic, not a function of each lane's holder, which was compiled out of line.
    let zero = L::splat(0.0);
    let leaf = L::select(zero.le(holder), holder + L::splat(first_leaf), zero);
    Some((t, leaf))
}

/// `hit_kept`'s lanes that miss whatever comes before and after in the window, from the latest
/// entry `e` and earliest exit `x` of the kept children (`missed`: lanes that miss one; `mw`:
/// the margin at `t_max`): the window is empty, or ends before `e - mw`, or the spans are
/// disjoint by `mw`. Each only grows as more children narrow `e` and `x` (rounding is
/// monotonic), so a lane apart among some children is apart among all.
#[inline(always)]
fn apart<L: Lane>(e: L, x: L, missed: L::Mask, window: &Window<L>, mw: L) -> L::Mask {
    let (t_min, t_max) = (window.t_min, window.t_max);
    L::or(L::or(missed, t_max.le(t_min)), L::or(t_max.le(e - mw), (x + mw).lt(e - mw)))
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

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use glam::{DMat4, DVec3, Vec3};

    use crate::accel::packet::Ray8;
    use crate::accel::AccelKind;
    use crate::desc::{CsgOp, InteriorDesc, ObjectDesc, SceneDesc, ShapeDesc, SourceRef, Transform};
    use crate::lanes::{Lane, F8};
    use crate::ray::{Ray, MISS};
    use crate::scene::build::{Scene, ShapeKind};

    thread_local! {
        /// How many packets or rays `hit_kept` answered on this thread.
        pub static DIRECT: Cell<usize> = const { Cell::new(0) };
        /// How many packets or rays `hit_spans` answered before the last child's span.
        pub static STOPPED: Cell<usize> = const { Cell::new(0) };
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
            transform: Transform { matrix: m, inverse: m.inverse() }.into(),
            texture: Default::default(),
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
        let stopped_before = STOPPED.with(Cell::get);
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
        // Both paths are exercised, each compared bit for bit above. Some calls now end before
        // `hit_kept` (an empty window, or `apart` among the first children), which leaves about
        // 3000 answered directly where it was over 3000.
        let direct = DIRECT.with(Cell::get) - before;
        assert!(rays > 9000 && hits > 1000 && direct > 2500, "{rays} rays, {hits} hits, {direct} answered directly");
        let stopped = STOPPED.with(Cell::get) - stopped_before;
        assert!(stopped > 100, "{stopped} answered before the last child");
    }

    /// A node of many children culls them by groups (`CsgGroup`) before one by one: the same
    /// answers, bit for bit, as the same node culling one by one, for single rays, packets and
    /// f64, from afar and cutting through.
    #[test]
    fn grouped_children_cull_as_one_by_one() {
        // `scene`'s difference subtracts its overlapping children, leaving nothing: a box dented
        // by small spheres on and around its top instead.
        let dented = |r: &mut Rng| {
            let mut kids =
                vec![object(ShapeDesc::Box { corner1: DVec3::splat(-1.0), corner2: DVec3::ONE }, DMat4::IDENTITY)];
            for _ in 0..40 {
                let c = r.v(-1.2, 1.2) * Vec3::new(1.0, 0.3, 1.0) + Vec3::Y;
                kids.push(object(
                    ShapeDesc::Sphere { center: c.as_dvec3(), radius: r.f(0.1, 0.3) as f64 },
                    DMat4::IDENTITY,
                ));
            }
            let node = object(ShapeDesc::Csg { op: CsgOp::Difference, children: kids }, DMat4::IDENTITY);
            let desc = SceneDesc { objects: vec![node], ..SceneDesc::default() };
            Scene::build(&desc, DVec3::ZERO, AccelKind::Bvh)
        };
        // (`clipped_by` is an intersection whose first child alone has surfaces; `scene`'s, of
        // 64 children, holds nothing.)
        for (case, op) in [CsgOp::Intersection, CsgOp::Difference].into_iter().enumerate() {
            let seed = 0x6A0 + case as u64;
            let build = |r: &mut Rng| if op == CsgOp::Difference { dented(r) } else { scene(r, op, 64) };
            let grouped = build(&mut Rng(seed));
            let mut plain = build(&mut Rng(seed));
            assert!(grouped.csg.iter().any(|n| n.groups > 1), "{op:?}: grouped");
            for n in &mut plain.csg {
                n.groups = 0;
            }
            let prim = grouped.prims.iter().find(|p| p.kind == ShapeKind::Csg).expect("a node");
            let r = &mut Rng(seed ^ 0x55);
            let (mut hits, mut rays) = (0, 0);
            for k in 0..600 {
                let origin = r.v(-1.0, 1.0).normalize() * r.f(1.0, 9.0);
                let target = if k % 3 == 0 { r.v(-3.0, 3.0) } else { r.v(-1.0, 1.0) };
                let ray = Ray::new(origin, (target - origin).normalize());
                let (lo, hi) = if k % 7 == 0 { (r.f(0.0, 4.0), r.f(2.0, 9.0)) } else { (0.0, f32::INFINITY) };
                for direct in [false, true] {
                    let want = plain.hit_node(prim.index, &ray.lanes(), lo, hi, direct);
                    let got = grouped.hit_node(prim.index, &ray.lanes(), lo, hi, direct);
                    assert_eq!(
                        (got.0.to_bits(), got.1.to_bits()),
                        (want.0.to_bits(), want.1.to_bits()),
                        "{op:?} {ray:?}"
                    );
                    let want = plain.hit_node(prim.index, &ray.lanes_f64(), lo as f64, hi as f64, direct);
                    let got = grouped.hit_node(prim.index, &ray.lanes_f64(), lo as f64, hi as f64, direct);
                    assert_eq!((got.0.to_bits(), got.1.to_bits()), (want.0.to_bits(), want.1.to_bits()), "f64 {ray:?}");
                }
                let packet = Ray8::from_fn(|i| {
                    let o = ray.origin + Vec3::splat(i as f32 * 0.03);
                    (o, ray.dir, ray.inv_dir)
                });
                let want = plain.hit_csg(prim.index, &packet, F8::splat(lo), F8::splat(hi));
                let got = grouped.hit_csg(prim.index, &packet, F8::splat(lo), F8::splat(hi));
                for i in 0..8 {
                    assert_eq!(
                        (got.0 .0[i].to_bits(), got.1 .0[i].to_bits()),
                        (want.0 .0[i].to_bits(), want.1 .0[i].to_bits())
                    );
                }
                rays += 1;
                hits += (want.0 .0[0] != MISS) as usize;
            }
            assert!(hits > 50 && hits < rays, "{op:?}: {hits} of {rays} rays hit");
        }
    }
}
