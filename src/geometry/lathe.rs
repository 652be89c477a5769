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
        let dh2 = d.x * d.x + d.z * d.z;
        let level = d.y.abs() <= 1e-9 * dh2.sqrt();
        let band = RadialRay::new(o, d);
        let inv_dy = 1.0 / d.y;
        // The polynomial's multiples of y², y, 1 and r² (`Squares`).
        let (ax, az) = (o.x * d.y - o.y * d.x, o.z * d.y - o.y * d.z);
        let (k_y2, k_y, k_1, k_r2) = (dh2, 2.0 * (ax * d.x + az * d.z), ax * ax + az * az, d.y * d.y);
        let mut roots = [0.0; MAX_DEGREE];
        for k in along(self.pieces.len(), d.y) {
            if !may.may_meet(k) {
                continue;
            }
            let (p, sq) = (&self.pieces[k], &self.squares[k]);
            // The piece's height slab along the ray.
            let mut slab = (f64::NEG_INFINITY, f64::INFINITY);
            if level {
                if o.y < p.lo.y || o.y > p.hi.y {
                    continue;
                }
            } else {
                // Widened by a part in 10⁹: a product by 1/d.y is not the quotient's bits.
                let (a, b) = ((p.lo.y - o.y) * inv_dy, (p.hi.y - o.y) * inv_dy);
                let pad = 1e-9 * (a.abs() + b.abs());
                let (a, b) = (a.min(b) - pad, a.max(b) + pad);
                if b <= s_min || a >= best {
                    continue;
                }
                if band.misses(a.max(s_min), b.min(best), sq.r2_min, sq.r2_max) {
                    continue;
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
                        continue;
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
                            return Some(slab.1);
                        }
                    }
                    roots_unit_to(&c[..len], b, FOR_F32, &mut roots)
                };
                for &t in &roots[..m] {
                    hits[n] = (p.at(t).y - o.y) * inv_dy;
                    n += 1;
                }
            }
            for &s in &hits[..n] {
                if s > s_min && s < best {
                    best = s;
                }
            }
        }
        (best < s_max).then_some(best)
    }

    /// Every lane not level with the axis answered at once (`lathe_linear`), with the lanes
    /// left to `solve` (level: `solve`'s test). A method, not a closure: as a closure it was
    /// compiled out of line, without AVX2.
    #[inline(always)]
    fn hit_cones<L: Lane>(&self, c: &Candidates, o: V3<L>, d: V3<L>, t_min: L, t_max: L) -> (L, u8) {
        // A loop, not a fold's closure (compiled out of line, without AVX2).
        let mut level = 0u8;
        for i in 0..L::WIDTH {
            let (x, y, z) = (d.x.get_f64(i), d.y.get_f64(i), d.z.get_f64(i));
            level |= u8::from(y.abs() <= 1e-9 * (x * x + z * z).sqrt()) << i;
        }
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
        let (answers, left) =
            if self.cones.is_empty() { (L::splat(MISS), lanes) } else { self.hit_cones(&c, o, d, t_min, t_max) };
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
mod tests {
    use super::*;
    use crate::desc::SplineKind;
    use crate::geometry::spline::open_pieces;
    use crate::ray::Ray;

    /// A cylinder of radius 1 from y = 0 to 2 as a closed linear outline.
    fn can(xf: DAffine3) -> Lathe {
        let p = |r: f64, y: f64| DVec2::new(r, y);
        let pts = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 2.0), p(0.0, 2.0)];
        Lathe::new(xf, &open_pieces(SplineKind::Linear, &pts).expect("lathe"))
    }

    #[test]
    fn walls_level_rays_axis_rays_and_extremes() {
        let l = can(DAffine3::IDENTITY);
        let hit = |o: Vec3, d: Vec3| l.intersect(&Ray::new(o, d.normalize()), 0.0, f32::INFINITY);
        // Level ray (d.y = 0): the wall at x = -1.
        assert!((hit(Vec3::new(-5.0, 1.0, 0.0), Vec3::X).expect("level") - 4.0).abs() < 1e-5);
        assert!((l.normal_at(Vec3::new(-1.0, 1.0, 0.0)) - -Vec3::X).length() < 1e-5);
        // Slanted: enters the wall at y = 1.5.
        let t = hit(Vec3::new(0.0, 2.5, -2.0), Vec3::new(0.0, -1.0, 1.0)).expect("slant");
        assert!((t - 2f32.sqrt()).abs() < 1e-4, "{t}");
        // Down the axis: the top disc of the outline.
        assert!((hit(Vec3::new(0.0, 5.0, 0.0), -Vec3::Y).expect("axis") - 3.0).abs() < 1e-5);
        assert!((l.normal_at(Vec3::new(0.3, 2.0, 0.0)) - Vec3::Y).length() < 1e-5);
        // Beside it, parallel to the axis: a miss.
        assert_eq!(hit(Vec3::new(1.5, 5.0, 0.0), -Vec3::Y), None);
        // Grazing the wall: a miss or a hit on it.
        let g = hit(Vec3::new(-5.0, 1.0, 1.0), Vec3::X);
        assert!(g.is_none_or(|t| (t - 5.0).abs() < 1e-2), "{g:?}");
        assert!(
            l.inside(V3::from_vec3(Vec3::new(0.5, 1.0, 0.2))) && !l.inside(V3::from_vec3(Vec3::new(1.5, 1.0, 0.0)))
        );
        for (s, at) in [(1e-4, 0.0), (1e5, 0.0), (1.0, 1e6)] {
            let xf = DAffine3::from_translation(DVec3::splat(at)) * DAffine3::from_scale(DVec3::splat(s));
            let l = can(xf);
            let o = Vec3::new(-5.0, 1.0, 0.0) * s as f32 + Vec3::splat(at as f32);
            let t = l.intersect(&Ray::new(o, Vec3::X), 0.0, f32::INFINITY).expect("far");
            let want = 4.0 * s as f32;
            assert!((t - want).abs() <= want * 1e-4 + at as f32 * 1e-6, "{s} {at}: {t}");
        }
    }

    /// The straight pieces solved eight lanes at once (`lathe_linear`) give the scalar solve's
    /// bits, in packets and single rays, over seeded random rays at the kernel vase (scaled,
    /// moved, seen from near and far), some level with the axis (left to the scalar solve),
    /// some nearly so, some along it.
    #[test]
    fn cones_give_the_scalar_solves_bits() {
        use crate::lanes::F8;
        use crate::ray::MISS;
        let p = |r: f64, y: f64| DVec2::new(r, y);
        let vase = [p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
        let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1)) * DAffine3::from_scale(DVec3::splat(2.0));
        let wide = Lathe::new(xf, &open_pieces(SplineKind::Linear, &vase).expect("lathe"));
        assert_eq!(wide.cones.len(), wide.pieces.len());
        let scalar = Lathe { cones: Vec::new(), ..wide.clone() };
        let mut rand = crate::geometry::test_support::uniform(0x94d0_49bb_1331_11ebu64);
        let (lo, hi) = wide.bounds();
        let mut hits = 0;
        for case in 0..2000 {
            let rays: [Ray; 8] = std::array::from_fn(|i| {
                let at = |a: f64, b: f64, c: f64| lo + (hi - lo) * Vec3::new(a as f32, b as f32, c as f32);
                let far = [1.0, 30.0][case % 2];
                let o = at(rand() * 1.4 - 0.2, rand() * 1.4 - 0.2, rand() * 1.4 - 0.2 - far);
                let mut d = (at(rand(), rand(), rand()) - o).normalize();
                match (case + i) % 7 {
                    0 => d.y = 0.0,
                    1 => d.y *= 1e-9,
                    2 => d = Vec3::new(0.0, -1.0, 0.0),
                    _ => {}
                }
                Ray::new(o, d.normalize())
            });
            let packet = RayLanes::<F8> {
                o: V3::from_lanes(|i| rays[i].origin),
                d: V3::from_lanes(|i| rays[i].dir),
                inv: V3::from_lanes(|i| rays[i].inv_dir),
            };
            let t_min = F8::from_fn(|i| [0.0, 0.5, 2.0][(case + i) % 3]);
            let (a, b) = (wide.hit(&packet, t_min, F8::splat(MISS)), scalar.hit(&packet, t_min, F8::splat(MISS)));
            for (i, r) in rays.iter().enumerate() {
                let one = wide.hit(&r.lanes(), t_min.get(i), MISS);
                assert_eq!(a.get(i).to_bits(), b.get(i).to_bits(), "case {case} lane {i}: {r:?}");
                assert_eq!(one.to_bits(), b.get(i).to_bits(), "case {case} lane {i}: {r:?}");
                hits += usize::from(one != MISS);
            }
        }
        assert!(hits > 2000, "{hits}");
    }

    /// `blocks` misses exactly where `hit` does for the curved kernel vases: seeded random rays
    /// at them, a third ending inside their box, and shadow rays leaving their hits every way.
    #[test]
    fn blocks_as_hit_does() {
        use crate::geometry::test_support::{blocks_rays, check_blocks};
        let p = |r: f64, y: f64| DVec2::new(r, y);
        let vase = [p(0.0, -0.1), p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
        for (kind, pts) in [(SplineKind::Quadratic, &vase[..6]), (SplineKind::Cubic, &vase[..])] {
            let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1));
            let l = Lathe::new(xf, &open_pieces(kind, pts).expect("lathe"));
            let (lo, hi) = l.bounds();
            let rays = blocks_rays(&l, lo, hi, 400, 77);
            let hits = check_blocks(&l, &rays);
            assert!(hits > 100 && hits < rays.len() - 100, "{kind:?}: {hits} of {}", rays.len());
        }
    }

    /// Every spline kind of the kernel vase (each outline closed by the axis), seeded random rays from around it: eight-lane
    /// packets give the single rays' distances bit for bit, and a ray from a point outside
    /// crosses the surface an even number of times, from inside an odd number (grazing rays
    /// and starts on the surface decide nothing and are passed over).
    #[test]
    fn packets_match_single_rays_and_crossings_match_inside() {
        use crate::lanes::F8;
        use crate::ray::MISS;
        let p = |r: f64, y: f64| DVec2::new(r, y);
        let vase = [p(0.0, 0.0), p(0.45, 0.0), p(0.3, 0.4), p(0.45, 0.75), p(0.25, 0.95), p(0.0, 0.95)];
        let cubic = [&[p(0.0, -0.1)][..], &vase, &[p(0.0, 1.05)]].concat();
        let bezier = [
            p(0.0, 0.0),
            p(0.6, 0.0),
            p(0.1, 0.5),
            p(0.45, 0.75),
            p(0.45, 0.75),
            p(0.3, 1.0),
            p(0.2, 0.9),
            p(0.0, 0.95),
        ];
        let mut seed = 0x853c_49e6_748f_ea9bu64;
        let mut rand = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 40) as f32 / (1u32 << 24) as f32
        };
        let mut checked = 0;
        for (kind, pts) in [
            (SplineKind::Linear, &vase[..]),
            (SplineKind::Quadratic, &cubic[..cubic.len() - 1]),
            (SplineKind::Cubic, &cubic[..]),
            (SplineKind::Bezier, &bezier[..]),
        ] {
            let xf = DAffine3::from_translation(DVec3::new(0.3, -0.2, 0.1)) * DAffine3::from_scale(DVec3::splat(2.0));
            let l = Lathe::new(xf, &open_pieces(kind, pts).expect("lathe"));
            let (lo, hi) = l.bounds();
            for _ in 0..300 {
                let at = |t: Vec3| lo + (hi - lo) * t;
                let rays: [Ray; 8] = std::array::from_fn(|_| {
                    let o = at(Vec3::new(rand(), rand(), rand()) * 1.4 - Vec3::splat(0.2));
                    let target = at(Vec3::new(rand(), rand(), rand()));
                    Ray::new(o, (target - o).normalize())
                });
                let packet = RayLanes::<F8> {
                    o: V3::from_lanes(|i| rays[i].origin),
                    d: V3::from_lanes(|i| rays[i].dir),
                    inv: V3::from_lanes(|i| rays[i].inv_dir),
                };
                let wide = l.hit(&packet, F8::splat(0.0), F8::splat(MISS));
                for (i, r) in rays.iter().enumerate() {
                    let single = l.hit(&r.lanes(), 0.0, MISS);
                    assert_eq!(wide.get(i).to_bits(), single.to_bits(), "{kind:?} lane {i}");
                    let mut crossings = Vec::new();
                    let mut t = 0.0;
                    while crossings.len() < 16 {
                        let Some(next) = l.intersect(r, t, f32::INFINITY) else { break };
                        crossings.push(next);
                        t = next;
                    }
                    let scale = 1.0 + r.origin.length();
                    if crossings.first().is_some_and(|&c| c < 1e-3 * scale)
                        || crossings.windows(2).any(|w| w[1] - w[0] < 1e-3 * scale)
                    {
                        continue;
                    }
                    let inside = l.inside(V3::from_vec3(r.origin));
                    assert_eq!(inside, crossings.len() % 2 == 1, "{kind:?} {r:?}: {crossings:?}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 8000, "{checked}");
    }
}
