//! The `strahl` command line: parses arguments (`cli`), runs one subcommand, prints one error.

use std::process::ExitCode;

use clap::Parser;

use strahl::headless::capture;
use strahl::headless::{self, bench, still_part, tradeoff, CliError};
use strahl::render::RenderSettings;

mod cli;
use cli::*;

fn view(v: ViewCmd) -> Result<(), CliError> {
    if !(v.target_fps.is_finite() && v.target_fps > 0.0) {
        return Err(CliError::user(format!("--target-fps must be a positive number, not {}", v.target_fps)));
    }
    if v.common.res_scale.is_some() {
        return Err(CliError::user(
            "--res-scale is for render, capture and bench: the window picks its own resolution while the camera moves",
        ));
    }
    let settings = v.common.settings();
    let options = strahl::app::ViewOptions {
        width: v.common.width,
        height: v.common.height,
        aa: settings.aa,
        quality: settings.quality,
        threads: v.common.threads,
        accel: v.common.accel.into(),
        target_fps: v.target_fps,
        frames: v.frames,
        screenshot: v.screenshot,
        scene: v.scene.clone(),
        hud: v.hud,
        path: v.path.as_deref().map(|p| strahl::app::PathPlay::load(p, v.path_seconds)).transpose()?,
        report: v.report,
        reproject: !v.no_reproject,
    };
    strahl::app::view_file(&v.scene, &v.common.include, options)
}

fn run(cli: Cli) -> Result<(), CliError> {
    // No subcommand means `strahl view` with its defaults, so `cargo run` opens the window.
    let command = match cli.command {
        Some(c) => c,
        None => match Cli::parse_from(["strahl", "view"]).command {
            Some(c) => c,
            None => unreachable!("`strahl view` parses to the view command"),
        },
    };
    match command {
        Command::View(v) => view(v),
        Command::Scaling(s) => headless::scaling::run_scaling(&s),
        Command::Gen(g) => headless::scaling::run_gen(&g),
        Command::Survey(s) => headless::survey::run(&s),
        Command::Path(PathCmd::Orbit(o)) => headless::orbit::run(&headless::orbit::OrbitArgs {
            scene: o.scene,
            include: o.include,
            output: o.output,
            keys: o.frames,
            seconds: o.seconds,
            quiet: o.quiet,
        }),
        Command::Merge(m) => still_part::merge(&m.parts, &m.output, None, m.quiet),
        Command::Farm(FarmCmd::Slurm(f)) => farm_slurm(f),
        Command::Render(r) => {
            let merge = r.merge;
            let args = headless::render::RenderArgs {
                clock: match &r.ini {
                    Some(ini) => headless::render::clock_from_ini(ini, r.frame)?,
                    None => strahl::pov::Clock::default(),
                },
                scene: r.scene,
                include: r.common.include.clone(),
                output: r.output,
                settings: r.common.settings(),
                res_scale: r.common.res_scale(),
                threads: r.common.threads,
                accel: r.common.accel.into(),
                quiet: r.quiet,
                shard: r.shard,
                chunk: r.chunk,
            };
            if merge {
                headless::render::run_merge(&args)
            } else {
                headless::render::run(&args)
            }
        }
        Command::Capture(c) if !c.merge.is_empty() => capture::run_merge(&c.merge, &c.output),
        Command::Capture(c) => capture::run(&capture::CaptureArgs {
            // clap enforces these unless --merge is given, which the arm above handles.
            scene: c.scene.unwrap_or_default(),
            path: c.path.unwrap_or_default(),
            frames: c.frames.unwrap_or(0),
            include: c.common.include.clone(),
            range: c.frames_range,
            shard: c.shard,
            chunk: c.chunk,
            output: c.output,
            settings: RenderSettings { tile: c.tile, ..c.common.settings() },
            res_scale: c.common.res_scale(),
            threads: c.common.threads,
            accel: c.common.accel.into(),
            clock: c.clock,
            quiet: c.quiet,
            force: c.force,
        }),
        Command::Tradeoff(t) => tradeoff::run(&tradeoff::TradeoffArgs {
            scene: t.scene,
            include: t.include,
            path: t.path,
            frames: t.frames.unwrap_or(3),
            width: t.width,
            height: t.height,
            output: t.output,
            threads: t.threads,
            repeats: t.repeats,
            accel: t.accel.into(),
        }),
        Command::Bench(b) => bench::run(&bench::BenchArgs {
            scene: b.scene,
            include: b.common.include.clone(),
            path: b.path,
            frames: b.frames,
            warmup: b.warmup,
            json: b.json,
            settings: RenderSettings { tile: b.tile, ..b.common.settings() },
            res_scale: b.common.res_scale(),
            threads: b.common.threads,
            accel: b.common.accel.into(),
            threads_sweep: b.threads_sweep,
            clock: b.clock,
        }),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.code as u8)
        }
    }
}
