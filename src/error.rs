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
            // Tabs keep their width so the caret lines up under the column.
            let pad: String = self
                .source_line
                .chars()
                .take(self.col.saturating_sub(1) as usize)
                .map(|c| if c == '\t' { '\t' } else { ' ' })
                .collect();
            write!(f, "\n  {}\n  {}^", self.source_line, pad)?;
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
    fn offset_past_end_is_clamped() {
        let e = LocatedError::at_offset("s.pov", "ab", 99, "unexpected end of file");
        assert_eq!((e.line, e.col), (1, 3));
    }
}
