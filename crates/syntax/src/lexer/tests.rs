use super::*;

fn toks(text: &str) -> Vec<Tok<'_>> {
    let lexed = lex(FileId(0), text);
    assert!(lexed.errors.is_empty(), "{:?}", lexed.errors);
    lexed.tokens.into_iter().map(|(_, t, _)| t).collect()
}

fn errors(text: &str) -> Vec<SyntaxError> {
    lex(FileId(0), text).errors
}

#[test]
fn keywords_match_in_any_case_and_identifiers_keep_spelling() {
    assert_eq!(
        toks("ENTITY Foo Is"),
        vec![Tok::Kw(Kw::Entity), Tok::Ident("Foo"), Tok::Kw(Kw::Is)]
    );
    assert_eq!(toks("QuAnTiTy"), vec![Tok::Kw(Kw::Quantity)]);
}

#[test]
fn force_and_release_are_identifiers_in_the_2002_baseline() {
    assert_eq!(
        toks("force release"),
        vec![Tok::Ident("force"), Tok::Ident("release")]
    );
}

#[test]
fn extended_identifiers() {
    assert_eq!(toks(r"\foo bar\"), vec![Tok::ExtIdent(r"\foo bar\")]);
    assert_eq!(toks(r"\a\\b\"), vec![Tok::ExtIdent(r"\a\\b\")]);
}

#[test]
fn decimal_literals_with_underscores_and_exponents() {
    assert_eq!(toks("1_000"), vec![Tok::Int(1000)]);
    assert_eq!(toks("1E3"), vec![Tok::Int(1000)]);
    assert_eq!(toks("1.5e-3"), vec![Tok::Real(1.5e-3)]);
    assert_eq!(toks("1.234_5"), vec![Tok::Real(1.2345)]);
}

#[test]
fn based_literals() {
    assert_eq!(toks("16#FF#"), vec![Tok::Int(255)]);
    assert_eq!(toks("2#1010_1010#"), vec![Tok::Int(170)]);
    assert_eq!(toks("2#1.1#e3"), vec![Tok::Real(12.0)]);
    assert_eq!(toks("16#F.8#"), vec![Tok::Real(15.5)]);
    assert!(!errors("16#FG#").is_empty());
    assert!(!errors("17#1#").is_empty());
}

#[test]
fn physical_literals_are_a_number_and_a_unit() {
    assert_eq!(toks("10 ms"), vec![Tok::Int(10), Tok::Ident("ms")]);
    assert_eq!(toks("1.5 sec"), vec![Tok::Real(1.5), Tok::Ident("sec")]);
}

#[test]
fn character_literal_versus_tick() {
    assert_eq!(toks("'a'"), vec![Tok::Char('a')]);
    assert_eq!(
        toks("x'dot"),
        vec![Tok::Ident("x"), Tok::Tick, Tok::Ident("dot")]
    );
    assert_eq!(
        toks("t'('a')"),
        vec![
            Tok::Ident("t"),
            Tok::Tick,
            Tok::LParen,
            Tok::Char('a'),
            Tok::RParen
        ]
    );
    assert_eq!(
        toks("f(x)'length"),
        vec![
            Tok::Ident("f"),
            Tok::LParen,
            Tok::Ident("x"),
            Tok::RParen,
            Tok::Tick,
            Tok::Ident("length")
        ]
    );
    assert_eq!(
        toks("(''')"),
        vec![Tok::LParen, Tok::Char('\''), Tok::RParen]
    );
    assert_eq!(
        toks("c = ' '"),
        vec![Tok::Ident("c"), Tok::Eq, Tok::Char(' ')]
    );
}

#[test]
fn strings_and_bit_strings() {
    assert_eq!(toks(r#""say ""hi""""#), vec![Tok::Str(r#""say ""hi""""#)]);
    assert_eq!(toks(r#"X"F0""#), vec![Tok::BitStr("11110000".into())]);
    assert_eq!(toks(r#"b"1010""#), vec![Tok::BitStr("1010".into())]);
    assert_eq!(toks(r#"O"17""#), vec![Tok::BitStr("001111".into())]);
    assert!(!errors(r#"B"102""#).is_empty());
}

#[test]
fn comments_are_skipped() {
    assert_eq!(
        toks("a -- comment\nb"),
        vec![Tok::Ident("a"), Tok::Ident("b")]
    );
    assert_eq!(
        toks("a /* x\n y */ b"),
        vec![Tok::Ident("a"), Tok::Ident("b")]
    );
}

#[test]
fn compound_delimiters() {
    assert_eq!(
        toks("== => <= := /= ** <> >= < >"),
        vec![
            Tok::SimEq,
            Tok::Arrow,
            Tok::Le,
            Tok::Assign,
            Tok::Ne,
            Tok::Pow,
            Tok::Box,
            Tok::Ge,
            Tok::Lt,
            Tok::Gt
        ]
    );
}

#[test]
fn bad_input_is_diagnosed_not_fatal() {
    assert!(matches!(
        errors("\"abc")[0],
        SyntaxError::Unterminated { .. }
    ));
    assert!(matches!(
        errors("a /* never closed")[0],
        SyntaxError::Unterminated { .. }
    ));
    assert!(matches!(
        errors("a $ b")[0],
        SyntaxError::BadCharacter { .. }
    ));
    assert!(matches!(
        errors("a__b")[0],
        SyntaxError::BadIdentifier { .. }
    ));
    assert!(matches!(
        errors("99999999999999999999")[0],
        SyntaxError::BadNumber { .. }
    ));
    let deep = "(".repeat(5000);
    assert!(matches!(errors(&deep)[0], SyntaxError::TooDeep { .. }));
}

proptest::proptest! {
    #[test]
    fn lexer_never_panics(s in "\\PC{0,200}") {
        let _ = lex(FileId(0), &s);
    }

    #[test]
    fn lexer_never_panics_on_vhdl_like_text(s in "[a-z0-9_'\"#.()\\\\ ;:=<>/*+-]{0,200}") {
        let _ = lex(FileId(0), &s);
    }
}
