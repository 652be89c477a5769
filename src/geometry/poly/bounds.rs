//! Where a quadric's inside can be: its own box where the quadratic part is definite (an
//! ellipsoid written as a quadric), and the box of its inside within a slab or box, which
//! bounds a CSG `intersection` of a cylinder or hyperboloid with planes (chess2.pov's pieces).

use glam::{Affine3A, DMat3, DVec3, Vec3};

use super::Poly;

impl Poly {
    /// Render-space bounds of this quadric's inside within the render-space box `lo..hi`
    /// (whose sides may be infinite): what a CSG `intersection` of it with a slab or a box
    /// can reach. `None` where it cannot tighten the box: not a quadric, cross terms (a
    /// rotated quadric in its own space), an axis where it opens both ways. chess2.pov's
    /// pieces are intersections of `Cylinder_Y` and `Hyperboloid_Y` (shapes.inc) with
    /// planes: bounded this way they sit in the BVH instead of being tested by every ray.
    pub fn inside_bounds_within(&self, lo: Vec3, hi: Vec3) -> Option<(Vec3, Vec3)> {
        if self.order != 2 {
            return None;
        }
        // f = Σ a_i x_i² + g_i x_i + k, inside where f < 0.
        let (mut a, mut g, mut k) = ([0.0f64; 3], [0.0f64; 3], 0.0f64);
        for &(c, e) in &self.terms {
            match e {
                [0, 0, 0] => k += c,
                _ => {
                    let axes: Vec<usize> = (0..3).filter(|&ax| e[ax] > 0).collect();
                    match (axes.as_slice(), e[axes[0]]) {
                        (&[ax], 2) => a[ax] += c,
                        (&[ax], 1) => g[ax] += c,
                        _ => return None,
                    }
                }
            }
        }
        let object_from_render = affine_f64(&self.frame.object_from_render);
        let (olo, ohi) = interval_transform(&object_from_render, lo.as_dvec3(), hi.as_dvec3());
        let (mut blo, mut bhi) = (olo.to_array(), ohi.to_array());
        for j in 0..3 {
            let m = k + (0..3).filter(|&i| i != j).map(|i| least(a[i], g[i], blo[i], bhi[i])).sum::<f64>();
            if m == f64::NEG_INFINITY || m.is_nan() {
                continue;
            }
            let (aj, gj) = (a[j], g[j]);
            if aj > 0.0 {
                let disc = gj * gj - 4.0 * aj * m;
                if disc < 0.0 {
                    return None;
                }
                let r = disc.sqrt();
                blo[j] = blo[j].max((-gj - r) / (2.0 * aj));
                bhi[j] = bhi[j].min((-gj + r) / (2.0 * aj));
            } else if aj == 0.0 && gj > 0.0 {
                bhi[j] = bhi[j].min(-m / gj);
            } else if aj == 0.0 && gj < 0.0 {
                blo[j] = blo[j].max(-m / gj);
            }
            if blo[j] > bhi[j] {
                return None;
            }
        }
        let render_from_object = object_from_render.inverse();
        let (rlo, rhi) = interval_transform(&render_from_object, DVec3::from(blo), DVec3::from(bhi));
        // Padded for the f32 boxes and the rounding of the two transforms.
        let pad = (rhi - rlo).abs().max(rlo.abs().max(rhi.abs())) * 1e-5 + DVec3::splat(1e-6);
        let pad = DVec3::select(pad.cmpgt(DVec3::ZERO) & pad.is_finite_mask(), pad, DVec3::ZERO);
        Some(((rlo - pad).as_vec3().max(lo), (rhi + pad).as_vec3().min(hi)))
    }
}

fn affine_f64(m: &Affine3A) -> glam::DAffine3 {
    glam::DAffine3::from_mat3_translation(glam::Mat3::from(m.matrix3).as_dmat3(), m.translation.as_dvec3())
}

/// The box of `m` applied to the box `lo..hi`, by interval arithmetic: exact for an axis-aligned
/// map, conservative otherwise, and infinite sides stay infinite (a zero coefficient times an
/// infinite side adds nothing, where the corners would give NaN).
fn interval_transform(m: &glam::DAffine3, lo: DVec3, hi: DVec3) -> (DVec3, DVec3) {
    let (mut out_lo, mut out_hi) = (m.translation.to_array(), m.translation.to_array());
    for i in 0..3 {
        let col = m.matrix3.col(i);
        for j in 0..3 {
            let c = col[j];
            if c == 0.0 {
                continue;
            }
            let (p, q) = (c * lo[i], c * hi[i]);
            out_lo[j] += p.min(q);
            out_hi[j] += p.max(q);
        }
    }
    (DVec3::from(out_lo), DVec3::from(out_hi))
}

/// The least of `a x² + g x` for `x` in `[l, h]` (either side may be infinite).
fn least(a: f64, g: f64, l: f64, h: f64) -> f64 {
    if (l == f64::NEG_INFINITY && (a < 0.0 || (a == 0.0 && g > 0.0)))
        || (h == f64::INFINITY && (a < 0.0 || (a == 0.0 && g < 0.0)))
    {
        return f64::NEG_INFINITY;
    }
    let q = |x: f64| a * x * x + g * x;
    let mut m = f64::INFINITY;
    if l.is_finite() {
        m = m.min(q(l));
    }
    if h.is_finite() {
        m = m.min(q(h));
    }
    if a > 0.0 {
        let v = -g / (2.0 * a);
        if v >= l && v <= h {
            m = m.min(q(v));
        }
    }
    if a == 0.0 && g == 0.0 {
        m = m.min(0.0);
    }
    m
}

/// The object-space box of a quadric (order-2 terms) whose quadratic part is definite and whose
/// surface is not empty: an ellipsoid. `None` for every other quadric (cylinders, cones,
/// paraboloids, hyperboloids, planes), which are unbounded.
pub(super) fn quadric_box(terms: &[(f64, [u8; 3])]) -> Option<(DVec3, DVec3)> {
    let (mut a, mut g, mut k) = (DMat3::ZERO, DVec3::ZERO, 0.0);
    for &(c, e) in terms {
        let axes: Vec<usize> = (0..3).flat_map(|ax| std::iter::repeat_n(ax, e[ax] as usize)).collect();
        match axes[..] {
            [p, q] if p == q => a.col_mut(p)[p] += c,
            [p, q] => {
                a.col_mut(p)[q] += c / 2.0;
                a.col_mut(q)[p] += c / 2.0;
            }
            [p] => g[p] += c,
            _ => k += c,
        }
    }
    // Definite: Sylvester's criterion on A or on −A.
    let sign = if a.x_axis.x < 0.0 { -1.0 } else { 1.0 };
    let (a, g, k) = (a * sign, g * sign, k * sign);
    let m1 = a.x_axis.x;
    let m2 = a.x_axis.x * a.y_axis.y - a.x_axis.y * a.y_axis.x;
    let m3 = a.determinant();
    let size = a.x_axis.length() + a.y_axis.length() + a.z_axis.length();
    if !(m1 > 1e-12 * size && m2 > 1e-12 * size * size && m3 > 1e-12 * size * size * size) {
        return None;
    }
    // f(x) = (x − c)ᵀA(x − c) + f(c) with c = −A⁻¹g/2.
    let inv = a.inverse();
    let c = -(inv * g) * 0.5;
    let fc = k - c.dot(a * c);
    if fc.is_nan() || fc >= 0.0 {
        return None;
    }
    // Half-widths sqrt(−f(c)·(A⁻¹)ᵢᵢ), padded for rounding.
    let h = DVec3::new(inv.x_axis.x, inv.y_axis.y, inv.z_axis.z).max(DVec3::ZERO) * -fc;
    let h = DVec3::new(h.x.sqrt(), h.y.sqrt(), h.z.sqrt()) * (1.0 + 1e-6) + DVec3::splat(1e-9 * c.abs().max_element());
    Some((c - h, c + h))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::roots::Solver;
    use crate::geometry::Shape;
    use crate::lanes::{Lane, V3};

    #[test]
    fn a_quadric_inside_a_slab_gets_the_box_of_its_inside_there() {
        let inf = f32::INFINITY;
        // Cylinder_Y scaled by 2 (x² + z² − 1 < 0) in the slab 8 < y < 10: |x|, |z| ≤ 2.
        let cyl = Poly::new(
            Affine3A::from_scale(Vec3::new(2.0, 1.0, 2.0)),
            2,
            &[1., 0., 0., 0., 0., 0., 0., 1., 0., -1.],
            Solver::Fast,
        );
        let (lo, hi) = cyl.inside_bounds_within(Vec3::new(-inf, 8.0, -inf), Vec3::new(inf, 10.0, inf)).unwrap();
        assert!((lo - Vec3::new(-2.0, 8.0, -2.0)).abs().max_element() < 1e-3, "{lo}");
        assert!((hi - Vec3::new(2.0, 10.0, 2.0)).abs().max_element() < 1e-3, "{hi}");
        // Hyperboloid_Y (x² − y² + z² − 1 < 0) moved up 5, in 3 < y < 8: x² + z² < 1 + 9.
        let hyp = Poly::new(
            Affine3A::from_translation(Vec3::new(0.0, 5.0, 0.0)),
            2,
            &[1., 0., 0., 0., -1., 0., 0., 1., 0., -1.],
            Solver::Fast,
        );
        let (lo, hi) = hyp.inside_bounds_within(Vec3::new(-inf, 3.0, -inf), Vec3::new(inf, 8.0, inf)).unwrap();
        let r = 10f32.sqrt();
        assert!((lo - Vec3::new(-r, 3.0, -r)).abs().max_element() < 1e-3, "{lo}");
        assert!((hi - Vec3::new(r, 8.0, r)).abs().max_element() < 1e-3, "{hi}");
        // Every inside point of the slab lies in the box (seeded grid).
        for i in 0..2000 {
            let h = |k: u32| ((i * 7919 + k * 104729) % 1000) as f32 / 1000.0;
            let p = Vec3::new(h(1) * 10.0 - 5.0, 3.0 + h(2) * 5.0, h(3) * 10.0 - 5.0);
            if f32::mask_lane(hyp.inside(V3::<f32>::from_vec3(p)), 0) {
                assert!(p.cmpge(lo).all() && p.cmple(hi).all(), "{p} outside {lo}..{hi}");
            }
        }
        // Unbounded across: a paraboloid opening along the slab's free axes stays unbounded.
        let cone = Poly::new(Affine3A::IDENTITY, 2, &[1., 0., 0., 0., -1., 0., 0., 1., 0., 0.], Solver::Fast);
        let (lo, _) = cone.inside_bounds_within(Vec3::splat(-inf), Vec3::splat(inf)).unwrap();
        assert!(lo.x.is_infinite());
    }
}
