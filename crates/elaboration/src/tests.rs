//! Elaboration tests: small inline designs per construct, and the headlight models.

mod constructs;
mod models;
mod subprograms;

use vams_design::Design;
use vams_semantics::stdlib;
use vams_syntax::ast::DesignFile;
use vams_syntax::diagnostics::render_plain;
use vams_syntax::parser;
use vams_syntax::source::{FileId, SourceMap};

use super::{ElabError, ElabOptions, elaborate};

/// The stdlib plus `user` files (name, text), parsed; panics on syntax errors (test input).
pub(super) fn parse_all(user: &[(&str, &str)]) -> (SourceMap, Vec<(FileId, DesignFile)>) {
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    for (name, text) in user {
        ids.push(sources.add(*name, "work", text.to_string()));
    }
    let mut files = Vec::new();
    for id in ids {
        let (ast, errors) = parser::parse(id, &sources.file(id).text.clone());
        assert!(
            errors.is_empty(),
            "syntax errors in {}: {errors:?}",
            sources.file(id).name
        );
        files.push((id, ast));
    }
    (sources, files)
}

/// Elaborates `top` from one inline file.
pub(super) fn run(
    text: &str,
    top: &str,
    generics: &[(&str, &str)],
) -> (SourceMap, Result<Design, Vec<ElabError>>) {
    let (sources, files) = parse_all(&[("test.vhd", text)]);
    let options = ElabOptions {
        top: top.into(),
        generics: generics
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect(),
    };
    let result = elaborate(&sources, &files, &options);
    (sources, result)
}

/// Elaborates and expects success, printing the diagnostics otherwise.
pub(super) fn ok(text: &str, top: &str) -> Design {
    let (sources, r) = run(text, top, &[]);
    match r {
        Ok(d) => d,
        Err(errors) => {
            let text: Vec<String> = errors.iter().map(|e| render_plain(e, &sources)).collect();
            panic!("elaboration failed:\n{}", text.join("\n"));
        }
    }
}

/// Elaborates and expects failure; the rendered diagnostics.
pub(super) fn errors(text: &str, top: &str) -> Vec<String> {
    let (sources, r) = run(text, top, &[]);
    match r {
        Ok(_) => panic!("elaboration succeeded"),
        Err(errors) => errors.iter().map(|e| render_plain(e, &sources)).collect(),
    }
}

/// The binding rule is analysis's: an architecture belongs to the entity declared before it
/// (a folder of variants redeclares entities), so a later redeclaration without an
/// architecture leaves the entity with none, instead of elaborating the earlier entity's
/// architecture against the later interface.
#[test]
fn an_architecture_belongs_to_the_entity_declared_before_it() {
    let first = "entity leaf is generic (k : real := 1.0); end;\n\
                 architecture one of leaf is signal s : real := k; begin end;\n";
    let second = "entity leaf is generic (k : integer := 2); end;\n";
    let top = "entity top is end;\narchitecture a of top is begin u : entity work.leaf; end;\n";
    let (sources, files) = parse_all(&[("a.vhd", first), ("b.vhd", second), ("c.vhd", top)]);
    let options = ElabOptions {
        top: "top".into(),
        generics: Vec::new(),
    };
    let errors = elaborate(&sources, &files, &options).expect_err("leaf has no architecture");
    let text: Vec<String> = errors.iter().map(|e| render_plain(e, &sources)).collect();
    assert!(
        text.iter()
            .any(|t| t.contains("architecture") && t.contains("leaf")),
        "{text:?}"
    );
    // In the other order the architecture follows the entity it was written for.
    let (sources, files) = parse_all(&[("b.vhd", second), ("a.vhd", first), ("c.vhd", top)]);
    assert!(elaborate(&sources, &files, &options).is_ok());
}

/// Names resolve to the declarations analysis chose: an item of a package no `use` clause
/// names (`work.p.k`, the package in a later file) elaborates, and a model's own `string`
/// type does not change what a string literal is.
#[test]
fn names_elaborate_from_their_analysed_declarations() {
    let top = "entity top is end;\narchitecture a of top is\n\
               type string is range 0 to 9;\n\
               signal s : work.p.small := work.p.first;\n\
               signal r : real := work.p.k * 2.0;\n\
               begin\n\
               process begin report \"text\"; wait; end process;\n\
               end;\n";
    let pkg = "package p is\n  type small is range 0 to 3;\n  constant first : small := 2;\n  \
               constant k : real := 1.5;\nend package p;\n";
    let (sources, files) = parse_all(&[("top.vhd", top), ("p.vhd", pkg)]);
    let options = ElabOptions {
        top: "top".into(),
        generics: Vec::new(),
    };
    let design = match elaborate(&sources, &files, &options) {
        Ok(d) => d,
        Err(errors) => {
            let text: Vec<String> = errors.iter().map(|e| render_plain(e, &sources)).collect();
            panic!("elaboration failed:\n{}", text.join("\n"));
        }
    };
    let init = |name: &str| {
        design
            .signals
            .iter()
            .find(|s| s.name.ends_with(name))
            .map(|s| s.init.clone())
    };
    assert_eq!(init("s"), Some(vams_design::Value::Integer(2)));
    assert_eq!(init("r"), Some(vams_design::Value::Real(3.0)));
}
