//! Parser: tokens → syntax tree (`ast`). Knows the grammar of strahl's subset of POV-Ray's
//! language and rejects everything else by name; evaluates nothing (that is `lower`'s job).
//!
//! Split by topic: `expr` (expressions, colours), `scene` (camera, lights, objects) and
//! `textures` (pigment, normal, finish, texture, interior).

mod expr;
mod keywords;
mod scene;
mod textures;

use super::ast::{ClauseTest, DeclValue, DefaultItem, Expr, MessageKind, Stmt, StrExpr, SwitchClause};
use super::lexer::{Token, TokenKind};
use super::source::{Diag, PResult, Span};
pub(crate) use keywords::{is_pov_keyword, RESERVED, UNSUPPORTED_SHAPES};

/// Deepest nesting of blocks, parentheses and vectors; deeper input is rejected so that hostile
/// files cannot overflow the stack of this recursive-descent parser.
pub const MAX_DEPTH: usize = 128;

/// Why a second texture on one object (or in one declaration) is refused.
pub(crate) const LAYERED: &str =
    "layered textures (a `texture` over another one) are not supported yet; use one `texture`";

/// Directives that end a nested statement list.
const BLOCK_ENDS: &[&str] = &["end", "else", "elseif", "case", "range"];

/// Parses one file's tokens (`text` is only used to quote positions in messages).
pub fn parse(tokens: &[Token], text: &str) -> PResult<Vec<Stmt>> {
    let mut p = Parser { tokens, pos: 0, depth: 0, text, in_csg: false, bare_name: None };
    let stmts = p.stmts(false)?;
    Ok(stmts)
}

pub(crate) struct Parser<'a> {
    tokens: &'a [Token],
    pos: usize,
    depth: usize,
    text: &'a str,
    /// True while reading the children of a `union`/`merge` (modifiers end the list).
    in_csg: bool,
    /// The token index of a lone word just read as a declared name where a keyword could also
    /// stand (`finish { F_Shiny ...`, a light's bare colour): `unknown_in` checks whether it was
    /// a misspelt keyword instead (`finish { phongg 1 }`).
    bare_name: Option<usize>,
}

impl<'a> Parser<'a> {
    // ---- token helpers -------------------------------------------------------------------

    fn peek(&self) -> &'a Token {
        // `lex` always ends with Eof, and `bump` never moves past it.
        &self.tokens[self.pos.min(self.tokens.len() - 1)]
    }

    fn bump(&mut self) -> &'a Token {
        let t = self.peek();
        if t.kind != TokenKind::Eof {
            self.pos += 1;
        }
        t
    }

    fn peek_ident(&self) -> Option<&'a str> {
        match &self.peek().kind {
            TokenKind::Ident(s) => Some(s.as_str()),
            _ => None,
        }
    }

    fn is_punct(&self, c: char) -> bool {
        self.peek().kind == TokenKind::Punct(c)
    }

    fn eat_punct(&mut self, c: char) -> bool {
        if self.is_punct(c) {
            self.bump();
            true
        } else {
            false
        }
    }

    fn expect_punct(&mut self, c: char, context: &str) -> PResult<Span> {
        if self.is_punct(c) {
            return Ok(self.bump().span);
        }
        let t = self.peek();
        Err(Diag::new(t.span, format!("expected `{c}` {context}, found {}", t.describe())))
    }

    /// "3:1" for a span in this file, for messages that point back at an opener.
    fn line_col(&self, span: Span) -> String {
        let before = &self.text[..(span.start as usize).min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        format!("{line}:{col}")
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
    fn at_block_end(&self) -> bool {
        matches!(self.peek().kind, TokenKind::Punct('}') | TokenKind::Eof)
    }

    /// Parses the value at the cursor with `value`, remembering it in `bare_name` when it is
    /// one lone word (which may be a misspelt keyword rather than a declared name).
    fn maybe_bare_name<T>(&mut self, value: impl FnOnce(&mut Self) -> PResult<T>) -> PResult<T> {
        let start = self.pos;
        let v = value(self)?;
        let lone_word = self.pos == start + 1 && matches!(self.tokens[start].kind, TokenKind::Ident(_));
        self.bare_name = lone_word.then_some(start);
        Ok(v)
    }

    /// Whether the word at token `at`, read as a declared name, was rather meant as one of the
    /// `expected` keywords: the token after it cannot follow a name there (checked by the
    /// caller), and it is a value (`phongg 1`) or the word is a near miss of a keyword (`colr
    /// Red`). `F_Shiny phongg 1` still blames `phongg`.
    fn misread_keyword(&self, at: usize, expected: &[&str]) -> Option<&'a Token> {
        let word_token = &self.tokens[at];
        let TokenKind::Ident(word) = &word_token.kind else { return None };
        let followed_by_value =
            !matches!(self.peek().kind, TokenKind::Ident(_) | TokenKind::Punct('}') | TokenKind::Eof);
        let near_miss = expected.iter().any(|k| is_near_miss(word, k));
        (followed_by_value || near_miss).then_some(word_token)
    }

    /// The error for a word a block does not accept.
    fn unknown_in(&self, context: &str, expected: &[&str]) -> Diag {
        if let Some(at) = self.bare_name.filter(|&at| at + 1 == self.pos) {
            if let Some(word) = self.misread_keyword(at, expected) {
                return self.unknown_token(word, context, expected);
            }
        }
        self.unknown_token(self.peek(), context, expected)
    }

    fn unknown_token(&self, t: &Token, context: &str, expected: &[&str]) -> Diag {
        let list = expected.join(", ");
        let message = match &t.kind {
            TokenKind::Ident(word) if is_pov_keyword(word) => {
                format!("`{word}` is not supported in {context} (supported: {list})")
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

    // ---- statements ----------------------------------------------------------------------

    /// Statements until end of file, or (when `nested`) until a directive that ends a block
    /// (`#end`, `#else`, `#elseif`, `#case`, `#range`), which is left for the caller. Inside a
    /// `union` (`self.in_csg`), a modifier keyword or `}` also ends the list.
    fn stmts(&mut self, nested: bool) -> PResult<Vec<Stmt>> {
        let mut out = Vec::new();
        loop {
            let t = self.peek();
            match &t.kind {
                TokenKind::Eof => {
                    if nested {
                        return Err(Diag::new(t.span, "expected `#end`, found end of file"));
                    }
                    return Ok(out);
                }
                TokenKind::Directive(d) if BLOCK_ENDS.contains(&d.as_str()) => {
                    if nested {
                        return Ok(out);
                    }
                    let opener = match d.as_str() {
                        "case" | "range" => "`#switch`",
                        "end" => "`#if`, `#ifdef`, `#ifndef`, `#while` or `#switch`",
                        _ => "`#if`",
                    };
                    return Err(Diag::new(t.span, format!("`#{d}` without a matching {opener}")));
                }
                TokenKind::Directive(d) => {
                    let d = d.clone();
                    out.push(self.directive(&d)?);
                }
                TokenKind::Punct(';') => {
                    // A stray `;` after an object or declaration, as POV-Ray tolerates.
                    self.bump();
                }
                TokenKind::Punct('}') if self.in_csg => return Ok(out),
                TokenKind::Ident(w) if self.in_csg && scene::MODIFIERS.contains(&w.as_str()) => return Ok(out),
                _ => out.push(self.item()?),
            }
        }
    }

    /// `( expression )` after a directive: comparisons and logic are allowed inside.
    fn condition(&mut self, directive: &str) -> PResult<Expr> {
        self.expect_punct('(', &format!("after `#{directive}`"))?;
        let e = self.full_expr()?;
        self.expect_punct(')', &format!("to close the condition of `#{directive}`"))?;
        Ok(e)
    }

    /// The directive that ended a nested statement list, or an error naming what was open.
    fn block_end(&self, opener: &str, start: Span) -> PResult<(&'a str, Span)> {
        let t = self.peek();
        match &t.kind {
            TokenKind::Directive(d) => Ok((d.as_str(), t.span)),
            _ => Err(Diag::new(
                t.span,
                format!(
                    "expected `#end` to close `#{opener}` opened at {}, found {}",
                    self.line_col(start),
                    t.describe()
                ),
            )),
        }
    }

    fn directive(&mut self, name: &str) -> PResult<Stmt> {
        let start = self.bump().span;
        match name {
            "version" => {
                let value = self.expr()?;
                self.eat_punct(';');
                Ok(Stmt::Version { span: start.to(value.span), value })
            }
            "include" => {
                let t = self.bump();
                match &t.kind {
                    TokenKind::Str(path) => Ok(Stmt::Include { path: path.clone(), span: start, path_span: t.span }),
                    _ => Err(Diag::new(
                        t.span,
                        format!("expected a file name string after `#include`, found {}", t.describe()),
                    )),
                }
            }
            "declare" | "local" => self.declare(name == "local", start),
            "ifdef" | "ifndef" => {
                self.enter(start)?;
                self.expect_punct('(', &format!("after `#{name}`"))?;
                let t = self.bump();
                let ident = match &t.kind {
                    TokenKind::Ident(s) => s.clone(),
                    _ => {
                        return Err(Diag::new(
                            t.span,
                            format!("expected an identifier in `#{name}`, found {}", t.describe()),
                        ))
                    }
                };
                self.expect_punct(')', &format!("to close `#{name}`"))?;
                let body = self.stmts(true)?;
                let mut otherwise = Vec::new();
                if self.block_end(name, start)?.0 == "else" {
                    self.bump();
                    otherwise = self.stmts(true)?;
                }
                self.expect_end(name, start)?;
                self.leave();
                Ok(Stmt::IfDef { name: ident, negate: name == "ifndef", body, otherwise, span: start })
            }
            "if" => {
                self.enter(start)?;
                let mut branches = vec![(self.condition("if")?, self.stmts(true)?)];
                let mut otherwise = None;
                loop {
                    match self.block_end("if", start)? {
                        ("elseif", _) if otherwise.is_none() => {
                            self.bump();
                            branches.push((self.condition("elseif")?, self.stmts(true)?));
                        }
                        ("else", _) if otherwise.is_none() => {
                            self.bump();
                            otherwise = Some(self.stmts(true)?);
                        }
                        _ => break,
                    }
                }
                self.expect_end("if", start)?;
                self.leave();
                Ok(Stmt::If { branches, otherwise, span: start })
            }
            "while" => {
                self.enter(start)?;
                let cond = self.condition("while")?;
                let body = self.stmts(true)?;
                self.expect_end("while", start)?;
                self.leave();
                Ok(Stmt::While { cond, body, span: start })
            }
            "switch" => self.switch(start),
            "default" => self.default(start),
            "break" => Ok(Stmt::Break { span: start }),
            "debug" | "warning" | "error" => {
                let kind = match name {
                    "debug" => MessageKind::Debug,
                    "warning" => MessageKind::Warning,
                    _ => MessageKind::Error,
                };
                let text = self.str_expr()?;
                Ok(Stmt::Message { kind, text, span: start })
            }
            // `lex` rejects unknown directives by name; block ends are handled by `stmts`.
            _ => Err(Diag::new(start, format!("`#{name}` is not allowed here"))),
        }
    }

    /// Consumes the `#end` of a block opened by `#opener`, or says what was found instead.
    fn expect_end(&mut self, opener: &str, start: Span) -> PResult<()> {
        match self.block_end(opener, start)? {
            ("end", _) => {
                self.bump();
                Ok(())
            }
            (d, span) => Err(Diag::new(
                span,
                format!("`#{d}` is not allowed in `#{opener}` opened at {} (expected `#end`)", self.line_col(start)),
            )),
        }
    }

    /// A string literal, `concat(s, ...)` or `str(value, width, precision)`.
    fn str_expr(&mut self) -> PResult<StrExpr> {
        let t = self.bump();
        match &t.kind {
            TokenKind::Str(s) => Ok(StrExpr::Lit(s.clone())),
            TokenKind::Ident(w) if w == "concat" => {
                self.expect_punct('(', "after `concat`")?;
                self.enter(t.span)?;
                let mut parts = vec![self.str_expr()?];
                while self.eat_punct(',') {
                    parts.push(self.str_expr()?);
                }
                self.expect_punct(')', "to close `concat(`")?;
                self.leave();
                Ok(StrExpr::Concat(parts))
            }
            TokenKind::Ident(w) if w == "str" => {
                self.expect_punct('(', "after `str`")?;
                let value = self.full_expr()?;
                self.expect_punct(',', "in `str(value, width, precision)`")?;
                let width = self.full_expr()?;
                self.expect_punct(',', "in `str(value, width, precision)`")?;
                let precision = self.full_expr()?;
                self.expect_punct(')', "to close `str(`")?;
                Ok(StrExpr::Str(Box::new(value), Box::new(width), Box::new(precision)))
            }
            _ => Err(Diag::new(
                t.span,
                format!("expected a string (a literal, `concat(...)` or `str(...)`), found {}", t.describe()),
            )),
        }
    }

    fn switch(&mut self, start: Span) -> PResult<Stmt> {
        self.enter(start)?;
        let value = self.condition("switch")?;
        let mut clauses = Vec::new();
        loop {
            let (d, span) = self.block_end("switch", start)?;
            let test = match d {
                "case" => {
                    self.bump();
                    ClauseTest::Case(self.condition("case")?)
                }
                "range" => {
                    self.bump();
                    self.expect_punct('(', "after `#range`")?;
                    let lo = self.full_expr()?;
                    self.expect_punct(',', "between the bounds of `#range`")?;
                    let hi = self.full_expr()?;
                    self.expect_punct(')', "to close `#range`")?;
                    ClauseTest::Range(lo, hi)
                }
                "else" => {
                    self.bump();
                    ClauseTest::Else
                }
                "end" => {
                    self.bump();
                    break;
                }
                _ => {
                    return Err(Diag::new(
                        span,
                        format!("expected `#case`, `#range`, `#else` or `#end` in `#switch`, found `#{d}`"),
                    ))
                }
            };
            let body = self.stmts(true)?;
            clauses.push(SwitchClause { test, body, span });
        }
        self.leave();
        Ok(Stmt::Switch { value, clauses, span: start })
    }

    /// `#default { texture {..} pigment {..} normal {..} finish {..} }`, in any number and order.
    fn default(&mut self, start: Span) -> PResult<Stmt> {
        const ITEMS: &[&str] = &["texture", "pigment", "normal", "finish"];
        self.open_block("#default", start)?;
        let mut items = Vec::new();
        while !self.at_block_end() {
            items.push(match self.peek_ident() {
                Some("texture") => {
                    let t = self.texture()?;
                    self.refuse_layer()?;
                    DefaultItem::Texture(t)
                }
                Some("pigment") => DefaultItem::Pigment(self.pigment()?),
                Some("normal") => DefaultItem::Normal(self.normal()?),
                Some("finish") => DefaultItem::Finish(self.finish()?),
                _ => return Err(self.unknown_in("#default", ITEMS)),
            });
        }
        let end = self.close_block("#default", start)?;
        Ok(Stmt::Default { items, span: start.to(end) })
    }

    /// After a `texture { }` that a second one could layer over: POV-Ray would composite them
    /// (`texture {A} texture {B}`); strahl refuses rather than drop a layer.
    pub(super) fn refuse_layer(&self) -> PResult<()> {
        match self.peek_ident() {
            Some("texture") => Err(Diag::new(self.peek().span, LAYERED)),
            _ => Ok(()),
        }
    }

    fn declare(&mut self, local: bool, start: Span) -> PResult<Stmt> {
        let t = self.bump();
        let name = match &t.kind {
            TokenKind::Ident(s) => s.clone(),
            _ => {
                return Err(Diag::new(
                    t.span,
                    format!("expected an identifier after `#declare`, found {}", t.describe()),
                ))
            }
        };
        if RESERVED.contains(&name.as_str()) || is_pov_keyword(&name) {
            return Err(Diag::new(t.span, format!("cannot declare `{name}`: it is a keyword")));
        }
        let name_span = t.span;
        self.expect_punct('=', &format!("after `#declare {name}`"))?;
        let value = match self.peek_ident() {
            Some("pigment") => DeclValue::Pigment(self.pigment()?),
            Some("normal") => DeclValue::Normal(self.normal()?),
            Some("finish") => DeclValue::Finish(self.finish()?),
            Some("texture") => {
                let t = self.texture()?;
                self.refuse_layer()?;
                DeclValue::Texture(t)
            }
            Some("interior") => DeclValue::Interior(self.interior()?),
            Some("color_map" | "colour_map") => DeclValue::ColorMap(self.color_map()?),
            Some("camera") => DeclValue::Camera(self.camera_items()?.0),
            Some(word) if scene::is_object_keyword(word) || UNSUPPORTED_SHAPES.contains(&word) => {
                DeclValue::Object(self.object()?)
            }
            _ => DeclValue::Expr(self.color()?),
        };
        self.eat_punct(';');
        Ok(Stmt::Declare { name, local, value, span: start.to(name_span) })
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
