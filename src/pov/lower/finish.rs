//! `finish { }` and `interior { }` blocks → `FinishDesc`, `InteriorDesc` (POV-Ray 3.4.6.3,
//! 3.4.8.1). A block that starts with a declared name copies it, then applies the rest in
//! written order.

use glam::DVec3;

use super::Lowerer;
use crate::desc::{FadeDesc, FinishDesc, InteriorDesc};
use crate::pov::ast::{Finish, FinishItem, FinishKey, Interior, InteriorItem};
use crate::pov::source::{Diag, PResult};
use crate::pov::value::Value;

impl Lowerer<'_> {
    pub(super) fn finish_block(&mut self, f: &Finish) -> PResult<FinishDesc> {
        let mut out = self.default_texture.finish;
        for item in &f.items {
            match item {
                FinishItem::Base(e) => match self.declared(e)? {
                    Some(Value::Finish(base)) => out = *base,
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared finish")),
                    None => return Err(Diag::new(e.span, "expected a declared finish")),
                },
                FinishItem::Set(key, e) => match key {
                    FinishKey::Ambient => out.ambient = self.color(e)?.rgb,
                    FinishKey::Reflection => out.reflection = self.color(e)?.rgb,
                    FinishKey::Diffuse => out.diffuse = self.float(e)?,
                    FinishKey::Brilliance => out.brilliance = self.float(e)?,
                    FinishKey::Phong => out.phong = self.float(e)?,
                    FinishKey::PhongSize => out.phong_size = self.float(e)?,
                    FinishKey::Specular => out.specular = self.float(e)?,
                    FinishKey::Roughness => {
                        let r = self.float(e)?;
                        if r <= 0.0 {
                            return Err(Diag::new(e.span, "roughness must be positive"));
                        }
                        out.roughness = r;
                    }
                    FinishKey::Metallic => out.metallic = self.float(e)?,
                    FinishKey::Emission => out.emission = self.color(e)?.rgb,
                    FinishKey::ReflectionExponent => out.reflection_exponent = self.float(e)?,
                    FinishKey::ConserveEnergy => out.conserve_energy = self.float(e)? != 0.0,
                    FinishKey::DiffuseAlbedo => {
                        out.diffuse = self.float(e)?;
                        out.albedo.diffuse = true;
                    }
                    FinishKey::PhongAlbedo => {
                        out.phong = self.float(e)?;
                        out.albedo.phong = true;
                    }
                    FinishKey::SpecularAlbedo => {
                        out.specular = self.float(e)?;
                        out.albedo.specular = true;
                    }
                },
                FinishItem::Reflection(r) => {
                    out.reflection = self.color(&r.max)?.rgb;
                    out.reflection_fresnel = match &r.fresnel {
                        Some(e) => self.float(e)? != 0.0,
                        None => false,
                    };
                    // One colour is a constant reflection, but a Fresnel one rises from zero.
                    out.reflection_min = match &r.min {
                        Some(e) => Some(self.color(e)?.rgb),
                        None if out.reflection_fresnel => Some(DVec3::ZERO),
                        None => None,
                    };
                    if let Some(e) = &r.falloff {
                        out.reflection_falloff = self.float(e)?;
                    }
                    if let Some(e) = &r.exponent {
                        out.reflection_exponent = self.float(e)?;
                    }
                    if let Some(e) = &r.metallic {
                        out.reflection_metallic = self.float(e)?;
                    }
                }
            }
        }
        Ok(out)
    }

    pub(super) fn interior(&mut self, i: &Interior) -> PResult<InteriorDesc> {
        let mut out = InteriorDesc::default();
        // POV-Ray's defaults: distance and power 0 (no fading), colour black.
        let mut fade = FadeDesc { distance: 0.0, power: 0.0, color: DVec3::ZERO };
        for item in &i.items {
            match item {
                InteriorItem::Base(e) => match self.declared(e)? {
                    Some(Value::Interior(base)) => {
                        out = base.clone();
                        if let Some(f) = &base.fade {
                            fade = **f;
                        }
                    }
                    Some(other) => return Err(other.wrong_kind(e.span, "a declared interior")),
                    None => return Err(Diag::new(e.span, "expected a declared interior")),
                },
                InteriorItem::Ior(e) => {
                    let ior = self.float(e)?;
                    if ior <= 0.0 {
                        return Err(Diag::new(e.span, "ior must be positive"));
                    }
                    out.ior = ior;
                }
                InteriorItem::FadeDistance(e) => fade.distance = self.float(e)?,
                InteriorItem::FadePower(e) => fade.power = self.float(e)?,
                InteriorItem::FadeColor(e) => fade.color = self.color(e)?.rgb,
            }
        }
        // Off while either is 0, as POV-Ray documents.
        out.fade = (fade.distance != 0.0 && fade.power != 0.0).then(|| Box::new(fade));
        Ok(out)
    }
}
