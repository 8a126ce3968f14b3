//! Loading a compilation: files and directories -> a [`SourceMap`] holding the bundled stdlib
//! and the user's files (library `work`), each parsed, with the syntax errors of each file kept
//! for the caller to print or act on.
//!
//! A directory stands for its `.vhd`, `.vhdl` and `.ams` files, recursively, sorted. A user
//! file identical to a bundled stdlib file (a copy of `stdlib/` passed on the command line) is
//! skipped: the bundled copy is already loaded. The same file named twice is loaded once.

use std::path::{Path, PathBuf};

use miette::Diagnostic;
use thiserror::Error;

use crate::ast::DesignFile;
use crate::diagnostics::SyntaxError;
use crate::source::{FileId, SourceMap};
use crate::{parser, stdlib};

/// Problems with the inputs themselves.
#[derive(Debug, Error, Diagnostic)]
pub enum InputError {
    #[error("cannot read `{path}`: {reason}")]
    #[diagnostic(
        code(vams::input::unreadable),
        help("check the path; directories are searched for .vhd, .vhdl and .ams files")
    )]
    Unreadable { path: String, reason: String },
    #[error("no VHDL-AMS sources under `{path}`")]
    #[diagnostic(
        code(vams::input::empty_directory),
        help("vams reads files ending in .vhd, .vhdl or .ams")
    )]
    NoSources { path: String },
    #[error("the SPICE deck `{path}` comes with other sources")]
    #[diagnostic(
        code(vams::input::netlist_with_sources),
        help(
            "run a deck on its own (`vams run deck.cir`); SPICE subcircuits inside a VHDL-AMS design are not supported yet"
        )
    )]
    NetlistWithSources { path: String },
}

/// A loaded and parsed compilation.
#[derive(Debug)]
pub struct Loaded {
    pub sources: SourceMap,
    /// Every parsed file, stdlib first, in the order loaded (what elaboration takes).
    pub files: Vec<(FileId, DesignFile)>,
    /// The syntax errors of each file that has some, in file order.
    pub syntax_errors: Vec<(FileId, Vec<SyntaxError>)>,
}

impl Loaded {
    /// Total number of syntax errors.
    pub fn error_count(&self) -> usize {
        self.syntax_errors.iter().map(|(_, e)| e.len()).sum()
    }

    /// Design units parsed, stdlib included.
    pub fn unit_count(&self) -> usize {
        self.files.iter().map(|(_, f)| f.units.len()).sum()
    }

    /// True when the file has syntax errors.
    pub fn has_errors(&self, id: FileId) -> bool {
        self.syntax_errors.iter().any(|(f, _)| *f == id)
    }
}

/// Collects the source files a path stands for, sorted for a stable order.
pub fn source_files(path: &Path) -> Result<Vec<PathBuf>, InputError> {
    let unreadable = |e: std::io::Error| InputError::Unreadable {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    let meta = std::fs::metadata(path).map_err(unreadable)?;
    if !meta.is_dir() {
        return Ok(vec![path.to_path_buf()]);
    }
    let mut out = Vec::new();
    let mut stack = vec![path.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).map_err(unreadable)? {
            let p = entry.map_err(unreadable)?.path();
            if p.is_dir() {
                stack.push(p);
            } else if p
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| matches!(e.to_ascii_lowercase().as_str(), "vhd" | "vhdl" | "ams"))
            {
                out.push(p);
            }
        }
    }
    if out.is_empty() {
        return Err(InputError::NoSources {
            path: path.display().to_string(),
        });
    }
    out.sort();
    Ok(out)
}

/// Reads a file as text; non-UTF-8 input is read as ISO 8859-1, VHDL's own character set.
pub(crate) fn read_text(file: &Path) -> Result<String, InputError> {
    let bytes = std::fs::read(file).map_err(|e| InputError::Unreadable {
        path: file.display().to_string(),
        reason: e.to_string(),
    })?;
    Ok(String::from_utf8(bytes)
        .unwrap_or_else(|e| e.into_bytes().iter().map(|&b| b as char).collect()))
}

/// `--lib NAME=PATH`: the sources under PATH, analysed into library NAME (what `library
/// util; use util.stimulus_generators.all;` names) instead of `work`.
#[derive(Clone, Debug, PartialEq)]
pub struct LibrarySources {
    pub name: String,
    pub path: PathBuf,
}

/// Parses `NAME=PATH` for `--lib`.
pub fn parse_library(text: &str) -> Result<LibrarySources, String> {
    let Some((name, path)) = text.split_once('=') else {
        return Err(format!(
            "`{text}`: expected NAME=PATH, e.g. --lib util=../util"
        ));
    };
    let name = name.trim().to_ascii_lowercase();
    let identifier = name.starts_with(|c: char| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !identifier {
        return Err(format!(
            "`{name}` is not a VHDL identifier (a library name)"
        ));
    }
    if matches!(
        name.as_str(),
        "std" | "ieee" | "ieee_proposed" | "vams" | "work"
    ) {
        return Err(format!(
            "library `{name}` is {}; choose another name",
            if name == "work" {
                "where the files given without --lib go"
            } else {
                "bundled with vams"
            }
        ));
    }
    if path.trim().is_empty() {
        return Err(format!("`{text}`: the path after `=` is missing"));
    }
    Ok(LibrarySources {
        name,
        path: PathBuf::from(path.trim()),
    })
}

/// Loads the sources under `paths` (library `work`) and `libraries`, and the bundled
/// standard packages they need
/// (`std.standard`, and the packages their units name, transitively), and parses every file.
/// Only the packages a design names are parsed and analysed: the stdlib grows (numeric_std,
/// the arithmetic packages) without slowing down designs that do not use it.
pub fn load(paths: &[PathBuf]) -> Result<Loaded, InputError> {
    load_with_libraries(paths, &[])
}

/// [`load`], with the sources of `libraries` analysed into their own libraries.
pub fn load_with_libraries(
    paths: &[PathBuf],
    libraries: &[LibrarySources],
) -> Result<Loaded, InputError> {
    let mut sources = SourceMap::new();
    let mut ids = Vec::new();
    let mut seen: Vec<PathBuf> = Vec::new();
    let named = paths
        .iter()
        .map(|p| ("work", p))
        .chain(libraries.iter().map(|l| (l.name.as_str(), &l.path)));
    for (library, path) in named {
        for file in source_files(path)? {
            let key = std::fs::canonicalize(&file).unwrap_or_else(|_| file.clone());
            if seen.contains(&key) {
                continue;
            }
            seen.push(key);
            let text = read_text(&file)?;
            if stdlib::FILES.iter().any(|(_, _, t)| *t == text) {
                continue; // The bundled copy of this file is already loaded.
            }
            ids.push(sources.add(file.display().to_string(), library, text));
        }
    }
    Ok(parse_loaded(sources, ids))
}

/// One source text in library `work`, with the bundled packages it names: what [`load`] gives
/// for a file holding `text` (for the fuzz target, and tools that hold the text in memory).
pub fn load_text(name: &str, text: String) -> Loaded {
    load_texts(vec![(name.to_string(), text)])
}

/// Several source texts in library `work` (a preset's bundled models), as [`load_text`].
pub fn load_texts(texts: Vec<(String, String)>) -> Loaded {
    let mut sources = SourceMap::new();
    let ids = texts
        .into_iter()
        .map(|(name, text)| sources.add(name, "work", text))
        .collect();
    parse_loaded(sources, ids)
}

/// Parses the user's files `ids` of `sources` and adds the bundled packages they need.
fn parse_loaded(mut sources: SourceMap, ids: Vec<FileId>) -> Loaded {
    let mut user = Vec::with_capacity(ids.len());
    let mut syntax_errors = Vec::new();
    let parse = |id: FileId, sources: &SourceMap, errs: &mut Vec<(FileId, Vec<_>)>| {
        let text = sources.file(id).text.clone();
        let (ast, errors) = parser::parse(id, &text);
        if !errors.is_empty() {
            errs.push((id, errors));
        }
        ast
    };
    for id in ids {
        let ast = parse(id, &sources, &mut syntax_errors);
        user.push((id, ast));
    }
    // The bundled packages named, transitively, starting from std.standard.
    let (mut files, stdlib_errors) = stdlib::load_needed(&mut sources, &user);
    syntax_errors.extend(stdlib_errors);
    // The stdlib first, in its own order, then the user's files.
    files.extend(user);
    Loaded {
        sources,
        files,
        syntax_errors,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loads_directories_once_skips_stdlib_copies_and_keeps_errors() {
        let dir = tempfile::tempdir().unwrap();
        let sub = dir.path().join("sub");
        std::fs::create_dir(&sub).unwrap();
        std::fs::write(dir.path().join("a.vhd"), "entity a is end;").unwrap();
        std::fs::write(sub.join("b.VHDL"), "entity b is port (x : in bit) end;").unwrap();
        std::fs::write(sub.join("notes.txt"), "not vhdl").unwrap();
        let (_, _, stdlib_text) = stdlib::FILES[0];
        std::fs::write(dir.path().join("copy.vhd"), stdlib_text).unwrap();
        let a = dir.path().join("a.vhd");
        let loaded = load(&[dir.path().to_path_buf(), a]).unwrap();
        // The two user files and std.standard, the one bundled package they need.
        assert_eq!(loaded.files.len(), 3);
        let names: Vec<&str> = loaded
            .sources
            .files()
            .map(|(_, f)| f.name.as_str())
            .collect();
        assert!(names[0].ends_with("a.vhd") && names[1].ends_with("b.VHDL"));
        assert_eq!(names[2], "stdlib/std/standard.vhd");
        assert_eq!(loaded.syntax_errors.len(), 1);
        assert!(loaded.has_errors(loaded.syntax_errors[0].0));
        assert!(loaded.error_count() >= 1);
    }

    #[test]
    fn a_text_in_memory_loads_like_a_file() {
        let loaded = load_text(
            "m.vhd",
            "entity m is end; architecture a of m is begin end;".into(),
        );
        assert_eq!(loaded.error_count(), 0);
        // The text, then std.standard.
        assert_eq!(loaded.files.len(), 2);
        let bad = load_text("bad.vhd", "entity is".into());
        assert_eq!(bad.syntax_errors.len(), 1);
    }

    #[test]
    fn only_the_bundled_packages_a_design_names_are_loaded() {
        let dir = tempfile::tempdir().unwrap();
        let model = dir.path().join("m.vhd");
        std::fs::write(
            &model,
            "library ieee_proposed; use ieee_proposed.electrical_systems.all;\n\
             entity m is end;\narchitecture a of m is\n\
             constant pi2 : real := 2.0 * ieee.math_real.math_pi;\nbegin end;\n",
        )
        .unwrap();
        let loaded = load(&[model]).unwrap();
        let names: Vec<&str> = loaded
            .sources
            .files()
            .map(|(_, f)| f.name.as_str())
            .collect();
        for needed in ["standard", "electrical_systems", "math_real"] {
            assert!(
                names.iter().any(|n| n.ends_with(&format!("/{needed}.vhd"))),
                "{needed} missing from {names:?}"
            );
        }
        for unused in ["numeric_std", "numeric_bit", "std_logic_arith", "textio"] {
            assert!(!names.iter().any(|n| n.ends_with(&format!("/{unused}.vhd"))));
        }
        // The stdlib comes first among the parsed files (analysis and elaboration order).
        let first = loaded.sources.file(loaded.files[0].0).name.as_str();
        assert!(first.starts_with("stdlib/"), "{first}");
    }

    #[test]
    fn missing_paths_and_empty_directories_are_diagnosed() {
        let dir = tempfile::tempdir().unwrap();
        assert!(matches!(
            load(&[dir.path().join("nope.vhd")]),
            Err(InputError::Unreadable { .. })
        ));
        assert!(matches!(
            load(&[dir.path().to_path_buf()]),
            Err(InputError::NoSources { .. })
        ));
    }
}
