//! Located errors for everything a user writes: scene files, camera paths, CLI arguments.
//!
//! Every message a user sees for bad input reads `file:line:col: message`, followed by the source
//! line and a caret under the column. The CLI maps these to exit code 2.

use std::fmt;

/// An error at a place in a text file a user wrote.
#[derive(Clone, Debug, PartialEq)]
pub struct LocatedError {
    pub file: String,
    /// 1-based.
    pub line: u32,
    /// 1-based, in characters.
    pub col: u32,
    pub message: String,
    /// The text of the offending line, without its newline (empty when unknown).
    pub source_line: String,
}

impl LocatedError {
    /// Builds the error for byte offset `offset` of `text` (the contents of `file`).
    pub fn at_offset(file: &str, text: &str, offset: usize, message: impl Into<String>) -> Self {
        let offset = offset.min(text.len());
        let before = &text[..floor_char_boundary(text, offset)];
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let line = before.matches('\n').count() as u32 + 1;
        let col = before[line_start..].chars().count() as u32 + 1;
        let line_end = text[line_start..].find('\n').map_or(text.len(), |i| line_start + i);
        LocatedError {
            file: file.to_string(),
            line,
            col,
            message: message.into(),
            source_line: text[line_start..line_end].trim_end_matches('\r').to_string(),
        }
    }

    /// An error about a whole file (unreadable, not text), located at its start.
    pub fn whole_file(file: &str, message: impl Into<String>) -> Self {
        LocatedError { file: file.to_string(), line: 1, col: 1, message: message.into(), source_line: String::new() }
    }
}

/// A character as a message quotes it: visible ones in backticks (`` `@` ``), invisible ones
/// (controls, spaces other than the plain one, zero-width and format characters) by code point,
/// `U+FEFF`, since quoting them would show nothing.
pub fn quote_char(c: char) -> String {
    if is_invisible(c) {
        match invisible_name(c) {
            Some(name) => format!("U+{:04X} ({name})", c as u32),
            None => format!("U+{:04X}", c as u32),
        }
    } else {
        format!("`{c}`")
    }
}

/// `text` with each invisible character written as `<U+FEFF>`, for quoting words and strings.
pub fn visible(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if is_invisible(c) {
            out.push_str(&format!("<U+{:04X}>", c as u32));
        } else {
            out.push(c);
        }
    }
    out
}

/// Characters a terminal shows as nothing or as a plain blank, so a message must name them.
fn is_invisible(c: char) -> bool {
    (c.is_control() || c.is_whitespace() || is_format_char(c)) && c != ' '
}

/// Zero-width and other format characters (Unicode category Cf and the fillers), which
/// `char` has no predicate for.
fn is_format_char(c: char) -> bool {
    matches!(c as u32,
        0xAD | 0x34F | 0x61C | 0x115F | 0x1160 | 0x17B4 | 0x17B5 | 0x180B..=0x180E
        | 0x200B..=0x200F | 0x202A..=0x202E | 0x2060..=0x206F | 0x3164 | 0xFE00..=0xFE0F
        | 0xFEFF | 0xFFA0 | 0xFFF0..=0xFFFB | 0x1D173..=0x1D17A | 0xE0000..=0xE0FFF)
}

/// What the invisible characters people paste by accident are called.
fn invisible_name(c: char) -> Option<&'static str> {
    Some(match c {
        '\u{feff}' => "byte-order mark / zero-width no-break space",
        '\u{a0}' => "no-break space",
        '\u{200b}' => "zero-width space",
        '\u{ad}' => "soft hyphen",
        '\t' => "tab",
        _ => return None,
    })
}

fn floor_char_boundary(text: &str, mut i: usize) -> usize {
    while i > 0 && !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

impl fmt::Display for LocatedError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: {}", self.file, self.line, self.col, self.message)?;
        if !self.source_line.is_empty() {
            // Tabs keep their width so the caret lines up under the column; other invisible
            // characters are shown as `<U+FEFF>`, and the padding under them is as wide.
            let (mut shown, mut pad) = (String::new(), String::new());
            for (i, c) in self.source_line.chars().enumerate() {
                let before_col = i + 1 < self.col as usize;
                if c == '\t' || !is_invisible(c) {
                    shown.push(c);
                    if before_col {
                        pad.push(if c == '\t' { '\t' } else { ' ' });
                    }
                } else {
                    let code = format!("<U+{:04X}>", c as u32);
                    if before_col {
                        pad.push_str(&" ".repeat(code.len()));
                    }
                    shown.push_str(&code);
                }
            }
            write!(f, "\n  {shown}\n  {pad}^")?;
        }
        Ok(())
    }
}

impl std::error::Error for LocatedError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locates_line_and_column() {
        let text = "camera {\n  locaton <0,0,0>\n}";
        let e = LocatedError::at_offset("s.pov", text, 11, "unknown keyword `locaton`");
        assert_eq!((e.line, e.col), (2, 3));
        assert_eq!(e.to_string(), "s.pov:2:3: unknown keyword `locaton`\n    locaton <0,0,0>\n    ^");
    }

    #[test]
    fn invisible_characters_are_quoted_by_code_point() {
        assert_eq!(quote_char('@'), "`@`");
        assert_eq!(quote_char('é'), "`é`");
        assert_eq!(quote_char('\u{feff}'), "U+FEFF (byte-order mark / zero-width no-break space)");
        assert_eq!(quote_char('\u{a0}'), "U+00A0 (no-break space)");
        assert_eq!(quote_char('\u{7}'), "U+0007");
        assert_eq!(quote_char('\u{2009}'), "U+2009");
        assert_eq!(visible("a\u{200b}b c"), "a<U+200B>b c");
    }

    #[test]
    fn invisible_character_in_the_quoted_line_is_shown_and_the_caret_stays_under_the_column() {
        let e = LocatedError::at_offset("s.pov", "a\u{feff}b c", 6, "unknown keyword `c`");
        assert_eq!(e.col, 5);
        assert_eq!(e.to_string(), "s.pov:1:5: unknown keyword `c`\n  a<U+FEFF>b c\n             ^");
    }

    #[test]
    fn offset_past_end_is_clamped() {
        let e = LocatedError::at_offset("s.pov", "ab", 99, "unexpected end of file");
        assert_eq!((e.line, e.col), (1, 3));
    }
}
