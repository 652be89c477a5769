//! The free-flying camera: input state in, camera out. Pure, so it is tested with synthetic input;
//! `app` translates window and gamepad events into an [`InputState`] and nothing more.

use glam::{DVec2, DVec3};

use crate::camera::{Basis, Camera};

/// What the user is asking for right now, independent of any windowing library.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InputState {
    pub forward: bool,
    pub back: bool,
    pub left: bool,
    pub right: bool,
    pub up: bool,
    pub down: bool,
    /// Shift: faster.
    pub fast: bool,
    /// Alt: slower.
    pub slow: bool,
    /// Mouse motion since the last step, in pixels (x right, y down), only while the mouse is
    /// grabbed. Consumed by `step`'s caller.
    pub mouse: DVec2,
    /// Speed changes since the last step (mouse wheel notches, bumpers). Consumed likewise.
    pub speed_steps: i32,
    /// Analog movement after dead zone: x right, y forward, each in [-1, 1].
    pub stick_move: DVec2,
    /// Analog look rate after dead zone and response curve: x right, y up, each in [-1, 1].
    pub stick_look: DVec2,
    /// Analog vertical movement (right trigger minus left trigger), in [-1, 1].
    pub stick_lift: f64,
}

impl InputState {
    /// Whether anything asks the camera to move or turn.
    pub fn is_active(&self) -> bool {
        self.forward
            || self.back
            || self.left
            || self.right
            || self.up
            || self.down
            || self.mouse != DVec2::ZERO
            || self.speed_steps != 0
            || self.stick_move != DVec2::ZERO
            || self.stick_look != DVec2::ZERO
            || self.stick_lift != 0.0
    }

    /// Forgets held keys and pending motion (focus lost: key releases will not arrive).
    pub fn release_all(&mut self) {
        *self = InputState::default();
    }
}

/// Radians per pixel of mouse motion.
pub const MOUSE_SENSITIVITY: f64 = 0.0025;
/// Radians per second at full stick deflection.
pub const STICK_TURN_RATE: f64 = 2.5;
/// Speed factor per wheel notch or bumper press.
pub const SPEED_STEP: f64 = 1.25;
pub const FAST_FACTOR: f64 = 4.0;
pub const SLOW_FACTOR: f64 = 0.25;
/// Seconds the default speed takes to cross the diagonal of the scene's bounded objects.
pub const CROSSING_SECONDS: f64 = 4.0;
/// How far wheel and bumper steps may take the speed from the scene's default, either way: a
/// bound relative to the scene, so a tiny or a huge scene steps exactly like the seed.
pub const SPEED_RANGE: f64 = 1e4;
const MAX_PITCH: f64 = 89.0 * std::f64::consts::PI / 180.0;

/// Position, heading and speed of the fly camera. Starts as the scene's camera exactly: until the
/// user turns, `camera()` keeps the scene camera's own vectors, so a still view converges to
/// `strahl render` of that camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlyState {
    pub position: DVec3,
    /// Radians about +y; 0 looks along +z, positive turns towards +x.
    pub yaw: f64,
    /// Radians above the horizon.
    pub pitch: f64,
    /// World units per second.
    pub speed: f64,
    /// The speed `new` was given (the scene's default): the centre of [`SPEED_RANGE`].
    base_speed: f64,
    /// The scene camera: its vector lengths (field of view, aspect) and handedness are kept.
    pub origin: Camera,
    origin_yaw: f64,
    origin_pitch: f64,
}

impl FlyState {
    pub fn new(origin: Camera, speed: f64) -> FlyState {
        let d = origin.direction.try_normalize().unwrap_or(DVec3::Z);
        let yaw = d.x.atan2(d.z);
        let pitch = d.y.clamp(-1.0, 1.0).asin();
        FlyState {
            position: origin.location,
            yaw,
            pitch,
            speed,
            base_speed: speed,
            origin,
            origin_yaw: yaw,
            origin_pitch: pitch,
        }
    }

    /// Starts again from `camera` (a played path's), keeping the speed and its range.
    pub fn moved_to(&self, camera: Camera) -> FlyState {
        FlyState { speed: self.speed, ..FlyState::new(camera, self.base_speed) }
    }

    /// Unit viewing direction.
    pub fn forward(&self) -> DVec3 {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        DVec3::new(cp * sy, sp, cp * cy)
    }

    /// The POV-Ray camera for this state.
    pub fn camera(&self) -> Camera {
        if self.yaw == self.origin_yaw && self.pitch == self.origin_pitch {
            return Camera { location: self.position, ..self.origin };
        }
        let o = &self.origin;
        let basis = Basis::from_forward(self.forward(), DVec3::Y);
        // A scene that flips `right` (right-handed coordinates) keeps that flip.
        let sign = if o.right.dot(DVec3::Y.cross(o.direction)) < 0.0 { -1.0 } else { 1.0 };
        Camera {
            location: self.position,
            direction: basis.forward * o.direction.length(),
            right: basis.right * (sign * o.right.length()),
            up: basis.up * o.up.length(),
            // The projection and focal blur fly along: the window moves the camera, nothing else.
            lens: o.lens,
        }
    }
}

/// Advances the camera by `dt` seconds of `input`. Pure: the same inputs give the same state.
///
/// W/S move along the view direction, A/D strafe horizontally, up/down move along world +y.
pub fn step(state: &FlyState, input: &InputState, dt: f64) -> FlyState {
    let mut s = *state;
    let dt = if dt.is_finite() { dt.clamp(0.0, 0.25) } else { 0.0 };
    let steps = SPEED_STEP.powi(input.speed_steps.clamp(-100, 100));
    s.speed = (s.speed * steps).clamp(s.base_speed / SPEED_RANGE, s.base_speed * SPEED_RANGE);

    s.yaw += input.mouse.x * MOUSE_SENSITIVITY + input.stick_look.x * STICK_TURN_RATE * dt;
    s.pitch -= input.mouse.y * MOUSE_SENSITIVITY;
    s.pitch += input.stick_look.y * STICK_TURN_RATE * dt;
    s.pitch = s.pitch.clamp(-MAX_PITCH, MAX_PITCH);
    if input.mouse != DVec2::ZERO || input.stick_look != DVec2::ZERO {
        s.yaw = wrap_angle(s.yaw);
    }

    let axis = |pos: bool, neg: bool| (pos as i32 - neg as i32) as f64;
    let forward = (axis(input.forward, input.back) + input.stick_move.y).clamp(-1.0, 1.0);
    let strafe = (axis(input.right, input.left) + input.stick_move.x).clamp(-1.0, 1.0);
    let lift = (axis(input.up, input.down) + input.stick_lift).clamp(-1.0, 1.0);
    if forward != 0.0 || strafe != 0.0 || lift != 0.0 {
        let mut speed = s.speed;
        if input.fast {
            speed *= FAST_FACTOR;
        }
        if input.slow {
            speed *= SLOW_FACTOR;
        }
        let (sy, cy) = s.yaw.sin_cos();
        let right = DVec3::new(cy, 0.0, -sy);
        let v = s.forward() * forward + right * strafe + DVec3::Y * lift;
        s.position += v * (speed * dt);
    }
    s
}

/// The default flying speed: crosses the diagonal of the scene's bounded objects (`world_bounds`,
/// `Scene::world_bounds`) in [`CROSSING_SECONDS`]. Both are in world units because the camera
/// flies in world units (render space is in the camera's unit of length, so its bounds would
/// give every scale the same speed). A scene of planes alone crosses `unit`, the camera's
/// distance to `look_at`, instead.
pub fn initial_speed(world_bounds: Option<(DVec3, DVec3)>, unit: f64) -> f64 {
    let extent = world_bounds.map_or(0.0, |(lo, hi)| (hi - lo).length());
    let length = if extent.is_finite() && extent > 0.0 { extent } else { unit };
    length / CROSSING_SECONDS
}

/// How far the framing bounds the default speed's crossing length, either way: a subject may be
/// far bigger than what the camera frames (a 10⁴-unit ground box under a 5-unit model) or far
/// smaller (a mote in a wide view), and the camera's distance to `look_at` is what the scene's
/// author chose to look from.
pub const FRAMING_RANGE: f64 = 4.0;

/// The window's default speed: [`initial_speed`] of the scene's subject (its bounded objects
/// less those around the camera, `Scene::subject_bounds`), its crossing length kept
/// within [`FRAMING_RANGE`] of `look_distance`, the camera's distance to its `look_at` (when
/// the scene gives one: without it the direction's length says nothing about the scene's size).
pub fn scene_speed(subject: Option<(DVec3, DVec3)>, unit: f64, look_distance: Option<f64>) -> f64 {
    let speed = initial_speed(subject, unit);
    match look_distance {
        Some(d) if d.is_finite() && d > 0.0 => {
            speed.clamp(d / FRAMING_RANGE / CROSSING_SECONDS, d * FRAMING_RANGE / CROSSING_SECONDS)
        }
        _ => speed,
    }
}

fn wrap_angle(a: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    if (-PI..=PI).contains(&a) {
        a
    } else {
        (a + PI).rem_euclid(TAU) - PI
    }
}

/// A stick's raw position → its effect: a radial dead zone, then `magnitude^exponent` so that
/// small deflections give fine control and full deflection gives full rate.
pub fn stick_response(raw: DVec2, dead_zone: f64, exponent: f64) -> DVec2 {
    let m = raw.length();
    if !m.is_finite() || m <= dead_zone {
        return DVec2::ZERO;
    }
    let t = ((m - dead_zone) / (1.0 - dead_zone)).min(1.0);
    raw / m * t.powf(exponent)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::desc::CameraDesc;

    fn seed_camera() -> Camera {
        let base = Camera::from_desc(&CameraDesc::default());
        Camera::looking_at(DVec3::new(3.0, 3.0, -1.0), DVec3::new(0.0, 1.0, 2.0), None, &base)
    }

    #[test]
    fn starts_as_the_scene_camera_exactly() {
        let cam = seed_camera();
        let s = FlyState::new(cam, 1.0);
        assert_eq!(s.camera(), cam);
        assert_eq!(step(&s, &InputState::default(), 0.016).camera(), cam);
        assert!((s.forward() - cam.direction.normalize()).length() < 1e-12);
    }

    #[test]
    fn turning_keeps_lengths_and_rebuilding_matches_look_at() {
        let cam = seed_camera();
        let s = FlyState::new(cam, 1.0);
        let turned = step(&s, &InputState { mouse: DVec2::new(40.0, -10.0), ..Default::default() }, 0.016);
        let c = turned.camera();
        assert!((c.direction.length() - cam.direction.length()).abs() < 1e-12);
        assert!((c.right.length() - cam.right.length()).abs() < 1e-12);
        assert!((c.up.length() - cam.up.length()).abs() < 1e-12);
        assert!(c.right.dot(c.direction).abs() < 1e-9 && c.up.dot(c.direction).abs() < 1e-9);
        // Turning back and rebuilding equals POV-Ray's look_at of the same direction.
        let mut back = turned;
        back.yaw += 1e-3;
        let rebuilt = back.camera();
        let expect = Camera::looking_at(rebuilt.location, rebuilt.location + back.forward(), None, &cam);
        assert!((rebuilt.right - expect.right).length() < 1e-12);
        assert!((rebuilt.up - expect.up).length() < 1e-12);
    }

    #[test]
    fn keys_move_along_view_and_world_axes() {
        let s = FlyState::new(Camera::from_desc(&CameraDesc::default()), 2.0);
        let fwd = step(&s, &InputState { forward: true, ..Default::default() }, 0.25);
        assert!((fwd.position - DVec3::new(0.0, 0.0, 0.5)).length() < 1e-12);
        let right = step(&s, &InputState { right: true, fast: true, ..Default::default() }, 0.25);
        assert!((right.position - DVec3::new(2.0, 0.0, 0.0)).length() < 1e-12);
        let up = step(&s, &InputState { up: true, slow: true, ..Default::default() }, 0.25);
        assert!((up.position - DVec3::new(0.0, 0.125, 0.0)).length() < 1e-12);
        let both = step(&s, &InputState { forward: true, back: true, ..Default::default() }, 0.25);
        assert_eq!(both.position, s.position);
    }

    #[test]
    fn mouse_right_turns_right_and_up_looks_up() {
        let s = FlyState::new(Camera::from_desc(&CameraDesc::default()), 1.0);
        let t = step(&s, &InputState { mouse: DVec2::new(100.0, -100.0), ..Default::default() }, 0.0);
        let f = t.forward();
        assert!(f.x > 0.0 && f.y > 0.0);
        // POV-Ray's right vector still points to the right of the view.
        assert!(t.camera().right.x > 0.0);
    }

    #[test]
    fn pitch_is_clamped_and_speed_steps_scale() {
        let s = FlyState::new(Camera::from_desc(&CameraDesc::default()), 1.0);
        let t = step(&s, &InputState { mouse: DVec2::new(0.0, -1e6), speed_steps: 2, ..Default::default() }, 0.0);
        assert!(t.pitch <= MAX_PITCH && t.camera().right.is_finite());
        assert!((t.speed - 1.5625).abs() < 1e-12);
    }

    /// The speed's limits were absolute (1e-4..1e6 units/s): a scene scaled by 1e-6 started at
    /// the floor and its first wheel notch did nothing, or jumped.
    #[test]
    fn speed_steps_scale_with_the_scene_not_absolute_limits() {
        for base in [1e-7, 1.0, 1e7] {
            let s = FlyState::new(Camera::from_desc(&CameraDesc::default()), base);
            let up = step(&s, &InputState { speed_steps: 1, ..Default::default() }, 0.0);
            assert!((up.speed / base - SPEED_STEP).abs() < 1e-12, "{base}: {}", up.speed);
            let down = step(&s, &InputState { speed_steps: -3, ..Default::default() }, 0.0);
            assert!((down.speed / base - SPEED_STEP.powi(-3)).abs() < 1e-12, "{base}: {}", down.speed);
            let floor = step(&s, &InputState { speed_steps: -100, ..Default::default() }, 0.0);
            assert!((floor.speed / base - 1.0 / SPEED_RANGE).abs() < 1e-12);
            let ceiling = step(&s, &InputState { speed_steps: 100, ..Default::default() }, 0.0);
            assert!((ceiling.speed / base - SPEED_RANGE).abs() < 1e-9);
            // Following a path keeps the range centred on the scene's speed.
            let moved = ceiling.moved_to(seed_camera());
            assert_eq!(moved.speed, ceiling.speed);
            let back = step(&moved, &InputState { speed_steps: -100, ..Default::default() }, 0.0);
            assert!((back.speed / base - 1.0 / SPEED_RANGE).abs() < 1e-12);
        }
    }

    #[test]
    fn scene_speed_follows_the_subject_within_the_framing() {
        let b = |d: f64| Some((DVec3::ZERO, DVec3::new(d, 0.0, 0.0)));
        // The seed: a few units across, seen from 7: the subject's own size.
        assert!((scene_speed(b(5.0), 7.0, Some(7.0)) - 5.0 / CROSSING_SECONDS).abs() < 1e-12);
        // A 10⁴-unit floor under a model seen from 10 crosses at most 40 units in the crossing time.
        assert!((scene_speed(b(1e4), 10.0, Some(10.0)) - 40.0 / CROSSING_SECONDS).abs() < 1e-9);
        // A tiny subject in a wide view, and a scene of planes alone.
        assert!((scene_speed(b(1e-3), 100.0, Some(100.0)) - 25.0 / CROSSING_SECONDS).abs() < 1e-9);
        assert!((scene_speed(None, 3.0, Some(3.0)) - 3.0 / CROSSING_SECONDS).abs() < 1e-12);
        // Without a look_at the subject alone decides.
        assert!((scene_speed(b(1e4), 1.0, None) - 1e4 / CROSSING_SECONDS).abs() < 1e-9);
        assert!(scene_speed(b(f64::NAN), 1.0, Some(f64::NAN)).is_finite());
    }

    #[test]
    fn huge_or_bad_dt_is_harmless() {
        let s = FlyState::new(seed_camera(), 1.0);
        let input = InputState { forward: true, ..Default::default() };
        assert!(step(&s, &input, f64::NAN).position == s.position);
        assert!((step(&s, &input, 100.0).position - s.position).length() <= 0.25 + 1e-12);
    }

    #[test]
    fn stick_dead_zone_and_curve() {
        assert_eq!(stick_response(DVec2::new(0.1, 0.05), 0.15, 2.0), DVec2::ZERO);
        let full = stick_response(DVec2::new(1.0, 0.0), 0.15, 2.0);
        assert!((full - DVec2::X).length() < 1e-12);
        let half = stick_response(DVec2::new(0.0, 0.575), 0.15, 2.0);
        assert!((half.y - 0.25).abs() < 1e-12, "{half}");
        assert_eq!(stick_response(DVec2::new(f64::NAN, 0.0), 0.15, 2.0), DVec2::ZERO);
    }

    #[test]
    fn release_all_stops_motion() {
        let mut i = InputState { forward: true, mouse: DVec2::ONE, ..Default::default() };
        assert!(i.is_active());
        i.release_all();
        assert!(!i.is_active());
    }
}
