//! Tokens, at two levels (logos).
//!
//! Takes the text of one physical line (comments already cut) with its byte offset in the
//! file; gives [`Token`]s with exact spans. The *card* level ([`lex_card`]) knows only what
//! separates the fields of an element line or a dot-card: whitespace, `=`, `(`, `)`, `,`,
//! `{expression}`, `'expression'` and `"file name"`; everything else up to the next separator
//! is one [`TokKind::Word`] (a name, a node, a number, or a bare expression such as `2*a+1`).
//! The *expression* level ([`lex_expr`]) splits the text of a brace, a quote or a word into
//! operators, numbers and identifiers for the expression parser. Never fails outright: a bad
//! character or an unterminated brace is a diagnostic, and lexing goes on.

use logos::Logos;
use vams_syntax::source::{FileId, Span};

use crate::error::SpiceError;

/// What a card-level token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokKind {
    /// A run of characters without separators: a name, node, number or bare expression.
    Word,
    Eq,
    LParen,
    RParen,
    Comma,
    /// `{...}`, braces included in the text.
    Brace,
    /// `'...'`, quotes included: an expression, as ngspice reads it.
    Quote,
    /// `"..."`, quotes included: a file name.
    Str,
}

/// A card-level token: its kind, the text as written, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    pub kind: TokKind,
    pub text: String,
    pub span: Span,
}

impl Token {
    /// The text folded to lower case (SPICE is case-insensitive).
    pub fn key(&self) -> String {
        self.text.to_ascii_lowercase()
    }

    pub fn is_word(&self) -> bool {
        self.kind == TokKind::Word
    }

    /// Whether it is the word `w` in any case.
    pub fn is_keyword(&self, w: &str) -> bool {
        self.kind == TokKind::Word && self.text.eq_ignore_ascii_case(w)
    }

    /// The text between the delimiters of a brace, quote or string, with its offset.
    pub fn inner(&self) -> (&str, usize) {
        match self.kind {
            TokKind::Brace | TokKind::Quote | TokKind::Str => {
                let end = self.text.len().saturating_sub(1).max(1);
                (
                    self.text.get(1..end).unwrap_or(""),
                    self.span.start as usize + 1,
                )
            }
            _ => (&self.text, self.span.start as usize),
        }
    }
}

#[derive(Logos, Clone, Copy, Debug, PartialEq)]
#[logos(skip r"[ \t\r\x0B\x0C]+")]
enum RawCard {
    #[regex(r#"[^ \t\r\n\x0B\x0C=(),{}'"]+"#)]
    Word,
    #[token("=")]
    Eq,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token(",")]
    Comma,
    #[regex(r"\{[^}\n]*\}")]
    Brace,
    #[regex(r"\{[^}\n]*")]
    OpenBrace,
    #[regex(r"'[^'\n]*'")]
    Quote,
    #[regex(r"'[^'\n]*")]
    OpenQuote,
    #[regex(r#""[^"\n]*""#)]
    Str,
    #[regex(r#""[^"\n]*"#)]
    OpenStr,
}

/// The card-level tokens of `text`, which starts at byte `base` of `file`.
pub fn lex_card(text: &str, base: usize, file: FileId, errors: &mut Vec<SpiceError>) -> Vec<Token> {
    let mut out = Vec::new();
    let mut lex = RawCard::lexer(text);
    while let Some(raw) = lex.next() {
        let range = lex.span();
        let span = Span::new(file, base + range.start, base + range.end);
        let slice = lex.slice();
        let kind = match raw {
            Ok(RawCard::Word) => TokKind::Word,
            Ok(RawCard::Eq) => TokKind::Eq,
            Ok(RawCard::LParen) => TokKind::LParen,
            Ok(RawCard::RParen) => TokKind::RParen,
            Ok(RawCard::Comma) => TokKind::Comma,
            Ok(RawCard::Brace) => TokKind::Brace,
            Ok(RawCard::Quote) => TokKind::Quote,
            Ok(RawCard::Str) => TokKind::Str,
            Ok(RawCard::OpenBrace) => {
                errors.push(unterminated(span, "brace expression", "}"));
                continue;
            }
            Ok(RawCard::OpenQuote) => {
                errors.push(unterminated(span, "quoted expression", "'"));
                continue;
            }
            Ok(RawCard::OpenStr) => {
                errors.push(unterminated(span, "string", "\""));
                continue;
            }
            Err(()) => {
                errors.push(SpiceError::BadToken {
                    span,
                    text: slice.to_string(),
                });
                continue;
            }
        };
        out.push(Token {
            kind,
            text: slice.to_string(),
            span,
        });
    }
    out
}

fn unterminated(span: Span, what: &'static str, closer: &'static str) -> SpiceError {
    // Point at the opening character only: the rest of the line is the reader's guess.
    let start = Span {
        end: span.start + 1,
        ..span
    };
    SpiceError::Unterminated {
        span: start,
        what,
        closer,
    }
}

/// An expression-level token.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ETok {
    Number,
    Ident,
    Plus,
    Minus,
    Star,
    Slash,
    Percent,
    /// `^` or `**`
    Pow,
    LParen,
    RParen,
    Comma,
    Question,
    Colon,
    EqEq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    AndAnd,
    OrOr,
    Not,
}

#[derive(Logos, Clone, Copy, Debug, PartialEq)]
#[logos(skip r"[ \t\r\n\x0B\x0C]+")]
enum RawExpr {
    #[regex(r"([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?[a-zA-Z]*")]
    Number,
    #[regex(r"[a-zA-Z_][a-zA-Z0-9_]*")]
    Ident,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("/")]
    Slash,
    #[token("%")]
    Percent,
    #[token("^")]
    #[token("**")]
    Pow,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token(",")]
    Comma,
    #[token("?")]
    Question,
    #[token(":")]
    Colon,
    #[token("==")]
    EqEq,
    #[token("!=")]
    Ne,
    #[token("<")]
    Lt,
    #[token(">")]
    Gt,
    #[token("<=")]
    Le,
    #[token(">=")]
    Ge,
    #[token("&&")]
    AndAnd,
    #[token("||")]
    OrOr,
    #[token("!")]
    Not,
}

/// An expression token with its text and span.
#[derive(Clone, Debug, PartialEq)]
pub struct ExprToken {
    pub kind: ETok,
    pub text: String,
    pub span: Span,
}

/// The expression tokens of `text`, which starts at byte `base` of `file`; the first bad
/// character is an error.
pub fn lex_expr(text: &str, base: usize, file: FileId) -> Result<Vec<ExprToken>, SpiceError> {
    let mut out = Vec::new();
    let mut lex = RawExpr::lexer(text);
    while let Some(raw) = lex.next() {
        let range = lex.span();
        let span = Span::new(file, base + range.start, base + range.end);
        let kind = match raw {
            Ok(r) => match r {
                RawExpr::Number => ETok::Number,
                RawExpr::Ident => ETok::Ident,
                RawExpr::Plus => ETok::Plus,
                RawExpr::Minus => ETok::Minus,
                RawExpr::Star => ETok::Star,
                RawExpr::Slash => ETok::Slash,
                RawExpr::Percent => ETok::Percent,
                RawExpr::Pow => ETok::Pow,
                RawExpr::LParen => ETok::LParen,
                RawExpr::RParen => ETok::RParen,
                RawExpr::Comma => ETok::Comma,
                RawExpr::Question => ETok::Question,
                RawExpr::Colon => ETok::Colon,
                RawExpr::EqEq => ETok::EqEq,
                RawExpr::Ne => ETok::Ne,
                RawExpr::Lt => ETok::Lt,
                RawExpr::Gt => ETok::Gt,
                RawExpr::Le => ETok::Le,
                RawExpr::Ge => ETok::Ge,
                RawExpr::AndAnd => ETok::AndAnd,
                RawExpr::OrOr => ETok::OrOr,
                RawExpr::Not => ETok::Not,
            },
            Err(()) => {
                return Err(SpiceError::syntax(
                    span,
                    format!("unexpected `{}` in an expression", lex.slice()),
                    "not part of an expression",
                    "expressions use numbers, parameter names, + - * / ^ % ( ), comparisons, \
                     && || ! and `c ? a : b`",
                ));
            }
        };
        out.push(ExprToken {
            kind,
            text: lex.slice().to_string(),
            span,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<(TokKind, String)> {
        let mut errors = Vec::new();
        let toks = lex_card(text, 0, FileId(0), &mut errors);
        assert!(errors.is_empty(), "{errors:?}");
        toks.into_iter().map(|t| (t.kind, t.text)).collect()
    }

    #[test]
    fn card_tokens() {
        use TokKind::*;
        assert_eq!(
            kinds(".model qnl npn(bf=80, va={v*2})"),
            vec![
                (Word, ".model".into()),
                (Word, "qnl".into()),
                (Word, "npn".into()),
                (LParen, "(".into()),
                (Word, "bf".into()),
                (Eq, "=".into()),
                (Word, "80".into()),
                (Comma, ",".into()),
                (Word, "va".into()),
                (Eq, "=".into()),
                (Brace, "{v*2}".into()),
                (RParen, ")".into()),
            ]
        );
        assert_eq!(
            kinds(".include \"a b.lib\" 'x+1' in+"),
            vec![
                (Word, ".include".into()),
                (Str, "\"a b.lib\"".into()),
                (Quote, "'x+1'".into()),
                (Word, "in+".into()),
            ]
        );
    }

    #[test]
    fn spans_carry_the_base_offset() {
        let mut errors = Vec::new();
        let toks = lex_card("r1 a", 10, FileId(3), &mut errors);
        assert_eq!(toks[1].span, Span::new(FileId(3), 13, 14));
        let t = &lex_card("{ab}", 5, FileId(0), &mut errors)[0];
        assert_eq!(t.inner(), ("ab", 6));
    }

    #[test]
    fn unterminated_and_bad_tokens_are_reported() {
        let mut errors = Vec::new();
        let toks = lex_card("r1 a b {1k*2", 0, FileId(0), &mut errors);
        assert_eq!(toks.len(), 3);
        assert!(matches!(errors[0], SpiceError::Unterminated { span, .. } if span.start == 7));
        errors.clear();
        lex_card("r1 } a", 0, FileId(0), &mut errors);
        assert!(matches!(&errors[0], SpiceError::BadToken { text, .. } if text == "}"));
    }

    #[test]
    fn expression_tokens() {
        let toks = lex_expr("2**-a>=1k?b:c", 0, FileId(0)).unwrap_or_default();
        let k: Vec<ETok> = toks.iter().map(|t| t.kind).collect();
        use ETok::*;
        assert_eq!(
            k,
            vec![
                Number, Pow, Minus, Ident, Ge, Number, Question, Ident, Colon, Ident
            ]
        );
        assert_eq!(toks[5].text, "1k");
        assert!(lex_expr("a # b", 0, FileId(0)).is_err());
    }
}
