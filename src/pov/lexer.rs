//! Lexer: scene text → tokens with byte spans. Comments and whitespace vanish here; keywords stay
//! identifiers (the parser knows which words are keywords in which block).

use std::rc::Rc;

use super::source::{Diag, FileId, PResult, Span};
use crate::error::{quote_char, visible};

/// POV-Ray 3.7's directives; any other `#word` is rejected by name.
pub const DIRECTIVES: &[&str] = &[
    "version",
    "include",
    "declare",
    "local",
    "undef",
    "ifdef",
    "ifndef",
    "if",
    "elseif",
    "else",
    "while",
    "for",
    "switch",
    "case",
    "range",
    "break",
    "end",
    "macro",
    "debug",
    "warning",
    "error",
    "render",
    "statistics",
    "default",
    "fopen",
    "fclose",
    "read",
    "write",
];

#[derive(Clone, Debug, PartialEq)]
pub enum TokenKind {
    Number(f64),
    /// Identifiers and keywords alike (shared text: tokens are copied as macros expand).
    Ident(Rc<str>),
    Str(Rc<str>),
    /// `#name`, without the `#`.
    Directive(&'static str),
    /// One of `{ } < > ( ) [ ] , ; + - * / = ! & | ? : .`.
    Punct(char),
    /// A two-character operator: `<=`, `>=` or `!=`.
    Op2(&'static str),
    /// The end of an include or a macro body, as the parser's stream reports it (never made
    /// by the lexer): the frame is closed when the parser reads past it.
    FrameEnd,
    Eof,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    pub kind: TokenKind,
    pub span: Span,
}

impl Token {
    /// How the token reads in a message: "`sphere`", "number 3", "end of file".
    pub fn describe(&self) -> String {
        match &self.kind {
            TokenKind::Number(v) => format!("number {v}"),
            TokenKind::Ident(s) => format!("`{s}`"),
            TokenKind::Str(s) => format!("string \"{}\"", visible(s)),
            TokenKind::Directive(d) => format!("`#{d}`"),
            TokenKind::Punct(c) => format!("`{c}`"),
            TokenKind::Op2(op) => format!("`{op}`"),
            TokenKind::FrameEnd => "the end of the macro or included file".to_string(),
            TokenKind::Eof => "end of file".to_string(),
        }
    }
}

const PUNCT: &str = "{}<>()[],;+-*/=!&|?:.^";

/// Two-character operators, matched before single punctuation.
const OPS2: &[&str] = &["<=", ">=", "!="];

/// Splits `text` into tokens, ending with one `Eof` token (for small texts read whole: `#read`
/// data, tests; scene files are read a token at a time through `next_token`).
pub fn lex(file: FileId, text: &str) -> PResult<Vec<Token>> {
    let mut tokens = Vec::new();
    let mut i = 0;
    while let Some((t, end)) = next_token(file, text, i, text.len())? {
        tokens.push(t);
        i = end;
    }
    tokens.push(Token { kind: TokenKind::Eof, span: Span::new(file, text.len(), text.len()) });
    Ok(tokens)
}

/// The token starting at or after byte `i` of `text` (skipping blanks and comments), and the
/// offset just past it; `None` when only blanks and comments are left before `end`.
///
/// The parser reads a file through this, a token at a time, and re-reads a loop's or a macro's
/// stretch of text from a remembered offset: no file is held as tokens (a million generated
/// spheres were 24 million tokens of 40 bytes).
pub fn next_token(file: FileId, text: &str, mut i: usize, end: usize) -> PResult<Option<(Token, usize)>> {
    let bytes = &text.as_bytes()[..end];
    let span = |a: usize, b: usize| Span::new(file, a, b);
    while i < bytes.len() {
        let c = bytes[i];
        let start = i;
        if c.is_ascii_whitespace() {
            i += 1;
        } else if bytes[i..].starts_with(b"//") {
            // Include files are mostly comments: find the line's end in one search.
            i = bytes[i..].iter().position(|&b| b == b'\n').map_or(bytes.len(), |k| i + k);
        } else if bytes[i..].starts_with(b"/*") {
            i = skip_block_comment(bytes, i)
                .ok_or_else(|| Diag::new(span(start, start + 2), "block comment `/*` is never closed with `*/`"))?;
        } else if c.is_ascii_digit() || (c == b'.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)) {
            let (value, end) = lex_number(bytes, i).map_err(|m| Diag::new(span(start, i + 1), m))?;
            return Ok(Some((Token { kind: TokenKind::Number(value), span: span(start, end) }, end)));
        } else if c.is_ascii_alphabetic() || c == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            return Ok(Some((Token { kind: TokenKind::Ident(Rc::from(&text[start..i])), span: span(start, i) }, i)));
        } else if c == b'"' {
            let (s, end) = lex_string(&text[..end], i)
                .ok_or_else(|| Diag::new(span(start, start + 1), "string is never closed with `\"`"))?;
            return Ok(Some((Token { kind: TokenKind::Str(Rc::from(s)), span: span(start, end) }, end)));
        } else if c == b'#' {
            i += 1;
            // POV-Ray allows blanks, even line breaks, between `#` and the directive name.
            while i < bytes.len() && bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            let name_start = i;
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            let name = &text[name_start..i];
            if name.is_empty() {
                // A `#` with no directive after it is ignored by POV-Ray 3.7 (checked by
                // rendering `look_at <0,2,0>#` before a `}`); so it is here.
                continue;
            }
            let Some(&name) = DIRECTIVES.iter().find(|&&d| d == name) else {
                return Err(Diag::new(
                    span(start, i),
                    format!("`#{name}` is not a POV-Ray directive (directives: #{})", DIRECTIVES.join(", #")),
                ));
            };
            return Ok(Some((Token { kind: TokenKind::Directive(name), span: span(start, i) }, i)));
        } else if let Some(op) = OPS2.iter().find(|op| bytes[i..].starts_with(op.as_bytes())) {
            return Ok(Some((Token { kind: TokenKind::Op2(op), span: span(start, i + 2) }, i + 2)));
        } else if c.is_ascii() && PUNCT.contains(c as char) {
            return Ok(Some((Token { kind: TokenKind::Punct(c as char), span: span(start, i + 1) }, i + 1)));
        } else {
            let ch = text[i..].chars().next().unwrap_or('?');
            return Err(Diag::new(
                span(start, start + ch.len_utf8()),
                format!("unexpected character {}", quote_char(ch)),
            ));
        }
    }
    Ok(None)
}

/// Returns the offset just past the comment opened at `i`; comments nest, as POV-Ray allows.
fn skip_block_comment(bytes: &[u8], mut i: usize) -> Option<usize> {
    let mut depth = 0usize;
    while i < bytes.len() {
        // Only `/` and `*` can open or close a comment: skip to the next of either.
        match bytes[i..].iter().position(|&b| b == b'/' || b == b'*') {
            Some(k) => i += k,
            None => return None,
        }
        if bytes[i..].starts_with(b"/*") {
            depth += 1;
            i += 2;
        } else if bytes[i..].starts_with(b"*/") {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return Some(i);
            }
        } else {
            i += 1;
        }
    }
    None
}

/// `1`, `.5`, `2.`, `1e-3`: returns the value and the end offset.
fn lex_number(bytes: &[u8], start: usize) -> Result<(f64, usize), String> {
    let mut i = start;
    let digits = |i: &mut usize| {
        while *i < bytes.len() && bytes[*i].is_ascii_digit() {
            *i += 1;
        }
    };
    digits(&mut i);
    if i < bytes.len() && bytes[i] == b'.' {
        i += 1;
        digits(&mut i);
    }
    if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
        let mut j = i + 1;
        if j < bytes.len() && (bytes[j] == b'+' || bytes[j] == b'-') {
            j += 1;
        }
        if j < bytes.len() && bytes[j].is_ascii_digit() {
            i = j;
            digits(&mut i);
        } else {
            return Err("malformed number: exponent has no digits".to_string());
        }
    }
    // The slice is ASCII digits, '.', 'e' and a sign, so it is valid UTF-8.
    let s = std::str::from_utf8(&bytes[start..i]).map_err(|_| "malformed number".to_string())?;
    let value: f64 = s.parse().map_err(|_| format!("malformed number `{s}`"))?;
    if !value.is_finite() {
        return Err("number overflows to infinity".to_string());
    }
    Ok((value, i))
}

/// A string opened at `start`; `\"` and `\\` are escapes. Returns the contents and end offset.
fn lex_string(text: &str, start: usize) -> Option<(String, usize)> {
    let mut out = String::new();
    let mut chars = text[start + 1..].char_indices();
    while let Some((k, c)) = chars.next() {
        match c {
            '"' => return Some((out, start + 1 + k + 1)),
            '\n' => return None,
            '\\' => match chars.next() {
                Some((_, e @ ('"' | '\\'))) => out.push(e),
                Some((_, 'n')) => out.push('\n'),
                Some((_, e)) => {
                    out.push('\\');
                    out.push(e);
                }
                None => return None,
            },
            c => out.push(c),
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<TokenKind> {
        lex(0, text).unwrap().into_iter().map(|t| t.kind).collect()
    }

    #[test]
    fn numbers_in_all_forms() {
        assert_eq!(
            kinds("1 .5 1e-3 2. 3E2 1.e1"),
            vec![
                TokenKind::Number(1.0),
                TokenKind::Number(0.5),
                TokenKind::Number(1e-3),
                TokenKind::Number(2.0),
                TokenKind::Number(300.0),
                TokenKind::Number(10.0),
                TokenKind::Eof
            ]
        );
    }

    #[test]
    fn comments_nest_and_vanish() {
        assert_eq!(
            kinds("a // x\n /* b /* c */ d */ e"),
            vec![TokenKind::Ident("a".into()), TokenKind::Ident("e".into()), TokenKind::Eof]
        );
    }

    #[test]
    fn spans_are_byte_ranges() {
        let t = lex(0, "  sphere{").unwrap();
        assert_eq!((t[0].span.start, t[0].span.end), (2, 8));
        assert_eq!(t[1].kind, TokenKind::Punct('{'));
    }

    #[test]
    fn directives_and_strings() {
        assert_eq!(
            kinds("# include \"a b.inc\""),
            vec![TokenKind::Directive("include"), TokenKind::Str("a b.inc".into()), TokenKind::Eof]
        );
    }

    #[test]
    fn comparison_operators() {
        assert_eq!(
            kinds("a<=b >= != ! & | ? : . < ="),
            vec![
                TokenKind::Ident("a".into()),
                TokenKind::Op2("<="),
                TokenKind::Ident("b".into()),
                TokenKind::Op2(">="),
                TokenKind::Op2("!="),
                TokenKind::Punct('!'),
                TokenKind::Punct('&'),
                TokenKind::Punct('|'),
                TokenKind::Punct('?'),
                TokenKind::Punct(':'),
                TokenKind::Punct('.'),
                TokenKind::Punct('<'),
                TokenKind::Punct('='),
                TokenKind::Eof
            ]
        );
    }

    #[test]
    fn unsupported_directive_is_named() {
        let e = lex(0, "\n #macros Foo()").unwrap_err();
        assert!(e.message.starts_with("`#macros` is not a POV-Ray directive"), "{}", e.message);
        assert_eq!(e.span.start, 2);
    }

    #[test]
    fn overflow_unclosed_and_stray_bytes_are_errors() {
        assert_eq!(lex(0, "1e999").unwrap_err().message, "number overflows to infinity");
        assert!(lex(0, "/* x").unwrap_err().message.contains("never closed"));
        assert!(lex(0, "\"abc").unwrap_err().message.contains("never closed"));
        assert_eq!(lex(0, "a @").unwrap_err().message, "unexpected character `@`");
        assert!(lex(0, "1e+").is_err());
    }

    #[test]
    fn stray_invisible_character_is_named_by_code_point() {
        let e = lex(0, "a\u{feff}b").unwrap_err();
        assert_eq!(e.message, "unexpected character U+FEFF (byte-order mark / zero-width no-break space)");
        assert_eq!((e.span.start, e.span.end), (1, 4));
        assert_eq!(lex(0, "a\u{a0}b").unwrap_err().message, "unexpected character U+00A0 (no-break space)");
        assert_eq!(lex(0, "\u{1b}").unwrap_err().message, "unexpected character U+001B");
        assert_eq!(
            Token { kind: TokenKind::Str("a\u{200b}".into()), span: Span::default() }.describe(),
            "string \"a<U+200B>\""
        );
    }
}
