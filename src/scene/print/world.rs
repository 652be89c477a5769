//! Lights and the atmosphere (`sky_sphere`, fogs, rainbows), in world space.

use std::fmt::Write;

use glam::DMat4;

use super::textures::pigment;
use super::{color, num, vec};
use crate::desc::{LightDesc, LightKind, SceneDesc};

/// A light with every modifier it has (the kinds' defaults written out).
pub(super) fn light(s: &mut String, l: &LightDesc) {
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
pub(super) fn atmosphere(s: &mut String, desc: &SceneDesc) {
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
