//! `mesh`, `mesh2` and `height_field` bodies (POV-Ray 3.4.5.2.2, 3.4.5.2.3, 3.4.5.1.6), read
//! and evaluated as they are parsed: a million triangles held as expressions would take
//! gigabytes, as numbers they take 36 bytes each. Their modifiers (`inside_vector`,
//! `hierarchy` and the usual ones) are read by `object`.

use std::sync::Arc;

use glam::DVec3;

use super::Parser;
use crate::desc::{MeshDesc, MeshFace, ShapeDesc};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

/// What may follow a triangle's vectors.
const TRIANGLE_ITEMS: &[&str] = &["texture", "uv_vectors"];
/// mesh2's sections, in the order POV-Ray requires.
const MESH2_SECTIONS: &[&str] =
    &["vertex_vectors", "normal_vectors", "uv_vectors", "texture_list", "face_indices", "normal_indices", "uv_indices"];
/// Image types a height field reads.
pub const HF_TYPES: &[&str] = &["png", "pgm", "ppm", "tga", "gif", "pot", "jpeg"];
/// Types POV-Ray reads that strahl does not.
const HF_OTHER_TYPES: &[&str] = &["exr", "hdr", "iff", "sys", "tiff"];

/// Per-triangle features read but not modelled, for one warning each.
#[derive(Default)]
struct Unmodelled {
    textures: Option<Span>,
}

/// The uv corners of a mesh triangle without `uv_vectors` (POV-Ray's default: the unit
/// square's lower right half).
const DEFAULT_TRIANGLE_UV: [glam::DVec2; 3] =
    [glam::DVec2::new(0.0, 0.0), glam::DVec2::new(1.0, 0.0), glam::DVec2::new(1.0, 1.0)];

/// Appends one face's uv corners, returning their indices.
fn push_uvs(uvs: &mut Vec<glam::DVec2>, corners: [glam::DVec2; 3]) -> [u32; 3] {
    let first = uvs.len() as u32;
    uvs.extend(corners);
    [first, first + 1, first + 2]
}

impl Parser<'_, '_> {
    /// `mesh { triangle { a, b, c } smooth_triangle { a, na, b, nb, c, nc } ... }`, up to the
    /// modifiers. Every triangle gets its own three vertices.
    pub(super) fn mesh_body(&mut self, kw: Span) -> PResult<ShapeDesc> {
        let mut mesh = MeshDesc::default();
        let mut unmodelled = Unmodelled::default();
        while let Some(word) = self.peek_ident().filter(|w| matches!(&**w, "triangle" | "smooth_triangle")) {
            let smooth = &*word == "smooth_triangle";
            let tkw = self.bump().span;
            self.open_block(&word, tkw)?;
            let v = self.triangle_vectors(&word, smooth)?;
            let mut uv = None;
            while !self.at_block_end() {
                match self.peek_ident().as_deref() {
                    Some("texture") => {
                        let t = self.texture()?;
                        unmodelled.textures.get_or_insert(t.span);
                    }
                    Some("uv_vectors") => {
                        self.bump();
                        let mut corners = [glam::DVec2::ZERO; 3];
                        for (i, c) in corners.iter_mut().enumerate() {
                            if i > 0 {
                                self.eat_punct(',');
                            }
                            let e = self.expr()?;
                            *c = self.low.vec3(&e)?.truncate();
                        }
                        uv = Some(corners);
                    }
                    _ => return Err(self.unknown_in(&word, TRIANGLE_ITEMS)),
                }
            }
            self.close_block(&word, tkw)?;
            let first = mesh.vertices.len() as u32;
            let face = [first, first + 1, first + 2];
            if let Some(corners) = uv {
                // Faces before the first with uv_vectors get POV-Ray's default triangle map.
                while mesh.uv_faces.len() < mesh.faces.len() {
                    mesh.uv_faces.push(push_uvs(&mut mesh.uvs, DEFAULT_TRIANGLE_UV));
                }
                mesh.uv_faces.push(push_uvs(&mut mesh.uvs, corners));
            } else if !mesh.uv_faces.is_empty() {
                mesh.uv_faces.push(push_uvs(&mut mesh.uvs, DEFAULT_TRIANGLE_UV));
            }
            if smooth {
                mesh.vertices.extend([v[0], v[2], v[4]]);
                let n = mesh.normals.len() as u32;
                mesh.normals.extend([v[1], v[3], v[5]]);
                mesh.faces.push(MeshFace { vertices: face, normals: Some([n, n + 1, n + 2]) });
            } else {
                mesh.vertices.extend(&v[..3]);
                mesh.faces.push(MeshFace { vertices: face, normals: None });
            }
        }
        if mesh.faces.is_empty() {
            return Err(Diag::new(self.peek().span, "mesh needs at least one triangle or smooth_triangle"));
        }
        self.warn_unmodelled("mesh", &unmodelled);
        let _ = kw;
        Ok(ShapeDesc::Mesh { mesh: Arc::new(mesh), inside_vector: None })
    }

    /// A `triangle`'s three corners, or a `smooth_triangle`'s corners each followed by its
    /// normal (`[a, na, b, nb, c, nc]`).
    fn triangle_vectors(&mut self, word: &str, smooth: bool) -> PResult<[DVec3; 6]> {
        let count = if smooth { 6 } else { 3 };
        let mut v = [DVec3::ZERO; 6];
        for (i, slot) in v.iter_mut().take(count).enumerate() {
            if i > 0 {
                self.eat_punct(',');
            }
            if !self.starts_expr(super::scene::MODIFIERS) || self.peek_ident().as_deref() == Some("uv_vectors") {
                let what = if smooth { "three corners, each followed by its normal" } else { "three corners" };
                return Err(Diag::new(self.peek().span, format!("{word} needs {what}: found {i} vectors")));
            }
            let e = self.expr()?;
            *slot = self.low.vec3(&e)?;
        }
        Ok(v)
    }

    /// A `smooth_triangle` object: a mesh of one smooth face, up to the modifiers.
    pub(super) fn smooth_triangle_body(&mut self) -> PResult<ShapeDesc> {
        let v = self.triangle_vectors("smooth_triangle", true)?;
        let mesh = MeshDesc {
            vertices: vec![v[0], v[2], v[4]],
            normals: vec![v[1], v[3], v[5]],
            faces: vec![MeshFace { vertices: [0, 1, 2], normals: Some([0, 1, 2]) }],
            ..MeshDesc::default()
        };
        Ok(ShapeDesc::Mesh { mesh: Arc::new(mesh), inside_vector: None })
    }

    /// `mesh2 { vertex_vectors {..} [normal_vectors {..}] [uv_vectors {..}] [texture_list {..}]
    /// face_indices {..} [normal_indices {..}] [uv_indices {..}] }`, up to the modifiers.
    pub(super) fn mesh2_body(&mut self, kw: Span) -> PResult<ShapeDesc> {
        let mut mesh = MeshDesc::default();
        let mut unmodelled = Unmodelled::default();
        let mut normal_indices: Option<(Vec<[u32; 3]>, Span)> = None;
        let mut uv_indices: Option<(Vec<[u32; 3]>, Span)> = None;
        let mut faces: Option<(Vec<[u32; 3]>, Span)> = None;
        let mut last = None::<usize>;
        while let Some(word) = self.peek_ident().filter(|w| MESH2_SECTIONS.contains(&&**w)) {
            let order = MESH2_SECTIONS.iter().position(|s| *s == &*word).unwrap_or(0);
            let skw = self.bump().span;
            if last.is_some_and(|l| l >= order) {
                return Err(Diag::new(
                    skw,
                    format!("`{word}` out of order in mesh2 (POV-Ray's order: {})", MESH2_SECTIONS.join(", ")),
                ));
            }
            last = Some(order);
            self.open_block(&word, skw)?;
            let count = self.section_count(&word, skw)?;
            match &*word {
                "vertex_vectors" | "normal_vectors" => {
                    let mut out = Vec::with_capacity(count.min(1 << 24));
                    self.section_items(&word, count, |p| {
                        let e = p.expr()?;
                        out.push(p.low.vec3(&e)?);
                        Ok(true)
                    })?;
                    if &*word == "vertex_vectors" {
                        mesh.vertices = out;
                    } else {
                        mesh.normals = out;
                    }
                }
                "uv_vectors" => {
                    let mut out = Vec::with_capacity(count.min(1 << 24));
                    self.section_items(&word, count, |p| {
                        let e = p.expr()?;
                        out.push(p.low.vec3(&e)?.truncate());
                        Ok(true)
                    })?;
                    mesh.uvs = out;
                }
                "texture_list" => {
                    self.section_items(&word, count, |p| {
                        if p.peek_ident().as_deref() != Some("texture") {
                            return Err(Diag::new(p.peek().span, "texture_list holds `texture { ... }` blocks"));
                        }
                        p.texture_one().map(|_| true)
                    })?;
                    unmodelled.textures.get_or_insert(skw);
                }
                "face_indices" | "normal_indices" | "uv_indices" => {
                    let limit = match &*word {
                        "face_indices" => mesh.vertices.len(),
                        "normal_indices" => mesh.normals.len(),
                        _ => mesh.uvs.len(),
                    };
                    let mut out = Vec::with_capacity(count.min(1 << 24));
                    let name = word.clone();
                    let mut textured = false;
                    self.section_items(&word, count, |p| {
                        let e = p.expr()?;
                        match p.low.eval(&e)? {
                            // Texture indices after a face (`<a, b, c>, t` or `, t1, t2, t3`).
                            Value::Float(_) if &*name == "face_indices" && !out.is_empty() => {
                                textured = true;
                                Ok(false)
                            }
                            Value::Vector(v) if v.len() == 3 => {
                                let mut ix = [0u32; 3];
                                for (k, &x) in v.iter().enumerate() {
                                    if !(x >= 0.0 && (x as usize) < limit) {
                                        return Err(Diag::new(
                                            e.span,
                                            format!("{name}: index {x} out of range (0 to {})", limit as f64 - 1.0),
                                        ));
                                    }
                                    ix[k] = x as u32;
                                }
                                out.push(ix);
                                Ok(true)
                            }
                            other => Err(other.wrong_kind(e.span, "a vector of three indices")),
                        }
                    })?;
                    if textured {
                        unmodelled.textures.get_or_insert(skw);
                    }
                    match &*word {
                        "face_indices" => faces = Some((out, skw)),
                        "normal_indices" => normal_indices = Some((out, skw)),
                        _ => uv_indices = Some((out, skw)),
                    }
                }
                _ => unreachable!("one of MESH2_SECTIONS"),
            }
            self.close_block(&word, skw)?;
        }
        if mesh.vertices.is_empty() {
            return Err(Diag::new(self.peek().span, "mesh2 needs vertex_vectors with at least three vertices"));
        }
        let Some((faces, faces_span)) = faces else {
            return Err(Diag::new(self.peek().span, "mesh2 needs face_indices"));
        };
        let normals_of: Option<Vec<[u32; 3]>> = match normal_indices {
            Some((n, span)) if n.len() != faces.len() => {
                return Err(Diag::new(
                    span,
                    format!("normal_indices has {} entries, face_indices {}: they must match", n.len(), faces.len()),
                ));
            }
            Some((n, _)) => Some(n),
            // Without normal_indices, the face indices index the normals too.
            None if mesh.normals.is_empty() => None,
            None if mesh.normals.len() == mesh.vertices.len() => Some(faces.clone()),
            None => {
                return Err(Diag::new(
                    faces_span,
                    format!(
                        "mesh2 without normal_indices needs one normal per vertex: {} normals, {} vertices",
                        mesh.normals.len(),
                        mesh.vertices.len()
                    ),
                ));
            }
        };
        mesh.faces = faces
            .iter()
            .enumerate()
            .map(|(i, &v)| MeshFace { vertices: v, normals: normals_of.as_ref().map(|n| n[i]) })
            .collect();
        mesh.uv_faces = match uv_indices {
            Some((u, span)) if u.len() != faces.len() => {
                return Err(Diag::new(
                    span,
                    format!("uv_indices has {} entries, face_indices {}: they must match", u.len(), faces.len()),
                ));
            }
            Some((u, _)) => u,
            None if mesh.uvs.is_empty() => Vec::new(),
            // Without uv_indices, the face indices index the uv vectors too.
            None if mesh.uvs.len() >= mesh.vertices.len() => faces.clone(),
            None => {
                return Err(Diag::new(
                    faces_span,
                    format!(
                        "mesh2 without uv_indices needs one uv vector per vertex: {} uv vectors, {} vertices",
                        mesh.uvs.len(),
                        mesh.vertices.len()
                    ),
                ));
            }
        };
        self.warn_unmodelled("mesh2", &unmodelled);
        let _ = kw;
        Ok(ShapeDesc::Mesh { mesh: Arc::new(mesh), inside_vector: None })
    }

    /// `height_field { TYPE "file" [smooth] [water_level w] ... }`, up to the modifiers.
    pub(super) fn height_field_body(&mut self, kw: Span) -> PResult<ShapeDesc> {
        if self.peek_ident().as_deref() == Some("function") {
            // `function W, H { BODY }`: the function sampled on a W × H grid.
            let at = self.bump().span;
            let w = self.expr()?;
            self.eat_punct(',');
            let h = self.expr()?;
            let size = (self.low.float(&w)?, self.low.float(&h)?);
            let f = self.function_after(at)?;
            let (smooth, water_level) = self.height_field_options()?;
            return self.low.function_height_field(&f, size, at.to(h.span), smooth, water_level);
        }
        let format = match self.peek_ident() {
            Some(w) if HF_TYPES.contains(&&*w) => {
                self.bump();
                w.to_string()
            }
            Some(w) if HF_OTHER_TYPES.contains(&&*w) => {
                return Err(Diag::unmodelled(
                    self.peek().span,
                    format!("height_field: `{w}` images are not supported (supported: {})", HF_TYPES.join(", ")),
                ));
            }
            // No type keyword: POV-Ray 3.7 takes the type from the file name's extension.
            _ if self.starts_expr(&[]) => String::new(),
            _ => {
                return Err(Diag::new(
                    self.peek().span,
                    format!("height_field needs the image type ({}) and the file name", HF_TYPES.join(", ")),
                ));
            }
        };
        let name_expr = self.expr()?;
        let name = match self.low.eval(&name_expr)? {
            Value::Str(s) => s.to_string(),
            other => return Err(other.wrong_kind(name_expr.span, "the image's file name")),
        };
        let format = if !format.is_empty() {
            format
        } else {
            match crate::image_file::type_from_extension(&name) {
                Some(t) if HF_TYPES.contains(&t) => t.to_string(),
                Some(t) => {
                    return Err(Diag::unmodelled(
                        name_expr.span,
                        format!("height_field: `{t}` images are not supported (supported: {})", HF_TYPES.join(", ")),
                    ));
                }
                None => {
                    return Err(Diag::new(
                        name_expr.span,
                        format!(
                            "height_field: no image type given and none known from \"{name}\"'s extension \
                             (write one of {})",
                            HF_TYPES.join(", ")
                        ),
                    ));
                }
            }
        };
        let (smooth, water_level) = self.height_field_options()?;
        let _ = kw;
        self.low.height_field(&format, &name, name_expr.span, smooth, water_level)
    }

    /// `smooth`, `water_level w` (and the unmodelled `gamma`, `premultiplied`) after the image.
    fn height_field_options(&mut self) -> PResult<(bool, f64)> {
        let (mut smooth, mut water_level) = (false, 0.0);
        loop {
            match self.peek_ident().as_deref() {
                Some("smooth") => {
                    self.bump();
                    smooth = true;
                }
                Some("water_level") => {
                    self.bump();
                    let e = self.expr()?;
                    water_level = self.low.float(&e)?;
                }
                Some("gamma" | "premultiplied") => {
                    let span = self.bump().span;
                    self.expr()?;
                    self.low.warn(Diag::new(span, "height_field: `gamma` and `premultiplied` are not modelled"));
                }
                _ => break,
            }
        }
        Ok((smooth, water_level))
    }

    /// A section's entry count, the first thing in it.
    fn section_count(&mut self, word: &str, kw: Span) -> PResult<usize> {
        if !self.starts_expr(&[]) {
            return Err(Diag::new(self.peek().span, format!("{word} needs its number of entries first")));
        }
        let e = self.expr()?;
        let n = self.low.float(&e)?;
        if !(n >= 0.0 && n.fract() == 0.0 && n < u32::MAX as f64) {
            return Err(Diag::new(e.span, format!("{word}: the number of entries must be a whole number ≥ 0")));
        }
        let _ = kw;
        Ok(n as usize)
    }

    /// Reads a section's entries (commas between them optional) to its closing brace; `item`
    /// reads one and says whether it counts as an entry. Their number must be `count`.
    fn section_items(
        &mut self,
        word: &str,
        count: usize,
        mut item: impl FnMut(&mut Self) -> PResult<bool>,
    ) -> PResult<()> {
        let mut found = 0usize;
        loop {
            self.eat_punct(',');
            if self.at_block_end() {
                break;
            }
            let span = self.peek().span;
            if item(self)? {
                found += 1;
                if found > count {
                    return Err(Diag::new(span, format!("{word}: more than the {count} entries it declares")));
                }
            }
        }
        if found != count {
            return Err(Diag::new(self.peek().span, format!("{word} declares {count} entries, found {found}")));
        }
        Ok(())
    }

    fn warn_unmodelled(&mut self, word: &str, u: &Unmodelled) {
        if let Some(span) = u.textures {
            self.low.warn(Diag::new(
                span,
                format!("{word}: per-triangle textures are not modelled; the {word}'s own texture is used"),
            ));
        }
    }
}
