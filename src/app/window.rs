//! The winit application: events in, `InputState` and render requests out, frames presented.

use std::num::NonZeroU32;
use std::path::PathBuf;
use std::rc::Rc;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use glam::DVec2;
use softbuffer::{Context, Surface};
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{DeviceEvent, DeviceId, ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::PhysicalKey;
use winit::window::{CursorGrabMode, Window, WindowId};

use crate::app::blit::Blitter;
use crate::app::font::Canvas;
use crate::app::frame_costs::FrameCosts;
use crate::app::gamepad::Gamepads;
use crate::app::hud::{draw_error, draw_hud_and_help, FrameTimes, HudInfo};
use crate::app::keys::{apply_key, Command};
use crate::app::playback::Playback;
use crate::app::render_thread::{Frame, Progress, ReloadStatus, RenderThread, View, Watch};
use crate::app::{no_display, quality_preset, ViewOptions};
use crate::camera::Camera;
use crate::fly::{step, FlyState, InputState};
use crate::headless::{output, CliError};
use crate::scene::build::Scene;

/// Sent by the render thread when a frame is ready.
struct FrameReady;

/// While input is held the camera is stepped this often, even without new events.
const TICK: Duration = Duration::from_millis(5);

/// Runs the window until it is closed, `--frames` is done or the path has played; returns the
/// playback's record, if a path was played.
pub fn run(
    scene: Scene,
    camera: Camera,
    speed: f64,
    unmodelled: Vec<String>,
    watch: Option<Watch>,
    playback: Option<Playback>,
    options: ViewOptions,
) -> Result<Option<Playback>, CliError> {
    let event_loop = EventLoop::<FrameReady>::with_user_event().build().map_err(|e| no_display(&winit_message(&e)))?;
    let proxy = event_loop.create_proxy();
    let render = RenderThread::spawn(scene, watch, options.threads, options.target_fps, move || {
        let _ = proxy.send_event(FrameReady);
    })?;
    let mut app = App {
        fly: FlyState::new(camera, speed),
        speed,
        unmodelled,
        scene_camera: camera,
        render,
        gamepads: Gamepads::open(),
        shown: None,
        blitter: Blitter::default(),
        input: InputState::default(),
        last_tick: Instant::now(),
        was_active: false,
        size: (options.width, options.height),
        surface_size: (0, 0),
        grabbed: false,
        hud: options.hud,
        preset: 0,
        times: FrameTimes::new(120),
        last_present: None,
        presented: 0,
        screenshot: None,
        error: None,
        playback,
        reload: ReloadStatus::default(),
        options,
        win: None,
    };
    event_loop.run_app(&mut app).map_err(|e| CliError::user(format!("window: {e}")))?;
    match app.error.take() {
        Some(e) => Err(e),
        None => Ok(app.playback.take()),
    }
}

struct Win {
    window: Rc<Window>,
    surface: Surface<Rc<Window>, Rc<Window>>,
}

struct App {
    options: ViewOptions,
    scene_camera: Camera,
    speed: f64,
    /// What the scene uses that strahl does not model, named in the HUD.
    unmodelled: Vec<String>,
    fly: FlyState,
    render: RenderThread,
    gamepads: Gamepads,
    /// The frame on screen; goes back to the render thread when a newer one arrives.
    shown: Option<Frame>,
    blitter: Blitter,
    input: InputState,
    last_tick: Instant,
    was_active: bool,
    /// Window size in physical pixels; (0, 0) while minimised.
    size: (u32, u32),
    surface_size: (u32, u32),
    grabbed: bool,
    hud: bool,
    preset: usize,
    times: FrameTimes,
    last_present: Option<Instant>,
    presented: u64,
    /// A screenshot to save with the next presented buffer.
    screenshot: Option<PathBuf>,
    error: Option<CliError>,
    /// `--path`: the camera follows the path instead of the input.
    playback: Option<Playback>,
    /// The latest reload outcome seen; its error is drawn over the picture.
    reload: ReloadStatus,
    win: Option<Win>,
}

impl App {
    fn fail(&mut self, event_loop: &ActiveEventLoop, e: CliError) {
        self.error.get_or_insert(e);
        event_loop.exit();
    }

    fn set_grab(&mut self, grab: bool) {
        let Some(win) = &self.win else { return };
        let w = &win.window;
        if grab {
            // Locked keeps the pointer still (raw motion only); X11 can only confine it.
            let _ = w.set_cursor_grab(CursorGrabMode::Locked).or_else(|_| w.set_cursor_grab(CursorGrabMode::Confined));
            w.set_cursor_visible(false);
            // Raw motion turns the camera even where neither grab mode is available.
            self.grabbed = true;
        } else {
            let _ = w.set_cursor_grab(CursorGrabMode::None);
            w.set_cursor_visible(true);
            self.grabbed = false;
        }
    }

    fn command(&mut self, event_loop: &ActiveEventLoop, c: Command) {
        match c {
            Command::Escape if self.grabbed => self.set_grab(false),
            Command::Escape => event_loop.exit(),
            Command::ResetCamera => self.fly = FlyState::new(self.scene_camera, self.speed),
            Command::Screenshot => {
                let path = self.options.screenshot.clone().unwrap_or_else(|| {
                    let secs = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
                    PathBuf::from(format!("strahl-{secs}.png"))
                });
                self.screenshot = Some(path);
                self.redraw();
            }
            Command::CycleQuality => {
                self.preset = (self.preset + 1) % 4;
                eprintln!("quality: {}", quality_preset(self.options.quality, self.options.aa, self.preset).name);
            }
            Command::PrintCamera => println!("{}", self.fly.camera().to_pov()),
            Command::ToggleHud => {
                self.hud = !self.hud;
                self.redraw();
            }
            Command::Reload => self.render.request_reload(),
        }
    }

    fn redraw(&self) {
        if let Some(win) = &self.win {
            win.window.request_redraw();
        }
    }

    /// Steps the camera and asks the render thread for the resulting view.
    fn tick(&mut self, event_loop: &ActiveEventLoop) {
        let now = Instant::now();
        let dt = if self.was_active { (now - self.last_tick).as_secs_f64() } else { 0.0 };
        self.last_tick = now;
        if self.gamepads.poll(&mut self.input).toggle_hud {
            self.hud = !self.hud;
            self.redraw();
        }
        let mut active = self.input.is_active();
        self.fly = step(&self.fly, &self.input, dt);
        if let Some(playback) = &mut self.playback {
            let (camera, ended) = playback.camera(now, &self.scene_camera);
            self.fly = self.fly.moved_to(camera);
            // Keep ticking along the path; once it ends, one more present saves and exits.
            active = !ended;
            if ended {
                self.redraw();
            }
        }
        self.input.mouse = DVec2::ZERO;
        self.input.speed_steps = 0;
        self.was_active = active;
        if self.size.0 > 0 && self.size.1 > 0 {
            let preset = quality_preset(self.options.quality, self.options.aa, self.preset);
            self.render.submit(View {
                camera: self.fly.camera(),
                width: self.size.0,
                height: self.size.1,
                aa: preset.aa,
                quality: preset.quality,
                max_scale: preset.max_scale,
                reproject: self.options.reproject,
            });
        }
        if !self.render.is_alive() {
            self.fail(event_loop, CliError { message: "the render thread stopped".into(), code: 1 });
        }
        event_loop.set_control_flow(if active || self.gamepads.any_connected() {
            ControlFlow::WaitUntil(now + TICK)
        } else {
            ControlFlow::Wait
        });
    }

    fn present(&mut self, event_loop: &ActiveEventLoop) {
        let (w, h) = self.size;
        let (Some(nw), Some(nh)) = (NonZeroU32::new(w), NonZeroU32::new(h)) else {
            return;
        }; // minimised
        let fresh = match self.render.latest() {
            Some(f) => {
                if let Some(old) = self.shown.replace(f) {
                    self.render.give_back(old);
                }
                true
            }
            None => false,
        };
        let Some(frame) = &self.shown else { return };
        let Some(win) = &mut self.win else { return };
        if self.surface_size != (w, h) {
            if let Err(e) = win.surface.resize(nw, nh) {
                eprintln!("warning: cannot resize the window buffer: {e}");
                return;
            }
            self.surface_size = (w, h);
        }
        let acquire = Instant::now();
        let mut buffer = match win.surface.buffer_mut() {
            Ok(b) => b,
            Err(e) => {
                eprintln!("warning: cannot get the window buffer: {e}");
                return;
            }
        };
        let blit = Instant::now();
        self.blitter.blit(&frame.pixels, frame.width, frame.height, &mut buffer, w, h);
        let now = Instant::now();
        let mut costs = FrameCosts {
            trace: frame.render_time.saturating_sub(frame.encode_time),
            encode: frame.encode_time,
            handoff: frame.sent_at.map_or(Duration::ZERO, |sent| acquire.saturating_duration_since(sent)),
            acquire: blit - acquire,
            blit: now - blit,
            ..FrameCosts::default()
        };
        if fresh {
            // Only gaps between moving frames measure the frame rate: a still view presents
            // rarely, and the gap from its last frame to the first moving one is idle time.
            if frame.progress == Progress::Moving {
                if let Some(prev) = self.last_present.replace(now) {
                    self.times.push(now - prev);
                }
            } else {
                self.last_present = None;
            }
            self.presented += 1;
            if let (Some(playback), Some(view)) = (&mut self.playback, frame.view) {
                let shown = playback.wants_sample().then_some((&buffer[..], w, h));
                playback.presented(now, frame.scale, view.camera, shown);
            }
        }
        let hud = Instant::now();
        if self.hud {
            let (avg, p95) = self.times.summary();
            let secs = frame.render_time.as_secs_f64();
            let info = HudInfo {
                frame_avg: avg,
                frame_p95: p95,
                render_time: frame.render_time,
                scale: frame.scale,
                internal: (frame.width, frame.height),
                rays_per_s: if secs > 0.0 { frame.stats.total_rays() as f64 / secs } else { 0.0 },
                position: self.fly.position,
                speed: self.fly.speed,
                quality: quality_preset(self.options.quality, self.options.aa, self.preset).name,
                precision: quality_preset(self.options.quality, self.options.aa, self.preset).quality.precision,
                progress: frame.progress,
                unmodelled: &self.unmodelled,
            };
            let mut canvas = Canvas { pixels: &mut buffer, width: w, height: h };
            draw_hud_and_help(&mut canvas, &info);
        }
        costs.hud = hud.elapsed();
        let status = self.render.reload_status();
        if status.generation != self.reload.generation {
            if let Some(camera) = status.camera {
                // R now resets to the edited scene's camera; the view stays where it was flown.
                self.scene_camera = camera;
            }
            if let Some(names) = &status.unmodelled {
                self.unmodelled.clone_from(names);
            }
            if status.error.is_none() && self.reload.error.is_some() {
                eprintln!("reloaded: the scene loads again");
            }
            if let Some(e) = &status.error {
                eprintln!("reload failed (showing the last good scene):\n{e}");
            }
            self.reload = status;
        }
        if let Some(message) = &self.reload.error {
            let mut canvas = Canvas { pixels: &mut buffer, width: w, height: h };
            draw_error(&mut canvas, message);
        }
        // A still view stops producing frames once converged, so that ends the run as well.
        let converged = frame.progress.is_converged();
        let done = self.options.frames.is_some_and(|n| fresh && (self.presented >= n || converged))
            || self.playback.as_ref().is_some_and(Playback::finished);
        if done && self.screenshot.is_none() {
            self.screenshot = self.options.screenshot.clone();
        }
        let shot = self.screenshot.take().map(|path| (path, save_screenshot(&buffer, w, h)));
        let present = Instant::now();
        if let Err(e) = buffer.present() {
            eprintln!("warning: cannot present: {e}");
        }
        costs.present = present.elapsed();
        if let (true, Some(playback)) = (fresh, &mut self.playback) {
            playback.costs(costs, frame.reprojected.is_some());
        }
        if let Some((path, rgb)) = shot {
            match output::write_png(&path, w, h, &rgb) {
                Ok(()) => eprintln!("saved {}", path.display()),
                Err(e) if done => return self.fail(event_loop, e),
                Err(e) => eprintln!("warning: {e}"),
            }
        }
        if done {
            event_loop.exit();
        }
    }
}

/// A winit error without the `os error at SOURCE.rs:LINE: ` that its OS errors start with:
/// winit's own source path means nothing to the user, and the error carries nothing else.
fn winit_message(e: &dyn std::fmt::Display) -> String {
    let text = e.to_string();
    let Some(rest) = text.strip_prefix("os error at ") else {
        return text;
    };
    // `rest` is `FILE:LINE: message`; the first `:DIGITS: ` ends the location.
    let bytes = rest.as_bytes();
    for (i, _) in rest.match_indices(':') {
        let digits = bytes[i + 1..].iter().take_while(|b| b.is_ascii_digit()).count();
        if digits > 0 && rest[i + 1 + digits..].starts_with(": ") {
            return rest[i + 3 + digits..].to_string();
        }
    }
    text
}

/// The presented 0RGB words as RGB bytes, exactly what the window shows.
fn save_screenshot(buffer: &[u32], w: u32, h: u32) -> Vec<u8> {
    let mut rgb = Vec::with_capacity(w as usize * h as usize * 3);
    for &p in &buffer[..w as usize * h as usize] {
        rgb.extend_from_slice(&[(p >> 16) as u8, (p >> 8) as u8, p as u8]);
    }
    rgb
}

impl ApplicationHandler<FrameReady> for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.win.is_some() {
            return;
        }
        let attrs = Window::default_attributes()
            .with_title(format!("strahl - {}", self.options.scene.display()))
            .with_inner_size(PhysicalSize::new(self.options.width, self.options.height));
        let window = match event_loop.create_window(attrs) {
            Ok(w) => Rc::new(w),
            Err(e) => return self.fail(event_loop, no_display(&winit_message(&e))),
        };
        let surface = Context::new(window.clone()).and_then(|cx| Surface::new(&cx, window.clone()));
        match surface {
            Ok(surface) => {
                let s = window.inner_size();
                self.size = (s.width, s.height);
                self.win = Some(Win { window, surface });
                self.tick(event_loop);
            }
            Err(e) => self.fail(event_loop, no_display(&format!("no pixel buffer for the window: {e}"))),
        }
    }

    fn user_event(&mut self, _event_loop: &ActiveEventLoop, _event: FrameReady) {
        self.redraw();
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => {
                self.size = (size.width, size.height);
                self.redraw();
            }
            WindowEvent::Focused(false) => {
                // Key releases that happen elsewhere never arrive: forget what is held.
                self.input.release_all();
                self.set_grab(false);
            }
            WindowEvent::KeyboardInput { event, .. } => {
                if let PhysicalKey::Code(code) = event.physical_key {
                    let pressed = event.state == ElementState::Pressed;
                    if let Some(c) = apply_key(code, pressed, event.repeat, &mut self.input) {
                        self.command(event_loop, c);
                    }
                }
            }
            WindowEvent::MouseInput {
                state: ElementState::Pressed,
                button: MouseButton::Right | MouseButton::Left,
                ..
            } if !self.grabbed => self.set_grab(true),
            WindowEvent::MouseWheel { delta, .. } => {
                let y = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y as f64,
                    MouseScrollDelta::PixelDelta(p) => p.y / 40.0,
                };
                self.input.speed_steps += y.signum() as i32 * (y.abs().ceil().min(10.0) as i32);
            }
            WindowEvent::RedrawRequested => self.present(event_loop),
            _ => {}
        }
    }

    fn device_event(&mut self, _event_loop: &ActiveEventLoop, _id: DeviceId, event: DeviceEvent) {
        if let DeviceEvent::MouseMotion { delta } = event {
            if self.grabbed {
                self.input.mouse += DVec2::new(delta.0, delta.1);
            }
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.win.is_some() {
            self.tick(event_loop);
        }
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        // Drop the surface before the window it draws into.
        self.win = None;
    }
}

#[cfg(test)]
mod tests {
    use super::winit_message;

    /// A failed X connection printed `os error at /root/.cargo/registry/.../winit-0.30/src/...`.
    #[test]
    fn winit_errors_lose_winit_source_paths() {
        let e = "os error at /home/u/.cargo/registry/src/index/winit-0.30.13/src/platform_impl/linux/mod.rs:788: failed to open display: :12";
        assert_eq!(winit_message(&e), "failed to open display: :12");
        assert_eq!(winit_message(&"EventLoop can't be recreated"), "EventLoop can't be recreated");
        assert_eq!(winit_message(&"os error at odd"), "os error at odd");
    }
}
