//! `strahl scaling --bvh-build`: the BVH build alone, on one thread and on the pool, over the
//! boxes of the generated cloud (issue #42): time, speed-up, nodes and memory per object.
//!
//! The parallel tree is checked against the serial one node for node before a figure is
//! printed. Memory is the process's peak (VmHWM) over what it held before the first build,
//! so run one count per process for a clean figure (the script does).

use std::time::Instant;

use crate::accel::aabb::Aabb;
use crate::accel::bvh::Bvh;
use crate::desc::ShapeDesc;
use crate::headless::bench::cpu_model;
use crate::headless::{output, peak_memory_bytes, resident_memory_bytes, with_threads, CliError};
use crate::scene::generate::{cloud, Kind};

/// Prints one line per count: serial and parallel median ms over `reps` builds.
pub fn run(counts: &[usize], reps: u32, threads: usize) -> Result<(), CliError> {
    println!("bvh build: the boxes of `strahl gen spheres N`, median of {reps}; cpu: {}", cpu_model());
    println!(
        "{:>10} {:>8} {:>10} {:>10} {:>8} {:>10} {:>9} {:>12}",
        "N", "threads", "serial ms", "par ms", "speedup", "nodes/obj", "B/obj", "peak +MB"
    );
    for &n in counts {
        let bounds: Vec<Aabb> = cloud(Kind::Spheres, n)
            .filter_map(|o| match o.shape {
                ShapeDesc::Sphere { center, radius } => {
                    let (c, r) = (center.as_vec3(), glam::Vec3::splat(radius as f32));
                    Some(Aabb::new(c - r, c + r))
                }
                _ => None,
            })
            .collect();
        let before = resident_memory_bytes().unwrap_or(0);
        let mut par_ms = Vec::new();
        let (bvh, used) = with_threads(threads, || {
            let mut bvh = Bvh::default();
            for _ in 0..reps {
                drop(std::mem::take(&mut bvh));
                let start = Instant::now();
                bvh = Bvh::build(&bounds);
                par_ms.push(start.elapsed().as_secs_f64() * 1e3);
            }
            (bvh, rayon::current_num_threads())
        })?;
        let peak = peak_memory_bytes().unwrap_or(0).saturating_sub(before);
        let mut serial_ms = Vec::new();
        let mut serial = Bvh::default();
        for _ in 0..reps {
            drop(std::mem::take(&mut serial));
            let start = Instant::now();
            serial = Bvh::build_serial(&bounds);
            serial_ms.push(start.elapsed().as_secs_f64() * 1e3);
        }
        if !bvh.same_as(&serial) {
            return Err(CliError::user(format!("the parallel build of {n} boxes differs from the serial one")));
        }
        let (s, p) = (median(&mut serial_ms), median(&mut par_ms));
        let per = |x: usize| x as f64 / n.max(1) as f64;
        let bytes = bvh.nodes.len() * std::mem::size_of_val(&bvh.nodes[0]) + 4 * bvh.prim_order.len();
        println!(
            "{n:>10} {used:>8} {s:>10.1} {p:>10.1} {:>7.2}x {:>10.3} {:>9.1} {:>12.1}",
            s / p,
            per(bvh.nodes.len()),
            per(bytes),
            peak as f64 / 1e6
        );
        output::flush_stdout();
    }
    Ok(())
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}
