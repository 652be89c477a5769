//! Keyboard events → held-key state and one-shot commands. The only place key codes are named.

use winit::keyboard::KeyCode;

use crate::fly::InputState;

/// One-shot commands bound to a key press.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// Esc: release the mouse, or quit when it is free.
    Escape,
    ResetCamera,
    Screenshot,
    CycleQuality,
    PrintCamera,
    ToggleHud,
    /// F5: reload the scene from disk.
    Reload,
}

/// Applies a key to the held-key state; returns the command a fresh press asks for.
pub fn apply_key(code: KeyCode, pressed: bool, repeat: bool, input: &mut InputState) -> Option<Command> {
    let held = match code {
        KeyCode::KeyW | KeyCode::ArrowUp => Some(&mut input.forward),
        KeyCode::KeyS | KeyCode::ArrowDown => Some(&mut input.back),
        KeyCode::KeyA | KeyCode::ArrowLeft => Some(&mut input.left),
        KeyCode::KeyD | KeyCode::ArrowRight => Some(&mut input.right),
        KeyCode::KeyE | KeyCode::Space => Some(&mut input.up),
        KeyCode::KeyQ | KeyCode::ControlLeft | KeyCode::ControlRight => Some(&mut input.down),
        KeyCode::ShiftLeft | KeyCode::ShiftRight => Some(&mut input.fast),
        KeyCode::AltLeft | KeyCode::AltRight => Some(&mut input.slow),
        _ => None,
    };
    if let Some(flag) = held {
        *flag = pressed;
        return None;
    }
    if !pressed || repeat {
        return None;
    }
    match code {
        KeyCode::Escape => Some(Command::Escape),
        KeyCode::KeyR => Some(Command::ResetCamera),
        KeyCode::F12 => Some(Command::Screenshot),
        KeyCode::F2 => Some(Command::CycleQuality),
        KeyCode::KeyP => Some(Command::PrintCamera),
        KeyCode::F1 => Some(Command::ToggleHud),
        KeyCode::F5 => Some(Command::Reload),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn held_keys_follow_press_and_release() {
        let mut i = InputState::default();
        assert_eq!(apply_key(KeyCode::KeyW, true, false, &mut i), None);
        assert!(i.forward);
        apply_key(KeyCode::ArrowUp, false, false, &mut i);
        assert!(!i.forward);
        apply_key(KeyCode::ControlLeft, true, false, &mut i);
        assert!(i.down);
    }

    #[test]
    fn commands_fire_once_per_press() {
        let mut i = InputState::default();
        assert_eq!(apply_key(KeyCode::F12, true, false, &mut i), Some(Command::Screenshot));
        assert_eq!(apply_key(KeyCode::F12, true, true, &mut i), None);
        assert_eq!(apply_key(KeyCode::F12, false, false, &mut i), None);
        assert_eq!(i, InputState::default());
    }
}
