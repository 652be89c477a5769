//! `strahl view` end to end: a real window on a virtual X server, its presented pixels compared
//! with `strahl render` of the same scene; and the message on a machine without a display.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use strahl::headless::output::read_png;

const BIN: &str = env!("CARGO_BIN_EXE_strahl");

fn seed() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join("seed.pov")
}

fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(program).is_file()))
}

/// An Xvfb server on a free display number, stopped on drop.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    fn start() -> Option<Xvfb> {
        for n in 90..200 {
            let socket = format!("/tmp/.X11-unix/X{n}");
            let lock = format!("/tmp/.X{n}-lock");
            if Path::new(&socket).exists() || Path::new(&lock).exists() {
                continue;
            }
            let mut child = Command::new("Xvfb")
                .args([
                    format!(":{n}").as_str(),
                    "-screen",
                    "0",
                    "1280x1024x24",
                    "-nolisten",
                    "tcp",
                ])
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .ok()?;
            let start = Instant::now();
            while start.elapsed() < Duration::from_secs(10) {
                if Path::new(&socket).exists() {
                    return Some(Xvfb {
                        child,
                        display: format!(":{n}"),
                    });
                }
                if let Ok(Some(_)) = child.try_wait() {
                    break; // lost a race for this number; try the next
                }
                std::thread::sleep(Duration::from_millis(50));
            }
            let _ = child.kill();
            let _ = child.wait();
        }
        None
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Peak signal-to-noise ratio of two 8-bit images of the same size, in dB.
fn psnr(a: &[u8], b: &[u8]) -> f64 {
    assert_eq!(a.len(), b.len());
    let mse = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| (x as f64 - y as f64).powi(2))
        .sum::<f64>()
        / a.len() as f64;
    if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (255.0f64 * 255.0 / mse).log10()
    }
}

fn tmp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("strahl-window-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn psnr_helper() {
    assert_eq!(psnr(&[1, 2, 3], &[1, 2, 3]), f64::INFINITY);
    assert!((psnr(&[0; 4], &[255; 4])).abs() < 1e-12);
}

#[test]
fn view_screenshot_matches_render() {
    let _xvfb;
    let display = if on_path("Xvfb") {
        match Xvfb::start() {
            Some(x) => {
                let d = x.display.clone();
                _xvfb = x;
                d
            }
            None => panic!("Xvfb is installed but would not start"),
        }
    } else if let Some(d) = std::env::var_os("DISPLAY") {
        d.to_string_lossy().into_owned()
    } else {
        println!("skipping: no X server (install xvfb)");
        return;
    };
    let dir = tmp_dir("shot");
    let shot = dir.join("shot.png");
    let reference = dir.join("render.png");

    let mut child = Command::new(BIN)
        .args([
            "view",
            seed().to_str().unwrap(),
            "-W",
            "640",
            "-H",
            "480",
            "--frames",
            "8",
            "--aa",
            "1",
            "--screenshot",
        ])
        .arg(&shot)
        .env("DISPLAY", &display)
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if start.elapsed() > Duration::from_secs(240) {
            let _ = child.kill();
            panic!("strahl view did not finish within 240 s");
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let out = child.wait_with_output().unwrap();
    assert!(
        status.success(),
        "strahl view failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );

    let r = Command::new(BIN)
        .args([
            "render",
            seed().to_str().unwrap(),
            "-W",
            "640",
            "-H",
            "480",
            "--aa",
            "1",
            "-q",
            "-o",
        ])
        .arg(&reference)
        .output()
        .unwrap();
    assert!(
        r.status.success(),
        "strahl render failed: {}",
        String::from_utf8_lossy(&r.stderr)
    );

    let (sw, sh, a) = read_png(&shot).unwrap();
    let (rw, rh, b) = read_png(&reference).unwrap();
    assert_eq!((sw, sh), (rw, rh), "screenshot size");
    let p = psnr(&a, &b);
    assert!(
        p >= 40.0,
        "screenshot vs render: PSNR {p:.2} dB < 40 dB ({} and {})",
        shot.display(),
        reference.display()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn view_without_display_points_to_headless_commands() {
    let out = Command::new(BIN)
        .args(["view", seed().to_str().unwrap()])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("cannot open a window"), "{err}");
    assert!(
        err.contains("strahl render") && err.contains("strahl capture"),
        "{err}"
    );
}
