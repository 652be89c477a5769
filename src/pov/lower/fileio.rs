//! `#fopen`, `#read`, `#write`, `#fclose`: text files beside the scene. Reading finds files as
//! `#include` does; writing stays inside the scene's folder (the loader refuses other paths), and
//! a written file appears whole when it is closed (or when the scene ends), never half-written.

use std::collections::HashMap;
use std::path::PathBuf;
use std::rc::Rc;

use super::Lowerer;
use crate::pov::lexer::{lex, Token, TokenKind};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::Value;

/// Most bytes a scene may write to one file (a runaway `#write` loop stops here).
pub const MAX_WRITE_BYTES: usize = 64 << 20;

/// Most files open at once.
pub const MAX_OPEN_FILES: usize = 64;

#[derive(Debug)]
enum Stream {
    Read { tokens: Vec<Token>, pos: usize },
    Write { path: PathBuf, text: String, append: bool },
}

/// The scene's open files, by handle name.
#[derive(Debug, Default)]
pub struct OpenFiles {
    open: HashMap<Rc<str>, Stream>,
}

/// How `#fopen` opens a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Read,
    Write,
    Append,
}

impl Lowerer<'_> {
    /// `#fopen Handle "name" read|write|append`.
    pub(crate) fn fopen(&mut self, handle: &str, name: &str, mode: Mode, span: Span) -> PResult<()> {
        if self.open_files.open.len() >= MAX_OPEN_FILES && !self.open_files.open.contains_key(handle) {
            return Err(Diag::new(span, format!("more than {MAX_OPEN_FILES} files open at once")));
        }
        let path = self.files.data_path(name, mode != Mode::Read).map_err(|m| Diag::new(span, m))?;
        let stream = match mode {
            Mode::Read => {
                let bytes = std::fs::read(&path)
                    .map_err(|e| Diag::new(span, format!("cannot read \"{}\": {e}", path.display())))?;
                let text = crate::text::decode_user_text(bytes);
                let mut tokens = lex(span.file, &text)
                    .map_err(|d| Diag::new(span, format!("cannot read values from \"{name}\": {}", d.message)))?;
                // Spans in the data file mean nothing in the scene: point them at `#fopen`.
                for t in &mut tokens {
                    t.span = span;
                }
                Stream::Read { tokens, pos: 0 }
            }
            Mode::Write | Mode::Append => Stream::Write { path, text: String::new(), append: mode == Mode::Append },
        };
        self.open_files.open.insert(Rc::from(handle), stream);
        self.assign(handle, false, &[], Value::Str(Rc::from(name)), span)
    }

    /// `#fclose Handle`: a written file is saved now.
    pub(crate) fn fclose(&mut self, handle: &str, span: Span) -> PResult<()> {
        if let Some(stream) = self.open_files.open.remove(handle) {
            save(stream).map_err(|m| Diag::new(span, m))?;
        }
        self.undef(handle);
        Ok(())
    }

    /// Saves the files the scene left open, as POV-Ray does at the end of parsing.
    pub(crate) fn close_all_files(&mut self) -> Result<(), String> {
        let mut open: Vec<_> = self.open_files.open.drain().collect();
        open.sort_by(|a, b| a.0.cmp(&b.0));
        open.into_iter().try_for_each(|(_, s)| save(s))
    }

    /// `#read (Handle, A, B, ...)`: the next values of the file, in order. Once the last value
    /// is read the handle becomes undefined, as in POV-Ray (scenes loop `#while
    /// (defined(Handle))`).
    pub(crate) fn read_values(&mut self, handle: &str, targets: &[Rc<str>], span: Span) -> PResult<()> {
        for target in targets {
            let (value, at_end) = match self.open_files.open.get_mut(handle) {
                Some(Stream::Read { tokens, pos }) => {
                    let v = next_value(tokens, pos, span)?;
                    while tokens.get(*pos).is_some_and(|t| t.kind == TokenKind::Punct(',')) {
                        *pos += 1;
                    }
                    (v, tokens.get(*pos).is_none_or(|t| t.kind == TokenKind::Eof))
                }
                Some(Stream::Write { .. }) => {
                    return Err(Diag::new(span, format!("`{handle}` was opened for writing, not reading")))
                }
                None => return Err(Diag::new(span, format!("`{handle}` is not an open file"))),
            };
            if let Some(v) = value {
                self.assign(target, false, &[], v, span)?;
            }
            if at_end {
                self.open_files.open.remove(handle);
                self.undef(handle);
                return Ok(());
            }
        }
        Ok(())
    }

    /// `#write (Handle, item, ...)`: strings as they are, numbers and vectors as POV-Ray writes
    /// them.
    pub(crate) fn write_values(&mut self, handle: &str, values: &[Value], span: Span) -> PResult<()> {
        let Some(Stream::Write { text, .. }) = self.open_files.open.get_mut(handle) else {
            return Err(Diag::new(span, format!("`{handle}` is not a file open for writing")));
        };
        for v in values {
            match v {
                Value::Str(s) => text.push_str(s),
                Value::Float(x) => text.push_str(&number(*x)),
                Value::Vector(c) => {
                    let parts: Vec<String> = c.iter().map(|x| number(*x)).collect();
                    text.push_str(&format!("<{}>", parts.join(",")));
                }
                Value::Color(c) => {
                    let parts: Vec<String> =
                        [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit].iter().map(|x| number(*x)).collect();
                    text.push_str(&format!("<{}>", parts.join(",")));
                }
                other => return Err(other.wrong_kind(span, "a string, float or vector to write")),
            }
            if text.len() > MAX_WRITE_BYTES {
                return Err(Diag::new(span, format!("more than {MAX_WRITE_BYTES} bytes written to `{handle}`")));
            }
        }
        Ok(())
    }
}

/// A float as `#write` prints it: up to 6 significant decimals, no trailing zeros.
fn number(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// The next value in a data file: a number, a vector `<a, b, ...>` or a string, with the commas
/// between values skipped. `None` at the end of the file.
fn next_value(tokens: &[Token], pos: &mut usize, span: Span) -> PResult<Option<Value>> {
    let kind = |p: usize| tokens.get(p).map_or(&TokenKind::Eof, |t| &t.kind);
    while *kind(*pos) == TokenKind::Punct(',') {
        *pos += 1;
    }
    let signed = |p: &mut usize| -> Option<f64> {
        let sign = match kind(*p) {
            TokenKind::Punct('-') => {
                *p += 1;
                -1.0
            }
            TokenKind::Punct('+') => {
                *p += 1;
                1.0
            }
            _ => 1.0,
        };
        match kind(*p) {
            TokenKind::Number(v) => {
                *p += 1;
                Some(sign * v)
            }
            _ => None,
        }
    };
    let bad = || Diag::new(span, "the file holds something other than numbers, vectors and strings");
    Ok(Some(match kind(*pos) {
        TokenKind::Eof => return Ok(None),
        TokenKind::Str(s) => {
            let s = s.clone();
            *pos += 1;
            Value::Str(s)
        }
        TokenKind::Punct('<') => {
            *pos += 1;
            let mut comps = vec![signed(pos).ok_or_else(bad)?];
            while *kind(*pos) == TokenKind::Punct(',') {
                *pos += 1;
                comps.push(signed(pos).ok_or_else(bad)?);
            }
            if *kind(*pos) != TokenKind::Punct('>') || !(2..=5).contains(&comps.len()) {
                return Err(bad());
            }
            *pos += 1;
            Value::Vector(comps)
        }
        _ => Value::Float(signed(pos).ok_or_else(bad)?),
    }))
}

/// Writes a closed file whole: into a temporary beside it, then renamed over the target.
fn save(stream: Stream) -> Result<(), String> {
    let Stream::Write { path, mut text, append } = stream else { return Ok(()) };
    if append {
        if let Ok(old) = std::fs::read_to_string(&path) {
            text.insert_str(0, &old);
        }
    }
    let tmp = path.with_extension("strahl-tmp");
    std::fs::write(&tmp, text.as_bytes()).and_then(|()| std::fs::rename(&tmp, &path)).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot write \"{}\": {e}", path.display())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_written_as_pov_ray_reads_them() {
        assert_eq!(number(1.0), "1");
        assert_eq!(number(-0.25), "-0.25");
        assert_eq!(number(1.0 / 3.0), "0.333333");
        assert_eq!(number(-0.0), "0");
    }

    #[test]
    fn values_are_read_back_in_order() {
        let tokens = lex(0, "1, -2.5, <1, -2, 3>, \"a b\"").unwrap();
        let mut pos = 0;
        let s = Span::default();
        assert_eq!(next_value(&tokens, &mut pos, s).unwrap(), Some(Value::Float(1.0)));
        assert_eq!(next_value(&tokens, &mut pos, s).unwrap(), Some(Value::Float(-2.5)));
        assert_eq!(next_value(&tokens, &mut pos, s).unwrap(), Some(Value::Vector(vec![1.0, -2.0, 3.0])));
        assert_eq!(next_value(&tokens, &mut pos, s).unwrap(), Some(Value::Str("a b".into())));
        assert_eq!(next_value(&tokens, &mut pos, s).unwrap(), None);
    }
}
