//! `vams check FILES|DIRS...`: reads the given sources (a directory means its `.vhd`, `.vhdl`
//! and `.ams` files, recursively) together with the bundled stdlib, and reports every
//! diagnostic with file, line, column and a help line. Exit 0 when clean, 1 on any error.
//!
//! Today this runs the lexer and the parser; semantic analysis is the next stage to plug in.

use std::path::{Path, PathBuf};

use clap::Args;
use miette::{Diagnostic, Report};
use thiserror::Error;

use crate::diagnostics::render_plain;
use crate::source::SourceMap;
use crate::{parser, stdlib};

/// Arguments of `vams check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Source files or directories.
    #[arg(required = true)]
    pub paths: Vec<PathBuf>,
    /// Show at most this many diagnostics per file.
    #[arg(long, default_value_t = 20)]
    pub max_errors: usize,
}

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
    #[error("{count} error(s) found")]
    #[diagnostic(code(vams::check::failed))]
    Failed { count: usize },
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

/// Runs the check; every diagnostic goes to stderr.
pub fn run(args: &CheckArgs) -> Result<(), Report> {
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    for path in &args.paths {
        for file in source_files(path)? {
            let bytes = std::fs::read(&file).map_err(|e| InputError::Unreadable {
                path: file.display().to_string(),
                reason: e.to_string(),
            })?;
            // Non-UTF-8 input is read as ISO 8859-1, VHDL's own character set.
            let text = String::from_utf8(bytes)
                .unwrap_or_else(|e| e.into_bytes().iter().map(|&b| b as char).collect());
            if stdlib::FILES.iter().any(|(_, _, t)| *t == text) {
                continue; // The bundled copy of this file is already loaded.
            }
            ids.push(sources.add(file.display().to_string(), "work", text));
        }
    }
    let mut count = 0;
    let mut units = 0;
    for id in ids {
        let text = sources.file(id).text.clone();
        let (ast, errors) = parser::parse(id, &text);
        units += ast.units.len();
        count += errors.len();
        for e in errors.iter().take(args.max_errors) {
            eprint!("{}", render_plain(e, &sources));
        }
        if errors.len() > args.max_errors {
            eprintln!(
                "  ... and {} more in {}\n",
                errors.len() - args.max_errors,
                sources.file(id).name
            );
        }
    }
    if count > 0 {
        return Err(InputError::Failed { count }.into());
    }
    eprintln!(
        "checked {} file(s), {units} design unit(s): no errors",
        sources.len()
    );
    Ok(())
}
