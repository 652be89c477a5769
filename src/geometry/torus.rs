//! POV-Ray's `torus { major, minor }`: the ring of radius `major` in the xz-plane around the
//! y axis, swept by a circle of radius `minor`. A quartic surface, solved per lane in f64 by
//! `roots` (this shape has no 8-wide arithmetic: packets run its f64 solve lane by lane).
//!
//! In object space the major radius is 1 (the frame's scale carries it), so the quartic's
//! coefficients have the size of the torus. The ray is first moved to its point nearest the
//! centre and its direction made unit, which keeps them so for a torus seen from far away.

use glam::{Affine3A, Vec3};

use super::cuboid::{frame_for, BoxFrame};
use super::roots::{roots_in, MAX_DEGREE};
use super::{transformed_bounds, Shape};
use crate::lanes::{Lane, V3};
use crate::ray::{RayLanes, MISS};

#[derive(Clone, Copy, Debug)]
pub struct Torus {
    pub frame: BoxFrame,
    /// Minor radius relative to the major one.
    pub minor: f32,
    pub min: Vec3,
    pub max: Vec3,
}

impl Torus {
    /// A torus of major radius 1 and minor radius `minor` under `render_from_object`.
    pub fn new(render_from_object: Affine3A, minor: f32) -> Torus {
        let extent = Vec3::new(1.0 + minor, minor, 1.0 + minor);
        let (lo, hi) = transformed_bounds(&render_from_object, -extent, extent);
        Torus { frame: frame_for(render_from_object), minor, min: lo, max: hi }
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (self.min, self.max)
    }
}

/// The nearest `t` in `(t_min, t_max)` where `o + t·d` (object space) meets the torus.
/// `round` is the lane's rounding (`Lane::round_f64`): roots are compared with the interval as
/// the lane will hold them.
fn solve(o: [f64; 3], d: [f64; 3], minor: f64, t_min: f64, t_max: f64, round: fn(f64) -> f64) -> Option<f64> {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let super::CentredRay { p, u, t_c, len } = super::centred_ray(o, d)?;
    let outer = 1.0 + minor;
    let reach2 = outer * outer - dot(p, p);
    if reach2.is_nan() || reach2 < 0.0 {
        return None;
    }
    // s: distance along u from p; t = t_c + s / len.
    // Padded: the outer equator lies on this sphere, and a root there must not be cut off.
    let reach = reach2.sqrt() * (1.0 + 1e-9) + 1e-12;
    let lo = (-reach).max((t_min - t_c) * len);
    let hi = reach.min((t_max - t_c) * len);
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return None;
    }
    let e = dot(p, p) + 1.0 - minor * minor;
    let f = dot(p, u);
    let a2 = u[0] * u[0] + u[2] * u[2];
    let b2 = p[0] * u[0] + p[2] * u[2];
    let c2 = p[0] * p[0] + p[2] * p[2];
    let c = [1.0, 4.0 * f, 4.0 * f * f + 2.0 * e - 4.0 * a2, 4.0 * f * e - 8.0 * b2, e * e - 4.0 * c2];
    // The first root whose `t` lies in the interval: a root at `t_min` itself (CSG looking
    // past a rejected crossing, with `t_min` that crossing rounded) may land on either side.
    let mut roots = [0.0; MAX_DEGREE];
    let n = roots_in(&c, lo, hi, &mut roots);
    roots[..n].iter().map(|s| round(t_c + s / len)).find(|&t| t > t_min && t < t_max)
}

impl Shape for Torus {
    #[inline(always)]
    fn hit<L: Lane>(&self, ray: &RayLanes<L>, t_min: L, t_max: L) -> L {
        let o = ray.o.transform_point(&self.frame.object_from_render);
        let d = ray.d.transform_vector(&self.frame.object_from_render);
        L::from_fn_f64(|i| {
            let v = |v: V3<L>| [v.x.get_f64(i), v.y.get_f64(i), v.z.get_f64(i)];
            let (lo, hi) = (t_min.get_f64(i), t_max.get_f64(i));
            solve(v(o), v(d), self.minor as f64, lo, hi, L::round_f64).unwrap_or(MISS as f64)
        })
    }

    /// Away from the nearest point of the ring.
    #[inline(always)]
    fn normal<L: Lane>(&self, p: V3<L>) -> V3<L> {
        let q = p.transform_point(&self.frame.object_from_render);
        let rho = (q.x * q.x + q.z * q.z).sqrt();
        let ring = V3 { x: q.x / rho, y: L::splat(0.0), z: q.z / rho };
        q.sub(ring).mat3_mul(&self.frame.normal_to_render).normalize_or(V3::splat(Vec3::Y))
    }

    #[inline(always)]
    fn inside<L: Lane>(&self, p: V3<L>) -> L::Mask {
        let q = p.transform_point(&self.frame.object_from_render);
        let rho = (q.x * q.x + q.z * q.z).sqrt() - L::splat(1.0);
        (rho * rho + q.y * q.y).lt(L::splat(self.minor * self.minor))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lanes::F8;
    use crate::ray::Ray;

    fn torus() -> Torus {
        // Major 2, minor 0.5, centred at z = 10.
        Torus::new(Affine3A::from_translation(Vec3::new(0.0, 0.0, 10.0)) * Affine3A::from_scale(Vec3::splat(2.0)), 0.25)
    }

    #[test]
    fn hits_outer_and_inner_walls_and_misses_the_hole() {
        let t = torus();
        // Along z over the ring's x = 2: the tube's outer surface, 1.5 before the centre plane.
        let r = Ray::new(Vec3::new(2.0, 0.0, 0.0), Vec3::Z);
        let hit = t.intersect(&r, 0.0, f32::INFINITY).expect("tube");
        assert!((hit - 8.5).abs() < 1e-5, "{hit}");
        // Along z through the hole: nothing... the ring lies across it at z = 10 ± 2 though.
        let hole = Ray::new(Vec3::new(0.0, 0.0, 0.0), Vec3::Z);
        let hit = t.intersect(&hole, 0.0, f32::INFINITY).expect("ring across the axis");
        assert!((hit - 7.5).abs() < 1e-5, "{hit}");
        // Straight down the y axis through the hole: a miss.
        let down = Ray::new(Vec3::new(0.0, 5.0, 10.0), -Vec3::Y);
        assert_eq!(t.intersect(&down, 0.0, f32::INFINITY), None);
        // Down through the tube.
        let tube = Ray::new(Vec3::new(2.0, 5.0, 10.0), -Vec3::Y);
        let hit = t.intersect(&tube, 0.0, f32::INFINITY).expect("top of tube");
        assert!((hit - 4.5).abs() < 1e-5);
        assert!((t.normal_at(tube.at(hit)) - Vec3::Y).length() < 1e-5);
        // From inside the tube, the far wall.
        let inside = Ray::new(Vec3::new(2.0, 0.0, 10.0), Vec3::X);
        let hit = t.intersect(&inside, 0.0, f32::INFINITY).expect("wall");
        assert!((hit - 0.5).abs() < 1e-5);
    }

    #[test]
    fn grazing_and_far_rays_and_packets() {
        let t = torus();
        // Tangent to the top of the tube: y = 0.5 exactly.
        let graze = Ray::new(Vec3::new(-10.0, 0.5, 10.0), Vec3::X);
        let hit = t.intersect(&graze, 0.0, f32::INFINITY);
        assert!(hit.is_none_or(|h| (h - 8.0).abs() < 1e-2 || (h - 12.0).abs() < 1e-2), "{hit:?}");
        // From 1e5 away the tube is still where it is.
        let far = Ray::new(Vec3::new(2.0, 0.0, -1e5), Vec3::Z);
        let hit = t.intersect(&far, 0.0, f32::INFINITY).expect("far");
        assert!((hit - (1e5 + 8.5)).abs() < 2e-2, "{hit}");
        let rays: [Ray; 8] = std::array::from_fn(|i| {
            let o = Vec3::new(i as f32 * 0.6 - 2.0, 0.1 * i as f32, 0.0);
            Ray::new(o, (Vec3::new(1.5, 0.2, 10.0) - o).normalize())
        });
        let packet = RayLanes::<F8> {
            o: V3::from_lanes(|i| rays[i].origin),
            d: V3::from_lanes(|i| rays[i].dir),
            inv: V3::from_lanes(|i| rays[i].inv_dir),
        };
        let wide = t.hit(&packet, F8::splat(0.0), F8::splat(MISS));
        for (i, r) in rays.iter().enumerate() {
            assert_eq!(wide.get(i).to_bits(), t.hit(&r.lanes(), 0.0, MISS).to_bits());
        }
    }
}
