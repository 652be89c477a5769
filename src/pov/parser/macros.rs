//! `#macro` definitions and calls. A body is kept as tokens and expanded where it is called, in
//! a scope of its own: arguments that are bare identifiers are passed by reference (what the
//! macro declares into its parameter is written back to the caller's variable), others by
//! value; parameters marked `optional` may be left out.

use std::rc::Rc;

use super::stream::{FrameKind, Text};
use super::Parser;
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, Expansion, PResult, Span};
use crate::pov::value::{Macro, Value};

/// How deep macro calls may nest (recursion included): far beyond real scenes, and each level
/// costs only a frame and a scope.
pub const MAX_MACRO_DEPTH: usize = 1000;

/// A macro call being run: its by-reference parameters and the caller's variables they stand for.
#[derive(Debug)]
pub struct MacroCall {
    by_ref: Vec<(Rc<str>, Rc<str>)>,
}

impl Parser<'_, '_> {
    /// `#macro Name(A, optional B) ... #end`: stores the body unread.
    pub(super) fn define_macro(&mut self, start: Span) -> PResult<()> {
        let (name, name_span): (Rc<str>, Span) = self.raw_name("#macro")?;
        if super::is_pov_keyword(&name) || super::is_reserved(&name) {
            return Err(Diag::new(name_span, format!("cannot name a macro `{name}`: it is a keyword")));
        }
        self.expect_raw('(', &format!("after `#macro {name}`"))?;
        let mut params: Vec<(Rc<str>, bool)> = Vec::new();
        while self.cur.kind != TokenKind::Punct(')') {
            let optional = matches!(&self.cur.kind, TokenKind::Ident(w) if &**w == "optional");
            if optional {
                self.take_raw();
            }
            let (param, span) = self.raw_name("a macro's `(`")?;
            if params.iter().any(|(p, _)| *p == param) {
                return Err(Diag::new(span, format!("parameter `{param}` is named twice")));
            }
            params.push((param, optional));
            if self.cur.kind == TokenKind::Punct(',') {
                self.take_raw();
            } else if self.cur.kind != TokenKind::Punct(')') {
                return Err(Diag::new(
                    self.cur.span,
                    format!("expected `,` or `)` in the parameters of `{name}`, found {}", self.cur.describe()),
                ));
            }
        }
        // The body starts at the token after `)`, in the frame the definition is written in.
        let source = self.stream.text().unwrap_or_else(|| Text { file: name_span.file, text: Rc::from("") });
        let body_start = self.stream.mark().pos;
        self.take_raw();
        self.skip_to(&["end"], "#macro", start)?;
        let body_end = self.stream.cursor_mark().pos;
        self.take_raw();
        let m = Macro {
            name: name.clone(),
            params,
            source,
            body: body_start..body_end.max(body_start),
            defined: name_span,
        };
        self.low.define_macro(&name, Value::Macro(Rc::new(m)));
        Ok(())
    }

    /// Expands a call of `m` at the cursor: reads the arguments, opens the macro's scope and
    /// pushes its body.
    pub(super) fn call_macro(&mut self, m: Rc<Macro>) -> PResult<()> {
        let called = self.take_raw().span;
        let depth = self.stream.count(&FrameKind::Macro);
        if depth >= MAX_MACRO_DEPTH {
            return Err(Diag::new(
                called,
                format!("macro calls nested deeper than {MAX_MACRO_DEPTH} levels (a recursion that never ends?)"),
            ));
        }
        self.expand();
        if self.cur.kind != TokenKind::Punct('(') {
            return Err(Diag::new(
                self.cur.span,
                format!("expected `(` after macro `{}`, found {}", m.name, self.cur.describe()),
            ));
        }
        self.take_raw();
        let mut by_value: Vec<(Rc<str>, Value)> = Vec::new();
        let mut by_ref: Vec<(Rc<str>, Rc<str>)> = Vec::new();
        for (i, (param, _)) in m.params.iter().enumerate() {
            self.expand();
            if self.cur.kind == TokenKind::Punct(')') {
                if let Some((missing, _)) = m.params[i..].iter().find(|(_, optional)| !optional) {
                    return Err(Diag::new(
                        self.cur.span,
                        format!("macro `{}` needs argument `{missing}` (it takes {})", m.name, m.params.len()),
                    ));
                }
                break;
            }
            if i > 0 && self.cur.kind == TokenKind::Punct(',') {
                // POV-Ray lets the comma between arguments be left out (shapes.pov does).
                self.take_raw();
                self.expand();
            }
            // A bare identifier is passed by reference (also an undeclared one: the macro may
            // declare it).
            let bare = match &self.cur.kind {
                TokenKind::Ident(w)
                    if matches!(self.stream.peek_kind(), Some(TokenKind::Punct(',' | ')')))
                        && !super::is_pov_keyword(w)
                        && !super::is_reserved(w) =>
                {
                    Some(w.clone())
                }
                _ => None,
            };
            match bare {
                Some(target) => {
                    self.take_raw();
                    if let Some(v) = self.low.lookup(&target) {
                        by_value.push((param.clone(), v.clone()));
                    }
                    by_ref.push((param.clone(), target));
                }
                None => {
                    let v = self.argument()?;
                    by_value.push((param.clone(), v));
                }
            }
        }
        self.expand();
        if self.cur.kind == TokenKind::Punct(',') {
            return Err(Diag::new(self.cur.span, format!("macro `{}` takes {} argument(s)", m.name, m.params.len())));
        }
        if self.cur.kind != TokenKind::Punct(')') {
            return Err(Diag::new(
                self.cur.span,
                format!("expected `)` to close the call of `{}`, found {}", m.name, self.cur.describe()),
            ));
        }
        let expansion = self.expansion(Expansion { name: m.name.to_string(), defined: m.defined, called });
        self.low.push_macro_scope(by_value, m.params.iter().map(|(p, _)| p.clone()).collect());
        self.calls.push(MacroCall { by_ref });
        self.stream.push(m.source.clone(), m.body.clone(), FrameKind::Macro, expansion);
        // The `)` is dropped; the body's first token comes next.
        self.consumed += 1;
        self.advance_raw();
        Ok(())
    }

    /// One argument: any expression, a colour with keywords, or what a declaration may hold
    /// (`pigment { }`, an object, another macro's object).
    fn argument(&mut self) -> PResult<Value> {
        match self.peek_ident() {
            Some(w) if super::declarations::starts_declared_block(&w) => self.declared_value(),
            _ => {
                let e = self.full_color()?;
                self.low.eval(&e)
            }
        }
    }

    /// Closes the innermost call: its scope goes, and its by-reference parameters that the
    /// macro assigned are written back to the caller's variables.
    pub(super) fn end_call(&mut self) {
        let Some(call) = self.calls.pop() else { return };
        let written = self.low.pop_macro_scope();
        for (param, target) in call.by_ref {
            if let Some((_, v)) = written.iter().find(|(p, _)| *p == param) {
                self.low.write_back(&target, v.clone());
            }
        }
    }

    /// The id of an expansion for `Span::expansion` (the same call site and chain share one).
    fn expansion(&mut self, e: Expansion) -> u32 {
        if let Some(&id) = self.expansion_ids.get(&e) {
            return id;
        }
        self.expansions.push(e.clone());
        let id = self.expansions.len() as u32;
        self.expansion_ids.insert(e, id);
        id
    }

    /// A frame ran out: closes the include or macro call it held.
    pub(super) fn frame_ended(&mut self, kind: FrameKind, id: u64) -> PResult<()> {
        if let Some(open) = self.conds.last() {
            if open.frame_is(id) {
                let place = if kind == FrameKind::Macro { "the macro" } else { "the file" };
                return Err(open.unclosed(place));
            }
        }
        match kind {
            FrameKind::Macro => self.end_call(),
            FrameKind::Include => {
                self.low.pop_scope();
                self.low.files.leave_include();
            }
            FrameKind::Main => {}
        }
        Ok(())
    }
}
