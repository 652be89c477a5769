//! The token source the parser reads: a stack of frames, each a stretch of source text with a
//! cursor (the scene file, an included file, a macro body). Tokens are lexed as the parser asks
//! for them, never held for a whole file; loops rewind a frame to a remembered byte offset and
//! read the text again, as POV-Ray does. A frame that runs out is popped and reported, so the
//! interpreter can close the scope it opened.

use std::ops::Range;
use std::rc::Rc;

use crate::pov::lexer::{next_token, Token, TokenKind};
use crate::pov::source::{Diag, FileId, Span};

/// Why a frame is on the stack, and what must happen when it runs out.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FrameKind {
    /// The scene file: its end is the end of input.
    Main,
    /// An `#include`d file, with its own scope for `#local`.
    Include,
    /// A macro body, run in the scope of its call.
    Macro,
}

/// One file's text, shared by the frames reading it and the macros written in it.
#[derive(Clone)]
pub struct Text {
    pub file: FileId,
    pub text: Rc<str>,
}

impl PartialEq for Text {
    /// The same file: texts are shared, never copied.
    fn eq(&self, other: &Text) -> bool {
        self.file == other.file && Rc::ptr_eq(&self.text, &other.text)
    }
}

impl std::fmt::Debug for Text {
    /// The file and its length: a scene's text may be a hundred megabytes.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Text(file {}, {} bytes)", self.file, self.text.len())
    }
}

#[derive(Debug)]
struct Frame {
    source: Text,
    /// Byte offset just past the token last returned.
    pos: usize,
    /// Byte offset where the token last returned starts (`unread`, `cursor_mark`).
    last: usize,
    end: usize,
    kind: FrameKind,
    /// Unique over the whole load: loops remember it to rewind only the frame they began in.
    id: u64,
    /// Given to every token read from the frame (`Span::expansion`).
    expansion: u32,
}

/// A place in the stream a loop can return to: a byte offset in a frame's text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mark {
    pub frame: u64,
    pub pos: usize,
}

/// What `Stream::next` found.
pub enum Next {
    Token(Token),
    /// The top frame ran out (it stays until `pop`, so that a directive can finish first).
    FrameEnd,
    /// Every frame has run out: `Eof` at this span.
    End(Span),
    /// The text at the cursor is no token (an unclosed comment, a stray character).
    Error(Diag),
}

#[derive(Debug, Default)]
pub struct Stream {
    frames: Vec<Frame>,
    next_id: u64,
    /// Where input ended, for the final `Eof`.
    eof: Span,
}

impl Stream {
    /// Pushes the bytes `range` of `source` to be read next.
    pub fn push(&mut self, source: Text, range: Range<usize>, kind: FrameKind, expansion: u32) {
        if self.frames.is_empty() {
            let len = source.text.len();
            self.eof = Span::new(source.file, len, len);
        }
        self.next_id += 1;
        let (pos, end) = (range.start, range.end);
        self.frames.push(Frame { source, pos, last: pos, end, kind, id: self.next_id, expansion });
    }

    /// Number of frames of `kind` on the stack.
    pub fn count(&self, kind: &FrameKind) -> usize {
        self.frames.iter().filter(|f| f.kind == *kind).count()
    }

    /// The next token of the top frame, or what ended.
    pub fn next(&mut self) -> Next {
        let Some(f) = self.frames.last_mut() else { return Next::End(self.eof) };
        match next_token(f.source.file, &f.source.text, f.pos, f.end) {
            Ok(Some((mut t, after))) => {
                f.last = t.span.start as usize;
                f.pos = after;
                t.span.expansion = f.expansion;
                Next::Token(t)
            }
            Ok(None) if f.kind == FrameKind::Main => Next::End(Span::new(f.source.file, f.end, f.end)),
            Ok(None) => {
                f.last = f.end;
                f.pos = f.end;
                Next::FrameEnd
            }
            Err(mut e) => {
                e.span.expansion = f.expansion;
                Next::Error(e)
            }
        }
    }

    /// Removes the top frame, which ran out; returns its kind and id.
    pub fn pop(&mut self) -> Option<(FrameKind, u64)> {
        self.frames.pop().map(|f| (f.kind, f.id))
    }

    /// The kind of the token after the one last returned, without taking it (within the top
    /// frame; `None` at its end).
    pub fn peek_kind(&self) -> Option<TokenKind> {
        let f = self.frames.last()?;
        next_token(f.source.file, &f.source.text, f.pos, f.end).ok().flatten().map(|(t, _)| t.kind)
    }

    /// The place just after the token last returned.
    pub fn mark(&self) -> Mark {
        self.frames.last().map_or(Mark { frame: 0, pos: 0 }, |f| Mark { frame: f.id, pos: f.pos })
    }

    /// The place where the token last returned starts (to read it again from there).
    pub fn cursor_mark(&self) -> Mark {
        self.frames.last().map_or(Mark { frame: 0, pos: 0 }, |f| Mark { frame: f.id, pos: f.last })
    }

    /// Hands the token last read back to the top frame, to be read again (after the frames
    /// pushed above it are done).
    pub fn unread(&mut self) {
        if let Some(f) = self.frames.last_mut() {
            f.pos = f.last;
        }
    }

    /// The top frame's text (a macro body is a stretch of it).
    pub fn text(&self) -> Option<Text> {
        self.frames.last().map(|f| f.source.clone())
    }

    /// The id of the top frame.
    pub fn frame_id(&self) -> u64 {
        self.frames.last().map_or(0, |f| f.id)
    }

    /// Continues from `mark`, which must be in the top frame.
    pub fn rewind(&mut self, mark: Mark) -> bool {
        match self.frames.last_mut() {
            Some(f) if f.id == mark.frame => {
                f.pos = mark.pos;
                f.last = mark.pos;
                true
            }
            _ => false,
        }
    }
}
