//! Pigments, normals, patterns and finishes, each pattern's transform relative to its object.

use std::fmt::Write;

use glam::{DMat4, DVec3};

use super::transform::modifiers;
use super::{color, num, vec};
use crate::desc::{FinishDesc, NormalDesc, NormalPattern, PigmentDesc, PigmentPattern, Turbulence};

pub(super) fn pigment(s: &mut String, p: &PigmentDesc, object_inverse: &DMat4) {
    if let PigmentPattern::Layered(list) = &p.pattern {
        // Layers belong to textures (`texture_blocks` writes one block per layer); a layered
        // pigment elsewhere (a sky sphere's are a list) is printed as its bottom layer.
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
            let (head, tail) = list_head(pd);
            let _ = write!(s, "{head} ");
            for p in list {
                pigment(s, p, &outer.transform.inverse);
                let _ = write!(s, " ");
            }
            write!(s, "{tail}")
        }
        PigmentPattern::Layered(_) => unreachable!("handled above"),
        PigmentPattern::ImageMap(im) => write!(s, "image_map {{ {} }}", image_text(im)),
    };
    turbulence(s, p.turbulence.as_ref());
    let _ = write!(s, "{} }}", modifiers(&(*object_inverse * p.transform.matrix)));
}

pub(super) fn normal(s: &mut String, n: &NormalDesc, object_inverse: &DMat4) {
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
fn image_text(im: &crate::desc::ImageMapDesc) -> String {
    use crate::desc::ImageMapping;
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
fn fractal_text(f: &crate::desc::Fractal) -> String {
    use crate::desc::FractalKind as F;
    let c = |c: [f64; 2]| format!("<{}, {}>", num(c[0]), num(c[1]));
    let head = match f.kind {
        F::Mandel { exponent } => format!("mandel {} exponent {exponent}", f.iterations),
        F::Julia { c: k, exponent } => format!("julia {}, {} exponent {exponent}", c(k), f.iterations),
        F::MagnetMandel { magnet } => format!("magnet {magnet} mandel {}", f.iterations),
        F::MagnetJulia { magnet, c: k } => format!("magnet {magnet} julia {}, {}", c(k), f.iterations),
    };
    format!("{head} interior {}, {} exterior {}, {}", f.interior.0, num(f.interior.1), f.exterior.0, num(f.exterior.1))
}

/// A list pattern as the text before its list and the text after it. The list comes right
/// after the keyword and its options (`brick_size`, `mortar`) after it, as POV-Ray reads them;
/// the `object` pattern's list is inside its block, after the object.
pub(super) fn list_head(pd: &crate::desc::PatternDesc) -> (String, String) {
    let text = pattern_text(pd);
    if let crate::desc::PatternKind::Object(solid) = &pd.kind {
        let written = object_text(solid);
        let rest = text.strip_prefix(&written).unwrap_or("");
        return (written.trim_end_matches('}').to_string(), format!("}}{rest}"));
    }
    let (keyword, options) = text.split_once(' ').unwrap_or((&text, ""));
    (keyword.to_string(), options.to_string())
}

/// The `object` pattern's block without its list: `object { OBJECT }` (a union of the parts
/// it was made of), each part's shape and transform; their textures do not matter to it.
fn object_text(solid: &crate::desc::SolidRef) -> String {
    let parts = solid.0.objects();
    let mut out = String::from("object { ");
    if parts.len() != 1 {
        out.push_str(
            "union {
",
        );
    }
    for o in parts {
        super::shapes::solid(&mut out, o);
    }
    if parts.len() != 1 {
        out.push_str(
            "}
",
        );
    }
    out.push('}');
    out
}

/// A pattern keyword with its parameters and value modifiers.
pub(super) fn pattern_text(p: &crate::desc::PatternDesc) -> String {
    use crate::desc::{PatternKind as K, Warp, WarpMap, Wave};
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
        K::Slope(sl) => {
            let at = if sl.point_at { "point_at " } else { "" };
            let mut t = format!("slope {{ {at}{}, {}, {}", vec(sl.direction), num(sl.range[0]), num(sl.range[1]));
            if let Some((a, r)) = sl.altitude {
                t += &format!(" altitude {}, {}, {}", vec(a), num(r[0]), num(r[1]));
            }
            t + " }"
        }
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
        K::Object(solid) => object_text(solid),
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
    // A warp written after transforms: those transforms before it (what changed since the
    // previous warp's), and their undoing after the last, so each warp works in the same
    // space when the printed scene is read again.
    let mut space = DMat4::IDENTITY;
    for placed in p.warps.iter().filter(|w| !w.inherited) {
        if placed.space.matrix != space {
            out.push_str(&modifiers(&(placed.space.matrix * space.inverse())));
            space = placed.space.matrix;
        }
        let _ = match placed.warp {
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
            Warp::BlackHole { center, radius, strength, falloff, inverse, repeat } => write!(
                out,
                " warp {{ black_hole {}, {} strength {} falloff {}{} repeat {} }}",
                v(center),
                num(radius),
                num(strength),
                num(falloff),
                if inverse { " inverse" } else { "" },
                v(repeat)
            ),
            Warp::Mapping { map, orientation, dist_exp } => match map {
                WarpMap::Planar { distance } => write!(out, " warp {{ planar {}, {} }}", v(orientation), num(distance)),
                WarpMap::Cubic => write!(out, " warp {{ cubic }}"),
                WarpMap::Toroidal { major_radius } => write!(
                    out,
                    " warp {{ toroidal orientation {} dist_exp {} major_radius {} }}",
                    v(orientation),
                    num(dist_exp),
                    num(major_radius)
                ),
                WarpMap::Cylindrical | WarpMap::Spherical => write!(
                    out,
                    " warp {{ {} orientation {} dist_exp {} }}",
                    if map == WarpMap::Cylindrical { "cylindrical" } else { "spherical" },
                    v(orientation),
                    num(dist_exp)
                ),
            },
        };
    }
    out.push_str(&modifiers(&space.inverse()));
    out
}

pub(super) fn finish(s: &mut String, f: &FinishDesc) {
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
