//! Lowering: syntax tree → `SceneDesc`. Evaluates expressions, resolves `#declare`/`#local`
//! names in file order, follows `#include` (through `Files`), and composes transforms the way
//! POV-Ray does. Split by topic: `eval` (expressions, colours, transforms), `camera`,
//! `textures`, `objects`.

mod camera;
mod eval;
mod objects;
mod textures;
pub mod value;

use std::collections::HashMap;

use crate::pov::ast::{DeclValue, GlobalItem, Stmt};
use crate::pov::source::{Diag, FileId, PResult, Span};
use crate::scene::desc::{LightDesc, SceneDesc, SourceRef};
use value::Value;

/// What lowering needs from the loader: included files' syntax trees, and positions for
/// `ObjectDesc::source`.
pub trait Files {
    /// Resolves, reads and parses `#include "path"`; errors (not found, cycle, too deep) are
    /// located at `path_span`/`directive`.
    fn enter_include(
        &mut self,
        path: &str,
        directive: Span,
        path_span: Span,
    ) -> PResult<(FileId, Vec<Stmt>)>;
    /// Called when the include entered last has been lowered.
    fn leave_include(&mut self);
    fn source_ref(&self, span: Span) -> SourceRef;
}

pub struct Lowerer<'f> {
    files: &'f mut dyn Files,
    scene: SceneDesc,
    /// The language version in effect (`#version`); read by the `version` keyword.
    version: f64,
    /// `#declare`d names (index 0) and one map of `#local` names per open file.
    scopes: Vec<HashMap<String, Value>>,
    pub warnings: Vec<Diag>,
}

impl<'f> Lowerer<'f> {
    pub fn new(files: &'f mut dyn Files) -> Self {
        Lowerer {
            files,
            scene: SceneDesc::default(),
            version: 3.7,
            scopes: vec![HashMap::new(), HashMap::new()],
            warnings: Vec::new(),
        }
    }

    /// Lowers the main file's statements and returns the finished scene.
    pub fn finish(mut self, stmts: &[Stmt]) -> PResult<(SceneDesc, Vec<Diag>)> {
        self.stmts(stmts)?;
        self.scene.version = self.version;
        Ok((self.scene, self.warnings))
    }

    fn lookup(&self, name: &str) -> Option<&Value> {
        self.scopes.iter().rev().find_map(|s| s.get(name))
    }

    fn lookup_or_err(&self, name: &str, span: Span) -> PResult<&Value> {
        self.lookup(name)
            .ok_or_else(|| Diag::new(span, format!("undefined identifier `{name}`")))
    }

    fn stmts(&mut self, stmts: &[Stmt]) -> PResult<()> {
        for s in stmts {
            self.stmt(s)?;
        }
        Ok(())
    }

    fn stmt(&mut self, stmt: &Stmt) -> PResult<()> {
        match stmt {
            Stmt::Version { value, .. } => {
                let v = self.eval(value)?.as_float(value.span)?;
                if !(1.0..=3.8).contains(&v) {
                    return Err(Diag::new(
                        value.span,
                        format!("unsupported #version {v} (expected 1.0 to 3.8)"),
                    ));
                }
                self.version = v;
            }
            Stmt::Include {
                path,
                span,
                path_span,
            } => {
                let (_, stmts) = self.files.enter_include(path, *span, *path_span)?;
                self.scopes.push(HashMap::new());
                let result = self.stmts(&stmts);
                self.scopes.pop();
                self.files.leave_include();
                result?;
            }
            Stmt::Declare {
                name, local, value, ..
            } => {
                let v = match value {
                    DeclValue::Expr(e) => self.eval(e)?,
                    DeclValue::Pigment(p) => Value::Pigment(Box::new(self.pigment(p)?)),
                    DeclValue::Normal(n) => Value::Normal(Box::new(self.normal(n)?)),
                    DeclValue::Finish(f) => Value::Finish(self.finish_block(f)?),
                    DeclValue::Texture(t) => Value::Texture(Box::new(self.texture(t)?)),
                    DeclValue::Interior(i) => Value::Interior(self.interior(i)?),
                    DeclValue::Object(o) => Value::Object(Box::new(self.object(o)?)),
                };
                let scope = if *local { self.scopes.len() - 1 } else { 0 };
                if !*local {
                    // `#declare` replaces the global value; a same-named local would shadow it.
                    for s in &mut self.scopes[1..] {
                        s.remove(name);
                    }
                }
                self.scopes[scope].insert(name.clone(), v);
            }
            Stmt::IfDef {
                name, negate, body, ..
            } => {
                if self.lookup(name).is_some() != *negate {
                    self.stmts(body)?;
                }
            }
            Stmt::Camera { items, span } => self.scene.camera = self.camera(items, *span)?,
            Stmt::Light(l) => {
                let mut position = self.vec3(&l.position)?;
                let color = match &l.color {
                    Some(c) => self.color(c)?.rgb,
                    None => glam::DVec3::ONE,
                };
                for t in &l.transforms {
                    position = self.transform(t)?.matrix.transform_point3(position);
                }
                self.scene.lights.push(LightDesc { position, color });
            }
            Stmt::Background { color, .. } => self.scene.background = self.color(color)?,
            Stmt::GlobalSettings { items, .. } => {
                for item in items {
                    match item {
                        GlobalItem::AssumedGamma(e) => {
                            let g = self.float(e)?;
                            if g <= 0.0 {
                                return Err(Diag::new(e.span, "assumed_gamma must be positive"));
                            }
                            self.scene.global.assumed_gamma = Some(g);
                        }
                        GlobalItem::MaxTraceLevel(e) => {
                            let n = self.float(e)?;
                            if !(1.0..=256.0).contains(&n) {
                                return Err(Diag::new(
                                    e.span,
                                    "max_trace_level must be between 1 and 256",
                                ));
                            }
                            self.scene.global.max_trace_level = n as u32;
                        }
                        GlobalItem::AmbientLight(e) => {
                            self.scene.global.ambient_light = self.color(e)?.rgb
                        }
                    }
                }
            }
            Stmt::Object(o) => {
                let obj = self.object(o)?;
                self.scene.objects.push(obj);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
