//! POV-Ray 3.7's projections and focal blur: how a camera turns image coordinates into rays.
//!
//! Image coordinates are `u, v` in [0, 1]² with v down, as `render` samples pixels. Every
//! projection is written from POV-Ray's documentation and checked against POV-Ray 3.7 renders
//! (tests/reference/scenes/cameras_*.pov); the formulas are in terms of the centred coordinates
//! `px = u - 0.5` (right) and `py = 0.5 - v` (up). `Rn`, `Un`, `Dn` are the unit right, up and
//! direction vectors.
//!
//! | projection | ray |
//! |---|---|
//! | perspective | from `location` along `D + px·R + py·U` (in `render`, f32, unchanged) |
//! | orthographic | from `location + px·R + py·U` along `Dn` |
//! | fisheye | polar (r, φ) of (2px, 2py) stretched to a circle; θ = r·angle/2 off `Dn`; none past r = 1 |
//! | ultra_wide_angle | x = px·angle, y = py·angle·\|U\|/\|R\|; `sin x·Rn + sin y·Un + cos x cos y·Dn` |
//! | omnimax | polar (r, φ) as fisheye's where \|R\|/\|U\| ≤ 1, else about a centre moved down (`omnimax_polar`); θ = 1.41127 r − 0.09439 r³ + 0.25674 r⁵; none past r = 1 or more than 45° below the axis's horizon |
//! | panoramic | lon = px·π, lat = py·π; `cos lat (sin lon·R + cos lon·D) + sin lat·U` (the vectors' lengths are the ellipsoid's axes) |
//! | cylinder 1 | vertical axis, fixed eye: x = px·angle; `sin x·Rn + py·U + cos x·Dn` |
//! | cylinder 2 | horizontal axis, fixed eye: y = py·angle; `px·R + sin y·Un + cos y·Dn` |
//! | cylinder 3 | vertical axis, eye moves: from `location + py·U` along `sin x·Rn + cos x·Dn` |
//! | cylinder 4 | horizontal axis, eye moves: from `location + px·R` along `sin y·Un + cos y·Dn` |
//! | spherical | lon = px·h, lat = py·v; `cos lat sin lon·Rn + sin lat·Un + cos lat cos lon·Dn` |
//!
//! Focal blur moves each ray's origin to a point of the lens (a disc of radius `aperture`/4
//! across `Rn`, `Un`) and aims it at the point where the unblurred ray meets the focal plane
//! (facing `Dn`, as far from `location` as `focal_point` is). The lens point and a jitter inside the pixel come from
//! a hash of (pixel, sub-sample, blur sample): never a shared generator, so an image is the
//! same whatever the thread count or tile order.

use glam::DVec3;

use super::mesh::CameraMesh;
use crate::desc::{Lens, Projection};

/// A camera's vectors (already in render space) with the projection, ready to make rays in f64.
#[derive(Clone, Copy, Debug)]
pub struct LensRays<'a> {
    pub projection: Projection,
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    rn: DVec3,
    un: DVec3,
    dn: DVec3,
    /// |R| / |U|.
    aspect: f64,
    /// Render units per world unit.
    scale: f64,
    /// Focal blur: lens radius and the focal plane's distance along `dn` from `location`.
    blur: Option<(f64, f64)>,
    /// A mesh camera's faces (`Projection::Mesh`).
    mesh: Option<&'a CameraMesh>,
}

impl<'a> LensRays<'a> {
    /// `location` and the vectors in render space (`scale` render units per world unit);
    /// `world_location` is the camera's location in the scene, where `focal_point` is measured.
    pub fn new(
        lens: &Lens,
        (location, world_location): (DVec3, DVec3),
        direction: DVec3,
        right: DVec3,
        up: DVec3,
        scale: f64,
    ) -> LensRays<'a> {
        let unit = |v: DVec3| v.try_normalize().unwrap_or(DVec3::ZERO);
        let dn = unit(direction);
        let blur = lens.blur.map(|b| {
            // The focal plane lies as far along `dn` as `focal_point` is from the camera (its
            // distance, not its depth: measured, an off-axis focal point moves the plane away).
            let focal = (b.focal_point - world_location).length() * scale;
            // Measured on POV-Ray 3.7 (a thin line behind the focal plane, its blur's width for
            // several apertures, focal distances and angles): the lens disc has radius
            // aperture/4, half of what `aperture` as a diameter would give.
            (0.25 * b.aperture * scale, focal)
        });
        LensRays {
            projection: lens.projection,
            location,
            direction,
            right,
            up,
            rn: unit(right),
            un: unit(up),
            dn,
            aspect: right.length() / up.length(),
            scale,
            blur,
            mesh: None,
        }
    }

    /// These rays with a mesh camera's faces (render space), which `Projection::Mesh` needs.
    pub fn with_mesh(self, mesh: Option<&'a CameraMesh>) -> LensRays<'a> {
        LensRays { mesh, ..self }
    }

    /// A mesh camera's ray number `ray` of pixel (x, y) of a w×h image at image point
    /// (u, v) (`camera::mesh`), moved along its normal by `location.z` and reversed as
    /// `direction` says; `None` where no face belongs to it, or for other projections.
    pub fn mesh_ray(&self, pixel: (u32, u32, u32, u32), uv: (f64, f64), ray: u32) -> Option<(DVec3, DVec3)> {
        let Projection::Mesh { offset, reverse, .. } = self.projection else { return None };
        let (o, n) = self.mesh?.ray(pixel, uv, ray)?;
        let d = if reverse { -n } else { n };
        Some((o + n * (offset * self.scale), d))
    }

    /// Whether rays are moved onto a lens (focal blur).
    pub fn has_blur(&self) -> bool {
        self.blur.is_some()
    }

    /// Whether every ray starts at `location` (before focal blur).
    pub fn shared_origin(&self) -> bool {
        !matches!(
            self.projection,
            Projection::Orthographic | Projection::Cylinder { kind: 3 | 4, .. } | Projection::Mesh { .. }
        )
    }

    /// Whether every pixel has a ray (fisheye and omnimax leave the corners black).
    pub fn covers_image(&self) -> bool {
        !matches!(self.projection, Projection::Fisheye { .. } | Projection::Omnimax | Projection::Mesh { .. })
    }

    /// The ray (origin, unnormalised direction) through image point (u, v), or `None` where
    /// the projection has none (POV-Ray leaves such pixels black).
    pub fn ray(&self, u: f64, v: f64) -> Option<(DVec3, DVec3)> {
        let (px, py) = (u - 0.5, 0.5 - v);
        let (rn, un, dn) = (self.rn, self.un, self.dn);
        let o = self.location;
        let r = match self.projection {
            Projection::Perspective => (o, self.direction + self.right * px + self.up * py),
            Projection::Orthographic => (o + self.right * px + self.up * py, dn),
            Projection::Fisheye { angle } => {
                let (phi, r) = self.polar(px, py)?;
                let theta = r * angle.to_radians() * 0.5;
                (o, self.off_axis(phi, theta))
            }
            Projection::Omnimax => {
                let (phi, rad) = self.omnimax_polar(px, py)?;
                let [a, b, c] = OMNIMAX_THETA;
                let d = self.off_axis(phi, rad * (a + rad * rad * (b + rad * rad * c)));
                // Nothing more than 45° below the view axis's horizon: the dome's lower edge.
                if d.dot(un) + d.dot(dn) < 0.0 {
                    return None;
                }
                (o, d)
            }
            Projection::UltraWideAngle { angle } => {
                let a = angle.to_radians();
                let (x, y) = (px * a, py * a / self.aspect);
                (o, rn * x.sin() + un * y.sin() + dn * (x.cos() * y.cos()))
            }
            Projection::Panoramic => {
                let (x, y) = (px * std::f64::consts::PI, py * std::f64::consts::PI);
                let (d, rr, uu) = (self.direction.length(), self.right.length(), self.up.length());
                (o, rn * (x.sin() * y.cos() * rr) + un * (y.sin() * uu) + dn * (x.cos() * y.cos() * d))
            }
            Projection::Cylinder { kind, angle } => {
                let a = angle.to_radians();
                let (x, y) = (px * a, py * a);
                // `up` and `right` in world units: render space is `scale` times larger.
                match kind {
                    1 => (o, rn * x.sin() + self.up * (py / self.scale) + dn * x.cos()),
                    2 => (o, self.right * (px / self.scale) + un * y.sin() + dn * y.cos()),
                    3 => (o + self.up * py, rn * x.sin() + dn * x.cos()),
                    _ => (o + self.right * px, un * y.sin() + dn * y.cos()),
                }
            }
            Projection::Spherical { h, v } => {
                let (lon, lat) = (px * h.to_radians(), py * v.to_radians());
                (o, rn * (lat.cos() * lon.sin()) + un * lat.sin() + dn * (lat.cos() * lon.cos()))
            }
            // Rays of a mesh camera need the pixel's number: `mesh_ray`.
            Projection::Mesh { .. } => return None,
        };
        Some(r)
    }

    /// Polar coordinates (φ, r) of the centred point stretched so the image's shorter side
    /// spans [-1, 1]; `None` outside the unit circle.
    fn polar(&self, px: f64, py: f64) -> Option<(f64, f64)> {
        let (mut x, mut y) = (2.0 * px, 2.0 * py);
        if self.aspect > 1.0 {
            x *= self.aspect;
        } else {
            y /= self.aspect;
        }
        let r = x.hypot(y);
        (r <= 1.0).then(|| (y.atan2(x), r))
    }

    /// Omnimax's polar coordinates (φ, r) of the centred point, measured from POV-Ray 3.7
    /// (each ray's x, y and z coded as 16-bit grey at five `right`/`up` ratios a: every
    /// pixel's ray or its absence reproduced, directions to 0.001°). With both image axes
    /// spanning [-1, 1], a ≤ 1 stretches y by 1/a as the fisheye does; above 1 the centre
    /// moves down by s − 1 and both axes shrink by s = min(a, OMNIMAX_STRETCH), x stretched
    /// by a. `None` outside the unit circle.
    fn omnimax_polar(&self, px: f64, py: f64) -> Option<(f64, f64)> {
        let (u, v, a) = (2.0 * px, 2.0 * py, self.aspect);
        let (x, y) = if a <= 1.0 {
            (u, v / a)
        } else {
            let s = a.min(OMNIMAX_STRETCH);
            (u * a / s, (v + s - 1.0) / s)
        };
        let r = x.hypot(y);
        (r <= 1.0).then(|| (y.atan2(x), r))
    }

    /// The unit direction `theta` off the view axis, at polar angle `phi` in the image plane.
    fn off_axis(&self, phi: f64, theta: f64) -> DVec3 {
        let (sp, cp) = phi.sin_cos();
        let (st, ct) = theta.sin_cos();
        self.rn * (cp * st) + self.un * (sp * st) + self.dn * ct
    }

    /// `ray` moved onto the lens: from a point of the aperture disc (`lens` in [0, 1)², mapped
    /// uniformly onto the disc) towards where `ray` meets the focal plane. Unchanged without
    /// blur, or where the ray never meets the plane ahead.
    pub fn blurred(&self, (o, d): (DVec3, DVec3), lens: (f64, f64)) -> (DVec3, DVec3) {
        let Some((radius, focal)) = self.blur else { return (o, d) };
        let along = d.dot(self.dn);
        if along <= 0.0 {
            return (o, d);
        }
        let t = (focal - (o - self.location).dot(self.dn)) / along;
        let target = o + d * t;
        let (r, a) = (radius * lens.0.sqrt(), std::f64::consts::TAU * lens.1);
        let origin = o + self.rn * (r * a.cos()) + self.un * (r * a.sin());
        let dir = if t > 0.0 { target - origin } else { d };
        (origin, dir)
    }
}

/// The largest `right`/`up` ratio by which an omnimax image moves its axis down and
/// shrinks (measured: `Lens::omnimax_polar`).
const OMNIMAX_STRETCH: f64 = 1.283458;

/// Omnimax's θ off the axis, an odd quintic of the polar radius (fitted to POV-Ray 3.7's
/// rays, 0.0014° rms): about 90° at the rim.
const OMNIMAX_THETA: [f64; 3] = [1.41126898, -0.09439041, 0.25674048];

/// A well-mixed 64-bit hash (SplitMix64's finaliser) of a few words: the jitter of one sample.
pub fn hash_words(words: &[u64]) -> u64 {
    let mut h = 0x9E37_79B9_7F4A_7C15u64;
    for &w in words {
        h ^= w.wrapping_add(0x9E37_79B9_7F4A_7C15).wrapping_add(h << 6).wrapping_add(h >> 2);
        h = (h ^ (h >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        h = (h ^ (h >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        h ^= h >> 31;
    }
    h
}

/// Four numbers in [0, 1) for blur sample `sample` of a pixel's sub-sample: lens (r², angle)
/// and the jitter inside the pixel.
///
/// The samples of one pixel are the four-dimensional R-sequence (Roberts 2018: `s·αₖ mod 1`,
/// αₖ = φ₄^−k for φ₄ the root of x⁵ = x + 1) shifted by a hash of the pixel (Cranley–Patterson
/// rotation). Every prefix of it covers the lens and the pixel evenly, so a pixel that stops
/// early (`blur_samples`' adaptive stop, `render::blur`) has seen its whole blur disc, and the
/// mean converges faster than with independent samples; neighbouring pixels stay decorrelated.
pub fn blur_jitter(x: u32, y: u32, sx: u32, sy: u32, sample: u32) -> [f64; 4] {
    const ALPHA: [f64; 4] =
        [0.856_674_883_854_502_9, 0.733_891_856_627_126, 0.628_706_721_037_808_7, 0.538_597_257_223_610_1];
    let a = hash_words(&[x as u64, y as u64, ((sx as u64) << 32) | sy as u64]);
    let b = hash_words(&[a, 0x5EED]);
    let unit = |h: u64| (h >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
    let shift = [unit(a), unit(b), unit(a.rotate_left(29) ^ b), unit(b.rotate_left(17) ^ a.rotate_left(41))];
    std::array::from_fn(|k| {
        let v = (shift[k] + sample as f64 * ALPHA[k]).fract();
        // Below 1 whatever the rounding.
        v.min(1.0 - f64::EPSILON / 2.0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::FocalBlur;

    fn gen(projection: Projection) -> LensRays<'static> {
        let lens = Lens { projection, blur: None };
        LensRays::new(&lens, (DVec3::ZERO, DVec3::ZERO), DVec3::Z, DVec3::new(1.33, 0.0, 0.0), DVec3::Y, 1.0)
    }

    fn dir(g: &LensRays, u: f64, v: f64) -> DVec3 {
        g.ray(u, v).unwrap().1.normalize()
    }

    fn close(a: DVec3, b: DVec3) {
        assert!((a - b).length() < 1e-9, "{a} != {b}");
    }

    #[test]
    fn every_projection_looks_ahead_at_the_centre() {
        for p in [
            Projection::Perspective,
            Projection::Orthographic,
            Projection::Fisheye { angle: 180.0 },
            Projection::UltraWideAngle { angle: 270.0 },
            // (Omnimax looks above the axis at the centre: `omnimax_matches_povrays_rays_..`.)
            Projection::Panoramic,
            Projection::Cylinder { kind: 1, angle: 90.0 },
            Projection::Cylinder { kind: 2, angle: 90.0 },
            Projection::Cylinder { kind: 3, angle: 90.0 },
            Projection::Cylinder { kind: 4, angle: 90.0 },
            Projection::Spherical { h: 360.0, v: 180.0 },
        ] {
            close(dir(&gen(p), 0.5, 0.5), DVec3::Z);
            close(gen(p).ray(0.5, 0.5).unwrap().0, DVec3::ZERO);
        }
    }

    #[test]
    fn orthographic_rays_are_parallel_from_the_image_plane() {
        let g = gen(Projection::Orthographic);
        let (o, d) = g.ray(0.0, 0.0).unwrap();
        close(o, DVec3::new(-0.665, 0.5, 0.0));
        close(d, DVec3::Z);
        let (o, _) = g.ray(1.0, 1.0).unwrap();
        close(o, DVec3::new(0.665, -0.5, 0.0));
    }

    #[test]
    fn fisheye_edges_and_corners() {
        // 180°: the top edge's middle looks straight up, the left edge's circle point 90° left.
        let g = gen(Projection::Fisheye { angle: 180.0 });
        close(dir(&g, 0.5, 0.0), DVec3::Y);
        close(dir(&g, 0.5, 1.0), -DVec3::Y);
        // Width 1.33: x = (2u - 1)·1.33 = -1 at u = 0.5 - 0.5/1.33.
        close(dir(&g, 0.5 - 0.5 / 1.33, 0.5), -DVec3::X);
        assert!(g.ray(0.0, 0.0).is_none(), "corners are outside the circle");
        // 360°: the circle's rim looks backwards.
        close(dir(&gen(Projection::Fisheye { angle: 360.0 }), 0.5, 0.0), -DVec3::Z);
    }

    #[test]
    fn omnimax_matches_povrays_rays_at_several_aspects() {
        // POV-Ray 3.7's rays at pixel centres of 480×480 images (x, y, z coded as 16-bit grey,
        // so to about 3e-5), `None` where it traces no ray, for `right` a·x and `up` y.
        let povray: &[(f64, [(u32, u32, Option<[f64; 3]>); 6])] = &[
            (
                0.8,
                [
                    (100, 100, Some([-0.61724, 0.77155, 0.15405])),
                    (240, 240, Some([0.00295, -0.00368, 0.99999])),
                    (380, 420, None),
                    (60, 300, Some([-0.85392, -0.35978, 0.37602])),
                    (240, 470, None),
                    (20, 240, Some([-0.98238, -0.00279, 0.18689])),
                ],
            ),
            (
                1.2,
                [
                    (100, 100, Some([-0.64154, 0.71857, 0.26850])),
                    (240, 240, Some([0.00291, 0.23029, 0.97313])),
                    (380, 420, None),
                    (60, 300, Some([-0.87962, -0.05104, 0.47292])),
                    (240, 470, None),
                    (20, 240, Some([-0.97200, 0.17529, 0.15640])),
                ],
            ),
            (
                2.0,
                [
                    (100, 100, None),
                    (240, 240, Some([0.00450, 0.30365, 0.95278])),
                    (380, 420, None),
                    (60, 300, None),
                    (240, 470, Some([0.00417, -0.67502, 0.73780])),
                    (20, 240, None),
                ],
            ),
        ];
        for (a, pixels) in povray {
            let lens = Lens { projection: Projection::Omnimax, blur: None };
            let g = LensRays::new(&lens, (DVec3::ZERO, DVec3::ZERO), DVec3::Z, DVec3::X * *a, DVec3::Y, 1.0);
            for &(x, y, want) in pixels {
                let (u, v) = ((x as f64 + 0.5) / 480.0, (y as f64 + 0.5) / 480.0);
                let got = g.ray(u, v).map(|(_, d)| d.normalize());
                match (got, want) {
                    (Some(d), Some(w)) => {
                        let err = (d - DVec3::from(w)).length();
                        assert!(err < 2e-4, "aspect {a}, pixel ({x}, {y}): {d} != {w:?}");
                    }
                    (None, None) => {}
                    _ => panic!("aspect {a}, pixel ({x}, {y}): strahl {got:?}, POV-Ray {want:?}"),
                }
            }
        }
    }

    #[test]
    fn ultra_wide_angle_corners() {
        let g = gen(Projection::UltraWideAngle { angle: 180.0 });
        close(dir(&g, 1.0, 0.5), DVec3::X);
        let y = (90f64 / 1.33).to_radians();
        close(dir(&g, 0.5, 0.0), DVec3::new(0.0, y.sin(), y.cos()));
        // Top-left corner: x = -90°, y = 90°/1.33 (POV-Ray 3.7's directions, measured).
        close(dir(&g, 0.0, 0.0), DVec3::new(-1.0, y.sin(), 0.0).normalize());
    }

    #[test]
    fn panoramic_is_spherical_180_180_with_unit_vectors() {
        let lens = Lens { projection: Projection::Panoramic, blur: None };
        let p = LensRays::new(&lens, (DVec3::ZERO, DVec3::ZERO), DVec3::Z, DVec3::X, DVec3::Y, 1.0);
        let lens = Lens { projection: Projection::Spherical { h: 180.0, v: 180.0 }, blur: None };
        let s = LensRays::new(&lens, (DVec3::ZERO, DVec3::ZERO), DVec3::Z, DVec3::X, DVec3::Y, 1.0);
        for (u, v) in [(0.0, 0.0), (1.0, 0.3), (0.25, 0.9)] {
            close(dir(&p, u, v), dir(&s, u, v));
        }
    }

    #[test]
    fn cylinders() {
        let c1 = gen(Projection::Cylinder { kind: 1, angle: 180.0 });
        close(dir(&c1, 1.0, 0.5), DVec3::X);
        close(c1.ray(0.5, 0.0).unwrap().1, DVec3::new(0.0, 0.5, 1.0));
        let c3 = gen(Projection::Cylinder { kind: 3, angle: 180.0 });
        let (o, d) = c3.ray(0.0, 0.0).unwrap();
        close(o, DVec3::new(0.0, 0.5, 0.0));
        close(d.normalize(), -DVec3::X);
        let c4 = gen(Projection::Cylinder { kind: 4, angle: 90.0 });
        let (o, d) = c4.ray(1.0, 0.5).unwrap();
        close(o, DVec3::new(0.665, 0.0, 0.0));
        close(d, DVec3::Z);
        let c2 = gen(Projection::Cylinder { kind: 2, angle: 120.0 });
        let y = 60f64.to_radians();
        close(dir(&c2, 0.5, 0.0), DVec3::new(0.0, y.sin(), y.cos()));
    }

    #[test]
    fn spherical_corners() {
        let g = gen(Projection::Spherical { h: 360.0, v: 180.0 });
        close(dir(&g, 0.0, 0.5), -DVec3::Z);
        close(dir(&g, 0.75, 0.5), DVec3::X);
        close(dir(&g, 0.3, 0.0), DVec3::Y);
    }

    #[test]
    fn focal_blur_keeps_the_focal_plane_sharp() {
        // The scene's camera at the origin, and far from it (render space is camera-relative,
        // so the focal distance must be measured in the scene). An off-axis focal point puts
        // the plane at its distance (5), not its depth (4).
        for (world, focal_point, plane) in [
            (DVec3::ZERO, DVec3::new(0.0, 0.0, 4.0), 4.0),
            (DVec3::new(1e3, -50.0, 7.0), DVec3::new(1e3, -50.0, 11.0), 4.0),
            (DVec3::ZERO, DVec3::new(3.0, 0.0, 4.0), 5.0),
        ] {
            let lens = Lens {
                projection: Projection::Perspective,
                blur: Some(FocalBlur { aperture: 0.5, max_samples: 8, focal_point, ..Default::default() }),
            };
            let g = LensRays::new(&lens, (DVec3::ZERO, world), DVec3::Z, DVec3::new(1.33, 0.0, 0.0), DVec3::Y, 1.0);
            let ray = g.ray(0.2, 0.7).unwrap();
            let on_plane = ray.1 * (plane / ray.1.z);
            let mut widest = 0.0f64;
            for s in 0..64 {
                let j = blur_jitter(3, 4, 0, 0, s);
                let (o, d) = g.blurred(ray, (j[0], j[1]));
                widest = widest.max(o.length());
                close(o + d * ((plane - o.z) / d.z), on_plane);
            }
            // POV-Ray's lens radius is aperture/4 (measured).
            assert!(widest <= 0.125 + 1e-12 && widest > 0.1, "{widest}");
        }
    }

    #[test]
    fn jitter_is_a_pure_function_in_range() {
        let a = blur_jitter(10, 20, 1, 0, 5);
        assert_eq!(a, blur_jitter(10, 20, 1, 0, 5));
        assert_ne!(a, blur_jitter(10, 20, 1, 0, 6));
        assert!(a.iter().all(|v| (0.0..1.0).contains(v)));
    }

    /// A pixel's first 20 samples are spread over the lens more evenly than independent ones:
    /// the counts in the four quarters of the unit square of (r², angle) stray from 5 by 3 at
    /// most, and their mean squared deviation over 200 pixels is below 2 (independent samples:
    /// 3.75, the binomial variance, with strays of 5 and more).
    #[test]
    fn blur_samples_are_spread_in_every_prefix() {
        let mut squares = 0.0;
        for pixel in 0..200u32 {
            let mut quarters = [0i32; 4];
            for s in 0..20 {
                let j = blur_jitter(pixel, 7, 0, 0, s);
                quarters[(j[0] * 2.0) as usize * 2 + (j[1] * 2.0) as usize] += 1;
            }
            assert!(quarters.iter().all(|&q| (q - 5).abs() <= 3), "pixel {pixel}: {quarters:?}");
            squares += quarters.iter().map(|&q| ((q - 5) * (q - 5)) as f64).sum::<f64>() / 4.0;
        }
        let mean = squares / 200.0;
        assert!(mean < 2.0, "mean squared deviation {mean}");
    }
}
