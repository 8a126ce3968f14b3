//! The lexer: source text to tokens.
//!
//! Takes the text of one file; gives a vector of `(start, Tok, end)` triples for the parser
//! and the lexical diagnostics. Never fails outright: a bad character or literal becomes a
//! diagnostic and lexing goes on. VHDL is case-insensitive: keywords match in any case, and
//! identifiers keep the user's spelling in the token (the parser lowercases them for the AST).
//!
//! The one context-sensitive rule, character literal versus attribute tick (`'a'` vs `x'dot` vs
//! `t'('a')`), is decided here from the previous token, as the LRM's lexical rules imply: after
//! an identifier, `)` or `]` an apostrophe is a tick.

mod keyword;
mod literal;
#[cfg(test)]
mod tests;

use logos::Logos;

pub use keyword::Kw;

use crate::diagnostics::SyntaxError;
use crate::source::{FileId, Span};

/// Deepest parenthesis nesting accepted: deeper input is rejected before parsing so that no
/// later recursive pass can overflow the stack.
pub const MAX_NESTING: usize = 256;

/// A token as the parser sees it.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok<'a> {
    Ident(&'a str),
    ExtIdent(&'a str),
    Kw(Kw),
    Int(i64),
    Real(f64),
    Char(char),
    /// A string literal with its quotes, doubled quotes not yet collapsed.
    Str(&'a str),
    /// A bit-string literal expanded to its bits.
    BitStr(String),
    Tick,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Comma,
    Semi,
    Colon,
    Dot,
    Bar,
    Amp,
    Plus,
    Minus,
    Star,
    Slash,
    Lt,
    Gt,
    Eq,
    Arrow,
    Pow,
    Assign,
    Ne,
    Ge,
    Le,
    Box,
    SimEq,
    Question,
}

/// Tokens before keyword classification and character-literal resolution.
#[derive(Logos, Clone, Copy, Debug, PartialEq)]
#[logos(skip r"[ \t\r\n\x0B\x0C\u{A0}]+")]
#[logos(skip(r"--[^\n]*", allow_greedy = true))]
enum Raw {
    #[regex(r"[a-zA-Z][a-zA-Z0-9_]*")]
    Ident,
    #[regex(r"\\([^\\\n]|\\\\)*\\")]
    ExtIdent,
    #[regex(r"\\([^\\\n]|\\\\)*")]
    UnterminatedExtIdent,
    #[regex(r"[0-9][0-9_]*(\.[0-9][0-9_]*)?([eE][+-]?[0-9][0-9_]*)?")]
    Decimal,
    #[regex(r"[0-9][0-9_]*#[0-9a-zA-Z_]+(\.[0-9a-zA-Z_]+)?#([eE][+-]?[0-9][0-9_]*)?")]
    Based,
    #[regex(r#""([^"\n]|"")*""#)]
    Str,
    #[regex(r#""([^"\n]|"")*"#)]
    UnterminatedStr,
    #[regex(r#"[bBoOxX]"[^"\n]*""#)]
    BitStr,
    #[token("/*", block_comment)]
    BlockComment,
    #[token("'")]
    Tick,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token("[")]
    LBracket,
    #[token("]")]
    RBracket,
    #[token(",")]
    Comma,
    #[token(";")]
    Semi,
    #[token(":")]
    Colon,
    #[token(".")]
    Dot,
    #[token("|")]
    #[token("!")]
    Bar,
    #[token("&")]
    Amp,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("/")]
    Slash,
    #[token("<")]
    Lt,
    #[token(">")]
    Gt,
    #[token("=")]
    Eq,
    #[token("=>")]
    Arrow,
    #[token("**")]
    Pow,
    #[token(":=")]
    Assign,
    #[token("/=")]
    Ne,
    #[token(">=")]
    Ge,
    #[token("<=")]
    Le,
    #[token("<>")]
    Box,
    #[token("==")]
    SimEq,
    #[token("?")]
    Question,
}

/// Skips a `/* ... */` comment; `false` (a lexing error) when it never ends.
fn block_comment(lex: &mut logos::Lexer<Raw>) -> logos::FilterResult<(), ()> {
    match lex.remainder().find("*/") {
        Some(end) => {
            lex.bump(end + 2);
            logos::FilterResult::Skip
        }
        None => {
            lex.bump(lex.remainder().len());
            logos::FilterResult::Error(())
        }
    }
}

/// Spanned token triple, as LALRPOP consumes it.
pub type Spanned<'a> = (usize, Tok<'a>, usize);

/// The result of lexing one file.
#[derive(Debug, Default)]
pub struct Lexed<'a> {
    pub tokens: Vec<Spanned<'a>>,
    pub errors: Vec<SyntaxError>,
}

/// Lexes a whole file.
pub fn lex(file: FileId, text: &str) -> Lexed<'_> {
    let mut out = Lexed {
        tokens: Vec::with_capacity(text.len() / 4),
        errors: Vec::new(),
    };
    let mut lexer = Raw::lexer(text);
    let mut depth = 0usize;
    let mut too_deep_reported = false;
    while let Some(raw) = lexer.next() {
        let range = lexer.span();
        let span = Span::new(file, range.start, range.end);
        let slice = lexer.slice();
        let raw = match raw {
            Ok(raw) => raw,
            Err(()) => {
                out.errors.push(bad_input(span, slice));
                continue;
            }
        };
        let tok = match raw {
            Raw::Ident => {
                if let Some(problem) = literal::check_identifier(slice) {
                    out.errors.push(SyntaxError::BadIdentifier {
                        span,
                        text: slice.to_string(),
                        problem,
                    });
                }
                match Kw::from_ident(slice) {
                    Some(kw) => Tok::Kw(kw),
                    None => Tok::Ident(slice),
                }
            }
            Raw::ExtIdent => Tok::ExtIdent(slice),
            Raw::UnterminatedExtIdent => {
                out.errors.push(SyntaxError::Unterminated {
                    span,
                    what: "extended identifier",
                    closer: "\\",
                });
                continue;
            }
            Raw::Decimal | Raw::Based => match literal::number(slice, raw == Raw::Based) {
                Ok(tok) => tok,
                Err(problem) => {
                    out.errors.push(SyntaxError::BadNumber {
                        span,
                        text: slice.to_string(),
                        problem,
                    });
                    Tok::Int(0)
                }
            },
            Raw::Str => Tok::Str(slice),
            Raw::UnterminatedStr => {
                out.errors.push(SyntaxError::Unterminated {
                    span,
                    what: "string literal",
                    closer: "\"",
                });
                continue;
            }
            Raw::BitStr => match literal::bit_string(slice) {
                Ok(bits) => Tok::BitStr(bits),
                Err(problem) => {
                    out.errors.push(SyntaxError::BadNumber {
                        span,
                        text: slice.to_string(),
                        problem,
                    });
                    Tok::BitStr(String::new())
                }
            },
            // Skipped by its callback; an unterminated one arrives as `Err` above.
            Raw::BlockComment => continue,
            Raw::Tick => {
                let tick_allowed = matches!(
                    out.tokens.last(),
                    Some((
                        _,
                        Tok::Ident(_) | Tok::ExtIdent(_) | Tok::RParen | Tok::RBracket,
                        _
                    ))
                );
                let mut chars = lexer.remainder().chars();
                match (chars.next(), chars.next()) {
                    (Some(c), Some('\'')) if !tick_allowed && c != '\n' => {
                        lexer.bump(c.len_utf8() + 1);
                        let end = lexer.span().end;
                        out.tokens.push((range.start, Tok::Char(c), end));
                        continue;
                    }
                    _ => Tok::Tick,
                }
            }
            Raw::LParen => {
                depth += 1;
                if depth > MAX_NESTING && !too_deep_reported {
                    too_deep_reported = true;
                    out.errors.push(SyntaxError::TooDeep {
                        span,
                        limit: MAX_NESTING,
                    });
                }
                Tok::LParen
            }
            Raw::RParen => {
                depth = depth.saturating_sub(1);
                Tok::RParen
            }
            Raw::LBracket => Tok::LBracket,
            Raw::RBracket => Tok::RBracket,
            Raw::Comma => Tok::Comma,
            Raw::Semi => Tok::Semi,
            Raw::Colon => Tok::Colon,
            Raw::Dot => Tok::Dot,
            Raw::Bar => Tok::Bar,
            Raw::Amp => Tok::Amp,
            Raw::Plus => Tok::Plus,
            Raw::Minus => Tok::Minus,
            Raw::Star => Tok::Star,
            Raw::Slash => Tok::Slash,
            Raw::Lt => Tok::Lt,
            Raw::Gt => Tok::Gt,
            Raw::Eq => Tok::Eq,
            Raw::Arrow => Tok::Arrow,
            Raw::Pow => Tok::Pow,
            Raw::Assign => Tok::Assign,
            Raw::Ne => Tok::Ne,
            Raw::Ge => Tok::Ge,
            Raw::Le => Tok::Le,
            Raw::Box => Tok::Box,
            Raw::SimEq => Tok::SimEq,
            Raw::Question => Tok::Question,
        };
        out.tokens.push((range.start, tok, range.end));
    }
    out
}

fn bad_input(span: Span, slice: &str) -> SyntaxError {
    if slice.starts_with("/*") {
        SyntaxError::Unterminated {
            span: Span::new(span.file, span.start as usize, span.start as usize + 2),
            what: "block comment",
            closer: "*/",
        }
    } else {
        SyntaxError::BadCharacter {
            span,
            text: slice.chars().take(8).collect(),
        }
    }
}
