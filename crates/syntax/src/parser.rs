//! The parser: tokens to AST.
//!
//! Takes the text of one file; gives its [`DesignFile`] and every lexical and syntax error
//! found, never failing outright (errors are recovered at `;` inside declaration and statement
//! lists). Wraps the LALRPOP grammar in `grammar/vhdl.lalrpop`; it knows nothing about names or
//! types.

pub mod support;
#[cfg(test)]
mod tests;

use lalrpop_util::{ErrorRecovery, ParseError, lalrpop_mod};

use crate::ast::{DesignFile, Ident};
use crate::diagnostics::SyntaxError;
use crate::lexer::{self, Tok};
use crate::source::{FileId, Span};

lalrpop_mod!(
    #[allow(clippy::all, unused_parens, dead_code)]
    grammar,
    "/vhdl.rs"
);

/// Parses one file; the AST holds every design unit that could be recovered.
pub fn parse(file: FileId, text: &str) -> (DesignFile, Vec<SyntaxError>) {
    let lexed = lexer::lex(file, text);
    let mut diagnostics = lexed.errors;
    if diagnostics
        .iter()
        .any(|e| matches!(e, SyntaxError::TooDeep { .. }))
    {
        return (DesignFile::default(), diagnostics);
    }
    let dotted = dotted_pairs(file, &lexed.tokens);
    let mut recovered: support::Errors<'_> = Vec::new();
    let result = grammar::DesignFileParser::new().parse(
        file,
        &mut recovered,
        lexed.tokens.into_iter().map(Ok::<_, SyntaxError>),
    );
    diagnostics.extend(recovered.into_iter().map(|r| convert(file, text, r)));
    let ast = match result {
        Ok(mut ast) => {
            assign_dotted(&mut ast, dotted);
            ast
        }
        // A file that ends inside a unit after an error was recovered is that error's
        // cascade (recovery skipped the unit's `end`): reporting it again would only be noise.
        Err(ParseError::UnrecognizedEof { .. }) if !diagnostics.is_empty() => DesignFile::default(),
        Err(error) => {
            diagnostics.push(convert(
                file,
                text,
                ErrorRecovery {
                    error,
                    dropped_tokens: Vec::new(),
                },
            ));
            DesignFile::default()
        }
    };
    diagnostics.sort_by_key(|d| d.span().start);
    (ast, diagnostics)
}

/// Every `a.b` of two plain identifiers, in text order.
fn dotted_pairs(file: FileId, tokens: &[lexer::Spanned<'_>]) -> Vec<(Ident, Ident)> {
    let ident = |&(l, ref t, r): &lexer::Spanned<'_>| match t {
        Tok::Ident(s) => Some(Ident {
            name: s.to_ascii_lowercase(),
            span: Span::new(file, l, r),
        }),
        _ => None,
    };
    tokens
        .windows(3)
        .filter(|w| matches!(w[1].1, Tok::Dot))
        .filter_map(|w| Some((ident(&w[0])?, ident(&w[2])?)))
        .collect()
}

/// Gives each unit the pairs inside its span (both in text order).
fn assign_dotted(ast: &mut DesignFile, dotted: Vec<(Ident, Ident)>) {
    let mut pairs = dotted.into_iter().peekable();
    for unit in &mut ast.units {
        while pairs
            .next_if(|(a, _)| a.span.start < unit.span.start)
            .is_some()
        {}
        while let Some(pair) = pairs.next_if(|(a, _)| a.span.end <= unit.span.end) {
            unit.dotted.push(pair);
        }
    }
}

fn convert(file: FileId, text: &str, r: ErrorRecovery<usize, Tok<'_>, SyntaxError>) -> SyntaxError {
    match r.error {
        ParseError::User { error } => error,
        ParseError::UnrecognizedEof { location, expected } => {
            // Point at the last character so the label is visible.
            let start = location.min(text.len()).saturating_sub(1);
            SyntaxError::UnexpectedEof {
                span: Span::new(file, start, location.min(text.len())),
                expected: expected_list(&expected),
            }
        }
        ParseError::UnrecognizedToken {
            token: (l, tok, r),
            expected,
        } => unexpected(file, l, &tok, r, &expected),
        ParseError::ExtraToken { token: (l, tok, r) } => unexpected(file, l, &tok, r, &[]),
        ParseError::InvalidToken { location } => SyntaxError::BadCharacter {
            span: Span::new(file, location, location + 1),
            text: text
                .get(location..)
                .and_then(|s| s.chars().next())
                .map(String::from)
                .unwrap_or_default(),
        },
    }
}

fn unexpected(file: FileId, l: usize, tok: &Tok<'_>, r: usize, expected: &[String]) -> SyntaxError {
    let found = describe(tok);
    let wants = |t: &str| expected.iter().any(|e| e.trim_matches('"') == t);
    let help = if let Tok::Kw(kw) = tok
        && wants("id")
    {
        Some(format!(
            "`{}` is a reserved word of VHDL-AMS and cannot be used as a name; choose another \
             (note: across, through, quantity, terminal, nature, reference, tolerance, \
             procedural, break, limit, spectrum, noise, subnature are reserved in VHDL-AMS)",
            kw.as_str()
        ))
    } else if matches!(tok, Tok::Eq) && (wants(";") || wants("==") || wants(":=")) {
        Some(
            "`=` compares; a simultaneous statement is written `lhs == rhs;`, a signal \
             assignment `s <= value;`, a variable assignment `v := value;`"
                .into(),
        )
    } else if wants(";") {
        Some("a `;` may be missing at the end of the previous declaration or statement".into())
    } else {
        None
    };
    SyntaxError::Unexpected {
        span: Span::new(file, l, r),
        found,
        expected: expected_list(expected),
        help,
    }
}

fn expected_list(expected: &[String]) -> String {
    if expected.is_empty() {
        return "not expected here".into();
    }
    let mut names: Vec<String> = expected
        .iter()
        .map(|e| {
            let t = e.trim_matches('"').replace("\\\"", "\"");
            match t.as_str() {
                "id" | "extid" => "an identifier".to_string(),
                "int" | "real" => "a number".to_string(),
                "char" => "a character literal".to_string(),
                "str" => "a string".to_string(),
                "bitstr" => "a bit string".to_string(),
                _ => format!("`{t}`"),
            }
        })
        .collect();
    names.dedup();
    const SHOWN: usize = 8;
    let more = names.len().saturating_sub(SHOWN);
    names.truncate(SHOWN);
    let mut s = format!("expected {}", names.join(", "));
    if more > 0 {
        s.push_str(&format!(" or {more} more"));
    }
    s
}

fn describe(tok: &Tok<'_>) -> String {
    match tok {
        Tok::Ident(s) | Tok::ExtIdent(s) => format!("identifier `{s}`"),
        Tok::Kw(k) => format!("keyword `{}`", k.as_str()),
        Tok::Int(_) | Tok::Real(_) => "number".into(),
        Tok::Char(c) => format!("character literal '{c}'"),
        Tok::Str(s) => format!("string {s}"),
        Tok::BitStr(_) => "bit-string literal".into(),
        other => format!("`{}`", punctuation(other)),
    }
}

fn punctuation(tok: &Tok<'_>) -> &'static str {
    match tok {
        Tok::Tick => "'",
        Tok::LParen => "(",
        Tok::RParen => ")",
        Tok::LBracket => "[",
        Tok::RBracket => "]",
        Tok::Comma => ",",
        Tok::Semi => ";",
        Tok::Colon => ":",
        Tok::Dot => ".",
        Tok::Bar => "|",
        Tok::Amp => "&",
        Tok::Plus => "+",
        Tok::Minus => "-",
        Tok::Star => "*",
        Tok::Slash => "/",
        Tok::Lt => "<",
        Tok::Gt => ">",
        Tok::Eq => "=",
        Tok::Arrow => "=>",
        Tok::Pow => "**",
        Tok::Assign => ":=",
        Tok::Ne => "/=",
        Tok::Ge => ">=",
        Tok::Le => "<=",
        Tok::Box => "<>",
        Tok::SimEq => "==",
        Tok::Question => "?",
        _ => "token",
    }
}
