//! Lowering: scene items → `SceneDesc`, one at a time as the parser reads them. Holds the symbol
//! table the directives write (scopes for files and macro calls), evaluates expressions, and
//! composes transforms the way POV-Ray does. Split by topic: `eval` (expressions, colours,
//! transforms), `camera`, `textures`, `objects`.

mod atmosphere;
pub(crate) mod bicubic;
mod blob;
mod camera;
mod eval;
mod fileio;
mod finish;
mod functions;
mod height_field;
mod images;
mod isosurface;
mod julia;
mod lights;
mod looks;
mod material;
mod objects;
mod shape_args;
mod sweeps;
mod text;
mod texture_block;
mod textures;

use std::rc::Rc;
use std::sync::Arc;

use crate::desc::{CsgOp, LightDesc, SceneDesc, SourceRef, TextureDesc, UnmodelledFeature};
use crate::pov::ast::{DeclValue, DefaultItem, GlobalItem, Stmt};
use crate::pov::names::NameMap;
use crate::pov::source::{Diag, FileId, PResult, Span};
use crate::pov::value::{Part, Value};
use crate::pov::ParseOptions;
pub(crate) use fileio::Mode as FileMode;
pub(crate) use images::ImageOptions;

/// Total loop iterations (`#while`, `#for`) allowed in one scene: far beyond real scenes (a
/// 100³ grid of spheres is a million), small enough that a loop that never ends fails in
/// seconds.
pub const MAX_LOOP_ITERATIONS: u64 = 10_000_000;

/// Objects allowed in the scene, and children in one union: an `ObjectDesc` is under 200 bytes
/// (`desc::tests` holds it), so this bounds the descriptions near 3 GiB even for a union that
/// doubles itself in a loop, and lets the ten million objects of a generated cloud load.
pub const MAX_OBJECTS: usize = 16_000_000;

/// Most bytes of `#debug` text and warnings one scene may print (a runaway loop that prints
/// stops here instead of filling memory).
pub const MAX_OUTPUT_BYTES: usize = 16 << 20;

/// What a scene prints while it is lowered: `#debug` text (POV-Ray's debug stream, exactly as
/// written, newlines included) and located warnings.
#[derive(Clone, Debug, PartialEq)]
pub enum Output {
    Debug(String),
    Warning(Diag),
}

/// `#debug` (and `#render`, `#statistics`), `#warning`, `#error`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MessageKind {
    Debug,
    Warning,
    Error,
}

/// What lowering needs from the loader: included files' tokens, and positions for
/// `ObjectDesc::source`.
pub trait Files {
    /// Resolves, reads and lexes `#include "path"`; errors (not found, cycle, too deep) are
    /// located at `path_span`/`directive`.
    fn enter_include(&mut self, path: &str, directive: Span, path_span: Span) -> PResult<(FileId, Rc<str>)>;
    /// Called when the include entered last has been run.
    fn leave_include(&mut self);
    fn source_ref(&self, span: Span) -> SourceRef;
    /// `file_exists(name)`: whether `#include` would find it.
    fn file_exists(&self, name: &str) -> bool;
    /// Where `#fopen` reads `name` (found as `#include` finds files) or writes it (inside the
    /// scene's folder only); why not, as a message.
    fn data_path(&self, name: &str, write: bool) -> Result<std::path::PathBuf, String>;
}

/// One level of the symbol table: the scene's globals, a file's `#local`s, a macro call.
#[derive(Debug, Default)]
struct Scope {
    vars: NameMap<Rc<str>, Value>,
    /// A macro call's parameters (empty for other scopes).
    params: Vec<Rc<str>>,
    /// Parameters the macro assigned, to write back to by-reference arguments.
    written: Vec<Rc<str>>,
}

pub struct Lowerer<'f> {
    pub(crate) files: &'f mut dyn Files,
    scene: SceneDesc,
    /// The language version in effect (`#version`); read by the `version` keyword.
    version: f64,
    /// Global names (index 0), the scene file's `#local`s (1), then one scope per open include
    /// or macro call. Names are looked up innermost first, as POV-Ray does.
    scopes: Vec<Scope>,
    /// `#debug` text and warnings, in the order the scene produced them.
    output: Vec<Output>,
    options: ParseOptions,
    /// The children gathered so far by each open `union`/`merge`, innermost last.
    csg_stack: Vec<Vec<Part>>,
    /// Lights met inside the CSG objects being lowered, for the innermost object to take.
    child_lights: Vec<LightDesc>,
    /// For each open CSG object: whether a union among its children stays whole (one child,
    /// in anything but a union).
    csg_whole_unions: Vec<bool>,
    /// Loop iterations so far, against `MAX_LOOP_ITERATIONS`.
    loop_iterations: u64,
    /// The texture `#default` last set (POV-Ray's own until then): where every texture, pigment,
    /// finish and normal block starts, and what objects without one get when placed (shared
    /// by all of them).
    default_texture: Arc<TextureDesc>,
    /// The distinct textures of the objects placed last, for objects that look alike to share
    /// one copy (`share_looks`).
    looks: Vec<Arc<TextureDesc>>,
    /// `seed()`'s streams for `rand()`.
    random: functions::RandomStreams,
    /// Files `#fopen` opened.
    open_files: fileio::OpenFiles,
    /// Bytes of messages so far, against `MAX_OUTPUT_BYTES`.
    output_bytes: usize,
}

impl<'f> Lowerer<'f> {
    pub fn new(files: &'f mut dyn Files, options: &ParseOptions) -> Self {
        Lowerer {
            files,
            scene: SceneDesc::default(),
            version: 3.7,
            scopes: vec![Scope::default(), Scope::default()],
            output: Vec::new(),
            options: options.clone(),
            csg_stack: Vec::new(),
            child_lights: Vec::new(),
            csg_whole_unions: Vec::new(),
            loop_iterations: 0,
            default_texture: Arc::default(),
            looks: Vec::new(),
            random: Default::default(),
            open_files: Default::default(),
            output_bytes: 0,
        }
    }

    /// The finished scene with what it printed. Files the scene left open are saved (an
    /// error saving one is a warning: the scene itself is complete).
    pub fn finish(mut self) -> (SceneDesc, Vec<Output>) {
        if let Err(m) = self.close_all_files() {
            self.output.push(Output::Warning(Diag::new(Span::default(), m)));
        }
        self.scene.version = self.version;
        (self.scene, self.output)
    }

    /// Records a warning (POV-Ray's "Scale by 0.0", `#warning`, ...) for the caller to print.
    pub(crate) fn warn(&mut self, diag: Diag) {
        self.output.push(Output::Warning(diag));
    }

    /// Notes a rendering feature strahl does not model (`radiosity`, `media`, ...): the first
    /// use of each is named in a warning and kept in `SceneDesc::unmodelled`; the scene renders
    /// without it.
    pub(crate) fn not_modelled(&mut self, feature: &str, span: Span) {
        if self.scene.unmodelled.iter().any(|f| f.name == feature) {
            return;
        }
        let at = self.files.source_ref(span);
        self.scene.unmodelled.push(UnmodelledFeature { name: feature.to_string(), at });
        self.warn(Diag::new(span, format!("`{feature}` is not modelled by strahl; the scene renders without it")));
    }

    pub(crate) fn source_ref(&self, span: Span) -> SourceRef {
        self.files.source_ref(span)
    }

    // ---- the symbol table, for the directives ------------------------------------------

    pub(crate) fn lookup(&self, name: &str) -> Option<&Value> {
        self.scopes.iter().rev().find_map(|s| s.vars.get(name))
    }

    pub(crate) fn set_version(&mut self, v: f64) {
        self.version = v;
        self.scene.version_directive = true;
    }

    /// `#undef Name`: the innermost declaration goes.
    pub(crate) fn undef(&mut self, name: &str) {
        if let Some(s) = self.scopes.iter_mut().rev().find(|s| s.vars.contains_key(name)) {
            s.vars.remove(name);
        }
    }

    /// Counts one loop iteration; false once there were too many.
    pub(crate) fn count_iteration(&mut self) -> bool {
        self.loop_iterations += 1;
        self.loop_iterations <= MAX_LOOP_ITERATIONS
    }

    /// `#declare` (global, or a macro's parameter of that name) or `#local` (innermost scope)
    /// of `name`, or of one element of it with `index`.
    pub(crate) fn assign(&mut self, name: &str, local: bool, index: &[usize], value: Value, span: Span) -> PResult<()> {
        let innermost = self.scopes.len() - 1;
        self.assign_in(name, local.then_some(innermost), index, value, span)
    }

    /// The innermost scope now: where a `#local` begun here writes.
    pub(crate) fn innermost_scope(&self) -> usize {
        self.scopes.len() - 1
    }

    /// `assign`, a `#local` writing into `local_scope`: the innermost scope when the
    /// declaration began, since a macro that gives the value may end only after it
    /// (`#local N = F(3)` where `F` ends in `Q;`, as in POV-Ray's tracevines.pov).
    pub(crate) fn assign_in(
        &mut self,
        name: &str,
        local_scope: Option<usize>,
        index: &[usize],
        value: Value,
        span: Span,
    ) -> PResult<()> {
        let innermost = self.scopes.len() - 1;
        let holder = self.scopes.iter().rposition(|s| s.vars.contains_key(name));
        let param_scope = holder.filter(|&i| self.scopes[i].params.iter().any(|p| &**p == name));
        let scope = if let Some(s) = local_scope {
            s.min(innermost)
        } else if let Some(i) = param_scope {
            i
        } else if index.is_empty() {
            // `#declare` replaces the global value; a same-named local would shadow it.
            for s in &mut self.scopes[1..] {
                if !s.params.iter().any(|p| &**p == name) {
                    s.vars.remove(name);
                }
            }
            0
        } else {
            holder.unwrap_or(0)
        };
        if self.scopes[scope].params.iter().any(|p| &**p == name) {
            let s = &mut self.scopes[scope];
            if !s.written.iter().any(|p| &**p == name) {
                s.written.push(Rc::from(name));
            }
        }
        if index.is_empty() {
            self.scopes[scope].vars.insert(Rc::from(name), value);
            return Ok(());
        }
        let array = match self.scopes[scope].vars.get_mut(name) {
            Some(Value::Array(a)) => a,
            Some(other) => return Err(Diag::new(span, format!("`{name}` is {}, not an array", other.kind_name()))),
            None => return Err(Diag::new(span, format!("undefined array `{name}`"))),
        };
        let at = array.offset(index).map_err(|m| Diag::new(span, m))?;
        Rc::make_mut(array).items[at] = Some(value);
        Ok(())
    }

    /// Sets a declared name where it is declared (the innermost scope that holds it), as
    /// `trace`'s normal argument is written; `false` when it is not declared.
    pub(crate) fn reassign(&mut self, name: &str, value: Value) -> bool {
        match self.scopes.iter_mut().rev().find(|s| s.vars.contains_key(name)) {
            Some(s) => {
                s.vars.insert(Rc::from(name), value);
                true
            }
            None => false,
        }
    }

    /// `#macro`: macros are global, as in POV-Ray.
    pub(crate) fn define_macro(&mut self, name: &str, m: Value) {
        self.scopes[0].vars.insert(Rc::from(name), m);
    }

    /// A scope for an include file's `#local`s.
    pub(crate) fn push_scope(&mut self) {
        self.scopes.push(Scope::default());
    }

    pub(crate) fn pop_scope(&mut self) {
        if self.scopes.len() > 2 {
            self.scopes.pop();
        }
    }

    /// A macro call's scope, its parameters bound to `args`.
    pub(crate) fn push_macro_scope(&mut self, args: Vec<(Rc<str>, Value)>, params: Vec<Rc<str>>) {
        self.scopes.push(Scope { vars: args.into_iter().collect(), params, written: Vec::new() });
    }

    /// Closes a macro call's scope; returns the parameters it assigned, with their values.
    pub(crate) fn pop_macro_scope(&mut self) -> Vec<(Rc<str>, Value)> {
        if self.scopes.len() <= 2 {
            return Vec::new();
        }
        let mut s = self.scopes.pop().unwrap_or_default();
        s.written.iter().filter_map(|p| s.vars.remove(p).map(|v| (p.clone(), v))).collect()
    }

    /// A by-reference argument's new value, into the caller's variable (innermost scope that
    /// has it; a new global when the caller had none).
    pub(crate) fn write_back(&mut self, target: &str, value: Value) {
        let scope = self.scopes.iter().rposition(|s| s.vars.contains_key(target)).unwrap_or(0);
        if self.scopes[scope].params.iter().any(|p| &**p == target) {
            let s = &mut self.scopes[scope];
            if !s.written.iter().any(|p| &**p == target) {
                s.written.push(Rc::from(target));
            }
        }
        self.scopes[scope].vars.insert(Rc::from(target), value);
    }

    /// The value of a declaration's right-hand side.
    pub(crate) fn declaration(&mut self, value: &DeclValue) -> PResult<Value> {
        Ok(match value {
            DeclValue::Expr(e) => self.eval(e)?,
            DeclValue::Pigment(p) => Value::Pigment(Box::new(self.pigment(p)?)),
            DeclValue::Normal(n) => Value::Normal(Box::new(self.normal(n)?)),
            DeclValue::Finish(f) => Value::Finish(self.finish_block(f)?),
            DeclValue::Texture(t) => Value::Texture(Box::new(self.texture(t)?)),
            DeclValue::Interior(i) => Value::Interior(self.interior(i)?),
            DeclValue::Material(m) => Value::Material(Box::new(self.material(m)?)),
            DeclValue::ColorMap(m) => Value::ColorMap(self.color_map(m)?),
            DeclValue::SlopeMap(m) => Value::SlopeMap(self.slope_map(m)?),
            DeclValue::Object(o) => Value::Object(Box::new(self.object(o)?)),
            DeclValue::Camera(items) => Value::Camera(Box::new(self.camera_state(items)?)),
            DeclValue::Light(l) => self.declared_light(l)?,
            DeclValue::Atmosphere(a) => Value::Atmosphere(Rc::new(a.clone())),
        })
    }

    /// `#default { ... }`: where later texture blocks and untextured objects start.
    pub(crate) fn set_default(&mut self, items: &[DefaultItem]) -> PResult<()> {
        for item in items {
            match item {
                DefaultItem::Texture(t) => self.default_texture = Arc::new(self.texture(t)?),
                DefaultItem::Pigment(p) => Arc::make_mut(&mut self.default_texture).pigment = self.pigment(p)?,
                DefaultItem::Normal(n) => Arc::make_mut(&mut self.default_texture).normal = self.default_normal(n)?,
                DefaultItem::Finish(f) => Arc::make_mut(&mut self.default_texture).finish = self.finish_block(f)?,
            }
        }
        Ok(())
    }

    /// `#debug` text goes to the debug stream, `#warning` becomes a warning, `#error` stops.
    pub(crate) fn message(&mut self, kind: MessageKind, text: String, span: Span) -> PResult<()> {
        self.output_bytes += text.len();
        if self.output_bytes > MAX_OUTPUT_BYTES {
            return Err(Diag::new(span, format!("the scene printed more than {MAX_OUTPUT_BYTES} bytes of messages")));
        }
        match kind {
            MessageKind::Debug => self.output.push(Output::Debug(text)),
            MessageKind::Warning => self.warn(Diag::new(span, text)),
            MessageKind::Error => return Err(Diag::new(span, format!("#error: {text}"))),
        }
        Ok(())
    }

    /// Rejects scene-level statements inside a `union`.
    fn not_in_csg(&self, what: &str, span: Span) -> PResult<()> {
        if self.csg_stack.is_empty() {
            Ok(())
        } else {
            Err(Diag::new(span, format!("`{what}` is not supported inside a CSG object (`union`, `merge`, `intersection`, `difference`, `clipped_by`)")))
        }
    }

    /// Adds one scene item.
    pub(crate) fn stmt(&mut self, stmt: &Stmt) -> PResult<()> {
        match stmt {
            Stmt::Camera { items, span } => {
                self.not_in_csg("camera", *span)?;
                self.scene.camera = self.camera(items, *span)?
            }
            Stmt::Light(l) => {
                let (light, start, base_looks) = self.light_placed(l)?;
                if self.csg_stack.is_empty() {
                    self.scene.lights.push(light);
                } else {
                    // It moves with the object it is written in.
                    self.child_lights.push(light);
                }
                for object in self.looks_like(l, start, &base_looks) {
                    self.stmt(&Stmt::Object(object))?;
                }
            }
            Stmt::Atmosphere(a) => {
                self.not_in_csg(a.kind.keyword(), a.span)?;
                self.atmosphere(a)?;
            }
            Stmt::Media(span) => self.media_warning(*span),
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
                        GlobalItem::NoiseGenerator(e) => {
                            let n = self.float(e)?;
                            if ![1.0, 2.0, 3.0].contains(&n) {
                                return Err(Diag::new(e.span, "noise_generator must be 1, 2 or 3"));
                            }
                            self.scene.global.noise_generator = n as u32;
                        }
                        GlobalItem::NumberOfWaves(e) => {
                            let n = self.float(e)?;
                            if !(1.0..=1000.0).contains(&n) {
                                return Err(Diag::new(e.span, "number_of_waves must be between 1 and 1000"));
                            }
                            self.scene.global.number_of_waves = n as u32;
                        }
                        GlobalItem::IridWavelength(e) => self.scene.global.irid_wavelength = self.color(e)?.rgb,
                        GlobalItem::AdcBailout(e) => {
                            let b = self.float(e)?;
                            if !(0.0..=1.0).contains(&b) {
                                return Err(Diag::new(e.span, "adc_bailout must be between 0 and 1"));
                            }
                            if (b - 1.0 / 255.0).abs() > 1e-6 {
                                self.not_modelled("adc_bailout (other than 1/255)", e.span);
                            }
                        }
                    }
                }
            }
            Stmt::Object(o) => {
                let group = self.object(o)?;
                let before = match self.csg_stack.last() {
                    Some(children) => children.len(),
                    None => self.scene.objects.len(),
                };
                if before + group.parts.iter().map(Part::leaf_count).sum::<usize>() > MAX_OBJECTS {
                    let place = if self.csg_stack.is_empty() { "the scene" } else { "a union" };
                    return Err(Diag::new(o.span, format!("{place} would have more than {MAX_OBJECTS} objects")));
                }
                if self.csg_stack.is_empty() {
                    self.place_lights(&group.lights);
                } else {
                    self.child_lights.extend(group.lights.iter().copied());
                }
                let whole = group.csg && self.csg_whole_unions.last() == Some(&true);
                match self.csg_stack.last_mut() {
                    Some(children) if whole => {
                        let source = self.files.source_ref(o.span);
                        children.push(Part::node(CsgOp::Union, group.parts, source))
                    }
                    Some(children) => children.extend(group.parts),
                    None => {
                        // POV-Ray gives an object without a texture the default in effect where
                        // it is placed, not moved by the object's transforms (checked by rendering
                        // a declared sphere placed after a `#default`, and a scaled plane).
                        for part in group.parts {
                            let mut desc = part.into_desc(&self.default_texture);
                            self.share_looks(&mut desc);
                            self.scene.objects.push(desc);
                        }
                    }
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod flow_tests;
#[cfg(test)]
pub(crate) mod tests;
