//! Camera paths: keyframes of location, look_at and (optionally) angle, interpolated with
//! Catmull-Rom splines, optionally reparameterised by arc length for constant speed.
//!
//! The text format is parsed in `path_file` (documented in `docs/camera-paths.md`); this file
//! owns only the curve. A path never touches a scene: `camera_at` turns a point on the path into
//! a `Camera` shaped like the scene's own (same right/up lengths, so the same aspect).

use std::path::Path as FsPath;

use glam::DVec3;

use crate::camera::Camera;
use crate::error::LocatedError;

/// One keyframe as written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Key {
    pub time: f64,
    pub location: DVec3,
    pub look_at: DVec3,
    /// Horizontal field of view in degrees; given on every key or on none.
    pub angle: Option<f64>,
}

/// How knots are spaced along the Catmull-Rom curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Spline {
    /// Knot spacing √distance: no cusps or self-loops between keys (Yuksel et al. 2011), so it
    /// is the default for hand-placed keys that are unevenly far apart.
    #[default]
    Centripetal,
    /// Equal knot spacing: the textbook curve; overshoots where keys are unevenly spaced.
    Uniform,
}

impl Spline {
    pub fn name(self) -> &'static str {
        match self {
            Spline::Centripetal => "centripetal",
            Spline::Uniform => "uniform",
        }
    }

    fn alpha(self) -> f64 {
        match self {
            Spline::Centripetal => 0.5,
            Spline::Uniform => 0.0,
        }
    }
}

/// Samples per key segment in the arc-length table. 256 keeps the spacing error of
/// `constant_speed` under 0.1% on the shipped paths, for a table of a few kB.
const ARC_SAMPLES_PER_SEGMENT: usize = 256;

/// A validated camera path (at least two keys, strictly increasing finite times).
#[derive(Clone, Debug, PartialEq)]
pub struct CameraPath {
    keys: Vec<Key>,
    pub spline: Spline,
    /// Whether the path is a closed loop (last key repeats the first, tangents wrap around).
    pub closed: bool,
    pub constant_speed: bool,
    /// Cumulative arc length of the location curve at `ARC_SAMPLES_PER_SEGMENT` steps per
    /// segment, starting at 0; empty unless `constant_speed`.
    arc_table: Vec<f64>,
}

impl CameraPath {
    /// Builds a path from keys the caller has validated (`path_file` does; tests may too).
    /// Panics on fewer than two keys or non-increasing times: those are programming errors here,
    /// user files get located errors from `parse`.
    pub fn new(keys: Vec<Key>, spline: Spline, closed: bool, constant_speed: bool) -> CameraPath {
        assert!(keys.len() >= 2, "a camera path needs two keys");
        assert!(keys.windows(2).all(|w| w[1].time > w[0].time), "key times must increase");
        let mut path = CameraPath { keys, spline, closed, constant_speed, arc_table: Vec::new() };
        if constant_speed {
            path.arc_table = path.build_arc_table();
        }
        path
    }

    /// Parses the text of a path file; `file` names it in errors.
    pub fn parse(file: &str, text: &str) -> Result<CameraPath, LocatedError> {
        super::path_file::parse(file, text)
    }

    /// Reads and parses a path file.
    pub fn load(path: &FsPath) -> Result<CameraPath, LocatedError> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| LocatedError::whole_file(&name, format!("cannot read: {e}")))?;
        // A byte-order mark or a Latin-1 comment is read as in scene files.
        Self::parse(&name, &crate::text::decode_user_text(bytes))
    }

    pub fn keys(&self) -> &[Key] {
        &self.keys
    }

    /// The camera at normalised path position `t` (clamped to 0..=1), shaped like `base`.
    pub fn camera_at(&self, t: f64, base: &Camera) -> Camera {
        let (location, look_at, angle) = self.sample(t);
        Camera::looking_at(location, look_at, angle, base)
    }

    /// (location, look_at, angle) at normalised position `t` in 0..=1.
    pub fn sample(&self, t: f64) -> (DVec3, DVec3, Option<f64>) {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let (seg, u) = if self.constant_speed { self.param_by_arc(t) } else { self.param_by_time(t) };
        self.eval(seg, u)
    }

    fn segments(&self) -> usize {
        self.keys.len() - 1
    }

    /// Maps normalised time onto (segment, local parameter) using the keys' times.
    fn param_by_time(&self, t: f64) -> (usize, f64) {
        let first = self.keys[0].time;
        let last = self.keys[self.keys.len() - 1].time;
        let time = first + t * (last - first);
        // The last segment whose start is at or before `time`.
        let seg = self.keys[1..].iter().take_while(|k| k.time <= time).count().min(self.segments() - 1);
        let (a, b) = (self.keys[seg].time, self.keys[seg + 1].time);
        (seg, ((time - a) / (b - a)).clamp(0.0, 1.0))
    }

    /// Maps normalised arc length onto (segment, local parameter) through the sampled table.
    fn param_by_arc(&self, t: f64) -> (usize, f64) {
        let total = self.arc_table[self.arc_table.len() - 1];
        if total <= 1e-12 {
            // The camera does not move; only the view turns. Time is the only sensible clock.
            return self.param_by_time(t);
        }
        let target = t * total;
        // First table entry at or past the target; the sample before it brackets it.
        let i = self.arc_table.partition_point(|&s| s < target).clamp(1, self.arc_table.len() - 1);
        let (s0, s1) = (self.arc_table[i - 1], self.arc_table[i]);
        let frac = if s1 > s0 { (target - s0) / (s1 - s0) } else { 0.0 };
        let global = ((i - 1) as f64 + frac) / ARC_SAMPLES_PER_SEGMENT as f64;
        let seg = (global.floor() as usize).min(self.segments() - 1);
        (seg, (global - seg as f64).clamp(0.0, 1.0))
    }

    fn build_arc_table(&self) -> Vec<f64> {
        let n = self.segments() * ARC_SAMPLES_PER_SEGMENT;
        let mut table = Vec::with_capacity(n + 1);
        table.push(0.0);
        let mut prev = self.keys[0].location;
        let mut total = 0.0;
        for i in 1..=n {
            let g = i as f64 / ARC_SAMPLES_PER_SEGMENT as f64;
            let seg = ((g.floor()) as usize).min(self.segments() - 1);
            let p = self.location_at(seg, g - seg as f64);
            total += (p - prev).length();
            table.push(total);
            prev = p;
        }
        table
    }

    /// The four control points of segment `seg` for `field`, with phantom ends: mirrored for an
    /// open path, wrapped around for a closed one (whose last key equals its first).
    fn controls(&self, seg: usize, field: impl Fn(&Key) -> DVec3) -> [DVec3; 4] {
        let n = self.keys.len();
        let p1 = field(&self.keys[seg]);
        let p2 = field(&self.keys[seg + 1]);
        let p0 = if seg > 0 {
            field(&self.keys[seg - 1])
        } else if self.closed {
            field(&self.keys[n - 2])
        } else {
            2.0 * p1 - p2
        };
        let p3 = if seg + 2 < n {
            field(&self.keys[seg + 2])
        } else if self.closed {
            field(&self.keys[1])
        } else {
            2.0 * p2 - p1
        };
        [p0, p1, p2, p3]
    }

    fn location_at(&self, seg: usize, u: f64) -> DVec3 {
        catmull_rom(self.controls(seg, |k| k.location), u, self.spline.alpha())
    }

    fn eval(&self, seg: usize, u: f64) -> (DVec3, DVec3, Option<f64>) {
        let location = self.location_at(seg, u);
        let look_at = catmull_rom(self.controls(seg, |k| k.look_at), u, self.spline.alpha());
        let (a, b) = (&self.keys[seg], &self.keys[seg + 1]);
        let angle = match (a.angle, b.angle) {
            (Some(x), Some(y)) => Some(x + (y - x) * u),
            _ => None,
        };
        (location, look_at, angle)
    }
}

/// One Catmull-Rom segment from `p[1]` (u = 0) to `p[2]` (u = 1), knots spaced by
/// distance^alpha (0 uniform, 0.5 centripetal), in cubic Hermite form.
fn catmull_rom(p: [DVec3; 4], u: f64, alpha: f64) -> DVec3 {
    let knot = |a: DVec3, b: DVec3| (a - b).length().powf(alpha);
    let d1 = knot(p[2], p[1]);
    if d1 < 1e-12 {
        // Coincident keys (a look_at that stays put): stay put rather than bulge.
        return p[1].lerp(p[2], u);
    }
    // A coincident phantom neighbour would divide by zero; borrow the middle spacing instead.
    let nonzero = |d: f64| if d < 1e-12 { d1 } else { d };
    let d0 = nonzero(knot(p[1], p[0]));
    let d2 = nonzero(knot(p[3], p[2]));
    let m1 = ((p[1] - p[0]) / d0 - (p[2] - p[0]) / (d0 + d1) + (p[2] - p[1]) / d1) * d1;
    let m2 = ((p[2] - p[1]) / d1 - (p[3] - p[1]) / (d1 + d2) + (p[3] - p[2]) / d2) * d1;
    let (u2, u3) = (u * u, u * u * u);
    p[1] * (2.0 * u3 - 3.0 * u2 + 1.0) + m1 * (u3 - 2.0 * u2 + u) + p[2] * (-2.0 * u3 + 3.0 * u2) + m2 * (u3 - u2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::CameraDesc;

    fn key(time: f64, location: DVec3, look_at: DVec3, angle: Option<f64>) -> Key {
        Key { time, location, look_at, angle }
    }

    fn zigzag(spline: Spline, constant_speed: bool) -> CameraPath {
        let keys = vec![
            key(0.0, DVec3::new(0.0, 1.0, 0.0), DVec3::ZERO, Some(60.0)),
            key(1.0, DVec3::new(1.0, 1.0, 0.0), DVec3::X, Some(40.0)),
            key(1.5, DVec3::new(5.0, 2.0, 3.0), DVec3::Z, Some(50.0)),
            key(4.0, DVec3::new(5.5, 1.0, 10.0), DVec3::Z, Some(90.0)),
        ];
        CameraPath::new(keys, spline, false, constant_speed)
    }

    #[test]
    fn passes_through_every_key_at_its_time() {
        for spline in [Spline::Centripetal, Spline::Uniform] {
            let path = zigzag(spline, false);
            for k in path.keys() {
                let (l, a, ang) = path.sample(k.time / 4.0);
                assert!((l - k.location).length() < 1e-9, "{spline:?} location at {}", k.time);
                assert!((a - k.look_at).length() < 1e-9, "{spline:?} look_at at {}", k.time);
                assert!((ang.unwrap_or(0.0) - k.angle.unwrap_or(0.0)).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn angle_is_linear_between_keys() {
        let path = zigzag(Spline::Centripetal, false);
        // Halfway between t=0 and t=1 (of 4): 0.125 normalised.
        assert!((path.sample(0.125).2.unwrap_or(0.0) - 50.0).abs() < 1e-9);
    }

    #[test]
    fn uniform_segment_midpoint_matches_textbook_weights() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::new(2.0, 1.0, 0.0), DVec3::new(3.0, 1.0, 0.0)];
        // Uniform Catmull-Rom at u = 0.5: (-p0 + 9 p1 + 9 p2 - p3) / 16.
        let expect = (-p[0] + 9.0 * p[1] + 9.0 * p[2] - p[3]) / 16.0;
        assert!((catmull_rom(p, 0.5, 0.0) - expect).length() < 1e-12);
    }

    #[test]
    fn coincident_keys_hold_still() {
        let p = [DVec3::ZERO, DVec3::ONE, DVec3::ONE, DVec3::splat(2.0)];
        assert_eq!(catmull_rom(p, 0.3, 0.5), DVec3::ONE);
    }

    fn step_ratio(path: &CameraPath, n: usize) -> f64 {
        let pts: Vec<DVec3> = (0..=n).map(|i| path.sample(i as f64 / n as f64).0).collect();
        let steps: Vec<f64> = pts.windows(2).map(|w| (w[1] - w[0]).length()).collect();
        let max = steps.iter().cloned().fold(0.0, f64::max);
        let min = steps.iter().cloned().fold(f64::INFINITY, f64::min);
        max / min
    }

    #[test]
    fn constant_speed_spaces_samples_evenly() {
        let even = zigzag(Spline::Centripetal, true);
        assert!(step_ratio(&even, 100) < 1.05, "ratio {}", step_ratio(&even, 100));
        // The check can fail: by time, the same keys move at very different speeds.
        assert!(step_ratio(&zigzag(Spline::Centripetal, false), 100) > 2.0);
        // Constant speed still starts and ends on the end keys.
        assert!((even.sample(0.0).0 - even.keys()[0].location).length() < 1e-9);
        assert!((even.sample(1.0).0 - even.keys()[3].location).length() < 1e-6);
    }

    #[test]
    fn closed_path_is_smooth_through_the_seam() {
        let ring = |i: usize| {
            let a = i as f64 * std::f64::consts::TAU / 4.0;
            DVec3::new(a.cos(), 0.0, a.sin()) * 5.0
        };
        let keys = (0..=4).map(|i| key(i as f64, ring(i % 4), DVec3::ZERO, None)).collect();
        let path = CameraPath::new(keys, Spline::Centripetal, true, false);
        let h = 1e-4;
        let v_end = (path.sample(1.0).0 - path.sample(1.0 - h).0) / h;
        let v_start = (path.sample(h).0 - path.sample(0.0).0) / h;
        assert!((v_end - v_start).length() < 1e-2 * v_start.length(), "{v_end} vs {v_start}");
        assert!((path.sample(1.0).0 - path.sample(0.0).0).length() < 1e-9);
    }

    #[test]
    fn camera_at_keeps_the_base_shape() {
        let base = Camera::from_desc(&CameraDesc::default());
        let path = CameraPath::new(
            vec![
                key(0.0, DVec3::new(0.0, 0.0, -5.0), DVec3::ZERO, None),
                key(1.0, DVec3::new(5.0, 0.0, 0.0), DVec3::ZERO, None),
            ],
            Spline::Centripetal,
            false,
            false,
        );
        let c = path.camera_at(0.0, &base);
        assert_eq!(c.location, DVec3::new(0.0, 0.0, -5.0));
        assert!((c.right.length() - base.right.length()).abs() < 1e-12);
        assert!((c.up.length() - base.up.length()).abs() < 1e-12);
        assert!((c.direction.normalize() - DVec3::Z).length() < 1e-12);
    }
}
