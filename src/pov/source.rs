//! Source files and spans: every token and syntax node carries a `Span` into a `SourceMap`, so
//! any stage can turn a problem into a `LocatedError` with `file:line:col`.

use std::path::PathBuf;

use crate::error::LocatedError;

/// Index of a file in the `SourceMap`.
pub type FileId = u32;

/// A byte range in one source file, and the macro expansion its token came through (0: none;
/// else an index + 1 into `SourceMap::expansions`), so errors can print the chain of calls.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    pub file: FileId,
    pub start: u32,
    pub end: u32,
    pub expansion: u32,
}

impl Span {
    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        // Files over 4 GiB are rejected when read, so offsets always fit.
        Span { file, start: start as u32, end: end as u32, expansion: 0 }
    }

    /// The span covering both `self` and `other` (same file).
    pub fn to(self, other: Span) -> Span {
        if other.file != self.file || other.expansion != self.expansion {
            return self;
        }
        Span { start: self.start.min(other.start), end: self.end.max(other.end), ..self }
    }
}

/// One macro call: which macro, where it was defined, and where it was called (whose own
/// `expansion` leads further out).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Expansion {
    pub name: String,
    pub defined: Span,
    pub called: Span,
}

/// A problem found before we know how the file is displayed; turned into a `LocatedError` by
/// `SourceMap::locate`.
#[derive(Clone, Debug, PartialEq)]
pub struct Diag {
    pub span: Span,
    pub message: String,
    /// Other places the message refers to ("declared here").
    pub notes: Vec<(Span, String)>,
    /// A feature POV-Ray has and strahl does not model yet (rather than a mistake in the
    /// scene): a declaration that needs it is kept as unmodelled instead of failing.
    pub unmodelled: bool,
}

impl Diag {
    pub fn new(span: Span, message: impl Into<String>) -> Diag {
        Diag { span, message: message.into(), notes: Vec::new(), unmodelled: false }
    }

    /// An error naming a POV-Ray feature strahl does not model yet.
    pub fn unmodelled(span: Span, message: impl Into<String>) -> Diag {
        Diag { unmodelled: true, ..Diag::new(span, message) }
    }

    pub fn with_note(mut self, span: Span, note: impl Into<String>) -> Diag {
        self.notes.push((span, note.into()));
        self
    }
}

/// Shorthand for results of the lexer, parser and lowering.
pub type PResult<T> = Result<T, Diag>;

/// One loaded scene or include file.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// How messages name the file (the path as given or as found on the include path).
    /// Shared with the `SourceRef` of every object written in the file.
    pub display: std::sync::Arc<str>,
    pub path: PathBuf,
    /// Shared with the parser's frames and macros, which read it as they go.
    pub text: std::rc::Rc<str>,
    /// The `#include` directive that read this file (none for the scene itself).
    pub included_from: Option<Span>,
}

/// All files read while loading one scene.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    pub files: Vec<SourceFile>,
    /// Byte offsets where each file's lines start, for `line_col` without rescanning the text
    /// (every object records where it is written).
    line_starts: Vec<Vec<u32>>,
    /// Macro calls that tokens came through; see `Span::expansion`.
    pub expansions: Vec<Expansion>,
}

/// How many lines of "in macro ... called from ..." an error prints at most; deeper chains
/// (recursion) are summarised.
const MAX_CHAIN_LINES: usize = 12;

impl SourceMap {
    pub fn add(&mut self, file: SourceFile) -> FileId {
        let starts = std::iter::once(0).chain(file.text.match_indices('\n').map(|(i, _)| i as u32 + 1)).collect();
        self.line_starts.push(starts);
        self.files.push(file);
        (self.files.len() - 1) as FileId
    }

    pub fn file(&self, id: FileId) -> Option<&SourceFile> {
        self.files.get(id as usize)
    }

    /// Line and column (1-based) of the start of `span`.
    pub fn line_col(&self, span: Span) -> (u32, u32) {
        let (Some(f), Some(starts)) = (self.file(span.file), self.line_starts.get(span.file as usize)) else {
            return (1, 1);
        };
        let offset = (span.start as usize).min(f.text.len());
        let line = starts.partition_point(|&s| s as usize <= offset).max(1);
        let start = starts[line - 1] as usize;
        // Columns count characters, as `LocatedError::at_offset` does.
        let col = f.text.get(start..offset).map_or(0, |t| t.chars().count());
        (line as u32, col as u32 + 1)
    }

    /// The error with its position, followed by the macro calls and includes that led there,
    /// innermost first, as a compiler prints an instantiation stack.
    pub fn locate(&self, diag: &Diag) -> LocatedError {
        let mut message = diag.message.clone();
        for (span, note) in &diag.notes {
            message.push_str(&format!("\n  note: {note}: {}", self.position(*span)));
        }
        for line in self.chain(diag.span) {
            message.push_str("\n  ");
            message.push_str(&line);
        }
        match self.file(diag.span.file) {
            Some(f) => LocatedError::at_offset(&f.display, &f.text, diag.span.start as usize, &message),
            None => LocatedError::whole_file("<unknown>", &message),
        }
    }

    /// "file:line:col" of a span's start.
    pub fn position(&self, span: Span) -> String {
        let (line, col) = self.line_col(Span { expansion: 0, ..span });
        let file = self.file(span.file).map_or("<unknown>", |f| &*f.display);
        format!("{file}:{line}:{col}")
    }

    /// The macro calls and includes that `span` was reached through, innermost first.
    pub fn chain(&self, span: Span) -> Vec<String> {
        let mut lines = Vec::new();
        let mut at = span;
        let mut skipped = 0usize;
        loop {
            if at.expansion == 0 {
                // Includes of the file the outermost call stands in.
                let mut file = at.file;
                let mut hops = 0;
                while let Some(from) = self.file(file).and_then(|f| f.included_from) {
                    lines.push(format!("in a file included from {}", self.position(from)));
                    file = from.file;
                    hops += 1;
                    if hops > 64 {
                        break;
                    }
                }
                break;
            }
            let Some(e) = self.expansions.get(at.expansion as usize - 1) else { break };
            if lines.len() < MAX_CHAIN_LINES {
                lines.push(format!(
                    "in macro `{}` (defined at {}), called from {}",
                    e.name,
                    self.position(e.defined),
                    self.position(e.called)
                ));
            } else {
                skipped += 1;
            }
            at = e.called;
        }
        if skipped > 0 {
            lines.insert(MAX_CHAIN_LINES, format!("... and {skipped} more macro calls"));
        }
        lines
    }
}
