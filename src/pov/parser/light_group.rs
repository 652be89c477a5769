//! `light_group { objects light_sources [global_lights on|off] modifiers }` (POV-Ray 3.4.4.2):
//! the objects and lights of the group, and the flag, in any order before the modifiers.

use super::Parser;
use crate::pov::ast::{Expr, Stmt};
use crate::pov::lexer::TokenKind;
use crate::pov::source::PResult;

impl Parser<'_, '_> {
    /// The group's objects and lights (and the directives that make them), and
    /// `global_lights`' value when written (`global_lights` alone is on).
    pub(super) fn light_group_body(&mut self) -> PResult<(Vec<Stmt>, Option<Option<Expr>>)> {
        let mut children = Vec::new();
        let mut global = None;
        loop {
            match &self.peek().kind {
                TokenKind::Eof | TokenKind::Punct('}') => break,
                TokenKind::Punct(';') => {
                    self.bump();
                }
                TokenKind::Ident(w) if &**w == "global_lights" => {
                    self.bump();
                    global = Some(if self.starts_bool() { Some(self.expr()?) } else { None });
                }
                TokenKind::Ident(w) if super::scene::MODIFIERS.contains(&&**w) => break,
                _ => children.push(self.item()?),
            }
        }
        Ok((children, global))
    }
}
