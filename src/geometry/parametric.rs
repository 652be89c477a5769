//! POV-Ray's `parametric` (3.4.5.x): the surface `(x(u, v), y(u, v), z(u, v))` over a
//! rectangle of (u, v), clipped to its `contained_by` box or sphere. A shell: nothing is
//! inside it.
//!
//! Built once: the (u, v) rectangle is cut into `GRID`² cells, each bounded by the box of its
//! sampled points grown by how far the surface may bulge between them (`max_gradient` times
//! half the cell's (u, v) size, as POV-Ray's documentation defines the gradient), and the
//! cells are grouped four by four into a quadtree of boxes. A ray walks the tree to the cells
//! it meets, nearest first, and solves `P(u, v) = o + t·d` there by Newton's method in f64,
//! derivatives by forward differences, its first step taken on the cell's tangent plane kept
//! from the build: a cell whose plane puts the crossing outside it (by more than `OWN`) is
//! passed over, as its neighbour holding the root is a candidate too; a solution must stay inside the (u, v) rectangle, the
//! container and within `accuracy`. The normal at a point finds its (u, v) again the same
//! way (by least squares from the cells whose boxes hold the point).

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::{Arc, Mutex};

use glam::{DAffine3, DVec2, DVec3, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::{affine_f32, transformed_bounds};
use crate::desc::{Container, ParametricParams};
use crate::function::Program;

/// Cells along u and along v (a power of two, for the quadtree).
const GRID: usize = 128;
/// Newton steps per candidate cell: from a cell's centre a solution in it converges in four
/// or five.
const NEWTON_STEPS: usize = 8;

/// How far (in cells) Newton's method may wander from its cell before it is given up: that
/// solution belongs to another candidate.
const WANDER: f64 = 2.0;

/// How far (in cells) past its own cell the ray's crossing of a cell's tangent plane may lie
/// for Newton's method to be started there. A root lies in some cell, whose box the ray meets
/// before it (the boxes bound the surface), and that cell's tangent plane puts the crossing
/// within it up to the plane's error; the neighbours, which would converge to the same root,
/// are passed over.
const OWN: f64 = 0.5;

#[derive(Clone, Copy, Debug)]
struct Node {
    min: DVec3,
    max: DVec3,
}

#[derive(Clone, Debug)]
pub struct Parametric {
    pub frame: BoxFrame,
    functions: [Program; 3],
    container: Container,
    uv: ParametricParams,
    tree: Arc<Tree>,
    pub min: Vec3,
    pub max: Vec3,
}

/// What a parametric builds once from its functions and (u, v) rectangle: shared by every
/// copy of it (`shared_tree`; scenes/kernels/parametric.pov places 64).
#[derive(Debug)]
struct Tree {
    /// Quadtree levels, coarsest first: level `k` has `2^k × 2^k` boxes, row-major in v.
    levels: Vec<Vec<Node>>,
    /// Each leaf cell's point at its centre and the tangents there (`point_and_tangents`): its
    /// tangent plane, the first step of Newton's method from the centre.
    planes: Vec<[DVec3; 3]>,
}

/// The tree of `functions` over `uv`, built by `build` unless a parametric with the same ones
/// built it before. Built under the lock: a copy waits for the first rather than build it again
/// (`build` runs no parallel work that could need the waiting thread).
fn shared_tree(functions: &[Program; 3], uv: ParametricParams, build: impl FnOnce() -> Tree) -> Arc<Tree> {
    type Entry = ([Program; 3], ParametricParams, Arc<Tree>);
    /// Distinct trees kept; the oldest goes first.
    const KEPT: usize = 16;
    static CACHE: Mutex<Vec<Entry>> = Mutex::new(Vec::new());
    // A poisoned lock only means another build panicked: the entries are whole.
    let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, _, tree)) = cache.iter().find(|(f, p, _)| f == functions && *p == uv) {
        return tree.clone();
    }
    let tree = Arc::new(build());
    if cache.len() >= KEPT {
        cache.remove(0);
    }
    cache.push((functions.clone(), uv, tree.clone()));
    tree
}

impl Parametric {
    pub fn new(
        render_from_object: DAffine3,
        functions: [Program; 3],
        container: Container,
        uv: ParametricParams,
    ) -> Parametric {
        let mut p = Parametric {
            frame: frame_for(affine_f32(&render_from_object)),
            functions,
            container,
            uv,
            tree: Arc::new(Tree { levels: Vec::new(), planes: Vec::new() }),
            min: Vec3::ZERO,
            max: Vec3::ZERO,
        };
        p.tree = shared_tree(&p.functions, uv, || p.build_tree());
        // The surface's box, cut to the container's.
        let (clo, chi) = container.bounds();
        let root = p.tree.levels[0][0];
        let (lo, hi) = (root.min.max(clo), root.max.min(chi));
        let (lo, hi) = if lo.cmple(hi).all() { (lo, hi) } else { (DVec3::ZERO, DVec3::ZERO) };
        let xf = affine_f32(&render_from_object);
        let (min, max) = transformed_bounds(&xf, lo.as_vec3(), hi.as_vec3());
        let pad = (max - min).max(min.abs().max(max.abs())) * 4.0 * f32::EPSILON;
        p.min = min - pad;
        p.max = max + pad;
        p
    }

    /// The cells' boxes and tangent planes, from the functions and the (u, v) rectangle alone.
    fn build_tree(&self) -> Tree {
        let uv = self.uv;
        let cell = (uv.hi - uv.lo) / GRID as f64;
        let mut leaves = Vec::with_capacity(GRID * GRID);
        let planes =
            (0..GRID * GRID).map(|k| <[DVec3; 3]>::from(self.point_and_tangents(self.cell_centre(k)))).collect();
        for j in 0..GRID {
            for i in 0..GRID {
                let base = uv.lo + cell * DVec2::new(i as f64, j as f64);
                let (mut min, mut max) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
                for (a, b) in (0..9).map(|k| (k % 3, k / 3)) {
                    let q = self.point(base + cell * DVec2::new(a as f64, b as f64) * 0.5);
                    min = min.min(q);
                    max = max.max(q);
                }
                // Every (u, v) of the cell is within a quarter cell (along each axis) of a
                // sample, and no coordinate changes faster than max_gradient along u or v. A
                // max_gradient set too low must not open holes: at least a twentieth of the
                // samples' own spread too.
                let pad = (uv.max_gradient * 0.25 * (cell.x.abs() + cell.y.abs())).max(0.05 * (max - min).length())
                    + uv.accuracy;
                leaves.push(Node { min: min - pad, max: max + pad });
            }
        }
        let mut levels = vec![leaves];
        let mut n = GRID;
        while n > 1 {
            let fine = &levels[levels.len() - 1];
            let half = n / 2;
            let coarse: Vec<Node> = (0..half * half)
                .map(|k| {
                    let (i, j) = (k % half, k / half);
                    let kids = [(2 * i, 2 * j), (2 * i + 1, 2 * j), (2 * i, 2 * j + 1), (2 * i + 1, 2 * j + 1)];
                    kids.iter().fold(Node { min: DVec3::INFINITY, max: DVec3::NEG_INFINITY }, |b, &(a, c)| {
                        let k = &fine[c * n + a];
                        Node { min: b.min.min(k.min), max: b.max.max(k.max) }
                    })
                })
                .collect();
            levels.push(coarse);
            n = half;
        }
        levels.reverse();
        Tree { levels, planes }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    fn point(&self, uv: DVec2) -> DVec3 {
        let a = [uv.x, uv.y, 0.0];
        DVec3::new(self.functions[0].eval(&a), self.functions[1].eval(&a), self.functions[2].eval(&a))
    }

    /// ∂P/∂u and ∂P/∂v by central differences.
    fn tangents(&self, uv: DVec2) -> (DVec3, DVec3) {
        let h = (self.uv.hi - self.uv.lo).abs() * 1e-6;
        let du = (self.point(uv + DVec2::new(h.x, 0.0)) - self.point(uv - DVec2::new(h.x, 0.0))) / (2.0 * h.x);
        let dv = (self.point(uv + DVec2::new(0.0, h.y)) - self.point(uv - DVec2::new(0.0, h.y))) / (2.0 * h.y);
        (du, dv)
    }

    /// `P(uv)` with ∂P/∂u and ∂P/∂v by forward differences from it, for Newton's method,
    /// which only needs them roughly: the three points in one pass of each function's code
    /// (`Program::eval_lanes`, a fourth lane idle).
    fn point_and_tangents(&self, uv: DVec2) -> (DVec3, DVec3, DVec3) {
        let h = (self.uv.hi - self.uv.lo).abs() * 1e-7;
        let args = [[uv.x, uv.x + h.x, uv.x, uv.x], [uv.y, uv.y, uv.y + h.y, uv.y], [0.0; 4]];
        let [x, y, z] = [0, 1, 2].map(|k| self.functions[k].eval_lanes(&args));
        let at = |i: usize| DVec3::new(x[i], y[i], z[i]);
        let p = at(0);
        (p, (at(1) - p) / h.x, (at(2) - p) / h.y)
    }

    fn in_domain(&self, uv: DVec2) -> bool {
        let (lo, hi) = (self.uv.lo.min(self.uv.hi), self.uv.lo.max(self.uv.hi));
        let e = (hi - lo) * 1e-9;
        uv.cmpge(lo - e).all() && uv.cmple(hi + e).all()
    }

    /// The centre (u, v) of leaf cell `k`.
    fn cell_centre(&self, k: usize) -> DVec2 {
        let cell = (self.uv.hi - self.uv.lo) / GRID as f64;
        self.uv.lo + cell * DVec2::new((k % GRID) as f64 + 0.5, (k / GRID) as f64 + 0.5)
    }

    /// The leaf cells whose boxes the ray meets in `(t_min, t_max)`, with the entry `t`,
    /// nearest first (`Candidates`).
    fn candidates(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64) -> Candidates<'_> {
        let mut walk = Candidates { tree: &self.tree, o, inv: d.recip(), t_min, t_max, heap: BinaryHeap::new() };
        walk.push(0, 0, 0);
        walk
    }

    pub fn solve(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64) -> Option<f64> {
        let (enter, exit) = self.container_span(o, d)?;
        let (t_lo, t_hi) = (t_min.max(enter), t_max.min(exit));
        if t_lo.partial_cmp(&t_hi) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        let len = d.length();
        let mut best = t_hi;
        let mut found = false;
        let cell = ((self.uv.hi - self.uv.lo) / GRID as f64).abs();
        for (t_enter, k) in self.candidates(o, d, t_lo, t_hi) {
            if t_enter >= best {
                break;
            }
            let centre = self.cell_centre(k);
            // Newton's first step from the centre: where the ray crosses the tangent plane.
            let [p, du, dv] = self.tree.planes[k];
            let m = glam::DMat3::from_cols(du, dv, -d);
            let det = m.determinant();
            let first = if det.abs() < 1e-300 || !det.is_finite() {
                None
            } else {
                let s = m.inverse() * (o - p);
                let uv = centre + DVec2::new(s.x, s.y);
                // Past its own cell (and the plane's error): another candidate's root.
                if !uv.is_finite() || !s.z.is_finite() || (uv - centre).abs().cmpgt(cell * (0.5 + OWN)).any() {
                    continue;
                }
                Some((uv, s.z))
            };
            let (uv, t) = first.unwrap_or((centre, t_enter));
            let Some((t, _)) = self.newton(o, d, centre, uv, t, WANDER) else { continue };
            // Past the ray's own start by more than the accuracy: not the surface it left.
            if t > t_lo && t < best && (t - t_min) * len > self.uv.accuracy * 0.5 {
                best = t;
                found = true;
            }
        }
        found.then_some(best)
    }

    fn container_span(&self, o: DVec3, d: DVec3) -> Option<(f64, f64)> {
        match self.container {
            Container::Box { min, max } => {
                let inv = d.recip();
                let (a, b) = ((min - o) * inv, (max - o) * inv);
                let (lo, hi) = (a.min(b).max_element(), a.max(b).min_element());
                (lo <= hi).then_some((lo, hi))
            }
            Container::Sphere { center, radius } => {
                let oc = o - center;
                let (a, b, c) = (d.dot(d), oc.dot(d), oc.dot(oc) - radius * radius);
                let disc = b * b - a * c;
                (disc >= 0.0 && a > 0.0).then(|| ((-b - disc.sqrt()) / a, (-b + disc.sqrt()) / a))
            }
        }
    }

    /// Newton's method on `P(u, v) − (o + t·d) = 0` from `(uv, t)`.
    /// `start` is the centre of the cell it began in, the one it may not wander far from.
    fn newton(&self, o: DVec3, d: DVec3, start: DVec2, mut uv: DVec2, mut t: f64, wander: f64) -> Option<(f64, DVec2)> {
        let reach = ((self.uv.hi - self.uv.lo) / GRID as f64).abs() * (0.5 + wander);
        for _ in 0..NEWTON_STEPS {
            let (p, du, dv) = self.point_and_tangents(uv);
            let r = p - (o + t * d);
            // [du dv −d]·(Δu, Δv, Δt) = −r, by Cramer's rule.
            let m = glam::DMat3::from_cols(du, dv, -d);
            let det = m.determinant();
            if det.abs() < 1e-300 || !det.is_finite() {
                return None;
            }
            let step = m.inverse() * -r;
            uv += DVec2::new(step.x, step.y);
            t += step.z;
            if !uv.is_finite() || !t.is_finite() || (uv - start).abs().cmpgt(reach).any() {
                return None;
            }
            if step.length() < 1e-10 * (1.0 + t.abs()) {
                break;
            }
        }
        let p = o + t * d;
        let ok = self.in_domain(uv) && (self.point(uv) - p).length() < self.uv.accuracy && self.container.contains(p);
        ok.then_some((t, uv))
    }

    /// The (u, v) of a point on the surface: least squares from each cell whose box holds it
    /// (found through the quadtree), the best fit kept; an exact one ends the search.
    fn uv_at(&self, q: DVec3) -> DVec2 {
        let holds = |n: &Node| q.cmpge(n.min).all() && q.cmple(n.max).all();
        let mut best = (f64::INFINITY, self.cell_centre(0));
        let last = self.tree.levels.len() - 1;
        let mut stack = vec![(0usize, 0usize)];
        while let Some((level, k)) = stack.pop() {
            if !holds(&self.tree.levels[level][k]) {
                continue;
            }
            if level < last {
                let n = 1usize << level;
                let (i, j) = (k % n, k / n);
                for (a, b) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    stack.push((level + 1, (2 * j + b) * 2 * n + 2 * i + a));
                }
                continue;
            }
            let uv = self.fit(q, self.cell_centre(k));
            if uv.is_finite() && self.in_domain(uv) {
                let e = (self.point(uv) - q).length();
                if e < best.0 {
                    best = (e, uv);
                    if e < self.uv.accuracy * 1e-3 {
                        break;
                    }
                }
            }
        }
        best.1
    }

    /// Gauss–Newton from `uv` towards the (u, v) whose point is nearest `q`.
    fn fit(&self, q: DVec3, mut uv: DVec2) -> DVec2 {
        for _ in 0..NEWTON_STEPS {
            let r = self.point(uv) - q;
            let (du, dv) = self.tangents(uv);
            // The normal equations of [du dv]·Δ = −r.
            let (a, b, c) = (du.dot(du), du.dot(dv), dv.dot(dv));
            let det = a * c - b * b;
            if det.abs() < 1e-300 {
                break;
            }
            let (ru, rv) = (-du.dot(r), -dv.dot(r));
            let step = DVec2::new(c * ru - b * rv, a * rv - b * ru) / det;
            uv += step;
            if !uv.is_finite() || step.length() < 1e-12 {
                break;
            }
        }
        uv
    }

    fn normal_object(&self, q: DVec3) -> DVec3 {
        let (du, dv) = self.tangents(self.uv_at(q));
        du.cross(dv)
    }
}

shape_solved_in_f64!(Parametric, normal: normal_object, inside: none);

/// The leaf cells a ray's box tests admit, in order of their entry `t`, found lazily: the
/// quadtree is walked best first (a child's box lies within its parent's, so it is entered no
/// sooner), and `solve` stops asking once a cell starts past its nearest root. Walking every
/// admitted leaf and sorting them all first was more than half of
/// scenes/kernels/parametric.pov's frame. Equal entries (every cell around a shadow ray's
/// origin starts at `t_min`) come in the order that walk and its stable sort gave them (depth
/// first, children (1, 1), (0, 1), (1, 0), (0, 0)), so `solve` takes the same roots.
struct Candidates<'a> {
    tree: &'a Tree,
    o: DVec3,
    inv: DVec3,
    t_min: f64,
    t_max: f64,
    /// Boxes admitted and not yet opened: (entry `t` as an ordered key, rank in the depth-first
    /// order of the first leaf below, level, index).
    heap: BinaryHeap<Reverse<(u64, u32, u8, u32)>>,
}

impl Candidates<'_> {
    /// Admits box `k` of `level` (rank `prefix` among its level's boxes in the depth-first
    /// order) where the ray meets it.
    fn push(&mut self, level: usize, k: usize, prefix: u32) {
        let n = &self.tree.levels[level][k];
        let (a, b) = ((n.min - self.o) * self.inv, (n.max - self.o) * self.inv);
        let lo = a.min(b).max_element().max(self.t_min);
        let hi = a.max(b).min_element().min(self.t_max);
        if lo <= hi {
            let last = self.tree.levels.len() - 1;
            let rank = prefix << (2 * (last - level));
            self.heap.push(Reverse((total_order_key(lo), rank, level as u8, k as u32)));
        }
    }
}

impl Iterator for Candidates<'_> {
    type Item = (f64, usize);

    fn next(&mut self) -> Option<(f64, usize)> {
        let last = self.tree.levels.len() - 1;
        while let Some(Reverse((key, rank, level, k))) = self.heap.pop() {
            let (level, k) = (level as usize, k as usize);
            if level == last {
                return Some((from_total_order_key(key), k));
            }
            let prefix = rank >> (2 * (last - level));
            let n = 1usize << level;
            let (i, j) = (k % n, k / n);
            for (a, b) in [(1, 1), (0, 1), (1, 0), (0, 0)] {
                let digit = 3 - (a + 2 * b) as u32;
                self.push(level + 1, (2 * j + b) * 2 * n + 2 * i + a, prefix * 4 + digit);
            }
        }
        None
    }
}

/// `x`'s bits as a key whose integer order is `f64::total_cmp`'s.
fn total_order_key(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// The `x` of `total_order_key(x)`.
fn from_total_order_key(key: u64) -> f64 {
    f64::from_bits(if key >> 63 == 1 { key & !(1 << 63) } else { !key })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::function::{Binary, Node as F, Unary};
    use crate::geometry::Shape;
    use crate::ray::Ray;

    /// The unit sphere of POV-Ray's documentation: (sin u cos v, sin u sin v, cos u).
    fn sphere() -> Parametric {
        let (u, v) = (F::Param(0), F::Param(1));
        let s = |a: F| F::unary(Unary::Sin, a);
        let c = |a: F| F::unary(Unary::Cos, a);
        let fx = F::binary(Binary::Mul, s(u.clone()), c(v.clone()));
        let fy = F::binary(Binary::Mul, s(u.clone()), s(v.clone()));
        let fz = c(u);
        let f = [fx, fy, fz].map(|f| Program::compile(&f, 3));
        let uv = ParametricParams {
            lo: DVec2::ZERO,
            hi: DVec2::new(std::f64::consts::PI, 2.0 * std::f64::consts::PI),
            accuracy: 0.001,
            max_gradient: 1.0,
        };
        Parametric::new(DAffine3::IDENTITY, f, Container::Sphere { center: DVec3::ZERO, radius: 1.1 }, uv)
    }

    #[test]
    fn the_documentations_sphere_is_a_sphere() {
        let s = sphere();
        for (o, d, want) in [
            (Vec3::new(0.0, 0.0, -5.0), Vec3::Z, 4.0),
            (Vec3::new(0.3, 0.2, -5.0), Vec3::Z, 5.0 - (1.0f32 - 0.13).sqrt()),
            (Vec3::new(5.0, 0.0, 0.0), -Vec3::X, 4.0),
        ] {
            let t = s.intersect(&Ray::new(o, d), 0.0, f32::INFINITY).expect("hit");
            assert!((t - want).abs() < 1e-4, "{o}: {t} vs {want}");
            let p = o + t * d;
            let n = s.normal_at(p);
            assert!(n.dot(p.normalize()).abs() > 0.999, "{p}: {n}");
        }
        // The far side, past the first hit; a miss beside it.
        let t = s.intersect(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), 4.01, f32::INFINITY);
        assert!((t.expect("far side") - 6.0).abs() < 1e-4);
        assert_eq!(s.intersect(&Ray::new(Vec3::new(0.0, 1.2, -5.0), Vec3::Z), 0.0, f32::INFINITY), None);
    }

    /// Seeded random rays, many of them grazing: the cells passed over for their tangent
    /// planes lose no hit. Each ray meets the parametric sphere where the analytic one does,
    /// but within the accuracy of its silhouette; and two copies share one tree.
    #[test]
    fn random_rays_hit_where_the_sphere_is() {
        let s = sphere();
        assert!(Arc::ptr_eq(&s.tree, &sphere().tree), "copies share the tree");
        let mut uniform = crate::geometry::test_support::uniform(7);
        let mut rnd = || uniform() * 2.0 - 1.0;
        let mut hits = 0;
        for _ in 0..3000 {
            let o = DVec3::new(rnd(), rnd(), rnd()).normalize() * 4.0;
            // Aimed within a radius of 1.05 of the centre: a fifth of the rays pass near the rim.
            let aim = DVec3::new(rnd(), rnd(), rnd()).normalize() * (rnd().abs().sqrt() * 1.05);
            let d = (aim - o).normalize();
            let (b, c) = (o.dot(d), o.dot(o) - 1.0);
            let disc = b * b - c;
            let want = (disc >= 0.0).then(|| -b - disc.sqrt());
            let got = s.solve(o, d, 0.0, 100.0);
            // How far the ray passes from the sphere: near the rim either answer is right.
            let miss = (o - o.dot(d) * d).length() - 1.0;
            match (got, want) {
                (Some(g), Some(w)) => assert!((g - w).abs() < 2e-3 || miss.abs() < 2e-3, "{o} {d}: {g} vs {w}"),
                (None, None) => {}
                _ => assert!(miss.abs() < 2e-3, "{o} {d}: {got:?} vs {want:?}, {miss} from the rim"),
            }
            hits += got.is_some() as usize;
        }
        assert!(hits > 2000, "{hits}");
    }

    /// The best-first walk gives the leaves of the depth-first walk of every admitted box,
    /// stably sorted by entry, as `solve` took them before it was lazy: the same cells in the
    /// same order, ties included (shadow rays from the surface, whose nearby cells all start
    /// at `t_min`), so the same roots.
    #[test]
    fn candidates_come_in_the_order_of_a_full_walk_sorted() {
        let s = sphere();
        let full = |o: DVec3, d: DVec3, t_min: f64, t_max: f64| {
            let inv = d.recip();
            let mut out = Vec::new();
            let mut stack = vec![(0usize, 0usize)];
            let last = s.tree.levels.len() - 1;
            while let Some((level, k)) = stack.pop() {
                let n = &s.tree.levels[level][k];
                let (a, b) = ((n.min - o) * inv, (n.max - o) * inv);
                let (lo, hi) = (a.min(b).max_element().max(t_min), a.max(b).min_element().min(t_max));
                if lo > hi {
                    continue;
                }
                if level == last {
                    out.push((lo, k));
                    continue;
                }
                let w = 1usize << level;
                let (i, j) = (k % w, k / w);
                for (a, b) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    stack.push((level + 1, (2 * j + b) * 2 * w + 2 * i + a));
                }
            }
            out.sort_by(|a, b| a.0.total_cmp(&b.0));
            out
        };
        let mut uniform = crate::geometry::test_support::uniform(11);
        let mut rnd = || uniform() * 2.0 - 1.0;
        let (mut compared, mut ties) = (0, 0);
        for i in 0..300 {
            let d = DVec3::new(rnd(), rnd(), rnd()).normalize();
            // From outside, and from points on the surface (every nearby cell starts at 0).
            let o = if i % 2 == 0 {
                DVec3::new(rnd(), rnd(), rnd()).normalize() * 3.0
            } else {
                DVec3::new(rnd(), rnd(), rnd()).normalize()
            };
            let want = full(o, d, 0.0, 10.0);
            let got: Vec<(f64, usize)> = s.candidates(o, d, 0.0, 10.0).collect();
            assert_eq!(got.len(), want.len(), "{o} {d}");
            for (g, w) in got.iter().zip(&want) {
                assert!(g.0.to_bits() == w.0.to_bits() && g.1 == w.1, "{o} {d}: {g:?} vs {w:?}");
            }
            compared += want.len();
            ties += want.windows(2).filter(|w| w[0].0 == w[1].0).count();
        }
        assert!(compared > 2_000 && ties > 1_000, "{compared} cells, {ties} ties");
    }

    #[test]
    fn total_order_keys_order_as_total_cmp() {
        let xs = [f64::NEG_INFINITY, -3.5, -0.0, 0.0, 1e-300, 2.0, f64::INFINITY];
        for w in xs.windows(2) {
            assert!(total_order_key(w[0]) < total_order_key(w[1]), "{} {}", w[0], w[1]);
        }
        for x in xs {
            assert_eq!(from_total_order_key(total_order_key(x)).to_bits(), x.to_bits());
        }
    }
}
