//! Declarations: `#declare`/`#local` and what their right-hand side may be (a value, a block,
//! an object, an array), `#default`, and how a declaration that needs an unmodelled feature is
//! kept as "declared, not modelled" with the rest of its syntax skipped.

use std::rc::Rc;

use super::{is_pov_keyword, Parser, LAYERED, UNSUPPORTED_SHAPES};
use crate::pov::ast::{AtmosphereKind, DeclValue, DefaultItem, Stmt};
use crate::pov::lexer::TokenKind;
use crate::pov::source::{Diag, PResult, Span};
use crate::pov::value::{Array, Unmodelled, Value, MAX_ARRAY_DIMENSIONS, MAX_ARRAY_ELEMENTS};

impl Parser<'_, '_> {
    /// `[i][j]...` after an array's name (none: empty).
    pub(super) fn indices(&mut self) -> PResult<Vec<usize>> {
        let mut out = Vec::new();
        while self.next_is('[') {
            let open = self.bump().span;
            let e = self.full_expr()?;
            let v = self.low.float(&e)?;
            self.expect_raw(']', "to close the array index")?;
            if !(0.0..4.0e9).contains(&v) {
                return Err(Diag::new(e.span, format!("array index {v} is negative or too large")));
            }
            out.push(v as usize);
            if out.len() > MAX_ARRAY_DIMENSIONS {
                return Err(Diag::new(open, format!("arrays have at most {MAX_ARRAY_DIMENSIONS} dimensions")));
            }
        }
        Ok(out)
    }

    /// `#declare Name = value` / `#local`, also `#declare Name[i] = value` for an element.
    pub(super) fn declare(&mut self, local: bool, start: Span) -> PResult<()> {
        let directive = if local { "#local" } else { "#declare" };
        // `#declare deprecated [once] "message" Name = ...`: POV-Ray warns where the name is
        // used; strahl does not track uses and only reads the words.
        if matches!(&self.cur.kind, TokenKind::Ident(w) if &**w == "deprecated") {
            self.take_raw();
            if matches!(&self.cur.kind, TokenKind::Ident(w) if &**w == "once") {
                self.take_raw();
            }
            if let TokenKind::Str(_) = &self.cur.kind {
                self.take_raw();
            }
        }
        let (name, name_span) = self.raw_name(directive)?;
        if super::is_reserved(&name) || is_pov_keyword(&name) {
            return Err(Diag::new(name_span, format!("cannot declare `{name}`: it is a keyword")));
        }
        let indices = self.indices()?;
        self.expect_punct('=', &format!("after `{directive} {name}`"))?;
        let scope = self.low.innermost_scope();
        let value = self.declared_value()?;
        self.low.assign_in(&name, local.then_some(scope), &indices, value, start.to(name_span))?;
        self.eat_raw_semicolon();
        Ok(())
    }

    /// The value after `#declare Name =`. A value that needs a feature strahl does not model
    /// yet becomes `Value::Unmodelled` once the rest of its syntax is skipped, so that include
    /// files declaring more than a scene uses still load.
    pub(super) fn declared_value(&mut self) -> PResult<Value> {
        let (braces, depth, in_csg) = (self.braces, self.depth, self.in_csg);
        let decl = match self.declared_syntax() {
            Ok(Declared::Value(v)) => return Ok(v),
            Ok(Declared::Syntax(decl)) => decl,
            Err(e) if e.unmodelled && self.pending.is_none() => {
                // Nesting still open that is not a block: the `(` (or `<`) the error stopped
                // in, whose `)` the skip must not take for the declaration's end
                // (`#local R = (F(1, 2));` with `F` unmodelled).
                let open = (self.depth.saturating_sub(depth)).saturating_sub(self.braces.saturating_sub(braces));
                self.depth = depth;
                self.in_csg = in_csg;
                self.skip_declaration(braces, open);
                return Ok(Value::Unmodelled(Rc::new(Unmodelled::from_error(e))));
            }
            Err(e) => return Err(e),
        };
        // Read in full: only its value may need what strahl does not model.
        match self.low.declaration(&decl) {
            Err(e) if e.unmodelled => Ok(Value::Unmodelled(Rc::new(Unmodelled::from_error(e)))),
            other => other,
        }
    }

    /// Skips the rest of a declaration: its open blocks, or to the `;` or directive that ends
    /// it when no block is open. Further `texture { }` layers belong to it too.
    fn skip_declaration(&mut self, braces: usize, open_parens: usize) {
        // Whether a block of the declaration was open or has been skipped: what follows at
        // the declaration's level is then the next statement (or another texture layer).
        let mut had_block = self.braces > braces;
        // `(` minus `)` taken at the declaration's level (`function(x, y) { }`).
        let mut parens = open_parens;
        loop {
            match &self.cur.kind {
                TokenKind::Eof => return,
                // The declaration may go on after the macro that wrote part of it.
                TokenKind::FrameEnd => {
                    self.close_frame();
                    if self.pending.is_some() {
                        return;
                    }
                }
                _ if self.braces > braces => {
                    self.take_raw();
                }
                TokenKind::Punct('(') => {
                    parens += 1;
                    self.take_raw();
                }
                TokenKind::Punct(')') if parens > 0 => {
                    parens -= 1;
                    self.take_raw();
                }
                TokenKind::Punct(',') if parens > 0 => {
                    self.take_raw();
                }
                TokenKind::Punct('}' | ';' | ',' | ')') | TokenKind::Directive(_) => return,
                TokenKind::Ident(w) if &**w == "texture" => {
                    self.take_raw();
                    had_block = false;
                }
                _ if had_block => return,
                TokenKind::Punct('{') => {
                    self.take_raw();
                    had_block = true;
                }
                _ => {
                    // A word or value before the block it opens (`cone {`, `function(x) {`).
                    self.take_raw();
                }
            }
        }
    }

    fn declared_syntax(&mut self) -> PResult<Declared> {
        let decl = match self.peek_ident().as_deref() {
            Some("pigment") => DeclValue::Pigment(self.pigment()?),
            Some("normal") => DeclValue::Normal(self.normal()?),
            Some("finish") => DeclValue::Finish(self.finish()?),
            Some("texture") => {
                let t = self.texture()?;
                self.refuse_layer()?;
                DeclValue::Texture(t)
            }
            Some("interior") => DeclValue::Interior(self.interior()?),
            Some("material") => DeclValue::Material(self.material()?),
            Some("color_map" | "colour_map") => DeclValue::ColorMap(self.color_map()?),
            Some("slope_map") => DeclValue::SlopeMap(self.slope_map()?.0),
            Some("camera") => DeclValue::Camera(self.camera_items()?.0),
            Some("light_source") => DeclValue::Light(self.light()?),
            Some(w @ ("sky_sphere" | "fog" | "rainbow")) => {
                let kind = match w {
                    "sky_sphere" => AtmosphereKind::SkySphere,
                    "fog" => AtmosphereKind::Fog,
                    _ => AtmosphereKind::Rainbow,
                };
                match self.atmosphere(kind)? {
                    Stmt::Atmosphere(a) => DeclValue::Atmosphere(a),
                    _ => unreachable!("atmosphere() returns an atmosphere"),
                }
            }
            Some("array") => return self.array().map(Declared::Value),
            Some("spline") => return self.spline().map(|s| Declared::Value(Value::Spline(Rc::new(s)))),
            Some("function") => {
                let kw = self.bump().span;
                // `function { transform { .. } }` and `function { spline { .. } }`: functions
                // giving a vector, read in `parser::spline`.
                let brace = self.is_punct('{');
                let special = match self.stream.peek_kind() {
                    Some(TokenKind::Ident(w)) if brace => Some(w.clone()),
                    _ => None,
                };
                if let Some(w @ ("transform" | "spline")) = special.as_deref() {
                    return self.vector_function(kw, w == "spline").map(Declared::Value);
                }
                return self.function_after(kw).map(|f| Declared::Value(Value::Function(Rc::new(f))));
            }
            Some("transform") => {
                let kw = self.bump().span;
                return self.transform_after(kw).map(|(t, _)| Declared::Value(Value::Transform(t)));
            }
            Some(word) if super::scene::is_object_keyword(word) || UNSUPPORTED_SHAPES.contains(&word) => {
                DeclValue::Object(self.object()?)
            }
            Some(word) if DECLARABLE_UNMODELLED.contains(&word) => {
                let t = self.peek();
                return Err(Diag::unmodelled(t.span, format!("`{word}` is not supported yet")));
            }
            _ => DeclValue::Expr(self.color()?),
        };
        Ok(Declared::Syntax(decl))
    }

    /// `array[d1][d2]... [{ v, v, ... }]`, nested braces per dimension.
    fn array(&mut self) -> PResult<Value> {
        let kw = self.bump().span;
        let dims = self.indices()?;
        if dims.is_empty() {
            return Err(Diag::new(kw, "expected `[size]` after `array`"));
        }
        let total = dims.iter().try_fold(1usize, |n, &d| n.checked_mul(d)).unwrap_or(usize::MAX);
        if total > MAX_ARRAY_ELEMENTS || dims.contains(&0) {
            return Err(Diag::new(
                kw,
                format!("array sizes must be 1 or more, {MAX_ARRAY_ELEMENTS} elements in all at most"),
            ));
        }
        let mut array = Array { dims: dims.clone(), items: vec![None; total] };
        if self.next_is('{') {
            let mut at = 0;
            self.array_items(&mut array, 0, &mut at)?;
        }
        Ok(Value::Array(Rc::new(array)))
    }

    /// The `{ ... }` of dimension `dim`, filling `array.items` from `*at`.
    fn array_items(&mut self, array: &mut Array, dim: usize, at: &mut usize) -> PResult<()> {
        let open = self.expect_punct('{', "to start the array's elements")?;
        self.enter(open)?;
        let n = array.dims[dim];
        let mut count = 0;
        while !self.is_punct('}') {
            if count == n {
                return Err(Diag::new(
                    self.peek().span,
                    format!("too many elements: dimension {} has size {n}", dim + 1),
                ));
            }
            if dim + 1 < array.dims.len() {
                self.array_items(array, dim + 1, at)?;
            } else {
                let v = self.declared_value()?;
                array.items[*at] = Some(v);
                *at += 1;
            }
            count += 1;
            // Commas between elements may be left out, as POV-Ray allows.
            self.eat_punct(',');
        }
        let close = self.close_block("array", open)?;
        if count < n {
            return Err(Diag::new(
                close,
                format!("too few elements: dimension {} has size {n}, found {count}", dim + 1),
            ));
        }
        Ok(())
    }

    /// `#default { texture {..} pigment {..} normal {..} finish {..} }`, in any number and order.
    pub(super) fn default(&mut self, start: Span) -> PResult<()> {
        const ITEMS: &[&str] = &["texture", "pigment", "normal", "finish"];
        self.open_block("#default", start)?;
        let mut items = Vec::new();
        while !self.at_block_end() {
            items.push(match self.peek_ident().as_deref() {
                Some("texture") => {
                    let t = self.texture()?;
                    if self.peek_ident().as_deref() == Some("texture") {
                        return Err(Diag::new(self.peek().span, LAYERED));
                    }
                    DefaultItem::Texture(t)
                }
                Some("pigment") => DefaultItem::Pigment(self.pigment()?),
                Some("normal") => DefaultItem::Normal(self.normal()?),
                Some("finish") => DefaultItem::Finish(self.finish()?),
                _ => return Err(self.unknown_in("#default", ITEMS)),
            });
        }
        self.close_block("#default", start)?;
        self.low.set_default(&items)
    }
}

/// Whether `word` starts a block value (a texture item, an object, an array) rather than an
/// expression.
pub(super) fn starts_declared_block(word: &str) -> bool {
    matches!(
        word,
        "pigment"
            | "normal"
            | "finish"
            | "texture"
            | "interior"
            | "material"
            | "color_map"
            | "colour_map"
            | "slope_map"
            | "camera"
            | "array"
            | "light_source"
            | "function"
            | "transform"
            | "spline"
    ) || super::scene::is_object_keyword(word)
        || UNSUPPORTED_SHAPES.contains(&word)
        || DECLARABLE_UNMODELLED.contains(&word)
}

/// A declaration's right-hand side as read: syntax to lower, or (an array) its value.
enum Declared {
    Syntax(DeclValue),
    Value(Value),
}

/// Values POV-Ray can declare that strahl does not model yet: their declarations are kept as
/// unmodelled (an error only where they are used).
const DECLARABLE_UNMODELLED: &[&str] =
    &["media", "density", "pigment_map", "normal_map", "texture_map", "density_map", "photons", "radiosity", "matrix"];
