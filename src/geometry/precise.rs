//! The shapes in f64, for the precise render path (`render::precise`): rays, ray tests,
//! geometric normals, bounds and secondary-ray origins, one routine per kind as in the f32 files.
//!
//! Each routine is the f32 routine's formula in f64 (the stable sphere roots, the slab test with
//! the same NaN handling, Möller–Trumbore, the crossing-number polygon test), so the two paths
//! differ only by rounding. The f32 kernels stay generic over `Lane` for packets; these are plain
//! scalar code, since the precise path traces single rays only.

use glam::{DAffine3, DMat3, DVec2, DVec3};

/// A ray in render space, f64.
#[derive(Clone, Copy, Debug)]
pub struct RayD {
    pub origin: DVec3,
    /// Unit length, so `t` is a distance.
    pub dir: DVec3,
    /// `1 / dir`, with ±0 components giving ±inf.
    pub inv_dir: DVec3,
}

impl RayD {
    #[inline]
    pub fn new(origin: DVec3, dir: DVec3) -> RayD {
        RayD { origin, dir, inv_dir: dir.recip() }
    }

    #[inline]
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.dir * t
    }
}

/// `geometry::ray::HIT_ERROR_ULPS` for f64: the same 32 ulps of the point's magnitude, which at
/// |p| = 10 moves an origin by 7e-14 instead of f32's 2e-5.
pub const HIT_ERROR_ULPS_F64: f64 = 32.0 * f64::EPSILON;
/// Shadow rays stop this fraction of their length short of the light.
const SHADOW_SHRINK_F64: f64 = 1.0 - 4.0 * f64::EPSILON;

#[inline]
fn max_abs(v: DVec3) -> f64 {
    v.abs().max_element()
}

/// `geometry::ray::offset_origin` in f64: moves a hit point off its surface to the side `dir`
/// leaves towards, by the f64 error bound of the hit point.
#[inline]
pub fn offset_origin(p: DVec3, n: DVec3, dir: DVec3) -> DVec3 {
    let d = max_abs(p) * HIT_ERROR_ULPS_F64 + f64::MIN_POSITIVE * 16.0;
    let offset = if n.dot(dir) >= 0.0 { n * d } else { -n * d };
    p + offset
}

/// `geometry::ray::shadow_t_max` in f64.
#[inline]
pub fn shadow_t_max(origin: DVec3, light: DVec3) -> f64 {
    let magnitude = max_abs(origin).max(max_abs(light));
    let t = (light - origin).length() * SHADOW_SHRINK_F64 - magnitude * HIT_ERROR_ULPS_F64;
    t.max(0.0)
}

/// `Lane::min` for f32: the second operand when either is NaN.
#[inline]
fn min(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

#[inline]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// The near root if it lies in `(t_min, t_max)`, else the far one.
#[inline]
fn pick_root(near: f64, far: f64, t_min: f64, t_max: f64) -> Option<f64> {
    if near > t_min && near < t_max {
        Some(near)
    } else if far > t_min && far < t_max {
        Some(far)
    } else {
        None
    }
}

/// Slab test: (entry, exit) against an axis-aligned box, as `lanes::slabs`.
#[inline]
pub fn slabs(lo: DVec3, hi: DVec3, o: DVec3, inv: DVec3) -> (f64, f64) {
    let t0 = (lo - o) * inv;
    let t1 = (hi - o) * inv;
    let near = DVec3::new(min(t0.x, t1.x), min(t0.y, t1.y), min(t0.z, t1.z));
    let far = DVec3::new(max(t0.x, t1.x), max(t0.y, t1.y), max(t0.z, t1.z));
    (max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z))
}

/// Conservative slab test for bounding volumes, as `lanes::node_slabs`: an axis giving NaN
/// (a ray lying in a face plane) bounds nothing.
#[inline]
pub fn node_slabs(lo: DVec3, hi: DVec3, o: DVec3, inv: DVec3) -> (f64, f64) {
    let t0 = (lo - o) * inv;
    let t1 = (hi - o) * inv;
    let axis = |a: f64, b: f64| {
        if a.is_nan() || b.is_nan() {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (min(a, b), max(a, b))
        }
    };
    let (nx, fx) = axis(t0.x, t1.x);
    let (ny, fy) = axis(t0.y, t1.y);
    let (nz, fz) = axis(t0.z, t1.z);
    (max(max(nx, ny), nz), min(min(fx, fy), fz))
}

#[derive(Clone, Copy, Debug)]
pub struct SphereD {
    pub center: DVec3,
    pub radius: f64,
}

impl SphereD {
    /// The stable form of `lanes::sphere`.
    #[inline]
    pub fn intersect(&self, ray: &RayD, t_min: f64, t_max: f64) -> Option<f64> {
        let oc = ray.origin - self.center;
        let b = oc.dot(ray.dir);
        let perp = oc - ray.dir * b;
        let r2 = self.radius * self.radius;
        let disc = r2 - perp.dot(perp);
        if disc < 0.0 {
            return None;
        }
        let c = oc.dot(oc) - r2;
        let q = -b - if b >= 0.0 { 1.0 } else { -1.0 } * disc.sqrt();
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q) };
        pick_root(min(t0, t1), max(t0, t1), t_min, t_max)
    }

    #[inline]
    pub fn normal_at(&self, p: DVec3) -> DVec3 {
        ((p - self.center) / self.radius).normalize_or(DVec3::Y)
    }

    pub fn bounds(&self) -> (DVec3, DVec3) {
        (self.center - self.radius, self.center + self.radius)
    }
}

/// The affine frame of an ellipsoid or a rotated box.
#[derive(Clone, Copy, Debug)]
pub struct FrameD {
    pub object_from_render: DAffine3,
    /// Inverse transpose of the render-from-object linear part.
    pub normal_to_render: DMat3,
    pub render_from_object: DAffine3,
}

impl FrameD {
    pub fn new(render_from_object: DAffine3) -> FrameD {
        FrameD {
            object_from_render: render_from_object.inverse(),
            normal_to_render: render_from_object.matrix3.inverse().transpose(),
            render_from_object,
        }
    }
}

/// The unit sphere under an affine map.
#[derive(Clone, Copy, Debug)]
pub struct EllipsoidD {
    pub frame: FrameD,
}

impl EllipsoidD {
    /// As `Ellipsoid::intersect`: `t` stays a render-space distance.
    #[inline]
    pub fn intersect(&self, ray: &RayD, t_min: f64, t_max: f64) -> Option<f64> {
        let o = self.frame.object_from_render.transform_point3(ray.origin);
        let d = self.frame.object_from_render.transform_vector3(ray.dir);
        let a = d.length_squared();
        let b = o.dot(d) / a;
        let perp = o - b * d;
        let disc = 1.0 - perp.length_squared();
        if disc < 0.0 {
            return None;
        }
        let c = (o.length_squared() - 1.0) / a;
        let q = -b - b.signum() * (disc / a).sqrt();
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q) };
        pick_root(min(t0, t1), max(t0, t1), t_min, t_max)
    }

    pub fn normal_at(&self, p: DVec3) -> DVec3 {
        let local = self.frame.object_from_render.transform_point3(p);
        (self.frame.normal_to_render * local).normalize_or(DVec3::Y)
    }

    /// The extent along each render axis is the length of that row of the linear part.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let m = self.frame.render_from_object.matrix3;
        let rows = DVec3::new(m.row(0).length(), m.row(1).length(), m.row(2).length());
        let c = self.frame.render_from_object.translation;
        (c - rows, c + rows)
    }
}

/// A box: axis-aligned in render space (`frame: None`) or in its own space.
#[derive(Clone, Copy, Debug)]
pub struct CuboidD {
    pub min: DVec3,
    pub max: DVec3,
    pub frame: Option<FrameD>,
}

impl CuboidD {
    #[inline]
    pub fn intersect(&self, ray: &RayD, t_min: f64, t_max: f64) -> Option<f64> {
        let (near, far) = match &self.frame {
            None => slabs(self.min, self.max, ray.origin, ray.inv_dir),
            Some(f) => {
                let o = f.object_from_render.transform_point3(ray.origin);
                let d = f.object_from_render.transform_vector3(ray.dir);
                slabs(self.min, self.max, o, d.recip())
            }
        };
        if near <= far {
            pick_root(near, far, t_min, t_max)
        } else {
            None
        }
    }

    /// Outward normal of the face nearest to `p`, relative to the box's extent per axis.
    pub fn normal_at(&self, p: DVec3) -> DVec3 {
        let local = match &self.frame {
            None => p,
            Some(f) => f.object_from_render.transform_point3(p),
        };
        let size = (self.max - self.min).max(DVec3::splat(f64::MIN_POSITIVE));
        let d_min = ((local - self.min) / size).abs();
        let d_max = ((self.max - local) / size).abs();
        let (mut best_d, mut best_n) = (d_min.x, -DVec3::X);
        for (d, n) in
            [(d_max.x, DVec3::X), (d_min.y, -DVec3::Y), (d_max.y, DVec3::Y), (d_min.z, -DVec3::Z), (d_max.z, DVec3::Z)]
        {
            if d < best_d {
                best_d = d;
                best_n = n;
            }
        }
        match &self.frame {
            None => best_n,
            Some(f) => (f.normal_to_render * best_n).normalize_or(best_n),
        }
    }

    pub fn bounds(&self) -> (DVec3, DVec3) {
        match &self.frame {
            None => (self.min, self.max),
            Some(f) => {
                let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
                for i in 0..8 {
                    let c = DVec3::new(
                        if i & 1 == 0 { self.min.x } else { self.max.x },
                        if i & 2 == 0 { self.min.y } else { self.max.y },
                        if i & 4 == 0 { self.min.z } else { self.max.z },
                    );
                    let w = f.render_from_object.transform_point3(c);
                    lo = lo.min(w);
                    hi = hi.max(w);
                }
                (lo, hi)
            }
        }
    }
}

#[derive(Clone, Copy, Debug)]
pub struct TriangleD {
    pub v0: DVec3,
    pub e1: DVec3,
    pub e2: DVec3,
    pub normal: DVec3,
}

impl TriangleD {
    pub fn new(a: DVec3, b: DVec3, c: DVec3) -> TriangleD {
        let (e1, e2) = (b - a, c - a);
        TriangleD { v0: a, e1, e2, normal: e1.cross(e2).normalize_or(DVec3::Y) }
    }

    /// Möller–Trumbore, as `lanes::triangle`.
    #[inline]
    pub fn intersect(&self, ray: &RayD, t_min: f64, t_max: f64) -> Option<f64> {
        let p = ray.dir.cross(self.e2);
        let det = self.e1.dot(p);
        if det == 0.0 {
            return None;
        }
        let inv = 1.0 / det;
        let s = ray.origin - self.v0;
        let u = s.dot(p) * inv;
        let q = s.cross(self.e1);
        let v = ray.dir.dot(q) * inv;
        let t = self.e2.dot(q) * inv;
        let inside = (0.0..=1.0).contains(&u) && 0.0 <= v && u + v <= 1.0;
        (inside && t > t_min && t < t_max).then_some(t)
    }

    pub fn bounds(&self) -> (DVec3, DVec3) {
        let (b, c) = (self.v0 + self.e1, self.v0 + self.e2);
        (self.v0.min(b).min(c), self.v0.max(b).max(c))
    }
}

#[derive(Clone, Debug)]
pub struct PolygonD {
    pub normal: DVec3,
    pub distance: f64,
    pub axes: [usize; 2],
    pub points: Vec<DVec2>,
    pub min: DVec3,
    pub max: DVec3,
}

impl PolygonD {
    /// Newell's method (a robust normal for any simple planar polygon) and the dominant
    /// projection; `Polygon::new` rounds this to f32.
    pub fn new(points: &[DVec3]) -> PolygonD {
        let mut n = DVec3::ZERO;
        for (i, a) in points.iter().enumerate() {
            let b = points[(i + 1) % points.len()];
            n += DVec3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        let normal = n.normalize_or(DVec3::Y);
        let centroid = points.iter().copied().sum::<DVec3>() / points.len().max(1) as f64;
        let a = normal.abs();
        let axes = if a.x >= a.y && a.x >= a.z {
            [1, 2]
        } else if a.y >= a.z {
            [2, 0]
        } else {
            [0, 1]
        };
        let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for p in points {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        PolygonD {
            normal,
            distance: normal.dot(centroid),
            axes,
            points: points.iter().map(|p| DVec2::new(p[axes[0]], p[axes[1]])).collect(),
            min: lo,
            max: hi,
        }
    }

    #[inline]
    pub fn intersect(&self, ray: &RayD, t_min: f64, t_max: f64) -> Option<f64> {
        let t = PlaneD { normal: self.normal, distance: self.distance }.intersect(ray, t_min, t_max)?;
        let p = ray.at(t);
        self.contains(DVec2::new(p[self.axes[0]], p[self.axes[1]])).then_some(t)
    }

    fn contains(&self, q: DVec2) -> bool {
        let mut inside = false;
        let n = self.points.len();
        let mut j = n - 1;
        for i in 0..n {
            let (a, b) = (self.points[i], self.points[j]);
            if (a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x {
                inside = !inside;
            }
            j = i;
        }
        inside
    }
}

/// Points `p` with `normal · p = distance`, `normal` of unit length.
#[derive(Clone, Copy, Debug)]
pub struct PlaneD {
    pub normal: DVec3,
    pub distance: f64,
}

impl PlaneD {
    /// Whether `a` and `b` lie strictly on opposite sides.
    #[inline]
    pub fn separates(&self, a: DVec3, b: DVec3) -> bool {
        let (sa, sb) = (self.normal.dot(a) - self.distance, self.normal.dot(b) - self.distance);
        (sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)
    }

    /// A ray parallel to the plane never hits it.
    #[inline]
    pub fn intersect(&self, ray: &RayD, t_min: f64, t_max: f64) -> Option<f64> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.distance - self.normal.dot(ray.origin)) / denom;
        (t > t_min && t < t_max).then_some(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_hit_where_expected() {
        let r = RayD::new(DVec3::ZERO, DVec3::Z);
        let s = SphereD { center: DVec3::new(0.0, 0.0, 5.0), radius: 1.0 };
        assert_eq!(s.intersect(&r, 0.0, f64::INFINITY), Some(4.0));
        let inside = RayD::new(DVec3::new(0.0, 0.0, 5.0), DVec3::Z);
        assert_eq!(s.intersect(&inside, 0.0, f64::INFINITY), Some(1.0));
        let b =
            CuboidD { min: DVec3::splat(-1.0) + DVec3::Z * 5.0, max: DVec3::splat(1.0) + DVec3::Z * 5.0, frame: None };
        assert_eq!(b.intersect(&r, 0.0, f64::INFINITY), Some(4.0));
        assert_eq!(b.normal_at(r.at(4.0)), -DVec3::Z);
        let t = TriangleD::new(DVec3::new(-1.0, -1.0, 2.0), DVec3::new(1.0, -1.0, 2.0), DVec3::new(0.0, 1.0, 2.0));
        assert_eq!(t.intersect(&r, 0.0, f64::INFINITY), Some(2.0));
        let floor = PlaneD { normal: DVec3::Y, distance: -1.0 };
        assert_eq!(floor.intersect(&RayD::new(DVec3::ZERO, -DVec3::Y), 0.0, f64::INFINITY), Some(1.0));
        assert_eq!(floor.intersect(&RayD::new(DVec3::ZERO, DVec3::X), 0.0, f64::INFINITY), None);
        let e = EllipsoidD {
            frame: FrameD::new(
                DAffine3::from_translation(DVec3::new(0.0, 0.0, 10.0))
                    * DAffine3::from_scale(DVec3::new(1.0, 1.0, 3.0)),
            ),
        };
        let t = e.intersect(&r, 0.0, f64::INFINITY).unwrap_or(f64::NAN);
        assert!((t - 7.0).abs() < 1e-12, "{t}");
        let (lo, hi) = e.bounds();
        assert_eq!((lo, hi), (DVec3::new(-1.0, -1.0, 7.0), DVec3::new(1.0, 1.0, 13.0)));
    }

    #[test]
    fn offset_moves_to_the_leaving_side_at_every_scale() {
        for scale in [1e-4, 1.0, 1e5, 1e6, 1e12] {
            let p = DVec3::new(scale, 0.5 * scale, 0.0);
            let up = offset_origin(p, DVec3::Y, DVec3::new(0.3, 1.0, 0.0).normalize());
            let down = offset_origin(p, DVec3::Y, DVec3::new(0.3, -1.0, 0.0).normalize());
            assert!(up.y > p.y && down.y < p.y, "scale {scale}");
        }
    }
}
