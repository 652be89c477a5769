//! End-to-end tests of `strahl tradeoff` on `scenes/seed.pov`, of its argument errors (exit 2,
//! nothing written), and of the `--preset`/`--res-scale` flags it measures.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn seed() -> &'static str {
    concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/seed.pov")
}

/// A fresh scratch path for one test: nothing there, neither folder nor file.
fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tradeoff").join(test);
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_file(&dir);
    std::fs::create_dir_all(dir.parent().unwrap_or(Path::new("."))).unwrap_or_else(|e| panic!("{e}"));
    dir
}

fn strahl(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_strahl")).args(args).output().unwrap_or_else(|e| panic!("cannot run strahl: {e}"))
}

fn ok(args: &[&str]) -> Output {
    let out = strahl(args);
    assert!(out.status.success(), "strahl {args:?} failed:\n{}", String::from_utf8_lossy(&out.stderr));
    out
}

/// Runs a command that must fail with exit code 2; returns its stderr.
fn fails(args: &[&str]) -> String {
    let out = strahl(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "strahl {args:?}: {stderr}");
    stderr
}

/// The CSV's rows as (setting → column → value).
fn read_csv(path: &Path) -> Vec<Vec<(String, String)>> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap_or_default().split(',').map(String::from).collect();
    lines.map(|l| header.iter().cloned().zip(l.split(',').map(String::from)).collect()).collect()
}

fn field(row: &[(String, String)], name: &str) -> f64 {
    let v = &row.iter().find(|(k, _)| k == name).unwrap_or_else(|| panic!("no column {name}")).1;
    v.parse().unwrap_or_else(|e| panic!("{name} = {v}: {e}"))
}

#[test]
fn tradeoff_writes_reports_and_full_beats_quarter_resolution() {
    let dir = scratch("seed");
    let d = dir.display().to_string();
    let out = ok(&["tradeoff", seed(), "-W", "64", "-H", "48", "-o", &d, "--threads", "2"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("preset full") && stdout.contains("res-scale 0.25"), "{stdout}");
    for f in [
        "tradeoff.csv",
        "tradeoff.md",
        "tradeoff.svg",
        "reference.png",
        "errors/res-scale-0.25.png",
        "errors/preset-fast.png",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let rows = read_csv(&dir.join("tradeoff.csv"));
    assert_eq!(rows.len(), 21);
    let row = |name: &str| rows.iter().find(|r| r[0].1 == name).unwrap_or_else(|| panic!("no row {name}")).clone();
    let (full, quarter, reference) = (row("preset full"), row("res-scale 0.25"), row("preset reference"));
    assert!(field(&full, "psnr_db") > field(&quarter, "psnr_db"));
    assert!(field(&full, "ssim") > field(&quarter, "ssim"));
    // The reference preset renders the reference image again: no error at all.
    assert!(field(&reference, "psnr_db").is_infinite());
    assert_eq!(field(&reference, "max_abs_err"), 0.0);
    let svg = std::fs::read_to_string(dir.join("tradeoff.svg")).unwrap_or_default();
    assert_eq!(svg.matches("<circle").count(), rows.len());
    let md = std::fs::read_to_string(dir.join("tradeoff.md")).unwrap_or_default();
    assert_eq!(md.lines().filter(|l| l.starts_with("| `--")).count(), rows.len());
    // No temporary files are left behind by the atomic writes.
    let names: Vec<String> = std::fs::read_dir(&dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.ends_with(".tmp")), "{names:?}");
}

#[test]
fn tradeoff_bad_arguments_exit_2_and_write_nothing() {
    let dir = scratch("bad");
    let d = dir.display().to_string();
    let e = fails(&["tradeoff", "no/such/scene.pov", "-W", "8", "-H", "6", "-o", &d]);
    assert!(e.contains("no/such/scene.pov"), "{e}");
    let e = fails(&["tradeoff", seed(), "--path", "no/such.path", "-W", "8", "-H", "6", "-o", &d]);
    assert!(e.contains("no/such.path"), "{e}");
    let e = fails(&["tradeoff", seed(), "--frames", "3", "-o", &d]);
    assert!(e.contains("--path"), "{e}");
    let e = fails(&["tradeoff", seed(), "--repeats", "1", "-o", &d]);
    assert!(e.contains("--repeats"), "{e}");
    assert!(!dir.exists(), "a failed run created {d}");
    // An output path that is a file is refused before anything renders.
    std::fs::write(&dir, b"not a folder").unwrap_or_else(|e| panic!("{e}"));
    let e = fails(&["tradeoff", seed(), "-W", "8", "-H", "6", "-o", &d]);
    assert!(e.contains("not a folder"), "{e}");
}

#[test]
fn tradeoff_output_folder_is_checked_before_rendering() {
    // A folder under a regular file can never be created; the run used to render the whole
    // sweep (22 s at 1280×720) and only then fail to create it.
    let dir = scratch("blocked");
    std::fs::write(&dir, b"a file").unwrap_or_else(|e| panic!("{e}"));
    let out = dir.join("reports").display().to_string();
    // Checked even before the scene is read: a missing scene is not what it reports.
    let e = fails(&["tradeoff", "no/such/scene.pov", "-o", &out]);
    assert!(e.contains(&dir.display().to_string()) && e.contains("not a folder"), "{e}");
    let run = strahl(&["tradeoff", seed(), "-W", "1280", "-H", "720", "-o", &out]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("not a folder") && run.stdout.is_empty(), "{stderr}");
    assert_eq!(std::fs::read(&dir).unwrap_or_default(), b"a file");
    // A folder that can be made is checked without being made: a bad scene leaves nothing.
    let fresh = scratch("fresh");
    fails(&["tradeoff", "no/such/scene.pov", "-o", &fresh.join("a").join("b").display().to_string()]);
    assert!(!fresh.exists(), "{} was created", fresh.display());
}

#[test]
fn render_presets_and_res_scale() {
    let dir = scratch("presets");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let png = |name: &str| dir.join(name).display().to_string();
    let size = ["-W", "40", "-H", "30", "-q"];
    let render = |extra: &[&str], out: &str| {
        let mut args = vec!["render", seed(), "-o", out];
        args.extend_from_slice(&size);
        args.extend_from_slice(extra);
        ok(&args);
        std::fs::read(out).unwrap_or_else(|e| panic!("{out}: {e}"))
    };
    // `--preset full` is the default; an explicit flag overrides a preset's field.
    assert_eq!(render(&["--preset", "full"], &png("full.png")), render(&[], &png("plain.png")));
    let ref1 = render(&["--preset", "reference", "--aa", "1", "--precision", "f32"], &png("ref1.png"));
    assert_eq!(ref1, render(&[], &png("plain.png")));
    // `reference` is 4×4 aa in f64.
    let reference = render(&["--preset", "reference"], &png("ref.png"));
    assert_eq!(reference, render(&["--aa", "4", "--precision", "f64"], &png("aa4.png")));
    // A quarter-size render comes back at the full size, and differs.
    let quarter = render(&["--res-scale", "0.25"], &png("quarter.png"));
    assert_ne!(quarter, render(&[], &png("plain.png")));
    assert_eq!(quarter[16..24], [0, 0, 0, 40, 0, 0, 0, 30], "IHDR width and height");
    let e = fails(&["render", seed(), "-o", &png("x.png"), "--res-scale", "0.05"]);
    assert!(e.contains("0.05") && e.contains("0.1 to 1"), "{e}");
    let e = fails(&["render", seed(), "-o", &png("x.png"), "--preset", "quick"]);
    assert!(e.contains("fast, balanced, full, reference"), "{e}");
}
