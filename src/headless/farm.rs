//! `strahl farm slurm`: a Slurm job script for a sharded capture or still, and its submission.
//!
//! HPC centres render animations as Slurm job arrays: the same command N times, each task told
//! its index in `SLURM_ARRAY_TASK_ID`. The script runs `--shard auto` in every array task and,
//! as a second job that Slurm starts only once every task succeeded (`--dependency=afterok`),
//! the merge. One file holds both roles (the merge job is submitted with `STRAHL_FARM_STEP=merge`)
//! so the shards and the merge cannot drift apart; run outside a job (`bash strahl.sbatch`) it
//! submits both, as `--submit` does from here.
//!
//! Tasks are marked `--requeue` and logs opened in append mode: a task that a node failure or
//! `scontrol requeue` kills comes back, resumes from the frames it finished (`capture --shard`
//! skips them), and its log keeps both attempts.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::headless::{output, CliError};

/// What the array tasks render.
#[derive(Clone, Debug, PartialEq)]
pub enum Work {
    /// `strahl capture` with these arguments (scene, path, frames and render options; not `-o`
    /// or `--shard`), one folder of frames per shard, merged into `DIR/frames`.
    Capture { args: Vec<String> },
    /// `strahl render` with these arguments, parts in `DIR/parts`, merged into `DIR/NAME.png`.
    Still { args: Vec<String>, name: String },
}

/// A farm job: the work, how many tasks, and what Slurm should give each.
#[derive(Clone, Debug, PartialEq)]
pub struct SlurmJob {
    /// The strahl executable the tasks run (absolute: tasks start in another folder).
    pub strahl: PathBuf,
    /// The output folder (absolute).
    pub dir: PathBuf,
    /// Slurm's job name (`%x` in log names); the merge job is NAME-merge.
    pub name: String,
    pub tasks: u32,
    pub cpus_per_task: u32,
    /// `--time` for each task, in Slurm's syntax.
    pub time: Option<String>,
    pub partition: Option<String>,
    /// More `#SBATCH` options, verbatim (`--account=proj`, `--mem=4G`).
    pub extra: Vec<String>,
    /// `--chunk`: contiguous frames or rows per shard instead of interleaved ones.
    pub chunk: bool,
    pub work: Work,
}

/// The script's file name in the output folder.
pub const SCRIPT: &str = "strahl.sbatch";

/// `s` as one word for bash: single-quoted unless it is plainly safe.
pub fn quote(s: &str) -> String {
    let safe = !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || "-_./=:,+@%".contains(c));
    if safe {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

fn words(args: &[String]) -> String {
    args.iter().map(|a| quote(a)).collect::<Vec<_>>().join(" ")
}

impl SlurmJob {
    /// The command line of array task `$SLURM_ARRAY_TASK_ID`, as bash text.
    fn task_command(&self) -> String {
        let chunk = if self.chunk { " --chunk" } else { "" };
        match &self.work {
            Work::Capture { args } => format!(
                "\"$strahl\" capture {} --shard auto{chunk} --threads \"$threads\" -o \"$out/parts/$SLURM_ARRAY_TASK_ID\"",
                words(args)
            ),
            Work::Still { args, name } => format!(
                "\"$strahl\" render {} --shard auto{chunk} --threads \"$threads\" -o \"$out/parts/\"{}",
                words(args),
                quote(&format!("{name}.png"))
            ),
        }
    }

    /// The merge's command line, naming every part, so a stale part of another run is never
    /// picked up by a pattern.
    fn merge_command(&self) -> String {
        match &self.work {
            Work::Capture { .. } => {
                let dirs: Vec<String> = (0..self.tasks).map(|i| format!("\"$out/parts/{i}\"")).collect();
                format!("\"$strahl\" capture --merge {} -o \"$out/frames\"", dirs.join(" "))
            }
            Work::Still { name, .. } => {
                let parts: Vec<String> = (0..self.tasks)
                    .map(|i| format!("\"$out/parts/\"{}", quote(&format!("{name}.shard-{i}-of-{}.png", self.tasks))))
                    .collect();
                format!("\"$strahl\" merge {} -o \"$out/\"{}", parts.join(" "), quote(&format!("{name}.png")))
            }
        }
    }

    /// Where the merged result lands.
    pub fn result(&self) -> PathBuf {
        match &self.work {
            Work::Capture { .. } => self.dir.join("frames"),
            Work::Still { name, .. } => self.dir.join(format!("{name}.png")),
        }
    }

    /// The text of `DIR/strahl.sbatch`.
    pub fn script(&self) -> String {
        let dir = self.dir.display().to_string();
        let logs = format!("{dir}/logs/%x_%A_%a.out");
        let mut s = String::new();
        let what = match self.work {
            Work::Capture { .. } => "capture",
            Work::Still { .. } => "still",
        };
        let _ = writeln!(s, "#!/bin/bash");
        let _ = writeln!(
            s,
            "# Written by `strahl farm slurm` (strahl {}): a {what} in {} shards.",
            env!("CARGO_PKG_VERSION"),
            self.tasks
        );
        let _ = writeln!(s, "#");
        let _ = writeln!(s, "# Submit the shards and the merge (which starts once every shard succeeded):");
        let _ = writeln!(s, "#   bash {}", quote(&format!("{dir}/{SCRIPT}")));
        let _ = writeln!(s, "# `sbatch` on this file alone submits only the shards; then merge with");
        let _ = writeln!(
            s,
            "#   sbatch --dependency=afterok:ARRAY_JOB_ID --array=0 --export=ALL,STRAHL_FARM_STEP=merge {SCRIPT}"
        );
        let _ = writeln!(s, "# A task that is requeued (node failure, `scontrol requeue`) resumes where it stopped.");
        let _ = writeln!(s, "# Logs: {dir}/logs/{}_<job>_<task>.out; result: {}", self.name, self.result().display());
        let _ = writeln!(s, "#SBATCH --job-name={}", self.name);
        let _ = writeln!(s, "#SBATCH --array=0-{}", self.tasks - 1);
        let _ = writeln!(s, "#SBATCH --cpus-per-task={}", self.cpus_per_task);
        let _ = writeln!(s, "#SBATCH --ntasks=1");
        let _ = writeln!(s, "#SBATCH --output={logs}");
        let _ = writeln!(s, "#SBATCH --open-mode=append");
        let _ = writeln!(s, "#SBATCH --requeue");
        if let Some(t) = &self.time {
            let _ = writeln!(s, "#SBATCH --time={t}");
        }
        if let Some(p) = &self.partition {
            let _ = writeln!(s, "#SBATCH --partition={p}");
        }
        for e in &self.extra {
            let _ = writeln!(s, "#SBATCH {e}");
        }
        let _ = writeln!(s, "set -euo pipefail");
        let _ = writeln!(s, "strahl={}", quote(&self.strahl.display().to_string()));
        let _ = writeln!(s, "out={}", quote(&dir));
        let _ = writeln!(s);
        let _ = writeln!(s, "if [ -z \"${{SLURM_JOB_ID:-}}\" ]; then");
        let _ = writeln!(s, "    # Not in a job: submit the array, then the merge that waits for all of it.");
        let _ = writeln!(s, "    array=$(sbatch --parsable \"$0\")");
        let _ = writeln!(s, "    array=${{array%%;*}}");
        let _ = writeln!(
            s,
            "    merge=$(sbatch --parsable --dependency=afterok:\"$array\" --array=0 --cpus-per-task=1 \\\n        {} --export=ALL,STRAHL_FARM_STEP=merge \"$0\")",
            quote(&format!("--job-name={}-merge", self.name))
        );
        let _ = writeln!(s, "    echo \"array job $array ({} shards), logs in $out/logs\"", self.tasks);
        let _ = writeln!(s, "    echo \"merge job ${{merge%%;*}} (afterok:$array)\"");
        let _ = writeln!(s, "    exit 0");
        let _ = writeln!(s, "fi");
        let _ = writeln!(s);
        let _ = writeln!(s, "echo \"$(date -u +%FT%TZ) job ${{SLURM_JOB_ID}} task ${{SLURM_ARRAY_TASK_ID:-}} on $(hostname) (restart ${{SLURM_RESTART_COUNT:-0}})\"");
        let _ = writeln!(s, "if [ \"${{STRAHL_FARM_STEP:-}}\" = merge ]; then");
        let _ = writeln!(s, "    {}", self.merge_command());
        let _ = writeln!(s, "    exit");
        let _ = writeln!(s, "fi");
        let _ = writeln!(s, "threads=${{SLURM_CPUS_PER_TASK:-0}}");
        let _ = writeln!(s, "mkdir -p \"$out/parts\"");
        let _ = writeln!(s, "{}", self.task_command());
        s
    }
}

/// Writes `DIR/strahl.sbatch` (and the `logs` folder Slurm needs before the first task starts)
/// and returns the script's path.
pub fn write(job: &SlurmJob) -> Result<PathBuf, CliError> {
    output::check_folder_writable("-o", &job.dir)?;
    output::create_dir(&job.dir.join("logs"))?;
    output::create_dir(&job.dir.join("parts"))?;
    let script = job.dir.join(SCRIPT);
    output::write_atomic(&script, job.script().as_bytes())?;
    set_executable(&script);
    Ok(script)
}

#[cfg(unix)]
fn set_executable(path: &Path) {
    use std::os::unix::fs::PermissionsExt;
    let _ = std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o755));
}

#[cfg(not(unix))]
fn set_executable(_: &Path) {}

/// Runs `sbatch --parsable ARGS` and returns the job id (`--parsable` prints `ID` or `ID;CLUSTER`).
fn sbatch(args: &[String]) -> Result<String, String> {
    let out = Command::new("sbatch")
        .arg("--parsable")
        .args(args)
        .output()
        .map_err(|e| format!("cannot run sbatch ({e}): is this a Slurm login node?"))?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        return Err(format!("sbatch failed ({}): {}", out.status, String::from_utf8_lossy(&out.stderr).trim()));
    }
    let id = stdout.trim().split(';').next().unwrap_or("").to_string();
    if id.is_empty() || !id.chars().all(|c| c.is_ascii_digit()) {
        return Err(format!("sbatch printed no job id: {}", stdout.trim()));
    }
    Ok(id)
}

/// The ids `--submit` got: the array job's and the merge job's.
pub struct Submitted {
    pub array: String,
    pub merge: String,
}

/// Submits the script's array, then its merge with `--dependency=afterok` on the array.
pub fn submit(job: &SlurmJob, script: &Path) -> Result<Submitted, CliError> {
    let shown = script.display().to_string();
    let array = sbatch(&[shown.clone()])
        .map_err(|e| CliError::user(format!("{e}\nThe script is written; submit it later with: bash {shown}")))?;
    let merge = sbatch(&[
        format!("--dependency=afterok:{array}"),
        "--array=0".into(),
        "--cpus-per-task=1".into(),
        format!("--job-name={}-merge", job.name),
        "--export=ALL,STRAHL_FARM_STEP=merge".into(),
        shown.clone(),
    ])
    .map_err(|e| {
        CliError::user(format!(
            "{e}\nThe shards are submitted as job {array}; submit the merge with: sbatch --dependency=afterok:{array} \
             --array=0 --export=ALL,STRAHL_FARM_STEP=merge {shown}"
        ))
    })?;
    Ok(Submitted { array, merge })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn job(work: Work) -> SlurmJob {
        SlurmJob {
            strahl: "/opt/strahl/bin/strahl".into(),
            dir: "/scratch/my farm".into(),
            name: "strahl-seed".into(),
            tasks: 4,
            cpus_per_task: 2,
            time: Some("00:10:00".into()),
            partition: None,
            extra: vec!["--account=proj".into()],
            chunk: false,
            work,
        }
    }

    #[test]
    fn quoting_keeps_words_whole() {
        assert_eq!(quote("plain/path.pov"), "plain/path.pov");
        assert_eq!(quote("a b"), "'a b'");
        assert_eq!(quote("it's"), "'it'\\''s'");
        assert_eq!(quote(""), "''");
        assert_eq!(quote("$HOME"), "'$HOME'");
    }

    #[test]
    fn capture_script_has_the_array_logs_cpus_and_merge() {
        let args = vec!["/s/seed.pov".into(), "--path".into(), "/s/o.path".into(), "--frames".into(), "24".into()];
        let s = job(Work::Capture { args }).script();
        for line in [
            "#SBATCH --array=0-3",
            "#SBATCH --cpus-per-task=2",
            "#SBATCH --output=/scratch/my farm/logs/%x_%A_%a.out",
            "#SBATCH --requeue",
            "#SBATCH --open-mode=append",
            "#SBATCH --time=00:10:00",
            "#SBATCH --account=proj",
            "out='/scratch/my farm'",
            "\"$strahl\" capture /s/seed.pov --path /s/o.path --frames 24 --shard auto --threads \"$threads\" -o \"$out/parts/$SLURM_ARRAY_TASK_ID\"",
            "\"$strahl\" capture --merge \"$out/parts/0\" \"$out/parts/1\" \"$out/parts/2\" \"$out/parts/3\" -o \"$out/frames\"",
        ] {
            assert!(s.lines().any(|l| l.trim() == line), "missing `{line}` in\n{s}");
        }
        assert!(s.contains("--dependency=afterok:\"$array\""), "{s}");
        assert!(!s.contains("--partition"));
    }

    #[test]
    fn still_script_merges_every_named_part() {
        let s = SlurmJob { chunk: true, ..job(Work::Still { args: vec!["/s/a b.pov".into()], name: "a b".into() }) }
            .script();
        assert!(s.contains("\"$strahl\" render '/s/a b.pov' --shard auto --chunk --threads \"$threads\" -o \"$out/parts/\"'a b.png'"), "{s}");
        assert!(s.contains("\"$strahl\" merge \"$out/parts/\"'a b.shard-0-of-4.png'"), "{s}");
        assert!(s.contains("\"$out/parts/\"'a b.shard-3-of-4.png' -o \"$out/\"'a b.png'"), "{s}");
    }
}
