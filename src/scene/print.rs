//! SceneDesc → POV-Ray source that `pov::load_scene` reads back as the same scene (up to float
//! rounding of the transforms). For round-trip tests and for saving generated scenes.
//!
//! Everything is written explicitly: the camera as location/direction/right/up/sky (no
//! `look_at`), colours with filter and transmit, every finish value. Our parser has no `matrix`
//! keyword, so a transform is written as `rotate`, `scale`, `rotate`, `translate`: any affine
//! map's linear part is U·Σ·Vᵀ (singular value decomposition) with U and V rotations and Σ a
//! diagonal scale (negative for a mirror), which covers shear too. Shapes stay in object space
//! and each pattern's transform is written relative to its object (O⁻¹·P), inside the pattern
//! block, so the loader composes it back to P.

use std::fmt::Write;

use glam::{DMat3, DMat4, DVec3};

use crate::scene::desc::{
    BlobShape, Color, ComplexFn, Container, CsgOp, FinishDesc, JuliaFunction, LightDesc, LightKind, NormalDesc,
    NormalPattern, ObjectDesc, PigmentDesc, PigmentPattern, PolyForm, SceneDesc, ShapeDesc, Transform, Turbulence,
};

/// The scene as POV-Ray source (no `#include`s needed).
pub fn to_pov(desc: &SceneDesc) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "#version {};", num(desc.version));
    let g = &desc.global;
    let _ = write!(s, "global_settings {{");
    if let Some(gamma) = g.assumed_gamma {
        let _ = write!(s, " assumed_gamma {}", num(gamma));
    }
    let _ = writeln!(s, " max_trace_level {} ambient_light rgb {} }}", g.max_trace_level, vec(g.ambient_light));
    let _ = writeln!(s, "background {{ {} }}", color(&desc.background));
    let c = &desc.camera;
    let _ = writeln!(
        s,
        "camera {{\n  location {}\n  direction {}\n  right {}\n  up {}\n  sky {}\n}}",
        vec(c.location),
        vec(c.direction),
        vec(c.right),
        vec(c.up),
        vec(c.sky)
    );
    for l in &desc.lights {
        light(&mut s, l);
    }
    atmosphere(&mut s, desc);
    for o in &desc.objects {
        object(&mut s, o);
    }
    s
}

fn object(s: &mut String, o: &ObjectDesc) {
    let inverse = if o.inverse { "  inverse\n" } else { "" };
    if let ShapeDesc::Csg { op, children } = &o.shape {
        // The node's transforms and textures are on its shapes.
        match (op, children.split_first()) {
            (CsgOp::Clip, Some((first, clips))) => {
                let _ = writeln!(s, "object {{");
                object(s, first);
                let _ = writeln!(s, "clipped_by {{");
                clips.iter().for_each(|c| object(s, c));
                let _ = writeln!(s, "}}\n{inverse}}}");
            }
            _ => {
                let _ = writeln!(s, "{} {{", op.keyword());
                children.iter().for_each(|c| object(s, c));
                let _ = writeln!(s, "{inverse}}}");
            }
        }
        return;
    }
    let _ = match &o.shape {
        ShapeDesc::Sphere { center, radius } => write!(s, "sphere {{ {}, {}", vec(*center), num(*radius)),
        ShapeDesc::Plane { normal, distance } => write!(s, "plane {{ {}, {}", vec(*normal), num(*distance)),
        ShapeDesc::Box { corner1, corner2 } => write!(s, "box {{ {}, {}", vec(*corner1), vec(*corner2)),
        ShapeDesc::Triangle { a, b, c } => write!(s, "triangle {{ {}, {}, {}", vec(*a), vec(*b), vec(*c)),
        ShapeDesc::Polygon { points } => {
            let pts: Vec<String> = points.iter().map(|p| vec(*p)).collect();
            write!(s, "polygon {{ {}, {}", points.len(), pts.join(", "))
        }
        ShapeDesc::Cone { base, base_radius, cap, cap_radius, open, cylinder } => {
            let open = if *open { " open" } else { "" };
            if *cylinder {
                write!(s, "cylinder {{ {}, {}, {}{open}", vec(*base), vec(*cap), num(*base_radius))
            } else {
                let (b, r0, c, r1) = (vec(*base), num(*base_radius), vec(*cap), num(*cap_radius));
                write!(s, "cone {{ {b}, {r0}, {c}, {r1}{open}")
            }
        }
        ShapeDesc::Disc { center, normal, radius, hole } => {
            write!(s, "disc {{ {}, {}, {}, {}", vec(*center), vec(*normal), num(*radius), num(*hole))
        }
        ShapeDesc::Torus { major, minor } => write!(s, "torus {{ {}, {}", num(*major), num(*minor)),
        ShapeDesc::Csg { .. } => unreachable!("written above"),
        ShapeDesc::Superellipsoid { e, n } => write!(s, "superellipsoid {{ <{}, {}>", num(*e), num(*n)),
        ShapeDesc::Poly { order, coefficients, sturm, written } => {
            let c = coefficients;
            let sturm = if *sturm { " sturm" } else { "" };
            let list = |c: &[f64]| c.iter().map(|&k| num(k)).collect::<Vec<_>>().join(", ");
            match written {
                // Back from the order-2 poly x², xy, xz, x, y², yz, y, z², z, 1.
                PolyForm::Quadric => write!(
                    s,
                    "quadric {{ <{}, {}, {}>, <{}, {}, {}>, <{}, {}, {}>, {}",
                    num(c[0]),
                    num(c[4]),
                    num(c[7]),
                    num(c[1]),
                    num(c[2]),
                    num(c[5]),
                    num(c[3]),
                    num(c[6]),
                    num(c[8]),
                    num(c[9])
                ),
                PolyForm::Poly => write!(s, "poly {{ {order}, <{}>{sturm}", list(c)),
                other => write!(s, "{} {{ <{}>{sturm}", other.keyword(), list(c)),
            }
        }
        ShapeDesc::Prism { spline, conic, h1, h2, points, open } => {
            let sweep = if *conic { "conic_sweep" } else { "linear_sweep" };
            let open = if *open { " open" } else { "" };
            let (kw, a, b) = (spline.keyword(), num(*h1), num(*h2));
            write!(s, "prism {{ {kw} {sweep} {a}, {b}, {}, {}{open}", points.len(), vec2s(points))
        }
        ShapeDesc::Lathe { spline, points } => {
            write!(s, "lathe {{ {} {}, {}", spline.keyword(), points.len(), vec2s(points))
        }
        ShapeDesc::Sor { points, open } => {
            let open = if *open { " open" } else { "" };
            write!(s, "sor {{ {}, {}{open}", points.len(), vec2s(points))
        }
        ShapeDesc::Julia { param, function, max_iteration, precision, slice } => {
            let v4 = |v: glam::DVec4| format!("<{}, {}, {}, {}>", num(v.x), num(v.y), num(v.z), num(v.w));
            let f = match function {
                JuliaFunction::QuaternionSqr => "quaternion sqr".to_string(),
                JuliaFunction::QuaternionCube => "quaternion cube".to_string(),
                JuliaFunction::Hypercomplex(ComplexFn::Pwr(x, y)) => {
                    format!("hypercomplex pwr({}, {})", num(*x), num(*y))
                }
                JuliaFunction::Hypercomplex(g) => format!("hypercomplex {}", g.keyword().unwrap_or("sqr")),
            };
            write!(
                s,
                "julia_fractal {{ {} {f} max_iteration {max_iteration} precision {} slice {}, {}",
                v4(*param),
                num(*precision),
                v4(slice.0),
                num(slice.1)
            )
        }
        ShapeDesc::Blob { components, threshold } => {
            let _ = write!(s, "blob {{ threshold {}", num(*threshold));
            for c in components {
                let (r, k) = (num(c.radius), num(c.strength));
                let _ = match c.shape {
                    BlobShape::Sphere { center } => write!(s, "\n  sphere {{ {}, {r}, strength {k}", vec(center)),
                    BlobShape::Cylinder { base, cap } => {
                        write!(s, "\n  cylinder {{ {}, {}, {r}, strength {k}", vec(base), vec(cap))
                    }
                };
                let _ = write!(s, "{} }}", modifiers(&c.transform.matrix));
            }
            Ok(())
        }
        ShapeDesc::Mesh { mesh, inside_vector } => {
            mesh_body(s, mesh);
            match inside_vector {
                Some(v) => write!(s, " inside_vector {}", vec(*v)),
                None => Ok(()),
            }
        }
        ShapeDesc::HeightField { field, smooth, water_level } => {
            let quote = |t: &str| t.replace('\\', "\\\\").replace('"', "\\\"");
            let smooth = if *smooth { " smooth" } else { "" };
            let (format, file, water) = (&field.format, quote(&field.file), num(*water_level));
            write!(s, "height_field {{ {format} \"{file}\"{smooth} water_level {water}")
        }
        ShapeDesc::Isosurface { function, container, params } => {
            let c = match container {
                Container::Box { min, max } => format!("box {{ {}, {} }}", vec(*min), vec(*max)),
                Container::Sphere { center, radius } => format!("sphere {{ {}, {} }}", vec(*center), num(*radius)),
            };
            let open = if params.open { " open" } else { "" };
            write!(
                s,
                "isosurface {{ function {{ /* {} instructions */ }} contained_by {{ {c} }} threshold {} accuracy {} \
                 max_gradient {}{open}",
                function.len(),
                num(params.threshold),
                num(params.accuracy),
                num(params.max_gradient)
            )
        }
        ShapeDesc::Parametric { functions, container, params } => {
            let c = match container {
                Container::Box { min, max } => format!("box {{ {}, {} }}", vec(*min), vec(*max)),
                Container::Sphere { center, radius } => format!("sphere {{ {}, {} }}", vec(*center), num(*radius)),
            };
            let lens = functions.iter().map(|f| format!("function {{ /* {} instructions */ }}", f.len()));
            write!(
                s,
                "parametric {{ {} <{}, {}>, <{}, {}> contained_by {{ {c} }} accuracy {} max_gradient {}",
                lens.collect::<Vec<_>>().join(" "),
                num(params.lo.x),
                num(params.lo.y),
                num(params.hi.x),
                num(params.hi.y),
                num(params.accuracy),
                num(params.max_gradient)
            )
        }
        ShapeDesc::Text { font, string, thickness, offset, .. } => {
            let quote = |t: &str| t.replace('\\', "\\\\").replace('"', "\\\"");
            write!(s, "text {{ ttf \"{}\" \"{}\" {}, {}", quote(font), quote(string), num(*thickness), vec(*offset))
        }
    };
    if let Some(src) = (!o.source.file.is_empty()).then_some(&o.source) {
        let _ = write!(s, " // {}:{}:{}", src.file.replace(['\n', '\r'], " "), src.line, src.col);
    }
    let object_inverse = o.transform.inverse;
    let t = &o.texture;
    let _ = write!(s, "\n  texture {{\n    ");
    pigment(s, &t.pigment, &object_inverse);
    if let Some(n) = &t.normal {
        let _ = write!(s, "\n    ");
        normal(s, n, &object_inverse);
    }
    let _ = write!(s, "\n    ");
    finish(s, &t.finish);
    let _ = write!(s, "\n  }}\n  interior {{ ior {}", num(o.interior.ior));
    if let Some(f) = &o.interior.fade {
        let _ = write!(s, " fade_distance {} fade_power {} fade_color {}", num(f.distance), num(f.power), vec(f.color));
    }
    let _ = writeln!(s, " }}");
    let _ = writeln!(s, "  {}\n{inverse}}}", modifiers(&o.transform.matrix).trim_start());
}

/// A light with every modifier it has (the kinds' defaults written out).
fn light(s: &mut String, l: &LightDesc) {
    let _ = write!(s, "light_source {{ {} color rgb {}", vec(l.position), vec(l.color));
    if l.kind != LightKind::Point {
        let (r, f, t) = l.spot_params();
        let kind = if l.kind == LightKind::Spot { "spotlight" } else { "cylinder" };
        let _ = write!(s, " {kind} radius {} falloff {} tightness {}", num(r), num(f), num(t));
    }
    if l.parallel {
        let _ = write!(s, " parallel");
    }
    if l.kind != LightKind::Point || l.parallel {
        let _ = write!(s, " point_at {}", vec(l.point_at));
    }
    if l.fade_distance > 0.0 {
        let _ = write!(s, " fade_distance {} fade_power {}", num(l.fade_distance), num(l.fade_power));
    }
    if let Some(a) = &l.area {
        let _ = write!(s, " area_light {}, {}, {}, {}", vec(a.axis1), vec(a.axis2), a.size1, a.size2);
        if let Some(n) = a.adaptive {
            let _ = write!(s, " adaptive {n}");
        }
        for (on, word) in [(a.jitter, "jitter"), (a.circular, "circular"), (a.orient, "orient")] {
            if on {
                let _ = write!(s, " {word}");
            }
        }
    }
    if l.shadowless {
        let _ = write!(s, " shadowless");
    }
    if !l.media_interaction {
        let _ = write!(s, " media_interaction off");
    }
    if l.media_attenuation {
        let _ = write!(s, " media_attenuation on");
    }
    let _ = writeln!(s, " }}");
}

/// `sky_sphere`, fogs and rainbows, in world space.
fn atmosphere(s: &mut String, desc: &SceneDesc) {
    if let Some(sky) = &desc.sky_sphere {
        let _ = write!(s, "sky_sphere {{");
        for p in &sky.pigments {
            let _ = write!(s, "\n  ");
            pigment(s, p, &DMat4::IDENTITY);
        }
        let _ = writeln!(s, "\n  emission rgb {}\n}}", vec(sky.emission));
    }
    for f in &desc.fogs {
        let _ = writeln!(
            s,
            "fog {{ fog_type {} distance {} {} fog_offset {} fog_alt {} up {} turbulence {} }}",
            f.fog_type,
            num(f.distance),
            color(&f.color),
            num(f.offset),
            num(f.alt),
            vec(f.up),
            vec(f.turbulence)
        );
    }
    for r in &desc.rainbows {
        let entries: Vec<String> =
            r.color_map.iter().map(|e| format!("[{} {}]", num(e.value), color(&e.color))).collect();
        let _ = writeln!(
            s,
            "rainbow {{ direction {} angle {} width {} distance {} jitter {} up {} arc_angle {} falloff_angle {} \
             color_map {{ {} }} }}",
            vec(r.direction),
            num(r.angle),
            num(r.width),
            num(r.distance),
            num(r.jitter),
            vec(r.up),
            num(r.arc_angle),
            num(r.falloff_angle),
            entries.join(" ")
        );
    }
}

fn pigment(s: &mut String, p: &PigmentDesc, object_inverse: &DMat4) {
    if let PigmentPattern::Layered(list) = &p.pattern {
        // Layers belong to textures; printed as the bottom layer alone (lossy).
        if let Some(bottom) = list.first() {
            return pigment(s, bottom, object_inverse);
        }
    }
    let _ = write!(s, "pigment {{ ");
    let outer = p;
    let _ = match &p.pattern {
        PigmentPattern::Solid(c) => write!(s, "{}", color(c)),
        PigmentPattern::Checker(a, b) => write!(s, "checker {} {}", color(a), color(b)),
        PigmentPattern::Wood(map) => {
            let entries: Vec<String> = map.iter().map(|e| format!("[{} {}]", num(e.value), color(&e.color))).collect();
            write!(s, "wood color_map {{ {} }}", entries.join(" "))
        }
        PigmentPattern::Mapped(pd, map) => {
            let entries: Vec<String> = map.iter().map(|e| format!("[{} {}]", num(e.value), color(&e.color))).collect();
            write!(s, "{} color_map {{ {} }}", pattern_text(pd), entries.join(" "))
        }
        PigmentPattern::PigmentMap(pd, entries) => {
            let _ = write!(s, "{} pigment_map {{ ", pattern_text(pd));
            for (v, p) in entries {
                let _ = write!(s, "[{} ", num(*v));
                // Inner pigments are read inside this one's transform: printed relative to it.
                pigment(s, p, &outer.transform.inverse);
                let _ = write!(s, "] ");
            }
            write!(s, "}}")
        }
        PigmentPattern::List(pd, list) => {
            // The list right after the keyword, its options (`brick_size`, `mortar`) after it,
            // as POV-Ray reads them.
            let text = pattern_text(pd);
            let (keyword, options) = text.split_once(' ').unwrap_or((&text, ""));
            let _ = write!(s, "{keyword} ");
            for p in list {
                pigment(s, p, &outer.transform.inverse);
                let _ = write!(s, " ");
            }
            write!(s, "{options}")
        }
        PigmentPattern::Layered(_) => unreachable!("handled above"),
        PigmentPattern::ImageMap(im) => write!(s, "image_map {{ {} }}", image_text(im)),
    };
    turbulence(s, p.turbulence.as_ref());
    let _ = write!(s, "{} }}", modifiers(&(*object_inverse * p.transform.matrix)));
}

fn normal(s: &mut String, n: &NormalDesc, object_inverse: &DMat4) {
    let _ = match n.pattern {
        NormalPattern::Bumps(amount) => write!(s, "normal {{ bumps {}", num(amount)),
        NormalPattern::Pattern(ref pd, amount) => {
            let _ = write!(s, "normal {{ {} bump_size {}", pattern_text(pd), num(amount));
            if n.accuracy != 0.02 {
                let _ = write!(s, " accuracy {}", num(n.accuracy));
            }
            if !n.slope_map.is_empty() {
                let _ = write!(s, " slope_map {{");
                for e in &n.slope_map {
                    let _ = write!(s, " [{}, <{}, {}>]", num(e.value), num(e.height), num(e.slope));
                }
                let _ = write!(s, " }}");
            }
            Ok(())
        }
        NormalPattern::Map(ref pd, ref entries) => {
            let _ = write!(s, "normal {{ {} normal_map {{ ", pattern_text(pd));
            for (v, e) in entries {
                let _ = write!(s, "[{} ", num(*v));
                // Inner normals are read inside this one's transform: printed relative to it.
                normal(s, e, &n.transform.inverse);
                let _ = write!(s, "] ");
            }
            write!(s, "}}")
        }
    };
    turbulence(s, n.turbulence.as_ref());
    let _ = write!(s, "{} }}", modifiers(&(*object_inverse * n.transform.matrix)));
}

fn albedo(set: bool) -> &'static str {
    if set {
        "albedo "
    } else {
        ""
    }
}

/// The inside of an `image_map { }` / `image_pattern { }` block.
fn image_text(im: &crate::scene::desc::ImageMapDesc) -> String {
    use crate::scene::desc::ImageMapping;
    let map_type = match im.mapping {
        ImageMapping::Planar => 0,
        ImageMapping::Spherical => 1,
        ImageMapping::Cylindrical => 2,
        ImageMapping::Torus => 5,
    };
    let mut out = format!(
        "{} \"{}\" map_type {map_type} interpolate {}",
        im.format,
        im.file.replace('"', "\\\""),
        im.interpolate
    );
    for (word, list) in [("filter", &im.filter), ("transmit", &im.transmit)] {
        for (i, v) in list {
            match i {
                Some(i) => out += &format!(" {word} {i} {}", num(*v)),
                None => out += &format!(" {word} all {}", num(*v)),
            }
        }
    }
    for (flag, word) in [(im.once, " once"), (im.use_index, " use_index"), (im.use_alpha, " use_alpha")] {
        if flag {
            out += word;
        }
    }
    out
}

/// A fractal pattern's keywords.
fn fractal_text(f: &crate::scene::desc::Fractal) -> String {
    use crate::scene::desc::FractalKind as F;
    let c = |c: [f64; 2]| format!("<{}, {}>", num(c[0]), num(c[1]));
    let head = match f.kind {
        F::Mandel { exponent } => format!("mandel {} exponent {exponent}", f.iterations),
        F::Julia { c: k, exponent } => format!("julia {}, {} exponent {exponent}", c(k), f.iterations),
        F::MagnetMandel { magnet } => format!("magnet {magnet} mandel {}", f.iterations),
        F::MagnetJulia { magnet, c: k } => format!("magnet {magnet} julia {}, {}", c(k), f.iterations),
    };
    format!("{head} interior {}, {} exterior {}, {}", f.interior.0, num(f.interior.1), f.exterior.0, num(f.exterior.1))
}

/// A pattern keyword with its parameters and value modifiers.
fn pattern_text(p: &crate::scene::desc::PatternDesc) -> String {
    use crate::scene::desc::{PatternKind as K, Warp, Wave};
    let v = |d: glam::DVec3| format!("<{}, {}, {}>", num(d.x), num(d.y), num(d.z));
    let mut out = match &p.kind {
        K::Function(f) => format!("function {{ /* {} instructions */ }}", f.len()),
        &K::Gradient(d) => format!("gradient {}", v(d)),
        K::Bozo => "bozo".into(),
        K::Granite => "granite".into(),
        K::Marble => "marble".into(),
        &K::Agate { turb } => format!("agate agate_turb {}", num(turb)),
        &K::Crackle { form, metric, offset, solid } => format!(
            "crackle form {} metric {} offset {}{}",
            v(form),
            num(metric),
            num(offset),
            if solid { " solid" } else { "" }
        ),
        K::Cells => "cells".into(),
        K::Wrinkles => "wrinkles".into(),
        K::Dents => "dents".into(),
        K::Leopard => "leopard".into(),
        K::Ripples => "ripples".into(),
        K::Waves => "waves".into(),
        K::Radial => "radial".into(),
        K::Onion => "onion".into(),
        &K::Spiral1(n) => format!("spiral1 {}", num(n)),
        &K::Spiral2(n) => format!("spiral2 {}", num(n)),
        &K::Brick { size, mortar } => format!("brick brick_size {} mortar {}", v(size), num(mortar)),
        K::Hexagon => "hexagon".into(),
        K::Checker => "checker".into(),
        K::Boxed => "boxed".into(),
        K::Cylindrical => "cylindrical".into(),
        K::Spherical => "spherical".into(),
        K::Planar => "planar".into(),
        &K::Quilted { c0, c1 } => format!("quilted control0 {} control1 {}", num(c0), num(c1)),
        K::Fractal(f) => fractal_text(f),
        K::Density { file, interpolate, .. } => {
            format!("density_file df3 \"{}\" interpolate {interpolate}", file.replace('"', "\\\""))
        }
        K::PigmentPattern(pig) => {
            let mut inner = String::new();
            pigment(&mut inner, pig, &DMat4::IDENTITY);
            format!("pigment_pattern {}", inner.trim_start_matches("pigment "))
        }
        K::Wood => "wood".into(),
        K::Average => "average".into(),
        K::Image(ref im) => format!("image_pattern {{ {} }}", image_text(im)),
        // The object itself is not kept: the printed scene shows where it was.
        K::Object(_) => "object { /* a solid */ }".into(),
    };
    let wave = match p.wave {
        Wave::Ramp => "ramp_wave".to_string(),
        Wave::Triangle => "triangle_wave".into(),
        Wave::Sine => "sine_wave".into(),
        Wave::Scallop => "scallop_wave".into(),
        Wave::Cubic => "cubic_wave".into(),
        Wave::Poly(e) => format!("poly_wave {}", num(e)),
    };
    if p.kind.list_len().is_none() && !matches!(p.kind, K::Average) {
        let _ = write!(out, " {wave} frequency {} phase {}", num(p.frequency), num(p.phase));
    }
    for w in &p.warps {
        let _ = match *w {
            Warp::Turbulence(t) => write!(
                out,
                " warp {{ turbulence {} octaves {} omega {} lambda {} }}",
                v(t.amount),
                t.octaves,
                num(t.omega),
                num(t.lambda)
            ),
            Warp::Repeat { dir, offset, flip } => {
                write!(out, " warp {{ repeat {} offset {} flip {} }}", v(dir), v(offset), v(flip))
            }
            Warp::BlackHole { center, radius, strength, falloff, inverse } => write!(
                out,
                " warp {{ black_hole {}, {} strength {} falloff {}{} }}",
                v(center),
                num(radius),
                num(strength),
                num(falloff),
                if inverse { " inverse" } else { "" }
            ),
        };
    }
    out
}

fn finish(s: &mut String, f: &FinishDesc) {
    let _ = write!(
        s,
        "finish {{ ambient rgb {} diffuse {}{} brilliance {} phong {}{} phong_size {} specular {}{} roughness {} \
         reflection rgb {} }}",
        vec(f.ambient),
        albedo(f.albedo.diffuse),
        num(f.diffuse),
        num(f.brilliance),
        albedo(f.albedo.phong),
        num(f.phong),
        num(f.phong_size),
        albedo(f.albedo.specular),
        num(f.specular),
        num(f.roughness),
        vec(f.reflection)
    );
    // What the seed's finishes do not use is printed only where set, so their text stays.
    s.pop();
    if f.metallic != 0.0 {
        let _ = write!(s, " metallic {}", num(f.metallic));
    }
    if f.emission != DVec3::ZERO {
        let _ = write!(s, " emission rgb {}", vec(f.emission));
    }
    if f.conserve_energy {
        s.push_str(" conserve_energy");
    }
    let variable = f.reflection_min.is_some() || f.reflection_exponent != 1.0 || f.reflection_metallic != 0.0;
    if variable {
        let min = f.reflection_min.unwrap_or(f.reflection);
        let _ = write!(
            s,
            " reflection {{ rgb {}, rgb {} fresnel {} falloff {} exponent {} metallic {} }}",
            vec(min),
            vec(f.reflection),
            u8::from(f.reflection_fresnel),
            num(f.reflection_falloff),
            num(f.reflection_exponent),
            num(f.reflection_metallic)
        );
    }
    s.push('}');
}

fn turbulence(s: &mut String, t: Option<&Turbulence>) {
    if let Some(t) = t {
        let _ = write!(
            s,
            " turbulence {} octaves {} omega {} lambda {}",
            vec(t.amount),
            t.octaves,
            num(t.omega),
            num(t.lambda)
        );
    }
}

/// `m` as ` rotate … scale … rotate … translate …` (empty for the identity).
fn modifiers(m: &DMat4) -> String {
    if *m == DMat4::IDENTITY {
        return String::new();
    }
    let d = decompose(m);
    let mut out = String::new();
    for (word, v, skip) in [
        ("rotate", d.rotate_first, DVec3::ZERO),
        ("scale", d.scale, DVec3::ONE),
        ("rotate", d.rotate_then, DVec3::ZERO),
        ("translate", d.translate, DVec3::ZERO),
    ] {
        if v != skip {
            let _ = write!(out, " {word} {}", vec(v));
        }
    }
    out
}

/// An affine map as POV-Ray modifiers, applied in this order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decomposed {
    /// Euler angles in degrees (about x, then y, then z), POV-Ray's `rotate`.
    pub rotate_first: DVec3,
    pub scale: DVec3,
    pub rotate_then: DVec3,
    pub translate: DVec3,
}

impl Decomposed {
    /// The matrix the loader builds from these modifiers.
    pub fn matrix(&self) -> DMat4 {
        DMat4::from_translation(self.translate)
            * euler_matrix(self.rotate_then)
            * DMat4::from_scale(self.scale)
            * euler_matrix(self.rotate_first)
    }
}

/// `rotate <a, b, c>` (degrees) as the loader builds it.
fn euler_matrix(deg: DVec3) -> DMat4 {
    let r = deg * (std::f64::consts::PI / 180.0);
    DMat4::from_rotation_z(r.z) * DMat4::from_rotation_y(r.y) * DMat4::from_rotation_x(r.x)
}

/// Splits the linear part of `m` as U·Σ·Vᵀ (one-sided Jacobi SVD, f64), U and V proper rotations.
pub fn decompose(m: &DMat4) -> Decomposed {
    let lin = DMat3::from_mat4(*m);
    let mut a = [lin.x_axis, lin.y_axis, lin.z_axis];
    let mut v = [DVec3::X, DVec3::Y, DVec3::Z];
    // Each sweep rotates column pairs until they are orthogonal; 3×3 converges in a few sweeps.
    for _ in 0..60 {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let alpha = a[p].length_squared();
            let beta = a[q].length_squared();
            let gamma = a[p].dot(a[q]);
            if gamma == 0.0 || gamma.abs() <= 1e-17 * (alpha * beta).sqrt() {
                continue;
            }
            rotated = true;
            let zeta = (beta - alpha) / (2.0 * gamma);
            let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
            let c = 1.0 / (1.0 + t * t).sqrt();
            let s = c * t;
            let (ap, aq) = (a[p], a[q]);
            a[p] = c * ap - s * aq;
            a[q] = s * ap + c * aq;
            let (vp, vq) = (v[p], v[q]);
            v[p] = c * vp - s * vq;
            v[q] = s * vp + c * vq;
        }
        if !rotated {
            break;
        }
    }
    let mut sigma = DVec3::new(a[0].length(), a[1].length(), a[2].length());
    let mut u = [0, 1, 2].map(|i| if sigma[i] > 0.0 { a[i] / sigma[i] } else { DVec3::ZERO });
    // A zero singular value (never from the loader, which refuses scale 0) gets any completing axis.
    for i in 0..3 {
        if sigma[i] == 0.0 {
            u[i] = u[(i + 1) % 3].cross(u[(i + 2) % 3]).try_normalize().unwrap_or(DVec3::X);
        }
    }
    let mut u_mat = DMat3::from_cols(u[0], u[1], u[2]);
    let v_mat = DMat3::from_cols(v[0], v[1], v[2]);
    if u_mat.determinant() < 0.0 {
        // A mirror: fold the reflection into the scale.
        sigma.x = -sigma.x;
        u_mat.x_axis = -u_mat.x_axis;
    }
    Decomposed {
        rotate_first: euler_degrees(&v_mat.transpose()),
        scale: sigma,
        rotate_then: euler_degrees(&u_mat),
        translate: m.w_axis.truncate(),
    }
}

/// Angles `<a, b, c>` (degrees) with `R = Rz(c)·Ry(b)·Rx(a)`.
fn euler_degrees(r: &DMat3) -> DVec3 {
    let at = |row: usize, col: usize| r.col(col)[row];
    let cos_b = (at(0, 0) * at(0, 0) + at(1, 0) * at(1, 0)).sqrt();
    let b = (-at(2, 0)).atan2(cos_b);
    let (a, c) = if cos_b > 1e-12 {
        (at(2, 1).atan2(at(2, 2)), at(1, 0).atan2(at(0, 0)))
    } else {
        // Gimbal lock: only a ± c is defined; put it all in a.
        ((-at(1, 2)).atan2(at(1, 1)), 0.0)
    };
    DVec3::new(a, b, c) * (180.0 / std::f64::consts::PI)
}

/// Shortest decimal that reads back as the same f64, never in exponent form (the lexer's
/// numbers are plain decimals).
/// A mesh as `mesh2` when its faces are all flat or all smooth (its indices as they are), else
/// as `mesh` triangles (each with its own vertices, as `mesh` reads them).
fn mesh_body(s: &mut String, mesh: &crate::scene::desc::MeshDesc) {
    let smooth = mesh.faces.iter().filter(|f| f.normals.is_some()).count();
    let list = |s: &mut String, name: &str, items: &mut dyn Iterator<Item = String>, n: usize| {
        let _ = write!(s, "\n  {name} {{ {n}");
        for it in items {
            let _ = write!(s, ", {it}");
        }
        let _ = write!(s, " }}");
    };
    let ix = |i: [u32; 3]| format!("<{}, {}, {}>", i[0], i[1], i[2]);
    if smooth == 0 || smooth == mesh.faces.len() {
        let _ = write!(s, "mesh2 {{");
        list(s, "vertex_vectors", &mut mesh.vertices.iter().map(|v| vec(*v)), mesh.vertices.len());
        if smooth > 0 {
            list(s, "normal_vectors", &mut mesh.normals.iter().map(|v| vec(*v)), mesh.normals.len());
        }
        list(s, "face_indices", &mut mesh.faces.iter().map(|f| ix(f.vertices)), mesh.faces.len());
        if smooth > 0 {
            let normals = &mut mesh.faces.iter().filter_map(|f| f.normals.map(ix));
            list(s, "normal_indices", normals, mesh.faces.len());
        }
        return;
    }
    let _ = write!(s, "mesh {{");
    for f in &mesh.faces {
        let v = |k: usize| vec(mesh.vertices[f.vertices[k] as usize]);
        let _ = match f.normals {
            Some(n) => {
                let n = |k: usize| vec(mesh.normals[n[k] as usize]);
                write!(s, "\n  smooth_triangle {{ {}, {}, {}, {}, {}, {} }}", v(0), n(0), v(1), n(1), v(2), n(2))
            }
            None => write!(s, "\n  triangle {{ {}, {}, {} }}", v(0), v(1), v(2)),
        };
    }
}

fn num(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        // Not expressible in the scene language; 0 keeps the output parseable.
        "0".to_string()
    }
}

/// 2-D points as `<u, v>, ...`.
fn vec2s(points: &[glam::DVec2]) -> String {
    let pts: Vec<String> = points.iter().map(|p| format!("<{}, {}>", num(p.x), num(p.y))).collect();
    pts.join(", ")
}

fn vec(v: DVec3) -> String {
    format!("<{}, {}, {}>", num(v.x), num(v.y), num(v.z))
}

fn color(c: &Color) -> String {
    format!("color rgb {} filter {} transmit {}", vec(c.rgb), num(c.filter), num(c.transmit))
}

/// The transform POV-Ray's modifiers from `decompose` rebuild: for checks.
pub fn recomposed(t: &Transform) -> DMat4 {
    decompose(&t.matrix).matrix()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decompose_rebuilds_rotation_scale_shear_and_mirror() {
        let cases = [
            DMat4::IDENTITY,
            DMat4::from_rotation_y(0.3) * DMat4::from_scale(DVec3::new(1.0, 2.0, 3.0)),
            DMat4::from_scale(DVec3::new(1.0, 2.0, 3.0)) * DMat4::from_rotation_x(0.7) * DMat4::from_rotation_z(-1.1),
            DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0)) * DMat4::from_rotation_y(0.2),
            DMat4::from_translation(DVec3::new(1e6, -3.0, 2.5)) * DMat4::from_rotation_x(std::f64::consts::FRAC_PI_2),
            DMat4::from_rotation_y(std::f64::consts::FRAC_PI_2) * DMat4::from_scale(DVec3::splat(1e-4)),
            DMat4::from_scale(DVec3::new(2.0, 2.0, 0.5)),
        ];
        for m in cases {
            let back = decompose(&m).matrix();
            let err = (back - m).to_cols_array().iter().map(|v| v.abs()).fold(0.0, f64::max);
            let size = m.to_cols_array().iter().map(|v| v.abs()).fold(0.0, f64::max);
            assert!(err <= 1e-12 * size, "{m:?} → {:?}, error {err}", decompose(&m));
        }
    }

    #[test]
    fn prints_numbers_without_exponents() {
        assert_eq!(num(1e-7), "0.0000001");
        assert_eq!(num(-2.5), "-2.5");
        assert_eq!(num(f64::NAN), "0");
    }
}
