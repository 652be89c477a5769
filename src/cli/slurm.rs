//! `strahl farm slurm`: its arguments, and turning them into a checked job script.

use std::path::PathBuf;

use clap::{Args, Subcommand};

use strahl::headless::capture::ClockRange;
use strahl::headless::farm::{self, SlurmJob, Work};
use strahl::headless::shard::MAX_SHARDS;
use strahl::headless::{self, CliError};

use super::common::*;

#[derive(Subcommand)]
pub(crate) enum FarmCmd {
    /// Write DIR/strahl.sbatch: a Slurm job array over the shards (logs DIR/logs/%x_%A_%a.out)
    /// and a merge job that runs once every shard succeeded. With --path, a capture (merged
    /// into DIR/frames); without, a still in bands (merged into DIR/SCENE.png).
    Slurm(SlurmCmd),
}

#[derive(Args)]
#[command(
    override_usage = "strahl farm slurm <SCENE> [--path <PATH> --frames <N>] -o <DIR> --tasks <N> [--submit] [OPTIONS]"
)]
pub(crate) struct SlurmCmd {
    /// The POV-Ray scene file.
    pub(crate) scene: PathBuf,
    /// Camera path: farm a capture of --frames frames along it (without it: a still).
    #[arg(long, requires = "frames")]
    pub(crate) path: Option<PathBuf>,
    /// Frames in the capture (with --path).
    #[arg(long, value_name = "N", requires = "path", value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) frames: Option<u32>,
    #[arg(long, value_name = "A..B", allow_hyphen_values = true, requires = "path", help = CLOCK_HELP)]
    pub(crate) clock: Option<ClockRange>,
    /// Output folder: the script, logs/, parts/ and the merged result (created if missing).
    #[arg(short = 'o', long, value_name = "DIR")]
    pub(crate) output: PathBuf,
    /// Array tasks (shards).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=MAX_SHARDS as i64))]
    pub(crate) tasks: u32,
    /// Cores per task; each task renders with this many threads.
    #[arg(long, value_name = "C", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub(crate) cpus_per_task: u32,
    /// Time limit per task, in Slurm's syntax (e.g. 01:00:00).
    #[arg(long, value_name = "T")]
    pub(crate) time: Option<String>,
    /// Slurm partition.
    #[arg(long, value_name = "NAME")]
    pub(crate) partition: Option<String>,
    /// Another #SBATCH option, verbatim (repeatable), e.g. --sbatch=--account=proj.
    #[arg(long = "sbatch", value_name = "OPTION", allow_hyphen_values = true)]
    pub(crate) sbatch: Vec<String>,
    /// Slurm job name (default: strahl-SCENE).
    #[arg(long, value_name = "NAME")]
    pub(crate) job_name: Option<String>,
    /// Deal each shard contiguous frames or rows instead of interleaved ones.
    #[arg(long)]
    pub(crate) chunk: bool,
    /// The strahl executable the tasks run (default: this one).
    #[arg(long, value_name = "PATH")]
    pub(crate) strahl: Option<PathBuf>,
    /// Submit the array and the merge with sbatch and print their job ids.
    #[arg(long)]
    pub(crate) submit: bool,
    #[command(flatten)]
    pub(crate) common: Common,
}

/// `strahl farm slurm`: checks the job, writes the script, and submits it where asked.
pub(crate) fn farm_slurm(f: SlurmCmd) -> Result<(), CliError> {
    if f.common.threads != 0 {
        return Err(CliError::user("--threads is not for a farm: each task uses --cpus-per-task threads"));
    }
    let scene = absolute(&f.scene)?;
    let stem = scene.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "strahl".into());
    let mut args = vec![scene.display().to_string()];
    let work = match (&f.path, f.frames) {
        (Some(path), Some(frames)) => {
            if f.tasks > frames {
                return Err(CliError::user(format!(
                    "--tasks {} is more than the {frames} frames: give at most {frames}",
                    f.tasks
                )));
            }
            args.extend([
                "--path".into(),
                absolute(path)?.display().to_string(),
                "--frames".into(),
                frames.to_string(),
            ]);
            if let Some(c) = f.clock {
                args.push(format!("--clock={c}"));
            }
            args.extend(f.common.to_args()?);
            Work::Capture { args }
        }
        _ => {
            let (unit, what) = if f.chunk { (1, "rows") } else { (headless::band::STRIP, "strips of 8 rows") };
            let units = f.common.height.div_ceil(unit);
            if f.tasks > units {
                return Err(CliError::user(format!(
                    "--tasks {} is more than the image's {units} {what}: give at most {units}",
                    f.tasks
                )));
            }
            args.extend(f.common.to_args()?);
            Work::Still { args, name: stem.clone() }
        }
    };
    let strahl = match &f.strahl {
        Some(p) => absolute(p)?,
        None => std::env::current_exe()
            .map_err(|e| CliError::user(format!("cannot find this strahl executable ({e}); give --strahl")))?,
    };
    headless::output::check_folder_writable("-o", &f.output)?;
    headless::output::create_dir(&f.output)?;
    let job = SlurmJob {
        strahl,
        dir: absolute(&f.output)?,
        name: f.job_name.unwrap_or_else(|| format!("strahl-{stem}")),
        tasks: f.tasks,
        cpus_per_task: f.cpus_per_task,
        time: f.time,
        partition: f.partition,
        extra: f.sbatch,
        chunk: f.chunk,
        work,
    };
    let script = farm::write(&job)?;
    println!("wrote {}", script.display());
    if f.submit {
        let ids = farm::submit(&job, &script)?;
        println!("array job {} ({} shards), logs in {}", ids.array, job.tasks, job.dir.join("logs").display());
        println!("merge job {} (afterok:{}), result: {}", ids.merge, ids.array, job.result().display());
    } else {
        println!("submit with: bash {}", script.display());
    }
    headless::output::flush_stdout();
    Ok(())
}
