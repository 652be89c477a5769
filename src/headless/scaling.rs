//! `strahl scaling` and `strahl gen`: how build and frame time grow with the number of objects
//! (issue #4), on the deterministic scenes of `scene::generate`, and how much of a frame goes
//! to intersection tests (chapter 24.4's 75–95% claim, `--intersection-share`).
//!
//! Frames are timed with `bench::timed_run`, so the figures mean what `strahl bench` figures
//! mean: the median of `--frames` renders after `--warmup` untimed ones, nothing written.
//!
//! The slow modes (grid, brute force) run only where they end in seconds: each cell's time is
//! predicted before it runs (`predict_slow`) and cells over `--slow-budget` are skipped with a
//! note, so the defaults finish in about a minute instead of spending minutes on brute force.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;

use crate::accel::bvh::Bvh;
use crate::accel::grid::Grid;
use crate::accel::Accel;
use crate::camera::Camera;
use crate::desc::SceneDesc;
use crate::headless::bench::{cpu_model, frame_times, timed_run, Run};
use crate::headless::json::Json;
use crate::headless::progress::Progress;
use crate::headless::{output, with_threads, CliError};
use crate::ray::Ray;
use crate::render::stats::RenderStats;
use crate::render::trace::{light_direction, shadow_ray, ShadowRay, Tracer};
use crate::render::{packet, primary_ray, Quality, RenderSettings};
use crate::scene::build::{AccelKind, Scene};
use crate::scene::generate::{generate, write_generated_to, IoText, Kind};

mod bvh_build;

fn parse_kind(s: &str) -> Result<Kind, String> {
    Kind::parse(s).ok_or_else(|| {
        format!("unknown kind `{s}` (supported: spheres, boxes, triangles, cylinders, mixed, mesh, tori, mesh2)")
    })
}

/// `strahl gen KIND N -o FILE`: writes a generated scene as POV-Ray text.
#[derive(Args)]
pub struct GenCmd {
    /// spheres, boxes, triangles, cylinders, mixed, mesh, tori, or mesh2 (one sheet of exactly N
    /// triangles).
    #[arg(value_parser = parse_kind)]
    kind: Kind,
    /// Number of objects (plus the floor).
    count: usize,
    /// Output .pov file.
    #[arg(short = 'o', long)]
    output: PathBuf,
    /// mesh2: also write one normal per vertex (`normal_vectors`), for smooth shading.
    #[arg(long)]
    normals: bool,
}

/// Writes the file and says so, since nothing else shows that it worked. The text goes to the
/// file as it is made (ten million objects are a gigabyte of it), beside the output until whole.
pub fn run_gen(c: &GenCmd) -> Result<(), CliError> {
    if c.normals && c.kind != Kind::Mesh2 {
        return Err(CliError::user(format!("--normals is for mesh2, not {}", c.kind.name())));
    }
    let tmp = output::temp_sibling(&c.output);
    let written = std::fs::File::create(&tmp).map_err(|e| e.to_string()).and_then(|file| {
        let mut text = IoText { inner: std::io::BufWriter::with_capacity(1 << 20, file), error: None };
        let result = write_generated_to(&mut text, c.kind, c.count, c.normals);
        match text.error.take() {
            Some(e) => Err(e.to_string()),
            None => result,
        }?;
        text.inner.into_inner().map_err(|e| e.error().to_string())?;
        std::fs::rename(&tmp, &c.output).map_err(|e| e.to_string())
    });
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(CliError::user(format!("{}: cannot write: {e}", c.output.display())));
    }
    println!("wrote {} ({} {})", c.output.display(), c.count, c.kind.plural());
    output::flush_stdout();
    Ok(())
}

/// `strahl scaling`: BVH build and frame time against the number of objects.
#[derive(Args)]
pub struct ScalingCmd {
    /// spheres, boxes, triangles, cylinders, mixed, mesh or tori.
    #[arg(long, default_value = "spheres", value_parser = parse_kind)]
    kind: Kind,
    /// Object counts, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "1000,10000,100000,1000000")]
    counts: Vec<usize>,
    /// Image width in pixels.
    #[arg(short = 'W', long, default_value_t = 640)]
    width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long, default_value_t = 360)]
    height: u32,
    /// Timed frames per configuration (the median is reported).
    #[arg(long, value_name = "N", default_value_t = 5)]
    frames: u32,
    /// Untimed frames first.
    #[arg(long, value_name = "K", default_value_t = 1)]
    warmup: u32,
    /// Worker threads (0 = one per core; at most 4 per core).
    #[arg(long, default_value_t = 0, value_parser = crate::headless::parse_threads)]
    threads: usize,
    /// Grid and brute force are timed only up to this many objects (brute force is O(N) per ray).
    #[arg(long, value_name = "N", default_value_t = 10_000)]
    slow_max: usize,
    /// Grid and brute force are timed at a count only when their predicted time for the
    /// warm-up and timed frames is at most this many seconds; the others are skipped with a note.
    #[arg(long, value_name = "SECONDS", default_value_t = 20.0)]
    slow_budget: f64,
    /// Instead of the table: time a visibility-only pass (the same primary and shadow rays,
    /// intersection tests only) against the full render, on one thread, for each count.
    #[arg(long)]
    intersection_share: bool,
    /// Instead of the table: time the BVH build alone, serial and on `--threads` workers, over
    /// the boxes of N generated spheres (median of `--frames`), and check the two trees equal.
    #[arg(long)]
    bvh_build: bool,
    /// Accelerator for --intersection-share.
    #[arg(long, default_value = "none", value_parser = ["bvh", "grid", "none"])]
    accel: String,
    /// Also write the results as JSON.
    #[arg(long, value_name = "FILE")]
    json: Option<PathBuf>,
}

/// One timed accelerator/packet configuration at one N.
pub struct Mode {
    pub accel: AccelKind,
    pub packets: bool,
    pub median_ms: f64,
    pub mrays: f64,
    /// Primary rays per second, millions.
    pub primary_mrays: f64,
    /// Per ray (all kinds) of the timed frames: BVH nodes or grid cells visited, shape tests, and
    /// nanoseconds; they separate algorithmic growth (visits) from memory effects (ns per visit).
    pub nodes_per_ray: f64,
    pub tests_per_ray: f64,
    pub ns_per_ray: f64,
}

/// A slow-mode cell left out because its predicted time was over `--slow-budget`.
pub struct Skipped {
    pub accel: AccelKind,
    pub predicted_s: f64,
}

/// Everything measured at one N.
pub struct Row {
    pub n: usize,
    pub bvh_build_ms: f64,
    pub bvh_nodes: usize,
    pub bvh_depth: usize,
    pub grid_build_ms: Option<f64>,
    pub modes: Vec<Mode>,
    pub skipped: Vec<Skipped>,
}

impl Row {
    fn mode(&self, accel: AccelKind, packets: bool) -> Option<&Mode> {
        self.modes.iter().find(|m| m.accel == accel && m.packets == packets)
    }
}

fn mode_of(accel: AccelKind, packets: bool, run: &Run) -> Mode {
    Mode {
        accel,
        packets,
        median_ms: frame_times(&run.times_ms).median_ms,
        mrays: run.mrays(run.stats.total_rays()),
        primary_mrays: run.mrays(run.stats.primary_rays),
        nodes_per_ray: run.stats.nodes_visited as f64 / run.stats.total_rays().max(1) as f64,
        tests_per_ray: run.stats.tests.iter().sum::<u64>() as f64 / run.stats.total_rays().max(1) as f64,
        ns_per_ray: run.seconds * 1e9 / run.stats.total_rays().max(1) as f64,
    }
}

fn settings(c: &ScalingCmd, packets: bool) -> RenderSettings {
    RenderSettings { width: c.width, height: c.height, packets, ..RenderSettings::default() }
}

/// Builds `desc` without an accelerator; the caller times and installs one.
fn bare_scene(desc: &SceneDesc) -> Scene {
    Scene::build(desc, desc.camera.location, AccelKind::None)
}

/// Seconds a cell took in all, warm-up included (`Run::seconds` covers the timed frames only).
fn cell_seconds(c: &ScalingCmd, run: &Run) -> f64 {
    run.seconds * (c.frames + c.warmup) as f64 / c.frames as f64
}

/// The slow modes' last measured cell: (objects, seconds), for `predict_slow`.
#[derive(Default)]
struct SlowRuns {
    grid: Option<(usize, f64)>,
    none: Option<(usize, f64)>,
}

/// Predicted seconds of a slow-mode cell (`accel` is grid or none) at `n` objects, or `None`
/// where there is nothing to predict from. From the mode's own last cell, scaled linearly in N:
/// brute force tests every object for every ray, and the grid's cost grows slower than that, so
/// the guess errs long. Brute force without a cell yet: from the BVH single-ray cell of the same
/// rays (`bvh_s` seconds, `bvh_work` node visits plus shape tests per ray), at its cost per
/// visit or test (a node's box test costs about a shape test), since brute force makes about
/// `n` + 1 tests per ray (the floor too); that cost also carries the shading, so where n is
/// larger than the BVH's work per ray this guess errs long as well (1000 spheres at 160×90:
/// 0.74 s predicted, 0.8 s measured). The grid without a cell yet is not predicted
/// (`--slow-max` bounds it).
fn predict_slow(accel: AccelKind, n: usize, last: Option<(usize, f64)>, bvh_s: f64, bvh_work: f64) -> Option<f64> {
    match (last, accel) {
        (Some((n0, s0)), _) => Some(s0 * n as f64 / n0.max(1) as f64),
        (None, AccelKind::None) => Some(bvh_s * (n as f64 + 1.0) / bvh_work.max(1.0)),
        (None, _) => None,
    }
}

/// The progress bar over all cells (count × mode), naming the one that runs. Cells differ in
/// cost by orders of magnitude, so it shows the time so far, not an ETA.
struct Cells {
    bar: Progress,
    done: u64,
    total: u64,
}

impl Cells {
    /// Cells per count: BVH with and without packets, grid, brute force.
    const PER_COUNT: u64 = 4;

    fn new(counts: usize) -> Cells {
        let total = counts as u64 * Cells::PER_COUNT;
        Cells { bar: Progress::new(total, "cells", false).without_eta(), done: 0, total }
    }

    fn start(&self, n: usize, what: &str) {
        self.bar.update_weighted(self.done, self.done as f64 / self.total as f64, &format!("N = {n}: {what}"));
    }

    fn end(&mut self) {
        self.done += 1;
        self.bar.update_weighted(self.done, self.done as f64 / self.total as f64, "");
    }
}

fn measure(c: &ScalingCmd, n: usize, slow: &mut SlowRuns, cells: &mut Cells) -> Result<Row, CliError> {
    cells.start(n, "generating and building");
    let desc = generate(c.kind, n, c.width, c.height);
    let cameras = vec![Camera::from_desc(&desc.camera); c.frames as usize];
    let mut scene = bare_scene(&desc);
    drop(desc);
    let bounds = scene.prim_bounds();
    let start = Instant::now();
    let bvh = Bvh::build(&bounds);
    let bvh_build_ms = start.elapsed().as_secs_f64() * 1e3;
    let (bvh_nodes, bvh_depth) = (bvh.nodes.len(), bvh.depth());
    scene.accel = Accel::Bvh(bvh);
    let mut modes = Vec::new();
    let mut bvh_single_s = 0.0;
    for packets in [true, false] {
        cells.start(n, if packets { "bvh with packets" } else { "bvh, single rays" });
        let run = with_threads(c.threads, || timed_run(&scene, &cameras, c.warmup, &settings(c, packets)))?;
        modes.push(mode_of(AccelKind::Bvh, packets, &run));
        bvh_single_s = cell_seconds(c, &run);
        cells.end();
    }
    let bvh_work = modes.last().map_or(1.0, |m| m.nodes_per_ray + m.tests_per_ray);
    let (mut grid_build_ms, mut skipped) = (None, Vec::new());
    for accel in [AccelKind::Grid, AccelKind::None] {
        let last = if accel == AccelKind::Grid { &mut slow.grid } else { &mut slow.none };
        let predicted = predict_slow(accel, n, *last, bvh_single_s, bvh_work);
        if n > c.slow_max || predicted.is_some_and(|p| p > c.slow_budget) {
            if n <= c.slow_max {
                skipped.push(Skipped { accel, predicted_s: predicted.unwrap_or(f64::NAN) });
            }
            cells.end();
            continue;
        }
        cells.start(n, if accel == AccelKind::Grid { "grid" } else { "brute force" });
        if accel == AccelKind::Grid {
            let start = Instant::now();
            scene.accel = Accel::Grid(Grid::build(&bounds));
            grid_build_ms = Some(start.elapsed().as_secs_f64() * 1e3);
        } else {
            scene.accel = Accel::None { count: bounds.len() as u32 };
        }
        // Packets only run over a BVH (`render::packet::supported`); elsewhere "on" would
        // time the single-ray path twice.
        let packet_modes: &[bool] = if packet::supported(&scene) { &[true, false] } else { &[false] };
        let mut seconds = 0.0;
        for &packets in packet_modes {
            let run = with_threads(c.threads, || timed_run(&scene, &cameras, c.warmup, &settings(c, packets)))?;
            modes.push(mode_of(accel, packets, &run));
            seconds += cell_seconds(c, &run);
        }
        *last = Some((n, seconds));
        cells.end();
    }
    Ok(Row { n, bvh_build_ms, bvh_nodes, bvh_depth, grid_build_ms, modes, skipped })
}

fn ms(m: Option<&Mode>) -> String {
    m.map_or("-".into(), |m| format!("{:.1}", m.median_ms))
}

/// The human-readable table, one line per N.
pub fn table(rows: &[Row]) -> String {
    let mut o = header();
    for r in rows {
        o.push_str(&row_line(r));
    }
    o
}

/// The table's column names, one line.
fn header() -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "{:>8} {:>9} {:>8} {:>5} {:>10} {:>10} {:>9} {:>9} {:>9} {:>8} {:>10} {:>9} {:>9} {:>9} {:>9} {:>7}",
        "N",
        "build ms",
        "nodes",
        "depth",
        "bvh+pkt",
        "bvh-pkt",
        "grid",
        "none",
        "Mrays/s",
        "pkt x",
        "ms/log2N",
        "bvh/none",
        "grid ms",
        "nodes/ray",
        "tests/ray",
        "ns/ray"
    );
    o
}

/// One table line: the figures at one N.
fn row_line(r: &Row) -> String {
    let mut o = String::new();
    let b = r.mode(AccelKind::Bvh, true);
    let single = r.mode(AccelKind::Bvh, false);
    let none = r.mode(AccelKind::None, false);
    let log2 = (r.n.max(2) as f64).log2();
    let speedup = |a: Option<&Mode>, b: Option<&Mode>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}", a.median_ms / b.median_ms),
        _ => "-".into(),
    };
    let _ = writeln!(
        o,
        "{:>8} {:>9.1} {:>8} {:>5} {:>10} {:>10} {:>9} {:>9} {:>9.2} {:>8} {:>10.2} {:>9} {:>9} {:>9.1} {:>9.1} {:>7.0}",
        r.n,
        r.bvh_build_ms,
        r.bvh_nodes,
        r.bvh_depth,
        ms(b),
        ms(single),
        ms(r.mode(AccelKind::Grid, false)),
        ms(none),
        b.map_or(f64::NAN, |m| m.mrays),
        speedup(single, b),
        b.map_or(f64::NAN, |m| m.median_ms / log2),
        speedup(none, b),
        r.grid_build_ms.map_or("-".into(), |g| format!("{g:.1}")),
        single.map_or(f64::NAN, |m| m.nodes_per_ray),
        single.map_or(f64::NAN, |m| m.tests_per_ray),
        single.map_or(f64::NAN, |m| m.ns_per_ray),
    );
    o
}

fn rows_json(c: &ScalingCmd, rows: &[Row], cpu: &str) -> Json {
    let rows = rows
        .iter()
        .map(|r| {
            let modes = r
                .modes
                .iter()
                .map(|m| {
                    Json::object(vec![
                        ("accel", Json::str(m.accel.name())),
                        ("packets", Json::Bool(m.packets)),
                        ("median_ms", Json::Number(m.median_ms)),
                        ("mrays_per_s", Json::Number(m.mrays)),
                        ("primary_mrays_per_s", Json::Number(m.primary_mrays)),
                        ("nodes_per_ray", Json::Number(m.nodes_per_ray)),
                        ("tests_per_ray", Json::Number(m.tests_per_ray)),
                        ("ns_per_ray", Json::Number(m.ns_per_ray)),
                    ])
                })
                .collect();
            Json::object(vec![
                ("n", Json::Number(r.n as f64)),
                ("bvh_build_ms", Json::Number(r.bvh_build_ms)),
                ("bvh_nodes", Json::Number(r.bvh_nodes as f64)),
                ("bvh_depth", Json::Number(r.bvh_depth as f64)),
                ("grid_build_ms", r.grid_build_ms.map_or(Json::Null, Json::Number)),
                ("modes", Json::Array(modes)),
                (
                    "skipped",
                    Json::Array(
                        r.skipped
                            .iter()
                            .map(|s| {
                                Json::object(vec![
                                    ("accel", Json::str(s.accel.name())),
                                    ("predicted_s", Json::Number(s.predicted_s)),
                                ])
                            })
                            .collect(),
                    ),
                ),
            ])
        })
        .collect();
    Json::object(vec![
        ("kind", Json::str(c.kind.name())),
        ("width", Json::Number(c.width as f64)),
        ("height", Json::Number(c.height as f64)),
        ("frames", Json::Number(c.frames as f64)),
        ("warmup", Json::Number(c.warmup as f64)),
        ("slow_max", Json::Number(c.slow_max as f64)),
        ("slow_budget_s", Json::Number(c.slow_budget)),
        ("cpu", Json::str(cpu)),
        ("rows", Json::Array(rows)),
    ])
}

pub fn run_scaling(c: &ScalingCmd) -> Result<(), CliError> {
    if c.frames == 0 || c.counts.is_empty() {
        return Err(CliError::user("--frames and --counts must not be empty"));
    }
    if c.width == 0 || c.height == 0 {
        return Err(CliError::user("-W and -H must be at least 1"));
    }
    if c.slow_budget.is_nan() || c.slow_budget < 0.0 {
        return Err(CliError::user(format!("--slow-budget {} must be a number of seconds, 0 or more", c.slow_budget)));
    }
    if c.intersection_share {
        return run_share(c);
    }
    if c.bvh_build {
        return bvh_build::run(&c.counts, c.frames, c.threads);
    }
    let cpu = cpu_model();
    println!(
        "scaling: {} at {}x{}, {} frames (+{} warm-up) per cell, median ms; cpu: {cpu}",
        c.kind.name(),
        c.width,
        c.height,
        c.frames,
        c.warmup
    );
    println!("columns: bvh+pkt/bvh-pkt = BVH with/without 8x8 packets; grid/none single rays (packets need a BVH);");
    println!("         Mrays/s and ms/log2N for bvh+pkt; pkt x = bvh-pkt/bvh+pkt; bvh/none = none/bvh+pkt;");
    println!("         nodes/ray, tests/ray, ns/ray over all rays of bvh-pkt (single rays)");
    // Rows are printed as they come (the 1M row takes a while), each once, under the header.
    print!("{}", header());
    output::flush_stdout();
    let (mut rows, mut slow, mut cells) = (Vec::new(), SlowRuns::default(), Cells::new(c.counts.len()));
    for &n in &c.counts {
        let row = measure(c, n, &mut slow, &mut cells)?;
        cells.bar.clear();
        print!("{}", row_line(&row));
        output::flush_stdout();
        rows.push(row);
    }
    cells.bar.finish();
    print!("{}", skip_notes(c, &rows));
    if let Some(file) = &c.json {
        output::write_atomic(file, rows_json(c, &rows, &cpu).to_pretty().as_bytes())?;
    }
    Ok(())
}

/// Why cells are empty: counts over `--slow-max` (one line), and each cell over `--slow-budget`
/// with its prediction.
fn skip_notes(c: &ScalingCmd, rows: &[Row]) -> String {
    let mut o = String::new();
    if rows.iter().any(|r| r.n > c.slow_max) {
        let _ = writeln!(o, "note: grid and brute force are not run above --slow-max {}", c.slow_max);
    }
    for r in rows {
        for s in &r.skipped {
            let what = if s.accel == AccelKind::Grid { "grid" } else { "brute force" };
            let _ = writeln!(
                o,
                "note: {what} at N = {} skipped: predicted {:.0} s for {} frame{}, over --slow-budget {} s",
                r.n,
                s.predicted_s,
                c.frames + c.warmup,
                if c.frames + c.warmup == 1 { "" } else { "s" },
                c.slow_budget
            );
        }
    }
    o
}

/// The rays of one frame that need only intersection tests: every primary ray, and the shadow
/// ray each primary hit sends to each light. (Reflected rays and what they spawn are left out;
/// their count is reported so the reader can see what was missed.)
struct VisibilityRays {
    primary: Vec<Ray>,
    shadow: Vec<ShadowRay>,
}

fn visibility_rays(scene: &Scene, camera: &Camera, w: u32, h: u32, quality: &Quality) -> VisibilityRays {
    let mut tracer = Tracer::new(scene, quality);
    let mut rays = VisibilityRays { primary: Vec::with_capacity((w * h) as usize), shadow: Vec::new() };
    for y in 0..h {
        for x in 0..w {
            let ray = primary_ray(scene, camera, w, h, x, y);
            if let Some(hit) = scene.intersect(&ray, f32::INFINITY, &mut tracer.stats) {
                let surface = tracer.surface(&ray, &hit);
                rays.shadow.extend(scene.lights.iter().filter_map(|l| {
                    light_direction(&surface, l.position).map(|d| shadow_ray(surface.p, surface.facing, d, l.position))
                }));
            }
            rays.primary.push(ray);
        }
    }
    rays
}

/// Time of nearest-hit tests for the primary rays and occlusion tests for the shadow rays, and
/// the statistics they counted.
fn visibility_pass(scene: &Scene, rays: &VisibilityRays) -> (f64, RenderStats) {
    let mut stats = RenderStats::default();
    let start = Instant::now();
    for r in &rays.primary {
        black_box(scene.intersect(r, f32::INFINITY, &mut stats));
    }
    for s in &rays.shadow {
        black_box(scene.occluded_towards(&s.ray, s.t_max, s.light, &mut stats));
    }
    (start.elapsed().as_secs_f64() * 1e3, stats)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn run_share(c: &ScalingCmd) -> Result<(), CliError> {
    let accel = match c.accel.as_str() {
        "bvh" => AccelKind::Bvh,
        "grid" => AccelKind::Grid,
        _ => AccelKind::None,
    };
    println!(
        "intersection share: {} scene, accel {}, {}x{}, one thread, single rays, median of {} (+{} warm-up)",
        c.kind.name(),
        accel.name(),
        c.width,
        c.height,
        c.frames,
        c.warmup
    );
    println!(
        "{:>8} {:>10} {:>10} {:>8} {:>10} {:>8} {:>11}",
        "N", "full ms", "visib. ms", "share", "tests vis", "of all", "est. share"
    );
    for &n in &c.counts {
        let desc = generate(c.kind, n, c.width, c.height);
        let scene = Scene::build(&desc, desc.camera.location, accel);
        let camera = Camera::from_desc(&desc.camera);
        let s = settings(c, false);
        let cameras = vec![camera; c.frames as usize];
        let full = with_threads(1, || timed_run(&scene, &cameras, c.warmup, &s))?;
        let full_ms = frame_times(&full.times_ms).median_ms;
        let full_tests: u64 = full.stats.tests.iter().sum::<u64>() / c.frames as u64;
        let rays = visibility_rays(&scene, &camera, c.width, c.height, &s.quality);
        let (times, stats): (Vec<f64>, Vec<RenderStats>) = with_threads(1, || {
            for _ in 0..c.warmup {
                visibility_pass(&scene, &rays);
            }
            (0..c.frames).map(|_| visibility_pass(&scene, &rays)).unzip()
        })?;
        let vis_ms = median(times);
        let vis_tests: u64 = stats[0].tests.iter().sum();
        let of_all = vis_tests as f64 / full_tests.max(1) as f64;
        // Tests the visibility pass skipped (reflected rays and their shadows) cost about as much
        // each as the ones it made.
        let estimate = vis_ms / of_all / full_ms;
        println!(
            "{:>8} {:>10.1} {:>10.1} {:>7.1}% {:>10} {:>7.1}% {:>10.1}%",
            n,
            full_ms,
            vis_ms,
            100.0 * vis_ms / full_ms,
            vis_tests,
            100.0 * of_all,
            100.0 * estimate
        );
        output::flush_stdout();
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slow_cells_are_predicted_before_they_run() {
        // Brute force with no cell of its own yet: the BVH cell took 2 s visiting and testing
        // 25 nodes and shapes per ray, brute force makes n + 1 = 1000 tests: 40 times the work.
        let p = predict_slow(AccelKind::None, 999, None, 2.0, 25.0);
        assert_eq!(p, Some(80.0));
        // From its own last cell, linearly in N: 1.5 s at 1000 objects is 15 s at 10 000.
        assert_eq!(predict_slow(AccelKind::None, 10_000, Some((1000, 1.5)), 2.0, 25.0), Some(15.0));
        assert_eq!(predict_slow(AccelKind::Grid, 10_000, Some((1000, 0.25)), 2.0, 25.0), Some(2.5));
        // The grid's first cell has nothing to go by; --slow-max bounds it.
        assert_eq!(predict_slow(AccelKind::Grid, 1000, None, 2.0, 25.0), None);
    }
}
