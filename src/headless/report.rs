//! The statistics block printed after a render, modelled on POV-Ray's.

use std::fmt::Write;
use std::time::Duration;

use crate::render::stats::RenderStats;
use crate::scene::build::ShapeKind;

pub struct Timings {
    pub parse: Duration,
    pub build: Duration,
    pub trace: Duration,
}

/// The files a scene included and from where, one line each, for the statistics (empty when
/// there were none).
pub fn included_files(included: &[crate::desc::IncludedFile]) -> String {
    let mut o = String::new();
    for f in included {
        let _ = writeln!(o, "Included: {}  (from {}:{}:{})", f.path, f.from.file, f.from.line, f.from.col);
    }
    o
}

pub fn statistics(
    name: &str,
    w: u32,
    h: u32,
    s: &RenderStats,
    max_level: u32,
    t: &Timings,
    peak: Option<u64>,
) -> String {
    let mut o = String::new();
    let line = "-".repeat(78);
    let _ = writeln!(o, "{name} Statistics, Resolution {w} x {h}");
    let _ = writeln!(o, "{line}");
    let spp = if s.pixels > 0 { s.samples as f64 / s.pixels as f64 } else { 0.0 };
    let _ = writeln!(o, "Pixels:     {:>12}   Samples:   {:>12}   Smpls/Pxl: {spp:.2}", s.pixels, s.samples);
    let _ = writeln!(o, "Rays:       {:>12}   Max Level: {:>9}/{max_level}", s.total_rays(), s.max_depth);
    let _ = writeln!(
        o,
        "  Primary:  {:>12}   Shadow:    {:>12}   Reflected: {:>10}   Refracted: {:>10}",
        s.primary_rays, s.shadow_rays, s.reflected_rays, s.refracted_rays
    );
    let _ = writeln!(o, "{line}");
    let _ = writeln!(o, "Ray->Shape Intersection          Tests       Succeeded  Percentage");
    let _ = writeln!(o, "{line}");
    for kind in ShapeKind::ALL {
        let (tests, hits) = s.by_kind(kind);
        if tests == 0 {
            continue;
        }
        let pct = 100.0 * hits as f64 / tests as f64;
        let _ = writeln!(o, "{:<24} {:>14} {:>15} {:>11.2}", kind.name(), tests, hits, pct);
    }
    let _ = writeln!(o, "{:<24} {:>14}", "Bounding nodes/cells", s.nodes_visited);
    let _ = writeln!(o, "{line}");
    if s.bad_samples > 0 {
        let _ = writeln!(o, "NaN/infinite samples:    {:>14}", s.bad_samples);
    }
    match peak {
        Some(b) => {
            let _ = writeln!(o, "Peak memory used:        {:>14} bytes", b);
        }
        None => {
            let _ = writeln!(o, "Peak memory used:        {:>14}", "unknown");
        }
    }
    let _ = writeln!(o, "{line}");
    let _ = writeln!(o, "Parse Time:   {:>10.3} s", t.parse.as_secs_f64());
    let _ = writeln!(o, "Build Time:   {:>10.3} s", t.build.as_secs_f64());
    let _ = writeln!(o, "Trace Time:   {:>10.3} s", t.trace.as_secs_f64());
    o
}
