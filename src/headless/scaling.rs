//! `strahl scaling` and `strahl gen`: how build and frame time grow with the number of objects
//! (issue #4), on the deterministic scenes of `scene::generate`, and how much of a frame goes
//! to intersection tests (chapter 24.4's 75–95% claim, `--intersection-share`).
//!
//! Frames are timed with `bench::timed_run`, so the figures mean what `strahl bench` figures
//! mean: the median of `--frames` renders after `--warmup` untimed ones, nothing written.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;

use crate::accel::bvh::Bvh;
use crate::accel::grid::Grid;
use crate::accel::Accel;
use crate::camera::Camera;
use crate::geometry::ray::Ray;
use crate::headless::bench::{cpu_model, frame_times, timed_run, Run};
use crate::headless::json::Json;
use crate::headless::{output, with_threads, CliError};
use crate::render::stats::RenderStats;
use crate::render::trace::{light_direction, shadow_ray, ShadowRay, Tracer};
use crate::render::{packet, primary_ray, Quality, RenderSettings};
use crate::scene::build::{AccelKind, Scene};
use crate::scene::desc::SceneDesc;
use crate::scene::generate::{generate, write_pov, Kind};

fn parse_kind(s: &str) -> Result<Kind, String> {
    Kind::parse(s).ok_or_else(|| format!("unknown kind `{s}` (supported: spheres, boxes, triangles, mixed)"))
}

/// `strahl gen KIND N -o FILE`: writes a generated scene as POV-Ray text.
#[derive(Args)]
pub struct GenCmd {
    /// spheres, boxes, triangles or mixed.
    #[arg(value_parser = parse_kind)]
    kind: Kind,
    /// Number of objects (plus the floor).
    count: usize,
    /// Output .pov file.
    #[arg(short = 'o', long)]
    output: PathBuf,
}

pub fn run_gen(c: &GenCmd) -> Result<(), CliError> {
    let text = write_pov(&generate(c.kind, c.count)).map_err(CliError::user)?;
    output::write_atomic(&c.output, text.as_bytes())
}

/// `strahl scaling`: BVH build and frame time against the number of objects.
#[derive(Args)]
pub struct ScalingCmd {
    /// spheres, boxes, triangles or mixed.
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
    /// Worker threads (0 = one per core).
    #[arg(long, default_value_t = 0)]
    threads: usize,
    /// Grid and brute force are timed only up to this many objects (brute force is O(N) per ray).
    #[arg(long, value_name = "N", default_value_t = 10_000)]
    slow_max: usize,
    /// Instead of the table: time a visibility-only pass (the same primary and shadow rays,
    /// intersection tests only) against the full render, on one thread, for each count.
    #[arg(long)]
    intersection_share: bool,
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

/// Everything measured at one N.
pub struct Row {
    pub n: usize,
    pub bvh_build_ms: f64,
    pub bvh_nodes: usize,
    pub bvh_depth: usize,
    pub grid_build_ms: Option<f64>,
    pub modes: Vec<Mode>,
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

fn measure(c: &ScalingCmd, n: usize) -> Result<Row, CliError> {
    let desc = generate(c.kind, n);
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
    for packets in [true, false] {
        let run = with_threads(c.threads, || timed_run(&scene, &cameras, c.warmup, &settings(c, packets)))?;
        modes.push(mode_of(AccelKind::Bvh, packets, &run));
    }
    let mut grid_build_ms = None;
    if n <= c.slow_max {
        let start = Instant::now();
        scene.accel = Accel::Grid(Grid::build(&bounds));
        grid_build_ms = Some(start.elapsed().as_secs_f64() * 1e3);
        for accel in [AccelKind::Grid, AccelKind::None] {
            if accel == AccelKind::None {
                scene.accel = Accel::None { count: bounds.len() as u32 };
            }
            // Packets only run over a BVH (`render::packet::supported`); elsewhere "on" would
            // time the single-ray path twice.
            let packet_modes: &[bool] = if packet::supported(&scene) { &[true, false] } else { &[false] };
            for &packets in packet_modes {
                let run = with_threads(c.threads, || timed_run(&scene, &cameras, c.warmup, &settings(c, packets)))?;
                modes.push(mode_of(accel, packets, &run));
            }
        }
    }
    Ok(Row { n, bvh_build_ms, bvh_nodes, bvh_depth, grid_build_ms, modes })
}

fn ms(m: Option<&Mode>) -> String {
    m.map_or("-".into(), |m| format!("{:.1}", m.median_ms))
}

/// The human-readable table, one line per N.
pub fn table(rows: &[Row]) -> String {
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
    for r in rows {
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
    }
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
            ])
        })
        .collect();
    Json::object(vec![
        ("kind", Json::str(c.kind.name())),
        ("width", Json::Number(c.width as f64)),
        ("height", Json::Number(c.height as f64)),
        ("frames", Json::Number(c.frames as f64)),
        ("warmup", Json::Number(c.warmup as f64)),
        ("cpu", Json::str(cpu)),
        ("rows", Json::Array(rows)),
    ])
}

pub fn run_scaling(c: &ScalingCmd) -> Result<(), CliError> {
    if c.frames == 0 || c.counts.is_empty() {
        return Err(CliError::user("--frames and --counts must not be empty"));
    }
    if c.intersection_share {
        return run_share(c);
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
    let mut rows = Vec::new();
    for &n in &c.counts {
        rows.push(measure(c, n)?);
        // Print as we go: the 1M row takes a while.
        print!("{}", table(&rows).lines().last().map_or(String::new(), |l| format!("{l}\n")));
        output::flush_stdout();
    }
    println!("\n{}", table(&rows));
    if let Some(file) = &c.json {
        output::write_atomic(file, rows_json(c, &rows, &cpu).to_pretty().as_bytes())?;
    }
    Ok(())
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
        let desc = generate(c.kind, n);
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
