//! Deck text to logical lines.
//!
//! Takes the text of one file (and whether its first line is a title, as it is in the file a
//! simulator is given but not in an included one); gives the title, the logical lines as
//! card-level tokens with their own spans into the original text, the span of the `.end` that
//! stopped reading, the skipped `.control` blocks, and the lexical diagnostics. Knows nothing
//! of what a card means.
//!
//! The rules are ngspice's: the first line is the title, whatever it holds; a line starting
//! with `+` (after optional blanks) continues the previous logical line, even across blank and
//! comment lines; a line starting with `*` (or `$`) is a comment; `;` starts an end-of-line comment
//! anywhere outside quotes and braces, `$` does when whitespace precedes it; `.end` stops the
//! file; `.control` ... `.endc` is skipped without being lexed. Tokens keep their text as
//! written: case folding is the reader's.

use vams_syntax::source::{FileId, Span};

use crate::error::SpiceError;
use crate::lexer::{Token, lex_card};

/// One logical line: a card or an element, continuation lines joined.
#[derive(Clone, Debug)]
pub struct Line {
    pub tokens: Vec<Token>,
    /// Its lexical errors: when there are any, the reader reports them where the line stands
    /// and skips the line.
    pub errors: Vec<SpiceError>,
}

impl Line {
    /// From the first token's start to the last token's end.
    pub fn span(&self) -> Span {
        match (self.tokens.first(), self.tokens.last()) {
            (Some(a), Some(b)) => a.span.to(b.span),
            _ => Span::default(),
        }
    }
}

/// The lines of one file.
#[derive(Debug, Default)]
pub struct Lines {
    /// The title line's text (trimmed) and span, when the file has one.
    pub title: Option<(String, Span)>,
    pub lines: Vec<Line>,
    /// The `.end` card that stopped reading, if any.
    pub end: Option<Span>,
    /// The `.control` card of each skipped block.
    pub controls: Vec<Span>,
    /// Errors of no line (a `+` line continuing nothing).
    pub errors: Vec<SpiceError>,
    /// Where the text ends (for diagnostics about a missing closer).
    pub eof: Span,
}

/// Splits `text` (the contents of `file`) into logical lines.
pub fn split(text: &str, file: FileId, has_title: bool) -> Lines {
    let mut out = Lines {
        eof: Span::new(file, text.len(), text.len()),
        ..Lines::default()
    };
    let mut in_control = false;
    let mut offset = 0;
    let mut first = has_title;
    for raw in text.split_inclusive('\n') {
        let start = offset;
        offset += raw.len();
        let line = raw.trim_end_matches(['\n', '\r']);
        if first {
            first = false;
            let trimmed = line.trim();
            let lead = line.len() - line.trim_start().len();
            let span = Span::new(file, start + lead, start + lead + trimmed.len());
            out.title = Some((trimmed.to_string(), span));
            continue;
        }
        let lead = line.len() - line.trim_start().len();
        let body = &line[lead..];
        let word = first_word(body);
        let word_span = Span::new(file, start + lead, start + lead + word.len());
        if in_control {
            if word.eq_ignore_ascii_case(".endc") {
                in_control = false;
            }
            continue;
        }
        // ngspice turns a line starting with `$` into a comment too.
        if body.is_empty() || body.starts_with(['*', '$']) {
            continue;
        }
        if word.eq_ignore_ascii_case(".control") {
            in_control = true;
            out.controls.push(word_span);
            continue;
        }
        if word.eq_ignore_ascii_case(".end") {
            out.end = Some(word_span);
            break;
        }
        let (content, content_start) = match body.strip_prefix('+') {
            Some(rest) => (rest, start + lead + 1),
            None => (body, start + lead),
        };
        let content = cut_comment(content);
        let mut errors = Vec::new();
        let tokens = lex_card(content, content_start, file, &mut errors);
        if body.starts_with('+') {
            match out.lines.last_mut() {
                Some(prev) => {
                    prev.tokens.extend(tokens);
                    prev.errors.extend(errors);
                }
                None => out.errors.push(SpiceError::syntax(
                    Span::new(file, start + lead, start + lead + 1),
                    "a continuation line with nothing to continue",
                    "continues no line",
                    "a `+` line continues the element or card above it; remove the `+`",
                )),
            }
        } else if !tokens.is_empty() || !errors.is_empty() {
            out.lines.push(Line { tokens, errors });
        }
    }
    out
}

/// The text up to the first blank.
fn first_word(body: &str) -> &str {
    let end = body
        .find(|c: char| c.is_ascii_whitespace())
        .unwrap_or(body.len());
    &body[..end]
}

/// The text before an end-of-line comment: `;` anywhere, `$` after whitespace, neither inside
/// quotes or braces.
fn cut_comment(text: &str) -> &str {
    let mut quote: Option<u8> = None;
    let mut brace = false;
    let mut prev_blank = false;
    for (i, b) in text.bytes().enumerate() {
        match (quote, b) {
            (Some(q), _) if b == q => quote = None,
            (Some(_), _) => {}
            (None, b'\'' | b'"') if !brace => quote = Some(b),
            (None, b'{') => brace = true,
            (None, b'}') => brace = false,
            (None, b';') if !brace => return &text[..i],
            (None, b'$') if !brace && prev_blank => return &text[..i],
            _ => {}
        }
        prev_blank = b == b' ' || b == b'\t';
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(lines: &Lines) -> Vec<Vec<String>> {
        assert!(lines.lines.iter().all(|l| l.errors.is_empty()));
        lines
            .lines
            .iter()
            .map(|l| l.tokens.iter().map(|t| t.text.clone()).collect())
            .collect()
    }

    #[test]
    fn title_comments_and_continuations() {
        let text = "* a title that looks like a comment\n\
                    r1 a b\n\
                    * a comment between\n\
                    \n\
                    + 1k ; the value\n\
                    c1 a 0 1p $ a dollar comment\n\
                    $ a comment line too\n\
                    v1 net$1 0 1\n\
                    .END\n\
                    r2 never read\n";
        let lines = split(text, FileId(0), true);
        assert!(lines.errors.is_empty(), "{:?}", lines.errors);
        assert_eq!(
            lines.title.as_ref().map(|t| t.0.as_str()),
            Some("* a title that looks like a comment")
        );
        assert_eq!(
            words(&lines),
            vec![
                vec!["r1", "a", "b", "1k"],
                vec!["c1", "a", "0", "1p"],
                vec!["v1", "net$1", "0", "1"]
            ]
        );
        assert!(lines.end.is_some());
        // The continued token's span points at its own line.
        let k = &lines.lines[0].tokens[3];
        assert_eq!(&text[k.span.start as usize..k.span.end as usize], "1k");
    }

    #[test]
    fn control_blocks_are_skipped_unlexed() {
        let text = "t\n.control\nrun \"unterminated\nplot {x\n.endc\nr1 a b 1\n";
        let lines = split(text, FileId(0), true);
        assert!(lines.errors.is_empty(), "{:?}", lines.errors);
        assert_eq!(lines.controls.len(), 1);
        assert_eq!(words(&lines), vec![vec!["r1", "a", "b", "1"]]);
        assert!(lines.end.is_none());
    }

    #[test]
    fn included_files_have_no_title() {
        let lines = split("r1 a b 1\r\n+ tc1=0\r\n", FileId(0), false);
        assert!(lines.title.is_none());
        assert_eq!(
            words(&lines),
            vec![vec!["r1", "a", "b", "1", "tc1", "=", "0"]]
        );
    }

    #[test]
    fn comment_markers_inside_quotes_and_braces_stay() {
        assert_eq!(cut_comment("a {x ;y} b; c"), "a {x ;y} b");
        assert_eq!(cut_comment(".include \"a;b\" ; c"), ".include \"a;b\" ");
        assert_eq!(cut_comment("a$b $c"), "a$b ");
    }

    #[test]
    fn a_leading_continuation_is_an_error() {
        let lines = split("+ r1 a b\n", FileId(0), false);
        assert_eq!(lines.errors.len(), 1);
    }
}
