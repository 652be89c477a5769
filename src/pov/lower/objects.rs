//! Objects: the shape (`shape_args` lowers its arguments to a `ShapeDesc`), then modifiers in
//! written order. A transform moves the object and the patterns already attached to it; a pigment given
//! after the transform is not moved, exactly as in POV-Ray. A `union` is flattened into its
//! children, each carrying the union's transforms; `merge`, `intersection`, `difference` and
//! `clipped_by` make CSG nodes, whose transforms likewise go down to their shapes.

use super::texture_block::{layer_over, texture_uv_span, transform_texture, uv_span};
use super::Lowerer;
use std::sync::Arc;

use crate::desc::{InteriorDesc, ObjectDesc, Placement, PolyForm, ShapeDesc, TextureDesc};
use crate::pov::ast::{Clip, CsgOp, Expr, ExprKind, Modifier, Object, ObjectKind, Stmt};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::{Group, MaterialValue, Part, Value};

impl Lowerer<'_> {
    pub(super) fn object(&mut self, o: &Object) -> PResult<Group> {
        // The lights written inside this object's children are collected apart from those of
        // the objects around it.
        let outer_lights = std::mem::take(&mut self.child_lights);
        let shape = match &o.kind {
            ObjectKind::Shape(kind, args) => Some(self.shape(*kind, args, o.span)?),
            ObjectKind::Blob(blob) => Some(self.blob(blob, o.span)?),
            ObjectKind::Julia(julia) => Some(self.julia(julia, o.span)?),
            ObjectKind::Built(shape) => Some(shape.clone()),
            _ => None,
        };
        let mut group = match &o.kind {
            ObjectKind::Shape(..) | ObjectKind::Blob(_) | ObjectKind::Julia(_) | ObjectKind::Built(_) => Group {
                parts: vec![Part::leaf(ObjectDesc {
                    shape: shape.expect("a shape was lowered above"),
                    transform: Placement::Identity,
                    texture: Arc::default(),
                    interior_texture: None,
                    interior: InteriorDesc::default(),
                    no_shadow: false,
                    inverse: false,
                    hollow: false,
                    light_group: None,
                    bounded_by: None,
                    source: self.files.source_ref(o.span),
                })],
                csg: false,
                lights: Vec::new(),
            },
            ObjectKind::Inner(inner) => self.object(inner)?,
            ObjectKind::Ref(e) => match (&e.kind, self.eval(e)?) {
                (ExprKind::Value(_), Value::Object(group)) => *group,
                // `object { L rotate .. }` on a declared light_source (POV-Ray's desk.pov,
                // media2.pov): the light and its `looks_like` objects, moved as one.
                (ExprKind::Value(_), Value::Light(light, looks)) => {
                    Group { parts: looks.to_vec(), csg: true, lights: vec![*light] }
                }
                (_, other) => return Err(other.wrong_kind(e.span, "a declared object")),
            },
            ObjectKind::LightGroup { children, global_lights } => {
                // A light group flattens as a union does (and a union or group inside it too).
                let mut parts = self.children(children, "union", o.span)?;
                let lights = std::mem::take(&mut self.child_lights);
                let global = match global_lights {
                    Some(on) => self.hollow(on.as_ref())?,
                    None => false,
                };
                let lights = self.light_group(&mut parts, lights, global);
                // The group's lights travel with it, as a lamp's do: moved by its transforms
                // and those of every object it is placed in (a CSG, a declared group placed
                // inside another), and added to the scene where the whole is placed.
                Group { parts, csg: true, lights }
            }
            ObjectKind::Csg { op: CsgOp::Union, children } => {
                Group { parts: self.children(children, "union", o.span)?, csg: true, lights: Vec::new() }
            }
            ObjectKind::Csg { op, children } => {
                let parts = self.children(children, op.keyword(), o.span)?;
                Group {
                    parts: vec![Part::node(*op, parts, self.files.source_ref(o.span))],
                    csg: false,
                    lights: Vec::new(),
                }
            }
        };
        group.lights.append(&mut std::mem::replace(&mut self.child_lights, outer_lights));
        // A union flattens into its children unless something needs it whole.
        if group.csg && o.modifiers.iter().any(|m| matches!(m, Modifier::Inverse | Modifier::ClippedBy(_))) {
            let parts = std::mem::take(&mut group.parts);
            let node = Part::node(CsgOp::Union, parts, self.files.source_ref(o.span));
            group = Group { parts: vec![node], csg: false, lights: std::mem::take(&mut group.lights) };
        }
        if !group.lights.is_empty() {
            for m in &o.modifiers {
                if let Modifier::Transform(t) = m {
                    let t = self.transform(t)?;
                    for light in &mut group.lights {
                        super::lights::transform_light(light, &t.matrix);
                    }
                }
            }
        }
        if group.csg {
            self.csg_modifiers(&mut group.parts, &o.modifiers, "union")?;
        } else {
            for part in &mut group.parts {
                self.modifiers(part, &o.modifiers)?;
            }
        }
        Ok(group)
    }

    /// One object's modifiers, in written order. A transform moves the object and the patterns
    /// already attached to it; on a CSG node, everything but `inverse` and `clipped_by` goes to
    /// its children as a union's does.
    fn modifiers(&mut self, part: &mut Part, modifiers: &[Modifier]) -> PResult<()> {
        let mut pending = Inherited::default();
        for m in modifiers {
            match m {
                Modifier::Inverse => part.desc.inverse = !part.desc.inverse,
                Modifier::ClippedBy(clip) => {
                    let clips = match clip {
                        Clip::Objects(children, span) => self.children(children, "clipped_by", *span)?,
                        // `clipped_by { bounded_by }`: the bounding objects clip.
                        Clip::Other(span) => match modifiers.iter().find_map(|m| match m {
                            Modifier::BoundedBy(Clip::Objects(children, span)) => Some((children, span)),
                            _ => None,
                        }) {
                            Some((children, span)) => self.children(children, "bounded_by", *span)?,
                            None => {
                                return Err(Diag::new(
                                    *span,
                                    "`clipped_by { bounded_by }` needs a `bounded_by` with objects",
                                ))
                            }
                        },
                    };
                    if part.is_node() {
                        self.inherit(&mut part.children, &mut pending);
                    }
                    let inner = std::mem::replace(part, Part::leaf(part.desc.clone()));
                    let mut children = vec![inner];
                    children.extend(clips);
                    *part = Part::node(CsgOp::Clip, children, part.desc.source.clone());
                }
                // A hint: the shapes below skip rays that miss the bounding objects' box.
                Modifier::BoundedBy(Clip::Objects(children, span)) => {
                    self.bounded_by(std::slice::from_mut(part), children, *span)?;
                }
                Modifier::BoundedBy(Clip::Other(_)) => {}
                _ if part.is_node() => {
                    let word = part.desc.shape.keyword();
                    self.csg_modifier(&mut part.children, m, &mut pending, word)?
                }
                _ => self.leaf_modifier(part, m)?,
            }
        }
        if part.is_node() {
            self.inherit(&mut part.children, &mut pending);
        }
        Ok(())
    }

    /// One modifier of a single shape.
    fn leaf_modifier(&mut self, part: &mut Part, m: &Modifier) -> PResult<()> {
        let surface = matches!(m, Modifier::Pigment(_) | Modifier::Normal(_) | Modifier::Finish(_));
        if surface && !part.textured {
            // The first of these starts the object's texture from the default in effect (an
            // object's `uv_mapping` before it stays).
            let uv = part.desc.texture.uv_mapping;
            part.desc.texture = self.default_texture.clone();
            part.desc.texture_mut().uv_mapping |= uv;
        }
        let obj = &mut part.desc;
        // An object's `uv_mapping` holds for the textures given after it too.
        let object_uv = obj.texture.uv_mapping;
        match m {
            Modifier::Pigment(p) => {
                let pigment = self.pigment(p)?;
                let texture = obj.texture_mut();
                texture.pigment = pigment;
                texture.uv_mapping |= uv_span(p).is_some();
            }
            Modifier::UvMapping(_) => obj.texture_mut().uv_mapping = true,
            Modifier::Normal(n) => obj.texture_mut().normal = Some(self.normal(n)?),
            Modifier::Finish(f) => obj.texture_mut().finish = self.finish_block(f)?,
            // A second texture on an object lies over the first as a layer (POV-Ray 3.4.6.6).
            Modifier::Texture(t) if part.textured => {
                let upper = self.texture(t)?;
                layer_over(part.desc.texture_mut(), upper);
            }
            Modifier::Texture(t) => {
                let mut texture = self.texture(t)?;
                texture.uv_mapping |= object_uv;
                obj.texture = Arc::new(texture);
            }
            Modifier::Interior(i) => {
                obj.interior = self.interior(i)?;
                part.has_interior = true;
            }
            // POV-Ray 3.4.5.5.3: a material's texture goes over the object's own as a layer;
            // its interior replaces the object's.
            Modifier::Material(m) => {
                let MaterialValue { texture, interior } = self.material(m)?;
                let obj = &mut part.desc;
                if let Some(tex) = texture {
                    match part.textured {
                        true => layer_over(obj.texture_mut(), tex),
                        false => obj.texture = Arc::new(tex),
                    }
                    part.textured = true;
                }
                if let Some(i) = interior {
                    obj.interior = i;
                    part.has_interior = true;
                }
            }
            Modifier::InteriorTexture(t) if !part.textured => return Err(interior_without_texture(t.span)),
            Modifier::InteriorTexture(t) => obj.interior_texture = Some(Box::new(self.texture(t)?)),
            Modifier::Transform(t) => {
                let t = self.transform(t)?;
                obj.transform = obj.transform.then(&t);
                transform_texture(obj.texture_mut(), &t);
                if let Some(inner) = &mut obj.interior_texture {
                    transform_texture(inner, &t);
                }
            }
            Modifier::NoShadow => obj.no_shadow = true,
            Modifier::Hollow(on) => obj.hollow = self.hollow(on.as_ref())?,
            Modifier::Open(span) => match &mut obj.shape {
                ShapeDesc::Cone { open, .. } | ShapeDesc::Prism { open, .. } | ShapeDesc::Sor { open, .. } => {
                    *open = true
                }
                ShapeDesc::Isosurface { params, .. } => params.open = true,
                other => return Err(flag_not_taken(*span, "open", other.keyword(), OPEN_TAKERS)),
            },
            Modifier::Sturm(span) => match &mut obj.shape {
                ShapeDesc::Torus { .. }
                | ShapeDesc::Prism { .. }
                | ShapeDesc::Lathe { .. }
                | ShapeDesc::Sor { .. }
                | ShapeDesc::Blob { .. } => {}
                ShapeDesc::Poly { sturm, written, .. } if *written != PolyForm::Quadric => *sturm = true,
                other => return Err(flag_not_taken(*span, "sturm", other.keyword(), STURM_SHAPES)),
            },
            Modifier::InsideVector(e) => match &mut obj.shape {
                ShapeDesc::Mesh { inside_vector, .. } => *inside_vector = Some(self.vec3(e)?),
                other => {
                    return Err(Diag::new(
                        e.span,
                        format!("`inside_vector` is for mesh and mesh2, not {}", other.keyword()),
                    ))
                }
            },
            Modifier::Inverse | Modifier::ClippedBy(_) | Modifier::BoundedBy(_) => {
                unreachable!("handled by `modifiers`")
            }
        }
        if surface || matches!(m, Modifier::Texture(_)) {
            part.textured = true;
        }
        let uv = match m {
            Modifier::UvMapping(span) => Some(*span),
            Modifier::Pigment(p) => uv_span(p),
            Modifier::Texture(t) => texture_uv_span(t),
            _ => None,
        };
        if let Some(span) = uv.filter(|_| !crate::geometry::uv::has_uv(&part.desc.shape)) {
            self.not_modelled(&format!("uv_mapping on a {} (no surface coordinates)", part.desc.shape.keyword()), span);
        }
        Ok(())
    }

    /// The children of a `union`, `merge`, `intersection`, `difference` or `clipped_by`.
    pub(super) fn children(&mut self, children: &[Stmt], word: &str, span: Span) -> PResult<Vec<Part>> {
        self.csg_stack.push(Vec::new());
        // A union flattens into a union only: in anything else it is one child.
        self.csg_whole_unions.push(word != "union");
        let result = children.iter().try_for_each(|c| self.stmt(c));
        self.csg_whole_unions.pop();
        let parts = self.csg_stack.pop().unwrap_or_default();
        result?;
        if parts.is_empty() {
            self.warn(Diag::new(span, format!("`{word}` has no objects")));
        }
        Ok(parts)
    }

    /// Registers a `light_group` (POV-Ray 3.4.4.2) lighting only `parts` (and, through
    /// `parent`, the parts of the groups written inside this one), and returns its `lights`
    /// marked as the group's (those of groups inside it keep their own): they join the scene's
    /// lights, and the group's list, where the group is placed (`Lowerer::place_lights`).
    fn light_group(
        &mut self,
        parts: &mut [Part],
        mut lights: Vec<crate::desc::LightDesc>,
        global_lights: bool,
    ) -> Vec<crate::desc::LightDesc> {
        let id = self.scene.light_groups.len() as u32;
        for light in &mut lights {
            light.light_group.get_or_insert(id);
        }
        let groups = &mut self.scene.light_groups;
        groups.push(crate::desc::LightGroupDesc { lights: Vec::new(), global_lights, parent: None });
        let mut mark = |p: &mut Part| match p.desc.light_group {
            None => p.desc.light_group = Some(id),
            Some(inner) if inner != id && groups[inner as usize].parent.is_none() => {
                groups[inner as usize].parent = Some(id)
            }
            Some(_) => {}
        };
        // Shading looks at the shapes' own descriptions (a CSG node's children are shaded
        // with their materials), so only the leaves are marked.
        for part in parts {
            part.for_each_leaf(&mut mark);
        }
        lights
    }

    /// Lights placed in the scene (at the top level, or inside an object placed there): each
    /// joins the scene's lights and, if it is in a `light_group`, that group's list.
    pub(super) fn place_lights(&mut self, lights: &[crate::desc::LightDesc]) {
        for light in lights {
            if let Some(group) = light.light_group {
                let index = self.scene.lights.len() as u32;
                self.scene.light_groups[group as usize].lights.push(index);
            }
            self.scene.lights.push(*light);
        }
    }

    /// `hollow` alone is on; with a value, on unless it is 0.
    fn hollow(&self, on: Option<&Expr>) -> PResult<bool> {
        on.map_or(Ok(true), |e| Ok(self.float(e)? != 0.0))
    }

    /// A union's modifiers: transforms and `no_shadow` apply to every child; the union's own
    /// texture and interior go, at the end, to the children that have none, as in POV-Ray.
    fn csg_modifiers(&mut self, parts: &mut [Part], modifiers: &[Modifier], word: &str) -> PResult<()> {
        let mut pending = Inherited::default();
        for m in modifiers {
            self.csg_modifier(parts, m, &mut pending, word)?;
        }
        self.inherit(parts, &mut pending);
        Ok(())
    }

    /// `bounded_by { children }` on `parts`: the world box of the bounding objects (asked of
    /// `render::probe`, the renderer's own bounds), kept by every shape below in its own object
    /// space, so that transforms written later move it with the shape. Unbounded bounding
    /// objects bound nothing.
    fn bounded_by(&mut self, parts: &mut [Part], children: &[Stmt], span: Span) -> PResult<()> {
        let bound = self.children(children, "bounded_by", span)?;
        let objects: Vec<ObjectDesc> = bound.into_iter().map(|p| p.into_desc(&Arc::default())).collect();
        let Some((lo, hi)) = crate::render::probe::bounds(&objects) else { return Ok(()) };
        for part in parts {
            part.for_each_leaf(&mut |leaf: &mut Part| {
                leaf.desc.bounded_by = Some(Box::new(crate::desc::box_through(&leaf.desc.transform.inverse(), lo, hi)));
            });
        }
        Ok(())
    }

    /// One modifier of a CSG object, for its `parts` (and the shapes below them).
    fn csg_modifier(&mut self, parts: &mut [Part], m: &Modifier, pending: &mut Inherited, word: &str) -> PResult<()> {
        let each = |parts: &mut [Part], f: &mut dyn FnMut(&mut Part)| {
            for p in parts.iter_mut() {
                p.for_each_leaf(&mut |leaf: &mut Part| f(leaf));
            }
        };
        match m {
            Modifier::Pigment(p) => {
                let pigment = self.pigment(p)?;
                let texture = pending.texture.get_or_insert_with(|| (*self.default_texture).clone());
                texture.pigment = pigment;
                texture.uv_mapping |= uv_span(p).is_some();
            }
            Modifier::UvMapping(_) => {
                each(parts, &mut |leaf| leaf.desc.texture_mut().uv_mapping = true);
                if let Some(t) = &mut pending.texture {
                    t.uv_mapping = true;
                }
            }
            Modifier::Normal(n) => {
                let normal = self.normal(n)?;
                pending.texture.get_or_insert_with(|| (*self.default_texture).clone()).normal = Some(normal);
            }
            Modifier::Finish(f) => {
                let finish = self.finish_block(f)?;
                pending.texture.get_or_insert_with(|| (*self.default_texture).clone()).finish = finish;
            }
            Modifier::Texture(t) => {
                let tex = self.texture(t)?;
                match &mut pending.texture {
                    Some(below) => layer_over(below, tex),
                    None => pending.texture = Some(tex),
                }
            }
            Modifier::Interior(i) => pending.interior = Some(self.interior(i)?),
            Modifier::Material(m) => {
                let MaterialValue { texture, interior } = self.material(m)?;
                if let Some(tex) = texture {
                    match &mut pending.texture {
                        Some(below) => layer_over(below, tex),
                        None => pending.texture = Some(tex),
                    }
                }
                if interior.is_some() {
                    pending.interior = interior;
                }
            }
            // Given to the shapes below that have none (as the texture is, but at once: a
            // transform after it moves it with them below).
            Modifier::InteriorTexture(t) if pending.texture.is_none() => return Err(interior_without_texture(t.span)),
            Modifier::InteriorTexture(t) => {
                let inner = self.texture(t)?;
                each(parts, &mut |leaf| {
                    leaf.desc.interior_texture.get_or_insert_with(|| Box::new(inner.clone()));
                });
            }
            Modifier::Transform(t) => {
                let t = self.transform(t)?;
                each(parts, &mut |leaf| {
                    leaf.desc.transform = leaf.desc.transform.then(&t);
                    transform_texture(leaf.desc.texture_mut(), &t);
                    if let Some(inner) = &mut leaf.desc.interior_texture {
                        transform_texture(inner, &t);
                    }
                });
                if let Some(tex) = &mut pending.texture {
                    transform_texture(tex, &t);
                }
            }
            Modifier::NoShadow => each(parts, &mut |leaf| leaf.desc.no_shadow = true),
            Modifier::Open(span) => return Err(flag_not_taken(*span, "open", word, OPEN_TAKERS)),
            Modifier::Sturm(span) => return Err(flag_not_taken(*span, "sturm", word, STURM_SHAPES)),
            // As in POV-Ray, `hollow` on a CSG object applies to all its parts.
            Modifier::Hollow(on) => {
                let hollow = self.hollow(on.as_ref())?;
                each(parts, &mut |leaf| leaf.desc.hollow = hollow);
            }
            Modifier::BoundedBy(Clip::Objects(children, span)) => self.bounded_by(parts, children, *span)?,
            Modifier::BoundedBy(Clip::Other(_)) => {}
            Modifier::InsideVector(e) => {
                return Err(Diag::new(e.span, format!("`inside_vector` is for mesh and mesh2, not {word}")))
            }
            Modifier::Inverse | Modifier::ClippedBy(_) => unreachable!("a union taking these is made whole first"),
        }
        Ok(())
    }

    /// Gives the pending texture and interior of a CSG object to the shapes below `parts` that
    /// have none.
    fn inherit(&self, parts: &mut [Part], pending: &mut Inherited) {
        let Inherited { texture, interior } = std::mem::take(pending);
        if texture.is_none() && interior.is_none() {
            return;
        }
        // One copy for all the children: a union of a million spheres shares it.
        let texture = texture.map(Arc::new);
        for p in parts.iter_mut() {
            p.for_each_leaf(&mut |leaf| {
                if let (false, Some(tex)) = (leaf.textured, &texture) {
                    leaf.desc.texture = tex.clone();
                    leaf.textured = true;
                }
                if let (false, Some(int)) = (leaf.has_interior, &interior) {
                    leaf.desc.interior = int.clone();
                    leaf.has_interior = true;
                }
            });
        }
    }
}

/// The shapes that take `open` and `sturm`, for messages.
const OPEN_TAKERS: &str = "cylinder, cone, prism, sor and isosurface";
const STURM_SHAPES: &str = "torus, cubic, quartic, poly, prism, lathe and sor";
/// A CSG object's texture and interior, given to its children without one at the end of its
/// modifiers.
#[derive(Default)]
struct Inherited {
    texture: Option<TextureDesc>,
    interior: Option<InteriorDesc>,
}

/// `flag` written on a shape that does not take it.
fn flag_not_taken(span: Span, flag: &str, on: &str, takes: &str) -> Diag {
    Diag::new(span, format!("`{flag}` does not apply to {on} (only to {takes})"))
}

/// POV-Ray's rule: an `interior_texture` follows the object's own texture (or pigment).
fn interior_without_texture(span: crate::pov::source::Span) -> Diag {
    Diag::new(span, "interior_texture needs the object's own texture (or pigment) before it, as in POV-Ray")
}
