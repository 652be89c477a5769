//! `light_source` → `LightDesc`: kinds, spot and area parameters, fading, and the transforms
//! in written order. `looks_like` objects are placed by `Lowerer::stmt` (they are objects).

use std::rc::Rc;

use glam::{DMat4, DVec3};

use super::Lowerer;
use crate::desc::{AreaLightDesc, LightDesc, LightKind};
use crate::pov::ast::{Light, LightItem};
use crate::pov::source::{Diag, PResult};
use crate::pov::value::{Group, Part, Value};

/// The most points one area light may have (rows × columns): far above the sample scenes'
/// 9×9 (and the presets' caps), small enough that a typo cannot ask for a billion rays a pixel.
pub const MAX_AREA_POINTS: u32 = 65_536;

impl Lowerer<'_> {
    /// `#declare L = light_source { .. }`: the light and its `looks_like` objects, lowered
    /// (and not placed) as a declared object's are.
    pub(super) fn declared_light(&mut self, l: &Light) -> PResult<Value> {
        let (light, start, base_looks) = self.light_placed(l)?;
        let mut parts = Vec::new();
        for object in self.looks_like(l, start, &base_looks) {
            parts.extend(self.object(&object)?.parts);
        }
        Ok(Value::Light(Box::new(light), parts.into()))
    }

    /// A `light_source`; its position may be a declared light, which it continues from.
    /// Returns the light, its position before the transforms (where a `looks_like` object
    /// starts), and the `looks_like` objects of the declared light it continues from, if any.
    pub(super) fn light_placed(&mut self, l: &Light) -> PResult<(LightDesc, DVec3, Rc<[Part]>)> {
        let (mut light, base_looks) = match self.eval(&l.position)? {
            Value::Light(base, looks) => (*base, looks),
            v => (LightDesc { position: v.as_vec3(l.position.span)?, ..LightDesc::default() }, Rc::from([])),
        };
        let start = light.position;
        if let Some(c) = &l.color {
            light.color = self.color(c)?.rgb;
        }
        light.shadowless |= l.shadowless;
        for item in &l.items {
            match item {
                LightItem::Kind(word, _) => match *word {
                    "spotlight" => light.kind = LightKind::Spot,
                    "cylinder" => light.kind = LightKind::Cylinder,
                    _ => light.parallel = true,
                },
                LightItem::Value(word, e, span) => match *word {
                    "point_at" => light.point_at = self.vec3(e)?,
                    "radius" => light.radius = Some(self.float(e)?),
                    "falloff" => light.falloff = Some(self.float(e)?),
                    "tightness" => light.tightness = Some(self.float(e)?),
                    "fade_distance" => light.fade_distance = self.float(e)?,
                    "fade_power" => light.fade_power = self.float(e)?,
                    _ => {
                        let n = self.float(e)?;
                        if n < 0.0 {
                            return Err(Diag::new(e.span, "adaptive must be 0 or more"));
                        }
                        match &mut light.area {
                            Some(a) => a.adaptive = Some(n as u32),
                            None => self.warn(Diag::new(*span, "`adaptive` without `area_light` has no effect")),
                        }
                    }
                },
                LightItem::Flag(word, value, span) => {
                    let on = value.as_ref().map_or(Ok(true), |e| Ok::<bool, Diag>(self.float(e)? != 0.0))?;
                    match *word {
                        "media_interaction" => light.media_interaction = on,
                        "media_attenuation" => light.media_attenuation = on,
                        "area_illumination" => {
                            if on {
                                // The area light shades as a point light at its centre, with
                                // soft shadows.
                                self.not_modelled("area_illumination", *span);
                            }
                        }
                        _ => match &mut light.area {
                            Some(a) => match *word {
                                "jitter" => a.jitter = on,
                                "circular" => a.circular = on,
                                _ => a.orient = on,
                            },
                            None => self.warn(Diag::new(*span, format!("`{word}` without `area_light` has no effect"))),
                        },
                    }
                }
                LightItem::AreaLight { axis1, axis2, size1, size2, span } => {
                    let (a1, a2) = (self.vec3(axis1)?, self.vec3(axis2)?);
                    let n1 = self.float(size1)?;
                    let n2 = self.float(size2)?;
                    for (n, e) in [(n1, size1), (n2, size2)] {
                        if n.is_nan() || n < 1.0 {
                            return Err(Diag::new(e.span, "area_light sizes must be at least 1"));
                        }
                    }
                    let (n1, n2) = (n1 as u32, n2 as u32);
                    if n1.saturating_mul(n2) > MAX_AREA_POINTS {
                        return Err(Diag::new(
                            *span,
                            format!("area_light has {n1} × {n2} points, more than the {MAX_AREA_POINTS} allowed"),
                        ));
                    }
                    let old = light.area;
                    light.area = Some(AreaLightDesc {
                        axis1: a1,
                        axis2: a2,
                        size1: n1,
                        size2: n2,
                        adaptive: old.and_then(|a| a.adaptive),
                        jitter: old.is_some_and(|a| a.jitter),
                        circular: old.is_some_and(|a| a.circular),
                        orient: old.is_some_and(|a| a.orient),
                    });
                }
                LightItem::LooksLike(..) => {}
                LightItem::ProjectedThrough(span) => self.not_modelled("projected_through", *span),
                LightItem::Transform(t) => {
                    let m = self.transform(t)?.matrix;
                    transform_light(&mut light, &m);
                }
            }
        }
        if light.fade_distance < 0.0 {
            return Err(Diag::new(l.span, "fade_distance must not be negative"));
        }
        Ok((light, start, base_looks))
    }

    /// The `looks_like` objects of `l`, as objects to place: each starts at the light's
    /// position, follows the light's transforms and casts no shadow (POV-Ray's implied
    /// `no_shadow`).
    /// A light continuing from a declared one keeps that light's `looks_like` objects (already
    /// at the declared light's place; they follow the new transforms), unless it has its own.
    pub(super) fn looks_like(&mut self, l: &Light, start: DVec3, base: &Rc<[Part]>) -> Vec<crate::pov::ast::Object> {
        use crate::pov::ast::{Expr, ExprKind, Modifier, Object, ObjectKind, TransformItem, TransformKind};
        let mut out = Vec::new();
        let own = l.items.iter().any(|item| matches!(item, LightItem::LooksLike(..)));
        if !own && !base.is_empty() {
            let group = Group { parts: base.to_vec(), csg: true, lights: Vec::new() };
            let value = Expr { kind: ExprKind::Value(Rc::new(Value::Object(Box::new(group)))), span: l.span };
            let modifiers = l
                .items
                .iter()
                .filter_map(|t| match t {
                    LightItem::Transform(t) => Some(Modifier::Transform(t.clone())),
                    _ => None,
                })
                .collect();
            out.push(Object { kind: ObjectKind::Ref(value), modifiers, span: l.span });
        }
        for item in &l.items {
            let LightItem::LooksLike(object, span) = item else { continue };
            let mut o = (**object).clone();
            o.modifiers.push(Modifier::NoShadow);
            let value = Expr {
                kind: ExprKind::Value(std::rc::Rc::new(Value::Vector(vec![start.x, start.y, start.z]))),
                span: *span,
            };
            o.modifiers.push(Modifier::Transform(TransformItem { kind: TransformKind::Translate, value, span: *span }));
            for t in &l.items {
                if let LightItem::Transform(t) = t {
                    o.modifiers.push(Modifier::Transform(t.clone()));
                }
            }
            out.push(o);
        }
        out
    }
}

/// Moves a light by `m`: its position, where it points and its area axes.
pub(super) fn transform_light(light: &mut LightDesc, m: &DMat4) {
    light.position = m.transform_point3(light.position);
    light.point_at = m.transform_point3(light.point_at);
    if let Some(a) = &mut light.area {
        a.axis1 = m.transform_vector3(a.axis1);
        a.axis2 = m.transform_vector3(a.axis2);
    }
}
