//! Byte offsets (our spans) to LSP positions and back. LSP counts lines from 0 and columns in
//! UTF-16 code units (the protocol's default encoding, which every client supports); a line
//! ends at `\n`, and the `\r` of a CRLF belongs to no column a client can name.

use lsp_types::{Position, Range};

use crate::source::Span;

/// The start of each line of one text, for converting positions in both directions.
pub struct LineIndex<'a> {
    text: &'a str,
    /// Byte offset of each line's first character; the first is 0.
    starts: Vec<usize>,
}

impl<'a> LineIndex<'a> {
    pub fn new(text: &'a str) -> LineIndex<'a> {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        LineIndex { text, starts }
    }

    /// The position of byte `offset` (clamped to the text, and back to a character boundary).
    pub fn position(&self, offset: usize) -> Position {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        // The last line starting at or before `offset`; `starts[0]` is 0, so there is one.
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let column = self.text[self.starts[line]..offset]
            .chars()
            .map(char::len_utf16)
            .sum::<usize>();
        Position::new(line as u32, column as u32)
    }

    pub fn range(&self, span: Span) -> Range {
        Range::new(
            self.position(span.start as usize),
            self.position(span.end as usize),
        )
    }

    /// The byte offset of `position`; a line past the end is the end of the text, a column
    /// past the end of its line is the end of the line (LSP's rule), one inside a surrogate
    /// pair is the character's start.
    pub fn offset(&self, position: Position) -> usize {
        let Some(&start) = self.starts.get(position.line as usize) else {
            return self.text.len();
        };
        let line = self.line_text(start);
        let mut units = 0;
        for (i, c) in line.char_indices() {
            units += c.len_utf16();
            if units > position.character as usize {
                return start + i;
            }
        }
        start + line.len()
    }

    /// The text of the line starting at `start`, without its line end.
    fn line_text(&self, start: usize) -> &'a str {
        let rest = &self.text[start..];
        let line = rest.split('\n').next().unwrap_or(rest);
        line.strip_suffix('\r').unwrap_or(line)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_lines_count_from_zero() {
        let text = "entity e is\nend;\n";
        let index = LineIndex::new(text);
        assert_eq!(index.position(0), Position::new(0, 0));
        assert_eq!(index.position(12), Position::new(1, 0));
        assert_eq!(index.position(15), Position::new(1, 3));
        assert_eq!(index.offset(Position::new(1, 3)), 15);
        // The end of the text is the start of the empty last line.
        assert_eq!(index.position(text.len()), Position::new(2, 0));
    }

    #[test]
    fn multi_byte_characters_count_in_utf16_units() {
        // `é` is 2 bytes and 1 unit; `𝄞` is 4 bytes and 2 units (a surrogate pair).
        let text = "-- é𝄞x\nq";
        let index = LineIndex::new(text);
        let x = text.find('x').unwrap();
        assert_eq!(index.position(x), Position::new(0, 6));
        assert_eq!(index.offset(Position::new(0, 6)), x);
        // Inside the surrogate pair: the character's start.
        let clef = text.find('𝄞').unwrap();
        assert_eq!(index.offset(Position::new(0, 5)), clef);
        // A byte offset inside a character goes back to its start.
        assert_eq!(index.position(clef + 1), Position::new(0, 4));
    }

    #[test]
    fn crlf_line_ends_are_not_columns() {
        let text = "ab\r\ncd\r\n";
        let index = LineIndex::new(text);
        assert_eq!(index.position(4), Position::new(1, 0));
        assert_eq!(index.offset(Position::new(1, 1)), 5);
        // Past the end of a line: its end, before the `\r`.
        assert_eq!(index.offset(Position::new(0, 99)), 2);
        assert_eq!(index.offset(Position::new(1, 99)), 6);
    }

    #[test]
    fn positions_past_the_end_clamp() {
        let text = "x";
        let index = LineIndex::new(text);
        assert_eq!(index.offset(Position::new(7, 0)), 1);
        assert_eq!(index.position(99), Position::new(0, 1));
        assert_eq!(LineIndex::new("").offset(Position::new(0, 5)), 0);
    }
}
