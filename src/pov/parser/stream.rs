//! The token source the parser reads: a stack of frames, each a run of tokens with a cursor
//! (the scene file, an included file, a macro body). Loops rewind a frame; a frame that runs out
//! is popped and reported, so the interpreter can close the scope it opened.

use std::ops::Range;
use std::rc::Rc;

use crate::pov::lexer::{Token, TokenKind};
use crate::pov::source::Span;

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

#[derive(Debug)]
struct Frame {
    tokens: Rc<[Token]>,
    pos: usize,
    end: usize,
    kind: FrameKind,
    /// Unique over the whole load: loops remember it to rewind only the frame they began in.
    id: u64,
    /// Given to every token read from the frame (`Span::expansion`).
    expansion: u32,
}

/// A place in the stream a loop can return to.
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
}

#[derive(Debug, Default)]
pub struct Stream {
    frames: Vec<Frame>,
    next_id: u64,
    /// Where input ended, for the final `Eof`.
    eof: Span,
}

impl Stream {
    /// Pushes `tokens[range]` (the lexer's final `Eof` excluded by the caller).
    pub fn push(&mut self, tokens: Rc<[Token]>, range: Range<usize>, kind: FrameKind, expansion: u32) {
        if let Some(last) = tokens.last() {
            if self.frames.is_empty() {
                self.eof = last.span;
            }
        }
        self.next_id += 1;
        self.frames.push(Frame { tokens, pos: range.start, end: range.end, kind, id: self.next_id, expansion });
    }

    /// Number of frames of `kind` on the stack.
    pub fn count(&self, kind: &FrameKind) -> usize {
        self.frames.iter().filter(|f| f.kind == *kind).count()
    }

    /// The next token of the top frame, or what ended.
    pub fn next(&mut self) -> Next {
        let Some(f) = self.frames.last_mut() else { return Next::End(self.eof) };
        if f.pos < f.end {
            let mut t = f.tokens[f.pos].clone();
            f.pos += 1;
            t.span.expansion = f.expansion;
            return Next::Token(t);
        }
        if f.kind == FrameKind::Main {
            return Next::End(f.tokens.get(f.end).map_or(self.eof, |t| t.span));
        }
        Next::FrameEnd
    }

    /// Removes the top frame, which ran out; returns its kind and id.
    pub fn pop(&mut self) -> Option<(FrameKind, u64)> {
        self.frames.pop().map(|f| (f.kind, f.id))
    }

    /// The kind of the token after the one last returned, without taking it (within the top
    /// frame; `None` at its end).
    pub fn peek_kind(&self) -> Option<&TokenKind> {
        let f = self.frames.last()?;
        (f.pos < f.end).then(|| &f.tokens[f.pos].kind)
    }

    /// The place just after the token last returned.
    pub fn mark(&self) -> Mark {
        self.frames.last().map_or(Mark { frame: 0, pos: 0 }, |f| Mark { frame: f.id, pos: f.pos })
    }

    /// Hands the token last read back to the top frame, to be read again (after the frames
    /// pushed above it are done).
    pub fn unread(&mut self) {
        if let Some(f) = self.frames.last_mut() {
            f.pos = f.pos.saturating_sub(1);
        }
    }

    /// The top frame's tokens (a macro body is a range of them).
    pub fn tokens(&self) -> Option<Rc<[Token]>> {
        self.frames.last().map(|f| f.tokens.clone())
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
                true
            }
            _ => false,
        }
    }
}
