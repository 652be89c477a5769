//! `sky_sphere`, `fog`, `rainbow` → `SceneDesc` (`scene::atmosphere` builds and evaluates
//! them); atmospheric `media` is warned about, once per block.

use glam::DVec3;

use super::textures::sorted_map;
use super::Lowerer;
use crate::desc::{FogDesc, RainbowDesc, SkySphereDesc, Transform};
use crate::pov::ast::{AtmoItem, Atmosphere, AtmosphereKind};
use crate::pov::source::{Diag, PResult, Span};

impl Lowerer<'_> {
    pub(super) fn atmosphere(&mut self, a: &Atmosphere) -> PResult<()> {
        match a.kind {
            AtmosphereKind::SkySphere => {
                let sky = self.sky_sphere(a)?;
                self.scene.sky_sphere = Some(sky);
            }
            AtmosphereKind::Fog => {
                let fog = self.fog(a)?;
                self.scene.fogs.push(fog);
            }
            AtmosphereKind::Rainbow => {
                let rainbow = self.rainbow(a)?;
                self.scene.rainbows.push(rainbow);
            }
        }
        Ok(())
    }

    pub(super) fn media_warning(&mut self, span: Span) {
        self.not_modelled("media", span);
    }

    fn transforms_of(&mut self, a: &Atmosphere) -> PResult<Transform> {
        let mut all = Transform::default();
        for item in &a.items {
            if let AtmoItem::Transform(t) = item {
                all = all.then(&self.transform(t)?);
            }
        }
        Ok(all)
    }

    fn sky_sphere(&mut self, a: &Atmosphere) -> PResult<SkySphereDesc> {
        let tr = self.transforms_of(a)?;
        let mut sky = SkySphereDesc { pigments: Vec::new(), emission: DVec3::ONE };
        for item in &a.items {
            match item {
                AtmoItem::Pigment(p) => {
                    let mut p = self.pigment(p)?;
                    p.transform = p.transform.then(&tr);
                    sky.pigments.push(p);
                }
                AtmoItem::Value(_, e, _) => sky.emission = self.color(e)?.rgb,
                _ => {}
            }
        }
        if sky.pigments.is_empty() {
            return Err(Diag::new(a.span, "sky_sphere needs a pigment"));
        }
        Ok(sky)
    }

    fn fog(&mut self, a: &Atmosphere) -> PResult<FogDesc> {
        let mut fog = FogDesc::default();
        let mut distance_given = false;
        for item in &a.items {
            match item {
                AtmoItem::Color(e) => fog.color = self.color(e)?,
                AtmoItem::Value(word, e, span) => match *word {
                    "fog_type" => {
                        let t = self.float(e)?;
                        if t != 1.0 && t != 2.0 {
                            return Err(Diag::new(e.span, "fog_type must be 1 (constant) or 2 (ground fog)"));
                        }
                        fog.fog_type = t as u32;
                    }
                    "distance" => {
                        fog.distance = self.float(e)?;
                        distance_given = true;
                    }
                    "fog_offset" => fog.offset = self.float(e)?,
                    "fog_alt" => fog.alt = self.float(e)?,
                    "up" => fog.up = self.vec3(e)?,
                    "turbulence" => {
                        fog.turbulence = match self.eval(e)? {
                            crate::pov::value::Value::Float(f) => DVec3::splat(f),
                            v => v.as_vec3(e.span)?,
                        };
                        if fog.turbulence != DVec3::ZERO {
                            self.not_modelled("fog turbulence", *span);
                        }
                    }
                    _ => {
                        self.float(e)?;
                    }
                },
                AtmoItem::Transform(t) => {
                    let m = self.transform(t)?.matrix;
                    fog.up = m.transform_vector3(fog.up);
                }
                _ => {}
            }
        }
        if !distance_given {
            return Err(Diag::new(a.span, "fog needs a `distance`"));
        }
        if fog.fog_type == 2 && fog.alt <= 0.0 {
            return Err(Diag::new(a.span, "ground fog (fog_type 2) needs a positive `fog_alt`"));
        }
        Ok(fog)
    }

    fn rainbow(&mut self, a: &Atmosphere) -> PResult<RainbowDesc> {
        let mut r = RainbowDesc::default();
        for item in &a.items {
            match item {
                AtmoItem::ColorMap(m) => r.color_map = sorted_map(&self.color_map(m)?),
                AtmoItem::Value(word, e, _) => match *word {
                    "direction" => r.direction = self.vec3(e)?,
                    "up" => r.up = self.vec3(e)?,
                    "angle" => r.angle = self.float(e)?,
                    "width" => r.width = self.float(e)?,
                    "distance" => r.distance = self.float(e)?,
                    "jitter" => r.jitter = self.float(e)?,
                    "arc_angle" => r.arc_angle = self.float(e)?,
                    _ => r.falloff_angle = self.float(e)?,
                },
                AtmoItem::Transform(t) => {
                    let m = self.transform(t)?.matrix;
                    r.direction = m.transform_vector3(r.direction);
                    r.up = m.transform_vector3(r.up);
                }
                _ => {}
            }
        }
        if r.color_map.is_empty() {
            return Err(Diag::new(a.span, "rainbow needs a color_map"));
        }
        Ok(r)
    }
}
