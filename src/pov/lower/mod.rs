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

use crate::pov::ast::{ClauseTest, DeclValue, DefaultItem, GlobalItem, MessageKind, Stmt, StrExpr};
use crate::pov::source::{Diag, FileId, PResult, Span};
use crate::pov::ParseOptions;
use crate::scene::desc::{LightDesc, SceneDesc, SourceRef, TextureDesc};
use value::{truthy, Part, Value, EPSILON};

/// Total `#while` iterations allowed in one scene: far beyond real scenes (a 100³ grid of
/// spheres is a million), small enough that a loop that never ends fails in seconds.
pub const MAX_LOOP_ITERATIONS: u64 = 10_000_000;

/// Objects allowed in the scene, and children in one union: an `ObjectDesc` is about 1 KiB, so
/// this bounds memory near 2 GiB even for a union that doubles itself in a loop.
pub const MAX_OBJECTS: usize = 2_000_000;

/// How a statement list ended: normally, or at a `#break` that the enclosing `#switch` or
/// `#while` must honour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Flow {
    Normal,
    Break(Span),
}

/// What a scene prints while it is lowered: `#debug` text (POV-Ray's debug stream, exactly as
/// written, newlines included) and located warnings.
#[derive(Clone, Debug, PartialEq)]
pub enum Output {
    Debug(String),
    Warning(Diag),
}

/// What lowering needs from the loader: included files' syntax trees, and positions for
/// `ObjectDesc::source`.
pub trait Files {
    /// Resolves, reads and parses `#include "path"`; errors (not found, cycle, too deep) are
    /// located at `path_span`/`directive`.
    fn enter_include(&mut self, path: &str, directive: Span, path_span: Span) -> PResult<(FileId, Vec<Stmt>)>;
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
    /// `#debug` text and warnings, in the order the scene produced them.
    output: Vec<Output>,
    options: ParseOptions,
    /// The children gathered so far by each open `union`/`merge`, innermost last.
    csg_stack: Vec<Vec<Part>>,
    /// `#while` iterations so far, against `MAX_LOOP_ITERATIONS`.
    loop_iterations: u64,
    /// The texture `#default` last set (POV-Ray's own until then): where every texture, pigment,
    /// finish and normal block starts, and what objects without one get when placed.
    default_texture: TextureDesc,
}

impl<'f> Lowerer<'f> {
    pub fn new(files: &'f mut dyn Files, options: &ParseOptions) -> Self {
        Lowerer {
            files,
            scene: SceneDesc::default(),
            version: 3.7,
            scopes: vec![HashMap::new(), HashMap::new()],
            output: Vec::new(),
            options: options.clone(),
            csg_stack: Vec::new(),
            loop_iterations: 0,
            default_texture: TextureDesc::default(),
        }
    }

    /// Lowers the main file's statements and returns the finished scene with what it printed.
    pub fn finish(mut self, stmts: &[Stmt]) -> PResult<(SceneDesc, Vec<Output>)> {
        if let Flow::Break(span) = self.stmts(stmts)? {
            return Err(Diag::new(span, "`#break` outside `#switch` or `#while`"));
        }
        self.scene.version = self.version;
        Ok((self.scene, self.output))
    }

    /// Records a warning (POV-Ray's "Scale by 0.0", `#warning`, ...) for the caller to print.
    fn warn(&mut self, diag: Diag) {
        self.output.push(Output::Warning(diag));
    }

    fn lookup(&self, name: &str) -> Option<&Value> {
        self.scopes.iter().rev().find_map(|s| s.get(name))
    }

    fn lookup_or_err(&self, name: &str, span: Span) -> PResult<&Value> {
        self.lookup(name).ok_or_else(|| Diag::new(span, format!("undefined identifier `{name}`")))
    }

    fn stmts(&mut self, stmts: &[Stmt]) -> PResult<Flow> {
        for s in stmts {
            if let Flow::Break(span) = self.stmt(s)? {
                return Ok(Flow::Break(span));
            }
        }
        Ok(Flow::Normal)
    }

    /// The text of a message's string expression.
    fn string(&self, e: &StrExpr) -> PResult<String> {
        Ok(match e {
            StrExpr::Lit(s) => s.clone(),
            StrExpr::Concat(parts) => {
                let mut out = String::new();
                for p in parts {
                    out.push_str(&self.string(p)?);
                }
                out
            }
            StrExpr::Str(value, width, precision) => {
                let v = self.float(value)?;
                let w = self.float(width)?.clamp(0.0, 64.0) as usize;
                // POV-Ray: a negative precision means its default of 6 digits.
                let p = self.float(precision)?;
                let p = if p < 0.0 { 6 } else { p.min(16.0) as usize };
                format!("{v:w$.p$}")
            }
        })
    }

    /// Rejects scene-level statements inside a `union`.
    fn not_in_csg(&self, what: &str, span: Span) -> PResult<()> {
        if self.csg_stack.is_empty() {
            Ok(())
        } else {
            Err(Diag::new(span, format!("`{what}` is not supported inside `union` or `merge`")))
        }
    }

    fn stmt(&mut self, stmt: &Stmt) -> PResult<Flow> {
        match stmt {
            Stmt::Version { value, .. } => {
                let v = self.eval(value)?.as_float(value.span)?;
                if !(1.0..=3.8).contains(&v) {
                    return Err(Diag::new(value.span, format!("unsupported #version {v} (expected 1.0 to 3.8)")));
                }
                self.version = v;
                self.scene.version_directive = true;
            }
            Stmt::Include { path, span, path_span } => {
                let (_, stmts) = self.files.enter_include(path, *span, *path_span)?;
                self.scopes.push(HashMap::new());
                let result = self.stmts(&stmts);
                self.scopes.pop();
                self.files.leave_include();
                if let Flow::Break(span) = result? {
                    // POV-Ray does not let `#break` leave the file it is written in.
                    return Err(Diag::new(span, "`#break` outside `#switch` or `#while`"));
                }
            }
            Stmt::Declare { name, local, value, .. } => {
                let v = match value {
                    DeclValue::Expr(e) => self.eval(e)?,
                    DeclValue::Pigment(p) => Value::Pigment(Box::new(self.pigment(p)?)),
                    DeclValue::Normal(n) => Value::Normal(Box::new(self.normal(n)?)),
                    DeclValue::Finish(f) => Value::Finish(self.finish_block(f)?),
                    DeclValue::Texture(t) => Value::Texture(Box::new(self.texture(t)?)),
                    DeclValue::Interior(i) => Value::Interior(self.interior(i)?),
                    DeclValue::ColorMap(m) => Value::ColorMap(self.color_map(m)?),
                    DeclValue::Object(o) => Value::Object(Box::new(self.object(o)?)),
                    DeclValue::Camera(items) => Value::Camera(Box::new(self.camera_state(items)?)),
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
            Stmt::IfDef { name, negate, body, otherwise, .. } => {
                let taken = if self.lookup(name).is_some() != *negate { body } else { otherwise };
                return self.stmts(taken);
            }
            Stmt::If { branches, otherwise, .. } => {
                for (cond, body) in branches {
                    if truthy(self.float(cond)?) {
                        return self.stmts(body);
                    }
                }
                if let Some(body) = otherwise {
                    return self.stmts(body);
                }
            }
            Stmt::While { cond, body, span } => {
                while truthy(self.float(cond)?) {
                    self.loop_iterations += 1;
                    if self.loop_iterations > MAX_LOOP_ITERATIONS {
                        return Err(Diag::new(
                            *span,
                            format!(
                                "`#while` loops ran more than {MAX_LOOP_ITERATIONS} iterations in \
                                 total; is the condition ever false?"
                            ),
                        ));
                    }
                    if let Flow::Break(_) = self.stmts(body)? {
                        break;
                    }
                }
            }
            Stmt::Switch { value, clauses, .. } => {
                let v = self.float(value)?;
                let mut matched = None;
                for (i, clause) in clauses.iter().enumerate() {
                    let hit = match &clause.test {
                        ClauseTest::Case(e) => (self.float(e)? - v).abs() < EPSILON,
                        ClauseTest::Range(lo, hi) => (self.float(lo)?..=self.float(hi)?).contains(&v),
                        ClauseTest::Else => true,
                    };
                    if hit {
                        matched = Some(i);
                        break;
                    }
                }
                // Clauses fall through into the next one until a `#break` (POV-Ray 3.7).
                if let Some(first) = matched {
                    for clause in &clauses[first..] {
                        if let Flow::Break(_) = self.stmts(&clause.body)? {
                            break;
                        }
                    }
                }
            }
            Stmt::Break { span } => return Ok(Flow::Break(*span)),
            Stmt::Default { items, .. } => {
                for item in items {
                    match item {
                        DefaultItem::Texture(t) => self.default_texture = self.texture(t)?,
                        DefaultItem::Pigment(p) => self.default_texture.pigment = self.pigment(p)?,
                        DefaultItem::Normal(n) => self.default_texture.normal = Some(self.normal(n)?),
                        DefaultItem::Finish(f) => self.default_texture.finish = self.finish_block(f)?,
                    }
                }
            }
            Stmt::Message { kind, text, span } => match kind {
                MessageKind::Debug => {
                    let text = self.string(text)?;
                    self.output.push(Output::Debug(text));
                }
                MessageKind::Warning => {
                    let text = self.string(text)?;
                    self.warn(Diag::new(*span, text));
                }
                MessageKind::Error => {
                    let text = self.string(text)?;
                    return Err(Diag::new(*span, format!("#error: {text}")));
                }
            },
            Stmt::Camera { items, span } => {
                self.not_in_csg("camera", *span)?;
                self.scene.camera = self.camera(items, *span)?
            }
            Stmt::Light(l) => {
                self.not_in_csg("light_source", l.span)?;
                let mut position = self.vec3(&l.position)?;
                let color = match &l.color {
                    Some(c) => self.color(c)?.rgb,
                    None => glam::DVec3::ONE,
                };
                for t in &l.transforms {
                    position = self.transform(t)?.matrix.transform_point3(position);
                }
                self.scene.lights.push(LightDesc { position, color, shadowless: l.shadowless });
            }
            Stmt::Background { color, span } => {
                self.not_in_csg("background", *span)?;
                self.scene.background = self.color(color)?
            }
            Stmt::GlobalSettings { items, span } => {
                self.not_in_csg("global_settings", *span)?;
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
                                return Err(Diag::new(e.span, "max_trace_level must be between 1 and 256"));
                            }
                            self.scene.global.max_trace_level = n as u32;
                        }
                        GlobalItem::AmbientLight(e) => self.scene.global.ambient_light = self.color(e)?.rgb,
                    }
                }
            }
            Stmt::Object(o) => {
                let group = self.object(o)?;
                let before = match self.csg_stack.last() {
                    Some(children) => children.len(),
                    None => self.scene.objects.len(),
                };
                if before + group.parts.len() > MAX_OBJECTS {
                    let place = if self.csg_stack.is_empty() { "the scene" } else { "a union" };
                    return Err(Diag::new(o.span, format!("{place} would have more than {MAX_OBJECTS} objects")));
                }
                match self.csg_stack.last_mut() {
                    Some(children) => children.extend(group.parts),
                    None => {
                        // POV-Ray gives an object without a texture the default in effect where
                        // it is placed, not moved by the object's transforms (checked by rendering
                        // a declared sphere placed after a `#default`, and a scaled plane).
                        for part in group.parts {
                            let mut desc = part.desc;
                            if !part.textured {
                                desc.texture = self.default_texture.clone();
                            }
                            self.scene.objects.push(desc);
                        }
                    }
                }
            }
        }
        Ok(Flow::Normal)
    }
}

#[cfg(test)]
mod flow_tests;
#[cfg(test)]
mod tests;
