//! Source files and spans: every token and syntax node carries a `Span` into a `SourceMap`, so
//! any stage can turn a problem into a `LocatedError` with `file:line:col`.

use std::path::PathBuf;

use crate::error::LocatedError;

/// Index of a file in the `SourceMap`.
pub type FileId = u32;

/// A byte range in one source file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Span {
    pub file: FileId,
    pub start: u32,
    pub end: u32,
}

impl Span {
    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        // Files over 4 GiB are rejected when read, so offsets always fit.
        Span { file, start: start as u32, end: end as u32 }
    }

    /// The span covering both `self` and `other` (same file).
    pub fn to(self, other: Span) -> Span {
        Span { file: self.file, start: self.start.min(other.start), end: self.end.max(other.end) }
    }
}

/// A problem found before we know how the file is displayed; turned into a `LocatedError` by
/// `SourceMap::locate`.
#[derive(Clone, Debug, PartialEq)]
pub struct Diag {
    pub span: Span,
    pub message: String,
}

impl Diag {
    pub fn new(span: Span, message: impl Into<String>) -> Diag {
        Diag { span, message: message.into() }
    }
}

/// Shorthand for results of the lexer, parser and lowering.
pub type PResult<T> = Result<T, Diag>;

/// One loaded scene or include file.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// How messages name the file (the path as given or as found on the include path).
    pub display: String,
    pub path: PathBuf,
    pub text: String,
}

/// All files read while loading one scene.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    pub files: Vec<SourceFile>,
}

impl SourceMap {
    pub fn add(&mut self, file: SourceFile) -> FileId {
        self.files.push(file);
        (self.files.len() - 1) as FileId
    }

    pub fn file(&self, id: FileId) -> Option<&SourceFile> {
        self.files.get(id as usize)
    }

    /// Line and column (1-based) of the start of `span`.
    pub fn line_col(&self, span: Span) -> (u32, u32) {
        let e = self.locate(&Diag::new(span, ""));
        (e.line, e.col)
    }

    pub fn locate(&self, diag: &Diag) -> LocatedError {
        match self.file(diag.span.file) {
            Some(f) => LocatedError::at_offset(&f.display, &f.text, diag.span.start as usize, &diag.message),
            None => LocatedError::whole_file("<unknown>", &diag.message),
        }
    }
}
