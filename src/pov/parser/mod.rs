//! Parser and interpreter of the scene language: tokens → scene items (`ast::Stmt`), each handed
//! to `lower` as soon as it is read. POV-Ray's language is a token stream run by a directive
//! interpreter, and so is this: `stream` holds the frames (file, include, macro body),
//! `directives` runs `#declare`, `#if`, `#while`, `#macro`... the moment the parser would see
//! them, and `macros` expands calls. Declared names are resolved as they are read.
//!
//! Split by topic: `expr` (expressions, colours), `scene` (camera, lights, objects) and
//! `textures` (pigment, normal, finish, texture, interior).

mod atmosphere;
mod bicubic;
mod blob;
mod camera;
mod declarations;
mod directives;
mod expr;
mod finish;
mod function;
mod global;
mod image;
mod isosurface;
mod julia;
mod keywords;
mod light;
mod light_group;
mod macros;
mod material;
mod mesh;
mod probe;
mod scene;
mod spline;
mod stream;
mod textures;

use std::rc::Rc;

use super::ast::Stmt;
use super::lexer::{Token, TokenKind};
use super::lower::Lowerer;
use super::source::{Diag, Expansion, FileId, PResult, Span};
use directives::Cond;
pub(crate) use keywords::{is_pov_keyword, is_reserved, UNSUPPORTED_SHAPES};
use macros::MacroCall;
pub(crate) use stream::Text;
use stream::{FrameKind, Next, Stream};

/// Deepest nesting of blocks, parentheses and vectors; deeper input is rejected so that hostile
/// files cannot overflow the stack of this recursive-descent parser.
pub const MAX_DEPTH: usize = 128;

/// Why a second texture on one object (or in one declaration) is refused.
pub(crate) const LAYERED: &str =
    "layered textures (a `texture` over another one) are not supported yet; use one `texture`";

/// Runs a scene file's text, lowering each item into `low` as soon as it is read.
/// Returns the macro expansions that spans refer to, for locating errors, also on failure.
pub fn run(low: &mut Lowerer<'_>, file: FileId, text: Rc<str>) -> (PResult<()>, Vec<Expansion>) {
    let mut stream = Stream::default();
    let end = text.len();
    stream.push(Text { file, text }, 0..end, FrameKind::Main, 0);
    let mut p = Parser {
        stream,
        cur: Token { kind: TokenKind::Eof, span: Span::default() },
        ready: false,
        low,
        pending: None,
        depth: 0,
        in_csg: false,
        bare_name: None,
        consumed: 0,
        braces: 0,
        conds: Vec::new(),
        calls: Vec::new(),
        expansions: Vec::new(),
        expansion_ids: Default::default(),
    };
    p.advance_raw();
    let result = p.top_level();
    let result = match p.pending.take() {
        Some(e) => Err(e),
        None => result,
    };
    (result, p.expansions)
}

pub(crate) struct Parser<'l, 'f> {
    stream: Stream,
    /// The token at the cursor, as read from the stream (a directive or macro call in it has
    /// not run yet unless `ready`).
    cur: Token,
    /// `cur` is a plain token: its directive ran or it was found not to be a macro call.
    ready: bool,
    /// Declarations, scopes and lowering: directives store values there as they run.
    pub(crate) low: &'l mut Lowerer<'f>,
    /// The error a directive or macro call met while the parser was only peeking; the cursor
    /// shows end of file from then on, and `run` reports this error instead of what follows.
    pending: Option<Diag>,
    depth: usize,
    /// True while reading the children of a `union`/`merge` (modifiers end the list).
    in_csg: bool,
    /// A lone word just read as a declared name where a keyword could also stand (`finish {
    /// F_Shiny ...`, a light's bare colour), with the token count after it: `unknown_in`
    /// checks whether it was a misspelt keyword instead (`finish { phongg 1 }`).
    bare_name: Option<(u64, Token)>,
    /// Tokens consumed so far.
    consumed: u64,
    /// `{` minus `}` consumed so far (to skip the rest of an unmodelled declaration).
    braces: usize,
    /// Open `#if`, `#while`, `#for`, `#switch`, innermost last.
    conds: Vec<Cond>,
    /// Macro calls being run, innermost last.
    calls: Vec<MacroCall>,
    expansions: Vec<Expansion>,
    expansion_ids: std::collections::HashMap<Expansion, u32>,
}

impl Parser<'_, '_> {
    // ---- the token stream ----------------------------------------------------------------

    /// Reads the next token from the stream into `cur` (`FrameEnd` where a frame runs out).
    fn advance_raw(&mut self) {
        if self.pending.is_some() {
            return;
        }
        match self.stream.next() {
            Next::Token(t) => {
                self.cur = t;
                self.ready = false;
            }
            Next::FrameEnd => {
                // Closed when the parser reads past it (`expand`), not now: the directive that
                // took the frame's last token may still need the frame's scope.
                self.cur = Token { kind: TokenKind::FrameEnd, span: self.cur.span };
                self.ready = false;
            }
            Next::End(span) => {
                self.cur = Token { kind: TokenKind::Eof, span };
                self.ready = true;
            }
            Next::Error(e) => self.fail(e),
        }
    }

    /// Stops the stream at an error met while peeking.
    fn fail(&mut self, e: Diag) {
        let span = e.span;
        if self.pending.is_none() {
            self.pending = Some(e);
        }
        self.cur = Token { kind: TokenKind::Eof, span };
        self.ready = true;
    }

    /// Runs directives and macro calls at the cursor until a plain token stands there.
    fn expand(&mut self) {
        while !self.ready {
            let result = match &self.cur.kind {
                TokenKind::FrameEnd => {
                    self.close_frame();
                    Ok(())
                }
                TokenKind::Directive(d) => {
                    // A directive inside another one's value (`#declare A = #if (..) 1 #end`)
                    // nests on the stack: counted like any other nesting.
                    let (d, span) = (*d, self.cur.span);
                    self.enter(span).and_then(|()| {
                        let result = self.directive(d);
                        self.leave();
                        result
                    })
                }
                TokenKind::Ident(name) => match self.low.lookup(name) {
                    Some(super::value::Value::Macro(m)) => {
                        let (m, span) = (m.clone(), self.cur.span);
                        // Arguments may call macros in turn: counted as nesting.
                        self.enter(span).and_then(|()| {
                            let result = self.call_macro(m);
                            self.leave();
                            result
                        })
                    }
                    _ => {
                        self.ready = true;
                        Ok(())
                    }
                },
                _ => {
                    self.ready = true;
                    Ok(())
                }
            };
            if let Err(e) = result {
                self.fail(e);
            }
        }
    }

    /// At `FrameEnd`: closes the frame (its scope, its include) and reads on in the one below.
    fn close_frame(&mut self) {
        if let Some((kind, id)) = self.stream.pop() {
            match self.frame_ended(kind, id) {
                Ok(()) => self.advance_raw(),
                Err(e) => self.fail(e),
            }
        } else {
            self.ready = true;
        }
    }

    /// Takes the token at the cursor as it is (a directive's own words: names are not
    /// resolved, directives do not run).
    fn take_raw(&mut self) -> Token {
        if matches!(self.cur.kind, TokenKind::Eof | TokenKind::FrameEnd) {
            return self.cur.clone();
        }
        let t = std::mem::replace(&mut self.cur, Token { kind: TokenKind::Eof, span: Span::default() });
        match t.kind {
            TokenKind::Punct('{') => self.braces += 1,
            TokenKind::Punct('}') => self.braces = self.braces.saturating_sub(1),
            _ => {}
        }
        self.consumed += 1;
        self.advance_raw();
        t
    }

    /// The next plain token, without taking it.
    fn peek(&mut self) -> Token {
        self.expand();
        self.cur.clone()
    }

    fn bump(&mut self) -> Token {
        self.expand();
        self.take_raw()
    }

    fn peek_ident(&mut self) -> Option<Rc<str>> {
        self.expand();
        match &self.cur.kind {
            TokenKind::Ident(s) => Some(s.clone()),
            _ => None,
        }
    }

    fn is_punct(&mut self, c: char) -> bool {
        self.expand();
        self.cur.kind == TokenKind::Punct(c)
    }

    fn eat_punct(&mut self, c: char) -> bool {
        if self.is_punct(c) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// After a directive: takes `;` if it stands next, without running what follows (a
    /// `#declare` must store its value before the next directive reads it).
    fn eat_raw_semicolon(&mut self) {
        if self.cur.kind == TokenKind::Punct(';') {
            self.take_raw();
        }
    }

    fn expect_punct(&mut self, c: char, context: &str) -> PResult<Span> {
        if self.is_punct(c) {
            return Ok(self.bump().span);
        }
        let t = self.peek();
        Err(Diag::new(t.span, format!("expected `{c}` {context}, found {}", t.describe())))
    }

    /// "3:1" for a span in the file at the cursor, "file:3:1" elsewhere: for messages that
    /// point back at an opener.
    fn line_col(&self, span: Span) -> String {
        let at = self.low.source_ref(span);
        if span.file == self.cur.span.file {
            format!("{}:{}", at.line, at.col)
        } else {
            format!("{}:{}:{}", at.file, at.line, at.col)
        }
    }

    /// Counts one level of nesting; pair with `leave`.
    fn enter(&mut self, span: Span) -> PResult<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(Diag::new(span, format!("nesting deeper than {MAX_DEPTH} levels")));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Consumes `{` after a block keyword and counts the nesting level.
    fn open_block(&mut self, keyword: &str, kw_span: Span) -> PResult<()> {
        self.expect_punct('{', &format!("after `{keyword}`"))?;
        self.enter(kw_span)
    }

    /// At the end of a block body: consumes `}` or reports what was found instead.
    fn close_block(&mut self, keyword: &str, kw_span: Span) -> PResult<Span> {
        if self.is_punct('}') {
            self.leave();
            return Ok(self.bump().span);
        }
        let t = self.peek();
        Err(Diag::new(
            t.span,
            format!("expected `}}` to close `{keyword}` opened at {}, found {}", self.line_col(kw_span), t.describe()),
        ))
    }

    /// True at the end of a block body (`}` or end of file).
    fn at_block_end(&mut self) -> bool {
        matches!(self.peek().kind, TokenKind::Punct('}') | TokenKind::Eof)
    }

    /// Parses the value at the cursor with `value`, remembering it in `bare_name` when it is
    /// one lone word (which may be a misspelt keyword rather than a declared name).
    fn maybe_bare_name<T>(&mut self, value: impl FnOnce(&mut Self) -> PResult<T>) -> PResult<T> {
        let start = self.consumed;
        let first = self.peek();
        let v = value(self)?;
        let lone_word = self.consumed == start + 1 && matches!(first.kind, TokenKind::Ident(_));
        self.bare_name = lone_word.then_some((self.consumed, first));
        Ok(v)
    }

    /// Whether the word at token `at`, read as a declared name, was rather meant as one of the
    /// `expected` keywords: the token after it cannot follow a name there (checked by the
    /// caller), and it is a value (`phongg 1`) or the word is a near miss of a keyword (`colr
    /// Red`). `F_Shiny phongg 1` still blames `phongg`.
    fn misread_keyword(&mut self, word_token: &Token, expected: &[&str]) -> bool {
        let TokenKind::Ident(word) = &word_token.kind else { return false };
        let followed_by_value =
            !matches!(self.peek().kind, TokenKind::Ident(_) | TokenKind::Punct('}') | TokenKind::Eof);
        let near_miss = expected.iter().any(|k| is_near_miss(word, k));
        followed_by_value || near_miss
    }

    /// The error for a word a block does not accept.
    fn unknown_in(&mut self, context: &str, expected: &[&str]) -> Diag {
        if let Some((at, word)) = self.bare_name.clone() {
            if at == self.consumed && self.misread_keyword(&word, expected) {
                return self.unknown_token(&word, context, expected);
            }
        }
        let t = self.peek();
        self.unknown_token(&t, context, expected)
    }

    fn unknown_token(&self, t: &Token, context: &str, expected: &[&str]) -> Diag {
        let list = expected.join(", ");
        let message = match &t.kind {
            TokenKind::Ident(word) if is_pov_keyword(word) || is_reserved(word) => {
                return Diag::unmodelled(t.span, format!("`{word}` is not supported in {context} (supported: {list})"));
            }
            TokenKind::Ident(word) => {
                format!("unknown keyword `{word}` in {context} (expected one of: {list})")
            }
            TokenKind::Eof => {
                format!("unexpected end of file in {context}")
            }
            _ => format!("unexpected {} in {context} (expected one of: {list})", t.describe()),
        };
        Diag::new(t.span, message)
    }

    /// At the keyword of a feature strahl does not model (`radiosity { }`, `media { }`,
    /// `photons { }`): takes it and its block, if one follows, running the directives and macro
    /// calls inside as POV-Ray would, and notes the feature once (`Lowerer::not_modelled`).
    pub(super) fn skip_unmodelled(&mut self, feature: &str) -> PResult<()> {
        let kw = self.bump().span;
        self.low.not_modelled(feature, kw);
        if self.is_punct('{') {
            self.skip_braced(feature, kw)?;
        }
        Ok(())
    }

    /// Skips a `{ .. }` block after `keyword` (spanned `kw`), nested blocks included.
    pub(super) fn skip_braced(&mut self, keyword: &str, kw: Span) -> PResult<()> {
        self.open_block(keyword, kw)?;
        self.skip_to_close(keyword, kw)
    }

    /// Skips to the `}` that closes the block open now (nested blocks included), and past it.
    pub(super) fn skip_to_close(&mut self, keyword: &str, kw: Span) -> PResult<()> {
        let mut depth = 0usize;
        loop {
            let t = self.peek();
            match t.kind {
                TokenKind::Eof => {
                    return Err(Diag::new(t.span, format!("unexpected end of file in `{keyword}` opened here")));
                }
                TokenKind::Punct('{') => depth += 1,
                TokenKind::Punct('}') if depth == 0 => break,
                TokenKind::Punct('}') => depth -= 1,
                _ => {}
            }
            self.bump();
        }
        self.close_block(keyword, kw)?;
        Ok(())
    }

    /// Whether a boolean value follows an optional-boolean keyword (`jitter`, `hollow off`).
    pub(super) fn starts_bool(&mut self) -> bool {
        match &self.peek().kind {
            TokenKind::Number(_) => true,
            TokenKind::Punct(c) => matches!(c, '(' | '-' | '+'),
            TokenKind::Ident(w) => matches!(&**w, "on" | "off" | "true" | "false" | "yes" | "no"),
            _ => false,
        }
    }

    // ---- statements ----------------------------------------------------------------------

    /// The scene: each item is lowered as soon as it is read, so that the directives after it
    /// see the scene as it stands.
    fn top_level(&mut self) -> PResult<()> {
        loop {
            match self.peek().kind {
                TokenKind::Eof => break,
                TokenKind::Punct(';') => {
                    // A stray `;` after an object or declaration, as POV-Ray tolerates.
                    self.bump();
                }
                // `default { }` without its `#`, which POV-Ray still reads (whiltile.pov).
                TokenKind::Ident(w) if &*w == "default" => {
                    let start = self.bump().span;
                    self.default(start)?;
                }
                _ => {
                    let stmt = self.item()?;
                    if self.pending.is_some() {
                        break;
                    }
                    self.low.stmt(&stmt)?;
                }
            }
        }
        if let Some(open) = self.conds.last() {
            return Err(open.unclosed("the scene file"));
        }
        Ok(())
    }

    /// The children of a `union` or `merge`, until its `}` or a modifier.
    fn children(&mut self) -> PResult<Vec<Stmt>> {
        let mut out = Vec::new();
        loop {
            let t = self.peek();
            match &t.kind {
                TokenKind::Eof | TokenKind::Punct('}') => return Ok(out),
                TokenKind::Punct(';') => {
                    self.bump();
                }
                TokenKind::Ident(w) if scene::MODIFIERS.contains(&&**w) => return Ok(out),
                _ => out.push(self.item()?),
            }
        }
    }

    /// After a `texture { }` that a second one could layer over: POV-Ray would composite them
    /// (`texture {A} texture {B}`); strahl refuses rather than drop a layer.
    pub(super) fn refuse_layer(&mut self) -> PResult<()> {
        if matches!(self.cur.kind, TokenKind::Directive(_)) {
            // A directive after the texture ends it (a `#declare` must store it first).
            return Ok(());
        }
        // A word after it is not expanded: a macro call there (`Screen_Plane(T, ..)` in
        // POV-Ray's incdemo/screen.pov) must run after the declaration stores the texture.
        match self.more_ident().as_deref() {
            Some("texture") => Err(Diag::unmodelled(self.peek().span, LAYERED)),
            _ => Ok(()),
        }
    }
}

/// Whether `word` is one or two edits (insert, delete, replace a character) away from keyword
/// `keyword`, and not so short that anything is: `phongg`, `colr`, `Color` for `phong`, `color`.
fn is_near_miss(word: &str, keyword: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (word.chars().collect(), keyword.chars().collect());
    // Levenshtein distance, one row at a time.
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = if ca == cb { prev } else { prev + 1 };
            prev = row[j + 1];
            row[j + 1] = cost.min(row[j] + 1).min(prev + 1);
        }
    }
    let distance = row[b.len()];
    distance <= 2 && 2 * distance < b.len()
}

#[cfg(test)]
mod tests;
