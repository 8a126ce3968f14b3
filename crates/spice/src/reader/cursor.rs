//! Small helpers over the tokens of one logical line.
//!
//! Takes card-level tokens; gives names, values (`Expr`) and `key=value` lists, or located
//! diagnostics. Shared by the element and the card readers.

use vams_syntax::source::Span;

use crate::deck::{Name, Param};
use crate::error::SpiceError;
use crate::expr::{Expr, bad_number, parse_card_tokens};
use crate::lexer::{TokKind, Token};
use crate::number::{parse_number, starts_like_number};

/// The name a word token spells.
pub fn name_of(tok: &Token) -> Name {
    Name {
        key: tok.key(),
        text: tok.text.clone(),
        span: tok.span,
    }
}

/// Whether a token can only be a value: a brace, a quote, or a word that starts like a number.
pub fn is_value_like(tok: &Token) -> bool {
    match tok.kind {
        TokKind::Brace | TokKind::Quote => true,
        TokKind::Word => starts_like_number(&tok.text),
        _ => false,
    }
}

/// The value one token holds: a number, a `{...}` or `'...'` expression, or a word read as
/// an expression (`rval`, `2*a`).
pub fn value_of(tok: &Token) -> Result<Expr, SpiceError> {
    match tok.kind {
        TokKind::Word if starts_like_number(&tok.text) => match parse_number(&tok.text) {
            Ok(v) => Ok(Expr::num(v, tok.span)),
            // `2*a`: an expression written without braces, which ngspice also reads.
            Err(e) => parse_card_tokens(std::slice::from_ref(tok))
                .map_err(|_| bad_number(&tok.text, tok.span, e)),
        },
        TokKind::Word | TokKind::Brace | TokKind::Quote => {
            parse_card_tokens(std::slice::from_ref(tok))
        }
        _ => Err(expected(tok.span, "a value", &tok.text, "")),
    }
}

/// `expected {what}, found `{found}``, labelled on `span`.
pub fn expected(span: Span, what: &str, found: &str, help: &str) -> SpiceError {
    SpiceError::syntax(
        span,
        format!("expected {what}, found `{found}`"),
        format!("expected {what}"),
        help,
    )
}

/// `{what} is missing`, labelled after the last token of the line.
pub fn missing(line_end: Span, what: &str, help: &str) -> SpiceError {
    SpiceError::syntax(
        line_end,
        format!("{what} is missing"),
        format!("expected {what} after this"),
        help,
    )
}

/// A cursor over the tokens of a line.
pub struct Cursor<'t> {
    toks: &'t [Token],
    pos: usize,
}

impl<'t> Cursor<'t> {
    pub fn new(toks: &'t [Token]) -> Cursor<'t> {
        Cursor { toks, pos: 0 }
    }

    pub fn peek(&self) -> Option<&'t Token> {
        self.toks.get(self.pos)
    }

    pub fn peek_at(&self, ahead: usize) -> Option<&'t Token> {
        self.toks.get(self.pos + ahead)
    }

    pub fn next(&mut self) -> Option<&'t Token> {
        let t = self.toks.get(self.pos);
        if t.is_some() {
            self.pos += 1;
        }
        t
    }

    pub fn is_done(&self) -> bool {
        self.pos >= self.toks.len()
    }

    pub fn rest(&self) -> &'t [Token] {
        self.toks.get(self.pos..).unwrap_or(&[])
    }

    /// The span of the line's last token (to label what is missing at its end).
    pub fn end_span(&self) -> Span {
        self.toks.last().map(|t| t.span).unwrap_or_default()
    }

    /// Whether `key=` comes next.
    pub fn at_key_value(&self) -> bool {
        matches!(
            (self.peek(), self.peek_at(1)),
            (Some(a), Some(b)) if a.is_word() && b.kind == TokKind::Eq
        )
    }

    /// Skips commas.
    pub fn skip_commas(&mut self) {
        while self.peek().is_some_and(|t| t.kind == TokKind::Comma) {
            self.pos += 1;
        }
    }

    /// A word, as a name.
    pub fn name(&mut self, what: &str, help: &str) -> Result<Name, SpiceError> {
        match self.next() {
            Some(t) if t.is_word() => Ok(name_of(t)),
            Some(t) => Err(expected(t.span, what, &t.text, help)),
            None => Err(missing(self.end_span(), what, help)),
        }
    }

    /// One value token.
    pub fn value(&mut self, what: &str, help: &str) -> Result<Expr, SpiceError> {
        match self.next() {
            Some(t) if matches!(t.kind, TokKind::Word | TokKind::Brace | TokKind::Quote) => {
                value_of(t)
            }
            Some(t) => Err(expected(t.span, what, &t.text, help)),
            None => Err(missing(self.end_span(), what, help)),
        }
    }

    /// `key=value` at the cursor (the caller checked [`Cursor::at_key_value`]).
    pub fn key_value(&mut self) -> Result<Param, SpiceError> {
        let name = self.name("a parameter name", "")?;
        self.pos += 1; // the `=`
        let value = match self.next() {
            Some(t) if matches!(t.kind, TokKind::Word | TokKind::Brace | TokKind::Quote) => {
                value_of(t)?
            }
            Some(t) => {
                return Err(expected(t.span, "a value", &t.text, "write `name=value`"));
            }
            None => {
                return Err(missing(
                    self.end_span(),
                    &format!("the value of `{}`", name.text),
                    "write `name=value`",
                ));
            }
        };
        Ok(Param { name, value })
    }
}
