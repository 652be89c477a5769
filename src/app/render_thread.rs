//! The window's renderer: a background thread that owns the scene and a rayon pool, takes the
//! latest requested view, and sends back finished 0RGB frames. Tracing overlaps presenting.
//!
//! Policy, per frame: a view that differs from the last one rendered is "moving" and renders at
//! the adaptive scale with one sample per pixel; a view that has held still for `SETTLE` renders
//! full-resolution sub-sample passes into a `progressive::Accumulator` until it has all aa² of
//! them, when it equals `strahl render --aa N`. Then the thread sleeps until the view changes.
//!
//! Frames circulate between the two threads (at most `FRAMES` exist), so the steady state
//! allocates nothing. This module knows no window type: the caller passes a `wake` callback.
//!
//! Live reload happens here too: given a [`Watch`], the thread polls the scene's files between
//! frames (and every `reload::POLL` while idle), rebuilds its `Scene` when they change or F5 asks,
//! and publishes the outcome in a [`ReloadStatus`]; a broken file leaves the old scene in place.

use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Condvar, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use glam::DVec3;

use crate::app::reload::{Reloader, POLL};
use crate::camera::Camera;
use crate::headless::CliError;
use crate::render::adaptive::ScaleController;
use crate::render::image::Image;
use crate::render::moving_mode::{Mode, ModeChoice, Recorded};
use crate::render::progressive::Accumulator;
use crate::render::reproject::{ReprojectStats, Reprojector};
use crate::render::stats::RenderStats;
use crate::render::{render, Quality, RenderSettings};
use crate::scene::build::{AccelKind, Scene};

/// How long a view must stay unchanged before refinement starts, so that a camera moving in
/// small steps (key repeat, a slow stick) is not interrupted by a full-resolution pass.
const SETTLE: Duration = Duration::from_millis(60);
/// One frame shown, one in the channel, one being rendered.
const FRAMES: usize = 3;

fn encode(image: &Image, srgb: bool, frame: &mut Frame) {
    let start = Instant::now();
    frame.width = image.width;
    frame.height = image.height;
    frame.pixels.resize(image.pixels.len(), 0);
    image.write_xrgb(srgb, &mut frame.pixels);
    frame.encode_time = start.elapsed();
}

/// What to render: the camera and the full (window) resolution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub camera: Camera,
    pub width: u32,
    pub height: u32,
    pub aa: u32,
    pub quality: Quality,
    /// Upper bound on the adaptive scale while moving (a preset's `res_scale`; 1 = none).
    pub max_scale: f64,
    /// Moving frames may trace a quarter of their pixels and reuse the rest from the frame
    /// before (`render::reproject`) where the camera allows it and that is measured to be
    /// cheaper here (`render::moving_mode`).
    pub reproject: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Progress {
    /// Reduced resolution while the camera moves.
    #[default]
    Moving,
    /// Full resolution, `pass` of `total` sub-sample passes done.
    Refining { pass: u32, total: u32 },
}

impl Progress {
    pub fn is_converged(self) -> bool {
        matches!(self, Progress::Refining { pass, total } if pass >= total)
    }
}

/// A finished frame at the internal resolution.
#[derive(Clone, Debug, Default)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// 0RGB, row-major, top row first (softbuffer's format).
    pub pixels: Vec<u32>,
    pub scale: f64,
    pub progress: Progress,
    pub stats: RenderStats,
    pub render_time: Duration,
    /// The view this frame shows.
    pub view: Option<View>,
    /// Where a reprojected moving frame's pixels came from; `None` for frames rendered whole.
    pub reprojected: Option<ReprojectStats>,
    /// The part of `render_time` spent turning the traced result into `pixels`.
    pub encode_time: Duration,
    /// When the render thread sent the frame (for the window's hand-off time).
    pub sent_at: Option<Instant>,
}

/// What the render thread needs to rebuild its scene from disk.
pub struct Watch {
    pub reloader: Reloader,
    /// The render origin the first scene was built around; kept, so that a reload changes only
    /// what the file changed.
    pub origin: DVec3,
    pub accel: AccelKind,
}

/// The outcome of the latest reload, for the window to show.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ReloadStatus {
    /// Counts reloads, failed ones included, so the window can tell that something happened.
    pub generation: u64,
    /// The located error of the last reload; `None` once a reload succeeds.
    pub error: Option<String>,
    /// The camera the reloaded scene declares (for R, reset camera).
    pub camera: Option<Camera>,
    /// What the reloaded scene uses that strahl does not model (for the HUD); `None` until a
    /// reload succeeds.
    pub unmodelled: Option<Vec<String>>,
}

struct Slot {
    view: Option<View>,
    quit: bool,
    /// F5: reload even if no file changed.
    reload: bool,
    status: ReloadStatus,
}

type Shared = Arc<(Mutex<Slot>, Condvar)>;

pub struct RenderThread {
    shared: Shared,
    frames: Receiver<Frame>,
    recycle: Sender<Frame>,
    handle: Option<JoinHandle<()>>,
}

impl RenderThread {
    /// Starts the thread with a pool of `threads` workers (0 = one per core). `wake` is called
    /// after each frame is sent.
    pub fn spawn(
        scene: Scene,
        watch: Option<Watch>,
        threads: usize,
        target_fps: f64,
        wake: impl Fn() + Send + 'static,
    ) -> Result<RenderThread, CliError> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .thread_name(|i| format!("strahl-render-{i}"))
            .build()
            .map_err(|e| CliError::user(format!("cannot start {threads} render threads: {e}")))?;
        let shared: Shared = Arc::new((
            Mutex::new(Slot { view: None, quit: false, reload: false, status: ReloadStatus::default() }),
            Condvar::new(),
        ));
        let (frame_tx, frame_rx) = mpsc::channel();
        let (recycle_tx, recycle_rx) = mpsc::channel();
        let worker = Worker {
            scene,
            watch,
            pool,
            shared: shared.clone(),
            frames: frame_tx,
            recycle: recycle_rx,
            allocated: 0,
            controller: ScaleController::new(target_fps),
            mode: ModeChoice::default(),
            reprojector: Reprojector::default(),
            moving_quality: None,
            wake: Box::new(wake),
        };
        let handle = std::thread::Builder::new()
            .name("strahl-view".into())
            .spawn(move || worker.run())
            .map_err(|e| CliError::user(format!("cannot start the render thread: {e}")))?;
        Ok(RenderThread { shared, frames: frame_rx, recycle: recycle_tx, handle: Some(handle) })
    }

    /// Asks for `view`; the thread renders the latest view it has been given.
    pub fn submit(&self, view: View) {
        let (lock, cvar) = &*self.shared;
        let mut slot = lock.lock().unwrap_or_else(PoisonError::into_inner);
        if slot.view != Some(view) {
            slot.view = Some(view);
            cvar.notify_one();
        }
    }

    /// Asks for the scene to be reloaded from disk (F5); a no-op without a [`Watch`].
    pub fn request_reload(&self) {
        let (lock, cvar) = &*self.shared;
        lock.lock().unwrap_or_else(PoisonError::into_inner).reload = true;
        cvar.notify_one();
    }

    /// The outcome of the latest reload.
    pub fn reload_status(&self) -> ReloadStatus {
        let slot = self.shared.0.lock().unwrap_or_else(PoisonError::into_inner);
        slot.status.clone()
    }

    /// The newest finished frame, if any arrived; older ones go straight back to the pool.
    pub fn latest(&self) -> Option<Frame> {
        let mut newest = None;
        while let Ok(f) = self.frames.try_recv() {
            if let Some(old) = newest.replace(f) {
                self.give_back(old);
            }
        }
        newest
    }

    /// Returns a frame's buffer for reuse.
    pub fn give_back(&self, frame: Frame) {
        let _ = self.recycle.send(frame);
    }

    /// Whether the thread is still running (it stops only on quit, or if a render panicked).
    pub fn is_alive(&self) -> bool {
        self.handle.as_ref().is_some_and(|h| !h.is_finished())
    }
}

impl Drop for RenderThread {
    fn drop(&mut self) {
        {
            let (lock, cvar) = &*self.shared;
            lock.lock().unwrap_or_else(PoisonError::into_inner).quit = true;
            cvar.notify_one();
        }
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

struct Worker {
    scene: Scene,
    watch: Option<Watch>,
    pool: rayon::ThreadPool,
    shared: Shared,
    frames: Sender<Frame>,
    recycle: Receiver<Frame>,
    allocated: usize,
    controller: ScaleController,
    /// Whether moving frames are made whole or reprojected, by what each costs here.
    mode: ModeChoice,
    /// Moving frames by reuse of the frame before; reset with a new scene or quality.
    reprojector: Reprojector,
    /// The quality the reprojector's history and the mode choice belong to.
    moving_quality: Option<Quality>,
    wake: Box<dyn Fn() + Send>,
}

/// What the next frame is.
enum Job {
    Preview(View),
    Refine(View),
    /// Reload the scene: a watched file changed, or F5.
    Reload,
}

impl Worker {
    fn run(mut self) {
        let mut last: Option<View> = None;
        let mut changed_at = Instant::now();
        let mut acc = Accumulator::default();
        let mut acc_view: Option<View> = None;
        let mut pass = Image::default();
        let mut resolved = Image::default();
        loop {
            let Some(job) = self.next_job(&mut last, &mut changed_at, &acc, acc_view) else {
                return;
            };
            if let Job::Reload = job {
                if self.reload() {
                    // Render the same view again, from a fresh preview, with the new scene.
                    last = None;
                    acc_view = None;
                    self.reprojector.reset();
                    self.mode = ModeChoice::default();
                }
                (self.wake)();
                continue;
            }
            let Some(mut frame) = self.take_frame() else {
                return;
            };
            let start = Instant::now();
            match job {
                Job::Preview(view) => {
                    let scale = self.controller.scale().min(view.max_scale);
                    let w = ((view.width as f64 * scale).round() as u32).max(1);
                    let h = ((view.height as f64 * scale).round() as u32).max(1);
                    let settings = self.settings(&view, w, h, None);
                    if self.moving_quality != Some(view.quality) {
                        self.reprojector.reset();
                        self.mode = ModeChoice::default();
                        self.moving_quality = Some(view.quality);
                    }
                    frame.reprojected = None;
                    let reprojectable = view.reproject && Reprojector::supports(&self.scene, &view.camera);
                    let mode = if reprojectable { self.mode.next() } else { Mode::Whole };
                    if mode == Mode::Reprojected {
                        let (scene, reprojector) = (&self.scene, &mut self.reprojector);
                        let (pixels, stats, counts) =
                            self.pool.install(|| reprojector.frame(scene, &view.camera, &settings));
                        frame.stats = stats;
                        frame.reprojected = Some(counts);
                        (frame.width, frame.height) = (w, h);
                        let copy = Instant::now();
                        frame.pixels.clear();
                        frame.pixels.extend_from_slice(pixels);
                        frame.encode_time = copy.elapsed();
                    } else {
                        frame.stats = self.pool.install(|| render(&self.scene, &view.camera, &settings, &mut pass));
                        self.pool.install(|| encode(&pass, self.scene.srgb, &mut frame));
                    }
                    frame.progress = Progress::Moving;
                    frame.scale = w as f64 / view.width as f64;
                    frame.view = Some(view);
                    let seconds = start.elapsed().as_secs_f64();
                    match reprojectable.then(|| self.mode.record(mode, frame.scale, seconds)) {
                        None | Some(Recorded::Chosen) => {
                            self.controller.update(frame.scale, seconds);
                        }
                        Some(Recorded::Probe) => {}
                        Some(Recorded::Switched(ratio)) => self.controller.rescale_cost(ratio),
                    }
                }
                Job::Refine(view) => {
                    if acc_view != Some(view) {
                        acc.reset(view.width, view.height, view.aa);
                        acc_view = Some(view);
                    }
                    let sub = acc.next_subsample();
                    let settings = self.settings(&view, view.width, view.height, sub);
                    frame.stats = self.pool.install(|| render(&self.scene, &view.camera, &settings, &mut pass));
                    acc.add(&pass);
                    acc.resolve(&mut resolved);
                    self.pool.install(|| encode(&resolved, self.scene.srgb, &mut frame));
                    frame.reprojected = None;
                    frame.progress = Progress::Refining { pass: acc.passes(), total: acc.total() };
                    frame.scale = 1.0;
                    frame.view = Some(view);
                }
                Job::Reload => unreachable!("handled above"),
            }
            frame.render_time = start.elapsed();
            frame.sent_at = Some(Instant::now());
            if self.frames.send(frame).is_err() {
                return;
            }
            (self.wake)();
        }
    }

    fn settings(&self, view: &View, width: u32, height: u32, subsample: Option<(u32, u32)>) -> RenderSettings {
        let aa = if subsample.is_some() { view.aa } else { 1 };
        RenderSettings { width, height, aa, quality: view.quality, subsample, ..RenderSettings::default() }
    }

    /// Reloads the scene and publishes the outcome; whether the scene changed.
    fn reload(&mut self) -> bool {
        let Some(watch) = &mut self.watch else {
            return false;
        };
        let (result, camera, unmodelled) = match watch.reloader.reload() {
            Ok(desc) => {
                self.scene = Scene::build(desc, watch.origin, watch.accel);
                (None, Some(Camera::from_desc(&desc.camera)), Some(crate::app::unmodelled_names(desc)))
            }
            Err(message) => (Some(message.to_string()), None, None),
        };
        let ok = result.is_none();
        let mut slot = self.shared.0.lock().unwrap_or_else(PoisonError::into_inner);
        slot.status.generation += 1;
        slot.status.error = result;
        slot.status.camera = camera.or(slot.status.camera);
        slot.status.unmodelled = unmodelled.or(slot.status.unmodelled.take());
        ok
    }

    /// Whether a watched file changed (checked at most every `POLL`).
    fn files_changed(&mut self) -> bool {
        self.watch.as_mut().is_some_and(|w| w.reloader.poll())
    }

    /// Blocks until there is something to render (or quit: `None`).
    fn next_job(
        &mut self,
        last: &mut Option<View>,
        changed_at: &mut Instant,
        acc: &Accumulator,
        acc_view: Option<View>,
    ) -> Option<Job> {
        let shared = self.shared.clone();
        let (lock, cvar) = &*shared;
        let mut slot = lock.lock().unwrap_or_else(PoisonError::into_inner);
        loop {
            if slot.quit {
                return None;
            }
            if std::mem::take(&mut slot.reload) || self.files_changed() {
                return Some(Job::Reload);
            }
            if let Some(view) = slot.view {
                if *last != Some(view) {
                    *last = Some(view);
                    *changed_at = Instant::now();
                    return Some(Job::Preview(view));
                }
                let done = acc_view == Some(view) && acc.is_converged();
                if !done {
                    let still = changed_at.elapsed();
                    if still >= SETTLE {
                        return Some(Job::Refine(view));
                    }
                    slot = cvar.wait_timeout(slot, SETTLE - still).unwrap_or_else(PoisonError::into_inner).0;
                    continue;
                }
            }
            slot = if self.watch.is_some() {
                // Idle, but the files still need looking at.
                cvar.wait_timeout(slot, POLL).unwrap_or_else(PoisonError::into_inner).0
            } else {
                cvar.wait(slot).unwrap_or_else(PoisonError::into_inner)
            };
        }
    }

    /// A frame buffer to render into: a returned one, a new one while fewer than `FRAMES`
    /// exist, or else the next one the window gives back. `None` when the window is gone.
    fn take_frame(&mut self) -> Option<Frame> {
        if let Ok(f) = self.recycle.try_recv() {
            return Some(f);
        }
        if self.allocated < FRAMES {
            self.allocated += 1;
            return Some(Frame::default());
        }
        loop {
            match self.recycle.recv_timeout(Duration::from_millis(50)) {
                Ok(f) => return Some(f),
                Err(RecvTimeoutError::Disconnected) => return None,
                Err(RecvTimeoutError::Timeout) => {
                    if self.shared.0.lock().unwrap_or_else(PoisonError::into_inner).quit {
                        return None;
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::mpsc;

    use super::*;
    use crate::scene::build::AccelKind;
    use crate::scene::fixtures::seed_scene as seed_like;

    fn next_frame(rt: &RenderThread, woke: &mpsc::Receiver<()>) -> Frame {
        loop {
            woke.recv_timeout(Duration::from_secs(60)).expect("a frame within a minute");
            if let Some(f) = rt.latest() {
                return f;
            }
        }
    }

    /// A moving view renders reduced, a still one refines to exactly the headless `--aa` render.
    #[test]
    fn moving_then_still_converges_to_the_headless_render() {
        let desc = seed_like();
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let srgb = scene.srgb;
        let (tx, woke) = mpsc::channel();
        let rt = RenderThread::spawn(scene, None, 2, 60.0, move || {
            let _ = tx.send(());
        })
        .unwrap();
        let camera = Camera::from_desc(&desc.camera);
        let view =
            View { camera, width: 64, height: 48, aa: 2, quality: Quality::default(), max_scale: 1.0, reproject: true };
        rt.submit(View { camera: Camera { location: camera.location + glam::DVec3::X, ..camera }, ..view });
        let first = next_frame(&rt, &woke);
        assert_eq!(first.progress, Progress::Moving);
        assert!(first.scale <= 1.0 && first.width == (64.0 * first.scale).round() as u32);
        rt.give_back(first);

        rt.submit(view);
        let last = loop {
            let f = next_frame(&rt, &woke);
            if f.view == Some(view) && f.progress.is_converged() {
                break f;
            }
            rt.give_back(f);
        };
        assert_eq!(last.progress, Progress::Refining { pass: 4, total: 4 });

        let desc_scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let mut image = Image::default();
        let settings = RenderSettings { width: 64, height: 48, aa: 2, ..RenderSettings::default() };
        render(&desc_scene, &camera, &settings, &mut image);
        let mut expect = vec![0; 64 * 48];
        image.write_xrgb(srgb, &mut expect);
        assert_eq!(last.pixels, expect);
    }

    fn converged(rt: &RenderThread, woke: &mpsc::Receiver<()>, view: View) -> Frame {
        loop {
            let f = next_frame(rt, woke);
            if f.view == Some(view) && f.progress.is_converged() {
                return f;
            }
            rt.give_back(f);
        }
    }

    /// Waits (up to a minute) for the thread to publish reload number `generation`.
    fn reload_number(rt: &RenderThread, generation: u64) -> ReloadStatus {
        let start = Instant::now();
        loop {
            let s = rt.reload_status();
            if s.generation >= generation {
                return s;
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no reload within a minute");
            std::thread::sleep(Duration::from_millis(10));
        }
    }

    /// Saving a broken scene reports its located error and keeps the old picture; fixing it
    /// renders the new scene with the camera where it was; F5 reloads an unchanged file.
    #[test]
    fn edits_on_disk_reload_the_scene_and_errors_keep_the_old_one() {
        use std::fs;
        use std::time::UNIX_EPOCH;

        let dir = std::env::temp_dir().join(format!("strahl-rt-reload-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let file = dir.join("s.pov");
        let write = |text: &str, secs: u64| {
            fs::write(&file, text).unwrap();
            let f = fs::File::options().write(true).open(&file).unwrap();
            f.set_modified(UNIX_EPOCH + Duration::from_secs(secs)).unwrap();
        };
        let scene_with = |color: &str| {
            format!(
                "camera {{ location <0, 1, -4> look_at <0, 1, 0> }}\n\
                 light_source {{ <2, 4, -4> color rgb 1 }}\n\
                 sphere {{ <0, 1, 0>, 1 pigment {{ color rgb {color} }} }}\n"
            )
        };
        write(&scene_with("<1, 0, 0>"), 100);
        let reloader = Reloader::open(&file, &[]).unwrap();
        let desc = reloader.last_good().clone();
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let watch = Watch { reloader, origin: desc.camera.location, accel: AccelKind::Bvh };
        let (tx, woke) = mpsc::channel();
        let rt = RenderThread::spawn(scene, Some(watch), 2, 60.0, move || {
            let _ = tx.send(());
        })
        .unwrap();
        // A camera the user has flown somewhere else than the scene's.
        let camera = Camera::from_desc(&desc.camera);
        let camera = Camera { location: camera.location + glam::DVec3::new(0.1, 0.0, 0.5), ..camera };
        let view =
            View { camera, width: 32, height: 24, aa: 1, quality: Quality::default(), max_scale: 1.0, reproject: true };
        rt.submit(view);
        let red = converged(&rt, &woke, view);
        rt.give_back(red.clone());

        write("camera { location <0, 1, -4> look_at <0, 1, 0> }\nsphere { <0, 1, 0>, 1 pigment { color rgb } }\n", 200);
        let broken = reload_number(&rt, 1);
        let message = broken.error.expect("a broken file reports an error");
        assert!(message.starts_with(&format!("{}:2:", file.display())), "{message}");
        // Nothing new is rendered: the last good frame stays on screen.
        std::thread::sleep(Duration::from_millis(100));
        assert!(rt.latest().is_none());

        write(&scene_with("<0, 0, 1>"), 300);
        let fixed = reload_number(&rt, 2);
        assert_eq!(fixed.error, None, "fixing the file clears the error");
        let blue = converged(&rt, &woke, view);
        assert_eq!(blue.view.unwrap().camera, camera, "the camera stays where it was flown");
        let centre = |f: &Frame| f.pixels[(12 * 32 + 16) as usize];
        assert!(centre(&red) >> 16 & 0xff > centre(&red) & 0xff, "{:06x}", centre(&red));
        assert!(centre(&blue) & 0xff > centre(&blue) >> 16 & 0xff, "{:06x}", centre(&blue));
        rt.give_back(blue);

        rt.request_reload();
        assert_eq!(reload_number(&rt, 3).error, None);
        let _ = fs::remove_dir_all(&dir);
    }
}
