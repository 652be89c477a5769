//! Sharding end to end through the `strahl` binary, without a scheduler: stills rendered in
//! bands and merged into the one-machine render's bytes (several antialiasing settings, a
//! focal-blur camera, a reduced resolution), capture shards dealt and resumed, the errors for
//! bad shards and mismatched parts, and the job script of `farm slurm` run by hand the way
//! Slurm runs it. The real cluster is in tests/packages/slurm.rs.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use strahl::headless::manifest::Manifest;

const BIN: &str = env!("CARGO_BIN_EXE_strahl");

fn scene(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name).display().to_string()
}

/// A fresh, empty scratch folder for one test (created).
fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("farm").join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    dir
}

/// The scheduler variables a test must not inherit from a CI that runs inside a job array.
const SCHEDULER_VARS: [&str; 9] = [
    "SLURM_ARRAY_TASK_ID",
    "SLURM_ARRAY_TASK_COUNT",
    "SLURM_ARRAY_TASK_MIN",
    "SLURM_ARRAY_TASK_MAX",
    "SLURM_ARRAY_TASK_STEP",
    "SLURM_JOB_ID",
    "AWS_BATCH_JOB_ARRAY_INDEX",
    "AWS_BATCH_JOB_ARRAY_SIZE",
    "JOB_COMPLETION_INDEX",
];

fn run(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(BIN);
    for v in SCHEDULER_VARS {
        c.env_remove(v);
    }
    c.args(args).envs(env.iter().copied());
    c.output().unwrap_or_else(|e| panic!("cannot run strahl: {e}"))
}

fn ok(args: &[&str]) -> Output {
    let out = run(args, &[]);
    assert!(out.status.success(), "strahl {args:?} failed:\n{}", String::from_utf8_lossy(&out.stderr));
    out
}

/// Runs a command that must fail with exit code 2; returns its stderr.
fn fails(args: &[&str], env: &[(&str, &str)]) -> String {
    let out = run(args, env);
    assert_eq!(out.status.code(), Some(2), "strahl {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn s(p: &Path) -> String {
    p.display().to_string()
}

/// Renders `scene` whole and in `n` shards (interleaved, then `--chunk`), merges the parts
/// both ways, and asserts every merge is the whole render's file, byte for byte.
fn bands_merge_to_the_whole(test: &str, scene: &str, n: u32, opts: &[&str]) {
    let dir = scratch(test);
    let whole = dir.join("whole.png");
    ok(&[&["render", scene, "-q", "-o", &s(&whole)], opts].concat());
    let expected = std::fs::read(&whole).unwrap();
    for chunk in [false, true] {
        let out = dir.join(if chunk { "chunk.png" } else { "strips.png" });
        let mut parts = Vec::new();
        for i in 0..n {
            let (shard, o) = (format!("{i}/{n}"), s(&out));
            let mut args: Vec<&str> = [&["render", scene, "-q", "-o", &o, "--shard", &shard], opts].concat();
            if chunk {
                args.push("--chunk");
            }
            ok(&args);
            parts.push(s(&dir.join(format!("{}.shard-{i}-of-{n}.png", out.file_stem().unwrap().to_string_lossy()))));
        }
        // `render --merge` finds the parts by name and checks them against its command line.
        ok(&[&["render", scene, "-q", "-o", &s(&out), "--merge"], opts].concat());
        assert!(std::fs::read(&out).unwrap() == expected, "{test}: render --merge (chunk {chunk}) differs");
        // `strahl merge` takes them in any order.
        let merged = dir.join(format!("merged-{chunk}.png"));
        let mut args = vec!["merge", "-q"];
        args.extend(parts.iter().rev().map(String::as_str));
        let m = s(&merged);
        args.extend(["-o", &m]);
        ok(&args);
        assert!(std::fs::read(&merged).unwrap() == expected, "{test}: strahl merge (chunk {chunk}) differs");
    }
}

#[test]
fn still_bands_merge_into_the_one_machine_render_at_every_aa() {
    // 61×45: the last strip and the last block column are cut short.
    for aa in ["1", "2", "3"] {
        bands_merge_to_the_whole(&format!("aa{aa}"), &scene("seed.pov"), 3, &["-W", "61", "-H", "45", "--aa", aa]);
    }
}

#[test]
fn still_bands_merge_for_focal_blur_and_reduced_resolution() {
    let blur = ["-W", "40", "-H", "30", "--aa", "2", "--max-blur-samples", "8"];
    bands_merge_to_the_whole("focal_blur", &scene("focal_blur.pov"), 4, &blur);
    bands_merge_to_the_whole("res_scale", &scene("seed.pov"), 3, &["-W", "64", "-H", "48", "--res-scale", "0.6"]);
    bands_merge_to_the_whole("no_packets", &scene("seed.pov"), 2, &["-W", "33", "-H", "20", "--no-packets"]);
}

#[test]
fn shard_syntax_and_environment_errors_exit_2_and_write_nothing() {
    let dir = scratch("shard_errors");
    let out = s(&dir.join("x.png"));
    let seed = scene("seed.pov");
    let base = ["render", seed.as_str(), "-W", "16", "-H", "16", "-o", out.as_str()];
    for (bad, why) in
        [("4/4", "index must be below 4"), ("1", "is not a shard"), ("a/b", "is not a shard"), ("0/0", "out of range")]
    {
        let err = fails(&[&base[..], &["--shard", bad]].concat(), &[]);
        assert!(err.contains(why), "--shard {bad}: {err}");
    }
    let err = fails(&[&base[..], &["--shard", "auto"]].concat(), &[]);
    assert!(err.contains("no scheduler's array index is set"), "{err}");
    let err = fails(&[&base[..], &["--shard", "auto"]].concat(), &[("JOB_COMPLETION_INDEX", "1")]);
    assert!(err.contains("write --shard auto/N"), "{err}");
    let err = fails(&[&base[..], &["--shard", "auto"]].concat(), &[("SLURM_ARRAY_TASK_ID", "x")]);
    assert!(err.contains("SLURM_ARRAY_TASK_ID=x"), "{err}");
    // 16 rows are 2 strips of 8: a third shard would get nothing.
    let err = fails(&[&base[..], &["--shard", "2/3"]].concat(), &[]);
    assert!(err.contains("gets no rows") && err.contains("at most 2 shards"), "{err}");
    let err = fails(&[&base[..], &["--merge"]].concat(), &[]);
    assert!(err.contains("no parts beside"), "{err}");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0, "a failed command left files behind");
}

#[test]
fn mismatched_parts_are_refused_and_nothing_is_written() {
    let dir = scratch("mismatched");
    let seed = scene("seed.pov");
    let part = |name: &str, shard: &str, extra: &[&str]| {
        let out = s(&dir.join(name));
        ok(&[&["render", seed.as_str(), "-q", "-W", "24", "-H", "16", "-o", out.as_str(), "--shard", shard], extra]
            .concat());
    };
    part("a.png", "0/2", &[]);
    part("a.png", "1/2", &[]);
    part("b.png", "1/2", &["--aa", "2"]);
    part("c.png", "1/3", &[]);
    let (a0, a1) = (s(&dir.join("a.shard-0-of-2.png")), s(&dir.join("a.shard-1-of-2.png")));
    let (b1, c1) = (s(&dir.join("b.shard-1-of-2.png")), s(&dir.join("c.shard-1-of-3.png")));
    let out = s(&dir.join("out.png"));
    assert!(fails(&["merge", &a0, &b1, "-o", &out], &[]).contains("another render"));
    assert!(fails(&["merge", &a0, &c1, "-o", &out], &[]).contains("a part of 3 shards"));
    assert!(fails(&["merge", &a0, "-o", &out], &[]).contains("shard 1 of 2 is missing"));
    assert!(fails(&["merge", &a0, &a0, "-o", &out], &[]).contains("are both shard 0/2"));
    // A part damaged after it was written (a byte of its compressed pixels flipped).
    let bad = dir.join("bad.shard-1-of-2.png");
    let mut damaged = std::fs::read(&a1).unwrap();
    let at = damaged.len() - 20;
    damaged[at] ^= 0xff;
    std::fs::write(&bad, &damaged).unwrap();
    let err = fails(&["merge", &a0, &s(&bad), "-o", &out], &[]);
    assert!(err.contains("bad.shard-1-of-2.png"), "{err}");
    // `render --merge` with other settings than the parts'.
    let a = s(&dir.join("a.png"));
    let err = fails(&["render", &seed, "-W", "24", "-H", "16", "--aa", "3", "-o", &a, "--merge"], &[]);
    assert!(err.contains("this command line") && err.contains("settings"), "{err}");
    assert!(!dir.join("out.png").exists() && !dir.join("a.png").exists(), "a refused merge wrote its output");
    ok(&["merge", &a1, &a0, "-o", &out]);
}

fn capture(dir: &Path, extra: &[&str], env: &[(&str, &str)]) -> Output {
    let (seed, orbit) = (scene("seed.pov"), scene("seed.orbit.path"));
    let d = s(dir);
    let args =
        [&["capture", seed.as_str(), "--path", &orbit, "--frames", "7", "-W", "24", "-H", "18", "-o", &d], extra]
            .concat();
    let out = run(&args, env);
    assert!(out.status.success(), "strahl {args:?} failed:\n{}", String::from_utf8_lossy(&out.stderr));
    out
}

#[test]
fn capture_shards_deal_frames_and_resume() {
    let dir = scratch("capture_shards");
    let whole = dir.join("whole");
    capture(&whole, &["-q"], &[]);
    let whole_m = Manifest::read(&whole).unwrap();
    for (chunk, expect) in [(false, vec![1, 4]), (true, vec![2, 3])] {
        let mut parts = Vec::new();
        for i in 0..3 {
            let part = dir.join(format!("part-{chunk}-{i}"));
            let shard = format!("{i}/3");
            let mut extra = vec!["-q", "--shard", &shard];
            if chunk {
                extra.push("--chunk");
            }
            capture(&part, &extra, &[]);
            parts.push(s(&part));
        }
        let listed: Vec<u32> = Manifest::read(Path::new(&parts[1])).unwrap().frames.iter().map(|f| f.index).collect();
        assert_eq!(listed, expect, "shard 1/3 (chunk {chunk})");
        let merged = dir.join(format!("merged-{chunk}"));
        let mut args = vec!["capture", "--merge"];
        args.extend(parts.iter().map(String::as_str));
        let m = s(&merged);
        args.extend(["-o", &m]);
        ok(&args);
        assert!(Manifest::read(&merged).unwrap().same_content(&whole_m), "merged shards (chunk {chunk}) differ");
    }
    // `--shard auto` from Slurm's variables, then a "killed" run: one frame's file damaged and
    // one frame dropped from the manifest; the rerun renders those two and keeps the rest.
    let slurm = [("SLURM_ARRAY_TASK_ID", "0"), ("SLURM_ARRAY_TASK_COUNT", "2"), ("SLURM_ARRAY_TASK_MIN", "0")];
    let part = dir.join("auto-0");
    let first = capture(&part, &["--shard", "auto"], &slurm);
    let said = String::from_utf8_lossy(&first.stdout).into_owned();
    assert!(said.contains("shard 0/2 (Slurm: SLURM_ARRAY_TASK_ID=0") && !said.contains("resuming"), "{said}");
    let mut m = Manifest::read(&part).unwrap();
    assert_eq!(m.frames.iter().map(|f| f.index).collect::<Vec<_>>(), vec![0, 2, 4, 6]);
    std::fs::write(part.join("frame_0002.png"), b"cut short").unwrap();
    m.frames.retain(|f| f.index != 6);
    std::fs::write(part.join("manifest.json"), m.to_json().to_pretty()).unwrap();
    std::fs::write(part.join(".frame_0006.png.999.tmp"), b"left by a kill").unwrap();
    let again = capture(&part, &["--shard", "auto"], &slurm);
    let said = String::from_utf8_lossy(&again.stdout).into_owned();
    assert!(said.contains("resuming: 2 already done, 2 to render"), "{said}");
    assert!(!part.join(".frame_0006.png.999.tmp").exists(), "the stale temporary was not removed");
    let resumed = Manifest::read(&part).unwrap();
    let expected: Vec<_> = whole_m.frames.iter().filter(|f| f.index % 2 == 0).cloned().collect();
    assert_eq!(resumed.frames.len(), 4);
    for (a, b) in resumed.frames.iter().zip(&expected) {
        assert!(a.same_content(b), "frame {} after resuming differs", a.index);
    }
    let other = dir.join("auto-1");
    capture(&other, &["-q", "--shard", "auto"], &[("SLURM_ARRAY_TASK_ID", "1"), ("SLURM_ARRAY_TASK_COUNT", "2")]);
    let merged = dir.join("merged-auto");
    ok(&["capture", "--merge", &s(&part), &s(&other), "-o", &s(&merged)]);
    assert!(Manifest::read(&merged).unwrap().same_content(&whole_m), "resumed shards differ from one run");
}

/// The job script's two roles run by hand, as Slurm would run them: four array tasks, then
/// the merge; the result must be the one-machine render.
#[test]
fn farm_script_runs_its_tasks_and_merge_like_slurm_does() {
    let dir = scratch("farm_script");
    let seed = scene("seed.pov");
    let farm = dir.join("job");
    let opts = ["-W", "40", "-H", "32", "--aa", "2"];
    let out =
        ok(&[&["farm", "slurm", seed.as_str(), "-o", &s(&farm), "--tasks", "4", "--cpus-per-task", "2"], &opts[..]]
            .concat());
    assert!(String::from_utf8_lossy(&out.stdout).contains("strahl.sbatch"));
    let script = farm.join("strahl.sbatch");
    let text = std::fs::read_to_string(&script).unwrap();
    for line in ["#SBATCH --array=0-3", "#SBATCH --cpus-per-task=2", "#SBATCH --requeue"] {
        assert!(text.contains(line), "{line} missing:\n{text}");
    }
    assert!(text.contains(&format!("#SBATCH --output={}/logs/%x_%A_%a.out", s(&farm))), "{text}");
    let bash = |env: &[(&str, &str)]| {
        let mut c = Command::new("bash");
        for v in SCHEDULER_VARS {
            c.env_remove(v);
        }
        let out = c.arg(&script).envs(env.iter().copied()).output().unwrap();
        assert!(
            out.status.success(),
            "{env:?}: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    };
    for i in ["0", "1", "2", "3"] {
        bash(&[
            ("SLURM_JOB_ID", "7"),
            ("SLURM_ARRAY_TASK_ID", i),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
            ("SLURM_ARRAY_TASK_MIN", "0"),
            ("SLURM_CPUS_PER_TASK", "2"),
        ]);
    }
    bash(&[("SLURM_JOB_ID", "8"), ("SLURM_ARRAY_TASK_ID", "0"), ("STRAHL_FARM_STEP", "merge")]);
    let whole = dir.join("whole.png");
    ok(&[&["render", seed.as_str(), "-q", "-o", &s(&whole)], &opts[..]].concat());
    assert!(
        std::fs::read(farm.join("seed.png")).unwrap() == std::fs::read(&whole).unwrap(),
        "the farm's still differs"
    );
    // More tasks than strips, and --threads, are refused before anything is written.
    let none = dir.join("none");
    let err = fails(&["farm", "slurm", &seed, "-W", "40", "-H", "32", "-o", &s(&none), "--tasks", "5"], &[]);
    assert!(err.contains("more than the image's 4 strips"), "{err}");
    assert!(!none.exists());
}
