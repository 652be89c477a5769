//! End-to-end tests of the `strahl` binary: capture, merge and bench against `scenes/seed.pov`,
//! and the argument errors that must exit with code 2 and leave nothing behind.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use strahl::headless::json::Json;
use strahl::headless::manifest::Manifest;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn seed() -> String {
    root().join("scenes/seed.pov").display().to_string()
}

fn orbit() -> String {
    root().join("scenes/seed.orbit.path").display().to_string()
}

/// A fresh, empty scratch folder for one test (the folder itself is not created).
fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli").join(test);
    let _ = std::fs::remove_dir_all(&dir);
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
    assert_eq!(out.status.code(), Some(2), "strahl {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn capture(dir: &Path, extra: &[&str]) -> Manifest {
    let (scene, path, d) = (seed(), orbit(), dir.display().to_string());
    let mut args = vec!["capture", &scene, "--path", &path, "--frames", "5", "-W", "32", "-H", "24", "-q", "-o", &d];
    args.extend_from_slice(extra);
    ok(&args);
    Manifest::read(dir).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn capture_writes_frames_and_manifest() {
    let dir = scratch("capture_writes");
    let m = capture(&dir, &[]);
    assert_eq!((m.width, m.height, m.frame_count, m.frames.len()), (32, 24, 5, 5));
    assert_eq!(m.frames[4].t, 1.0);
    for f in &m.frames {
        assert!(dir.join(&f.file).is_file(), "{}", f.file);
        assert_eq!(f.sha256.len(), 64);
        assert!(f.render_ms >= 0.0);
    }
    // A closed orbit ends where it starts.
    assert_eq!(m.frames[0].camera.location, m.frames[4].camera.location);
}

#[test]
fn capture_is_deterministic_across_runs_and_threads() {
    let a = capture(&scratch("determinism_a"), &["--threads", "1", "--tile", "8"]);
    let b = capture(&scratch("determinism_b"), &["--threads", "2", "--tile", "37"]);
    let c = capture(&scratch("determinism_c"), &["--threads", "8"]);
    assert!(a.same_content(&b) && b.same_content(&c));
}

#[test]
fn capture_shards_merge_into_the_whole() {
    let whole = capture(&scratch("merge_whole"), &[]);
    let (s1, s2, out) = (scratch("merge_s1"), scratch("merge_s2"), scratch("merge_out"));
    let first = capture(&s1, &["--frames-range", "0..2"]);
    assert_eq!(first.frames.len(), 2, "a shard lists only its frames");
    capture(&s2, &["--frames-range", "2..5"]);
    let (p1, p2, po) = (s1.display().to_string(), s2.display().to_string(), out.display().to_string());
    ok(&["capture", "--merge", &p1, &p2, "-o", &po]);
    let merged = Manifest::read(&out).unwrap_or_else(|e| panic!("{e}"));
    assert!(merged.same_content(&whole), "merged shards differ from one run");
    assert!(out.join("frame_0004.png").is_file());
    // An incomplete merge is refused and writes nothing.
    let partial = scratch("merge_partial");
    let pp = partial.display().to_string();
    assert!(fails(&["capture", "--merge", &p1, "-o", &pp]).contains("no shard has frame 2, 3, 4 of 5"));
    assert!(!partial.exists());
}

#[test]
fn capture_rejects_zero_frames() {
    let dir = scratch("zero_frames");
    let d = dir.display().to_string();
    fails(&["capture", &seed(), "--path", &orbit(), "--frames", "0", "-o", &d]);
    assert!(!dir.exists(), "nothing may be written");
}

#[test]
fn capture_rejects_range_out_of_bounds() {
    let dir = scratch("range_bounds");
    let d = dir.display().to_string();
    let err = fails(&["capture", &seed(), "--path", &orbit(), "--frames", "4", "--frames-range", "2..5", "-o", &d]);
    assert!(err.contains("--frames-range 2..5 is out of bounds: the capture has frames 0..4"), "{err}");
    assert!(!dir.exists());
}

#[test]
fn capture_rejects_malformed_ranges() {
    let dir = scratch("range_malformed");
    let d = dir.display().to_string();
    for (range, says) in
        [("2-5", "not a frame range"), ("5..3", "is empty"), ("a..3", "not a frame range"), ("3..3", "is empty")]
    {
        let err = fails(&["capture", &seed(), "--path", &orbit(), "--frames", "9", "--frames-range", range, "-o", &d]);
        assert!(err.contains(says), "{range}: {err}");
    }
    assert!(!dir.exists());
}

/// Writes `text` as a camera path file and runs a capture on it that must fail; returns the
/// error, having checked that the output folder was not created.
fn capture_with_bad_path(test: &str, file_name: &str, text: &str) -> String {
    let dir = scratch(test);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let file = dir.join(file_name);
    std::fs::write(&file, text).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.join("out");
    let (file, out_arg) = (file.display().to_string(), out.display().to_string());
    let err = fails(&["capture", &seed(), "--path", &file, "--frames", "2", "-o", &out_arg]);
    assert!(!out.exists());
    err
}

#[test]
fn capture_reports_path_errors_with_location() {
    let text = "key 0 location <0,0,0> look_at <1,1,1>\nkey 1 location <0,nan,0> look_at <1,1,1>\n";
    let err = capture_with_bad_path("bad_path", "bad.path", text);
    assert!(err.contains("bad.path:2:19: location y must be a finite number"), "{err}");
    assert!(err.contains("^"), "a caret under the column: {err}");
}

#[test]
fn bench_writes_json_report() {
    let dir = scratch("bench_json");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let json = dir.join("bench.json");
    let out = ok(&[
        "bench",
        &seed(),
        "--path",
        &orbit(),
        "-W",
        "32",
        "-H",
        "24",
        "--frames",
        "4",
        "--warmup",
        "1",
        "--threads",
        "2",
        "--json",
        &json.display().to_string(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("frame time: median"), "{stdout}");
    let text = std::fs::read_to_string(&json).unwrap_or_else(|e| panic!("{e}"));
    let v = Json::parse(&text).unwrap_or_else(|e| panic!("{e}"));
    for key in [
        "median_ms",
        "p95_ms",
        "p99_ms",
        "max_ms",
        "fps_median",
        "mrays_per_s",
        "width",
        "height",
        "frames",
        "threads",
        "accel",
        "packets",
        "quality",
        "cpu",
        "rays",
        "mrays_per_s_by_kind",
    ] {
        assert!(v.get(key).is_some(), "missing `{key}` in {text}");
    }
    assert_eq!(v.get("threads").and_then(Json::as_u64), Some(2));
    assert_eq!(v.get("frames").and_then(Json::as_u64), Some(4));
    assert!(v.get("median_ms").and_then(Json::as_f64).is_some_and(|m| m > 0.0));
}

#[test]
fn bench_rejects_a_bad_path_file() {
    let err = fails(&["bench", &seed(), "--path", "/nonexistent/x.path", "--frames", "2"]);
    assert!(err.contains("x.path:1:1: cannot read"), "{err}");
}

// What a new user trips over first: limits and outputs checked before any work.

#[test]
fn threads_above_cap_is_rejected_before_work() {
    let dir = scratch("threads_cap");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.join("x.png").display().to_string();
    let (scene, path) = (seed(), orbit());
    for args in [
        vec!["render", &scene, "--threads", "100000", "-o", &out],
        vec!["bench", &scene, "--threads", "1000", "--frames", "1"],
        vec!["capture", &scene, "--path", &path, "--frames", "2", "-o", &out, "--threads", "10000"],
        vec!["tradeoff", &scene, "-o", &out, "--threads", "100000"],
        vec!["view", &scene, "--threads", "100000"],
        vec!["scaling", "--threads", "100000"],
    ] {
        let err = fails(&args);
        assert!(err.contains("too many") && err.contains("cores"), "{args:?}: {err}");
    }
    assert!(!dir.join("x.png").exists(), "nothing is written");
    // Up to four per core (at least 16) stays allowed: determinism checks oversubscribe.
    ok(&["render", &scene, "-W", "16", "-H", "12", "--threads", "16", "-q", "-o", &out]);
}

#[test]
fn render_output_folder_is_checked_before_the_scene_is_read() {
    let dir = scratch("render_output_checked");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let missing_scene = dir.join("missing.pov").display().to_string();
    let out = dir.join("nodir").join("x.png").display().to_string();
    // Were the output checked after the work, the missing scene would be the error.
    let err = fails(&["render", &missing_scene, "-o", &out]);
    assert!(err.contains("-o") && err.contains("does not exist"), "{err}");
    let err = fails(&["render", &seed(), "--preset", "reference", "-o", dir.display().to_string().as_str()]);
    assert!(err.contains("is a folder"), "{err}");
}

#[test]
fn render_refuses_a_non_png_output_name() {
    let dir = scratch("render_non_png");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.join("x.jpg");
    let err = fails(&["render", &seed(), "-W", "16", "-H", "12", "-o", out.display().to_string().as_str()]);
    assert!(err.contains(".png"), "{err}");
    assert!(!out.exists(), "no PNG bytes under a .jpg name");
}

#[test]
fn render_says_what_file_it_wrote() {
    let dir = scratch("render_says");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.join("seed.png").display().to_string();
    let stdout =
        String::from_utf8_lossy(&ok(&["render", &seed(), "-W", "20", "-H", "10", "-o", &out]).stdout).into_owned();
    assert!(stdout.lines().any(|l| l == format!("wrote {out} (20x10)")), "{stdout}");
}

#[test]
fn bench_json_path_is_checked_before_the_benchmark_runs() {
    let dir = scratch("bench_json_checked");
    let json = dir.join("nodir").join("b.json").display().to_string();
    let out = strahl(&["bench", &seed(), "-W", "16", "-H", "12", "--frames", "2", "--warmup", "0", "--json", &json]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--json") && stderr.contains("does not exist"), "{stderr}");
    assert!(out.stdout.is_empty(), "no report before the error: {}", String::from_utf8_lossy(&out.stdout));
}

#[test]
fn include_folder_that_does_not_exist_is_an_error() {
    let err = fails(&["render", &seed(), "-L", "/nonexistent/strahl-include", "-o", "unused.png"]);
    assert!(err.contains("/nonexistent/strahl-include") && err.contains("does not exist"), "{err}");
}

#[test]
fn capture_into_a_folder_of_another_capture_is_refused() {
    let dir = scratch("capture_other_folder");
    capture(&dir, &[]);
    let old = std::fs::read(dir.join("frame_0004.png")).unwrap_or_else(|e| panic!("{e}"));
    let (scene, path, d) = (seed(), orbit(), dir.display().to_string());
    let smaller = ["capture", &scene, "--path", &path, "--frames", "3", "-W", "16", "-H", "12", "-q", "-o", &d];
    let err = fails(&smaller);
    assert!(err.contains("not empty") && err.contains("--force"), "{err}");
    assert_eq!(std::fs::read(dir.join("frame_0004.png")).ok(), Some(old), "the refused capture changed nothing");
    // The same capture again may reuse its own folder.
    capture(&dir, &[]);
    // --force deletes strahl's own files only, so no old frame survives among the new ones.
    std::fs::write(dir.join("notes.txt"), "mine").unwrap_or_else(|e| panic!("{e}"));
    let mut forced = smaller.to_vec();
    forced.push("--force");
    ok(&forced);
    let m = Manifest::read(&dir).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((m.width, m.frames.len()), (16, 3));
    assert!(!dir.join("frame_0003.png").exists() && !dir.join("frame_0004.png").exists());
    assert_eq!(std::fs::read_to_string(dir.join("notes.txt")).ok().as_deref(), Some("mine"));
}

#[test]
fn capture_into_a_non_empty_folder_without_a_manifest_is_refused() {
    let dir = scratch("capture_foreign_folder");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(dir.join("frame_0000.png"), b"not ours").unwrap_or_else(|e| panic!("{e}"));
    let (scene, path, d) = (seed(), orbit(), dir.display().to_string());
    let err = fails(&["capture", &scene, "--path", &path, "--frames", "2", "-W", "8", "-H", "6", "-q", "-o", &d]);
    assert!(err.contains("not empty"), "{err}");
    assert_eq!(std::fs::read(dir.join("frame_0000.png")).ok().as_deref(), Some(&b"not ours"[..]));
}

#[test]
fn capture_help_shows_scene_path_and_frames_as_required() {
    let help = String::from_utf8_lossy(&ok(&["help", "capture"]).stdout).into_owned();
    assert!(help.contains("strahl capture <SCENE> --path <PATH> --frames <N> -o <DIR>"), "{help}");
    assert!(help.contains("strahl capture --merge <DIR>... -o <DIR>"), "{help}");
    assert!(help.contains("--force"), "{help}");
}

#[test]
fn help_wraps_to_the_terminal_width() {
    let out = Command::new(env!("CARGO_BIN_EXE_strahl"))
        .args(["help", "render"])
        .env("COLUMNS", "72")
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let help = String::from_utf8_lossy(&out.stdout);
    let widest = help.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    assert!(widest <= 72, "help is {widest} columns wide:\n{help}");
}

#[test]
fn render_prints_debug_text_and_scale_0_warning_once() {
    let dir = scratch("debug_text");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let scene = dir.join("s.pov");
    std::fs::write(&scene, "#debug \"dbg-out\\n\"\nsphere { 0, 1 scale 0 pigment { rgb 1 } }\n")
        .unwrap_or_else(|e| panic!("{e}"));
    let png = dir.join("out.png").display().to_string();
    let out = ok(&["render", &scene.display().to_string(), "-W", "8", "-H", "6", "-o", &png]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("dbg-out\n"), "{err}");
    assert_eq!(err.matches("Scale by 0.0").count(), 1, "{err}");
}

#[test]
fn render_of_an_empty_scene_warns_no_objects_in_scene() {
    let dir = scratch("empty_scene");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let scene = dir.join("empty.pov");
    std::fs::write(&scene, "camera { location <0, 0, -5> look_at 0 }\n").unwrap_or_else(|e| panic!("{e}"));
    let png = dir.join("out.png");
    let out = ok(&["render", &scene.display().to_string(), "-W", "8", "-H", "6", "-o", &png.display().to_string()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("empty.pov:1:1: No objects in scene."), "{err}");
    assert!(png.exists(), "it still renders, as POV-Ray does");
}

#[test]
fn path_key_with_look_at_equal_to_location_is_a_located_error() {
    let text = "key 0 location <0,1,-5> look_at <0,0,0>\nkey 1 location <1,1,1> look_at <1,1,1>\n";
    let err = capture_with_bad_path("path_look_at", "same.path", text);
    assert!(err.contains("same.path:2:32: camera look_at is the same point as its location"), "{err}");
}
