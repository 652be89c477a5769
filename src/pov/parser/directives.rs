//! Directives, run where the stream meets them: inside any block, between the tokens of an
//! expression, as POV-Ray runs them. Conditionals skip the tokens of the branches not taken;
//! loops rewind the stream to their condition at `#end`.

use std::rc::Rc;

use super::stream::{FrameKind, Mark};
use super::Parser;
use crate::pov::lexer::TokenKind;
use crate::pov::lower::{FileMode, MessageKind, MAX_LOOP_ITERATIONS};
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::{truthy, Value, EPSILON};

/// A directive block being run.
#[derive(Clone, Debug)]
pub struct Cond {
    kind: CondKind,
    /// The directive that opened it.
    span: Span,
    /// The stream frame it was opened in: its `#end` must be in the same file or macro.
    frame: u64,
}

#[derive(Clone, Debug)]
enum CondKind {
    /// The branch of an `#if`/`#ifdef`/`#ifndef` being run.
    If,
    /// `#while`: `#end` rewinds to the condition.
    While { condition: Mark },
    /// `#for (Name, start, end, step)`: `#end` steps `Name` and rewinds to the body.
    For { name: Rc<str>, end: f64, step: f64, body: Mark },
    /// A `#switch` clause being run; later clauses fall through until `#break` or `#end`.
    Switch,
}

impl Cond {
    fn name(&self) -> &'static str {
        match self.kind {
            CondKind::If => "#if",
            CondKind::While { .. } => "#while",
            CondKind::For { .. } => "#for",
            CondKind::Switch => "#switch",
        }
    }

    pub fn frame_is(&self, id: u64) -> bool {
        self.frame == id
    }

    /// The error for a block still open at the end of `place`.
    pub fn unclosed(&self, place: &str) -> Diag {
        Diag::new(self.span, format!("`{}` is not closed by `#end` before the end of {place}", self.name()))
    }
}

/// Directives that open a block closed by `#end`.
const OPENERS: &[&str] = &["if", "ifdef", "ifndef", "while", "for", "switch", "macro"];

impl Parser<'_, '_> {
    /// Runs the directive at the cursor (`cur` is its token).
    pub(super) fn directive(&mut self, name: &'static str) -> PResult<()> {
        let start = self.cur.span;
        // Directives that close a block act before their token is taken: taking the last
        // token of a macro body or file closes that frame, and the block must be closed first.
        match name {
            "end" => return self.end(start),
            "break" => return self.break_out(start),
            "elseif" | "else" if matches!(self.conds.last().map(|c| &c.kind), Some(CondKind::If)) => {
                // The end of the branch that ran: skip the others.
                let cond = self.conds.pop().unwrap_or_else(|| unreachable!());
                self.skip_to(&["end"], "#if", cond.span)?;
                self.take_raw();
                return Ok(());
            }
            _ => {}
        }
        self.take_raw();
        match name {
            "version" => {
                let e = self.expr()?;
                let v = self.low.float(&e)?;
                if !(1.0..=3.8).contains(&v) {
                    return Err(Diag::new(e.span, format!("unsupported #version {v} (expected 1.0 to 3.8)")));
                }
                self.low.set_version(v);
                self.eat_raw_semicolon();
            }
            "include" => self.include(start)?,
            "declare" | "local" => self.declare(name == "local", start)?,
            "undef" => {
                let (name, _) = self.raw_name("#undef")?;
                self.low.undef(&name);
            }
            "ifdef" | "ifndef" => {
                self.expect_punct('(', &format!("after `#{name}`"))?;
                let defined = self.defined_name(name)?;
                self.expect_raw(')', &format!("to close `#{name}`"))?;
                if defined != (name == "ifndef") {
                    self.open(CondKind::If, start);
                } else {
                    self.skip_branch(name, start, false)?;
                }
            }
            "if" => {
                let c = self.condition("if")?;
                if truthy(c) {
                    self.open(CondKind::If, start);
                } else {
                    self.skip_branch("if", start, true)?;
                }
            }
            "elseif" | "else" => match self.conds.last().map(|c| &c.kind) {
                // `#else` in a `#switch` falls through like `#case`.
                Some(CondKind::Switch) if name == "else" => {}
                _ => return Err(Diag::new(start, format!("`#{name}` without a matching `#if`"))),
            },
            "case" | "range" => match self.conds.last().map(|c| &c.kind) {
                Some(CondKind::Switch) => {
                    // Falling through from the clause before: the test is read, not used.
                    self.clause_matches(name, 0.0)?;
                }
                _ => return Err(Diag::new(start, format!("`#{name}` without a matching `#switch`"))),
            },
            "while" => {
                let condition = self.cursor_mark();
                let c = self.condition("while")?;
                if truthy(c) {
                    self.count_iteration(start)?;
                    self.open(CondKind::While { condition }, start);
                } else {
                    self.skip_to(&["end"], "#while", start)?;
                    self.take_raw();
                }
            }
            "for" => self.for_loop(start)?,
            "switch" => {
                let v = self.condition("switch")?;
                self.enter_switch(v, start)?;
            }
            "macro" => self.define_macro(start)?,
            "debug" | "warning" | "error" | "render" | "statistics" => {
                let (text, _) = self.string_arg(name)?;
                let kind = match name {
                    "warning" => MessageKind::Warning,
                    "error" => MessageKind::Error,
                    _ => MessageKind::Debug,
                };
                self.low.message(kind, text, start)?;
            }
            "default" => self.default(start)?,
            "fopen" => {
                let (handle, _) = self.raw_name("#fopen")?;
                let (file, _) = self.string_arg("fopen")?;
                let mode = match &self.cur.kind {
                    TokenKind::Ident(w) if &**w == "read" => FileMode::Read,
                    TokenKind::Ident(w) if &**w == "write" => FileMode::Write,
                    TokenKind::Ident(w) if &**w == "append" => FileMode::Append,
                    _ => {
                        return Err(Diag::new(
                            self.cur.span,
                            format!(
                                "expected `read`, `write` or `append` after the file name, found {}",
                                self.cur.describe()
                            ),
                        ))
                    }
                };
                self.take_raw();
                self.low.fopen(&handle, &file, mode, start)?;
            }
            "fclose" => {
                let (handle, _) = self.raw_name("#fclose")?;
                self.low.fclose(&handle, start)?;
            }
            "read" => {
                self.expect_punct('(', "after `#read`")?;
                let (handle, _) = self.raw_name("#read (")?;
                let mut targets = Vec::new();
                while self.cur.kind == TokenKind::Punct(',') {
                    self.take_raw();
                    targets.push(self.raw_name("a comma in `#read`")?.0);
                }
                self.expect_raw(')', "to close `#read (...)`")?;
                self.low.read_values(&handle, &targets, start)?;
            }
            "write" => {
                self.expect_punct('(', "after `#write`")?;
                let (handle, _) = self.raw_name("#write (")?;
                let mut values = Vec::new();
                // The commas are optional, as POV-Ray reads them (`#write (F Header)`).
                while !self.is_punct(')') && !matches!(self.cur.kind, TokenKind::Eof | TokenKind::FrameEnd) {
                    self.eat_punct(',');
                    let e = self.full_expr()?;
                    values.push(self.low.eval(&e)?);
                }
                self.expect_raw(')', "to close `#write (...)`")?;
                self.low.write_values(&handle, &values, start)?;
            }
            _ => return Err(Diag::new(start, format!("`#{name}` is not allowed here"))),
        }
        Ok(())
    }

    /// Whether punctuation `c` comes next, without running a directive there first (what
    /// follows a declaration's value must wait until it is stored).
    pub(super) fn next_is(&mut self, c: char) -> bool {
        !matches!(self.cur.kind, TokenKind::Directive(_)) && self.is_punct(c)
    }

    fn open(&mut self, kind: CondKind, span: Span) {
        self.conds.push(Cond { kind, span, frame: self.stream.frame_id() });
    }

    /// Where the cursor's token stands, to come back to it (the token must be from the top
    /// frame, as it is right after a directive's own token).
    fn cursor_mark(&self) -> Mark {
        self.stream.cursor_mark()
    }

    /// Continues at `mark` in the top frame.
    fn rewind(&mut self, mark: Mark, cond: &Cond) -> PResult<()> {
        if !self.stream.rewind(mark) {
            return Err(Diag::new(cond.span, format!("`{}` must end in the file or macro it begins in", cond.name())));
        }
        self.advance_raw();
        Ok(())
    }

    fn count_iteration(&mut self, span: Span) -> PResult<()> {
        if !self.low.count_iteration() {
            return Err(Diag::new(
                span,
                format!("loops ran more than {MAX_LOOP_ITERATIONS} iterations in total; is the condition ever false?"),
            ));
        }
        Ok(())
    }

    /// `( expression )` after a directive, as a float: comparisons and logic are allowed.
    fn condition(&mut self, directive: &str) -> PResult<f64> {
        self.expect_punct('(', &format!("after `#{directive}`"))?;
        let e = self.full_expr()?;
        self.expect_raw(')', &format!("to close the condition of `#{directive}`"))?;
        self.low.float(&e)
    }

    /// Takes punctuation `c` without running what follows it.
    pub(super) fn expect_raw(&mut self, c: char, context: &str) -> PResult<Span> {
        self.expand();
        if self.cur.kind == TokenKind::Punct(c) {
            return Ok(self.take_raw().span);
        }
        Err(Diag::new(self.cur.span, format!("expected `{c}` {context}, found {}", self.cur.describe())))
    }

    /// An identifier a directive names (not resolved, not expanded).
    pub(super) fn raw_name(&mut self, directive: &str) -> PResult<(Rc<str>, Span)> {
        match &self.cur.kind {
            TokenKind::Ident(s) => {
                let s = s.clone();
                Ok((s, self.take_raw().span))
            }
            _ => Err(Diag::new(
                self.cur.span,
                format!("expected an identifier after `{directive}`, found {}", self.cur.describe()),
            )),
        }
    }

    /// `Name` or `Name[i]...` in `#ifdef (...)`: whether it is declared (an array element:
    /// whether it was given a value).
    pub(super) fn defined_name(&mut self, directive: &str) -> PResult<bool> {
        let (name, span) = self.raw_name(&format!("#{directive} ("))?;
        let indices = self.indices()?;
        let Some(value) = self.low.lookup(&name) else { return Ok(false) };
        if indices.is_empty() {
            return Ok(true);
        }
        match value {
            Value::Array(a) => {
                let at = a.offset(&indices).map_err(|m| Diag::new(span, m))?;
                Ok(a.items[at].is_some())
            }
            other => Err(Diag::new(span, format!("`{name}` is {}, not an array", other.kind_name()))),
        }
    }

    /// Skips the branch of an `#if` (or `#ifdef`) not taken: runs the first `#elseif` whose
    /// condition holds, or the `#else`, or ends at `#end`.
    fn skip_branch(&mut self, opener: &str, start: Span, elseif: bool) -> PResult<()> {
        let stops: &[&str] = if elseif { &["else", "elseif", "end"] } else { &["else", "end"] };
        loop {
            let found = self.skip_to(stops, &format!("#{opener}"), start)?;
            self.take_raw();
            match found {
                "elseif" => {
                    if truthy(self.condition("elseif")?) {
                        self.open(CondKind::If, start);
                        return Ok(());
                    }
                }
                "else" => {
                    self.open(CondKind::If, start);
                    return Ok(());
                }
                _ => return Ok(()),
            }
        }
    }

    /// Skips tokens of the current frame up to a directive in `stops` standing at the nesting
    /// level the skip began at, and leaves it at the cursor (not taken).
    pub(super) fn skip_to(&mut self, stops: &[&str], opener: &str, start: Span) -> PResult<&'static str> {
        let frame = self.stream.frame_id();
        let mut depth = 0usize;
        loop {
            match &self.cur.kind {
                TokenKind::Directive(d) => {
                    if depth == 0 && stops.contains(d) {
                        return Ok(d);
                    }
                    if OPENERS.contains(d) {
                        depth += 1;
                    } else if *d == "end" {
                        depth = depth.saturating_sub(1);
                    }
                }
                TokenKind::Eof | TokenKind::FrameEnd => {
                    let place = if self.cur.kind == TokenKind::Eof { "the file" } else { "its macro or file" };
                    return Err(Diag::new(
                        start,
                        format!("`{opener}` is not closed by `#end` before the end of {place}"),
                    ));
                }
                _ => {}
            }
            self.ready = true;
            self.take_raw();
            debug_assert_eq!(self.stream.frame_id(), frame);
        }
    }

    /// Whether directive `name` at the cursor only ends the `#if` branch being run, in the
    /// frame that opened it (its `#else`, `#elseif` or `#end`): it skips tokens or closes the
    /// block, reading no variable, so an expression may run it and go on. A macro body
    /// `#if (..) Value #else #error ".." #end` is then a value the caller can continue
    /// (`Rand_Array_Item(A, S) * 2` in advanced/isocacti.pov).
    pub(super) fn ends_running_branch(&self, name: &str) -> bool {
        matches!(name, "else" | "elseif" | "end")
            && matches!(self.conds.last(), Some(c) if matches!(c.kind, CondKind::If) && c.frame == self.stream.frame_id())
    }

    fn end(&mut self, start: Span) -> PResult<()> {
        let Some(cond) = self.conds.pop() else {
            return Err(Diag::new(
                start,
                "`#end` without a matching `#if`, `#ifdef`, `#ifndef`, `#while`, `#for`, `#switch` or `#macro`",
            ));
        };
        if cond.frame != self.stream.frame_id() {
            return Err(Diag::new(cond.span, format!("`{}` must end in the file or macro it begins in", cond.name())));
        }
        match &cond.kind {
            CondKind::If | CondKind::Switch => {
                self.take_raw();
            }
            CondKind::While { condition } => {
                let condition = *condition;
                self.rewind(condition, &cond)?;
                if truthy(self.condition("while")?) {
                    self.count_iteration(cond.span)?;
                    self.conds.push(cond);
                } else {
                    self.skip_to(&["end"], "#while", cond.span)?;
                    self.take_raw();
                }
            }
            CondKind::For { name, end, step, body } => {
                let (name, end, step, body) = (name.clone(), *end, *step, *body);
                let i = match self.low.lookup(&name) {
                    Some(Value::Float(v)) => *v + step,
                    _ => return Err(Diag::new(cond.span, format!("`#for` variable `{name}` is no longer a float"))),
                };
                if in_range(i, end, step) {
                    self.count_iteration(cond.span)?;
                    self.low.assign(&name, false, &[], Value::Float(i), cond.span)?;
                    self.rewind(body, &cond)?;
                    self.conds.push(cond);
                } else {
                    self.take_raw();
                }
            }
        }
        Ok(())
    }

    /// `#for (Name, Start, End [, Step])`: `Name` runs from `Start` while not past `End`.
    fn for_loop(&mut self, start: Span) -> PResult<()> {
        self.expect_punct('(', "after `#for`")?;
        let (name, name_span) = self.raw_name("#for (")?;
        self.expect_punct(',', "after the `#for` variable")?;
        let mut values = Vec::new();
        loop {
            let e = self.full_expr()?;
            values.push(self.low.float(&e)?);
            if values.len() == 3 || !self.is_punct(',') {
                break;
            }
            self.bump();
        }
        let close = self.expect_raw(')', "to close `#for (...)`")?;
        if values.len() < 2 {
            return Err(Diag::new(close, "`#for` needs a start and an end value"));
        }
        let (from, end, step) = (values[0], values[1], values.get(2).copied().unwrap_or(1.0));
        if step.abs() < EPSILON {
            return Err(Diag::new(close, "`#for` step must not be zero"));
        }
        self.low.assign(&name, false, &[], Value::Float(from), name_span)?;
        if in_range(from, end, step) {
            self.count_iteration(start)?;
            let body = self.cursor_mark();
            self.open(CondKind::For { name, end, step, body }, start);
        } else {
            self.skip_to(&["end"], "#for", start)?;
            self.take_raw();
        }
        Ok(())
    }

    /// After `#switch (v)`: runs from the first clause that matches `v`.
    fn enter_switch(&mut self, v: f64, start: Span) -> PResult<()> {
        loop {
            let found = self.skip_to(&["case", "range", "else", "end"], "#switch", start)?;
            self.take_raw();
            match found {
                "end" => return Ok(()),
                "else" => break,
                clause => {
                    if self.clause_matches(clause, v)? {
                        break;
                    }
                }
            }
        }
        self.open(CondKind::Switch, start);
        Ok(())
    }

    /// Reads the test of `#case (c)` or `#range (lo, hi)` and says whether `v` passes it.
    fn clause_matches(&mut self, clause: &str, v: f64) -> PResult<bool> {
        if clause == "case" {
            return Ok((self.condition("case")? - v).abs() < EPSILON);
        }
        self.expect_punct('(', "after `#range`")?;
        let lo = self.full_expr()?;
        self.expect_punct(',', "between the bounds of `#range`")?;
        let hi = self.full_expr()?;
        self.expect_raw(')', "to close `#range`")?;
        Ok((self.low.float(&lo)?..=self.low.float(&hi)?).contains(&v))
    }

    /// `#break`: leaves the innermost `#switch`, `#while` or `#for`, skipping to its `#end`
    /// (the cursor is on `#break`, which the skip passes over).
    fn break_out(&mut self, start: Span) -> PResult<()> {
        let Some(target) = self.conds.iter().rposition(|c| !matches!(c.kind, CondKind::If)) else {
            return Err(Diag::new(start, "`#break` outside `#switch`, `#while` or `#for`"));
        };
        while self.conds.len() > target {
            let cond = self.conds.pop().unwrap_or_else(|| unreachable!());
            if cond.frame != self.stream.frame_id() {
                return Err(Diag::new(
                    start,
                    format!("`#break` cannot leave the macro or file of its `{}`", cond.name()),
                ));
            }
            self.skip_to(&["end"], cond.name(), cond.span)?;
            self.take_raw();
        }
        Ok(())
    }

    /// `#include "file"` (a string expression): the file's tokens run next.
    fn include(&mut self, start: Span) -> PResult<()> {
        let (name, name_span) = self.string_arg("include")?;
        let (file, text) = self.low.files.enter_include(&name, start, name_span)?;
        // The token after the name was read already (from the top frame: frames end only
        // when read past): it is read again when the file is done.
        if !matches!(self.cur.kind, TokenKind::Eof | TokenKind::FrameEnd) {
            self.stream.unread();
        }
        let end = text.len();
        self.stream.push(super::Text { file, text }, 0..end, FrameKind::Include, 0);
        self.low.push_scope();
        self.advance_raw();
        Ok(())
    }

    /// A string argument of a directive (`#include`, `#debug`): a literal or string
    /// expression.
    fn string_arg(&mut self, directive: &str) -> PResult<(String, Span)> {
        self.expand();
        if let TokenKind::Str(s) = &self.cur.kind {
            // A literal: taken without reading past it.
            let next_is_operator = matches!(self.stream.peek_kind(), Some(TokenKind::Punct('+' | '*' | '/' | '-')));
            if !next_is_operator {
                let s = s.to_string();
                return Ok((s, self.take_raw().span));
            }
        }
        let e = self.full_expr()?;
        match self.low.eval(&e)? {
            Value::Str(s) => Ok((s.to_string(), e.span)),
            other => {
                Err(Diag::new(e.span, format!("expected a string after `#{directive}`, found {}", other.kind_name())))
            }
        }
    }
}

/// Whether a `#for` variable at `i` is still within `end`, counting in the direction of `step`.
fn in_range(i: f64, end: f64, step: f64) -> bool {
    if step > 0.0 {
        i <= end + EPSILON
    } else {
        i >= end - EPSILON
    }
}
