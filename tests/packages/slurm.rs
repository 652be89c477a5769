//! `strahl farm slurm` on a real Slurm: a one-node cluster on localhost (Debian's slurmctld,
//! slurmd, slurm-client and munge), started as root in a temporary folder, runs the generated
//! script for a 24-frame capture in 4 tasks and a still in 4 bands; the merged frames and the
//! still must be byte for byte the one-machine renders. Then one task is killed in the middle
//! (`scontrol requeue`) and must resume from the frames it finished, with the same result.
//!
//! `#[ignore]`d without the packages; `.ci/run` installs them and runs it with `--ignored`,
//! where a missing package is a failure, never a pass. The cluster is a guard: it is shut down
//! (jobs cancelled, `scontrol shutdown`, then the daemons killed by their pid files' ids) however
//! the test ends, and on failure the daemons' logs and the jobs' logs are printed.

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use strahl::headless::manifest::Manifest;

const BIN: &str = env!("CARGO_BIN_EXE_strahl");
const NEEDS_SLURM: &str =
    "needs Debian's slurmctld, slurmd, slurm-client and munge, run as root: .ci/run runs it with --ignored";

/// Frames and tasks of the farmed capture; the still's bands.
const FRAMES: u32 = 24;
const TASKS: u32 = 4;
const SIZE: [&str; 4] = ["-W", "64", "-H", "48"];

/// Generous limits: CI machines are slow and shared.
const START_LIMIT: Duration = Duration::from_secs(90);
const JOB_LIMIT: Duration = Duration::from_secs(400);

fn scenes(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name).display().to_string()
}

/// Where `program` is: on PATH, or in /usr/sbin (where Debian puts the daemons, and which a
/// non-login shell's PATH may lack).
fn find(program: &str) -> Option<PathBuf> {
    let paths = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&paths)
        .chain([PathBuf::from("/usr/sbin"), PathBuf::from("/usr/bin")])
        .map(|d| d.join(program))
        .find(|p| p.is_file())
}

fn on_path(program: &str) -> bool {
    find(program).is_some()
}

fn text(out: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

/// Two distinct free TCP ports now, for slurmctld and slurmd: both listeners are held until
/// both are known, so the two differ, then dropped (a port taken in between makes a daemon fail
/// to start, which the start-up check reports with its log).
fn free_ports() -> (u16, u16) {
    let bind = || TcpListener::bind("0.0.0.0:0").unwrap_or_else(|e| panic!("cannot find a free port: {e}"));
    let (a, b) = (bind(), bind());
    (a.local_addr().unwrap().port(), b.local_addr().unwrap().port())
}

/// A one-node Slurm cluster in its own folder, on ports of its own.
struct Cluster {
    dir: PathBuf,
    conf: PathBuf,
    started: Duration,
    /// Set once everything passed: the folder is removed on drop; kept for inspection otherwise.
    passed: bool,
}

impl Cluster {
    fn start(dir: &Path) -> Cluster {
        for p in ["slurmctld", "slurmd", "sbatch", "scontrol", "squeue", "sinfo", "munge", "unmunge"] {
            assert!(on_path(p), "{p} is missing: install slurmctld slurmd slurm-client munge; this test {NEEDS_SLURM}");
        }
        let uid = Command::new("id").arg("-u").output().map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
        assert_eq!(uid.as_deref().ok(), Some("0"), "slurmd must run as root to start jobs; this test {NEEDS_SLURM}");
        ensure_munge();
        let t0 = Instant::now();
        std::fs::create_dir_all(dir.join("state")).unwrap();
        std::fs::create_dir_all(dir.join("spool")).unwrap();
        let cpus = std::thread::available_parallelism().map_or(1, |n| n.get()).clamp(1, 4);
        let (ctld_port, d_port) = free_ports();
        let d = dir.display();
        let conf = dir.join("slurm.conf");
        let text = format!(
            "ClusterName=strahltest\n\
             SlurmctldHost=localhost\n\
             SlurmctldPort={ctld_port}\n\
             SlurmdPort={d_port}\n\
             SlurmUser=root\n\
             SlurmdUser=root\n\
             AuthType=auth/munge\n\
             ProctrackType=proctrack/linuxproc\n\
             TaskPlugin=task/none\n\
             SelectType=select/cons_tres\n\
             SelectTypeParameters=CR_CPU\n\
             SlurmdParameters=config_overrides\n\
             StateSaveLocation={d}/state\n\
             SlurmdSpoolDir={d}/spool\n\
             SlurmctldPidFile={d}/slurmctld.pid\n\
             SlurmdPidFile={d}/slurmd.pid\n\
             SlurmctldLogFile={d}/slurmctld.log\n\
             SlurmdLogFile={d}/slurmd.log\n\
             MailProg=/bin/true\n\
             MpiDefault=none\n\
             ReturnToService=2\n\
             MinJobAge=3600\n\
             NodeName=localhost NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN\n\
             PartitionName=farm Nodes=localhost Default=YES MaxTime=INFINITE State=UP\n"
        );
        std::fs::write(&conf, text).unwrap();
        let mut cluster = Cluster { dir: dir.to_path_buf(), conf, started: Duration::ZERO, passed: false };
        let conf_arg = cluster.conf.display().to_string();
        let ctld = cluster.run("slurmctld", &["-c", "-f", &conf_arg]);
        assert!(ctld.status.success(), "slurmctld would not start: {}\n{}", text_of(&ctld), cluster.diagnostics());
        let slurmd = cluster.run("slurmd", &["-c", "-f", &conf_arg, "-N", "localhost"]);
        assert!(slurmd.status.success(), "slurmd would not start: {}\n{}", text_of(&slurmd), cluster.diagnostics());
        let mut state = String::new();
        while t0.elapsed() < START_LIMIT {
            state = cluster.stdout("sinfo", &["-h", "-o", "%T"]);
            if state.trim() == "idle" {
                cluster.started = t0.elapsed();
                return cluster;
            }
            std::thread::sleep(Duration::from_millis(200));
        }
        panic!("the node is `{}`, not idle, {START_LIMIT:?} after start\n{}", state.trim(), cluster.diagnostics());
    }

    /// A Slurm command run against this cluster.
    fn command(&self, program: &str) -> Command {
        let mut c = Command::new(find(program).unwrap_or_else(|| PathBuf::from(program)));
        c.env("SLURM_CONF", &self.conf);
        c
    }

    fn run(&self, program: &str, args: &[&str]) -> Output {
        self.command(program).args(args).output().unwrap_or_else(|e| panic!("cannot run {program}: {e}"))
    }

    fn stdout(&self, program: &str, args: &[&str]) -> String {
        String::from_utf8_lossy(&self.run(program, args).stdout).into_owned()
    }

    /// The daemons' logs, the queue and every job log under `jobs`, for a failure message.
    fn diagnostics(&self) -> String {
        let mut s = String::new();
        for name in ["slurmctld.log", "slurmd.log"] {
            let log = std::fs::read_to_string(self.dir.join(name)).unwrap_or_default();
            let tail: Vec<&str> = log.lines().rev().take(60).collect();
            s += &format!("--- {name} (last 60 lines) ---\n");
            for l in tail.iter().rev() {
                s += l;
                s.push('\n');
            }
        }
        s += &format!("--- squeue ---\n{}", self.stdout("squeue", &[]));
        s += &format!("--- sinfo ---\n{}", self.stdout("sinfo", &[]));
        s
    }

    /// `JobState=` of every record `scontrol show job ID` prints (one per array task).
    fn states(&self, id: &str) -> (Vec<String>, String) {
        let shown = self.stdout("scontrol", &["show", "job", id]);
        let states = shown.split_whitespace().filter_map(|w| w.strip_prefix("JobState=")).map(str::to_string).collect();
        (states, shown)
    }

    /// Waits until job `id` completed; panics with the logs if it failed or never ran.
    fn wait(&self, id: &str, what: &str, logs: &Path) -> Duration {
        let start = Instant::now();
        loop {
            let (states, shown) = self.states(id);
            if !states.is_empty() && states.iter().all(|s| s == "COMPLETED") {
                return start.elapsed();
            }
            let bad = states.iter().any(|s| {
                ["FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY", "BOOT_FAIL", "DEADLINE"]
                    .contains(&s.as_str())
            }) || shown.contains("DependencyNeverSatisfied");
            if bad || start.elapsed() > JOB_LIMIT {
                panic!(
                    "{what} (job {id}) did not complete within {JOB_LIMIT:?}: states {states:?}\n{shown}\n{}\n{}",
                    job_logs(logs),
                    self.diagnostics()
                );
            }
            std::thread::sleep(Duration::from_millis(250));
        }
    }
}

fn text_of(o: &Output) -> String {
    text(o)
}

/// Every log in `dir`, for a failure message.
fn job_logs(dir: &Path) -> String {
    let mut s = String::new();
    let mut files: Vec<PathBuf> =
        std::fs::read_dir(dir).map(|d| d.filter_map(|e| e.ok()).map(|e| e.path()).collect()).unwrap_or_default();
    files.sort();
    for f in files {
        s += &format!("--- {} ---\n{}", f.display(), std::fs::read_to_string(&f).unwrap_or_default());
    }
    s
}

impl Drop for Cluster {
    fn drop(&mut self) {
        // Jobs first (this cluster's queue holds only this test's), so no render outlives it.
        let ids = self.stdout("squeue", &["-h", "-o", "%A"]);
        let ids: Vec<&str> = ids.split_whitespace().collect();
        if !ids.is_empty() {
            let _ = self.command("scancel").args(&ids).output();
        }
        let _ = self.run("scontrol", &["shutdown"]);
        // The daemons by the ids in their own pid files: never anything else of the machine's.
        let pids: Vec<String> = ["slurmd.pid", "slurmctld.pid"]
            .iter()
            .filter_map(|f| std::fs::read_to_string(self.dir.join(f)).ok())
            .map(|p| p.trim().to_string())
            .filter(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_digit()))
            .collect();
        let alive = |p: &String| Path::new("/proc").join(p).exists();
        let start = Instant::now();
        while pids.iter().any(alive) && start.elapsed() < Duration::from_secs(20) {
            std::thread::sleep(Duration::from_millis(200));
        }
        for p in pids.iter().filter(|p| alive(p)) {
            eprintln!("slurm daemon {p} still running 20 s after `scontrol shutdown`: killing it");
            let _ = Command::new("kill").args(["-9", p]).output();
        }
        if self.passed {
            let _ = std::fs::remove_dir_all(&self.dir);
        } else {
            eprintln!("kept the cluster's folder for inspection: {}", self.dir.display());
        }
    }
}

/// munged up: started with Debian's init script where it is not answering. It is the
/// machine's daemon, not the cluster's, so it is left running.
fn ensure_munge() {
    let works =
        || Command::new("sh").args(["-c", "munge -n | unmunge >/dev/null"]).output().is_ok_and(|o| o.status.success());
    if works() {
        return;
    }
    let started = Command::new("/etc/init.d/munge").arg("start").output();
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(20) {
        if works() {
            return;
        }
        std::thread::sleep(Duration::from_millis(200));
    }
    panic!("munge does not answer, and `/etc/init.d/munge start` gave {:?}", started.as_ref().map(text));
}

fn strahl(args: &[&str], env: &[(&str, &str)], cluster: &Cluster) -> Output {
    let mut c = cluster.command(BIN);
    c.args(args);
    for (k, v) in env {
        c.env(k, v);
    }
    let out = c.output().unwrap_or_else(|e| panic!("cannot run strahl: {e}"));
    assert!(out.status.success(), "strahl {args:?} failed:\n{}", text(&out));
    out
}

/// How a test submits the generated script.
#[derive(Clone, Copy, PartialEq)]
enum Submit {
    /// `strahl farm slurm ... --submit`.
    Strahl,
    /// `strahl farm slurm ...`, then `bash DIR/strahl.sbatch`, as a user submits it later.
    Script,
}

/// Writes the job script for `args` (which hold `-o DIR`) and submits it `how`; returns the
/// array's and the merge's job ids, which both ways print alike.
fn submit(cluster: &Cluster, args: &[&str], env: &[(&str, &str)], how: Submit) -> (String, String) {
    let mut all = vec!["farm", "slurm"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--tasks", "4", "--cpus-per-task", "1"]);
    if how == Submit::Strahl {
        all.push("--submit");
    }
    let mut out = text(&strahl(&all, env, cluster));
    if how == Submit::Script {
        let dir = args.iter().position(|a| *a == "-o").map(|i| args[i + 1]).expect("-o DIR");
        let mut c = cluster.command("bash");
        c.arg(Path::new(dir).join("strahl.sbatch")).envs(env.iter().copied());
        let o = c.output().unwrap_or_else(|e| panic!("cannot run bash: {e}"));
        assert!(o.status.success(), "bash {dir}/strahl.sbatch failed:\n{}", text(&o));
        out = text(&o);
    }
    let id = |prefix: &str| {
        out.lines()
            .find_map(|l| l.strip_prefix(prefix))
            .and_then(|r| r.split_whitespace().next())
            .map(str::to_string)
            .unwrap_or_else(|| panic!("no `{prefix}ID` in the output of the submission:\n{out}"))
    };
    (id("array job "), id("merge job "))
}

/// The frames of a capture folder, by file name.
fn frames(dir: &Path) -> Vec<(String, Vec<u8>)> {
    (0..FRAMES)
        .map(|i| {
            let name = format!("frame_{i:04}.png");
            let bytes = std::fs::read(dir.join(&name)).unwrap_or_else(|e| panic!("{}: {e}", dir.join(&name).display()));
            (name, bytes)
        })
        .collect()
}

/// Frames of the merged capture in `farm` equal the one-machine capture's, byte for byte, and
/// so do the manifests but for timing. Returns the bytes compared.
fn assert_same_capture(reference: &Path, farm: &Path) -> usize {
    let (a, b) = (frames(reference), frames(&farm.join("frames")));
    for ((name, x), (_, y)) in a.iter().zip(&b) {
        assert!(x == y, "{name} of the farmed capture differs from the one-machine capture's");
    }
    let (ma, mb) = (Manifest::read(reference).unwrap(), Manifest::read(&farm.join("frames")).unwrap());
    // The farm's scene and path are absolute; the rest must agree.
    let mb = Manifest { scene: ma.scene.clone(), path: ma.path.clone(), ..mb };
    assert!(ma.same_content(&mb), "the merged manifest differs from the one-machine capture's");
    a.iter().map(|(_, x)| x.len()).sum()
}

#[test]
#[ignore = "needs Debian's slurmctld, slurmd, slurm-client and munge, run as root: .ci/run runs it with --ignored"]
fn farm_on_a_one_node_slurm_cluster() {
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.subsec_nanos());
    let work = std::env::temp_dir().join(format!("strahl-slurm-{}-{nanos}", std::process::id()));
    let mut cluster = Cluster::start(&work.join("cluster"));
    let (seed, orbit) = (scenes("seed.pov"), scenes("seed.orbit.path"));
    let w = |p: &str| work.join(p).display().to_string();

    // One machine: the reference capture and still.
    let mut capture = vec!["capture", seed.as_str(), "--path", orbit.as_str(), "--frames", "24", "-q"];
    capture.extend_from_slice(&SIZE);
    let reference = w("reference-frames");
    strahl(&[capture.as_slice(), &["-o", &reference]].concat(), &[], &cluster);
    let still_opts = ["--aa", "2"];
    let reference_still = w("reference.png");
    strahl(&[&["render", seed.as_str(), "-q", "-o", &reference_still], &SIZE[..], &still_opts].concat(), &[], &cluster);

    // The capture in 4 array tasks (submitted by `--submit`), then the still in 4 bands
    // (submitted by running the script, as a user would later).
    let t = Instant::now();
    let cap_dir = w("capture");
    let farm_capture = [&[seed.as_str(), "--path", &orbit, "--frames", "24", "-o", &cap_dir], &SIZE[..]].concat();
    let (array, merge) = submit(&cluster, &farm_capture, &[], Submit::Strahl);
    let logs = work.join("capture/logs");
    cluster.wait(&array, "the capture's shards", &logs);
    let shards_done = t.elapsed();
    cluster.wait(&merge, "the capture's merge", &logs);
    let capture_done = t.elapsed();
    let capture_bytes = assert_same_capture(Path::new(&reference), Path::new(&cap_dir));

    let t = Instant::now();
    let still_dir = w("still");
    let farm_still = [&[seed.as_str(), "-o", still_dir.as_str()], &SIZE[..], &still_opts].concat();
    let (still_array, still_merge) = submit(&cluster, &farm_still, &[], Submit::Script);
    let still_logs = work.join("still/logs");
    cluster.wait(&still_array, "the still's bands", &still_logs);
    cluster.wait(&still_merge, "the still's merge", &still_logs);
    let still_done = t.elapsed();
    let (a, b) = (std::fs::read(&reference_still).unwrap(), std::fs::read(work.join("still/seed.png")).unwrap());
    assert!(a == b, "the farmed still differs from the one-machine render ({} vs {} bytes)", a.len(), b.len());
    for i in 0..TASKS {
        assert!(work.join(format!("still/parts/seed.shard-{i}-of-4.png")).is_file(), "part {i} is missing");
    }

    // Kill task 1 in the middle (frames slowed to 500 ms each so it can be caught there),
    // requeue it, and let it run again at once (a requeued job waits two minutes otherwise).
    let t = Instant::now();
    let re_dir = w("requeue");
    let farm_again = [&[seed.as_str(), "--path", &orbit, "--frames", "24", "-o", &re_dir], &SIZE[..]].concat();
    let (re_array, re_merge) = submit(&cluster, &farm_again, &[("STRAHL_FRAME_DELAY_MS", "500")], Submit::Strahl);
    let re_logs = work.join("requeue/logs");
    let shard1 = work.join("requeue/parts/1");
    let listed = |dir: &Path| Manifest::read(dir).map_or(0, |m| m.frames.len());
    let wait_start = Instant::now();
    while listed(&shard1) < 2 {
        assert!(
            wait_start.elapsed() < JOB_LIMIT,
            "task 1 never finished 2 frames\n{}\n{}",
            job_logs(&re_logs),
            cluster.diagnostics()
        );
        std::thread::sleep(Duration::from_millis(50));
    }
    let task = format!("{re_array}_1");
    let requeue = cluster.run("scontrol", &["requeue", &task]);
    let killed_after = listed(&shard1);
    assert!(requeue.status.success(), "scontrol requeue {task}: {}\n{}", text(&requeue), cluster.diagnostics());
    assert!(killed_after < (FRAMES / TASKS) as usize, "task 1 finished before it could be killed");
    // The requeued task passes through COMPLETING before it is PENDING on its begin time; the
    // begin time is set then, so it is moved to now only once the task waits on it.
    let release = Instant::now();
    loop {
        let shown = cluster.stdout("scontrol", &["show", "job", &task]);
        if shown.contains("JobState=RUNNING") || shown.contains("JobState=COMPLETED") {
            break;
        }
        if shown.contains("JobState=PENDING") && shown.contains("Reason=BeginTime") {
            let _ = cluster.run("scontrol", &["update", &format!("jobid={task}"), "StartTime=now"]);
        }
        assert!(
            release.elapsed() < Duration::from_secs(90),
            "{task} did not start again within 90 s of its requeue:\n{shown}\n{}",
            cluster.diagnostics()
        );
        std::thread::sleep(Duration::from_millis(250));
    }
    let restarted_after = release.elapsed();
    cluster.wait(&re_array, "the requeued capture's shards", &re_logs);
    cluster.wait(&re_merge, "the requeued capture's merge", &re_logs);
    let requeue_done = t.elapsed();
    let log = std::fs::read_to_string(re_logs.join(format!("strahl-seed_{re_array}_1.out"))).unwrap_or_default();
    let resumed = log
        .lines()
        .find_map(|l| l.split("resuming: ").nth(1))
        .and_then(|r| r.split_whitespace().next())
        .and_then(|n| n.parse::<usize>().ok())
        .unwrap_or_else(|| panic!("task 1's log shows no resumed run:\n{log}"));
    assert!(resumed >= 2 && resumed < 6, "task 1 resumed with {resumed} frames done, expected 2 to 5:\n{log}");
    assert!(log.contains("restart 1"), "task 1 was not restarted:\n{log}");
    let requeue_bytes = assert_same_capture(Path::new(&reference), Path::new(&re_dir));

    // The merges alone, timed here (the same commands the merge jobs ran).
    let t = Instant::now();
    let parts: Vec<String> = (0..TASKS).map(|i| w(&format!("capture/parts/{i}"))).collect();
    let mut merge_args = vec!["capture", "--merge"];
    merge_args.extend(parts.iter().map(String::as_str));
    let remerged = w("remerged");
    merge_args.extend(["-o", remerged.as_str()]);
    strahl(&merge_args, &[], &cluster);
    let capture_merge = t.elapsed();
    let t = Instant::now();
    let still_parts: Vec<String> = (0..TASKS).map(|i| w(&format!("still/parts/seed.shard-{i}-of-4.png"))).collect();
    let mut still_merge_args = vec!["merge"];
    still_merge_args.extend(still_parts.iter().map(String::as_str));
    let remerged_still = w("remerged.png");
    still_merge_args.extend(["-o", remerged_still.as_str()]);
    strahl(&still_merge_args, &[], &cluster);
    let still_merge_time = t.elapsed();
    assert!(std::fs::read(&remerged_still).unwrap() == a, "the still merged again differs");

    eprintln!(
        "slurm farm: cluster up (node idle) in {:.2} s; capture {FRAMES} frames 64x48 in {TASKS} tasks: shards done \
         {:.1} s, merged {:.1} s after submission, {capture_bytes} bytes of {FRAMES} PNGs identical; still 64x48 aa 2 in \
         {TASKS} bands: {:.1} s submission to merged, {} bytes identical; requeue of task 1 after {killed_after} of 6 \
         frames: running again {:.1} s later, resumed with {resumed} done, all done {:.1} s after submission, \
         {requeue_bytes} bytes identical; \
         merge alone: capture {:.0} ms, still {:.0} ms",
        cluster.started.as_secs_f64(),
        shards_done.as_secs_f64(),
        capture_done.as_secs_f64(),
        still_done.as_secs_f64(),
        a.len(),
        restarted_after.as_secs_f64(),
        requeue_done.as_secs_f64(),
        capture_merge.as_secs_f64() * 1e3,
        still_merge_time.as_secs_f64() * 1e3,
    );
    cluster.passed = true;
    drop(cluster);
    let _ = std::fs::remove_dir_all(&work);
}
