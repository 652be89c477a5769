//! Ray/polygon intersection as in chapter 24.3: hit the polygon's plane, then test whether the
//! point lies inside the outline (crossing-number test in the plane's dominant 2D projection).

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::plane::Plane;
use super::Shape;
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Debug)]
pub struct Polygon {
    /// The polygon's plane.
    pub plane: Plane,
    /// The two axes kept by the projection (the normal's largest component is dropped).
    pub axes: [usize; 2],
    /// Outline projected onto `axes`.
    pub points: Vec<Vec2>,
    pub min: Vec3,
    pub max: Vec3,
}

impl Polygon {
    /// `points` (render space, f64) must be planar with a well-defined normal (the parser
    /// rejects degenerate ones). The plane and projection are found once, in f64 (Newell's
    /// method, a robust normal for any simple planar polygon, and the dominant axes), then
    /// rounded to f32.
    pub fn new(points: &[DVec3]) -> Polygon {
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
        Polygon {
            plane: Plane { normal: normal.as_vec3(), distance: normal.dot(centroid) as f32 },
            axes,
            points: points.iter().map(|p| DVec2::new(p[axes[0]], p[axes[1]]).as_vec2()).collect(),
            min: lo.as_vec3(),
            max: hi.as_vec3(),
        }
    }
}

impl Shape for Polygon {
    /// The plane's hit, kept where it lies inside the outline by the even-odd rule: count the
    /// edges a ray from the point towards +u crosses.
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let t = self.plane.hit(ray, t_min, t_max);
        let p = ray.at(t);
        let (qx, qy) = (p.axis(self.axes[0]), p.axis(self.axes[1]));
        let mut inside = L::lt(L::splat(0.0), L::splat(0.0));
        let n = self.points.len();
        let mut j = n - 1;
        for i in 0..n {
            let (a, b) = (self.points[i], self.points[j]);
            let straddles = L::xor(qy.lt(L::splat(a.y)), qy.lt(L::splat(b.y)));
            let x = L::splat(b.x - a.x) * (qy - L::splat(a.y)) / L::splat(b.y - a.y) + L::splat(a.x);
            inside = L::xor(inside, L::and(straddles, qx.lt(x)));
            j = i;
        }
        L::select(L::and(inside, t.lt(L::splat(MISS))), t, L::splat(MISS))
    }

    #[inline(always)]
    fn normal<L: Lane>(&self, _: V3<L>) -> V3<L> {
        V3::splat(self.plane.normal)
    }

    /// Flat: no inside.
    #[inline(always)]
    fn inside<L: Lane>(&self, _: V3<L>) -> L::Mask {
        L::mask_from_fn(|_| false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ray::Ray;

    /// An L-shaped (concave) outline in the plane z = 3.
    fn ell() -> Polygon {
        let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)];
        Polygon::new(&pts.map(|(x, y)| DVec3::new(x, y, 3.0)))
    }

    #[test]
    fn hit_miss_and_concave_notch() {
        let p = ell();
        let at = |x: f32, y: f32| Ray::new(Vec3::new(x, y, 0.0), Vec3::Z);
        assert_eq!(p.intersect(&at(0.5, 0.5), 0.0, f32::INFINITY), Some(3.0));
        assert_eq!(p.intersect(&at(1.5, 1.5), 0.0, f32::INFINITY), None, "notch");
        assert_eq!(p.intersect(&at(3.0, 0.5), 0.0, f32::INFINITY), None);
        let behind = Ray::new(Vec3::new(0.5, 0.5, 4.0), Vec3::Z);
        assert_eq!(p.intersect(&behind, 0.0, f32::INFINITY), None);
        let parallel = Ray::new(Vec3::new(0.5, 0.5, 3.0), Vec3::X);
        assert_eq!(p.intersect(&parallel, 0.0, f32::INFINITY), None);
    }

    #[test]
    fn normal_is_unit_and_perpendicular() {
        let p = ell();
        assert!((p.plane.normal.abs() - Vec3::Z).length() < 1e-6);
    }
}
