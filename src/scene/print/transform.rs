//! A transform as `rotate`, `scale`, `rotate`, `translate` (singular value decomposition).

use std::fmt::Write;

use glam::{DMat3, DMat4, DVec3};

use super::vec;
use crate::desc::Transform;

/// `m` as ` rotate … scale … rotate … translate …` (empty for the identity).
pub(super) fn modifiers(m: &DMat4) -> String {
    if *m == DMat4::IDENTITY {
        return String::new();
    }
    let d = decompose(m);
    let mut out = String::new();
    for (word, v, skip) in [
        ("rotate", d.rotate_first, DVec3::ZERO),
        ("scale", d.scale, DVec3::ONE),
        ("rotate", d.rotate_then, DVec3::ZERO),
        ("translate", d.translate, DVec3::ZERO),
    ] {
        if v != skip {
            let _ = write!(out, " {word} {}", vec(v));
        }
    }
    out
}

/// An affine map as POV-Ray modifiers, applied in this order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decomposed {
    /// Euler angles in degrees (about x, then y, then z), POV-Ray's `rotate`.
    pub rotate_first: DVec3,
    pub scale: DVec3,
    pub rotate_then: DVec3,
    pub translate: DVec3,
}

impl Decomposed {
    /// The matrix the loader builds from these modifiers.
    pub fn matrix(&self) -> DMat4 {
        DMat4::from_translation(self.translate)
            * euler_matrix(self.rotate_then)
            * DMat4::from_scale(self.scale)
            * euler_matrix(self.rotate_first)
    }
}

/// `rotate <a, b, c>` (degrees) as the loader builds it.
fn euler_matrix(deg: DVec3) -> DMat4 {
    let r = deg * (std::f64::consts::PI / 180.0);
    DMat4::from_rotation_z(r.z) * DMat4::from_rotation_y(r.y) * DMat4::from_rotation_x(r.x)
}

/// Splits the linear part of `m` as U·Σ·Vᵀ (one-sided Jacobi SVD, f64), U and V proper rotations.
pub fn decompose(m: &DMat4) -> Decomposed {
    let lin = DMat3::from_mat4(*m);
    let mut a = [lin.x_axis, lin.y_axis, lin.z_axis];
    let mut v = [DVec3::X, DVec3::Y, DVec3::Z];
    // Each sweep rotates column pairs until they are orthogonal; 3×3 converges in a few sweeps.
    for _ in 0..60 {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let alpha = a[p].length_squared();
            let beta = a[q].length_squared();
            let gamma = a[p].dot(a[q]);
            if gamma == 0.0 || gamma.abs() <= 1e-17 * (alpha * beta).sqrt() {
                continue;
            }
            rotated = true;
            let zeta = (beta - alpha) / (2.0 * gamma);
            let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
            let c = 1.0 / (1.0 + t * t).sqrt();
            let s = c * t;
            let (ap, aq) = (a[p], a[q]);
            a[p] = c * ap - s * aq;
            a[q] = s * ap + c * aq;
            let (vp, vq) = (v[p], v[q]);
            v[p] = c * vp - s * vq;
            v[q] = s * vp + c * vq;
        }
        if !rotated {
            break;
        }
    }
    let mut sigma = DVec3::new(a[0].length(), a[1].length(), a[2].length());
    let mut u = [0, 1, 2].map(|i| if sigma[i] > 0.0 { a[i] / sigma[i] } else { DVec3::ZERO });
    // A zero singular value (never from the loader, which refuses scale 0) gets any completing axis.
    for i in 0..3 {
        if sigma[i] == 0.0 {
            u[i] = u[(i + 1) % 3].cross(u[(i + 2) % 3]).try_normalize().unwrap_or(DVec3::X);
        }
    }
    let mut u_mat = DMat3::from_cols(u[0], u[1], u[2]);
    let v_mat = DMat3::from_cols(v[0], v[1], v[2]);
    if u_mat.determinant() < 0.0 {
        // A mirror: fold the reflection into the scale.
        sigma.x = -sigma.x;
        u_mat.x_axis = -u_mat.x_axis;
    }
    Decomposed {
        rotate_first: euler_degrees(&v_mat.transpose()),
        scale: sigma,
        rotate_then: euler_degrees(&u_mat),
        translate: m.w_axis.truncate(),
    }
}

/// Angles `<a, b, c>` (degrees) with `R = Rz(c)·Ry(b)·Rx(a)`.
fn euler_degrees(r: &DMat3) -> DVec3 {
    let at = |row: usize, col: usize| r.col(col)[row];
    let cos_b = (at(0, 0) * at(0, 0) + at(1, 0) * at(1, 0)).sqrt();
    let b = (-at(2, 0)).atan2(cos_b);
    let (a, c) = if cos_b > 1e-12 {
        (at(2, 1).atan2(at(2, 2)), at(1, 0).atan2(at(0, 0)))
    } else {
        // Gimbal lock: only a ± c is defined; put it all in a.
        ((-at(1, 2)).atan2(at(1, 1)), 0.0)
    };
    DVec3::new(a, b, c) * (180.0 / std::f64::consts::PI)
}

/// The transform POV-Ray's modifiers from `decompose` rebuild: for checks.
pub fn recomposed(t: &Transform) -> DMat4 {
    decompose(&t.matrix).matrix()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decompose_rebuilds_rotation_scale_shear_and_mirror() {
        let cases = [
            DMat4::IDENTITY,
            DMat4::from_rotation_y(0.3) * DMat4::from_scale(DVec3::new(1.0, 2.0, 3.0)),
            DMat4::from_scale(DVec3::new(1.0, 2.0, 3.0)) * DMat4::from_rotation_x(0.7) * DMat4::from_rotation_z(-1.1),
            DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0)) * DMat4::from_rotation_y(0.2),
            DMat4::from_translation(DVec3::new(1e6, -3.0, 2.5)) * DMat4::from_rotation_x(std::f64::consts::FRAC_PI_2),
            DMat4::from_rotation_y(std::f64::consts::FRAC_PI_2) * DMat4::from_scale(DVec3::splat(1e-4)),
            DMat4::from_scale(DVec3::new(2.0, 2.0, 0.5)),
        ];
        for m in cases {
            let back = decompose(&m).matrix();
            let err = (back - m).to_cols_array().iter().map(|v| v.abs()).fold(0.0, f64::max);
            let size = m.to_cols_array().iter().map(|v| v.abs()).fold(0.0, f64::max);
            assert!(err <= 1e-12 * size, "{m:?} → {:?}, error {err}", decompose(&m));
        }
    }
}
