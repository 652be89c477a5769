//! Gamepad input through gilrs, folded into the same `InputState` the keyboard fills.
//! Without a gamepad, or where gilrs cannot start, this is silently absent.

use gilrs::{Axis, Button, EventType, Gilrs};
use glam::DVec2;

use crate::fly::{stick_response, InputState};

/// Sticks rest within about 10% of centre on worn pads; 15% keeps a resting stick still.
const DEAD_ZONE: f64 = 0.15;
/// Quadratic response: fine aim near the centre, full speed at the rim.
const RESPONSE: f64 = 2.0;
/// Triggers below this count as released.
const TRIGGER_DEAD: f64 = 0.05;

/// Discrete requests a gamepad can make besides motion.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PadActions {
    pub toggle_hud: bool,
}

pub struct Gamepads {
    gilrs: Option<Gilrs>,
}

impl Gamepads {
    /// Starts gilrs; `None` inside means no gamepad support here.
    pub fn open() -> Gamepads {
        // No gamepad support is not an error worth showing: the keyboard works regardless.
        Gamepads { gilrs: Gilrs::new().ok() }
    }

    /// Whether a gamepad is connected (the window then polls instead of sleeping).
    pub fn any_connected(&self) -> bool {
        self.gilrs.as_ref().is_some_and(|g| g.gamepads().next().is_some())
    }

    /// Drains pending events into `input` (bumpers → speed steps) and sets the analog state from
    /// the first connected pad.
    pub fn poll(&mut self, input: &mut InputState) -> PadActions {
        let mut actions = PadActions::default();
        let Some(gilrs) = self.gilrs.as_mut() else {
            return actions;
        };
        while let Some(ev) = gilrs.next_event() {
            if let EventType::ButtonPressed(button, _) = ev.event {
                match button {
                    Button::LeftTrigger => input.speed_steps -= 1,
                    Button::RightTrigger => input.speed_steps += 1,
                    Button::Start => actions.toggle_hud = !actions.toggle_hud,
                    _ => {}
                }
            }
        }
        input.stick_move = DVec2::ZERO;
        input.stick_look = DVec2::ZERO;
        input.stick_lift = 0.0;
        if let Some((_, pad)) = gilrs.gamepads().next() {
            let axis = |a: Axis| pad.value(a) as f64;
            // gilrs reports stick y positive up: pushing forward moves forward, pulling back looks down.
            input.stick_move =
                stick_response(DVec2::new(axis(Axis::LeftStickX), axis(Axis::LeftStickY)), DEAD_ZONE, RESPONSE);
            input.stick_look =
                stick_response(DVec2::new(axis(Axis::RightStickX), axis(Axis::RightStickY)), DEAD_ZONE, RESPONSE);
            let trigger = |b: Button| {
                let v = pad.button_data(b).map_or(0.0, |d| d.value() as f64);
                if v > TRIGGER_DEAD {
                    v
                } else {
                    0.0
                }
            };
            input.stick_lift = trigger(Button::RightTrigger2) - trigger(Button::LeftTrigger2);
        }
        actions
    }
}
