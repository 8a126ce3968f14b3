//! Elaboration tests: small inline designs per construct, and the headlight models.

mod constructs;
mod models;
mod subprograms;

use crate::ast::DesignFile;
use crate::design::Design;
use crate::diagnostics::render_plain;
use crate::source::{FileId, SourceMap};
use crate::{parser, stdlib};

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
