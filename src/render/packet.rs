//! Packet tracing (the scene walks are in `rows`): primary rays in 8×8 pixel blocks, and their shadow rays towards each point
//! light as packets too. Everything after the first hit (shading, reflection, refraction) goes
//! through the single-ray `Tracer`, so the image is bit-identical to single-ray rendering: the
//! 8-wide kernels are the single-ray kernels (`geometry::Shape`), and shading is shared.
//!
//! AVX2 is used when the CPU has it (`is_x86_feature_detected!`): the same generic code is
//! compiled twice, once inside a `#[target_feature(enable = "avx2")]` function. Without FMA
//! contraction both compute identical bits, so the choice never shows in the image.

// Lane loops index several per-lane arrays at once; iterators would hide which lane is meant.
#![allow(clippy::needless_range_loop)]
use glam::Vec3;

use crate::accel::packet::{Frustum, Ray8, RowTest};
use crate::accel::Accel;
use crate::geometry::Shape;
use crate::lanes::{has_avx2, Lane, F8, M8, V3};
use crate::ray::Ray;
use crate::ray::MISS;
use crate::ray::{HIT_ERROR_ULPS, SHADOW_SHRINK};
use crate::render::block_rows::{BlockRows, ShadowRows, Soa3, SurfaceRows};
use crate::render::intersect::{Hit, HitShape};
use crate::render::shade::{self, LightSample, LocalHit};
use crate::render::stats::RenderStats;
use crate::render::trace::{Shadows, Surface, Tracer};
use crate::scene::build::{Scene, ShapeKind};
use crate::shading::normal::perturb_normal_lanes;
use crate::shading::pattern::{Rgbft, RgbftLanes};
use crate::shading::pigment::eval_surface_pigment_lanes;

/// Packet edge in pixels: 8×8 = 64 rays, eight rows of eight lanes.
pub const BLOCK: u32 = 8;
/// Lights whose shadows are traced as packets; scenes with more shade their primaries one by
/// one with single-ray shadows.
const MAX_PACKET_LIGHTS: usize = 8;

/// `no hit` in a lane's id.
pub(crate) const NO_HIT: u32 = u32::MAX;
/// Ids at or above this are planes.
const PLANE_ID: u32 = 1 << 31;

mod rows;
use rows::{intersect_rows, occluded_rows};

/// Whether this scene and these settings can use packets.
pub fn supported(scene: &Scene) -> bool {
    matches!(scene.accel, Accel::Bvh(_))
}

/// Traces one block of primary rays (`rays[row]`, `rows` rows valid, `lanes` lanes valid per
/// row) and returns their colours (row by row, lane `i` the ray of lane `i`), exactly as
/// `Tracer::trace` would for each ray. Lanes past `lanes` hold the background.
pub fn trace_block(tracer: &mut Tracer, rays: &[Ray8; 8], rows: usize, lanes: usize) -> [V3<F8>; 8] {
    #[cfg(target_arch = "x86_64")]
    if has_avx2() {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { trace_block_avx2(tracer, rays, rows, lanes) };
    }
    trace_block_generic(tracer, rays, rows, lanes)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn trace_block_avx2(tracer: &mut Tracer, rays: &[Ray8; 8], rows: usize, lanes: usize) -> [V3<F8>; 8] {
    trace_block_generic(tracer, rays, rows, lanes)
}

/// The single ray of lane `i`.
#[inline(always)]
pub(crate) fn lane_ray(rays: &Ray8, i: usize) -> Ray {
    Ray { origin: rays.o.lane(i), dir: rays.d.lane(i), inv_dir: rays.inv.lane(i) }
}

/// What lane's hit `id` (and `face`, `NO_HIT` unless the hit is on a mesh) is.
/// The id of the object `shape` lies on, as a packet lane holds it: a primitive or CSG leaf
/// (a mesh for its faces), or `PLANE_ID + i` for plane `i`; never `NO_HIT`.
#[inline(always)]
pub(crate) fn object_id(shape: HitShape) -> u32 {
    match shape {
        HitShape::Prim(i) | HitShape::Face { prim: i, .. } => i,
        HitShape::Plane(i) => PLANE_ID + i,
    }
}

#[inline(always)]
fn hit_shape(id: u32, face: u32) -> Option<HitShape> {
    match id {
        NO_HIT => None,
        id if id >= PLANE_ID => Some(HitShape::Plane(id - PLANE_ID)),
        prim if face != NO_HIT => Some(HitShape::Face { prim, face }),
        id => Some(HitShape::Prim(id)),
    }
}

/// The nearest hits of one block of primary rays: per row the hit distances, and per lane the
/// hit's id (a primitive, CSG leaf or mesh; `PLANE_ID + i` for plane `i`; `NO_HIT`) and face
/// (`NO_HIT` unless the hit is on a mesh).
pub(crate) struct BlockHits {
    pub t: [F8; 8],
    pub ids: [[u32; 8]; 8],
    pub faces: [[u32; 8]; 8],
}

impl BlockHits {
    /// Lane `i` of row `r` as a hit, `None` where the ray missed.
    #[inline(always)]
    pub fn hit(&self, r: usize, i: usize) -> Option<Hit> {
        hit_shape(self.ids[r][i], self.faces[r][i]).map(|shape| Hit { t: self.t[r].0[i], shape })
    }
}

/// The nearest hits of one block of primary rays, as `Tracer::trace` finds them for each ray
/// (resolved to CSG leaves and mesh faces, refined in f64 where the tracer refines).
pub(crate) fn primary_hits(tracer: &mut Tracer, rays: &[Ray8; 8], rows: usize, lanes: usize) -> BlockHits {
    #[cfg(target_arch = "x86_64")]
    if has_avx2() {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { primary_hits_avx2(tracer, rays, rows, lanes) };
    }
    primary_hits_generic(tracer, rays, rows, lanes)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn primary_hits_avx2(tracer: &mut Tracer, rays: &[Ray8; 8], rows: usize, lanes: usize) -> BlockHits {
    primary_hits_generic(tracer, rays, rows, lanes)
}

#[inline(always)]
fn primary_hits_generic(tracer: &mut Tracer, rays: &[Ray8; 8], rows: usize, lanes: usize) -> BlockHits {
    let scene = tracer.scene;
    let mut t = [F8::splat(MISS); 8];
    let mut ids = [[NO_HIT; 8]; 8];
    // The face of each lane's hit on a mesh (`NO_HIT` elsewhere).
    let mut faces = [[NO_HIT; 8]; 8];
    // The frustum bounds rays from one origin; orthographic, cylinder 3/4 and focal-blur
    // packets (each lane its own origin) walk the tree without it.
    let o = rays[0].o.lane(0);
    // Lane-wise comparisons, counted once: lane by lane with a branch each, this was 2 % of a
    // simple scene's frame. A loop, not `Iterator::all` with a closure, which was compiled out
    // of line without AVX2.
    let (ox, oy, oz) = (F8::splat(o.x), F8::splat(o.y), F8::splat(o.z));
    let mut same = M8([-1; 8]);
    for r in &rays[..rows] {
        let x = F8::and(r.o.x.le(ox), ox.le(r.o.x));
        let y = F8::and(r.o.y.le(oy), oy.le(r.o.y));
        let z = F8::and(r.o.z.le(oz), oz.le(r.o.z));
        same = F8::and(same, F8::and(x, F8::and(y, z)));
    }
    let shared = same.count() == 8;
    let frustum = if shared { Some(Frustum::new(o, &rays[..rows])) } else { None };
    let frustum = frustum.as_ref();
    intersect_rows(
        scene,
        &rays[..rows],
        &mut t[..rows],
        &mut ids[..rows],
        &mut faces[..rows],
        frustum,
        &mut tracer.stats,
    );
    if !scene.csg.is_empty() || !scene.meshes.is_empty() {
        // The packet's search named each CSG hit's leaf and each mesh hit's face; a leaf that is
        // a mesh learns its face here, one ray at a time (`Scene::resolve`). Other leaves need
        // nothing: the call was asked of every hit (3 % of a CSG scene's frame).
        for r in 0..rows {
            for i in 0..lanes {
                if let Some(shape @ HitShape::Prim(prim)) = hit_shape(ids[r][i], faces[r][i]) {
                    if !scene.resolves(prim) {
                        continue;
                    }
                    match scene.resolve(&lane_ray(&rays[r], i), Hit { t: t[r].0[i], shape }).shape {
                        HitShape::Prim(leaf) => ids[r][i] = leaf,
                        HitShape::Face { prim, face } => (ids[r][i], faces[r][i]) = (prim, face),
                        HitShape::Plane(_) => {}
                    }
                }
            }
        }
    }
    if tracer.refines() {
        for r in 0..rows {
            for i in 0..lanes {
                let Some(shape) = hit_shape(ids[r][i], faces[r][i]) else { continue };
                t[r].0[i] = scene.refine(&lane_ray(&rays[r], i), Hit { t: t[r].0[i], shape }).t;
            }
        }
    }
    BlockHits { t, ids, faces }
}

#[inline(always)]
fn trace_block_generic(tracer: &mut Tracer, rays: &[Ray8; 8], rows: usize, lanes: usize) -> [V3<F8>; 8] {
    let scene = tracer.scene;
    let BlockHits { t, ids, faces } = primary_hits_generic(tracer, rays, rows, lanes);
    let n = (rows * lanes) as u64;
    tracer.stats.primary_rays += n;
    tracer.stats.max_depth = tracer.stats.max_depth.max(1);
    let background = scene.background.rgb;

    // Transparent blockers tint shadow rays, which only single rays model; so do lights other
    // than plain point lights (`shading::light`: spot, cylinder, parallel, fading, area), and
    // fog and rainbows (`scene::atmosphere`), which change every ray's colour, are applied per
    // ray too. Checked once per block, so the seed scene pays nothing per pixel for them. A sky
    // sphere colours only the rays that miss: those lanes ask it one by one, below.
    if scene.features.transparency
        || scene.lights.len() > MAX_PACKET_LIGHTS
        || scene.features.complex_lights
        || scene.atmosphere.along_rays()
    {
        let mut colors = [V3::splat(background); 8];
        for r in 0..rows {
            for i in 0..lanes {
                let ray = lane_ray(&rays[r], i);
                let hit = hit_shape(ids[r][i], faces[r][i]).map(|shape| Hit { t: t[r].0[i], shape });
                colors[r].set_lane(i, tracer.shade_hit(&ray, hit.as_ref(), 1, 1.0));
            }
        }
        return colors;
    }

    // A block of sky (nothing hit): no surfaces, no shadow rays; each lane's miss colour.
    if ids[..rows].iter().all(|row| row[..lanes].iter().all(|&id| id == NO_HIT)) {
        let mut colors = [V3::splat(background); 8];
        sky_lanes(tracer, rays, &ids, rows, lanes, &mut colors);
        return colors;
    }

    // Surfaces first, so all shadow rays of the block can be traced together.
    let q = tracer.pattern_quality();
    // The block's rows, reused (`render::block_rows`): only `valid` starts afresh.
    let mut block = tracer.block.take().unwrap_or_else(BlockRows::new);
    let BlockRows { surfaces: soa, pigments, shadow, lights: light_rows } = &mut *block;
    soa.valid = [M8::default(); 8];
    // Per row: each lane's material where it is shaded eight lanes wide (`NO_HIT` for a miss
    // or a lane shaded singly), the pigment colours of those lanes (in `pigments`), and the
    // single lanes' surfaces.
    let mut materials = [[NO_HIT; 8]; 8];
    // (row, lane, surface) of the lanes shaded singly, in row and lane order; most blocks have
    // none, and a `Vec` costs nothing until pushed to (a 64-entry array was set to `None` per
    // block).
    let mut surfaces: Vec<(usize, usize, Surface)> = Vec::new();
    let in_block = M8::from_fn(|i| i < lanes);
    for r in 0..rows {
        // Lanes whose material the local model below covers go eight wide, a group per material
        // (OSPRay's `foreach_unique`); the rest (reflection, transparency, uv mapping, layers,
        // interior textures) go through `Tracer::shade_surface` one by one. A material is looked
        // up once per object of the row, not per lane (a face does not change it).
        let hit = F8::and(in_block, F8::not(M8::equal(&ids[r], NO_HIT)));
        let mut row_materials = [NO_HIT; 8];
        for (id, group) in Groups::of(&ids[r], hit) {
            let Some(shape) = hit_shape(id, NO_HIT) else { continue };
            let m = scene.material_of(shape);
            for i in 0..8 {
                row_materials[i] = if group.lane(i) { m } else { row_materials[i] };
            }
        }
        let mut in_lanes = M8::default();
        for (m, group) in Groups::of(&row_materials, hit) {
            if scene.local[m as usize] {
                in_lanes = F8::or(in_lanes, group);
            }
        }
        // Branch-free per lane, so it vectorises.
        for i in 0..8 {
            let keep = in_lanes.0[i] as u32;
            materials[r][i] = (row_materials[i] & keep) | (NO_HIT & !keep);
        }
        if in_lanes.any() {
            // `Tracer::surface`, eight lanes at a time; other lanes sit at the ray origin.
            let ray = &rays[r];
            let p = ray.o.add(ray.d.scale(F8::select(in_lanes, t[r], F8::splat(0.0))));
            // The geometric normal, one shape at a time (the same bits lane by lane or eight
            // wide); a shape on one or two lanes, or one that solves its normals point by point
            // whatever the width, is asked for its own lanes only.
            let mut geometric = V3::splat(Vec3::Y);
            for (id, same_id) in Groups::of(&ids[r], in_lanes) {
                // A mesh's lanes mostly hit faces of their own: gathered, eight at a time.
                let mut lead = 0;
                while lead < 7 && !same_id.lane(lead) {
                    lead += 1;
                }
                if faces[r][lead] != NO_HIT && same_id.count() > 2 && scene.gathers_face_normals(id) {
                    geometric = V3::select(same_id, scene.normal_faces(id, &faces[r], same_id, lead, p), geometric);
                    continue;
                }
                for (face, group) in Groups::of(&faces[r], same_id) {
                    let Some(shape) = hit_shape(id, face) else { continue };
                    if group.count() > 2 && !scene.normal_per_lane(shape) {
                        geometric = V3::select(group, scene.normal_lanes(shape, p), geometric);
                    } else {
                        for j in (0..8).filter(|&j| group.lane(j)) {
                            let n = scene.normal_at(shape, p.lane(j));
                            (geometric.x.0[j], geometric.y.0[j], geometric.z.0[j]) = (n.x, n.y, n.z);
                        }
                    }
                }
            }
            let entering = geometric.dot(ray.d).lt(F8::splat(0.0));
            let facing = V3::select(entering, geometric, geometric.neg());
            let mut normal = facing;
            let mut pigment = RgbftLanes::splat(Rgbft::default());
            for (m, group) in Groups::of(&materials[r], in_lanes) {
                let material = &scene.materials[m as usize];
                if let Some(n) = &material.normal {
                    normal = V3::select(group, perturb_normal_lanes(n, p, facing, q), normal);
                }
                let own = eval_surface_pigment_lanes(&material.pigment, p, geometric, q);
                pigment = RgbftLanes::select(group, own, pigment);
            }
            soa.p[r] = Soa3::from(p);
            soa.facing[r] = Soa3::from(facing);
            soa.normal[r] = Soa3::from(normal);
            soa.valid[r] = in_lanes;
            pigments[r] = pigment;
        }
        if !F8::and(hit, F8::not(in_lanes)).any() {
            continue;
        }
        for i in 0..lanes {
            if in_lanes.lane(i) {
                continue;
            }
            let Some(shape) = hit_shape(ids[r][i], faces[r][i]) else { continue };
            let s = tracer.surface(&lane_ray(&rays[r], i), &Hit { t: t[r].0[i], shape });
            set_surface_lane(soa, r, i, &s);
            surfaces.push((r, i, s));
        }
    }

    // Per light and row: the direction to the light, and the lanes it reaches unblocked (rows
    // below `rows` are written for every light before they are read). Rows past `rows` of the
    // shadow rays are never read, and `shadow_setup` rewrites rows below it per light.
    light_rows.resize(scene.lights.len(), ([V3::splat(Vec3::ZERO); 8], [M8::default(); 8]));
    for (l, light) in scene.lights.iter().enumerate() {
        let unshadowed = light.shadowless || !tracer.quality.shadows;
        shadow_setup(soa, rows, light.position, unshadowed, shadow);
        let active = shadow.active;
        let count: u64 = active[..rows].iter().map(|m| m.count() as u64).sum();
        let blocked = if count == 0 {
            [M8::default(); 8]
        } else {
            tracer.stats.shadow_rays += count;
            occluded_rows(
                scene,
                &shadow.rays[..rows],
                &mut shadow.t_max[..rows],
                &active[..rows],
                light.position,
                &mut tracer.stats,
            )
        };
        let (dir, on) = &mut light_rows[l];
        for r in 0..rows {
            dir[r] = shadow.rays[r].d;
            on[r] = F8::and(shadow.lit[r], F8::not(blocked[r]));
        }
    }

    let lights = scene.lights.len();
    let mut colors = [V3::splat(background); 8];
    for r in 0..rows {
        let pigment = pigments[r];
        let hit = LocalHit {
            color: pigment.rgb,
            opacity: shade::opacity(pigment.filter, pigment.transmit),
            normal: soa.normal[r].v(),
            ray_dir: rays[r].d,
        };
        let reflected = shade::reflect(hit.ray_dir, hit.normal);
        // `Tracer::shade_surface` for a material without reflection or refraction, once per
        // material of the row over all eight lanes, kept where the lanes have it.
        let in_lanes = M8::from_fn(|i| materials[r][i] != NO_HIT);
        for (m, group) in Groups::of(&materials[r], in_lanes) {
            let material = &scene.materials[m as usize];
            let finish = &material.finish;
            let mut color = shade::ambient(finish, scene.ambient_light, &hit);
            for (l, light) in scene.lights.iter().enumerate() {
                if !material.lit_by(l) {
                    continue;
                }
                let (dir, on) = &light_rows[l];
                let sample = LightSample { dir: dir[r], color: V3::splat(light.color * Vec3::ONE), on: on[r] };
                color = shade::add_light(finish, &hit, reflected, color, &sample);
            }
            colors[r] = V3::select(group, color, colors[r]);
        }
    }
    sky_lanes(tracer, rays, &ids, rows, lanes, &mut colors);
    for (r, i, s) in &surfaces {
        let (r, i) = (*r, *i);
        let lit: [Vec3; MAX_PACKET_LIGHTS] = std::array::from_fn(|l| {
            if l < lights && light_rows[l].1[r].lane(i) {
                light_rows[l].0[r].lane(i)
            } else {
                Vec3::ZERO
            }
        });
        let c = tracer.shade_surface(&lane_ray(&rays[r], i), s, 1, 1.0, Shadows::Given(&lit[..lights]));
        colors[r].set_lane(i, c);
    }
    tracer.block = Some(block);
    colors
}

/// The lanes that hit nothing (`NO_HIT`) take the sky sphere's colour, one by one as the
/// single-ray path gives it; without a sky sphere they keep the background.
fn sky_lanes(
    tracer: &mut Tracer,
    rays: &[Ray8; 8],
    ids: &[[u32; 8]; 8],
    rows: usize,
    lanes: usize,
    colors: &mut [V3<F8>; 8],
) {
    if tracer.scene.atmosphere.sky.is_none() {
        return;
    }
    for r in 0..rows {
        for i in (0..lanes).filter(|&i| ids[r][i] == NO_HIT) {
            colors[r].set_lane(i, tracer.shade_hit(&lane_ray(&rays[r], i), None, 1, 1.0));
        }
    }
}

/// The distinct values of `values` among the lanes of `mask`, each with the lanes that hold it,
/// in lane order of first appearance. An iterator, not a function taking a closure: closures
/// are compiled out of line, without AVX2 (see `RowTest`).
struct Groups<'a> {
    values: &'a [u32; 8],
    left: M8,
}

impl Groups<'_> {
    #[inline(always)]
    fn of(values: &[u32; 8], mask: M8) -> Groups<'_> {
        Groups { values, left: mask }
    }
}

impl Iterator for Groups<'_> {
    type Item = (u32, M8);

    #[inline(always)]
    fn next(&mut self) -> Option<(u32, M8)> {
        // One vector test ends the walk, instead of eight lane tests each a branch.
        if !self.left.any() {
            return None;
        }
        let i = (0..8).find(|&i| self.left.lane(i))?;
        let v = self.values[i];
        let group = F8::and(self.left, M8::equal(self.values, v));
        self.left = F8::and(self.left, F8::not(group));
        Some((v, group))
    }
}

/// A block's hit points and normals in structure-of-arrays form, eight lanes per row.
/// Lane `i` of row `r` of `soa` from a singly shaded lane's surface.
fn set_surface_lane(soa: &mut SurfaceRows, r: usize, i: usize, s: &Surface) {
    soa.p[r].set(i, s.p);
    soa.facing[r].set(i, s.facing);
    soa.normal[r].set(i, s.normal);
    soa.valid[r].0[i] = -1;
}

fn shadow_setup(s: &SurfaceRows, rows: usize, light: Vec3, shadowless: bool, out: &mut ShadowRows) {
    #[cfg(target_arch = "x86_64")]
    if has_avx2() {
        // SAFETY: the CPU supports AVX2, checked just above.
        return unsafe { shadow_setup_avx2(s, rows, light, shadowless, out) };
    }
    shadow_setup_generic(s, rows, light, shadowless, out)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn shadow_setup_avx2(s: &SurfaceRows, rows: usize, light: Vec3, shadowless: bool, out: &mut ShadowRows) {
    shadow_setup_generic(s, rows, light, shadowless, out)
}

/// `trace::light_direction` and `trace::shadow_ray` eight lanes at a time: the same operations
/// in the same order, so these rays are bit-identical to the single-ray path's (packet and
/// `--no-packets` images are compared bit for bit in the tests). Done one lane at a time this
/// was about a sixth of the seed scene's frame.
#[inline(always)]
fn shadow_setup_generic(s: &SurfaceRows, rows: usize, light: Vec3, shadowless: bool, out: &mut ShadowRows) {
    let zero = F8::splat(0.0);
    let light8 = V3::splat(light);
    let light_magnitude = F8::splat(V3::from_vec3(light).max_abs());
    for r in 0..rows {
        // A row with no surface (all sky) has no shadow rays: its lanes are neither lit nor
        // traced, as `lit` below would find.
        if !s.valid[r].any() {
            (out.active[r], out.lit[r]) = (M8::default(), M8::default());
            out.t_max[r] = F8::splat(f32::NEG_INFINITY);
            continue;
        }
        let (p, facing, normal) = (s.p[r].v(), s.facing[r].v(), s.normal[r].v());
        // trace::light_direction
        let to_light = light8.sub(p);
        let dist = to_light.dot(to_light).sqrt();
        let l = V3 { x: to_light.x / dist, y: to_light.y / dist, z: to_light.z / dist };
        let lit = F8::and(F8::and(s.valid[r], zero.lt(dist)), F8::and(zero.lt(normal.dot(l)), zero.lt(facing.dot(l))));
        // ray::offset_origin
        let d = p.max_abs() * F8::splat(HIT_ERROR_ULPS) + F8::splat(f32::MIN_POSITIVE * 16.0);
        let towards = zero.le(facing.dot(l));
        let origin = p.add(V3::select(towards, facing.scale(d), facing.neg().scale(d)));
        // ray::shadow_t_max
        let magnitude = origin.max_abs().max(light_magnitude);
        let span = light8.sub(origin);
        let t = (span.dot(span).sqrt() * F8::splat(SHADOW_SHRINK) - magnitude * F8::splat(HIT_ERROR_ULPS)).max(zero);
        let active = if shadowless { M8::default() } else { lit };
        out.rays[r] = Ray8 { o: origin, d: l, inv: l.recip() };
        out.t_max[r] = F8::select(active, t, F8::splat(f32::NEG_INFINITY));
        out.active[r] = active;
        out.lit[r] = lit;
    }
}
