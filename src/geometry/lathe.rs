//! POV-Ray's `lathe` (3.4.6.x Lathe): a 2-D spline (`spline` pieces in (r, y)) revolved around
//! the y axis. Per piece the ray meets the surface where `x² + z² = r(t)²` at height `y(t)`:
//! with `s = (y(t) − o.y) / d.y` that is one polynomial in `t` of degree up to 6, solved in f64
//! per lane by `bernstein` (no 8-wide arithmetic, as the torus), or, where every piece is
//! straight (a quadratic in `t`), eight lanes at once by `lathe_linear`. A ray level with the axis
//! (`d.y ≈ 0`) meets it where `y(t) = o.y` instead, then the circle there. Inside is even-odd of
//! (√(x² + z²), y) against the outline, as POV-Ray's parity test; `sturm` changes nothing.

use glam::{DAffine3, DVec2, DVec3, Vec3};

use super::bernstein::{one_root_unit, roots_between, roots_unit_to, to_bernstein, FOR_F32, MAX as MAX_B};
use super::cuboid::{frame_for, BoxFrame};
use super::lathe_linear::{self, Cone};
use super::lathe_quartic::{self, Quad};
use super::revolved::{along, candidates, object_ray, solve_left, Band, Candidates, LaneCandidates};
use super::roots::MAX_DEGREE;
use super::spline::{along_monotone, closest_t, even_odd, Piece};
use super::wide::{lane_f64, lanes_f64, to_lane, W};
use super::{affine_f32, transformed_bounds, RadialRay, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Debug)]
pub struct Lathe {
    pub frame: BoxFrame,
    /// The outline's (r, y) pieces, scaled to unit size: what `inside` tests (even-odd).
    outline: Vec<Piece>,
    /// The outline cut where `r` or `y` turns (`Piece::monotone_parts`): what rays are solved
    /// on and normals found on. The box of a part's ends holds it, so its band (`revolved`) is
    /// as tight as a box can be, and far fewer rays reach a part than reached its bulging
    /// piece's control-point box (POV-Ray bounds each piece by its own cylinder).
    pieces: Vec<Piece>,
    /// Per piece, what every ray's polynomial is made of (`Squares`).
    squares: Vec<Squares>,
    /// Per piece, its heights and radii, for the eight-lane cull (`revolved`).
    bands: Vec<Band>,
    /// The band of all of `bands`.
    whole: Band,
    /// Where every piece is straight, each as a cone (`lathe_linear`, eight lanes at once);
    /// empty otherwise.
    cones: Vec<Cone>,
    /// Where every piece is quadratic, each with its quartic's terms (`lathe_quartic`, eight
    /// lanes at once); empty otherwise.
    quads: Vec<Quad>,
    /// For a straight outline that bounds a simple polygon (`lathe_linear::outward_right`),
    /// each piece's outward unit normal in `(r, y)`: the normal without a tangent, a square
    /// root or an even-odd test. Empty otherwise.
    outward: Vec<DVec2>,
    pub min: Vec3,
    pub max: Vec3,
}

/// A piece's `y(t)`, `y(t)²` and `r(t)²` (degree `2·deg`, `y` padded), lowest power first and
/// as Bernstein coefficients on `[0, 1]`, with the band its radius keeps to, `r_min² ..= r_max²`
/// (from its control points' box: convex hull). A ray `o + s·d` meets the piece where
/// `|α + y(t)·d_h|² = (r(t)·d.y)²` with `α = o_h·d.y − o.y·d_h` (the horizontal part of the ray
/// at height `y`, times `d.y`): `d_h²·y² + 2(α·d_h)·y + α² − d.y²·r²`, so each ray's polynomial
/// is three multiples of these in either basis, without multiplying polynomials or changing
/// basis per ray.
#[derive(Clone, Copy, Debug)]
struct Squares {
    y: [f64; 7],
    y2: [f64; 7],
    r2: [f64; 7],
    y_b: [f64; MAX_B + 1],
    y2_b: [f64; MAX_B + 1],
    r2_b: [f64; MAX_B + 1],
    r2_min: f64,
    r2_max: f64,
}

impl Squares {
    fn of(p: &Piece) -> Squares {
        let deg = p.degree;
        let square = |c: &[f64; 4]| {
            let mut out = [0.0; 7];
            for i in 0..=deg {
                for j in 0..=deg {
                    out[i + j] += c[i] * c[j];
                }
            }
            out
        };
        let mut y = [0.0; 7];
        y[..=deg].copy_from_slice(&p.v[..=deg]);
        let (y2, r2) = (square(&p.v), square(&p.u));
        let n = 2 * deg;
        let r_max = p.lo.x.abs().max(p.hi.x.abs());
        let r_min = if p.lo.x > 0.0 {
            p.lo.x
        } else if p.hi.x < 0.0 {
            -p.hi.x
        } else {
            0.0
        };
        Squares {
            y,
            y2,
            r2,
            y_b: to_bernstein(&y[..=n]),
            y2_b: to_bernstein(&y2[..=n]),
            r2_b: to_bernstein(&r2[..=n]),
            r2_min: r_min * r_min,
            r2_max: r_max * r_max,
        }
    }
}

/// One ray (object space) as every piece's polynomial takes it (`Squares`): the multiples of
/// `y²`, `y`, `1` and `r²`, whether it runs level with the axis, and its distance from the axis.
#[derive(Clone, Copy)]
struct PieceRay {
    o: DVec3,
    d: DVec3,
    dh2: f64,
    level: bool,
    band: RadialRay,
    inv_dy: f64,
    k_y2: f64,
    k_y: f64,
    k_1: f64,
    k_r2: f64,
}

impl PieceRay {
    #[inline(always)]
    fn new(o: DVec3, d: DVec3) -> PieceRay {
        let dh2 = d.x * d.x + d.z * d.z;
        let (ax, az) = (o.x * d.y - o.y * d.x, o.z * d.y - o.y * d.z);
        PieceRay {
            o,
            d,
            dh2,
            level: d.y.abs() <= 1e-9 * dh2.sqrt(),
            band: RadialRay::new(o, d),
            inv_dy: 1.0 / d.y,
            k_y2: dh2,
            k_y: 2.0 * (ax * d.x + az * d.z),
            k_1: ax * ax + az * az,
            k_r2: d.y * d.y,
        }
    }
}

/// What one piece answers a ray (`Lathe::solve_piece`).
enum Cross {
    Miss,
    /// The nearest crossing below the bound.
    At(f64),
    /// A shadow ray is certainly blocked (`one_root_unit`); the slab's far end.
    Sure(f64),
}

impl Lathe {
    pub fn new(render_from_object: DAffine3, pieces: &[Piece]) -> Lathe {
        let r = pieces.iter().fold(0.0f64, |m, p| m.max(p.lo.x.abs()).max(p.hi.x.abs()));
        let (ylo, yhi) =
            pieces.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.lo.y), b.max(p.hi.y)));
        let cy = 0.5 * (ylo + yhi);
        let s = r.max(0.5 * (yhi - ylo));
        let s = if s > 0.0 && s.is_finite() { s } else { 1.0 };
        let local = DAffine3::from_translation(DVec3::new(0.0, cy, 0.0)) * DAffine3::from_scale(DVec3::splat(s));
        let outline: Vec<Piece> = pieces.iter().map(|p| p.map(|q| DVec2::new(q.x / s, (q.y - cy) / s))).collect();
        let pieces: Vec<Piece> = outline.iter().flat_map(Piece::monotone_parts).collect();
        let squares: Vec<Squares> = pieces.iter().map(Squares::of).collect();
        let bands: Vec<Band> =
            pieces.iter().zip(&squares).map(|(p, q)| Band::new(p.lo.y, p.hi.y, q.r2_min, q.r2_max)).collect();
        let cones = if pieces.iter().all(|p| p.degree == 1) {
            let first3 = |c: &[f64; 7]| [c[0], c[1], c[2]];
            pieces
                .iter()
                .zip(&squares)
                .map(|(p, q)| Cone { y: first3(&q.y), y2: first3(&q.y2), r2: first3(&q.r2), v: p.v })
                .collect()
        } else {
            Vec::new()
        };
        let quads = if pieces.iter().all(|p| p.degree == 2) {
            let first5 = |c: &[f64; 7]| [c[0], c[1], c[2], c[3], c[4]];
            let b5 = |c: &[f64; MAX_B + 1]| [c[0], c[1], c[2], c[3], c[4]];
            pieces
                .iter()
                .zip(&squares)
                .map(|(p, q)| Quad {
                    y: first5(&q.y),
                    y2: first5(&q.y2),
                    r2: first5(&q.r2),
                    y_b: b5(&q.y_b),
                    y2_b: b5(&q.y2_b),
                    r2_b: b5(&q.r2_b),
                    y_lo: p.lo.y,
                    y_hi: p.hi.y,
                    rising: p.at(1.0).y > p.at(0.0).y,
                })
                .collect()
        } else {
            Vec::new()
        };
        let xf = render_from_object * local;
        let xf = affine_f32(&xf);
        let (r, h) = ((r / s) as f32, ((yhi - ylo) / (2.0 * s)) as f32);
        let (min, max) = transformed_bounds(&xf, Vec3::new(-r, -h, -r), Vec3::new(r, h, r));
        let pad = (max - min).max(min.abs().max(max.abs())) * 4.0 * f32::EPSILON;
        Lathe {
            frame: frame_for(xf),
            outward: match lathe_linear::outward_right(&outline) {
                // A line's tangent is the same at every `t`: these are `oriented`'s bits.
                Some(out) => {
                    pieces.iter().map(|p| Lathe::right_normal(p, 0.0) * if out { 1.0 } else { -1.0 }).collect()
                }
                None => Vec::new(),
            },
            outline,
            pieces,
            squares,
            whole: Band::around(&bands),
            bands,
            cones,
            quads,
            min: min - pad,
            max: max + pad,
        }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }

    /// The nearest crossing in `(s_min, s_max)` with the pieces `may` holds (`revolved`). With
    /// `any` (a shadow ray: the lane's rounding), a piece whose polynomial certainly has one
    /// root (`bernstein::one_root_unit`) within a height slab lying inside the interval, past
    /// `s_min`'s rounding, answers the slab's far end unpolished (`Shape::blocks`).
    fn solve(
        &self,
        may: LaneCandidates,
        o: DVec3,
        d: DVec3,
        s_min: f64,
        s_max: f64,
        any: Option<fn(f64) -> f64>,
    ) -> Option<f64> {
        let mut best = s_max;
        let ray = PieceRay::new(o, d);
        for k in along(self.pieces.len(), d.y) {
            if !may.may_meet(k) {
                continue;
            }
            match self.solve_piece(k, &ray, s_min, best, s_max, any) {
                Cross::Sure(s) => return Some(s),
                Cross::At(s) => best = s,
                Cross::Miss => {}
            }
        }
        (best < s_max).then_some(best)
    }

    /// Piece `k` alone, as `solve` takes it with `best` found so far: its nearest crossing in
    /// `(s_min, best)`, or (`any`) a crossing certainly inside `(s_min, s_max)`.
    #[inline(always)]
    fn solve_piece(
        &self,
        k: usize,
        ray: &PieceRay,
        s_min: f64,
        best: f64,
        s_max: f64,
        any: Option<fn(f64) -> f64>,
    ) -> Cross {
        let PieceRay { o, d, dh2, level, band, inv_dy, k_y2, k_y, k_1, k_r2 } = *ray;
        let mut roots = [0.0; MAX_DEGREE];
        let (p, sq) = (&self.pieces[k], &self.squares[k]);
        // The piece's height slab along the ray.
        let mut slab = (f64::NEG_INFINITY, f64::INFINITY);
        if level {
            if o.y < p.lo.y || o.y > p.hi.y {
                return Cross::Miss;
            }
        } else {
            // Widened by a part in 10⁹: a product by 1/d.y is not the quotient's bits.
            let (a, b) = ((p.lo.y - o.y) * inv_dy, (p.hi.y - o.y) * inv_dy);
            let pad = 1e-9 * (a.abs() + b.abs());
            let (a, b) = (a.min(b) - pad, a.max(b) + pad);
            if b <= s_min || a >= best {
                return Cross::Miss;
            }
            if band.misses(a.max(s_min), b.min(best), sq.r2_min, sq.r2_max) {
                return Cross::Miss;
            }
            slab = (a, b);
        }
        let mut hits = [f64::NAN; 2 * MAX_DEGREE];
        let mut n = 0;
        if level {
            // y(t) = o.y, then |o_h + s·d_h|² = r(t)².
            let (c, k) = p.combine(0.0, 1.0, -o.y);
            let m = roots_between(&c[..k], 0.0, 1.0, &mut roots);
            for &t in &roots[..m] {
                let r = p.at(t).x;
                let b = o.x * d.x + o.z * d.z;
                let c = o.x * o.x + o.z * o.z - r * r;
                let disc = b * b - dh2 * c;
                if disc >= 0.0 {
                    let q = -(b + b.signum() * disc.sqrt());
                    for s in [q / dh2, c / q] {
                        hits[n] = s;
                        n += 1;
                    }
                }
            }
        } else {
            let len = 2 * p.degree + 1;
            // Highest power first, as the solvers take it.
            let mut c = [0.0; 7];
            for (i, slot) in c[..len].iter_mut().enumerate() {
                let k = len - 1 - i;
                *slot = k_y2 * sq.y2[k] + k_y * sq.y[k] - k_r2 * sq.r2[k];
            }
            c[len - 1] += k_1;
            let m = if len <= 3 {
                // As the eight-lane solve skips and solves it (`lathe_linear`), for its bits.
                if !lathe_linear::may_cross(c[0], c[1], c[2]) {
                    return Cross::Miss;
                }
                let mut m = 0;
                for (t, ok) in lathe_linear::roots_unit(W([c[0]]), W([c[1]]), W([c[2]])) {
                    if ok[0] {
                        roots[m] = t.0[0];
                        m += 1;
                    }
                }
                m
            } else {
                let mut b = [0.0; MAX_B + 1];
                for (k, slot) in b[..len].iter_mut().enumerate() {
                    *slot = k_y2 * sq.y2_b[k] + k_y * sq.y_b[k] - k_r2 * sq.r2_b[k] + k_1;
                }
                if let Some(round) = any {
                    // The root's crossing lies in the slab, which lies in the interval.
                    if round(slab.0) > s_min && slab.1 < s_max && one_root_unit(&c[..len], b) {
                        return Cross::Sure(slab.1);
                    }
                }
                roots_unit_to(&c[..len], b, FOR_F32, &mut roots)
            };
            for &t in &roots[..m] {
                hits[n] = (p.at(t).y - o.y) * inv_dy;
                n += 1;
            }
        }
        let mut near = best;
        for &s in &hits[..n] {
            if s > s_min && s < near {
                near = s;
            }
        }
        if near < best {
            Cross::At(near)
        } else {
            Cross::Miss
        }
    }

    /// Piece `k` alone for one lane of the eight-lane quartic solve (`lathe_quartic`), where
    /// that declined: its first crossing in `(s_min, s_max)` that `round` puts above `s_min`
    /// (`hit_lanes_f64`'s retries), or (`any`) one certainly there.
    #[allow(clippy::too_many_arguments)]
    fn piece_alone(
        &self,
        k: usize,
        o: DVec3,
        d: DVec3,
        s_min: f64,
        s_max: f64,
        round: fn(f64) -> f64,
        any: bool,
    ) -> Option<f64> {
        let ray = PieceRay::new(o, d);
        let mut from = s_min;
        for _ in 0..4 {
            match self.solve_piece(k, &ray, from, s_max, s_max, any.then_some(round)) {
                Cross::Sure(s) => return Some(s),
                Cross::At(s) if round(s) > s_min => return Some(s),
                Cross::At(s) => from = s,
                Cross::Miss => return None,
            }
        }
        None
    }

    /// The lanes (bit `i` for lane `i`) level with the axis: `solve`'s test.
    #[inline(always)]
    fn level_lanes<L: Lane>(d: V3<L>) -> u8 {
        // A loop, not a fold's closure (compiled out of line, without AVX2).
        let mut level = 0u8;
        for i in 0..L::WIDTH {
            let (x, y, z) = (d.x.get_f64(i), d.y.get_f64(i), d.z.get_f64(i));
            level |= u8::from(y.abs() <= 1e-9 * (x * x + z * z).sqrt()) << i;
        }
        level
    }

    /// Every lane not level with the axis answered at once (`lathe_linear`), with the lanes
    /// left to `solve` (level: `solve`'s test). A method, not a closure: as a closure it was
    /// compiled out of line, without AVX2.
    #[inline(always)]
    fn hit_cones<L: Lane>(&self, c: &Candidates, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> (L, u8) {
        let level = Lathe::level_lanes(d);
        let t = if L::WIDTH == 8 {
            let skip = std::array::from_fn(|i| level >> i & 1 != 0);
            let (o, d, lo, hi) = (lanes_f64(o), lanes_f64(d), lane_f64(t_min), lane_f64(t_max));
            to_lane(lathe_linear::hit::<8>(&self.cones, c, skip, o, d, lo, hi, L::round_f64))
        } else {
            let (o, d, lo, hi) = (lanes_f64(o), lanes_f64(d), lane_f64(t_min), lane_f64(t_max));
            to_lane(lathe_linear::hit::<1>(&self.cones, c, [level != 0], o, d, lo, hi, L::round_f64))
        };
        (t, level)
    }

    /// Every lane not level with the axis answered at once (`lathe_quartic`), with the lanes
    /// left to `solve` (level: `solve`'s test), as `hit_cones`.
    #[inline(always)]
    fn hit_quads<L: Lane>(&self, c: &Candidates, o: V3<L>, d: V3<L>, t_min: L, t_max: L, any: bool) -> (L, u8) {
        let level = Lathe::level_lanes(d);
        let alone = |i: usize, k: usize, lo: f64, hi: f64| {
            let v = |w: V3<L>| DVec3::new(w.x.get_f64(i), w.y.get_f64(i), w.z.get_f64(i));
            self.piece_alone(k, v(o), v(d), lo, hi, L::round_f64, any)
        };
        let (ow, dw) = (lanes_f64(o), lanes_f64(d));
        let t = if L::WIDTH == 8 {
            let skip = std::array::from_fn(|i| level >> i & 1 != 0);
            let (lo, hi) = (lane_f64(t_min), lane_f64(t_max));
            to_lane(lathe_quartic::hit::<8>(&self.quads, c, skip, ow, dw, lo, hi, L::round_f64, any, alone))
        } else {
            let (o1, d1, lo, hi) = (lanes_f64(o), lanes_f64(d), lane_f64(t_min), lane_f64(t_max));
            to_lane(lathe_quartic::hit::<1>(&self.quads, c, [level != 0], o1, d1, lo, hi, L::round_f64, any, alone))
        };
        (t, level)
    }

    fn profile(q: DVec3) -> DVec2 {
        DVec2::new((q.x * q.x + q.z * q.z).sqrt(), q.y)
    }

    fn normal_object(&self, q: DVec3) -> DVec3 {
        let w = Lathe::profile(q);
        // The piece nearest `w`, the first in order among equally near ones. A piece's box
        // bounds how near it can be (`gap`), so the pieces whose boxes hold `w` go first: the
        // piece the point lies on is one of them, and then the box test rules out nearly every
        // other piece without its closest-point solve (in order, the pieces before it were
        // solved: a third of the lathe_quadratic kernel scene's frame was these solves).
        let gap = |p: &Piece| (p.lo.abs().min(p.lo) - w).max(w - p.hi.abs().max(p.hi)).max(DVec2::ZERO).length();
        let mut best: Option<(f64, usize, f64)> = None;
        // First the parts whose (padded) box holds `w`, each by one monotone solve
        // (`along_monotone`): a hit point lies on one of them to its rounding, far below
        // `ON`. Where exactly one part passes that near, it is the nearest (every other lies
        // farther than `ON`); a point near a joint, where two pass and the nearest decides
        // which piece's normal it gets (a quadratic spline's tangent turns there), and a point
        // no part passes near, are given the nearest-point solves below.
        const ON: f64 = 1e-4;
        let mut near = 0;
        for (i, p) in self.pieces.iter().enumerate() {
            if (p.lo - w).max(w - p.hi).max_element() > ON {
                continue;
            }
            let (t, off) = along_monotone(p, w);
            if off <= ON {
                near += 1;
                best = Some((off, i, t));
            }
        }
        if near == 1 {
            return self.oriented(q, w, best);
        }
        best = None;
        for holds in [true, false] {
            for (i, p) in self.pieces.iter().enumerate() {
                let g = gap(p);
                if (g == 0.0) != holds {
                    continue;
                }
                if best.is_some_and(|(d, j, _)| g > d || (g == d && i > j)) {
                    continue;
                }
                let t = closest_t(p, w);
                let dist = (p.at(t) - w).length();
                if best.is_none_or(|(d, j, _)| dist < d || (dist == d && i < j)) {
                    best = Some((dist, i, t));
                }
            }
        }
        self.oriented(q, w, best)
    }

    /// The unit right-hand normal `(tan.y, −tan.x)` of piece `p` at `t`.
    fn right_normal(p: &Piece, t: f64) -> DVec2 {
        let tan = p.tangent(t);
        DVec2::new(tan.y, -tan.x).normalize_or_zero()
    }

    /// The outward normal at `q` (profile point `w`) from the tangent of piece `i` at `t`.
    fn oriented(&self, q: DVec3, w: DVec2, best: Option<(f64, usize, f64)>) -> DVec3 {
        let Some((_, i, t)) = best else { return DVec3::Y };
        let n2 = if let Some(&n2) = self.outward.get(i) {
            n2
        } else {
            let p = &self.pieces[i];
            let n2 = Lathe::right_normal(p, t);
            let at = p.at(t);
            let eps = 1e-6 * (1.0 + at.abs().max_element());
            if even_odd(&self.outline, at + eps * n2) {
                -n2
            } else {
                n2
            }
        };
        let (ux, uz) = if w.x > 0.0 {
            let inv = 1.0 / w.x;
            (q.x * inv, q.z * inv)
        } else {
            (1.0, 0.0)
        };
        DVec3::new(n2.x * ux, n2.y, n2.x * uz)
    }
}

impl Lathe {
    /// `hit` (`any` false) or `blocks` (`solve`'s shadow-ray shortcut).
    #[inline(always)]
    fn hit_any<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L, any: bool) -> L {
        let (o, d) = object_ray(&self.frame, ray);
        let Some((c, lanes)) = candidates(&self.whole, &self.bands, o, d, t_min, t_max) else {
            return L::splat(MISS);
        };
        let (answers, left) = if !self.cones.is_empty() {
            self.hit_cones(&c, o, d, t_min, t_max)
        } else if !self.quads.is_empty() {
            self.hit_quads(&c, o, d, t_min, t_max, any)
        } else {
            (L::splat(MISS), lanes)
        };
        let round: Option<fn(f64) -> f64> = if any { Some(L::round_f64) } else { None };
        solve_left(&c, left & lanes, answers, o, d, t_min, t_max, |m, o, d, lo, hi| self.solve(m, o, d, lo, hi, round))
    }
}

impl Shape for Lathe {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.hit_any(ray, t_min, t_max, false)
    }

    #[inline(always)]
    fn blocks<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        self.hit_any(ray, t_min, t_max, true)
    }

    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        super::normal_lanes_f64(&self.frame, p, |q| self.normal_object(q))
    }

    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        super::inside_lanes_f64(&self.frame, p, |q| even_odd(&self.outline, Lathe::profile(q)))
    }
}

#[cfg(test)]
mod tests;
