//! Orbit paths: a closed circle of keyframes around a scene's `look_at`, so every scene has a
//! camera path for `strahl bench --path` and `strahl view --path --report` (`strahl path orbit`).
//!
//! Pure geometry: the caller gives the scene camera and the world-space boxes of the scene's
//! bounded objects; this file picks the circle ([`Orbit::for_camera`]) and writes it in the path
//! format of `docs/camera-paths.md` ([`Orbit::path_text`]). Reading scenes is `headless::orbit`'s.

use std::f64::consts::TAU;
use std::fmt::Write as _;

use glam::DVec3;

use crate::camera::path::Key;
use crate::desc::CameraDesc;

/// A world-space axis-aligned box (min, max).
pub type Bounds = (DVec3, DVec3);

/// A horizontal circle (about world +y, the sky `Camera::looking_at` uses) the camera flies
/// around, always looking at `centre`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// What the camera looks at: the scene's `look_at`.
    pub centre: DVec3,
    /// Horizontal distance from `centre`.
    pub radius: f64,
    /// The camera's world y on the whole circle.
    pub height: f64,
    /// Radians about +y of the first key, from +z towards +x (the scene camera's bearing).
    pub start: f64,
    /// The first key's location exactly (the scene camera's, where the orbit starts from it),
    /// so a played path starts at the picture `strahl render` makes.
    pub first: DVec3,
}

impl Orbit {
    /// The orbit of a scene camera: around its `look_at`, at its height and horizontal distance,
    /// starting where it stands. Where that circle has no size (the camera straight above or
    /// below `look_at`) the radius comes from `subject`, the bounds of what the scene shows
    /// (`Scene::subject_bounds`). Without a `look_at` the centre is the point on the view ray
    /// nearest the subject's centre (without a subject: nearest the origin, when it lies ahead;
    /// else one direction length ahead).
    pub fn for_camera(camera: &CameraDesc, subject: Option<Bounds>) -> Orbit {
        let eye = camera.location;
        let forward = camera.direction.try_normalize().unwrap_or(DVec3::Z);
        let diagonal = subject.map(|(lo, hi)| (hi - lo).length()).filter(|d| d.is_finite() && *d > 0.0);
        let centre = match (camera.look_at, subject) {
            (Some(p), _) if p.is_finite() && p != eye => p,
            (_, Some((lo, hi))) => {
                let ahead = (0.5 * (lo + hi) - eye).dot(forward);
                eye + forward * if ahead > 0.0 { ahead } else { diagonal.unwrap_or(1.0) }
            }
            // Nothing bounded to go by: scenes are mostly built around the origin, so its
            // nearest point on the view ray when it lies ahead, else one direction length on.
            _ if (-eye).dot(forward) > 0.0 => eye + forward * (-eye).dot(forward),
            _ if camera.direction.length_squared() > 0.0 => eye + camera.direction,
            _ => eye + DVec3::Z,
        };
        let offset = eye - centre;
        let horizontal = (offset.x * offset.x + offset.z * offset.z).sqrt();
        if horizontal > 1e-6 * offset.length() {
            return Orbit { centre, radius: horizontal, height: eye.y, start: offset.x.atan2(offset.z), first: eye };
        }
        // Straight above or below: circle at the distance the camera keeps, or the subject's size.
        let radius = diagonal.map_or(offset.length(), |d| d.max(offset.length()));
        let radius = if radius > 0.0 { radius } else { 1.0 };
        let start = forward.x.atan2(forward.z) + std::f64::consts::PI;
        let first = DVec3::new(centre.x + radius * start.sin(), eye.y, centre.z + radius * start.cos());
        Orbit { centre, radius, height: eye.y, start, first }
    }

    /// The location at `turn` (0..1 of a full circle from the start).
    pub fn location(&self, turn: f64) -> DVec3 {
        let a = self.start + turn * TAU;
        DVec3::new(self.centre.x + self.radius * a.sin(), self.height, self.centre.z + self.radius * a.cos())
    }

    /// `count` keys evenly around the circle plus one more repeating the first (a closed path
    /// needs it), at times 0..`seconds`.
    pub fn keys(&self, count: u32, seconds: f64) -> Vec<Key> {
        let count = count.max(3);
        (0..=count)
            .map(|i| {
                let location = if i == 0 || i == count { self.first } else { self.location(i as f64 / count as f64) };
                Key { time: seconds * i as f64 / count as f64, location, look_at: self.centre, angle: None }
            })
            .collect()
    }

    /// The path file (docs/camera-paths.md): centripetal, constant speed, closed, `count` keys
    /// around plus the closing one, no `angle` (the scene camera's field of view is kept).
    /// Numbers are written in Rust's shortest round-trip form, so reading gives the same f64s.
    pub fn path_text(&self, scene: &str, count: u32, seconds: f64) -> String {
        let v = |p: DVec3| format!("<{}, {}, {}>", p.x, p.y, p.z);
        let mut s = String::new();
        let _ = writeln!(s, "# An orbit of {scene} (strahl path orbit): around look_at {},", v(self.centre));
        let _ = writeln!(
            s,
            "# radius {}, height {}, starting at the scene camera; {seconds} s per turn.",
            self.radius, self.height
        );
        s.push_str("spline centripetal\nconstant_speed true\nclosed true\n\n");
        for k in self.keys(count, seconds) {
            let _ = writeln!(s, "key {}  location {}  look_at {}", k.time, v(k.location), v(k.look_at));
        }
        s
    }
}

/// The bounds of what a scene shows, from its bounded objects' world boxes: the boxes that hold
/// the camera are left out (a sky dome or a room's walls around the viewer, which would make a
/// 10 000-unit sphere the scene's size), and so are non-finite ones. `None` without any left.
pub fn subject_of(boxes: impl IntoIterator<Item = Bounds>, eye: DVec3) -> Option<Bounds> {
    let mut out: Option<Bounds> = None;
    for (lo, hi) in boxes {
        let finite = lo.is_finite() && hi.is_finite() && lo.cmple(hi).all();
        let holds_eye = eye.cmpge(lo).all() && eye.cmple(hi).all();
        if finite && !holds_eye {
            out = Some(out.map_or((lo, hi), |(a, b)| (a.min(lo), b.max(hi))));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::path::CameraPath;

    fn camera(location: DVec3, look_at: Option<DVec3>) -> CameraDesc {
        let direction = look_at.map_or(DVec3::Z, |p| (p - location).normalize());
        CameraDesc { location, look_at, direction, ..CameraDesc::default() }
    }

    #[test]
    fn circles_look_at_at_the_cameras_distance_and_height() {
        let c = camera(DVec3::new(0.0, 3.0, -4.5), Some(DVec3::new(0.0, 1.0, 2.5)));
        let o = Orbit::for_camera(&c, None);
        assert_eq!(o.centre, DVec3::new(0.0, 1.0, 2.5));
        assert!((o.radius - 7.0).abs() < 1e-12 && o.height == 3.0);
        let keys = o.keys(8, 10.0);
        assert_eq!(keys.len(), 9);
        assert_eq!(keys[0].location, c.location);
        assert_eq!(keys[8].location, c.location, "closed: ends where it starts");
        assert_eq!((keys[0].time, keys[8].time), (0.0, 10.0));
        for k in &keys {
            let h = k.location - o.centre;
            assert!(((h.x * h.x + h.z * h.z).sqrt() - 7.0).abs() < 1e-9 && k.location.y == 3.0);
            assert_eq!(k.look_at, o.centre);
        }
        // A quarter turn from the seed's bearing (from +z towards +x): <7, 3, 2.5>... mirrored.
        assert!((keys[2].location - DVec3::new(-7.0, 3.0, 2.5)).length() < 1e-9, "{}", keys[2].location);
    }

    #[test]
    fn straight_down_uses_the_subjects_size() {
        let c = camera(DVec3::new(1.0, 10.0, 2.0), Some(DVec3::new(1.0, 0.0, 2.0)));
        let subject = (DVec3::splat(-20.0), DVec3::splat(20.0));
        let o = Orbit::for_camera(&c, Some(subject));
        assert!((o.radius - (40.0f64 * 3.0f64.sqrt())).abs() < 1e-9, "{}", o.radius);
        assert!(o.radius.is_finite() && o.height == 10.0);
        let keys = o.keys(6, 5.0);
        assert_eq!(keys[0].location, keys[6].location);
        assert!(keys.iter().all(|k| k.location != k.look_at));
        let no_subject = Orbit::for_camera(&c, None);
        assert!((no_subject.radius - 10.0).abs() < 1e-12);
    }

    #[test]
    fn without_look_at_the_centre_is_on_the_view_ray_nearest_the_subject() {
        let c = camera(DVec3::new(0.0, 2.0, -10.0), None);
        let o = Orbit::for_camera(&c, Some((DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 1.0, 1.0))));
        assert!((o.centre - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-12, "{}", o.centre);
        assert!((o.radius - 10.0).abs() < 1e-12);
        let bare = Orbit::for_camera(&c, None);
        assert!((bare.centre - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-12, "{}", bare.centre);
        let away = Orbit::for_camera(&camera(DVec3::new(0.0, 2.0, 10.0), None), None);
        assert!((away.centre - DVec3::new(0.0, 2.0, 11.0)).length() < 1e-12, "{}", away.centre);
    }

    #[test]
    fn the_text_parses_back_to_the_same_keys() {
        for scale in [1e-6, 1.0, 3.7e5] {
            let c = camera(DVec3::new(3.1, 2.9, -7.3) * scale, Some(DVec3::new(0.1, 1.3, 0.7) * scale));
            let o = Orbit::for_camera(&c, None);
            let text = o.path_text("x.pov", 12, 7.5);
            let path = CameraPath::parse("orbit.path", &text).unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(path.keys(), &o.keys(12, 7.5)[..]);
            assert!(path.closed && path.constant_speed);
            let (start, _, _) = path.sample(0.0);
            let (end, _, _) = path.sample(1.0);
            assert!((start - c.location).length() <= 1e-9 * scale && (end - c.location).length() <= 1e-9 * scale);
        }
    }

    #[test]
    fn the_subject_leaves_out_boxes_around_the_eye_and_bad_boxes() {
        let eye = DVec3::new(0.0, 1.0, -5.0);
        let sky = (DVec3::splat(-1e4), DVec3::splat(1e4));
        let thing = (DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 2.0, 1.0));
        let other = (DVec3::new(3.0, 0.0, 0.0), DVec3::new(4.0, 1.0, 1.0));
        let nan = (DVec3::splat(f64::NAN), DVec3::ONE);
        let s = subject_of([sky, thing, nan, other], eye).unwrap();
        assert_eq!(s, (DVec3::new(-1.0, 0.0, -1.0), DVec3::new(4.0, 2.0, 1.0)));
        assert_eq!(subject_of([sky], eye), None);
        assert_eq!(subject_of([], eye), None);
    }
}
