//! Ray/polygon intersection as in chapter 24.3: hit the polygon's plane, then test whether the
//! point lies inside the outline (crossing-number test in the plane's dominant 2D projection).

use glam::{DVec3, Vec2, Vec3};

use super::precise::PolygonD;
use super::ray::Ray;

#[derive(Clone, Debug)]
pub struct Polygon {
    pub normal: Vec3,
    pub distance: f32,
    /// The two axes kept by the projection (the normal's largest component is dropped).
    pub axes: [usize; 2],
    /// Outline projected onto `axes`.
    pub points: Vec<Vec2>,
    pub min: Vec3,
    pub max: Vec3,
}

impl Polygon {
    /// `points` (render space, f64) must be planar with a well-defined normal (the parser
    /// rejects degenerate ones). The plane and projection are found once, in f64
    /// (`PolygonD::new`: Newell's normal, the dominant axes), and rounded to f32 here.
    pub fn new(points: &[DVec3]) -> Polygon {
        let d = PolygonD::new(points);
        Polygon {
            normal: d.normal.as_vec3(),
            distance: d.distance as f32,
            axes: d.axes,
            points: d.points.iter().map(|p| p.as_vec2()).collect(),
            min: d.min.as_vec3(),
            max: d.max.as_vec3(),
        }
    }

    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.distance - self.normal.dot(ray.origin)) / denom;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let p = ray.at(t);
        self.contains(Vec2::new(p[self.axes[0]], p[self.axes[1]])).then_some(t)
    }

    /// Even-odd rule: count crossings of a ray towards +u.
    fn contains(&self, q: Vec2) -> bool {
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

#[cfg(test)]
mod tests {
    use super::*;

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
        assert!((p.normal.abs() - Vec3::Z).length() < 1e-6);
    }
}
