//! The bundled standard packages (`stdlib/`): `std.standard`, `std.textio`, `std.env`,
//! `ieee.std_logic_1164`, `ieee.math_real` and the IEEE 1076.1.1 discipline packages, compiled
//! into the binary by `build.rs` so that `vams` needs no installation directory.

include!(concat!(env!("OUT_DIR"), "/stdlib_files.rs"));

use vams_syntax::ast::{ContextItem, DesignFile, ExprKind};
use vams_syntax::diagnostics::SyntaxError;
use vams_syntax::source::{FileId, SourceMap};

/// Registers every bundled file in `sources` under its library; returns their ids.
pub fn load(sources: &mut SourceMap) -> Vec<FileId> {
    FILES
        .iter()
        .map(|(lib, path, text)| sources.add(*path, lib, (*text).to_string()))
        .collect()
}

/// Registers and parses the bundled files that `user` (parsed files) needs: std.standard and
/// the packages named, transitively. Returns them in [`FILES`] order with the syntax errors
/// of any (there are none in a correct build).
#[allow(clippy::type_complexity)]
pub fn load_needed(
    sources: &mut SourceMap,
    user: &[(FileId, DesignFile)],
) -> (Vec<(FileId, DesignFile)>, Vec<(FileId, Vec<SyntaxError>)>) {
    let mut wanted: Vec<usize> = package_file("std", "standard").into_iter().collect();
    for (_, f) in user {
        wanted.extend(named_packages(f));
    }
    let mut parsed: Vec<Option<(FileId, DesignFile)>> = vec![None; FILES.len()];
    let mut errors = Vec::new();
    while let Some(i) = wanted.pop() {
        if parsed[i].is_some() {
            continue;
        }
        let (lib, path, text) = FILES[i];
        let id = sources.add(path, lib, text.to_string());
        let (ast, errs) = vams_syntax::parser::parse(id, text);
        if !errs.is_empty() {
            errors.push((id, errs));
        }
        wanted.extend(named_packages(&ast));
        parsed[i] = Some((id, ast));
    }
    (parsed.into_iter().flatten().collect(), errors)
}

/// The index in [`FILES`] of the bundled package `lib.name` (each file holds the package
/// its name says, `stdlib/ieee/numeric_std.vhd`; `ieee_proposed` is `ieee`).
pub fn package_file(lib: &str, name: &str) -> Option<usize> {
    let lib = match lib.to_ascii_lowercase().as_str() {
        "ieee_proposed" => "ieee".to_string(),
        other => other.to_string(),
    };
    let name = name.to_ascii_lowercase();
    FILES.iter().position(|(l, path, _)| {
        *l == lib
            && std::path::Path::new(path)
                .file_stem()
                .and_then(|s| s.to_str())
                .is_some_and(|stem| stem == name)
    })
}

/// The bundled files that the units of `file` name: the packages of its `use` clauses and
/// of its selected names `lib.pkg` (indices in [`FILES`]).
pub fn named_packages(file: &DesignFile) -> Vec<usize> {
    let mut out = Vec::new();
    for unit in &file.units {
        for item in &unit.context {
            if let ContextItem::Use(names, _) = item {
                for n in names {
                    if let Some((lib, pkg)) = first_two(n) {
                        out.extend(package_file(&lib, &pkg));
                    }
                }
            }
        }
        for (lib, pkg) in &unit.dotted {
            out.extend(package_file(&lib.name, &pkg.name));
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// `lib.pkg` of a selected name `lib.pkg[.item]`.
fn first_two(e: &vams_syntax::ast::Expr) -> Option<(String, String)> {
    let ExprKind::Selected(prefix, suffix) = &e.kind else {
        return None;
    };
    match &prefix.kind {
        ExprKind::Name(lib) => Some((lib.name.clone(), suffix.name.clone())),
        ExprKind::Selected(..) => first_two(prefix),
        _ => None,
    }
}
