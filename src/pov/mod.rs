//! POV-Ray's scene language: lexer (tokens with spans) → parser (syntax tree) → lower (SceneDesc).
//!
//! It produces a `desc::SceneDesc` and never builds render data or a BVH; the parse-time
//! questions (`trace`, `inside`, `min_extent`) go to `render::probe`. `load_scene` reads
//! files and follows `#include`; every problem comes back as one `LocatedError`.
//!
//! Layer 8 of docs/design/architecture.md: uses `render` (its probes) and below; `headless` and `app` use it.

pub mod ast;
pub mod lexer;
mod lower;
mod names;
pub mod parser;
pub mod source;
pub mod value;

use std::fmt;
use std::path::{Path, PathBuf};

use crate::desc::{IncludedFile, SceneDesc, SourceRef};
use crate::error::{visible, LocatedError};
use crate::text::decode_user_text;
use source::{Diag, FileId, PResult, SourceFile, SourceMap, Span};
use std::rc::Rc;

/// The warning for a scene without objects, in POV-Ray 3.7's words.
pub const NO_OBJECTS: &str = "No objects in scene.";

/// How deep `#include` may nest (POV-Ray's own limit is similar); deeper is surely a runaway.
pub const MAX_INCLUDE_DEPTH: usize = 32;

/// Where `#include` looks, in POV-Ray's order: the including scene's folder, then each `-L` dir,
/// then POV-Ray's own include folders, then the project's bundled `scenes/include`.
#[derive(Clone, Debug, Default)]
pub struct IncludePath {
    pub dirs: Vec<PathBuf>,
}

/// What the scene can read about the render it is parsed for (`image_width`, `clock`, ...).
#[derive(Clone, Debug, PartialEq)]
pub struct ParseOptions {
    pub image_width: u32,
    pub image_height: u32,
    pub clock: Clock,
}

/// POV-Ray's animation values for the frame being parsed (`+KI +KF +KFI +KFF`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Clock {
    pub clock: f64,
    pub clock_delta: f64,
    pub frame_number: u32,
    pub initial_clock: f64,
    pub final_clock: f64,
    pub initial_frame: u32,
    pub final_frame: u32,
    /// Whether an animation is being rendered (`clock_on`).
    pub on: bool,
}

impl Default for Clock {
    /// A still image, as POV-Ray parses it: clock 0, frame 0, clock_delta 0, not animated.
    fn default() -> Self {
        Clock {
            clock: 0.0,
            clock_delta: 0.0,
            frame_number: 0,
            initial_clock: 0.0,
            final_clock: 0.0,
            initial_frame: 0,
            final_frame: 0,
            on: false,
        }
    }
}

impl Clock {
    /// Frame `index` (0-based) of `frames` with the clock running from `from` to `to`, as POV-Ray
    /// numbers an animation: frames 1..=frames, the clock at `from` on the first and `to` on
    /// the last.
    pub fn frame(from: f64, to: f64, index: u32, frames: u32) -> Clock {
        Clock::numbered(1, frames.max(1), from, to, index + 1)
    }

    /// Frame `number` of an animation numbered `first..=last` (POV-Ray's `Initial_Frame` and
    /// `Final_Frame`), the clock running from `from` on the first to `to` on the last.
    pub fn numbered(first: u32, last: u32, from: f64, to: f64, number: u32) -> Clock {
        let steps = last.saturating_sub(first).max(1);
        let delta = (to - from) / f64::from(steps);
        let clock = if last <= first { from } else { from + delta * f64::from(number.saturating_sub(first)) };
        Clock {
            clock,
            clock_delta: delta,
            frame_number: number,
            initial_clock: from,
            final_clock: to,
            initial_frame: first,
            final_frame: last,
            on: true,
        }
    }
}

impl Default for ParseOptions {
    /// POV-Ray's default image size, 640×480, and a still image.
    fn default() -> Self {
        ParseOptions { image_width: 640, image_height: 480, clock: Clock::default() }
    }
}

/// Loads and lowers a scene file for the default image size (640×480).
pub fn load_scene(path: &Path, include: &IncludePath) -> Result<SceneDesc, LocatedError> {
    load_scene_with_warnings(path, include).map(|(scene, _)| scene)
}

/// Loads and lowers a scene file for the render `options` describe; scenes often write
/// `right x*image_width/image_height`.
pub fn load_scene_with_options(
    path: &Path,
    include: &IncludePath,
    options: &ParseOptions,
) -> Result<SceneDesc, LocatedError> {
    load_scene_with_options_and_warnings(path, include, options).map(|(scene, _)| scene)
}

/// Like `load_scene`, also returning warnings (POV-Ray's "Scale by 0.0" and the like) for the
/// caller to print.
pub fn load_scene_with_warnings(
    path: &Path,
    include: &IncludePath,
) -> Result<(SceneDesc, Vec<LocatedError>), LocatedError> {
    load_scene_with_options_and_warnings(path, include, &ParseOptions::default())
}

/// `load_scene_with_options`, also returning warnings.
pub fn load_scene_with_options_and_warnings(
    path: &Path,
    include: &IncludePath,
    options: &ParseOptions,
) -> Result<(SceneDesc, Vec<LocatedError>), LocatedError> {
    let (scene, messages) = load_scene_with_messages(path, include, options)?;
    let warnings = messages
        .into_iter()
        .filter_map(|m| match m {
            Message::Warning(w) => Some(w),
            Message::Debug(_) => None,
        })
        .collect();
    Ok((scene, warnings))
}

/// What a scene prints while it loads, in the order it printed it.
#[derive(Clone, Debug, PartialEq)]
pub enum Message {
    /// `#debug` text: POV-Ray's debug stream, printed exactly as written (the scene writes its
    /// own newlines).
    Debug(String),
    /// `#warning`, POV-Ray's warnings ("Scale by 0.0", "No objects in scene"), located.
    Warning(LocatedError),
}

impl fmt::Display for Message {
    /// How the CLI prints it to stderr: debug text as is, a warning on lines of its own.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Message::Debug(text) => f.write_str(text),
            Message::Warning(w) => writeln!(f, "warning: {w}"),
        }
    }
}

/// `load_scene_with_options`, also returning what the scene printed: `#debug` text and
/// warnings, in order.
pub fn load_scene_with_messages(
    path: &Path,
    include: &IncludePath,
    options: &ParseOptions,
) -> Result<(SceneDesc, Vec<Message>), LocatedError> {
    let mut loader = Loader {
        map: SourceMap::default(),
        include,
        stack: Vec::new(),
        options: options.clone(),
        included: Vec::new(),
    };
    let result = loader.load_main(path);
    result.map_err(|d| loader.map.locate(&d))
}

struct Loader<'a> {
    map: SourceMap,
    include: &'a IncludePath,
    /// Files being lowered, outermost first, for cycle detection and depth.
    stack: Vec<(PathBuf, FileId)>,
    options: ParseOptions,
    /// Every file `#include` read, in order.
    included: Vec<IncludedFile>,
}

impl Loader<'_> {
    fn load_main(&mut self, path: &Path) -> PResult<(SceneDesc, Vec<Message>)> {
        let display = path.display().to_string();
        let (file, text) = self.read(path, display.clone(), None)?;
        self.stack.push((canonical(path), file));
        let options = self.options.clone();
        let mut low = lower::Lowerer::new(self, &options);
        let (result, expansions) = parser::run(&mut low, file, text);
        let (mut scene, output) = low.finish();
        self.map.expansions = expansions;
        result?;
        scene.included = std::mem::take(&mut self.included);
        let mut messages: Vec<Message> = output
            .into_iter()
            .map(|o| match o {
                lower::Output::Debug(text) => Message::Debug(text),
                lower::Output::Warning(d) => Message::Warning(self.map.locate(&d)),
            })
            .collect();
        if scene.objects.is_empty() {
            // POV-Ray 3.7 warns too, then renders the background: an empty image is rarely meant.
            messages.push(Message::Warning(LocatedError::whole_file(&display, NO_OBJECTS)));
        }
        Ok((scene, messages))
    }

    /// Reads a file into the source map (the parser lexes it as it goes). An unreadable file
    /// still gets an entry, so its error is located like any other. The text is decoded by
    /// `decode_user_text`: a byte-order mark is dropped and a file that is not UTF-8 is read as
    /// Latin-1.
    fn read(&mut self, path: &Path, display: String, included_from: Option<Span>) -> PResult<(FileId, Rc<str>)> {
        let (text, problem) = match std::fs::read(path) {
            Err(e) => (String::new(), Some(format!("cannot read file: {e}"))),
            Ok(b) if b.len() >= u32::MAX as usize => (String::new(), Some("file is too large".to_string())),
            Ok(b) => (decode_user_text(b), None),
        };
        let text: Rc<str> = Rc::from(text);
        let id = self.map.add(SourceFile {
            display: display.into(),
            path: path.to_path_buf(),
            text: text.clone(),
            included_from,
        });
        if let Some(message) = problem {
            return Err(Diag::new(Span::new(id, 0, 0), message));
        }
        Ok((id, text))
    }

    /// The including file's folder first, then the include path in order.
    fn resolve(&self, name: &str) -> Option<PathBuf> {
        let including = self.stack.last().and_then(|(_, id)| self.map.file(*id)).map(|f| f.path.clone());
        let here = including.as_deref().and_then(Path::parent).map(Path::to_path_buf);
        here.into_iter().chain(self.include.dirs.iter().cloned()).map(|d| d.join(name)).find(|p| p.is_file())
    }
}

impl lower::Files for Loader<'_> {
    fn enter_include(&mut self, name: &str, directive: Span, path_span: Span) -> PResult<(FileId, Rc<str>)> {
        let Some(found) = self.resolve(name) else {
            let searched: Vec<String> = self.include.dirs.iter().map(|d| d.display().to_string()).collect();
            return Err(Diag::new(
                path_span,
                format!(
                    "include file \"{}\" not found (searched the scene's folder{}{})",
                    visible(name),
                    if searched.is_empty() { "" } else { ", " },
                    searched.join(", ")
                ),
            ));
        };
        let key = canonical(&found);
        if let Some(pos) = self.stack.iter().position(|(p, _)| *p == key) {
            let mut chain: Vec<String> = self.stack[pos..].iter().map(|(p, _)| short_name(p)).collect();
            chain.push(short_name(&key));
            return Err(Diag::new(directive, format!("include cycle: {}", chain.join(" → "))));
        }
        if self.stack.len() > MAX_INCLUDE_DEPTH {
            return Err(Diag::new(directive, format!("#include nested deeper than {MAX_INCLUDE_DEPTH} levels")));
        }
        let (id, text) = self.read(&found, found.display().to_string(), Some(directive))?;
        self.included.push(IncludedFile { path: found.display().to_string(), from: self.source_ref(directive) });
        self.stack.push((key, id));
        Ok((id, text))
    }

    fn leave_include(&mut self) {
        self.stack.pop();
    }

    fn file_exists(&self, name: &str) -> bool {
        self.resolve(name).is_some()
    }

    fn data_path(&self, name: &str, write: bool) -> Result<PathBuf, String> {
        if !write {
            return self.resolve(name).ok_or_else(|| format!("file \"{}\" not found", visible(name)));
        }
        let relative = Path::new(name);
        let inside = relative.components().all(|c| matches!(c, std::path::Component::Normal(_)));
        if !inside {
            return Err(format!(
                "#fopen writes only inside the scene's folder, not \"{}\" (give a plain relative name)",
                visible(name)
            ));
        }
        let scene = self.stack.first().and_then(|(_, id)| self.map.file(*id)).map(|f| f.path.clone());
        let folder = scene.as_deref().and_then(Path::parent).map(Path::to_path_buf).unwrap_or_default();
        Ok(folder.join(relative))
    }

    fn source_ref(&self, span: Span) -> SourceRef {
        let (line, col) = self.map.line_col(span);
        let file = self.map.file(span.file).map(|f| f.display.clone()).unwrap_or_default();
        SourceRef { file, line, col }
    }
}

fn canonical(p: &Path) -> PathBuf {
    std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf())
}

fn short_name(p: &Path) -> String {
    p.file_name().map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into_owned())
}
