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

/// Writes a scene whose sphere moves and grows with `clock` (radius 0.5 at clock 0, 1 at clock
/// 1), so every clock value gives other pixels; returns its path.
fn clock_scene(test: &str) -> String {
    let dir = scratch(test);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let scene = dir.join("clock.pov");
    let text = "camera { location <0, 0, -5> look_at 0 }\nlight_source { <5, 5, -5> color rgb 1 }\n\
                sphere { <clock, 0, 0>, 0.5 + clock / 2 pigment { rgb <1, 0.5, 0> } }\n";
    std::fs::write(&scene, text).unwrap_or_else(|e| panic!("{e}"));
    scene.display().to_string()
}

/// Captures 3 frames of `scene` at 24×18 into `dir` with `extra` arguments; returns the
/// manifest and the PNG bytes of every frame it lists.
fn clock_capture(scene: &str, dir: &Path, extra: &[&str]) -> (Manifest, Vec<(u32, Vec<u8>)>) {
    let (path, d) = (orbit(), dir.display().to_string());
    let mut args = vec!["capture", scene, "--path", &path, "--frames", "3", "-W", "24", "-H", "18", "-q", "-o", &d];
    args.extend_from_slice(extra);
    ok(&args);
    let m = Manifest::read(dir).unwrap_or_else(|e| panic!("{e}"));
    let pngs = m.frames.iter().map(|f| (f.index, std::fs::read(dir.join(&f.file)).unwrap_or_else(|e| panic!("{e}"))));
    let pngs = pngs.collect();
    (m, pngs)
}

#[test]
fn capture_with_clock_parses_each_frame_at_its_clock_and_shards_agree() {
    let scene = clock_scene("clock_scene");
    let (whole, frames) = clock_capture(&scene, &scratch("clock_whole"), &["--clock", "0..1"]);
    assert_eq!(whole.frames.len(), 3);
    let shas: Vec<&str> = whole.frames.iter().map(|f| f.sha256.as_str()).collect();
    assert!(shas[0] != shas[1] && shas[1] != shas[2] && shas[0] != shas[2], "{shas:?}");
    let text = std::fs::read_to_string(scratch_path("clock_whole").join("manifest.json")).unwrap_or_default();
    let v = Json::parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let clock = v.get("clock").unwrap_or_else(|| panic!("no clock in {text}"));
    assert_eq!(
        (clock.get("from").and_then(Json::as_f64), clock.get("to").and_then(Json::as_f64)),
        (Some(0.0), Some(1.0))
    );
    // A shard parses frame i at frame i's clock of the whole capture, not of the shard.
    let (first, shard_a) =
        clock_capture(&scene, &scratch("clock_shard_a"), &["--clock", "0..1", "--frames-range", "0..1"]);
    let (last, shard_b) =
        clock_capture(&scene, &scratch("clock_shard_b"), &["--clock", "0..1", "--frames-range", "2..3"]);
    assert_eq!(shard_a, vec![frames[0].clone()], "frame 0 of shard 0..1 differs from the whole capture's");
    assert_eq!(shard_b, vec![frames[2].clone()], "frame 2 of shard 2..3 differs from the whole capture's");
    let (a, b) =
        (scratch_path("clock_shard_a").display().to_string(), scratch_path("clock_shard_b").display().to_string());
    let mid = scratch("clock_shard_mid");
    clock_capture(&scene, &mid, &["--clock", "0..1", "--frames-range", "1..2"]);
    let (m, out) = (mid.display().to_string(), scratch("clock_merged"));
    ok(&["capture", "--merge", &a, &m, &b, "-o", &out.display().to_string()]);
    let merged = Manifest::read(&out).unwrap_or_else(|e| panic!("{e}"));
    assert!(merged.same_content(&whole), "merged clock shards differ from one run");
    assert!(first.same_header(&last) && first.same_header(&whole));
    // Another clock range is another capture: refused in the same folder, and it differs.
    let dir = scratch_path("clock_whole").display().to_string();
    let path = orbit();
    let err = fails(&[
        "capture", &scene, "--path", &path, "--frames", "3", "-W", "24", "-H", "18", "--clock", "0..0.5", "-o", &dir,
    ]);
    assert!(err.contains("not empty") && err.contains("clock range"), "{err}");
    let (half, _) = clock_capture(&scene, &scratch("clock_half"), &["--clock", "0..0.5"]);
    assert_eq!(half.frames[0].sha256, whole.frames[0].sha256, "both start at clock 0");
    assert_ne!(half.frames[2].sha256, whole.frames[2].sha256, "clock 0.5 against clock 1");
}

/// The scratch folder of `test` without clearing it.
fn scratch_path(test: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli").join(test)
}

#[test]
fn capture_without_clock_parses_once_at_clock_0() {
    let scene = clock_scene("noclock_scene");
    let (m, frames) = clock_capture(&scene, &scratch("noclock"), &[]);
    // The orbit is closed, so frames 0 and 2 share a camera; the scene at clock 0 does not move.
    assert_eq!(frames[0].1, frames[2].1, "the same clock and camera give the same frame");
    let text = std::fs::read_to_string(scratch_path("noclock").join("manifest.json")).unwrap_or_default();
    assert!(!text.contains("\"clock\""), "no clock in the manifest of a still capture: {text}");
    // Without --clock the scene sees clock 0: the same as the first frame of --clock 0..1.
    let (clocked, clocked_frames) = clock_capture(&scene, &scratch("noclock_vs"), &["--clock", "0..1"]);
    assert_eq!(frames[0].1, clocked_frames[0].1);
    assert_ne!(m.frames[2].sha256, clocked.frames[2].sha256, "clock 1 moves the sphere");
}

#[test]
fn malformed_clock_ranges_are_rejected_before_work() {
    let dir = scratch("clock_malformed");
    let d = dir.display().to_string();
    let (scene, path) = (seed(), orbit());
    for clock in ["x..y", "1", "nan..1", "0..inf", "..1", "-1e308..1e308"] {
        let err = fails(&["capture", &scene, "--path", &path, "--frames", "3", "--clock", clock, "-o", &d]);
        assert!(err.contains("--clock") && err.contains(clock), "{clock}: {err}");
        let err = fails(&["bench", &scene, "--frames", "2", "--clock", clock]);
        assert!(err.contains("--clock") && err.contains(clock), "bench {clock}: {err}");
    }
    // The argument is checked before the scene is read: a missing scene is not the error.
    let err = fails(&["bench", "/nonexistent/scene.pov", "--clock", "1"]);
    assert!(err.contains("--clock"), "{err}");
    assert!(!dir.exists(), "nothing may be written");
}

#[test]
fn bench_with_clock_reparses_every_timed_frame() {
    let scene = clock_scene("bench_clock_scene");
    let dir = scratch("bench_clock");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let json = dir.join("bench.json");
    let (path, j) = (orbit(), json.display().to_string());
    let args =
        ["bench", &scene, "--path", &path, "-W", "16", "-H", "12", "--frames", "3", "--warmup", "1", "--json", &j];
    let mut clocked = args.to_vec();
    clocked.extend_from_slice(&["--clock", "1..0"]);
    let stdout = String::from_utf8_lossy(&ok(&clocked).stdout).into_owned();
    assert!(stdout.contains("clock:      1..0, scene parsed and built anew"), "{stdout}");
    let v = Json::parse(&std::fs::read_to_string(&json).unwrap_or_default()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(v.get("parse_ms").and_then(Json::as_array).map(|a| a.len()), Some(3));
    assert_eq!(v.get("frame_ms").and_then(Json::as_array).map(|a| a.len()), Some(3));
    assert_eq!(v.get("clock").and_then(|c| c.get("to")).and_then(Json::as_f64), Some(0.0));
    // Without --clock nothing about parsing is reported.
    let stdout = String::from_utf8_lossy(&ok(&args).stdout).into_owned();
    assert!(!stdout.contains("clock:"), "{stdout}");
    let v = Json::parse(&std::fs::read_to_string(&json).unwrap_or_default()).unwrap_or_else(|e| panic!("{e}"));
    assert!(v.get("parse_ms").is_none() && v.get("clock").is_none());
}

#[test]
fn render_names_every_included_file_and_where_it_was_included() {
    let dir = scratch("render_included");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("inner.inc"), "#declare R = 1;\n").unwrap();
    std::fs::write(dir.join("outer.inc"), "#declare Q = 2;\n#include \"inner.inc\"\n").unwrap();
    std::fs::write(dir.join("s.pov"), "#include \"outer.inc\"\nsphere { 0, R }\n").unwrap();
    let scene = dir.join("s.pov");
    let png = dir.join("s.png");
    let out = ok(&["render", scene.to_str().unwrap(), "-W", "8", "-H", "6", "-o", png.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = stdout.lines().filter(|l| l.starts_with("Included: ")).collect();
    assert_eq!(lines.len(), 2, "{stdout}");
    assert!(lines[0].contains("outer.inc") && lines[0].ends_with("s.pov:1:1)"), "{stdout}");
    assert!(lines[1].contains("inner.inc") && lines[1].ends_with("outer.inc:2:1)"), "{stdout}");
}

#[test]
fn render_with_an_ini_parses_the_scene_at_the_animations_frame() {
    let dir = scratch("render_ini");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    // As POV-Ray's portfolio samples do: a still image (frame 0) indexes the array at -1.
    let scene = dir.join("anim.pov");
    std::fs::write(
        &scene,
        "#declare C = array[3] { rgb <1,0,0>, rgb <0,1,0>, rgb <0,0,1> }\n\
         background { C[frame_number - 1] * (1 + clock) }\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let ini = dir.join("anim.ini");
    std::fs::write(&ini, "Initial_Frame=1\nFinal_Frame=3\nInitial_Clock=0\nFinal_Clock=1 ; the last\n")
        .unwrap_or_else(|e| panic!("{e}"));
    let (scene, ini) = (scene.display().to_string(), ini.display().to_string());
    let out = |name: &str| dir.join(name).display().to_string();
    let still = fails(&["render", &scene, "-W", "4", "-H", "4", "-q", "-o", &out("still.png")]);
    assert!(still.contains("anim.pov:2:"), "{still}");
    let (first, last) = (out("first.png"), out("last.png"));
    ok(&["render", &scene, "--ini", &ini, "-W", "4", "-H", "4", "-q", "-o", &first]);
    ok(&["render", &scene, "--ini", &ini, "--frame", "3", "-W", "4", "-H", "4", "-q", "-o", &last]);
    let pixel = |f: &str| {
        let decoder = png::Decoder::new(std::fs::File::open(f).unwrap_or_else(|e| panic!("{e}")));
        let mut reader = decoder.read_info().unwrap_or_else(|e| panic!("{e}"));
        let mut buf = vec![0; reader.output_buffer_size()];
        reader.next_frame(&mut buf).unwrap_or_else(|e| panic!("{e}"));
        [buf[0], buf[1], buf[2]]
    };
    assert_eq!(pixel(&first), [255, 0, 0], "frame 1 at clock 0: C[0]");
    assert_eq!(pixel(&last)[..2], [0, 0], "frame 3: C[2], blue, clock 1 doubles it (clipped)");
    assert_eq!(pixel(&last)[2], 255);
    let err = fails(&["render", &scene, "--ini", &ini, "--frame", "4", "-q", "-o", &out("x.png")]);
    assert!(err.contains("--frame 4 is outside the animation's frames 1..3"), "{err}");
    assert!(!dir.join("x.png").exists(), "nothing written on an error");
}

#[test]
fn survey_renders_a_scratch_copy_so_scenes_may_write_and_the_folder_is_untouched() {
    let dir = scratch("survey_copy");
    std::fs::create_dir_all(dir.join("sub")).unwrap_or_else(|e| panic!("{e}"));
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).unwrap_or_else(|e| panic!("{e}"));
    // As POV-Ray's portfolio samples do: a scene writes a file beside itself.
    write(
        "writes.pov",
        "#fopen F \"out.txt\" write\n#write (F, \"x\")\n#fclose F\nsphere { 0, 1 pigment { rgb 1 } }\n",
    );
    write("sub/plain.pov", "sphere { 0, 1 pigment { rgb 1 } }\n");
    write("sub/bad.pov", "sphere { 0, 1 nonsense }\n");
    let d = dir.display().to_string();
    let out = ok(&["survey", &d, "-q", "--list"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("2 of 3 scenes render"), "{text}");
    assert!(
        text.contains(&format!("{}: Rendered", dir.join("writes.pov").display())),
        "listed by their own path: {text}"
    );
    assert!(!dir.join("out.txt").exists(), "the surveyed folder is never written");
}

#[test]
fn path_orbit_writes_a_closed_orbit_that_bench_follows() {
    let dir = scratch("path_orbit");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let file = dir.join("seed.orbit.path");
    let p = file.display().to_string();
    ok(&["path", "orbit", &seed(), "-o", &p, "--frames", "6", "--seconds", "4", "-q"]);
    let path = strahl::camera::path::CameraPath::load(&file).unwrap_or_else(|e| panic!("{e}"));
    let keys = path.keys();
    assert_eq!(keys.len(), 7, "six keys around and one closing the loop");
    assert!(path.closed && path.constant_speed);
    assert_eq!((keys[0].time, keys[6].time), (0.0, 4.0));
    // The seed's camera: location <3, 3, -1>, look_at <0, 1, 2>; radius √18 at height 3.
    assert_eq!(keys[0].location, glam::DVec3::new(3.0, 3.0, -1.0));
    assert_eq!(keys[6].location, keys[0].location);
    for k in keys {
        assert_eq!(k.look_at, glam::DVec3::new(0.0, 1.0, 2.0));
        let r = k.location - k.look_at;
        assert!(
            ((r.x * r.x + r.z * r.z).sqrt() - 18f64.sqrt()).abs() < 1e-9 && k.location.y == 3.0,
            "{:?}",
            k.location
        );
    }
    let json = dir.join("bench.json").display().to_string();
    ok(&["bench", &seed(), "--path", &p, "-W", "32", "-H", "24", "--frames", "3", "--warmup", "0", "--json", &json]);
}

#[test]
fn path_orbit_errors_exit_2_and_write_nothing() {
    let dir = scratch("path_orbit_errors");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.join("o.path");
    let o = out.display().to_string();
    let bad = dir.join("bad.pov");
    std::fs::write(&bad, "camera { location <0, 1, -3> look_at 0 }\nsphere { 0, 1 nonsense }\n")
        .unwrap_or_else(|e| panic!("{e}"));
    let err = fails(&["path", "orbit", &bad.display().to_string(), "-o", &o]);
    assert!(err.contains("bad.pov:2:"), "a located scene error: {err}");
    let err = fails(&["path", "orbit", &seed(), "-o", &dir.join("nodir").join("o.path").display().to_string()]);
    assert!(err.contains("does not exist"), "{err}");
    for seconds in ["0", "-1", "nan", "inf", "x", "1e9"] {
        let err = fails(&["path", "orbit", &seed(), "-o", &o, "--seconds", seconds]);
        assert!(err.contains("seconds"), "{seconds}: {err}");
    }
    for frames in ["2", "0", "-3", "x"] {
        fails(&["path", "orbit", &seed(), "-o", &o, "--frames", frames]);
    }
    assert!(!out.exists(), "nothing is written on an error");
    assert_eq!(std::fs::read_dir(&dir).map(|d| d.count()).unwrap_or(0), 1, "no temporary files left");
}
